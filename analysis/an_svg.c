/* an_svg.c: SVG plot primitives (an_svg.h) */
#include "analysis/an_svg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double an_svg_nice(double x, int round)
{
    if (!(x > 0) || !isfinite(x)) return 1;
    double e = floor(log10(x)), p = pow(10, e), f = x / p, nf;
    if (round) nf = f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10;
    else nf = f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10;
    return nf * p;
}

int an_svg_ticks(double lo, double hi, int target, double *t, double *step)
{
    if (!isfinite(lo) || !isfinite(hi)) lo = hi = 0;
    if (lo > hi) {
        double s = lo;
        lo = hi;
        hi = s;
    }
    if (hi - lo <= 1e-12 * fmax(fabs(lo), fabs(hi))) {
        double d = lo == 0 ? 1 : fabs(lo) / 10;
        lo -= d;
        hi += d;
    }
    if (target < 1) target = 1;
    double d = an_svg_nice(an_svg_nice(hi - lo, 0) / target, 1);
    /* a step the tick array cannot hold: the next nice one */
    while ((ceil(hi / d - 1e-9) - floor(lo / d + 1e-9)) + 1 > AN_SVG_MAXTICKS)
        d = an_svg_nice(d * 1.01, 0);
    double k0 = floor(lo / d + 1e-9), k1 = ceil(hi / d - 1e-9);
    int n = 0;
    for (double k = k0; k <= k1 + 0.5 && n < AN_SVG_MAXTICKS; k++) {
        double v = k * d;
        t[n++] = fabs(v) < 1e-12 * d ? 0 : v;
    }
    *step = d;
    return n;
}

void an_svg_tick_label(double v, double step, char *buf, size_t n)
{
    int dec = step > 0 ? (int)-floor(log10(step) + 1e-9) : 0;
    if (dec < 0) dec = 0;
    if (dec > 9) dec = 9;
    if (fabs(v) < 0.5 * step * 1e-6) v = 0;
    snprintf(buf, n, "%.*f", dec, v);
    if (strspn(buf, "-0.") == strlen(buf) && buf[0] == '-') memmove(buf, buf + 1, strlen(buf));
}

void an_svg_axes_fit(an_svg_axes *a, double x0, double y0, double w, double h, double xmin,
                     double xmax, double ymin, double ymax)
{
    memset(a, 0, sizeof *a);
    a->x0 = x0;
    a->y0 = y0;
    a->w = w;
    a->h = h;
    a->nxt = an_svg_ticks(xmin, xmax, 6, a->xt, &a->xstep);
    a->nyt = an_svg_ticks(ymin, ymax, 5, a->yt, &a->ystep);
    a->xmin = a->xt[0];
    a->xmax = a->xt[a->nxt - 1];
    a->ymin = a->yt[0];
    a->ymax = a->yt[a->nyt - 1];
}

double an_svg_px(const an_svg_axes *a, double x)
{
    return a->x0 + (x - a->xmin) / (a->xmax - a->xmin) * a->w;
}

double an_svg_py(const an_svg_axes *a, double y)
{
    return a->y0 + a->h - (y - a->ymin) / (a->ymax - a->ymin) * a->h;
}

void an_svg_escape(FILE *f, const char *s)
{
    for (; s && *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&#39;", f); break;
        default: fputc(*s, f);
        }
    }
}

void an_svg_begin(FILE *f, double w, double h, const char *label)
{
    fprintf(f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
            "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"11\" "
            "role=\"img\" aria-label=\"",
            w, h, w, h);
    an_svg_escape(f, label);
    fputs("\">\n", f);
}

void an_svg_end(FILE *f)
{
    fputs("</svg>\n", f);
}

void an_svg_text(FILE *f, double x, double y, const char *anchor, double size, const char *fill,
                 const char *text)
{
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\"", x, y);
    if (anchor && strcmp(anchor, "start") != 0) fprintf(f, " text-anchor=\"%s\"", anchor);
    if (size > 0 && size != 11) fprintf(f, " font-size=\"%g\"", size);
    if (fill) fprintf(f, " fill=\"%s\"", fill);
    fputc('>', f);
    an_svg_escape(f, text);
    fputs("</text>\n", f);
}

void an_svg_line(FILE *f, double x1, double y1, double x2, double y2, const char *color,
                 double width, const char *dash)
{
    fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"", x1, y1, x2,
            y2, color);
    if (width != 1) fprintf(f, " stroke-width=\"%g\"", width);
    if (dash) fprintf(f, " stroke-dasharray=\"%s\"", dash);
    fputs("/>\n", f);
}

void an_svg_rect(FILE *f, double x, double y, double w, double h, const char *fill,
                 const char *title)
{
    fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"", x, y,
            w > 0 ? w : 0, h > 0 ? h : 0, fill);
    if (!title) {
        fputs("/>\n", f);
        return;
    }
    fputs("><title>", f);
    an_svg_escape(f, title);
    fputs("</title></rect>\n", f);
}

void an_svg_polygon(FILE *f, const double *px, const double *py, int n, const char *fill,
                    const char *stroke, double opacity)
{
    if (n < 2) return;
    fputs("<polygon points=\"", f);
    for (int i = 0; i < n; i++)
        fprintf(f, "%s%.1f,%.1f", i ? " " : "", px[i], py[i]);
    fprintf(f, "\" fill=\"%s\" stroke=\"%s\"", fill ? fill : "none", stroke ? stroke : "none");
    if (opacity < 1) fprintf(f, " fill-opacity=\"%.2f\"", opacity);
    fputs("/>\n", f);
}

void an_svg_draw_axes(FILE *f, const an_svg_axes *a, const char *xlabel, const char *ylabel)
{
    char b[48];
    double bot = a->y0 + a->h;
    /* grid */
    fputs("<g stroke=\"#e4e4e4\">", f);
    for (int i = 1; i < a->nxt - 1; i++) {
        double x = an_svg_px(a, a->xt[i]);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>", x, a->y0, x, bot);
    }
    for (int i = 1; i < a->nyt - 1; i++) {
        double y = an_svg_py(a, a->yt[i]);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>", a->x0, y,
                a->x0 + a->w, y);
    }
    fputs("</g>\n", f);
    /* zero line when inside */
    if (a->ymin < 0 && a->ymax > 0)
        an_svg_line(f, a->x0, an_svg_py(a, 0), a->x0 + a->w, an_svg_py(a, 0), "#999", 1, NULL);
    fprintf(f,
            "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
            "stroke=\"#444\"/>\n",
            a->x0, a->y0, a->w, a->h);
    /* ticks and their labels */
    for (int i = 0; i < a->nxt; i++) {
        double x = an_svg_px(a, a->xt[i]);
        an_svg_line(f, x, bot, x, bot + 4, "#444", 1, NULL);
        an_svg_tick_label(a->xt[i], a->xstep, b, sizeof b);
        an_svg_text(f, x, bot + 15, "middle", 0, NULL, b);
    }
    for (int i = 0; i < a->nyt; i++) {
        double y = an_svg_py(a, a->yt[i]);
        an_svg_line(f, a->x0 - 4, y, a->x0, y, "#444", 1, NULL);
        an_svg_tick_label(a->yt[i], a->ystep, b, sizeof b);
        an_svg_text(f, a->x0 - 6, y + 4, "end", 0, NULL, b);
    }
    if (xlabel) an_svg_text(f, a->x0 + a->w / 2, bot + 30, "middle", 12, NULL, xlabel);
    if (ylabel) {
        fprintf(f,
                "<text transform=\"translate(%.1f %.1f) rotate(-90)\" text-anchor=\"middle\" "
                "font-size=\"12\">",
                a->x0 - 44, a->y0 + a->h / 2);
        an_svg_escape(f, ylabel);
        fputs("</text>\n", f);
    }
}

/* one point of a path: "M" to start a run, then implicit line-tos */
static void path_point(FILE *f, double x, double y, int *pen)
{
    fprintf(f, *pen == 0 ? "M%.1f %.1f" : *pen == 1 ? "L%.1f %.1f" : " %.1f %.1f", x, y);
    (*pen)++;
}

/* one pixel column's samples: first, lowest, highest, last in the order they came */
typedef struct {
    long col;
    size_t idx[4]; /* first, min, max, last */
    double y[4];
    int n;
} svg_col;

static size_t col_flush(FILE *f, const an_svg_axes *a, const double *x, const svg_col *c,
                        int *pen)
{
    size_t order[4] = {c->idx[0], c->idx[1], c->idx[2], c->idx[3]};
    double ys[4] = {c->y[0], c->y[1], c->y[2], c->y[3]};
    /* sort the four by sample index (insertion sort) */
    for (int i = 1; i < 4; i++)
        for (int j = i; j > 0 && order[j] < order[j - 1]; j--) {
            size_t t = order[j];
            order[j] = order[j - 1];
            order[j - 1] = t;
            double u = ys[j];
            ys[j] = ys[j - 1];
            ys[j - 1] = u;
        }
    size_t k = 0;
    double lo = a->y0 - 2, hi = a->y0 + a->h + 2;
    for (int i = 0; i < 4; i++) {
        if (i && order[i] == order[i - 1]) continue;
        double py = an_svg_py(a, ys[i]);
        path_point(f, an_svg_px(a, x[order[i]]), py < lo ? lo : py > hi ? hi : py, pen);
        k++;
    }
    return k;
}

size_t an_svg_path(FILE *f, const an_svg_axes *a, const double *x, const double *y, size_t n,
                   double yscale, const char *color, double width, const char *dash)
{
    size_t k = 0;
    int pen = 0;
    svg_col c = {.col = -1, .n = 0};
    double eps = 1e-9 * (a->xmax - a->xmin);
    fputs("<path d=\"", f);
    for (size_t i = 0; i < n; i++) {
        double v = y[i] * yscale;
        if (!isfinite(v) || !isfinite(x[i]) || x[i] < a->xmin - eps || x[i] > a->xmax + eps) {
            if (c.n) k += col_flush(f, a, x, &c, &pen);
            c.n = 0;
            c.col = -1;
            pen = 0;
            continue;
        }
        long col = (long)floor(an_svg_px(a, x[i]));
        if (c.n && col != c.col) {
            k += col_flush(f, a, x, &c, &pen);
            c.n = 0;
        }
        if (!c.n) {
            c.col = col;
            for (int j = 0; j < 4; j++) {
                c.idx[j] = i;
                c.y[j] = v;
            }
            c.n = 1;
            continue;
        }
        if (v < c.y[1]) c.idx[1] = i, c.y[1] = v;
        if (v > c.y[2]) c.idx[2] = i, c.y[2] = v;
        c.idx[3] = i;
        c.y[3] = v;
    }
    if (c.n) k += col_flush(f, a, x, &c, &pen);
    fprintf(f, "\" fill=\"none\" stroke=\"%s\" stroke-width=\"%g\" stroke-linejoin=\"round\"",
            color, width);
    if (dash) fprintf(f, " stroke-dasharray=\"%s\"", dash);
    fputs("/>\n", f);
    return k;
}

void an_svg_legend(FILE *f, double x, double y, const char *const *labels,
                   const char *const *colors, const char *const *dash, int n)
{
    if (n <= 0) return;
    size_t wmax = 0;
    for (int i = 0; i < n; i++)
        if (strlen(labels[i]) > wmax) wmax = strlen(labels[i]);
    double w = 34 + 6.2 * (double)wmax, h = 6 + 15 * n;
    fprintf(f,
            "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#fff\" "
            "fill-opacity=\"0.85\" stroke=\"#bbb\"/>\n",
            x, y, w, h);
    for (int i = 0; i < n; i++) {
        double yy = y + 12 + 15 * i;
        an_svg_line(f, x + 5, yy - 4, x + 25, yy - 4, colors[i], 2, dash ? dash[i] : NULL);
        an_svg_text(f, x + 30, yy, "start", 0, NULL, labels[i]);
    }
}

const char *an_svg_color(int i)
{
    static const char *pal[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
    int n = (int)(sizeof pal / sizeof pal[0]);
    return pal[((i % n) + n) % n];
}

static int cmp_xy(const void *pa, const void *pb)
{
    const double *a = pa, *b = pb;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return a[1] < b[1] ? -1 : a[1] > b[1];
}

static double cross(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

int an_svg_hull(double *xy, int n, double *hull)
{
    if (n < 3) {
        memcpy(hull, xy, sizeof(double) * 2 * (size_t)(n > 0 ? n : 0));
        return n > 0 ? n : 0;
    }
    qsort(xy, (size_t)n, 2 * sizeof(double), cmp_xy);
    int k = 0;
    for (int i = 0; i < n; i++) { /* lower hull */
        while (k >= 2 && cross(hull + 2 * (k - 2), hull + 2 * (k - 1), xy + 2 * i) <= 0) k--;
        hull[2 * k] = xy[2 * i];
        hull[2 * k + 1] = xy[2 * i + 1];
        k++;
    }
    for (int i = n - 2, lo = k + 1; i >= 0; i--) { /* upper hull */
        while (k >= lo && cross(hull + 2 * (k - 2), hull + 2 * (k - 1), xy + 2 * i) <= 0) k--;
        hull[2 * k] = xy[2 * i];
        hull[2 * k + 1] = xy[2 * i + 1];
        k++;
    }
    return k - 1; /* the last point repeats the first */
}

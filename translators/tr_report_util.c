/* tr_report_util.c: what the report's sections share: reading, headings, line plots */
#include "analysis/an_svg.h"
#include "translators/tr_report_int.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int rp_read(tr_rp *c, const char *path, mcs_array *a)
{
    mcs_error e = {0};
    memset(a, 0, sizeof *a);
    if (mcs_results_kind(c->r, path) != MCS_RES_DATASET) return -1;
    if (mcs_results_read(c->r, path, a, &e)) {
        mcs_array_free(a);
        return -1;
    }
    return 0;
}

void rp_attr(tr_rp *c, const char *path, const char *name, char *buf, size_t n)
{
    char *s = NULL;
    mcs_error e = {0};
    buf[0] = 0;
    if (!mcs_results_has_attr(c->r, path, name)) return;
    if (mcs_results_attr_str(c->r, path, name, &s, &e) == MCS_OK) snprintf(buf, n, "%s", s);
    free(s);
}

char **rp_list(tr_rp *c, const char *group, int *n)
{
    char **names = NULL;
    mcs_error e = {0};
    *n = 0;
    if (mcs_results_kind(c->r, group) != MCS_RES_GROUP) return NULL;
    if (mcs_results_list(c->r, group, &names, n, &e)) *n = 0;
    return names;
}

static void append(char *dst, size_t cap, const char *s)
{
    size_t k = strlen(dst);
    snprintf(dst + k, cap - k, "%s%s", k ? "," : "", s);
}

void rp_esc(tr_rp *c, const char *s)
{
    an_svg_escape(c->f, s);
}

void rp_section(tr_rp *c, const char *id, const char *title)
{
    fprintf(c->f, "<section id=\"%s\"><h2>", id);
    rp_esc(c, title);
    fputs("</h2>\n", c->f);
    c->sum->nsections++;
    append(c->sum->sections, sizeof c->sum->sections, id);
}

void rp_skip(tr_rp *c, const char *id, const char *why)
{
    (void)why;
    append(c->sum->skipped, sizeof c->sum->skipped, id);
}

void rp_h3(tr_rp *c, const char *text)
{
    fputs("<h3>", c->f);
    rp_esc(c, text);
    fputs("</h3>\n", c->f);
}

double *rp_column(const mcs_array *a, int k)
{
    size_t n = a->rank >= 1 ? a->dims[0] : 0, w = a->rank >= 2 ? a->dims[1] : 1;
    double *v = malloc(sizeof *v * (n ? n : 1));
    if (!v) return NULL;
    for (size_t i = 0; i < n; i++) v[i] = (size_t)k < w ? a->v[i * w + (size_t)k] : NAN;
    return v;
}

double *rp_norm3(const mcs_array *a)
{
    size_t n = a->rank >= 1 ? a->dims[0] : 0, w = a->rank >= 2 ? a->dims[1] : 1;
    double *v = malloc(sizeof *v * (n ? n : 1));
    if (!v) return NULL;
    for (size_t i = 0; i < n; i++) {
        double s = 0;
        for (size_t j = 0; j < w && j < 3; j++) s += a->v[i * w + j] * a->v[i * w + j];
        v[i] = sqrt(s);
    }
    return v;
}

/* the finite range of v * scale over n samples into [lo, hi] */
static void range(const double *v, size_t n, double scale, double *lo, double *hi)
{
    for (size_t i = 0; i < n; i++) {
        double y = v[i] * scale;
        if (!isfinite(y)) continue;
        if (y < *lo) *lo = y;
        if (y > *hi) *hi = y;
    }
}

void rp_lines(tr_rp *c, const rp_plot *p, const rp_series *s, int ns)
{
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (int i = 0; i < ns; i++) {
        range(s[i].x, s[i].n, p->xscale, &xlo, &xhi);
        range(s[i].y, s[i].n, p->yscale, &ylo, &yhi);
    }
    if (!(xlo <= xhi) || !(ylo <= yhi)) return;
    if (isfinite(p->ymin0) && p->ymin0 < ylo) ylo = p->ymin0;
    if (isfinite(p->ymax0) && p->ymax0 > yhi) yhi = p->ymax0;
    FILE *f = c->f;
    double W = c->svg_w, H = 262;
    an_svg_axes a;
    an_svg_axes_fit(&a, 64, 28, 360, 190, xlo, xhi, ylo, yhi);
    an_svg_begin(f, W, H, p->title);
    fputs("<g font-weight=\"bold\">", f);
    an_svg_text(f, 8, 16, "start", 13, NULL, p->title);
    fputs("</g>\n", f);
    an_svg_draw_axes(f, &a, p->xlabel, p->ylabel);
    const char *lab[16], *col[16], *dash[16];
    int nl = 0;
    for (int i = 0; i < ns; i++) {
        double *xs = malloc(sizeof *xs * (s[i].n ? s[i].n : 1));
        if (!xs) continue;
        for (size_t k = 0; k < s[i].n; k++) xs[k] = s[i].x[k] * p->xscale;
        const char *color = s[i].color ? s[i].color : an_svg_color(i);
        an_svg_path(f, &a, xs, s[i].y, s[i].n, p->yscale, color, 1.6, s[i].dash);
        free(xs);
        if (nl < 16 && s[i].label) {
            lab[nl] = s[i].label;
            col[nl] = color;
            dash[nl++] = s[i].dash;
        }
    }
    an_svg_legend(f, a.x0 + a.w + 12, a.y0, lab, col, dash, nl);
    an_svg_end(f);
    c->sum->nsvg++;
}

void rp_copy(char *dst, size_t n, const char *src)
{
    size_t k = strlen(src);
    if (k >= n) k = n - 1;
    memcpy(dst, src, k);
    dst[k] = 0;
}

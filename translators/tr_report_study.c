/* tr_report_study.c: the report's study page (a STUDY.h5 of `mcrash study`, docs/contracts.md
 * "Studies"): per response, the main-effect plots (the mean response at each level of a
 * factor, over the cases that have a value) and the two-factor interaction plots (the mean of
 * each cell: the first factor's levels along x, one line per level of the second). Factors
 * with 2 to RP_MAXLEV distinct values are plotted (a Latin hypercube's are not: each level
 * is one case); with compare: the variant (0 the scenario, 1 the compared one) is a factor
 * too. Each point carries its value as a tooltip (<title>mean ... (n cases)</title>). */
#include "analysis/an_svg.h"
#include "translators/tr_report_int.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RP_MAXLEV 8
#define RP_MAXFAC 27
#define RP_MAXPAIR 6 /* interaction plots per response */

typedef struct {
    char name[128];
    const double *x; /* value per case (stride: the design's width) */
    int stride;
    int nlev;
    double lev[RP_MAXLEV]; /* distinct values, ascending */
} rp_factor;

/* the distinct values of a factor over the cases (0 when more than RP_MAXLEV or fewer than 2) */
static int levels(rp_factor *f, long ncase)
{
    f->nlev = 0;
    for (long c = 0; c < ncase; c++) {
        double v = f->x[c * f->stride];
        int k = 0;
        while (k < f->nlev && f->lev[k] != v) k++;
        if (k < f->nlev) continue;
        if (f->nlev == RP_MAXLEV) return f->nlev = 0;
        f->lev[f->nlev++] = v;
    }
    for (int i = 1; i < f->nlev; i++) /* insertion sort */
        for (int k = i; k > 0 && f->lev[k - 1] > f->lev[k]; k--) {
            double t = f->lev[k];
            f->lev[k] = f->lev[k - 1], f->lev[k - 1] = t;
        }
    return f->nlev >= 2 ? f->nlev : (f->nlev = 0);
}

static int level_of(const rp_factor *f, long c)
{
    for (int k = 0; k < f->nlev; k++)
        if (f->lev[k] == f->x[c * f->stride]) return k;
    return -1;
}

/* means of y per level of a (and of b when b is not NULL: cells [la * nb + lb]) */
static void cell_means(const rp_factor *a, const rp_factor *b, const double *y, long ncase,
                       double *mean, int *cnt)
{
    int nb = b ? b->nlev : 1;
    memset(cnt, 0, sizeof *cnt * a->nlev * nb);
    for (int i = 0; i < a->nlev * nb; i++)
        mean[i] = 0;
    for (long c = 0; c < ncase; c++) {
        int la = level_of(a, c), lb = b ? level_of(b, c) : 0;
        if (la < 0 || lb < 0 || !isfinite(y[c])) continue;
        mean[la * nb + lb] += y[c], cnt[la * nb + lb]++;
    }
    for (int i = 0; i < a->nlev * nb; i++)
        mean[i] = cnt[i] ? mean[i] / cnt[i] : NAN;
}

/* one plot: x the levels of a, one line per level of b (or one line), points with tooltips */
static void effect_plot(tr_rp *c, const rp_factor *a, const rp_factor *b, const double *y,
                        long ncase, const char *resp, const char *unit)
{
    int nb = b ? b->nlev : 1;
    double mean[RP_MAXLEV * RP_MAXLEV], lo = INFINITY, hi = -INFINITY;
    int cnt[RP_MAXLEV * RP_MAXLEV];
    cell_means(a, b, y, ncase, mean, cnt);
    for (int i = 0; i < a->nlev * nb; i++)
        if (isfinite(mean[i])) lo = fmin(lo, mean[i]), hi = fmax(hi, mean[i]);
    if (!(hi >= lo)) return;
    char title[400], ylab[200];
    if (b)
        snprintf(title, sizeof title, "interaction %s x %s: %s", a->name, b->name, resp);
    else
        snprintf(title, sizeof title, "main effect of %s: %s", a->name, resp);
    char xlab[200];
    snprintf(ylab, sizeof ylab, "mean %s [%s]", resp, unit);
    snprintf(xlab, sizeof xlab, "%s [SI]", a->name);
    double w = c->svg_w, h = 300;
    an_svg_axes ax;
    an_svg_axes_fit(&ax, 70, 30, w - (b ? 230 : 100), h - 80, a->lev[0], a->lev[a->nlev - 1],
                    lo, hi);
    an_svg_begin(c->f, w, h, title);
    an_svg_text(c->f, w / 2, 16, "middle", 13, "#222", title);
    an_svg_draw_axes(c->f, &ax, xlab, ylab);
    const char *lab[RP_MAXLEV], *col[RP_MAXLEV];
    char labs[RP_MAXLEV][64];
    for (int lb = 0; lb < nb; lb++) {
        double xs[RP_MAXLEV], ys[RP_MAXLEV];
        for (int la = 0; la < a->nlev; la++)
            xs[la] = a->lev[la], ys[la] = mean[la * nb + lb];
        col[lb] = an_svg_color(lb);
        an_svg_path(c->f, &ax, xs, ys, (size_t)a->nlev, 1, col[lb], 2, NULL);
        for (int la = 0; la < a->nlev; la++) {
            if (!isfinite(ys[la])) continue;
            fprintf(c->f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"><title>",
                    an_svg_px(&ax, xs[la]), an_svg_py(&ax, ys[la]), col[lb]);
            fprintf(c->f, "mean %.6g at %.6g", ys[la], xs[la]);
            if (b) fprintf(c->f, ", %.6g", b->lev[lb]);
            fprintf(c->f, " (%d cases)</title></circle>\n", cnt[la * nb + lb]);
        }
        snprintf(labs[lb], sizeof labs[lb], "%.6g", b ? b->lev[lb] : 0);
        lab[lb] = labs[lb];
    }
    if (b) {
        char head[40];
        snprintf(head, sizeof head, "%.24s%s [SI]:", b->name, strlen(b->name) > 24 ? "..." : "");
        an_svg_text(c->f, w - 150, 40, "start", 11, "#222", head);
        an_svg_legend(c->f, w - 150, 48, lab, col, NULL, nb);
    }
    an_svg_end(c->f);
    c->sum->nsvg++;
}

/* the factors as rp_factor, the variant last when there is one; their count */
static int read_factors(tr_rp *c, const mcs_array *d, const mcs_array *var, rp_factor *f)
{
    char names[4096];
    rp_attr(c, "/study", "factors", names, sizeof names);
    int k = (int)d->dims[1], n = 0;
    char *save = NULL, *tok = strtok_r(names, "\n", &save);
    for (int j = 0; j < k && n < RP_MAXFAC - 1; j++) {
        f[n] = (rp_factor){.x = d->v + j, .stride = k};
        rp_copy(f[n++].name, sizeof f[0].name, tok ? tok : "?");
        if (tok) tok = strtok_r(NULL, "\n", &save);
    }
    if (var->n == d->dims[0] && n < RP_MAXFAC) {
        f[n] = (rp_factor){.x = var->v, .stride = 1};
        rp_copy(f[n++].name, sizeof f[0].name, "variant (0 scenario, 1 compare)");
    }
    return n;
}

/* per response: its main effects, then up to RP_MAXPAIR interactions */
static void response_plots(tr_rp *c, const char *resp, rp_factor *f, int nf, long ncase)
{
    char path[300];
    snprintf(path, sizeof path, "/study/responses/%s", resp);
    mcs_array y = {0};
    if (rp_read(c, path, &y) || y.n != (size_t)ncase) {
        mcs_array_free(&y);
        return;
    }
    rp_h3(c, resp);
    fputs("<div class=\"plots\">\n", c->f);
    for (int j = 0; j < nf; j++)
        if (f[j].nlev) effect_plot(c, &f[j], NULL, y.v, ncase, resp, y.unit[0] ? y.unit : "-");
    int np = 0;
    for (int j = 0; j < nf; j++)
        for (int q = j + 1; q < nf && np < RP_MAXPAIR; q++)
            if (f[j].nlev && f[q].nlev) {
                effect_plot(c, &f[j], &f[q], y.v, ncase, resp, y.unit[0] ? y.unit : "-");
                np++;
            }
    fputs("</div>\n", c->f);
    mcs_array_free(&y);
}

void rp_study(tr_rp *c)
{
    mcs_array d = {0}, var = {0}, st = {0};
    if (rp_read(c, "/study/design", &d) || d.rank != 2 || d.dims[0] < 1) {
        rp_skip(c, "study", "no /study/design");
        mcs_array_free(&d);
        return;
    }
    rp_read(c, "/study/variant", &var);
    rp_read(c, "/study/status", &st);
    long ncase = (long)d.dims[0], nfail = 0;
    for (size_t i = 0; i < st.n; i++)
        nfail += st.v[i] != 0;
    rp_factor f[RP_MAXFAC];
    int nf = read_factors(c, &d, &var, f), nplot = 0;
    for (int j = 0; j < nf; j++)
        nplot += levels(&f[j], ncase) > 0;
    char design[64], resp[4096];
    rp_attr(c, "/study", "design", design, sizeof design);
    rp_attr(c, "/study", "responses", resp, sizeof resp);
    rp_section(c, "study", "Study: main effects and interactions");
    fprintf(c->f, "<p>design %s, %ld cases (%ld failed, left out of the means), %d factors, "
                  "%d of them with 2 to %d levels (plotted).</p>\n",
            design, ncase, nfail, nf, nplot, RP_MAXLEV);
    char *save = NULL;
    for (char *r = strtok_r(resp, "\n", &save); r && nplot; r = strtok_r(NULL, "\n", &save))
        response_plots(c, r, f, nf, ncase);
    fputs("</section>\n", c->f);
    mcs_array_free(&d), mcs_array_free(&var), mcs_array_free(&st);
}

/* study_analyze.c: `mcrash study --analyze STUDY.h5 [--json]`: per response, the multiple
 * linear regression on the factors (in SI, as given, not normalised) and, for factorial
 * designs, the ANOVA of the main effects and two-factor interactions (an_stats.h). Failed
 * cases (NaN responses) are left out. JSON: DESIGN.md "Studies" and its extensions in
 * docs/contracts.md. */
#include "analysis/an_stats.h"
#include "cli/cli_common.h"
#include "cli/study.h"
#include "core/mcs_results.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    long ncase;
    int nfactor, nresp;
    char *design, *fnames, *rnames; /* attributes (newline-joined names) */
    const char *fn[64], *rn[STUDY_MAXRESP];
    double *x;                      /* ncase x nfactor */
    double *y[STUDY_MAXRESP];       /* ncase each */
    char unit[STUDY_MAXRESP][32];
} study_data;

static int split(char *s, const char **out, int max)
{
    int n = 0;
    for (char *p = s; p && *p && n < max; n++) {
        out[n] = p;
        p = strchr(p, '\n');
        if (p) *p++ = 0;
    }
    return n;
}

static void data_free(study_data *d)
{
    free(d->design), free(d->fnames), free(d->rnames), free(d->x);
    for (int i = 0; i < d->nresp; i++)
        free(d->y[i]);
}

/* the iso13232 design: its constant columns (a point's coordinate no code changes) left out,
 * and with compare: the variant (0 the scenario, 1 the compared one) a factor */
static mcs_status iso_columns(mcs_results *r, study_data *d, mcs_error *err)
{
    mcs_array v = {0};
    int k = d->nfactor, m = 0, var = mcs_results_kind(r, "/study/variant") == MCS_RES_DATASET;
    if (var && (mcs_results_read(r, "/study/variant", &v, err) || (long)v.n != d->ncase)) {
        mcs_array_free(&v);
        return err->status ? err->status : MCS_ERR(err, MCS_ERR_FORMAT, "/study/variant");
    }
    double *x = malloc((size_t)d->ncase * (k + 1) * sizeof *x);
    if (!x) return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    for (int j = 0; j <= k; j++) {
        const double *col = j < k ? d->x + j : v.v;
        int step = j < k ? k : 1, same = 1;
        if (j == k && !var) break;
        for (long c = 1; c < d->ncase; c++)
            same &= col[c * step] == col[0];
        if (same) continue;
        for (long c = 0; c < d->ncase; c++)
            x[c * (k + 1) + m] = col[c * step];
        d->fn[m++] = j < k ? d->fn[j] : "variant";
    }
    for (long c = 0; c < d->ncase; c++) /* rows of m columns */
        memmove(x + c * m, x + c * (k + 1), (size_t)m * sizeof *x);
    free(d->x);
    d->x = x, d->nfactor = m;
    mcs_array_free(&v);
    return MCS_OK;
}

static mcs_status data_read(const char *path, study_data *d, mcs_error *err)
{
    memset(d, 0, sizeof *d);
    mcs_results *r = NULL;
    mcs_array a = {0};
    mcs_status st = mcs_results_open(&r, path, err);
    if (!st) st = mcs_results_attr_str(r, "/study", "design", &d->design, err);
    if (!st) st = mcs_results_attr_str(r, "/study", "factors", &d->fnames, err);
    if (!st) st = mcs_results_attr_str(r, "/study", "responses", &d->rnames, err);
    if (!st) st = mcs_results_read(r, "/study/design", &a, err);
    if (!st) {
        d->nfactor = split(d->fnames, d->fn, 64);
        d->nresp = split(d->rnames, d->rn, STUDY_MAXRESP);
        d->ncase = (long)a.dims[0];
        if (a.rank != 2 || (int)a.dims[1] != d->nfactor)
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: /study/design is not [ncase, %d]", path,
                         d->nfactor);
        d->x = a.v, a.v = NULL;
    }
    mcs_array_free(&a);
    for (int i = 0; !st && i < d->nresp; i++) {
        char p[256];
        snprintf(p, sizeof p, "/study/responses/%s", d->rn[i]);
        st = mcs_results_read(r, p, &a, err);
        if (!st && (long)a.n != d->ncase)
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s has not %ld values", path, p, d->ncase);
        if (!st) snprintf(d->unit[i], sizeof d->unit[i], "%s", a.unit);
        d->y[i] = a.v, a.v = NULL;
        mcs_array_free(&a);
    }
    if (!st && !strcmp(d->design, "iso13232")) st = iso_columns(r, d, err);
    mcs_results_close(&r);
    return st;
}

static int factorial(const study_data *d)
{
    return !strcmp(d->design, "full_factorial") || !strcmp(d->design, "fractional_factorial");
}

/* a number in JSON: null for NaN and infinities */
static void jnum(double v)
{
    isfinite(v) ? printf("%.10g", v) : printf("null");
}

static void term_name(const study_data *d, const an_anova *a, int t, char *s, size_t n)
{
    if (a->fb[t] < 0)
        snprintf(s, n, "%s", d->fn[a->fa[t]]);
    else
        snprintf(s, n, "%s:%s", d->fn[a->fa[t]], d->fn[a->fb[t]]);
}

static void print_regression(const study_data *d, const an_regression *g)
{
    printf("  regression: n %d, R^2 %.4g, adjusted %.4g, F %.4g (p %.3g), residual sd %.4g\n",
           g->n, g->r2, g->adj_r2, g->F, g->F_p, g->sigma);
    printf("  %-32s %13s %10s %12s %9s %10s %10s\n", "term", "coefficient", "std.coef",
           "std.error", "t", "p", "partial r");
    for (int q = 0; q <= d->nfactor; q++)
        printf("  %-32.32s %13.6g %10.4g %12.4g %9.4g %10.3g %10.4g\n",
               q ? d->fn[q - 1] : "intercept", g->coef[q], q ? g->std_coef[q - 1] : 0.0, g->se[q],
               g->t[q], g->p[q], q ? g->partial[q - 1] : NAN);
}

static void print_anova(const study_data *d, const an_anova *a)
{
    printf("  ANOVA (type I sums of squares%s): n %d\n",
           a->interactions ? "" : "; interactions pooled into the residual", a->n);
    printf("  %-40s %12s %4s %10s %10s\n", "term", "SS", "df", "F", "p");
    for (int t = 0; t < a->nterm; t++) {
        char nm[200];
        term_name(d, a, t, nm, sizeof nm);
        printf("  %-40.40s %12.6g %4d %10.4g %10.3g\n", nm, a->ss[t], a->df[t], a->F[t], a->p[t]);
    }
    printf("  %-40s %12.6g %4d\n", "residual", a->ss_resid, a->df_resid);
}

static void json_regression(const study_data *d, const an_regression *g)
{
    const char *key[5] = {"coefficients", "std_coefficients", "t", "p", "partial"};
    for (int k = 0; k < 5; k++) {
        int q0 = k == 1 || k == 4; /* no intercept */
        printf("%s\"%s\": {", k ? ", " : "", key[k]);
        for (int q = q0; q <= d->nfactor; q++) {
            printf(q > q0 ? ", " : "");
            cli_json_string(q ? d->fn[q - 1] : "intercept");
            printf(": ");
            jnum(k == 0   ? g->coef[q]
                 : k == 1 ? g->std_coef[q - 1]
                 : k == 2 ? g->t[q]
                 : k == 3 ? g->p[q]
                          : g->partial[q - 1]);
        }
        printf("}");
    }
    printf(", \"r2\": "), jnum(g->r2);
    printf(", \"adj_r2\": "), jnum(g->adj_r2);
    printf(", \"F\": "), jnum(g->F);
    printf(", \"F_p\": "), jnum(g->F_p);
    printf(", \"n\": %d, \"df\": %d", g->n, g->df);
}

/* the main effects (contract) or the interactions (extension) of an ANOVA */
static void json_anova(const study_data *d, const an_anova *a, int inter)
{
    int first = 1;
    for (int t = 0; t < a->nterm; t++) {
        if ((a->fb[t] >= 0) != inter) continue;
        char nm[200];
        term_name(d, a, t, nm, sizeof nm);
        printf(first ? "" : ", ");
        first = 0;
        cli_json_string(nm);
        printf(": {\"F\": "), jnum(a->F[t]);
        printf(", \"p\": "), jnum(a->p[t]);
        printf(", \"SS\": "), jnum(a->ss[t]);
        printf(", \"df\": %d}", a->df[t]);
    }
}

typedef struct {
    int ok_reg, ok_anova;
    an_regression g;
    an_anova a;
    char why[1024];
} resp_fit;

static void fit_all(const study_data *d, resp_fit *f)
{
    for (int i = 0; i < d->nresp; i++) {
        mcs_error err = {0};
        f[i].ok_reg = !an_regress((int)d->ncase, d->nfactor, d->x, d->y[i], &f[i].g, &err);
        if (!f[i].ok_reg) snprintf(f[i].why, sizeof f[i].why, "%s", err.msg);
        mcs_error_clear(&err);
        f[i].ok_anova = factorial(d) &&
                        !an_anova_fit((int)d->ncase, d->nfactor, d->x, d->y[i], 1, &f[i].a, &err);
    }
}

static void print_json(const study_data *d, const resp_fit *f)
{
    const char *sec[3] = {"regression", "anova", "anova_interactions"};
    printf("{");
    for (int k = 0; k < 3; k++) {
        printf("%s\"%s\": {", k ? ", " : "", sec[k]);
        int first = 1;
        for (int i = 0; i < d->nresp; i++) {
            if (k == 0 ? !f[i].ok_reg : !f[i].ok_anova) continue;
            printf(first ? "" : ", ");
            first = 0;
            cli_json_string(d->rn[i]);
            printf(": {");
            if (k == 0)
                json_regression(d, &f[i].g);
            else
                json_anova(d, &f[i].a, k == 2);
            printf("}");
        }
        printf("}");
    }
    study_analyze_more(d->ncase, d->nfactor, d->x, d->nresp, d->y, d->fn, d->rn, factorial(d),
                       1);
    printf("}\n");
}

int study_analyze(const char *h5, int json)
{
    study_data d;
    mcs_error err = {0};
    if (data_read(h5, &d, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        data_free(&d);
        return 2;
    }
    resp_fit *f = calloc((size_t)d.nresp + 1, sizeof *f);
    if (!f) return 2;
    fit_all(&d, f);
    if (json) {
        print_json(&d, f);
    } else {
        printf("%s: %ld cases, design %s, %d factors (SI)\n", h5, d.ncase, d.design, d.nfactor);
        for (int i = 0; i < d.nresp; i++) {
            printf("\nresponse %s [%s]\n", d.rn[i], d.unit[i]);
            if (f[i].ok_reg)
                print_regression(&d, &f[i].g);
            else
                printf("  regression: none (%s)\n", f[i].why);
            if (f[i].ok_anova) print_anova(&d, &f[i].a);
        }
        study_analyze_more(d.ncase, d.nfactor, d.x, d.nresp, d.y, d.fn, d.rn, factorial(&d), 0);
    }
    for (int i = 0; i < d.nresp; i++)
        an_regression_free(&f[i].g);
    free(f);
    data_free(&d);
    return fflush(stdout) ? 2 : 0;
}

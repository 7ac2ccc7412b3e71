/* study_analyze_more.c: the stepwise selections, quadratic response surfaces and the MANOVA of
 * `mcrash study --analyze` (analysis/an_stats.h; docs/contracts.md "Studies") */
#include "analysis/an_stats.h"
#include "cli/cli_common.h"
#include "cli/study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define P_ENTER 0.05  /* stepwise: p to enter */
#define P_REMOVE 0.10 /* stepwise: p to remove */

static void jnum(double v)
{
    isfinite(v) ? printf("%.10g", v) : printf("null");
}

/* name of quadratic term c of k factors: "A", "A^2", "A*B" */
static void rsm_name(const char *const *fn, int k, int c, char *s, size_t n)
{
    if (c < k) {
        snprintf(s, n, "%s", fn[c]);
        return;
    }
    if (c < 2 * k) {
        snprintf(s, n, "%s^2", fn[c - k]);
        return;
    }
    c -= 2 * k;
    for (int a = 0; a < k; a++)
        for (int b = a + 1; b < k; b++, c--)
            if (c == 0) {
                snprintf(s, n, "%s*%s", fn[a], fn[b]);
                return;
            }
}

/* every factor has 3 distinct values or more (a square is estimable) */
static int three_levels(long n, int k, const double *x)
{
    for (int j = 0; j < k; j++) {
        double v[3];
        int nv = 0;
        for (long i = 0; i < n && nv < 3; i++) {
            int seen = 0;
            for (int q = 0; q < nv; q++)
                seen |= v[q] == x[i * k + j];
            if (!seen) v[nv++] = x[i * k + j];
        }
        if (nv < 3) return 0;
    }
    return 1;
}

static void stepwise(long n, int k, const double *x, int nresp, double *const *y,
                     const char *const *fn, const char *const *rn, int json)
{
    int *sel = calloc((size_t)k, sizeof *sel), *order = calloc((size_t)k * 8 + 8, sizeof *order);
    if (!sel || !order) goto done;
    json ? printf(", \"stepwise\": {")
         : printf("\nstepwise selection (p to enter %.2f, to remove %.2f)\n", P_ENTER, P_REMOVE);
    for (int i = 0, first = 1; i < nresp; i++) {
        int nstep = 0;
        mcs_error err = {0};
        if (an_stepwise((int)n, k, x, y[i], P_ENTER, P_REMOVE, sel, order, &nstep, &err))
            continue;
        if (json) {
            printf(first ? "" : ", ");
            cli_json_string(rn[i]);
            printf(": {\"selected\": [");
            for (int j = 0, f2 = 1; j < k; j++)
                if (sel[j]) printf(f2 ? "" : ", "), cli_json_string(fn[j]), f2 = 0;
            printf("], \"steps\": [");
            for (int s = 0; s < nstep; s++) {
                char t[256];
                snprintf(t, sizeof t, "%c%s", order[s] > 0 ? '+' : '-', fn[abs(order[s]) - 1]);
                printf(s ? ", " : ""), cli_json_string(t);
            }
            printf("]}");
        } else {
            printf("  %s:", rn[i]);
            int none = 1;
            for (int j = 0; j < k; j++)
                if (sel[j]) printf(" %s", fn[j]), none = 0;
            printf(none ? " (no factor)\n" : "\n");
        }
        first = 0;
    }
    if (json) printf("}");
done:
    free(sel), free(order);
}

static void quadratic(long n, int k, const double *x, int nresp, double *const *y,
                      const char *const *fn, const char *const *rn, int json)
{
    int ok = three_levels(n, k, x), q = an_rsm_nterm(k);
    json ? printf(", \"quadratic\": {")
         : printf("\nquadratic response surfaces%s\n",
                  ok ? "" : ": none (a factor has < 3 levels)");
    for (int i = 0, first = 1; ok && i < nresp; i++) {
        an_regression r;
        mcs_error err = {0};
        if (an_rsm_fit((int)n, k, x, y[i], &r, &err)) {
            if (!json) printf("  %s: none (%s)\n", rn[i], err.msg);
            continue;
        }
        char nm[300];
        if (json) {
            printf(first ? "" : ", ");
            cli_json_string(rn[i]);
            for (int s = 0; s < 2; s++) {
                printf(s ? ", \"p\": {" : ": {\"coefficients\": {");
                for (int c = 0; c <= q; c++) {
                    if (c) rsm_name(fn, k, c - 1, nm, sizeof nm);
                    printf(c ? ", " : ""), cli_json_string(c ? nm : "intercept");
                    printf(": "), jnum(s ? r.p[c] : r.coef[c]);
                }
                printf("}");
            }
            printf(", \"r2\": "), jnum(r.r2), printf("}");
        } else {
            printf("  %s: R^2 %.4g, adjusted %.4g, n %d\n", rn[i], r.r2, r.adj_r2, r.n);
            for (int c = 0; c <= q; c++) {
                if (c) rsm_name(fn, k, c - 1, nm, sizeof nm);
                printf("    %-40.40s %13.6g  p %.3g\n", c ? nm : "intercept", r.coef[c], r.p[c]);
            }
        }
        first = 0;
        an_regression_free(&r);
    }
    if (json) printf("}");
}

static void manova(long n, int k, const double *x, int nresp, double *const *y,
                   const char *const *fn, int json)
{
    double *yy = malloc(((size_t)n * nresp + 1) * sizeof *yy);
    an_manova a;
    mcs_error err = {0};
    for (long i = 0; yy && i < n; i++)
        for (int q = 0; q < nresp; q++)
            yy[i * nresp + q] = y[q][i];
    int ok = yy && nresp > 1 && !an_manova_fit((int)n, k, x, nresp, yy, 1, &a, &err);
    free(yy);
    json ? printf(", \"manova\": {")
         : printf("\nMANOVA of the %d responses (Wilks' lambda, Rao's F)%s\n", nresp,
                  ok ? "" : ": none (needs 2 responses or more and residual df >= responses)");
    for (int t = 0; ok && t < a.nterm; t++) {
        char nm[300];
        if (a.fb[t] < 0)
            snprintf(nm, sizeof nm, "%s", fn[a.fa[t]]);
        else
            snprintf(nm, sizeof nm, "%s:%s", fn[a.fa[t]], fn[a.fb[t]]);
        if (json) {
            printf(t ? ", " : ""), cli_json_string(nm);
            printf(": {\"wilks\": "), jnum(a.wilks[t]);
            printf(", \"F\": "), jnum(a.F[t]);
            printf(", \"df1\": "), jnum(a.df1[t]);
            printf(", \"df2\": "), jnum(a.df2[t]);
            printf(", \"p\": "), jnum(a.p[t]), printf("}");
        } else {
            printf("  %-40.40s lambda %.4g  F %.4g (%g, %g)  p %.3g\n", nm, a.wilks[t], a.F[t],
                   a.df1[t], a.df2[t], a.p[t]);
        }
    }
    if (json) printf("}");
}

void study_analyze_more(long ncase, int k, const double *x, int nresp, double *const *y,
                        const char *const *fn, const char *const *rn, int factorial, int json)
{
    stepwise(ncase, k, x, nresp, y, fn, rn, json);
    quadratic(ncase, k, x, nresp, y, fn, rn, json);
    if (factorial) manova(ncase, k, x, nresp, y, fn, json);
}

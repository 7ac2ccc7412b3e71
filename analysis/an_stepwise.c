/* an_stepwise.c: stepwise selection of factors (an_stats.h) */
#include "analysis/an_stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* p of factor `which` in the regression of y on the factors in sel (plus `which`); NaN when
 * the fit fails */
static double p_in_model(int n, int k, const double *x, const double *y, const int *sel,
                         int which, double *xs)
{
    int cols[64], q = 0, pos = -1;
    for (int j = 0; j < k; j++)
        if (sel[j] || j == which) {
            if (j == which) pos = q;
            cols[q++] = j;
        }
    for (int i = 0; i < n; i++)
        for (int c = 0; c < q; c++)
            xs[(size_t)i * q + c] = x[(size_t)i * k + cols[c]];
    an_regression r;
    mcs_error err = {0};
    double p = NAN;
    if (an_regress(n, q, xs, y, &r, &err) == MCS_OK) p = r.p[pos + 1];
    an_regression_free(&r);
    return p;
}

mcs_status an_stepwise(int n, int k, const double *x, const double *y, double p_enter,
                       double p_remove, int *sel, int *order, int *nstep, mcs_error *err)
{
    if (k < 1 || k > 64 || !(p_enter <= p_remove))
        return MCS_ERR(err, MCS_ERR_USAGE, "error: stepwise needs 1..64 factors and "
                       "p_enter <= p_remove");
    double *xs = malloc(((size_t)n * k + 1) * sizeof *xs);
    if (!xs) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    memset(sel, 0, (size_t)k * sizeof *sel);
    *nstep = 0;
    for (int iter = 0; iter < 4 * k; iter++) {
        /* forward: the outside factor of smallest p, if below p_enter */
        int best = -1;
        double pb = p_enter;
        for (int j = 0; j < k; j++) {
            if (sel[j]) continue;
            double p = p_in_model(n, k, x, y, sel, j, xs);
            if (p < pb) pb = p, best = j;
        }
        if (best >= 0) sel[best] = 1, order[(*nstep)++] = best + 1;
        /* backward: the inside factor of largest p, if above p_remove */
        int worst = -1;
        double pw = p_remove;
        for (int j = 0; j < k; j++) {
            if (!sel[j]) continue;
            double p = p_in_model(n, k, x, y, sel, j, xs);
            if (p > pw) pw = p, worst = j;
        }
        if (worst >= 0) sel[worst] = 0, order[(*nstep)++] = -(worst + 1);
        if (best < 0 && worst < 0) break;
    }
    free(xs);
    return MCS_OK;
}

/* an_hic.c: head injury criterion, the exact maximum over all window pairs */
#include "analysis/an_criteria.h"

#include <math.h>
#include <stdlib.h>

/* (t2 - t1) * (I/(t2 - t1))^2.5 = I^2.5 / dt^1.5, without pow */
static double hic_of(double integral, double dt)
{
    if (!(integral > 0) || !(dt > 0)) return 0.0;
    return integral * integral * sqrt(integral) / (dt * sqrt(dt));
}

/* wmax[i] = max of a[i..j] over samples with t[j] - t[i] <= window (monotonic deque) */
static void window_max(const double *t, const double *a, int n, double window, double *wmax,
                       int *dq)
{
    int head = 0, tail = 0;
    for (int i = n - 1; i >= 0; i--) {
        /* deque: indices of the window ahead of i, a decreasing from head to tail */
        while (tail > head && a[dq[tail - 1]] <= a[i]) tail--;
        dq[tail++] = i;
        while (t[dq[head]] - t[i] > window * (1 + 1e-12)) head++;
        wmax[i] = a[dq[head]];
    }
}

mcs_status an_hic(const double *t, const double *a, int n, double window, an_hic_result *r,
                  mcs_error *err)
{
    r->hic = 0, r->t1 = r->t2 = n > 0 ? t[0] : 0;
    if (n < 2) return MCS_ERR(err, MCS_ERR_RANGE, "HIC: %d samples, need at least 2", n);
    if (!(window > 0)) return MCS_ERR(err, MCS_ERR_RANGE, "HIC: window %g s must be > 0", window);
    double *cum = malloc((size_t)n * sizeof(double));
    double *ag = malloc((size_t)n * sizeof(double));
    double *wmax = malloc((size_t)n * sizeof(double));
    int *dq = malloc((size_t)n * sizeof(int));
    if (!cum || !ag || !wmax || !dq) {
        free(cum), free(ag), free(wmax), free(dq);
        return MCS_ERR(err, MCS_ERR_NOMEM, "HIC: out of memory (%d samples)", n);
    }
    /* cumulative trapezoid integral of a in g [g*s] */
    cum[0] = 0;
    for (int i = 0; i < n; i++) ag[i] = a[i] / AN_G0;
    for (int i = 1; i < n; i++) cum[i] = cum[i - 1] + 0.5 * (ag[i] + ag[i - 1]) * (t[i] - t[i - 1]);
    /* pruning bound: a window starting at i has mean <= wmax[i], so
     * HIC <= (t2 - t1) wmax^2.5 <= window * wmax^2.5 */
    window_max(t, ag, n, window, wmax, dq);
    double best = 0;
    int bi = 0, bj = 0;
    for (int i = 0; i + 1 < n; i++) {
        double m = wmax[i];
        if (m <= 0 || window * m * m * sqrt(m) <= best) continue;
        for (int j = i + 1; j < n && t[j] - t[i] <= window * (1 + 1e-12); j++) {
            double h = hic_of(cum[j] - cum[i], t[j] - t[i]);
            if (h > best) best = h, bi = i, bj = j;
        }
    }
    r->hic = best;
    r->t1 = t[bi];
    r->t2 = t[bj];
    free(cum), free(ag), free(wmax), free(dq);
    return MCS_OK;
}

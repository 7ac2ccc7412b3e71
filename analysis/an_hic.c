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

/* best pair so far; ties go to the earlier t1, then the earlier t2 (deterministic) */
typedef struct {
    double best;
    int i, j;
} hic_best;

static void consider(hic_best *b, const double *t, const double *cum, int i, int j)
{
    double h = hic_of(cum[j] - cum[i], t[j] - t[i]);
    if (h > b->best || (h == b->best && h > 0 && (i < b->i || (i == b->i && j < b->j))))
        b->best = h, b->i = i, b->j = j;
}

/* every pair (i, j) of blocks bi <= bj of AN_HIC_BLOCK samples is bounded before its
 * samples are visited: with I <= max cum(bj) - min cum(bi) and t2 - t1 >= t(start bj) -
 * t(end bi), HIC <= I^2.5 / dt^1.5; and with a <= M over [start bi, end bi + W],
 * HIC <= min(W, t(end bj) - t(start bi)) M^2.5. A block pair whose bound does not beat the
 * best so far cannot hold the maximum, so the result is the exact all-pairs maximum. The
 * block starts are tried first for a good early best. */
#define AN_HIC_BLOCK 64

static void hic_search(const double *t, const double *cum, const double *wmax, int n, double w,
                       hic_best *b)
{
    int nb = (n + AN_HIC_BLOCK - 1) / AN_HIC_BLOCK;
    /* coarse pass: block starts */
    for (int p = 0; p < nb; p++)
        for (int q = p + 1; q < nb && t[q * AN_HIC_BLOCK] - t[p * AN_HIC_BLOCK] <= w; q++)
            consider(b, t, cum, p * AN_HIC_BLOCK, q * AN_HIC_BLOCK);
    for (int p = 0; p < nb; p++) {
        int s0 = p * AN_HIC_BLOCK, e0 = s0 + AN_HIC_BLOCK - 1 < n - 1 ? s0 + AN_HIC_BLOCK - 1 : n - 1;
        double cmin = cum[s0];
        for (int i = s0; i <= e0; i++) cmin = fmin(cmin, cum[i]);
        double m = fmax(wmax[s0], wmax[e0]);
        if (m <= 0) continue;
        double m25 = m * m * sqrt(m);
        for (int q = p; q < nb; q++) {
            int s1 = q * AN_HIC_BLOCK, e1 = s1 + AN_HIC_BLOCK - 1 < n - 1 ? s1 + AN_HIC_BLOCK - 1 : n - 1;
            double dlo = t[s1] - t[e0];
            if (dlo > w) break;
            double dhi = fmin(w, t[e1] - t[s0]);
            double bound = dhi * m25;
            if (bound <= b->best) continue;
            if (dlo > 0) {
                double cmax = cum[s1];
                for (int j = s1; j <= e1; j++) cmax = fmax(cmax, cum[j]);
                double iu = cmax - cmin;
                if (iu <= 0) continue;
                bound = fmin(bound, iu * iu * sqrt(iu) / (dlo * sqrt(dlo)));
                if (bound <= b->best) continue;
            }
            for (int i = s0; i <= e0; i++)
                for (int j = (s1 > i + 1 ? s1 : i + 1); j <= e1 && t[j] - t[i] <= w; j++)
                    consider(b, t, cum, i, j);
        }
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
    window_max(t, ag, n, window, wmax, dq);
    hic_best b = {0};
    hic_search(t, cum, wmax, n, window * (1 + 1e-12), &b);
    double best = b.best;
    int bi = b.i, bj = b.j;
    r->hic = best;
    r->t1 = t[bi];
    r->t2 = t[bj];
    free(cum), free(ag), free(wmax), free(dq);
    return MCS_OK;
}

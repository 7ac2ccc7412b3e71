/* an_iso18571.c: ISO/TS 18571 objective rating (REFERENCES.md "Objective rating").
 *
 * Choices where the text leaves room (documented here and in the report):
 * - Corridor Z is computed on the unshifted pair over the whole common span.
 * - Phase: Pearson correlation of the overlapping samples only (ref[i] with cmp[i + n]); shifts
 *   |n| <= floor(0.2 N); the smallest |n| wins ties (+n is tried before -n); E_P uses 0.2 N
 *   (not floored): E_P = ((0.2 N - |n|)/(0.2 N))^k_p, 0 from |n| >= 0.2 N on.
 * - Magnitude and slope use the phase-shifted pair, which keeps only the overlapping N - |n|
 *   samples (no padding, no wrap-around): the part of each signal shifted out is dropped.
 * - DTW: steps (1,0), (0,1), (1,1), cost (c_i - r_j)^2, band |i - j| <= ceil(0.1 M) - 1 on
 *   the shifted length M, as the TU Graz / OpenVT ISO18571 code (a Sakoe-Chiba window of
 *   size ceil(0.1 M) - 1) and the yeonsoo-p/ISO18571 scorer (|i - j| < ceil(0.1 M)); it
 *   differs from floor(0.1 M) when 0.1 M is whole (M = 1500: 149, not 150). Ties prefer the
 *   diagonal, then (i-1, j), then (i, j-1) (only exact cost ties are affected).
 * - Slope: derivatives by central differences with one-sided differences at the two ends, a
 *   9-point centred moving average whose window shrinks symmetrically (1, 3, 5, 7 points) at
 *   the ends; E_S = (2 - e)/2 clipped to [0, 1].
 */
#include "analysis/an_iso18571.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/an_resample.h"

an_iso_opts an_iso_opts_default(void)
{
    an_iso_opts o = {
        .sample_rate = 10000.0,
        .a0 = 0.05,
        .b0 = 0.5,
        .k_z = 2.0,
        .max_shift = 0.2,
        .k_p = 1.0,
        .eps_m = 0.5,
        .k_m = 1.0,
        .band = 0.1,
        .eps_s = 2.0,
        .smooth = 9,
        .w_z = 0.4,
        .w_p = 0.2,
        .w_m = 0.2,
        .w_s = 0.2,
    };
    return o;
}

const char *an_iso_grade(double rating)
{
    if (rating > 0.94) return "excellent";
    if (rating > 0.80) return "good";
    if (rating > 0.58) return "fair";
    return "poor";
}

double an_iso_corridor(const double *ref, const double *cmp, int n, double a0, double b0,
                       double k)
{
    double rmax = 0;
    for (int i = 0; i < n; i++) rmax = fmax(rmax, fabs(ref[i]));
    double inner = a0 * rmax, outer = b0 * rmax, sum = 0;
    for (int i = 0; i < n; i++) {
        double d = fabs(cmp[i] - ref[i]);
        if (d <= inner)
            sum += 1.0;
        else if (d < outer)
            sum += pow((outer - d) / (outer - inner), k);
    }
    return n > 0 ? sum / n : 0.0;
}

double an_pearson(const double *x, const double *y, int n)
{
    if (n < 2) return 0.0;
    double mx = 0, my = 0;
    for (int i = 0; i < n; i++) {
        mx += x[i];
        my += y[i];
    }
    mx /= n;
    my /= n;
    double sxy = 0, sxx = 0, syy = 0;
    for (int i = 0; i < n; i++) {
        double dx = x[i] - mx, dy = y[i] - my;
        sxy += dx * dy;
        sxx += dx * dx;
        syy += dy * dy;
    }
    if (!(sxx > 0) || !(syy > 0)) return 0.0;
    double rho = sxy / sqrt(sxx * syy);
    return fmax(-1.0, fmin(1.0, rho));
}

/* correlation of ref[i] with cmp[i + s] over the overlap */
static double shifted_pearson(const double *ref, const double *cmp, int n, int s)
{
    if (s >= 0) return an_pearson(ref, cmp + s, n - s);
    return an_pearson(ref - s, cmp, n + s);
}

int an_iso_phase_shift(const double *ref, const double *cmp, int n, int max_shift, double *rho)
{
    if (max_shift > n - 2) max_shift = n - 2;
    int best = 0;
    double best_rho = shifted_pearson(ref, cmp, n, 0);
    /* strictly better by more than rounding, so equal correlations keep the smaller shift */
    for (int m = 1; m <= max_shift; m++) {
        for (int sgn = 1; sgn >= -1; sgn -= 2) {
            double c = shifted_pearson(ref, cmp, n, sgn * m);
            if (c > best_rho + 1e-12) {
                best_rho = c;
                best = sgn * m;
            }
        }
    }
    if (rho) *rho = best_rho;
    return best;
}

/* direction codes of the DTW back-pointers */
enum { DTW_DIAG = 0, DTW_UP = 1, DTW_LEFT = 2 };

mcs_status an_dtw_error(const double *c, const double *r, int m, int w, double *e,
                        int *path_len, mcs_error *err)
{
    if (m < 1) return MCS_ERR(err, MCS_ERR_RANGE, "DTW: empty signals");
    if (w < 0) w = 0;
    if (w > m - 1) w = m - 1;
    int width = 2 * w + 1;
    size_t cells = (size_t)m * (size_t)width;
    if (cells > ((size_t)1 << 31))
        return MCS_ERR(err, MCS_ERR_NOMEM,
                       "DTW: %d samples with a band of %d need %zu MB of back-pointers; "
                       "shorten the signals or lower the sample rate",
                       m, w, cells >> 20);
    uint8_t *dir = malloc(cells);
    double *prev = malloc((size_t)width * sizeof(double));
    double *cur = malloc((size_t)width * sizeof(double));
    if (!dir || !prev || !cur) {
        free(dir);
        free(prev);
        free(cur);
        return MCS_ERR(err, MCS_ERR_NOMEM, "DTW: %zu cells", cells);
    }
    /* row i holds columns j = i - w .. i + w at offsets o = j - i + w */
    for (int i = 0; i < m; i++) {
        for (int o = 0; o < width; o++) {
            int j = i - w + o;
            cur[o] = INFINITY;
            dir[(size_t)i * width + o] = DTW_DIAG;
            if (j < 0 || j >= m) continue;
            double d = (c[i] - r[j]) * (c[i] - r[j]);
            if (i == 0 && j == 0) {
                cur[o] = d;
                continue;
            }
            double best = INFINITY;
            uint8_t how = DTW_DIAG;
            if (i > 0 && j > 0) best = prev[o];                 /* (i-1, j-1) */
            if (i > 0 && o + 1 < width && prev[o + 1] < best) { /* (i-1, j) */
                best = prev[o + 1];
                how = DTW_UP;
            }
            if (j > 0 && o > 0 && cur[o - 1] < best) { /* (i, j-1) */
                best = cur[o - 1];
                how = DTW_LEFT;
            }
            cur[o] = d + best;
            dir[(size_t)i * width + o] = how;
        }
        double *tmp = prev;
        prev = cur;
        cur = tmp;
    }
    /* walk back from (m-1, m-1) to (0, 0) summing the L1 norms along the path */
    int i = m - 1, j = m - 1, len = 0;
    double num = 0, den = 0;
    for (;;) {
        num += fabs(c[i] - r[j]);
        den += fabs(r[j]);
        len++;
        if (i == 0 && j == 0) break;
        uint8_t how = dir[(size_t)i * width + (j - i + w)];
        if (i == 0)
            how = DTW_LEFT;
        else if (j == 0)
            how = DTW_UP;
        if (how == DTW_DIAG) {
            i--;
            j--;
        } else if (how == DTW_UP) {
            i--;
        } else {
            j--;
        }
    }
    free(dir);
    free(prev);
    free(cur);
    if (path_len) *path_len = len;
    if (!(den > 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "magnitude rating undefined: the phase-shifted reference is zero");
    *e = num / den;
    return MCS_OK;
}

void an_iso_derivative(const double *y, int n, double dt, int len, double *dy)
{
    if (n < 2) {
        if (n == 1) dy[0] = 0;
        return;
    }
    double *d = malloc((size_t)n * sizeof(double));
    double *p = malloc((size_t)(n + 1) * sizeof(double));
    if (!d || !p) { /* tiny buffers; fall back to the unsmoothed derivative in place */
        free(d);
        free(p);
        dy[0] = (y[1] - y[0]) / dt;
        dy[n - 1] = (y[n - 1] - y[n - 2]) / dt;
        for (int i = 1; i < n - 1; i++) dy[i] = (y[i + 1] - y[i - 1]) / (2 * dt);
        return;
    }
    d[0] = (y[1] - y[0]) / dt;
    d[n - 1] = (y[n - 1] - y[n - 2]) / dt;
    for (int i = 1; i < n - 1; i++) d[i] = (y[i + 1] - y[i - 1]) / (2 * dt);
    /* centred moving average from prefix sums; half-width shrinks to fit at the ends */
    p[0] = 0;
    for (int i = 0; i < n; i++) p[i + 1] = p[i] + d[i];
    int h = len / 2;
    for (int i = 0; i < n; i++) {
        int k = h;
        if (i < k) k = i;
        if (n - 1 - i < k) k = n - 1 - i;
        dy[i] = (p[i + k + 1] - p[i - k]) / (2 * k + 1);
    }
    free(d);
    free(p);
}

static mcs_status check_opts(const an_iso_opts *o, mcs_error *err)
{
    if (!(o->a0 >= 0 && o->b0 > o->a0))
        return MCS_ERR(err, MCS_ERR_RANGE, "ISO 18571: need 0 <= a0 < b0 (a0 %g, b0 %g)", o->a0,
                       o->b0);
    if (!(o->max_shift > 0 && o->max_shift < 1) || !(o->band >= 0 && o->band <= 1))
        return MCS_ERR(err, MCS_ERR_RANGE, "ISO 18571: max_shift in (0,1), band in [0,1]");
    if (!(o->eps_m > 0) || !(o->eps_s > 0) || o->smooth < 1 || o->smooth % 2 == 0)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "ISO 18571: eps_m, eps_s > 0 and an odd smoothing length >= 1");
    double wsum = o->w_z + o->w_p + o->w_m + o->w_s;
    if (!(fabs(wsum - 1.0) < 1e-9))
        return MCS_ERR(err, MCS_ERR_RANGE, "ISO 18571: weights sum to %g, must be 1", wsum);
    return MCS_OK;
}

/* E = ((lim - e)/lim)^k for 0 <= e < lim, 1 at e = 0, 0 from lim on */
static double score_of_error(double e, double lim, double k)
{
    if (e <= 0) return 1.0;
    if (e >= lim) return 0.0;
    return pow((lim - e) / lim, k);
}

/* slope error e_S of the shifted pair (m samples) */
static mcs_status slope_error(const double *r, const double *c, int m, double dt, int len,
                              double *e, mcs_error *err)
{
    double *dr = malloc((size_t)m * sizeof(double));
    double *dc = malloc((size_t)m * sizeof(double));
    if (!dr || !dc) {
        free(dr);
        free(dc);
        return MCS_ERR(err, MCS_ERR_NOMEM, "slope rating: %d samples", m);
    }
    an_iso_derivative(r, m, dt, len, dr);
    an_iso_derivative(c, m, dt, len, dc);
    double num = 0, den = 0;
    for (int i = 0; i < m; i++) {
        num += fabs(dc[i] - dr[i]);
        den += fabs(dr[i]);
    }
    free(dr);
    free(dc);
    if (!(den > 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "slope rating undefined: the phase-shifted reference is constant");
    *e = num / den;
    return MCS_OK;
}

mcs_status an_iso18571_arrays(const double *ref, const double *cmp, int n, double dt,
                              const an_iso_opts *o, an_iso_result *r, mcs_error *err)
{
    memset(r, 0, sizeof *r);
    an_iso_opts def = an_iso_opts_default();
    if (!o) o = &def;
    mcs_status st = check_opts(o, err);
    if (st) return st;
    if (n < 10)
        return MCS_ERR(err, MCS_ERR_RANGE, "ISO 18571: needs at least 10 samples, got %d", n);
    if (!(dt > 0) || !isfinite(dt))
        return MCS_ERR(err, MCS_ERR_RANGE, "ISO 18571: sample interval must be > 0");
    double rmin = INFINITY, rmax = -INFINITY;
    for (int i = 0; i < n; i++) {
        if (!isfinite(ref[i]) || !isfinite(cmp[i]))
            return MCS_ERR(err, MCS_ERR_RANGE, "ISO 18571: sample %d is not a finite number",
                           i + 1);
        rmin = fmin(rmin, ref[i]);
        rmax = fmax(rmax, ref[i]);
    }
    if (rmin == 0 && rmax == 0)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "ISO 18571: the reference is zero everywhere; the corridors (a fraction "
                       "of max|reference|) have no width");
    if (rmin == rmax)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "ISO 18571: the reference is constant (%g); phase and slope ratings are "
                       "undefined",
                       rmin);
    r->n = n;
    r->dt = dt;

    /* corridor: unshifted pair, whole span */
    r->corridor = an_iso_corridor(ref, cmp, n, o->a0, o->b0, o->k_z);

    /* phase: best Pearson shift within max_shift N */
    double lim = o->max_shift * n;
    int s = an_iso_phase_shift(ref, cmp, n, (int)floor(lim), &r->rho);
    r->shift = s;
    r->shift_time = s * dt;
    r->phase = score_of_error(abs(s), lim, o->k_p);

    /* the shifted pair keeps the overlap: ref[i] with cmp[i + s] */
    int m = n - abs(s);
    const double *rs = s >= 0 ? ref : ref - s;
    const double *cs = s >= 0 ? cmp + s : cmp;

    /* magnitude: DTW of the shifted pair, |i - j| <= ceil(band m) - 1 */
    int w = (int)ceil(o->band * m) - 1;
    st = an_dtw_error(cs, rs, m, w < 0 ? 0 : w, &r->mag_error, &r->n_warp, err);
    if (st) return st;
    r->magnitude = score_of_error(r->mag_error, o->eps_m, o->k_m);

    /* slope: smoothed derivatives of the shifted pair */
    st = slope_error(rs, cs, m, dt, o->smooth, &r->slope_error, err);
    if (st) return st;
    r->slope = fmax(0.0, fmin(1.0, (o->eps_s - r->slope_error) / o->eps_s));

    r->rating = o->w_z * r->corridor + o->w_p * r->phase + o->w_m * r->magnitude +
                o->w_s * r->slope;
    return MCS_OK;
}

mcs_status an_iso18571(const an_signal *ref, const an_signal *cmp, const an_iso_opts *o,
                       an_iso_result *r, mcs_error *err)
{
    an_iso_opts def = an_iso_opts_default();
    if (!o) o = &def;
    an_pair p;
    mcs_status st = an_resample_pair(ref->t, ref->y, ref->n, cmp->t, cmp->y, cmp->n,
                                     o->sample_rate, 10, &p, err);
    if (st) return st;
    st = an_iso18571_arrays(p.ref, p.cmp, p.n, p.dt, o, r, err);
    r->t0 = p.t0;
    an_pair_free(&p);
    return st;
}

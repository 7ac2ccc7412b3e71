/* tests for analysis/an_resample and analysis/an_iso18571: each expected value is derived by
 * hand in the comment above its check (ISO/TS 18571 as in REFERENCES.md "Objective rating"). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/an_iso18571.h"
#include "analysis/an_resample.h"
#include "tests/harness.h"

#define PI 3.14159265358979323846

/* half-sine pulse of amplitude amp on samples a..b, zero elsewhere */
static void half_sine(double *y, int n, int a, int b, double amp)
{
    for (int i = 0; i < n; i++)
        y[i] = (i >= a && i <= b) ? amp * sin(PI * (i - a) / (b - a)) : 0.0;
}

static void test_resample_linear(void)
{
    /* a straight line is reproduced exactly by linear interpolation; the grid starts at the
     * later start 0.02 s and ends at the earlier end 0.1 s: 0.08 s * 10 kHz + 1 = 801 samples */
    double t1[50], y1[50], t2[40], y2[40];
    for (int i = 0; i < 50; i++) {
        t1[i] = 0.1 * i / 49.0 + (i > 0 && i < 49 ? 0.0007 * sin(i) : 0.0); /* irregular */
        y1[i] = 3.0 * t1[i] + 1.0;
    }
    for (int i = 0; i < 40; i++) {
        t2[i] = 0.02 + 0.13 * i / 39.0;
        y2[i] = -2.0 * t2[i];
    }
    an_pair p;
    mcs_error err = {0};
    CHECK(an_resample_pair(t1, y1, 50, t2, y2, 40, 10000.0, 10, &p, &err) == MCS_OK);
    CHECK(p.n == 801);
    CHECK_NEAR(p.t0, 0.02, 1e-15);
    CHECK_NEAR(p.dt, 1e-4, 1e-18);
    double worst = 0;
    for (int k = 0; k < p.n; k++) {
        double t = p.t0 + k * p.dt;
        worst = fmax(worst, fabs(p.ref[k] - (3.0 * t + 1.0)));
        worst = fmax(worst, fabs(p.cmp[k] + 2.0 * t));
    }
    CHECK_NEAR(worst, 0.0, 1e-12);
    an_pair_free(&p);
    CHECK(p.ref == NULL && p.n == 0);
}

static void test_resample_errors(void)
{
    double t1[3] = {0, 1, 2}, y1[3] = {0, 1, 2};
    double t2[3] = {3, 4, 5}, y2[3] = {0, 1, 2};
    double tb[3] = {0, 2, 1}, yn[3] = {0, NAN, 1};
    an_pair p;
    mcs_error err = {0};
    CHECK(an_resample_pair(t1, y1, 3, t2, y2, 3, 10.0, 2, &p, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "do not overlap");
    mcs_error_clear(&err);
    CHECK(an_resample_pair(t1, y1, 3, tb, y1, 3, 10.0, 2, &p, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "not strictly increasing");
    mcs_error_clear(&err);
    CHECK(an_resample_pair(t1, y1, 3, t1, yn, 3, 10.0, 2, &p, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "not a finite number");
    mcs_error_clear(&err);
    CHECK(an_resample_pair(t1, y1, 3, t1, y1, 3, 0.0, 2, &p, &err) == MCS_ERR_RANGE);
    mcs_error_clear(&err);
    /* span 2 s at 1 Hz = 3 samples < 10 required */
    CHECK(an_resample_pair(t1, y1, 3, t1, y1, 3, 1.0, 10, &p, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "only 3 samples");
    CHECK(p.ref == NULL && p.cmp == NULL);
}

static void test_identical_curves(void)
{
    /* c = r: every difference is 0, so Z = 1, the best shift is 0 (rho = 1), the DTW path is the
     * diagonal with zero cost (e_M = 0), and the derivatives agree (e_S = 0): R = 1 */
    enum { N = 1501 };
    static double r[N];
    half_sine(r, N, 200, 1100, 50.0);
    an_iso_result res;
    mcs_error err = {0};
    CHECK(an_iso18571_arrays(r, r, N, 1e-4, NULL, &res, &err) == MCS_OK);
    CHECK_NEAR(res.corridor, 1.0, 0);
    CHECK_NEAR(res.phase, 1.0, 0);
    CHECK_NEAR(res.magnitude, 1.0, 0);
    CHECK_NEAR(res.slope, 1.0, 0);
    CHECK_NEAR(res.rating, 1.0, 1e-15);
    CHECK(res.shift == 0);
    CHECK_NEAR(res.rho, 1.0, 1e-12);
    CHECK(res.n_warp == N);
    CHECK(strcmp(an_iso_grade(res.rating), "excellent") == 0);
}

static void test_corridor_scaled_half_sine(void)
{
    /* r = A sin(theta), theta = pi i/(N-1), c = 1.4 r: |d| = 0.4 A sin(theta).
     * inner 0.05 A: score 1 where sin(theta) < 0.125, i.e. theta < th0 = asin(0.125) (and the
     * mirror); outer 0.5 A is never reached. Elsewhere ((0.5 - 0.4 s)/0.45)^2, s = sin(theta).
     * Z = (1/pi) [2 th0 + (2/0.2025) int_th0^(pi/2) (0.25 - 0.4 s + 0.16 s^2) dtheta]
     *   = (1/pi) [2 th0 + (2/0.2025)(0.25 (pi/2 - th0) - 0.4 cos th0
     *                                 + 0.16 (pi/4 - th0/2 + sin(2 th0)/4))].
     * The mean over the N samples (both ends included, score 1 there) is
     * ((N - 1) T + 1)/N = T + (1 - T)/N with T the trapezoid rule, which matches the integral
     * mean Z to O(h^2) = 2.5e-6 times max|f''|/12 (h = pi/(N - 1)): tolerance 1e-6. */
    enum { N = 2001 };
    static double r[N], c[N];
    for (int i = 0; i < N; i++) {
        r[i] = 7.0 * sin(PI * i / (N - 1));
        c[i] = 1.4 * r[i];
    }
    double th0 = asin(0.125);
    double integral = 0.25 * (PI / 2 - th0) - 0.4 * cos(th0) +
                      0.16 * (PI / 4 - th0 / 2 + sin(2 * th0) / 4);
    double z = (2 * th0 + 2.0 / 0.2025 * integral) / PI;
    z += (1 - z) / N;
    CHECK_NEAR(an_iso_corridor(r, c, N, 0.05, 0.5, 2.0), z, 1e-6);
    /* the same pair mirrored (c = 0.6 r, |d| = 0.4 A sin) gives the same score: symmetric */
    for (int i = 0; i < N; i++) c[i] = 0.6 * r[i];
    CHECK_NEAR(an_iso_corridor(r, c, N, 0.05, 0.5, 2.0), z, 1e-6);
    /* the comparison shifted by a constant beyond the outer corridor (0.6 A) scores 0 */
    for (int i = 0; i < N; i++) c[i] = r[i] + 0.6 * 7.0;
    CHECK_NEAR(an_iso_corridor(r, c, N, 0.05, 0.5, 2.0), 0.0, 0);
}

/* rectangular pulse: amp on samples a..b-1, zero elsewhere */
static void square(double *y, int n, int a, int b, double amp)
{
    for (int i = 0; i < n; i++) y[i] = (i >= a && i < b) ? amp : 0.0;
}

static void check_scaled_square(double s)
{
    /* r: rectangle of height A on p = 400 of N = 1000 samples; c = s r.
     * phase: Pearson is scale-invariant, rho(0) = 1 and every other shift is lower -> n = 0,
     *   E_P = 1.
     * magnitude: each plateau c_i = sA costs at least (s-1)^2 A^2 (paired with r_j = A; with
     *   r_j = 0 it costs s^2 A^2, more); the diagonal reaches that bound, and an optimal path
     *   can only add zero-cost (0,0) pairs, which change neither sum. So
     *   e_M = p |s-1| A / (p A) = |s-1| and E_M = (0.5 - |s-1|)/0.5 = 1 - 2|s-1|.
     * slope: derivatives are linear, c' = s r', e_S = |s-1| sum|r'| / sum|r'| = |s-1|,
     *   E_S = (2 - |s-1|)/2.
     * corridor: |d| = |s-1| A on the plateau, inside (0.05 A, 0.5 A) for the s used:
     *   score ((0.5 - |s-1|)/0.45)^2 there, 1 elsewhere: Z = (N - p + p q)/N. */
    enum { N = 1000, A0 = 300, B0 = 700 };
    static double r[N], c[N];
    const double amp = 12.0;
    square(r, N, A0, B0, amp);
    for (int i = 0; i < N; i++) c[i] = s * r[i];
    an_iso_result res;
    mcs_error err = {0};
    CHECK(an_iso18571_arrays(r, c, N, 1e-4, NULL, &res, &err) == MCS_OK);
    double d = fabs(s - 1), p = B0 - A0;
    double q = pow((0.5 - d) / 0.45, 2);
    double z = (N - p + p * q) / N;
    CHECK(res.shift == 0);
    CHECK_NEAR(res.phase, 1.0, 0);
    CHECK_NEAR(res.mag_error, d, 1e-12);
    CHECK_NEAR(res.magnitude, 1 - 2 * d, 1e-12);
    CHECK_NEAR(res.slope_error, d, 1e-12);
    CHECK_NEAR(res.slope, (2 - d) / 2, 1e-12);
    CHECK_NEAR(res.corridor, z, 1e-12);
    CHECK_NEAR(res.rating, 0.4 * z + 0.2 + 0.2 * (1 - 2 * d) + 0.2 * (2 - d) / 2, 1e-12);
}

static void test_scaled_square_pulse(void)
{
    check_scaled_square(1.2);
    check_scaled_square(0.85);
    check_scaled_square(1.3);
}

static void test_magnitude_beyond_limit(void)
{
    /* s = 1.7: e_M = 0.7 > 0.5 so E_M = 0 (clipped, never negative); |d| = 0.7 A > 0.5 A so the
     * plateau scores 0 in the corridor: Z = (N - p)/N = 0.6 */
    enum { N = 1000 };
    static double r[N], c[N];
    square(r, N, 300, 700, 1.0);
    for (int i = 0; i < N; i++) c[i] = 1.7 * r[i];
    an_iso_result res;
    mcs_error err = {0};
    CHECK(an_iso18571_arrays(r, c, N, 1e-4, NULL, &res, &err) == MCS_OK);
    CHECK_NEAR(res.mag_error, 0.7, 1e-12);
    CHECK_NEAR(res.magnitude, 0.0, 0);
    CHECK_NEAR(res.corridor, 0.6, 1e-12);
    CHECK_NEAR(res.slope, (2 - 0.7) / 2, 1e-12);
}

static void check_time_shift(int k)
{
    /* c[i] = r[i - k]: a pulse well inside the span, zero tails. On the overlap
     * ref[i] <-> cmp[i + k] the pair is identical, so rho(k) = 1 and n = k;
     * E_P = (0.2 N - |k|)/(0.2 N). The shifted pair is identical: e_M = 0 (diagonal path, zero
     * cost), e_S = 0, so E_M = E_S = 1. */
    enum { N = 1001 };
    static double r[N], c[N];
    half_sine(r, N, 350, 600, 3.0);
    half_sine(c, N, 350 + k, 600 + k, 3.0);
    an_iso_result res;
    mcs_error err = {0};
    CHECK(an_iso18571_arrays(r, c, N, 1e-4, NULL, &res, &err) == MCS_OK);
    CHECK(res.shift == k);
    CHECK_NEAR(res.shift_time, k * 1e-4, 1e-15);
    CHECK_NEAR(res.phase, (0.2 * N - abs(k)) / (0.2 * N), 1e-14);
    CHECK_NEAR(res.magnitude, 1.0, 1e-12);
    CHECK_NEAR(res.slope, 1.0, 1e-12);
    CHECK_NEAR(res.rho, 1.0, 1e-12);
}

static void test_time_shift(void)
{
    check_time_shift(37);
    check_time_shift(-37); /* symmetric: the same E_P for a lead as for a lag */
    check_time_shift(150);
    check_time_shift(1);
}

static void test_shift_beyond_limit(void)
{
    /* a shift of 250 samples > 0.2 N = 200 cannot be found; whatever shift wins, |n| <= 200 and
     * E_P = 0 exactly when it reaches 200 (never negative) */
    enum { N = 1000 };
    static double r[N], c[N];
    half_sine(r, N, 100, 300, 1.0);
    half_sine(c, N, 350, 550, 1.0);
    an_iso_result res;
    mcs_error err = {0};
    CHECK(an_iso18571_arrays(r, c, N, 1e-4, NULL, &res, &err) == MCS_OK);
    CHECK(abs(res.shift) <= 200);
    CHECK(res.phase >= 0 && res.phase <= 1);
    CHECK(res.rating >= 0 && res.rating <= 1);
}

static void test_constant_offset(void)
{
    /* c = r + C: derivatives identical, e_S = 0 -> E_S = 1. Pearson ignores the offset, so
     * n = 0 and E_P = 1. |d| = C = 0.1 max|r| everywhere: score ((0.5 - 0.1)/0.45)^2 = 64/81 at
     * every sample, Z = 64/81. */
    enum { N = 1200 };
    static double r[N], c[N];
    half_sine(r, N, 100, 1000, 20.0);
    for (int i = 0; i < N; i++) c[i] = r[i] + 2.0;
    an_iso_result res;
    mcs_error err = {0};
    CHECK(an_iso18571_arrays(r, c, N, 1e-4, NULL, &res, &err) == MCS_OK);
    CHECK(res.shift == 0);
    CHECK_NEAR(res.phase, 1.0, 0);
    CHECK_NEAR(res.slope, 1.0, 1e-12);
    CHECK_NEAR(res.corridor, 64.0 / 81.0, 1e-12);
    CHECK(res.magnitude > 0 && res.magnitude < 1);
}

/* independent DTW: full (m x m) cumulative cost matrix, same steps and band, then the L1 ratio
 * along the path found by walking back through the matrix (min of the three predecessors) */
static double dtw_full(const double *c, const double *r, int m, int w)
{
    double *D = malloc((size_t)m * m * sizeof(double));
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++) {
            double v = INFINITY;
            if (abs(i - j) <= w) {
                double d = (c[i] - r[j]) * (c[i] - r[j]);
                if (i == 0 && j == 0)
                    v = d;
                else {
                    double b = INFINITY;
                    if (i > 0 && j > 0) b = fmin(b, D[(i - 1) * m + j - 1]);
                    if (i > 0) b = fmin(b, D[(i - 1) * m + j]);
                    if (j > 0) b = fmin(b, D[i * m + j - 1]);
                    v = d + b;
                }
            }
            D[i * m + j] = v;
        }
    int i = m - 1, j = m - 1;
    double num = 0, den = 0;
    for (;;) {
        num += fabs(c[i] - r[j]);
        den += fabs(r[j]);
        if (i == 0 && j == 0) break;
        double dg = (i > 0 && j > 0) ? D[(i - 1) * m + j - 1] : INFINITY;
        double up = i > 0 ? D[(i - 1) * m + j] : INFINITY;
        double lf = j > 0 ? D[i * m + j - 1] : INFINITY;
        if (dg <= up && dg <= lf) {
            i--;
            j--;
        } else if (up <= lf)
            i--;
        else
            j--;
    }
    free(D);
    return num / den;
}

static void test_dtw_against_full_matrix(void)
{
    /* deterministic pseudo-random smooth signals; the banded O(m w) DTW must find the same
     * path error as the full-matrix one, for a narrow band, the 10 % band and no band */
    enum { M = 160 };
    double r[M], c[M];
    unsigned long s = 12345;
    double a = 0, b = 0;
    for (int i = 0; i < M; i++) {
        s = s * 6364136223846793005UL + 1442695040888963407UL;
        a = 0.8 * a + ((double)(s >> 33) / 2147483648.0 - 0.5);
        s = s * 6364136223846793005UL + 1442695040888963407UL;
        b = 0.8 * b + ((double)(s >> 33) / 2147483648.0 - 0.5);
        r[i] = sin(0.07 * i) + 0.3 * a;
        c[i] = 1.1 * sin(0.07 * i - 0.2) + 0.3 * b;
    }
    int widths[] = {3, M / 10, M - 1};
    for (int k = 0; k < 3; k++) {
        double e;
        int len;
        mcs_error err = {0};
        CHECK(an_dtw_error(c, r, M, widths[k], &e, &len, &err) == MCS_OK);
        CHECK_NEAR(e, dtw_full(c, r, M, widths[k]), 1e-12);
        CHECK(len >= M && len <= 2 * M - 1);
    }
    /* a zero reference has no magnitude error: clear error, no NaN */
    double z[M] = {0}, e = -1;
    mcs_error err = {0};
    CHECK(an_dtw_error(c, z, M, 16, &e, NULL, &err) == MCS_ERR_RANGE);
    CHECK(e == -1);
}

static void check_band(int n, double e_ref, int len_ref)
{
    /* r has a unit spike at 1, c the same spike at 2, on a common bump 2 4 6 4 2 (samples 3-7),
     * zeros after 9: sum|r| = 19. The best Pearson shift is 0 (rho 0.976 at N = 10, 0.977 at
     * 11; the bump outweighs the spike). The band is |i - j| <= ceil(0.1 M) - 1 (TU Graz /
     * OpenVT ISO18571 code: dtwalign SakoechibaWindow(size = ceil(0.1 M) - 1)).
     * M = 10: band 0, the diagonal: |c - r| = 1 at samples 1 and 2, e_M = 2/19.
     * M = 11: band 1: the path (0,0) (1,0) (2,1) (2,2) (3,3) ... pairs c's spike with r's and
     *   costs (c_2 - r_2)^2 = 1 (the diagonal costs 2), sum|c - r| = 1 over r's 0 0 1 0 2 4 6 4
     *   2 0 0 (sum 19): e_M = 1/19, 12 pairs. floor(0.1 M) would give band 1 at M = 10 too. */
    double r[11] = {0, 1, 0, 2, 4, 6, 4, 2, 0, 0, 0}, c[11] = {0, 0, 1, 2, 4, 6, 4, 2, 0, 0, 0};
    an_iso_result res;
    mcs_error err = {0};
    CHECK(an_iso18571_arrays(r, c, n, 1e-4, NULL, &res, &err) == MCS_OK);
    CHECK(res.shift == 0);
    CHECK_NEAR(res.mag_error, e_ref, 1e-15);
    CHECK_NEAR(res.magnitude, (0.5 - e_ref) / 0.5, 1e-15);
    CHECK(res.n_warp == len_ref);
}

static void test_dtw_band(void)
{
    check_band(10, 2.0 / 19.0, 10);
    check_band(11, 1.0 / 19.0, 12);
}

static void test_derivative(void)
{
    /* y = t^2, t_i = i dt: central differences are exact (2 t_i) inside; a centred average of a
     * linear sequence returns its centre value, so dy_i = 2 t_i wherever the 9-point window
     * stays off the two end differences (5 <= i <= n-6). The ends use one-sided differences,
     * d_0 = (dt^2 - 0)/dt = dt and d_(n-1) = 2 t_(n-1) - dt, and the window shrinks to 1 point
     * there: dy_0 = dt, dy_(n-1) = 2 t_(n-1) - dt. dy_1 averages d_0..d_2 = (dt + 2dt + 4dt)/3. */
    enum { N = 50 };
    double y[N], dy[N], dt = 0.01;
    for (int i = 0; i < N; i++) y[i] = (i * dt) * (i * dt);
    an_iso_derivative(y, N, dt, 9, dy);
    CHECK_NEAR(dy[0], dt, 1e-12);
    CHECK_NEAR(dy[1], 7 * dt / 3, 1e-12);
    CHECK_NEAR(dy[N - 1], 2 * (N - 1) * dt - dt, 1e-12);
    double worst = 0;
    for (int i = 5; i <= N - 6; i++) worst = fmax(worst, fabs(dy[i] - 2 * i * dt));
    CHECK_NEAR(worst, 0.0, 1e-12);
}

static void test_bad_input(void)
{
    /* zero and constant references and non-finite samples are clear errors; the result stays
     * zeroed (no NaN) */
    enum { N = 100 };
    double z[N] = {0}, k[N], c[N];
    for (int i = 0; i < N; i++) {
        k[i] = 5.0;
        c[i] = sin(0.1 * i);
    }
    an_iso_result res;
    mcs_error err = {0};
    CHECK(an_iso18571_arrays(z, c, N, 1e-4, NULL, &res, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "zero everywhere");
    CHECK(res.rating == 0 && !isnan(res.corridor));
    mcs_error_clear(&err);
    CHECK(an_iso18571_arrays(k, c, N, 1e-4, NULL, &res, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "constant");
    mcs_error_clear(&err);
    c[7] = NAN;
    CHECK(an_iso18571_arrays(k, c, N, 1e-4, NULL, &res, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "sample 8");
    mcs_error_clear(&err);
    CHECK(an_iso18571_arrays(k, c, 5, 1e-4, NULL, &res, &err) == MCS_ERR_RANGE);
    mcs_error_clear(&err);
    an_iso_opts o = an_iso_opts_default();
    o.w_z = 0.5;
    c[7] = 0;
    CHECK(an_iso18571_arrays(c, c, N, 1e-4, &o, &res, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "weights");
    /* a constant comparison is allowed: zero variance gives rho = 0 at every shift, n = 0 */
    mcs_error_clear(&err);
    CHECK(an_iso18571_arrays(c, k, N, 1e-4, NULL, &res, &err) == MCS_OK);
    CHECK(res.shift == 0 && res.rho == 0);
    CHECK(isfinite(res.rating));
}

static void test_grades(void)
{
    /* ISO/TS 18571 grades: excellent R > 0.94, good > 0.80, fair > 0.58, poor <= 0.58 */
    CHECK(strcmp(an_iso_grade(0.95), "excellent") == 0);
    CHECK(strcmp(an_iso_grade(0.94), "good") == 0);
    CHECK(strcmp(an_iso_grade(0.81), "good") == 0);
    CHECK(strcmp(an_iso_grade(0.80), "fair") == 0);
    CHECK(strcmp(an_iso_grade(0.59), "fair") == 0);
    CHECK(strcmp(an_iso_grade(0.58), "poor") == 0);
    CHECK(strcmp(an_iso_grade(0.0), "poor") == 0);
}

static void test_signals_resampled(void)
{
    /* the same half-sine pulse sampled at 20 kHz on 0..0.1 s and at 8 kHz on 0.01..0.12 s:
     * compared over 0.01..0.1 s at 10 kHz = 901 samples. Linear interpolation of
     * sin at 8 kHz errs by at most (dt^2/8) max|y''| = (1.25e-4^2/8)(pi/0.06)^2 A = 5e-6 A
     * (both grids have nodes at the pulse ends 0.02 and 0.08 s) and its slope by at most
     * (dt/2) max|y''| = 0.17 A/s. Over 0.09 s, mean|y| = (2/pi)(0.06/0.09) A = 0.42 A and
     * mean|y'| = 2A/0.09 s = 22 A/s: e_M <= 1.2e-5, e_S <= 7.7e-3, so
     * R >= 1 - 0.2 (2 e_M) - 0.2 (e_S/2) = 1 - 7.8e-4. */
    enum { N1 = 2001, N2 = 881 };
    static double t1[N1], y1[N1], t2[N2], y2[N2];
    for (int i = 0; i < N1; i++) {
        t1[i] = i * 5e-5;
        y1[i] = (t1[i] > 0.02 && t1[i] < 0.08) ? 100 * sin(PI * (t1[i] - 0.02) / 0.06) : 0;
    }
    for (int i = 0; i < N2; i++) {
        t2[i] = 0.01 + i * 1.25e-4;
        y2[i] = (t2[i] > 0.02 && t2[i] < 0.08) ? 100 * sin(PI * (t2[i] - 0.02) / 0.06) : 0;
    }
    an_signal a = {.name = "ref", .n = N1, .t = t1, .y = y1};
    an_signal b = {.name = "cmp", .n = N2, .t = t2, .y = y2};
    an_iso_result res;
    mcs_error err = {0};
    CHECK(an_iso18571(&a, &b, NULL, &res, &err) == MCS_OK);
    CHECK(res.n == 901);
    CHECK_NEAR(res.t0, 0.01, 1e-15);
    CHECK(res.shift == 0);
    CHECK_NEAR(res.corridor, 1.0, 1e-12);
    CHECK(res.rating > 1 - 7.8e-4);
}

int main(void)
{
    RUN(test_resample_linear);
    RUN(test_resample_errors);
    RUN(test_identical_curves);
    RUN(test_corridor_scaled_half_sine);
    RUN(test_scaled_square_pulse);
    RUN(test_magnitude_beyond_limit);
    RUN(test_time_shift);
    RUN(test_shift_beyond_limit);
    RUN(test_constant_offset);
    RUN(test_dtw_against_full_matrix);
    RUN(test_dtw_band);
    RUN(test_derivative);
    RUN(test_bad_input);
    RUN(test_grades);
    RUN(test_signals_resampled);
    TEST_END();
}

/* tests for analysis/an_cora: each expected value is derived by hand in the comment above it
 * (CORA as read in analysis/an_cora.c, CORAplus 4.0.x defaults). */
#include <math.h>
#include <string.h>

#include "analysis/an_cora.h"
#include "tests/harness.h"
#include "tests/figures.h"

#define PI 3.14159265358979323846
enum { N = 1000 };
static const double DT = 1e-4;

static void square(double *y, int a, int b, double amp)
{
    for (int i = 0; i < N; i++) y[i] = (i >= a && i < b) ? amp : 0.0;
}

static void half_sine(double *y, int a, int b, double amp)
{
    for (int i = 0; i < N; i++)
        y[i] = (i >= a && i <= b) ? amp * sin(PI * (i - a) / (b - a)) : 0.0;
}

/* square pulse on 300..699: t_a = 300 dt (first |r| >= 3 %), t_b = 699 dt (last >= 7.5 %),
 * t_b - t_a = 399 dt; start 300 - 0.01*399 = 296.01 -> first sample 297; end
 * 699 + 0.2*399 = 778.8 -> last sample 778: 482 samples, T = 481 dt */
static void test_interval_square(void)
{
    static double r[N];
    square(r, 300, 700, 5.0);
    an_cora_opts o = an_cora_opts_default();
    int i0, i1;
    mcs_error err = {0};
    CHECK(an_cora_interval(r, N, 0.0, DT, &o, &i0, &i1, &err) == MCS_OK);
    CHECK(i0 == 297 && i1 == 778);
    /* explicit limits override: 0.02..0.09 s -> samples 200..900 */
    o.t_min = 0.02;
    o.t_max = 0.09;
    CHECK(an_cora_interval(r, N, 0.0, DT, &o, &i0, &i1, &err) == MCS_OK);
    CHECK(i0 == 200 && i1 == 900);
}

static void test_interval_half_sine(void)
{
    /* r = sin(pi j/200), j = i - 300 on 0..200: |r| >= 0.03 first at j_a = ceil(200 asin(0.03)/pi)
     * = ceil(1.910) = 2; >= 0.075 last at j_b = floor(200 - 200 asin(0.075)/pi) = floor(195.22)
     * = 195. Start 302 - 0.01*193 = 300.07 -> 301; end 495 + 0.2*193 = 533.6 -> 533. */
    static double r[N];
    half_sine(r, 300, 500, -8.0); /* the sign does not matter: thresholds act on |r| */
    int ja = (int)ceil(200 * asin(0.03) / PI), jb = (int)floor(200 - 200 * asin(0.075) / PI);
    CHECK(ja == 2 && jb == 195);
    an_cora_opts o = an_cora_opts_default();
    int i0, i1;
    mcs_error err = {0};
    CHECK(an_cora_interval(r, N, 0.0, DT, &o, &i0, &i1, &err) == MCS_OK);
    CHECK(i0 == 301 && i1 == 533);
}

static void test_identical(void)
{
    /* c = r: Z = 1; K(0) = 1 so shift 0, E_P = 1; energies equal, E_G = 1; E_V = ((1+1)/2)^10 = 1 */
    static double r[N];
    half_sine(r, 200, 800, 3.0);
    an_cora_result res;
    mcs_error err = {0};
    CHECK(an_cora_arrays(r, r, N, 0.0, DT, NULL, &res, &err) == MCS_OK);
    CHECK_NEAR(res.corridor, 1.0, 0);
    CHECK_NEAR(res.phase, 1.0, 0);
    CHECK_NEAR(res.size, 1.0, 1e-15);
    CHECK_NEAR(res.progression, 1.0, 1e-12);
    CHECK_NEAR(res.rating, 1.0, 1e-12);
    CHECK(res.shift == 0);
}

static void check_scaled(double s)
{
    /* c = s r, r a square pulse of height A on p = 400 samples of the 482-sample interval
     * (test_interval_square). K is scale-invariant: K(0) = 1, shift 0, E_P = 1, E_V = 1.
     * Size: Ec/Er = s^2, E_G = min(s^2, 1/s^2).
     * Corridor: |d| = |s-1| A on the plateau, q = ((0.5 - |s-1|)/0.45)^2 there, 1 on the other 82
     * samples: Z = (82 + 400 q)/482. CORA = 0.5 Z + 0.5 (0.5 + 0.25 E_G + 0.25). */
    static double r[N], c[N];
    square(r, 300, 700, 2.0);
    for (int i = 0; i < N; i++) c[i] = s * r[i];
    an_cora_result res;
    mcs_error err = {0};
    CHECK(an_cora_arrays(r, c, N, 0.0, DT, NULL, &res, &err) == MCS_OK);
    double eg = s < 1 ? s * s : 1 / (s * s);
    double d = fabs(s - 1), q = pow((0.5 - d) / 0.45, 2), z = (82 + 400 * q) / 482;
    CHECK(res.i_start == 297 && res.i_end == 778);
    CHECK(res.shift == 0);
    CHECK_NEAR(res.phase, 1.0, 0);
    CHECK_NEAR(res.progression, 1.0, 1e-12);
    CHECK_NEAR(res.size, eg, 1e-12);
    CHECK_NEAR(res.corridor, z, 1e-12);
    CHECK_NEAR(res.rating, 0.5 * z + 0.5 * (0.5 + 0.25 * eg + 0.25), 1e-12);
}

static void test_scaled(void)
{
    check_scaled(1.25);
    check_scaled(0.8); /* symmetric: 0.8 = 1/1.25 gives the same size rating 0.64 */
    check_scaled(1.1);
}

static void test_size_symmetric(void)
{
    /* E_G(s) = E_G(1/s): the energy ratio is taken smaller over larger */
    static double r[N], a[N], b[N];
    half_sine(r, 250, 750, 1.0);
    for (int i = 0; i < N; i++) {
        a[i] = 1.6 * r[i];
        b[i] = r[i] / 1.6;
    }
    an_cora_result ra, rb;
    mcs_error err = {0};
    CHECK(an_cora_arrays(r, a, N, 0.0, DT, NULL, &ra, &err) == MCS_OK);
    CHECK(an_cora_arrays(r, b, N, 0.0, DT, NULL, &rb, &err) == MCS_OK);
    CHECK_NEAR(ra.size, 1 / (1.6 * 1.6), 1e-12);
    CHECK_NEAR(rb.size, ra.size, 1e-12);
}

static void check_shift(int k, double ep)
{
    /* c[i] = r[i - k], r the half-sine on 300..500: interval 301..533 (test_interval_half_sine),
     * T = 232 dt, so D_MIN T = 2.32 and D_MAX T = 27.84 samples. The comparison outside the
     * interval is available, so the shifted overlap is the identical pulse: K(k) = 1, E_V = 1,
     * E_G = 1, and E_P = (27.84 - |k|)/(27.84 - 2.32), clipped to [0, 1]. */
    static double r[N], c[N];
    half_sine(r, 300, 500, 4.0);
    half_sine(c, 300 + k, 500 + k, 4.0);
    an_cora_result res;
    mcs_error err = {0};
    CHECK(an_cora_arrays(r, c, N, 0.0, DT, NULL, &res, &err) == MCS_OK);
    CHECK(res.shift == k);
    CHECK_NEAR(res.shift_time, k * DT, 1e-15);
    CHECK_NEAR(res.phase, ep, 1e-12);
    CHECK_NEAR(res.progression, 1.0, 1e-12);
    CHECK_NEAR(res.size, 1.0, 1e-12);
}

static void test_time_shift(void)
{
    check_shift(15, (27.84 - 15) / (27.84 - 2.32));
    check_shift(-15, (27.84 - 15) / (27.84 - 2.32)); /* symmetric */
    check_shift(2, 1.0);                             /* below D_MIN T */
    check_shift(30, 0.0);                            /* beyond D_MAX T */
}

static void test_offset_progression(void)
{
    /* r = 1 on 300..699, c = r + 0.1 everywhere; interval 297..778 (482 samples, 400 on the
     * plateau). At m = 0: sum r^2 = 400, sum r c = 400 (1.1) = 440,
     * sum c^2 = 400 (1.21) + 82 (0.01) = 484.82, K = 440/sqrt(400 * 484.82). A shift m loses |m|
     * plateau products (sum r c = 440 - |m|) with the same sum c^2, so m = 0 is best.
     * E_V = ((1 + K)/2)^10, E_G = 400/484.82, E_P = 1; |d| = 0.1 everywhere: Z = (0.4/0.45)^2
     * = 64/81. */
    static double r[N], c[N];
    square(r, 300, 700, 1.0);
    for (int i = 0; i < N; i++) c[i] = r[i] + 0.1;
    an_cora_result res;
    mcs_error err = {0};
    CHECK(an_cora_arrays(r, c, N, 0.0, DT, NULL, &res, &err) == MCS_OK);
    double K = 440 / sqrt(400 * 484.82), ev = pow((1 + K) / 2, 10), eg = 400 / 484.82;
    CHECK(res.shift == 0);
    CHECK_NEAR(res.xcorr, K, 1e-12);
    CHECK_NEAR(res.progression, ev, 1e-12);
    CHECK_NEAR(res.size, eg, 1e-12);
    CHECK_NEAR(res.phase, 1.0, 0);
    CHECK_NEAR(res.corridor, 64.0 / 81.0, 1e-12);
    CHECK_NEAR(res.cross, 0.5 * ev + 0.25 * eg + 0.25, 1e-12);
    CHECK_NEAR(res.rating, 0.5 * 64.0 / 81.0 + 0.5 * (0.5 * ev + 0.25 * eg + 0.25), 1e-12);
}

static void test_bad_input(void)
{
    /* a zero reference has no interval and no corridor width: clear error, result zeroed */
    static double z[N], c[N];
    half_sine(c, 100, 900, 1.0);
    an_cora_result res;
    mcs_error err = {0};
    CHECK(an_cora_arrays(z, c, N, 0.0, DT, NULL, &res, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "zero everywhere");
    CHECK(res.rating == 0 && !isnan(res.size));
    /* a zero comparison is rated, not an error: K = 0 (E_V = 0.5^10), E_G = 0, no NaN */
    mcs_error_clear(&err);
    CHECK(an_cora_arrays(c, z, N, 0.0, DT, NULL, &res, &err) == MCS_OK);
    CHECK_NEAR(res.size, 0.0, 0);
    CHECK_NEAR(res.progression, pow(0.5, 10), 1e-15);
    CHECK(isfinite(res.rating));
    /* non-finite samples, bad weights */
    c[5] = INFINITY;
    mcs_error_clear(&err);
    CHECK(an_cora_arrays(c, c, N, 0.0, DT, NULL, &res, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "sample 6");
    c[5] = 0;
    an_cora_opts o = an_cora_opts_default();
    o.g_v = 0.6;
    mcs_error_clear(&err);
    CHECK(an_cora_arrays(c, c, N, 0.0, DT, &o, &res, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "weights");
    /* an explicit interval where the reference is zero */
    o = an_cora_opts_default();
    o.t_min = 0.0;
    o.t_max = 0.005;
    mcs_error_clear(&err);
    CHECK(an_cora_arrays(c, c, N, 0.0, DT, &o, &res, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "zero in the interval");
}

static void test_signals_resampled(void)
{
    /* a 2 kHz copy of a half-sine against a 10 kHz one over 0.005..0.095 s (901 samples at
     * 10 kHz): same curve, so every part is near 1. Linear interpolation at 2 kHz errs by at
     * most e = (5e-4)^2/8 (pi/0.05)^2 A = 1.2e-4 A, so the energies differ by at most
     * e * 2 int|r| = e (4/pi) A T against int r^2 = A^2 T/2: 1 - E_G <= 3.1e-4, weighted 0.125
     * in the rating; corridor and phase stay 1 and 1 - K is O(e^2): R >= 1 - 4e-5. */
    enum { N1 = 1001, N2 = 181 };
    static double t1[N1], y1[N1], t2[N2], y2[N2];
    for (int i = 0; i < N1; i++) {
        t1[i] = i * 1e-4;
        y1[i] = (t1[i] > 0.02 && t1[i] < 0.07) ? 30 * sin(PI * (t1[i] - 0.02) / 0.05) : 0;
    }
    for (int i = 0; i < N2; i++) {
        t2[i] = 0.005 + i * 5e-4;
        y2[i] = (t2[i] > 0.02 && t2[i] < 0.07) ? 30 * sin(PI * (t2[i] - 0.02) / 0.05) : 0;
    }
    an_signal a = {.name = "ref", .n = N1, .t = t1, .y = y1};
    an_signal b = {.name = "cmp", .n = N2, .t = t2, .y = y2};
    an_cora_result res;
    mcs_error err = {0};
    CHECK(an_cora(&a, &b, NULL, &res, &err) == MCS_OK);
    CHECK(res.n == 901);
    CHECK_NEAR(res.t0, 0.005, 1e-15);
    CHECK(res.shift == 0);
    CHECK(res.rating > 1 - 4e-5);
}

int main(void)
{
    RUN(test_interval_square);
    RUN(test_interval_half_sine);
    RUN(test_identical);
    RUN(test_scaled);
    RUN(test_size_symmetric);
    RUN(test_time_shift);
    RUN(test_offset_progression);
    RUN(test_bad_input);
    RUN(test_signals_resampled);
    TEST_END();
}

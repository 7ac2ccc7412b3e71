/* tests for the SAE J211-1 App. C CFC filters (analysis/an_cfc.c) */
#include "analysis/an_cfc.h"
#include "tests/harness.h"
#include "tests/figures.h"

#include <stdlib.h>

/* amplitude of the component at frequency f in y[i0..i1) by least squares on sin and cos:
 * exact for a pure sinusoid, so the only error left is the end transient (decayed to
 * e^-10 or less in the middle half of a long record) and round-off */
static double sine_amplitude(const double *y, int i0, int i1, double dt, double f)
{
    double ss = 0, cc = 0, sc = 0, ys = 0, yc = 0;
    for (int i = i0; i < i1; i++) {
        double s = sin(2 * M_PI * f * i * dt), c = cos(2 * M_PI * f * i * dt);
        ss += s * s, cc += c * c, sc += s * c, ys += y[i] * s, yc += y[i] * c;
    }
    double det = ss * cc - sc * sc;
    double a = (ys * cc - yc * sc) / det, b = (yc * ss - ys * sc) / det;
    return sqrt(a * a + b * b);
}

/* measured gain of the filter for a unit sine at f, over a record of `cycles` periods */
static double measured_gain(double cfc, double fs, double f, double cycles)
{
    double dt = 1.0 / fs;
    int n = (int)(cycles / f * fs);
    double *x = malloc((size_t)n * sizeof(double));
    for (int i = 0; i < n; i++) x[i] = sin(2 * M_PI * f * i * dt);
    mcs_error e = {0};
    double g = -1;
    if (an_cfc_filter(x, n, dt, cfc, x, &e) == MCS_OK)
        g = sine_amplitude(x, n / 4, 3 * n / 4, dt, f);
    free(x);
    return g;
}

static double db(double g) { return 20 * log10(g); }

/* forward-backward gain of J211 App. C at f (written here, not an_cfc_gain): each pass is the
 * bilinear Butterworth with wa = tan(pi 2.0775 CFC dt), |H|^2 = 1/(1 + (tan(pi f dt)/wa)^4),
 * and the two passes multiply |H| by itself */
static double j211_gain(double cfc, double dt, double f)
{
    double r = tan(M_PI * f * dt) / tan(M_PI * 2.0775 * cfc * dt);
    return 1.0 / (1.0 + r * r * r * r);
}

/* DC gain 1: (a0 + a1 + a2) / (1 - b1 - b2) = 1 from the J211 coefficients, and a constant
 * comes out unchanged (the mirror padding and the y = x start make it exact to round-off) */
static void test_dc_gain(void)
{
    an_cfc_coef c;
    mcs_error e = {0};
    CHECK(an_cfc_design(180, 1e-4, &c, &e) == MCS_OK);
    CHECK_NEAR((c.a0 + c.a1 + c.a2) / (1 - c.b1 - c.b2), 1.0, 1e-13);
    double x[500];
    for (int i = 0; i < 500; i++) x[i] = 7.25;
    CHECK(an_cfc_filter(x, 500, 1e-4, 60, x, &e) == MCS_OK);
    for (int i = 0; i < 500; i++) CHECK_NEAR(x[i], 7.25, 1e-12);
}

/* -6.02 dB (amplitude 1/2 exactly: each pass is the -3.01 dB corner of the pre-warped
 * Butterworth) at 2.0775·CFC, for the four standard classes and two sample rates.
 * Tolerance 1e-12 in the ratio: the fit over the middle 150 of 300 cycles leaves the end
 * transients (75 cycles away, e^-300 and less) and round-off. */
static void test_gain_at_design_frequency(void)
{
    const double classes[] = {60, 180, 600, 1000};
    const double rates[] = {10000, 50000};
    double worst = db(0.5); /* the measured dB farthest from -20 log10 2 */
    for (int k = 0; k < 4; k++)
        for (int r = 0; r < 2; r++) {
            double g = measured_gain(classes[k], rates[r], 2.0775 * classes[k], 300);
            CHECK_NEAR(g, 0.5, 1e-12);
            if (fabs(db(g) - db(0.5)) > fabs(worst - db(0.5))) worst = db(g);
        }
    FIG("signals.cfc_gain_design_db", "%.6f", worst);
}

/* about -3 dB at 1.667·CFC when the rate is high against the class: analytic gain
 * 1/(1 + (1.667/2.0775)^4) = 0.7070 -> -3.01 dB as dt -> 0; at fs = 100·CFC the warping
 * moves it by < 0.01 dB, so |dB + 3| < 0.05. The measurement matches the analytic transfer
 * function |H|^2 = 1/(1 + (tan(pi f dt)/tan(pi fd dt))^4) to 1e-12 at any rate (the same
 * fit as above). */
static void test_gain_3db(void)
{
    const double classes[] = {60, 180, 600, 1000};
    for (int k = 0; k < 4; k++) {
        double cfc = classes[k], fs = 100 * cfc;
        double g = measured_gain(cfc, fs, 1.667 * cfc, 300);
        CHECK_NEAR(db(g), -3.0, 0.05);
        CHECK_NEAR(g, j211_gain(cfc, 1 / fs, 1.667 * cfc), 1e-12);
        if (k == 0) FIG("signals.cfc_gain_3db_db", "%.4f", db(g));
    }
    /* a coarse rate for CFC 1000 (10 kHz): the analytic gain still holds, -2.45 dB */
    double g = measured_gain(1000, 10000, 1667, 300);
    CHECK_NEAR(g, j211_gain(1000, 1e-4, 1667), 1e-12);
    /* pass band: at f = CFC the gain lies in J211's +0.5/-1 dB corridor (-0.454 dB as
     * dt -> 0, -0.437 dB at 20 kHz for CFC 600 by the transfer function) */
    g = measured_gain(600, 20000, 600, 300);
    CHECK(db(g) < 0.5 && db(g) > -1.0);
    CHECK_NEAR(g, j211_gain(600, 1 / 20000.0, 600), 1e-12);
    FIG("signals.cfc_gain_at_cfc_db", "%.3f", db(g));
}

/* the thesis' Butterworth low-pass with corner fc: each pass is -3.01 dB at fc, so the
 * forward-backward amplitude there is 1/2 (same fit and tolerance as above) */
static void test_butterworth(void)
{
    double fs = 20000, fc = 500, dt = 1 / fs;
    int n = (int)(300 / fc * fs);
    double *x = malloc((size_t)n * sizeof(double));
    for (int i = 0; i < n; i++) x[i] = sin(2 * M_PI * fc * i * dt);
    mcs_error e = {0};
    CHECK(an_butterworth_filter(x, n, dt, fc, x, &e) == MCS_OK);
    CHECK_NEAR(sine_amplitude(x, n / 4, 3 * n / 4, dt, fc), 0.5, 1e-12);
    free(x);
}

/* zero phase: a symmetric pulse stays symmetric and its peak does not move. Tolerance 1e-13
 * (the peak is 1.5): with zero signal at both ends the forward and backward passes commute up
 * to round-off. */
static void test_zero_phase(void)
{
    enum { N = 2001 };
    double x[N], dt = 1e-4;
    for (int i = 0; i < N; i++) {
        double t = (i - 1000) * dt;
        x[i] = exp(-t * t / (2 * 0.002 * 0.002)) + (fabs(t) < 0.003 ? 0.5 : 0.0);
    }
    mcs_error e = {0};
    CHECK(an_cfc_filter(x, N, dt, 180, x, &e) == MCS_OK);
    int imax = 0;
    for (int i = 0; i < N; i++) {
        CHECK_NEAR(x[i], x[N - 1 - i], 1e-13);
        if (x[i] > x[imax]) imax = i;
    }
    CHECK(imax == 1000);
}

/* a straight line passes unchanged (the point mirror continues the slope; the filter has
 * gain 1 and zero group delay at DC). The start-up of each pass is 15 time constants away,
 * so what is left of the ramp lag sqrt(2)/wn * slope = 0.09 (CFC 60, slope 50/s) is
 * e^-15 * 0.09 = 3e-8: the tolerance. */
static void test_ramp(void)
{
    enum { N = 1000 };
    double x[N], dt = 1e-4;
    for (int i = 0; i < N; i++) x[i] = 3 + 50 * i * dt;
    mcs_error e = {0};
    CHECK(an_cfc_filter(x, N, dt, 60, x, &e) == MCS_OK);
    for (int i = 0; i < N; i++) CHECK_NEAR(x[i], 3 + 50 * i * dt, 3e-8);
}

/* the filter of a channel: uniform sampling required; CFC recorded */
static void test_signal_and_rate(void)
{
    double t[100], y[100];
    for (int i = 0; i < 100; i++) t[i] = i * 2.5e-4, y[i] = i % 2;
    an_signal s = {.n = 100, .t = t, .y = y};
    mcs_error e = {0};
    /* CFC 1000 needs a rate above 2 * 2077.5 Hz = 4155 Hz; 4000 Hz is refused */
    CHECK(an_cfc_signal(&s, 1000, &e) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e.msg, "too low");
    mcs_error e2 = {0};
    CHECK(an_cfc_signal(&s, 600, &e2) == MCS_OK);
    CHECK(s.cfc == 600);
    /* the alternating (Nyquist) component is removed: the bilinear numerator (1 + 1/z)^2 is
     * zero at z = -1; what is left 20 samples from the ends is the start-up transient of the
     * mirrored ends (4e-8 measured): tolerance 1e-7 */
    for (int i = 20; i < 80; i++) CHECK_NEAR(y[i], 0.5, 1e-7);
    t[50] += 1e-5;
    mcs_error e3 = {0};
    CHECK(an_cfc_signal(&s, 60, &e3) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e3.msg, "uniform");
    CHECK(an_cfc_default("head_acceleration") == 1000);
    CHECK(an_cfc_default("neck_force") == 600);
    CHECK(an_cfc_default("chest_acceleration") == 180);
    CHECK(an_cfc_default("vehicle") == 60);
    CHECK(an_cfc_default("elbow") == 0);
}

int main(void)
{
    RUN(test_dc_gain);
    RUN(test_gain_at_design_frequency);
    RUN(test_gain_3db);
    RUN(test_butterworth);
    RUN(test_zero_phase);
    RUN(test_ramp);
    RUN(test_signal_and_rate);
    TEST_END();
}

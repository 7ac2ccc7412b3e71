/* tests for the thesis' ch. 7 numerical processing: natural cubic splines with their
 * derivatives, and trapezoid integration of accelerations (analysis/an_spline.h,
 * analysis/an_integrate.h). Error orders are measured by halving the step. */
#include "analysis/an_integrate.h"
#include "analysis/an_spline.h"
#include "tests/harness.h"
#include "tests/figures.h"

#include <stdlib.h>

/* passes through the knots; a straight line is reproduced exactly (all M = 0) with its slope */
static void test_spline_knots_and_lines(void)
{
    double x[] = {0, 0.5, 1.2, 2.0, 3.5}, y[5], yl[5];
    for (int i = 0; i < 5; i++) y[i] = cos(3 * x[i]), yl[i] = 2 - 4 * x[i];
    an_spline s;
    mcs_error e = {0};
    CHECK(an_spline_natural(x, y, 5, &s, &e) == MCS_OK);
    for (int i = 0; i < 5; i++) CHECK_NEAR(an_spline_eval(&s, x[i]), y[i], 1e-14);
    CHECK_NEAR(an_spline_deriv2(&s, 0), 0, 1e-14); /* natural ends */
    CHECK_NEAR(an_spline_deriv2(&s, 3.5), 0, 1e-14);
    an_spline_free(&s);
    CHECK(an_spline_natural(x, yl, 5, &s, &e) == MCS_OK);
    for (double v = 0; v <= 3.5; v += 0.07) {
        CHECK_NEAR(an_spline_eval(&s, v), 2 - 4 * v, 1e-13);
        CHECK_NEAR(an_spline_deriv(&s, v), -4, 1e-13);
    }
    an_spline_free(&s);
    double xb[] = {0, 1, 1};
    CHECK(an_spline_natural(xb, y, 3, &s, &e) == MCS_ERR_RANGE);
}

/* max errors of value and slope of the spline through sin on [0, pi] with n knots. sin'' = 0
 * at both ends, so the natural end condition is the true one and the classical orders hold:
 * O(h^4) value, O(h^3) slope (de Boor, A Practical Guide to Splines, ch. IV/V). */
static void sin_errors(int n, double *ev, double *ed)
{
    double *x = malloc((size_t)n * sizeof(double)), *y = malloc((size_t)n * sizeof(double));
    for (int i = 0; i < n; i++) x[i] = M_PI * i / (n - 1), y[i] = sin(x[i]);
    an_spline s;
    mcs_error e = {0};
    *ev = *ed = 1e300;
    if (an_spline_natural(x, y, n, &s, &e) == MCS_OK) {
        *ev = *ed = 0;
        for (int k = 0; k <= 5000; k++) {
            double v = M_PI * k / 5000;
            *ev = fmax(*ev, fabs(an_spline_eval(&s, v) - sin(v)));
            *ed = fmax(*ed, fabs(an_spline_deriv(&s, v) - cos(v)));
        }
        an_spline_free(&s);
    }
    free(x), free(y);
}

/* measured orders over 11 -> 21 -> 41 -> 81 knots must be 4 +/- 0.3 (value) and 3 +/- 0.3
 * (slope); the band allows the pre-asymptotic first halving */
static void test_spline_convergence(void)
{
    double ev[4], ed[4];
    const int ns[] = {11, 21, 41, 81};
    for (int k = 0; k < 4; k++) sin_errors(ns[k], &ev[k], &ed[k]);
    for (int k = 1; k < 4; k++) {
        double pv = log2(ev[k - 1] / ev[k]), pd = log2(ed[k - 1] / ed[k]);
        CHECK_NEAR(pv, 4.0, 0.3);
        CHECK_NEAR(pd, 3.0, 0.3);
    }
    /* the orders of the last halving (41 -> 81 knots), as docs/signals.md states them */
    FIG("signals.spline_order_value", "%.2f", log2(ev[2] / ev[3]));
    FIG("signals.spline_order_slope", "%.2f", log2(ed[2] / ed[3]));
    /* and the sizes, against the bounds Hall & Meyer (J. Approx. Theory 16, 1976) prove for
     * the spline with exact end slopes (here the exact end condition is sin'' = 0), used as
     * tolerances, |sin''''| <= 1: |f - s| <= 5/384 h^4 (3.1e-8 at 81 knots; measured 6.2e-9),
     * |f' - s'| <= (sqrt(3)/216 + 1/24) h^3 (3.0e-6; measured 4.9e-7) */
    double h = M_PI / 80;
    CHECK(ev[3] <= 5.0 / 384 * pow(h, 4));
    CHECK(ed[3] <= (sqrt(3.0) / 216 + 1.0 / 24) * pow(h, 3));
}

/* film analysis: a head trajectory digitised at 1000 frames/s, x(t) = 0.3 sin(40 t) (m);
 * the spline slope gives the velocity 12 cos(40 t) m/s. Interior error with h = 1 ms: the
 * O(h^3) slope term ~ (40 h)^3 * 12 / 24 ~ 3e-5 m/s; the natural end condition (x'' != 0 at
 * the ends here) spoils only the first few frames (its error decays by 2 - sqrt(3) a knot),
 * so check from 10 frames in: measured 6.1e-6 m/s, tolerance 2e-5 m/s. */
static void test_spline_film_velocity(void)
{
    enum { N = 201 };
    double t[N], x[N];
    for (int i = 0; i < N; i++) t[i] = i * 1e-3, x[i] = 0.3 * sin(40 * t[i]);
    an_spline s;
    mcs_error e = {0};
    CHECK(an_spline_natural(t, x, N, &s, &e) == MCS_OK);
    double emax = 0;
    for (double v = 0.010; v <= 0.190; v += 1e-4)
        emax = fmax(emax, fabs(an_spline_deriv(&s, v) - 12 * cos(40 * v)));
    CHECK(emax < 2e-5);
    an_spline_free(&s);
}

/* a = sin(w t): v = (1 - cos w t)/w, x = t/w - sin(w t)/w^2 (v0 = x0 = 0). Max errors over
 * [0, 0.1 s] (w = 100/s) at h, h/2, h/4: the trapezoid's global error is O(h^2), so each
 * halving divides it by 4 (order 2 +/- 0.1). */
static void integ_errors(double h, double *evel, double *edis)
{
    int n = (int)(0.1 / h + 0.5) + 1;
    double w = 100;
    double *t = calloc((size_t)n * 4, sizeof(double));
    *evel = *edis = 1e300;
    if (!t) return;
    double *a = t + n, *v = a + n, *x = v + n;
    for (int i = 0; i < n; i++) t[i] = i * h, a[i] = sin(w * t[i]);
    mcs_error e = {0};
    if (an_integrate_accel(t, a, n, 0, 0, v, x, &e) == MCS_OK) {
        *evel = *edis = 0;
        for (int i = 0; i < n; i++) {
            *evel = fmax(*evel, fabs(v[i] - (1 - cos(w * t[i])) / w));
            *edis = fmax(*edis, fabs(x[i] - (t[i] / w - sin(w * t[i]) / (w * w))));
        }
    }
    free(t);
}

static void test_integration_order(void)
{
    double ev[3], ex[3];
    for (int k = 0; k < 3; k++) integ_errors(1e-3 / (1 << k), &ev[k], &ex[k]);
    for (int k = 1; k < 3; k++) {
        CHECK_NEAR(log2(ev[k - 1] / ev[k]), 2.0, 0.1);
        CHECK_NEAR(log2(ex[k - 1] / ex[k]), 2.0, 0.1);
    }
    FIG("signals.trapezoid_order_v", "%.3f", log2(ev[1] / ev[2]));
    FIG("signals.trapezoid_order_x", "%.3f", log2(ex[1] / ex[2]));
    /* leading term: velocity error h^2 w / 12 * |cos - 1| <= h^2 w / 6 */
    CHECK(ev[0] <= 1e-6 * 100 / 6 * 1.05);
}

/* an offset e in the acceleration: the trapezoid is exact on constants and lines, so the
 * velocity drifts by exactly e t and the displacement by exactly e t^2 / 2 (to round-off),
 * whatever the step; uneven steps on purpose */
static void test_integration_offset_drift(void)
{
    enum { N = 500 };
    double t[N], a[N], a2[N], v[N], x[N], v2[N], x2[N], off = 0.2;
    t[0] = 0;
    for (int i = 1; i < N; i++) t[i] = t[i - 1] + 1e-4 * (1 + 0.5 * sin(i));
    for (int i = 0; i < N; i++) a[i] = 50 * sin(60 * t[i]) * exp(-20 * t[i]), a2[i] = a[i] + off;
    mcs_error e = {0};
    CHECK(an_integrate_accel(t, a, N, 13.4, 0, v, x, &e) == MCS_OK);
    CHECK(an_integrate_accel(t, a2, N, 13.4, 0, v2, x2, &e) == MCS_OK);
    for (int i = 0; i < N; i++) {
        CHECK_NEAR(v2[i] - v[i], off * t[i], 1e-13);
        CHECK_NEAR(x2[i] - x[i], off * t[i] * t[i] / 2, 1e-13);
    }
    t[7] = t[6];
    CHECK(an_integrate_accel(t, a, N, 0, 0, v, x, &e) == MCS_ERR_RANGE);
}

int main(void)
{
    RUN(test_spline_knots_and_lines);
    RUN(test_spline_convergence);
    RUN(test_spline_film_velocity);
    RUN(test_integration_order);
    RUN(test_integration_offset_drift);
    TEST_END();
}

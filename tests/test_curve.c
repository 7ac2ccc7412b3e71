/* tests for core/mcs_curve: validation messages, evaluation, extrapolation, slope, exact
 * integrals, inverses, scaling and the thesis §3.2 series combination of two bodies */
#include "core/mcs_curve.h"
#include "tests/harness.h"

static mcs_curve *mk(int n, const double (*xy)[2], mcs_extrap lo, mcs_extrap hi)
{
    mcs_error e;
    mcs_error_clear(&e);
    mcs_curve *c = NULL;
    if (mcs_curve_create_xy("test", n, xy, lo, hi, &c, &e) != MCS_OK)
        fprintf(stderr, "unexpected: %s\n", e.msg);
    return c;
}

static void test_validation_names_the_point(void)
{
    mcs_error e;
    mcs_curve *c = NULL;
    const double bad[][2] = {{0, 0}, {0.01, 100}, {0.01, 200}, {0.03, 300}};
    mcs_error_clear(&e);
    CHECK(mcs_curve_create_xy("pad.loading", 4, bad, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR, &c,
                              &e) == MCS_ERR_RANGE);
    CHECK(c == NULL);
    CHECK_STR_CONTAINS(e.msg, "pad.loading: point 3 of 4 has x = 0.01");
    CHECK_STR_CONTAINS(e.msg, "x must increase strictly");

    const double nan_pt[][2] = {{0, 0}, {NAN, 1}};
    mcs_error_clear(&e);
    CHECK(mcs_curve_create_xy("k", 2, nan_pt, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR, &c, &e) ==
          MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e.msg, "point 2 of 2");
    CHECK_STR_CONTAINS(e.msg, "not finite");

    mcs_error_clear(&e);
    CHECK(mcs_curve_create("k", 0, NULL, NULL, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR, &c, &e) ==
          MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e.msg, "at least one point");

    const double one[][2] = {{1, 5}};
    mcs_error_clear(&e);
    CHECK(mcs_curve_create_xy("k", 1, one, MCS_EXTRAP_LINEAR, MCS_EXTRAP_CONSTANT, &c, &e) ==
          MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e.msg, "one-point curve");
    mcs_error_clear(&e);
    CHECK(mcs_curve_create_xy("k", 1, one, MCS_EXTRAP_CONSTANT, MCS_EXTRAP_CONSTANT, &c, &e) ==
          MCS_OK);
    CHECK(mcs_curve_eval(c, -3) == 5 && mcs_curve_eval(c, 7) == 5 && mcs_curve_slope(c, 1) == 0);
    /* integral of the constant 5 from -1 to 3 is 20 */
    CHECK_NEAR(mcs_curve_integral(c, -1, 3), 20, 1e-12);
    mcs_curve_destroy(&c);
    CHECK(c == NULL);
}

/* y = 0, 100, 150 at x = 0, 0.01, 0.03: slopes 1e4 and 2.5e3 */
static const double bil[][2] = {{0, 0}, {0.01, 100}, {0.03, 150}};

static void test_eval_and_extrapolation(void)
{
    mcs_curve *lin = mk(3, bil, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *con = mk(3, bil, MCS_EXTRAP_CONSTANT, MCS_EXTRAP_CONSTANT);
    mcs_curve *mix = mk(3, bil, MCS_EXTRAP_CONSTANT, MCS_EXTRAP_LINEAR);
    /* at and between the points */
    for (int i = 0; i < 3; i++)
        CHECK_NEAR(mcs_curve_eval(lin, bil[i][0]), bil[i][1], 1e-12);
    CHECK_NEAR(mcs_curve_eval(lin, 0.005), 50, 1e-12);
    CHECK_NEAR(mcs_curve_eval(lin, 0.02), 125, 1e-12);
    /* linear: end segments continue; constant: end values held */
    CHECK_NEAR(mcs_curve_eval(lin, -0.01), -100, 1e-12);
    CHECK_NEAR(mcs_curve_eval(lin, 0.05), 150 + 2500 * 0.02, 1e-12);
    CHECK_NEAR(mcs_curve_eval(con, -0.01), 0, 0);
    CHECK_NEAR(mcs_curve_eval(con, 0.05), 150, 0);
    CHECK_NEAR(mcs_curve_eval(mix, -0.01), 0, 0);
    CHECK_NEAR(mcs_curve_eval(mix, 0.05), 200, 1e-12);
    /* slopes: right derivative at a breakpoint, 0 in a hold region */
    CHECK_NEAR(mcs_curve_slope(lin, 0.005), 1e4, 1e-8);
    CHECK_NEAR(mcs_curve_slope(lin, 0.01), 2500, 1e-9);
    CHECK_NEAR(mcs_curve_slope(lin, -1), 1e4, 1e-8);
    CHECK_NEAR(mcs_curve_slope(lin, 1), 2500, 1e-9);
    CHECK(mcs_curve_slope(con, -1) == 0 && mcs_curve_slope(con, 0.03) == 0);
    CHECK(lin->monotone == 1);
    CHECK(isnan(mcs_curve_eval(lin, NAN)));
    mcs_curve_destroy(&lin);
    mcs_curve_destroy(&con);
    mcs_curve_destroy(&mix);
}

/* the hinted lookup must agree with bisection for any hint, and keep a valid hint */
static void test_segment_hint(void)
{
    double xy[40][2];
    for (int i = 0; i < 40; i++) {
        xy[i][0] = i * i * 0.01;
        xy[i][1] = sin(i);
    }
    mcs_curve *c = mk(40, xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_CONSTANT);
    unsigned s = 12345;
    int hint = -1, bad = 0;
    double x = 0;
    for (int k = 0; k < 20000; k++) {
        s = s * 1103515245u + 12345u;
        double r = (double)(s >> 8) / (double)(1u << 24);     /* [0, 1) */
        x = (k % 3 == 0) ? -2 + 20 * r : x + 0.2 * (r - 0.5); /* jumps and small moves */
        int h0 = mcs_curve_segment(c, x, -1);
        int hr = mcs_curve_segment(c, x, (int)(r * 45) - 2); /* any hint, even invalid */
        double v = mcs_curve_eval_hint(c, x, &hint);
        if (h0 != hr || v != mcs_curve_eval(c, x) || hint != h0) bad++;
        if (x >= xy[0][0] && x <= xy[39][0] && !(xy[h0][0] <= x && x <= xy[h0 + 1][0])) bad++;
    }
    CHECK(bad == 0);
    mcs_curve_destroy(&c);
}

/* integral of the piecewise-linear curve = sum of trapezoids; by hand for `bil`:
 * int_0^0.01 = 0.5*100*0.01 = 0.5; int_0.01^0.03 = 0.5*(100+150)*0.02 = 2.5.
 * Linear extension beyond 0.03: y = 150 + 2500 (x - 0.03), int_0.03^0.05 = 150*0.02 + 1250*0.02^2
 * = 3.5. Below 0: y = 1e4 x, int_-0.01^0 = -0.5. Constant hold: 150*0.02 = 3. */
static void test_integral_exact(void)
{
    mcs_curve *lin = mk(3, bil, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *con = mk(3, bil, MCS_EXTRAP_CONSTANT, MCS_EXTRAP_CONSTANT);
    CHECK_NEAR(mcs_curve_integral(lin, 0, 0.01), 0.5, 1e-14);
    CHECK_NEAR(mcs_curve_integral(lin, 0.01, 0.03), 2.5, 1e-14);
    CHECK_NEAR(mcs_curve_integral(lin, 0, 0.03), 3.0, 1e-14);
    CHECK_NEAR(mcs_curve_integral(lin, 0.03, 0.05), 3.5, 1e-13);
    CHECK_NEAR(mcs_curve_integral(lin, -0.01, 0), -0.5, 1e-14);
    CHECK_NEAR(mcs_curve_integral(con, 0.03, 0.05), 3.0, 1e-13);
    CHECK_NEAR(mcs_curve_integral(con, -0.01, 0), 0.0, 1e-14);
    /* partial segments: int_0.005^0.02 of y: [0.005,0.01]: 0.5*(50+100)*0.005 = 0.375,
     * [0.01,0.02]: 0.5*(100+125)*0.01 = 1.125; total 1.5; reversed limits give -1.5 */
    CHECK_NEAR(mcs_curve_integral(lin, 0.005, 0.02), 1.5, 1e-14);
    CHECK_NEAR(mcs_curve_integral(lin, 0.02, 0.005), -1.5, 1e-14);
    /* a many-point curve: between breakpoints the integral is the sum of the table's trapezoids
     * (x_{i+1} - x_i) (y_i + y_{i+1}) / 2, summed here from the table itself; below x_0 the
     * first segment continues, a trapezoid from y(a) = y_0 + (a - x_0) s_0 */
    double xy[25][2];
    for (int i = 0; i < 25; i++) {
        xy[i][0] = 0.1 * i + 0.003 * i * i;
        xy[i][1] = cos(0.7 * i) * 10;
    }
    mcs_curve *w = mk(25, xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    double trap = 0;
    for (int i = 3; i < 20; i++)
        trap += (xy[i + 1][0] - xy[i][0]) * (xy[i][1] + xy[i + 1][1]) / 2;
    CHECK_NEAR(mcs_curve_integral(w, xy[3][0], xy[20][0]), trap, 1e-12);
    double a = -0.3, s0 = (xy[1][1] - xy[0][1]) / (xy[1][0] - xy[0][0]);
    double ya = xy[0][1] + (a - xy[0][0]) * s0;
    CHECK_NEAR(mcs_curve_integral(w, a, xy[0][0]), (xy[0][0] - a) * (ya + xy[0][1]) / 2, 1e-13);
    mcs_curve_destroy(&lin);
    mcs_curve_destroy(&con);
    mcs_curve_destroy(&w);
}

static void test_inverse(void)
{
    mcs_curve *lin = mk(3, bil, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *con = mk(3, bil, MCS_EXTRAP_LINEAR, MCS_EXTRAP_CONSTANT);
    CHECK_NEAR(mcs_curve_inverse(lin, 50), 0.005, 1e-15);
    CHECK_NEAR(mcs_curve_inverse(lin, 125), 0.02, 1e-15);
    CHECK_NEAR(mcs_curve_inverse(lin, 200), 0.05, 1e-15);   /* linear extension */
    CHECK_NEAR(mcs_curve_inverse(lin, -100), -0.01, 1e-15); /* linear extension */
    CHECK_NEAR(mcs_curve_inverse(con, 200), 0.03, 0);       /* no x reaches 200: clamped */
    /* y(x) by hand: 1e4 x up to 0.01, then 100 + 2500 (x - 0.01), both ends extended */
    for (int k = 0; k <= 100; k++) {
        double x = -0.02 + 0.0007 * k, y = x < 0.01 ? 1e4 * x : 100 + 2500 * (x - 0.01);
        CHECK_NEAR(mcs_curve_inverse(lin, y), x, 1e-15);
    }
    /* decreasing curve */
    const double dec[][2] = {{0, 10}, {1, 4}, {3, 0}};
    mcs_curve *d = mk(3, dec, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    CHECK(d->monotone == -1);
    CHECK_NEAR(mcs_curve_inverse(d, 7), 0.5, 1e-15);
    CHECK_NEAR(mcs_curve_inverse(d, 2), 2.0, 1e-15);
    CHECK_NEAR(mcs_curve_inverse(d, -2), 4.0, 1e-15);
    CHECK_NEAR(mcs_curve_inverse(d, 13), -0.5, 1e-15);
    /* not monotone: NaN, and no inverse curve */
    const double hump[][2] = {{0, 0}, {1, 4}, {3, 1}};
    mcs_curve *h = mk(3, hump, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    CHECK(h->monotone == 0 && isnan(mcs_curve_inverse(h, 2)));
    mcs_error e;
    mcs_error_clear(&e);
    mcs_curve *hi = NULL;
    CHECK(mcs_curve_create_inverse(h, NULL, &hi, &e) == MCS_ERR_RANGE && hi == NULL);
    CHECK_STR_CONTAINS(e.msg, "strictly monotone");
    /* inverse curve of the decreasing one: points reversed, evaluates x(y) */
    mcs_curve *di = NULL;
    mcs_error_clear(&e);
    CHECK(mcs_curve_create_inverse(d, "x(y)", &di, &e) == MCS_OK);
    CHECK(di->n == 3 && di->x[0] == 0 && di->y[0] == 3);
    /* x(y) by hand: (10 - y) / 6 on the first segment (y >= 4), 1 + (4 - y) / 2 below */
    for (int k = 0; k <= 20; k++) {
        double y = -1 + 0.6 * k, x = y >= 4 ? (10 - y) / 6 : 1 + (4 - y) / 2;
        CHECK_NEAR(mcs_curve_eval(di, y), x, 1e-14);
    }
    mcs_curve_destroy(&lin);
    mcs_curve_destroy(&con);
    mcs_curve_destroy(&d);
    mcs_curve_destroy(&h);
    mcs_curve_destroy(&di);
}

static void test_scaled(void)
{
    mcs_curve *c = mk(3, bil, MCS_EXTRAP_CONSTANT, MCS_EXTRAP_LINEAR), *s = NULL;
    mcs_error e;
    mcs_error_clear(&e);
    /* mm -> m style rescale: s(x) = 3 c(x / 2); c by hand: 0 below 0 (held), 1e4 u up to
     * u = 0.01, then 100 + 2500 (u - 0.01) (extended) */
    CHECK(mcs_curve_create_scaled(c, "s", 2.0, 3.0, &s, &e) == MCS_OK);
    for (int k = 0; k <= 30; k++) {
        double x = -0.02 + 0.004 * k, u = x / 2;
        double cu = u < 0 ? 0 : u < 0.01 ? 1e4 * u : 100 + 2500 * (u - 0.01);
        CHECK_NEAR(mcs_curve_eval(s, x), 3 * cu, 1e-12);
    }
    /* integral scales with sx * sy: 6 x 3.0 (test_integral_exact's hand value on [0, 0.03]) */
    CHECK_NEAR(mcs_curve_integral(s, 0, 0.06), 18.0, 1e-13);
    CHECK(s->lo == MCS_EXTRAP_CONSTANT && s->hi == MCS_EXTRAP_LINEAR && s->monotone == 1);
    mcs_curve *bad = NULL;
    CHECK(mcs_curve_create_scaled(c, "s", -1, 1, &bad, &e) == MCS_ERR_RANGE && !bad);
    mcs_curve_destroy(&c);
    mcs_curve_destroy(&s);
}

/* thesis §3.2: two deformable bodies in contact carry the same force and their deflections add.
 * Two linear springs k1, k2 in series: x = F/k1 + F/k2, so k = k1 k2 / (k1 + k2). */
static void test_series_linear_springs(void)
{
    const double k1 = 2e5, k2 = 5e4, k = k1 * k2 / (k1 + k2); /* 4e4 N/m */
    const double a_xy[][2] = {{0, 0}, {0.01, k1 * 0.01}};
    const double b_xy[][2] = {{0, 0}, {0.02, k2 * 0.02}};
    mcs_curve *a = mk(2, a_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *b = mk(2, b_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *s = NULL;
    mcs_error e;
    mcs_error_clear(&e);
    CHECK(mcs_curve_create_series(a, b, "head+airbag", &s, &e) == MCS_OK);
    for (int i = 0; i <= 20; i++) {
        double x = 0.005 * i; /* well beyond both tables: linear extension */
        CHECK_REL(mcs_curve_eval(s, x), k * x, 1e-12);
    }
    CHECK_REL(mcs_curve_slope(s, 0.5), k, 1e-12);
    mcs_curve_destroy(&a);
    mcs_curve_destroy(&b);
    mcs_curve_destroy(&s);
}

/* nonlinear pair: body 1 bilinear (k 1e4 to 100 N, then 2.5e3), body 2 linear 2e4 N/m.
 * x(F) by hand: F = 150: x1 = 0.03, x2 = 0.0075 -> 0.0375; F = 60: x1 = 0.006, x2 = 0.003.
 * With body 1's plateau (constant hold above 150 N) the pair cannot carry more than 150 N. */
static void test_series_nonlinear_and_cap(void)
{
    const double b_xy[][2] = {{0, 0}, {0.01, 200}};
    mcs_curve *a = mk(3, bil, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *ac = mk(3, bil, MCS_EXTRAP_LINEAR, MCS_EXTRAP_CONSTANT);
    mcs_curve *b = mk(2, b_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *s = NULL, *sc = NULL;
    mcs_error e;
    mcs_error_clear(&e);
    CHECK(mcs_curve_create_series(a, b, NULL, &s, &e) == MCS_OK);
    CHECK_NEAR(mcs_curve_inverse(s, 150), 0.0375, 1e-15);
    CHECK_NEAR(mcs_curve_inverse(s, 60), 0.009, 1e-15);
    CHECK_NEAR(mcs_curve_eval(s, 0.009), 60, 1e-12);
    for (int i = 0; i <= 50; i++) { /* anywhere: x1(F) + x2(F), x1 by hand (both ends extended) */
        double F = -20 + 6 * i, x1 = F <= 100 ? F / 1e4 : 0.01 + (F - 100) / 2500;
        CHECK_NEAR(mcs_curve_inverse(s, F), x1 + F / 2e4, 1e-15);
    }
    CHECK(mcs_curve_create_series(ac, b, NULL, &sc, &e) == MCS_OK);
    CHECK_NEAR(mcs_curve_eval(sc, 0.0375), 150, 1e-12);
    CHECK_NEAR(mcs_curve_eval(sc, 0.2), 150, 0);
    /* a non-monotone body is refused by name */
    const double hump[][2] = {{0, 0}, {1, 4}, {3, 1}};
    mcs_curve *h = mk(3, hump, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR), *sh = NULL;
    CHECK(mcs_curve_create_series(h, b, "pair", &sh, &e) == MCS_ERR_RANGE && !sh);
    CHECK_STR_CONTAINS(e.msg, "pair: curve 'test' must have strictly increasing force");
    mcs_curve_destroy(&a);
    mcs_curve_destroy(&ac);
    mcs_curve_destroy(&b);
    mcs_curve_destroy(&s);
    mcs_curve_destroy(&sc);
    mcs_curve_destroy(&h);
}

int main(void)
{
    RUN(test_validation_names_the_point);
    RUN(test_eval_and_extrapolation);
    RUN(test_segment_hint);
    RUN(test_integral_exact);
    RUN(test_inverse);
    RUN(test_scaled);
    RUN(test_series_linear_springs);
    RUN(test_series_nonlinear_and_cap);
    TEST_END();
}

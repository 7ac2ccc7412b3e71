/* tests for core/mcs_hysteresis: loading, unloading by slope / scaled curve / slope-then-curve,
 * permanent set, reloading, elastic limit, closed-cycle energy (areas computed by hand), the
 * work = stored + dissipated balance on random histories, the two-sided joint, and a fork
 * M_def(phi) of the shape of the paper's Fig. 7 (elastic, plastic plateau, unloading parallel
 * to the elastic slope, a stop). */
#include "core/mcs_hysteresis.h"
#include "tests/harness.h"
#include "tests/figures.h"

static mcs_curve *mk(int n, const double (*xy)[2], mcs_extrap lo, mcs_extrap hi)
{
    mcs_error e;
    mcs_error_clear(&e);
    mcs_curve *c = NULL;
    if (mcs_curve_create_xy("test", n, xy, lo, hi, &c, &e) != MCS_OK)
        fprintf(stderr, "unexpected: %s\n", e.msg);
    return c;
}

/* linear loading k1 = 1e5 N/m (DESIGN.md's "straight line through the points, extrapolated") */
static const double k1 = 1e5, k2 = 4e5;
static const double lin_xy[][2] = {{0, 0}, {0.01, 1000}};

/* the loading curve of test_loading_follows_curve by hand: through (0, 0), (0.01, 1000),
 * (0.03, 2000), (0.04, 4000), the last slope 2e5 N/m extrapolated */
static double loading_by_hand(double x)
{
    if (x <= 0.01) return 1e5 * x;
    if (x <= 0.03) return 1000 + 5e4 * (x - 0.01);
    return 2000 + 2e5 * (x - 0.03);
}

static void test_loading_follows_curve(void)
{
    const double xy[][2] = {{0, 0}, {0.01, 1000}, {0.03, 2000}, {0.04, 4000}};
    mcs_curve *L = mk(4, xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model m = {.loading = L, .unload = MCS_UNLOAD_SLOPE, .unload_slope = k2};
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    for (int i = 1; i <= 100; i++) {
        double x = 0.0005 * i;
        double f = mcs_hyst_update(&m, &s, x);
        CHECK_NEAR(f, loading_by_hand(x), 1e-9);
        CHECK(s.x_max == x);
    }
    /* work of monotone loading = integral of F_L by trapezoids of the straight pieces:
     * 0.01 * 500 + 0.02 * 1500 + 0.01 * 3000 + 0.01 * (4000 + 6000)/2 = 5 + 30 + 30 + 50 */
    CHECK_REL(s.work, 115.0, 1e-12);
    /* a gap (x <= 0) carries no force; the element never pulls */
    mcs_hyst_reset(&m, &s);
    CHECK(mcs_hyst_update(&m, &s, -0.01) == 0 && s.work == 0);
    mcs_curve_destroy(&L);
}

/* unloading from x_max with slope k2 reaches zero at x_set = x_max - F(x_max)/k2.
 * k1 = 1e5, x_max = 0.02: F = 2000 N, x_set = 0.02 - 2000/4e5 = 0.015 m. */
static void test_unload_slope_permanent_set(void)
{
    mcs_curve *L = mk(2, lin_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model m = {.loading = L, .unload = MCS_UNLOAD_SLOPE, .unload_slope = k2};
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    for (int i = 1; i <= 20; i++)
        mcs_hyst_update(&m, &s, 0.001 * i);
    CHECK_NEAR(s.force, 2000, 1e-9);
    CHECK_NEAR(s.x_set, 0.015, 1e-15);
    CHECK_NEAR(mcs_hyst_update(&m, &s, 0.017), 2000 - k2 * 0.003, 1e-9);
    CHECK_NEAR(mcs_hyst_stiffness(&m, &s, 0.017), k2, 1e-6);
    CHECK_NEAR(mcs_hyst_update(&m, &s, 0.015), 0, 1e-9);
    CHECK(mcs_hyst_update(&m, &s, 0.012) == 0); /* below the set: open gap */
    CHECK(mcs_hyst_stiffness(&m, &s, 0.012) == 0);
    CHECK_NEAR(s.x_set, 0.015, 1e-15); /* unchanged by unloading */
    mcs_curve_destroy(&L);
}

/* closed cycle load -> unload -> reload -> unload with linear loading k1, unloading k2:
 * the loading triangle holds F^2/(2 k1), the unloading triangle F^2/(2 k2); the area between
 * the paths is dissipated: F = 2000 N gives 4e6/2e5 - 4e6/8e5 = 20 - 5 = 15 J. Reloading along
 * the unloading path and unloading again adds nothing. */
static void test_closed_cycle_energy(void)
{
    mcs_curve *L = mk(2, lin_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model m = {.loading = L, .unload = MCS_UNLOAD_SLOPE, .unload_slope = k2};
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    const double F = 2000, xm = F / k1;
    for (int i = 1; i <= 40; i++)
        mcs_hyst_update(&m, &s, xm * i / 40);
    CHECK_REL(s.work, F * F / (2 * k1), 1e-12);                  /* 20 J */
    CHECK_REL(mcs_hyst_stored(&m, &s), F * F / (2 * k2), 1e-12); /* 5 J  */
    CHECK_REL(mcs_hyst_dissipated(&m, &s), F * F / (2 * k1) - F * F / (2 * k2), 1e-12);
    for (int i = 39; i >= -5; i--)
        mcs_hyst_update(&m, &s, xm * i / 40); /* unload past the set */
    CHECK_REL(s.work, 15.0, 1e-12);
    CHECK_NEAR(mcs_hyst_stored(&m, &s), 0, 1e-12);
    /* half-way up the reload: stored = k2 (x - x_set)^2 / 2 = 2e5 * 0.0025^2 = 1.25 J */
    mcs_hyst_update(&m, &s, 0.0175);
    CHECK_REL(mcs_hyst_stored(&m, &s), 1.25, 1e-12);
    CHECK_REL(s.work, 15.0 + 1.25, 1e-12);
    mcs_hyst_update(&m, &s, xm);
    mcs_hyst_update(&m, &s, 0.0);
    CHECK_REL(s.work, 15.0, 1e-12);
    CHECK_REL(mcs_hyst_dissipated(&m, &s), 15.0, 1e-12);

    /* nonlinear loading (0,0) (0.01,1000) (0.03,2000), unloading slope 2e5 from 0.03:
     * set 0.03 - 2000/2e5 = 0.02; area under loading 0.5*1000*0.01 + 0.5*3000*0.02 = 35 J,
     * under unloading 0.5*2000*0.01 = 10 J: 25 J dissipated in the cycle */
    const double xy[][2] = {{0, 0}, {0.01, 1000}, {0.03, 2000}};
    mcs_curve *N = mk(3, xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model mn = {.loading = N, .unload = MCS_UNLOAD_SLOPE, .unload_slope = 2e5};
    mcs_hyst_reset(&mn, &s);
    mcs_hyst_update(&mn, &s, 0.03);
    CHECK_NEAR(s.x_set, 0.02, 1e-15);
    mcs_hyst_update(&mn, &s, 0.0);
    CHECK_REL(s.work, 25.0, 1e-12);
    CHECK_REL(mcs_hyst_dissipated(&mn, &s), 25.0, 1e-12);
    mcs_curve_destroy(&L);
    mcs_curve_destroy(&N);
}

/* reloading follows the unloading path until it meets the loading curve, then the loading curve */
static void test_reload_along_unloading_path(void)
{
    mcs_curve *L = mk(2, lin_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model m = {.loading = L, .unload = MCS_UNLOAD_SLOPE, .unload_slope = k2};
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    mcs_hyst_update(&m, &s, 0.02);
    mcs_hyst_update(&m, &s, 0.016); /* partial unload, not to zero */
    for (int i = 0; i <= 60; i++) {
        double x = 0.016 + 0.0001 * i; /* up to 0.022 */
        double f = mcs_hyst_update(&m, &s, x);
        double expect = x <= 0.02 ? 2000 - k2 * (0.02 - x) : k1 * x;
        CHECK_NEAR(f, expect, 1e-8);
    }
    /* new maximum 0.022: new set 0.022 - 2200/4e5 = 0.0165 */
    CHECK_NEAR(s.x_set, 0.0165, 1e-15);
    /* mcs_hyst_force does not change the state */
    mcs_hyst_state before = s;
    CHECK_NEAR(mcs_hyst_force(&m, &s, 0.03), 3000, 1e-9);
    CHECK(memcmp(&before, &s, sizeof s) == 0);
    /* a NaN deflection gives NaN and leaves the history alone */
    CHECK(isnan(mcs_hyst_update(&m, &s, NAN)));
    CHECK(memcmp(&before, &s, sizeof s) == 0);
    mcs_curve_destroy(&L);
}

/* below the elastic limit the element unloads along the loading curve: no set, no loss */
static void test_elastic_limit(void)
{
    mcs_curve *L = mk(2, lin_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model m = {
        .loading = L, .unload = MCS_UNLOAD_SLOPE, .unload_slope = k2, .elastic_limit = 0.01};
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    for (int cycle = 0; cycle < 3; cycle++) {
        mcs_hyst_update(&m, &s, 0.008);
        CHECK_NEAR(mcs_hyst_update(&m, &s, 0.004), 400, 1e-9); /* on the loading line */
        mcs_hyst_update(&m, &s, 0.0);
    }
    CHECK(s.x_set == 0);
    CHECK_NEAR(s.work, 0, 1e-12);
    CHECK_NEAR(mcs_hyst_dissipated(&m, &s), 0, 1e-12);
    /* exactly at the limit: still elastic */
    mcs_hyst_update(&m, &s, 0.01);
    mcs_hyst_update(&m, &s, 0.0);
    CHECK_NEAR(s.work, 0, 1e-12);
    /* beyond: plastic, set 0.012 - 1200/4e5 = 0.009, loss 1200^2/2e5 - 1200^2/8e5 = 5.4 J */
    mcs_hyst_update(&m, &s, 0.012);
    CHECK_NEAR(s.x_set, 0.009, 1e-15);
    mcs_hyst_update(&m, &s, 0.0);
    CHECK_REL(s.work, 5.4, 1e-12);
    /* fully elastic: elastic_limit = INFINITY */
    mcs_hyst_model me = m;
    me.elastic_limit = INFINITY;
    mcs_hyst_reset(&me, &s);
    mcs_hyst_update(&me, &s, 0.05);
    mcs_hyst_update(&me, &s, 0.0);
    CHECK_NEAR(s.work, 0, 1e-12);
    mcs_curve_destroy(&L);
}

/* MCS_UNLOAD_CURVE: G scaled uniformly by s = F_max / G(u_e) and shifted to end at the maximum.
 * G: (0,0) (0.01,100) (0.02,1000). Loading k = 1e4 to x_max = 0.05: F = 500 N, s = 0.5,
 * U(x) = 0.5 G(0.02 + 2 (x - 0.05)): zero at 0.04, kink at 0.045 (U = 50), 500 at 0.05.
 * Area under U = s^2 * area under G = 0.25 * (0.5 + 5.5) = 1.5 J; under loading 12.5 J:
 * 11 J dissipated. */
static void test_unload_curve_scaled(void)
{
    const double lxy[][2] = {{0, 0}, {0.01, 100}};
    const double gxy[][2] = {{0, 0}, {0.01, 100}, {0.02, 1000}};
    mcs_curve *L = mk(2, lxy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *G = mk(3, gxy, MCS_EXTRAP_CONSTANT, MCS_EXTRAP_LINEAR);
    mcs_hyst_model m = {.loading = L, .unloading = G, .unload = MCS_UNLOAD_CURVE};
    mcs_error e;
    mcs_error_clear(&e);
    CHECK(mcs_hyst_model_check(&m, "pad", &e) == MCS_OK);
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    mcs_hyst_update(&m, &s, 0.05);
    CHECK_NEAR(s.x_set, 0.04, 1e-15);
    CHECK_NEAR(mcs_hyst_force(&m, &s, 0.045), 50, 1e-9);
    CHECK_NEAR(mcs_hyst_force(&m, &s, 0.0475), 0.5 * (100 + 900 * 0.5), 1e-9);
    CHECK_NEAR(mcs_hyst_stiffness(&m, &s, 0.0475), 9e4, 1e-6); /* G's slope is kept */
    CHECK_REL(mcs_hyst_stored(&m, &s), 1.5, 1e-12);
    mcs_hyst_update(&m, &s, 0.0);
    CHECK_REL(s.work, 11.0, 1e-12);
    CHECK_REL(mcs_hyst_dissipated(&m, &s), 11.0, 1e-12);

    /* a straight G of slope k2 is the same as MCS_UNLOAD_SLOPE, on any history */
    const double gl[][2] = {{0, 0}, {0.001, 0.001 * k2}};
    mcs_curve *GL = mk(2, gl, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *K1 = mk(2, lin_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model mc = {.loading = K1, .unloading = GL, .unload = MCS_UNLOAD_CURVE};
    mcs_hyst_model ms = {.loading = K1, .unload = MCS_UNLOAD_SLOPE, .unload_slope = k2};
    mcs_hyst_state sc, ss;
    mcs_hyst_reset(&mc, &sc);
    mcs_hyst_reset(&ms, &ss);
    double x = 0;
    for (int i = 0; i < 2000; i++) {
        x += 0.001 * sin(0.01 * i * i) + 0.00002;
        CHECK_NEAR(mcs_hyst_update(&mc, &sc, x), mcs_hyst_update(&ms, &ss, x), 1e-8);
    }
    CHECK_REL(sc.work, ss.work, 1e-12);
    /* validation: G must end at a positive force */
    const double g0[][2] = {{0, 0}, {0.01, 0}};
    mcs_curve *G0 = mk(2, g0, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model bad = {.loading = L, .unloading = G0, .unload = MCS_UNLOAD_CURVE};
    CHECK(mcs_hyst_model_check(&bad, "pad", &e) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e.msg, "pad: the unloading curve must end at a positive force");
    mcs_curve_destroy(&L);
    mcs_curve_destroy(&G);
    mcs_curve_destroy(&GL);
    mcs_curve_destroy(&K1);
    mcs_curve_destroy(&G0);
}

static void test_model_check(void)
{
    mcs_curve *L = mk(2, lin_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_error e;
    mcs_hyst_model m = {.loading = NULL};
    mcs_error_clear(&e);
    CHECK(mcs_hyst_model_check(&m, "knee", &e) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(e.msg, "knee: a loading curve is required");
    m = (mcs_hyst_model){.loading = L, .unload = MCS_UNLOAD_SLOPE, .unload_slope = -3};
    mcs_error_clear(&e);
    CHECK(mcs_hyst_model_check(&m, "knee", &e) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e.msg, "unloading slope -3");
    m = (mcs_hyst_model){.loading = L, .unload = MCS_UNLOAD_SLOPE_CURVE, .unload_slope = 1};
    mcs_error_clear(&e);
    CHECK(mcs_hyst_model_check(&m, "knee", &e) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(e.msg, "unloading curve is required");
    m = (mcs_hyst_model){.loading = L, .elastic_limit = -1};
    mcs_error_clear(&e);
    CHECK(mcs_hyst_model_check(&m, "knee", &e) == MCS_ERR_RANGE);
    mcs_hyst2_model j = {.pos = {.loading = L}, .neg = {.loading = NULL}};
    mcs_error_clear(&e);
    CHECK(mcs_hyst2_model_check(&j, "neck", &e) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(e.msg, "neck (negative side): a loading curve is required");
    /* damping helper (thesis §3.1, F = k x + d xdot): a contact never pulls */
    CHECK_NEAR(mcs_hyst_damped(100, 50, 1.0, 1), 150, 0);
    CHECK_NEAR(mcs_hyst_damped(100, 50, -3.0, 1), 0, 0);
    CHECK_NEAR(mcs_hyst_damped(100, 50, -3.0, 0), -50, 0);
    mcs_curve_destroy(&L);
}

/* The fork of the paper's Fig. 7 (numbers ours, the shape theirs): moment M_def vs. rearward
 * deflection angle phi. Elastic k_e = 2000 N m/rad up to phi_e = 0.05 rad (100 N m), plastic
 * plateau rising to 120 N m at 0.3 rad, then a stop (wheel against the frame) of 5e4 N m/rad.
 * Unloading parallel to the elastic slope (MCS_UNLOAD_SLOPE, k = k_e). */
static const double fork_xy[][2] = {{0, 0}, {0.05, 100}, {0.3, 120}, {0.32, 1120}};

static void test_fork_fig7(void)
{
    mcs_curve *M = mk(4, fork_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model m = {
        .loading = M, .unload = MCS_UNLOAD_SLOPE, .unload_slope = 2000, .elastic_limit = 0.05};
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    /* a: elastic cycle to 0.04 rad: back to zero, nothing lost */
    mcs_hyst_update(&m, &s, 0.04);
    mcs_hyst_update(&m, &s, 0.0);
    CHECK_NEAR(s.work, 0, 1e-12);
    CHECK(s.x_set == 0);
    /* b: plastic to 0.2 rad: M = 100 + 20 * 0.15/0.25 = 112, set 0.2 - 112/2000 = 0.144;
     * unloading stiffness is the elastic one; loss = int_0^0.2 M - 112 * 0.056 / 2
     * = (2.5 + 0.15 * 106) - 3.136 = 15.264 J */
    for (int i = 1; i <= 200; i++)
        mcs_hyst_update(&m, &s, 0.001 * i);
    CHECK_NEAR(s.force, 112, 1e-9);
    CHECK_NEAR(s.x_set, 0.144, 1e-14);
    mcs_hyst_update(&m, &s, 0.18);
    CHECK_NEAR(mcs_hyst_stiffness(&m, &s, 0.18), 2000, 1e-9);
    CHECK_NEAR(s.force, 112 - 2000 * 0.02, 1e-9);
    for (int i = 180; i >= 0; i--)
        mcs_hyst_update(&m, &s, 0.001 * i);
    CHECK_REL(s.work, 15.264, 1e-12);
    /* c: into the stop, to 0.31 rad (M = 620). The lowest line of slope 2000 through any plastic
     * point is through the stop's start (0.3, 120): line 2000 phi - 480, zero at 0.24. Unloading
     * goes down the stop (elastic, 5e4) to 0.3, then parallel to the elastic slope to 0.24: the
     * fork stays blocked near the stop, with the elastic restitution (MYMOSA). The stop's energy
     * is returned; loss = int_0^0.3 M - 120 * 0.06 / 2 = (2.5 + 27.5) - 3.6 = 26.4 J. */
    for (int i = 1; i <= 310; i++)
        mcs_hyst_update(&m, &s, 0.001 * i);
    CHECK_NEAR(s.force, 620, 1e-8);
    CHECK_NEAR(s.x_set, 0.24, 1e-12);
    CHECK_NEAR(mcs_hyst_update(&m, &s, 0.305), 370, 1e-8); /* on the stop */
    CHECK_NEAR(mcs_hyst_stiffness(&m, &s, 0.305), 5e4, 1e-6);
    CHECK_NEAR(mcs_hyst_update(&m, &s, 0.27), 60, 1e-8); /* parallel to elastic */
    mcs_hyst_update(&m, &s, 0.0);
    CHECK_REL(s.work, 26.4, 1e-12);
    CHECK_REL(mcs_hyst_dissipated(&m, &s), 26.4, 1e-12);
    /* reloading: along 2000 phi - 480 to 0.3, then up the stop */
    CHECK_NEAR(mcs_hyst_update(&m, &s, 0.29), 100, 1e-8);
    CHECK_NEAR(mcs_hyst_update(&m, &s, 0.315), 870, 1e-8);
    mcs_curve_destroy(&M);
}

/* MCS_UNLOAD_SLOPE_CURVE (the paper's words for Fig. 7: "unloading is first parallel to the
 * hysteresis slope and then along M_def,unloading"). G absolute: 0 up to 0.1 rad, then 200 N m/rad.
 * From phi_max = 0.25 (M = 116): the line 116 - 2000 (0.25 - phi) meets G = 200 (phi - 0.1) at
 * phi_c = 364/1800; then G down to 0 at 0.1 (the set). */
static void test_slope_then_curve(void)
{
    const double gxy[][2] = {{0.1, 0}, {0.3, 40}};
    mcs_curve *M = mk(4, fork_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *G = mk(2, gxy, MCS_EXTRAP_CONSTANT, MCS_EXTRAP_LINEAR);
    mcs_hyst_model m = {.loading = M,
                        .unloading = G,
                        .unload = MCS_UNLOAD_SLOPE_CURVE,
                        .unload_slope = 2000,
                        .elastic_limit = 0.05};
    mcs_error e;
    mcs_error_clear(&e);
    CHECK(mcs_hyst_model_check(&m, "fork", &e) == MCS_OK);
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    for (int i = 1; i <= 250; i++)
        mcs_hyst_update(&m, &s, 0.001 * i);
    const double pc = 364.0 / 1800.0, gc = 200 * (pc - 0.1);
    CHECK_NEAR(s.x_set, 0.1, 1e-14);
    CHECK_NEAR(mcs_hyst_force(&m, &s, 0.22), 116 - 2000 * 0.03, 1e-9); /* on the line */
    CHECK_NEAR(mcs_hyst_force(&m, &s, pc), gc, 1e-9);
    CHECK_NEAR(mcs_hyst_force(&m, &s, 0.15), 10, 1e-9); /* on G */
    CHECK_NEAR(mcs_hyst_stiffness(&m, &s, 0.15), 200, 1e-9);
    /* loss = int_0^0.25 M - (line area + G area)
     * int_0^0.25 M = 2.5 + 0.2 * (100 + 116)/2 = 24.1; line: (gc + 116)/2 * (0.25 - pc);
     * G: gc/2 * (pc - 0.1) */
    double loss = 24.1 - 0.5 * (gc + 116) * (0.25 - pc) - 0.5 * gc * (pc - 0.1);
    for (int i = 249; i >= 0; i--)
        mcs_hyst_update(&m, &s, 0.001 * i);
    CHECK_REL(s.work, loss, 1e-12);
    CHECK_REL(mcs_hyst_dissipated(&m, &s), loss, 1e-12);
    mcs_curve_destroy(&M);
    mcs_curve_destroy(&G);
}

static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (double)(*s >> 8) / (double)(1u << 24);
}

/* work (accumulated step by step) = stored + dissipated (functions of the state alone) at every
 * step of a random walk, to 1e-9 relative; the exact work integral does not depend on how a
 * motion is cut into steps; dissipation never decreases for the slope rules and is >= 0 */
static void random_walk(const mcs_hyst_model *m, double scale, unsigned seed, int nsteps)
{
    mcs_hyst_state s, fine;
    mcs_hyst_reset(m, &s);
    mcs_hyst_reset(m, &fine);
    double x = 0, dprev = 0, worst = 0;
    int bad_balance = 0, bad_dis = 0, bad_split = 0, bad_set = 0;
    for (int i = 0; i < nsteps; i++) {
        /* growing cycles from a gap (x < 0) to new maxima, with random jitter and reversals */
        double env = 1.2 * scale * (i + 1) / nsteps;
        x = env * (0.55 - 0.65 * cos(0.021 * i)) + 0.02 * scale * (rnd(&seed) - 0.5);
        double x0 = s.x;
        mcs_hyst_update(m, &s, x);
        for (int k = 1; k <= 7; k++)
            mcs_hyst_update(m, &fine, x0 + (x - x0) * k / 7.0);
        double st = mcs_hyst_stored(m, &s), dis = mcs_hyst_dissipated(m, &s);
        double ref = fmax(fabs(s.work), 1e-3 * scale * mcs_curve_eval(m->loading, scale));
        double err = fabs(s.work - (st + dis)) / ref;
        if (err > worst) worst = err;
        /* docs/hysteresis.md: below 1e-12 on 2000 steps, 1e-11 on the 20000 of make verify
         * (the summed work's round-off grows with the number of steps) */
        if (err > (nsteps > 2000 ? 1e-11 : 1e-12)) bad_balance++;
        if (dis < -1e-12 * ref || st < -1e-12 * ref) bad_dis++;
        if (m->unload != MCS_UNLOAD_CURVE && dis < dprev - 1e-9 * ref) bad_dis++;
        if (fabs(fine.work - s.work) > 1e-9 * ref) bad_split++;
        /* the permanent set is where the path reaches zero: no force there, force just above */
        double fs = mcs_hyst_force(m, &s, s.x_set), dx = 1e-6 * scale;
        if (fs > 1e-9 * s.f_max) bad_set++;
        if (s.x_set + dx < s.x_max && !(mcs_hyst_force(m, &s, s.x_set + dx) > 0)) bad_set++;
        if (s.x_set - dx > 0 && mcs_hyst_force(m, &s, s.x_set - dx) != 0) bad_set++;
        dprev = dis;
    }
    CHECK(bad_balance == 0);
    CHECK(bad_dis == 0);
    CHECK(bad_split == 0);
    CHECK(bad_set == 0);
    if (bad_balance || getenv("MCRASH_TEST_VERBOSE"))
        fprintf(stderr,
                "random walk (rule %d): worst |W - S - D|/W = %.3g, final W %.6g J, D %.6g J\n",
                (int)m->unload, worst, s.work, mcs_hyst_dissipated(m, &s));
}

static void test_work_balance_random_walk(void)
{
    const double nxy[][2] = {{0, 0}, {0.01, 1000}, {0.03, 2000}, {0.035, 6000}};
    const double gxy[][2] = {{0, 0}, {0.001, 100}, {0.002, 1000}};
    const double g2[][2] = {{0.1, 0}, {0.3, 40}};
    mcs_curve *N = mk(4, nxy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *G = mk(3, gxy, MCS_EXTRAP_CONSTANT, MCS_EXTRAP_LINEAR);
    mcs_curve *M = mk(4, fork_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_curve *G2 = mk(2, g2, MCS_EXTRAP_CONSTANT, MCS_EXTRAP_LINEAR);
    mcs_hyst_model ms = {
        .loading = N, .unload = MCS_UNLOAD_SLOPE, .unload_slope = 3e5, .elastic_limit = 0.005};
    mcs_hyst_model mc = {
        .loading = N, .unloading = G, .unload = MCS_UNLOAD_CURVE, .elastic_limit = 0.004};
    mcs_hyst_model mf = {
        .loading = M, .unload = MCS_UNLOAD_SLOPE, .unload_slope = 2000, .elastic_limit = 0.05};
    mcs_hyst_model mb = {.loading = M,
                         .unloading = G2,
                         .unload = MCS_UNLOAD_SLOPE_CURVE,
                         .unload_slope = 2000,
                         .elastic_limit = 0.05};
    mcs_hyst_model me = {.loading = N, .unload = MCS_UNLOAD_ELASTIC};
    /* free play: no force up to 0.1 rad, then a stiff restraint */
    const double fp[][2] = {{0, 0}, {0.1, 0}, {0.2, 1000}};
    mcs_curve *FP = mk(3, fp, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model mp = {.loading = FP, .unload = MCS_UNLOAD_SLOPE, .unload_slope = 1.5e4};
    mcs_hyst_model mp2 = {
        .loading = FP, .unloading = G2, .unload = MCS_UNLOAD_SLOPE_CURVE, .unload_slope = 1.5e4};
    int n = th_verify() ? 20000 : 2000;
    random_walk(&ms, 0.035, 1, n);
    random_walk(&mc, 0.035, 2, n);
    random_walk(&mf, 0.31, 3, n);
    random_walk(&mb, 0.31, 4, n);
    random_walk(&me, 0.035, 5, n);
    random_walk(&mp, 0.25, 6, n);
    random_walk(&mp2, 0.25, 7, n);
    mcs_curve_destroy(&FP);
    mcs_curve_destroy(&N);
    mcs_curve_destroy(&G);
    mcs_curve_destroy(&M);
    mcs_curve_destroy(&G2);
}

/* the two-sided joint with the same branch on both sides is odd-symmetric: F(-x) = -F(x) for the
 * mirrored history, with equal energies; the branches keep independent histories */
static void test_bidirectional_joint(void)
{
    mcs_curve *M = mk(4, fork_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model b = {
        .loading = M, .unload = MCS_UNLOAD_SLOPE, .unload_slope = 2000, .elastic_limit = 0.05};
    mcs_hyst2_model j = {.pos = b, .neg = b};
    mcs_error e;
    mcs_error_clear(&e);
    CHECK(mcs_hyst2_model_check(&j, "steering", &e) == MCS_OK);
    mcs_hyst2_state sp, sn;
    mcs_hyst2_reset(&j, &sp);
    mcs_hyst2_reset(&j, &sn);
    unsigned seed = 7;
    double x = 0;
    int bad = 0;
    for (int i = 0; i < 3000; i++) {
        x += 0.02 * (rnd(&seed) - 0.5);
        double fp = mcs_hyst2_update(&j, &sp, x), fn = mcs_hyst2_update(&j, &sn, -x);
        if (fabs(fp + fn) > 1e-9 * (1 + fabs(fp))) bad++;
        if (fabs(mcs_hyst2_stiffness(&j, &sp, x) - mcs_hyst2_stiffness(&j, &sn, -x)) > 1e-6) bad++;
        double w = mcs_hyst2_work(&sp);
        if (fabs(w - mcs_hyst2_work(&sn)) > 1e-9 * (1 + fabs(w))) bad++;
        if (fabs(w - mcs_hyst2_stored(&j, &sp) - mcs_hyst2_dissipated(&j, &sp)) > 1e-9 * (1 + w))
            bad++;
    }
    CHECK(bad == 0);
    /* independent branches: bend to +0.2 (set 0.144), then to -0.2: the negative side starts
     * from its own virgin curve at 0; between 0 and the positive set there is no torque */
    mcs_hyst2_reset(&j, &sp);
    mcs_hyst2_update(&j, &sp, 0.2);
    CHECK_NEAR(sp.pos.x_set, 0.144, 1e-14);
    CHECK(mcs_hyst2_update(&j, &sp, 0.1) == 0);
    CHECK_NEAR(mcs_hyst2_update(&j, &sp, -0.02), -40, 1e-9);
    CHECK_NEAR(mcs_hyst2_update(&j, &sp, -0.2), -112, 1e-9);
    CHECK_NEAR(sp.neg.x_set, 0.144, 1e-14);
    CHECK_NEAR(sp.pos.x_set, 0.144, 1e-14);
    mcs_curve_destroy(&M);
}

/* free play (zero force up to 0.1 rad) then 1e4 N m/rad.
 * k = 2e4 from 0.15 (500 N m): set 0.15 - 500/2e4 = 0.125, outside the free play.
 * k = 5000, below the restraint's 1e4: like a stop, the restraint is steeper than the unloading
 * slope, so it is elastic: the anchor is where it starts (0.1, 0), the path is F_L above it,
 * the set is 0.1 and a cycle dissipates nothing. Beyond the last point (0.25, 1500 N m,
 * extrapolated) with k = 2e4: 0.25 - 1500/2e4 = 0.175. */
static void test_free_play_set(void)
{
    const double fp[][2] = {{0, 0}, {0.1, 0}, {0.2, 1000}};
    mcs_curve *FP = mk(3, fp, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model m = {.loading = FP, .unload = MCS_UNLOAD_SLOPE, .unload_slope = 2e4};
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    mcs_hyst_update(&m, &s, 0.15);
    CHECK_NEAR(s.x_set, 0.125, 1e-14);
    CHECK_NEAR(mcs_hyst_force(&m, &s, 0.14), 300, 1e-9);
    mcs_hyst_update(&m, &s, 0.0);
    CHECK_REL(s.work, 0.5 * 500 * 0.05 - 0.5 * 500 * 0.025, 1e-12); /* 6.25 J */
    m.unload_slope = 5000;
    mcs_hyst_reset(&m, &s);
    mcs_hyst_update(&m, &s, 0.15);
    CHECK_NEAR(s.x_anchor, 0.1, 1e-15);
    CHECK_NEAR(s.x_set, 0.1, 1e-14);
    CHECK_NEAR(mcs_hyst_force(&m, &s, 0.12), 200, 1e-9);
    mcs_hyst_update(&m, &s, 0.0);
    CHECK_NEAR(s.work, 0, 1e-12);
    m.unload_slope = 2e4;
    mcs_hyst_reset(&m, &s);
    mcs_hyst_update(&m, &s, 0.25);
    CHECK_NEAR(s.x_set, 0.175, 1e-14);
    mcs_curve_destroy(&FP);
}

/* follow_set (kinematic shift): a permanent set on one side moves the other side's origin to
 * it, so the bent joint is elastic about its set. Fork curve (2000 N m/rad to 0.05 rad, then
 * 80 N m/rad), unloading 2000: bend to 0.2 rad (M = 112, set 0.2 - 112/2000 = 0.144); at 0.1
 * the negative side is 0.044 rad into its virgin curve (-88 N m; independent branches give 0
 * here); back to 0: 0.144 rad deep, M = 100 + 80 * 0.094 = 107.52, set 0.144 - 0.05376 =
 * 0.08824, which moves the positive origin to 0.144 - 0.08824 = 0.05576: 0.01 beyond it is the
 * virgin 2000 * 0.01 = 20 N m. Work = stored + dissipated on a random walk. */
static void test_follow_set(void)
{
    mcs_curve *M = mk(4, fork_xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR);
    mcs_hyst_model b = {
        .loading = M, .unload = MCS_UNLOAD_SLOPE, .unload_slope = 2000, .elastic_limit = 0.05};
    mcs_hyst2_model j = {.pos = b, .neg = b, .follow_set = 1};
    mcs_hyst2_state s;
    mcs_hyst2_reset(&j, &s);
    CHECK_NEAR(mcs_hyst2_update(&j, &s, 0.2), 112, 1e-9);
    CHECK_NEAR(s.o_neg, 0.144, 1e-14);
    CHECK_NEAR(mcs_hyst2_update(&j, &s, 0.1), -88, 1e-9);
    CHECK_NEAR(mcs_hyst2_force(&j, &s, 0.144), 0, 1e-9);
    CHECK_NEAR(mcs_hyst2_update(&j, &s, 0.0), -107.52, 1e-9);
    CHECK_NEAR(s.o_pos, 0.144 - (0.144 - 107.52 / 2000), 1e-14);
    CHECK_NEAR(mcs_hyst2_update(&j, &s, s.o_pos + 0.01), 20, 1e-9);
    CHECK_NEAR(mcs_hyst2_stiffness(&j, &s, s.o_pos + 0.01), 2000, 1e-9);
    /* energy identity along a random history */
    mcs_hyst2_reset(&j, &s);
    unsigned seed = 11;
    double x = 0;
    int bad = 0, moved = 0;
    for (int i = 0; i < 4000; i++) {
        double op = s.o_pos, on = s.o_neg;
        x += 0.03 * (rnd(&seed) - 0.5);
        mcs_hyst2_update(&j, &s, x);
        moved += op != s.o_pos || on != s.o_neg;
        double w = mcs_hyst2_work(&s);
        if (fabs(w - mcs_hyst2_stored(&j, &s) - mcs_hyst2_dissipated(&j, &s)) > 1e-12 * (1 + w))
            bad++;
    }
    FIG("hysteresis.follow_set_moves", "%.0f", (double)moved);
    printf("  follow_set: %d origin moves on the random walk, energy identity broken %d times\n",
           moved, bad);
    CHECK(moved > 2);
    CHECK(bad == 0);
    mcs_curve_destroy(&M);
}

int main(void)
{
    RUN(test_loading_follows_curve);
    RUN(test_unload_slope_permanent_set);
    RUN(test_closed_cycle_energy);
    RUN(test_reload_along_unloading_path);
    RUN(test_elastic_limit);
    RUN(test_unload_curve_scaled);
    RUN(test_model_check);
    RUN(test_fork_fig7);
    RUN(test_slope_then_curve);
    RUN(test_work_balance_random_walk);
    RUN(test_bidirectional_joint);
    RUN(test_follow_set);
    RUN(test_free_play_set);
    TEST_END();
}

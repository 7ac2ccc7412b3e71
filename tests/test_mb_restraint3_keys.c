/* test_mb_restraint3_keys.c: per-axis neutral angle and preload of spherical and universal joint
 * restraints (scenario keys neutral: [..], preload: [..]; mb_restraint3, docs/joints.md) and
 * their channels <joint>_angle_{x,y,z} / <joint>_moment_{x,y,z}, against closed forms.
 *
 * Angles are the rotation-vector components theta_i of the child relative to the parent since
 * the initial posture, on the restraint axes (spherical: the parent's x, y, z; universal:
 * axis, axis2). For a rotation about one axis alone theta_i is that rotation's angle and the
 * restraint torque about the axis is exactly g_i = P_i + k (theta_i - n_i) + d dtheta_i/dt. */
#include "core/mcs_results.h"
#include "harness.h"
#include "tests/mb_test_util.h"
#include "stage1_mb/mb_model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- static deflection under a gravity moment ---- */

/* An arm of mass m = 2 kg with its CG d = 0.1 m from a spherical joint, gravity g = 9.81:
 * arm along +x gives the gravity moment W d cos(theta) about +y (W d = 1.962 N m), arm along
 * -y the same about +x. Restraint k = 20 N m/rad, damper 1.5 N m s/rad (near critical on the
 * 0.03 kg m^2 arm), top-out kT = 2000 N m/rad on the negative side; settled over 1 s.
 * Equilibrium on the loaded axis: P + F_h(theta - n) = W d cos(theta). */
static double settled(const char *arm, const char *keys, int axis, double *other, double *zero,
                      double *drift)
{
    char y[2000];
    snprintf(y, sizeof y,
             "mcrash: 1\n"
             "simulation: {end_time: 1 s, time_step: 100 us}\n"
             "environment: {gravity: 9.81 m/s^2}\n"
             "characteristics:\n"
             "  k: {type: moment, loading: [[0, 0], [0.1, 2]], damping: 1.5}\n"
             "  topout: {type: moment, loading: [[0, 0], [0.001, 2]]}\n"
             "bodies:\n"
             "  - {name: arm, mass: 2, inertia: [0.01, 0.01, 0.01], position: %s, velocity: [0, 0, 0]}\n"
             "joints:\n"
             "  - {name: neck, type: spherical, parent: ground, child: arm, anchor: [0, 0, 1],\n"
             "     restraint: k, restraint_negative: topout, %s}\n",
             arm, keys);
    mcs_error err = {0};
    mb_model *m = mt_model_text("r3.yaml", y, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL);
    if (!m) return NAN;
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    while (s && s->step < m->nsteps && mb_step(m, s, &err) == MCS_OK) {
    }
    if (err.status) fprintf(stderr, "%s\n", err.msg);
    CHECK(s && s->step == m->nsteps);
    double th = s ? s->r3[0].theta[axis] : NAN;
    *other = 0;
    for (int k = 0; s && k < 3; k++)
        if (k != axis) *other = fmax(*other, fabs(s->r3[0].theta[k]));
    *zero = m->restraint3[0].zero[axis];
    *drift = s ? mb_energy_drift(m, s) : NAN;
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    return th;
}

/* solve P + k (t - n) = Wd cos t (t > n) or P - kT (n - t) = Wd cos t (t < n) by Newton */
static double equilibrium(double P, double n, double k, double kT, double Wd)
{
    double t = 0;
    for (int i = 0; i < 50; i++) {
        double kk = t >= n ? k : kT;
        double f = P + kk * (t - n) - Wd * cos(t), df = kk + Wd * sin(t);
        t -= f / df;
    }
    return t;
}

static void test_preload_gravity(void)
{
    const double Wd = 2 * 9.81 * 0.1, k = 20, kT = 2000;
    double other, zero, drift;
    /* (a) P = 0.5 N m about y, neutral given as 0: k theta + P = Wd cos theta, ~(Wd - P)/k */
    double t = settled("[0.1, 0, 1]", "preload: [0, 0.5 N*m, 0], neutral: [0, 0, 0]", 1, &other,
                       &zero, &drift);
    double te = equilibrium(0.5, 0, k, kT, Wd);
    printf("  preload 0.5 N m, neutral 0: theta_y %.7f rad (exact %.7f, small-angle (Wd - P)/k "
           "= %.7f), others %.1e, energy drift %.1e\n",
           t, te, (Wd - 0.5) / k, other, drift);
    CHECK_NEAR(t, te, 1e-6);
    CHECK(other < 1e-9);
    CHECK(zero == 0);
    CHECK(drift < 3e-3); /* the step's shadow energy, O(w h) = 2.6e-3 (w = 26 rad/s, h = 1e-4) */
    /* (b) the same about x (arm along -y): the preload acts per axis */
    t = settled("[0, -0.1, 1]", "preload: [0.5 N*m, 0, 0], neutral: [0, 0, 0]", 0, &other, &zero,
                &drift);
    printf("  same about x: theta_x %.7f rad (exact %.7f)\n", t, te);
    CHECK_NEAR(t, te, 1e-6);
    CHECK(other < 1e-9);
    /* (c) P = 3 N m > Wd, default neutral: the zero at N^-1(P) = P/kT; the spring is held by
     * its top-out, so the arm only compresses the top-out: kT theta = Wd cos theta */
    t = settled("[0.1, 0, 1]", "preload: [0, 3 N*m, 0]", 1, &other, &zero, &drift);
    te = equilibrium(3, 3 / kT, k, kT, Wd);
    printf("  preload 3 N m > W d, default neutral %.6f rad: theta_y %.4e rad (exact %.4e = "
           "Wd/kT to %.1e)\n",
           zero, t, te, fabs(te - Wd / kT));
    CHECK_NEAR(zero, 3 / kT, 1e-12);
    CHECK_NEAR(t, te, 1e-7);
    /* (d) P = 1 N m < Wd: past the top-out, theta = P/kT + (Wd cos theta - P)/k */
    t = settled("[0.1, 0, 1]", "preload: [0, 1 N*m, 0]", 1, &other, &zero, &drift);
    te = equilibrium(1, 1 / kT, k, kT, Wd);
    printf("  preload 1 N m < W d: theta_y %.7f rad (exact %.7f; small angle P/kT + (Wd - P)/k "
           "= %.7f)\n",
           t, te, 1 / kT + (Wd - 1) / k);
    CHECK_NEAR(t, te, 1e-6);
}

/* ---- neutral offset: oscillation about the neutral angle, period per axis ---- */

/* upward crossings of v(t) - c, linearly interpolated; returns the mean spacing */
static double mean_period(const double *v, size_t n, double dt, double c, int *ncross)
{
    double first = NAN, last = NAN;
    *ncross = 0;
    for (size_t i = 1; i < n; i++)
        if (v[i - 1] - c < 0 && v[i] - c >= 0) {
            double t = dt * ((double)i - 1 + (c - v[i - 1]) / (v[i] - v[i - 1]));
            if (!(*ncross)++) first = t;
            last = t;
        }
    return *ncross > 1 ? (last - first) / (*ncross - 1) : NAN;
}

/* Three bodies at rest on spherical joints through their CGs, no gravity, k = 10 N m/rad,
 * undamped, body i with neutral n = 0.05 rad on axis i only. The equation of motion about axis
 * i is I_i theta'' = -k (theta - n), theta(0) = 0, theta'(0) = 0:
 * theta = n (1 - cos w t), w = sqrt(k / I_i): the body swings about its neutral angle, with the
 * moment zero there, and the period is the small-angle pendulum's 2 pi sqrt(I_i / k).
 * Then two bodies on universal joints (axis = world x, axis2 = world y), neutral 0.05 rad on
 * axis and on axis2: periods 2 pi sqrt(Ixx / k) and 2 pi sqrt(Iyy / k). */
static const char *OSC =
    "mcrash: 1\n"
    "simulation: {end_time: 1 s, time_step: 20 us, output_rate: 50 kHz}\n"
    "environment: {gravity: 0}\n"
    "characteristics:\n"
    "  k: {type: moment, loading: [[0, 0], [1, 10]]}\n"
    "bodies:\n"
    "  - {name: bx, mass: 1, inertia: [0.02, 0.03, 0.05], position: [0, 0, 1], velocity: [0, 0, 0]}\n"
    "  - {name: by, mass: 1, inertia: [0.02, 0.03, 0.05], position: [1, 0, 1], velocity: [0, 0, 0]}\n"
    "  - {name: bz, mass: 1, inertia: [0.02, 0.03, 0.05], position: [2, 0, 1], velocity: [0, 0, 0]}\n"
    "  - {name: u1, mass: 1, inertia: [0.02, 0.03, 0.05], position: [3, 0, 1], velocity: [0, 0, 0]}\n"
    "  - {name: u2, mass: 1, inertia: [0.02, 0.03, 0.05], position: [4, 0, 1], velocity: [0, 0, 0]}\n"
    "joints:\n"
    "  - {name: sx, type: spherical, parent: ground, child: bx, anchor: [0, 0, 1], restraint: k,\n"
    "     neutral: [0.05 rad, 0, 0]}\n"
    "  - {name: sy, type: spherical, parent: ground, child: by, anchor: [1, 0, 1], restraint: k,\n"
    "     neutral: [0, 0.05 rad, 0]}\n"
    "  - {name: sz, type: spherical, parent: ground, child: bz, anchor: [2, 0, 1], restraint: k,\n"
    "     neutral: [0, 0, 0.05 rad]}\n"
    "  - {name: ua, type: universal, parent: ground, child: u1, anchor: [3, 0, 1], axis: [1, 0, 0],\n"
    "     axis2: [0, 1, 0], restraint: k, neutral: [0.05 rad, 0]}\n"
    "  - {name: ub, type: universal, parent: ground, child: u2, anchor: [4, 0, 1], axis: [1, 0, 0],\n"
    "     axis2: [0, 1, 0], restraint: k, neutral: [0, 0.05 rad]}\n";

static void test_neutral_and_periods(void)
{
    mcs_error err = {0};
    mb_model *m = mt_model_text("r3.yaml", OSC, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL);
    if (!m) return;
    const char *out = "/tmp/mcrash_test_r3_keys.h5";
    mb_run_opts o = {.out_path = out, .quiet = 1};
    mb_run_summary sum = {0};
    CHECK(mb_run(m, &o, &sum, &err) == MCS_OK);
    if (err.status) fprintf(stderr, "%s\n", err.msg);
    const double k = 10, n0 = 0.05, dt = 20e-6;
    static const char *const chan[5] = {"sx_angle_x", "sy_angle_y", "sz_angle_z", "ua_angle_x",
                                        "ub_angle_y"};
    static const char *const mom[5] = {"sx_moment_x", "sy_moment_y", "sz_moment_z", "ua_moment_x",
                                       "ub_moment_y"};
    const double I[5] = {0.02, 0.03, 0.05, 0.02, 0.03}; /* universal: axis = x, axis2 = y */
    for (int c = 0; c < 5; c++) {
        size_t n = 0, nm = 0;
        char unit[32] = "", unit2[32] = "";
        double *v = mt_read_channel(out, chan[c], &n, unit, NULL);
        double *g = mt_read_channel(out, mom[c], &nm, unit2, NULL);
        CHECK(v != NULL && g != NULL && n == nm && n > 1000);
        if (!v || !g) {
            free(v), free(g);
            continue;
        }
        CHECK(strcmp(unit, "rad") == 0 && strcmp(unit2, "N m") == 0);
        double w = sqrt(k / I[c]), Te = 2 * M_PI / w;
        /* the channel at sample i is theta before step i: time i dt - h, h = dt here */
        double worst = 0, gworst = 0, vmax = 0, vmin = 1;
        for (size_t i = 1; i < n; i++) {
            double t = dt * ((double)i - 1);
            worst = fmax(worst, fabs(v[i] - n0 * (1 - cos(w * t))));
            gworst = fmax(gworst, fabs(g[i] - k * (v[i] - n0)));
            vmax = fmax(vmax, v[i]), vmin = fmin(vmin, v[i]);
        }
        int nc = 0;
        double T = mean_period(v, n, dt, n0, &nc);
        printf("  %s: period %.6f s (2 pi sqrt(I/k) = %.6f, %d crossings), swing %.5f..%.5f rad "
               "about the neutral %.2f (max error %.1e rad), moment = k (theta - n) to %.1e\n",
               chan[c], T, Te, nc, vmin, vmax, n0, worst, gworst);
        CHECK(nc >= 3);
        CHECK_REL(T, Te, 1e-4);
        CHECK(worst < 1e-3 * n0); /* semi-implicit Euler: phase error O(w h), w h < 5e-4 */
        CHECK(gworst < 1e-9);
        CHECK_NEAR(vmin, 0, 1e-5);
        CHECK_NEAR(vmax, 2 * n0, 1e-5);
        free(v), free(g);
    }
    /* the other axes stay still; a universal joint writes no _z channel */
    size_t n = 0;
    char unit[32];
    double *v = mt_read_channel(out, "sx_angle_y", &n, unit, NULL), peak = 0;
    for (size_t i = 0; v && i < n; i++) peak = fmax(peak, fabs(v[i]));
    CHECK(v != NULL && peak < 1e-9);
    free(v);
    mcs_error none = {0};
    v = mt_read_channel(out, "ua_angle_z", &n, unit, &none);
    CHECK(v == NULL);
    free(v);
    printf("  energy drift of the five oscillators %.1e\n", sum.energy_drift);
    CHECK(sum.energy_drift < 1e-3);
    mb_model_destroy(&m);
    remove(out);
}

/* neutral and preload together: P = 2 N m with neutral 0.2 rad on k = 10 N m/rad gives
 * g(0) = P + k (0 - n) = 0: a free body (no gravity) stays at rest in its initial posture */
static void test_preload_cancels_at_neutral(void)
{
    const char *y =
        "mcrash: 1\n"
        "simulation: {end_time: 0.2 s, time_step: 100 us}\n"
        "environment: {gravity: 0}\n"
        "characteristics:\n"
        "  k: {type: moment, loading: [[0, 0], [1, 10]]}\n"
        "bodies:\n"
        "  - {name: b, mass: 1, inertia: [0.02, 0.03, 0.05], position: [0, 0, 1], velocity: [0, 0, 0]}\n"
        "joints:\n"
        "  - {name: j, type: spherical, parent: ground, child: b, anchor: [0, 0, 1], restraint: k,\n"
        "     neutral: [0, 0.2 rad, 0], preload: [0, 2 N*m, 0]}\n";
    mcs_error err = {0};
    mb_model *m = mt_model_text("r3.yaml", y, &err);
    CHECK(m != NULL);
    if (!m) return;
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    double worst = 0, gw = 0;
    while (s && s->step < m->nsteps && mb_step(m, s, &err) == MCS_OK)
        for (int k = 0; k < 3; k++)
            worst = fmax(worst, fabs(s->r3[0].theta[k])), gw = fmax(gw, fabs(s->r3[0].load[k]));
    printf("  preload 2 N m at neutral 0.2 rad: largest angle %.1e rad, moment %.1e N m\n", worst,
           gw);
    CHECK(s && s->step == m->nsteps);
    CHECK(worst < 1e-12 && gw < 1e-12);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* ---- bad input: located errors ---- */

static void test_errors(void)
{
    const char *head = "mcrash: 1\n"
                       "simulation: {end_time: 1 ms}\n"
                       "characteristics:\n"
                       "  k: {type: moment, loading: [[0, 0], [1, 10]]}\n"
                       "bodies:\n"
                       "  - {name: b, mass: 1, inertia: [0.02, 0.03, 0.05], position: [0, 0, 1], "
                       "velocity: [0, 0, 0]}\n"
                       "joints:\n";
    static const char *const bad[][2] = {
        {"  - {name: j, type: spherical, parent: ground, child: b, anchor: [0, 0, 1],\n"
         "     preload: [0, 1, 0]}\n",
         "preload needs a restraint"},
        {"  - {name: j, type: universal, parent: ground, child: b, anchor: [0, 0, 1],\n"
         "     axis: [0, 1, 0], axis2: [1, 0, 0], restraint: k, neutral: [0, 0, 0]}\n",
         "neutral"},
        {"  - {name: j, type: spherical, parent: ground, child: b, anchor: [0, 0, 1],\n"
         "     restraint: k, preload: [0, 1]}\n",
         "preload"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char y[1200];
        snprintf(y, sizeof y, "%s%s", head, bad[i][0]);
        mcs_error err = {0};
        mb_model *m = mt_model_text("r3.yaml", y, &err);
        CHECK(m == NULL);
        CHECK(err.status != MCS_OK);
        CHECK_STR_CONTAINS(err.msg, bad[i][1]);
        CHECK_STR_CONTAINS(err.msg, "r3.yaml:");
        printf("  refused: %s\n", err.msg);
        mb_model_destroy(&m);
    }
}

int main(void)
{
    RUN(test_preload_gravity);
    RUN(test_neutral_and_periods);
    RUN(test_preload_cancels_at_neutral);
    RUN(test_errors);
    TEST_END();
}

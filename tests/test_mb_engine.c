/* test_mb_engine.c: the stage-1 engine (stage1_mb/mb_model.h) against analytic answers.
 * Scenarios are in scenarios/verification/ (each says its numbers); time step h = 10 us unless
 * said. Tolerances are justified by the step: the ODE step is semi-implicit Euler (symplectic),
 * whose error in a contact of natural frequency w is of order w h (w h = 3.2e-3 for
 * k = 1e5 N/m, m = 1 kg, h = 10 us). */
#include "harness.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

static mb_model *load_model(const char *path)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mb_model *m = NULL;
    if (mcs_scenario_load(path, &scn, &err) || mb_model_build(scn, NULL, &m, &err))
        fprintf(stderr, "%s: %s\n", path, err.msg);
    mcs_scenario_destroy(&scn);
    return m;
}

/* the set-up every file case repeats: load the scenario and create its state (both checked);
 * NULL (and nothing to free) on failure */
static mb_model *start_run(const char *path, mb_state **s)
{
    mb_model *m = load_model(path);
    mcs_error err = {0};
    *s = NULL;
    CHECK(m != NULL);
    if (m) CHECK(mb_state_create(m, s, &err) == MCS_OK);
    if (m && !*s) mb_model_destroy(&m);
    return m;
}

static mb_model *load_text(const char *text, mcs_error *err)
{
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    if (mcs_scenario_load_text("test.yaml", text, strlen(text), &scn, err) == MCS_OK)
        mb_model_build(scn, NULL, &m, err);
    mcs_scenario_destroy(&scn);
    return m;
}

/* Elastic bounce: energy is conserved, so the ball climbs back to its drop height 0.5 m.
 * Errors: the free fall of semi-implicit Euler lowers the height by g h t / 2 per leg
 * (1.4e-5 m) and the contact's w h = 3.2e-3 error stays in the contact energy, which is zero
 * after separation up to O((w h)^2); 1e-4 m (2e-4 relative) bounds both. The legs' errors
 * cancel (the integrator is symplectic): 3e-07 m measured, asserted to 1e-6 m. */
static void test_elastic_bounce_returns_to_height(void)
{
    mb_state *s = NULL;
    mb_model *m = start_run("scenarios/verification/bounce_elastic.yaml", &s);
    if (!m) return;
    mcs_error err = {0};
    double zmin = 1, zmax_after = 0, fmax = 0;
    int touched = 0;
    while (s->step < m->nsteps) {
        CHECK(mb_step(m, s, &err) == MCS_OK);
        double z = s->kin[0].pos[2];
        if (z < zmin) zmin = z;
        if (s->pair[0].fn > fmax) fmax = s->pair[0].fn;
        if (s->pair[0].depth > 0) touched = 1;
        if (touched && s->pair[0].depth == 0 && z > zmax_after) zmax_after = z;
    }
    /* deepest point: m g (0.4 + d) = k d^2 / 2 -> d = (m g + sqrt((m g)^2 + 0.8 k m g)) / k */
    double mg = 9.81, k = 1e5;
    double d = (mg + sqrt(mg * mg + 0.8 * k * mg)) / k;
    CHECK_NEAR(0.1 - zmin, d, 2e-6 * d); /* 7e-7 measured */
    CHECK_NEAR(fmax, k * d, 2e-6 * k * d);
    CHECK_NEAR(zmax_after, 0.5, 1e-6);
    /* energy balance: the elastic case keeps total energy to 0.2 % of the largest energy */
    CHECK(mb_energy_drift(m, s) < 2e-3);
    FIG("stage1_engine.bounce_rebound_err_m", "%.0e", fabs(zmax_after - 0.5));
    FIG("stage1_engine.bounce_drift", "%.1e", mb_energy_drift(m, s));
    CHECK(s->e.dissipated == 0);
    CHECK(s->nrec == m->nout);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Damped bounce, m x'' + c x' + k x = 0 during contact with x the penetration and x(0) = 0,
 * x'(0) = v0: x = (v0 / wd) exp(-z w t) sin(wd t), w = sqrt(k / m), wd = w sqrt(1 - z^2).
 * Without the clamp the ball would leave at wd t = pi with the textbook restitution
 * e0 = exp(-z pi / sqrt(1 - z^2)) (e.g. Stronge, Impact Mechanics, 2000). The force
 * k x + c x' is clamped at 0 (a contact never pulls), so the ball leaves earlier, when
 * k x + c x' = 0: dividing by m v0 w exp(...): (w/wd)(1 - 2 z^2) sin(wd t) + 2 z cos(wd t) = 0,
 * tan(wd t*) = -2 z sqrt(1 - z^2) / (1 - 2 z^2), wd t* in (pi/2, pi) for z < 1/sqrt(2); then
 * e = -x'(t*) / v0 = -exp(-z w t*) (cos(wd t*) - z / sqrt(1 - z^2) sin(wd t*)), larger than e0.
 * After t* the force stays 0 (x keeps shrinking), so the exit speed is e v0. */
static void test_damped_bounce_matches_exact_solution(void)
{
    mb_state *s = NULL;
    mb_model *m = start_run("scenarios/verification/bounce_damped.yaml", &s);
    if (!m) return;
    mcs_error err = {0};
    double k = 1e5, mass = 1, z = 0.2, v0 = 2;
    double w = sqrt(k / mass), wd = w * sqrt(1 - z * z);
    double ts = (M_PI - atan(2 * z * sqrt(1 - z * z) / (1 - 2 * z * z))) / wd;
    double e = -exp(-z * w * ts) * (cos(wd * ts) - z / sqrt(1 - z * z) * sin(wd * ts));
    double e0 = exp(-z * M_PI / sqrt(1 - z * z));
    double t0 = -1, xmax = 0, err_x = 0;
    while (s->step < m->nsteps) {
        CHECK(mb_step(m, s, &err) == MCS_OK);
        double x = s->pair[0].depth;
        if (x > 0 && t0 < 0) t0 = s->t - x / v0; /* first touch, interpolated */
        if (x > xmax) xmax = x;
        /* penetration against the exact solution while the force acts */
        if (x > 0 && s->pair[0].fn > 0) {
            double t = s->t - t0;
            double xe = v0 / wd * exp(-z * w * t) * sin(wd * t);
            if (fabs(x - xe) > err_x) err_x = fabs(x - xe);
        }
    }
    double vout = s->kin[0].vel[2];
    /* x_max = (v0 / wd) exp(-z w t_m) sin(wd t_m), tan(wd t_m) = sqrt(1 - z^2) / z */
    double tm = atan(sqrt(1 - z * z) / z) / wd;
    double xm = v0 / wd * exp(-z * w * tm) * sin(wd * tm);
    printf("damped bounce: e = %.5f (exact, clamped %.5f; unclamped %.5f), x_max %.6g (exact "
           "%.6g), max |x - x_exact| %.3g m\n",
           vout / v0, e, e0, xmax, xm, err_x);
    FIG("stage1_engine.damped_e", "%.4f", vout / v0);
    FIG("stage1_engine.damped_xmax_err_pct", "%.1f", 100 * fabs(xmax - xm) / xm);
    FIG("stage1_engine.damped_x_err_um", "%.0f", err_x * 1e6);
    CHECK(e > e0);
    CHECK_NEAR(vout / v0, e, 0.0025 * e); /* 8e-4 measured */
    CHECK_NEAR(xmax, xm, 0.003 * xm);     /* 0.1 % stated */
    CHECK(err_x < 1.8e-5);                /* 6 um stated */
    /* balance: kinetic energy lost = dissipated by the damper (no hysteresis; 6.4e-4 measured) */
    CHECK_NEAR(s->e.dissipated, 0.5 * mass * (v0 * v0 - vout * vout), 2e-3 * s->e.dissipated);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Two spheres with hysteresis: loading k1 to the deepest point d (relative kinetic energy
 * mu v^2 / 2 = k1 d^2 / 2), unloading on the line of slope k2 from (d, k1 d) gives back
 * (k1 d)^2 / (2 k2). So e^2 = v_out^2 / v^2 = k1 / k2 (e = 0.5 for k1 = 1e5, k2 = 4e5 N/m) and
 * the hysteresis loop dissipates its area (1 - k1/k2) mu v^2 / 2 = 3.375 J. Equal and opposite
 * forces at one point keep the momentum to rounding. */
static void test_two_spheres_momentum_restitution_loop_area(void)
{
    mb_state *s = NULL;
    mb_model *m = start_run("scenarios/verification/two_spheres.yaml", &s);
    if (!m) return;
    mcs_error err = {0};
    double m1 = 1, m2 = 3, v1 = 2, v2 = -1, p0 = m1 * v1 + m2 * v2, dp = 0;
    while (s->step < m->nsteps) {
        CHECK(mb_step(m, s, &err) == MCS_OK);
        double p[3];
        for (int i = 0; i < 3; i++) p[i] = m1 * s->kin[0].vel[i] + m2 * s->kin[1].vel[i];
        double d = fabs(p[0] - p0) + fabs(p[1]) + fabs(p[2]);
        if (d > dp) dp = d;
    }
    CHECK(s->pair[0].depth == 0); /* apart again */
    double u1 = s->kin[0].vel[0], u2 = s->kin[1].vel[0];
    double e = (u2 - u1) / (v1 - v2);
    double mu = m1 * m2 / (m1 + m2), v = v1 - v2;
    double diss = 0.5 * mu * v * v * (1 - 1e5 / 4e5);
    printf("two spheres: e = %.5f (exact 0.5), momentum error %.3g kg m/s, dissipated %.5f J "
           "(loop area %.5f J)\n",
           e, dp, s->e.dissipated, diss);
    FIG("stage1_engine.spheres_e", "%.5f", e);
    FIG_TOL("stage1_engine.spheres_momentum_err", "%.0e", dp, 1e-13);
    FIG("stage1_engine.spheres_dissipated_j", "%.5f", s->e.dissipated);
    CHECK(dp < 3e-14); /* 8e-15 stated */
    CHECK_NEAR(e, 0.5, 1.5e-6); /* 5e-7 measured */
    CHECK_NEAR(s->e.dissipated, diss, 1e-5 * diss);
    /* the balance closes: kinetic energy lost = dissipated */
    double ke = 0.5 * (m1 * u1 * u1 + m2 * u2 * u2), ke0 = 0.5 * (m1 * v1 * v1 + m2 * v2 * v2);
    CHECK_NEAR(ke0 - ke, s->e.dissipated, 1e-5 * diss); /* 3.5e-6 measured */
    CHECK(mb_energy_drift(m, s) < 5e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Pendulum: period T = 2 pi sqrt(I_O / (m g d)) (1 + theta0^2/16 + 11 theta0^4/3072 + ...),
 * the series of 2 K(sin(theta0 / 2)) / pi (e.g. Landau & Lifshitz, Mechanics, §11 problem 1).
 * Measured from successive upward zero crossings of the bob's x, linearly interpolated between
 * 1 kHz samples; h = 100 us here (w h = 4.3e-4). */
static void test_pendulum_keeps_its_period(void)
{
    mb_state *s = NULL;
    mb_model *m = start_run("scenarios/verification/pendulum.yaml", &s);
    if (!m) return;
    mcs_error err = {0};
    while (s->step < m->nsteps) CHECK(mb_step(m, s, &err) == MCS_OK);
    double cross[8];
    int nc = 0;
    for (long i = 1; i < s->nrec && nc < 8; i++) {
        double x0 = s->rec_body[(i - 1) * MB_BODY_ROW], x1 = s->rec_body[i * MB_BODY_ROW];
        if (x0 < 0 && x1 >= 0) cross[nc++] = s->rec_t[i - 1] + (s->rec_t[i] - s->rec_t[i - 1]) *
                                                                    (-x0) / (x1 - x0);
    }
    CHECK(nc >= 2);
    double th = 5 * M_PI / 180;
    double T = 2 * M_PI * sqrt(0.26 / (9.81 * 0.5)) *
               (1 + th * th / 16 + 11 * pow(th, 4) / 3072);
    double Tm = nc >= 2 ? (cross[nc - 1] - cross[0]) / (nc - 1) : 0;
    printf("pendulum: period %.6f s (exact %.6f s), energy drift %.3g\n", Tm, T,
           mb_energy_drift(m, s));
    FIG("stage1_engine.pendulum_period_s", "%.6f", Tm);
    CHECK_NEAR(Tm, T, 7e-6 * T); /* 4e-6 s of 1.447 s stated */
    CHECK(mb_energy_drift(m, s) < 7e-4);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* run a scenario file to its end; NULL model on failure */
static mb_state *run_file(const char *path, mb_model **pm)
{
    *pm = load_model(path);
    if (!*pm) return NULL;
    mb_state *s = NULL;
    mcs_error err = {0};
    if (mb_state_create(*pm, &s, &err)) return NULL;
    while (s->step < (*pm)->nsteps)
        if (mb_step(*pm, s, &err)) {
            fprintf(stderr, "%s: %s\n", path, err.msg);
            break;
        }
    return s;
}

/* Restrained revolute joint: I theta'' = -k theta, theta(0) = 0, theta'(0) = w0:
 * theta = (w0 / W) sin(W t), W = sqrt(k / I); the torsional oscillator of any dynamics text.
 * Period from the recorded angular velocity's downward zero crossings (1e-4 s samples,
 * interpolated); energy swaps between kinetic and internal (restraint) with the total kept. */
static void test_restraint_oscillator(void)
{
    mb_model *m = NULL;
    mb_state *s = run_file("scenarios/verification/torsion_restraint.yaml", &m);
    CHECK(s != NULL);
    if (!s) return;
    double W = sqrt(10 / 0.01), T = 2 * M_PI / W, amp = 1 / W;
    double cross[8], emax_int = 0;
    int nc = 0;
    for (long i = 1; i < s->nrec; i++) {
        double w0 = s->rec_body[(i - 1) * MB_BODY_ROW + 11], w1 = s->rec_body[i * MB_BODY_ROW + 11];
        if (w0 > 0 && w1 <= 0 && nc < 8)
            cross[nc++] = s->rec_t[i - 1] + (s->rec_t[i] - s->rec_t[i - 1]) * w0 / (w0 - w1);
        double ei = s->rec_energy[i * MB_NENERGY + 2]; /* internal */
        if (ei > emax_int) emax_int = ei;
    }
    CHECK(nc >= 2);
    double Tm = nc >= 2 ? (cross[nc - 1] - cross[0]) / (nc - 1) : 0;
    /* stored energy at the amplitude: k amp^2 / 2 = I w0^2 / 2 = 5 mJ */
    printf("restraint oscillator: period %.6f s (exact %.6f s), peak stored %.6g J (exact %.6g J), "
           "drift %.3g\n", Tm, T, emax_int, 0.5 * 10 * amp * amp, mb_energy_drift(m, s));
    FIG("stage1_engine.torsion_period_s", "%.6f", Tm);
    FIG("stage1_engine.torsion_stored_mj", "%.0f", emax_int * 1e3);
    CHECK_NEAR(Tm, T, 1.2e-8 * T);                           /* 4e-9 measured */
    CHECK_NEAR(emax_int, 0.5 * 10 * amp * amp, 3e-7 * 0.005); /* 9e-8 measured */
    CHECK(mb_energy_drift(m, s) < 5e-4);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Breakable attachment: x = (v0 / w) sin(w t) until k x = F_fail: t_b = asin(F_fail / (v0
 * sqrt(k m))) / w = asin(0.5) / 100 s, then free flight at v0 cos(w t_b); the spring energy
 * F_fail^2 / (2 k) = 0.125 J is lost with the break (dissipated). The break is detected at the
 * first step past t_b, so the time is late by less than one step (asserted: one step). */
static void test_attachment_breaks(void)
{
    mb_model *m = NULL;
    mb_state *s = run_file("scenarios/verification/attachment_break.yaml", &m);
    CHECK(s != NULL);
    if (!s) return;
    double tb = asin(0.5) / 100;
    CHECK(s->att[0].broken == 1);
    CHECK(s->att[0].t_break >= tb && s->att[0].t_break < tb + m->h);
    CHECK_NEAR(s->kin[0].vel[0], cos(asin(0.5)), 1.5e-4); /* 5e-05 stated */
    CHECK_NEAR(s->e.dissipated, 0.125, 0.125 * 0.004);    /* 0.1 % stated */
    CHECK_NEAR(s->e.total, s->e_total0, 1e-3 * 0.5);
    FIG("stage1_engine.break_t_err_steps", "%.1f", fabs(s->att[0].t_break - tb) / m->h);
    FIG("stage1_engine.break_v_err", "%.0e", fabs(s->kin[0].vel[0] - cos(asin(0.5))));
    FIG("stage1_engine.break_diss_err_pct", "%.1f", 100 * fabs(s->e.dissipated - 0.125) / 0.125);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Two deformable surfaces in series (thesis §3.2): the same force, deflections added, so the
 * pair stiffness is k_a k_b / (k_a + k_b) = 7.5e4 N/m; head-on elastic impact of a
 * mass-spring: deepest approach v sqrt(mu / k), contact time pi sqrt(mu / k), e = 1. Contact is
 * seen at the first step in it and the first step out of it, both late by less than one step,
 * so the measured duration is within one step of the true one (asserted: one step). */
static void test_series_characteristics(void)
{
    mb_state *s = NULL;
    mb_model *m = start_run("scenarios/verification/series_spheres.yaml", &s);
    if (!m) return;
    mcs_error err = {0};
    double dmax = 0, t_in = -1, t_out = -1;
    while (s->step < m->nsteps) {
        CHECK(mb_step(m, s, &err) == MCS_OK);
        double d = s->pair[0].depth;
        if (d > dmax) dmax = d;
        if (d > 0 && t_in < 0) t_in = s->t;
        if (d == 0 && t_in > 0 && t_out < 0) t_out = s->t;
    }
    double k = 7.5e4, mu = 0.5, v = 2;
    printf("series springs: depth %.6g m (exact %.6g), contact %.6g s (exact %.6g)\n", dmax,
           v * sqrt(mu / k), t_out - t_in, M_PI * sqrt(mu / k));
    CHECK_NEAR(dmax, v * sqrt(mu / k), 1.5e-6 * v * sqrt(mu / k)); /* 5e-07 stated */
    FIG("stage1_engine.series_depth_err", "%.0e", fabs(dmax / (v * sqrt(mu / k)) - 1));
    FIG("stage1_engine.series_time_err_steps", "%.1f",
        fabs(t_out - t_in - M_PI * sqrt(mu / k)) / m->h);
    CHECK_NEAR(t_out - t_in, M_PI * sqrt(mu / k), m->h);
    CHECK_NEAR(s->kin[0].vel[0], -1, 3e-6); /* elastic: the velocities swap (1e-6 measured) */
    CHECK_NEAR(s->kin[1].vel[0], 1, 3e-6);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Sliding sphere (e.g. Goldstein or any billiards analysis): friction at the contact point
 * changes v and w until the point stops slipping; angular momentum about the contact point,
 * m v r + I w, is kept, so v_end = m r^2 v0 / (m r^2 + I) = 5/7 v0 for a solid sphere, reached
 * at t = 2 v0 / (7 mu g) with Coulomb friction; the kinetic energy lost (2/7 of m v0^2 / 2) is
 * friction's dissipation (the regularised stick ramp below 10 mm/s adds an exponential tail). */
static void test_sliding_sphere_starts_rolling(void)
{
    mb_model *m = NULL;
    mb_state *s = run_file("scenarios/verification/rolling_sphere.yaml", &m);
    CHECK(s != NULL);
    if (!s) return;
    double v0 = 2, r = 0.1, ve = 5.0 / 7.0 * v0;
    double v = s->kin[0].vel[0], w = s->kin[0].angvel[1];
    /* the time the slip ended: first sample with |v - w r| < 1 % of v0 */
    double t_roll = -1;
    for (long i = 0; i < s->nrec && t_roll < 0; i++) {
        const double *row = s->rec_body + i * MB_BODY_ROW;
        if (fabs(row[7] - row[11] * r) < 0.01 * v0) t_roll = s->rec_t[i];
    }
    double t_exact = 2 * v0 / (7 * 0.3 * 9.81);
    printf("rolling: v %.6f m/s (exact %.6f), w r %.6f, slip ended %.4f s (Coulomb %.4f s), "
           "dissipated %.5f J (exact %.5f J)\n",
           v, ve, w * r, t_roll, t_exact, s->e.dissipated, 2.0 / 7.0 * 2);
    FIG("stage1_engine.sphere_v_err", "%.0e", fabs(v - ve) / ve);
    FIG("stage1_engine.sphere_slip_err_pct", "%.1f", 100 * fabs(t_roll - t_exact) / t_exact);
    FIG("stage1_engine.sphere_diss_err_pct", "%.1f",
        100 * fabs(s->e.dissipated - 4.0 / 7.0) / (4.0 / 7.0));
    CHECK_NEAR(v, ve, 8.5e-4 * ve); /* 3e-04 stated */
    CHECK_NEAR(w * r, ve, 8.5e-4 * ve);
    CHECK_NEAR(t_roll, t_exact, 0.018 * t_exact);                  /* 0.6 % stated */
    CHECK_NEAR(s->e.dissipated, 2.0 / 7.0 * 2, 0.0023 * 2.0 / 7.0 * 2); /* 0.1 % stated */
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Joint range stop: a free revolute joint (I = 0.01 kg m^2, no gravity) turning at 1 rad/s meets
 * its stop at 0.1 rad, a linear spring of 1e3 N m/rad (the default without a characteristic):
 * it overshoots by w0 sqrt(I / k) = 3.16 mrad, stays pi sqrt(I / k) = 9.93 ms in the stop and
 * comes back at -1 rad/s (elastic). */
static void test_revolute_range_stop(void)
{
    const char *y = "mcrash: 1\n"
                    "simulation: {end_time: 0.13 s, time_step: 10 us}\n"
                    "environment: {gravity: 0}\n"
                    "bodies:\n"
                    "  - {name: arm, mass: 1, inertia: [0.01, 0.01, 0.01], position: [0, 0, 1],\n"
                    "     velocity: [0, 0, 0], angular_velocity: [0, 1, 0]}\n"
                    "joints:\n"
                    "  - {type: revolute, parent: ground, child: arm, anchor: [0, 0, 1],\n"
                    "     axis: [0, 1, 0], range: [-0.1, 0.1]}\n";
    mcs_error err = {0};
    mb_model *m = load_text(y, &err);
    CHECK(m != NULL);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    double qmax = 0, t_in = -1, t_out = -1;
    while (s->step < m->nsteps) {
        CHECK(mb_step(m, s, &err) == MCS_OK);
        double q = mb_joint_position(s->world, 0);
        if (q > qmax) qmax = q;
        if (q > 0.1 && t_in < 0) t_in = s->t;
        if (q <= 0.1 && t_in > 0 && t_out < 0) t_out = s->t;
    }
    double over = sqrt(0.01 / 1e3);
    CHECK_NEAR(qmax, 0.1 + over, 2.7e-6 * over); /* 9e-07 stated */
    /* entry and exit seen at the first step past each: within one step */
    CHECK_NEAR(t_out - t_in, M_PI * over, m->h);
    CHECK_NEAR(s->kin[0].angvel[1], -1, 3.5e-6); /* 1e-06 stated */
    CHECK(mb_energy_drift(m, s) < 2e-3);
    FIG("stage1_engine.stop_over_err", "%.0e", fabs(qmax - 0.1 - over) / over);
    FIG("stage1_engine.stop_time_err_steps", "%.1f", fabs(t_out - t_in - M_PI * over) / m->h);
    FIG("stage1_engine.stop_w_err", "%.0e", fabs(s->kin[0].angvel[1] + 1));
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Sliding wheel (cylinder surface = tyre torus against the ground): as the sphere, angular
 * momentum about the contact point gives v_end = v0 / (1 + I / (m R^2)) = 2 m/s for a disc,
 * with Coulomb friction reached at t = v0 / (mu g (1 + m R^2 / I)). */
static void test_sliding_wheel_starts_rolling(void)
{
    mb_model *m = NULL;
    mb_state *s = run_file("scenarios/verification/rolling_wheel.yaml", &m);
    CHECK(s != NULL);
    if (!s) return;
    double v0 = 3, R = 0.3, ve = 2;
    double v = s->kin[0].vel[0], w = s->kin[0].angvel[1];
    double t_roll = -1;
    for (long i = 0; i < s->nrec && t_roll < 0; i++) {
        const double *row = s->rec_body + i * MB_BODY_ROW;
        if (fabs(row[7] - row[11] * R) < 0.01 * v0) t_roll = s->rec_t[i];
    }
    double t_exact = v0 / (0.5 * 9.81 * 3);
    printf("wheel: v %.6f m/s (exact 2), w R %.6f, slip ended %.4f s (Coulomb %.4f s), "
           "height %.7f m\n", v, w * R, t_roll, t_exact, s->kin[0].pos[2]);
    FIG("stage1_engine.wheel_v_err", "%.1e", fabs(v - ve) / ve);
    FIG("stage1_engine.wheel_slip_err_pct", "%.0f", 100 * fabs(t_roll - t_exact) / t_exact);
    CHECK_NEAR(v, ve, 3.3e-4 * ve); /* 1.1e-04 stated */
    CHECK_NEAR(w * R, ve, 3.3e-4 * ve);
    CHECK_NEAR(t_roll, t_exact, 0.02 * t_exact);
    CHECK_NEAR(s->kin[0].pos[2], 0.3 - 98.1 / 1e6, 1e-6); /* resting on the tyre */
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Deforming hinge (the fork's M_def(phi), paper Fig. 7, as a restrained revolute joint): the
 * body (I = 0.01 kg m^2, no gravity) turns at w0 into an elastic-plastic characteristic
 * M = 1000 phi up to 0.1 rad, then 100 + 125 (phi - 0.1) N m; unloading slope k_u = 2000 N m/rad.
 * Energy: I w0^2 / 2 = integral of M up to phi_max, so w0 = sqrt(2 * 27.5 / I) reaches
 * phi_max = 0.3 rad (5 J + 22.5 J). Unloading along k_u from M_max = 125 N m leaves the
 * permanent set phi_max - M_max / k_u = 0.2375 rad and gives back E1 = M_max^2 / (2 k_u) =
 * 3.906 J: the hinge passes its set at sqrt(2 E1 / I) = 27.95 rad/s. There the negative side
 * (the same curve, mirrored) starts from the set (mcs_hyst2 follow_set): 500 u^2 = E1 gives
 * u1 = 0.08839 rad, q_min = 0.2375 - u1 = 0.14911 rad; it unloads along k_u from 1000 u1 and
 * gives back E2 = (1000 u1)^2 / (2 k_u) = E1 / 2, with its set u1 / 2; the positive side now
 * starts from 0.2375 - u1 / 2 = 0.19331 rad and 500 u^2 = E2 gives u = 0.0625 rad:
 * the second maximum is 0.25581 rad. */
static void test_deforming_hinge_keeps_permanent_set(void)
{
    const char *y = "mcrash: 1\n"
                    "simulation: {end_time: 0.04 s, time_step: 10 us}\n"
                    "environment: {gravity: 0}\n"
                    "characteristics:\n"
                    "  fork: {type: moment, loading: [[0, 0], [0.1, 100], [0.3, 125]],\n"
                    "         unloading_slope: 2000, elastic_limit: 0}\n"
                    "bodies:\n"
                    "  - {name: fork, mass: 1, inertia: [0.01, 0.01, 0.01], position: [0, 0, 1],\n"
                    "     velocity: [0, 0, 0], angular_velocity: [0, 74.16198487095663, 0]}\n"
                    "joints:\n"
                    "  - {name: hinge, type: revolute, parent: ground, child: fork,\n"
                    "     anchor: [0, 0, 1], axis: [0, 1, 0], restraint: fork}\n";
    mcs_error err = {0};
    mb_model *m = load_text(y, &err);
    CHECK(m != NULL);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    double qmax = 0, w_back = 0, diss = 0, set = 0, qmin = 1, qmax2 = 0;
    int phase = 0; /* 0 loading, 1 back past the set, 2 back up from q_min */
    while (s->step < m->nsteps) {
        CHECK(mb_step(m, s, &err) == MCS_OK);
        double q = mb_joint_position(s->world, 0), w = s->kin[0].angvel[1];
        if (q > qmax) qmax = q;
        if (phase == 0 && qmax > 0.2 && q < s->r1[0].h.pos.x_set) { /* passing the set */
            set = s->r1[0].h.pos.x_set;
            w_back = w;
            diss = s->e.dissipated;
            phase = 1;
        }
        if (phase == 1) qmin = fmin(qmin, q);
        if (phase == 1 && w > 0) phase = 2;
        if (phase == 2) qmax2 = fmax(qmax2, q);
    }
    double u1 = sqrt(125.0 * 125.0 / 4000 / 500); /* 500 u1^2 = E1 */
    printf("deforming hinge: phi_max %.5f rad (exact 0.3), set %.5f rad (exact 0.2375), back "
           "at %.4f rad/s (exact -27.95), dissipated %.4f J (exact %.4f J), then min %.5f rad "
           "(exact %.5f), max %.5f rad (exact %.5f)\n",
           qmax, set, w_back, diss, 27.5 - 125.0 * 125.0 / 4000, qmin, 0.2375 - u1, qmax2,
           0.2375 - u1 / 2 + 0.0625);
    FIG("stage1_engine.hinge_phi_max_rad", "%.5f", qmax);
    FIG("stage1_engine.hinge_set_rad", "%.5f", set);
    FIG("stage1_engine.hinge_w_back", "%.4f", w_back);
    FIG("stage1_engine.hinge_dissipated_j", "%.4f", diss);
    /* measured 5e-7, 4e-7, 2.5e-5, 5.5e-5, 5e-7, 4e-7 off; asserted to about 3x */
    CHECK_NEAR(qmax, 0.3, 1.5e-6);
    CHECK_NEAR(set, 0.3 - 125.0 / 2000, 1.5e-6);
    CHECK_NEAR(w_back, -sqrt(125.0 * 125.0 / 2000 / 0.01), 7.5e-5);
    CHECK_NEAR(diss, 27.5 - 125.0 * 125.0 / 4000, 1.7e-4);
    CHECK_NEAR(qmin, 0.2375 - u1, 1.5e-6);
    CHECK_NEAR(qmax2, 0.2375 - u1 / 2 + 0.0625, 1.2e-6);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *c = p;
    for (size_t i = 0; i < n; i++) h = (h ^ c[i]) * 1099511628211ULL;
    return h;
}

static uint64_t run_hash(const char *path)
{
    mb_model *m = load_model(path);
    if (!m) return 0;
    mb_state *s = NULL;
    mcs_error err = {0};
    uint64_t h = 1469598103934665603ULL;
    if (mb_state_create(m, &s, &err) == MCS_OK) {
        while (s->step < m->nsteps && mb_step(m, s, &err) == MCS_OK) {}
        h = fnv(h, s->rec_body, sizeof(double) * s->nrec * m->nbody * MB_BODY_ROW);
        h = fnv(h, s->rec_energy, sizeof(double) * s->nrec * MB_NENERGY);
    }
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    return h;
}

/* the same input gives the same bytes: two runs hash the same */
static void test_determinism(void)
{
    uint64_t a = run_hash("scenarios/verification/two_spheres.yaml");
    uint64_t b = run_hash("scenarios/verification/two_spheres.yaml");
    CHECK(a != 0);
    CHECK(a == b);
}

/* a contact far too stiff for the step (w h = 3.2 > 2) blows up: MCS_ERR_NUMERIC naming the
 * body and the time */
static void test_instability_is_reported(void)
{
    const char *y = "mcrash: 1\n"
                    "simulation: {end_time: 0.1 s, time_step: 100 us}\n"
                    "environment: {gravity: 9.81, ground: {height: 0}}\n"
                    "characteristics: {stiff: {loading: [[0, 0], [0.001, 1e6]]}}\n"
                    "bodies:\n"
                    "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004],\n"
                    "     position: [0, 0, 0.1005], velocity: [0, 0, -1],\n"
                    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, "
                    "0.1]}]}\n"
                    "contacts: [{a: ball, b: ground, characteristic: stiff}]\n";
    mcs_error err = {0};
    mb_model *m = load_text(y, &err);
    CHECK(m != NULL);
    if (!m) return;
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    mcs_status st = MCS_OK;
    while (!st && s->step < m->nsteps) st = mb_step(m, s, &err);
    CHECK(st == MCS_ERR_NUMERIC);
    CHECK_STR_CONTAINS(err.msg, "ball");
    CHECK_STR_CONTAINS(err.msg, "t = ");
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* bad input is refused when the model is built, with FILE:LINE:COL and the key */
static void test_build_errors_are_located(void)
{
    const char *head = "mcrash: 1\n"
                       "simulation: {end_time: 0.1 s}\n"
                       "characteristics: {pad: {loading: [[0, 0], [0.01, 1000]]},\n"
                       "  hinge: {type: moment, loading: [[0, 0], [1, 10]]}}\n";
    char y[2048];
    mcs_error err = {0};
    /* a contact with the ground but no environment.ground */
    snprintf(y, sizeof y, "%s%s", head,
             "bodies: [{name: b, mass: 1, inertia: [1, 1, 1], position: [0, 0, 0], velocity: "
             "[0, 0, 0],\n  surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [1, 1, "
             "1]}]}]\n"
             "contacts: [{a: b, b: ground, characteristic: pad}]\n");
    CHECK(load_text(y, &err) == NULL);
    CHECK(err.status == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(err.msg, "test.yaml:7:");
    CHECK_STR_CONTAINS(err.msg, "environment.ground");
    /* a surface stage 1 does not have yet (finite planes) */
    mcs_error_clear(&err);
    snprintf(y, sizeof y, "%s%s", head,
             "bodies: [{name: b, mass: 1, inertia: [1, 1, 1], position: [0, 0, 0], velocity: "
             "[0, 0, 0],\n  surfaces: [{type: plane, point: [0, 0, 0], normal: [0, 0, 1], "
             "size: [1, 1]}]}]\n");
    CHECK(load_text(y, &err) == NULL);
    CHECK(err.status == MCS_ERR_UNSUPPORTED);
    CHECK_STR_CONTAINS(err.msg, "test.yaml:6:");
    CHECK_STR_CONTAINS(err.msg, "finite planes");
    /* a cylinder (wheel) longer than its diameter */
    mcs_error_clear(&err);
    snprintf(y, sizeof y, "%s%s", head,
             "bodies: [{name: b, mass: 1, inertia: [1, 1, 1], position: [0, 0, 0], velocity: "
             "[0, 0, 0],\n  surfaces: [{type: cylinder, center: [0, 0, 0], radius: 0.1, length: "
             "0.5, axis: [0, 1, 0]}]}]\n");
    CHECK(load_text(y, &err) == NULL);
    CHECK(err.status == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "bodies[0].surfaces[0].length");
    /* a moment characteristic on a contact */
    mcs_error_clear(&err);
    snprintf(y, sizeof y, "%s%s", head,
             "environment: {ground: {height: 0}}\n"
             "bodies: [{name: b, mass: 1, inertia: [1, 1, 1], position: [0, 0, 2], velocity: "
             "[0, 0, 0],\n  surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [1, 1, "
             "1]}]}]\n"
             "contacts: [{a: b, b: ground, characteristic: hinge}]\n");
    CHECK(load_text(y, &err) == NULL);
    CHECK(err.status == MCS_ERR_TYPE);
    CHECK_STR_CONTAINS(err.msg, "contacts[0].characteristic");
    /* a model file (no simulation block) cannot run */
    mcs_error_clear(&err);
    CHECK(load_text("mcrash: 1\nbodies: [{name: b, mass: 1, inertia: [1, 1, 1], position: [0, "
                    "0, 0], velocity: [0, 0, 0]}]\n",
                    &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "simulation");
}

int main(void)
{
    RUN(test_elastic_bounce_returns_to_height);
    RUN(test_damped_bounce_matches_exact_solution);
    RUN(test_two_spheres_momentum_restitution_loop_area);
    RUN(test_pendulum_keeps_its_period);
    RUN(test_restraint_oscillator);
    RUN(test_revolute_range_stop);
    RUN(test_deforming_hinge_keeps_permanent_set);
    RUN(test_attachment_breaks);
    RUN(test_series_characteristics);
    RUN(test_sliding_sphere_starts_rolling);
    RUN(test_sliding_wheel_starts_rolling);
    RUN(test_determinism);
    RUN(test_instability_is_reported);
    RUN(test_build_errors_are_located);
    TEST_END();
}

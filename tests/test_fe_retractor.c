/* tests for fe_retractor: pretensioner pay-in (2023 paper, Eq. 3), load limiter (2 kN),
 * locking, film spool and pretensioner stall, against closed forms.
 *
 * The belt is one linear segment of axial stiffness k_b between the retractor and an end
 * point that the test moves: its tension is F = k_b (x - L), x the end's pull-out (x = F0 / k_b
 * at rest with the comfort tension F0), L the retractor's payout. This is exactly what the
 * FE kernel's truss next to the retractor computes. */
#include "fe/fe_retractor.h"
#include "tests/harness.h"
#include "tests/figures.h"

#include <stdio.h>

static fe_retractor_model *make(const fe_retractor_desc *d)
{
    fe_retractor_model *m = NULL;
    mcs_error err = {0};
    if (fe_retractor_model_create("belt_left", d, &m, &err) != MCS_OK)
        fprintf(stderr, "%s\n", err.msg);
    return m;
}

/* one step with the end at x: trial tension with the current payout */
static void step(const fe_retractor_model *m, fe_retractor_state *s, double dt, double x, double kb)
{
    mcs_error err = {0};
    if (fe_retractor_advance(m, s, dt, kb * (x - s->payout), kb, &err) != MCS_OK)
        fprintf(stderr, "%s\n", err.msg);
}

/* paper Eq. 3 written out */
static double eq3(double t, double tf)
{
    if (t < tf) return 0.0;
    if (t <= tf + 0.015) return -(0.100 / 0.015) * (t - tf);
    return -0.100;
}

/* pay-in follows Eq. 3 after the firing time and nothing happens before it: a soft belt
 * (k_b = 10 kN/m) with its end held, so the tension after the full 100 mm stroke is
 * F0 + k_b 0.1 m = 1005 N, below the 2 kN limit; the limiter never acts */
static void test_payin_eq3(void)
{
    fe_retractor_desc d = fe_retractor_desc_default();
    fe_retractor_model *m = make(&d);
    CHECK(m != NULL);
    if (!m) return;
    fe_retractor_state s;
    fe_retractor_state_init(m, &s, 0.0);
    const double kb = 1e4, x = d.spool_force / kb, dt = 1e-6, tf = 0.012;
    double emax = 0.0;
    for (int k = 1; k <= 40000; k++) {
        step(m, &s, dt, x, kb);
        double t = k * dt;
        if (t < tf - 0.5 * dt) {
            CHECK(s.payout == 0.0 && !s.fired && !s.locked);
            CHECK_NEAR(s.force, d.spool_force, 1e-12);
        }
        emax = fmax(emax, fabs(s.payout - eq3(t, tf)));
        CHECK_NEAR(s.force, d.spool_force - kb * s.payout, 1e-9);
    }
    printf("  pay-in vs Eq. 3: max |L - L_eq3| = %.2e m; at 40 ms L = %.4f m, F = %.1f N\n", emax,
           s.payout, s.force);
    FIG("gasbag.payin_eq3_err_m", "%.0e", emax);
    CHECK(emax < 1.5e-13); /* 4e-14 stated */
    CHECK_NEAR(s.payout, -0.100, 1e-12);
    CHECK_NEAR(s.force, 1005.0, 1e-6);
    CHECK(s.fired && s.locked && s.payout_limiter == 0.0 && s.energy_limiter == 0.0);
    CHECK_NEAR(fe_retractor_payin(m, 0.012 + 0.0075), -0.050, 1e-15);
    CHECK(fe_retractor_channel(&s, FE_RETRACTOR_CH_payout) == s.payout);
    CHECK(strcmp(fe_retractor_channel_name[FE_RETRACTOR_CH_force], "force") == 0);
    CHECK(strcmp(fe_retractor_channel_unit[FE_RETRACTOR_CH_energy_limiter], "J") == 0);
    /* work of the pretensioner = elastic energy gained by the belt, (F1^2 - F0^2)/(2 k_b) */
    CHECK_REL(s.energy_pretensioner, (1005.0 * 1005.0 - 25.0) / (2.0 * kb), 1e-9);
    fe_retractor_model_destroy(&m);
    CHECK(m == NULL);
}

/* load limiter: the belt end pulled out at constant speed v from a locked retractor with a
 * film spool. The tension rises at k_eff v, 1/k_eff = 1/k_b + 1/k_s, then plateaus at
 * F_lim = 2 kN; geometry gives the limiter payout L_ll = x - F_lim/k_b - F_lim/k_s, the
 * absorbed energy is F_lim L_ll, and the work of the pull equals L_ll F_lim plus the elastic
 * energies F_lim^2/(2 k_b) + F_lim^2/(2 k_s). */
static void test_load_limiter_plateau(void)
{
    fe_retractor_desc d = fe_retractor_desc_default();
    d.fire_time = 0.0; /* fired and locked from the start ... */
    d.npayin = 1;      /* ... with no pay-in stroke */
    d.payin_time[0] = 0.0, d.payin_length[0] = 0.0;
    d.spool_stiffness = 4e5;
    fe_retractor_model *m = make(&d);
    CHECK(m != NULL);
    if (!m) return;
    fe_retractor_state s;
    fe_retractor_state_init(m, &s, 0.0);
    CHECK(s.locked && s.fired);
    const double kb = 2e5, ks = 4e5, v = 2.0, dt = 1e-6, flim = 2000.0;
    const double keff = 1.0 / (1.0 / kb + 1.0 / ks);
    double x = d.spool_force / kb, work = 0.0, f_prev = s.force, t_plateau = -1.0;
    s.payout_spool = d.spool_force / ks; /* consistent start: the spool carries F0 too */
    s.payout = s.payout_spool;
    x += s.payout;
    int nstep = 50000;
    for (int k = 1; k <= nstep; k++) {
        x += v * dt;
        step(m, &s, dt, x, kb);
        work += 0.5 * (f_prev + s.force) * v * dt;
        if (t_plateau < 0.0 && s.force >= flim) t_plateau = k * dt;
        if (k * dt < (flim - d.spool_force) / (keff * v) - dt)
            CHECK_NEAR(s.force, d.spool_force + keff * v * k * dt, 1e-6);
        f_prev = s.force;
    }
    double xt = x - d.spool_force / kb - d.spool_force / ks; /* pull beyond the start */
    double lll = xt + d.spool_force * (1.0 / kb + 1.0 / ks) - flim / kb - flim / ks;
    double e_el0 = d.spool_force * d.spool_force * (0.5 / kb + 0.5 / ks);
    double e_el = flim * flim * (0.5 / kb + 0.5 / ks);
    printf("  load limiter: plateau from %.2f ms at %.3f N; payout %.6f m (closed form "
           "%.6f); energy %.3f J, pull work - elastic %.3f J\n",
           t_plateau * 1e3, s.force, s.payout_limiter, lll, s.energy_limiter,
           work - (e_el - e_el0));
    FIG("gasbag.limiter_plateau_ms", "%.2f", 1e3 * t_plateau);
    FIG("gasbag.limiter_energy_j", "%.3f", s.energy_limiter);
    FIG("gasbag.limiter_work_err", "%.0e", fabs(work / (s.energy_limiter + e_el - e_el0) - 1));
    CHECK_NEAR(t_plateau, (flim - d.spool_force) / (keff * v), 2 * dt);
    CHECK_NEAR(s.force, flim, 1e-9);
    CHECK_REL(s.payout_limiter, lll, 1e-9);
    CHECK_REL(s.energy_limiter, flim * lll, 1e-9); /* F_lim times the geometric payout */
    CHECK_REL(work, s.energy_limiter + e_el - e_el0, 1e-9); /* trapezoid over the kink: 3e-10 */
    CHECK_REL(s.payout_rate, v, 1e-6);                      /* all the pull goes out */

    /* rigid phase: unloading follows k_eff with no pay-in, reloading pays out only at F_lim */
    double ll = s.payout_limiter, e = s.energy_limiter;
    for (int k = 0; k < 1000; k++) {
        x -= v * dt;
        step(m, &s, dt, x, kb);
    }
    CHECK_NEAR(s.force, flim - keff * v * 1000 * dt, 1e-6);
    CHECK(s.payout_limiter == ll && s.energy_limiter == e);
    for (int k = 0; k < 999; k++) {
        x += v * dt;
        step(m, &s, dt, x, kb);
    }
    CHECK(s.force < flim && s.payout_limiter == ll);
    for (int k = 0; k < 100; k++) {
        x += v * dt;
        step(m, &s, dt, x, kb);
    }
    CHECK_NEAR(s.force, flim, 1e-9);
    CHECK_REL(s.payout_limiter, ll + 99 * v * dt, 1e-6);
    fe_retractor_model_destroy(&m);
}

/* locking: unlocked, the spool pays out freely at the comfort tension; the webbing sensor
 * locks when the pull-out rate exceeds 1.5 m/s; locked, the tension rises at k_b v (rigid
 * spool). Locking by time: tension from the lock time on. */
static void test_locking(void)
{
    fe_retractor_desc d = fe_retractor_desc_default();
    d.fire_time = 1.0; /* no firing in this test */
    d.lock_payout_rate = 1.5;
    fe_retractor_model *m = make(&d);
    CHECK(m != NULL);
    if (!m) return;
    fe_retractor_state s;
    fe_retractor_state_init(m, &s, 0.0);
    const double kb = 1e5, dt = 1e-5;
    double x = d.spool_force / kb;
    for (int k = 0; k < 2000; k++) { /* 20 ms at 0.5 m/s */
        x += 0.5 * dt;
        step(m, &s, dt, x, kb);
        CHECK(!s.locked);
        CHECK_NEAR(s.force, d.spool_force, 1e-9);
    }
    CHECK_NEAR(s.payout, 0.010, 1e-12);
    CHECK_NEAR(s.payout_unlocked, 0.010, 1e-12);
    double L_lock = s.payout;
    for (int k = 1; k <= 300; k++) { /* 3 m/s: locks on the first step */
        x += 3.0 * dt;
        step(m, &s, dt, x, kb);
        CHECK(s.locked);
        CHECK_NEAR(s.force, d.spool_force + kb * 3.0 * k * dt, 1e-6);
    }
    CHECK(s.payout == L_lock);
    CHECK(!s.fired && s.payout_pretensioner == 0.0);
    fe_retractor_model_destroy(&m);

    d = fe_retractor_desc_default();
    d.fire_time = 1.0;
    d.lock_time = 0.005005; /* mid-step: locks in the step ending at 5.01 ms */
    m = make(&d);
    fe_retractor_state_init(m, &s, 0.0);
    x = d.spool_force / kb;
    for (int k = 1; k <= 1000; k++) {
        x += 1.0 * dt;
        step(m, &s, dt, x, kb);
        CHECK(s.locked == (k > 500));
    }
    CHECK_NEAR(s.payout, 0.005, 1e-9); /* paid out until the lock step */
    CHECK_NEAR(s.force, d.spool_force + kb * (0.010 - 0.005), 1e-6);
    fe_retractor_model_destroy(&m);
}

/* pretensioner stall: against a stiff belt the pull-in stops when the tension reaches the
 * pretensioner's maximum force; the pulled-in length is (F_max - F0)/k_b */
static void test_stall(void)
{
    fe_retractor_desc d = fe_retractor_desc_default();
    d.pretensioner_max_force = 1500.0;
    fe_retractor_model *m = make(&d);
    CHECK(m != NULL);
    if (!m) return;
    fe_retractor_state s;
    fe_retractor_state_init(m, &s, 0.0);
    const double kb = 1e5, dt = 1e-6;
    for (int k = 0; k < 30000; k++)
        step(m, &s, dt, d.spool_force / kb, kb);
    CHECK_NEAR(s.force, 1500.0, 1e-9);
    CHECK_NEAR(s.payout_pretensioner, -(1500.0 - d.spool_force) / kb, 1e-12);
    CHECK(s.payout_limiter == 0.0);
    fe_retractor_model_destroy(&m);
}

static void test_bad_input(void)
{
    fe_retractor_desc d = fe_retractor_desc_default();
    fe_retractor_model *m = NULL;
    mcs_error err = {0};
    d.load_limit = -1.0;
    CHECK(fe_retractor_model_create("belt", &d, &m, &err) == MCS_ERR_RANGE && !m);
    CHECK_STR_CONTAINS(err.msg, "belt: load_limit");
    d = fe_retractor_desc_default();
    d.npayin = 2;
    d.payin_time[1] = 0.01, d.payin_length[1] = 0.05; /* pay-in must pull in */
    mcs_error_clear(&err);
    CHECK(fe_retractor_model_create("belt", &d, &m, &err) == MCS_ERR_RANGE && !m);
    CHECK_STR_CONTAINS(err.msg, "pay-in point 1");
    d.payin_length[1] = -0.05;
    d.payin_time[1] = 0.0; /* not increasing */
    mcs_error_clear(&err);
    CHECK(fe_retractor_model_create("belt", &d, &m, &err) != MCS_OK && !m);
    d = fe_retractor_desc_default();
    CHECK(fe_retractor_model_create("belt", &d, &m, &err) == MCS_OK && m);
    fe_retractor_state s;
    fe_retractor_state_init(m, &s, 0.0);
    fe_retractor_state keep = s;
    mcs_error_clear(&err);
    CHECK(fe_retractor_advance(m, &s, 1e-6, NAN, 1e5, &err) == MCS_ERR_NUMERIC);
    CHECK(fe_retractor_advance(m, &s, 1e-6, 10.0, 0.0, &err) == MCS_ERR_NUMERIC);
    CHECK(memcmp(&s, &keep, sizeof(s)) == 0);
    fe_retractor_model_destroy(&m);
}

/* the paper's three phases (Fig. 13): a 40 kg mass (the restrained pelvis and thighs) on a
 * belt (k_b = 50 kN/m) with 80 mm of slack, the retractor locked by the vehicle sensor at
 * t = 0 and fired at 12 ms, and a 6 g crash pulse from 20 to 80 ms pushing the mass forward
 * relative to the motorcycle: (i) pretensioning removes the slack and tensions the belt,
 * (ii) payout at the 2 kN limit, during which the mass accelerates at exactly
 * (m a_pulse - F_lim) / m, (iii) rigid restraint once the relative motion is stopped.
 * Central-difference integration as in the kernel. The retractor's energies are computed here
 * from the force history and the spool's payout, which follows from the end's position: taut,
 * F = k_b (x - L), so L = x - F / k_b; the pretensioner's part is Eq. 3 (written out above),
 * the limiter's the rest (rigid spool, locked from t = 0):
 *   E_limiter = sum F_mean dL_lim,  W_pretensioner = sum F_mean (-dL_eq3),
 * and the energy balance W_pulse + W_pretensioner = KE + F^2/(2 k_b) + E_limiter (to O(dt)). */
static void test_three_phases(void)
{
    fe_retractor_desc d = fe_retractor_desc_default();
    d.lock_time = 0.0;
    fe_retractor_model *m = make(&d);
    CHECK(m != NULL);
    if (!m) return;
    fe_retractor_state s;
    fe_retractor_state_init(m, &s, 0.0);
    const double kb = 5e4, mass = 40.0, dt = 1e-6, apulse = 6.0 * 9.81;
    double x = -0.080, v = 0.0, acc = 0.0, adev = 0.0, wext = 0.0;
    double t_lim = -1.0, t_rigid = -1.0, f_pre_end = 0.0, e_lim = 0.0, w_pre = 0.0;
    step(m, &s, dt, x, kb); /* slack: the tension is 0 */
    CHECK(s.force == 0.0);
    for (int k = 2; k <= 200000; k++) {
        double t = k * dt, fp = (t > 0.020 && t <= 0.080) ? mass * apulse : 0.0;
        double x_a = x, f_a = s.force, t_a = s.time;
        v += acc * dt; /* velocity at k - 1/2, then the position at k */
        x += v * dt;
        wext += fp * v * dt;
        step(m, &s, dt, x, kb);
        if (f_a > 0.0 && s.force > 0.0) { /* taut at both ends of the step */
            double dl = (x - s.force / kb) - (x_a - f_a / kb);
            double dl_pre = eq3(s.time, d.fire_time) - eq3(t_a, d.fire_time);
            e_lim += 0.5 * (f_a + s.force) * (dl - dl_pre);
            w_pre += 0.5 * (f_a + s.force) * -dl_pre;
        }
        acc = (fp - s.force) / mass;
        if (fabs(t - 0.027) < 0.5 * dt) f_pre_end = s.force;
        if (s.force >= d.load_limit) {
            if (fp > 0.0) adev = fmax(adev, fabs(acc - (apulse - d.load_limit / mass)));
            if (t_lim < 0.0) t_lim = t;
        } else if (t_lim > 0.0 && t_rigid < 0.0) {
            t_rigid = t;
        }
    }
    double vend = v + 0.5 * acc * dt;
    double e = 0.5 * mass * vend * vend + s.force * s.force / (2.0 * kb) + e_lim;
    double win = wext + w_pre;
    printf("  three phases: tension at the end of pretensioning %.0f N; at the limit from %.2f "
           "ms, rigid from %.2f ms; pull-in %.1f mm, limiter payout %.1f mm, %.1f J absorbed; "
           "energy balance %.2e\n",
           f_pre_end, t_lim * 1e3, t_rigid * 1e3, -s.payout_pretensioner * 1e3,
           s.payout_limiter * 1e3, s.energy_limiter, (e - win) / win);
    CHECK(f_pre_end > 0.0 && f_pre_end < d.load_limit); /* (i) before (ii) */
    CHECK(t_lim > 0.027 && t_rigid > 0.080);            /* (ii) during the pulse, then (iii) */
    CHECK(adev < 1e-9);
    CHECK_NEAR(s.payout_pretensioner, -0.100, 1e-12);
    CHECK(s.payout_limiter > 0.0);
    printf("  limiter energy from F and the payout of the positions %.4f J (retractor %.4f J), "
           "pretensioner work %.4f J (retractor %.4f J)\n",
           e_lim, s.energy_limiter, w_pre, s.energy_pretensioner);
    FIG("gasbag.three_phase_limiter_j", "%.1f", e_lim);
    FIG("gasbag.three_phase_limiter_err", "%.0e", fabs(s.energy_limiter / e_lim - 1));
    FIG("gasbag.three_phase_balance", "%.0e", fabs(e / win - 1));
    FIG("gasbag.three_phase_f_pre", "%.0f", f_pre_end);
    FIG("gasbag.three_phase_t_lim_ms", "%.0f", 1e3 * t_lim);
    FIG("gasbag.three_phase_t_rigid_ms", "%.0f", 1e3 * t_rigid);
    CHECK_REL(s.energy_limiter, e_lim, 1e-6);
    CHECK_REL(s.energy_pretensioner, w_pre, 3e-5); /* the step the slack is taken up */
    CHECK_NEAR(e, win, 3e-5 * win); /* 1e-5 stated */
    fe_retractor_model_destroy(&m);
}

int main(void)
{
    RUN(test_payin_eq3);
    RUN(test_load_limiter_plateau);
    RUN(test_locking);
    RUN(test_stall);
    RUN(test_three_phases);
    RUN(test_bad_input);
    TEST_END();
}

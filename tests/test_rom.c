/* test_rom: the reduced-order model (rom/rom.h) against closed forms, each with its source:
 * a linear spring-mass against a rigid wall (contact duration pi sqrt(m/k), rebound speed,
 * peak force), the damped 1-DOF free response during contact, the 2-DOF free response of two
 * masses in contact (modal solution by hand), the forced (base-excited) response, the energy
 * balance with hysteresis (dissipated = loop area), a free opponent, BDF against Adams, and the
 * /stage0 results layout through bin/mcrash. */
#include "rom/rom.h"
#include "tests/harness.h"
#include "tests/cli_util.h"
#include "tests/figures.h"

#include <math.h>

/* a model with linear, elastic elements of stiffness k (no damping); masses as given */
static rom_params linear_params(double k)
{
    rom_params p = rom_params_default();
    p.tyre_stiffness = p.rim_stiffness = k;
    p.tyre_travel = 1.0; /* the elastic limit: beyond any crush here */
    p.tyre_unload = k;
    p.tyre_damping = 0;
    p.fork_damping = p.frame_damping = p.rider_damping = p.rider_wall_damping = 0;
    p.rtol = 1e-9;
    return p;
}

static int build(rom_model *m, const double mass[ROM_NMASS], double v0, const rom_params *p,
                 double tend, double dt)
{
    mcs_error err = {0};
    mcs_status st = rom_model_init(m, mass, v0, 0, p, tend, dt, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    return st == MCS_OK;
}

/* first and last sample with a wall force */
static void contact_span(const rom_result *r, double *t0, double *t1)
{
    *t0 = *t1 = NAN;
    for (int i = 0; i < r->nt; i++)
        if (r->wall_force[i] > 0) {
            if (isnan(*t0)) *t0 = r->t[i];
            *t1 = r->t[i];
        }
}

/* a linear spring-mass (m, k) at v0 against a rigid wall, no damping: contact lasts half a
 * period, pi sqrt(m/k); the rebound speed equals the impact speed; the peak force is
 * v0 sqrt(k m) (Goldsmith, "Impact", 1960, ch. 1; any vibration text: half a sine of x) */
static void test_wall_impact_linear(void)
{
    const double m = 35, k = 4e5, v0 = 13.4, dt = 1e-6;
    double mass[ROM_NMASS] = {m, 0, 0, 0};
    rom_params p = linear_params(k);
    rom_model mod;
    rom_result r;
    mcs_error err = {0};
    CHECK(build(&mod, mass, v0, &p, 0.06, dt));
    CHECK(rom_run(&mod, &r, &err) == MCS_OK);
    double t0, t1, fpk = 0;
    contact_span(&r, &t0, &t1);
    for (int i = 0; i < r.nt; i++) fpk = fmax(fpk, r.wall_force[i]);
    double tc = M_PI * sqrt(m / k);
    printf("  contact %.6f s (pi sqrt(m/k) = %.6f), rebound %.6f m/s, peak %.1f N (%.1f)\n",
           t1 - t0 + dt, tc, r.v[ROM_FRONT][r.nt - 1], fpk, v0 * sqrt(k * m));
    CHECK_NEAR(t1 - t0 + dt, tc, 2 * dt);
    CHECK_NEAR(r.v[ROM_FRONT][r.nt - 1], -v0, 1e-5 * v0);
    CHECK_REL(fpk, v0 * sqrt(k * m), 1e-6);
    CHECK(r.energy_drift < 1e-6);
    FIG("rom.wall_contact_ms", "%.3f", 1e3 * (t1 - t0 + dt));
    rom_result_free(&r);
    rom_model_deinit(&mod);
}

/* damped 1-DOF in contact (thesis §3.1, m x'' + d x' + k x = 0 with x(0) = 0, x'(0) = v0):
 * x(t) = v0/wd exp(-z wn t) sin(wd t), wn = sqrt(k/m), z = d/(2 sqrt(k m)), wd = wn sqrt(1-z^2)
 * (Thomson, "Theory of Vibration with Applications", sec. 2.6); compared up to the maximum
 * compression, where the one-sided contact still pushes */
static void test_damped_free_response(void)
{
    const double m = 35, k = 4e5, v0 = 10, z = 0.2, dt = 1e-5;
    const double wn = sqrt(k / m), wd = wn * sqrt(1 - z * z);
    double mass[ROM_NMASS] = {m, 0, 0, 0};
    rom_params p = linear_params(k);
    p.tyre_damping = 2 * z * sqrt(k * m);
    rom_model mod;
    rom_result r;
    mcs_error err = {0};
    CHECK(build(&mod, mass, v0, &p, 0.01, dt));
    CHECK(rom_run(&mod, &r, &err) == MCS_OK);
    double tpk = atan(sqrt(1 - z * z) / z) / wd, worst = 0; /* x' = 0 */
    for (int i = 0; i < r.nt && r.t[i] <= tpk; i++) {
        double t = r.t[i], x = v0 / wd * exp(-z * wn * t) * sin(wd * t);
        worst = fmax(worst, fabs(r.x[ROM_FRONT][i] - x));
    }
    printf("  damped 1-DOF: max |x - closed form| = %.3g m up to %.4f s\n", worst, tpk);
    CHECK(worst < 1e-7);
    rom_result_free(&r);
    rom_model_deinit(&mod);
}

/* 2-DOF: front m1 on the wall through k1, frame m2 on the front through k2, both at v0 at
 * first contact. Relative to the wall, M x'' + K x = 0, K = [[k1 + k2, -k2], [-k2, k2]];
 * modes from det(K - w^2 M) = 0 (two roots of a quadratic) and x = sum_i phi_i c_i sin(w_i t)
 * with phi_i^T M x'(0) / (phi_i^T M phi_i) = c_i w_i (Meirovitch, "Elements of Vibration
 * Analysis", ch. 4). Compared while both springs are compressed. */
static void test_two_dof_free_response(void)
{
    const double m1 = 35, m2 = 173, k1 = 4e5, k2 = 1e6, v0 = 5, dt = 1e-5;
    double mass[ROM_NMASS] = {m1, m2, 0, 0};
    rom_params p = linear_params(k1);
    p.fork_stiffness = p.fork_hardening = p.fork_unload = k2;
    p.fork_yield = k2 * 0.5; /* elastic limit 0.5 m: never reached */
    p.fork_stop = 1.0;
    p.stop_stiffness = k2;
    p.frame_gap = 10; /* the frame never reaches the wall */
    rom_model mod;
    rom_result r;
    mcs_error err = {0};
    CHECK(build(&mod, mass, v0, &p, 0.03, dt));
    CHECK(rom_run(&mod, &r, &err) == MCS_OK);
    /* (k1 + k2 - w2 m1)(k2 - w2 m2) - k2^2 = 0: a w2^2 + b w2 + c = 0 */
    double a = m1 * m2, b = -((k1 + k2) * m2 + k2 * m1), c = k1 * k2;
    double q = sqrt(b * b - 4 * a * c), w2[2] = {(-b - q) / (2 * a), (-b + q) / (2 * a)};
    double phi[2][2], cf[2];
    for (int i = 0; i < 2; i++) {
        phi[i][0] = 1, phi[i][1] = (k1 + k2 - w2[i] * m1) / k2;
        double num = m1 * phi[i][0] * v0 + m2 * phi[i][1] * v0;
        double den = m1 * phi[i][0] * phi[i][0] + m2 * phi[i][1] * phi[i][1];
        cf[i] = num / den / sqrt(w2[i]);
    }
    double worst = 0;
    int n = 0;
    for (int i = 0; i < r.nt; i++) {
        double t = r.t[i], x1 = 0, x2 = 0;
        for (int j = 0; j < 2; j++) {
            x1 += phi[j][0] * cf[j] * sin(sqrt(w2[j]) * t);
            x2 += phi[j][1] * cf[j] * sin(sqrt(w2[j]) * t);
        }
        if (i > 0 && (x1 <= 0 || x2 - x1 <= 0)) break; /* a spring opens: no longer linear */
        worst = fmax(worst, fmax(fabs(r.x[ROM_FRONT][i] - x1), fabs(r.x[ROM_FRAME][i] - x2)));
        n++;
    }
    printf("  2-DOF: %d samples in contact, max |x - modal solution| = %.3g m\n", n, worst);
    CHECK(n > 100);
    CHECK(worst < 1e-7);
    rom_result_free(&r);
    rom_model_deinit(&mod);
}

/* forced (base-excited) response: a frame m on a linear fork k behind a front of mass M >> m
 * that strikes the wall through a linear tyre K, both at v0: while in contact the front moves as
 * x_b = v0/W sin(W t), W = sqrt(K/M) (the frame's reaction is m/M = 1e-5 of it), and the fork's
 * deflection z = x_frame - x_front obeys m z'' + k z = -m x_b'' = m v0 W sin(W t), z(0) = z'(0)
 * = 0: z = v0 W/(w^2 - W^2) (sin W t - (W/w) sin w t), w = sqrt(k/m) (the undamped forced
 * response, Thomson, "Theory of Vibration with Applications", ch. 3); compared while z > 0 and
 * the front is on the wall (t < pi/W) */
static void test_forced_response(void)
{
    const double M = 1e6, m = 10, W = 2 * M_PI * 10, k = 1e5, v0 = 1, dt = 1e-5;
    const double K = M * W * W, w = sqrt(k / m);
    double mass[ROM_NMASS] = {M, m, 0, 0};
    rom_params p = linear_params(K);
    p.fork_stiffness = p.fork_hardening = p.fork_unload = p.stop_stiffness = k;
    p.fork_yield = k * 0.5; /* elastic limit 0.5 m: never reached */
    p.fork_stop = 1.0;
    p.frame_gap = 10;
    rom_model mod;
    rom_result r;
    mcs_error err = {0};
    CHECK(build(&mod, mass, v0, &p, M_PI / W, dt));
    CHECK(rom_run(&mod, &r, &err) == MCS_OK);
    double worst = 0, zmax = 0;
    int n = 0;
    for (int i = 1; i < r.nt; i++) {
        double t = r.t[i], z = v0 * W / (w * w - W * W) * (sin(W * t) - W / w * sin(w * t));
        if (z <= 0) break;
        worst = fmax(worst, fabs(r.d[ROM_FORK][i] - z));
        zmax = fmax(zmax, z);
        n++;
    }
    printf("  forced: %d samples, max |z - closed form| = %.3g m of %.4f m\n", n, worst, zmax);
    CHECK(n > 1000);
    CHECK(worst < 1e-4 * zmax);
    rom_result_free(&r);
    rom_model_deinit(&mod);
}

/* hysteresis: linear loading k, unloading slope ku > k from x_m (thesis §5.3, paper Fig. 7):
 * x_m = v0 sqrt(m/k); the loop's area k x_m^2/2 (1 - k/ku) is dissipated, the rest returns:
 * rebound speed v0 sqrt(k/ku) (the areas by hand; tests/test_hysteresis.c has the element) */
static void test_hysteresis_energy(void)
{
    const double m = 35, k = 4e5, ku = 1.6e6, v0 = 13.4;
    double mass[ROM_NMASS] = {m, 0, 0, 0};
    rom_params p = linear_params(k);
    p.tyre_travel = 1e-4; /* elastic limit 0.1 mm, the slope k on both sides */
    p.tyre_unload = ku;
    rom_model mod;
    rom_result r;
    mcs_error err = {0};
    CHECK(build(&mod, mass, v0, &p, 0.05, 1e-5));
    CHECK(rom_run(&mod, &r, &err) == MCS_OK);
    double e0 = 0.5 * m * v0 * v0, loop = e0 * (1 - k / ku);
    int e = r.nt - 1;
    printf("  hysteresis: dissipated %.3f J (loop area %.3f), rebound %.5f m/s (%.5f), "
           "drift %.2g\n",
           r.dissipated[e], loop, r.v[ROM_FRONT][e], -v0 * sqrt(k / ku), r.energy_drift);
    CHECK_REL(r.dissipated[e], loop, 1e-5);
    CHECK_REL(r.v[ROM_FRONT][e], -v0 * sqrt(k / ku), 1e-5);
    CHECK(r.energy_drift < 1e-5);
    FIG("rom.hyst_dissipated_pct", "%.1f", 100 * r.dissipated[e] / e0);
    rom_result_free(&r);
    rom_model_deinit(&mod);
}

/* the default motorcycle (208 kg, 13.4 m/s) by BDF and by Adams: another method, the same
 * answer to the tolerances (rtol 1e-8); and its energy balance */
static void test_bdf_adams(void)
{
    double mass[ROM_NMASS] = {35, 173, 0, 0};
    rom_params p = rom_params_default();
    p.rtol = 1e-8;
    rom_model a, b;
    rom_result ra, rb;
    mcs_error err = {0};
    CHECK(build(&a, mass, 13.4, &p, 0.1, 1e-4));
    p.adams = 1;
    CHECK(build(&b, mass, 13.4, &p, 0.1, 1e-4));
    CHECK(rom_run(&a, &ra, &err) == MCS_OK);
    CHECK(rom_run(&b, &rb, &err) == MCS_OK);
    double fpk = 0, dv = 0, df = 0;
    for (int i = 0; i < ra.nt; i++) {
        fpk = fmax(fpk, ra.wall_force[i]);
        df = fmax(df, fabs(ra.wall_force[i] - rb.wall_force[i]));
        dv = fmax(dv, fabs(ra.v[ROM_FRAME][i] - rb.v[ROM_FRAME][i]));
    }
    printf("  BDF %ld steps, Adams %ld; max |dF| %.3g N of %.0f N, |dv| %.3g m/s; drift %.2g\n",
           ra.steps, rb.steps, df, fpk, dv, ra.energy_drift);
    CHECK(df < 1e-4 * fpk);
    CHECK(dv < 1e-4 * 13.4);
    CHECK(ra.energy_drift < 1e-5);
    rom_result_free(&ra), rom_result_free(&rb);
    rom_model_deinit(&a), rom_model_deinit(&b);
}

/* a moving opponent: front against a free mass M at rest, linear elastic contact: momentum
 * is kept and, elastic, the velocities after are v0 (m - M)/(m + M) and 2 m v0/(m + M)
 * (Newtonian elastic collision) */
static void test_opponent_elastic(void)
{
    const double m = 35, M = 100, k = 4e5, v0 = 10;
    double mass[ROM_NMASS] = {m, 0, 0, 0};
    rom_params p = linear_params(k);
    p.opponent_mass = M;
    rom_model mod;
    rom_result r;
    mcs_error err = {0};
    CHECK(build(&mod, mass, v0, &p, 0.05, 1e-5));
    CHECK(rom_run(&mod, &r, &err) == MCS_OK);
    int e = r.nt - 1;
    CHECK_REL(r.v[ROM_FRONT][e], v0 * (m - M) / (m + M), 1e-5);
    CHECK_REL(r.v[ROM_OPP][e], 2 * m * v0 / (m + M), 1e-5);
    rom_result_free(&r);
    rom_model_deinit(&mod);
}

/* `mcrash rom` on the thesis frontal barrier case: /stage0 in the results layout, and
 * `mcrash compare` reads its channels */
static void test_cli_layout(void)
{
    const char *out = "/tmp/mcrash_test_rom.h5";
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rom scenarios/thesis_frontal_barrier_13.4.yaml -o %s --json", out);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"stage0\"");
    snprintf(cmd, sizeof cmd,
             "compare %s:/stage0/channels/barrier_fn %s:/stage0/channels/barrier_fn", out, out);
    r = cli_run(cmd);
    CHECK(r->status == 0);
    mcs_results *f = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&f, out, &err) == MCS_OK);
    if (f) {
        const char *p[] = {"/stage0/time", "/stage0/channels/moto_frame_ax",
                           "/stage0/bodies/moto_frame/velocity", "/stage0/energy/total"};
        for (int i = 0; i < 4; i++) CHECK(mcs_results_exists(f, p[i]));
        mcs_results_close(&f);
    }
    r = cli_run("rom tests/data/does_not_exist.yaml -o /tmp/mcrash_test_rom_x.h5");
    CHECK(r->status == 2);
    remove(out);
}

/* `stage: rom` in a study: every case run by the model; each response equals a direct run of
 * the model at that case's speed (the same code path without the study: another route to the
 * same numbers); a response naming no /stage0 dataset exits 2 before any case runs */
static void test_study_stage_rom(void)
{
    const char *out = "/tmp/mcrash_test_rom_study.h5";
    char cmd[512];
    snprintf(cmd, sizeof cmd, "study tests/data/study/rom_speed.yaml -o %s -j 2 --quiet", out);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    mcs_results *f = NULL;
    mcs_error err = {0};
    mcs_array st = {0}, fpk = {0};
    if (mcs_results_open(&f, out, &err) == MCS_OK) {
        mcs_results_read(f, "/study/status", &st, &err);
        mcs_results_read(f, "/study/responses/max:stage0.channels.barrier_fn", &fpk, &err);
        mcs_results_close(&f);
    }
    CHECK(st.n == 3 && fpk.n == 3);
    mcs_scenario *scn = NULL;
    rom_model base;
    CHECK(mcs_scenario_load("scenarios/thesis_frontal_barrier_13.4.yaml", &scn, &err) == MCS_OK);
    CHECK(scn && rom_model_from_scenario(&base, scn, &err) == MCS_OK);
    const double v[3] = {6.7, 9.8, 13.4};
    for (int c = 0; c < 3 && st.n == 3 && fpk.n == 3; c++) {
        rom_model m;
        rom_result rr;
        CHECK(st.v[c] == 0);
        CHECK(rom_model_init(&m, base.mass, v[c], base.gap0, &base.p, base.end_time, base.out_dt,
                             &err) == MCS_OK);
        CHECK(rom_run(&m, &rr, &err) == MCS_OK);
        double pk = 0;
        for (int i = 0; i < rr.nt; i++) pk = fmax(pk, rr.wall_force[i]);
        printf("  study case %d: %.1f m/s, peak barrier force %.1f N (direct %.1f N)\n", c, v[c],
               fpk.v[c], pk);
        CHECK_REL(fpk.v[c], pk, 1e-12);
        rom_result_free(&rr);
        rom_model_deinit(&m);
    }
    rom_model_deinit(&base);
    mcs_scenario_destroy(&scn);
    mcs_array_free(&st), mcs_array_free(&fpk);
    r = cli_run("study tests/data/study/rom_bad_response.yaml -o /tmp/mcrash_test_rom_bad.h5");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "rom_bad_response.yaml:");
    CHECK_STR_CONTAINS(r->err, "/stage0/channels/no_such_channel");
}

/* the rider in /stage0 and `mcrash injury --stage 0`: the rider mass is read as the chest
 * (rider_torso), so the chest a3ms criterion is there; every rom: key names its own field */
static void test_rider_injury_and_params(void)
{
    const char *out = "/tmp/mcrash_test_rom_rider.h5";
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rom tests/data/rom/frontal_rider_13.4.yaml -o %s --quiet", out);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    snprintf(cmd, sizeof cmd, "injury %s --stage 0 --json", out);
    r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"stage\": 0");
    CHECK_STR_CONTAINS(r->out, "chest_a3ms");
    remove(out);
    r = cli_run("injury tests/data/rom/frontal_13.4.yaml --stage 4");
    CHECK(r->status == 2);
    rom_params p = rom_params_default();
    int n = 0, dup = 0;
    for (int i = 0; rom_param_names[i]; i++, n++) {
        double *a = rom_param_ptr(&p, rom_param_names[i]);
        CHECK(a != NULL);
        for (int j = 0; j < i; j++) dup += a == rom_param_ptr(&p, rom_param_names[j]);
    }
    CHECK(dup == 0);
    /* every double of rom_params is named (the int `adams` is the method key) */
    CHECK(n == (int)((sizeof p - sizeof(double)) / sizeof(double)));
}

int main(void)
{
    RUN(test_wall_impact_linear);
    RUN(test_damped_free_response);
    RUN(test_two_dof_free_response);
    RUN(test_forced_response);
    RUN(test_hysteresis_energy);
    RUN(test_bdf_adams);
    RUN(test_opponent_elastic);
    RUN(test_cli_layout);
    RUN(test_study_stage_rom);
    RUN(test_rider_injury_and_params);
    TEST_END();
}

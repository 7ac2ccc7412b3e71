/* tests for translators/tr_lm (bounded Levenberg-Marquardt) on problems with closed-form
 * answers, and for translators/tr_retune (`mcrash retune`): an identifiability test -- a target
 * made by stage 1 with known perturbed characteristics (written by hand below), stored in the
 * stage-3 layout, must give those parameters back -- and bad input exiting 2 naming the key. */
#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "tests/cli_util.h"
#include "tests/harness.h"

#include "tests/figures.h"
#include "translators/tr_lm.h"
#include "translators/tr_retune.h"

#include <math.h>

/* Rosenbrock as least squares: r = (10 (y - x^2), 1 - x); minimum (1, 1), cost 0
 * (Rosenbrock 1960; More, Garbow, Hillstrom 1981 problem 1, start (-1.2, 1)) */
static mcs_status rosen(void *ctx, const double *p, double *r, mcs_error *err)
{
    (void)ctx, (void)err;
    r[0] = 10 * (p[1] - p[0] * p[0]);
    r[1] = 1 - p[0];
    return MCS_OK;
}

/* y = a exp(-b t) sampled exactly at a = 2, b = 3: the fit's answer is (2, 3) */
static mcs_status expo(void *ctx, const double *p, double *r, mcs_error *err)
{
    (void)ctx, (void)err;
    for (int i = 0; i < 20; i++) {
        double t = 0.05 * i;
        r[i] = p[0] * exp(-p[1] * t) - 2 * exp(-3 * t);
    }
    return MCS_OK;
}

/* r = p - c: the bounded minimum is c projected onto the box (clip each component) */
static mcs_status shift(void *ctx, const double *p, double *r, mcs_error *err)
{
    (void)err;
    const double *c = ctx;
    r[0] = p[0] - c[0], r[1] = p[1] - c[1];
    return MCS_OK;
}

static void test_lm_closed_form(void)
{
    mcs_error e = {0};
    tr_lm_result res;
    tr_lm_opts o = tr_lm_opts_default();
    o.max_iter = 200;
    double p[2] = {-1.2, 1}, lo[2] = {-2, -2}, hi[2] = {2, 2};
    CHECK(tr_lm_solve(rosen, NULL, 2, 2, p, lo, hi, &o, &res, &e) == MCS_OK);
    CHECK_NEAR(p[0], 1, 1e-6);
    CHECK_NEAR(p[1], 1, 1e-6);
    CHECK(res.cost < 1e-12);

    double q[2] = {1, 1}, lq[2] = {0.1, 0.1}, hq[2] = {10, 10};
    CHECK(tr_lm_solve(expo, NULL, 2, 20, q, lq, hq, NULL, &res, &e) == MCS_OK);
    CHECK_NEAR(q[0], 2, 1e-6);
    CHECK_NEAR(q[1], 3, 1e-6);

    /* c = (3, -1) in the box [0, 2]^2: answer (2, 0), both on a bound */
    double c[2] = {3, -1}, s[2] = {1, 1}, ls[2] = {0, 0}, hs[2] = {2, 2};
    CHECK(tr_lm_solve(shift, c, 2, 2, s, ls, hs, NULL, &res, &e) == MCS_OK);
    CHECK_NEAR(s[0], 2, 1e-12);
    CHECK_NEAR(s[1], 0, 1e-12);

    double lb[2] = {1, 0};
    CHECK(tr_lm_solve(shift, c, 2, 2, s, lb, lb, NULL, &res, &e) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e.msg, "bounds");
}

#define SCN "scenarios/thesis_frontal_barrier_13.4.yaml"

/* the target: stage 1 of the thesis barrier case with the tyre's loading forces x 0.8 and the
 * fork hinge's moments x 1.3 (elastic limit 0.061667 rad and stop 0.2 rad kept, or moved to
 * phi_e, phi_s), every number written out by hand from scenarios/models/motorcycles/
 * sport_208kg.yaml; stored as /stage3/{time, rigidwall/barrier/force,
 * joints/moto_fork_deformation/angle} (docs/contracts.md) */
static int make_target(const char *dir, double t_end, double phi_e, double phi_s, const char *h5)
{
    char yaml[512], s1[512], cmd[2048];
    snprintf(yaml, sizeof yaml, "%s/target.yaml", dir);
    snprintf(s1, sizeof s1, "%s/target_s1.h5", dir);
    char *real = realpath(SCN, NULL);
    FILE *f = fopen(yaml, "w");
    if (!f || !real) return 0;
    double me = 1.3 * 3700, mp = 1.3 * 4700; /* 4810 and 6110 N m */
    fprintf(f,
            "mcrash: 1\ninclude: [\"%s\"]\nsimulation: {end_time: %g}\ncharacteristics:\n"
            "  tyre_front:\n    loading: [[0, 0], [10 mm, 1.44 kN], [30 mm, 4.8 kN], "
            "[60 mm, 12 kN], [80 mm, 40 kN], [200 mm, 56 kN], [300 mm, 160 kN]]\n"
            "  fork_deformation:\n    loading: [[0, 0], [%.9g, %.9g], [%.9g, %.9g], "
            "[%.9g, %.9g]]\n    unloading_slope: %.9g\n    elastic_limit: %.9g\n",
            real, t_end, phi_e, me, phi_s, mp, phi_s + 0.02, mp + 3e6 * 0.02, me / phi_e, phi_e);
    fclose(f);
    free(real);
    snprintf(cmd, sizeof cmd, "stage1 %s -o %s --quiet", yaml, s1);
    if (cli_run(cmd)->status != 0) return 0;
    static const char *const wall[] = {"front_tyre_barrier", "frame_barrier", "handlebar_barrier",
                                       "fork_barrier", "rear_tyre_barrier"};
    mcs_error e = {0};
    mcs_results *r = NULL, *w = NULL;
    mcs_array t = {0}, a = {0}, c = {0};
    int ok = mcs_results_open(&r, s1, &e) == MCS_OK &&
             mcs_results_read(r, "/stage1/time", &t, &e) == MCS_OK &&
             mcs_results_read(r, "/stage1/channels/moto_fork_deformation_angle", &a, &e) == MCS_OK;
    double *force = ok ? calloc(t.n, sizeof(double)) : NULL;
    for (int k = 0; k < 5 && ok; k++) {
        snprintf(cmd, sizeof cmd, "/stage1/channels/%s_fn", wall[k]);
        ok = mcs_results_read(r, cmd, &c, &e) == MCS_OK && c.n == t.n;
        for (size_t i = 0; ok && i < t.n; i++)
            force[i] += c.v[i];
        mcs_array_free(&c);
    }
    mcs_results_close(&r);
    size_t d[1] = {t.n};
    ok = ok && mcs_results_create(&w, h5, "", &e) == MCS_OK &&
         mcs_results_write(w, "/stage3/time", 1, d, t.v, "s", &e) == MCS_OK &&
         mcs_results_write(w, "/stage3/rigidwall/barrier/force", 1, d, force, "N", &e) == MCS_OK &&
         mcs_results_write(w, "/stage3/joints/moto_fork_deformation/angle", 1, d, a.v, "rad", &e) ==
             MCS_OK &&
         mcs_results_commit(&w, &e) == MCS_OK;
    mcs_results_abort(&w);
    if (!ok) fprintf(stderr, "target: %s\n", e.msg);
    free(force);
    mcs_array_free(&t), mcs_array_free(&a);
    return ok;
}

static void test_identifiability(void)
{
    char dir[] = "/tmp/mcrash_retune_XXXXXX", h5[128];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(h5, sizeof h5, "%s/target3.h5", dir);
    int full = th_verify();
    /* make test: the two scales on the first 150 ms; verify: all four over 250 ms with the
     * elastic limit moved to 0.075 rad and the stop to 0.24 rad */
    double phi_e = full ? 0.075 : 0.061667, phi_s = full ? 0.24 : 0.2;
    CHECK(make_target(dir, full ? 0.25 : 0.15, phi_e, phi_s, h5));
    tr_rt_opts o = tr_rt_opts_default();
    o.scenario = SCN;
    o.free_mask = full ? 0xf : 0x3;
    o.jobs = 2;
    tr_rt_target t;
    tr_rt_base b;
    tr_rt_result r;
    mcs_error e = {0};
    CHECK(tr_rt_read_target(h5, &o, &t, &e) == MCS_OK);
    CHECK(tr_rt_read_base(&o, &b, &e) == MCS_OK);
    CHECK(tr_rt_fit(&o, &b, &t, &r, &e) == MCS_OK);
    if (e.status) fprintf(stderr, "%s\n", e.msg);
    tr_rt_result_free(&r);
    tr_rt_target_free(&t);
    printf("retune: %d iterations %d runs (%s); p = %.5f %.5f %.5f %.5f; iso force %.3f -> "
           "%.3f, angle %.3f -> %.3f\n",
           r.iter, r.nfev, r.why, r.p[0], r.p[1], r.p[2], r.p[3], r.iso_force0, r.iso_force,
           r.iso_angle0, r.iso_angle);
    /* the known parameters within 2 % (issue 16 item 5) */
    CHECK_REL(r.p[0], 0.8, 0.02);
    CHECK_REL(r.p[1], 1.3, 0.02);
    CHECK_REL(r.p[2], phi_e, 0.02);
    CHECK_REL(r.p[3], phi_s, 0.02);
    /* the rating of a target reproduced is 1 (ISO/TS 18571 of identical signals) */
    CHECK(r.iso_force > 0.99 && r.iso_angle > 0.99);
    CHECK(r.iso_force0 < r.iso_force);
    if (full) {
        FIG("retune.verify_iso_force_before", "%.2f", r.iso_force0);
        FIG("retune.verify_iso_angle_before", "%.2f", r.iso_angle0);
    } else {
        FIG("retune.iso_force_before", "%.2f", r.iso_force0);
        FIG("retune.iso_angle_before", "%.2f", r.iso_angle0);
    }

    /* the command: CURVES.yaml that stage 1 includes, /curves in the results file */
    char cmd[1024], curves[256], s1[256];
    snprintf(curves, sizeof curves, "%s/curves.yaml", dir);
    /* the scenario's retune: block: one free parameter over the first 30 ms */
    snprintf(s1, sizeof s1, "%s/s1.yaml", dir);
    char *real = realpath(SCN, NULL);
    FILE *f = fopen(s1, "w");
    CHECK(f && real);
    if (f) {
        fprintf(f, "mcrash: 1\ninclude: [\"%s\"]\nretune: {free: [tyre_force_scale], "
                   "end_time: 30 ms, wall_body: barrier, tyre: tyre_front}\n",
                real);
        fclose(f);
    }
    free(real);
    snprintf(cmd, sizeof cmd, "retune %s --scenario %s -o %s -j 1 --csv %s/cmp.csv --json", h5, s1,
             curves, dir);
    cli_result *c = cli_run(cmd);
    CHECK(c->status == 0);
    if (c->status) fprintf(stderr, "%s", c->err);
    CHECK_STR_CONTAINS(c->out, "\"iso18571\": {\"wall_force\": {\"before\": ");
    /* the same fit two stage-1 runs at a time: the same output to the last digit (each run is
     * a fresh process whatever -j, docs/retune.md "Parallel runs") */
    char *out1 = strdup(c->out);
    CHECK_STR_CONTAINS(c->out, "\"fork_moment_scale\": {\"before\": 1, \"after\": 1,");
    /* the compared curves: a header and one row per 0.1 ms of the 30 ms */
    char csvp[256], line[512];
    snprintf(csvp, sizeof csvp, "%s/cmp.csv", dir);
    FILE *fc = fopen(csvp, "r");
    int rows = 0;
    CHECK(fc && fgets(line, sizeof line, fc));
    CHECK_STR_CONTAINS(line, "time [s], force_stage3 [N], force_before [N], force_after [N]");
    while (fc && fgets(line, sizeof line, fc))
        rows++;
    if (fc) fclose(fc);
    CHECK(rows == 301);
    snprintf(cmd, sizeof cmd, "retune %s --scenario %s -o %s -j 2 --csv %s/cmp.csv --json", h5, s1,
             curves, dir);
    c = cli_run(cmd);
    CHECK(c->status == 0);
    CHECK(out1 && strcmp(out1, c->out) == 0);
    if (c->status) fprintf(stderr, "-j 2: status %d: %s", c->status, c->err);
    if (out1 && strcmp(out1, c->out)) fprintf(stderr, "-j 1: %s-j 2: %s", out1, c->out);
    free(out1);
    mcs_scenario *s = NULL;
    CHECK(mcs_scenario_load(curves, &s, &e) == MCS_OK);
    mcs_scenario_destroy(&s);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, h5, &e) == MCS_OK);
    CHECK(mcs_results_exists(h, "/curves/tyre_front/loading"));
    CHECK(mcs_results_exists(h, "/curves/fork_deformation/unloading"));
    mcs_results_close(&h);
    if (!getenv("RETUNE_KEEP")) {
        snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
        CHECK(system(cmd) == 0);
    }
}

static void test_bad_input(void)
{
    cli_result *c = cli_run("retune tests/data/none.h5");
    CHECK(c->status == 2);
    CHECK_STR_CONTAINS(c->err, "--scenario");
    /* a results file without stage 3: the missing key is named */
    char dir[] = "/tmp/mcrash_retune_XXXXXX", h5[128], cmd[512];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(h5, sizeof h5, "%s/s1.h5", dir);
    mcs_results *w = NULL;
    mcs_error e = {0};
    double v[12] = {0};
    size_t d[1] = {12};
    CHECK(mcs_results_create(&w, h5, "", &e) == MCS_OK &&
          mcs_results_write(w, "/stage3/time", 1, d, v, "s", &e) == MCS_OK &&
          mcs_results_commit(&w, &e) == MCS_OK);
    snprintf(cmd, sizeof cmd, "retune %s --scenario %s", h5, SCN);
    c = cli_run(cmd);
    CHECK(c->status == 2);
    CHECK_STR_CONTAINS(c->err, "/stage3/joints/moto_fork_deformation/angle: not in the results");
    /* a scenario without the fork characteristic */
    tr_rt_opts o = tr_rt_opts_default();
    tr_rt_base b;
    o.scenario = "scenarios/verification/bounce_elastic.yaml";
    mcs_status st = tr_rt_read_base(&o, &b, &e);
    CHECK(st == MCS_ERR_KEY);
    CHECK(mcs_status_exit_code(st) == 2);
    CHECK_STR_CONTAINS(e.msg, "characteristics.tyre_front.loading: not in the scenario");
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
}

int main(void)
{
    RUN(test_lm_closed_form);
    RUN(test_bad_input);
    RUN(test_identifiability);
    TEST_END();
}

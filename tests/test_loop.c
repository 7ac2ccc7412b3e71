/* test_loop.c: `mcrash loop` (cli/cmd_loop.c, docs/loop.md) on a small case made for it
 * (tests/data/loop/: a rigid block with a hinged rod into a rigid wall as the stage-3 case, the
 * thesis barrier scenario retuned against it with one free parameter over 30 ms, a 50 ms crash
 * with stage 2). Checks the machinery, not the models:
 * - the loop runs stage 3, retune, stages 1 and 2 and the ratings, writes iter_<k>.h5 with
 *   /stage1, /stage2 and /curves, loop.json with DESIGN.md's keys and loop.csv;
 * - iteration 2's retune starts at iteration 1's fit, which is a fixed point of the fit (the
 *   LM moves only when the objective drops), so its parameters and every rating are the same:
 *   the loop stops "converged" after 2 iterations (the stopping rule, by construction);
 * - --max-iter 1 stops with reason max-iter, converged false, exit 0; a stage-3 results file
 *   as `wall:` is used as it is;
 * - a stage that fails stops the loop with that stage's exit status and says so. */
#include "core/mcs_results.h"
#include "tests/cli_util.h"
#include "tests/harness.h"

#include "tests/figures.h"
#include "analysis/an_cfc.h"
#include "analysis/an_iso18571.h"
#include "translators/tr_retune.h"

#include <math.h>

#include <stdlib.h>
#include <string.h>

#define DATA "tests/data/loop"

static char tdir[] = "/tmp/mcrash_loop_XXXXXX";

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *b = calloc(1, 1 << 20);
    if (b) b[fread(b, 1, (1 << 20) - 1, f)] = 0;
    fclose(f);
    return b;
}

/* a loop scenario in tdir naming wall, retune and crash (absolute paths) */
static void write_loop(const char *name, const char *wall, const char *retune, const char *crash)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", tdir, name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fprintf(f, "mcrash: 1\nloop: {wall: \"%s\", retune: \"%s\", crash: \"%s\"}\n", wall, retune,
            crash);
    fclose(f);
}

/* "name": <number> after the first occurrence of key in s */
static double json_num(const char *s, const char *key)
{
    const char *p = s ? strstr(s, key) : NULL;
    return p ? strtod(p + strlen(key), NULL) : -1;
}

static void test_converges(void)
{
    char cmd[1024], out[512], path[600];
    snprintf(out, sizeof out, "%s/run", tdir);
    snprintf(cmd, sizeof cmd, "loop %s/loop.yaml -o %s -j 2", DATA, out);
    cli_result *c = cli_run(cmd);
    CHECK(c->status == 0);
    if (c->status) fprintf(stderr, "%s%s", c->out, c->err);
    CHECK_STR_CONTAINS(c->out, "loop: converged: no rating changed by more than 0.01");
    snprintf(path, sizeof path, "%s/loop.json", out);
    char *j = slurp(path);
    CHECK(j != NULL);
    CHECK_STR_CONTAINS(j, "\"converged\": true, \"reason\": \"converged");
    CHECK_STR_CONTAINS(j, "{\"k\": 2,");
    CHECK(j && !strstr(j, "{\"k\": 3,"));
    CHECK_STR_CONTAINS(j, "\"ratings\": {\"stage1_vs_stage3\": {\"wall_force\": ");
    CHECK_STR_CONTAINS(j, "\"stage2_vs_stage1\": {\"moto_frame_ax\": ");
    CHECK_STR_CONTAINS(j, "\"criteria\": {\"stage1\": {");
    CHECK_STR_CONTAINS(j, "\"parameters\": {\"tyre_force_scale\": ");
    /* iteration 2 from iteration 1's fit: the same parameter and ratings */
    const char *j2 = j ? strstr(j, "{\"k\": 2,") : NULL;
    double p1 = json_num(j, "\"tyre_force_scale\": "), p2 = json_num(j2, "\"tyre_force_scale\": ");
    double f1 = json_num(j, "\"wall_force\": "), f2 = json_num(j2, "\"wall_force\": ");
    printf("loop: tyre_force_scale %.6f, %.6f; wall force rating %.4f, %.4f\n", p1, p2, f1, f2);
    CHECK(p1 >= 0.5 && p1 <= 2 && p1 == p2);
    CHECK(f1 >= 0 && f1 <= 1 && f1 == f2);
    free(j);
    snprintf(path, sizeof path, "%s/curves_2.csv", out);
    CHECK(access(path, F_OK) == 0);
    snprintf(path, sizeof path, "%s/loop.csv", out);
    char *csv = slurp(path);
    CHECK_STR_CONTAINS(csv, "k,group,name,value\n1,stage1_vs_stage3,wall_force,");
    CHECK_STR_CONTAINS(csv, "\n2,parameters,tyre_force_scale,");
    free(csv);
    mcs_results *h = NULL;
    mcs_error e = {0};
    snprintf(path, sizeof path, "%s/iter_2.h5", out);
    CHECK(mcs_results_open(&h, path, &e) == MCS_OK);
    CHECK(mcs_results_exists(h, "/stage1/channels/front_tyre_barrier_fn"));
    CHECK(mcs_results_exists(h, "/stage2/channels/front_tyre_barrier_fn"));
    CHECK(mcs_results_exists(h, "/curves/tyre_front/loading"));
    CHECK(mcs_results_exists(h, "/curves/fork_deformation/unloading"));
    mcs_results_close(&h);
}

static void test_max_iter_and_failures(void)
{
    char cmd[1024], out[512], path[600], wall[600], rt[600], cr[600], bad[600];
    char *d = realpath(DATA, NULL);
    CHECK(d != NULL);
    if (!d) return;
    snprintf(wall, sizeof wall, "%s/run/wall_stage3.h5", tdir);
    snprintf(rt, sizeof rt, "%s/retune_s1.yaml", d);
    snprintf(cr, sizeof cr, "%s/crash.yaml", d);
    /* the stage-3 run of test_converges as wall:, one iteration */
    write_loop("once.yaml", wall, rt, cr);
    snprintf(out, sizeof out, "%s/once", tdir);
    snprintf(cmd, sizeof cmd, "loop %s/once.yaml -o %s --max-iter 1", tdir, out);
    cli_result *c = cli_run(cmd);
    CHECK(c->status == 0);
    CHECK_STR_CONTAINS(c->out, "loop: max-iter: 1 iterations");
    snprintf(path, sizeof path, "%s/loop.json", out);
    char *j = slurp(path);
    CHECK_STR_CONTAINS(j, "\"converged\": false, \"reason\": \"max-iter: 1 iterations");
    free(j);
    snprintf(path, sizeof path, "%s/wall_stage3.h5", out);
    CHECK(access(path, F_OK) != 0); /* not run again */

    /* stage 3 fails: a stage-1 scenario given as the wall case (no fe: or stage3: block), exit 2
     * (not crash.yaml: the thesis case it includes has a stage3: block since the stage-3 wall case) */
    char *s1 = realpath("scenarios/verification/pendulum.yaml", NULL);
    CHECK(s1 != NULL);
    write_loop("bad3.yaml", s1 ? s1 : "missing.yaml", rt, cr);
    free(s1);
    snprintf(cmd, sizeof cmd, "loop %s/bad3.yaml -o %s/bad3", tdir, tdir);
    c = cli_run(cmd);
    CHECK(c->status == 2);
    CHECK_STR_CONTAINS(c->err, "loop: stage 3 of the wall case failed (exit status 2)");
    snprintf(path, sizeof path, "%s/bad3/loop.json", tdir);
    j = slurp(path);
    CHECK_STR_CONTAINS(j, "\"iterations\": [\n  ],\n  \"converged\": false, \"reason\": \"stage 3");
    free(j);

    /* the crash scenario has no stage2: block: refused naming the key, exit 2 */
    write_loop("bad2.yaml", wall, rt, rt);
    snprintf(cmd, sizeof cmd, "loop %s/bad2.yaml -o %s/bad2", tdir, tdir);
    c = cli_run(cmd);
    CHECK(c->status == 2);
    CHECK_STR_CONTAINS(c->err, "stage2: not in the crash scenario");

    /* a file that does not exist, at its key */
    snprintf(bad, sizeof bad, "%s/none.yaml", tdir);
    write_loop("bad1.yaml", wall, bad, cr);
    snprintf(cmd, sizeof cmd, "loop %s/bad1.yaml -o %s/bad1", tdir, tdir);
    c = cli_run(cmd);
    CHECK(c->status == 2);
    CHECK_STR_CONTAINS(c->err, "bad1.yaml:2:");
    CHECK_STR_CONTAINS(c->err, "loop.retune: ");
    free(d);
}

/* a stage-3 run of scenario scn: MCRASH_S3_CACHE/<name>.h5 when that directory holds one (a
 * rerun of the same stage-3 code), else run now into tdir (2.5 min of wall time); 1 when out
 * names the file */
static int stage3_of(const char *scn, const char *name, char *out, size_t n)
{
    const char *cache = getenv("MCRASH_S3_CACHE");
    if (cache) {
        snprintf(out, n, "%s/%s.h5", cache, name);
        if (access(out, R_OK) == 0) {
            printf("  stage 3 of %s: %s (cached)\n", scn, out);
            return 1;
        }
    }
    snprintf(out, n, "%s/%s.h5", tdir, name);
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "stage3 %s -o %s --quiet", scn, out);
    cli_result *c = cli_run(cmd);
    if (c->status) fprintf(stderr, "%s: %s", cmd, c->err);
    return c->status == 0;
}

/* the plots of docs/loop.md: into docs/img under `make figures` (MCRASH_FIGURES_OUT), else
 * into tdir; each must be an SVG with the three curves (stage 3, stage 1 before and after) */
static void plots(const tr_rt_result *r, const char *name, const char *what)
{
    for (int k = 0; k < 2; k++) {
        char path[600], title[160];
        snprintf(path, sizeof path, "%s/%s_%s.svg",
                 getenv("MCRASH_FIGURES_OUT") ? "docs/img" : tdir, name, k ? "angle" : "force");
        snprintf(title, sizeof title, "%s, %s: stage 1 before and after retune, and stage 3",
                 what, k ? "fork angle" : "wall force");
        FILE *f = fopen(path, "w");
        CHECK(f != NULL);
        if (!f) continue;
        tr_rt_write_svg(f, r, k, title);
        CHECK(fclose(f) == 0);
        char *svg = th_slurp(path, NULL);
        int npath = 0;
        for (const char *q = svg; q && (q = strstr(q, "<path d=")); q++)
            npath++;
        CHECK_STR_CONTAINS(svg, "<svg");
        CHECK_STR_CONTAINS(svg, "stage 1 after (ISO ");
        CHECK(npath == 3);
        free(svg);
    }
}

/* retune of the stage-3 file h5 against scenario scn (the scenario's retune: block; end > 0:
 * its compared span); after: a fit to rate at with nothing free (a case not in the fit) */
static int retune_of(const char *h5, const char *scn, double end, const double *after,
                     tr_rt_result *r)
{
    tr_rt_opts o = tr_rt_opts_default();
    o.scenario = scn;
    o.jobs = 2;
    tr_rt_target t;
    tr_rt_base b;
    mcs_error e = {0};
    int ok = tr_rt_read_opts(&o, &e) == MCS_OK;
    if (end > 0) o.end_time = end;
    if (after) {
        o.free_mask = 0, o.has_after = 1;
        memcpy(o.after, after, sizeof o.after);
    }
    ok = ok && tr_rt_read_target(h5, &o, &t, &e) == MCS_OK;
    ok = ok && tr_rt_read_base(&o, &b, &e) == MCS_OK;
    ok = ok && tr_rt_fit(&o, &b, &t, r, &e) == MCS_OK;
    if (!ok) fprintf(stderr, "retune %s: %s\n", h5, e.msg);
    tr_rt_target_free(&t);
    if (ok) {
        printf("  retune %s (%s): %d iterations, %d runs (%s); ISO force %.3f -> %.3f, angle "
               "%.3f -> %.3f\n  p =",
               h5, scn, r->iter, r->nfev, r->why, r->iso_force0, r->iso_force, r->iso_angle0,
               r->iso_angle);
        for (int i = 0; i < TR_RT_NPAR; i++)
            printf(" %s %.5g [%g, %g]%s", tr_rt_par_name(i), r->p[i], r->lo[i], r->hi[i],
                   r->p[i] <= r->lo[i] || r->p[i] >= r->hi[i] ? " (bound)" : "");
        printf("\n");
    }
    return ok;
}

/* the diagnosis of docs/retune.md "On the stage-3 wall case", from the stage-3 file h5 and the
 * fit r on it: per phase of the stage-3 run (its /stage3/phases: tyre, rim, fork, engine start
 * times) the mean wall force of stage 3, stage 1 before and after [kN] and the fork angles at
 * the phase's end [rad]; then the ceiling a stage 1 without a surface on the upper fork can
 * reach: the ISO/TS 18571 rating of stage 3's wall force against itself less the rigid upper
 * fork's share (both CFC 60 on the fit's grid) */
static void diagnose(const char *h5, const tr_rt_result *r)
{
    static const char *const ph[4] = {"tyre", "rim", "fork", "engine"};
    double t0[5];
    mcs_results *h = NULL;
    mcs_error e = {0};
    mcs_array a = {0}, ft = {0}, fu = {0}, tt = {0};
    CHECK(mcs_results_open(&h, h5, &e) == MCS_OK);
    for (int k = 0; k < 4 && h; k++) {
        char path[128];
        snprintf(path, sizeof path, "/stage3/phases/%s/start_time", ph[k]);
        CHECK(mcs_results_read(h, path, &a, &e) == MCS_OK && a.n == 1);
        t0[k] = a.n == 1 ? a.v[0] : NAN;
        mcs_array_free(&a);
    }
    t0[4] = r->t[r->nt - 1] + 1e-9;
    /* the keys written out: tests/test_figures.c finds each marker's key literally here */
    static const char *const key[4][6] = {
        {"loop.phase_tyre_f3", "loop.phase_tyre_f1b", "loop.phase_tyre_f1a",
         "loop.phase_tyre_a3", "loop.phase_tyre_a1b", "loop.phase_tyre_a1a"},
        {"loop.phase_rim_f3", "loop.phase_rim_f1b", "loop.phase_rim_f1a", "loop.phase_rim_a3",
         "loop.phase_rim_a1b", "loop.phase_rim_a1a"},
        {"loop.phase_fork_f3", "loop.phase_fork_f1b", "loop.phase_fork_f1a",
         "loop.phase_fork_a3", "loop.phase_fork_a1b", "loop.phase_fork_a1a"},
        {"loop.phase_engine_f3", "loop.phase_engine_f1b", "loop.phase_engine_f1a",
         "loop.phase_engine_a3", "loop.phase_engine_a1b", "loop.phase_engine_a1a"}};
    for (int k = 0; k < 4; k++) {
        double sum[3] = {0, 0, 0}, end[3] = {0, 0, 0};
        int n = 0;
        for (int i = 0; i < r->nt; i++) {
            if (r->t[i] < t0[k] || r->t[i] >= t0[k + 1]) continue;
            sum[0] += r->tf[i], sum[1] += r->f0[i], sum[2] += r->f1[i], n++;
            end[0] = r->ta[i], end[1] = r->a0[i], end[2] = r->a1[i];
        }
        CHECK(n > 0);
        printf("  phase %-6s from %5.1f ms: mean force stage 3 %6.1f, before %6.1f, after %6.1f "
               "kN; angle at its end %.3f, %.3f, %.3f rad\n",
               ph[k], 1e3 * t0[k], 1e-3 * sum[0] / n, 1e-3 * sum[1] / n, 1e-3 * sum[2] / n,
               end[0], end[1], end[2]);
        for (int j = 0; j < 6 && n > 0; j++) {
            if (j < 3)
                FIG(key[k][j], "%.0f", 1e-3 * sum[j] / n);
            else
                FIG(key[k][j], "%.2f", end[j - 3]);
        }
    }
    FIG("loop.phase_rim_t_ms", "%.1f", 1e3 * t0[1]);
    FIG("loop.phase_fork_t_ms", "%.1f", 1e3 * t0[2]);
    FIG("loop.phase_engine_t_ms", "%.1f", 1e3 * t0[3]);
    /* the upper fork's share: a rigid part against the rigid wall */
    int ok = h && mcs_results_read(h, "/stage3/time", &tt, &e) == MCS_OK &&
             mcs_results_read(h, "/stage3/rigidwall/barrier/force_mean", &ft, &e) == MCS_OK &&
             mcs_results_read(h, "/stage3/rigidwall/barrier/parts/moto_upper_fork/force", &fu,
                              &e) == MCS_OK &&
             ft.n == tt.n && fu.n == tt.n;
    CHECK(ok);
    int nt = r->nt;
    double *x = calloc(4 * (size_t)nt, sizeof(double)), *y = x + nt, *fx = y + nt, *fy = fx + nt;
    double dt = r->t[1] - r->t[0], peak = 0, tpk = 0, upk = 0;
    for (int i = 0; ok && x && i < nt; i++) {
        size_t m = 0; /* the stage-3 row at or before the grid time (rows every 0.1 ms) */
        while (m + 1 < tt.n && tt.v[m + 1] <= tt.v[0] + r->t[i] + 1e-9)
            m++;
        x[i] = ft.v[m], y[i] = ft.v[m] - fu.v[m];
        upk = fmax(upk, fu.v[m]);
    }
    if (ok && x) {
        CHECK(an_cfc_filter(x, nt, dt, 60, fx, &e) == MCS_OK);
        CHECK(an_cfc_filter(y, nt, dt, 60, fy, &e) == MCS_OK);
        for (int i = 0; i < nt; i++)
            if (fx[i] > peak) peak = fx[i], tpk = r->t[i];
        an_iso_opts io = an_iso_opts_default();
        an_iso_result res;
        CHECK(an_iso18571_arrays(fx, fy, nt, dt, &io, &res, &e) == MCS_OK);
        printf("  stage 3's wall force peak %.0f kN (CFC 60) at %.1f ms, the upper fork's "
               "0.1 ms mean up to %.0f kN; rating without the upper fork's share %.3f\n",
               1e-3 * peak, 1e3 * tpk, 1e-3 * upk, res.rating);
        FIG("loop.s3_force_peak_kn", "%.0f", 1e-3 * peak);
        FIG("loop.s3_force_peak_ms", "%.0f", 1e3 * tpk);
        FIG("loop.s3_upper_fork_kn", "%.0f", 1e-3 * upk);
        FIG("loop.ceiling_iso_force", "%.2f", res.rating);
    }
    free(x);
    mcs_array_free(&tt), mcs_array_free(&ft), mcs_array_free(&fu);
    mcs_results_close(&h);
}

/* make verify: the shipped loop (scenarios/thesis_barrier_loop.yaml: the FE motorcycle into
 * the rigid wall, 40 mm, 60 ms; retune of the thesis scenario's stage 1 with all six
 * parameters; its stage 1 and a stage 2 replaying the frame) converges within 5 iterations
 * (issue 16 item 5). Then the ratings of stage 1 against stage 3 on the loop's stage-3 run
 * with the scenario's curves and with the loop's fit (the fit case, plots, the phase by phase
 * diagnosis), and the same fit rated on the oblique barrier's stage 3 (not in the fit).
 * Ratings are measured, not checked against a reference: the checks are that the fit never
 * worsens its objective and that it stays in its bounds (docs/retune.md) */
static void test_shipped(void)
{
    if (!th_verify()) return;
    char cmd[2048], out[128], path[600], loop[600];
    snprintf(out, sizeof out, "%s/thesis", tdir);
    /* with MCRASH_S3_CACHE/wall40_60.h5 (a stage-3 run of the loop's wall case), the loop takes
     * it as its wall: (a results file is used as it is, docs/loop.md) */
    const char *cache = getenv("MCRASH_S3_CACHE");
    char *scn = realpath("scenarios/loop", NULL);
    snprintf(path, sizeof path, "%s/wall40_60.h5", cache ? cache : "");
    snprintf(loop, sizeof loop, "scenarios/thesis_barrier_loop.yaml");
    if (cache && scn && access(path, R_OK) == 0) {
        char rt[600], cr[600];
        snprintf(rt, sizeof rt, "%s/thesis_retune.yaml", scn);
        snprintf(cr, sizeof cr, "%s/thesis_crash.yaml", scn);
        write_loop("cached.yaml", path, rt, cr);
        snprintf(loop, sizeof loop, "%s/cached.yaml", tdir);
        printf("  the loop's wall case: %s (cached)\n", path);
    }
    free(scn);
    snprintf(cmd, sizeof cmd, "loop %s -o %s -j 2", loop, out);
    cli_result *c = cli_run(cmd);
    CHECK(c->status == 0);
    printf("%s", c->out);
    if (c->status) fprintf(stderr, "%s", c->err);
    snprintf(path, sizeof path, "%s/loop.json", out);
    char *j = slurp(path);
    CHECK_STR_CONTAINS(j, "\"converged\": true");
    int nit = 0;
    for (int k = 1; k <= 6; k++) {
        char key[32];
        snprintf(key, sizeof key, "{\"k\": %d,", k);
        if (j && strstr(j, key)) nit = k;
    }
    CHECK(nit >= 2 && nit <= 5);
    FIG("loop.thesis_iterations", "%.0f", (double)nit);
    /* the loop's fit: its last iteration's parameters */
    double pfit[TR_RT_NPAR];
    char last[32];
    snprintf(last, sizeof last, "{\"k\": %d,", nit);
    const char *jl = j ? strstr(j, last) : NULL;
    for (int i = 0; i < TR_RT_NPAR; i++) {
        char key[64];
        snprintf(key, sizeof key, "\"%s\": ", tr_rt_par_name(i));
        pfit[i] = json_num(jl ? strstr(jl, "\"parameters\"") : NULL, key);
    }
    free(j);

    /* the fit case: the loop's stage-3 run, stage 1 at the scenario's curves and at the fit */
    tr_rt_result r, h;
    snprintf(path, sizeof path, "%s/wall_stage3.h5", out);
    if (access(path, R_OK) != 0) snprintf(path, sizeof path, "%s/wall40_60.h5", cache);
    CHECK(retune_of(path, "scenarios/loop/thesis_retune.yaml", 0, pfit, &r));
    for (int i = 0; i < TR_RT_NPAR; i++)
        CHECK(r.p[i] >= r.lo[i] && r.p[i] <= r.hi[i]);
    FIG("loop.thesis_iso_force_before", "%.2f", r.iso_force0);
    FIG("loop.thesis_iso_force_after", "%.2f", r.iso_force);
    FIG("loop.thesis_iso_angle_before", "%.2f", r.iso_angle0);
    FIG("loop.thesis_iso_angle_after", "%.2f", r.iso_angle);
    FIG("loop.thesis_tyre_force_scale", "%.2f", r.p[0]);
    FIG("loop.thesis_fork_moment_scale", "%.2f", r.p[1]);
    FIG("loop.thesis_fork_elastic_limit", "%.3f", r.p[2]);
    FIG("loop.thesis_fork_stop_angle", "%.3f", r.p[3]);
    FIG("loop.thesis_rim_force_scale", "%.2f", r.p[4]);
    FIG("loop.thesis_fork_stop_stiffness_knm", "%.0f", 1e-3 * r.p[5]);
    plots(&r, "loop_wall", "Frontal wall (fit case)");
    diagnose(path, &r);

    /* not in the fit: the oblique barrier, stage 1 with the scenario's curves and the fit's */
    if (stage3_of("scenarios/loop/thesis_oblique_stage3.yaml", "obl40_60", path, sizeof path)) {
        CHECK(retune_of(path, "scenarios/loop/thesis_retune_oblique.yaml", 0, r.p, &h));
        FIG("loop.oblique_iso_force_before", "%.2f", h.iso_force0);
        FIG("loop.oblique_iso_force_after", "%.2f", h.iso_force);
        FIG("loop.oblique_iso_angle_before", "%.2f", h.iso_angle0);
        FIG("loop.oblique_iso_angle_after", "%.2f", h.iso_angle);
        plots(&h, "loop_oblique", "Oblique 30 deg barrier (not in the fit)");
        tr_rt_result_free(&h);
    } else {
        CHECK(0);
    }
    tr_rt_result_free(&r);
}

int main(void)
{
    CHECK(mkdtemp(tdir) != NULL);
    RUN(test_converges);
    RUN(test_max_iter_and_failures);
    RUN(test_shipped);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tdir);
    if (!getenv("LOOP_KEEP")) CHECK(system(cmd) == 0);
    TEST_END();
}

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

/* make verify: the shipped loop (scenarios/thesis_barrier_loop.yaml: the FE motorcycle into
 * the rigid wall, coarse, 15 ms; retune of the thesis scenario's stage 1 with all four
 * parameters; its stage 1 and a stage 2 replaying the frame) converges within 5 iterations
 * (issue 16 item 5); then retune alone on the same stage-3 run gives the ratings of stage 1
 * against stage 3 before and after (docs/loop.md) */
static void test_shipped(void)
{
    if (!th_verify()) return;
    if (access("scenarios/thesis_barrier_loop.yaml", F_OK)) { /* needs the stage-3 wall case */
        printf("  the shipped loop case is not in this tree yet: not run\n");
        return;
    }
    char cmd[2048], out[128], path[600];
    snprintf(out, sizeof out, "%s/thesis", tdir);
    snprintf(cmd, sizeof cmd, "loop scenarios/thesis_barrier_loop.yaml -o %s", out);
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
    FIG("loop.thesis_iterations", "%d", nit);
    free(j);
    snprintf(cmd, sizeof cmd,
             "retune %s/wall_stage3.h5 --scenario scenarios/loop/thesis_retune.yaml -o %s/c.yaml "
             "--csv %s/thesis_retune.csv --json",
             out, out, out);
    c = cli_run(cmd);
    CHECK(c->status == 0);
    printf("%s", c->out);
    const char *w = strstr(c->out, "\"wall_force\": {\"before\": ");
    const char *a = strstr(c->out, "\"fork_angle\": {\"before\": ");
    double f0 = json_num(w, "\"before\": "), f1 = json_num(w, "\"after\": ");
    double a0 = json_num(a, "\"before\": "), a1 = json_num(a, "\"after\": ");
    CHECK(w && a && f1 >= f0 && a1 + f1 >= a0 + f0); /* the fit lowers the joint objective */
    FIG("loop.thesis_iso_force_before", "%.2f", f0);
    FIG("loop.thesis_iso_force_after", "%.2f", f1);
    FIG("loop.thesis_iso_angle_before", "%.2f", a0);
    FIG("loop.thesis_iso_angle_after", "%.2f", a1);
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

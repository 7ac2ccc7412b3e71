/* test_fuzz_replay.c: replays the fuzzing harnesses' inputs (tests/fuzz/, docs/reliability.md
 * "Fuzzing") without libFuzzer: every file of tests/fuzz/<harness>/seeds/ and .../regress/ (the
 * inputs that once made a reader fail, kept after the fix) is fed to the same function `make
 * fuzz` fuzzes. Passing means no crash, no sanitizer report (`make check-asan`), no leak (ASan's
 * leak check at exit) and no input taking more than HANG_S seconds.
 * `test_fuzz_replay --write-h5-seed DIR` writes the small stage-1 results file of the results
 * harness's seeds (DIR/motion.h5). */
#define FUZZ_REPLAY_ALL
#include "tests/fuzz/fuzz_csv.c"
#include "tests/fuzz/fuzz_keyword.c"
#include "tests/fuzz/fuzz_mme.c"
#include "tests/fuzz/fuzz_obj.c"
#include "tests/fuzz/fuzz_results.c"
#include "tests/fuzz/fuzz_scenario.c"

#include <dirent.h>
#include <time.h>

#include "core/mcs_results.h"
#include "tests/harness.h"

/* libFuzzer's -timeout of `make fuzz` is 1 s per input; here, under ASan and a loaded machine,
 * only a hang is caught */
#define HANG_S 20.0

typedef int (*fuzz_fn)(const uint8_t *, size_t);

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* feed every file of dir to fn; returns the count (-1: no such folder); *worst the longest [s] */
static int replay_dir(const char *dir, fuzz_fn fn, double *worst, char *worst_name, size_t nw)
{
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        char p[1024];
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        size_t len = 0;
        char *buf = th_slurp(p, &len);
        if (!buf) continue;
        double t = now_s();
        fn((const uint8_t *)buf, len);
        t = now_s() - t;
        if (t > *worst) *worst = t, snprintf(worst_name, nw, "%s", p);
        free(buf);
        n++;
    }
    closedir(d);
    return n;
}

static void replay(const char *name, fuzz_fn fn)
{
    char dir[256], worst_name[1024] = "";
    double worst = 0;
    snprintf(dir, sizeof dir, "tests/fuzz/%s/seeds", name);
    int ns = replay_dir(dir, fn, &worst, worst_name, sizeof worst_name);
    snprintf(dir, sizeof dir, "tests/fuzz/%s/regress", name);
    int nr = replay_dir(dir, fn, &worst, worst_name, sizeof worst_name);
    printf("replay | %s | %d seeds | %d regressions | longest %.3f s (%s)\n", name, ns,
           nr < 0 ? 0 : nr, worst, worst_name);
    CHECK(ns > 0);
    CHECK(worst < HANG_S);
}

static void test_replay_scenario(void) { replay("scenario", fuzz_scenario); }
static void test_replay_keyword(void) { replay("keyword", fuzz_keyword); }
static void test_replay_csv(void) { replay("csv", fuzz_csv); }
static void test_replay_mme(void) { replay("mme", fuzz_mme); }
static void test_replay_obj(void) { replay("obj", fuzz_obj); }
static void test_replay_results(void) { replay("results", fuzz_results); }

/* a stage-1 results file of 8 samples: one body `block` moving at 1 m/s along x and a channel */
static int write_h5_seed(const char *dir)
{
    enum { NT = 8 };
    char p[512];
    snprintf(p, sizeof p, "%s/motion.h5", dir);
    mcs_results *r = NULL;
    mcs_error e = {0};
    if (mcs_results_create(&r, p, "", &e)) return 1;
    double t[NT], pos[NT * 3], q[NT * 4], v[NT * 3], w[NT * 3] = {0}, ax[NT] = {0};
    for (int i = 0; i < NT; i++) {
        t[i] = 1e-3 * i;
        pos[3 * i] = 1e-3 * i, pos[3 * i + 1] = 0, pos[3 * i + 2] = 0.8;
        q[4 * i] = 1, q[4 * i + 1] = q[4 * i + 2] = q[4 * i + 3] = 0;
        v[3 * i] = 1, v[3 * i + 1] = v[3 * i + 2] = 0;
    }
    size_t d1 = NT, d3[2] = {NT, 3}, d4[2] = {NT, 4};
    mcs_status st = mcs_results_write(r, "/stage1/time", 1, &d1, t, "s", &e);
    if (!st) st = mcs_results_write(r, "/stage1/bodies/block/position", 2, d3, pos, "m", &e);
    if (!st) st = mcs_results_write(r, "/stage1/bodies/block/orientation", 2, d4, q, "-", &e);
    if (!st) st = mcs_results_write(r, "/stage1/bodies/block/velocity", 2, d3, v, "m/s", &e);
    if (!st)
        st = mcs_results_write(r, "/stage1/bodies/block/angular_velocity", 2, d3, w, "rad/s", &e);
    if (!st) st = mcs_results_write(r, "/stage1/channels/head_ax", 1, &d1, ax, "m/s^2", &e);
    if (!st) st = mcs_results_commit(&r, &e);
    mcs_results_abort(&r);
    if (st) fprintf(stderr, "%s\n", e.msg);
    return st != MCS_OK;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "--write-h5-seed") == 0) return write_h5_seed(argv[2]);
    RUN(test_replay_scenario);
    RUN(test_replay_keyword);
    RUN(test_replay_csv);
    RUN(test_replay_mme);
    RUN(test_replay_obj);
    RUN(test_replay_results);
    TEST_END();
}

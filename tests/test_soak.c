/* test_soak.c: many stage-1 runs in one process through the library API (issue 18 item 5;
 * docs/reliability.md "Soak"): each run loads the scenario text, builds the model, runs it with
 * its results file and frees everything. The memory in use is measured after a warm-up (the
 * first runs set up HDF5's, ODE's and libyaml's once-only state and the allocator's caches:
 * 100 runs of 1000, 10 of 20) and after the last run:
 *   - malloc's bytes in use (mallinfo2 uordblks + hblkhd, after H5garbage_collect): a leak of
 *     72 bytes a run over runs 100..1000 would exceed the bound below;
 *   - the resident set (/proc/self/statm), which also sees the allocator's fragmentation.
 * `make verify` runs 1000, `make test` 20; under ASan (`make check-asan`) the allocator is ASan's,
 * so the figures are printed but not checked, and its leak check at exit finds what is lost. */
#include "core/mcs_scenario.h"
#include "stage1_mb/mb_model.h"
#include "tests/harness.h"

#include <hdf5.h>
#include <malloc.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define SOAK_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SOAK_ASAN 1
#endif
#endif
#ifndef SOAK_ASAN
#define SOAK_ASAN 0
#endif

/* the bounds on growth between the warm-up and the last run (the test's statement of "flat") */
#define SOAK_HEAP_BOUND (64.0 * 1024)       /* bytes in use */
#define SOAK_RSS_BOUND (4.0 * 1024 * 1024) /* resident bytes */

/* two spheres meeting head-on with a hysteresis pad (scenarios/verification/two_spheres.yaml,
 * 10 ms of it), with a sensor so that the run writes channels and injury criteria too */
static const char scn_text[] =
    "mcrash: 1\n"
    "name: soak\n"
    "simulation: {end_time: 10 ms, time_step: 10 us, output_rate: 10 kHz}\n"
    "environment: {gravity: 0}\n"
    "characteristics:\n"
    "  hyst_pad: {loading: [[0, 0], [0.01, 1000]], unloading_slope: 4e5 N/m}\n"
    "bodies:\n"
    "  - {name: a, mass: 1 kg, inertia: [0.004, 0.004, 0.004], position: [0, 0, 0],\n"
    "     velocity: [2 m/s, 0, 0],\n"
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"
    "  - {name: b, mass: 3 kg, inertia: [0.012, 0.012, 0.012], position: [0.203 m, 0, 0],\n"
    "     velocity: [0, 0, 0],\n"
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"
    "contacts: [{a: a, b: b, characteristic: hyst_pad}]\n";

static double heap_bytes(void)
{
    H5garbage_collect(); /* HDF5's free lists keep freed blocks for reuse until collected */
    struct mallinfo2 mi = mallinfo2();
    return (double)mi.uordblks + (double)mi.hblkhd;
}

static double rss_bytes(void)
{
    long size = 0, res = 0;
    FILE *f = fopen("/proc/self/statm", "r");
    if (!f) return 0;
    if (fscanf(f, "%ld %ld", &size, &res) != 2) res = 0;
    fclose(f);
    return (double)res * (double)sysconf(_SC_PAGESIZE);
}

/* one run: load, build, run with its results file, free; MCS_OK or the failing status */
static mcs_status one_run(const char *out)
{
    mcs_error err = {0};
    mcs_scenario *scn = NULL;
    mcs_status st = mcs_scenario_load_text("soak.yaml", scn_text, sizeof scn_text - 1, &scn, &err);
    mb_model *m = NULL;
    if (!st) st = mb_model_build(scn, NULL, &m, &err);
    if (!st) {
        mb_run_opts o = {.out_path = out, .scenario_text = scn_text, .quiet = 1};
        mb_run_summary sum = {0};
        st = mb_run(m, &o, &sum, &err);
        if (!st && sum.steps != 1000) st = MCS_ERR_RANGE; /* 10 ms at 10 us */
    }
    if (st) fprintf(stderr, "soak: %s\n", err.msg);
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);
    return st;
}

static void test_soak_stage1(void)
{
    const int nrun = th_verify() ? 1000 : 20;
    const int warmup = th_verify() ? 100 : nrun / 2;
    char dir[] = "/tmp/mcrash_soak_XXXXXX", out[64];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(out, sizeof out, "%s/soak.h5", dir);
    int failed = 0;
    double heap0 = 0, rss0 = 0;
    for (int i = 0; i < nrun; i++) {
        if (one_run(out)) failed++;
        if (i + 1 == warmup) heap0 = heap_bytes(), rss0 = rss_bytes();
        if ((i + 1) % 100 == 0)
            printf("soak | after %d runs: heap %.0f B, RSS %.0f kB\n", i + 1, heap_bytes(),
                   rss_bytes() / 1024);
    }
    const double heap1 = heap_bytes(), rss1 = rss_bytes();
    printf("soak | %d stage-1 runs | after %d: heap %.0f B, RSS %.0f kB | after %d: heap %.0f B, "
           "RSS %.0f kB | growth: heap %+.0f B, RSS %+.0f kB%s\n",
           nrun, warmup, heap0, rss0 / 1024, nrun, heap1, rss1 / 1024, heap1 - heap0,
           (rss1 - rss0) / 1024, SOAK_ASAN ? " (ASan: not checked)" : "");
    CHECK(failed == 0);
    if (!SOAK_ASAN) {
        CHECK(heap1 - heap0 < SOAK_HEAP_BOUND);
        CHECK(rss1 - rss0 < SOAK_RSS_BOUND);
    }
    remove(out);
    rmdir(dir);
}

int main(void)
{
    RUN(test_soak_stage1);
    TEST_END();
}

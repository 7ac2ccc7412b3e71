/* bench_rom.c: runs per second of the reduced-order model (rom/rom.h) on the thesis frontal
 * barrier case (250 ms, 10 kHz output), in process (model build + CVODE run), and of a
 * `stage: rom` study of 20 speeds through bin/mcrash (a process and a results file per case);
 * prints figures only */
#include "core/mcs_scenario.h"
#include "rom/rom.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(void)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load("scenarios/thesis_frontal_barrier_13.4.yaml", &scn, &err)) {
        fprintf(stderr, "bench_rom: %s\n", err.msg);
        return 1;
    }
    const int n = 200;
    long steps = 0;
    double t0 = now();
    for (int i = 0; i < n; i++) {
        rom_model m;
        rom_result r;
        if (rom_model_from_scenario(&m, scn, &err) || rom_run(&m, &r, &err)) {
            fprintf(stderr, "bench_rom: %s\n", err.msg);
            return 1;
        }
        steps += r.steps;
        rom_result_free(&r);
        rom_model_deinit(&m);
    }
    double dt = now() - t0;
    printf("bench_rom: in process %d runs of 250 ms, %.0f runs/s (%.2f ms each, %ld CVODE steps "
           "per run)\n",
           n, n / dt, 1e3 * dt / n, steps / n);
    mcs_scenario_destroy(&scn);
    /* a study through the command: fork, scenario, run, results file per case */
    FILE *f = fopen("build/bench_rom_study.yaml", "w");
    if (!f) return 1;
    fprintf(f, "study:\n  scenario: ../scenarios/thesis_frontal_barrier_13.4.yaml\n"
               "  stage: rom\n  design: {type: latin_hypercube, samples: 20, seed: 1}\n"
               "  factors:\n    - {path: impact.motorcycle_speed, range: [5 m/s, 15 m/s]}\n"
               "  responses: [\"max:/stage0/channels/barrier_fn\"]\n");
    fclose(f);
    t0 = now();
    int rc = system("bin/mcrash study build/bench_rom_study.yaml -o build/bench_rom_study.h5 "
                    "-j 1 --quiet >/dev/null 2>&1");
    dt = now() - t0;
    if (rc == 0)
        printf("bench_rom: mcrash study, stage: rom, 20 cases -j 1: %.1f runs/s\n", 20 / dt);
    else
        printf("bench_rom: mcrash study failed (%d)\n", rc);
    return 0;
}

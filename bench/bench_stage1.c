/* bench_stage1: steps per second of the stage-1 engine for a chain of N ellipsoid bodies
 * (each an ellipsoid, slightly non-spherical so the ellipsoid-ellipsoid Newton runs) linked by
 * restrained spherical joints, falling onto the ground with a contact to the ground per body and
 * one between neighbours; 50 ms at 10 us, output at 10 kHz, no file. Prints wall time, steps/s,
 * microseconds per step and the share of each sub-stage. Never fails on time. */
#include "stage1_mb/mb_model.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *scenario(int n)
{
    size_t cap = 4096 + (size_t)n * 900;
    char *y = malloc(cap);
    if (!y) return NULL;
    size_t k = (size_t)snprintf(y, cap,
                                "mcrash: 1\n"
                                "simulation: {end_time: 50 ms, time_step: 10 us}\n"
                                "environment: {gravity: 9.81, ground: {height: 0, friction: 0.3}}\n"
                                "characteristics:\n"
                                "  pad: {loading: [[0, 0], [0.01, 2000], [0.03, 12000]],\n"
                                "        unloading_slope: 1e6, damping: 50}\n"
                                "  neck: {type: moment, loading: [[0, 0], [1, 50]], damping: 0.5}\n"
                                "bodies:\n");
    for (int i = 0; i < n; i++)
        k += (size_t)snprintf(y + k, cap - k,
                              "  - {name: b%d, mass: 2, inertia: [0.01, 0.012, 0.014],\n"
                              "     position: [%g, 0, %g], velocity: [3, 0, -1],\n"
                              "     surfaces: [{type: ellipsoid, center: [0, 0, 0],\n"
                              "                 semi_axes: [0.1, 0.09, 0.08], characteristic: pad}]}\n",
                              i, 0.21 * i, 0.09 + 0.002 * (i % 3));
    k += (size_t)snprintf(y + k, cap - k, "contacts:\n");
    for (int i = 0; i < n; i++) {
        k += (size_t)snprintf(y + k, cap - k, "  - {a: b%d, b: ground, characteristic: pad}\n", i);
        if (i + 1 < n)
            k += (size_t)snprintf(y + k, cap - k, "  - {a: b%d, b: b%d, characteristic: pad}\n",
                                  i, i + 1);
    }
    if (n > 1) k += (size_t)snprintf(y + k, cap - k, "joints:\n");
    for (int i = 0; i + 1 < n; i += 2)
        k += (size_t)snprintf(y + k, cap - k,
                              "  - {type: spherical, parent: b%d, child: b%d, anchor: [%g, 0, %g],"
                              " restraint: neck}\n",
                              i, i + 1, 0.21 * i + 0.105, 0.09);
    return y;
}

static void bench(int n)
{
    char *y = scenario(n);
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    mcs_error err = {0};
    if (!y || mcs_scenario_load_text("bench.yaml", y, strlen(y), &scn, &err) ||
        mb_model_build(scn, NULL, &m, &err)) {
        printf("bench_stage1: N = %d: %s\n", n, err.msg);
        goto done;
    }
    mb_run_opts o = {.quiet = 1};
    mb_run_summary s;
    mcs_status st = mb_run(m, &o, &s, &err);
    if (st) {
        printf("bench_stage1: N = %d: %s\n", n, err.msg);
        goto done;
    }
    printf("bench_stage1: N = %3d bodies, %3d pairs: %6ld steps in %.3f s = %8.0f steps/s, "
           "%6.2f us/step, drift %.2g |",
           n, m->npair, s.steps, s.wall_time_s, s.steps / s.wall_time_s,
           1e6 * s.wall_time_s / s.steps, s.energy_drift);
    double tot = 0;
    for (int k = 0; k < MB_NTIMER; k++) tot += s.timer[k];
    for (int k = 0; k < MB_NTIMER; k++)
        printf(" %s %.0f%%", mb_timer_name(k), tot > 0 ? 100 * s.timer[k] / tot : 0);
    printf("\n");
done:
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);
    free(y);
}

int main(void)
{
    int ns[] = {1, 8, 32};
    for (int i = 0; i < 3; i++) bench(ns[i]);
    return 0;
}

/* bench_stage1: steps per second of the stage-1 engine.
 * 1. The ISO 13232 413-0/13.4 scenario (scenarios/iso13232_413-0_13.4_sedan.yaml, 300 ms,
 *    30 000 steps; issue 4 item 9: at most 2 s on one core), its version with the seated
 *    rider (..._rider.yaml; a stand-in built here when there is none) and with the rider
 *    restraint concept (..._rider_concept.yaml, coupled FE parts; issue 12: at most 10 s on
 *    one core; the FE runs on one thread here), no results file.
 * 2. A chain of N ellipsoid bodies (each slightly non-spherical so the ellipsoid-ellipsoid
 *    Newton runs) linked by restrained spherical joints, falling onto the ground with a contact
 *    to the ground per body and one between neighbours; 50 ms at 10 us, output at 10 kHz.
 * Prints wall and CPU time (this machine is shared: CPU time is the one-core figure), steps/s,
 * microseconds per step and the share of each sub-stage. Never fails on time. */
#include "fe/fe_parallel.h"
#include "stage1_mb/mb_model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define SCN_413 "scenarios/iso13232_413-0_13.4_sedan.yaml"
#define SCN_413R "scenarios/iso13232_413-0_13.4_sedan_rider.yaml" /* with the seated rider */
/* the same with the rider restraint concept (thigh belts, front airbag, leg protectors: FE
 * parts coupled to the bodies; issue 12: at most 10 s on one core) */
#define SCN_413C "scenarios/iso13232_413-0_13.4_sedan_rider_concept.yaml"

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* run m and print one line; returns 0 on success */
static int run_print(const char *what, const mb_model *m)
{
    mcs_error err = {0};
    mb_run_opts o = {.quiet = 1};
    mb_run_summary s;
    double c0 = cpu_now();
    if (mb_run(m, &o, &s, &err)) {
        printf("bench_stage1: %s: %s\n", what, err.msg);
        return 1;
    }
    double cpu = cpu_now() - c0;
    printf("bench_stage1: %s, %3d bodies, %3d pairs: %6ld steps, wall %.3f s, CPU %.3f s = "
           "%7.0f steps/s (CPU), %6.2f us/step, drift %.2g |",
           what, m->nbody, m->npair, s.steps, s.wall_time_s, cpu, s.steps / cpu,
           1e6 * cpu / s.steps, s.energy_drift);
    double tot = 0;
    for (int k = 0; k < MB_NTIMER; k++) tot += s.timer[k];
    for (int k = 0; k < MB_NTIMER; k++)
        printf(" %s %.0f%%", mb_timer_name(k), tot > 0 ? 100 * s.timer[k] / tot : 0);
    printf("\n");
    return 0;
}

/* returns 1 when the scenario has rider bodies */
static int bench_file(const char *path)
{
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    mcs_error err = {0};
    int rider = 0;
    if (mcs_scenario_load(path, &scn, &err) || mb_model_build(scn, NULL, &m, &err)) {
        printf("bench_stage1: %s: %s\n", path, err.msg);
    } else {
        run_print(path, m);
        rider = mb_model_body(m, "rider_pelvis") >= 0;
    }
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);
    return rider;
}

/* until the 413 scenario carries its rider: the same scenario with the Hybrid III rider seated
 * (models/riders/hybrid3_50th.yaml, 17 segments) and contacts rider-motorcycle (seat, tank),
 * rider-car and rider-road for every segment (the seat law): a stand-in of the full case */
static void bench_413_rider(void)
{
    static const char *const seg[] = {
        "head",        "neck",        "upper_torso", "lower_torso", "pelvis",  "upper_arm_l",
        "upper_arm_r", "lower_arm_l", "lower_arm_r", "hand_l",      "hand_r",  "thigh_l",
        "thigh_r",     "lower_leg_l", "lower_leg_r", "foot_l",      "foot_r"};
    char y[8192];
    size_t k = (size_t)snprintf(
        y, sizeof y,
        "mcrash: 1\n"
        "include: [iso13232_413-0_13.4_sedan.yaml, models/riders/hybrid3_50th.yaml]\n"
        "rider: {torso_lean: 40 deg}\n"
        "contacts:\n"
        "  - {a: rider_pelvis, b: moto_frame, characteristic: seat}\n"
        "  - {a: rider_thigh_l, b: moto_frame, characteristic: tank}\n"
        "  - {a: rider_thigh_r, b: moto_frame, characteristic: tank}\n"
        "  - {a: rider_lower_torso, b: moto_frame, characteristic: tank}\n");
    for (int i = 0; i < 17; i++)
        k += (size_t)snprintf(y + k, sizeof y - k,
                              "  - {a: rider_%s, b: sedan, characteristic: seat, friction: 0.3}\n"
                              "  - {a: rider_%s, b: ground, characteristic: seat, friction: 0.5}\n",
                              seg[i], seg[i]);
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load_text("scenarios/bench_413_rider.yaml", y, k, &scn, &err) ||
        mb_model_build(scn, NULL, &m, &err))
        printf("bench_stage1: 413 with rider: %s\n", err.msg);
    else
        run_print("413-0/13.4 + seated rider (stand-in)", m);
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);
}

/* CPU time of one quiet run of m [s]; negative on failure */
static double run_cpu(const mb_model *m)
{
    mcs_error err = {0};
    mb_run_opts o = {.quiet = 1};
    mb_run_summary sum;
    double c0 = cpu_now();
    if (mb_run(m, &o, &sum, &err)) {
        printf("bench_stage1: %s\n", err.msg);
        return -1;
    }
    return cpu_now() - c0;
}

/* the coupling's overhead (issue 12: at most 10 % over the bodies-only run): the 413 rider
 * scenario with one FE truss carried by the frame and nothing in contact with it -- the FE step,
 * the attached nodes and the exchange every ODE step, next to no element work -- against the
 * same scenario without it; each run 3 times, alternating, the least CPU time of each kept
 * (the machine is shared: single runs scatter by +-20 %) */
static void bench_413_coupled_idle(void)
{
    static const char y[] =
        "mcrash: 1\n"
        "include: [" SCN_413R "]\n"
        "fe:\n  parts:\n    - name: idle_bar\n"
        "      mesh: {generate: line, origin: [0.3, 0, 0.9], end: [0.4, 0, 0.9], divisions: 1}\n"
        "      section: {type: truss, area: 1e-4}\n"
        "      material: {model: elastic, density: 1000, youngs_modulus: 1 GPa, poisson: 0}\n"
        "      attach: {body: moto_frame, where: x_min}\n";
    mcs_scenario *scn = NULL, *scn0 = NULL;
    mb_model *m = NULL, *m0 = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load_text("bench_413_idle.yaml", y, sizeof y - 1, &scn, &err) ||
        mb_model_build(scn, NULL, &m, &err) || mcs_scenario_load(SCN_413R, &scn0, &err) ||
        mb_model_build(scn0, NULL, &m0, &err)) {
        printf("bench_stage1: 413 + idle FE part: %s\n", err.msg);
    } else {
        double c = INFINITY, c0 = INFINITY;
        for (int k = 0; k < 3; k++) {
            double a = run_cpu(m0), b = run_cpu(m);
            if (a < 0 || b < 0) break;
            c0 = fmin(c0, a), c = fmin(c, b);
        }
        printf("bench_stage1: coupling overhead (413 rider + one idle attached FE truss, least of "
               "3 runs): CPU %.3f s against %.3f s bodies only = %+.1f %%\n",
               c, c0, 100 * (c / c0 - 1));
    }
    mb_model_destroy(&m), mb_model_destroy(&m0);
    mcs_scenario_destroy(&scn), mcs_scenario_destroy(&scn0);
}

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
    char what[32];
    snprintf(what, sizeof what, "chain N = %d", n);
    run_print(what, m);
done:
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);
    free(y);
}

int main(void)
{
    mcs_log_set_level(MCS_LOG_WARN); /* not the rider positioning's info line */
    fe_set_threads(1);               /* one core: the coupled FE parts too */
    int rider = bench_file(SCN_413);
    FILE *f = fopen(SCN_413R, "rb");
    if (f) fclose(f);
    if (f) rider |= bench_file(SCN_413R);
    f = fopen(SCN_413C, "rb");
    if (f) fclose(f);
    if (f) bench_file(SCN_413C);
    if (rider) bench_413_coupled_idle();
    if (!rider) bench_413_rider();
    int ns[] = {1, 8, 32};
    for (int i = 0; i < 3; i++) bench(ns[i]);
    return 0;
}

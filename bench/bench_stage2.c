/* bench_stage2: stage 2 of the concept 413 case (issue 13 "Speed": <= 3 min wall for 300 ms on
 * 2 threads). Stage 1 of scenarios/iso13232_413-0_13.4_sedan_rider_concept.yaml is run to a
 * temporary file (the motion), then the shipped stage-2 scenario
 * (..._concept_stage2.yaml: vehicles prescribed by pose, rider free, FE belts, bag, leg
 * protectors and tank pads) with that motion: once stepped without output (steps, FE substeps,
 * elements, ns per element-cycle) and once through s2_run with its results file. Prints
 * figures; never fails on time (OMP_NUM_THREADS as set, the library's default otherwise). */
#include "stage1_mb/mb_couple.h"
#include "stage2_fe/s2_run.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#define S1 "scenarios/iso13232_413-0_13.4_sedan_rider_concept.yaml"
#define S2 "scenarios/iso13232_413-0_13.4_sedan_rider_concept_stage2.yaml"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(void)
{
    char dir[] = "/tmp/mcs_bench_s2_XXXXXX", h1[96], h2[96];
    if (!mkdtemp(dir)) return perror("mkdtemp"), 1;
    snprintf(h1, sizeof h1, "%s/s1.h5", dir);
    snprintf(h2, sizeof h2, "%s/s2.h5", dir);
    mcs_error err = {0};
    mcs_scenario *scn = NULL;
    mb_model *m1 = NULL;
    s2_model *m2 = NULL;
    mb_state *s = NULL;
    double w0 = now();
    mcs_status st = mcs_scenario_load(S1, &scn, &err);
    mb_run_opts o1 = {.out_path = h1, .quiet = 1};
    if (!st) st = mb_model_build(scn, NULL, &m1, &err);
    if (!st) st = mb_run(m1, &o1, NULL, &err);
    double w1 = now();
    mb_model_destroy(&m1);
    mcs_scenario_destroy(&scn);
    if (!st) st = mcs_scenario_load(S2, &scn, &err);
    if (!st) st = s2_model_build(scn, h1, &m2, &err);
    /* stepped alone: steps, FE substeps and the element-cycle cost */
    double w2 = now();
    if (!st) st = mb_state_create(m2->mb, &s, &err);
    while (!st && s->step < m2->mb->nsteps)
        st = mb_step(m2->mb, s, &err);
    double w3 = now();
    if (!st) {
        const mb_couple *c = m2->mb->couple;
        int nelem = c ? c->fe.model->nelem : 0;
        long sub = s->couple ? s->couple->substeps : 0;
        printf("bench_stage2: %s, %.3g s simulated\n", S2, m2->mb->t_end);
        printf("  stage 1 (motion file): %.1f s wall\n", w1 - w0);
        printf("  stage 2 stepped: %.1f s wall, %ld steps, %d bodies (%d prescribed), %d FE "
               "elements, %ld FE substeps, %.0f ns per element-cycle (the whole step over "
               "elements x substeps)\n",
               w3 - w2, s->step, m2->mb->nbody, tr_stage2_motion_count(m2->motion), nelem, sub,
               nelem && sub ? 1e9 * (w3 - w2) / ((double)nelem * (double)sub) : 0.0);
    }
    mb_state_destroy(&s);
    /* the command's run: the same with the /stage2 results file */
    s2_summary sum = {0};
    s2_run_opts o2 = {.out_path = h2, .quiet = 1};
    double w4 = now();
    if (!st) st = s2_run(m2, &o2, &sum, &err);
    if (!st)
        printf("  stage 2 with output (mcrash stage2): %.1f s wall (target <= 180 s), energy "
               "drift %.3g\n",
               now() - w4, sum.mb.energy_drift);
    s2_model_destroy(&m2);
    mcs_scenario_destroy(&scn);
    unlink(h1), unlink(h2), rmdir(dir);
    if (st) fprintf(stderr, "bench_stage2: %s\n", err.msg);
    return st ? 1 : 0;
}

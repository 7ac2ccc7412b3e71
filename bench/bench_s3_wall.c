/* bench_s3_wall: the thesis' frontal rigid-wall case in stage 3 at its run mesh (the
 * element_size of scenarios/thesis_frontal_barrier_13.4.yaml's stage3: block): elements, the
 * stable step, the cycles 100 ms takes, ns per element-cycle on 1 and 2 threads (a few hundred
 * cycles of the impact's start, timed), the wall time 100 ms would take at that rate against
 * the 15 minutes on 2 threads, and the mass added. Never fails on time; the machine is
 * shared: compare runs made when `uptime` shows a low load. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench/bench_fe_util.h"
#include "fe/fe_scn_build.h"
#include "fe/fe_state.h"
#include "stage3_fe/s3_moto.h"
#include "stage3_fe/s3_scenario.h"

#define SCENARIO "scenarios/thesis_frontal_barrier_13.4.yaml"
#define CYCLES 300

/* ns per element-cycle of `cycles` steps after 5 warm-up steps, on `threads` threads */
static double ns_per_elem_cycle(const fe_model *m, int threads, int cycles, double *dt)
{
    mcs_error err = {0};
    fe_state *s = NULL;
    fe_set_threads(threads);
    if (fe_state_create(m, &s, &err) != MCS_OK) return -1;
    for (int i = 0; i < 5; i++) fe_step(m, s);
    double t0 = bf_now(CLOCK_MONOTONIC);
    for (int i = 0; i < cycles && s->err.status == MCS_OK; i++) fe_step(m, s);
    double wall = bf_now(CLOCK_MONOTONIC) - t0;
    *dt = s->dt;
    int ok = s->err.status == MCS_OK;
    if (!ok) fprintf(stderr, "bench_s3_wall: stopped: %s\n", s->err.msg);
    fe_state_destroy(&s);
    return ok ? 1e9 * wall / ((double)cycles * m->nelem) : -1;
}

int main(void)
{
    s3_moto_register();
    mcs_scenario *scn = NULL, *s3 = NULL;
    mcs_error err = {0};
    fe_problem p = {0};
    mcs_status st = mcs_scenario_load(SCENARIO, &scn, &err);
    if (!st) st = s3_scenario_compile(scn, &s3, &err);
    if (!st) st = fe_scn_build(s3, &p, &err);
    if (st) {
        fprintf(stderr, "bench_s3_wall: %s\n", err.msg);
        return 1;
    }
    const fe_model *m = p.model;
    const mcs_node *parts = mcs_node_get(mcs_node_get(mcs_scenario_root(s3), "fe"), "parts");
    const mcs_node *mesh = mcs_node_get(mcs_node_at(parts, 0), "mesh");
    const double h = mcs_node_num(mcs_node_get(mesh, "element_size"));
    double dt1 = 0, dt2 = 0;
    const double ns1 = ns_per_elem_cycle(m, 1, CYCLES, &dt1);
    const double ns2 = ns_per_elem_cycle(m, 2, CYCLES, &dt2);
    const double cycles = p.end_time / dt1;
    printf("stage-3 wall case (%s, %.0f mm mesh, %.0f ms):\n", SCENARIO, 1e3 * h,
           1e3 * p.end_time);
    printf("  %d elements, %d nodes, stable step %.3g us: %.3g cycles\n", m->nelem, m->nnode,
           1e6 * dt1, cycles);
    printf("  %.0f ns per element-cycle on 1 thread, %.0f on 2 (%d cycles timed)\n", ns1, ns2,
           CYCLES);
    printf("  %.0f ms at that rate: %.1f min on 1 thread, %.1f min on 2 (issue: <= 15 min on 2)\n",
           1e3 * p.end_time, 1e-9 * ns1 * cycles * m->nelem / 60,
           1e-9 * ns2 * cycles * m->nelem / 60);
    printf("  mass added %.4g kg (%.3g %% of %.4g kg; issue: < 2 %%)\n", m->mass_added,
           100 * m->mass_added / (m->mass_total - m->mass_added), m->mass_total - m->mass_added);
    fe_problem_free(&p);
    mcs_scenario_destroy(&s3);
    mcs_scenario_destroy(&scn);
    return 0;
}

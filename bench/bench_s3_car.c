/* bench_s3_car: ISO 13232 413-0/13.4 in stage 3, the FE motorcycle into the FE sedan side, at
 * the run mesh (the element sizes of scenarios/iso13232_413-0_13.4_sedan_stage3.yaml's stage3:
 * block): elements, the stable step, the cycles 200 ms take, ns per element-cycle on 2 threads
 * of a few hundred cycles timed after the first contact (the contact search counts), the wall
 * time 200 ms would take at that rate against the 45 minutes on 2 threads, and the
 * mass added. An extrapolation from a short piece, not a run: the crushed mesh's later steps
 * can cost more (more contact pairs). Never fails on time; the machine is shared: compare runs
 * made when `uptime` shows a low load. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench/bench_fe_util.h"
#include "fe/fe_scn_build.h"
#include "fe/fe_state.h"
#include "stage3_fe/s3_moto.h"
#include "stage3_fe/s3_scenario.h"
#include "stage3_fe/s3_sedan.h"

#define SCENARIO "scenarios/iso13232_413-0_13.4_sedan_stage3.yaml"
#define T_WARM 2.0e-3 /* past the first contact (1.67 ms) [s] */
#define CYCLES 200

int main(void)
{
    s3_moto_register();
    s3_sedan_register();
    mcs_scenario *scn = NULL, *s3 = NULL;
    mcs_error err = {0};
    fe_problem p = {0};
    mcs_status st = mcs_scenario_load(SCENARIO, &scn, &err);
    if (!st) st = s3_scenario_compile(scn, &s3, &err);
    if (!st) st = fe_scn_build(s3, &p, &err);
    if (st) {
        fprintf(stderr, "bench_s3_car: %s\n", err.msg);
        return 1;
    }
    const fe_model *m = p.model;
    const mcs_node *parts = mcs_node_get(mcs_node_get(mcs_scenario_root(s3), "fe"), "parts");
    double h[2];
    for (int i = 0; i < 2; i++)
        h[i] = mcs_node_num(mcs_node_get(mcs_node_get(mcs_node_at(parts, i), "mesh"),
                                         "element_size"));
    fe_set_threads(2);
    fe_state *s = NULL;
    if (fe_state_create(m, &s, &err) != MCS_OK) return 1;
    const double w0 = bf_now(CLOCK_MONOTONIC);
    long nwarm = 0;
    while (s->time < T_WARM && s->err.status == MCS_OK) fe_step(m, s), nwarm++;
    const double t0 = bf_now(CLOCK_MONOTONIC);
    for (int i = 0; i < CYCLES && s->err.status == MCS_OK; i++) fe_step(m, s);
    const double wall = bf_now(CLOCK_MONOTONIC) - t0, dt = s->dt;
    if (s->err.status != MCS_OK) {
        fprintf(stderr, "bench_s3_car: stopped: %s\n", s->err.msg);
        return 1;
    }
    const double ns = 1e9 * wall / ((double)CYCLES * m->nelem);
    const double ns_warm = 1e9 * (t0 - w0) / ((double)nwarm * m->nelem);
    const double cycles = p.end_time / dt;
    printf("stage-3 413 car case (%s, motorcycle %.0f mm, sedan %.0f mm, %.0f ms):\n", SCENARIO,
           1e3 * h[0], 1e3 * h[1], 1e3 * p.end_time);
    printf("  %d elements, %d nodes, stable step %.3g us: %.3g cycles\n", m->nelem, m->nnode,
           1e6 * dt, cycles);
    printf("  %.0f ns per element-cycle on 2 threads in contact (%d cycles timed from %.1f ms), "
           "%.0f before it (%ld cycles)\n",
           ns, CYCLES, 1e3 * T_WARM, ns_warm, nwarm);
    printf("  %.0f ms at that rate: %.1f min on 2 threads (issue: <= 45 min on 2), "
           "extrapolated\n",
           1e3 * p.end_time, 1e-9 * ns * cycles * m->nelem / 60);
    printf("  mass added %.4g kg (%.3g %% of %.4g kg; issue: < 2 %%)\n", m->mass_added,
           100 * m->mass_added / (m->mass_total - m->mass_added), m->mass_total - m->mass_added);
    fe_state_destroy(&s);
    fe_problem_free(&p);
    mcs_scenario_destroy(&s3);
    mcs_scenario_destroy(&scn);
    return 0;
}

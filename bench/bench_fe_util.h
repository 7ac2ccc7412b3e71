/* bench_fe_util.h: set-up shared by the FE benches (every bench/bench_*.c is its own binary, so
 * these are static inline): the clocks, and the square tube crush of issue 5. */
#ifndef BENCH_FE_UTIL_H
#define BENCH_FE_UTIL_H

#include <stdio.h>
#include <string.h>
#include <time.h>

#include "fe/fe_model.h"

/* the clock `id` (CLOCK_MONOTONIC: wall; CLOCK_PROCESS_CPUTIME_ID, CLOCK_THREAD_CPUTIME_ID: the
 * CPU time that means something on a shared machine) [s] */
static inline double bf_now(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* part t (its material set by the caller) made the tube "tube": Belytschko-Tsay shells
 * 1.5 mm thick with 5 points, a square tube of 50 mm side and 200 mm along z from z = 0, 2.5 mm
 * elements (6400 shells) */
static inline void bf_tube_part(fe_part_desc *t)
{
    snprintf(t->name, sizeof t->name, "tube");
    t->section.type = FE_SECTION_SHELL;
    t->section.thickness = 1.5e-3;
    t->section.integration_points = 5;
    t->mesh.generate = FE_MESH_SQUARE_TUBE;
    t->mesh.side = 0.05, t->mesh.length = 0.2, t->mesh.element_size = 2.5e-3, t->mesh.axis = 2;
}

/* every node of part `part` at its lowest z fixed (all degrees of freedom) */
static inline void bf_clamp_base(fe_builder *b, const char *part, mcs_error *err)
{
    fe_boundary_desc bc;
    memset(&bc, 0, sizeof bc);
    snprintf(bc.part, sizeof bc.part, "%s", part);
    bc.where = FE_WHERE_Z_MIN;
    bc.fix = FE_DOF_ALL;
    fe_builder_add_boundary(b, &bc, err);
}

/* the tube t (bf_tube_part) added to b, clamped at z = 0 and crushed by the rigid wall "ram"
 * at its top (z = 0.2 m) moving down at 10 m/s */
static inline void bf_tube_crush(fe_builder *b, const fe_part_desc *t, mcs_error *err)
{
    fe_builder_add_part(b, t, NULL, err);
    bf_clamp_base(b, t->name, err);
    fe_wall_desc w;
    memset(&w, 0, sizeof w);
    snprintf(w.name, sizeof w.name, "ram");
    w.point[2] = 0.2, w.normal[2] = -1, w.velocity[2] = -10;
    fe_builder_add_wall(b, &w, err);
}

#endif

/* mb_test_util.h: set-up shared by the stage-1 tests (every tests/test_*.c is its own binary,
 * so these are static inline): a model from scenario text or a file, a run to the end, a
 * channel of a results file, and the rider: alone, its mass, seated on the motorcycle with a
 * helmet. */
#ifndef MB_TEST_UTIL_H
#define MB_TEST_UTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mcs_results.h"
#include "fe/fe_model.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

/* the model of scenario `text` read as the file `name` (its includes are relative to it);
 * NULL on failure, with the error in *err, or printed ("name: message") when err is NULL */
static inline mb_model *mt_model_text(const char *name, const char *text, mcs_error *err)
{
    mcs_error local = {0}, *e = err ? err : &local;
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    if (mcs_scenario_load_text(name, text, strlen(text), &scn, e) == MCS_OK)
        mb_model_build(scn, NULL, &m, e);
    mcs_scenario_destroy(&scn);
    if (!m && !err) fprintf(stderr, "%s: %s\n", name, local.msg);
    return m;
}

/* the model of the scenario file `path`; NULL on failure, the error printed */
static inline mb_model *mt_model_file(const char *path)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mb_model *m = NULL;
    if (mcs_scenario_load(path, &scn, &err) || mb_model_build(scn, NULL, &m, &err))
        fprintf(stderr, "%s: %s\n", path, err.msg);
    mcs_scenario_destroy(&scn);
    return m;
}

/* a new state *s of m stepped to the model's end (m->nsteps); the first failing status */
static inline mcs_status mt_run(const mb_model *m, mb_state **s, mcs_error *err)
{
    mcs_status st = mb_state_create(m, s, err);
    while (!st && (*s)->step < m->nsteps) st = mb_step(m, *s, err);
    return st;
}

/* the dataset /stage1/channels/<name> of the results file `path` (malloc'ed, *n values, its
 * unit into unit[32] unless unit is NULL); NULL on failure, with the error in *err, or printed
 * when err is NULL */
static inline double *mt_read_channel(const char *path, const char *name, size_t *n, char *unit,
                                      mcs_error *err)
{
    mcs_results *r = NULL;
    mcs_error local = {0}, *e = err ? err : &local;
    mcs_array a = {0};
    char ds[160];
    snprintf(ds, sizeof ds, "/stage1/channels/%s", name);
    double *v = NULL;
    if (mcs_results_open(&r, path, e) == MCS_OK && mcs_results_read(r, ds, &a, e) == MCS_OK) {
        v = malloc(a.n * sizeof *v);
        memcpy(v, a.v, a.n * sizeof *v);
        *n = a.n;
        if (unit) snprintf(unit, 32, "%s", a.unit);
    } else if (!err) {
        fprintf(stderr, "%s: %s\n", ds, local.msg);
    }
    mcs_array_free(&a);
    mcs_results_close(&r);
    return v;
}

/* ---- the rider (scenarios/models/riders/, docs/rider.md) ---- */

/* the rider of model file `file` (relative to scenarios/) alone: free fall, no contacts, 1 ms;
 * NULL on failure, the error printed */
static inline mb_model *mt_rider_alone(const char *file)
{
    char txt[1024];
    snprintf(txt, sizeof txt,
             "mcrash: 1\ninclude: [%s]\nsimulation: {end_time: 1 ms, time_step: 10 us}\n", file);
    return mt_model_text("scenarios/rider_alone.yaml", txt, NULL);
}

/* the total mass of the rider's bodies (names rider_*) [kg], their number in *n */
static inline double mt_rider_mass(const mb_model *m, int *n)
{
    double tot = 0;
    *n = 0;
    for (int i = 0; i < m->nbody; i++)
        if (strncmp(m->body_name[i], "rider_", 6) == 0) tot += m->body[i].mass, (*n)++;
    return tot;
}

/* the rider of model file `file` (relative to scenarios/, one with the helmet) seated by the
 * positioning step (40 deg lean, head pitched -10 deg) on sport_208kg with the seat contact,
 * 50 ms under gravity, read as the file `name` in scenarios/; NULL on failure (error in *err,
 * or printed when err is NULL) */
static inline mb_model *mt_rider_seated_helmet(const char *name, const char *file,
                                               mcs_error *err)
{
    char txt[2048];
    snprintf(txt, sizeof txt,
             "mcrash: 1\n"
             "include: [models/motorcycles/sport_208kg.yaml, %s]\n"
             "environment: {gravity: 9.81 m/s^2, ground: {height: 0 m, friction: 0.9}}\n"
             "simulation: {end_time: 50 ms, time_step: 10 us}\n"
             "rider: {torso_lean: 40 deg, head_pitch: -10 deg}\n"
             "contacts:\n  - {a: rider_pelvis, b: moto_frame, characteristic: seat}\n",
             file);
    return mt_model_text(name, txt, err);
}

/* how far the helmet shell's offset from the head, in the head's frame, is from d0 (the
 * offset in the model file, where the head's axes are the world's) [m] */
static inline double mt_helmet_offset_error(const mb_model *m, const double d0[3])
{
    int h = mb_model_body(m, "rider_head"), sh = mb_model_body(m, "rider_helmet_shell");
    double R[9], d[3], e[3];
    mb_quat_to_rot(m->body[h].quat, R);
    mb_sub(m->body[sh].pos, m->body[h].pos, d);
    mb_mat_tvec(R, d, e);
    mb_sub(e, d0, e);
    return mb_norm(e);
}

/* the largest force of the helmet's couplings (attachments rider_helmet*) in state s [N] */
static inline double mt_helmet_coupling_force(const mb_model *m, const mb_state *s)
{
    double f = 0;
    for (int i = 0; i < m->nattach; i++)
        if (!strncmp(m->attach_name[i], "rider_helmet", 12)) f = fmax(f, mb_norm(s->att[i].force));
    return f;
}

/* distance of x from the ellipsoid surface s of the built model (at its initial poses), to
 * first order: (f - 1) / |grad f|, f the ellipsoid's normalised radius [m] */
static inline double mt_surf_distance(const mb_model *m, const mb_surface *s, const double x[3])
{
    const mb_body_desc *b = &m->body[s->body];
    double R[9], c[3], d[3], e[3], l[3];
    mb_quat_to_rot(b->quat, R);
    for (int i = 0; i < 3; i++)
        c[i] = b->pos[i] + R[3 * i] * s->center[0] + R[3 * i + 1] * s->center[1] +
               R[3 * i + 2] * s->center[2];
    for (int i = 0; i < 3; i++)
        d[i] = x[i] - c[i];
    for (int i = 0; i < 3; i++)
        e[i] = R[i] * d[0] + R[3 + i] * d[1] + R[6 + i] * d[2];
    for (int i = 0; i < 3; i++)
        l[i] = s->rot[i] * e[0] + s->rot[3 + i] * e[1] + s->rot[6 + i] * e[2];
    double f2 = 0, g2 = 0;
    for (int i = 0; i < 3; i++) {
        f2 += l[i] * l[i] / (s->semi[i] * s->semi[i]);
        g2 += l[i] * l[i] / pow(s->semi[i], 4);
    }
    double f = sqrt(f2);
    return (f - 1) / (sqrt(g2) / f);
}

/* the least mt_surf_distance of the outer face nodes (hexahedron nodes 4-7) of the FE part
 * `part` from the surface `surf` at t = 0 [m]; *ip: the part's index; NAN (*ip -1) when the
 * part or the surface is missing */
static inline double mt_hex_face_gap(const mb_model *m, const fe_model *fm, const char *part,
                                     const char *surf, int *ip)
{
    int st = -1;
    *ip = -1;
    for (int i = 0; i < fm->npart; i++)
        if (strcmp(fm->part[i].name, part) == 0) *ip = i;
    for (int i = 0; i < m->nsurf; i++)
        if (strcmp(m->surf[i].name, surf) == 0) st = i;
    if (*ip < 0 || st < 0) return *ip = -1, NAN;
    const fe_part *p = &fm->part[*ip];
    double gap = INFINITY;
    for (int e = p->elem_begin; e < p->elem_end; e++)
        for (int j = 4; j < 8; j++)
            gap = fmin(gap, mt_surf_distance(m, &m->surf[st],
                                             fm->node_x0 + 3 * fm->hex_node[8 * e + j]));
    return gap;
}

#endif

/* s2_run.c: a stage-2 run (s2_run.h): the stage-1 engine's run of the stage-2 model, with
 * /stage2/motion written before the results file is committed */
#include "stage2_fe/s2_run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct {
    const s2_model *m;
    s2_summary *sum;
} s2_write_ctx;

/* one prescribed body: the motion at the file's samples t_k <= t_end against the written pose */
static mcs_status motion_error(const s2_model *m, int i, double t_end, mcs_results *in,
                               mcs_results *r, double *pmax, double *amax, mcs_error *err)
{
    const tr_motion *mo = tr_stage2_motion_get(m->motion);
    const char *from = NULL, *body = tr_stage2_motion_body(m->motion, i, &from);
    const char *file = tr_stage2_motion_path(m->motion);
    char path[512];
    mcs_array t = {0}, p = {0}, q = {0};
    mcs_status st = mcs_results_read(in, "/stage1/time", &t, err);
    snprintf(path, sizeof path, "/stage1/bodies/%s/position", from);
    if (!st) st = mcs_results_read(in, path, &p, err);
    snprintf(path, sizeof path, "/stage1/bodies/%s/orientation", from);
    if (!st) st = mcs_results_read(in, path, &q, err);
    size_t n = 0;
    while (!st && n < t.n && t.v[n] <= t_end * (1 + 1e-9) + 1e-12)
        n++;
    double *e = st ? NULL : malloc(2 * (n > 0 ? n : 1) * sizeof *e);
    if (!st && !e) st = MCS_ERR(err, MCS_ERR_NOMEM, "stage 2: out of memory");
    if (!st && (p.n < 3 * n || q.n < 4 * n))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: /stage1/bodies/%s: fewer rows than /stage1/time",
                     file, from);
    int k = tr_motion_body(mo, from);
    for (size_t j = 0; !st && j < n; j++) {
        tr_motion_kin kin;
        st = tr_motion_eval(mo, k, t.v[j], &kin, err);
        double d[3] = {kin.pos[0] - p.v[3 * j], kin.pos[1] - p.v[3 * j + 1],
                       kin.pos[2] - p.v[3 * j + 2]};
        e[j] = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        e[n + j] = tr_quat_angle(kin.quat, q.v + 4 * j);
        *pmax = fmax(*pmax, e[j]);
        *amax = fmax(*amax, e[n + j]);
    }
    const size_t dn = n;
    char grp[256];
    snprintf(grp, sizeof grp, "/stage2/motion/%s", body);
    snprintf(path, sizeof path, "%s/time", grp);
    if (!st) st = mcs_results_write(r, path, 1, &dn, t.v, "s", err);
    snprintf(path, sizeof path, "%s/position_error", grp);
    if (!st) st = mcs_results_write(r, path, 1, &dn, e, "m", err);
    snprintf(path, sizeof path, "%s/angle_error", grp);
    if (!st) st = mcs_results_write(r, path, 1, &dn, e + n, "rad", err);
    if (!st) st = mcs_results_set_attr_str(r, grp, "from", from, err);
    if (!st) st = mcs_results_set_attr_str(r, grp, "file", file, err);
    if (!st)
        st = mcs_results_set_attr_str(r, grp, "method",
                                      tr_motion_method_name(tr_motion_get_method(mo)), err);
    free(e);
    mcs_array_free(&t), mcs_array_free(&p), mcs_array_free(&q);
    return st;
}

static mcs_status write_motion(void *ctx, const mb_model *mb, const mb_state *s, mcs_results *r,
                               mcs_error *err)
{
    (void)mb;
    s2_write_ctx *c = ctx;
    mcs_results *in = NULL;
    mcs_status st = mcs_results_open(&in, tr_stage2_motion_path(c->m->motion), err);
    for (int i = 0; !st && i < tr_stage2_motion_count(c->m->motion); i++)
        st = motion_error(c->m, i, s->t, in, r, &c->sum->position_error, &c->sum->angle_error, err);
    mcs_results_close(&in);
    return st;
}

mcs_status s2_run(const s2_model *m, const s2_run_opts *o, s2_summary *sum, mcs_error *err)
{
    s2_summary local = {0};
    if (!sum) sum = &local;
    *sum = (s2_summary){.prescribed = tr_stage2_motion_count(m->motion)};
    s2_write_ctx c = {.m = m, .sum = sum};
    mb_run_opts mo = {.out_path = o ? o->out_path : NULL,
                      .scenario_text = o ? o->scenario_text : NULL,
                      .quiet = o && o->quiet,
                      .append = o && o->append,
                      .write_more = write_motion,
                      .write_ctx = &c};
    return mb_run(m->mb, &mo, &sum->mb, err);
}

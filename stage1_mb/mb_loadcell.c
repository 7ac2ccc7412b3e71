/* mb_loadcell.c: load-cell sensors (see mb_loadcell.h). */
#include "stage1_mb/mb_loadcell.h"
#include "analysis/an_cfc.h"
#include "stage1_mb/mb_build_internal.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

struct mb_loadcell {
    char name[MB_NAME]; /* channel prefix                                                  */
    int joint;          /* joint index                                                      */
    int body;           /* the body the loads act on (the joint's child or parent)          */
    int on_child;       /* 1: body is the joint's child                                     */
    int frame;          /* body carrying the cell point and axes                            */
    double point[3];    /* cell point, frame body's frame [m]                               */
    double axes[9];     /* cell axes in the frame body's frame (columns), ISO               */
    int cfc;            /* SAE J211 class, 0 = unfiltered                                   */
};

mcs_status mb_build_loadcells(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *list = mcs_node_get(root, "sensors");
    int n = 0;
    for (int i = 0; i < mcs_node_len(list); i++) {
        const char *ty = mcs_node_str(mcs_node_get(mcs_node_at(list, i), "type"));
        n += ty && strcmp(ty, "load_cell") == 0;
    }
    m->nloadcell = 0;
    m->loadcell = MB_NEW(struct mb_loadcell, n);
    if (!m->loadcell) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *sn = mcs_node_at(list, i);
        const char *ty = mcs_node_str(mcs_node_get(sn, "type"));
        if (!ty || strcmp(ty, "load_cell") != 0) continue;
        struct mb_loadcell *lc = &m->loadcell[m->nloadcell];
        snprintf(lc->name, MB_NAME, "%s", mcs_node_str(mcs_node_get(sn, "name")));
        lc->body = mb_build_body_ref(m, mcs_node_get(sn, "body"));
        const mcs_node *jn = mcs_node_get(sn, "joint");
        const char *jname = mcs_node_str(jn);
        if (!jname)
            return mcs_node_error(sn, err, MCS_ERR_KEY,
                                  "a load_cell sensor needs joint: (a joint name)");
        lc->joint = -1;
        for (int j = 0; j < m->njoint; j++)
            if (strcmp(m->joint[j].name, jname) == 0) lc->joint = j;
        if (lc->joint < 0)
            return mcs_node_error(jn, err, MCS_ERR_KEY, "no joint named '%s'", jname);
        const mb_joint_def *jd = &m->joint[lc->joint];
        if (lc->body != jd->child && lc->body != jd->parent)
            return mcs_node_error(mcs_node_get(sn, "body"), err, MCS_ERR_RANGE,
                                  "body %s is not connected by joint %s",
                                  lc->body >= 0 ? m->body_name[lc->body] : "ground", jname);
        lc->on_child = lc->body == jd->child;
        const mcs_node *fn = mcs_node_get(sn, "frame");
        lc->frame = mcs_node_str(fn) ? mb_build_body_ref(m, fn) : lc->body;
        if (lc->frame < 0)
            return mcs_node_error(fn ? fn : sn, err, MCS_ERR_RANGE,
                                  "a load cell's frame must be a body, not the ground");
        const mcs_node *p = mcs_node_get(sn, "point");
        if (mcs_node_kind(p) == MCS_NODE_SEQ) {
            mcs_status st = mcs_node_vec3(p, lc->point, err);
            if (st) return st;
        }
        double rpy[3] = {0, 0, 0};
        const mcs_node *o = mcs_node_get(sn, "orientation");
        if (mcs_node_kind(o) == MCS_NODE_SEQ) {
            mcs_status st = mcs_node_vec3(o, rpy, err);
            if (st) return st;
        }
        mb_build_cardan(rpy, lc->axes);
        lc->cfc = (int)mcs_node_num_or(sn, "cfc", 0);
        if (lc->cfc > 0 && 2.0775 * lc->cfc >= 0.5 * m->output_rate)
            return mcs_node_error(mcs_node_get(sn, "cfc"), err, MCS_ERR_RANGE,
                                  "CFC %d needs an output_rate above %g Hz (it is %g Hz)", lc->cfc,
                                  2 * 2.0775 * lc->cfc, m->output_rate);
        m->nloadcell++;
    }
    return MCS_OK;
}

/* the joint's load on its child at the last step: force, and torque about the child's CG */
static void child_load(const mb_model *m, const mb_state *s, int j, double f[3], double t[3])
{
    const mb_joint_def *jd = &m->joint[j];
    mb_joint_reaction(s->world, j, f, t);
    if (jd->restraint < 0) return;
    if (jd->type == MB_J_REVOLUTE || jd->type == MB_J_TRANSLATIONAL) {
        double ax[3];
        mb_joint_axis(s->world, j, ax);
        double L = s->r1[jd->restraint].load;
        if (jd->type == MB_J_REVOLUTE)
            mb_axpy(t, L, ax, t);
        else
            mb_axpy(f, L, ax, f);
    } else if (jd->type != MB_J_FIXED) {
        mb_add(t, s->r3[jd->restraint].torque, t);
    }
}

void mb_loadcell_value(const mb_model *m, const mb_state *s, int i, double out[6])
{
    const struct mb_loadcell *lc = &m->loadcell[i];
    const mb_joint_def *jd = &m->joint[lc->joint];
    double f[3], t[3], P[3], r[3], q[3];
    child_load(m, s, lc->joint, f, t);
    /* cell point (world) and the moment about it; the child's CG is the force's reference */
    const mb_body_kin *kf = &s->kin[lc->frame], *kc = &s->kin[jd->child];
    mb_mat_vec(kf->rot, lc->point, P);
    mb_add(P, kf->pos, P);
    mb_sub(kc->pos, P, r);
    mb_cross(r, f, q);
    mb_add(t, q, t);
    if (!lc->on_child) mb_scale(f, -1, f), mb_scale(t, -1, t);
    /* cell axes in the world: frame rotation x the cell's own axes */
    double A[9], fl[3], tl[3];
    mb_mat_mul(kf->rot, lc->axes, A);
    mb_mat_tvec(A, f, fl);
    mb_mat_tvec(A, t, tl);
    out[0] = fl[0], out[1] = -fl[1], out[2] = -fl[2];
    out[3] = tl[0], out[4] = -tl[1], out[5] = -tl[2];
}

void mb_loadcell_record(const mb_model *m, const mb_state *s, long row)
{
    for (int i = 0; i < m->nloadcell; i++)
        mb_loadcell_value(m, s, i, s->rec_loadcell + ((size_t)row * m->nloadcell + i) * 6);
}

mcs_status mb_loadcell_write(const mb_model *m, const mb_state *s, mcs_results *r, mcs_error *err)
{
    static const char *const sfx[6] = {"fx", "fy", "fz", "mx", "my", "mz"};
    size_t nt = (size_t)s->nrec;
    double dt = 1.0 / m->output_rate;
    double *buf = malloc((nt > 0 ? nt : 1) * sizeof *buf);
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1 output: out of memory");
    mcs_status st = MCS_OK;
    for (int i = 0; !st && i < m->nloadcell; i++) {
        const struct mb_loadcell *lc = &m->loadcell[i];
        for (int k = 0; !st && k < 6; k++) {
            for (size_t t = 0; t < nt; t++)
                buf[t] = s->rec_loadcell[(t * m->nloadcell + i) * 6 + k];
            if (lc->cfc > 0 && nt >= 2) st = an_cfc_filter(buf, (int)nt, dt, lc->cfc, buf, err);
            char name[MB_NAME + 8];
            snprintf(name, sizeof name, "%s_%s", lc->name, sfx[k]);
            if (!st)
                st = mcs_results_put_channel(r, mb_out_stage(m), name, nt, buf, k < 3 ? "N" : "N*m",
                                             "SAE J211 local (x forward, y right, z down)",
                                             nt >= 2 ? lc->cfc : 0, m->body_name[lc->frame], err);
        }
    }
    free(buf);
    return st;
}

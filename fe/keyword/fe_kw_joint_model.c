/* fe_kw_joint_model.c: a model's joints, nodal rigid bodies and extra nodes into its deck
 * (fe_kw_from_model; fe_kw_impl.h). LS-DYNA defines a joint by node pairs on the two rigid
 * bodies, so each joint gets new nodes: N1 (on A) and N2 (on B) at the joint point, N3 and N4
 * one length unit along the axis, (translational) N5 and N6 one unit along its normal; a
 * rigid part carries its new nodes as *CONSTRAINED_EXTRA_NODES_NODE, a nodal rigid body in its
 * node set; the ground's nodes are held by *BOUNDARY_SPC_NODE (mcrash reads a joint node held
 * in every translation and on no body as the ground; LS-DYNA would want a rigid body there).
 * The spring, damper and stops become *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED (angle, phi)
 * or _TRANSLATIONAL (slide, x) with two-point curves through the origin. Joints are placed as
 * at t = 0. */
#include "fe/fe_joint.h"
#include "fe/fe_kw_impl.h"
#include "fe/fe_solid.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static mcs_status nomem(mcs_error *err)
{
    return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory (joints)");
}

/* a node set with room for n ids; its index */
static mcs_status new_set(fe_kw_deck *d, int id, int n, int *index, mcs_error *err)
{
    fe_kw_set *s = kw_push((void **)&d->set, &d->nset, &d->cap_set, sizeof *s);
    if (!s) return nomem(err);
    s->id = id;
    s->ids = malloc(sizeof(int) * (size_t)(n > 0 ? n : 1));
    if (!s->ids) return nomem(err);
    *index = d->nset - 1;
    return MCS_OK;
}

/* a two-point curve (-1, -k), (1, k); its ID */
static mcs_status line_curve(fe_kw_deck *d, int id, double k, mcs_error *err)
{
    fe_kw_curve *c = kw_push((void **)&d->curve, &d->ncurve, &d->cap_curve, sizeof *c);
    if (!c) return nomem(err);
    c->id = id, c->n = 2;
    c->xy = malloc(4 * sizeof(double));
    if (!c->xy) return nomem(err);
    c->xy[0] = -1, c->xy[1] = -k, c->xy[2] = 1, c->xy[3] = k;
    return MCS_OK;
}

/* node n (0-based, ID n + 1) joins body b: a rigid part's extra node or a set member */
static mcs_status on_body(const fe_model *m, fe_kw_deck *d, int b, int nid, const int *set_of,
                          mcs_error *err)
{
    if (b < 0) { /* the ground */
        fe_kw_spc *s = kw_push((void **)&d->spc, &d->nspc, &d->cap_spc, sizeof *s);
        if (!s) return nomem(err);
        *s = (fe_kw_spc){FE_KW_ON_NODE, nid, FE_DOF_ALL, {0, 0}};
        return MCS_OK;
    }
    if (m->body[b].part < 0) {
        fe_kw_set *s = &d->set[set_of[b]];
        s->ids[s->n++] = nid;
        return MCS_OK;
    }
    fe_kw_nrb *r = kw_push((void **)&d->nrb, &d->nnrb, &d->cap_nrb, sizeof *r);
    if (!r) return nomem(err);
    *r = (fe_kw_nrb){.kind = 1, .pid = m->body[b].part + 1, .id = nid};
    return MCS_OK;
}

static mcs_status one_joint(const fe_model *m, fe_kw_deck *d, int j, int *nid, int *lcid,
                            const int *set_of, mcs_error *err)
{
    const fe_joint *J = &m->joint[j];
    const fe_body *A = &m->body[J->body[0]];
    double p[3], q[6][3];
    for (int k = 0; k < 3; k++)
        p[k] = A->x0[k] + J->r[0][k];
    const int nn = J->type == FE_JOINT_SPHERICAL ? 2 : J->type == FE_JOINT_TRANSLATIONAL ? 6 : 4;
    fe_kw_joint kj = {.id = j + 1, .type = J->type, .rps = J->scale / 0.1, .damp = 1};
    snprintf(kj.title, sizeof kj.title, "%s", J->name);
    mcs_status st = MCS_OK;
    for (int i = 0; i < nn && !st; i++) {
        const double *dir = i < 2 ? NULL : i < 4 ? J->axis : J->perp;
        for (int k = 0; k < 3; k++)
            q[i][k] = p[k] + (dir ? dir[k] * d->unit[0] : 0);
        kj.node[i] = ++*nid;
        st = fe_kw_deck_add_node(d, *nid, q[i], err);
        if (!st) st = on_body(m, d, J->body[i % 2], *nid, set_of, err);
    }
    if (st) return st;
    fe_kw_joint *pj = kw_push((void **)&d->joint, &d->njoint, &d->cap_joint, sizeof *pj);
    if (!pj) return nomem(err);
    *pj = kj;
    if (!(J->ks > 0) && !(J->cs > 0) && !J->has_range) return MCS_OK;
    const int slide = J->type == FE_JOINT_CYLINDRICAL || J->type == FE_JOINT_TRANSLATIONAL;
    fe_kw_jstiff s = {.translational = slide, .jsid = j + 1, .jid = j + 1};
    s.pida = A->part + 1;
    s.pidb = J->body[1] >= 0 ? m->body[J->body[1]].part + 1 : 0;
    if (J->ks > 0 && !(st = line_curve(d, ++*lcid, J->ks, err))) s.lc[0] = *lcid;
    if (!st && J->cs > 0 && !(st = line_curve(d, ++*lcid, J->cs, err))) s.dlc[0] = *lcid;
    if (J->has_range) s.neg[0] = J->range[0], s.pos[0] = J->range[1];
    fe_kw_jstiff *ps = kw_push((void **)&d->jstiff, &d->njstiff, &d->cap_jstiff, sizeof *ps);
    if (!ps) return nomem(err);
    *ps = s;
    return st;
}

mcs_status kw_joints_from_model(const fe_model *m, const double *x, fe_kw_deck *d, mcs_error *err)
{
    (void)x;
    if (m->nbody == 0) return MCS_OK;
    int nid = d->nnode ? d->node_id[d->nnode - 1] : 0, sid = 0, lcid = 0;
    for (int i = 0; i < d->nset; i++)
        sid = d->set[i].id > sid ? d->set[i].id : sid;
    for (int i = 0; i < d->ncurve; i++)
        lcid = d->curve[i].id > lcid ? d->curve[i].id : lcid;
    int *set_of = calloc((size_t)m->nbody, sizeof *set_of);
    if (!set_of) return nomem(err);
    mcs_status st = MCS_OK;
    /* nodal rigid bodies: a node set each (with room for their joints' nodes) */
    for (int b = 0; b < m->nbody && !st; b++) {
        const fe_body *B = &m->body[b];
        if (B->part < 0) {
            st = new_set(d, ++sid, B->node_end - B->node_begin + 6 * m->njoint, &set_of[b], err);
            fe_kw_set *s = &d->set[set_of[b]];
            for (int k = B->node_begin; k < B->node_end && !st; k++)
                s->ids[s->n++] = m->body_node[k] + 1;
            fe_kw_nrb *r = st ? NULL : kw_push((void **)&d->nrb, &d->nnrb, &d->cap_nrb, sizeof *r);
            if (!st && !r) st = nomem(err);
            if (!st) *r = (fe_kw_nrb){.kind = 0, .pid = m->npart + 1 + b, .id = sid};
            continue;
        }
        /* nodes a rigid part carries that none of its elements holds: extra nodes */
        for (int k = B->node_begin; k < B->node_end && !st; k++) {
            int n = m->body_node[k];
            if (m->node_part[n] == B->part) continue;
            st = on_body(m, d, b, n + 1, set_of, err);
        }
    }
    for (int j = 0; j < m->njoint && !st; j++)
        st = one_joint(m, d, j, &nid, &lcid, set_of, err);
    free(set_of);
    return st;
}

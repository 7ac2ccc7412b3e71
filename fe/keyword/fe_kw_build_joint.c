/* fe_kw_build_joint.c: a deck's nodal rigid bodies, extra nodes, joints and joint stiffnesses
 * into a builder (fe_kw_impl.h; kernel fe_joint.h). Errors name the deck's FILE:LINE. */
#include "fe/fe_joint.h"
#include "fe/fe_kw_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const jkw[4] = {"SPHERICAL", "REVOLUTE", "CYLINDRICAL", "TRANSLATIONAL"};

/* the node IDs an entry names: a joint's N1..Nk, an extra node, a node set's members */
static mcs_status nrb_ids(const fe_kw_deck *dk, const fe_kw_nrb *r, const int **ids, int *n,
                          mcs_error *err)
{
    static const char *const what[3] = {"*CONSTRAINED_NODAL_RIGID_BODY",
                                        "*CONSTRAINED_EXTRA_NODES_NODE",
                                        "*CONSTRAINED_EXTRA_NODES_SET"};
    if (r->kind == 1) {
        *ids = &r->id, *n = 1;
        return MCS_OK;
    }
    const fe_kw_set *s = fe_kw_find_set(dk, r->id, 0);
    if (!s)
        return kw_at(dk, r->loc, err, MCS_ERR_FORMAT, "%s %d: node set %d is not defined",
                  what[r->kind], r->pid, r->id);
    *ids = s->ids, *n = s->n;
    return MCS_OK;
}

/* deck node nid into the builder (added when no element holds it); its builder index */
static mcs_status node_in(fe_builder *b, const fe_kw_deck *dk, int *map, int nid, int *out,
                          fe_kw_loc loc, const char *what, mcs_error *err)
{
    int di = fe_kw_node_index(dk, nid);
    if (di < 0) return kw_at(dk, loc, err, MCS_ERR_FORMAT, "%s: node %d is not defined", what, nid);
    if (map[di] < 0) {
        mcs_status st = fe_builder_add_node(b, dk->node_x + 3 * di, &map[di], err);
        if (st) return st;
    }
    *out = map[di];
    return MCS_OK;
}

mcs_status kw_add_deck_joint_nodes(fe_builder *b, const fe_kw_deck *dk, int *map, mcs_error *err)
{
    int idx;
    char what[96];
    for (int j = 0; j < dk->njoint; j++) {
        const fe_kw_joint *J = &dk->joint[j];
        for (int k = 0; k < 6; k++) {
            if (J->node[k] <= 0) continue;
            snprintf(what, sizeof what, "*CONSTRAINED_JOINT_%s %d: N%d", jkw[J->type], J->id,
                     k + 1);
            mcs_status st = node_in(b, dk, map, J->node[k], &idx, J->loc, what, err);
            if (st) return st;
        }
    }
    for (int i = 0; i < dk->nnrb; i++) {
        const int *ids = NULL;
        int n = 0;
        mcs_status st = nrb_ids(dk, &dk->nrb[i], &ids, &n, err);
        snprintf(what, sizeof what, "*CONSTRAINED_%s %d",
                 dk->nrb[i].kind ? "EXTRA_NODES" : "NODAL_RIGID_BODY", dk->nrb[i].pid);
        for (int k = 0; k < n && !st; k++)
            st = node_in(b, dk, map, ids[k], &idx, dk->nrb[i].loc, what, err);
        if (st) return st;
    }
    return MCS_OK;
}

/* slope of a curve from its first to its last point, in the deck's units; 0 for none */
static mcs_status curve_slope(const fe_kw_deck *dk, int lcid, fe_kw_loc loc, double *k,
                              mcs_error *err)
{
    *k = 0;
    if (lcid <= 0) return MCS_OK;
    const fe_kw_curve *c = fe_kw_find_curve(dk, lcid);
    if (!c || c->n < 2)
        return kw_at(dk, loc, err, MCS_ERR_FORMAT,
                  "*CONSTRAINED_JOINT_STIFFNESS: curve %d is not defined (or has one point)", lcid);
    const double *p = c->xy;
    double dx = p[2 * (c->n - 1)] - p[0];
    if (!(dx > 0))
        return kw_at(dk, loc, err, MCS_ERR_FORMAT, "*CONSTRAINED_JOINT_STIFFNESS: curve %d is flat",
                  lcid);
    *k = (p[2 * (c->n - 1) + 1] - p[1]) / dx;
    return MCS_OK;
}

/* a *CONSTRAINED_JOINT_STIFFNESS onto joint d: the first axis with a curve or stops */
static mcs_status add_stiffness(const fe_kw_deck *dk, const fe_kw_jstiff *s, fe_joint_desc *d,
                                mcs_error *err)
{
    const char *kind = s->translational ? "TRANSLATIONAL" : "GENERALIZED";
    const int slide = d->type == FE_JOINT_CYLINDRICAL || d->type == FE_JOINT_TRANSLATIONAL;
    if (d->type == FE_JOINT_SPHERICAL || slide != s->translational)
        return kw_at(dk, s->loc, err, MCS_ERR_UNSUPPORTED,
                  "*CONSTRAINED_JOINT_STIFFNESS_%s %d: a %s joint's free coordinate takes "
                  "%s",
                  kind, s->jsid, fe_joint_type_name[d->type],
                  d->type == FE_JOINT_SPHERICAL ? "no stiffness"
                  : slide                       ? "_TRANSLATIONAL (the slide)"
                                                : "_GENERALIZED (the angle)");
    int ax = 0;
    while (ax < 2 && !s->lc[ax] && !s->dlc[ax] && !s->neg[ax] && !s->pos[ax])
        ax++;
    /* deck units: moment / rad or force / length, and their rates */
    const double *u = dk->unit, F = u[2] * u[0] / (u[1] * u[1]);
    const double ks = slide ? F / u[0] : F * u[0], cs = slide ? F * u[1] / u[0] : F * u[0] * u[1];
    double k, c;
    mcs_status st = curve_slope(dk, s->lc[ax], s->loc, &k, err);
    if (!st) st = curve_slope(dk, s->dlc[ax], s->loc, &c, err);
    if (st) return st;
    if (k < 0 || c < 0)
        return kw_at(dk, s->loc, err, MCS_ERR_FORMAT,
                  "*CONSTRAINED_JOINT_STIFFNESS_%s %d: a falling stiffness or damping curve", kind,
                  s->jsid);
    d->stiffness = k * ks, d->damping = c * cs;
    if (s->neg[ax] != 0 || s->pos[ax] != 0) {
        d->has_range = 1;
        d->range[0] = s->neg[ax] != 0 ? s->neg[ax] : -1e30;
        d->range[1] = s->pos[ax] != 0 ? s->pos[ax] : 1e30;
    }
    return MCS_OK;
}

static mcs_status add_nrbs(fe_builder *b, const fe_kw_deck *dk, const char (*names)[FE_NAME_MAX],
                           const int *map, mcs_error *err)
{
    for (int i = 0; i < dk->nnrb; i++) {
        const fe_kw_nrb *r = &dk->nrb[i];
        const int *ids = NULL;
        int n = 0;
        mcs_status st = nrb_ids(dk, r, &ids, &n, err);
        if (st) return st;
        int *idx = malloc(sizeof(int) * (size_t)(n > 0 ? n : 1));
        if (!idx) return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
        for (int k = 0; k < n; k++)
            idx[k] = map[fe_kw_node_index(dk, ids[k])];
        mcs_error kerr = {0};
        if (r->kind == 0) {
            char name[FE_NAME_MAX];
            snprintf(name, sizeof name, "nrb_%d", r->pid);
            st = fe_builder_add_nodal_rigid_body(b, name, idx, n, &kerr);
        } else {
            int k = 0;
            while (k < dk->npart && dk->part[k].id != r->pid)
                k++;
            if (k == dk->npart)
                st = MCS_ERR(&kerr, MCS_ERR_KEY, "part %d is not defined", r->pid);
            else
                st = fe_builder_add_extra_nodes(b, names[k], idx, n, &kerr);
        }
        free(idx);
        if (st)
            return kw_at(dk, r->loc, err, st, "*CONSTRAINED_%s %d: %s",
                      r->kind ? "EXTRA_NODES" : "NODAL_RIGID_BODY", r->pid, kerr.msg);
    }
    return MCS_OK;
}

mcs_status kw_add_deck_joints(fe_builder *b, const fe_kw_deck *dk, const char (*names)[FE_NAME_MAX],
                              const int *map, mcs_error *err)
{
    mcs_status st = add_nrbs(b, dk, names, map, err);
    for (int i = 0; i < dk->njstiff && !st; i++) {
        int j = 0;
        while (j < dk->njoint && dk->joint[j].id != dk->jstiff[i].jid)
            j++;
        if (j == dk->njoint)
            st = kw_at(dk, dk->jstiff[i].loc, err, MCS_ERR_FORMAT,
                    "*CONSTRAINED_JOINT_STIFFNESS %d: joint JID %d is not defined",
                    dk->jstiff[i].jsid, dk->jstiff[i].jid);
    }
    for (int j = 0; j < dk->njoint && !st; j++) {
        const fe_kw_joint *J = &dk->joint[j];
        fe_joint_desc d = fe_joint_desc_default();
        d.type = (fe_joint_type)J->type;
        size_t nt = strlen(J->title);
        if (nt && nt < sizeof d.name)
            memcpy(d.name, J->title, nt + 1);
        else
            snprintf(d.name, sizeof d.name, "joint_%d", J->id);
        for (int k = 0; k < 6; k++)
            d.node[k] = J->node[k] > 0 ? map[fe_kw_node_index(dk, J->node[k])] : -1;
        d.penalty_scale = fmin(1, 0.1 * J->rps);
        d.file = dk->file[J->loc.file], d.line = J->loc.line;
        for (int i = 0; i < dk->njstiff && !st; i++)
            if (dk->jstiff[i].jid == J->id) st = add_stiffness(dk, &dk->jstiff[i], &d, err);
        mcs_error kerr = {0};
        if (!st) st = fe_builder_add_joint(b, &d, &kerr);
        if (st && kerr.status) st = MCS_ERR(err, st, "%s", kerr.msg);
    }
    return st;
}

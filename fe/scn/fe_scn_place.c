/* fe_scn_place.c: the parts carried by placed stage-1 bodies move with them (fe_scn_build.h,
 * fe_scn_place). Runs on the builder after every key is read and before the model is frozen,
 * so everything the model derives from positions (masses, contact segments, rigid bodies,
 * bag volumes, belt lengths) sees the placed geometry. */
#include "fe/scn/fe_scn_place.h"
#include "fe/fe_builder_impl.h"
#include "fe/fe_restraint.h"
#include "fe/scn/fe_scn_node.h"
#include "fe/fe_slipring.h"

#include <stdlib.h>
#include <string.h>

typedef struct {
    const fe_scn_place *pl;
    int *grp;                 /* group carrying each part, -1 none (npart) */
    const mcs_node **carrier; /* body-name node carrying each part (npart)  */
} placing;

/* x <- R x (a direction) */
static void rotate_vec(const fe_scn_place *pl, double x[3])
{
    const double *R = pl->R;
    double y[3];
    for (int i = 0; i < 3; i++)
        y[i] = R[3 * i] * x[0] + R[3 * i + 1] * x[1] + R[3 * i + 2] * x[2];
    memcpy(x, y, sizeof y);
}

/* x <- R x + t (a point) */
static void move_point(const fe_scn_place *pl, double x[3])
{
    rotate_vec(pl, x);
    for (int i = 0; i < 3; i++)
        x[i] += pl->t[i];
}

/* part `pname` (named at pnode) is carried by the body named at bnode */
static mcs_status carry(const fe_builder *b, placing *p, const mcs_node *pnode,
                        const mcs_node *bnode, mcs_error *err)
{
    int ip = fe_builder_find_part(b, mcs_node_str(pnode));
    if (ip < 0) return MCS_OK; /* an unknown part is the builder's error, already reported */
    const char *body = mcs_node_str(bnode);
    int g = body ? p->pl->group(p->pl->ctx, body) : -1;
    if (g < 0) return mcs_node_error(bnode, err, MCS_ERR_KEY, "no body of that name");
    if (p->grp[ip] >= 0 && p->grp[ip] != g)
        return mcs_node_error(bnode, err, MCS_ERR_RANGE,
                              "part '%s' is carried by '%s' and by '%s', bodies of two groups "
                              "that the impact placement moves differently",
                              b->part[ip].name, mcs_node_str(p->carrier[ip]), body);
    if (p->grp[ip] < 0) p->grp[ip] = g, p->carrier[ip] = bnode;
    return MCS_OK;
}

/* carriers named in the keys: attach, retractors' anchor_body, slip rings' body */
static mcs_status carriers(const fe_builder *b, const mcs_node *fe, placing *p, mcs_error *err)
{
    const mcs_node *parts = fe_scn_get(fe, "parts");
    mcs_status st = MCS_OK;
    for (int i = 0; i < mcs_node_len(parts) && !st; i++) {
        const mcs_node *e = mcs_node_at(parts, i);
        if (fe_scn_given(e, "attach"))
            st = carry(b, p, fe_scn_get(e, "name"), fe_scn_get(fe_scn_get(e, "attach"), "body"),
                       err);
    }
    static const char *const list[2] = {"retractors", "sliprings"},
                             *key[2] = {"anchor_body", "body"};
    for (int k = 0; k < 2 && !st; k++) {
        const mcs_node *l = fe_scn_get(fe, list[k]);
        for (int i = 0; i < mcs_node_len(l) && !st; i++) {
            const mcs_node *e = mcs_node_at(l, i);
            if (fe_scn_given(e, key[k]))
                st = carry(b, p, fe_scn_get(e, "part"), fe_scn_get(e, key[k]), err);
        }
    }
    return st;
}

/* the fe.parts entry named `name` (for messages), else fe */
static const mcs_node *part_node(const mcs_node *fe, const char *name)
{
    const mcs_node *parts = fe_scn_get(fe, "parts");
    for (int i = 0; i < mcs_node_len(parts); i++) {
        const char *s = mcs_node_str(fe_scn_get(mcs_node_at(parts, i), "name"));
        if (s && strcmp(s, name) == 0) return mcs_node_at(parts, i);
    }
    return fe;
}

/* a part sharing nodes with a carried part is carried by the same group (and body) */
static mcs_status spread(const fe_builder *b, const mcs_node *fe, placing *p, int *ngrp,
                         int *npart_of, mcs_error *err)
{
    for (int changed = 1; changed;) {
        changed = 0;
        for (int n = 0; n < b->nnode; n++)
            ngrp[n] = -1, npart_of[n] = -1;
        for (int k = 0; k < FE_NKIND; k++) {
            const int nn = fe_kind_nnode(k);
            for (int e = 0; e < b->nelem[k]; e++) {
                const int ip = b->epart[k][e], g = p->grp[ip];
                if (g < 0) continue;
                for (int j = 0; j < nn; j++) {
                    const int n = b->conn[k][nn * e + j];
                    if (ngrp[n] >= 0 && ngrp[n] != g)
                        return mcs_node_error(part_node(fe, b->part[ip].name), err, MCS_ERR_RANGE,
                                              "parts '%s' and '%s' share nodes but are carried "
                                              "by bodies of two groups (impact:)",
                                              b->part[npart_of[n]].name, b->part[ip].name);
                    ngrp[n] = g, npart_of[n] = ip;
                }
            }
        }
        for (int k = 0; k < FE_NKIND; k++) {
            const int nn = fe_kind_nnode(k);
            for (int e = 0; e < b->nelem[k]; e++) {
                const int ip = b->epart[k][e];
                if (p->grp[ip] >= 0) continue;
                for (int j = 0; j < nn; j++) {
                    const int n = b->conn[k][nn * e + j];
                    if (ngrp[n] < 0) continue;
                    p->grp[ip] = ngrp[n], p->carrier[ip] = p->carrier[npart_of[n]];
                    changed = 1;
                    break;
                }
            }
        }
    }
    return MCS_OK;
}

static int moved_part(const fe_builder *b, const placing *p, const char *name)
{
    int ip = name ? fe_builder_find_part(b, name) : -1;
    return ip >= 0 && p->pl->moved >= 0 && p->grp[ip] == p->pl->moved;
}

/* anchors and points of the moved parts: on a body of the moved group they move; fixed to the
 * ground they would hold the part back (refused) */
static mcs_status points(fe_builder *b, const mcs_node *fe, const placing *p, mcs_error *err)
{
    static const char *const list[2] = {"retractors", "sliprings"};
    static const char *const key[2] = {"anchor_body", "body"}, *pt[2] = {"anchor", "point"};
    for (int k = 0; k < 2; k++) {
        const mcs_node *l = fe_scn_get(fe, list[k]);
        for (int i = 0; i < mcs_node_len(l); i++) {
            const mcs_node *e = mcs_node_at(l, i);
            const char *name = mcs_node_str(fe_scn_get(e, "name"));
            double *x =
                k == 0 ? fe_builder_retractor_anchor(b, name) : fe_builder_slipring_point(b, name);
            const char *body = mcs_node_str(fe_scn_get(e, key[k]));
            int g = body ? p->pl->group(p->pl->ctx, body) : -1;
            if (x && g >= 0 && g == p->pl->moved) move_point(p->pl, x);
            if (!body && moved_part(b, p, mcs_node_str(fe_scn_get(e, "part"))))
                return mcs_node_error(fe_scn_get(e, pt[k]), err, MCS_ERR_RANGE,
                                      "fixed to the ground, but part '%s' moves with the impact "
                                      "placement of its bodies: give %s",
                                      mcs_node_str(fe_scn_get(e, "part")), key[k]);
        }
    }
    const mcs_node *bl = fe_scn_get(fe, "boundary");
    for (int i = 0; i < b->nbc; i++)
        if ((b->bc[i].fix & FE_DOF_TRANS) && moved_part(b, p, b->bc[i].part))
            return mcs_node_error(i < mcs_node_len(bl) ? mcs_node_at(bl, i) : fe, err,
                                  MCS_ERR_RANGE,
                                  "holds translations of part '%s' in the world, but the part "
                                  "moves with the impact placement of its bodies",
                                  b->bc[i].part);
    /* the points that pick the nearest node of a moved part (after the move) */
    for (int i = 0; i < b->nspring; i++)
        for (int j = 0; j < 2; j++) {
            fe_spring_end *e = &b->spring[i].end[j];
            if (e->node < 0 && e->part[0] && moved_part(b, p, e->part)) move_point(p->pl, e->point);
        }
    for (int i = 0; i < b->nmass; i++)
        if (b->mass[i].at_point && moved_part(b, p, b->mass[i].part))
            move_point(p->pl, b->mass[i].point);
    return MCS_OK;
}

/* initial_velocity on a carried part: refused (it takes its body's velocity field) */
static mcs_status velocities(const fe_builder *b, const mcs_node *fe, const placing *p,
                             mcs_error *err)
{
    const mcs_node *parts = fe_scn_get(fe, "parts");
    for (int i = 0; i < mcs_node_len(parts); i++) {
        const mcs_node *e = mcs_node_at(parts, i);
        int ip = fe_builder_find_part(b, mcs_node_str(fe_scn_get(e, "name")));
        if (ip >= 0 && p->grp[ip] >= 0 && fe_scn_given(e, "initial_velocity"))
            return mcs_node_error(fe_scn_get(e, "initial_velocity"), err, MCS_ERR_RANGE,
                                  "part '%s' is carried by body '%s' and takes its velocity "
                                  "(v + w x r): remove initial_velocity",
                                  b->part[ip].name, mcs_node_str(p->carrier[ip]));
    }
    return MCS_OK;
}

mcs_status fe_scn_place_apply(fe_builder *b, const mcs_node *fe, const fe_scn_place *pl,
                              fe_problem *out, mcs_error *err)
{
    const size_t np = (size_t)(b->npart ? b->npart : 1), nn = (size_t)(b->nnode ? b->nnode : 1);
    placing p = {.pl = pl, .grp = malloc(np * sizeof *p.grp)};
    out->part_carrier = calloc(np, sizeof *out->part_carrier);
    p.carrier = out->part_carrier;
    int *ngrp = malloc(nn * sizeof *ngrp), *npart_of = malloc(nn * sizeof *npart_of);
    b->x_sel = malloc(3 * nn * sizeof *b->x_sel);
    mcs_status st = MCS_OK;
    if (!p.grp || !p.carrier || !ngrp || !npart_of || !b->x_sel)
        st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory placing the parts");
    for (int i = 0; i < b->npart && !st; i++)
        p.grp[i] = -1;
    if (!st) st = carriers(b, fe, &p, err);
    if (!st) st = spread(b, fe, &p, ngrp, npart_of, err);
    if (!st) st = velocities(b, fe, &p, err);
    if (!st) st = points(b, fe, &p, err);
    if (!st) {
        /* `where` selects on the positions before the move */
        memcpy(b->x_sel, b->x, 3 * (size_t)b->nnode * sizeof *b->x_sel);
        for (int n = 0; n < b->nnode; n++)
            if (pl->moved >= 0 && ngrp[n] == pl->moved) {
                move_point(pl, b->x + 3 * n);
                if (b->xref) move_point(pl, b->xref + 3 * n); /* a scaled mesh's reference */
            }
        for (int ip = 0; ip < b->npart; ip++)
            if (pl->moved >= 0 && p.grp[ip] == pl->moved)
                rotate_vec(pl, b->part[ip].material.fabric_direction);
    }
    free(p.grp), free(ngrp), free(npart_of);
    return st;
}

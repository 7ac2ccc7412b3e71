/* fe_joint.c: joints, nodal rigid bodies and extra nodes: the builder's lists and the model's
 * joints with their penalty stiffnesses (fe_joint.h). The time loop is fe_joint_step.c. */
#include "fe/fe_joint.h"
#include "fe/fe_builder_impl.h"
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const fe_joint_type_name[4] = {"spherical", "revolute", "cylindrical", "translational"};

typedef struct {
    char name[FE_NAME_MAX]; /* nodal rigid body, or the rigid part of extra nodes */
    int extra;              /* 1: extra nodes of a rigid part                     */
    int n;
    int *node;
} fe_nodeset;

struct fe_joint_list {
    int njoint, cap_joint;
    fe_joint_desc *joint;
    int nset, cap_set;
    fe_nodeset *set;
};

fe_joint_desc fe_joint_desc_default(void)
{
    fe_joint_desc d;
    memset(&d, 0, sizeof d);
    d.type = FE_JOINT_REVOLUTE;
    for (int i = 0; i < 6; i++)
        d.node[i] = -1;
    d.axis[2] = 1;
    return d;
}

static mcs_status list_get(fe_builder *b, mcs_error *err)
{
    if (!b->joints) b->joints = calloc(1, sizeof *b->joints);
    return b->joints ? MCS_OK : MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (joints)");
}

void fe_joint_list_free(fe_builder *b)
{
    if (!b->joints) return;
    for (int i = 0; i < b->joints->nset; i++)
        free(b->joints->set[i].node);
    free(b->joints->set);
    free(b->joints->joint);
    free(b->joints);
    b->joints = NULL;
}

/* "file:line:col: " of a descriptor, or "" */
static const char *where(const fe_joint_desc *d, char *buf, size_t n)
{
    if (d->file && d->line > 0 && d->col > 0)
        snprintf(buf, n, "%s:%d:%d: ", d->file, d->line, d->col);
    else if (d->file && d->line > 0)
        snprintf(buf, n, "%s:%d: ", d->file, d->line);
    else
        buf[0] = 0;
    return buf;
}

mcs_status fe_builder_add_joint(fe_builder *b, const fe_joint_desc *d, mcs_error *err)
{
    char at[512];
    where(d, at, sizeof at);
    if ((unsigned)d->type > FE_JOINT_TRANSLATIONAL)
        return MCS_ERR(err, MCS_ERR_RANGE, "%sfe: joint '%s': unknown type", at, d->name);
    if (!(d->stiffness >= 0) || !(d->damping >= 0) || !(d->penalty_scale >= 0) ||
        !isfinite(d->stiffness + d->damping + d->penalty_scale))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%sfe: joint '%s': stiffness, damping and penalty scale must be >= 0", at,
                       d->name);
    if (d->has_range && !(d->range[0] <= 0 && d->range[1] >= 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%sfe: joint '%s': range [%g, %g] must hold the start position 0", at,
                       d->name, d->range[0], d->range[1]);
    if (d->type == FE_JOINT_SPHERICAL && (d->stiffness > 0 || d->damping > 0 || d->has_range))
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                       "%sfe: joint '%s': a spherical joint takes no stiffness, damping or range",
                       at, d->name);
    if (d->node[0] < 0 && !d->body[0][0])
        return MCS_ERR(err, MCS_ERR_KEY, "%sfe: joint '%s': no body", at, d->name);
    mcs_status st = list_get(b, err);
    if (st) return st;
    struct fe_joint_list *l = b->joints;
    for (int i = 0; i < l->njoint; i++)
        if (!strcmp(l->joint[i].name, d->name))
            return MCS_ERR(err, MCS_ERR_KEY, "%sfe: joint '%s' given twice", at, d->name);
    if (l->njoint == l->cap_joint) {
        int cap = l->cap_joint ? 2 * l->cap_joint : 8;
        fe_joint_desc *p = realloc(l->joint, sizeof *p * (size_t)cap);
        if (!p) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (joints)");
        l->joint = p, l->cap_joint = cap;
    }
    l->joint[l->njoint++] = *d;
    return MCS_OK;
}

static mcs_status add_set(fe_builder *b, const char *name, int extra, const int *nodes, int n,
                          mcs_error *err)
{
    const char *what = extra ? "extra nodes of" : "nodal rigid body";
    if (n < 1) return MCS_ERR(err, MCS_ERR_RANGE, "fe: %s '%s': no nodes", what, name);
    for (int i = 0; i < n; i++)
        if (nodes[i] < 0 || nodes[i] >= b->nnode)
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: %s '%s': node index %d out of range", what,
                           name, nodes[i]);
    mcs_status st = list_get(b, err);
    if (st) return st;
    struct fe_joint_list *l = b->joints;
    if (!extra) {
        if (fe_builder_find_part(b, name) >= 0)
            return MCS_ERR(err, MCS_ERR_KEY, "fe: nodal rigid body '%s': a part has that name",
                           name);
        for (int i = 0; i < l->nset; i++)
            if (!l->set[i].extra && !strcmp(l->set[i].name, name))
                return MCS_ERR(err, MCS_ERR_KEY, "fe: nodal rigid body '%s' given twice", name);
    }
    if (l->nset == l->cap_set) {
        int cap = l->cap_set ? 2 * l->cap_set : 8;
        fe_nodeset *p = realloc(l->set, sizeof *p * (size_t)cap);
        if (!p) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (node sets)");
        l->set = p, l->cap_set = cap;
    }
    fe_nodeset *s = &l->set[l->nset];
    memset(s, 0, sizeof *s);
    s->node = malloc(sizeof(int) * (size_t)n);
    if (!s->node) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (node sets)");
    memcpy(s->node, nodes, sizeof(int) * (size_t)n);
    snprintf(s->name, sizeof s->name, "%s", name);
    s->extra = extra, s->n = n;
    l->nset++;
    return MCS_OK;
}

mcs_status fe_builder_add_nodal_rigid_body(fe_builder *b, const char *name, const int *nodes, int n,
                                           mcs_error *err)
{
    return add_set(b, name, 0, nodes, n, err);
}

mcs_status fe_builder_add_extra_nodes(fe_builder *b, const char *part, const int *nodes, int n,
                                      mcs_error *err)
{
    int ip = fe_builder_find_part(b, part);
    if (ip < 0) return MCS_ERR(err, MCS_ERR_KEY, "fe: extra nodes: unknown part '%s'", part);
    if (!fe_builder_part_rigid(b, ip))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: extra nodes: part '%s' is not rigid", part);
    return add_set(b, part, 1, nodes, n, err);
}

int fe_nrb_count(const fe_builder *b)
{
    int n = 0;
    for (int i = 0; b->joints && i < b->joints->nset; i++)
        n += !b->joints->set[i].extra;
    return n;
}

mcs_status fe_nrb_assign(const fe_builder *b, fe_model *m, int *nb, char (*names)[FE_NAME_MAX],
                         int cap, mcs_error *err)
{
    const struct fe_joint_list *l = b->joints;
    for (int i = 0; l && i < l->nset; i++) {
        const fe_nodeset *s = &l->set[i];
        int body;
        if (s->extra) {
            body = m->part[fe_builder_find_part(b, s->name)].body;
        } else {
            if (*nb >= cap) return MCS_ERR(err, MCS_ERR_RANGE, "fe: too many nodal rigid bodies");
            body = (*nb)++;
            snprintf(names[body], FE_NAME_MAX, "%s", s->name);
        }
        for (int j = 0; j < s->n; j++) {
            int n = s->node[j], *nbp = &m->node_body[n];
            if (*nbp >= 0 && *nbp != body)
                return MCS_ERR(err, MCS_ERR_RANGE,
                               "fe: node %d of %s '%s' already moves with another rigid body: "
                               "merge them",
                               n, s->extra ? "the extra nodes of" : "nodal rigid body", s->name);
            *nbp = body;
        }
    }
    return MCS_OK;
}

int fe_body_find(const fe_model *m, const char *name)
{
    for (int b = 0; b < m->nbody; b++)
        if (!strcmp(m->body[b].name, name)) return b;
    return -1;
}

const char *fe_body_name(const fe_model *m, int b)
{
    return b >= 0 && b < m->nbody ? m->body[b].name : "ground";
}

/* largest eigenvalue bound of a symmetric 3x3 (Gershgorin: exact for a diagonal one) */
static double eig_bound(const double a[3][3])
{
    double r = 0;
    for (int i = 0; i < 3; i++) {
        double s = fabs(a[i][0]) + fabs(a[i][1]) + fabs(a[i][2]);
        if (s > r) r = s;
    }
    return r;
}

/* largest compliance of body b at offset r (t = 0 axes) to a force there:
 * max eig (1/M + S^T I^-1 S), S = skew(r); and to a moment in the plane normal to `ax` (NULL:
 * any moment): max eig (P I^-1 P), P = 1 - ax ax^T. Held dofs count 0. */
static double compliance(const fe_model *m, int b, const double r[3], const double *ax,
                         double *lam_rot)
{
    *lam_rot = 0;
    if (b < 0) return 0;
    const fe_body *B = &m->body[b];
    double K[3][3] = {{0}}, S[3][3] = {{0, -r[2], r[1]}, {r[2], 0, -r[0]}, {-r[1], r[0], 0}};
    double lt = (B->fix & FE_DOF_TRANS) == FE_DOF_TRANS ? 0 : 1 / B->mass;
    for (int i = 0; i < 3; i++)
        K[i][i] = lt;
    if (B->fix & FE_DOF_ROT) return eig_bound(K);
    double P[3][3], T[3][3] = {{0}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            P[i][j] = (i == j) - (ax ? ax[i] * ax[j] : 0);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double k = 0, t = 0;
            for (int p = 0; p < 3; p++)
                for (int q = 0; q < 3; q++) {
                    k += S[p][i] * B->inertia0_inv[p][q] * S[q][j];
                    t += P[i][p] * B->inertia0_inv[p][q] * P[q][j];
                }
            K[i][j] += k, T[i][j] = t;
        }
    *lam_rot = eig_bound(T);
    return eig_bound(K);
}

/* body of a descriptor's side i: by node or by name; -1 ground (side B only) */
static mcs_status joint_body(const fe_model *m, const fe_joint_desc *d, int i, int *out,
                             const char *at, mcs_error *err)
{
    if (d->node[0] >= 0) {
        int n = d->node[i];
        if (n < 0 || n >= m->nnode)
            return MCS_ERR(err, MCS_ERR_RANGE, "%sfe: joint '%s': node N%d missing", at, d->name,
                           i + 1);
        *out = m->node_body[n];
        /* N2 on no body but held in every translation: the ground (a deck mcrash wrote) */
        if (*out < 0 && i == 1 && (m->node_fix[n] & FE_DOF_TRANS) == FE_DOF_TRANS) return MCS_OK;
        if (*out < 0)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%sfe: joint '%s': node N%d is on no rigid part or nodal rigid body", at,
                           d->name, i + 1);
        return MCS_OK;
    }
    if (i == 1 && !d->body[1][0]) {
        *out = -1;
        return MCS_OK;
    }
    *out = fe_body_find(m, d->body[i]);
    if (*out < 0)
        return MCS_ERR(err, MCS_ERR_KEY,
                       "%sfe: joint '%s': '%s' is no rigid part or nodal rigid body", at, d->name,
                       d->body[i]);
    return MCS_OK;
}

/* point and axis of a node-defined joint: the mean of each node pair */
static mcs_status node_geometry(const fe_model *m, const fe_joint_desc *d, double p[3], double a[3],
                                const char *at, mcs_error *err)
{
    int need = 2;
    if (d->type != FE_JOINT_SPHERICAL) need = 4;
    for (int i = 0; i < need; i++)
        if (d->node[i] < 0 || d->node[i] >= m->nnode)
            return MCS_ERR(err, MCS_ERR_RANGE, "%sfe: joint '%s': node N%d missing", at, d->name,
                           i + 1);
    const double *x = m->node_x0;
    for (int k = 0; k < 3; k++) {
        p[k] = 0.5 * (x[3 * d->node[0] + k] + x[3 * d->node[1] + k]);
        a[k] = need == 4 ? 0.5 * (x[3 * d->node[2] + k] + x[3 * d->node[3] + k]) - p[k] : 0;
    }
    if (need == 2) a[2] = 1;
    return MCS_OK;
}

static mcs_status build_one(const fe_model *m, const fe_joint_desc *d, fe_joint *J, mcs_error *err)
{
    char at[512];
    where(d, at, sizeof at);
    memset(J, 0, sizeof *J);
    snprintf(J->name, sizeof J->name, "%s", d->name);
    J->type = d->type;
    mcs_status st = joint_body(m, d, 0, &J->body[0], at, err);
    if (!st) st = joint_body(m, d, 1, &J->body[1], at, err);
    if (st) return st;
    if (J->body[0] == J->body[1])
        return MCS_ERR(err, MCS_ERR_RANGE, "%sfe: joint '%s' joins '%s' to itself", at, d->name,
                       fe_body_name(m, J->body[0]));
    double p[3], a[3];
    memcpy(p, d->point, sizeof p), memcpy(a, d->axis, sizeof a);
    if (d->node[0] >= 0 && (st = node_geometry(m, d, p, a, at, err))) return st;
    double na = sqrt(fe_dot(a, a));
    if (!(na > 0) || !isfinite(na + p[0] + p[1] + p[2]))
        return MCS_ERR(err, MCS_ERR_RANGE, "%sfe: joint '%s': axis of zero length", at, d->name);
    for (int k = 0; k < 3; k++)
        J->axis[k] = a[k] / na;
    /* a normal to the axis: the axis crossed with the world axis least along it */
    int lo = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(J->axis[k]) < fabs(J->axis[lo])) lo = k;
    double e[3] = {0, 0, 0};
    e[lo] = 1;
    fe_cross(J->axis, e, J->perp);
    double np = sqrt(fe_dot(J->perp, J->perp));
    for (int k = 0; k < 3; k++)
        J->perp[k] /= np;
    double lam = 0, lamr = 0;
    for (int i = 0; i < 2; i++) {
        int b = J->body[i];
        for (int k = 0; k < 3; k++)
            J->r[i][k] = p[k] - (b >= 0 ? m->body[b].x0[k] : 0);
        double lr;
        const double *ax =
            d->type == FE_JOINT_REVOLUTE || d->type == FE_JOINT_CYLINDRICAL ? J->axis : NULL;
        lam += compliance(m, b, J->r[i], ax, &lr);
        lamr += lr;
    }
    const double dt = m->dt_initial, sc = d->penalty_scale > 0 ? d->penalty_scale : 0.1;
    const double zeta = 0.1;
    if (!(lam > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "%sfe: joint '%s': both bodies are held", at, d->name);
    J->scale = sc;
    J->k = sc / (dt * dt * lam);
    J->c = 2 * zeta * sqrt(J->k / lam);
    J->kr = lamr > 0 ? sc / (dt * dt * lamr) : 0;
    J->cr = lamr > 0 ? 2 * zeta * sqrt(J->kr / lamr) : 0;
    J->ks = d->stiffness, J->cs = d->damping;
    J->has_range = d->has_range;
    memcpy(J->range, d->range, sizeof J->range);
    const int slide = d->type == FE_JOINT_CYLINDRICAL || d->type == FE_JOINT_TRANSLATIONAL;
    J->kstop = 0.1 * (slide ? J->k : J->kr); /* a softer stop: ~30 steps of contact */
    /* the free coordinate's spring and damper must not limit the step */
    double lq = slide ? lam : lamr;
    if (J->ks * lq * dt * dt > 1 || J->cs * lq * dt > 1)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%sfe: joint '%s': stiffness %g or damping %g too high for the step "
                       "%.3g s (at most %.3g and %.3g)",
                       at, d->name, J->ks, J->cs, dt, 1 / (lq * dt * dt), 1 / (lq * dt));
    return MCS_OK;
}

mcs_status fe_joints_build(const fe_builder *b, fe_model *m, mcs_error *err)
{
    const struct fe_joint_list *l = b->joints;
    if (!l || l->njoint == 0) return MCS_OK;
    m->joint = calloc((size_t)l->njoint, sizeof *m->joint);
    if (!m->joint) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (joints)");
    m->njoint = l->njoint;
    m->bytes += sizeof *m->joint * (size_t)l->njoint;
    for (int j = 0; j < l->njoint; j++) {
        mcs_status st = build_one(m, &l->joint[j], &m->joint[j], err);
        if (st) return st;
    }
    return MCS_OK;
}

/* mb_couple_contact.c: FE nodes against stage-1 bodies' surfaces (mb_couple_contact.h).
 *
 * Motion over the ODE step t0 -> t1 = t0 + h: each surface's reference point (an ellipsoid's
 * centre, a facet mesh's body CG) moves on the straight line between its world positions at
 * t0 and t1, as the attached nodes do; the body's orientation turns at a constant angular
 * velocity from q0 to q1 (spherical linear interpolation: q(tau) = q0 exp(tau log(q0^-1 q1)),
 * omega = R0 theta / h with theta the body-frame rotation vector of q0^-1 q1), and the
 * surface's rotation is the body's times its own (ellipsoid axes). The kernel's force of the
 * structure on a surface at t_j, times the step's dth, is summed per body as an impulse at
 * the CG and a moment about it (the kernel's moment about the surface's reference point plus
 * (reference point - CG) x force, both at tau_j). */
#include "stage1_mb/mb_couple_contact.h"
#include "stage1_mb/mb_prescribe.h"
#include "fe/fe_contact.h"
#include "fe/fe_state.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_pt.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int facets;  /* 1: kernel facet surface, 0: kernel ellipsoid              */
    int index;   /* its index in the kernel                                  */
    int body;    /* slot in the contact's body list (cb)                      */
    int surf;    /* stage-1 surface                                          */
    int contact; /* the bodies contact it belongs to                        */
} cc_surf;

struct mb_couple_contact {
    int nsurf, cap;
    cc_surf *s;
    int nbody; /* bodies any surface belongs to [-]                        */
    int *body; /* their mb body index (nbody)                              */
    int ncontact;
    char (*name)[FE_NAME_MAX];  /* each bodies contact's name (ncontact)     */
    char (*label)[FE_NAME_MAX]; /* its name if given, else its parts joined by '+' (ncontact) */
    char (*part0)[FE_NAME_MAX]; /* its first part (ncontact)                 */
};

struct mb_couple_contact_state {
    double *x0, *q0, *x1,
        *q1;             /* CG [m] and quaternion at the step's start and end (nbody x 3, 4) */
    double *th;          /* body-frame rotation vector of q0^-1 q1 (nbody x 3) [rad]  */
    double *imp;         /* force and moment impulse this step (nbody x 6) [N s, N m s] */
    double *fmean;       /* last step's mean force and moment (nbody x 6)             */
    double *force;       /* applied in the next ODE step (nbody x 6) [N, N m]         */
    double *jfe, *jbody; /* impulse so far the structure gave / the bodies received
                            (nbody x 6) [N s, N m s]                                  */
    double *simp, *sfmean, *sforce; /* imp, fmean, force per kernel surface (nsurf x 6): a
                                       body's are their sums (mb_egroup.c splits by them) */
};

/* ---- building --------------------------------------------------------------------------- */

static int body_slot(mb_couple_contact *c, int b)
{
    for (int i = 0; i < c->nbody; i++)
        if (c->body[i] == b) return i;
    int *nb = realloc(c->body, sizeof(int) * (size_t)(c->nbody + 1));
    if (!nb) return -1;
    c->body = nb;
    c->body[c->nbody] = b;
    return c->nbody++;
}

static int push_surf(mb_couple_contact *c, cc_surf v)
{
    if (c->nsurf == c->cap) {
        int cap = c->cap ? 2 * c->cap : 8;
        cc_surf *ns = realloc(c->s, sizeof *ns * (size_t)cap);
        if (!ns) return -1;
        c->s = ns, c->cap = cap;
    }
    c->s[c->nsurf++] = v;
    return 0;
}

/* one kernel surface for stage-1 surface k of body b, in contact `name` with parts */
static mcs_status add_surface(fe_builder *fb, const mb_model *m, int k, const char *name,
                              const char (*parts)[FE_NAME_MAX], int nparts, double mu, double scale,
                              const fe_body_law_desc *law, int *kind, mcs_error *err)
{
    const mb_surface *sf = &m->surf[k];
    const mb_body_desc *d = &m->body[sf->body];
    double q[4], R[9];
    mb_quat_unit(d->quat, q);
    mb_quat_to_rot(q, R);
    char nm[FE_NAME_MAX];
    snprintf(nm, sizeof nm, "%.20s:%.41s", name, sf->name);
    if (sf->type == MB_SURF_ELLIPSOID) {
        fe_ellipsoid_desc e;
        memset(&e, 0, sizeof e);
        memcpy(e.name, nm, sizeof nm);
        double c[3];
        mb_mat_vec(R, sf->center, c);
        for (int i = 0; i < 3; i++)
            e.center[i] = d->pos[i] + c[i];
        memcpy(e.semi_axes, sf->semi, sizeof e.semi_axes);
        e.penalty_scale = scale, e.friction = mu, e.nparts = nparts, e.law = *law;
        memcpy(e.parts, parts, sizeof(e.parts[0]) * (size_t)nparts);
        *kind = 0;
        return fe_builder_add_ellipsoid(fb, &e, err); /* pose set every subcycle */
    }
    if (law->n > 0)
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                       "body_characteristic: on ellipsoid surfaces only ('%s' is a facet mesh)",
                       sf->name);
    fe_facet_desc f;
    memset(&f, 0, sizeof f);
    memcpy(f.name, nm, sizeof nm);
    memcpy(f.center, d->pos, sizeof f.center);
    memcpy(f.orientation, q, sizeof f.orientation);
    f.vert = mb_mesh_vert(sf->mesh, &f.nvert);
    f.tri = mb_mesh_tri(sf->mesh);
    f.ntri = mb_mesh_ntri(sf->mesh);
    f.penalty_scale = scale, f.friction = mu, f.nparts = nparts;
    memcpy(f.parts, parts, sizeof(f.parts[0]) * (size_t)nparts);
    *kind = 1;
    return fe_builder_add_facets(fb, &f, err);
}

/* keys a bodies contact does not take (they belong to the segment contacts) */
static const char *const unsupported_keys[] = {"friction_dynamic", "friction_decay",
                                               "thickness_scale", "fabric_thickness", NULL};

/* the label and first part of the contact about to be added (cc->ncontact) */
static int label_contact(mb_couple_contact *cc, const char *nm, char (*parts)[FE_NAME_MAX], int np)
{
    const size_t n = (size_t)cc->ncontact + 1;
    char(*nl)[FE_NAME_MAX] = realloc(cc->label, sizeof *nl * n);
    if (nl) cc->label = nl;
    char(*np0)[FE_NAME_MAX] = realloc(cc->part0, sizeof *np0 * n);
    if (np0) cc->part0 = np0;
    if (!nl || !np0) return -1;
    char *l = cc->label[cc->ncontact];
    snprintf(l, FE_NAME_MAX, "%.63s", nm ? nm : "");
    for (int i = 0; !nm && i < np; i++) {
        size_t k = strlen(l);
        if (k + 2 < FE_NAME_MAX)
            snprintf(l + k, FE_NAME_MAX - k, "%s%.62s", i ? "+" : "", parts[i]);
    }
    snprintf(cc->part0[cc->ncontact], FE_NAME_MAX, "%.63s", np > 0 ? parts[0] : "");
    return 0;
}

/* body_characteristic: the bodies' surface compliance in series (docs/contracts.md "Soft body
 * surfaces in bodies contacts"), inline or the name of one of fe.body_characteristics */
static mcs_status body_law(const mcs_node *fe, const mcs_node *n, fe_body_law_desc *law,
                           mcs_error *err)
{
    memset(law, 0, sizeof *law);
    if (mcs_node_kind(n) == MCS_NODE_NULL) return MCS_OK;
    if (mcs_node_kind(n) == MCS_NODE_STR) {
        const mcs_node *named =
            mcs_node_get(mcs_node_get(fe, "body_characteristics"), mcs_node_str(n));
        if (!named) return mcs_node_error(n, err, MCS_ERR_KEY, "unknown body characteristic");
        n = named;
    }
    const mcs_node *c = mcs_node_get(n, "stress");
    const int len = mcs_node_curve_len(c);
    if (len < 2 || len > FE_BODY_LAW_PTS)
        return mcs_node_error(c, err, MCS_ERR_RANGE, "2 to %d points", FE_BODY_LAW_PTS);
    mcs_status st = mcs_node_curve(c, law->x, law->y, len, err);
    if (st) return st;
    law->n = len;
    law->unload_slope = mcs_node_num_or(n, "unloading_slope", 0);
    law->elastic_limit = mcs_node_num_or(n, "elastic_limit", 0);
    return MCS_OK;
}

static mcs_status add_contact(fe_builder *fb, mb_model *m, mb_couple_contact *cc,
                              const mcs_node *fe, const mcs_node *n, int index, mcs_error *err)
{
    for (int i = 0; unsupported_keys[i]; i++)
        if (mcs_node_kind(mcs_node_get(n, unsupported_keys[i])) != MCS_NODE_NULL)
            return mcs_node_error(mcs_node_get(n, unsupported_keys[i]), err, MCS_ERR_UNSUPPORTED,
                                  "not taken by a bodies contact");
    char name[FE_NAME_MAX];
    const char *nm = mcs_node_str(mcs_node_get(n, "name"));
    snprintf(name, sizeof name, "%s", nm ? nm : "");
    if (!nm) snprintf(name, sizeof name, "contact%d", index);
    const mcs_node *pl = mcs_node_get(n, "parts"), *bl = mcs_node_get(n, "bodies");
    char parts[FE_CONTACT_PARTS][FE_NAME_MAX];
    int np = mcs_node_len(pl);
    if (np > FE_CONTACT_PARTS)
        return mcs_node_error(pl, err, MCS_ERR_RANGE, "at most %d parts", FE_CONTACT_PARTS);
    for (int i = 0; i < np; i++)
        snprintf(parts[i], FE_NAME_MAX, "%s", mcs_node_str(mcs_node_at(pl, i)));
    char(*nn)[FE_NAME_MAX] = realloc(cc->name, sizeof *nn * (size_t)(cc->ncontact + 1));
    if (!nn) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    cc->name = nn;
    if (label_contact(cc, nm, parts, np))
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    memcpy(cc->name[cc->ncontact++], name, FE_NAME_MAX);
    const double mu = mcs_node_num_or(n, "friction", 0);
    const double scale = mcs_node_num_or(n, "penalty_scale", 0);
    fe_body_law_desc law;
    mcs_status lst = body_law(fe, mcs_node_get(n, "body_characteristic"), &law, err);
    if (lst) return lst;
    for (int j = 0; j < mcs_node_len(bl); j++) {
        const mcs_node *bn = mcs_node_at(bl, j);
        const int b = mb_model_body(m, mcs_node_str(bn));
        if (b < 0) return mcs_node_error(bn, err, MCS_ERR_KEY, "no body of that name");
        const int slot = body_slot(cc, b);
        if (slot < 0) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
        int found = 0;
        for (int k = 0; k < m->nsurf; k++) {
            const mb_surface *sf = &m->surf[k];
            if (sf->body != b || (sf->type != MB_SURF_ELLIPSOID && sf->type != MB_SURF_FACET))
                continue;
            mcs_error kerr = {0};
            int kind = 0;
            mcs_status st = add_surface(fb, m, k, name, parts, np, mu, scale, &law, &kind, &kerr);
            if (st) return mcs_node_error(bn, err, st, "%s", kerr.msg);
            cc_surf v = {kind, -1, slot, k, cc->ncontact - 1}; /* index: set below */
            if (push_surf(cc, v)) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
            found = 1;
        }
        if (!found)
            return mcs_node_error(bn, err, MCS_ERR_KEY,
                                  "body '%s' has no ellipsoid or facet surfaces to meet",
                                  mcs_node_str(bn));
    }
    return MCS_OK;
}

mcs_status mb_couple_contact_add(fe_builder *fb, const mcs_node *fe, void *ctx, mcs_error *err)
{
    mb_model *m = ctx;
    const mcs_node *list = mcs_node_get(fe, "contacts");
    mb_couple_contact *cc = NULL;
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *n = mcs_node_at(list, i);
        const char *type = mcs_node_str(mcs_node_get(n, "type"));
        if (!type || strcmp(type, "bodies") != 0) continue;
        if (!cc) {
            cc = calloc(1, sizeof *cc);
            if (!cc) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
            m->couple->contact = cc;
        }
        mcs_status st = add_contact(fb, m, cc, fe, n, i, err);
        if (st) return st;
    }
    if (!cc) return MCS_OK;
    /* kernel indices: the scenario's own rigid ellipsoids come first, then ours in order */
    int ne = 0, nf = 0;
    for (int k = 0; k < cc->nsurf; k++)
        ne += !cc->s[k].facets, nf += cc->s[k].facets;
    int e0 = fe_builder_nellipsoid(fb) - ne, f0 = fe_builder_nfacets(fb) - nf;
    for (int k = 0; k < cc->nsurf; k++)
        cc->s[k].index = cc->s[k].facets ? f0++ : e0++;
    return MCS_OK;
}

void mb_couple_contact_destroy(mb_couple_contact **p)
{
    mb_couple_contact *c = p ? *p : NULL;
    if (!c) return;
    free(c->s), free(c->body), free(c->name), free(c->label), free(c->part0), free(c);
    *p = NULL;
}

mcs_status mb_couple_contact_state_create(const mb_couple_contact *c, mb_couple_contact_state **out,
                                          mcs_error *err)
{
    *out = NULL;
    mb_couple_contact_state *s = calloc(1, sizeof *s);
    const size_t n = (size_t)(c->nbody ? c->nbody : 1);
    if (s) {
        s->x0 = calloc(3 * n, sizeof(double)), s->x1 = calloc(3 * n, sizeof(double));
        s->q0 = calloc(4 * n, sizeof(double)), s->q1 = calloc(4 * n, sizeof(double));
        s->th = calloc(3 * n, sizeof(double)), s->imp = calloc(6 * n, sizeof(double));
        s->fmean = calloc(6 * n, sizeof(double)), s->force = calloc(6 * n, sizeof(double));
        s->jfe = calloc(6 * n, sizeof(double)), s->jbody = calloc(6 * n, sizeof(double));
        const size_t ns = (size_t)(c->nsurf ? c->nsurf : 1);
        s->simp = calloc(6 * ns, sizeof(double)), s->sfmean = calloc(6 * ns, sizeof(double));
        s->sforce = calloc(6 * ns, sizeof(double));
    }
    if (!s || !s->x0 || !s->x1 || !s->q0 || !s->q1 || !s->th || !s->imp || !s->fmean || !s->force ||
        !s->jfe || !s->jbody || !s->simp || !s->sfmean || !s->sforce) {
        mb_couple_contact_state_destroy(&s);
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    }
    *out = s;
    return MCS_OK;
}

void mb_couple_contact_state_destroy(mb_couple_contact_state **p)
{
    mb_couple_contact_state *s = p ? *p : NULL;
    if (!s) return;
    free(s->x0), free(s->x1), free(s->q0), free(s->q1), free(s->th), free(s->imp);
    free(s->fmean), free(s->force), free(s->jfe), free(s->jbody);
    free(s->simp), free(s->sfmean), free(s->sforce), free(s);
    *p = NULL;
}

/* ---- quaternions (w, x, y, z) ------------------------------------------------------------ */

static void quat_mul(const double a[4], const double b[4], double o[4])
{
    o[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    o[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    o[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    o[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* rotation vector of unit quaternion q (the shorter way round) [rad] */
static void quat_log(const double q[4], double th[3])
{
    double sg = q[0] < 0 ? -1 : 1, s = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    double ang = 2 * atan2(s, sg * q[0]), f = s > 1e-300 ? sg * ang / s : 2 * sg;
    for (int i = 0; i < 3; i++)
        th[i] = f * q[i + 1];
}

static void quat_exp(const double th[3], double q[4])
{
    double a = mb_norm(th), s = a > 1e-300 ? sin(0.5 * a) / a : 0.5;
    q[0] = cos(0.5 * a);
    for (int i = 0; i < 3; i++)
        q[i + 1] = s * th[i];
}

/* ---- the step ---------------------------------------------------------------------------- */

static void body_pose(const mb_state *s, int b, double x[3], double q[4])
{
    mb_body_kin k;
    mb_body_get(s->world, b, &k);
    mb_copy(k.pos, x);
    memcpy(q, k.quat, sizeof k.quat);
}

void mb_couple_contact_apply(const mb_model *m, mb_state *s)
{
    const mb_couple_contact *c = m->couple->contact;
    mb_couple_contact_state *cs = s->couple->contact;
    for (int i = 0; i < c->nbody; i++) {
        body_pose(s, c->body[i], cs->x0 + 3 * i, cs->q0 + 4 * i);
        for (int k = 0; k < 6; k++)
            cs->jbody[6 * i + k] += m->h * cs->force[6 * i + k];
        mb_body_add_force(s->world, c->body[i], cs->force + 6 * i);
        mb_body_add_torque(s->world, c->body[i], cs->force + 6 * i + 3);
    }
}

void mb_couple_contact_begin(const mb_model *m, mb_state *s)
{
    const mb_couple_contact *c = m->couple->contact;
    mb_couple_contact_state *cs = s->couple->contact;
    for (int i = 0; i < c->nbody; i++) {
        double *q0 = cs->q0 + 4 * i, *q1 = cs->q1 + 4 * i, iq[4] = {q0[0], -q0[1], -q0[2], -q0[3]};
        double dq[4];
        body_pose(s, c->body[i], cs->x1 + 3 * i, q1);
        quat_mul(iq, q1, dq);
        quat_log(dq, cs->th + 3 * i);
    }
    memset(cs->imp, 0, 6 * (size_t)c->nbody * sizeof(double));
    memset(cs->simp, 0, 6 * (size_t)c->nsurf * sizeof(double));
}

/* body slot i at fraction tau: CG, rotation; world angular velocity over the step */
static void pose_at(const mb_couple_contact_state *cs, int i, double tau, double h, double x[3],
                    double R[9], double w[3])
{
    const double *x0 = cs->x0 + 3 * i, *x1 = cs->x1 + 3 * i, *q0 = cs->q0 + 4 * i;
    double th[3], dq[4], q[4], R0[9];
    for (int k = 0; k < 3; k++)
        x[k] = x0[k] + tau * (x1[k] - x0[k]), th[k] = tau * cs->th[3 * i + k];
    quat_exp(th, dq);
    quat_mul(q0, dq, q);
    mb_quat_to_rot(q, R);
    mb_quat_to_rot(q0, R0);
    mb_mat_vec(R0, cs->th + 3 * i, w);
    for (int k = 0; k < 3; k++)
        w[k] /= h;
}

/* surface k's reference point at fraction tau and its velocity over the step */
static void surf_point(const mb_model *m, const mb_couple_contact_state *cs, const cc_surf *v,
                       double tau, double h, double c[3], double vel[3])
{
    const mb_surface *sf = &m->surf[v->surf];
    const int i = v->body;
    double R0[9], R1[9], a[3], b[3];
    mb_quat_to_rot(cs->q0 + 4 * i, R0);
    mb_quat_to_rot(cs->q1 + 4 * i, R1);
    const double z[3] = {0, 0, 0};
    const double *off = v->facets ? z : sf->center;
    mb_mat_vec(R0, off, a);
    mb_mat_vec(R1, off, b);
    for (int k = 0; k < 3; k++) {
        double p0 = cs->x0[3 * i + k] + a[k], p1 = cs->x1[3 * i + k] + b[k];
        c[k] = p0 + tau * (p1 - p0);
        vel[k] = (p1 - p0) / h;
    }
}

void mb_couple_contact_pose(const mb_model *m, mb_state *s, double tau, double h)
{
    const mb_couple_contact *c = m->couple->contact;
    mb_couple_contact_state *cs = s->couple->contact;
    const fe_model *fm = m->couple->fe.model;
    fe_state *f = s->couple->fe;
    for (int k = 0; k < c->nsurf; k++) {
        const cc_surf *v = &c->s[k];
        double x[3], R[9], w[3], cp[3], vel[3];
        pose_at(cs, v->body, tau, h, x, R, w);
        surf_point(m, cs, v, tau, h, cp, vel);
        if (v->facets) {
            fe_contact_set_facets(fm, f, v->index, cp, R, vel, w);
        } else {
            double Re[9];
            mb_mat_mul(R, m->surf[v->surf].rot, Re); /* ellipsoid axes -> world */
            fe_contact_set_ellipsoid(fm, f, v->index, cp, Re, vel, w);
        }
    }
}

void mb_couple_contact_sum(const mb_model *m, mb_state *s, double tau, double dth)
{
    const mb_couple_contact *c = m->couple->contact;
    mb_couple_contact_state *cs = s->couple->contact;
    const fe_contact_state *ks = s->couple->fe->contact;
    for (int k = 0; k < c->nsurf; k++) {
        const cc_surf *v = &c->s[k];
        const double *F = (v->facets ? ks->fac_force : ks->ell_force) + 3 * v->index;
        const double *M = (v->facets ? ks->fac_moment : ks->ell_moment) + 3 * v->index;
        if (F[0] == 0 && F[1] == 0 && F[2] == 0 && M[0] == 0 && M[1] == 0 && M[2] == 0) continue;
        /* the moment about the CG at the forces' time (tau): reference point - CG cross F */
        double x[3], r[3], mc[3];
        const int i = v->body;
        for (int j = 0; j < 3; j++)
            x[j] = cs->x0[3 * i + j] + tau * (cs->x1[3 * i + j] - cs->x0[3 * i + j]);
        double cp[3], vel[3];
        surf_point(m, cs, v, tau, 1, cp, vel);
        mb_sub(cp, x, r);
        mb_cross(r, F, mc);
        double *imp = cs->imp + 6 * i, *si = cs->simp + 6 * k;
        for (int j = 0; j < 3; j++) {
            imp[j] += F[j] * dth;
            imp[3 + j] += (M[j] + mc[j]) * dth;
            si[j] += F[j] * dth;
            si[3 + j] += (M[j] + mc[j]) * dth;
        }
    }
}

void mb_couple_contact_end(const mb_model *m, mb_state *s, double h, double alpha, int started)
{
    const mb_couple_contact *c = m->couple->contact;
    mb_couple_contact_state *cs = s->couple->contact;
    mb_couple_mean_force(6 * c->nbody, cs->imp, 1, h, alpha, started, cs->fmean, cs->force);
    mb_couple_mean_force(6 * c->nsurf, cs->simp, 1, h, alpha, started, cs->sfmean, cs->sforce);
    for (int i = 0; i < 6 * c->nbody; i++)
        cs->jfe[i] += cs->imp[i];
    for (int i = 0; i < c->nbody; i++) {
        mb_copy(cs->x1 + 3 * i, cs->x0 + 3 * i);
        memcpy(cs->q0 + 4 * i, cs->q1 + 4 * i, 4 * sizeof(double));
    }
}

/* the work of the bodies' surfaces on the FE nodes so far, of every surface or of those on
 * prescribed bodies only [J] */
static double surf_work(const mb_model *m, const mb_state *s, int prescribed_only)
{
    const mb_couple_contact *c = m->couple->contact;
    const fe_contact_state *ks = s->couple->fe->contact;
    double w = 0;
    for (int k = 0; k < c->nsurf; k++) {
        const cc_surf *v = &c->s[k];
        if (!prescribed_only || mb_body_prescribed(m, c->body[v->body]))
            w += (v->facets ? ks->fac_work : ks->ell_work)[v->index];
    }
    return w;
}

double mb_couple_contact_work(const mb_model *m, const mb_state *s)
{
    return surf_work(m, s, 0);
}

double mb_couple_contact_work_prescribed(const mb_model *m, const mb_state *s)
{
    return surf_work(m, s, 1);
}

int mb_couple_contact_impulse(const mb_model *m, const mb_state *s, int body, double fe[6],
                              double onbody[6])
{
    const mb_couple_contact *c = m->couple ? m->couple->contact : NULL;
    for (int i = 0; c && i < c->nbody; i++)
        if (c->body[i] == body) {
            memcpy(fe, s->couple->contact->jfe + 6 * i, 6 * sizeof(double));
            memcpy(onbody, s->couple->contact->jbody + 6 * i, 6 * sizeof(double));
            return 0;
        }
    return -1;
}

int mb_couple_contact_find(const mb_model *m, const char *name)
{
    const mb_couple_contact *c = m->couple ? m->couple->contact : NULL;
    for (int k = 0; c && name && k < c->ncontact; k++)
        if (strcmp(c->name[k], name) == 0) return k;
    return -1;
}

void mb_couple_contact_force(const mb_model *m, const mb_state *s, int k, double f[3])
{
    const mb_couple_contact *c = m->couple->contact;
    const fe_contact_state *ks = s->couple->fe->contact;
    f[0] = f[1] = f[2] = 0;
    for (int i = 0; i < c->nsurf; i++) {
        const cc_surf *v = &c->s[i];
        if (v->contact != k) continue;
        const double *F = (v->facets ? ks->fac_force : ks->ell_force) + 3 * v->index;
        for (int j = 0; j < 3; j++)
            f[j] += F[j];
    }
}

int mb_couple_contact_nsurf(const mb_model *m)
{
    const mb_couple_contact *c = m->couple ? m->couple->contact : NULL;
    return c ? c->nsurf : 0;
}

int mb_couple_contact_surf(const mb_model *m, int k, int *contact)
{
    const mb_couple_contact *c = m->couple->contact;
    *contact = c->s[k].contact;
    return c->body[c->s[k].body];
}

double mb_couple_contact_surf_work(const mb_model *m, const mb_state *s, int k)
{
    const cc_surf *v = &m->couple->contact->s[k];
    const fe_contact_state *ks = s->couple->fe->contact;
    return (v->facets ? ks->fac_work : ks->ell_work)[v->index];
}

const char *mb_couple_contact_label(const mb_model *m, int k, const char **part0)
{
    const mb_couple_contact *c = m->couple->contact;
    *part0 = c->part0[k];
    return c->label[k];
}

const double *mb_couple_contact_surf_force(const mb_model *m, const mb_state *s, int k)
{
    (void)m;
    return s->couple->contact->sforce + 6 * k;
}

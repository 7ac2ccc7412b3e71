/* mb_couple.c: FE parts coupled to stage-1 bodies (mb_couple.h). Scheme (docs/stage1_engine.md
 * "Coupling to FE parts"): the ODE step t -> t + h takes, at each attached node, minus the
 * constraint force of the FE subcycle before it (its mean, centred at t - h/2, extrapolated
 * linearly to t from the subcycle before; the impulses telescope); then the FE
 * subcycles from t to t + h in k = ceil(h / dt_stable) equal steps, the attached nodes moving
 * on the straight line between their body points at t and t + h (velocity prescribed through
 * fe_state.node_vkin), and the constraint impulse r dth of every step is summed. */
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_rx.h"
#include "stage1_mb/mb_couple_contact.h"
#include "stage1_mb/mb_couple_pt.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_prescribe.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* impact group of a body by name for the FE placement (fe_scn_place): -1 unknown */
static int body_group(void *ctx, const char *name)
{
    const mb_model *m = ctx;
    int b = mb_model_body(m, name);
    return b < 0 ? -1 : m->body_group ? m->body_group[b] : MB_GROUP_NONE;
}

/* the velocity field v + w x r of body b at node n, into node_v0 (the fixed translations
 * too when all); with spin, a shell node's free rotations take w (node_w0) */
static void start_with_body(const mb_model *m, fe_model *fm, int b, int n, int all, int spin)
{
    const mb_body_desc *d = &m->body[b];
    double r[3], wr[3];
    for (int i = 0; i < 3; i++) r[i] = fm->node_x0[3 * n + i] - d->pos[i];
    mb_cross(d->angvel, r, wr);
    for (int i = 0; i < 3; i++) {
        if (all || !(fm->node_fix[n] & (1u << i))) fm->node_v0[3 * n + i] = d->vel[i] + wr[i];
        if (spin && fm->node_inertia[n] > 0 && !(fm->node_fix[n] & (8u << i)))
            fm->node_w0[3 * n + i] = d->angvel[i];
    }
}

/* the nodes of a part carried by a body start with the body's velocity field v + w x r
 * (attached nodes, and the rest of the part, whose fixed translations keep theirs); attached
 * nodes always do, with or without impact: (else the first subcycle jerks them to it: an
 * impulse m v on the body and a spurious energy loss) */
static void carried_velocities(const mb_model *m, mb_couple *c)
{
    fe_model *fm = c->fe.model;
    for (int a = 0; a < c->natt; a++) start_with_body(m, fm, c->body[a], c->node[a], 1, 0);
    if (!c->fe.part_carrier) return;
    unsigned char *att = calloc((size_t)fm->nnode + 1, 1);
    if (!att) return; /* only the start velocities of carried nodes are lost: never here */
    for (int a = 0; a < c->natt; a++) att[c->node[a]] = 1;
    for (int n = 0; n < fm->nnode; n++) {
        const int ip = fm->node_part[n];
        const mcs_node *bn = ip >= 0 ? c->fe.part_carrier[ip] : NULL;
        const int b = bn ? mb_model_body(m, mcs_node_str(bn)) : -1;
        if (b >= 0) start_with_body(m, fm, b, n, att[n], 1);
    }
    free(att);
}

mcs_status mb_couple_build(const mcs_scenario *scn, mb_model *m, mcs_error *err)
{
    const mcs_node *root = mcs_scenario_root(scn), *fe = mcs_node_get(root, "fe");
    if (mcs_node_kind(fe) != MCS_NODE_MAP) return MCS_OK;
    mb_couple *c = calloc(1, sizeof *c);
    if (!c) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    m->couple = c;
    /* with an impact: block, the parts carried by the bodies it placed move with them and
     * start with their velocity field (fe_scn_place); without, the parts start as the fe:
     * block puts them (initial_velocity, default at rest) */
    fe_scn_place pl = {.moved = MB_GROUP_MOTO, .group = body_group, .ctx = m};
    memcpy(pl.R, m->place_R, sizeof pl.R);
    memcpy(pl.t, m->place_t, sizeof pl.t);
    mcs_status st =
        fe_scn_build_with(scn, m->body_group ? &pl : NULL, mb_couple_contact_add, m, &c->fe, err);
    if (st) return st;
    /* one gravity for the bodies and the FE parts: stage 1's (environment.gravity, 9.81 m/s^2
     * by default, where stage 3 defaults to none) */
    for (int i = 0; i < 3; i++)
        c->fe.model->opts.gravity[i] = m->gravity[i];
    int n = c->natt = c->fe.natt;
    c->node = calloc((size_t)(n ? n : 1), sizeof *c->node);
    c->body = calloc((size_t)(n ? n : 1), sizeof *c->body);
    c->local = calloc((size_t)(n ? n : 1) * 3, sizeof *c->local);
    if (!c->node || !c->body || !c->local)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    const fe_model *fm = c->fe.model;
    /* local coordinates from the placed poses and nodes: the same as before the placement
     * (one rigid motion), to round-off */
    for (int a = 0; a < n; a++) {
        const mcs_node *bn = mcs_node_get(c->fe.att[a].attach, "body");
        int b = mb_model_body(m, mcs_node_str(bn));
        if (b < 0) return mcs_node_error(bn, err, MCS_ERR_KEY, "no body of that name");
        mb_couple_pt_local(&m->body[b], fm->node_x0 + 3 * c->fe.att[a].node, c->local + 3 * a);
        c->node[a] = c->fe.att[a].node;
        c->body[a] = b;
    }
    carried_velocities(m, c);
    return mb_couple_rx_build(scn, m, err); /* triggers, anchors on bodies */
}

void mb_couple_destroy(mb_couple **pc)
{
    mb_couple *c = pc ? *pc : NULL;
    if (!c) return;
    mb_couple_rx_destroy(&c->rx);
    fe_problem_free(&c->fe);
    mb_couple_contact_destroy(&c->contact);
    free(c->node), free(c->body), free(c->local);
    free(c);
    *pc = NULL;
}

mcs_status mb_couple_state_create(const mb_model *m, mb_couple_state **out, mcs_error *err)
{
    *out = NULL;
    const mb_couple *c = m->couple;
    mb_couple_state *cs = calloc(1, sizeof *cs);
    if (!cs) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    size_t na = (size_t)(c->natt ? c->natt : 1), nn = (size_t)c->fe.model->nnode;
    cs->vkin = calloc(3 * (nn ? nn : 1), sizeof *cs->vkin);
    cs->react = calloc(3 * (nn ? nn : 1), sizeof *cs->react);
    cs->imp = calloc(3 * na, sizeof *cs->imp);
    cs->force = calloc(3 * na, sizeof *cs->force);
    cs->xa = calloc(3 * na, sizeof *cs->xa);
    cs->vold = calloc(3 * na, sizeof *cs->vold);
    cs->fmean = calloc(3 * na, sizeof *cs->fmean);
    mcs_status st = MCS_OK;
    if (!cs->vkin || !cs->react || !cs->imp || !cs->force || !cs->xa || !cs->vold || !cs->fmean)
        st = MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    if (!st) st = fe_state_create(c->fe.model, &cs->fe, err);
    if (!st) st = mb_couple_rx_state_create(m, cs, err);
    if (!st && c->contact) st = mb_couple_contact_state_create(c->contact, &cs->contact, err);
    if (st) {
        mb_couple_state_destroy(&cs);
        return st;
    }
    memcpy(cs->vkin, c->fe.model->node_vfix, 3 * nn * sizeof *cs->vkin);
    cs->fe->node_vkin = cs->vkin;
    cs->fe->node_react = cs->react;
    *out = cs;
    return MCS_OK;
}

void mb_couple_state_destroy(mb_couple_state **p)
{
    mb_couple_state *cs = p ? *p : NULL;
    if (!cs) return;
    mb_couple_rx_state_destroy(&cs->rx);
    fe_state_destroy(&cs->fe);
    mb_couple_contact_state_destroy(&cs->contact);
    free(cs->vkin), free(cs->react), free(cs->imp), free(cs->force), free(cs->xa), free(cs->vold);
    free(cs->fmean);
    free(cs);
    *p = NULL;
}

void mb_couple_apply(const mb_model *m, mb_state *s)
{
    const mb_couple *c = m->couple;
    mb_couple_state *cs = s->couple;
    mb_couple_pt_apply(s, c->natt, c->body, c->local, cs->force, cs->xa);
    mb_couple_anchor_apply(m, s);
    if (c->contact) mb_couple_contact_apply(m, s);
}

mcs_status mb_couple_advance(const mb_model *m, mb_state *s, mcs_error *err)
{
    const mb_couple *c = m->couple;
    mb_couple_state *cs = s->couple;
    fe_state *f = cs->fe;
    const fe_model *fm = c->fe.model;
    const double t0 = f->time, t1 = s->t, h = t1 - t0;
    mb_couple_trigger_check(m, s); /* the contact forces of t fire inflators, retractors */
    mb_couple_anchor_begin(m, s);
    double *x1 = cs->force; /* scratch: body points at t + h, then the forces */
    for (int a = 0; a < c->natt; a++) {
        double x[3];
        mb_couple_pt_now(s, c->body[a], c->local + 3 * a, x);
        /* the body's work of the last forces over this step's displacement */
        for (int i = 0; i < 3; i++)
            cs->w_body += cs->force[3 * a + i] * (x[i] - cs->xa[3 * a + i]);
        mb_copy(x, x1 + 3 * a);
    }
    memset(cs->imp, 0, 3 * (size_t)c->natt * sizeof *cs->imp);
    if (c->contact) mb_couple_contact_begin(m, s);
    /* the impulses r dth of the FE steps at t_j span [t_j - dt_prev/2, t_j + dt/2] */
    const double i0 = f->time - 0.5 * f->dt_prev;
    while (f->time < t1 - 1e-12 * h) {
        double rem = t1 - f->time;
        long k = (long)ceil(rem / f->dt - 1e-9);
        double dt = rem / (double)(k > 0 ? k : 1), tau = (f->time + dt - t0) / h;
        f->dt = dt;
        for (int a = 0; a < c->natt; a++) { /* straight line from xa to x1 over the step */
            const int n = c->node[a];
            for (int i = 0; i < 3; i++) {
                double xt = cs->xa[3 * a + i] + tau * (x1[3 * a + i] - cs->xa[3 * a + i]);
                cs->vkin[3 * n + i] = (xt - f->node_x[3 * n + i]) / dt;
            }
        }
        const double dth = 0.5 * (dt + f->dt_prev), tau0 = (f->time - t0) / h;
        if (c->contact) mb_couple_contact_pose(m, s, tau0, h);
        double *vold = cs->vold;
        for (int a = 0; a < c->natt; a++)
            for (int i = 0; i < 3; i++)
                vold[3 * a + i] = f->node_v[3 * c->node[a] + i];
        mb_couple_anchor_move(m, s, (f->time - t0) / h); /* anchors on bodies at t_j */
        mcs_status st = fe_step(fm, f);
        if (st) {
            *err = f->err;
            return st;
        }
        mb_couple_anchor_collect(m, s, dth);
        cs->substeps++;
        if (c->contact) mb_couple_contact_sum(m, s, tau0, dth);
        for (int a = 0; a < c->natt; a++) {
            const int n = c->node[a];
            double w = 0;
            for (int i = 0; i < 3; i++) {
                double v0 = vold[3 * a + i], vn = f->node_v[3 * n + i];
                double r = cs->react[3 * n + i]; /* constraint force on the node (fe_integrate) */
                cs->imp[3 * a + i] += r * dth;
                w += r * dth * 0.5 * (v0 + vn);
            }
            cs->w_fe += w;
            if (mb_body_prescribed(m, c->body[a])) cs->w_fe_presc += w;
        }
    }
    /* the mean force is centred at tc (the impulses' interval, a half FE step before t + h/2):
     * extrapolated linearly to t + h from the subcycle before (second order in time; for
     * equal steps the impulses telescope) */
    const double tc = 0.5 * (i0 + f->time - 0.5 * f->dt_prev);
    const double alpha = cs->started ? (t1 - tc) / (tc - cs->tc) : 0;
    cs->tc = tc;
    memcpy(cs->xa, x1, 3 * (size_t)c->natt * sizeof *cs->xa);
    /* the reaction on the node loads the body with the opposite sign */
    mb_couple_mean_force(3 * c->natt, cs->imp, -1, h, alpha, cs->started, cs->fmean, cs->force);
    mb_couple_anchor_end(m, s, h, alpha, cs->started);
    if (c->contact) mb_couple_contact_end(m, s, h, alpha, cs->started);
    cs->started = 1;
    return MCS_OK;
}

double mb_couple_energy(const mb_model *m, const mb_state *s, double e[7])
{
    const mb_couple_state *cs = s->couple;
    const fe_state *f = cs->fe;
    const double *E = f->energy;
    e[0] = E[FE_E_kinetic];
    if (f->nstep == 0) { /* before the first FE step: the initial velocities' (carried parts) */
        const fe_model *fm = m->couple->fe.model;
        e[0] = 0;
        for (int n = 0; n < fm->nnode; n++) {
            const double *v = f->node_v + 3 * n, *w = f->node_w + 3 * n;
            e[0] += 0.5 * fm->node_mass[n] * mb_dot(v, v);
            e[0] += 0.5 * fm->node_inertia[n] * mb_dot(w, w);
        }
    }
    e[1] = E[FE_E_potential];
    e[2] = E[FE_E_internal] + E[FE_E_hourglass] + E[FE_E_eroded]; /* eroded: fe_stages.c */
    e[3] = E[FE_E_contact];
    e[4] = E[FE_E_dissipated];
    /* loads other than the bodies', and the retractors' on the bodies carrying their anchors */
    e[5] = E[FE_E_external_work] - cs->w_fe + cs->rx->w_anchor;
    if (m->couple->contact) e[5] -= mb_couple_contact_work(m, s); /* bodies' surfaces */
    e[6] = e[0] + e[1] + e[2] + e[3] + e[4] - e[5];
    return e[6];
}

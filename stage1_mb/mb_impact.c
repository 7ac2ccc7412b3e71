/* mb_impact.c: the impact: block -> placement and initial speeds of the motorcycle and opponent
 * groups of a built model (mb_impact.h). A rigid motion x' = R x + t of the motorcycle group,
 * R = Rz(psi) Rx(roll), then a Galilean boost of each group and the wheels' rolling spin. */
#include "stage1_mb/mb_impact.h"
#include "stage1_mb/mb_vec.h"

#include <fnmatch.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { G_NONE = MB_GROUP_NONE, G_MOTO = MB_GROUP_MOTO, G_OPP = MB_GROUP_OPP };

static const char *const default_moto[] = {"moto_*", "rider_*"};

/* 1 when name matches the patterns of g (a string or a list of strings) */
static int matches(const mcs_node *g, const char *name)
{
    if (mcs_node_kind(g) == MCS_NODE_STR) return fnmatch(mcs_node_str(g), name, 0) == 0;
    for (int i = 0; i < mcs_node_len(g); i++) {
        const char *p = mcs_node_str(mcs_node_at(g, i));
        if (p && fnmatch(p, name, 0) == 0) return 1;
    }
    return 0;
}

static void assign_groups(const mcs_node *imp, const mb_model *m, int *grp)
{
    const mcs_node *gm = mcs_node_get(imp, "motorcycle_bodies");
    const mcs_node *go = mcs_node_get(imp, "opponent_bodies");
    int has_m = mcs_node_kind(gm) != MCS_NODE_NULL, has_o = mcs_node_kind(go) != MCS_NODE_NULL;
    for (int b = 0; b < m->nbody; b++) {
        const char *nm = m->body_name[b];
        int moto =
            has_m ? matches(gm, nm)
                  : fnmatch(default_moto[0], nm, 0) == 0 || fnmatch(default_moto[1], nm, 0) == 0;
        grp[b] = moto ? G_MOTO : (!has_o || matches(go, nm)) ? G_OPP : G_NONE;
    }
}

/* q = a (x) b, quaternions w x y z */
static void quat_mul(const double a[4], const double b[4], double q[4])
{
    q[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    q[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    q[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    q[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

typedef struct {
    double R[9], q[4]; /* model -> world rotation, as a matrix and a quaternion */
    double t[3];       /* translation after the rotation [m] */
    double h_mc[3];    /* motorcycle heading, world (horizontal unit) */
    double h_op[3];    /* opponent heading, world (horizontal unit) */
    double v_mc, v_op; /* speeds along the headings [m/s] */
} plan;

static mcs_status make_plan(const mcs_node *imp, plan *p, mcs_error *err)
{
    double h[3] = {1, 0, 0};
    const mcs_node *hn = mcs_node_get(imp, "opponent_heading");
    if (mcs_node_kind(hn) == MCS_NODE_SEQ) {
        mcs_status st = mcs_node_vec3(hn, h, err);
        if (st) return st;
    }
    double psi_op = atan2(h[1], h[0]);
    double psi = psi_op + mcs_node_num_or(imp, "heading_angle", 0);
    double roll = mcs_node_num_or(imp, "roll_angle", 0);
    p->h_op[0] = cos(psi_op), p->h_op[1] = sin(psi_op), p->h_op[2] = 0;
    p->h_mc[0] = cos(psi), p->h_mc[1] = sin(psi), p->h_mc[2] = 0;
    p->v_mc = mcs_node_num_or(imp, "motorcycle_speed", 0);
    p->v_op = mcs_node_num_or(imp, "opponent_speed", 0);
    /* R = Rz(psi) Rx(roll); q = qz (x) qx */
    static const double ex[3] = {1, 0, 0}, ez[3] = {0, 0, 1};
    double Rx[9], Rz[9];
    mb_rot_axis_angle(ex, roll, Rx);
    mb_rot_axis_angle(ez, psi, Rz);
    mb_mat_mul(Rz, Rx, p->R);
    double qz[4] = {cos(psi / 2), 0, 0, sin(psi / 2)}, qx[4] = {cos(roll / 2), sin(roll / 2), 0, 0};
    quat_mul(qz, qx, p->q);
    p->t[0] = p->t[1] = p->t[2] = 0;
    const mcs_node *mcn = mcs_node_get(imp, "motorcycle_contact");
    if (mcs_node_kind(mcn) == MCS_NODE_SEQ) {
        double pm[3], po[3], rp[3];
        mcs_status st = mcs_node_vec3(mcn, pm, err);
        if (!st) st = mcs_node_vec3(mcs_node_get(imp, "opponent_contact"), po, err);
        if (st) return st;
        double gap = mcs_node_num_or(imp, "initial_gap", 0);
        mb_mat_vec(p->R, pm, rp);
        p->t[0] = po[0] - gap * p->h_mc[0] - rp[0];
        p->t[1] = po[1] - gap * p->h_mc[1] - rp[1];
        if (fabs(rp[2] - po[2]) > 1e-3)
            mcs_log(MCS_LOG_WARN,
                    "%s: impact: the contact points are %g m apart in height (the motorcycle "
                    "is not moved vertically)",
                    mcs_node_file(mcn), rp[2] - po[2]);
    }
    return MCS_OK;
}

/* the joints and attachments must not tie the motorcycle group to a body outside it; a moving
 * opponent must not be fixed to the ground */
static mcs_status check_ties(const mcs_node *root, const mcs_node *imp, const mb_model *m,
                             const int *grp, const plan *p, mcs_error *err)
{
    const mcs_node *jl = mcs_node_get(root, "joints"), *al = mcs_node_get(root, "attachments");
    for (int j = 0; j < m->njoint; j++) {
        const mb_joint_def *d = &m->joint[j];
        int gp = d->parent == MB_GROUND ? -1 : grp[d->parent], gc = grp[d->child];
        if ((gp == G_MOTO) != (gc == G_MOTO) && gp != -1)
            return mcs_node_error(mcs_node_at(jl, j), err, MCS_ERR_RANGE,
                                  "joint %s ties the motorcycle group to '%s' outside it; the "
                                  "impact placement moves the motorcycle group only",
                                  d->name, m->body_name[gp == G_MOTO ? d->child : d->parent]);
        if (p->v_op != 0 && gp == -1 && gc == G_OPP)
            return mcs_node_error(mcs_node_get(imp, "opponent_speed"), err, MCS_ERR_RANGE,
                                  "the opponent body '%s' is fixed to the ground by joint %s "
                                  "and cannot move",
                                  m->body_name[d->child], d->name);
    }
    for (int i = 0; i < m->nattach; i++) {
        const mb_attach_model *a = &m->attach[i];
        int ga = grp[a->body_a], gb = a->body_b == MB_GROUND ? -1 : grp[a->body_b];
        if ((ga == G_MOTO) != (gb == G_MOTO) && gb != -1)
            return mcs_node_error(mcs_node_at(al, i), err, MCS_ERR_RANGE,
                                  "attachment %s ties the motorcycle group to a body outside it",
                                  m->attach_name[i]);
    }
    return MCS_OK;
}

/* the rolling spin of a wheel body (its first cylinder surface) moving at v along h: w and the
 * CG velocity it adds; 0 when the body has no cylinder, -1 when its axle is along h. Called
 * after the placement (poses final). */
static int wheel_spin(const mb_model *m, int b, double v, const double h[3], double w[3],
                      double dv[3])
{
    const mb_surface *s = NULL;
    for (int i = 0; i < m->nsurf && !s; i++)
        if (m->surf[i].body == b && m->surf[i].type == MB_SURF_CYLINDER) s = &m->surf[i];
    if (!s) return 0;
    static const double ez[3] = {0, 0, 1};
    double Rb[9], a[3], lat[3], c[3];
    mb_quat_to_rot(m->body[b].quat, Rb);
    mb_mat_vec(Rb, s->normal, a);
    mb_normalize(a);
    mb_cross(ez, h, lat); /* the spin axis of rolling along h: w x (-z) R = -v h */
    double al = mb_dot(a, lat);
    if (fabs(al) < 0.5) return -1;
    /* rolling radius: where the engine applies the road friction -- midway between the
     * tyre's deepest point (R below the centre in the wheel plane) and the road -- so that
     * point has no slip from t = 0: r = (h + R) / 2 with h the centre's distance to the road
     * in the wheel plane, when the tyre is loaded (h < R); else R */
    double R = s->radius + s->tube, cw[3];
    mb_mat_vec(Rb, s->center, cw);
    mb_add(cw, m->body[b].pos, cw);
    if (m->ground_surf >= 0) {
        double hc = (cw[2] - m->surf[m->ground_surf].center[2]) / sqrt(1 - a[2] * a[2]);
        if (hc > 0 && hc < R) R = 0.5 * (hc + R);
    }
    mb_scale(a, (al > 0 ? 1 : -1) * v / R, w);
    mb_mat_vec(Rb, s->center, c); /* CG - centre = -c */
    mb_cross(w, c, dv);
    mb_scale(dv, -1, dv);
    return 1;
}

static mcs_status boost(const mcs_node *imp, mb_model *m, const int *grp, int which, double v,
                        const double h[3], mcs_error *err)
{
    for (int b = 0; b < m->nbody; b++) {
        if (grp[b] != which) continue;
        mb_body_desc *d = &m->body[b];
        mb_axpy(d->vel, v, h, d->vel);
        if (v == 0) continue;
        double w[3], dv[3];
        int r = wheel_spin(m, b, v, h, w, dv);
        if (r < 0)
            return mcs_node_error(imp, err, MCS_ERR_RANGE,
                                  "wheel body '%s': its axle is not across the heading, so it "
                                  "cannot roll",
                                  m->body_name[b]);
        if (r > 0) mb_add(d->angvel, w, d->angvel), mb_add(d->vel, dv, d->vel);
    }
    return MCS_OK;
}

static void move_point(const plan *p, double x[3])
{
    double y[3];
    mb_mat_vec(p->R, x, y);
    mb_add(y, p->t, x);
}

static void rotate_vec(const plan *p, double x[3])
{
    double y[3];
    mb_mat_vec(p->R, x, y);
    mb_copy(y, x);
}

static void place_moto(mb_model *m, const int *grp, const plan *p)
{
    for (int b = 0; b < m->nbody; b++) {
        if (grp[b] != G_MOTO) continue;
        mb_body_desc *d = &m->body[b];
        move_point(p, d->pos);
        rotate_vec(p, d->vel), rotate_vec(p, d->angvel);
        double q[4];
        quat_mul(p->q, d->quat, q);
        memcpy(d->quat, q, sizeof q);
    }
    for (int j = 0; j < m->njoint; j++) {
        mb_joint_def *d = &m->joint[j];
        if (grp[d->child] != G_MOTO) continue;
        move_point(p, d->anchor);
        rotate_vec(p, d->axis), rotate_vec(p, d->axis2);
    }
    for (int i = 0; i < m->nattach; i++) /* world points of attachments to the ground */
        if (grp[m->attach[i].body_a] == G_MOTO && m->attach[i].body_b == MB_GROUND)
            move_point(p, m->attach[i].pb);
}

mcs_status mb_impact_apply(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *imp = mcs_node_get(root, "impact");
    if (mcs_node_kind(imp) != MCS_NODE_MAP) return MCS_OK;
    int *grp = m->body_group = calloc((size_t)(m->nbody > 0 ? m->nbody : 1), sizeof *grp);
    if (!grp) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    assign_groups(imp, m, grp);
    plan p;
    mcs_status st = make_plan(imp, &p, err);
    if (!st) st = check_ties(root, imp, m, grp, &p, err);
    if (!st) {
        place_moto(m, grp, &p);
        memcpy(m->place_R, p.R, sizeof p.R); /* for the FE parts (mb_couple_build) */
        memcpy(m->place_t, p.t, sizeof p.t);
        st = boost(imp, m, grp, G_MOTO, p.v_mc, p.h_mc, err);
    }
    if (!st) st = boost(imp, m, grp, G_OPP, p.v_op, p.h_op, err);
    return st;
}

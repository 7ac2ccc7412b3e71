/* mb_build_joint.c: joints with their restraints, and breakable attachments.
 * Restraints: revolute and translational joints get mb_restraint (the characteristic on both
 * directions, mirrored, or `restraint_negative` on the negative side; the damping of
 * `restraint`; `neutral` and `preload`, docs/joints.md), spherical and universal joints
 * mb_restraint3 (the same characteristics on the three axes of the parent's frame; universal
 * joints on axis and axis2 only, the third being constrained; per-axis `neutral` and
 * `preload`, docs/joints.md). A permanent
 * set on one side moves the other side's origin (mcs_hyst2 follow_set: a bent hinge stays at
 * its set). A joint `range` becomes a stop: a
 * linear one-sided spring beyond the range of 10 times the steepest slope of the restraint's
 * loading curve, or 1e3 N m/rad (revolute) / 1e5 N/m (translational) without one.
 * Attachments: spring-dampers (mb_restraint.h). Without `length` they are at rest in the
 * initial posture: the point on b is taken where point_a is at t = 0 (zero free length). With
 * `length` L the points are as given and the spring acts on |b - a| - L (L = 0: isotropic). */
#include "stage1_mb/mb_build_internal.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const joint_types[] = {"revolute", "spherical", "universal", "translational",
                                          "fixed"};

static double steepest(const mcs_curve *c)
{
    double k = 0;
    for (int i = 0; i + 1 < c->n; i++)
        k = fmax(k, fabs((c->y[i + 1] - c->y[i]) / (c->x[i + 1] - c->x[i])));
    return k;
}

/* both sides' characteristics; a bent side moves the other's origin (follow_set) */
static mcs_hyst2_model two_sided(const mb_model *m, int chr, int neg)
{
    return (mcs_hyst2_model){
        .pos = m->chr[chr].hyst, .neg = m->chr[neg >= 0 ? neg : chr].hyst, .follow_set = 1};
}

/* preload P: by default the zero sits where the negative side carries P, N^-1(P), so the
 * joint is unloaded in its initial position (the spring held by its top-out) */
static mcs_status preload_neutral(const mcs_node *jn, mb_restraint_model *r, mcs_error *err)
{
    const mcs_node *pn = mcs_node_get(jn, "preload"), *nn = mcs_node_get(jn, "neutral");
    r->preload = mcs_node_num_or(jn, "preload", 0);
    r->neutral = mcs_node_num_or(jn, "neutral", 0);
    if (r->preload == 0 || mcs_node_kind(nn) == MCS_NODE_NUM) return MCS_OK;
    const mcs_curve *c = r->spring.neg.loading;
    double q = r->preload > 0 ? mcs_curve_inverse(c, r->preload) : NAN;
    if (!(q >= 0 && isfinite(q)))
        return mcs_node_error(pn, err, MCS_ERR_RANGE,
                              "preload %g: the negative side's characteristic must rise "
                              "strictly to it (or give neutral)",
                              r->preload);
    r->neutral = q;
    return MCS_OK;
}

static mcs_status build_restraint1(const mcs_node *jn, mb_model *m, int ij, int chr, int neg,
                                   mcs_error *err)
{
    const mb_joint_def *j = &m->joint[ij];
    const mcs_node *range = mcs_node_get(jn, "range");
    if (chr < 0 && mcs_node_kind(range) != MCS_NODE_SEQ) return MCS_OK;
    mb_restraint_model *r = &m->restraint1[m->nrestraint1];
    *r = (mb_restraint_model){.joint = ij, .lo = -INFINITY, .hi = INFINITY};
    if (chr >= 0) {
        r->has_spring = 1;
        r->spring = two_sided(m, chr, neg);
        r->damping = m->chr[chr].damping;
    }
    mcs_status st = preload_neutral(jn, r, err);
    if (st) return st;
    if (mcs_node_kind(range) == MCS_NODE_SEQ) {
        double lr[2];
        mcs_status st = mcs_node_vec(range, lr, 2, err);
        if (st) return st;
        if (!(lr[0] < 0 && 0 < lr[1]))
            return mcs_node_error(range, err, MCS_ERR_RANGE,
                                  "range [%g, %g] must contain the initial position 0", lr[0],
                                  lr[1]);
        r->lo = lr[0], r->hi = lr[1];
        double k = chr >= 0 ? 10 * steepest(m->chr[chr].loading) : 0;
        r->stop_stiffness = k > 0 ? k : (j->type == MB_J_REVOLUTE ? 1e3 : 1e5);
    }
    snprintf(m->restraint1_name[m->nrestraint1], MB_NAME, "%s", j->name);
    m->joint[ij].restraint = m->nrestraint1++;
    return MCS_OK;
}

/* universal joint: restraint axes (axis, axis2 made orthogonal to it, their cross product) in
 * the parent's body frame; spherical: the parent's own axes */
static void restraint3_frame(const mb_model *m, const mb_joint_def *j, double F[9])
{
    for (int i = 0; i < 9; i++) F[i] = (i % 4 == 0);
    if (j->type != MB_J_UNIVERSAL) return;
    double a[3], b[3], c[3], R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (j->parent >= 0) mb_quat_to_rot(m->body[j->parent].quat, R);
    mb_mat_tvec(R, j->axis, a);
    mb_mat_tvec(R, j->axis2, b);
    mb_normalize(a);
    double ab = mb_dot(a, b);
    for (int k = 0; k < 3; k++) b[k] -= ab * a[k];
    mb_normalize(b);
    mb_cross(a, b, c);
    for (int k = 0; k < 3; k++) F[3 * k] = a[k], F[3 * k + 1] = b[k], F[3 * k + 2] = c[k];
}

/* per-axis neutral angle and preload (docs/joints.md): n values on a spherical joint (3) or a
 * universal joint (2); with a preload and no neutral, the zero of axis i sits where the
 * characteristic carries the preload, N^-1(P) (P > 0, negative side) or -A^-1(-P) (P < 0),
 * so the joint is unloaded in its initial posture, as for a revolute joint */
static mcs_status restraint3_preload(const mcs_node *jn, mb_restraint3_model *r, int n,
                                     mcs_error *err)
{
    const mcs_node *pn = mcs_node_get(jn, "preload"), *nn = mcs_node_get(jn, "neutral");
    mcs_status st = MCS_OK;
    if (mcs_node_kind(pn) == MCS_NODE_SEQ) st = mcs_node_vec(pn, r->preload, n, err);
    if (!st && mcs_node_kind(nn) == MCS_NODE_SEQ) return mcs_node_vec(nn, r->zero, n, err);
    for (int i = 0; i < n && !st; i++) {
        double p = r->preload[i];
        if (p == 0) continue;
        const mcs_curve *c = p > 0 ? r->spring[i].neg.loading : r->spring[i].pos.loading;
        double q = mcs_curve_inverse(c, fabs(p));
        if (!(q >= 0 && isfinite(q)))
            return mcs_node_error(pn, err, MCS_ERR_RANGE,
                                  "preload %g on axis %d: the characteristic must rise strictly "
                                  "to it (or give neutral)",
                                  p, i + 1);
        r->zero[i] = p > 0 ? q : -q;
    }
    return st;
}

static mcs_status build_restraint3(const mcs_node *jn, mb_model *m, int ij, int chr, int neg,
                                   mcs_error *err)
{
    mb_restraint3_model *r = &m->restraint3[m->nrestraint3];
    const mb_joint_def *j = &m->joint[ij];
    int n = j->type == MB_J_UNIVERSAL ? 2 : 3; /* universal: the third axis is constrained */
    *r = (mb_restraint3_model){.joint = ij};
    restraint3_frame(m, j, r->frame);
    for (int k = 0; k < 3; k++) {
        r->has_spring[k] = k < n;
        if (k < n) r->spring[k] = two_sided(m, chr, neg);
        r->damping[k] = k < n ? m->chr[chr].damping : 0;
        r->lo[k] = -INFINITY, r->hi[k] = INFINITY;
    }
    mcs_status st = restraint3_preload(jn, r, n, err);
    if (st) return st;
    snprintf(m->restraint3_name[m->nrestraint3], MB_NAME, "%s", j->name);
    m->joint[ij].restraint = m->nrestraint3++;
    return MCS_OK;
}

static mcs_status build_joint(const mcs_node *jn, mb_model *m, int ij, mcs_error *err)
{
    mb_joint_def *j = &m->joint[ij];
    const char *ty = mcs_node_str(mcs_node_get(jn, "type"));
    for (int k = 0; k < 5; k++)
        if (ty && strcmp(ty, joint_types[k]) == 0) j->type = (mb_joint_type)k;
    const char *nm = mcs_node_str(mcs_node_get(jn, "name"));
    snprintf(j->name, MB_NAME, "%s", nm ? nm : "");
    if (!nm) snprintf(j->name, MB_NAME, "joints[%d]", ij);
    j->parent = mb_build_body_ref(m, mcs_node_get(jn, "parent"));
    j->child = mb_build_body_ref(m, mcs_node_get(jn, "child"));
    j->restraint = -1;
    mcs_status st = mcs_node_vec3(mcs_node_get(jn, "anchor"), j->anchor, err);
    if (!st && mcs_node_kind(mcs_node_get(jn, "axis")) == MCS_NODE_SEQ)
        st = mb_build_dir(mcs_node_get(jn, "axis"), j->axis, err);
    if (!st && mcs_node_kind(mcs_node_get(jn, "axis2")) == MCS_NODE_SEQ)
        st = mb_build_dir(mcs_node_get(jn, "axis2"), j->axis2, err);
    if (st) return st;
    if (j->type == MB_J_UNIVERSAL && fabs(mb_dot(j->axis, j->axis2)) > 1 - 1e-9)
        return mcs_node_error(mcs_node_get(jn, "axis2"), err, MCS_ERR_RANGE,
                              "axis2 is parallel to axis");
    const mcs_node *rn = mcs_node_get(jn, "restraint");
    const mcs_node *nn = mcs_node_get(jn, "restraint_negative");
    int chr = mb_build_char_ref(m, rn), neg = mb_build_char_ref(m, nn);
    int want_moment = j->type != MB_J_TRANSLATIONAL;
    if ((chr >= 0 || neg >= 0) && j->type == MB_J_FIXED)
        return mcs_node_error(chr >= 0 ? rn : nn, err, MCS_ERR_RANGE,
                              "a fixed joint has no restraint");
    if (neg >= 0 && chr < 0)
        return mcs_node_error(nn, err, MCS_ERR_KEY,
                              "restraint_negative needs restraint (the positive side)");
    const mcs_node *pn = mcs_node_get(jn, "preload");
    if (chr < 0 && mcs_node_kind(pn) != MCS_NODE_NULL)
        return mcs_node_error(pn, err, MCS_ERR_KEY, "a preload needs a restraint characteristic");
    for (int k = 0; k < 2; k++) {
        int c = k ? neg : chr;
        if (c >= 0 && m->chr[c].moment != want_moment)
            return mcs_node_error(k ? nn : rn, err, MCS_ERR_TYPE,
                                  "a %s joint needs a %s characteristic", ty,
                                  want_moment ? "moment (type: moment)" : "force");
    }
    if (j->type == MB_J_REVOLUTE || j->type == MB_J_TRANSLATIONAL)
        return build_restraint1(jn, m, ij, chr, neg, err);
    if (chr >= 0 && j->type != MB_J_FIXED) return build_restraint3(jn, m, ij, chr, neg, err);
    return MCS_OK;
}

mcs_status mb_build_joints(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *list = mcs_node_get(root, "joints");
    m->njoint = mcs_node_len(list);
    m->joint = MB_NEW(mb_joint_def, m->njoint);
    m->restraint1 = MB_NEW(mb_restraint_model, m->njoint);
    m->restraint1_name = MB_NEW(mb_name, m->njoint);
    m->restraint3 = MB_NEW(mb_restraint3_model, m->njoint);
    m->restraint3_name = MB_NEW(mb_name, m->njoint);
    if (!m->joint || !m->restraint1 || !m->restraint1_name || !m->restraint3 ||
        !m->restraint3_name)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int i = 0; i < m->njoint; i++) {
        mcs_status st = build_joint(mcs_node_at(list, i), m, i, err);
        if (st) return st;
    }
    return MCS_OK;
}

/* world position of a point given in body b's frame (world coordinates for the ground) */
static void initial_world_point(const mb_model *m, int b, const double p[3], double out[3])
{
    if (b == MB_GROUND) {
        mb_copy(p, out);
        return;
    }
    double R[9];
    mb_quat_to_rot(m->body[b].quat, R);
    mb_mat_vec(R, p, out);
    mb_add(out, m->body[b].pos, out);
}

static mcs_status build_attachment(const mcs_node *n, mb_model *m, int i, mcs_error *err)
{
    mb_attach_model *a = &m->attach[i];
    const char *nm = mcs_node_str(mcs_node_get(n, "name"));
    if (nm)
        snprintf(m->attach_name[i], MB_NAME, "%s", nm);
    else
        snprintf(m->attach_name[i], MB_NAME, "attachments[%d]", i);
    a->body_a = mb_build_body_ref(m, mcs_node_get(n, "a"));
    a->body_b = mb_build_body_ref(m, mcs_node_get(n, "b"));
    mcs_status st = mcs_node_vec3(mcs_node_get(n, "point_a"), a->pa, err);
    if (!st) st = mcs_node_vec3(mcs_node_get(n, "point_b"), a->pb, err);
    if (st) return st;
    if (a->body_a == MB_GROUND) { /* keep the world second */
        a->body_a = a->body_b, a->body_b = MB_GROUND;
        double t[3];
        mb_copy(a->pa, t), mb_copy(a->pb, a->pa), mb_copy(t, a->pb);
    }
    a->stiffness = mcs_node_num(mcs_node_get(n, "stiffness"));
    a->damping = mcs_node_num_or(n, "damping", 0);
    a->fail_force = mcs_node_num(mcs_node_get(n, "failure_force"));
    if (!(a->stiffness > 0))
        return mcs_node_error(mcs_node_get(n, "stiffness"), err, MCS_ERR_RANGE,
                              "an attachment needs a stiffness > 0 N/m");
    double L = mcs_node_num_or(n, "length", NAN);
    a->length = isnan(L) ? 0 : L; /* given: the points as given, spring on |b - a| - L */
    if (isnan(L)) { /* at rest now: b's point where a's point is */
        double wa[3];
        initial_world_point(m, a->body_a, a->pa, wa);
        if (a->body_b == MB_GROUND)
            mb_copy(wa, a->pb);
        else {
            double R[9], d[3];
            mb_quat_to_rot(m->body[a->body_b].quat, R);
            mb_sub(wa, m->body[a->body_b].pos, d);
            mb_mat_tvec(R, d, a->pb);
        }
    }
    return MCS_OK;
}

mcs_status mb_build_attachments(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *list = mcs_node_get(root, "attachments");
    m->nattach = mcs_node_len(list);
    m->attach = MB_NEW(mb_attach_model, m->nattach);
    m->attach_name = MB_NEW(mb_name, m->nattach);
    if (!m->attach || !m->attach_name) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int i = 0; i < m->nattach; i++) {
        mcs_status st = build_attachment(mcs_node_at(list, i), m, i, err);
        if (st) return st;
    }
    return MCS_OK;
}

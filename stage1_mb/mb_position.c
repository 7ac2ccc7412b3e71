/* mb_position.c: seating the rider on the motorcycle (see mb_position.h, docs/rider.md).
 * Every body's new pose is written as a rotation D_b applied to its file pose about the
 * world origin followed by a translation: new orientation D_b R0_b, and the world offsets of
 * the file posture (anchor - CG) turn with D_b. Positions follow by walking the joint tree from
 * the pelvis: anchor = parent CG + D_parent (anchor0 - parent CG0), child CG = anchor -
 * D_child (anchor0 - child CG0), so every joint stays closed exactly. */
#include "stage1_mb/mb_position.h"
#include "stage1_mb/mb_build_internal.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define SIDES 2
static const char *const side_sfx[SIDES] = {"l", "r"};

typedef struct {
    mb_model *m;
    const mcs_node *root;  /* the scenario */
    const mcs_node *block; /* its rider: block */
    mcs_error *err;
    int *rider;            /* 1 for rider bodies (nbody) */
    double (*D)[9];        /* rotation of each body from its file pose (nbody) */
    int *has_D;            /* 1 once D is set (nbody) */
    double (*pos)[3];      /* new CG (nbody) */
    double (*anchor)[3];   /* new joint anchors (njoint) */
} pos_ctx;

/* ---- small helpers --------------------------------------------------------------------------- */

static void rot_y(double ang, double R[9])
{
    static const double ey[3] = {0, 1, 0};
    mb_rot_axis_angle(ey, ang, R);
}

/* quaternion w, x, y, z of a rotation matrix (Shepperd) */
static void rot_to_quat(const double R[9], double q[4])
{
    double tr = R[0] + R[4] + R[8];
    if (tr > 0) {
        double s = 2 * sqrt(tr + 1);
        q[0] = s / 4, q[1] = (R[7] - R[5]) / s, q[2] = (R[2] - R[6]) / s, q[3] = (R[3] - R[1]) / s;
    } else if (R[0] > R[4] && R[0] > R[8]) {
        double s = 2 * sqrt(1 + R[0] - R[4] - R[8]);
        q[0] = (R[7] - R[5]) / s, q[1] = s / 4, q[2] = (R[1] + R[3]) / s, q[3] = (R[2] + R[6]) / s;
    } else if (R[4] > R[8]) {
        double s = 2 * sqrt(1 + R[4] - R[0] - R[8]);
        q[0] = (R[2] - R[6]) / s, q[1] = (R[1] + R[3]) / s, q[2] = s / 4, q[3] = (R[5] + R[7]) / s;
    } else {
        double s = 2 * sqrt(1 + R[8] - R[0] - R[4]);
        q[0] = (R[3] - R[1]) / s, q[1] = (R[2] + R[6]) / s, q[2] = (R[5] + R[7]) / s, q[3] = s / 4;
    }
}

/* rotation with columns a, b, a x b (a, b orthonormal) */
static void frame_cols(const double a[3], const double b[3], double F[9])
{
    double c[3];
    mb_cross(a, b, c);
    for (int i = 0; i < 3; i++) F[3 * i] = a[i], F[3 * i + 1] = b[i], F[3 * i + 2] = c[i];
}

/* out = A B^T */
static void mul_bt(const double A[9], const double B[9], double out[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[3 * i + j] = A[3 * i] * B[3 * j] + A[3 * i + 1] * B[3 * j + 1] + A[3 * i + 2] * B[3 * j + 2];
}

static int body_named(const mb_model *m, const char *base, const char *sfx)
{
    char nm[MB_NAME];
    if (sfx)
        snprintf(nm, sizeof nm, "%s_%s", base, sfx);
    else
        snprintf(nm, sizeof nm, "%s", base);
    return mb_model_body(m, nm);
}

/* the joint between parent p and child c, or -1 */
static int joint_between(const mb_model *m, int p, int c)
{
    for (int j = 0; j < m->njoint; j++)
        if (m->joint[j].parent == p && m->joint[j].child == c) return j;
    return -1;
}

/* ---- mount points ---------------------------------------------------------------------------- */

static const mcs_node *mount_node(const mcs_node *root, const char *name)
{
    const mcs_node *list = mcs_node_get(root, "mount_points");
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *n = mcs_node_at(list, i);
        const char *s = mcs_node_str(mcs_node_get(n, "name"));
        if (s && strcmp(s, name) == 0) return n;
    }
    return NULL;
}

/* body and body-frame point of a mount point; its world point in the file pose */
static mcs_status mount_get(pos_ctx *c, const char *name, int *body, double p[3], double w[3])
{
    const mcs_node *n = mount_node(c->root, name);
    if (!n)
        return mcs_node_error(c->block, c->err, MCS_ERR_KEY,
                              "seating the rider needs the mount point '%s' (mount_points:, "
                              "docs/rider.md)", name);
    *body = mb_build_body_ref(c->m, mcs_node_get(n, "body"));
    mcs_status st = mcs_node_vec3(mcs_node_get(n, "point"), p, c->err);
    if (st) return st;
    if (*body < 0)
        return mcs_node_error(mcs_node_get(n, "body"), c->err, MCS_ERR_KEY,
                              "mount point '%s' is not on a body", name);
    double R[9];
    mb_quat_to_rot(c->m->body[*body].quat, R);
    mb_mat_vec(R, p, w);
    mb_add(w, c->m->body[*body].pos, w);
    return MCS_OK;
}

int mb_mount_world(const mcs_node *root, const mb_model *m, const char *name, double out[3])
{
    const mcs_node *n = mount_node(root, name);
    if (!n) return -1;
    int b = mb_build_body_ref(m, mcs_node_get(n, "body"));
    double p[3];
    mcs_error e = {0};
    if (b < 0 || mcs_node_vec3(mcs_node_get(n, "point"), p, &e)) return -1;
    double R[9];
    mb_quat_to_rot(m->body[b].quat, R);
    mb_mat_vec(R, p, out);
    mb_add(out, m->body[b].pos, out);
    return 0;
}

/* ---- the joint tree ---------------------------------------------------------------------------- */

/* joint whose child is b and whose parent is a rider body, or -1 */
static int parent_joint(const pos_ctx *c, int b)
{
    for (int j = 0; j < c->m->njoint; j++) {
        const mb_joint_def *jd = &c->m->joint[j];
        if (jd->child == b && jd->parent >= 0 && c->rider[jd->parent]) return j;
    }
    return -1;
}

/* bodies without an explicit rotation take their parent's (repeated passes cover any depth) */
static void inherit_rotations(pos_ctx *c, const int *explicit_D)
{
    mb_model *m = c->m;
    for (int pass = 0; pass < m->nbody; pass++) {
        int changed = 0;
        for (int b = 0; b < m->nbody; b++) {
            if (!c->rider[b] || explicit_D[b]) continue;
            int j = parent_joint(c, b);
            if (j < 0 || !c->has_D[m->joint[j].parent]) continue;
            if (!c->has_D[b] || memcmp(c->D[b], c->D[m->joint[j].parent], sizeof c->D[b])) {
                memcpy(c->D[b], c->D[m->joint[j].parent], sizeof c->D[b]);
                c->has_D[b] = 1, changed = 1;
            }
        }
        if (!changed) break;
    }
}

/* positions of every rider body reachable from the placed pelvis through rider joints, and the
 * joints' new anchors; returns the number of bodies placed */
static int walk_tree(pos_ctx *c, int pelvis, int *placed)
{
    mb_model *m = c->m;
    for (int b = 0; b < m->nbody; b++) placed[b] = 0;
    placed[pelvis] = 1;
    int n = 1;
    for (int pass = 0; pass < m->nbody; pass++) {
        int changed = 0;
        for (int j = 0; j < m->njoint; j++) {
            const mb_joint_def *jd = &m->joint[j];
            int p = jd->parent, ch = jd->child;
            if (p < 0 || !c->rider[p] || !c->rider[ch] || placed[p] == placed[ch]) continue;
            int known = placed[p] ? p : ch, other = placed[p] ? ch : p;
            double d[3], a[3];
            mb_sub(jd->anchor, m->body[known].pos, d);
            mb_mat_vec(c->D[known], d, a);
            mb_add(c->pos[known], a, c->anchor[j]);
            mb_sub(jd->anchor, m->body[other].pos, d);
            mb_mat_vec(c->D[other], d, a);
            mb_sub(c->anchor[j], a, c->pos[other]);
            placed[other] = 1, n++, changed = 1;
        }
        if (!changed) break;
    }
    /* anchors of the joints between two rider bodies placed from both sides: the parent's */
    for (int j = 0; j < m->njoint; j++) {
        const mb_joint_def *jd = &m->joint[j];
        if (jd->parent < 0 || !c->rider[jd->parent] || !c->rider[jd->child]) continue;
        double d[3], a[3];
        mb_sub(jd->anchor, m->body[jd->parent].pos, d);
        mb_mat_vec(c->D[jd->parent], d, a);
        mb_add(c->pos[jd->parent], a, c->anchor[j]);
    }
    return n;
}

/* ---- the two-link chain ------------------------------------------------------------------------ */

/* A chain from the root point A (new) through the middle joint to the end point: link 1 is the
 * file vector r1 (root -> middle), link 2 r2 (middle -> end), bending about the file hinge axis
 * n0. Puts the end on T with the middle joint in the plane of A, T and the pole direction.
 * Closed form: with d = |T - A|, the middle joint lies a = (L1^2 - L2^2 + d^2) / (2 d) along
 * A->T and h = sqrt(L1^2 - a^2) towards the pole. D1, D2: the links' rotations. */
static mcs_status two_link(pos_ctx *c, const char *what, const double r1[3], const double r2[3],
                           const double n0[3], const double A[3], const double T[3],
                           const double pole[3], double D1[9], double D2[9])
{
    double L1 = mb_norm(r1), L2 = mb_norm(r2), u[3], v[3], B[3], e1[3], f1[3], n[3];
    mb_sub(T, A, u);
    double d = mb_norm(u);
    if (!(d < L1 + L2) || !(d > fabs(L1 - L2)))
        return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                              "seating the rider: the %s cannot reach its target: %.4f m away, "
                              "the chain reaches %.4f to %.4f m (change torso_lean or the "
                              "motorcycle's mount points)",
                              what, d, fabs(L1 - L2), L1 + L2);
    mb_scale(u, 1 / d, u);
    double a = (L1 * L1 - L2 * L2 + d * d) / (2 * d), h = sqrt(fmax(L1 * L1 - a * a, 0));
    mb_axpy(pole, -mb_dot(pole, u), u, v);
    if (!(mb_normalize(v) > 1e-9))
        return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                              "seating the rider: the %s points along its bending direction", what);
    mb_axpy(A, a, u, B);
    mb_axpy(B, h, v, B);
    mb_sub(B, A, e1), mb_scale(e1, 1 / L1, e1);
    mb_sub(T, B, f1), mb_scale(f1, 1 / L2, f1);
    /* the file's bending sense about n0, kept */
    double a1[3], a2[3], ref[3];
    mb_scale(r1, 1 / L1, a1), mb_scale(r2, 1 / L2, a2);
    mb_cross(a1, a2, ref);
    double sense = mb_dot(ref, n0) >= 0 ? 1 : -1;
    if (fabs(mb_dot(a1, n0)) > 1e-6 || fabs(mb_dot(a2, n0)) > 1e-6 || mb_norm(ref) < 1e-6)
        return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                              "seating the rider: in the model file the %s must be bent and its "
                              "hinge axis perpendicular to both links",
                              what);
    mb_cross(e1, f1, n);
    if (!(mb_normalize(n) > 1e-9))
        return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                              "seating the rider: the %s would be straight", what);
    mb_scale(n, sense, n);
    double F0[9], F1[9];
    frame_cols(a1, n0, F0), frame_cols(e1, n, F1), mul_bt(F1, F0, D1);
    frame_cols(a2, n0, F0), frame_cols(f1, n, F1), mul_bt(F1, F0, D2);
    return MCS_OK;
}

/* hinge axis of the middle joint (revolute: its axis; otherwise the file's bending plane) */
static void hinge_axis(const mb_model *m, int j, const double r1[3], const double r2[3],
                       double n0[3])
{
    if (j >= 0 && m->joint[j].type == MB_J_REVOLUTE) {
        mb_copy(m->joint[j].axis, n0);
        return;
    }
    mb_cross(r1, r2, n0);
    mb_normalize(n0);
}

/* ---- the posture ------------------------------------------------------------------------------- */

typedef struct {
    int upper, lower, end;     /* bodies: upper arm / thigh, forearm / lower leg, hand / foot */
    int j_root, j_mid, j_end;  /* joints: shoulder / hip, elbow / knee, wrist / ankle         */
} limb;

static mcs_status find_limb(pos_ctx *c, const char *upper, const char *lower, const char *end,
                            int side, int torso, limb *L)
{
    const char *s = side_sfx[side];
    L->upper = body_named(c->m, upper, s);
    L->lower = body_named(c->m, lower, s);
    L->end = body_named(c->m, end, s);
    const char *miss = L->upper < 0 ? upper : L->lower < 0 ? lower : L->end < 0 ? end : NULL;
    if (miss)
        return mcs_node_error(c->block, c->err, MCS_ERR_KEY,
                              "seating the rider needs the body %s_%s (docs/rider.md)", miss, s);
    L->j_root = joint_between(c->m, torso, L->upper);
    L->j_mid = joint_between(c->m, L->upper, L->lower);
    L->j_end = joint_between(c->m, L->lower, L->end);
    if (L->j_root < 0 || L->j_mid < 0 || L->j_end < 0)
        return mcs_node_error(c->block, c->err, MCS_ERR_KEY,
                              "seating the rider: %s_%s, %s_%s and %s_%s must be joined in a chain "
                              "to the trunk",
                              upper, s, lower, s, end, s);
    return MCS_OK;
}

/* the arm: shoulder -> elbow -> grip point (forearm and hand turn together) */
static mcs_status seat_arm(pos_ctx *c, const limb *L, int side, int *explicit_D)
{
    mb_model *m = c->m;
    char rn[32], mn[32], what[48];
    snprintf(rn, sizeof rn, "rider_grip_%s", side_sfx[side]);
    snprintf(mn, sizeof mn, "grip_%s", side_sfx[side]);
    int rb, mbody;
    double rp[3], rw0[3], mp[3], target[3];
    mcs_status st = mount_get(c, rn, &rb, rp, rw0);
    if (!st) st = mount_get(c, mn, &mbody, mp, target);
    if (st) return st;
    if (rb != L->end && rb != L->lower)
        return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                              "mount point %s must be on %s or %s", rn, m->body_name[L->end],
                              m->body_name[L->lower]);
    double r1[3], r2[3], n0[3], D1[9], D2[9];
    mb_sub(m->joint[L->j_mid].anchor, m->joint[L->j_root].anchor, r1);
    mb_sub(rw0, m->joint[L->j_mid].anchor, r2);
    hinge_axis(m, L->j_mid, r1, r2, n0);
    double pole[3] = {-0.2, side == 0 ? 0.5 : -0.5, -1}; /* elbows down, out, a little back */
    snprintf(what, sizeof what, "%s arm", side == 0 ? "left" : "right");
    st = two_link(c, what, r1, r2, n0, c->anchor[L->j_root], target, pole, D1, D2);
    if (st) return st;
    memcpy(c->D[L->upper], D1, sizeof D1), memcpy(c->D[L->lower], D2, sizeof D2);
    memcpy(c->D[L->end], D2, sizeof D2);
    explicit_D[L->upper] = explicit_D[L->lower] = explicit_D[L->end] = 1;
    return MCS_OK;
}

/* the leg: hip -> knee -> ankle, the foot pitched by foot_pitch and its peg point on the peg */
static mcs_status seat_leg(pos_ctx *c, const limb *L, int side, int *explicit_D)
{
    mb_model *m = c->m;
    char rn[32], mn[32], what[48];
    snprintf(rn, sizeof rn, "rider_peg_%s", side_sfx[side]);
    snprintf(mn, sizeof mn, "peg_%s", side_sfx[side]);
    int rb, mbody;
    double rp[3], rw0[3], mp[3], peg[3];
    mcs_status st = mount_get(c, rn, &rb, rp, rw0);
    if (!st) st = mount_get(c, mn, &mbody, mp, peg);
    if (st) return st;
    if (rb != L->end)
        return mcs_node_error(c->block, c->err, MCS_ERR_RANGE, "mount point %s must be on %s",
                              rn, m->body_name[L->end]);
    double Df[9], off[3], off_new[3], ankle[3];
    rot_y(mcs_node_num_or(c->block, "foot_pitch", 0), Df);
    mb_sub(rw0, m->joint[L->j_end].anchor, off);
    mb_mat_vec(Df, off, off_new);
    mb_sub(peg, off_new, ankle);
    double r1[3], r2[3], n0[3], D1[9], D2[9];
    mb_sub(m->joint[L->j_mid].anchor, m->joint[L->j_root].anchor, r1);
    mb_sub(m->joint[L->j_end].anchor, m->joint[L->j_mid].anchor, r2);
    hinge_axis(m, L->j_mid, r1, r2, n0);
    double pole[3] = {1, side == 0 ? 0.15 : -0.15, 0.3}; /* knees forward, up, a little out */
    snprintf(what, sizeof what, "%s leg", side == 0 ? "left" : "right");
    st = two_link(c, what, r1, r2, n0, c->anchor[L->j_root], ankle, pole, D1, D2);
    if (st) return st;
    memcpy(c->D[L->upper], D1, sizeof D1), memcpy(c->D[L->lower], D2, sizeof D2);
    memcpy(c->D[L->end], Df, sizeof Df);
    explicit_D[L->upper] = explicit_D[L->lower] = explicit_D[L->end] = 1;
    return MCS_OK;
}

/* revolute joints between rider bodies: the range moves by the posture's rotation delta about
 * the axis (the file gives it about its own posture); universal and translational axes turn */
static mcs_status joint_axes_ranges(pos_ctx *c)
{
    mb_model *m = c->m;
    for (int j = 0; j < m->njoint; j++) {
        mb_joint_def *jd = &m->joint[j];
        if (jd->parent < 0 || !c->rider[jd->parent] || !c->rider[jd->child]) continue;
        const double *Dp = c->D[jd->parent], *Dc = c->D[jd->child];
        double rel[9], t[3];
        mb_mat_tmul(Dp, Dc, rel);
        if (jd->type == MB_J_REVOLUTE) {
            mb_mat_vec(rel, jd->axis, t);
            mb_sub(t, jd->axis, t);
            if (mb_norm(t) > 1e-6)
                return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                                      "seating the rider turns revolute joint %s off its axis",
                                      jd->name);
            double w[3] = {rel[7] - rel[5], rel[2] - rel[6], rel[3] - rel[1]};
            double delta = atan2(0.5 * mb_dot(w, jd->axis), 0.5 * (rel[0] + rel[4] + rel[8] - 1));
            if (jd->restraint >= 0) {
                mb_restraint_model *r = &m->restraint1[jd->restraint];
                r->lo -= delta, r->hi -= delta;
                if (!(r->lo < 0 && r->hi > 0))
                    return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                                          "seating the rider puts joint %s %.1f deg from the "
                                          "model file's posture, outside its range [%.1f, %.1f] deg",
                                          jd->name, delta * 180 / M_PI, (r->lo + delta) * 180 / M_PI,
                                          (r->hi + delta) * 180 / M_PI);
            }
            mb_mat_vec(Dp, jd->axis, t), mb_copy(t, jd->axis);
        } else if (jd->type == MB_J_UNIVERSAL) {
            mb_mat_vec(Dc, jd->axis, t), mb_copy(t, jd->axis);
            mb_mat_vec(Dp, jd->axis2, t), mb_copy(t, jd->axis2);
            if (fabs(mb_dot(jd->axis, jd->axis2)) > 1e-6)
                return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                                      "seating the rider leaves universal joint %s with axes "
                                      "that are not perpendicular (use a spherical joint)",
                                      jd->name);
        } else if (jd->type == MB_J_TRANSLATIONAL) {
            mb_mat_vec(Dc, jd->axis, t), mb_copy(t, jd->axis);
        }
        mb_copy(c->anchor[j], jd->anchor);
    }
    return MCS_OK;
}

/* mount-point residuals after the posture [m] */
static double residual(pos_ctx *c)
{
    static const char *const pairs[5][2] = {{"rider_h_point", "seat_h_point"},
                                            {"rider_grip_l", "grip_l"},
                                            {"rider_grip_r", "grip_r"},
                                            {"rider_peg_l", "peg_l"},
                                            {"rider_peg_r", "peg_r"}};
    double worst = 0;
    for (int k = 0; k < 5; k++) {
        double a[3], b[3], d[3];
        if (mb_mount_world(c->root, c->m, pairs[k][0], a) || mb_mount_world(c->root, c->m, pairs[k][1], b))
            continue;
        mb_sub(a, b, d);
        worst = fmax(worst, mb_norm(d));
    }
    return worst;
}

static mcs_status seat(pos_ctx *c)
{
    mb_model *m = c->m;
    int pelvis = mb_model_body(m, "rider_pelvis"), torso = mb_model_body(m, "rider_upper_torso");
    int head = mb_model_body(m, "rider_head");
    if (pelvis < 0 || torso < 0 || head < 0)
        return mcs_node_error(c->block, c->err, MCS_ERR_KEY,
                              "seating the rider needs the bodies rider_pelvis, rider_upper_torso "
                              "and rider_head (include a rider model, docs/rider.md)");
    int seat_body, hb;
    double seat_p[3], seat_w[3], h_p[3], h_w0[3];
    mcs_status st = mount_get(c, "rider_h_point", &hb, h_p, h_w0);
    if (!st) st = mount_get(c, "seat_h_point", &seat_body, seat_p, seat_w);
    if (st) return st;
    if (hb != pelvis)
        return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                              "mount point rider_h_point must be on rider_pelvis");
    if (c->rider[seat_body])
        return mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                              "mount point seat_h_point must be on the motorcycle, not the rider");
    int *explicit_D = calloc((size_t)m->nbody, sizeof *explicit_D);
    int *placed = calloc((size_t)m->nbody, sizeof *placed);
    if (!explicit_D || !placed) {
        free(explicit_D), free(placed);
        return MCS_ERR(c->err, MCS_ERR_NOMEM, "stage 1: out of memory");
    }
    /* trunk pitched about the H-point; the neck shares the pitch back to the head's */
    double lean = mcs_node_num_or(c->block, "torso_lean", 0);
    double hp = mcs_node_num_or(c->block, "head_pitch", 0);
    rot_y(lean, c->D[pelvis]);
    c->has_D[pelvis] = explicit_D[pelvis] = 1;
    int chain[64], nchain = 0;
    for (int b = head; b != torso && nchain < 64;) {
        int j = parent_joint(c, b);
        if (j < 0) {
            nchain = -1;
            break;
        }
        chain[nchain++] = b = m->joint[j].parent;
    }
    if (nchain <= 0) {
        free(explicit_D), free(placed);
        return mcs_node_error(c->block, c->err, MCS_ERR_KEY,
                              "seating the rider: rider_head is not joined to rider_upper_torso");
    }
    nchain--; /* chain[0..nchain-1]: neck bodies from the head down; chain[nchain] = torso */
    for (int k = 0; k < nchain; k++) {
        int b = chain[k], from_torso = nchain - k;
        rot_y(lean + (hp - lean) * from_torso / (nchain + 1), c->D[b]);
        c->has_D[b] = explicit_D[b] = 1;
    }
    rot_y(hp, c->D[head]);
    c->has_D[head] = explicit_D[head] = 1;
    inherit_rotations(c, explicit_D);
    /* the pelvis's H-point on the seat point; first walk for the shoulders and hips */
    double d[3], a[3];
    mb_sub(h_w0, m->body[pelvis].pos, d);
    mb_mat_vec(c->D[pelvis], d, a);
    mb_sub(seat_w, a, c->pos[pelvis]);
    walk_tree(c, pelvis, placed);
    limb arm[SIDES], leg[SIDES];
    for (int s = 0; !st && s < SIDES; s++) {
        st = find_limb(c, "rider_upper_arm", "rider_lower_arm", "rider_hand", s, torso, &arm[s]);
        if (!st) st = find_limb(c, "rider_thigh", "rider_lower_leg", "rider_foot", s, pelvis, &leg[s]);
        if (!st) st = seat_arm(c, &arm[s], s, explicit_D);
        if (!st) st = seat_leg(c, &leg[s], s, explicit_D);
    }
    if (!st) {
        for (int b = 0; b < m->nbody; b++) c->has_D[b] |= explicit_D[b];
        inherit_rotations(c, explicit_D);
        walk_tree(c, pelvis, placed);
        /* helmet parts hang on attachments: they move with the head */
        for (int b = 0; !st && b < m->nbody; b++) {
            if (!c->rider[b] || placed[b]) continue;
            if (strncmp(m->body_name[b], "rider_helmet", 12) != 0) {
                st = mcs_node_error(c->block, c->err, MCS_ERR_RANGE,
                                    "seating the rider: body %s is not joined to the rider's "
                                    "joint tree (only rider_helmet* bodies may hang free)",
                                    m->body_name[b]);
                break;
            }
            memcpy(c->D[b], c->D[head], sizeof c->D[b]);
            mb_sub(m->body[b].pos, m->body[head].pos, d);
            mb_mat_vec(c->D[head], d, a);
            mb_add(c->pos[head], a, c->pos[b]);
            placed[b] = 1;
        }
    }
    if (!st) st = joint_axes_ranges(c);
    if (!st) {
        /* write the poses; velocities of the seat body's rigid motion */
        const mb_body_desc *sb = &m->body[seat_body];
        for (int b = 0; b < m->nbody; b++) {
            if (!c->rider[b]) continue;
            mb_body_desc *bd = &m->body[b];
            double R0[9], R[9], r[3], w[3];
            mb_quat_to_rot(bd->quat, R0);
            mb_mat_mul(c->D[b], R0, R);
            rot_to_quat(R, bd->quat);
            mb_copy(c->pos[b], bd->pos);
            mb_sub(bd->pos, sb->pos, r);
            mb_cross(sb->angvel, r, w);
            mb_add(sb->vel, w, bd->vel);
            mb_copy(sb->angvel, bd->angvel);
        }
        m->rider_residual = residual(c);
        mcs_log(MCS_LOG_INFO, "rider seated: torso lean %.1f deg, largest mount-point residual %.3g m",
                lean * 180 / M_PI, m->rider_residual);
    }
    free(explicit_D), free(placed);
    return st;
}

mcs_status mb_position_rider(const mcs_node *root, mb_model *m, mcs_error *err)
{
    m->rider_residual = -1;
    m->rider_dummy[0] = 0;
    const mcs_node *block = mcs_node_get(root, "rider");
    if (mcs_node_kind(block) != MCS_NODE_MAP) return MCS_OK;
    const char *dummy = mcs_node_str(mcs_node_get(block, "dummy"));
    snprintf(m->rider_dummy, sizeof m->rider_dummy, "%s", dummy ? dummy : "50th_male");
    pos_ctx c = {.m = m, .root = root, .block = block, .err = err};
    size_t nb = (size_t)m->nbody, nj = (size_t)(m->njoint > 0 ? m->njoint : 1);
    c.rider = calloc(nb, sizeof *c.rider);
    c.D = calloc(nb, sizeof *c.D);
    c.has_D = calloc(nb, sizeof *c.has_D);
    c.pos = calloc(nb, sizeof *c.pos);
    c.anchor = calloc(nj, sizeof *c.anchor);
    mcs_status st = MCS_OK;
    if (!c.rider || !c.D || !c.has_D || !c.pos || !c.anchor)
        st = MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int b = 0; !st && b < m->nbody; b++) {
        c.rider[b] = strncmp(m->body_name[b], "rider_", 6) == 0;
        static const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        memcpy(c.D[b], I, sizeof I);
        mb_copy(m->body[b].pos, c.pos[b]);
    }
    if (!st) st = seat(&c);
    free(c.rider), free(c.D), free(c.has_D), free(c.pos), free(c.anchor);
    return st;
}

/* ---- the five breakable attachments -------------------------------------------------------------- */

mcs_status mb_position_attach(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *block = mcs_node_get(root, "rider");
    if (mcs_node_kind(block) != MCS_NODE_MAP || !mcs_node_bool(mcs_node_get(block, "attachments"), 1))
        return MCS_OK;
    /* defaults [A], docs/rider.md: MYMOSA gives no numbers ("the grip force ... the maximum a
     * human can produce grabbing a cylinder") */
    static const char *const names[5] = {"rider_seat", "rider_grip_l", "rider_grip_r",
                                         "rider_peg_l", "rider_peg_r"};
    static const char *const mounts[5][2] = {{"rider_h_point", "seat_h_point"},
                                             {"rider_grip_l", "grip_l"},
                                             {"rider_grip_r", "grip_r"},
                                             {"rider_peg_l", "peg_l"},
                                             {"rider_peg_r", "peg_r"}};
    double fail[5];
    fail[0] = mcs_node_num_or(block, "seat_failure_force", 1500);
    fail[1] = fail[2] = mcs_node_num_or(block, "grip_failure_force", 400);
    fail[3] = fail[4] = mcs_node_num_or(block, "peg_failure_force", 500);
    double k = mcs_node_num_or(block, "attachment_stiffness", 2e4);
    double c = mcs_node_num_or(block, "attachment_damping", 200);
    mb_attach_model *na = realloc(m->attach, (size_t)(m->nattach + 5) * sizeof *na);
    if (na) m->attach = na;
    mb_name *nn = na ? realloc(m->attach_name, (size_t)(m->nattach + 5) * sizeof *nn) : NULL;
    if (nn) m->attach_name = nn;
    if (!na || !nn) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    pos_ctx pc = {.m = m, .root = root, .block = block, .err = err};
    for (int i = 0; i < 5; i++) {
        mb_attach_model *a = &m->attach[m->nattach];
        int ba, bb;
        double pa[3], wa[3], pb[3], wb[3];
        mcs_status st = mount_get(&pc, mounts[i][0], &ba, pa, wa);
        if (!st) st = mount_get(&pc, mounts[i][1], &bb, pb, wb);
        if (st) return st;
        /* at rest: b's point where a's point is (they coincide to the positioning residual) */
        double R[9], dd[3];
        mb_quat_to_rot(m->body[bb].quat, R);
        mb_sub(wa, m->body[bb].pos, dd);
        mb_mat_tvec(R, dd, pb);
        *a = (mb_attach_model){.body_a = ba, .body_b = bb, .stiffness = k, .damping = c,
                               .fail_force = fail[i]};
        mb_copy(pa, a->pa), mb_copy(pb, a->pb);
        snprintf(m->attach_name[m->nattach], MB_NAME, "%s", names[i]);
        m->nattach++;
    }
    return MCS_OK;
}

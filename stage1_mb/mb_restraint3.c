/* mb_restraint3: three-axis restraints of spherical and universal joints (see the header). */
#include "stage1_mb/mb_restraint3.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>

void mb_rot_log(const double R[9], double theta[3])
{
    double v[3] = {0.5 * (R[7] - R[5]), 0.5 * (R[2] - R[6]), 0.5 * (R[3] - R[1])}; /* sin(a) u */
    double s = mb_norm(v), c = 0.5 * (R[0] + R[4] + R[8] - 1);
    double a = atan2(s, c);
    if (a < 1e-4) { /* a / sin(a) = 1 + a^2/6 + ... */
        mb_scale(v, 1 + a * a / 6, theta);
    } else if (a < M_PI - 1e-4) {
        mb_scale(v, a / s, theta);
    } else { /* near pi: the axis from the symmetric part (R + I)/2 = u u' */
        int k = 0;
        for (int i = 1; i < 3; i++)
            if (R[4 * i] > R[4 * k]) k = i;
        double u[3];
        for (int i = 0; i < 3; i++)
            u[i] = 0.25 * (R[3 * i + k] + R[3 * k + i]) + (i == k ? 0.5 : 0);
        mb_normalize(u);
        if (mb_dot(u, v) < 0) mb_scale(u, -1, u);
        mb_scale(u, a, theta);
    }
}

mcs_status mb_restraint3_check(const mb_restraint3_model *m, const mb_world *w, const char *name,
                               mcs_error *err)
{
    if (m->joint < 0 || m->joint >= mb_world_njoint(w) || !mb_joint_is_spherical(w, m->joint))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: three-axis restraint needs a spherical or universal joint (joint %d)",
                       name, m->joint);
    /* the frame must be a rotation: orthonormal columns, determinant +1 */
    const double *F = m->frame;
    double FtF[9];
    mb_mat_tmul(F, F, FtF);
    double det = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                 F[2] * (F[3] * F[7] - F[4] * F[6]);
    for (int i = 0; i < 9; i++)
        if (!(fabs(FtF[i] - (i % 4 == 0)) < 1e-6))
            return MCS_ERR(err, MCS_ERR_RANGE, "%s: restraint frame is not orthonormal", name);
    if (!(det > 0)) return MCS_ERR(err, MCS_ERR_RANGE, "%s: restraint frame is left-handed", name);
    for (int i = 0; i < 3; i++) {
        if (!(m->damping[i] >= 0) || !(m->stop_stiffness[i] >= 0) || !(m->stop_damping[i] >= 0) ||
            !isfinite(m->damping[i]) || !isfinite(m->stop_stiffness[i]) ||
            !isfinite(m->stop_damping[i]))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%s: axis %d: damping and stop values must be finite and >= 0", name, i);
        if (m->stop_stiffness[i] > 0 && !(m->lo[i] < m->hi[i]))
            return MCS_ERR(err, MCS_ERR_RANGE, "%s: axis %d: range [%g, %g] is empty", name, i,
                           m->lo[i], m->hi[i]);
        if (!isfinite(m->zero[i]) || !isfinite(m->preload[i]) ||
            (m->preload[i] != 0 && !m->has_spring[i]))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%s: axis %d: neutral angle and preload must be finite; a preload "
                           "needs a restraint characteristic",
                           name, i);
        if (m->has_spring[i]) {
            mcs_status st = mcs_hyst2_model_check(&m->spring[i], name, err);
            if (st != MCS_OK) return st;
        }
    }
    return MCS_OK;
}

/* parent and child rotation and angular velocity (the world: identity, at rest) */
static void joint_kin(const mb_world *w, int j, double Rp[9], double wp[3], double Rc[9],
                      double wc[3])
{
    int p, c;
    mb_joint_bodies(w, j, &p, &c);
    mb_body_kin k;
    if (p >= 0) {
        mb_body_get(w, p, &k);
        for (int i = 0; i < 9; i++)
            Rp[i] = k.rot[i];
        mb_copy(k.angvel, wp);
    } else {
        for (int i = 0; i < 9; i++)
            Rp[i] = (i % 4 == 0);
        wp[0] = wp[1] = wp[2] = 0;
    }
    mb_body_get(w, c, &k);
    for (int i = 0; i < 9; i++)
        Rc[i] = k.rot[i];
    mb_copy(k.angvel, wc);
}

void mb_restraint3_reset(const mb_restraint3_model *m, mb_restraint3_state *s, const mb_world *w)
{
    *s = (mb_restraint3_state){0};
    double Rp[9], Rc[9], wp[3], wc[3];
    joint_kin(w, m->joint, Rp, wp, Rc, wc);
    mb_mat_tmul(Rp, Rc, s->neutral);
    /* the histories start at the initial deflection theta - zero = -zero, so their work there
     * is the energy the initial posture already holds (as the energy at t = 0 counts it) */
    for (int i = 0; i < 3; i++)
        if (m->has_spring[i]) {
            mcs_hyst2_reset(&m->spring[i], &s->h[i]);
            if (m->zero[i] != 0) mcs_hyst2_update(&m->spring[i], &s->h[i], -m->zero[i]);
        }
}

static double stop_excess(double k, double lo, double hi, double x)
{
    if (k <= 0) return 0;
    return x > hi ? x - hi : x < lo ? x - lo : 0;
}

/* J^-1 v with J the left Jacobian of the rotation vector t (sign = +1), or J^-T v (sign = -1):
 * J^-1 = I - [t]x / 2 + c [t]x^2, c = 1/a^2 - (1 + cos a) / (2 a sin a) */
static void jac_inv(const double t[3], const double v[3], int sign, double out[3])
{
    double a = mb_norm(t), c;
    c = a < 1e-3 ? 1.0 / 12 + a * a / 720 : 1 / (a * a) - (1 + cos(a)) / (2 * a * sin(a));
    double tv[3], ttv[3];
    mb_cross(t, v, tv);
    mb_cross(t, tv, ttv);
    for (int k = 0; k < 3; k++)
        out[k] = v[k] - sign * 0.5 * tv[k] + c * ttv[k];
}

void mb_restraint3_apply(const mb_restraint3_model *m, mb_restraint3_state *s, mb_world *w,
                         double h)
{
    double Rp[9], Rc[9], wp[3], wc[3], A[9], Q[9], QF[9], T[9];
    joint_kin(w, m->joint, Rp, wp, Rc, wc);
    /* Q = Rp' Rc N' (relative rotation since reset, parent axes), on the restraint axes F' Q F */
    mb_mat_tmul(Rp, Rc, A);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            Q[3 * i + j] = A[3 * i] * s->neutral[3 * j] + A[3 * i + 1] * s->neutral[3 * j + 1] +
                           A[3 * i + 2] * s->neutral[3 * j + 2];
    mb_mat_tmul(m->frame, Q, T);
    mb_mat_mul(T, m->frame, QF);
    mb_rot_log(QF, s->theta);
    /* relative angular velocity on the restraint axes, then dtheta/dt = J^-1 omega */
    double dw[3], wpar[3], wF[3];
    mb_sub(wc, wp, dw);
    mb_mat_tvec(Rp, dw, wpar);
    mb_mat_tvec(m->frame, wpar, wF);
    jac_inv(s->theta, wF, 1, s->rate);
    /* generalised loads per axis */
    double g[3];
    for (int i = 0; i < 3; i++) {
        double x = s->theta[i], r = s->rate[i];
        double f = m->has_spring[i] ? m->preload[i] +
                                          mcs_hyst2_update(&m->spring[i], &s->h[i], x - m->zero[i])
                                    : 0;
        double fd = m->damping[i] * r, fs = 0, fsd = 0;
        double e = stop_excess(m->stop_stiffness[i], m->lo[i], m->hi[i], x);
        if (e != 0) {
            fs = m->stop_stiffness[i] * e;
            fsd = m->stop_damping[i] * r;
            if (fs * (fs + fsd) < 0) fsd = -fs; /* a stop only pushes back */
        }
        g[i] = f + fd + fs + fsd;
        s->load[i] = g[i];
        s->e_damp += (fd + fsd) * r * h;
    }
    /* torque on the child: -J^-T g on the restraint axes, to world */
    double tF[3], tP[3];
    jac_inv(s->theta, g, -1, tF);
    mb_scale(tF, -1, tF);
    mb_mat_vec(m->frame, tF, tP);
    mb_mat_vec(Rp, tP, s->torque);
    int p, c;
    mb_joint_bodies(w, m->joint, &p, &c);
    mb_body_add_torque(w, c, s->torque);
    if (p >= 0) {
        double tp[3];
        mb_scale(s->torque, -1, tp);
        mb_body_add_torque(w, p, tp);
    }
}

double mb_restraint3_stored(const mb_restraint3_model *m, const mb_restraint3_state *s)
{
    double e = 0;
    for (int i = 0; i < 3; i++) {
        double x = stop_excess(m->stop_stiffness[i], m->lo[i], m->hi[i], s->theta[i]);
        e += 0.5 * m->stop_stiffness[i] * x * x;
        if (m->has_spring[i])
            e += mcs_hyst2_stored(&m->spring[i], &s->h[i]) + m->preload[i] * s->theta[i];
    }
    return e;
}

double mb_restraint3_dissipated(const mb_restraint3_model *m, const mb_restraint3_state *s)
{
    double e = s->e_damp;
    for (int i = 0; i < 3; i++)
        if (m->has_spring[i]) e += mcs_hyst2_dissipated(&m->spring[i], &s->h[i]);
    return e;
}

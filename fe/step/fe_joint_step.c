/* fe_joint_step.c: the penalty joint loads of one step (fe_joint.h): from the bodies' poses at
 * t and velocities at t - dt/2 to the loads on the bodies (state body_fj), the joints' outputs
 * and their energies. */
#include "fe/fe_elem.h"
#include "fe/fe_joint.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <string.h>

/* a body's pose and velocity at t (ground: identity, at rest) */
typedef struct {
    double x[3], R[3][3], v[3], w[3];
} pose;

static void get_pose(const fe_model *m, const fe_state *s, int b, pose *p)
{
    memset(p, 0, sizeof *p);
    for (int i = 0; i < 3; i++)
        p->R[i][i] = 1;
    if (b < 0) return;
    memcpy(p->x, s->body_x + 3 * b, sizeof p->x);
    memcpy(p->R, s->body_rot + 9 * b, sizeof p->R);
    memcpy(p->v, s->body_v + 3 * b, sizeof p->v);
    memcpy(p->w, s->body_w + 3 * b, sizeof p->w);
    (void)m;
}

static void rot(const double R[3][3], const double a[3], double o[3])
{
    for (int i = 0; i < 3; i++)
        o[i] = R[i][0] * a[0] + R[i][1] * a[1] + R[i][2] * a[2];
}

/* the rotation vector of R_A R_B^T (both from t = 0) */
static void rel_rotvec(const double A[3][3], const double B[3][3], double phi[3])
{
    double R[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = A[i][0] * B[j][0] + A[i][1] * B[j][1] + A[i][2] * B[j][2];
    double v[3] = {R[2][1] - R[1][2], R[0][2] - R[2][0], R[1][0] - R[0][1]};
    double c = 0.5 * (R[0][0] + R[1][1] + R[2][2] - 1), sn = 0.5 * sqrt(fe_dot(v, v));
    double th = atan2(sn, c), f = sn > 1e-12 ? th / (2 * sn) : 0.5;
    for (int i = 0; i < 3; i++)
        phi[i] = f * v[i];
}

static double wrap(double a)
{
    return a - 2 * M_PI * floor((a + M_PI) / (2 * M_PI));
}

/* the load on a body: force f at point P, moment mo */
static void load(fe_state *s, int b, const double P[3], const double f[3], const double mo[3])
{
    if (b < 0) return;
    double r[3], c[3];
    for (int i = 0; i < 3; i++)
        r[i] = P[i] - s->body_x[3 * b + i];
    fe_cross(r, f, c);
    double *o = s->body_fj + 6 * b;
    for (int i = 0; i < 3; i++)
        o[i] += f[i], o[3 + i] += c[i] + mo[i];
}

/* the free coordinate's spring, damper and stops: generalised force and stored energy */
static double free_force(const fe_joint *J, double q, double qd, double *eel, double *fdamp)
{
    double f = -J->ks * q;
    *eel += 0.5 * J->ks * q * q;
    if (J->has_range && q < J->range[0]) {
        f += J->kstop * (J->range[0] - q);
        *eel += 0.5 * J->kstop * (J->range[0] - q) * (J->range[0] - q);
    } else if (J->has_range && q > J->range[1]) {
        f -= J->kstop * (q - J->range[1]);
        *eel += 0.5 * J->kstop * (q - J->range[1]) * (q - J->range[1]);
    }
    *fdamp = -J->cs * qd;
    return f;
}

static void one_joint(const fe_model *m, fe_state *s, int j, double *e_el, double *p_diss)
{
    const fe_joint *J = &m->joint[j];
    double *out = s->joint_out + FE_JOUT_N * j;
    pose A, B;
    get_pose(m, s, J->body[0], &A);
    get_pose(m, s, J->body[1], &B);
    double rA[3], rB[3], PA[3], PB[3], aA[3], aB[3], uA[3], uB[3];
    rot(A.R, J->r[0], rA);
    rot(B.R, J->r[1], rB);
    rot(A.R, J->axis, aA);
    rot(B.R, J->axis, aB);
    rot(A.R, J->perp, uA);
    rot(B.R, J->perp, uB);
    /* velocities of the joint point P_A as a point of A and of B */
    double cA[3], cB[3], vrel[3], wrel[3], d[3];
    fe_cross(A.w, rA, cA);
    for (int i = 0; i < 3; i++)
        PA[i] = A.x[i] + rA[i], PB[i] = B.x[i] + rB[i];
    double rBA[3] = {PA[0] - B.x[0], PA[1] - B.x[1], PA[2] - B.x[2]};
    fe_cross(B.w, rBA, cB);
    for (int i = 0; i < 3; i++) {
        vrel[i] = A.v[i] + cA[i] - B.v[i] - cB[i];
        wrel[i] = A.w[i] - B.w[i];
        d[i] = PA[i] - PB[i];
    }
    const int slide = J->type == FE_JOINT_CYLINDRICAL || J->type == FE_JOINT_TRANSLATIONAL;
    double s_ax = fe_dot(d, aB), sd = fe_dot(vrel, aB), wa = fe_dot(wrel, aB);
    /* point: the gap (across the axis for sliding joints) */
    double F[3], Fd[3], Mo[3] = {0, 0, 0}, Md[3] = {0, 0, 0}, eel = 0;
    for (int i = 0; i < 3; i++) {
        double e = d[i] - (slide ? s_ax * aB[i] : 0), ed = vrel[i] - (slide ? sd * aB[i] : 0);
        F[i] = -J->k * e, Fd[i] = -J->c * ed;
        eel += 0.5 * J->k * e * e;
    }
    /* rotation: the axes aligned, or (translational) the whole rotation locked */
    if (J->type != FE_JOINT_SPHERICAL) {
        double er[3], erd[3];
        if (J->type == FE_JOINT_TRANSLATIONAL) {
            rel_rotvec(A.R, B.R, er);
            memcpy(erd, wrel, sizeof erd);
        } else {
            fe_cross(aB, aA, er);
            for (int i = 0; i < 3; i++)
                erd[i] = wrel[i] - wa * aB[i];
        }
        for (int i = 0; i < 3; i++) {
            Mo[i] = -J->kr * er[i], Md[i] = -J->cr * erd[i];
            eel += 0.5 * J->kr * er[i] * er[i];
        }
    }
    /* the free coordinates: slide and angle (unwrapped from the last value) */
    double ang = 0, uc[3];
    fe_cross(uB, uA, uc);
    ang = atan2(fe_dot(uc, aB), fe_dot(uB, uA));
    ang = out[FE_JOUT_ANGLE] + wrap(ang - wrap(out[FE_JOUT_ANGLE]));
    double fq = 0, fqd = 0;
    if (slide) {
        fq = free_force(J, s_ax, sd, &eel, &fqd);
        for (int i = 0; i < 3; i++)
            F[i] += fq * aB[i], Fd[i] += fqd * aB[i];
    } else if (J->type == FE_JOINT_REVOLUTE) {
        fq = free_force(J, ang, wa, &eel, &fqd);
        for (int i = 0; i < 3; i++)
            Mo[i] += fq * aB[i], Md[i] += fqd * aB[i];
    }
    /* loads: A gets F at P_A and M, B the opposite at the same point */
    double Ft[3], Mt[3], nF[3], nM[3];
    for (int i = 0; i < 3; i++) {
        Ft[i] = F[i] + Fd[i], Mt[i] = Mo[i] + Md[i], nF[i] = -Ft[i], nM[i] = -Mt[i];
        out[FE_JOUT_FORCE + i] = Ft[i];
        out[FE_JOUT_MOMENT + i] = Mt[i];
    }
    load(s, J->body[0], PA, Ft, Mt);
    load(s, J->body[1], PA, nF, nM);
    out[FE_JOUT_SLIDE] = s_ax;
    out[FE_JOUT_ANGLE] = ang;
    out[FE_JOUT_EEL] = eel;
    /* damper power at t - dt/2 (>= 0) */
    double pw = -(fe_dot(Fd, vrel) + fe_dot(Md, wrel));
    out[FE_JOUT_EDISS] += pw * s->dt_prev;
    *e_el += eel;
    *p_diss += pw * s->dt_prev;
}

void fe_joint_forces(const fe_model *m, fe_state *s)
{
    if (m->njoint == 0) return;
    memset(s->body_fj, 0, sizeof(double) * 6 * (size_t)m->nbody);
    double e_el = 0, diss = 0, e_old = 0;
    for (int j = 0; j < m->njoint; j++)
        e_old += s->joint_out[FE_JOUT_N * j + FE_JOUT_EEL];
    for (int j = 0; j < m->njoint; j++)
        one_joint(m, s, j, &e_el, &diss);
    /* stored energy as a level (its change this step), dissipation summed */
    s->free_energy[FE_E_internal] += e_el - e_old;
    s->free_energy[FE_E_dissipated] += diss;
}

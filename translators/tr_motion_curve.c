/* tr_motion_curve.c: the two prescribed-motion curves on one sample interval [t_i, t_i+1]
 * (tr_motion.h gives the schemes and their orders) and the pulse integral at the samples. */
#include "translators/tr_motion_internal.h"

#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <string.h>

/* q = exp(th) q0 with its rates, into k */
static void rotate(const double th[3], const double thd[3], const double thdd[3],
                   const double q0[4], tr_motion_kin *k)
{
    double e[4];
    tr_q_exp(th, e);
    tr_q_mul(e, q0, k->quat);
    double n = sqrt(k->quat[0] * k->quat[0] + k->quat[1] * k->quat[1] + k->quat[2] * k->quat[2] +
                    k->quat[3] * k->quat[3]);
    for (int j = 0; j < 4; j++)
        k->quat[j] /= n;
    tr_q_to_rot(k->quat, k->rot);
    tr_so3_rates(th, thd, thdd, k->angvel, k->angacc);
}

void tr_motion_pose_eval(const struct tr_motion *m, const tr_motion_body_data *b, int i, double t,
                         tr_motion_kin *k)
{
    double h = m->t[i + 1] - m->t[i], s = (t - m->t[i]) / h;
    /* position: cubic Hermite through the written positions and velocities */
    tr_hermite3(b->pos + 3 * i, b->vel + 3 * i, b->pos + 3 * (i + 1), b->vel + 3 * (i + 1), h, s,
                k->pos, k->vel, k->acc);
    /* orientation: Hermite in the rotation vector from q_i, ends matching q_i+1 and the w's */
    const double *q0 = b->quat + 4 * i, *q1 = b->quat + 4 * (i + 1);
    double c0[4] = {q0[0], -q0[1], -q0[2], -q0[3]}, r[4], th1[3], m1[3], zero[3] = {0, 0, 0};
    tr_q_mul(q1, c0, r);
    tr_q_log(r, th1);
    tr_so3_jinv(th1, b->angvel + 3 * (i + 1), m1);
    double th[3], thd[3], thdd[3];
    tr_hermite3(zero, b->angvel + 3 * i, th1, m1, h, s, th, thd, thdd);
    rotate(th, thd, thdd, q0, k);
}

/* the pulse's rotation vector from Q_i over tau: 4th-order Magnus of the linear w */
static void magnus(const double w0[3], const double w1[3], double h, double tau, double th[3],
                   double thd[3], double thdd[3])
{
    double dw[3], c[3];
    mb_sub(w1, w0, dw);
    mb_cross(w0, dw, c);
    for (int j = 0; j < 3; j++) {
        th[j] = tau * w0[j] + tau * tau / (2 * h) * dw[j] - tau * tau * tau / (12 * h) * c[j];
        thd[j] = w0[j] + tau / h * dw[j] - tau * tau / (4 * h) * c[j];
        thdd[j] = dw[j] / h - tau / (2 * h) * c[j];
    }
}

void tr_motion_pulse_eval(const struct tr_motion *m, const tr_motion_body_data *b, int i, double t,
                          tr_motion_kin *k)
{
    double h = m->t[i + 1] - m->t[i], s = (t - m->t[i]) / h, s2 = s * s, s3 = s2 * s;
    /* linear acceleration: the quadratic from the edge values A_i, A_i+1 whose mean over the
     * interval is the written mean, a(s) = A_i (1 - s) + A_i+1 s + 6 c s (1 - s),
     * c = mean - (A_i + A_i+1) / 2; integrated exactly from P_i, V_i */
    const double *a0 = b->aedge + 3 * i, *a1 = b->aedge + 3 * (i + 1), *am = b->acc + 3 * (i + 1);
    const double *p0 = b->ipos + 3 * i, *v0 = b->ivel + 3 * i;
    for (int j = 0; j < 3; j++) {
        double c = am[j] - 0.5 * (a0[j] + a1[j]);
        k->acc[j] = a0[j] * (1 - s) + a1[j] * s + 6 * c * (s - s2);
        k->vel[j] = v0[j] + h * (a0[j] * (s - 0.5 * s2) + a1[j] * 0.5 * s2 + c * (3 * s2 - 2 * s3));
        k->pos[j] = p0[j] + h * (v0[j] * s + h * (a0[j] * (0.5 * s2 - s3 / 6) + a1[j] * s3 / 6 +
                                                  c * (s3 - 0.5 * s2 * s2)));
    }
    double th[3], thd[3], thdd[3];
    magnus(b->angvel + 3 * i, b->angvel + 3 * (i + 1), h, t - m->t[i], th, thd, thdd);
    rotate(th, thd, thdd, b->iquat + 4 * i, k);
}

/* the acceleration at the samples from the interval means M_k (row k > 0) and a(t_0) (row 0):
 * inside, the linear interpolation of the means at the intervals' midpoints, A_k =
 * (M_k h_k+1 + M_k+1 h_k) / (h_k + h_k+1); at the end their linear extrapolation; at t_0 the
 * written a(t_0). Exact for a linear a(t). */
static void accel_edges(const struct tr_motion *m, tr_motion_body_data *b)
{
    int n = m->nt - 1; /* intervals */
    const double *M = b->acc;
    memcpy(b->aedge, b->acc, 3 * sizeof(double));
    for (int k = 1; k < n; k++) {
        double hk = m->t[k] - m->t[k - 1], hn = m->t[k + 1] - m->t[k];
        for (int j = 0; j < 3; j++)
            b->aedge[3 * k + j] = (M[3 * k + j] * hn + M[3 * (k + 1) + j] * hk) / (hk + hn);
    }
    for (int j = 0; j < 3; j++) {
        double e = M[3 * n + j];
        if (n > 1) {
            double hl = m->t[n] - m->t[n - 1], hp = m->t[n - 1] - m->t[n - 2];
            e += (M[3 * n + j] - M[3 * (n - 1) + j]) * hl / (hl + hp);
        }
        b->aedge[3 * n + j] = e;
    }
}

void tr_motion_pulse_integrate(const struct tr_motion *m, tr_motion_body_data *b)
{
    accel_edges(m, b);
    memcpy(b->ipos, b->pos, 3 * sizeof(double));
    memcpy(b->ivel, b->vel, 3 * sizeof(double));
    memcpy(b->iquat, b->quat, 4 * sizeof(double));
    memset(&b->drift, 0, sizeof b->drift);
    b->drift.t_pos = b->drift.t_angle = m->t[0];
    for (int i = 0; i + 1 < m->nt; i++) {
        tr_motion_kin k;
        tr_motion_pulse_eval(m, b, i, m->t[i + 1], &k);
        memcpy(b->ipos + 3 * (i + 1), k.pos, sizeof k.pos);
        memcpy(b->ivel + 3 * (i + 1), k.vel, sizeof k.vel);
        memcpy(b->iquat + 4 * (i + 1), k.quat, sizeof k.quat);
        double dp[3], dv[3];
        mb_sub(k.pos, b->pos + 3 * (i + 1), dp);
        mb_sub(k.vel, b->vel + 3 * (i + 1), dv);
        double ep = mb_norm(dp), ev = mb_norm(dv),
               ea = tr_quat_angle(k.quat, b->quat + 4 * (i + 1));
        if (ep > b->drift.pos) b->drift.pos = ep, b->drift.t_pos = m->t[i + 1];
        if (ea > b->drift.angle) b->drift.angle = ea, b->drift.t_angle = m->t[i + 1];
        if (ev > b->drift.vel) b->drift.vel = ev;
    }
}

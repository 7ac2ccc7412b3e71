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

/* the pulse's rotation vector from Q_i over tau for w(tau) = sum_n c_n tau^n (n < 4): the
 * Magnus series to its second term, theta = W1 + W2, W1 = int_0^tau w, W2 = 1/2 int_0^tau ds
 * int_0^s du w(s) x w(u) = 1/2 sum_mn c_m x c_n tau^(m+n+2) / ((n+1)(m+n+2)) (4th order;
 * exact for constant spin); theta' = w + w x W1 / 2, theta'' = w' + w' x W1 / 2 */
static void magnus(const double c[4][3], double tau, double th[3], double thd[3], double thdd[3])
{
    double w[3] = {0, 0, 0}, wd[3] = {0, 0, 0}, w1[3] = {0, 0, 0}, tp[7], x[3], y[3];
    tp[0] = 1;
    for (int n = 1; n < 7; n++)
        tp[n] = tp[n - 1] * tau;
    for (int n = 0; n < 4; n++)
        for (int j = 0; j < 3; j++) {
            w[j] += c[n][j] * tp[n];
            w1[j] += c[n][j] * tp[n + 1] / (n + 1);
            if (n) wd[j] += n * c[n][j] * tp[n - 1];
        }
    for (int j = 0; j < 3; j++)
        th[j] = w1[j];
    for (int mm = 0; mm < 4; mm++)
        for (int n = 0; n < 4; n++) {
            if (mm == n) continue;
            mb_cross(c[mm], c[n], x);
            double f = 0.5 * tau * tp[mm + n + 1] / ((n + 1) * (mm + n + 2));
            for (int j = 0; j < 3; j++)
                th[j] += f * x[j];
        }
    mb_cross(w, w1, x);
    mb_cross(wd, w1, y);
    for (int j = 0; j < 3; j++)
        thd[j] = w[j] + 0.5 * x[j], thdd[j] = wd[j] + 0.5 * y[j];
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
    /* angular velocity: the cubic Hermite through w_i, w_i+1 with the slopes W_i, W_i+1 */
    const double *w0 = b->angvel + 3 * i, *w1 = b->angvel + 3 * (i + 1);
    const double *d0 = b->wedge + 3 * i, *d1 = b->wedge + 3 * (i + 1);
    double c[4][3], th[3], thd[3], thdd[3];
    for (int j = 0; j < 3; j++) {
        double sl = (w1[j] - w0[j]) / h;
        c[0][j] = w0[j], c[1][j] = d0[j];
        c[2][j] = (3 * sl - 2 * d0[j] - d1[j]) / h;
        c[3][j] = (d0[j] + d1[j] - 2 * sl) / (h * h);
    }
    magnus(c, t - m->t[i], th, thd, thdd);
    rotate(th, thd, thdd, b->iquat + 4 * i, k);
}

/* the rate of a sampled quantity at the samples from its interval means, in place: E's rows
 * k > 0 hold the means M_k over [t_k-1, t_k] and become, inside, the means interpolated
 * linearly between the intervals' midpoints, E_k = (M_k h_k+1 + M_k+1 h_k) / (h_k + h_k+1)
 * (the 3-point derivative when M_k = (x_k - x_k-1) / h_k), at the end extrapolated the same
 * way; row 0 is kept when keep0, else extrapolated too. Exact for a linear rate. */
static void rate_edges(const double *t, int nt, double *E, int keep0)
{
    int n = nt - 1; /* intervals */
    for (int j = 0; j < 3; j++) {
        double mn = E[3 * n + j], e = mn, f = E[3 + j];
        if (n > 1) {
            double hl = t[n] - t[n - 1], hp = t[n - 1] - t[n - 2];
            e += (mn - E[3 * (n - 1) + j]) * hl / (hl + hp);
            double hf = t[1] - t[0], hs = t[2] - t[1];
            f -= (E[6 + j] - E[3 + j]) * hf / (hf + hs);
        }
        if (!keep0) E[j] = f;
        for (int k = 1; k < n; k++) {
            double hk = t[k] - t[k - 1], hn = t[k + 1] - t[k];
            E[3 * k + j] = (E[3 * k + j] * hn + E[3 * (k + 1) + j] * hk) / (hk + hn);
        }
        E[3 * n + j] = e;
    }
}

/* the acceleration at the samples (A_0 = the written a(t_0)) and the angular velocity's slopes
 * (from its interval means (w_k - w_k-1) / h_k) */
static void pulse_edges(const struct tr_motion *m, tr_motion_body_data *b)
{
    memcpy(b->aedge, b->acc, sizeof(double) * 3 * (size_t)m->nt);
    rate_edges(m->t, m->nt, b->aedge, 1);
    for (int k = 1; k < m->nt; k++)
        for (int j = 0; j < 3; j++)
            b->wedge[3 * k + j] =
                (b->angvel[3 * k + j] - b->angvel[3 * (k - 1) + j]) / (m->t[k] - m->t[k - 1]);
    rate_edges(m->t, m->nt, b->wedge, 0);
}

void tr_motion_pulse_integrate(const struct tr_motion *m, tr_motion_body_data *b)
{
    pulse_edges(m, b);
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

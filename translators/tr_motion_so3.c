/* tr_motion_so3.c: quaternions, the SO(3) exponential, its left Jacobian and the cubic Hermite
 * used by the prescribed-motion curves (tr_motion.h). For R = exp([th]x) R0 the world angular
 * velocity is w = J(th) th' with J = I + A [th]x + B [th]x^2, A = (1 - cos p)/p^2,
 * B = (p - sin p)/p^3, p = |th| (Chirikjian, Stochastic Models, Information Theory and Lie
 * Groups vol. 2, 2012, Sec. 10.6; Sola et al., "A micro Lie theory", arXiv:1812.01537, Eq. 145),
 * and J^-1 = I - [th]x / 2 + C [th]x^2, C = (1 - (p/2) cot(p/2)) / p^2 (ibid. Eq. 146). */
#include "translators/tr_motion_internal.h"

#include "stage1_mb/mb_vec.h"

#include <math.h>

void tr_q_mul(const double a[4], const double b[4], double out[4])
{
    double w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    double x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    double y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    double z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    out[0] = w, out[1] = x, out[2] = y, out[3] = z;
}

void tr_q_exp(const double th[3], double q[4])
{
    double p = mb_norm(th), p2 = p * p;
    /* sin(p/2)/p by its series below 1e-3 (relative error < 1e-14) */
    double s = p < 1e-3 ? 0.5 * (1 - p2 / 24 + p2 * p2 / 1920) : sin(0.5 * p) / p;
    q[0] = cos(0.5 * p);
    q[1] = s * th[0], q[2] = s * th[1], q[3] = s * th[2];
}

void tr_q_log(const double q[4], double th[3])
{
    double sg = q[0] < 0 ? -1.0 : 1.0; /* q and -q: the same rotation; the shorter one */
    double w = sg * q[0], v[3] = {sg * q[1], sg * q[2], sg * q[3]};
    double vn = mb_norm(v);
    double f = vn < 1e-8 ? 2.0 / w : 2.0 * atan2(vn, w) / vn;
    mb_scale(v, f, th);
}

void tr_q_to_rot(const double q[4], double R[9])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}

/* A, B of J and a1 = A'(p)/p, b1 = B'(p)/p; series below p = 0.5 (the closed forms cancel
 * to ~eps/p^4 there; 9 terms leave < 1e-19) */
static void jac_coef(double p, double *A, double *B, double *a1, double *b1)
{
    if (p < 0.5) {
        double p2 = p * p, pw = 1, pwm = 0, fact = 2; /* pw = p2^k, fact = (2k+2)! */
        *A = *B = *a1 = *b1 = 0;
        for (int k = 0; k < 9; k++) {
            double sg = (k & 1) ? -1 : 1, fa = 1 / fact, fb = 1 / (fact * (2 * k + 3));
            *A += sg * pw * fa, *B += sg * pw * fb;
            *a1 += sg * 2 * k * pwm * fa, *b1 += sg * 2 * k * pwm * fb;
            pwm = pw, pw *= p2, fact *= (2 * k + 3) * (2 * k + 4);
        }
        return;
    }
    double c = cos(p), s = sin(p), p2 = p * p, p4 = p2 * p2;
    *A = (1 - c) / p2;
    *B = (p - s) / (p2 * p);
    *a1 = (p * s - 2 + 2 * c) / p4;
    *b1 = (1 - c) / p4 - 3 * (p - s) / (p4 * p);
}

void tr_so3_rates(const double th[3], const double thd[3], const double thdd[3], double w[3],
                  double al[3])
{
    double A, B, a1, b1, c1[3], c2[3], e1[3], e2[3], f[3];
    jac_coef(mb_norm(th), &A, &B, &a1, &b1);
    double d = mb_dot(th, thd); /* p p' */
    mb_cross(th, thd, c1);      /* th x th'        */
    mb_cross(th, c1, c2);       /* th x (th x th') */
    for (int i = 0; i < 3; i++)
        w[i] = thd[i] + A * c1[i] + B * c2[i];
    /* d/dt: A' p' = a1 d; d/dt (th x (th x th')) = th' x c1 + th x (th x th'') */
    mb_cross(th, thdd, e1);
    mb_cross(th, e1, e2);
    mb_cross(thd, c1, f);
    for (int i = 0; i < 3; i++)
        al[i] = thdd[i] + a1 * d * c1[i] + A * e1[i] + b1 * d * c2[i] + B * (f[i] + e2[i]);
}

void tr_so3_jinv(const double th[3], const double w[3], double thd[3])
{
    double p = mb_norm(th), p2 = p * p, C, c1[3], c2[3];
    if (p < 0.5)
        C = 1.0 / 12 + p2 / 720 + p2 * p2 / 30240 + p2 * p2 * p2 / 1209600 +
            p2 * p2 * p2 * p2 / 47900160;
    else
        C = (1 - 0.5 * p * cos(0.5 * p) / sin(0.5 * p)) / p2;
    mb_cross(th, w, c1);
    mb_cross(th, c1, c2);
    for (int i = 0; i < 3; i++)
        thd[i] = w[i] - 0.5 * c1[i] + C * c2[i];
}

void tr_hermite3(const double x0[3], const double m0[3], const double x1[3], const double m1[3],
                 double h, double s, double x[3], double xd[3], double xdd[3])
{
    double s2 = s * s, s3 = s2 * s;
    double h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d11 = 3 * s2 - 2 * s;
    double e00 = 12 * s - 6, e10 = 6 * s - 4, e11 = 6 * s - 2;
    for (int i = 0; i < 3; i++) {
        double dx = x1[i] - x0[i]; /* h00 x0 + h01 x1 = x0 + h01 (x1 - x0) */
        x[i] = x0[i] + h01 * dx + h * (h10 * m0[i] + h11 * m1[i]);
        xd[i] = -d00 * dx / h + d10 * m0[i] + d11 * m1[i];
        xdd[i] = (-e00 * dx / h + e10 * m0[i] + e11 * m1[i]) / h;
    }
}

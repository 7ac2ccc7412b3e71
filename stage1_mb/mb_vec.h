/* mb_vec.h: small inline 3-vector and 3x3 matrix helpers for stage 1 (row-major 3x3). */
#ifndef MB_VEC_H
#define MB_VEC_H

#include <math.h>

static inline double mb_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void mb_cross(const double a[3], const double b[3], double out[3])
{
    double x = a[1] * b[2] - a[2] * b[1];
    double y = a[2] * b[0] - a[0] * b[2];
    double z = a[0] * b[1] - a[1] * b[0];
    out[0] = x, out[1] = y, out[2] = z;
}

static inline double mb_norm(const double a[3])
{
    return sqrt(mb_dot(a, a));
}

static inline void mb_sub(const double a[3], const double b[3], double out[3])
{
    out[0] = a[0] - b[0], out[1] = a[1] - b[1], out[2] = a[2] - b[2];
}

static inline void mb_add(const double a[3], const double b[3], double out[3])
{
    out[0] = a[0] + b[0], out[1] = a[1] + b[1], out[2] = a[2] + b[2];
}

/* out = a + s b */
static inline void mb_axpy(const double a[3], double s, const double b[3], double out[3])
{
    out[0] = a[0] + s * b[0], out[1] = a[1] + s * b[1], out[2] = a[2] + s * b[2];
}

static inline void mb_scale(const double a[3], double s, double out[3])
{
    out[0] = s * a[0], out[1] = s * a[1], out[2] = s * a[2];
}

static inline void mb_copy(const double a[3], double out[3])
{
    out[0] = a[0], out[1] = a[1], out[2] = a[2];
}

/* normalise in place; returns the former length (0 leaves a unchanged) */
static inline double mb_normalize(double a[3])
{
    double l = mb_norm(a);
    if (l > 0) mb_scale(a, 1.0 / l, a);
    return l;
}

/* out = M v (M row-major 3x3) */
static inline void mb_mat_vec(const double M[9], const double v[3], double out[3])
{
    double x = M[0] * v[0] + M[1] * v[1] + M[2] * v[2];
    double y = M[3] * v[0] + M[4] * v[1] + M[5] * v[2];
    double z = M[6] * v[0] + M[7] * v[1] + M[8] * v[2];
    out[0] = x, out[1] = y, out[2] = z;
}

/* out = M^T v */
static inline void mb_mat_tvec(const double M[9], const double v[3], double out[3])
{
    double x = M[0] * v[0] + M[3] * v[1] + M[6] * v[2];
    double y = M[1] * v[0] + M[4] * v[1] + M[7] * v[2];
    double z = M[2] * v[0] + M[5] * v[1] + M[8] * v[2];
    out[0] = x, out[1] = y, out[2] = z;
}

/* out = A^T B (out may not alias) */
static inline void mb_mat_tmul(const double A[9], const double B[9], double out[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[3 * i + j] = A[i] * B[j] + A[3 + i] * B[3 + j] + A[6 + i] * B[6 + j];
}

/* out = A B (out may not alias) */
static inline void mb_mat_mul(const double A[9], const double B[9], double out[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

/* a scenario's quaternion w, x, y, z made unit; all zero: the identity */
static inline void mb_quat_unit(const double in[4], double q[4])
{
    double l = sqrt(in[0] * in[0] + in[1] * in[1] + in[2] * in[2] + in[3] * in[3]);
    if (l == 0) {
        q[0] = 1, q[1] = q[2] = q[3] = 0;
        return;
    }
    for (int i = 0; i < 4; i++)
        q[i] = in[i] / l;
}

/* rotation matrix (row-major, body->world) from a unit quaternion w, x, y, z */
static inline void mb_quat_to_rot(const double q[4], double R[9])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}

/* rotation of angle (rad) about a unit axis (Rodrigues), row-major */
static inline void mb_rot_axis_angle(const double ax[3], double ang, double R[9])
{
    double c = cos(ang), s = sin(ang), t = 1 - c, x = ax[0], y = ax[1], z = ax[2];
    R[0] = t * x * x + c, R[1] = t * x * y - s * z, R[2] = t * x * z + s * y;
    R[3] = t * x * y + s * z, R[4] = t * y * y + c, R[5] = t * y * z - s * x;
    R[6] = t * x * z - s * y, R[7] = t * y * z + s * x, R[8] = t * z * z + c;
}

#endif

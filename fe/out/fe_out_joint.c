/* fe_out_joint.c: joint loads and rigid-body motion into /stage<N> (fe_out_joint.h) */
#include "fe/out/fe_out_joint.h"
#include "fe/fe_elem.h"
#include "fe/fe_joint.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char *const jwhat[5] = {"force", "moment", "displacement", "angle", "time"};
static const char *const junit[5] = {"N", "N m", "m", "rad", "s"};
static const char *const bwhat[5] = {"position", "orientation", "velocity", "angular_velocity",
                                     "acceleration"};
static const char *const bunit[5] = {"m", "-", "m/s", "rad/s", "m/s^2"};
static const size_t bcols[5] = {3, 4, 3, 3, 3};

mcs_status fe_out_joint_open(mcs_results *r, int stage, const fe_model *m, fe_out_joint *o,
                             mcs_error *err)
{
    *o = (fe_out_joint){0};
    o->tprev = -1;
    if (m->njoint == 0 && m->nbody == 0) return MCS_OK;
    /* /stage1 and /stage2 have their own bodies (the multibody's): joints only there */
    o->nj = m->njoint, o->nb = stage == 3 ? m->nbody : 0;
    o->jser = calloc((size_t)(5 * o->nj + 1), sizeof *o->jser);
    o->bser = calloc((size_t)(5 * o->nb + 1), sizeof *o->bser);
    o->vprev = calloc((size_t)(3 * o->nb + 1), sizeof *o->vprev);
    if (!o->jser || !o->bser || !o->vprev)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage %d: out of memory (joints)", stage);
    mcs_status st = MCS_OK;
    char path[256];
    const size_t three = 3;
    for (int j = 0; j < o->nj && !st; j++) {
        const fe_joint *J = &m->joint[j];
        const int has[5] = {1, 1,
                            J->type == FE_JOINT_CYLINDRICAL || J->type == FE_JOINT_TRANSLATIONAL,
                            J->type == FE_JOINT_REVOLUTE || J->type == FE_JOINT_CYLINDRICAL, 1};
        for (int k = 0; k < 5 && !st; k++) {
            if (!has[k]) continue;
            snprintf(path, sizeof path, "/stage%d/joints/%s/%s", stage, J->name, jwhat[k]);
            st = mcs_results_series_create(r, path, k < 2 ? 2 : 1, k < 2 ? &three : NULL, junit[k],
                                           0, &o->jser[5 * j + k], err);
        }
        if (!st) {
            snprintf(path, sizeof path, "/stage%d/joints/%s", stage, J->name);
            st = mcs_results_set_attr_str(r, path, "type", fe_joint_type_name[J->type], err);
        }
    }
    for (int b = 0; b < o->nb && !st; b++)
        for (int k = 0; k < 5 && !st; k++) {
            snprintf(path, sizeof path, "/stage%d/bodies/%s/%s", stage, m->body[b].name, bwhat[k]);
            st = mcs_results_series_create(r, path, 2, &bcols[k], bunit[k], 0, &o->bser[5 * b + k],
                                           err);
        }
    return st;
}

/* R = exp(skew(phi)) A (Rodrigues) */
static void turn(const double phi[3], const double A[3][3], double R[3][3])
{
    double th = sqrt(fe_dot(phi, phi)), E[3][3];
    double a = th > 1e-8 ? sin(th) / th : 1, c = th > 1e-8 ? (1 - cos(th)) / (th * th) : 0.5;
    const double K[3][3] = {{0, -phi[2], phi[1]}, {phi[2], 0, -phi[0]}, {-phi[1], phi[0], 0}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double k2 = K[i][0] * K[0][j] + K[i][1] * K[1][j] + K[i][2] * K[2][j];
            E[i][j] = (i == j) + a * K[i][j] + c * k2;
        }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = E[i][0] * A[0][j] + E[i][1] * A[1][j] + E[i][2] * A[2][j];
}

/* quaternion w, x, y, z of a rotation matrix (Shepperd) */
static void quat(const double R[3][3], double q[4])
{
    double tr = R[0][0] + R[1][1] + R[2][2];
    if (tr > 0) {
        double s = 2 * sqrt(tr + 1);
        q[0] = 0.25 * s, q[1] = (R[2][1] - R[1][2]) / s, q[2] = (R[0][2] - R[2][0]) / s;
        q[3] = (R[1][0] - R[0][1]) / s;
    } else {
        int i = R[1][1] > R[0][0] ? 1 : 0;
        if (R[2][2] > R[i][i]) i = 2;
        int j = (i + 1) % 3, k = (i + 2) % 3;
        double s = 2 * sqrt(1 + R[i][i] - R[j][j] - R[k][k]);
        q[0] = (R[k][j] - R[j][k]) / s;
        q[1 + i] = 0.25 * s;
        q[1 + j] = (R[j][i] + R[i][j]) / s;
        q[1 + k] = (R[k][i] + R[i][k]) / s;
    }
}

/* body b at t_n (the state is at t_n+1 with velocities at t_n+1/2 and loads at t_n) */
static void body_at_tn(const fe_model *m, const fe_state *s, int b, double row[16])
{
    const double h = s->dt_prev, M = m->body[b].mass, *V = s->body_v + 3 * b;
    const double *W = s->body_w + 3 * b, *F = s->body_fm + 6 * b;
    double R1[3][3], R[3][3], phi[3];
    for (int i = 0; i < 9; i++)
        R1[i / 3][i % 3] = s->body_rot[9 * b + i];
    for (int i = 0; i < 3; i++)
        phi[i] = -h * W[i];
    turn(phi, R1, R);
    const unsigned fix = m->body[b].fix;
    for (int i = 0; i < 3; i++) {
        /* a fixed (prescribed) translation moves at its prescribed velocity: V holds it
         * (fe_rigid.c), and F there is the constraint's reaction, not an acceleration */
        const int held = (fix >> i) & 1u;
        row[i] = s->body_x[3 * b + i] - h * V[i];
        row[7 + i] = held ? V[i] : V[i] - 0.5 * h * F[i] / M;
        row[10 + i] = W[i];
        row[13 + i] = held ? 0 : F[i] / M;
    }
    quat(R, row + 3);
}

mcs_status fe_out_joint_sample(const fe_model *m, const fe_state *s, fe_out_joint *o,
                               mcs_error *err)
{
    mcs_status st = MCS_OK;
    for (int j = 0; j < o->nj && !st; j++) {
        const double *jo = s->joint_out + FE_JOUT_N * j;
        const double *src[5] = {jo + FE_JOUT_FORCE, jo + FE_JOUT_MOMENT, jo + FE_JOUT_SLIDE,
                                jo + FE_JOUT_ANGLE, &s->energy_time};
        for (int k = 0; k < 5 && !st; k++)
            if (o->jser[5 * j + k]) st = mcs_results_series_append(o->jser[5 * j + k], src[k], err);
    }
    const double t = s->energy_time;
    for (int b = 0; b < o->nb && !st; b++) {
        double row[16];
        body_at_tn(m, s, b, row);
        if (o->tprev >= 0 && t > o->tprev)
            for (int i = 0; i < 3; i++)
                row[13 + i] = (row[7 + i] - o->vprev[3 * b + i]) / (t - o->tprev);
        for (int i = 0; i < 3; i++)
            o->vprev[3 * b + i] = row[7 + i];
        const int off[5] = {0, 3, 7, 10, 13};
        for (int k = 0; k < 5 && !st; k++)
            st = mcs_results_series_append(o->bser[5 * b + k], row + off[k], err);
    }
    if (o->nb) o->tprev = t;
    return st;
}

void fe_out_joint_free(fe_out_joint *o)
{
    free(o->jser);
    free(o->bser);
    free(o->vprev);
    *o = (fe_out_joint){0};
}

/* mb_sensor.c: the sensor sub-stage of mb_step (accelerations of the step) and the output
 * record at the output rate.
 * Accelerations are the backward difference of the step, (v(t) - v(t - h)) / h: kinematic
 * accelerations (gravity not included, as MADYMO's linear acceleration output). A sensor at a
 * point r of its body: a = a_cg + alpha x r + omega x (omega x r), v = v_cg + omega x r,
 * displacement = x(t) - x(0) of the point; expressed in the body's frame and turned into the
 * SAE J211 sign convention (x forward, y right, z down) from the ISO 8855 body axes
 * (x forward, y left, z up): (x, -y, -z). The first output row (t = 0) carries the
 * accelerations of the first step.
 * The body record's `acceleration` (/stage1/bodies/<b>/acceleration) is the mean over the
 * output interval that ends at the row, (v_k - v_k-1) / (t_k - t_k-1) of the recorded CG
 * velocities (row 0: the first step's): a sample of the step's acceleration at 10 kHz would
 * alias the contact pulses, which change within a few steps, and would not integrate back to
 * the velocities (the pulse method of translators/tr_motion.h integrates these means). The
 * sensor channels are not changed by this: the step's acceleration at the row, CFC filtered. */
#include "stage1_mb/mb_egroup.h"
#include "stage1_mb/mb_loadcell.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <string.h>

/* sensors: reads the new velocities (s->kin), writes s->acc and s->angacc */
void mb_kinematics_update(const mb_model *m, mb_state *s)
{
    for (int b = 0; b < m->nbody; b++) {
        const mb_body_kin *k = &s->kin[b];
        for (int i = 0; i < 3; i++) {
            s->acc[3 * b + i] = (k->vel[i] - s->vel_prev[3 * b + i]) / m->h;
            s->angacc[3 * b + i] = (k->angvel[i] - s->angvel_prev[3 * b + i]) / m->h;
        }
        mb_copy(k->vel, s->vel_prev + 3 * b);
        mb_copy(k->angvel, s->angvel_prev + 3 * b);
    }
}

/* one sensor's reading in the SAE J211 local frame [SI] */
static void sensor_value(const mb_state *s, const mb_sensor *se, double out[3])
{
    int b = se->body;
    const mb_body_kin *k = &s->kin[b];
    double r[3], q[3] = {0, 0, 0}, t[3], u[3];
    mb_mat_vec(k->rot, se->point, r);
    const double *w = k->angvel, *al = s->angacc + 3 * b;
    switch (se->type) {
    case MB_SENSOR_ACC:
        mb_cross(al, r, t);
        mb_cross(w, r, u);
        mb_cross(w, u, q);
        mb_add(q, t, q);
        mb_add(q, s->acc + 3 * b, q);
        break;
    case MB_SENSOR_VEL:
        mb_cross(w, r, q);
        mb_add(q, k->vel, q);
        break;
    case MB_SENSOR_DISP:
        mb_add(k->pos, r, q);
        mb_mat_vec(s->rot0 + 9 * b, se->point, t);
        mb_add(t, s->pos0 + 3 * b, t);
        mb_sub(q, t, q);
        break;
    case MB_SENSOR_ANGVEL: mb_copy(w, q); break;
    case MB_SENSOR_ANGACC: mb_copy(al, q); break;
    }
    mb_mat_tvec(k->rot, q, out);
    out[1] = -out[1], out[2] = -out[2];
}

static void record_row(const mb_model *m, const mb_state *s, long row)
{
    s->rec_t[row] = s->t;
    for (int b = 0; b < m->nbody; b++) {
        double *r = s->rec_body + ((size_t)row * m->nbody + b) * MB_BODY_ROW;
        const mb_body_kin *k = &s->kin[b];
        memcpy(r, k->pos, 3 * sizeof *r);
        memcpy(r + 3, k->quat, 4 * sizeof *r);
        memcpy(r + 7, k->vel, 3 * sizeof *r);
        memcpy(r + 10, k->angvel, 3 * sizeof *r);
        if (row == 0) {
            memcpy(r + 13, s->acc + 3 * b, 3 * sizeof *r);
            continue;
        }
        /* the mean over the output interval: (v_k - v_k-1) / (t_k - t_k-1) */
        const double *rp = r - (size_t)m->nbody * MB_BODY_ROW;
        double dt = s->t - s->rec_t[row - 1];
        for (int i = 0; i < 3; i++)
            r[13 + i] = (k->vel[i] - rp[7 + i]) / dt;
    }
    for (int i = 0; i < m->nsensor; i++)
        sensor_value(s, &m->sensor[i], s->rec_sensor + ((size_t)row * m->nsensor + i) * 3);
    double *e = s->rec_energy + (size_t)row * MB_NENERGY;
    int j = 0;
#define MB_X_COPY(name, unit) e[j++] = s->e.name;
    MB_ENERGY_FIELDS(MB_X_COPY)
#undef MB_X_COPY
    mb_channels_sample(m, s, s->rec_chan + (size_t)row * mb_channels_count(m));
    mb_loadcell_record(m, s, row);
}

/* output: at t = 0 and every out_every steps, the bodies, sensors and energies */
void mb_record(const mb_model *m, mb_state *s)
{
    if (s->step == 1) { /* t = 0 takes the first step's accelerations */
        mb_state *c = s;
        for (int b = 0; b < m->nbody; b++)
            memcpy(c->rec_body + (size_t)b * MB_BODY_ROW + 13, s->acc + 3 * b, 3 * sizeof(double));
        for (int i = 0; i < m->nsensor; i++) {
            if (m->sensor[i].type != MB_SENSOR_ACC && m->sensor[i].type != MB_SENSOR_ANGACC)
                continue;
            double v[3];
            sensor_value(s, &m->sensor[i], v);
            memcpy(c->rec_sensor + (size_t)i * 3, v, sizeof v);
        }
        mb_loadcell_record(m, s, 0); /* t = 0 takes the first step's joint loads too */
    }
    if (s->step % m->out_every != 0 || s->nrec >= m->nout) return;
    if (m->egroup) mb_egroup_record(m, s, s->nrec);
    record_row(m, s, s->nrec++);
}

/* mb_prescribe.c: prescribed bodies (mb_prescribe.h). The ODE step moves a kinematic body by
 * its velocity: it is given the secant velocities of the step (start pose to the callback's
 * pose at t + h), so joints to it see the motion it makes; after the step it is put exactly
 * on the callback's pose and velocities. The loads on it (contacts, restraints, coupled FE
 * parts: ODE's accumulators; joints: their reactions) times its displacement over the step
 * are the work it takes from the rest; minus that is the external work it does on them.
 * The coupled FE parts' loads are not taken from the accumulators: their work is the FE
 * side's (mb_prescribe_couple_work), in step with the FE energies. */
#include "stage1_mb/mb_prescribe.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_contact.h"
#include "stage1_mb/mb_couple_rx.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NEXT 13             /* pos 3, quat 4, vel 3, angvel 3 */
#define SLOT (NEXT + 7 + 6) /* then the pose at t (7), the loads before the coupling's (6) */

int mb_body_prescribed(const mb_model *m, int body)
{
    return m->presc && body >= 0 && body < m->nbody && m->presc[body].fn;
}

/* the rotation vector of q1 q0^-1 (world) [rad], the shorter way */
static void quat_delta(const double q0[4], const double q1[4], double th[3])
{
    /* q1 * conj(q0) */
    double w = q1[0] * q0[0] + q1[1] * q0[1] + q1[2] * q0[2] + q1[3] * q0[3];
    double v[3] = {-q1[0] * q0[1] + q1[1] * q0[0] - q1[2] * q0[3] + q1[3] * q0[2],
                   -q1[0] * q0[2] + q1[1] * q0[3] + q1[2] * q0[0] - q1[3] * q0[1],
                   -q1[0] * q0[3] - q1[1] * q0[2] + q1[2] * q0[1] + q1[3] * q0[0]};
    if (w < 0) w = -w, v[0] = -v[0], v[1] = -v[1], v[2] = -v[2];
    double s = mb_norm(v), a = 2 * atan2(s, w);
    double k = s > 1e-300 ? a / s : 2;
    mb_scale(v, k, th);
}

mcs_status mb_model_prescribe(mb_model *m, int body, mb_motion_fn fn, void *ctx, mcs_error *err)
{
    if (body < 0 || body >= m->nbody || !fn)
        return MCS_ERR(err, MCS_ERR_RANGE, "prescribed body %d: no such body or no motion", body);
    double p[3], q[4], v[3], w[3], qu[4], d[3], th[3];
    if (fn(ctx, body, 0, p, q, v, w))
        return MCS_ERR(err, MCS_ERR_RANGE, "body %s: its prescribed motion fails at t = 0",
                       m->body_name[body]);
    mb_body_desc *bd = &m->body[body];
    mb_quat_unit(bd->quat, qu);
    mb_quat_unit(q, q);
    mb_sub(p, bd->pos, d);
    quat_delta(qu, q, th);
    if (!(mb_norm(d) <= 1e-6) || !(mb_norm(th) <= 1e-6))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "body %s: prescribed pose at t = 0 is %.3g m and %.3g rad from the "
                       "body's initial pose",
                       m->body_name[body], mb_norm(d), mb_norm(th));
    if (!m->presc && !(m->presc = calloc((size_t)m->nbody, sizeof *m->presc)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    m->presc[body] = (mb_presc){fn, ctx};
    mb_copy(v, bd->vel);
    mb_copy(w, bd->angvel);
    return MCS_OK;
}

mcs_status mb_prescribe_init(const mb_model *m, mb_state *s, mcs_error *err)
{
    if (!m->presc) return MCS_OK;
    s->presc_next = calloc((size_t)m->nbody * SLOT, sizeof *s->presc_next);
    if (!s->presc_next) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int b = 0; b < m->nbody; b++)
        if (m->presc[b].fn) mb_body_set_kinematic(s->world, b);
    return MCS_OK;
}

/* minus the work of force f and torque t (about the CG) over the body's step dx, th */
static double work_on_rest(const double f[3], const double t[3], const double dx[3],
                           const double th[3])
{
    return -(mb_dot(f, dx) + mb_dot(t, th));
}

void mb_prescribe_loads(const mb_model *m, mb_state *s)
{
    if (!m->presc) return;
    for (int b = 0; b < m->nbody; b++)
        if (m->presc[b].fn) {
            double *l = s->presc_next + (size_t)b * SLOT + NEXT + 7;
            mb_body_get_load(s->world, b, l, l + 3);
        }
}

double mb_prescribe_couple_work(const mb_model *m, const mb_state *s)
{
    if (!m->presc || !m->couple) return 0;
    const mb_couple_state *cs = s->couple;
    double w = cs->w_fe_presc - cs->rx->w_anchor_presc;
    if (m->couple->contact) w += mb_couple_contact_work_prescribed(m, s);
    return w;
}

mcs_status mb_prescribe_begin(const mb_model *m, mb_state *s, mcs_error *err)
{
    if (!m->presc) return MCS_OK;
    const double t1 = (double)(s->step + 1) * m->h;
    for (int b = 0; b < m->nbody; b++) {
        if (!m->presc[b].fn) continue;
        double *n = s->presc_next + (size_t)b * SLOT, *start = n + NEXT;
        if (m->presc[b].fn(m->presc[b].ctx, b, t1, n, n + 3, n + 7, n + 10))
            return MCS_ERR(err, MCS_ERR_NUMERIC, "body %s: prescribed motion fails at t = %.9g s",
                           m->body_name[b], t1);
        mb_quat_unit(n + 3, n + 3);
        const mb_body_kin *k = &s->kin[b]; /* the pose at t */
        mb_copy(k->pos, start);
        memcpy(start + 3, k->quat, 4 * sizeof *start);
        const double *f = start + 7, *tq = start + 10;
        double dx[3], th[3], vs[3], ws[3];
        mb_sub(n, k->pos, dx);
        quat_delta(k->quat, n + 3, th);
        s->w_presc += work_on_rest(f, tq, dx, th);
        mb_scale(dx, 1 / m->h, vs);
        mb_scale(th, 1 / m->h, ws);
        mb_body_set_state(s->world, b, k->pos, k->quat, vs, ws);
    }
    return MCS_OK;
}

void mb_prescribe_end(const mb_model *m, mb_state *s)
{
    if (!m->presc) return;
    for (int b = 0; b < m->nbody; b++) {
        if (!m->presc[b].fn) continue;
        const double *n = s->presc_next + (size_t)b * SLOT;
        mb_body_set_state(s->world, b, n, n + 3, n + 7, n + 10);
    }
    /* the joints' constraint forces of the step on the prescribed bodies */
    for (int j = 0; j < m->njoint; j++) {
        const int ends[2] = {m->joint[j].child, m->joint[j].parent};
        for (int e = 0; e < 2; e++) {
            const int b = ends[e];
            if (!mb_body_prescribed(m, b)) continue;
            const double *n = s->presc_next + (size_t)b * SLOT, *start = n + NEXT;
            double f[3], tq[3], dx[3], th[3];
            if (e == 0)
                mb_joint_reaction(s->world, j, f, tq);
            else
                mb_joint_reaction_parent(s->world, j, f, tq);
            mb_sub(n, start, dx);
            quat_delta(start + 3, n + 3, th);
            s->w_presc += work_on_rest(f, tq, dx, th);
        }
    }
}

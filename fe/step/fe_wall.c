/* fe_wall: the motion of the planar rigid walls. A wall moves at its prescribed velocity, or,
 * with a mass M (fe_wall_desc.mass > 0; LS-DYNA *RIGIDWALL_PLANAR_MOVING, cards MASS and V0),
 * freely along its normal n under the force the structure puts on it.
 * Penalty wall with mass: V(n+1/2) = V(n-1/2) + dt_n (F(t_n).n) / M, d(n+1) = d(n) + dt V n,
 * the same central difference as the nodes, with the same force pair (the penalty forces of
 * fe_contact_forces at t_n), so the momentum M V + sum m v is conserved to round-off.
 * Kinematic wall with mass: the wall and its slaves are solved together before the node update
 * (fe_wall_kin.c, perfectly plastic landing, momentum conserved).
 * Energy: the wall's kinetic energy 1/2 M V(n-1/2) V(n+1/2) joins the kinetic energy, and the
 * work of the nodes on it (trapezoidal, fe_integrate's weights) the external work, so the
 * pair's work cancels apart from the penalty springs' own energy while in contact (penalty) or
 * the landing loss, moved to `dissipated` (kinematic), and the total is conserved. */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <string.h>

mcs_status fe_wall_check(const fe_wall_desc *d, mcs_error *err)
{
    if (!(d->mass >= 0) || !isfinite(d->mass))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: rigid wall '%s': mass must be >= 0, got %g",
                       d->name, d->mass);
    mcs_status st = fe_wall_motion_check(d, err); /* motion curves, friction */
    if (st || d->mass == 0) return st;
    double nn = sqrt(fe_dot(d->normal, d->normal)), vn = fe_dot(d->velocity, d->normal) / nn;
    double vt2 = fe_dot(d->velocity, d->velocity) - vn * vn;
    if (vt2 > 1e-18 * fe_dot(d->velocity, d->velocity))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: rigid wall '%s': a wall with mass moves along its normal: its "
                       "velocity must be parallel to the normal",
                       d->name);
    return MCS_OK;
}

/* stability of the penalty springs on a wall with mass: with k = s m_I / dt^2 per slave node
 * (s <= 1) and every slave in contact, (omega dt)^2 <= s (1 + sum m_I / M); M >= sum m_I / 20
 * keeps it below 2.1 s, inside the limit 4 */
mcs_status fe_wall_finish(fe_model *m, mcs_error *err)
{
    for (int w = 0; w < m->nwall; w++) {
        const fe_wall *W = &m->wall[w];
        if (!(W->mass > 0) || W->method != FE_WALL_PENALTY) continue;
        double ms = 0;
        for (int n = 0; n < m->nnode; n++)
            if (m->node_walls[n] & (1u << w)) ms += m->node_mass[n];
        if (W->penalty_scale > 1)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: rigid wall '%s': a wall with mass needs penalty_scale <= 1",
                           W->name);
        if (W->mass < ms / 20)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: rigid wall '%s': mass %g kg is below 1/20 of the %g kg of the "
                           "nodes it stops: its penalty contact would be unstable",
                           W->name, W->mass, ms);
    }
    return fe_wall_kin_finish(m, err);
}

void fe_wall_reset(const fe_model *m, fe_state *s)
{
    for (int w = 0; w < m->nwall; w++) {
        for (int i = 0; i < 3; i++) {
            s->wall_x[3 * w + i] = 0;
            s->wall_v[3 * w + i] = m->wall[w].velocity[i];
        }
        if (m->wall[w].nmotion > 0) fe_wall_motion_x(&m->wall[w], 0, s->wall_x + 3 * w);
    }
}

void fe_wall_predict(const fe_model *m, fe_state *s, const fe_wall_step *P)
{
    const double tn = s->time + P->dt;
    for (int w = 0; w < m->nwall; w++) {
        const fe_wall *W = &m->wall[w];
        double *xn = s->wall_xn + 3 * w;
        if (fe_wall_kin_mass(W)) {
            fe_wall_kin_solve(m, s, w, P);
        } else if (W->nmotion > 0) { /* curves (fe_wall_motion.c) */
            fe_wall_motion_x(W, tn, xn);
        } else if (!(W->mass > 0)) {
            for (int i = 0; i < 3; i++) xn[i] = W->velocity[i] * tn; /* d = V t */
        }
    }
}

/* the works of the force f (on the wall, along its normal, at t) as fe_integrate weighs them */
static void wall_work(double M, double fn, double vo, double vn, double dth, double hb,
                      double *ke, double *wb, double *wf)
{
    *ke += 0.5 * M * vo * vn;
    *wb += 0.5 * fn * hb * vo;
    *wf += 0.5 * fn * dth * vn;
}

void fe_wall_integrate(const fe_model *m, fe_state *s)
{
    const double dt = s->dt, dtp = s->dt_prev, dth = 0.5 * (dt + dtp), hb = dtp > 0 ? dth : 0;
    double ke = 0, wb = 0, wf = 0, lb = 0, lf = 0;
    if (m->nwall_slave) fe_wall_penalty_friction_after(m, s); /* fe_wall_fric.c */
    for (int w = 0; w < m->nwall; w++) { /* landing losses, penalty friction */
        lb += s->wall_diss[2 * w];
        lf += s->wall_diss[2 * w + 1];
    }
    for (int w = 0; w < m->nwall; w++) {
        const fe_wall *W = &m->wall[w];
        double *x = s->wall_x + 3 * w, *v = s->wall_v + 3 * w;
        if (!(W->mass > 0)) { /* prescribed; moved by curves: the velocity at t + dt/2 */
            for (int i = 0; i < 3; i++) {
                if (W->nmotion > 0) v[i] = (s->wall_xn[3 * w + i] - x[i]) / dt;
                x[i] = s->wall_xn[3 * w + i];
            }
            continue;
        }
        const double vo = fe_dot(v, W->normal);
        if (W->method == FE_WALL_KINEMATIC) {
            /* solved before the node update: the force is the momentum the nodes gave it */
            const double vn = fe_dot(s->wall_vn + 3 * w, W->normal);
            wall_work(W->mass, W->mass * (vn - vo) / dth, vo, vn, dth, hb, &ke, &wb, &wf);
            for (int i = 0; i < 3; i++) {
                v[i] = s->wall_vn[3 * w + i];
                x[i] = s->wall_xn[3 * w + i];
            }
            continue;
        }
        const double fn = fe_dot(s->wall_force + 3 * w, W->normal);
        const double vn = vo + dth * fn / W->mass;
        wall_work(W->mass, fn, vo, vn, dth, hb, &ke, &wb, &wf);
        for (int i = 0; i < 3; i++) {
            v[i] = vn * W->normal[i];
            x[i] += dt * v[i];
        }
    }
    s->energy[FE_E_kinetic] += ke;
    /* the kinematic landing loss and the penalty friction: dissipated, and given back to the
     * external work */
    s->work_ext += wb + lb;
    s->work_pending[0] += wf + lf;
    s->work_damp += lb;
    s->work_pending[2] += lf;
}

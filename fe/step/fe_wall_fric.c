/* fe_wall_fric: Coulomb friction on the planar rigid walls (LS-DYNA *RIGIDWALL_PLANAR FRIC:
 * 0 frictionless, 0 < FRIC < 1 Coulomb coefficient, 1 no sliding once in contact).
 *
 * Kinematic walls: a node that lands gets the normal impulse m dv_n; its velocity relative to
 * the wall at t + dt/2 then loses its tangential part u_t up to mu dv_n (Coulomb: the
 * tangential impulse is at most mu times the normal one), all of it with FRIC >= 1 (sticking).
 * A block pressed by gravity onto a floor thus decelerates at exactly mu g.
 * Penalty walls: with the penalty force f_n, a tangential force mu f_n against the sliding
 * velocity at t - dt/2, at most the m |u_t| / dt_h that stops the sliding in one step (m u_t /
 * dt_h with FRIC >= 1), so it never reverses the sliding (a regularised stick).
 *
 * Energy: the friction force f on a node (at t, trapezoidal works as fe_integrate weighs them)
 * dissipates D = -1/2 f.(v - V_wall) hb before t and -1/2 f.(v - V_wall) dt_h after t
 * (velocities relative to the wall's, at t -/+ dt/2); D is counted as dissipated and given back
 * to the external work (the node's work by f is already there), so `total` stays constant. */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>

/* the wall's velocity at t + dt/2 (before fe_wall_integrate stores it) */
static void wall_vnew(const fe_model *m, const fe_state *s, int w, double dt, double wn[3])
{
    for (int i = 0; i < 3; i++)
        wn[i] = fe_wall_kin_mass(&m->wall[w]) ? s->wall_vn[3 * w + i]
                                              : (s->wall_xn[3 * w + i] - s->wall_x[3 * w + i]) / dt;
}

void fe_wall_kin_friction(const fe_model *m, const fe_state *s, int w, double mass, double dvn,
                          const double vo[3], double vn[3], double hb, double dth, double dt,
                          double *wacc, double diss[2])
{
    const fe_wall *W = &m->wall[w];
    const double *nrm = W->normal, *wo = s->wall_v + 3 * w;
    double wn[3], t[3];
    wall_vnew(m, s, w, dt, wn);
    double rn = 0;
    for (int i = 0; i < 3; i++) rn += (vn[i] - wn[i]) * nrm[i];
    for (int i = 0; i < 3; i++) t[i] = vn[i] - wn[i] - rn * nrm[i];
    const double ut = sqrt(fe_dot(t, t));
    if (!(ut > 0)) return;
    const double dvt = W->friction >= 1 ? ut : fmin(ut, W->friction * dvn);
    double f[3];
    for (int i = 0; i < 3; i++) {
        const double dv = -dvt * t[i] / ut;
        vn[i] += dv;
        f[i] = mass * dv / dth; /* on the node, at t */
        wacc[i] -= f[i];
    }
    for (int i = 0; i < 3; i++) {
        diss[0] -= 0.5 * f[i] * (vo[i] - wo[i]) * hb;
        diss[1] -= 0.5 * f[i] * (vn[i] - wn[i]) * dth;
    }
}

void fe_wall_penalty_friction(const fe_model *m, fe_state *s)
{
    const double dt = s->dt, dtp = s->dt_prev, dth = 0.5 * (dt + dtp), hb = dtp > 0 ? dth : 0;
    for (int w = 0; w < m->nwall; w++) {
        const fe_wall *W = &m->wall[w];
        if (W->method != FE_WALL_PENALTY || !(W->friction > 0)) continue;
        const double *nrm = W->normal, *wv = s->wall_v + 3 * w;
        double db = 0;
        for (int k = m->wall_slave_off[w]; k < m->wall_slave_off[w + 1]; k++) {
            const int n = m->wall_slave[k];
            double *ft = s->wall_ft + 3 * (size_t)k, g = 0, rn = 0, t[3];
            ft[0] = ft[1] = ft[2] = 0;
            for (int i = 0; i < 3; i++)
                g += (s->node_x[3 * n + i] - W->point[i] - s->wall_x[3 * w + i]) * nrm[i];
            if (g >= 0) continue;
            const double mass = m->node_mass[n] + (m->nms_node ? s->node_dm[n] : 0);
            const double fn = -W->penalty_scale * mass / (dt * dt) * g;
            for (int i = 0; i < 3; i++) rn += (s->node_v[3 * n + i] - wv[i]) * nrm[i];
            for (int i = 0; i < 3; i++) t[i] = s->node_v[3 * n + i] - wv[i] - rn * nrm[i];
            const double ut = sqrt(fe_dot(t, t)), fs = mass * ut / dth;
            if (!(ut > 0)) continue;
            const double f = W->friction >= 1 ? fs : fmin(W->friction * fn, fs);
            for (int i = 0; i < 3; i++) {
                ft[i] = -f * t[i] / ut;
                s->node_fext[3 * n + i] += ft[i];
                s->wall_force[3 * w + i] -= ft[i];
                db -= 0.5 * ft[i] * t[i] * hb;
            }
        }
        s->wall_diss[2 * w] = db;
    }
}

/* after the node update, before the walls move: the half after t of the penalty friction's
 * dissipation */
void fe_wall_penalty_friction_after(const fe_model *m, fe_state *s)
{
    const double dt = s->dt, dth = 0.5 * (dt + s->dt_prev);
    for (int w = 0; w < m->nwall; w++) {
        const fe_wall *W = &m->wall[w];
        if (W->method != FE_WALL_PENALTY || !(W->friction > 0)) continue;
        double wn[3] = {0, 0, 0}, da = 0; /* a wall with mass moves along n, normal to f */
        if (!(W->mass > 0)) wall_vnew(m, s, w, dt, wn);
        for (int k = m->wall_slave_off[w]; k < m->wall_slave_off[w + 1]; k++) {
            const double *ft = s->wall_ft + 3 * (size_t)k, *v = s->node_v + 3 * m->wall_slave[k];
            for (int i = 0; i < 3; i++) da -= 0.5 * ft[i] * (v[i] - wn[i]) * dth;
        }
        s->wall_diss[2 * w + 1] = da;
    }
}

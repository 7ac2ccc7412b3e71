/* fe_slipring_step: the per-step return map of the slip rings (fe_slipring.h). Called at the
 * end of fe_external_forces with x = x(t_n): the truss stresses and node_fint are those of
 * t_n (fe_internal_forces) and the retractors have been advanced to t_n
 * (fe_restraint_forces). No allocation. */
#include "fe/fe_restraint.h"
#include "fe/fe_slipring.h"

#include <math.h>
#include <stdio.h>

/* one side of a ring at t_n: tension as a function of the unstretched length it gains */
typedef struct {
    int truss;        /* 1: a truss element; 0: a retractor segment                   */
    double sig;       /* truss: axial stress [Pa]                                      */
    double E, A;      /* truss: modulus [Pa], area [m^2]                               */
    double l0;        /* unstretched length [m]                                        */
    double F, k;      /* retractor: force [N], stiffness seen by the flow [N/m]        */
    double u[3], len; /* unit vector ring -> far end [-], current length [m]           */
} side;

/* tension after gaining dl of unstretched length, and its derivative */
static double side_tension(const side *q, double dl, double *dT)
{
    if (q->truss) {
        double T = q->A * (q->sig - q->E * log1p(dl / q->l0));
        *dT = T > 0 ? -q->E * q->A / (q->l0 + dl) : 0;
        return T > 0 ? T : 0;
    }
    double T = q->F - q->k * dl;
    *dT = T > 0 ? -q->k : 0;
    return T > 0 ? T : 0;
}

/* the largest gain before the side's tension reaches 0 (inf: never) */
static double side_zero(const side *q)
{
    if (q->truss) return q->sig > 0 ? q->l0 * expm1(q->sig / q->E) : 0;
    return q->k > 0 ? fmax(q->F, 0) / q->k : INFINITY;
}

/* flow x >= 0 into side h from side w so that T_h(x) = c T_w(-x) (g decreasing in x), on
 * [0, hi] where g(hi) <= 0; safeguarded Newton */
static double solve_flow(const side *h, const side *w, double c, double hi)
{
    double lo = 0, d0, d1;
    double g0 = side_tension(h, 0, &d0) - c * side_tension(w, 0, &d1);
    double slope = d0 + c * d1, x = slope < 0 ? -g0 / slope : 0.5 * hi;
    const double tol = 1e-13 * (side_tension(h, 0, &d0) + 1e-300);
    for (int it = 0; it < 200; it++) {
        if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
        double g = side_tension(h, x, &d0) - c * side_tension(w, -x, &d1);
        if (fabs(g) <= tol || hi - lo <= 1e-15 * (hi + x)) break;
        if (g > 0)
            lo = x;
        else
            hi = x;
        slope = d0 + c * d1;
        x = slope < 0 ? x - g / slope : 0.5 * (lo + hi);
    }
    return x;
}

/* read side k of ring r at t_n */
static void read_side(const fe_model *m, const fe_state *s, const fe_slipring *r, int k, side *q)
{
    const double *xr = s->node_x + 3 * r->node, *xf;
    const fe_slipring_ring_state *g = &s->slipring->ring[r - m->sliprings->ring];
    if (r->elem[k] >= 0) {
        const fe_part *p = &m->part[m->truss_part[r->elem[k]]];
        q->truss = 1;
        q->sig = s->truss_sig[r->elem[k]];
        q->E = p->material.youngs_modulus;
        q->A = p->section.area;
        q->l0 = k == 0 ? g->length0 : g->length1;
        xf = s->node_x + 3 * r->far[k];
    } else {
        const fe_belt_retractor *b = &m->restraints->retractor[r->retractor];
        const fe_retractor_state *rs = &s->restraint->retractor[r->retractor];
        q->truss = 0;
        q->F = rs->force;
        q->k = rs->locked ? b->k : 0; /* unlocked: the spool takes the webbing */
        xf = s->restraint->retractor_anchor + 3 * r->retractor;
    }
    double d2 = 0;
    for (int i = 0; i < 3; i++) {
        q->u[i] = xf[i] - xr[i];
        d2 += q->u[i] * q->u[i];
    }
    q->len = sqrt(d2);
    for (int i = 0; i < 3; i++)
        q->u[i] = q->len > 0 ? q->u[i] / q->len : 0;
}

/* side k gains dl: stress, forces, energies; returns the elastic energy released [J] */
static double apply_side(const fe_model *m, fe_state *s, const fe_slipring *r, int k, const side *q,
                         double dl)
{
    fe_slipring_ring_state *g = &s->slipring->ring[r - m->sliprings->ring];
    double *xr = s->node_x + 3 * r->node;
    if (r->elem[k] < 0) {
        fe_retractor_state *rs = &s->restraint->retractor[r->retractor];
        const double *anchor = s->restraint->retractor_anchor + 3 * r->retractor;
        double *fa = s->restraint->retractor_fanchor + 3 * r->retractor;
        double F1 = fmax(q->F - q->k * dl, 0), dF = F1 - rs->force;
        s->restraint->retractor_ring[r->retractor] += dl;
        rs->force = F1;
        /* the segment pulls the ring node towards the anchor, the anchor towards the node */
        for (int i = 0; i < 3; i++)
            if (q->len > 0) {
                double df = dF * (xr[i] - anchor[i]) / q->len;
                s->node_fext[3 * r->node + i] -= df;
                fa[i] += df;
            }
        return 0.5 * (q->F + F1) * dl;
    }
    const int e = r->elem[k], ip = m->truss_part[e];
    const fe_part *p = &m->part[ip];
    const int tonly = p->section.tension_only;
    const double de = log1p(dl / q->l0), sig1 = q->sig - q->E * de;
    double n0 = tonly ? fmax(q->sig, 0) : q->sig, n1 = tonly ? fmax(sig1, 0) : sig1;
    s->truss_sig[e] = sig1;
    if (k == 0)
        g->length0 += dl;
    else
        g->length1 += dl;
    /* element forces: f_b = N e, f_a = -N e (resisting), e from node a to node b */
    const int a = m->truss_node[2 * e], bn = m->truss_node[2 * e + 1];
    double d[3], dold[3];
    for (int i = 0; i < 3; i++) {
        d[i] = s->node_x[3 * bn + i] - s->node_x[3 * a + i];
        dold[i] = d[i] - s->dt_prev * (s->node_v[3 * bn + i] - s->node_v[3 * a + i]);
    }
    const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double lold = sqrt(dold[0] * dold[0] + dold[1] * dold[1] + dold[2] * dold[2]);
    double *f = s->slot_f + 3 * ((size_t)m->slot_base[FE_KIND_TRUSS] + 2 * (size_t)e);
    if (len > 0) {
        double fn = (n1 - n0) * p->section.area / len;
        for (int i = 0; i < 3; i++) {
            f[i] -= fn * d[i];
            f[3 + i] += fn * d[i];
            s->node_fint[3 * a + i] -= fn * d[i];
            s->node_fint[3 * bn + i] += fn * d[i];
        }
    }
    /* stored energy change at fixed geometry, N l d(strain), as fe_truss sums it */
    const double area = p->section.area;
    double dU = -0.5 * (n0 + n1) * area * len * de;
    /* fe_truss summed this step's stretching work with the tension before the ring; the
     * nodes feel the one after: the difference keeps the kernel's balance (at the step's
     * middle length, as fe_truss) */
    double fix = len > 0 && lold > 0
                     ? 0.5 * (n1 - n0) * area * 0.5 * (len + lold) * log(len / lold)
                     : 0;
    s->part_energy[FE_NENERGY * ip + FE_E_internal] += dU;
    s->part_energy[FE_NENERGY * ip + FE_E_dissipated] += fix - dU;
    return fix - dU;
}

static mcs_status ring_step(const fe_model *m, fe_state *s, int i)
{
    const fe_slipring *r = &m->sliprings->ring[i];
    fe_slipring_ring_state *g = &s->slipring->ring[i];
    side q[2];
    read_side(m, s, r, 0, &q[0]);
    read_side(m, s, r, 1, &q[1]);
    double cw = q[0].u[0] * q[1].u[0] + q[0].u[1] * q[1].u[1] + q[0].u[2] * q[1].u[2];
    g->wrap_angle = M_PI - acos(fmax(-1.0, fmin(1.0, cw)));
    double c = exp(r->mu * g->wrap_angle), d;
    double T0 = side_tension(&q[0], 0, &d), T1 = side_tension(&q[1], 0, &d);
    g->sliding = 0;
    g->slip_rate = 0;
    int locked = r->lock_time >= 0 && s->time >= r->lock_time;
    int h = T0 > c * T1 ? 0 : T1 > c * T0 ? 1 : -1;
    if (!locked && h >= 0) {
        const side *qh = &q[h], *qw = &q[1 - h];
        /* the giving side keeps at least min_length; the taking side stops at zero tension */
        double hi_w = qw->truss ? qw->l0 - r->min_length : INFINITY;
        double hi = fmin(hi_w, side_zero(qh)), dd;
        if (hi_w <= side_zero(qh) && side_tension(qh, hi, &dd) - c * side_tension(qw, -hi, &dd) > 0)
            return MCS_ERR(&s->err, MCS_ERR_NUMERIC,
                           "fe: slip ring '%s': side %d (%s) reached its minimum unstretched "
                           "length %g m at t = %.6g s: element handover to the next belt "
                           "element is not built; give that side more belt or a smaller "
                           "min_length",
                           r->name, 1 - h, r->elem[1 - h] >= 0 ? "belt element" : "retractor",
                           r->min_length, s->time);
        double x = hi > 0 ? solve_flow(qh, qw, c, hi) : 0;
        if (x > 0) {
            g->energy_friction += apply_side(m, s, r, h, qh, x);
            g->energy_friction += apply_side(m, s, r, 1 - h, qw, -x);
            g->slip += h == 0 ? x : -x;
            if (s->dt_prev > 0) g->slip_rate = (h == 0 ? x : -x) / s->dt_prev;
            g->sliding = 1;
        }
    }
    /* the tensions after the flow */
    side a[2];
    read_side(m, s, r, 0, &a[0]);
    read_side(m, s, r, 1, &a[1]);
    g->force0 = side_tension(&a[0], 0, &d);
    g->force1 = side_tension(&a[1], 0, &d);
    if (r->retractor >= 0) {
        const fe_retractor_state *rs = &s->restraint->retractor[r->retractor];
        g->length0 = m->restraints->retractor[r->retractor].l0 + rs->payout +
                     s->restraint->retractor_ring[r->retractor];
    }
    return MCS_OK;
}

void fe_slipring_forces(const fe_model *m, fe_state *s)
{
    if (!m->sliprings || !s->slipring || s->err.status != MCS_OK) return;
    for (int i = 0; i < m->sliprings->n; i++)
        if (ring_step(m, s, i) != MCS_OK) return;
}

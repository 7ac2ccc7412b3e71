/* fe_truss: 2-node truss / cable, constant area, axial stress from the stretching rate
 * (logarithmic strain increments ln(l_n / l_{n-1})), elastic or J2 uniaxial; tension-only carries no
 * compression (a slack cable: the stress keeps tracking the strain elastically, the force is
 * max(sigma, 0) A). Power: N (v_b - v_a).e, so f_b = N e, f_a = -N e (resisting). */
#include "fe/fe_elem.h"
#include "fe/fe_tet10.h"

#include <math.h>

void fe_truss_range(const fe_model *m, fe_state *s, int ip, int e0, int e1, fe_chunk_acc *acc)
{
    const fe_part *p = &m->part[ip];
    const double dt = s->dt_prev, area = p->section.area, c0 = p->wave_speed;
    const int tonly = p->section.tension_only;
    double e_int = 0, dtmin = INFINITY;
    int dtel = -1, bad = -1;
    for (int e = e0; e < e1; e++) {
        const int a = m->truss_node[2 * e], b = m->truss_node[2 * e + 1];
        double d[3], dv[3];
        for (int i = 0; i < 3; i++) {
            d[i] = s->node_x[3 * b + i] - s->node_x[3 * a + i];
            dv[i] = s->node_v[3 * b + i] - s->node_v[3 * a + i];
        }
        double len = sqrt(fe_dot(d, d));
        double *f = s->slot_f + 3 * ((size_t)m->slot_base[FE_KIND_TRUSS] + 2 * (size_t)e);
        if (!(len > 0)) {
            if (bad < 0) bad = e;
            for (int i = 0; i < 6; i++) f[i] = 0;
            continue;
        }
        /* logarithmic strain increment between the previous and the current length */
        double dold[3] = {d[0] - dt * dv[0], d[1] - dt * dv[1], d[2] - dt * dv[2]};
        double lold = sqrt(fe_dot(dold, dold));
        double de = lold > 0 ? log(len / lold) : 0, rate = dt > 0 ? de / dt : 0;
        double sig0 = s->truss_sig[e];
        s->truss_epsp[e] += fe_mat_1d(p, &s->truss_sig[e], de, s->truss_epsp[e], fabs(rate));
        double n0 = tonly ? fmax(sig0, 0) : sig0, n1 = tonly ? fmax(s->truss_sig[e], 0)
                                                             : s->truss_sig[e];
        /* the work N dl, dl = l de at the step's middle length (second order: with the end
         * length the error N dl^2 / 2l has N's sign, a steady gain for a tension-only belt) */
        e_int += 0.5 * (n0 + n1) * area * de * 0.5 * (len + lold);
        double fn = n1 * area / len;
        for (int i = 0; i < 3; i++) {
            f[i] = -fn * d[i];
            f[3 + i] = fn * d[i];
        }
        double dte = len / c0 * fe_dt_factor(m, FE_KIND_TRUSS, e);
        if (dte < dtmin) dtmin = dte, dtel = e;
    }
    acc->e_int = e_int;
    acc->e_hg = 0;
    acc->e_diss = 0;
    acc->dtmin = dtmin;
    acc->dtel = dtel;
    acc->bad = bad;
}

void fe_truss_part(const fe_model *m, fe_state *s, int ip)
{
    fe_chunk_acc acc = {0};
    fe_truss_range(m, s, ip, m->part[ip].elem_begin, m->part[ip].elem_end, &acc);
    fe_chunk_commit(s, ip, &acc);
}

/* element steps from geometry alone (model build and state reset; solids with the linear bulk
 * viscosity, fe_bulk_dt) */
double fe_part_dt(const fe_model *m, int ip, const double *x, int *elem)
{
    const fe_part *p = &m->part[ip];
    double dtmin = INFINITY;
    *elem = -1;
    /* rigid and null parts do not limit the step */
    if (p->body >= 0 || p->material.model == FE_MAT_NULL) return INFINITY;
    for (int e = p->elem_begin; e < p->elem_end; e++) {
        double len = 0;
        if (p->elem_kind == FE_KIND_TET10) { /* its own frequency ratio (fe_tet10.c) */
            double dte = fe_tet10_dt(m, p, e, x);
            if (dte < dtmin) dtmin = dte, *elem = e;
            continue;
        }
        if (p->elem_kind == FE_KIND_HEX) {
            double xe[8][3], b[8][3], a[8][3];
            for (int n = 0; n < 8; n++)
                for (int i = 0; i < 3; i++) xe[n][i] = x[3 * m->hex_node[8 * e + n] + i];
            len = fe_hex_length(xe, fe_hex_gradients(xe, b, a));
        } else if (p->elem_kind == FE_KIND_SHELL) {
            double xe[4][3], fr[3][3], xl[4], yl[4];
            for (int n = 0; n < 4; n++)
                for (int i = 0; i < 3; i++) xe[n][i] = x[3 * m->shell_node[4 * e + n] + i];
            len = fe_shell_length(xe, fe_shell_frame(xe, fr, xl, yl));
        } else {
            double d2 = 0;
            for (int i = 0; i < 3; i++) {
                double d = x[3 * m->truss_node[2 * e + 1] + i] - x[3 * m->truss_node[2 * e] + i];
                d2 += d * d;
            }
            len = sqrt(d2);
        }
        double dte = (p->elem_kind == FE_KIND_HEX ? fe_bulk_dt(m, len, p->wave_speed, 0)
                                                  : len / p->wave_speed) *
                     fe_dt_factor(m, p->elem_kind, e);
        if (dte < dtmin) dtmin = dte, *elem = e;
    }
    return dtmin;
}

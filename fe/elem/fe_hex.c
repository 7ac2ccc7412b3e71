/* fe_hex: 8-node hexahedron, one-point integration with Flanagan-Belytschko hourglass control
 * (Flanagan & Belytschko 1981, Int. J. Numer. Meth. Eng. 17:679-706).
 *
 * Uniform gradients b_I = (1/V) dV/dx_I make the element pass the patch test for any shape.
 * The volume of the trilinear element, with x = a0 + a1 xi + a2 eta + a3 zeta + a4 xi eta +
 * a5 eta zeta + a6 xi zeta + a7 xi eta zeta, integrates exactly to
 *     V = 8 a1.(a2 x a3) + 8/3 [a4.(a2 x a5) + a6.(a5 x a3) + a1.(a4 x a6)],
 * and dV/dx_I = sum_k (dV/da_k) h_k(I) / 8 follows in closed form.
 * Hourglass shape vectors gamma = Gamma - (Gamma . x_j) b_j are orthogonal to linear fields.
 * Viscous form: f = c q gamma, c = Q rho c_wave V^(2/3) / 4 (the LS-DYNA form).
 * Stiffness form: dQ/dt = k q, k = Q (lambda + 2 mu) V (sum_I b_I . b_I) / 8, rotated with the
 * spin. Stress: Jaumann rate, strain increment D dt at the current configuration; bulk
 * viscosity q = rho L (q1 L eps_v'^2 - q2 c eps_v') in compression (Wilkins/LS-DYNA form). */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <string.h>

const double fe_hex_xi[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

/* h_k(I) for k = 0..7 (1, xi, eta, zeta, xi eta, eta zeta, xi zeta, xi eta zeta) */
static const double hbase[8][8] = {
    {1, 1, 1, 1, 1, 1, 1, 1},         {-1, 1, 1, -1, -1, 1, 1, -1},
    {-1, -1, 1, 1, -1, -1, 1, 1},     {-1, -1, -1, -1, 1, 1, 1, 1},
    {1, -1, 1, -1, 1, -1, 1, -1},     {1, 1, -1, -1, -1, -1, 1, 1},
    {1, -1, -1, 1, -1, 1, 1, -1},     {-1, 1, -1, 1, 1, -1, 1, -1}};
/* the four hourglass modes: base vectors 4..7 */
enum { HG0 = 4 };

double fe_hex_gradients(const double xe[8][3], double b[8][3], double a[8][3])
{
    for (int k = 1; k < 8; k++)
        for (int i = 0; i < 3; i++) {
            double s = 0;
            for (int n = 0; n < 8; n++) s += hbase[k][n] * xe[n][i];
            a[k][i] = 0.125 * s;
        }
    for (int i = 0; i < 3; i++) a[0][i] = 0;
    double g[7][3], t1[3], t2[3];
    const double third = 1.0 / 3.0;
    fe_cross(a[2], a[3], g[1]);
    fe_cross(a[4], a[6], t1);
    for (int i = 0; i < 3; i++) g[1][i] += third * t1[i];
    fe_cross(a[3], a[1], g[2]);
    fe_cross(a[5], a[4], t1);
    for (int i = 0; i < 3; i++) g[2][i] += third * t1[i];
    fe_cross(a[1], a[2], g[3]);
    fe_cross(a[6], a[5], t1);
    for (int i = 0; i < 3; i++) g[3][i] += third * t1[i];
    fe_cross(a[2], a[5], t1);
    fe_cross(a[6], a[1], t2);
    for (int i = 0; i < 3; i++) g[4][i] = third * (t1[i] + t2[i]);
    fe_cross(a[4], a[2], t1);
    fe_cross(a[3], a[6], t2);
    for (int i = 0; i < 3; i++) g[5][i] = third * (t1[i] + t2[i]);
    fe_cross(a[5], a[3], t1);
    fe_cross(a[1], a[4], t2);
    for (int i = 0; i < 3; i++) g[6][i] = third * (t1[i] + t2[i]);
    double c23[3], c25[3], c53[3], c46[3];
    fe_cross(a[2], a[3], c23);
    fe_cross(a[2], a[5], c25);
    fe_cross(a[5], a[3], c53);
    fe_cross(a[4], a[6], c46);
    double vol = 8 * fe_dot(a[1], c23) +
                 8 * third * (fe_dot(a[4], c25) + fe_dot(a[6], c53) + fe_dot(a[1], c46));
    double inv = vol != 0 ? 1 / vol : 0;
    for (int n = 0; n < 8; n++)
        for (int i = 0; i < 3; i++)
            b[n][i] = inv * (hbase[1][n] * g[1][i] + hbase[2][n] * g[2][i] +
                             hbase[3][n] * g[3][i] + hbase[4][n] * g[4][i] +
                             hbase[5][n] * g[5][i] + hbase[6][n] * g[6][i]);
    return vol;
}

double fe_hex_length(const double xe[8][3], double vol)
{
    static const int face[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    double amax = 0;
    for (int f = 0; f < 6; f++) {
        double d1[3], d2[3], c[3];
        for (int i = 0; i < 3; i++) {
            d1[i] = xe[face[f][2]][i] - xe[face[f][0]][i];
            d2[i] = xe[face[f][3]][i] - xe[face[f][1]][i];
        }
        fe_cross(d1, d2, c);
        amax = fmax(amax, fe_dot(c, c)); /* squared: one square root below */
    }
    amax = 0.5 * sqrt(amax);
    return amax > 0 ? vol / amax : 0;
}

static void gather8(const double *src, const int *c, double out[8][3])
{
    for (int n = 0; n < 8; n++) {
        const double *p = src + 3 * c[n];
        out[n][0] = p[0];
        out[n][1] = p[1];
        out[n][2] = p[2];
    }
}

void fe_hex_range(const fe_model *m, fe_state *s, int ip, int e0, int e1, fe_chunk_acc *acc)
{
    const fe_part *p = &m->part[ip];
    if (p->section.formulation == FE_HEX_FULL) { /* 2x2x2 Gauss, B-bar (fe_hex_full.c) */
        fe_hex_full_range(m, s, ip, e0, e1, acc);
        return;
    }
    const double dt = s->dt_prev, rho = p->material.density, c0 = p->wave_speed;
    const double mod = p->lambda + 2 * p->mu, qhg = p->hg_coef;
    const int visc = p->section.hourglass == FE_HG_VISCOUS;
    const int cs = p->material.cowper_symonds_c > 0;
    const double fail = p->material.failure_strain; /* erosion (m->nerode > 0 then) */
    double e_int = 0, e_hg = 0, e_diss = 0, dtmin = INFINITY, e_erode = 0;
    int dtel = -1, bad = -1, nerode = 0;
    for (int e = e0; e < e1; e++) {
        if (fail > 0 && s->elem_dead[e]) { /* deleted: no forces, no step limit */
            memset(s->slot_f + 3 * (8 * e), 0, 24 * sizeof(double));
            continue;
        }
        const int *c = m->hex_node + 8 * e;
        double xe[8][3], ve[8][3], b[8][3], a[8][3];
        gather8(s->node_x, c, xe);
        gather8(s->node_v, c, ve);
        double vol = fe_hex_gradients(xe, b, a);
        if (!(vol > 0)) {
            if (bad < 0) bad = e;
            memset(s->slot_f + 3 * (8 * e), 0, 24 * sizeof(double));
            continue;
        }
        /* velocity gradient L_ij = sum_I v_iI b_jI */
        double L[3][3] = {{0}};
        for (int n = 0; n < 8; n++)
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) L[i][j] += ve[n][i] * b[n][j];
        double de[6] = {L[0][0] * dt, L[1][1] * dt, L[2][2] * dt, 0.5 * (L[0][1] + L[1][0]) * dt,
                        0.5 * (L[1][2] + L[2][1]) * dt, 0.5 * (L[2][0] + L[0][2]) * dt};
        double *sg = s->hex_sig + 6 * e;
        double W[3][3];
        fe_spin(L, dt, W);
        fe_jaumann(sg, W); /* the stress at t, rotated with the material */
        double old[6];
        memcpy(old, sg, sizeof old);
        double dv = de[0] + de[1] + de[2];
        if (p->material.model == FE_MAT_FOAM) { /* total form (fe_foam.c); epsp: e_max */
            double *h = s->foam_hist + 6 * ((size_t)p->foam_begin + (size_t)(e - p->elem_begin));
            fe_foam_hex(m, p, c, xe, L, sg, h, &s->hex_epsp[e], &s->hex_rate[e]);
        } else {
            double rate = 0;
            if (cs) { /* effective deviatoric strain rate: only Cowper-Symonds uses it */
                rate = dt > 0 ? sqrt(2.0 / 3.0 *
                                     ((de[0] - dv / 3) * (de[0] - dv / 3) +
                                      (de[1] - dv / 3) * (de[1] - dv / 3) +
                                      (de[2] - dv / 3) * (de[2] - dv / 3) +
                                      2 * (de[3] * de[3] + de[4] * de[4] + de[5] * de[5]))) /
                                    dt
                              : 0;
                rate = s->hex_rate[e] = fe_rate_filter(s->hex_rate[e], rate);
            }
            s->hex_epsp[e] += fe_mat_3d(p, sg, de, s->hex_epsp[e], rate);
        }
        double w = 0;
        for (int i = 0; i < 3; i++) w += (old[i] + sg[i]) * de[i];
        for (int i = 3; i < 6; i++) w += 2 * (old[i] + sg[i]) * de[i];
        e_int += 0.5 * w * vol;
        int erode = 0;
        if (fail > 0) {
            s->elem_eint[e] += 0.5 * w * vol;
            erode = s->hex_epsp[e] >= fail; /* its forces act this step, then it is gone */
        }
        /* bulk viscosity in compression */
        double len = fe_hex_length(xe, vol), q = 0, evr = 0;
        if (dt > 0 && dv < 0) {
            evr = dv / dt;
            q = rho * len * (m->opts.bulk_q1 * len * evr * evr - m->opts.bulk_q2 * c0 * evr);
        }
        /* dissipation with the trapezoidal rule of every other work (fe_state.h) */
        e_diss += -0.5 * (s->hex_q[e] + q) * dv * vol;
        s->hex_q[e] = q;
        double dte = fe_bulk_dt(m, len, c0, evr) * fe_dt_factor(m, FE_KIND_HEX, e);
        if (dte < dtmin) dtmin = dte, dtel = e;
        /* nodal forces f_iI = V sig_ij b_jI */
        double sxx = sg[0] - q, syy = sg[1] - q, szz = sg[2] - q;
        double *f = s->slot_f + 3 * (8 * e);
        for (int n = 0; n < 8; n++) {
            f[3 * n + 0] = vol * (sxx * b[n][0] + sg[3] * b[n][1] + sg[5] * b[n][2]);
            f[3 * n + 1] = vol * (sg[3] * b[n][0] + syy * b[n][1] + sg[4] * b[n][2]);
            f[3 * n + 2] = vol * (sg[5] * b[n][0] + sg[4] * b[n][1] + szz * b[n][2]);
        }
        /* hourglass: gamma_a = Gamma_a - (8 a_k . b_I), rates q_ia = sum_I v_iI gamma_aI */
        double gam[4][8], qh[4][3] = {{0}};
        for (int al = 0; al < 4; al++)
            for (int n = 0; n < 8; n++) {
                gam[al][n] = hbase[HG0 + al][n] - 8 * fe_dot(a[HG0 + al], b[n]);
                for (int i = 0; i < 3; i++) qh[al][i] += ve[n][i] * gam[al][n];
            }
        double *hg = s->hex_hg + 12 * e, fh[4][3];
        if (visc) {
            /* a rate force needs a rate: none before the first step */
            double ch = dt > 0 ? qhg * rho * c0 * cbrt(vol * vol) / 4 : 0;
            for (int al = 0; al < 4; al++)
                for (int i = 0; i < 3; i++) {
                    fh[al][i] = ch * qh[al][i];
                    e_hg += 0.5 * (hg[3 * al + i] + fh[al][i]) * qh[al][i] * dt;
                    hg[3 * al + i] = fh[al][i];
                }
        } else {
            double bb = 0;
            for (int n = 0; n < 8; n++) bb += fe_dot(b[n], b[n]);
            double kh = qhg * mod * vol * bb / 8;
            for (int al = 0; al < 4; al++) {
                double *h = hg + 3 * al, r[3];
                /* rotate the stored force with the spin: h += W h */
                for (int i = 0; i < 3; i++) r[i] = W[i][0] * h[0] + W[i][1] * h[1] + W[i][2] * h[2];
                for (int i = 0; i < 3; i++) {
                    double h0 = h[i] + r[i];
                    h[i] = h0 + kh * qh[al][i] * dt;
                    fh[al][i] = h[i];
                    e_hg += 0.5 * (h0 + h[i]) * qh[al][i] * dt;
                }
            }
        }
        for (int n = 0; n < 8; n++)
            for (int i = 0; i < 3; i++)
                f[3 * n + i] += fh[0][i] * gam[0][n] + fh[1][i] * gam[1][n] +
                                fh[2][i] * gam[2][n] + fh[3][i] * gam[3][n];
        if (erode) {
            s->elem_dead[e] = 1;
            e_erode += s->elem_eint[e];
            nerode++;
        }
    }
    acc->e_erode = e_erode;
    acc->nerode = nerode;
    acc->e_int = e_int;
    acc->e_hg = e_hg;
    acc->e_diss = e_diss;
    acc->dtmin = dtmin;
    acc->dtel = dtel;
    acc->bad = bad;
}

void fe_hex_part(const fe_model *m, fe_state *s, int ip)
{
    fe_chunk_acc acc = {0};
    fe_hex_range(m, s, ip, m->part[ip].elem_begin, m->part[ip].elem_end, &acc);
    fe_chunk_commit(s, ip, &acc);
}

/* fe_hex_full: fully integrated hex8 (section formulation: full): 2x2x2 Gauss points with a
 * selective-reduced volumetric term, so that nearly incompressible flow does not lock. No
 * hourglass modes, no hourglass control.
 *
 * At Gauss point g: L_g = sum_I v_I (x) dN_I/dx (x_g), D_g its symmetric part, and the
 * material sees
 *     D~_g = D_g + (beta / 3) (theta - tr D_g) 1,   theta = sum_I v_I . b_I
 * with b_I = (1/V) dV/dx_I the uniform gradients (theta = (dV/dt)/V, the mean dilatation).
 * For an isotropic elastic material beta = lambda / K makes C : D~_g = lambda theta 1 +
 * 2 mu D_g exactly: the lambda (bulk-excess) term at one point, the mu term at eight, the
 * selective-reduced integration of Hughes (1977; Malkus & Hughes 1978, Comput. Methods Appl.
 * Mech. Eng. 15:63-81): full integration at nu = 0 (exact bending with one element through
 * the thickness), the mean-dilatation B-bar as nu -> 1/2. J2 plasticity takes beta = 1 (the
 * B-bar of Hughes 1980 / Nagtegaal, Parks & Rice 1974: plastic flow is isochoric).
 * The stress power sum_g w_g J_g sig_g : D~_g gives the nodal forces
 *     f_I = sum_g w_g J_g (sig_g - beta p_g 1) dN_I/dx + (sum_g w_g J_g beta p_g) b_I
 * (p = tr sig / 3), plus the bulk viscosity q as in the one-point hex. The stress is
 * updated with the Jaumann rate (spin of the point). Shear locking in bending is that of the
 * trilinear element (parasitic shear of relative energy (a/h)^2 / (2(1 + nu)) for element
 * length a and height h: keep elements short along a bent beam, or use shells). hex_sig is
 * the volume average of the points' stresses; hex_epsp their mean plastic strain (foam:
 * largest compressive strain). */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <string.h>

/* shape-function derivatives dN_I/dxi at the 8 Gauss points (xi = +-1/sqrt(3)) */
static void gauss_dn(double dn[8][8][3])
{
    const double g = 1 / sqrt(3.0);
    for (int q = 0; q < 8; q++) {
        const double p[3] = {fe_hex_xi[q][0] * g, fe_hex_xi[q][1] * g, fe_hex_xi[q][2] * g};
        for (int n = 0; n < 8; n++) {
            const double *s = fe_hex_xi[n];
            dn[q][n][0] = 0.125 * s[0] * (1 + s[1] * p[1]) * (1 + s[2] * p[2]);
            dn[q][n][1] = 0.125 * s[1] * (1 + s[0] * p[0]) * (1 + s[2] * p[2]);
            dn[q][n][2] = 0.125 * s[2] * (1 + s[0] * p[0]) * (1 + s[1] * p[1]);
        }
    }
}

/* dN/dx = J^-T dN/dxi at one point of an element with nodes x; returns det J */
static double point_gradients(const double x[8][3], const double dn[8][3], double dx[8][3])
{
    double J[3][3] = {{0}}; /* J_ij = dx_i / dxi_j */
    for (int n = 0; n < 8; n++)
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) J[i][j] += x[n][i] * dn[n][j];
    double c[3][3] = {{J[1][1] * J[2][2] - J[1][2] * J[2][1], J[1][2] * J[2][0] - J[1][0] * J[2][2],
                       J[1][0] * J[2][1] - J[1][1] * J[2][0]},
                      {J[0][2] * J[2][1] - J[0][1] * J[2][2], J[0][0] * J[2][2] - J[0][2] * J[2][0],
                       J[0][1] * J[2][0] - J[0][0] * J[2][1]},
                      {J[0][1] * J[1][2] - J[0][2] * J[1][1], J[0][2] * J[1][0] - J[0][0] * J[1][2],
                       J[0][0] * J[1][1] - J[0][1] * J[1][0]}};
    double det = J[0][0] * c[0][0] + J[0][1] * c[0][1] + J[0][2] * c[0][2];
    if (!(det > 0)) return det;
    /* J^-1 = c^T / det, so dN/dx_i = sum_j dN/dxi_j (J^-1)_ji = sum_j dN/dxi_j c_ij / det */
    for (int n = 0; n < 8; n++)
        for (int i = 0; i < 3; i++)
            dx[n][i] = (dn[n][0] * c[i][0] + dn[n][1] * c[i][1] + dn[n][2] * c[i][2]) / det;
    return det;
}

static void gather8(const double *src, const int *c, double out[8][3])
{
    for (int n = 0; n < 8; n++) memcpy(out[n], src + 3 * c[n], sizeof out[n]);
}

void fe_hex_full_range(const fe_model *m, fe_state *s, int ip, int e0, int e1, fe_chunk_acc *acc)
{
    const fe_part *p = &m->part[ip];
    const double dt = s->dt_prev, rho = p->material.density, c0 = p->wave_speed;
    const int foam = p->material.model == FE_MAT_FOAM;
    const double beta = p->material.model == FE_MAT_ELASTIC_PLASTIC ? 1 : p->lambda / p->bulk;
    double dn[8][8][3];
    gauss_dn(dn);
    double e_int = 0, e_diss = 0, dtmin = INFINITY;
    int dtel = -1, bad = -1;
    for (int e = e0; e < e1; e++) {
        const int *c = m->hex_node + 8 * e;
        double xe[8][3], ve[8][3], b[8][3], a[8][3], x0[8][3];
        gather8(s->node_x, c, xe);
        gather8(s->node_v, c, ve);
        if (foam) gather8(m->node_x0, c, x0);
        double *f = s->slot_f + 3 * (8 * (size_t)e);
        double vol = fe_hex_gradients(xe, b, a);
        if (!(vol > 0)) {
            if (bad < 0) bad = e;
            memset(f, 0, 24 * sizeof(double));
            continue;
        }
        double theta = 0; /* mean dilatation rate (dV/dt)/V */
        for (int n = 0; n < 8; n++) theta += fe_dot(ve[n], b[n]);
        memset(f, 0, 24 * sizeof(double));
        double psum = 0, savg[6] = {0}, epsum = 0, rate0 = s->hex_rate[e], rate_new = rate0;
        for (int q = 0; q < 8; q++) {
            double dx[8][3], L[3][3] = {{0}};
            double wj = point_gradients(xe, dn[q], dx);
            if (!(wj > 0)) {
                if (bad < 0) bad = e;
                break;
            }
            for (int n = 0; n < 8; n++)
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++) L[i][j] += ve[n][i] * dx[n][j];
            double trd = beta * (L[0][0] + L[1][1] + L[2][2] - theta) / 3;
            double de[6] = {(L[0][0] - trd) * dt, (L[1][1] - trd) * dt, (L[2][2] - trd) * dt,
                            0.5 * (L[0][1] + L[1][0]) * dt, 0.5 * (L[1][2] + L[2][1]) * dt,
                            0.5 * (L[2][0] + L[0][2]) * dt};
            double *gp = s->hex_gp + 7 * ((size_t)p->gp_begin + 8 * (size_t)(e - p->elem_begin) + q);
            double *sg = gp, old[6];
            double W[3][3];
            fe_spin(L, dt, W);
            fe_jaumann(sg, W);
            memcpy(old, sg, sizeof old);
            if (foam) {
                /* the deformation gradient of the point, t = 0 -> t */
                double dx0[8][3], F[3][3] = {{0}}, r = rate0;
                (void)point_gradients(x0, dn[q], dx0);
                for (int n = 0; n < 8; n++)
                    for (int i = 0; i < 3; i++)
                        for (int j = 0; j < 3; j++) F[i][j] += xe[n][i] * dx0[n][j];
                double *h = s->foam_hist +
                            6 * ((size_t)p->foam_begin + 8 * (size_t)(e - p->elem_begin) + q);
                fe_foam_stress(p, F, L, sg, h, &gp[6], &r);
                if (q == 0) rate_new = r;
            } else {
                double dv = de[0] + de[1] + de[2], rate = 0;
                if (p->material.cowper_symonds_c > 0 && dt > 0) {
                    double d2 = 0;
                    for (int i = 0; i < 3; i++) d2 += (de[i] - dv / 3) * (de[i] - dv / 3);
                    for (int i = 3; i < 6; i++) d2 += 2 * de[i] * de[i];
                    rate = fe_rate_filter(rate0, sqrt(2.0 / 3.0 * d2) / dt);
                    if (q == 0) rate_new = rate;
                }
                gp[6] += fe_mat_3d(p, sg, de, gp[6], rate);
            }
            double w = 0;
            for (int i = 0; i < 3; i++) w += (old[i] + sg[i]) * de[i];
            for (int i = 3; i < 6; i++) w += 2 * (old[i] + sg[i]) * de[i];
            e_int += 0.5 * w * wj;
            /* the point's forces; beta p goes through b (mean dilatation) */
            double pm = beta * (sg[0] + sg[1] + sg[2]) / 3;
            double sxx = sg[0] - pm, syy = sg[1] - pm, szz = sg[2] - pm;
            for (int n = 0; n < 8; n++) {
                f[3 * n + 0] += wj * (sxx * dx[n][0] + sg[3] * dx[n][1] + sg[5] * dx[n][2]);
                f[3 * n + 1] += wj * (sg[3] * dx[n][0] + syy * dx[n][1] + sg[4] * dx[n][2]);
                f[3 * n + 2] += wj * (sg[5] * dx[n][0] + sg[4] * dx[n][1] + szz * dx[n][2]);
            }
            psum += wj * pm;
            for (int i = 0; i < 6; i++) savg[i] += wj * sg[i] / vol;
            epsum += gp[6] / 8;
        }
        s->hex_rate[e] = rate_new;
        memcpy(s->hex_sig + 6 * (size_t)e, savg, sizeof savg);
        s->hex_epsp[e] = epsum;
        /* bulk viscosity in compression, as the one-point hex */
        double len = fe_hex_length(xe, vol), qv = 0;
        if (dt > 0 && theta < 0)
            qv = rho * len * (m->opts.bulk_q1 * len * theta * theta - m->opts.bulk_q2 * c0 * theta);
        e_diss += -0.5 * (s->hex_q[e] + qv) * theta * dt * vol;
        s->hex_q[e] = qv;
        for (int n = 0; n < 8; n++)
            for (int i = 0; i < 3; i++) f[3 * n + i] += (psum - qv * vol) * b[n][i];
        double dte = fe_bulk_dt(m, len, c0, dt > 0 ? theta : 0) * fe_dt_factor(m, FE_KIND_HEX, e);
        if (dte < dtmin) dtmin = dte, dtel = e;
    }
    acc->e_int = e_int;
    acc->e_hg = 0;
    acc->e_diss = e_diss;
    acc->dtmin = dtmin;
    acc->dtel = dtel;
    acc->bad = bad;
}

/* fe_shell_bt: Belytschko-Tsay 4-node shell (Belytschko, Lin & Tsay 1984, Comput. Meth. Appl.
 * Mech. Eng. 42:225-251; Hallquist, LS-DYNA Theory Manual, "Belytschko-Tsay shell").
 *
 * Corotational local frame (e3 from the diagonals, e1 along side 1-2); Mindlin kinematics with
 * one point in the plane and Gauss points through the thickness:
 *   d_x(z) = sum B1 vx + z sum B1 wy,   d_y(z) = sum B2 vy - z sum B2 wx,
 *   2d_xy(z) = sum (B2 vx + B1 vy) + z sum (B2 wy - B1 wx),
 *   2d_xz = sum B1 vz + sum N wy,      2d_yz = sum B2 vz - sum N wx   (N = 1/4 at the centre).
 * Plane stress per point (fe_mat_plane_stress), elastic transverse shear with factor k.
 * Resisting nodal forces are the derivatives of the stress power A (N.d + M.kappa + Q.gamma).
 * Hourglass (stiffness form, local frame): gamma_I = h_I - (h.x) B1_I - (h.y) B2_I,
 * h = (1, -1, 1, -1); each mode's stiffness is Q_hg times an estimate of its physical one:
 *   in-plane  k_m = Q E t A (B.B) / 8,  out-of-plane w  k_w = Q k G t^3 A (B.B)^2 / 12
 *   (the twist stiffness of the mode), rotations k_r = Q E t^3 A (B.B) / 192.
 * The viscous form uses the same coefficients times the element transit time L/c.
 * Degenerate triangles (node 3 = node 4) use the same one-point formulas: the uniform gradients
 * are then those of the constant-strain triangle and every hourglass vector vanishes.
 * Not built: warping correction, thickness change, drilling stiffness. */
#include "fe/fe_elem.h"

#include <math.h>
#include <string.h>

double fe_shell_frame(const double xe[4][3], double e[3][3], double xl[4], double yl[4])
{
    double d1[3], d2[3], s1[3], cen[3];
    for (int i = 0; i < 3; i++) {
        d1[i] = xe[2][i] - xe[0][i];
        d2[i] = xe[3][i] - xe[1][i];
        s1[i] = xe[1][i] - xe[0][i];
        cen[i] = 0.25 * (xe[0][i] + xe[1][i] + xe[2][i] + xe[3][i]);
    }
    fe_cross(d1, d2, e[2]);
    double n = sqrt(fe_dot(e[2], e[2]));
    if (!(n > 0)) return 0;
    for (int i = 0; i < 3; i++) e[2][i] /= n;
    double sd = fe_dot(s1, e[2]);
    for (int i = 0; i < 3; i++) e[0][i] = s1[i] - sd * e[2][i];
    n = sqrt(fe_dot(e[0], e[0]));
    if (!(n > 0)) return 0;
    for (int i = 0; i < 3; i++) e[0][i] /= n;
    fe_cross(e[2], e[0], e[1]);
    for (int k = 0; k < 4; k++) {
        double r[3] = {xe[k][0] - cen[0], xe[k][1] - cen[1], xe[k][2] - cen[2]};
        xl[k] = fe_dot(r, e[0]);
        yl[k] = fe_dot(r, e[1]);
    }
    return 0.5 * ((xl[2] - xl[0]) * (yl[3] - yl[1]) + (xl[1] - xl[3]) * (yl[2] - yl[0]));
}

double fe_shell_length(const double xe[4][3], double area)
{
    double lmax = 0;
    for (int k = 0; k < 4; k++) {
        const double *a = xe[k], *b = xe[(k + 1) & 3];
        double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        lmax = fmax(lmax, fe_dot(d, d));
    }
    /* (1 + beta) A / longest side, beta = 1 for a degenerate triangle (its smallest altitude) */
    double beta = xe[2][0] == xe[3][0] && xe[2][1] == xe[3][1] && xe[2][2] == xe[3][2] ? 1 : 0;
    return lmax > 0 ? (1 + beta) * area / sqrt(lmax) : 0;
}

void fe_shell_part(const fe_model *m, fe_state *s, int ip)
{
    const fe_part *p = &m->part[ip];
    const double dt = s->dt_prev, t = p->section.thickness, c0 = p->wave_speed;
    const double E = p->material.youngs_modulus, G = p->mu, ks = p->shear_factor;
    const int nip = p->section.integration_points, stride = m->nip_max;
    const int visc = p->section.hourglass == FE_HG_VISCOUS;
    const double qhg = p->hg_coef;
    double e_int = 0, e_hg = 0, dtmin = INFINITY;
    int dtel = -1, bad = -1;
    for (int e = p->elem_begin; e < p->elem_end; e++) {
        const int *c = m->shell_node + 4 * e;
        double xe[4][3], fr[3][3], xl[4], yl[4];
        for (int k = 0; k < 4; k++) memcpy(xe[k], s->node_x + 3 * c[k], sizeof xe[k]);
        double A = fe_shell_frame(xe, fr, xl, yl);
        double *f = s->slot_f + 3 * ((size_t)m->slot_base[FE_KIND_SHELL] + 4 * (size_t)e);
        double *mo = s->shell_m + 12 * (size_t)e;
        if (!(A > 0)) {
            if (bad < 0) bad = e;
            memset(f, 0, 12 * sizeof(double));
            memset(mo, 0, 12 * sizeof(double));
            continue;
        }
        /* local velocities */
        double vx[4], vy[4], vz[4], wx[4], wy[4];
        for (int k = 0; k < 4; k++) {
            const double *v = s->node_v + 3 * c[k], *w = s->node_w + 3 * c[k];
            vx[k] = fe_dot(v, fr[0]);
            vy[k] = fe_dot(v, fr[1]);
            vz[k] = fe_dot(v, fr[2]);
            wx[k] = fe_dot(w, fr[0]);
            wy[k] = fe_dot(w, fr[1]);
        }
        const double i2a = 0.5 / A;
        const double B1[4] = {i2a * (yl[1] - yl[3]), i2a * (yl[2] - yl[0]), i2a * (yl[3] - yl[1]),
                              i2a * (yl[0] - yl[2])};
        const double B2[4] = {i2a * (xl[3] - xl[1]), i2a * (xl[0] - xl[2]), i2a * (xl[1] - xl[3]),
                              i2a * (xl[2] - xl[0])};
        double dm[3] = {0}, kp[3] = {0}, gs[2] = {0};
        for (int k = 0; k < 4; k++) {
            dm[0] += B1[k] * vx[k];
            dm[1] += B2[k] * vy[k];
            dm[2] += B2[k] * vx[k] + B1[k] * vy[k];
            kp[0] += B1[k] * wy[k];
            kp[1] -= B2[k] * wx[k];
            kp[2] += B2[k] * wy[k] - B1[k] * wx[k];
            gs[0] += B1[k] * vz[k] + 0.25 * wy[k];
            gs[1] += B2[k] * vz[k] - 0.25 * wx[k];
        }
        /* through-thickness points: plane stress update, resultants N and M */
        double N[3] = {0}, M[3] = {0}, w_int = 0;
        double *sg = s->shell_sig + 3 * (size_t)stride * e, *ep = s->shell_epsp + (size_t)stride * e;
        for (int g = 0; g < nip; g++) {
            double z = p->ip_z[g] * t, wt = p->ip_w[g] * t;
            double de[3] = {(dm[0] + z * kp[0]) * dt, (dm[1] + z * kp[1]) * dt,
                            (dm[2] + z * kp[2]) * dt};
            double *sp = sg + 3 * g, old[3] = {sp[0], sp[1], sp[2]};
            double rate = 0;
            if (dt > 0) {
                double ex = de[0] / dt, ey = de[1] / dt, gxy = de[2] / dt;
                rate = sqrt(4.0 / 3.0 * (ex * ex + ey * ey + ex * ey) + gxy * gxy / 3);
            }
            if (p->material.cowper_symonds_c > 0) {
                double *rf = s->shell_rate + (size_t)stride * e + g;
                rate = *rf = fe_rate_filter(*rf, rate);
            }
            ep[g] += fe_mat_plane_stress(p, sp, de, ep[g], rate);
            w_int += wt * ((old[0] + sp[0]) * de[0] + (old[1] + sp[1]) * de[1] +
                           (old[2] + sp[2]) * de[2]);
            for (int i = 0; i < 3; i++) {
                N[i] += wt * sp[i];
                M[i] += wt * z * sp[i];
            }
        }
        double *tau = s->shell_tau + 2 * (size_t)e, Q[2];
        for (int i = 0; i < 2; i++) {
            double t0 = tau[i];
            tau[i] += ks * G * gs[i] * dt;
            w_int += t * (t0 + tau[i]) * gs[i] * dt;
            Q[i] = t * tau[i];
        }
        e_int += 0.5 * A * w_int;
        /* hourglass */
        const double h[4] = {1, -1, 1, -1};
        double hx = 0, hy = 0, bb = 0;
        for (int k = 0; k < 4; k++) {
            hx += h[k] * xl[k];
            hy += h[k] * yl[k];
            bb += B1[k] * B1[k] + B2[k] * B2[k];
        }
        double gam[4], qh[5] = {0};
        for (int k = 0; k < 4; k++) {
            gam[k] = h[k] - hx * B1[k] - hy * B2[k];
            qh[0] += gam[k] * vx[k];
            qh[1] += gam[k] * vy[k];
            qh[2] += gam[k] * vz[k];
            qh[3] += gam[k] * wx[k];
            qh[4] += gam[k] * wy[k];
        }
        double km = qhg * E * t * A * bb / 8, kw = qhg * ks * G * t * t * t * A * bb * bb / 12,
               kr = qhg * E * t * t * t * A * bb / 192;
        double kk[5] = {km, km, kw, kr, kr}, fh[5];
        double len = fe_shell_length(xe, A);
        double *hg = s->shell_hg + 5 * (size_t)e;
        for (int i = 0; i < 5; i++) {
            if (visc) {
                fh[i] = dt > 0 ? kk[i] * (len / c0) * qh[i] : 0; /* no rate before step 1 */
                e_hg += 0.5 * (hg[i] + fh[i]) * qh[i] * dt;
                hg[i] = fh[i];
            } else {
                double h0 = hg[i];
                hg[i] += kk[i] * qh[i] * dt;
                fh[i] = hg[i];
                e_hg += 0.5 * (h0 + hg[i]) * qh[i] * dt;
            }
        }
        /* resisting local forces and moments, back to the global frame */
        for (int k = 0; k < 4; k++) {
            double fx = A * (B1[k] * N[0] + B2[k] * N[2]) + fh[0] * gam[k];
            double fy = A * (B2[k] * N[1] + B1[k] * N[2]) + fh[1] * gam[k];
            double fz = A * (B1[k] * Q[0] + B2[k] * Q[1]) + fh[2] * gam[k];
            double mx = A * (-B2[k] * M[1] - B1[k] * M[2] - 0.25 * Q[1]) + fh[3] * gam[k];
            double my = A * (B1[k] * M[0] + B2[k] * M[2] + 0.25 * Q[0]) + fh[4] * gam[k];
            for (int i = 0; i < 3; i++) {
                f[3 * k + i] = fx * fr[0][i] + fy * fr[1][i] + fz * fr[2][i];
                mo[3 * k + i] = mx * fr[0][i] + my * fr[1][i];
            }
        }
        double dte = len / c0;
        if (dte < dtmin) dtmin = dte, dtel = e;
    }
    double *pe = s->part_energy + FE_NENERGY * ip;
    pe[FE_E_internal] += e_int;
    pe[FE_E_hourglass] += e_hg;
    s->part_dt[ip] = dtmin;
    s->part_dt_elem[ip] = dtel;
    if (bad >= 0 && s->part_bad_elem[ip] < 0) s->part_bad_elem[ip] = bad;
}

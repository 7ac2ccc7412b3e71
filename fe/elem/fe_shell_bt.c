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

/* the frame and local coordinates (fe_shell_frame), inlined in the element loop */
static inline __attribute__((always_inline)) double shell_frame(const double xe[4][3], double e[3][3], double xl[4],
                                 double yl[4])
{
    double d1[3], d2[3], s1[3], cen[3];
    /* the 3-component loops are vectorised (`omp simd`: element-wise, so the same bits as
     * the scalar loop; the -O2 cost model leaves them scalar, and they are a tenth of the
     * element's time) */
#pragma omp simd
    for (int i = 0; i < 3; i++) {
        d1[i] = xe[2][i] - xe[0][i];
        d2[i] = xe[3][i] - xe[1][i];
        s1[i] = xe[1][i] - xe[0][i];
        cen[i] = 0.25 * (xe[0][i] + xe[1][i] + xe[2][i] + xe[3][i]);
    }
    /* both normalisations from the raw vectors, so the two square roots run in parallel:
     * with E = d1 x d2, e3 = E / |E| and e1 = (s1 - (s1.e3) e3) / |...| where
     * |s1 - (s1.e3) e3|^2 = (|E|^2 |s1|^2 - (s1.E)^2) / |E|^2 */
    double E[3];
    fe_cross(d1, d2, E);
    const double n2 = fe_dot(E, E), sE = fe_dot(s1, E), n0 = n2 * fe_dot(s1, s1) - sE * sE;
    if (!(n2 > 0) || !(n0 > 0)) return 0;
    /* one division: inv = 1 / (|E| sqrt(n0)); 1/|E| = sqrt(n0) inv */
    const double sa = sqrt(n2), sb = sqrt(n0), inv = 1 / (sa * sb);
#pragma omp simd
    for (int i = 0; i < 3; i++) {
        e[2][i] = E[i] * (sb * inv);
        e[0][i] = (n2 * s1[i] - sE * E[i]) * inv; /* = (s1 - (s1.e3) e3) / |...| */
    }
    fe_cross(e[2], e[0], e[1]);
    for (int k = 0; k < 4; k++) {
        double r[3] = {xe[k][0] - cen[0], xe[k][1] - cen[1], xe[k][2] - cen[2]};
        xl[k] = fe_dot(r, e[0]);
        yl[k] = fe_dot(r, e[1]);
    }
    return 0.5 * ((xl[2] - xl[0]) * (yl[3] - yl[1]) + (xl[1] - xl[3]) * (yl[2] - yl[0]));
}

/* squared longest side, and whether the quad is a degenerate triangle (node 3 = node 4) */
static inline __attribute__((always_inline)) double shell_side2(const double xe[4][3], int *tri)
{
    double lmax = 0;
    for (int k = 0; k < 4; k++) {
        const double *a = xe[k], *b = xe[(k + 1) & 3];
        double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double l2 = fe_dot(d, d);
        lmax = l2 > lmax ? l2 : lmax; /* fmax without the library call (lmax is never NaN) */
    }
    *tri = xe[2][0] == xe[3][0] && xe[2][1] == xe[3][1] && xe[2][2] == xe[3][2];
    return lmax;
}

double fe_shell_frame(const double xe[4][3], double e[3][3], double xl[4], double yl[4])
{
    return shell_frame(xe, e, xl, yl);
}

double fe_shell_length(const double xe[4][3], double area)
{
    int tri;
    double lmax = shell_side2(xe, &tri);
    /* (1 + beta) A / longest side, beta = 1 for a degenerate triangle (its smallest altitude) */
    return lmax > 0 ? (1 + tri) * area / sqrt(lmax) : 0;
}

/* the constants of thickness t: point positions and weights through it, hourglass stiffnesses */
static void thickness_consts(const fe_part *p, double t, double qhg, double E, double G,
                             double ks, double *zt, double *wt, double *wz, double *km0,
                             double *kw0, double *kr0)
{
    for (int g = 0; g < p->section.integration_points; g++) {
        zt[g] = p->ip_z[g] * t;
        wt[g] = p->ip_w[g] * t;
        wz[g] = wt[g] * zt[g];
    }
    *km0 = qhg * E * t / 8, *kw0 = qhg * ks * G * t * t * t / 12, *kr0 = qhg * E * t * t * t / 192;
}

void fe_shell_range(const fe_model *m, fe_state *s, int ip, int e0, int e1, fe_chunk_acc *acc)
{
    const fe_part *p = &m->part[ip];
    const double dt = s->dt_prev, c0 = p->wave_speed;
    double t = m->shell_t[e0 < e1 ? e0 : 0]; /* the per-thickness constants below follow it */
    const double E = p->material.youngs_modulus, G = p->mu, ks = p->shear_factor;
    const int nip = p->section.integration_points, stride = m->nip_max;
    const int visc = p->section.hourglass == FE_HG_VISCOUS;
    const int cs = p->material.cowper_symonds_c > 0;
    const double qhg = p->hg_coef, ic0 = 1 / c0, idt = dt > 0 ? 1 / dt : 0;
    /* per-part constants: plane stress, point positions and weights, hourglass stiffnesses */
    fe_ps_const k;
    fe_ps_const_init(p, &k);
    double zt[FE_NIP_MAX], wt[FE_NIP_MAX], wz[FE_NIP_MAX], km0, kw0, kr0;
    const double ksg = ks * G * dt;
    thickness_consts(p, t, qhg, E, G, ks, zt, wt, wz, &km0, &kw0, &kr0);
    const double *restrict X = s->node_x, *restrict V = s->node_v, *restrict W = s->node_w;
    double *restrict sig_all = s->shell_sig, *restrict epsp_all = s->shell_epsp;
    double e_int = 0, e_hg = 0, dtmin = INFINITY, e_erode = 0;
    int dtel = -1, bad = -1, nerode = 0;
    /* erosion (m->nerode > 0 then): shell e's flags at nhex + e */
    const double fail = p->material.failure_strain;
    unsigned char *dead = fail > 0 ? s->elem_dead + m->nhex : NULL;
    double *eint = fail > 0 ? s->elem_eint + m->nhex : NULL;
    for (int e = e0; e < e1; e++) {
        if (m->shell_t[e] != t) { /* a shell of its own thickness (*ELEMENT_SHELL_THICKNESS) */
            t = m->shell_t[e];
            thickness_consts(p, t, qhg, E, G, ks, zt, wt, wz, &km0, &kw0, &kr0);
        }
        const int *c = m->shell_node + 4 * e;
        double xe[4][3], fr[3][3], xl[4], yl[4];
        double *restrict f = s->slot_f + 3 * ((size_t)m->slot_base[FE_KIND_SHELL] + 4 * (size_t)e);
        double *restrict mo = s->shell_m + 12 * (size_t)e;
        if (dead && dead[e]) { /* deleted: no forces, no step limit */
            memset(f, 0, 12 * sizeof(double));
            memset(mo, 0, 12 * sizeof(double));
            continue;
        }
        for (int q = 0; q < 4; q++) memcpy(xe[q], X + 3 * c[q], sizeof xe[q]);
        double A = shell_frame(xe, fr, xl, yl);
        if (!(A > 0)) {
            if (bad < 0) bad = e;
            memset(f, 0, 12 * sizeof(double));
            memset(mo, 0, 12 * sizeof(double));
            continue;
        }
        /* local velocities */
        double vx[4], vy[4], vz[4], wx[4], wy[4];
        for (int q = 0; q < 4; q++) {
            const double *v = V + 3 * c[q], *w = W + 3 * c[q];
            vx[q] = fe_dot(v, fr[0]);
            vy[q] = fe_dot(v, fr[1]);
            vz[q] = fe_dot(v, fr[2]);
            wx[q] = fe_dot(w, fr[0]);
            wy[q] = fe_dot(w, fr[1]);
        }
        /* one division for 1/(2A) and the characteristic length (1 + beta) A / longest side
         * (beta = 1 for a degenerate triangle); a positive area has a positive longest side */
        int tri;
        const double side = sqrt(shell_side2(xe, &tri)), iAs = 1 / (A * side);
        const double i2a = 0.5 * side * iAs, len = (1 + tri) * A * A * iAs, dte = len * ic0;
        const double B1[4] = {i2a * (yl[1] - yl[3]), i2a * (yl[2] - yl[0]), i2a * (yl[3] - yl[1]),
                              i2a * (yl[0] - yl[2])};
        const double B2[4] = {i2a * (xl[3] - xl[1]), i2a * (xl[0] - xl[2]), i2a * (xl[1] - xl[3]),
                              i2a * (xl[2] - xl[0])};
        double dm[3] = {0}, kp[3] = {0}, gs[2] = {0};
        for (int q = 0; q < 4; q++) {
            dm[0] += B1[q] * vx[q];
            dm[1] += B2[q] * vy[q];
            dm[2] += B2[q] * vx[q] + B1[q] * vy[q];
            kp[0] += B1[q] * wy[q];
            kp[1] -= B2[q] * wx[q];
            kp[2] += B2[q] * wy[q] - B1[q] * wx[q];
            gs[0] += B1[q] * vz[q] + 0.25 * wy[q];
            gs[1] += B2[q] * vz[q] - 0.25 * wx[q];
        }
        /* through-thickness points: elastic trials, the plastic ones returned together
         * (fe_ps_return_batch), then the resultants N and M and the stress power */
        double N[3] = {0}, M[3] = {0}, w_int = 0;
        double *sg = sig_all + 3 * (size_t)stride * e, *ep = epsp_all + (size_t)stride * e;
        double deg[FE_NIP_MAX][3], old[FE_NIP_MAX][3];
        double psig[FE_NIP_MAX][3], pq[FE_NIP_MAX], pep[FE_NIP_MAX], prf[FE_NIP_MAX];
        fe_ps_flowpt pfl[FE_NIP_MAX];
        double pdp[FE_NIP_MAX];
        int pidx[FE_NIP_MAX], np = 0;
        for (int g = 0; g < nip; g++) {
            const double z = zt[g];
            double *de = deg[g], *sp = sg + 3 * g;
            de[0] = (dm[0] + z * kp[0]) * dt;
            de[1] = (dm[1] + z * kp[1]) * dt;
            de[2] = (dm[2] + z * kp[2]) * dt;
            old[g][0] = sp[0], old[g][1] = sp[1], old[g][2] = sp[2];
            double rate = 0;
            if (cs) {
                /* effective strain rate (only the Cowper-Symonds factor uses it) */
                double ex = de[0] * idt, ey = de[1] * idt, gxy = de[2] * idt;
                double *rf = s->shell_rate + (size_t)stride * e + g;
                rate = dt > 0 ? sqrt(4.0 / 3.0 * (ex * ex + ey * ey + ex * ey) + gxy * gxy / 3) : 0;
                rate = *rf = fe_rate_filter(*rf, rate);
            }
            if (fe_ps_trial(&k, sp, de, ep[g], rate, &pq[np], &prf[np], &pfl[np])) {
                psig[np][0] = sp[0], psig[np][1] = sp[1], psig[np][2] = sp[2];
                pep[np] = ep[g];
                pidx[np++] = g;
            }
        }
        if (np > 0) {
            fe_ps_return_batch(&k, np, psig, pq, pep, prf, pfl, pdp);
            for (int i = 0; i < np; i++) {
                double *sp = sg + 3 * pidx[i];
                sp[0] = psig[i][0], sp[1] = psig[i][1], sp[2] = psig[i][2];
                ep[pidx[i]] += pdp[i];
            }
        }
        for (int g = 0; g < nip; g++) {
            const double *sp = sg + 3 * g, *de = deg[g], *o = old[g];
            w_int += wt[g] * ((o[0] + sp[0]) * de[0] + (o[1] + sp[1]) * de[1] +
                              (o[2] + sp[2]) * de[2]);
#pragma omp simd
            for (int i = 0; i < 3; i++) {
                N[i] += wt[g] * sp[i];
                M[i] += wz[g] * sp[i];
            }
        }
        double *tau = s->shell_tau + 2 * (size_t)e, Q[2];
        for (int i = 0; i < 2; i++) {
            double t0 = tau[i];
            tau[i] += ksg * gs[i];
            w_int += t * (t0 + tau[i]) * gs[i] * dt;
            Q[i] = t * tau[i];
        }
        e_int += 0.5 * A * w_int;
        int erode = 0;
        if (dead) { /* any point through the thickness (LS-DYNA NUMFIP 1) */
            eint[e] += 0.5 * A * w_int;
            for (int g = 0; g < nip; g++) erode |= ep[g] >= fail;
        }
        /* hourglass */
        const double hx = xl[0] - xl[1] + xl[2] - xl[3], hy = yl[0] - yl[1] + yl[2] - yl[3];
        double bb = 0;
        for (int q = 0; q < 4; q++) bb += B1[q] * B1[q] + B2[q] * B2[q];
        double gam[4], qh[5] = {0};
        for (int q = 0; q < 4; q++) {
            static const double hsign[4] = {1, -1, 1, -1}; /* h = (1, -1, 1, -1) */
            gam[q] = hsign[q] - hx * B1[q] - hy * B2[q];
            qh[0] += gam[q] * vx[q];
            qh[1] += gam[q] * vy[q];
            qh[2] += gam[q] * vz[q];
            qh[3] += gam[q] * wx[q];
            qh[4] += gam[q] * wy[q];
        }
        const double km = km0 * A * bb, kw = kw0 * A * bb * bb, kr = kr0 * A * bb;
        const double kk[5] = {km, km, kw, kr, kr};
        double *hg = s->shell_hg + 5 * (size_t)e, fh[5];
        if (visc)
            for (int i = 0; i < 5; i++) {
                fh[i] = dt > 0 ? kk[i] * dte * qh[i] : 0; /* no rate before step 1 */
                e_hg += 0.5 * (hg[i] + fh[i]) * qh[i] * dt;
                hg[i] = fh[i];
            }
        else
            for (int i = 0; i < 5; i++) {
                double h0 = hg[i];
                hg[i] += kk[i] * qh[i] * dt;
                fh[i] = hg[i];
                e_hg += 0.5 * (h0 + hg[i]) * qh[i] * dt;
            }
        /* resisting local forces and moments, back to the global frame */
        for (int q = 0; q < 4; q++) {
            double fx = A * (B1[q] * N[0] + B2[q] * N[2]) + fh[0] * gam[q];
            double fy = A * (B2[q] * N[1] + B1[q] * N[2]) + fh[1] * gam[q];
            double fz = A * (B1[q] * Q[0] + B2[q] * Q[1]) + fh[2] * gam[q];
            double mx = A * (-B2[q] * M[1] - B1[q] * M[2] - 0.25 * Q[1]) + fh[3] * gam[q];
            double my = A * (B1[q] * M[0] + B2[q] * M[2] + 0.25 * Q[0]) + fh[4] * gam[q];
#pragma omp simd
            for (int i = 0; i < 3; i++) {
                f[3 * q + i] = fx * fr[0][i] + fy * fr[1][i] + fz * fr[2][i];
                mo[3 * q + i] = mx * fr[0][i] + my * fr[1][i];
            }
        }
        const double dts = dte * fe_dt_factor(m, FE_KIND_SHELL, e); /* mass scaling */
        if (dts < dtmin) dtmin = dts, dtel = e;
        if (erode) { /* its forces act this step, then it is gone */
            dead[e] = 1;
            e_erode += eint[e];
            nerode++;
        }
    }
    acc->e_erode = e_erode;
    acc->nerode = nerode;
    acc->e_int = e_int;
    acc->e_hg = e_hg;
    acc->e_diss = 0;
    acc->dtmin = dtmin;
    acc->dtel = dtel;
    acc->bad = bad;
}

void fe_shell_part(const fe_model *m, fe_state *s, int ip)
{
    fe_chunk_acc acc = {0};
    fe_shell_range(m, s, ip, m->part[ip].elem_begin, m->part[ip].elem_end, &acc);
    fe_chunk_commit(s, ip, &acc);
}

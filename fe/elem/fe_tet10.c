/* fe_tet10: the 10-node quadratic tetrahedron (section type tet10; LS-DYNA ELFORM 16-like).
 *
 * Shape functions in volume coordinates L1..L4 (Zienkiewicz & Taylor, The Finite Element
 * Method, vol. 1, 5th ed., sec. 8.8): corners N_i = L_i (2 L_i - 1), mid-edge nodes of edge
 * a-b N = 4 L_a L_b. The displacement field is complete to second order, so any quadratic
 * field is reproduced exactly and the strain is linear in a straight-edged element.
 * Integration: the 4-point Gauss rule of degree 2 (L = a, b, b, b and permutations,
 * a = (5 + 3 sqrt 5)/20, b = (5 - sqrt 5)/20, weight 1/24 of det J each; Zienkiewicz & Taylor
 * table 8.3), exact for the stiffness B^T D B of a straight-edged element (degree 2), so the
 * element has no spurious zero-energy modes and needs no hourglass control.
 * Each point carries its own stress, updated as in the fully integrated hex: velocity
 * gradient L_g = sum_I v_I (x) dN_I/dx, Jaumann rotation, the shared material update
 * (fe_mat_3d: elastic or J2 with hardening and Cowper-Symonds), bulk viscosity in compression
 * (q1, q2 as the hex) as a pressure of the point; f_I = sum_g w_g det J_g sig_g dN_I/dx.
 *
 * Lumped mass: the consistent mass has row sums -rho V / 20 at the corners (the integral of
 * L (2L - 1)) and rho V / 5 at the mid-edges, so the row-sum lumping gives negative corner
 * masses and cannot be used in an explicit code. HRZ lumping instead (Hinton, Rock &
 * Zienkiewicz 1976, Earthq. Eng. Struct. Dyn. 4:245-249): the consistent diagonal
 * (rho V / 70 at the corners, 8 rho V / 105 at the mid-edges for straight edges) scaled to the
 * element mass, i.e. rho V / 36 per corner and 4 rho V / 27 per mid-edge node: positive,
 * total mass exact, and the one in common use for this element in explicit dynamics.
 *
 * Stable step: the largest frequency of the element alone with that lumped mass,
 * omega_max^2 = lambda_max(M^-1/2 K M^-1/2) with K = sum_g w_g B_g^T D B_g (30 x 30, LAPACK
 * dsyev at t = 0). For lumped masses the mesh's highest frequency is at most the largest
 * element's (Irons & Treharne 1971; Hughes, The Finite Element Method, 1987, sec. 9.3:
 * the Rayleigh quotient of the assembly is a mass-weighted mean of the elements'), so
 * dt = 2 / omega_max bounds the central-difference limit. An L / c formula would be wrong by
 * a large factor here (the light corner nodes and the quadratic modes stiffen it), so the
 * element keeps the ratio f = (2 / omega_max) / (l / c) of t = 0 and its step during the run is
 * f l(t) / (q + sqrt(q^2 + c^2)), l the smallest altitude of the corner tetrahedron and q the
 * bulk-viscosity speed, as the hex. */
#include "fe/fe_tet10.h"
#include "fe/fe_elem.h"

#include <math.h>
#include <string.h>

const int fe_tet10_edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

#define HRZ_CORNER (1.0 / 36.0) /* mass fraction of a corner node [-]   */
#define HRZ_EDGE (4.0 / 27.0)   /* mass fraction of a mid-edge node [-] */

/* LAPACK: eigenvalues of a symmetric matrix (Fortran: the lengths of the two character
 * arguments are passed after the others, by value) */
extern void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda,
                   double *w, double *work, const int *lwork, int *info, size_t ljobz,
                   size_t luplo);

static void volume_coords(const double xi[3], double L[4])
{
    L[0] = 1 - xi[0] - xi[1] - xi[2], L[1] = xi[0], L[2] = xi[1], L[3] = xi[2];
}

void fe_tet10_shape(const double xi[3], double N[10])
{
    double L[4];
    volume_coords(xi, L);
    for (int i = 0; i < 4; i++) N[i] = L[i] * (2 * L[i] - 1);
    for (int k = 0; k < 6; k++) N[4 + k] = 4 * L[fe_tet10_edge[k][0]] * L[fe_tet10_edge[k][1]];
}

/* dN/dxi at a point */
static void shape_dxi(const double xi[3], double dn[10][3])
{
    static const double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double L[4];
    volume_coords(xi, L);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 3; j++) dn[i][j] = (4 * L[i] - 1) * dL[i][j];
    for (int k = 0; k < 6; k++) {
        const int a = fe_tet10_edge[k][0], b = fe_tet10_edge[k][1];
        for (int j = 0; j < 3; j++) dn[4 + k][j] = 4 * (L[b] * dL[a][j] + L[a] * dL[b][j]);
    }
}

/* volume coordinates of Gauss point q: L_q = a, the others b */
static void gauss_xi(int q, double xi[3])
{
    const double a = (5 + 3 * sqrt(5.0)) / 20, b = (5 - sqrt(5.0)) / 20;
    double L[4] = {b, b, b, b};
    L[q] = a;
    xi[0] = L[1], xi[1] = L[2], xi[2] = L[3];
}

double fe_tet10_grad(const double x[10][3], int q, double dx[10][3])
{
    double xi[3], dn[10][3];
    gauss_xi(q, xi);
    shape_dxi(xi, dn);
    double J[3][3] = {{0}}; /* J_ij = dx_i / dxi_j */
    for (int n = 0; n < 10; n++)
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) J[i][j] += x[n][i] * dn[n][j];
    double c[3][3]; /* cofactors: J^-1 = c^T / det */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = J[i1][j1] * J[i2][j2] - J[i1][j2] * J[i2][j1];
        }
    const double det = J[0][0] * c[0][0] + J[0][1] * c[0][1] + J[0][2] * c[0][2];
    if (!(det > 0)) return det;
    for (int n = 0; n < 10; n++)
        for (int i = 0; i < 3; i++)
            dx[n][i] = (dn[n][0] * c[i][0] + dn[n][1] * c[i][1] + dn[n][2] * c[i][2]) / det;
    return det;
}

double fe_tet10_volume(const double x[10][3])
{
    double v = 0, dx[10][3];
    for (int q = 0; q < FE_TET10_NGP; q++) {
        const double d = fe_tet10_grad(x, q, dx);
        if (!(d > 0)) return d;
        v += d / 24;
    }
    return v;
}

double fe_tet10_length(const double x[10][3])
{
    double a[3], b[3], c[3], n[3], amax = 0;
    for (int i = 0; i < 3; i++) {
        a[i] = x[1][i] - x[0][i], b[i] = x[2][i] - x[0][i], c[i] = x[3][i] - x[0][i];
    }
    fe_cross(a, b, n);
    const double v6 = fabs(fe_dot(n, c)); /* 6 V of the corner tetrahedron */
    static const int face[4][3] = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}};
    for (int f = 0; f < 4; f++) {
        const double *p = x[face[f][0]], *q = x[face[f][1]], *r = x[face[f][2]];
        double u[3], w[3];
        for (int i = 0; i < 3; i++) u[i] = q[i] - p[i], w[i] = r[i] - p[i];
        fe_cross(u, w, n);
        amax = fmax(amax, sqrt(fe_dot(n, n))); /* 2 A */
    }
    return amax > 0 ? v6 / amax : 0; /* 3 V / A = (6 V) / (2 A) */
}

static double node_fraction(int n) { return n < 4 ? HRZ_CORNER : HRZ_EDGE; }

double fe_tet10_omega2(const double x[10][3], double rho, double lambda, double mu)
{
    double K[30][30] = {{0}};
    double V = 0;
    for (int q = 0; q < FE_TET10_NGP; q++) {
        double dx[10][3];
        const double w = fe_tet10_grad(x, q, dx) / 24;
        if (!(w > 0)) return 0;
        V += w;
        /* K_IJ(ab) = w (lambda d_Ia d_Jb + mu (d_Ib d_Ja + delta_ab d_I . d_J)) */
        for (int I = 0; I < 10; I++)
            for (int J = 0; J < 10; J++) {
                const double dd = fe_dot(dx[I], dx[J]);
                for (int a = 0; a < 3; a++)
                    for (int b = 0; b < 3; b++)
                        K[3 * I + a][3 * J + b] +=
                            w * (lambda * dx[I][a] * dx[J][b] + mu * dx[I][b] * dx[J][a] +
                                 (a == b ? mu * dd : 0));
            }
    }
    double s[30]; /* M^-1/2 */
    for (int I = 0; I < 10; I++)
        for (int a = 0; a < 3; a++) s[3 * I + a] = 1 / sqrt(rho * V * node_fraction(I));
    for (int i = 0; i < 30; i++)
        for (int j = 0; j < 30; j++) K[i][j] *= s[i] * s[j];
    const int n = 30, lwork = 30 * 34;
    double ev[30], work[30 * 34];
    int info = 0;
    dsyev_("N", "U", &n, &K[0][0], &n, ev, work, &lwork, &info, 1, 1);
    return info == 0 ? ev[29] : 0;
}

static void gather10(const double *src, const int *c, double out[10][3])
{
    for (int n = 0; n < 10; n++) memcpy(out[n], src + 3 * c[n], sizeof out[n]);
}

mcs_status fe_tet10_lump(fe_model *m, int ip, mcs_error *err)
{
    const fe_part *p = &m->part[ip];
    const double rho = p->material.density;
    for (int e = p->elem_begin; e < p->elem_end; e++) {
        const int *c = m->tet10_node + 10 * e;
        double xe[10][3];
        gather10(m->node_x0, c, xe);
        const double v = fe_tet10_volume(xe);
        if (!(v > 0))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: part '%s': tet10 %d (nodes %d %d %d %d ...) is inverted or "
                           "degenerate at a Gauss point (det J = %g): order the corners so "
                           "that N4 is on the side of N1 N2 N3 their right-hand normal points "
                           "to, and put each mid-edge node near its edge's middle",
                           p->name, e - p->elem_begin, c[0], c[1], c[2], c[3], v);
        for (int n = 0; n < 10; n++) m->node_mass[c[n]] += rho * v * node_fraction(n);
    }
    return MCS_OK;
}

mcs_status fe_tet10_dt_build(fe_model *m, mcs_error *err)
{
    (void)err;
    for (int ip = 0; ip < m->npart; ip++) {
        const fe_part *p = &m->part[ip];
        if (p->elem_kind != FE_KIND_TET10) continue;
        const double rho = p->material.density, c0 = p->wave_speed;
        for (int e = p->elem_begin; e < p->elem_end; e++) {
            double xe[10][3];
            gather10(m->node_x0, m->tet10_node + 10 * e, xe);
            const double w2 = fe_tet10_omega2(xe, rho, p->lambda, p->mu);
            const double l = fe_tet10_length(xe);
            /* without a frequency (LAPACK failure) fall back to a conservative l / (3 c) */
            m->tet10_dtf[e] = w2 > 0 && l > 0 ? 2 / sqrt(w2) / (l / c0) : 1.0 / 3.0;
        }
    }
    return MCS_OK;
}

double fe_tet10_dt(const fe_model *m, const fe_part *p, int e, const double *x)
{
    double xe[10][3];
    gather10(x, m->tet10_node + 10 * e, xe);
    return m->tet10_dtf[e] * fe_bulk_dt(m, fe_tet10_length(xe), p->wave_speed, 0);
}

/* one Gauss point: stress update, its forces into f, energies; returns det J (<= 0: inverted) */
typedef struct {
    const fe_part *p;
    double dt, len, rho, c0, q1, q2, rate; /* rate: filtered strain rate of the element */
    double e_int, e_diss, vol, sum[6], epsp, theta_min;
} point_ctx;

static double point(point_ctx *k, const double xe[10][3], const double ve[10][3], int q,
                    double *gp, double f[10][3])
{
    double dx[10][3], L[3][3] = {{0}};
    const double wj = fe_tet10_grad(xe, q, dx) / 24;
    if (!(wj > 0)) return wj;
    for (int n = 0; n < 10; n++)
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) L[i][j] += ve[n][i] * dx[n][j];
    const double dt = k->dt;
    const double de[6] = {L[0][0] * dt, L[1][1] * dt, L[2][2] * dt, 0.5 * (L[0][1] + L[1][0]) * dt,
                          0.5 * (L[1][2] + L[2][1]) * dt, 0.5 * (L[2][0] + L[0][2]) * dt};
    double *sg = gp, old[6], W[3][3];
    fe_spin(L, dt, W);
    fe_jaumann(sg, W);
    memcpy(old, sg, sizeof old);
    gp[6] += fe_mat_3d(k->p, sg, de, gp[6], k->rate);
    double w = 0;
    for (int i = 0; i < 3; i++) w += (old[i] + sg[i]) * de[i];
    for (int i = 3; i < 6; i++) w += 2 * (old[i] + sg[i]) * de[i];
    k->e_int += 0.5 * w * wj;
    /* bulk viscosity of the point in compression, a pressure q */
    const double theta = L[0][0] + L[1][1] + L[2][2];
    double qv = 0;
    if (dt > 0 && theta < 0)
        qv = k->rho * k->len * (k->q1 * k->len * theta * theta - k->q2 * k->c0 * theta);
    k->e_diss += -0.5 * (gp[7] + qv) * theta * dt * wj;
    gp[7] = qv;
    k->theta_min = fmin(k->theta_min, theta);
    const double sxx = sg[0] - qv, syy = sg[1] - qv, szz = sg[2] - qv;
    for (int n = 0; n < 10; n++) {
        f[n][0] += wj * (sxx * dx[n][0] + sg[3] * dx[n][1] + sg[5] * dx[n][2]);
        f[n][1] += wj * (sg[3] * dx[n][0] + syy * dx[n][1] + sg[4] * dx[n][2]);
        f[n][2] += wj * (sg[5] * dx[n][0] + sg[4] * dx[n][1] + szz * dx[n][2]);
    }
    k->vol += wj;
    for (int i = 0; i < 6; i++) k->sum[i] += wj * sg[i];
    k->epsp += gp[6] / FE_TET10_NGP;
    return wj;
}

/* the element's filtered strain rate from its mean deviatoric rate (Cowper-Symonds only) */
static double elem_rate(const fe_part *p, const double xe[10][3], const double ve[10][3],
                        double rate0, double dt)
{
    if (!(p->material.cowper_symonds_c > 0) || !(dt > 0)) return rate0;
    double D[3][3] = {{0}}, dx[10][3];
    for (int q = 0; q < FE_TET10_NGP; q++) {
        if (!(fe_tet10_grad(xe, q, dx) > 0)) return rate0;
        for (int n = 0; n < 10; n++)
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    D[i][j] += 0.125 * (ve[n][i] * dx[n][j] + ve[n][j] * dx[n][i]);
    }
    const double tr = (D[0][0] + D[1][1] + D[2][2]) / 3;
    double d2 = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const double d = D[i][j] - (i == j ? tr : 0);
            d2 += d * d;
        }
    return fe_rate_filter(rate0, sqrt(2.0 / 3.0 * d2));
}

void fe_tet10_range(const fe_model *m, fe_state *s, int ip, int e0, int e1, fe_chunk_acc *acc)
{
    const fe_part *p = &m->part[ip];
    point_ctx k = {.p = p, .dt = s->dt_prev, .rho = p->material.density, .c0 = p->wave_speed,
                   .q1 = m->opts.bulk_q1, .q2 = m->opts.bulk_q2};
    double e_int = 0, e_diss = 0, dtmin = INFINITY;
    int dtel = -1, bad = -1;
    for (int e = e0; e < e1; e++) {
        const int *c = m->tet10_node + 10 * e;
        double xe[10][3], ve[10][3], f[10][3] = {{0}};
        gather10(s->node_x, c, xe);
        gather10(s->node_v, c, ve);
        double *slot = s->slot_f + 3 * ((size_t)m->slot_base[FE_KIND_TET10] + 10 * (size_t)e);
        k.len = fe_tet10_length(xe);
        k.rate = s->tet10_rate[e] = elem_rate(p, xe, ve, s->tet10_rate[e], k.dt);
        k.e_int = k.e_diss = k.vol = k.epsp = 0, k.theta_min = 0;
        memset(k.sum, 0, sizeof k.sum);
        int ok = k.len > 0;
        for (int q = 0; q < FE_TET10_NGP && ok; q++)
            ok = point(&k, xe, ve, q, s->tet10_gp + 32 * (size_t)e + 8 * q, f) > 0;
        if (!ok) {
            if (bad < 0) bad = e;
            memset(slot, 0, 30 * sizeof(double));
            continue;
        }
        memcpy(slot, f, sizeof f);
        e_int += k.e_int;
        e_diss += k.e_diss;
        for (int i = 0; i < 6; i++) s->tet10_sig[6 * (size_t)e + i] = k.sum[i] / k.vol;
        s->tet10_epsp[e] = k.epsp;
        /* step: the t = 0 frequency ratio on the current length, less the viscosity's share */
        const double dte = m->tet10_dtf[e] * fe_bulk_dt(m, k.len, k.c0, k.theta_min);
        if (dte < dtmin) dtmin = dte, dtel = e;
    }
    acc->e_int = e_int;
    acc->e_hg = 0;
    acc->e_diss = e_diss;
    acc->dtmin = dtmin;
    acc->dtel = dtel;
    acc->bad = bad;
}

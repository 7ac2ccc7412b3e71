/* fe_tet: 4-node tetrahedra and 6-node pentahedra as degenerate one-point hexahedra.
 *
 * A tetrahedron n1 n2 n3 n4 is stored in the hex slots as (n1 n2 n3 n3 n4 n4 n4 n4): every face
 * of that hex is then a plane triangle, a segment or a point, so the trilinear map fills the
 * tetrahedron exactly, its exact volume (fe_hex_gradients) is the tetrahedron's and the summed
 * uniform gradients of the merged slots are the constant-strain tetrahedron's,
 * b_I = (1/V) dV/dx_I (Zienkiewicz & Taylor, The Finite Element Method, vol. 1, 5th ed.,
 * sec. 6.2). The hourglass shape vectors are orthogonal to every linear field and a tetrahedron
 * has no other motion, so its hourglass forces vanish: the element is exactly the linear
 * (constant-strain) tetrahedron. (LS-DYNA writes a tetrahedron as n1 n2 n3 n4 n4 n4 n4 n4,
 * whose bottom face 1-2-3-4 would be a warped bilinear patch; the builder reorders it.)
 * A pentahedron is LS-DYNA's degenerate hexahedron n1 n2 n3 n4 n5 n5 n6 n6 (quad 1-2-3-4, ridge
 * 5-6), used as it is: the one-point hex with hourglass control, as LS-DYNA's ELFORM 1 does.
 * Lumped mass: an equal share rho V / n per distinct node (fe_model.c), the row sums of the
 * linear tetrahedron's consistent mass.
 *
 * Stable step of a tetrahedron: the element's own highest frequency with its lumped mass,
 * an upper bound for any mesh that contains it (Irons & Treharne 1971), computed at t = 0:
 * K = V B^T D B, M = rho V / 4 per node, so the nonzero eigenvalues of M^-1 K are those of the
 * 6 x 6 matrix V D^(1/2) (sum_I B_I B_I^T / m_I) D^(1/2) (Mandel strains, D = lambda m m^T +
 * 2 mu I), found by Jacobi rotations. dt_e = 2 / omega_max goes in as the element's step factor
 * against the hex formula L / c, which for a tetrahedron would be about a third of it. */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <string.h>

static int distinct(const int *c, int n)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < i; j++)
            if (c[i] == c[j]) return 0;
    return 1;
}

int fe_hex_shape(const int c[8])
{
    if (distinct(c, 8)) return 8;
    if (c[3] == c[2] && c[5] == c[4] && c[6] == c[4] && c[7] == c[4]) {
        int u[4] = {c[0], c[1], c[2], c[4]};
        if (distinct(u, 4)) return 4;
    }
    if (c[5] == c[4] && c[7] == c[6]) {
        int u[6] = {c[0], c[1], c[2], c[3], c[4], c[6]};
        if (distinct(u, 6)) return 6;
    }
    return 0;
}

int fe_solid_from_lsdyna(const int in[8], int out[8])
{
    int sh = fe_hex_shape(in);
    if (sh) {
        memcpy(out, in, 8 * sizeof(int));
        return sh;
    }
    /* tetrahedron n1 n2 n3 n4 n4 n4 n4 n4 */
    if (in[4] == in[3] && in[5] == in[3] && in[6] == in[3] && in[7] == in[3] && distinct(in, 4)) {
        const int t[8] = {in[0], in[1], in[2], in[2], in[3], in[3], in[3], in[3]};
        memcpy(out, t, sizeof t);
        return 4;
    }
    return 0;
}

void fe_solid_to_lsdyna(const int c[8], int out[8])
{
    if (fe_hex_shape(c) == 4) {
        const int t[8] = {c[0], c[1], c[2], c[4], c[4], c[4], c[4], c[4]};
        memcpy(out, t, sizeof t);
    } else {
        memcpy(out, c, 8 * sizeof(int));
    }
}

int fe_hex_distinct(const int c[8], int u[8])
{
    int n = 0;
    for (int i = 0; i < 8; i++) {
        int seen = 0;
        for (int j = 0; j < n; j++) seen |= u[j] == c[i];
        if (!seen) u[n++] = c[i];
    }
    return n;
}

/* largest eigenvalue of a symmetric 6 x 6 matrix (cyclic Jacobi) */
static double max_eig6(double a[6][6])
{
    for (int sweep = 0; sweep < 50; sweep++) {
        double off = 0, diag = 0;
        for (int i = 0; i < 6; i++) {
            diag += a[i][i] * a[i][i];
            for (int j = i + 1; j < 6; j++) off += a[i][j] * a[i][j];
        }
        if (off <= 1e-30 * diag) break;
        for (int p = 0; p < 6; p++)
            for (int q = p + 1; q < 6; q++) {
                if (a[p][q] == 0) continue;
                double th = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
                double t = (th >= 0 ? 1 : -1) / (fabs(th) + sqrt(th * th + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 6; k++) { /* columns p, q */
                    double kp = a[k][p], kq = a[k][q];
                    a[k][p] = c * kp - s * kq;
                    a[k][q] = s * kp + c * kq;
                }
                for (int k = 0; k < 6; k++) { /* rows p, q */
                    double pk = a[p][k], qk = a[q][k];
                    a[p][k] = c * pk - s * qk;
                    a[q][k] = s * pk + c * qk;
                }
            }
    }
    double mx = a[0][0];
    for (int i = 1; i < 6; i++) mx = fmax(mx, a[i][i]);
    return mx;
}

double fe_tet_omega2(const double x[4][3], double rho, double lambda, double mu)
{
    double xe[8][3], b[8][3], a[8][3];
    static const int slot[8] = {0, 1, 2, 2, 3, 3, 3, 3};
    for (int n = 0; n < 8; n++) memcpy(xe[n], x[slot[n]], sizeof xe[n]);
    double V = fe_hex_gradients(xe, b, a);
    if (!(V > 0)) return 0;
    double g[4][3] = {{0}};
    for (int n = 0; n < 8; n++)
        for (int i = 0; i < 3; i++) g[slot[n]][i] += b[n][i];
    /* G = sum_I B_I B_I^T / m_I, Mandel rows: xx, yy, zz, sqrt2 xy, sqrt2 yz, sqrt2 zx */
    const double m = rho * V / 4, r2 = sqrt(0.5);
    double G[6][6] = {{0}};
    for (int I = 0; I < 4; I++) {
        const double *q = g[I];
        double B[6][3] = {{q[0], 0, 0},           {0, q[1], 0},           {0, 0, q[2]},
                          {r2 * q[1], r2 * q[0], 0}, {0, r2 * q[2], r2 * q[1]},
                          {r2 * q[2], 0, r2 * q[0]}};
        for (int i = 0; i < 6; i++)
            for (int j = 0; j < 6; j++)
                G[i][j] += (B[i][0] * B[j][0] + B[i][1] * B[j][1] + B[i][2] * B[j][2]) / m;
    }
    /* D^(1/2) = sqrt(2 mu) I + (sqrt(3 lambda + 2 mu) - sqrt(2 mu)) m m^T / 3 */
    const double s0 = sqrt(2 * mu), s1 = (sqrt(3 * lambda + 2 * mu) - s0) / 3;
    double H[6][6], A[6][6];
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 6; j++) H[i][j] = (i == j ? s0 : 0) + (i < 3 && j < 3 ? s1 : 0);
    double T[6][6];
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 6; j++) {
            double t = 0;
            for (int k = 0; k < 6; k++) t += G[i][k] * H[k][j];
            T[i][j] = t;
        }
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 6; j++) {
            double t = 0;
            for (int k = 0; k < 6; k++) t += H[i][k] * T[k][j];
            A[i][j] = V * t;
        }
    return max_eig6(A);
}

mcs_status fe_tet_dt_build(fe_model *m, mcs_error *err)
{
    for (int ip = 0; ip < m->npart; ip++) {
        const fe_part *p = &m->part[ip];
        if (p->elem_kind != FE_KIND_HEX || p->material.model == FE_MAT_RIGID ||
            p->material.model == FE_MAT_NULL)
            continue;
        /* the elastic constants behind the part's wave speed (foam: lambda 0, 2 mu = rho c^2) */
        const double rho = p->material.density, rc2 = rho * p->wave_speed * p->wave_speed;
        double lam = p->lambda, mu = p->mu;
        if (!(lam + 2 * mu >= rc2 * (1 - 1e-12))) lam = 0, mu = 0.5 * rc2;
        for (int e = p->elem_begin; e < p->elem_end; e++) {
            const int *c = m->hex_node + 8 * e;
            if (fe_hex_shape(c) != 4) continue;
            double x[4][3], xe[8][3], b[8][3], a[8][3];
            const int u[4] = {c[0], c[1], c[2], c[4]};
            for (int n = 0; n < 4; n++) memcpy(x[n], m->node_x0 + 3 * u[n], sizeof x[n]);
            for (int n = 0; n < 8; n++) memcpy(xe[n], m->node_x0 + 3 * c[n], sizeof xe[n]);
            double w2 = fe_tet_omega2(x, rho, lam, mu), V = fe_hex_gradients(xe, b, a);
            double dth = fe_hex_length(xe, V) / p->wave_speed;
            if (!(w2 > 0) || !(dth > 0)) continue;
            mcs_status st = fe_dt_factors_alloc(m, err);
            if (st) return st;
            m->elem_dt_factor[e] *= 2 / sqrt(w2) / dth; /* hexes come first */
        }
    }
    return MCS_OK;
}

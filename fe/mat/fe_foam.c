/* fe_foam: rate-dependent, hysteretic low-density foam for hex8 (in the spirit of what users
 * know as LS-DYNA *MAT_FU_CHANG_FOAM (083) and *MAT_LOW_DENSITY_FOAM (057); this is our own
 * formulation, described here in full).
 *
 * Kinematics: the deformation gradient F (t = 0 -> t) at the element centre (or at each Gauss
 * point of the fully integrated hex, each with its own history), the left stretch from
 * B = F F^T = sum_i lambda_i^2 n_i n_i^T (Jacobi eigen-decomposition), engineering compressive
 * strains e_i = 1 - lambda_i. F = sum_i lambda_i n_i N_i^T: the material fibre now along n_i
 * lay along N_i = F^T n_i / lambda_i at t = 0.
 * Poisson's ratio nu (0 <= nu < 0.5): the curves are uniaxial-stress curves. Each direction
 * works on the uniaxial-equivalent strain
 *     u_i = [(1 - nu) e_i + nu (e_j + e_k)] / ((1 + nu)(1 - 2 nu)),   u = C^-1 e,
 * C the isotropic compliance pattern (1 on the diagonal, -nu off it): a direction whose
 * u_j = 0 carries no stress, so under uniaxial stress the lateral strains are -nu e_1, u_1 = e_1
 * and the axial nominal stress is the curve S(e_1) exactly; under uniaxial strain (lateral
 * e = 0) s_1 = S((1 - nu) e_1 / ((1 + nu)(1 - 2 nu))), s_lat = S(nu e_1 / ((1 + nu)(1 - 2 nu))).
 * With linear curves this is linear elasticity; with nonlinear ones it is not hyperelastic (a
 * closed strain cycle through several directions can leave a small energy residue), the
 * price of reproducing the uniaxial curve exactly. nu = 0: each direction is independent.
 * Hysteresis memory, per direction: a symmetric tensor M (6 numbers per point) in the t = 0
 * frame, so it follows the material through any rotation without an objective-rate update
 * (the frame of F's right side is the material's). Direction i remembers
 *     e_max,i = N_i . M . N_i,
 * and after the stresses M += sum_i max(0, u_i - e_max,i) N_i N_i^T: the N_i are orthonormal,
 * so each current direction's projection becomes exactly max(e_max,i, u_i). Loads that keep
 * their axes in the material (the cube loaded along x, unloaded, then along y) get one
 * independent maximum per axis (M diagonal there), as a scalar memory cannot: it would put
 * the y loading on the unloading branch of the x maximum. Approximate: a direction between
 * the loaded ones remembers the quadratic interpolation of their maxima (cos^2 weights), not
 * the largest strain that fibre itself saw (that would need the whole history of every
 * fibre); axes that turn in the material (shear) smear M over the swept fan of fibres, by
 * rank-one steps whose sum depends weakly on the step. Where two stretches are equal to
 * 1e-9 the principal directions in that plane are undefined by B (round-off picks them): they
 * are taken along the axes of M restricted to the plane, so equal strains with unequal
 * memories (x loaded before, now y compressed: x and z lateral) keep each axis's own memory.
 * The state per point is M; *emax (hex_epsp or the Gauss point's slot) only reports the
 * largest u seen in any direction.
 * Per direction, with e_i replaced by u_i, nominal stress (force per undeformed area):
 *   loading (u_i >= e_max,i):
 *       s_i = S(u_i, rate)
 *   unloading and reloading below e_max,i:
 *       s_i = S(u_i, rate) [HU + (1 - HU) (u_i / e_max,i)^shape]
 *     (HU = hysteresis in (0, 1]: 1 gives no hysteresis; the energy lost per cycle is the
 *      area between the loading and the unloading curve, and unloading ends at zero stress
 *      at zero strain, as a foam that recovers fully);
 *   tension (u_i < 0): s_i = -E u_i, capped at tension_cutoff when that is > 0.
 * S(e, rate) interpolates the loading curves linearly in log(rate) between the two tables
 * that bracket the rate (the lowest and highest table beyond the ends); each table is
 * piecewise linear, from (0, 0) to its first point, its last segment continued.
 * The rate is the engineering strain rate of the fastest principal direction,
 * max_i |lambda_i n_i.D.n_i|, averaged over about 12 cycles (fe_rate_filter, as for J2).
 * Cauchy stress: sigma = sum_i sigma_i n_i n_i^T with sigma_i = -s_i / (lambda_j lambda_k)
 * (compression negative). The stable step uses the stiffest of E and the tables' slopes. */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

mcs_status fe_foam_check(const fe_part_desc *d, mcs_error *err)
{
    const fe_material_desc *m = &d->material;
    const char *n = d->name;
    if (d->section.type != FE_SECTION_SOLID)
        return MCS_ERR(err, MCS_ERR_TYPE, "fe: part '%s': foam is for solid (hex8) sections", n);
    if (!(m->poisson >= 0 && m->poisson < 0.5))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': foam: poisson must be in [0, 0.5), got %g",
                       n, m->poisson);
    if (m->nfoam_curve < 1 || m->nfoam_curve > FE_FOAM_NCURVE)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': foam: 1..%d loading curves, got %d",
                       n, FE_FOAM_NCURVE, m->nfoam_curve);
    if (!(m->foam_hysteresis >= 0 && m->foam_hysteresis <= 1) || !(m->foam_shape >= 0) ||
        !(m->foam_tension_cutoff >= 0) || !isfinite(m->foam_shape) ||
        !isfinite(m->foam_tension_cutoff))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': foam: hysteresis in (0, 1], shape and tension_cutoff >= 0",
                       n);
    for (int c = 0; c < m->nfoam_curve; c++) {
        double r = m->foam_rate[c];
        if (m->nfoam_curve > 1 && (!(r > 0) || !isfinite(r) || (c > 0 && !(r > m->foam_rate[c - 1]))))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: part '%s': foam: curve %d: strain rates must be > 0 and increase",
                           n, c);
        int np = m->foam_npoint[c];
        if (np < 1 || np > FE_CURVE_MAX)
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': foam: curve %d: 1..%d points", n,
                           c, FE_CURVE_MAX);
        for (int i = 0; i < np; i++) {
            double e = m->foam_curve[c][i][0], s = m->foam_curve[c][i][1];
            double e0 = i ? m->foam_curve[c][i - 1][0] : 0, s0 = i ? m->foam_curve[c][i - 1][1] : 0;
            if (!(e >= 0 && e < 1) || !(s >= 0) || !isfinite(s) || (i > 0 && !(e > e0)) ||
                (i == 0 && e == 0 && s != 0) || s < s0)
                return MCS_ERR(err, MCS_ERR_RANGE,
                               "fe: part '%s': foam: curve %d point %d: strain in [0, 1) "
                               "increasing, stress >= 0 not decreasing, (0, 0) at zero strain",
                               n, c, i);
        }
    }
    return MCS_OK;
}

/* one table: stress at strain e >= 0 and its slope; (0, 0) is the implicit first point */
static double table(const fe_material_desc *m, int c, double e, double *slope)
{
    const double(*t)[2] = m->foam_curve[c];
    int np = m->foam_npoint[c];
    double x0 = 0, y0 = 0, x1 = t[0][0], y1 = t[0][1];
    int i = 0;
    if (x1 == 0) { /* the table starts at (0, 0) */
        if (np == 1) {
            *slope = 0;
            return 0;
        }
        x1 = t[1][0], y1 = t[1][1], i = 1;
    }
    while (e > x1 && i + 1 < np) {
        x0 = x1, y0 = y1;
        i++;
        x1 = t[i][0], y1 = t[i][1];
    }
    *slope = (y1 - y0) / (x1 - x0);
    return y0 + *slope * (e - x0);
}

/* loading stress S(e, rate) [Pa] */
static double loading(const fe_material_desc *m, double e, double rate)
{
    double k;
    int n = m->nfoam_curve;
    if (n == 1 || rate <= m->foam_rate[0]) return table(m, 0, e, &k);
    if (rate >= m->foam_rate[n - 1]) return table(m, n - 1, e, &k);
    int c = 0;
    while (rate > m->foam_rate[c + 1]) c++;
    double w = log(rate / m->foam_rate[c]) / log(m->foam_rate[c + 1] / m->foam_rate[c]);
    return (1 - w) * table(m, c, e, &k) + w * table(m, c + 1, e, &k);
}

void fe_foam_derive(fe_part *p)
{
    const fe_material_desc *m = &p->material;
    double kmax = m->youngs_modulus;
    for (int c = 0; c < m->nfoam_curve; c++) {
        double x0 = 0, y0 = 0;
        for (int i = 0; i < m->foam_npoint[c]; i++) {
            double x1 = m->foam_curve[c][i][0], y1 = m->foam_curve[c][i][1];
            if (x1 > x0) kmax = fmax(kmax, (y1 - y0) / (x1 - x0));
            x0 = x1, y0 = y1;
        }
    }
    /* uniaxial strain: the modulus grows by (1 - nu) / ((1 + nu)(1 - 2 nu)) */
    const double nu = m->poisson;
    p->wave_speed = sqrt(kmax * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / m->density);
}

/* eigenvalues d and eigenvectors (columns of v) of a symmetric 3x3 matrix (cyclic Jacobi) */
static void sym_eigen(const double a_in[3][3], double d[3], double v[3][3])
{
    double a[3][3];
    memcpy(a, a_in, sizeof a);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) v[i][j] = i == j;
    for (int sweep = 0; sweep < 50; sweep++) {
        double off = fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]);
        double scale = fabs(a[0][0]) + fabs(a[1][1]) + fabs(a[2][2]);
        if (off <= 1e-15 * scale || off == 0) break;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                if (a[p][q] == 0) continue;
                double th = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
                double t = copysign(1.0, th) / (fabs(th) + sqrt(th * th + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 3; k++) { /* a <- a J */
                    double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; k++) { /* a <- J^T a */
                    double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; k++) {
                    double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < 3; i++) d[i] = a[i][i];
}

/* x . M . y, M symmetric stored xx yy zz xy yz zx */
static double sym_form(const double M[6], const double x[3], const double y[3])
{
    return x[0] * (M[0] * y[0] + M[3] * y[1] + M[5] * y[2]) +
           x[1] * (M[3] * y[0] + M[1] * y[1] + M[4] * y[2]) +
           x[2] * (M[5] * y[0] + M[4] * y[1] + M[2] * y[2]);
}

/* the material directions N_i = F^T n_i / lambda_i (rows of N), normalised; in a plane of
 * equal stretches (to 1e-9) both n and N turn onto the axes of the memory M in that plane */
static void material_directions(const double F[3][3], double n[3][3], const double lam[3],
                                const double M[6], double N[3][3])
{
    for (int i = 0; i < 3; i++) {
        double l = 0;
        for (int a = 0; a < 3; a++) {
            N[i][a] = F[0][a] * n[0][i] + F[1][a] * n[1][i] + F[2][a] * n[2][i];
            l += N[i][a] * N[i][a];
        }
        l = sqrt(l);
        for (int a = 0; a < 3; a++) N[i][a] = l > 0 ? N[i][a] / l : n[a][i];
    }
    for (int sweep = 0; sweep < 4; sweep++) { /* Jacobi on M within the repeated stretches */
        int turned = 0;
        for (int i = 0; i < 2; i++)
            for (int j = i + 1; j < 3; j++) {
                if (!(fabs(lam[i] - lam[j]) <= 1e-9 * fmax(lam[i], lam[j]))) continue;
                double a = sym_form(M, N[i], N[i]), b = sym_form(M, N[j], N[j]);
                double c = sym_form(M, N[i], N[j]);
                if (!(fabs(c) > 1e-15 * (fabs(a) + fabs(b)))) continue;
                double phi = 0.5 * atan2(2 * c, a - b), cs = cos(phi), sn = sin(phi);
                for (int k = 0; k < 3; k++) {
                    double ni = N[i][k], nj = N[j][k];
                    N[i][k] = cs * ni + sn * nj, N[j][k] = cs * nj - sn * ni;
                    ni = n[k][i], nj = n[k][j];
                    n[k][i] = cs * ni + sn * nj, n[k][j] = cs * nj - sn * ni;
                }
                turned = 1;
            }
        if (!turned) break;
    }
}

void fe_foam_stress(const fe_part *p, const double F[3][3], const double L[3][3], double sig[6],
                    double hist[6], double *emax, double *rate)
{
    const fe_material_desc *m = &p->material;
    double B[3][3], d[3], n[3][3], lam[3], N[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            B[i][j] = F[i][0] * F[j][0] + F[i][1] * F[j][1] + F[i][2] * F[j][2];
    sym_eigen(B, d, n);
    for (int i = 0; i < 3; i++) lam[i] = sqrt(fmax(d[i], 0));
    material_directions(F, n, lam, hist, N);
    /* engineering strain rate of the fastest principal direction */
    double r = 0;
    for (int i = 0; i < 3; i++) {
        double dn = 0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) dn += n[a][i] * 0.5 * (L[a][b] + L[b][a]) * n[b][i];
        r = fmax(r, fabs(lam[i] * dn));
    }
    *rate = fe_rate_filter(*rate, r);
    const double hu = m->foam_hysteresis > 0 ? m->foam_hysteresis : 1;
    const double shape = m->foam_shape > 0 ? m->foam_shape : 1;
    const double nu = m->poisson, dn = (1 + nu) * (1 - 2 * nu);
    double si[3], ue[3], rise[3], eseen = *emax;
    for (int i = 0; i < 3; i++) /* uniaxial-equivalent strains u = C^-1 e */
        ue[i] = nu == 0 ? 1 - lam[i]
                        : ((1 - nu) * (1 - lam[i]) + nu * (2 - lam[(i + 1) % 3] - lam[(i + 2) % 3])) / dn;
    for (int i = 0; i < 3; i++) {
        double e = ue[i], em = sym_form(hist, N[i], N[i]), s;
        rise[i] = 0;
        if (e > 0) {
            s = loading(m, e, *rate);
            if (e < em) s *= hu + (1 - hu) * pow(e / em, shape);
            else rise[i] = e - em;
            eseen = fmax(eseen, e);
            s = -s;
        } else {
            s = -m->youngs_modulus * e;
            if (m->foam_tension_cutoff > 0) s = fmin(s, m->foam_tension_cutoff);
        }
        double area = lam[(i + 1) % 3] * lam[(i + 2) % 3];
        si[i] = area > 0 ? s / area : 0;
    }
    *emax = eseen;
    static const int ia[6] = {0, 1, 2, 0, 1, 2}, ib[6] = {0, 1, 2, 1, 2, 0};
    for (int k = 0; k < 6; k++) {
        double v = 0, h = 0;
        for (int i = 0; i < 3; i++) {
            v += si[i] * n[ia[k]][i] * n[ib[k]][i];
            h += rise[i] * N[i][ia[k]] * N[i][ib[k]];
        }
        sig[k] = v;
        hist[k] += h;
    }
}

void fe_hex_deformation(const double x0[8][3], const double x[8][3], double F[3][3])
{
    double b0[8][3], a[8][3];
    (void)fe_hex_gradients(x0, b0, a);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double v = 0;
            for (int n = 0; n < 8; n++) v += x[n][i] * b0[n][j];
            F[i][j] = v;
        }
}

void fe_foam_hex(const fe_model *m, const fe_part *p, const int *conn, const double xe[8][3],
                 const double L[3][3], double sig[6], double hist[6], double *emax, double *rate)
{
    double x0[8][3], F[3][3];
    for (int n = 0; n < 8; n++) memcpy(x0[n], m->node_x0 + 3 * conn[n], sizeof x0[n]);
    fe_hex_deformation(x0, xe, F);
    fe_foam_stress(p, F, L, sig, hist, emax, rate);
}

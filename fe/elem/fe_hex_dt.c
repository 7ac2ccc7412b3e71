/* fe_hex_dt: the stable step of lightly held one-point hexahedra.
 *
 * The element step L/c (L = V / largest face area, c = sqrt((lambda + 2 mu)/rho)) is the exact
 * limit 2/omega of the highest mode of a regular mesh of cubes (the alternating "checkerboard"
 * dilatation: omega^2 = 4 (lambda + 2 mu)/(rho h^2) with interior nodal masses rho h^3). An
 * element whose nodes carry little mass from neighbours has a faster mode: the uniform
 * dilatation of the element alone. With lumped mass m_I and the one-point gradients b_I
 * (fe_hex_gradients, b_I = (1/V) dV/dx_I), the Rayleigh quotient of u_I = S^-1 b_I alpha
 * (the least-norm nodal motion giving a pure dilatation, S = sum_I b_I b_I^T) gives
 *     omega_dil^2 = 3 V (3 lambda + 2 mu) / (mbar tr(S^-1)),   mbar = mean of the m_I,
 * which for a lone cube (m_I = rho h^3 / 8, tr S^-1 = 6 h^2) is 4 (3 lambda + 2 mu)/(rho h^2):
 * 1.36 times the L/c frequency at nu = 0.3, 1.62 times at nu = 0.45 — a single free cube goes
 * unstable at the 0.9 safety factor. Here each hex whose omega_dil exceeds 2c/L gets the step
 * factor (2c/L)/omega_dil from its initial shape and masses (fe_dt_factor); elements inside a
 * mesh (mbar >= 3 rho V / 8 for nu <= 0.45) are unchanged. nu <= 0 needs nothing
 * (3 lambda + 2 mu <= lambda + 2 mu). Shape changes during the run are not re-checked. */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>

/* omega_dil^2 / (2c/L)^2 of hex e of part p at its initial shape */
static double dil_ratio(const fe_model *m, const fe_part *p, int e)
{
    double xe[8][3], bv[8][3], av[8][3];
    const int *c = m->hex_node + 8 * e;
    double mbar = 0;
    for (int n = 0; n < 8; n++) {
        for (int k = 0; k < 3; k++) xe[n][k] = m->node_x0[3 * c[n] + k];
        mbar += m->node_mass[c[n]] / 8;
    }
    double V = fe_hex_gradients(xe, bv, av);
    if (!(V > 0) || !(mbar > 0)) return 0;
    double S[3][3] = {{0}};
    for (int n = 0; n < 8; n++)
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) S[i][j] += bv[n][i] * bv[n][j];
    double minors = S[0][0] * S[1][1] - S[0][1] * S[0][1] + S[1][1] * S[2][2] -
                    S[1][2] * S[1][2] + S[0][0] * S[2][2] - S[0][2] * S[0][2];
    double det = S[0][0] * (S[1][1] * S[2][2] - S[1][2] * S[1][2]) -
                 S[0][1] * (S[0][1] * S[2][2] - S[1][2] * S[0][2]) +
                 S[0][2] * (S[0][1] * S[1][2] - S[1][1] * S[0][2]);
    if (!(det > 0) || !(minors > 0)) return 0;
    double w_dil2 = 3 * V * (3 * p->lambda + 2 * p->mu) * det / (mbar * minors);
    double L = fe_hex_length(xe, V), c0 = p->wave_speed;
    double w_l2 = 4 * c0 * c0 / (L * L);
    return w_l2 > 0 ? w_dil2 / w_l2 : 0;
}

mcs_status fe_hex_dt_build(fe_model *m, mcs_error *err)
{
    for (int ip = 0; ip < m->npart; ip++) {
        const fe_part *p = &m->part[ip];
        if (p->elem_kind != FE_KIND_HEX || p->material.model == FE_MAT_RIGID ||
            p->material.model == FE_MAT_NULL)
            continue;
        if (!(p->lambda > 0)) continue;
        for (int e = p->elem_begin; e < p->elem_end; e++) {
            if (fe_hex_shape(m->hex_node + 8 * e) == 4) continue; /* tetrahedra: fe_tet.c */
            double r = dil_ratio(m, p, e);
            if (!(r > 1)) continue;
            mcs_status st = fe_dt_factors_alloc(m, err);
            if (st) return st;
            m->elem_dt_factor[e] /= sqrt(r); /* hexes come first in elem_dt_factor */
        }
    }
    return MCS_OK;
}

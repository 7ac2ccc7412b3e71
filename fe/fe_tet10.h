/* fe_tet10: the 10-node quadratic tetrahedron (fe_tet10.c). Private to the kernel and tests.
 *
 * Node order (LS-DYNA *ELEMENT_SOLID with 10 nodes, VTK / XDMF Tetrahedron_10): corners
 * 0..3, then the mid-edge nodes of the edges 0-1, 1-2, 2-0, 0-3, 1-3, 2-3. */
#ifndef FE_TET10_H
#define FE_TET10_H

#include "fe/fe_state.h"

#define FE_TET10_NGP 4 /* Gauss points per element [-] */

/* the edges of the mid-edge nodes 4..9 (corner pairs) */
extern const int fe_tet10_edge[6][2];

/* shape functions N[10] at volume coordinates L2 = xi, L3 = eta, L4 = zeta (L1 = 1 - sum) */
void fe_tet10_shape(const double xi[3], double N[10]);
/* dN/dx at Gauss point q (0..3) of an element with nodes x; returns det J (its weight is
 * 1/24 of it: sum_q det J_q / 24 = volume) [m^3] */
double fe_tet10_grad(const double x[10][3], int q, double dx[10][3]);
/* volume by the 4-point rule (exact for straight edges) [m^3]; <= 0 when a point is inverted */
double fe_tet10_volume(const double x[10][3]);
/* characteristic length: the smallest altitude 3 V / A_max of the corner tetrahedron [m] */
double fe_tet10_length(const double x[10][3]);
/* largest omega^2 of a lone element with the lumped (HRZ) mass and elastic constants
 * lambda, mu [1/s^2]; 0 on a degenerate element or a LAPACK failure */
double fe_tet10_omega2(const double x[10][3], double rho, double lambda, double mu);

/* model building: lumped masses of a tet10 part (fe_model.c), step factors (fe_solid_build) */
mcs_status fe_tet10_lump(fe_model *m, int ip, mcs_error *err);
mcs_status fe_tet10_dt_build(fe_model *m, mcs_error *err);
/* element step from geometry alone (no safety factor) of element e at positions x [s] */
double fe_tet10_dt(const fe_model *m, const fe_part *p, int e, const double *x);
/* the element loop of part ip on elements e0..e1-1 (fe_stages.c) */
void fe_tet10_range(const fe_model *m, fe_state *s, int ip, int e0, int e1, fe_chunk_acc *acc);

#endif

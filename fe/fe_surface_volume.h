/* fe_surface_volume: enclosed volume of a closed surface of triangles and quads, its gradient
 * with respect to the node positions, and the nodal forces of a uniform pressure.
 *
 * Divergence theorem: V = (1/3) oint x.n dA = (1/3) sum_i A_i (x_c,i . n_i) for flat faces.
 * A triangle (a, b, c) contributes the signed tetrahedron (1/6) (a-o).((b-o) x (c-o)); a quad
 * (possibly warped) is split into four triangles about its centroid c = mean of its nodes (the
 * split surface is watertight with its neighbours: edges stay straight). The gradient is exact:
 *   triangle:  dV/da = (1/6) (b-a) x (c-a) = A n / 3     (same for b, c cyclically)
 *   quad k:    dV/dx_k = (1/6) (c-x_k) x (x_{k-1}-x_{k+1}) + S/12,  S = (1/2)(x3-x1) x (x4-x2)
 * (o-independent because the face ring around a node closes). Pressure nodal forces are
 * f = p dV/dx, so the work they do equals p dV exactly for a virtual motion.
 *
 * Faces are given as nface x 4 node indices (0-based); a triangle has its 4th index < 0.
 * Faces must be oriented with outward normals (counter-clockwise seen from outside); then the
 * volume is positive. No function here allocates except fe_surface_check. */
#ifndef FE_SURFACE_VOLUME_H
#define FE_SURFACE_VOLUME_H

#include "core/mcs_error.h"

/* enclosed volume [m^3] of the closed surface; x: node positions [m] (nnode x 3) */
double fe_surface_volume(int nface, const int *face_node, const double *x);

/* same, and adds p * dV/dx into f (nnode x 3) [N]; returns the volume [m^3].
 * With p = 1 and f zeroed, f holds the gradient dV/dx [m^2]. */
double fe_surface_pressure_forces(int nface, const int *face_node, const double *x, double p,
                                  double *f);

/* dV/dt = sum_nodes dV/dx . v [m^3/s]; v: node velocities [m/s] (nnode x 3) */
double fe_surface_volume_rate(int nface, const int *face_node, const double *x, const double *v);

/* total face area [m^2] (quads as their four centroid triangles) */
double fe_surface_area(int nface, const int *face_node, const double *x);

/* sum over faces of the vector area A n [m^2] (3); zero for a closed surface, the projected
 * area for an open one (e.g. a hemisphere: its equator disc) */
void fe_surface_vector_area(int nface, const int *face_node, const double *x, double out[3]);

/* validate a surface (at model build): indices in [0, nnode), no repeated node in a face,
 * closed (every edge shared by exactly two faces) and consistently oriented (the two faces run
 * the edge in opposite directions). Names the first offending face or edge. Allocates a
 * temporary edge list. `name` labels the messages. */
mcs_status fe_surface_check(const char *name, int nnode, int nface, const int *face_node,
                            mcs_error *err);

#endif

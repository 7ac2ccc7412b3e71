/* mb_geom_wheel2.h: wheel-wheel (cylinder-cylinder) penetration geometry of stage 1
 * (docs/contact_geometry.md "Wheel against wheel").
 *
 * A wheel surface is the filled wheel of mb_geom_wheel_ellipsoid: the flat disc of radius
 * `radius` grown by a ball of radius `tube` (the convex hull of the tyre torus). Two such solids
 * overlap exactly when disc A grown by tube_a + tube_b overlaps disc B, with the same
 * penetration depth and normal (Minkowski sums: support functions add). So the query is
 * mb_geom_wheel_ellipsoid of wheel A with the tube tube_a + tube_b against B's disc as the flat
 * ellipsoid (R_b, R_b, MB_WHEEL_EPS R_b): the depth is exact for every normal not along B's
 * axis and at most MB_WHEEL_EPS R_b too deep along it (and likewise for A). The points are then
 * moved onto the two wheels' own surfaces: point_a on A's tyre, point_b on B's. This is the
 * swept-sphere (capsule-like) construction with a disc instead of a segment: depth =
 * tube_a + tube_b - distance(disc A, disc B) when the discs are apart. */
#ifndef MB_GEOM_WHEEL2_H
#define MB_GEOM_WHEEL2_H

#include "stage1_mb/mb_geom.h"

/* wheel a against wheel b: returns 1 and fills c (normal from b into a) when they penetrate,
 * 0 when apart (c->normal then holds a separating direction when one was found: the next
 * step's warm start); warm_normal as for mb_geom_wheel_ellipsoid */
int mb_geom_wheel_wheel(const mb_wheel *a, const mb_wheel *b, const double *warm_normal,
                        mb_contact *c);

#endif

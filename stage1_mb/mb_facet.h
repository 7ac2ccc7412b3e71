/* mb_facet.h: facet (triangle mesh) contact surfaces of stage 1: building the mesh from the
 * scenario (mb_build_facet.c) and the per-step detection against an ellipsoid (mb_facet.c).
 *
 * A facet surface is a triangle mesh fixed in its body's frame (vertices relative to the CG);
 * each triangle is one-sided, its outward side given by the counter-clockwise vertex order.
 * The penetration of an ellipsoid is the deepest single-triangle contact (face, edge or vertex,
 * mb_geom_ellipsoid_mesh_deepest with the AABB tree); a triangle only counts while the
 * ellipsoid's centre is on its outer side, so an ellipsoid pushed through a panel by more than
 * its semi-axis loses the contact: use facets for surfaces met at modest penetration (glass,
 * roof, hood, fairing, barrier faces) and ellipsoids for deep crush zones. Only ellipsoids meet
 * facets (cylinders and planes do not).
 * Depth continuity: a triangle whose contact would be deeper than the pair's depth at the last
 * step plus a quarter of the ellipsoid's smallest semi-axis is ignored. Such a contact cannot
 * come from motion over one step (10 um at 10 m/s); it appears when the centre of an ellipsoid
 * that overlaps a panel's edge from the side crosses the panel's plane (a head sliding up the
 * side glass past the roof edge), and it would add the energy of a sudden deep penetration.
 * Known limit: at an edge or vertex the depth is still measured along the face normal, which
 * is not the gradient of the contact energy, so edge contacts do work the balance does not see
 * (the 413 rider case drifts 3.4e-2). Applying the force along the gradient (tried: drift
 * 2.6e-3) made a head striking a panel edge sideways 5-10 times too stiff, because this depth
 * grows faster than the real overlap there; a distance-based penetration is the fix. */
#ifndef MB_FACET_H
#define MB_FACET_H

#include "stage1_mb/mb_model.h"

/* contact of an ellipsoid (placed in the world) with facet surface sf of a body at pose k
 * (NULL: the world); c->depth = 0 when apart */
void mb_facet_detect(const mb_ellipsoid *ea, const mb_surface *sf, const mb_body_kin *k,
                     double prev_depth, mb_contact *c);

#endif

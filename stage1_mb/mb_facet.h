/* mb_facet.h: facet (triangle mesh) contact surfaces of stage 1: building the mesh from the
 * scenario (mb_build_facet.c) and the per-step detection against an ellipsoid (mb_facet.c).
 *
 * A facet surface is a triangle mesh fixed in its body's frame (vertices relative to the CG);
 * each triangle is one-sided, its outward side given by the counter-clockwise vertex order.
 * The penetration of an ellipsoid through one triangle is a distance that is continuous in the
 * pose across the triangle's face, edge and vertex regions: the depth below the plane while
 * the ellipsoid's support point along -n projects inside the triangle, otherwise the
 * penetration of the nearest edge's line or vertex (its distance to the ellipsoid's surface),
 * with the contact normal along that distance (docs/contact_geometry.md). The surface's
 * contact is the deepest triangle's (mb_geom_ellipsoid_mesh_deepest with the AABB tree): the
 * largest of continuous functions is continuous, two faces sharing an edge give that edge the
 * same line penetration (no double count), and the force, along the gradient of the depth,
 * derives from the contact potential, so an elastic contact slid over an edge or a vertex does
 * no net work (tests/test_mb_facet_edge.c). A sphere over an edge or vertex meets exactly the
 * line or point contact R - distance.
 * A triangle only counts while the ellipsoid's centre is on its outer side, so an ellipsoid
 * pushed through a panel by more than its semi-axis loses the contact: use facets for surfaces
 * met at modest penetration (glass, roof, hood, fairing, barrier faces) and ellipsoids for deep
 * crush zones. Only ellipsoids meet facets (cylinders and planes do not). Where separate facet
 * surfaces (separate contacts) meet at a corner, each has its own contact there.
 * Depth continuity: a triangle whose contact would be deeper than the pair's depth at the last
 * step plus a quarter of the ellipsoid's smallest semi-axis is ignored. Such a contact cannot
 * come from motion over one step (10 um at 10 m/s); it appears when the centre of an ellipsoid
 * that has come through a panel from behind (a head through the side glass, under the roof)
 * crosses the panel's plane, and it would add the energy of a sudden deep penetration. The
 * pair's latch keeps such a triangle ignored until its contact ends (else it would begin at the
 * cap's depth once it shrinks below it). The same one-sidedness ends a contact at depth when
 * the centre passes a panel's plane beside its open edge: that contact's stored energy is lost
 * (docs/contact_geometry.md, known limit). */
#ifndef MB_FACET_H
#define MB_FACET_H

#include "stage1_mb/mb_model.h"

/* contact of an ellipsoid (placed in the world) with facet surface sf of a body at pose k
 * (NULL: the world); prev_depth: the pair's depth at the last step [m]; latch: the pair's
 * latched triangles (updated); c->depth = 0 when apart */
void mb_facet_detect(const mb_ellipsoid *ea, const mb_surface *sf, const mb_body_kin *k,
                     double prev_depth, mb_mesh_latch *latch, mb_contact *c);

#endif

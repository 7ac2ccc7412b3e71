/* fe_scn_pad: FE parts made from a stage-1 body's surfaces (the stage-2 cockpit, DESIGN.md
 * "Stage 2", docs/contracts.md "Stage 2").
 *
 * mesh: {generate: foam_pad, body: B, surface: S, thickness: T, layers: L,
 *        [ellipsoid: element_size: H, longitude: [lon0, lon1], latitude: [lat0, lat1]]}
 *   on an ellipsoid S of body B: a layer of hex8 elements over the patch lon0..lon1 x
 *   lat0..lat1, p(lon, lat) = c + Q (a cos lat cos lon, b cos lat sin lon, c sin lat) in the
 *   body frame (Q: the surface's orientation), put in the world at the body's position and
 *   orientation of t = 0; the inner face on the surface, L elements through the thickness along
 *   the surface's outward normal to T; ceil(arc / H) elements along each patch direction (the
 *   longest arc of that direction); a full turn of longitude closes on itself.
 *   On a facet surface S: the whole of it, one prism (LS-DYNA's pentahedron n1 n2 n3 n4 n5 n5
 *   n6 n6) per triangle and layer, along the area-weighted vertex normals.
 * mesh: {generate: surface_shell, body: B, surface: S, [ellipsoid: element_size, longitude,
 *        latitude]}: shells on the same patch (quads, the hexahedra's inner faces) or on the
 *   facet's triangles (degenerate quads a b c c), normals outward; section shell or membrane.
 * attach: {body: B, where: surface} carries the part's nodes that lie on one of B's ellipsoid
 *   or facet surfaces (distance below FE_SCN_SURFACE_TOL): a pad's inner face, a surface
 *   shell, or a keyword mesh modelled on the body. */
#ifndef FE_SCN_PAD_H
#define FE_SCN_PAD_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

#define FE_SCN_SURFACE_TOL 1e-4 /* a node this close to a body's surface lies on it [m] */

/* 1 when the mesh node is {generate: foam_pad | surface_shell, ...} */
int fe_scn_pad_is(const mcs_node *mesh);

/* add part d (its section and material read; d->mesh unused) with the pad mesh of `mesh`;
 * root: the scenario's root (the body and surface) */
mcs_status fe_scn_pad_add(fe_builder *b, const mcs_node *root, const mcs_node *mesh,
                          const fe_part_desc *d, mcs_error *err);

/* the nodes of `part` (a builder index) within FE_SCN_SURFACE_TOL of an ellipsoid or facet
 * surface of the body named `body` (its first 16 facet surfaces), at their positions before any
 * placement; written to idx (capacity cap), the count returned (-1 out of memory, 0 none or no such
 * body) */
int fe_scn_surface_nodes(const fe_builder *b, const mcs_node *root, int part, const char *body,
                         int *idx, int cap);

#endif

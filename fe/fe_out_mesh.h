/* fe_out_mesh: one part's initial mesh in /stage3/mesh/<part> with each element's own cell type
 * (mcs_results.h conventions): shells quad4, trusses line2, 10-node tetrahedra tet10, and a
 * solid part's hexahedra hex8, its tetrahedra tet4 and its pentahedra wedge6 (the kernel keeps
 * the last two as degenerate hexes, fe/fe_tet.c). A part with one solid shape writes it in
 * `elements`; with several, the hexahedra (else the wedges) go to `elements` and each other
 * shape to elements_<type>. */
#ifndef FE_OUT_MESH_H
#define FE_OUT_MESH_H

#include "core/mcs_results.h"
#include "fe/fe_model.h"

/* into /stage<stage>/mesh/<part> */
mcs_status fe_out_part_mesh(mcs_results *r, int stage, const fe_model *m, const fe_part *p,
                           mcs_error *err);

#endif

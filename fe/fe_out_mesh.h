/* fe_out_mesh: one part's initial mesh in /stage<N>/mesh/<part> with each element's own cell type
 * (mcs_results.h conventions): shells quad4, trusses line2, 10-node tetrahedra tet10, and a
 * solid part's hexahedra hex8, its tetrahedra tet4 and its pentahedra wedge6 (the kernel keeps
 * the last two as degenerate hexes, fe/elem/fe_tet.c). A part with one solid shape writes it in
 * `elements`; with several, the hexahedra (else the wedges) go to `elements` and each other
 * shape to elements_<type>. */
#ifndef FE_OUT_MESH_H
#define FE_OUT_MESH_H

#include "core/mcs_results.h"
#include "core/mcs_results_export.h"
#include "fe/fe_model.h"
#include "fe/fe_state.h"

/* the cell types the meshes carry (the `type` of each element block) with their node counts and
 * XDMF topologies, for the XDMF export (mcs_xdmf_opts.cells): line2 Polyline, tri3 Triangle,
 * quad4 Quadrilateral (a 4-wide block without `type`), tet4 Tetrahedron, wedge6 Wedge, hex8
 * Hexahedron, tet10 Tetrahedron_10; *n gets their count */
const mcs_cell_type *fe_out_cell_types(int *n);

/* into /stage<stage>/mesh/<part> */
mcs_status fe_out_part_mesh(mcs_results *r, int stage, const fe_model *m, const fe_part *p,
                           mcs_error *err);
/* every part's mesh */
mcs_status fe_out_meshes(mcs_results *r, int stage, const fe_model *m, mcs_error *err);

/* the displacement field of every node, /stage<stage>/fields/{time [nout] s, displacement
 * [nout, nnode, 3] m} (rows of the model's node numbering; each mesh's node_offset says where
 * its part begins) */
typedef struct {
    mcs_results_series *time, *disp;
    double *buf; /* (nnode x 3) */
} fe_out_field;

mcs_status fe_out_field_open(mcs_results *r, int stage, const fe_model *m, fe_out_field *o,
                             mcs_error *err);
/* one frame: time t [s] and x - x0 of the state's nodes */
mcs_status fe_out_field_sample(const fe_model *m, const fe_state *s, double t,
                               const fe_out_field *o, mcs_error *err);
void fe_out_field_free(fe_out_field *o);

#endif

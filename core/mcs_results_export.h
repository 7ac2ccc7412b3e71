/* mcs_results_export: a results file in other formats (`mcrash export`): CSV channel tables
 * and an XDMF file that ParaView opens beside the HDF5 file. */
#ifndef MCS_RESULTS_EXPORT_H
#define MCS_RESULTS_EXPORT_H

#include "core/mcs_results.h"

/* DIR/stageN_channels.csv and DIR/stageN_energy.csv for every stage that has them:
 * header `time [s], name [unit], ...`, first column /stageN/time, one row per output time.
 * DIR is created if missing; each file is written to a temporary and renamed.
 * *nfiles counts the files written. MCS_ERR_FORMAT when the file has no /stageN group. */
mcs_status mcs_results_export_csv(mcs_results *r, const char *dir, int *nfiles, mcs_error *err);

/* a cell type of the meshes of /stageN/mesh: the `type` attribute of an element block
 * (mcs_results.h), its nodes per cell and its XDMF TopologyType. The writer of the meshes owns
 * the list (fe_out_cell_types(), fe/fe_out_mesh.h); the export knows none of its own */
typedef struct {
    const char *name; /* `type` attribute, also the block name elements_<name> ("hex8") */
    int nodes;        /* nodes per cell                                                */
    const char *xdmf; /* XDMF TopologyType ("Hexahedron")                              */
    int by_width;     /* 1: a block without `type` that has `nodes` columns is of this type */
} mcs_cell_type;

typedef struct {
    int stride;     /* write every stride-th output time; 0 = so that at most max_frames remain */
    int max_frames; /* for stride 0 (default 2000)                                            */
    int legacy;     /* 1: XDMF 2 (HyperSlab items, deformed geometry as a Function) for
                       ParaView's legacy "XDMF Reader"; 0: XDMF 3 for the Xdmf3 readers      */
    const mcs_cell_type *cells; /* the meshes' cell types (NULL: a file with meshes is refused);
                                   a part's further blocks are looked up in this order     */
    int ncells;
} mcs_xdmf_opts;

mcs_xdmf_opts mcs_xdmf_opts_default(void);

/* an XDMF file for ParaView. For each stage: the FE parts of /stageN/mesh as a temporal
 * collection with the displacement of /stageN/fields/displacement at each output time as a
 * nodal vector (XDMF 3: on the reference geometry, shown deformed by Warp By Vector; legacy
 * XDMF 2: the geometry itself is nodes + displacement), and the rigid bodies of
 * /stageN/bodies as points moving along their position with their orientation quaternion
 * (w, x, y, z) as a 4-component attribute. HDF5 references name the results file relative
 * to the .xmf. The cell types of the meshes come from opts->cells. */
mcs_status mcs_results_export_xdmf(mcs_results *r, const char *xmf_path,
                                   const mcs_xdmf_opts *opts, mcs_error *err);

/* stage numbers present in the file (groups /stageN), ascending; returns the count */
int mcs_results_stages(mcs_results *r, int *stages, int max);

#endif

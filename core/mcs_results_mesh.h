/* mcs_results_mesh: read back one part's mesh that a run wrote to /stageN/mesh/<part>
 * (mcs_results.h conventions: nodes [nn,3] m with node_offset, elements [ne,k] with type,
 * elements_<type> for a part's other element shapes), in its reference shape or deformed by
 * /stageN/fields/displacement at a time of /stageN/fields/time (else /stageN/time). The reader
 * of the FE writer fe/out/fe_out_mesh.c: a mesh written by one stage's run is read into another
 * stage's scenario (`mesh: {from: OUT.h5:/stage2/mesh/<part>}`, fe/scn/fe_scn_from.c). */
#ifndef MCS_RESULTS_MESH_H
#define MCS_RESULTS_MESH_H

#include <stddef.h>

#include "core/mcs_error.h"

#define MCS_MESH_MAXBLOCK 8

typedef struct {
    char type[16]; /* the `type` attribute (ends in k); "": none (the width decides) */
    int k;         /* nodes per element [-] */
    size_t ne;     /* elements [-] */
    int *elem;     /* rows of the mesh's nodes, 0-based, VTK order (ne x k) */
} mcs_mesh_block;

typedef struct {
    size_t nn;                               /* nodes [-] */
    double *x;                               /* node positions [m] (nn x 3) */
    int node_offset;                         /* first row in the stage's node numbering [-] */
    double time;                             /* time of the shape; -1: the reference [s] */
    int nblock;                              /* element blocks [-] */
    mcs_mesh_block block[MCS_MESH_MAXBLOCK]; /* `elements` first, then elements_<type> */
} mcs_mesh;

typedef enum {
    MCS_MESH_REFERENCE, /* the nodes as written (the shape at t = 0) */
    MCS_MESH_AT,        /* deformed at a time within the written fields (linear between rows) */
    MCS_MESH_FINAL,     /* deformed at the last row of the fields */
} mcs_mesh_shape;

/* the mesh of `ref` = "FILE.h5:/stageN/mesh/<part>" in shape `shape` (`at` [s] for
 * MCS_MESH_AT); errors (missing file, group, fields, a time outside the fields, arrays of the
 * wrong shape) name the file and the path. Free with mcs_mesh_free. */
mcs_status mcs_results_read_mesh(const char *ref, mcs_mesh_shape shape, double at, mcs_mesh *out,
                                 mcs_error *err);
void mcs_mesh_free(mcs_mesh *m);

#endif

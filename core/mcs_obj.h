/* mcs_obj.h: a small reader of triangle meshes in the Wavefront OBJ text format, for facet
 * contact surfaces (docs/scenario_keys.md, surface type facet; docs/models.md). Read: "v x y z"
 * (vertex, metres) and "f a b c ..." (a face: 1-based vertex indices, or negative ones counting
 * back from the last vertex; "a/t/n" forms keep a; a polygon becomes a fan of triangles
 * a b c, a c d, ...). Blank lines, comments (#) and every other statement (vt, vn, o, g, s,
 * usemtl, mtllib, l) are skipped. Faces are counter-clockwise seen from outside. Errors name the
 * file and line. At most MCS_OBJ_MAX_VERT vertices and MCS_OBJ_MAX_TRI triangles. */
#ifndef MCS_OBJ_H
#define MCS_OBJ_H

#include "core/mcs_error.h"

#include <stddef.h>

#define MCS_OBJ_MAX_VERT 1000000
#define MCS_OBJ_MAX_TRI 2000000

typedef struct {
    int nvert, ntri;
    double *vert; /* nvert x 3 [m] (malloc) */
    int *tri;     /* ntri x 3, 0-based (malloc) */
} mcs_obj_mesh;

mcs_status mcs_obj_read(const char *path, mcs_obj_mesh *out, mcs_error *err);
/* the path of a file named in a scenario file: relative names are taken from the directory of
 * that scenario file (as include: does); 0, or -1 when buf is too small */
int mcs_obj_path(const char *scenario_file, const char *name, char *buf, size_t n);
void mcs_obj_free(mcs_obj_mesh *m);

#endif

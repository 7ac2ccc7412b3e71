/* mb_build_internal.h: shared helpers of the stage-1 model builder (mb_build*.c only). */
#ifndef MB_BUILD_INTERNAL_H
#define MB_BUILD_INTERNAL_H

#include "stage1_mb/mb_model.h"

#include <stdlib.h>

/* zeroed array of n items (at least one) or NULL */
#define MB_NEW(T, n) ((T *)calloc((size_t)((n) > 0 ? (n) : 1), sizeof(T)))

/* body index of a name; MB_GROUND for "ground" (references are checked by the schema) */
int mb_build_body_ref(const mb_model *m, const mcs_node *ref);
/* characteristic index of a name or -1 */
int mb_build_char_ref(const mb_model *m, const mcs_node *ref);
/* unit vector of a direction node into v */
mcs_status mb_build_dir(const mcs_node *n, double v[3], mcs_error *err);
/* rotation (row-major, local -> parent) of roll, pitch, yaw (z-y-x Cardan, ISO 8855) */
void mb_build_cardan(const double rpy[3], double R[9]);

mcs_status mb_build_chars(const mcs_node *root, mb_model *m, mcs_error *err);
mcs_status mb_build_surfaces(const mcs_node *root, mb_model *m, mcs_error *err);
/* a facet surface's mesh from its vertices/triangles or OBJ file (mb_build_facet.c) */
mcs_status mb_build_facet(const mcs_node *n, mb_surface *s, mcs_error *err);
mcs_status mb_build_contacts(const mcs_node *root, mb_model *m, mcs_error *err);
mcs_status mb_build_joints(const mcs_node *root, mb_model *m, mcs_error *err);
mcs_status mb_build_attachments(const mcs_node *root, mb_model *m, mcs_error *err);

#endif

/* s3_build_solid: the `fe:` keys of the discrete springs and dampers, point masses, gravity,
 * foam and rigid materials, the fully integrated hex and mass scaling (fe/fe_solid.h), read
 * into the kernel's descriptors for s3_build. Errors name FILE:LINE:COL and the key. */
#ifndef S3_BUILD_SOLID_H
#define S3_BUILD_SOLID_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

/* environment.gravity (magnitude along -z) and fe.mass_scaling into opts */
void s3_solid_opts(const mcs_node *root, fe_opts *opts);
/* fe.springs and fe.masses, after the parts */
mcs_status s3_solid_add(fe_builder *b, const mcs_node *fe, mcs_error *err);
/* material models foam and rigid (s3_build's read_material hands them over) */
mcs_status s3_solid_material(const mcs_node *mat, fe_material_desc *d, mcs_error *err);

#endif

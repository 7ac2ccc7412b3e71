/* fe_scn_solid: the `fe:` keys of the discrete springs and dampers, point masses, gravity,
 * foam and rigid materials, the fully integrated hex and mass scaling (fe/fe_solid.h), read
 * into the kernel's descriptors for fe_scn_build. Errors name FILE:LINE:COL and the key. */
#ifndef FE_SCN_SOLID_H
#define FE_SCN_SOLID_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

/* environment.gravity (magnitude along -z) and fe.mass_scaling into opts */
void fe_scn_solid_opts(const mcs_node *root, fe_opts *opts);
/* fe.springs and fe.masses, after the parts */
mcs_status fe_scn_solid_add(fe_builder *b, const mcs_node *fe, mcs_error *err);
/* material models foam and rigid (fe_scn_build's read_material hands them over) */
mcs_status fe_scn_solid_material(const mcs_node *mat, fe_material_desc *d, mcs_error *err);

#endif

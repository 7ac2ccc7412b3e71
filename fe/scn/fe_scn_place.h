/* fe_scn_place.h: the FE parts carried by placed stage-1 bodies moved with them in the builder,
 * before the model is frozen (fe_scn_build.h, fe_scn_place; fe_scn_place.c). */
#ifndef FE_SCN_PLACE_H
#define FE_SCN_PLACE_H

#include "fe/fe_scn_build.h"

/* carriers of the parts into out->part_carrier, then the moved group's parts, anchors and
 * points moved; errors at the key (FILE:LINE:COL) */
mcs_status fe_scn_place_apply(fe_builder *b, const mcs_node *fe, const fe_scn_place *pl,
                              fe_problem *out, mcs_error *err);

#endif

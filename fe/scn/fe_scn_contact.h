/* fe_scn_contact: the `fe.contacts` and `fe.rigid_ellipsoids` keys of a scenario into the
 * kernel's contact descriptors (fe/fe_contact.h). Types: single_surface {parts},
 * two_surface {slave, master} and surface_to_surface {a, b} (symmetric, two passes),
 * node_to_surface {a: slave nodes, b: master segments}; friction, friction_dynamic,
 * friction_decay, penalty_scale, thickness_scale, name. Errors name FILE:LINE:COL and key. */
#ifndef FE_SCN_CONTACT_H
#define FE_SCN_CONTACT_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

/* coupled: contacts of type bodies are left to the stage-1 coupling (else refused) */
mcs_status fe_scn_contact_add(fe_builder *b, const mcs_node *fe, int coupled, mcs_error *err);

#endif

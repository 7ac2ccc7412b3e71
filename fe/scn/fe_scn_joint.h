/* fe_scn_joint: the `fe.joints` scenario key (DESIGN.md "Stage 3 of a crash scenario") into
 * fe_builder_add_joint (fe_joint.h): {name, type, parts: [A, B] (one: A to the ground), point,
 * axis, stiffness, damping, range, penalty_scale}. */
#ifndef FE_SCN_JOINT_H
#define FE_SCN_JOINT_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

mcs_status fe_scn_add_joints(fe_builder *b, const mcs_node *fe, mcs_error *err);
/* the fe.joints entry a kernel message names ("joint '<name>'"): its parts key when the
 * message is about a body, else the entry; dflt when none */
const mcs_node *fe_scn_joint_node(const mcs_node *fe, const char *msg, const mcs_node *dflt);

#endif

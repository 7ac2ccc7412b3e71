/* s2_scenario: the scenario as stage 2 runs it (DESIGN.md "Stage 2", docs/contracts.md
 * "Stage 2"). Stage 2 runs the SAME scenario model as stage 1 (bodies, contacts, fe: restraints,
 * rider) with stage2.prescribed bodies moved from a stage-1 file; what exists in stage 2 only
 * (the FE cockpit: foam pads, panels, their contacts) is written under stage2.fe and appended
 * to fe:'s lists here, so one scenario file serves both stages:
 *
 *   stage2:
 *     motion: out/iso413_concept.h5
 *     prescribed: [{body: moto_frame}, {body: sedan}]
 *     fe:
 *       parts:    [{name: pad_tank_l, mesh: {generate: foam_pad, body: moto_frame, ...},
 *                   attach: {body: moto_frame, where: surface}, ...}]
 *       contacts: [{type: bodies, parts: [pad_tank_l], bodies: [rider_thigh_l]}]
 *
 * For the stage-2 runner (stage2_fe/s2_run.c): compile first, then build everything from the
 * compiled scenario as stage 1 does (mb_model_build, tr_stage2_motion_create take it):
 *
 *   mcs_scenario *s2 = NULL;
 *   st = s2_scenario_compile(scn, &s2, err);     // scn: as loaded; s2: owned by the caller
 *   ...  mb_model_build(s2, &opts, &m, err) ... tr_stage2_motion_create(&mo, s2, m, path, err)
 *   mcs_scenario_destroy(&s2);
 *
 * Errors (exit-2 class, FILE:LINE:COL of the key): no stage2: block (MCS_ERR_KEY); a stage2.fe
 * part named as one of fe:'s (the merged list's unique names). */
#ifndef S2_SCENARIO_H
#define S2_SCENARIO_H

#include "core/mcs_scenario.h"

/* scn with stage2.fe's lists appended to fe:'s and stage2.energy_groups merged on top of
 * energy_groups (both removed, the rest as loaded),
 * validated again; *out is a new scenario (mcs_scenario_destroy), independent of scn */
mcs_status s2_scenario_compile(const mcs_scenario *scn, mcs_scenario **out, mcs_error *err);

#endif

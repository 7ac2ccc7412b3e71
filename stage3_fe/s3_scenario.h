/* s3_scenario: the scenario as stage 3 runs it (docs/contracts.md "Stage 3"). A scenario that
 * stage 1 runs (bodies, contacts, impact:, an fe: block of restraints coupled to its bodies)
 * names its full-FE model in a stage3: block, so one file serves every stage:
 *
 *   stage3:
 *     simulation: {end_time: 100 ms}          # merged over simulation: key by key
 *     fe:                                      # the stage-3 model: replaces fe:
 *       parts:
 *         - name: moto
 *           mesh: {generate: motorcycle, model: models/motorcycles/sport_208kg.yaml,
 *                  element_size: 20 mm}
 *           initial_velocity: [13.4 m/s, 0, 0]
 *       rigid_walls: [{name: barrier, point: [1.725 m, 0, 0], normal: [-1, 0, 0], ...}]
 *
 * The compiled scenario is FE-only: fe: is stage3.fe, simulation: has stage3.simulation over
 * it, and the stage-1 keys (bodies, contacts, joints, attachments, sensors, impact, rider,
 * mount_points, energy_groups, stage2) are left out; characteristics and environment stay.
 * A scenario without a stage3: block is run by stage 3 as it is (an fe:-only scenario). */
#ifndef S3_SCENARIO_H
#define S3_SCENARIO_H

#include "core/mcs_scenario.h"

/* 1 when scn has a stage3: block */
int s3_scenario_has_block(const mcs_scenario *scn);

/* *out: the stage-3 scenario of scn (a new scenario, mcs_scenario_destroy; independent of
 * scn), validated again. MCS_ERR_KEY at the root when scn has no stage3: block */
mcs_status s3_scenario_compile(const mcs_scenario *scn, mcs_scenario **out, mcs_error *err);

#endif

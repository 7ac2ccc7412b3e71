/* s3_sedan: the opponent's side structure in FE (`mesh: {generate: sedan_side, model: FILE,
 * element_size: h}` in fe.parts; docs/validation_stage3.md "The sedan side").
 *
 * Built from the stage-1 sedan (a scenario file of its own, read by the scenario reader:
 * scenarios/models/opponents/sedan_1668kg.yaml): the body "sedan"'s position and its side
 * surfaces (front door, sill, B-pillar, roof rail ellipsoids; the body "sedan_upper"'s side
 * glass facet) place the parts; every body's mass, position and inertia give the car's total.
 * Parts, named <name>_<component>, on the struck (-x, right) side:
 *   door_outer, door_inner  front door skin and inner panel (shells, mild steel);
 *   door_beam   side impact beam, a round tube along the car at the door's mid-height;
 *   sill, b_pillar, roof_rail  closed rectangular sections (shells, high-strength steel);
 *   glass       front side glass, beltline to roof rail (elastic shells: no erosion yet);
 *   body        the rest of the car: a rigid shell box carrying the stage-1 car's mass, centre
 *               of gravity and inertia less the deformable parts' (given mass properties).
 * Every panel's perimeter and every section's end rings are extra nodes of `body` (the door
 * hinges, latch and frame; the pillars' and rails' joints to the body in white). */
#ifndef S3_SEDAN_H
#define S3_SEDAN_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

typedef struct {
    double element_size;        /* target element edge [m]          */
    char name[FE_NAME_MAX / 2]; /* part name prefix                 */
    double velocity[3];         /* initial velocity of every node    */
} s3_sedan_opts;

/* the car's stage-1 total (every body of the model): mass, centre of gravity, inertia about it
 * (world axes) */
typedef struct {
    double mass, cg[3], inertia[3][3];
} s3_sedan_mass;

/* add the side structure of the stage-1 sedan model (its root) to b; *total (may be NULL)
 * receives the stage-1 total it was built to */
mcs_status s3_sedan_build(fe_builder *b, const mcs_node *model, const s3_sedan_opts *o,
                          s3_sedan_mass *total, mcs_error *err);
/* the fe.parts entry `part` (mesh: {generate: sedan_side, ...}): loads the model file (relative
 * to the scenario file) and builds it (fe_scn_generator of fe/fe_scn_build.h) */
mcs_status s3_sedan_part(fe_builder *b, const mcs_node *root, const mcs_node *part, mcs_error *err);
/* registers s3_sedan_part as the fe: builder's `sedan_side` generator */
void s3_sedan_register(void);

#endif

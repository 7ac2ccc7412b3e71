/* s3_moto: the parametric FE motorcycle (`mesh: {generate: motorcycle, model: FILE,
 * element_size: h}` in fe.parts; docs/validation_stage3.md "The motorcycle mesh").
 *
 * Built from the stage-1 model file (a scenario file of its own, read by the scenario reader:
 * scenarios/models/motorcycles/sport_208kg.yaml): its bodies (mass, centre of gravity,
 * inertia), surfaces (engine, tank, seat and fairing ellipsoids; tyre cylinders), joints
 * (steering axis, fork hinge, suspension, axles, swing-arm pivot) and characteristics (front
 * spring and preload, rear moment and preload, dampers). Parts, named <name>_<component>:
 *   frame       rigid engine (closed box of shells) carrying the frame's remaining mass;
 *   head        steering head (shell tube), a nodal rigid body with the frame tubes' front
 *               rings and the fairing's rear face;
 *   frame_l/r   twin spars (elastic-plastic aluminium tubes), rear rings on the frame;
 *   tank, seat, fairing  shell boxes in the stage-1 ellipsoids (steel, ABS), bottom (fairing:
 *               rear) face on the frame (head);
 *   upper_fork  rigid triple clamps, upper stanchions and clip-ons;
 *   stanchion_l/r  43 x 2 mm steel tubes (sigma_y 700 MPa) below the lower clamp, the
 *               stage-1 fork-deformation body; the rest of its mass spread on their nodes;
 *   slider_l/r  aluminium tubes; suspension: a translational joint per leg (the stanchion's
 *               bottom ring and the slider's top ring, each a nodal rigid body) with a spring
 *               per leg carrying half the stage-1 curve, preload and damper;
 *   lower_fork  rigid axle; front_wheel / rear_wheel rigid hub and spokes on axle joints;
 *   front_rim / rear_rim  aluminium shell bands; front_tyre / rear_tyre rubber shells sealed on
 *               the rim edges, the closed volume with the rim a gas bag of the tyre's air
 *               (<name>_front_tyre, <name>_rear_tyre: constant gas mass at the cold inflation
 *               pressure, 250 / 290 kPa gauge);
 *   swing_arm   rigid, on the pivot joint; the shock: a spring whose lever gives the stage-1
 *               rear rate, preload and damper.
 * Each stage-1 body's mass, centre of gravity and inertia (diagonal, world axes) are met by the
 * generated shells plus six point masses (extra nodes of the body's rigid part) placed by the
 * parallel-axis theorem; the fork-deformation body (no rigid part) by its tubes' placement and
 * mass spread on them. */
#ifndef S3_MOTO_H
#define S3_MOTO_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

typedef struct {
    double element_size;      /* target element edge [m]                                  */
    char name[FE_NAME_MAX / 2]; /* part name prefix                                       */
    double velocity[3];       /* initial velocity of every node; wheels roll (w = v_x / R) */
    const mcs_node *at;       /* where the joints' messages point (must outlive the builder:
                                 the scenario's part entry), NULL none                       */
} s3_moto_opts;

/* add the motorcycle of the stage-1 model `model` (its root) to b */
mcs_status s3_moto_build(fe_builder *b, const mcs_node *model, const s3_moto_opts *o,
                         mcs_error *err);
/* the fe.parts entry `part` (mesh: {generate: motorcycle, ...}): loads the model file (relative
 * to the scenario file) and builds it (fe_scn_generator of fe/fe_scn_build.h) */
mcs_status s3_moto_part(fe_builder *b, const mcs_node *root, const mcs_node *part,
                        mcs_error *err);
/* registers s3_moto_part as the fe: builder's `motorcycle` generator */
void s3_moto_register(void);

#endif

/* mb_loadcell.h: load-cell sensors of stage 1 (sensors: type load_cell; docs/rider.md
 * "Load cells").
 *
 * A load cell reports the force and moment that its joint exerts on `body` (SAE J211: the
 * part of the dummy above the cell; `body` is the joint's child or parent), about the cell
 * point `point` of body `frame` (default `body`), on the cell axes (the frame body's axes
 * turned by `orientation`), in the J211 sign convention: ISO axes (x forward, y left, z up) ->
 * (x, -y, -z). The joint's load on its child is the constraint force and torque ODE computed
 * at the last step (dJointSetFeedback, the torque about the child's CG) plus the joint
 * restraint's torque (or force) applied at that step; on the parent it is the opposite
 * (Newton's third law, the same line of action). Moved to the cell point:
 *   M_P = M_cg + (c - P) x F.
 * Channels <name>_fx, _fy, _fz [N] and _mx, _my, _mz [N m]; so the upper-neck cell of a rider
 * gives neck_fx/fz/my for Nij (Fz > 0 tension, My > 0 flexion), femur_left_fz, tibia_left_*. */
#ifndef MB_LOADCELL_H
#define MB_LOADCELL_H

#include "stage1_mb/mb_model.h"

/* build the load_cell entries of sensors: (mb_build.c skips them) */
mcs_status mb_build_loadcells(const mcs_node *root, mb_model *m, mcs_error *err);
/* the six J211 values of load cell i from the state after a step [N, N m] */
void mb_loadcell_value(const mb_model *m, const mb_state *s, int i, double out[6]);
/* record every load cell into output row `row` */
void mb_loadcell_record(const mb_model *m, const mb_state *s, long row);
/* write /stage1/channels/<name>_f*, _m* */
mcs_status mb_loadcell_write(const mb_model *m, const mb_state *s, mcs_results *r,
                             mcs_error *err);

#endif

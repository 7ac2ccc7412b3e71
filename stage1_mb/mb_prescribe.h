/* mb_prescribe.h: prescribed bodies of stage 1 (issue 13, the stage-2 vehicles): a body whose
 * pose and velocities a callback gives at any time. Every step sets it at the step's end time
 * (an ODE kinematic body: infinite mass, moved by the secant velocity in the ODE step, then
 * put exactly on the callback's pose and velocities); it takes the contact, joint and
 * coupling forces without being moved by them, and the FE parts attached to it follow it as
 * they follow a free body. Energy (docs/stage1_engine.md "Prescribed bodies"): the work the
 * prescribed bodies do on the rest is external_work; their own kinetic and potential energy
 * are left out of the balance. */
#ifndef MB_PRESCRIBE_H
#define MB_PRESCRIBE_H

#include "stage1_mb/mb_model.h"

/* the motion of body `body` at time t [s]: CG position [m], orientation body -> world (w x y
 * z, unit), CG velocity [m/s], angular velocity (world) [rad/s]. Returns 0, or nonzero to stop
 * the run (SUNDIALS style: the message is the caller's) */
typedef int (*mb_motion_fn)(void *ctx, int body, double t, double pos[3], double quat[4],
                            double vel[3], double omega[3]);

/* one prescribed body of a model */
typedef struct mb_presc {
    mb_motion_fn fn; /* NULL: the body is free                                       */
    void *ctx;       /* the callback's (not owned; read by every state of the model) */
} mb_presc;

/* mark `body` prescribed by fn (after mb_model_build, before any state is created). The
 * callback's pose at t = 0 must be the body's initial pose (within 1 um and 1 urad: the FE
 * parts attached to it were placed with that); its initial velocities replace the model's. */
mcs_status mb_model_prescribe(mb_model *m, int body, mb_motion_fn fn, void *ctx, mcs_error *err);
int mb_body_prescribed(const mb_model *m, int body); /* 1 when prescribed */

/* in mb_state_create: the prescribed bodies made kinematic */
mcs_status mb_prescribe_init(const mb_model *m, mb_state *s, mcs_error *err);
/* after the contact and restraint loads, before the coupled FE parts' (mb_couple_apply):
 * the loads on the prescribed bodies */
void mb_prescribe_loads(const mb_model *m, mb_state *s);
/* the work of the prescribed bodies on the coupled FE parts: on the attached nodes and
 * through the bodies contacts (the FE side's), minus the anchor reactions' on them [J] */
double mb_prescribe_couple_work(const mb_model *m, const mb_state *s);
/* before the ODE step: the callback at t + h, the work of the loads of mb_prescribe_loads
 * over the step, the secant velocities for the ODE step */
mcs_status mb_prescribe_begin(const mb_model *m, mb_state *s, mcs_error *err);
/* after the ODE step: the bodies on the callback's pose and velocities at t + h, the work of
 * the joint reactions of the step */
void mb_prescribe_end(const mb_model *m, mb_state *s);

#endif

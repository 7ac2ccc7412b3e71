/* mb_couple_contact.h: fe.contacts[] of type bodies in a coupled stage-1 run (DESIGN.md
 * "Coupling bodies and FE parts"): the FE nodes of the named parts against the ellipsoid and
 * facet surfaces of the named bodies. Each surface is a moving rigid surface of the FE kernel
 * (fe/fe_contact.h: an ellipsoid, or a facet mesh in the body frame) whose pose is set before
 * every FE subcycle from the body's motion over the ODE step; the summed contact impulses of
 * the subcycles go back to the body in the next ODE step as a force at the CG and a moment,
 * as the attachment reactions do. docs/stage1_engine.md "Coupling to FE parts". */
#ifndef MB_COUPLE_CONTACT_H
#define MB_COUPLE_CONTACT_H

#include "fe/fe_scn_build.h"
#include "stage1_mb/mb_model.h"

typedef struct mb_couple_contact mb_couple_contact;
typedef struct mb_couple_contact_state mb_couple_contact_state;

/* the fe_scn_build_with hook: ctx is the mb_model (m->couple set); adds the kernel surfaces of
 * every type: bodies contact and keeps the map in m->couple->contact */
mcs_status mb_couple_contact_add(fe_builder *b, const mcs_node *fe, void *ctx, mcs_error *err);
void mb_couple_contact_destroy(mb_couple_contact **p);
mcs_status mb_couple_contact_state_create(const mb_couple_contact *c, mb_couple_contact_state **out,
                                          mcs_error *err);
void mb_couple_contact_state_destroy(mb_couple_contact_state **p);

/* before the ODE step: the bodies' poses at its start; the mean contact force and moment of
 * the last subcycles onto the bodies */
void mb_couple_contact_apply(const mb_model *m, mb_state *s);
/* after the ODE step, before the subcycles: the bodies' poses at its end */
void mb_couple_contact_begin(const mb_model *m, mb_state *s);
/* before an FE subcycle starting at fraction tau of the ODE step of length h: the surfaces'
 * poses and velocities */
void mb_couple_contact_pose(const mb_model *m, mb_state *s, double tau, double h);
/* after it: its contact impulses (force at t_j times dth) onto the bodies' sums */
void mb_couple_contact_sum(const mb_model *m, mb_state *s, double tau, double dth);
/* after the subcycles: mean force = impulse / h, extrapolated by alpha as the attachments' */
void mb_couple_contact_end(const mb_model *m, mb_state *s, double h, double alpha, int started);
/* the work the bodies' surfaces did on the FE parts so far [J] */
double mb_couple_contact_work(const mb_model *m, const mb_state *s);
/* the contact impulse on body `body` so far: as the structure gave it (the sum over the FE
 * subcycles) and as the body received it in its ODE steps (force and moment about the CG,
 * world) [N s, N m s]; -1 when no bodies contact names the body */
/* the same, of the surfaces on prescribed bodies only (mb_prescribe.h) [J] */
double mb_couple_contact_work_prescribed(const mb_model *m, const mb_state *s);
int mb_couple_contact_impulse(const mb_model *m, const mb_state *s, int body, double fe[6],
                              double onbody[6]);
/* a bodies contact by name (`name`, default contact<i> as the FE contacts): its index, -1 if
 * none; its force on the bodies at the last FE step (the sum over its surfaces, world) [N] */
int mb_couple_contact_find(const mb_model *m, const char *name);
void mb_couple_contact_force(const mb_model *m, const mb_state *s, int k, double f[3]);
/* the kernel surfaces of the bodies contacts (mb_egroup.c): how many; surface k's body and
 * contact; the work it did on the FE nodes so far [J]; a contact's label (its name, else its
 * parts joined by '+') and first part */
int mb_couple_contact_nsurf(const mb_model *m);
int mb_couple_contact_surf(const mb_model *m, int k, int *contact);
double mb_couple_contact_surf_work(const mb_model *m, const mb_state *s, int k);
const char *mb_couple_contact_label(const mb_model *m, int k, const char **part0);
/* the force at the CG and moment about it that surface k applies to its body in this ODE step
 * (its share of the body's, mb_couple_contact_apply) (6) [N, N m] */
const double *mb_couple_contact_surf_force(const mb_model *m, const mb_state *s, int k);

#endif

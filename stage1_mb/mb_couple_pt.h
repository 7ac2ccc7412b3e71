/* mb_couple_pt.h: what the coupling's loads on the bodies share (docs/stage1_engine.md
 * "Coupling to FE parts"): points carried by a body (attached nodes, mb_couple.c; retractor
 * anchors, mb_couple_anchor.c), which take the mean force of the last FE subcycle at their
 * position at the ODE step's start and do work over their displacement; and that mean force,
 * the impulse over the step divided by h and extrapolated (the bodies contacts' force and
 * moment too, mb_couple_contact.c). */
#ifndef MB_COUPLE_PT_H
#define MB_COUPLE_PT_H

#include "stage1_mb/mb_model.h"

/* the body frame offset l = R^T (x - c) about the CG of world point x at body d's model pose
 * (t = 0, after the placement) [m] */
void mb_couple_pt_local(const mb_body_desc *d, const double x[3], double l[3]);
/* the world position of body b's point l now [m] */
void mb_couple_pt_now(const mb_state *s, int b, const double l[3], double x[3]);
/* n points (body[i], local[i]): their world positions now into xa, force[i] applied there
 * (before the ODE step) */
void mb_couple_pt_apply(mb_state *s, int n, const int *body, const double *local,
                        const double *force, double *xa);
/* n force components from their impulses imp over the step h: the mean sg imp / h (sg = -1
 * for a reaction on the node that loads the body), force = mean + alpha (mean - last mean)
 * (fmean: the last mean, then this one; no extrapolation until started) */
void mb_couple_mean_force(int n, const double *imp, double sg, double h, double alpha, int started,
                          double *fmean, double *force);

#endif

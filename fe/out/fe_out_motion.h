/* fe_out_motion: the rigid-body "channels" of each element part, for an FE rider or any FE
 * part whose overall motion matters (issue 13):
 *   /stage<N>/parts/<part>/mass [1] kg: the lumped mass of the part's nodes (a node belongs to
 *     the part of its first element, fe_model.h node_part), mass scaling's added mass not
 *     included;
 *   /stage<N>/parts/<part>/motion/position [nt x 3] m: its centre of mass at t;
 *   /stage<N>/parts/<part>/motion/velocity [nt x 3] m/s: the mean velocity (momentum / mass),
 *     the nodes' velocities at t + dt/2 (the central-difference half step);
 *   /stage<N>/parts/<part>/motion/acceleration [nt x 3] m/s^2: the mean acceleration
 *     sum(m_i a_i) / M at t (net external force / M: internal forces cancel).
 * Parts carried by a rigid body (fe_rigid.c) and parts without nodes write nothing. */
#ifndef FE_OUT_MOTION_H
#define FE_OUT_MOTION_H

#include "core/mcs_results.h"
#include "fe/fe_state.h"

typedef struct {
    int n;                    /* element parts                                  */
    double *mass;             /* (n) part mass [kg], 0: not written             */
    mcs_results_series **ser; /* (n x 3): position, velocity, acceleration      */
} fe_out_motion;

mcs_status fe_out_motion_open(mcs_results *r, int stage, const fe_model *m, fe_out_motion *o,
                              mcs_error *err);
mcs_status fe_out_motion_sample(const fe_model *m, const fe_state *s, const fe_out_motion *o,
                                mcs_error *err);
void fe_out_motion_free(fe_out_motion *o);

#endif

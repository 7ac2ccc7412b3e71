/* fe_out_joint: joints and rigid bodies of an FE model under /stage<N> (DESIGN.md "Stage 3 of a
 * crash scenario"), one row per /stage<N>/time row (the state's energy time t_n):
 *   /stage<N>/joints/<name>/time [nt] s: the rows' times (= /stage<N>/time);
 *   /stage<N>/joints/<name>/force [nt x 3] N: force of B on A at the joint point (world);
 *   /stage<N>/joints/<name>/moment [nt x 3] N m: moment of B on A about the joint point;
 *   /stage<N>/joints/<name>/displacement [nt] m: slide of A along the axis from t = 0
 *     (cylindrical, translational);
 *   /stage<N>/joints/<name>/angle [nt] rad: angle of A about the axis relative to B from t = 0,
 *     unwrapped (revolute, cylindrical);
 *   /stage<N>/bodies/<body>/{position, orientation, velocity, angular_velocity, acceleration}:
 *     each rigid body (rigid part or nodal rigid body) in the /stage1 body layout: centre of
 *     mass [m], body-to-world quaternion w, x, y, z (body axes: the world's at t = 0), velocity
 *     [m/s], angular velocity [rad/s] (world), acceleration [m/s^2]: the mean over the output
 *     interval ending at the row of the written velocities (row 0: net force / mass at t = 0),
 *     as /stage1's (docs/contracts.md); stage 3 only (/stage1 and /stage2 hold the multibody's
 *     bodies there: a coupled run's FE joints write their joints alone). */
#ifndef FE_OUT_JOINT_H
#define FE_OUT_JOINT_H

#include "core/mcs_results.h"
#include "fe/fe_state.h"

typedef struct {
    int nj, nb;
    mcs_results_series **jser; /* (nj x 5): force, moment, displacement, angle, time (NULL: none) */
    mcs_results_series **bser; /* (nb x 5): position, orientation, velocity, angular_velocity,
                                  acceleration */
    double *vprev;             /* (nb x 3) velocity of the last row [m/s]                    */
    double tprev;              /* time of the last row [s]; < 0: no row yet                  */
} fe_out_joint;

mcs_status fe_out_joint_open(mcs_results *r, int stage, const fe_model *m, fe_out_joint *o,
                             mcs_error *err);
mcs_status fe_out_joint_sample(const fe_model *m, const fe_state *s, fe_out_joint *o,
                               mcs_error *err);
void fe_out_joint_free(fe_out_joint *o);

#endif

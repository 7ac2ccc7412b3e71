/* mb_restraint3.h: three-axis restraint of a spherical or universal joint (neck, shoulders,
 * hips): restoring torques per axis from the relative rotation of child and parent.
 *
 * Deflection: the rotation vector theta (axis times angle, |theta| < pi) of the child's rotation
 * relative to the parent since reset, expressed on the restraint axes (fixed in the parent).
 * Per axis i: g_i = P_i + F_h,i(theta_i - zero_i) + d_i dtheta_i/dt + stop_i(theta_i), P_i a
 * constant preload, zero_i the neutral angle (the rotation-vector component where F_h,i is
 * zero), F_h the two-branch hysteresis element (core/mcs_hysteresis.h), stops as in
 * mb_restraint.h. Stored energy includes P_i theta_i (theta = 0 at reset). The torque on the
 * child is -J^-T g on the restraint axes (the parent gets the opposite), with J the left
 * Jacobian of the rotation vector (omega_rel = J dtheta/dt): then the power is exactly -g .
 * dtheta/dt, so an elastic restraint conserves energy at any angle, not only small ones. */
#ifndef MB_RESTRAINT3_H
#define MB_RESTRAINT3_H

#include "core/mcs_hysteresis.h"
#include "stage1_mb/mb_ode.h"

typedef struct {
    int joint;                 /* mb_ode spherical or universal joint                          */
    double frame[9];           /* restraint axes in the parent's body frame, row-major; column
                                  i = axis i (identity = the parent's axes)                     */
    int has_spring[3];         /* per axis: 0 = no characteristic                               */
    mcs_hyst2_model spring[3]; /* restoring torque vs. theta_i, per direction [N m] vs [rad]    */
    double damping[3];         /* viscous, per axis [N m s/rad]                                 */
    double lo[3], hi[3];       /* range of theta_i [rad]                                        */
    double stop_stiffness[3];  /* stop beyond the range [N m/rad], 0 = none                     */
    double stop_damping[3];    /* stop damper [N m s/rad]                                       */
    double zero[3];            /* per axis: theta_i where the characteristic is zero [rad]      */
    double preload[3];         /* per axis: constant moment added to F_h,i [N m]                */
} mb_restraint3_model;

typedef struct {
    double neutral[9];    /* parent^T child rotation at reset (the unloaded posture)          */
    mcs_hyst2_state h[3]; /* histories per axis                                               */
    double theta[3];      /* deflection on the restraint axes at the last apply [rad]         */
    double rate[3];       /* its time derivative [rad/s]                                       */
    double torque[3];     /* torque applied to the child there, world [N m]                   */
    double e_damp;        /* energy dissipated by dampers [J]                                 */
    double load[3];       /* g_i resisting the deflection there (preload, F_h, damper, stop) [N m] */
} mb_restraint3_state;

mcs_status mb_restraint3_check(const mb_restraint3_model *m, const mb_world *w, const char *name,
                               mcs_error *err);
/* takes the bodies' current relative orientation as the neutral posture */
void mb_restraint3_reset(const mb_restraint3_model *m, mb_restraint3_state *s, const mb_world *w);
void mb_restraint3_apply(const mb_restraint3_model *m, mb_restraint3_state *s, mb_world *w,
                         double h);
double mb_restraint3_stored(const mb_restraint3_model *m, const mb_restraint3_state *s);
double mb_restraint3_dissipated(const mb_restraint3_model *m, const mb_restraint3_state *s);

/* rotation vector of a rotation matrix (row-major), |theta| in [0, pi] */
void mb_rot_log(const double R[9], double theta[3]);

#endif

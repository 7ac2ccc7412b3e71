/* tr_motion: stage-1 trajectories -> stage-2 prescribed motion (DESIGN.md "Stage 2").
 * Reads /stage1/time and /stage1/bodies/<name>/{position, orientation, velocity,
 * angular_velocity, acceleration} of a results file and gives, for each body asked for, the
 * pose, velocity and acceleration at any time t of the file's span [t_0, t_end], each the
 * time derivative of the one before it (the curve returned is the motion; its derivatives
 * are computed, not interpolated separately). Two methods (docs/validation_stage2.md
 * "Prescribed motion"):
 *
 * TR_MOTION_POSE: through the written poses. Position: cubic Hermite per sample interval
 *   with the written velocities (C1; exact for polynomials up to cubic; error O(h^4) in
 *   position, O(h^3) velocity, O(h^2) acceleration, h the sample interval). Orientation:
 *   q(t) = exp(theta(t)) q_i on the interval [t_i, t_i+1], theta a world rotation vector,
 *   cubic Hermite from theta(t_i) = 0, theta' = w_i to theta(t_i+1) = log(q_i+1 q_i^-1),
 *   theta' = J^-1(theta) w_i+1 (J: SO(3) left Jacobian, w = J(theta) theta'), so the curve
 *   passes through every written orientation with the written angular velocity (C1 on the
 *   unit sphere); exact for constant spin and for any rotation about a fixed axis whose angle
 *   is cubic in t; otherwise O(h^4) in angle. Angular acceleration is d/dt of w = J theta'.
 *   Linear and angular acceleration jump at the samples (the curve is C1, not C2).
 * TR_MOTION_PULSE: the paper's (seed 001 Sec. 2.2.2): the initial position, orientation and
 *   velocity, then the written linear acceleration and angular velocity histories integrated.
 *   Linear: the file's acceleration row k > 0 is the mean over [t_k-1, t_k] (stage 1 writes
 *   (v_k - v_k-1) / (t_k - t_k-1), stage1_mb/mb_sensor.c), row 0 is a(t_0). On each interval
 *   a(t) is the quadratic with the interval's mean and the edge values A_k (the means
 *   interpolated linearly to t_k between the intervals' midpoints; A_0 = a(t_0); at the end
 *   extrapolated): continuous, exact for a linear a(t), and the velocity it integrates to
 *   equals the written one at every sample (to round-off). Integrated exactly (position
 *   error O(h^4) on a smooth motion). Orientation: the written w (samples of the state) on
 *   each interval the cubic Hermite through w_i, w_i+1 with the slopes the same edge values
 *   give from the means (w_k - w_k-1) / h_k (the 3-point derivative; extrapolated at both
 *   ends), integrated by the Magnus series to its second term, theta = int w + 1/2 int int
 *   w(s) x w(u) du ds in closed form, then q = exp(theta) Q_i: exact for constant spin, 4th
 *   order. Angular velocity returned is d/dt of that orientation (it differs from the cubic w
 *   by the Magnus remainder). Nothing ties the integral to the written positions and orientations:
 *   it drifts; tr_motion_get_drift() gives the largest deviation from the written position,
 *   orientation and velocity.
 *
 * Errors (all exit-2 class): a file that is not HDF5 or is corrupt (MCS_ERR_IO/HDF5), without
 * /stage1 or /stage1/time, a time axis not strictly increasing, datasets of the wrong shape or
 * with NaN/Inf, a non-unit quaternion (MCS_ERR_FORMAT), a body missing (MCS_ERR_KEY), a time
 * outside the span (MCS_ERR_RANGE); the message names the file and the body. */
#ifndef TR_MOTION_H
#define TR_MOTION_H

#include "core/mcs_error.h"

typedef enum { TR_MOTION_POSE, TR_MOTION_PULSE } tr_motion_method;

typedef struct tr_motion tr_motion; /* the motion of some bodies of one file (read-only) */

/* one body's motion at one time, world frame */
typedef struct {
    double pos[3];    /* position [m]                                            */
    double quat[4];   /* orientation w, x, y, z, body -> world, unit [-]         */
    double rot[9];    /* the same as a rotation matrix, row-major [-]            */
    double vel[3];    /* velocity, d/dt pos [m/s]                                */
    double angvel[3]; /* angular velocity (world) [rad/s]                        */
    double acc[3];    /* acceleration, d/dt vel [m/s^2]                          */
    double angacc[3]; /* angular acceleration, d/dt angvel [rad/s^2]             */
} tr_motion_kin;

/* the pulse method's integral against the file at the file's samples (0 for pose) */
typedef struct {
    double pos;     /* largest |p - p_file| [m]                        */
    double angle;   /* largest rotation angle between q and q_file [rad] */
    double vel;     /* largest |v - v_file| [m/s]                      */
    double t_pos;   /* when the position's largest is reached [s]      */
    double t_angle; /* when the angle's [s]                            */
} tr_motion_drift;

/* "pose" | "pulse" -> method; MCS_ERR_KEY otherwise */
mcs_status tr_motion_method_parse(const char *name, tr_motion_method *out, mcs_error *err);
const char *tr_motion_method_name(tr_motion_method m);

/* read the bodies `names` (nbody of them; names NULL: every body of the file) of the stage-1
 * results file `path` for `method` */
mcs_status tr_motion_open(tr_motion **out, const char *path, const char *const *names, int nbody,
                          tr_motion_method method, mcs_error *err);
void tr_motion_destroy(tr_motion **m);

int tr_motion_nbody(const tr_motion *m);
const char *tr_motion_body_name(const tr_motion *m, int body);
int tr_motion_body(const tr_motion *m, const char *name); /* index, -1 when not read */
tr_motion_method tr_motion_get_method(const tr_motion *m);

/* the file's time span [s] and its number of samples */
void tr_motion_span(const tr_motion *m, double *t0, double *t_end, int *nt);
/* sample k's time [s] (0 <= k < nt) */
double tr_motion_time(const tr_motion *m, int k);

/* the motion of body (index) at t; MCS_ERR_RANGE when t is outside the span (a round-off
 * 1e-9 of the span beyond an end is taken as the end) */
mcs_status tr_motion_eval(const tr_motion *m, int body, double t, tr_motion_kin *k, mcs_error *err);

/* the drift of the pulse integral against the written motion (zeros for pose) */
tr_motion_drift tr_motion_get_drift(const tr_motion *m, int body);

/* rotation angle between two unit quaternions [rad], in [0, pi] */
double tr_quat_angle(const double a[4], const double b[4]);

#endif

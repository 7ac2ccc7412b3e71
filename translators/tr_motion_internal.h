/* tr_motion_internal.h: the layout of a tr_motion and its rotation helpers (tr_motion_*.c). */
#ifndef TR_MOTION_INTERNAL_H
#define TR_MOTION_INTERNAL_H

#include "translators/tr_motion.h"

typedef struct {
    char *name;            /* body name in the file                                    */
    double *pos;           /* written position [m] (nt x 3)                            */
    double *quat;          /* written orientation, unit, w x y z [-] (nt x 4)          */
    double *vel;           /* written velocity [m/s] (nt x 3)                          */
    double *angvel;        /* written angular velocity, world [rad/s] (nt x 3)         */
    double *acc;           /* written acceleration [m/s^2] (nt x 3), NULL for pose: row 0
                              a(t_0), row k > 0 the mean over [t_k-1, t_k]              */
    double *aedge;         /* pulse: acceleration at the samples (nt x 3) [m/s^2]      */
    double *wedge;         /* pulse: angular velocity's slope at the samples (nt x 3)
                              [rad/s^2]                                                 */
    double *ipos;          /* pulse: integrated position at the samples [m] (nt x 3)   */
    double *ivel;          /* pulse: integrated velocity at the samples [m/s] (nt x 3) */
    double *iquat;         /* pulse: integrated orientation at the samples (nt x 4)    */
    tr_motion_drift drift; /* pulse against the file                             */
} tr_motion_body_data;

struct tr_motion {
    char *path; /* the file read                                      */
    tr_motion_method method;
    int nt;    /* samples                                            */
    double *t; /* sample times, strictly increasing [s] (nt)         */
    int nbody;
    tr_motion_body_data *body; /* (nbody)                                            */
};

/* ---- tr_motion_so3.c ---- */
void tr_q_mul(const double a[4], const double b[4], double out[4]); /* out = a b        */
void tr_q_exp(const double th[3], double q[4]); /* rotation vector -> unit quaternion   */
void tr_q_log(const double q[4], double th[3]); /* the shortest rotation vector of q   */
void tr_q_to_rot(const double q[4], double R[9]);
/* w = J(th) thd and al = d/dt (J(th) thd) = J thdd + (dJ/dt) thd: the world angular velocity
 * and acceleration of exp(th(t)) q0 from the rotation vector and its derivatives */
void tr_so3_rates(const double th[3], const double thd[3], const double thdd[3], double w[3],
                  double al[3]);
/* thd = J(th)^-1 w (|th| < 2 pi) */
void tr_so3_jinv(const double th[3], const double w[3], double thd[3]);
/* cubic Hermite on [0, h] at s = tau / h: value, first and second derivative in tau */
void tr_hermite3(const double x0[3], const double m0[3], const double x1[3], const double m1[3],
                 double h, double s, double x[3], double xd[3], double xdd[3]);

/* ---- tr_motion_curve.c ---- */
void tr_motion_pose_eval(const struct tr_motion *m, const tr_motion_body_data *b, int i, double t,
                         tr_motion_kin *k);
void tr_motion_pulse_eval(const struct tr_motion *m, const tr_motion_body_data *b, int i, double t,
                          tr_motion_kin *k);
/* the pulse integral at the samples (b->ipos, ivel, iquat) and its drift */
void tr_motion_pulse_integrate(const struct tr_motion *m, tr_motion_body_data *b);

#endif

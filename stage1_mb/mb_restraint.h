/* mb_restraint.h: joint restraints and breakable attachments of stage 1 (issue 4 item 2).
 *
 * Joint restraint (revolute: torque vs. angle; translational: force vs. displacement):
 *   q = x - neutral, the deflection from the characteristic's zero [rad | m];
 *   load on the child = -(preload + F_h(q) + damping * rate + stop(q, rate)), the parent gets
 *   the opposite (a preloaded spring held by its top-out: docs/joints.md);
 *   F_h is the two-branch hysteresis element of core (loading/unloading per direction, permanent
 *   set: the deforming fork), stop() a stiff one-sided spring-damper beyond [lo, hi] that
 *   never pulls back.
 * Attachment (MYMOSA's rider pelvis-seat, hands-grips, feet-pegs): a linear spring-damper between
 *   a point of body a and a point of body b (or the world) of free length L (0: an isotropic
 *   spring k d; L > 0: k (|d| - L) along d), isotropic damper; it breaks for good the first
 *   step its force exceeds fail_force.
 * Each is applied once per step, before mb_world_step; energies are tracked for the balance. */
#ifndef MB_RESTRAINT_H
#define MB_RESTRAINT_H

#include "core/mcs_hysteresis.h"
#include "stage1_mb/mb_ode.h"

typedef struct {
    int joint;              /* mb_ode joint index (revolute or translational)                 */
    int has_spring;         /* 0: no characteristic (damping and stops only)                   */
    mcs_hyst2_model spring; /* restoring load vs. deflection per direction [N m | N]           */
    double damping;         /* viscous [N m s/rad | N s/m], >= 0                               */
    double neutral;         /* joint position where the spring is unloaded [rad | m]           */
    double lo, hi;          /* range of the joint position; beyond it the stop acts [rad | m]  */
    double stop_stiffness;  /* stop spring [N m/rad | N/m], 0 = no stops                       */
    double stop_damping;    /* stop damper, acts only while in the stop [N m s/rad | N s/m]    */
    double preload;         /* constant load added to F_h (needs has_spring) [N m | N]         */
} mb_restraint_model;

typedef struct {
    mcs_hyst2_state h; /* history of the characteristic                                     */
    double x;          /* joint position at the last apply [rad | m]                        */
    double rate;       /* joint rate there [rad/s | m/s]                                    */
    double load;       /* load applied to the child there [N m | N]                         */
    double e_damp;     /* energy dissipated by damping and stop damping [J]                 */
} mb_restraint_state;

mcs_status mb_restraint_check(const mb_restraint_model *m, const mb_world *w, const char *name,
                              mcs_error *err);
void mb_restraint_reset(const mb_restraint_model *m, mb_restraint_state *s);
/* read the joint, advance the history, add the load for the next step of h seconds */
void mb_restraint_apply(const mb_restraint_model *m, mb_restraint_state *s, mb_world *w, double h);
/* the characteristic's load at joint position x on the history s->h, committed (s->h, s->x);
 * without the damper and the stop [N m | N] */
double mb_restraint_spring(const mb_restraint_model *m, mb_restraint_state *s, double x);
double mb_restraint_stored(const mb_restraint_model *m, const mb_restraint_state *s);     /* J */
double mb_restraint_dissipated(const mb_restraint_model *m, const mb_restraint_state *s); /* J */

typedef struct {
    int body_a;        /* body index                                                    */
    int body_b;        /* body index, or -1 for the world                               */
    double pa[3];      /* point on a, a's body frame relative to its CG [m]             */
    double pb[3];      /* point on b, b's body frame (world coordinates if b = -1) [m]  */
    double stiffness;  /* isotropic spring [N/m], > 0                                   */
    double damping;    /* isotropic damper [N s/m], >= 0                                */
    double fail_force; /* breaks when |force| exceeds it [N], > 0; INFINITY = never     */
    double length;     /* free length [m], >= 0: the spring acts on |b - a| - length     */
} mb_attach_model;

typedef struct {
    int broken;        /* 1 once failed (permanent)                                     */
    double t_break;    /* simulated time of failure [s], NAN while intact               */
    double force[3];   /* force on a at the last apply, world [N]                       */
    double stretch[3]; /* point b - point a there, world [m]                            */
    double e_damp;     /* energy dissipated by the damper [J]                           */
    double e_lost;     /* spring energy released when it broke [J]                      */
} mb_attach_state;

mcs_status mb_attach_check(const mb_attach_model *m, const mb_world *w, const char *name,
                           mcs_error *err);
void mb_attach_reset(const mb_attach_model *m, mb_attach_state *s);
void mb_attach_apply(const mb_attach_model *m, mb_attach_state *s, mb_world *w, double h);
double mb_attach_stored(const mb_attach_model *m, const mb_attach_state *s); /* J */

#endif

/* fe_joint: kinematic joints between rigid bodies (LS-DYNA *CONSTRAINED_JOINT_*), nodal rigid
 * bodies (*CONSTRAINED_NODAL_RIGID_BODY) and extra nodes of rigid parts
 * (*CONSTRAINED_EXTRA_NODES) in the explicit FE kernel.
 *
 * A joint holds body A to body B (or to the ground) at a point p and an axis a, both given at
 * t = 0 and carried by each body from then on (P_A = x_A + R_A r_A, a_A = R_A a, same for B):
 *   spherical      P_A = P_B                          free: 3 rotations
 *   revolute       P_A = P_B, a_A || a_B               free: the angle about a
 *   cylindrical    (P_A - P_B) x a_B = 0, a_A || a_B    free: the slide along a and the angle
 *   translational  (P_A - P_B) x a_B = 0, R_A R_B^T = 1  free: the slide along a
 * Scheme: penalty (as LS-DYNA's default joints). Each step, from the positions at t and the
 * velocities at t - dt/2, the constraint error e (a vector: the gap of the points, or the
 * misalignment a_B x a_A, or the rotation vector of R_A R_B^T) gives a force F = -k e - c e'
 * applied at P_A on A and -F at the same point on B (so linear and angular momentum are kept
 * exactly), and a moment M = -k_r e_r - c_r e_r' on A, -M on B. The stiffnesses are scaled to
 * the bodies and to the model's step dt0 (fe_model.dt_initial):
 *   k = s / (dt0^2 (lambda_A + lambda_B)),  lambda = 1/M + |r|^2 max eig(I^-1)
 * (lambda: the largest compliance of a body at the joint point; held dofs count 0), k_r the
 * same with lambda_r = max eig(I^-1): with the penalty scale s = 0.1 each constraint term
 * alone has k dt^2 / m_eff <= 0.1, a fortieth of central differences' limit 4, so a body can
 * carry many joints and stay stable; c = 2 zeta sqrt(k m_eff) with zeta = 0.1 damps the
 * penalty's own vibration. The error under a load F is F / k, of order F dt^2 / m: micrometres
 * for the loads and steps of a crash (docs/fe.md "Joints").
 * The free coordinate q (the slide [m] or the angle [rad], unwrapped past +-pi) carries the
 * joint's own spring and damper (stiffness, damping: *CONSTRAINED_JOINT_STIFFNESS) and elastic
 * stops beyond [range_min, range_max] (penalty k or k_r).
 * Energies: the penalty and the spring and stops store elastic energy (internal), the dampers
 * dissipate (dissipated), both in the model's free energies (fe_state.free_energy). */
#ifndef FE_JOINT_H
#define FE_JOINT_H

#include "fe/fe_model.h"
#include "fe/fe_state.h"

typedef enum {
    FE_JOINT_SPHERICAL,
    FE_JOINT_REVOLUTE,
    FE_JOINT_CYLINDRICAL,
    FE_JOINT_TRANSLATIONAL
} fe_joint_type;

extern const char *const fe_joint_type_name[4]; /* "spherical", "revolute", ... */

typedef struct {
    char name[FE_NAME_MAX]; /* joint name (results: /stage3/joints/<name>)          */
    fe_joint_type type;
    char body[2][FE_NAME_MAX]; /* rigid parts or nodal rigid bodies A, B; B "": ground  */
    int node[6];               /* node[0] >= 0: LS-DYNA's node pairs define the joint:
                                  N1 (on A) N2 (on B) at the point, N3 N4 on the axis,
                                  (translational) N5 N6; the bodies are the nodes'; else
                                  -1 and body, point, axis [-]                         */
    double point[3];           /* joint point at t = 0 [m]                              */
    double axis[3];            /* joint axis at t = 0 (normalised at build) [-]         */
    double stiffness;          /* on the free coordinate: N/m (slide) or N m/rad [..]   */
    double damping;            /* N s/m or N m s/rad [..]                               */
    int has_range;             /* 1: stops at range [-]                                 */
    double range[2];           /* free coordinate's stops, from its t = 0 value [m|rad] */
    double penalty_scale;      /* s above; 0 takes 0.1 [-]                              */
    const char *file;          /* where it was given, for messages (may be NULL)      */
    int line, col;
} fe_joint_desc;

/* a joint of the frozen model */
typedef struct fe_joint {
    char name[FE_NAME_MAX];
    fe_joint_type type;
    int body[2];             /* bodies A, B; B -1: the ground [-]                              */
    double r[2][3];          /* joint point about each body's centre of mass, t = 0 axes
                                (ground: the point itself) [m]                                  */
    double axis[3], perp[3]; /* unit axis and a unit normal to it, t = 0 axes [-]              */
    double k, c;             /* point penalty [N/m], its damping [N s/m]                        */
    double kr, cr;           /* rotation penalty [N m/rad], its damping [N m s/rad]             */
    double ks, cs;           /* free coordinate's spring and damper [N/m | N m/rad, ..]        */
    int has_range;
    double range[2]; /* [m | rad]                                                       */
    double kstop;    /* stop stiffness: k (slide) or kr (angle) [..]                   */
    double scale;    /* the penalty scale s [-]                                         */
} fe_joint;

/* joint loads at t, per joint (state joint_out) */
enum {
    FE_JOUT_FORCE = 0,  /* force of B on A at the joint, world axes (3) [N]             */
    FE_JOUT_MOMENT = 3, /* moment of B on A about the joint point (3) [N m]             */
    FE_JOUT_SLIDE = 6,  /* slide of A along the axis from t = 0 [m]                     */
    FE_JOUT_ANGLE = 7,  /* angle of A about the axis relative to B, unwrapped [rad]     */
    FE_JOUT_EEL = 8,    /* elastic energy stored now [J]                                */
    FE_JOUT_EDISS = 9,  /* energy dissipated by its dampers so far [J]                  */
    FE_JOUT_N = 10
};

/* builder side: joints, nodal rigid bodies, extra nodes (kept until fe_model_create) */
mcs_status fe_builder_add_joint(fe_builder *b, const fe_joint_desc *d, mcs_error *err);
/* nodes (n >= 1 indices) of deformable parts that move as one rigid body named `name` */
mcs_status fe_builder_add_nodal_rigid_body(fe_builder *b, const char *name, const int *nodes, int n,
                                           mcs_error *err);
/* nodes carried by rigid part `part` (their masses join the body) */
mcs_status fe_builder_add_extra_nodes(fe_builder *b, const char *part, const int *nodes, int n,
                                      mcs_error *err);
fe_joint_desc fe_joint_desc_default(void);

/* model side (fe_model_create, fe_rigid_build, fe_solid_free) */
/* nodal rigid bodies and extra nodes into m->node_body: extra nodes take their part's body,
 * each nodal rigid body a body numbered from *nb on (names in names, FE_NAME_MAX each, room
 * for cap) */
mcs_status fe_nrb_assign(const fe_builder *b, fe_model *m, int *nb, char (*names)[FE_NAME_MAX],
                         int cap, mcs_error *err);
int fe_nrb_count(const fe_builder *b);
/* the joints, after the step dt_initial is known */
mcs_status fe_joints_build(const fe_builder *b, fe_model *m, mcs_error *err);
void fe_joint_list_free(fe_builder *b);
/* index of a body by name (rigid part or nodal rigid body), -1 none */
int fe_body_find(const fe_model *m, const char *name);
/* a body's name */
const char *fe_body_name(const fe_model *m, int b);

/* time loop: joint loads on the bodies (body_fj), outputs and energies (fe_internal_forces) */
void fe_joint_forces(const fe_model *m, fe_state *s);

#endif

/* mb_ode.h: a thin, checked wrapper around the ODE world for stage 1 (ODE types stay inside
 * mb_ode.c, STYLE.md section 6). Bodies and joints are addressed by index; every ODE call that
 * can fail is checked; ODE's message, debug and error handlers are routed to mcs_log. SI units.
 * Contact forces are not ODE contacts: callers apply them with mb_body_add_force_at_pos. */
#ifndef MB_ODE_H
#define MB_ODE_H

#include "core/mcs_error.h"

/* once per process (reference counted): dInitODE2, handlers, and the double-precision check.
 * mb_world_create calls it; call it yourself only to use ODE without a world. */
mcs_status mb_ode_init(mcs_error *err);
void mb_ode_close(void);           /* dCloseODE when the last user closes */
int mb_ode_double_precision(void); /* 1 when ODE was built with ODE_double_precision */
long mb_ode_message_count(void);   /* ODE warnings (dMessage) logged so far, this thread */

typedef struct mb_world mb_world; /* an ODE world with its bodies and joints (opaque) */

/* a rigid body to add */
typedef struct {
    const char *name;  /* for messages (copied, up to 63 characters)                         */
    double mass;       /* [kg] > 0                                                           */
    double inertia[6]; /* about the CG in body axes: Ixx Iyy Izz Ixy Ixz Iyz [kg m^2]; the
                          products are the tensor entries (I_xy = -sum m x y)               */
    double pos[3];     /* CG position, world [m]                                             */
    double quat[4];    /* orientation body -> world, w x y z (normalised on add); 0 = identity */
    double vel[3];     /* CG velocity, world [m/s]                                           */
    double angvel[3];  /* angular velocity, world [rad/s]                                    */
} mb_body_desc;

/* a body's kinematic state */
typedef struct {
    double pos[3];    /* CG, world [m]                      */
    double quat[4];   /* body -> world, w x y z             */
    double rot[9];    /* body -> world rotation, row-major  */
    double vel[3];    /* CG velocity, world [m/s]           */
    double angvel[3]; /* angular velocity, world [rad/s]    */
} mb_body_kin;

mcs_status mb_world_create(mb_world **out, int max_bodies, int max_joints, const double gravity[3],
                           mcs_error *err);
void mb_world_destroy(mb_world **w);

/* returns the body index (>= 0) or -1 with err set (bad mass/inertia, too many bodies) */
int mb_world_add_body(mb_world *w, const mb_body_desc *d, mcs_error *err);
int mb_world_nbody(const mb_world *w);
int mb_world_njoint(const mb_world *w);
double mb_world_time(const mb_world *w); /* simulated time [s] */
long mb_world_steps(const mb_world *w);  /* dWorldStep calls made */

/* loads for the next step (ODE clears them after every step) */
void mb_body_add_force_at_pos(mb_world *w, int b, const double f[3], const double p[3]);
void mb_body_add_force(mb_world *w, int b, const double f[3]);  /* at the CG [N] */
void mb_body_add_torque(mb_world *w, int b, const double t[3]); /* world [N m]   */

void mb_body_get(const mb_world *w, int b, mb_body_kin *out);
/* prescribed (kinematic) bodies, mb_prescribe.h: infinite mass, moved by their velocity in
 * the step, not by forces; the pose and velocities set here */
void mb_body_set_kinematic(mb_world *w, int b);
void mb_body_set_state(mb_world *w, int b, const double pos[3], const double quat[4],
                       const double vel[3], const double angvel[3]);
/* force [N] and torque about the CG [N m] added for the next step so far (world) */
void mb_body_get_load(const mb_world *w, int b, double force[3], double torque[3]);
void mb_body_point_vel(const mb_world *w, int b, const double p[3], double out[3]);
const char *mb_body_name(const mb_world *w, int b);

/* mechanical energy of the bodies [J]: kinetic sum(m v^2/2 + w.I_w w/2) and gravitational
 * potential -sum(m g.x) (zero at the world origin) */
double mb_world_kinetic_energy(const mb_world *w);
double mb_world_potential_energy(const mb_world *w);
double mb_body_mass(const mb_world *w, int b); /* [kg] */

/* one dWorldStep of h seconds; MCS_ERR_NUMERIC when ODE fails or a body becomes non-finite
 * (the message names the body and the time) */
mcs_status mb_world_step(mb_world *w, double h, mcs_error *err);

/* joints between parent and child (parent -1 = the world); anchor and axes in world [m], unit.
 * Each returns the joint index (>= 0) or -1 with err set. */
int mb_joint_revolute(mb_world *w, int parent, int child, const double anchor[3],
                      const double axis[3], mcs_error *err);
int mb_joint_spherical(mb_world *w, int parent, int child, const double anchor[3], mcs_error *err);
int mb_joint_universal(mb_world *w, int parent, int child, const double anchor[3],
                       const double axis1[3], const double axis2[3], mcs_error *err);
int mb_joint_translational(mb_world *w, int parent, int child, const double axis[3],
                           mcs_error *err);
int mb_joint_fixed(mb_world *w, int parent, int child, mcs_error *err);

/* revolute: angle [rad] and rate [rad/s] of child relative to parent about the axis, zero at
 * creation; translational: position [m] and rate [m/s] along the axis */
double mb_joint_position(const mb_world *w, int j);
double mb_joint_rate(const mb_world *w, int j);
/* the bodies a joint connects (parent -1 = the world) */
void mb_joint_bodies(const mb_world *w, int j, int *parent, int *child);
/* 1 for spherical and universal joints (restrained by mb_restraint3) */
int mb_joint_is_spherical(const mb_world *w, int j);

/* a generalised load on a revolute (torque about the axis [N m]) or translational (force along
 * the axis [N]) joint for the next step: +load on the child, -load on the parent. Returns 0, or
 * -1 for other joint types. */
int mb_joint_add_load(mb_world *w, int j, double load);
/* the joint's axis in world (revolute, translational); 0 vector for other types */
void mb_joint_axis(const mb_world *w, int j, double axis[3]);

/* constraint force and torque the joint applied to the child at the last step, world [N, N m]
 * (torque about the child's CG) */
void mb_joint_reaction(const mb_world *w, int j, double force[3], double torque[3]);
/* the same on the parent (torque about the parent's CG); zero when the parent is the world */
void mb_joint_reaction_parent(const mb_world *w, int j, double force[3], double torque[3]);

#endif

/* mb_ode: the checked ODE wrapper of stage 1 (see mb_ode.h). */
#include "stage1_mb/mb_ode.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <ode/ode.h>

/* ---- process-wide initialisation and ODE's handlers ------------------------------------------ */

static pthread_mutex_t ode_lock = PTHREAD_MUTEX_INITIALIZER;
static int ode_users; /* reference count of mb_ode_init calls */
static _Thread_local long ode_messages;

/* ODE warnings (e.g. "LCP internal error"): logged and counted, the step carries on */
static void ode_message(int num, const char *msg, va_list ap)
{
    char buf[512];
    vsnprintf(buf, sizeof buf, msg, ap);
    ode_messages++;
    mcs_log(MCS_LOG_WARN, "ODE message %d: %s", num, buf);
}

/* ODE errors and debug traps are failed internal assertions and must not return (ode/error.h):
 * log them, then abort as for any violated assertion */
static void ode_fatal(int num, const char *msg, va_list ap)
{
    char buf[512];
    vsnprintf(buf, sizeof buf, msg, ap);
    mcs_log(MCS_LOG_ERROR, "ODE internal error %d: %s", num, buf);
    abort();
}

mcs_status mb_ode_init(mcs_error *err)
{
    mcs_status st = MCS_OK;
    pthread_mutex_lock(&ode_lock);
    if (ode_users == 0) {
        dSetMessageHandler(ode_message);
        dSetErrorHandler(ode_fatal);
        dSetDebugHandler(ode_fatal);
        if (!dInitODE2(0))
            st = MCS_ERR(err, MCS_ERR_NUMERIC, "ODE: dInitODE2 failed");
        else if (!dCheckConfiguration("ODE_double_precision")) {
            dCloseODE();
            st = MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                         "ODE: library is not double precision (configuration: %s)",
                         dGetConfiguration());
        }
    }
    if (st == MCS_OK) ode_users++;
    pthread_mutex_unlock(&ode_lock);
    if (st == MCS_OK && !dAllocateODEDataForThread(dAllocateMaskAll)) {
        mb_ode_close();
        return MCS_ERR(err, MCS_ERR_NOMEM, "ODE: dAllocateODEDataForThread failed");
    }
    return st;
}

void mb_ode_close(void)
{
    pthread_mutex_lock(&ode_lock);
    if (ode_users > 0 && --ode_users == 0) dCloseODE();
    pthread_mutex_unlock(&ode_lock);
}

int mb_ode_double_precision(void)
{
    return dCheckConfiguration("ODE_double_precision") && sizeof(dReal) == sizeof(double);
}

long mb_ode_message_count(void)
{
    return ode_messages;
}

/* ---- world ------------------------------------------------------------------------------------
 */

typedef enum { J_REVOLUTE, J_SPHERICAL, J_UNIVERSAL, J_TRANSLATIONAL, J_FIXED } joint_type;

struct mb_world {
    dWorldID world;
    int nbody, max_bodies, njoint, max_joints;
    dBodyID *body;            /* (max_bodies)  */
    char (*body_name)[64];    /* (max_bodies)  */
    dJointID *joint;          /* (max_joints)  */
    int *joint_type;          /* joint_type (max_joints) */
    int (*joint_bodies)[2];   /* parent (-1 = world), child (max_joints) */
    dJointFeedback *joint_fb; /* reactions (max_joints) */
    double time;              /* simulated time [s] */
    long steps;               /* dWorldStep calls */
};

mcs_status mb_world_create(mb_world **out, int max_bodies, int max_joints, const double gravity[3],
                           mcs_error *err)
{
    *out = NULL;
    if (max_bodies < 1 || max_joints < 0)
        return MCS_ERR(err, MCS_ERR_RANGE, "world: max_bodies %d, max_joints %d", max_bodies,
                       max_joints);
    mcs_status st = mb_ode_init(err);
    if (st != MCS_OK) return st;
    mb_world *w = calloc(1, sizeof *w);
    if (w) {
        w->body = calloc((size_t)max_bodies, sizeof *w->body);
        w->body_name = calloc((size_t)max_bodies, sizeof *w->body_name);
        w->joint = calloc((size_t)max_joints + 1, sizeof *w->joint);
        w->joint_type = calloc((size_t)max_joints + 1, sizeof *w->joint_type);
        w->joint_bodies = calloc((size_t)max_joints + 1, sizeof *w->joint_bodies);
        w->joint_fb = calloc((size_t)max_joints + 1, sizeof *w->joint_fb);
        w->world = dWorldCreate();
    }
    if (!w || !w->body || !w->body_name || !w->joint || !w->joint_type || !w->joint_bodies ||
        !w->joint_fb || !w->world) {
        if (w) {
            w->max_bodies = max_bodies; /* so destroy can free what exists */
            mb_world_destroy(&w);
        } else {
            mb_ode_close();
        }
        return MCS_ERR(err, MCS_ERR_NOMEM, "world: out of memory");
    }
    w->max_bodies = max_bodies, w->max_joints = max_joints;
    dWorldSetGravity(w->world, gravity[0], gravity[1], gravity[2]);
    /* crash loads are our forces: no ODE auto-disable, no damping, no contact softness */
    dWorldSetAutoDisableFlag(w->world, 0);
    dWorldSetLinearDamping(w->world, 0);
    dWorldSetAngularDamping(w->world, 0);
    *out = w;
    return MCS_OK;
}

void mb_world_destroy(mb_world **pw)
{
    if (!pw || !*pw) return;
    mb_world *w = *pw;
    if (w->world) dWorldDestroy(w->world); /* destroys its bodies and joints */
    free(w->body), free(w->body_name), free(w->joint), free(w->joint_type), free(w->joint_fb);
    free(w->joint_bodies);
    free(w);
    *pw = NULL;
    mb_ode_close();
}

int mb_world_nbody(const mb_world *w)
{
    return w->nbody;
}
int mb_world_njoint(const mb_world *w)
{
    return w->njoint;
}
double mb_world_time(const mb_world *w)
{
    return w->time;
}
long mb_world_steps(const mb_world *w)
{
    return w->steps;
}
const char *mb_body_name(const mb_world *w, int b)
{
    return w->body_name[b];
}

/* inertia tensor must be symmetric positive definite with the triangle inequalities of a
 * physical mass distribution (I1 + I2 >= I3 for the principal moments) */
static int inertia_ok(const double I[6])
{
    double a = I[0], b = I[1], c = I[2], xy = I[3], xz = I[4], yz = I[5];
    double m2 = a * b - xy * xy;
    double det = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz);
    if (!(a > 0 && m2 > 0 && det > 0)) return 0;
    /* principal moments from the characteristic polynomial (trigonometric form) */
    double p1 = xy * xy + xz * xz + yz * yz, q = (a + b + c) / 3;
    double p2 = (a - q) * (a - q) + (b - q) * (b - q) + (c - q) * (c - q) + 2 * p1;
    double p = sqrt(p2 / 6);
    double e[3] = {a, b, c};
    if (p > 1e-15 * q) {
        double B[6] = {(a - q) / p, (b - q) / p, (c - q) / p, xy / p, xz / p, yz / p};
        double r = 0.5 * (B[0] * (B[1] * B[2] - B[5] * B[5]) - B[3] * (B[3] * B[2] - B[5] * B[4]) +
                          B[4] * (B[3] * B[5] - B[1] * B[4]));
        double phi = r <= -1 ? M_PI / 3 : r >= 1 ? 0 : acos(r) / 3;
        e[0] = q + 2 * p * cos(phi);
        e[2] = q + 2 * p * cos(phi + 2 * M_PI / 3);
        e[1] = 3 * q - e[0] - e[2];
    }
    double tol = 1e-9 * (e[0] + e[1] + e[2]);
    return e[0] <= e[1] + e[2] + tol && e[1] <= e[0] + e[2] + tol && e[2] <= e[0] + e[1] + tol;
}

static int all_finite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

int mb_world_add_body(mb_world *w, const mb_body_desc *d, mcs_error *err)
{
    const char *name = d->name ? d->name : "(unnamed)";
    if (w->nbody >= w->max_bodies) {
        MCS_ERR(err, MCS_ERR_RANGE, "body %s: more than %d bodies", name, w->max_bodies);
        return -1;
    }
    if (!(d->mass > 0) || !isfinite(d->mass)) {
        MCS_ERR(err, MCS_ERR_RANGE, "body %s: mass %g kg must be positive", name, d->mass);
        return -1;
    }
    if (!all_finite(d->inertia, 6) || !inertia_ok(d->inertia)) {
        MCS_ERR(err, MCS_ERR_RANGE,
                "body %s: inertia [%g %g %g %g %g %g] kg m^2 is not a physical inertia tensor "
                "(positive definite, principal moments obeying I1 + I2 >= I3)",
                name, d->inertia[0], d->inertia[1], d->inertia[2], d->inertia[3], d->inertia[4],
                d->inertia[5]);
        return -1;
    }
    if (!all_finite(d->pos, 3) || !all_finite(d->quat, 4) || !all_finite(d->vel, 3) ||
        !all_finite(d->angvel, 3)) {
        MCS_ERR(err, MCS_ERR_RANGE, "body %s: non-finite initial state", name);
        return -1;
    }
    double q[4];
    mb_quat_unit(d->quat, q);
    dBodyID b = dBodyCreate(w->world);
    dMass m;
    dMassSetZero(&m);
    /* ODE takes the tensor entries: I12 = Ixy etc. */
    dMassSetParameters(&m, d->mass, 0, 0, 0, d->inertia[0], d->inertia[1], d->inertia[2],
                       d->inertia[3], d->inertia[4], d->inertia[5]);
    dBodySetMass(b, &m);
    dBodySetPosition(b, d->pos[0], d->pos[1], d->pos[2]);
    dQuaternion dq = {q[0], q[1], q[2], q[3]};
    dBodySetQuaternion(b, dq);
    dBodySetLinearVel(b, d->vel[0], d->vel[1], d->vel[2]);
    dBodySetAngularVel(b, d->angvel[0], d->angvel[1], d->angvel[2]);
    int i = w->nbody++;
    w->body[i] = b;
    snprintf(w->body_name[i], sizeof w->body_name[i], "%s", name);
    return i;
}

void mb_body_add_force_at_pos(mb_world *w, int b, const double f[3], const double p[3])
{
    dBodyAddForceAtPos(w->body[b], f[0], f[1], f[2], p[0], p[1], p[2]);
}

void mb_body_add_force(mb_world *w, int b, const double f[3])
{
    dBodyAddForce(w->body[b], f[0], f[1], f[2]);
}

void mb_body_add_torque(mb_world *w, int b, const double t[3])
{
    dBodyAddTorque(w->body[b], t[0], t[1], t[2]);
}

void mb_body_get(const mb_world *w, int b, mb_body_kin *out)
{
    dBodyID id = w->body[b];
    const dReal *p = dBodyGetPosition(id), *q = dBodyGetQuaternion(id), *R = dBodyGetRotation(id);
    const dReal *v = dBodyGetLinearVel(id), *om = dBodyGetAngularVel(id);
    for (int k = 0; k < 3; k++)
        out->pos[k] = p[k], out->vel[k] = v[k], out->angvel[k] = om[k];
    for (int k = 0; k < 4; k++)
        out->quat[k] = q[k];
    /* ODE's dMatrix3 is 3x4 row-major (padding column) */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out->rot[3 * i + j] = R[4 * i + j];
}

void mb_body_set_kinematic(mb_world *w, int b)
{
    dBodySetKinematic(w->body[b]);
}

void mb_body_set_state(mb_world *w, int b, const double pos[3], const double quat[4],
                       const double vel[3], const double angvel[3])
{
    dBodyID id = w->body[b];
    double q[4];
    mb_quat_unit(quat, q);
    dQuaternion dq = {q[0], q[1], q[2], q[3]};
    dBodySetPosition(id, pos[0], pos[1], pos[2]);
    dBodySetQuaternion(id, dq);
    dBodySetLinearVel(id, vel[0], vel[1], vel[2]);
    dBodySetAngularVel(id, angvel[0], angvel[1], angvel[2]);
}

void mb_body_get_load(const mb_world *w, int b, double force[3], double torque[3])
{
    const dReal *f = dBodyGetForce(w->body[b]), *t = dBodyGetTorque(w->body[b]);
    for (int k = 0; k < 3; k++)
        force[k] = f[k], torque[k] = t[k];
}

void mb_body_point_vel(const mb_world *w, int b, const double p[3], double out[3])
{
    dVector3 v;
    dBodyGetPointVel(w->body[b], p[0], p[1], p[2], v);
    out[0] = v[0], out[1] = v[1], out[2] = v[2];
}

/* a body whose state went non-finite, or -1 */
static int first_nonfinite(const mb_world *w)
{
    for (int i = 0; i < w->nbody; i++) {
        mb_body_kin k;
        mb_body_get(w, i, &k);
        if (!all_finite(k.pos, 3) || !all_finite(k.vel, 3) || !all_finite(k.angvel, 3) ||
            !all_finite(k.quat, 4))
            return i;
    }
    return -1;
}

mcs_status mb_world_step(mb_world *w, double h, mcs_error *err)
{
    if (!(h > 0) || !isfinite(h))
        return MCS_ERR(err, MCS_ERR_RANGE, "world step: time step %g s must be positive", h);
    if (!dWorldStep(w->world, h))
        return MCS_ERR(err, MCS_ERR_NUMERIC, "ODE dWorldStep failed at t = %.9g s (out of memory)",
                       w->time);
    w->time += h;
    w->steps++;
    int bad = first_nonfinite(w);
    if (bad >= 0)
        return MCS_ERR(err, MCS_ERR_NUMERIC, "body %s: state not finite at t = %.9g s",
                       w->body_name[bad], w->time);
    return MCS_OK;
}

/* ---- joints ------------------------------------------------------------------------------------
 */

/* check indices and room; attach child as ODE body 1 and parent (or the world) as body 2 */
static int joint_begin(mb_world *w, int parent, int child, const char *what, mcs_error *err)
{
    if (w->njoint >= w->max_joints) {
        MCS_ERR(err, MCS_ERR_RANGE, "%s joint: more than %d joints", what, w->max_joints);
        return -1;
    }
    if (child < 0 || child >= w->nbody || parent < -1 || parent >= w->nbody || parent == child) {
        MCS_ERR(err, MCS_ERR_RANGE, "%s joint: bad bodies parent %d, child %d (%d bodies)", what,
                parent, child, w->nbody);
        return -1;
    }
    return w->njoint;
}

static int joint_end(mb_world *w, dJointID j, int type, int parent, int child)
{
    int i = w->njoint++;
    dJointAttach(j, w->body[child], parent >= 0 ? w->body[parent] : 0);
    dJointSetFeedback(j, &w->joint_fb[i]);
    w->joint[i] = j;
    w->joint_type[i] = type;
    w->joint_bodies[i][0] = parent, w->joint_bodies[i][1] = child;
    return i;
}

static int unit_ok(const double a[3], const char *what, mcs_error *err)
{
    double l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!(fabs(l - 1) < 1e-6)) {
        MCS_ERR(err, MCS_ERR_RANGE, "%s joint: axis [%g %g %g] is not a unit vector", what, a[0],
                a[1], a[2]);
        return 0;
    }
    return 1;
}

int mb_joint_revolute(mb_world *w, int parent, int child, const double anchor[3],
                      const double axis[3], mcs_error *err)
{
    if (joint_begin(w, parent, child, "revolute", err) < 0 || !unit_ok(axis, "revolute", err))
        return -1;
    dJointID j = dJointCreateHinge(w->world, 0);
    int i = joint_end(w, j, J_REVOLUTE, parent, child);
    dJointSetHingeAnchor(j, anchor[0], anchor[1], anchor[2]);
    dJointSetHingeAxis(j, axis[0], axis[1], axis[2]);
    return i;
}

int mb_joint_spherical(mb_world *w, int parent, int child, const double anchor[3], mcs_error *err)
{
    if (joint_begin(w, parent, child, "spherical", err) < 0) return -1;
    dJointID j = dJointCreateBall(w->world, 0);
    int i = joint_end(w, j, J_SPHERICAL, parent, child);
    dJointSetBallAnchor(j, anchor[0], anchor[1], anchor[2]);
    return i;
}

int mb_joint_universal(mb_world *w, int parent, int child, const double anchor[3],
                       const double axis1[3], const double axis2[3], mcs_error *err)
{
    if (joint_begin(w, parent, child, "universal", err) < 0 || !unit_ok(axis1, "universal", err) ||
        !unit_ok(axis2, "universal", err))
        return -1;
    if (fabs(axis1[0] * axis2[0] + axis1[1] * axis2[1] + axis1[2] * axis2[2]) > 1e-6) {
        MCS_ERR(err, MCS_ERR_RANGE, "universal joint: axes are not perpendicular");
        return -1;
    }
    dJointID j = dJointCreateUniversal(w->world, 0);
    int i = joint_end(w, j, J_UNIVERSAL, parent, child);
    dJointSetUniversalAnchor(j, anchor[0], anchor[1], anchor[2]);
    dJointSetUniversalAxis1(j, axis1[0], axis1[1], axis1[2]);
    dJointSetUniversalAxis2(j, axis2[0], axis2[1], axis2[2]);
    return i;
}

int mb_joint_translational(mb_world *w, int parent, int child, const double axis[3], mcs_error *err)
{
    if (joint_begin(w, parent, child, "translational", err) < 0 ||
        !unit_ok(axis, "translational", err))
        return -1;
    dJointID j = dJointCreateSlider(w->world, 0);
    int i = joint_end(w, j, J_TRANSLATIONAL, parent, child);
    dJointSetSliderAxis(j, axis[0], axis[1], axis[2]);
    return i;
}

int mb_joint_fixed(mb_world *w, int parent, int child, mcs_error *err)
{
    if (joint_begin(w, parent, child, "fixed", err) < 0) return -1;
    dJointID j = dJointCreateFixed(w->world, 0);
    int i = joint_end(w, j, J_FIXED, parent, child);
    dJointSetFixed(j);
    return i;
}

double mb_joint_position(const mb_world *w, int j)
{
    switch (w->joint_type[j]) {
    case J_REVOLUTE:
        return dJointGetHingeAngle(w->joint[j]);
    case J_TRANSLATIONAL:
        return dJointGetSliderPosition(w->joint[j]);
    default:
        return NAN; /* no single coordinate */
    }
}

double mb_joint_rate(const mb_world *w, int j)
{
    switch (w->joint_type[j]) {
    case J_REVOLUTE:
        return dJointGetHingeAngleRate(w->joint[j]);
    case J_TRANSLATIONAL:
        return dJointGetSliderPositionRate(w->joint[j]);
    default:
        return NAN;
    }
}

void mb_joint_reaction(const mb_world *w, int j, double force[3], double torque[3])
{
    const dJointFeedback *fb = &w->joint_fb[j];
    for (int k = 0; k < 3; k++)
        force[k] = fb->f1[k], torque[k] = fb->t1[k];
}

void mb_joint_reaction_parent(const mb_world *w, int j, double force[3], double torque[3])
{
    const dJointFeedback *fb = &w->joint_fb[j];
    const int world = w->joint_bodies[j][0] < 0;
    for (int k = 0; k < 3; k++)
        force[k] = world ? 0 : fb->f2[k], torque[k] = world ? 0 : fb->t2[k];
}

int mb_joint_add_load(mb_world *w, int j, double load)
{
    switch (w->joint_type[j]) {
    case J_REVOLUTE:
        dJointAddHingeTorque(w->joint[j], load);
        return 0;
    case J_TRANSLATIONAL:
        dJointAddSliderForce(w->joint[j], load);
        return 0;
    default:
        return -1;
    }
}

void mb_joint_axis(const mb_world *w, int j, double axis[3])
{
    dVector3 a = {0, 0, 0, 0};
    if (w->joint_type[j] == J_REVOLUTE) dJointGetHingeAxis(w->joint[j], a);
    if (w->joint_type[j] == J_TRANSLATIONAL) dJointGetSliderAxis(w->joint[j], a);
    axis[0] = a[0], axis[1] = a[1], axis[2] = a[2];
}

void mb_joint_bodies(const mb_world *w, int j, int *parent, int *child)
{
    *parent = w->joint_bodies[j][0], *child = w->joint_bodies[j][1];
}

int mb_joint_is_spherical(const mb_world *w, int j)
{
    return w->joint_type[j] == J_SPHERICAL || w->joint_type[j] == J_UNIVERSAL;
}

double mb_body_mass(const mb_world *w, int b)
{
    dMass m;
    dBodyGetMass(w->body[b], &m);
    return m.mass;
}

double mb_world_kinetic_energy(const mb_world *w)
{
    double e = 0;
    for (int i = 0; i < w->nbody; i++) {
        dMass m;
        dBodyGetMass(w->body[i], &m);
        mb_body_kin k;
        mb_body_get(w, i, &k);
        /* rotational part in body axes: w_b = R' w, I_b from the mass (3x4 rows) */
        double wb[3];
        for (int r = 0; r < 3; r++)
            wb[r] =
                k.rot[r] * k.angvel[0] + k.rot[3 + r] * k.angvel[1] + k.rot[6 + r] * k.angvel[2];
        double rot = 0;
        for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++)
                rot += wb[r] * m.I[4 * r + q] * wb[q];
        double v2 = k.vel[0] * k.vel[0] + k.vel[1] * k.vel[1] + k.vel[2] * k.vel[2];
        e += 0.5 * m.mass * v2 + 0.5 * rot;
    }
    return e;
}

double mb_world_potential_energy(const mb_world *w)
{
    dVector3 g;
    dWorldGetGravity(w->world, g);
    double e = 0;
    for (int i = 0; i < w->nbody; i++) {
        const dReal *p = dBodyGetPosition(w->body[i]);
        e -= mb_body_mass(w, i) * (g[0] * p[0] + g[1] * p[1] + g[2] * p[2]);
    }
    return e;
}

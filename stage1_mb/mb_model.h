/* mb_model.h: the stage-1 engine (issue 4 items 1, 7, 8). A scenario tree becomes an immutable
 * mb_model (bodies, surfaces, contact characteristics, contacts, joints with restraints,
 * attachments, sensors, options); an mb_state holds everything that changes (the ODE world,
 * the hysteresis histories of every contact pair, time, energies, the recorded output).
 * Many states per model work (no globals). mb_step (mb_step.c) advances one fixed step.
 *
 * Contact forces are the project's (docs/stage1_engine.md): per surface pair the penetration
 * geometry of mb_geom, the characteristic through the hysteresis element (never tensile),
 * viscous damping on the penetration rate, and Coulomb friction with a linear stick ramp.
 *
 * Energies [J] (DESIGN.md /stageN/energy): kinetic, potential (gravity, zero at z = 0),
 * contact (elastic energy stored in contacts), internal (stored in restraints and attachments),
 * dissipated (hysteresis, damping, friction, broken attachments), external_work (work of
 * prescribed bodies on the rest, mb_prescribe.h, and of loads on the coupled FE parts), total = kinetic + potential + contact + internal +
 * dissipated - external_work. Its drift is the energy error. */
#ifndef MB_MODEL_H
#define MB_MODEL_H

#include "core/mcs_curve.h"
#include "core/mcs_error.h"
#include "core/mcs_hysteresis.h"
#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_ode.h"
#include "stage1_mb/mb_restraint.h"
#include "stage1_mb/mb_restraint3.h"

#define MB_NAME 64
typedef char mb_name[MB_NAME]; /* a fixed-size name */
#define MB_GROUND -1 /* body index of the ground / the world */

/* ---- model ------------------------------------------------------------------------------- */

/* options the scenario does not set */
typedef struct {
    double energy_tol;  /* stop when total energy grows by more than this fraction of the
                           reference energy (largest kinetic + stored so far) [-]          */
    double energy_floor; /* reference energy never below this [J]                           */
    double slip_speed;  /* friction reaches mu Fn at this slip speed (linear stick ramp) [m/s] */
    int stage;          /* results group the run writes: /stage<stage> (1; stage 2: 2)      */
} mb_opts;

mb_opts mb_opts_default(void);

typedef enum { MB_SURF_ELLIPSOID, MB_SURF_PLANE, MB_SURF_CYLINDER, MB_SURF_FACET } mb_surf_type;

typedef struct {
    char name[MB_NAME]; /* surface name or "<body>.surfaces[i]"                            */
    int body;           /* body index, MB_GROUND for the ground plane                       */
    mb_surf_type type;  /* ellipsoid, plane (half-space) or cylinder (a wheel: a torus)      */
    double center[3];   /* ellipsoid / cylinder centre, a plane point, body frame [m]       */
    double rot[9];      /* ellipsoid axes -> body frame, row-major                          */
    double semi[3];     /* ellipsoid semi-axes [m]                                          */
    double normal[3];   /* plane outward unit normal / cylinder unit axis, body frame       */
    double radius;      /* cylinder: crown circle radius R - L/2 [m]                        */
    double tube;        /* cylinder: tube radius L/2 (rounded tyre profile) [m]             */
    int sphere;         /* 1: all semi-axes equal (exact sphere-sphere geometry)             */
    int chr;            /* characteristic index, -1 = none (rigid: the contact's applies)   */
    mb_mesh *mesh;      /* facet: triangles in the body frame, AABB tree (owned), else NULL */
} mb_surface;

typedef struct {
    char name[MB_NAME];  /* the characteristics: key                                        */
    int moment;          /* 1: moment vs. angle (joints), 0: force vs. deflection           */
    mcs_curve *loading;  /* loading curve [N | N m] vs. [m | rad] (owned)                   */
    mcs_curve *unloading; /* unloading curve or NULL (owned)                                */
    mcs_hyst_model hyst; /* one-sided element on these curves                               */
    double damping;      /* viscous [N s/m | N m s/rad]                                     */
    double friction;     /* Coulomb coefficient [-]                                         */
} mb_char;

/* one surface pair of a contact, with its force law (the contact's characteristic, or the
 * series combination of both surfaces' characteristics) */
typedef struct {
    int contact;          /* owning contact                                                 */
    int sa, sb;           /* surfaces: sa an ellipsoid or cylinder, sb an ellipsoid or plane */
    int ba, bb;           /* their bodies (bb may be MB_GROUND)                             */
    mcs_hyst_model hyst;  /* force vs. penetration                                          */
    double damping;       /* [N s/m]                                                        */
    double friction;      /* [-]                                                            */
} mb_pair;

typedef struct {
    char name[MB_NAME]; /* contact name or "<a>-<b>"                                       */
    int body_a, body_b; /* body indices (MB_GROUND allowed for b)                           */
    int pair0, npair;   /* its surface pairs in mb_model.pair                               */
} mb_contact_def;

typedef enum { MB_J_REVOLUTE, MB_J_SPHERICAL, MB_J_UNIVERSAL, MB_J_TRANSLATIONAL, MB_J_FIXED }
    mb_joint_type;

typedef struct {
    char name[MB_NAME];
    mb_joint_type type;
    int parent, child;  /* body indices, parent MB_GROUND = the world                        */
    double anchor[3];   /* world [m]                                                        */
    double axis[3];     /* unit, world                                                      */
    double axis2[3];    /* unit, world (universal)                                          */
    int restraint;      /* index into restraint1 (revolute, translational) or restraint3, -1 */
} mb_joint_def;

typedef enum {
    MB_SENSOR_ACC,
    MB_SENSOR_VEL,
    MB_SENSOR_DISP,
    MB_SENSOR_ANGVEL,
    MB_SENSOR_ANGACC
} mb_sensor_type;

typedef struct {
    char name[MB_NAME]; /* channel prefix: channels <name>_<q>x/y/z                         */
    int body;
    mb_sensor_type type;
    double point[3];    /* body frame [m]                                                   */
    int cfc;            /* SAE J211 class, 0 = unfiltered                                    */
} mb_sensor;

typedef struct {
    /* sizes */
    int nbody, nsurf, nchar, ncontact, npair, njoint, nrestraint1, nrestraint3, nattach, nsensor;
    /* bodies */
    mb_name *body_name;         /* (nbody)                                                  */
    mb_body_desc *body;         /* mass, inertia, initial pose and velocities (nbody)         */
    double (*body_iinv)[9];     /* inverse inertia tensor, body axes [1/(kg m^2)] (nbody)     */
    /* contacts */
    mb_surface *surf;           /* (nsurf), the ground plane included when present            */
    int ground_surf;            /* surface index of the ground plane, -1 if none              */
    mb_char *chr;               /* (nchar)                                                    */
    mcs_curve **own_curves;     /* series-combined curves owned by the model (npair)           */
    mb_contact_def *contact;    /* (ncontact)                                                 */
    mb_pair *pair;              /* (npair)                                                    */
    /* joints, restraints, attachments */
    mb_joint_def *joint;               /* (njoint), ODE joint index = position here          */
    mb_restraint_model *restraint1;    /* (nrestraint1)                                      */
    mb_name *restraint1_name;          /* (nrestraint1)                                      */
    mb_restraint3_model *restraint3;   /* (nrestraint3)                                      */
    mb_name *restraint3_name;          /* (nrestraint3)                                      */
    mb_attach_model *attach;           /* (nattach)                                          */
    mb_name *attach_name;              /* (nattach)                                          */
    mb_sensor *sensor;                 /* (nsensor)                                          */
    /* simulation */
    double gravity[3];   /* world [m/s^2]                                                   */
    double h;            /* fixed time step [s]                                              */
    double t_end;        /* end time [s]                                                     */
    double output_rate;  /* [Hz]                                                             */
    long nsteps;         /* steps to t_end                                                   */
    int out_every;       /* steps between output samples                                     */
    long nout;           /* output samples, t = 0 included                                   */
    mb_opts opts;
    double rider_residual; /* largest rider mount point to motorcycle mount point distance after
                              seating the rider (mb_position.c) [m]; -1 without a rider: block */
    char rider_dummy[16]; /* Hybrid III size of the rider (rider: dummy:, an_dummy.h names),
                             "" without a rider: block; written as /stage1 attribute `dummy` */
    int nloadcell;          /* load-cell sensors (mb_loadcell.h)                              */
    struct mb_loadcell *loadcell; /* (nloadcell)                                              */
    struct mb_couple *couple;     /* FE parts coupled to the bodies (mb_couple.h), NULL none */
    struct mb_presc *presc;       /* prescribed bodies (mb_prescribe.h) (nbody), NULL none    */
    struct mb_egroup *egroup;     /* energy groups (mb_egroup.h: the rider's), NULL none      */
    /* the impact: placement (mb_impact.c) of the motorcycle group, x' = R x + t; the FE parts
     * carried by its bodies move with it (mb_couple.c, fe/scn/fe_scn_place.c) */
    double place_R[9], place_t[3]; /* rotation (row-major) [-], translation [m]             */
    int *body_group;              /* impact group of each body: MB_GROUP_* (nbody); NULL without
                                     an impact: block                                          */
} mb_model;

enum { MB_GROUP_NONE = 0, MB_GROUP_MOTO = 1, MB_GROUP_OPP = 2 }; /* impact groups (mb_impact.h) */

/* build from a loaded scenario; every error names FILE:LINE:COL and the key */
mcs_status mb_model_build(const mcs_scenario *scn, const mb_opts *opts, mb_model **out,
                          mcs_error *err);
void mb_model_destroy(mb_model **m);
int mb_model_body(const mb_model *m, const char *name); /* index or -1 */
/* the results stage the model writes (opts.stage, 1 when unset) */
int mb_out_stage(const mb_model *m);

/* ---- state ------------------------------------------------------------------------------- */

/* X(name, unit): the energy series, in /stage1/energy order */
#define MB_ENERGY_FIELDS(X)                                                                        \
    X(kinetic, "J")                                                                                \
    X(potential, "J")                                                                              \
    X(internal, "J")                                                                               \
    X(contact, "J")                                                                                \
    X(dissipated, "J")                                                                             \
    X(external_work, "J")                                                                          \
    X(total, "J")

typedef struct {
#define MB_X_FIELD(name, unit) double name; /* [J] */
    MB_ENERGY_FIELDS(MB_X_FIELD)
#undef MB_X_FIELD
} mb_energy;

/* X(name, width): the recorded body quantities, in /stage1/bodies/<b>/ order; width per row */
#define MB_BODY_FIELDS(X)                                                                          \
    X(position, 3)                                                                                 \
    X(orientation, 4)                                                                              \
    X(velocity, 3)                                                                                 \
    X(angular_velocity, 3)                                                                         \
    X(acceleration, 3)
#define MB_BODY_ROW 16 /* sum of the widths */

/* per-pair contact state */
typedef struct {
    mcs_hyst_state h;  /* history of the force law                                         */
    double normal[3];  /* last normal (warm start of ellipsoid-ellipsoid) , world           */
    int has_normal;    /* 1 once normal is set                                             */
    double e_damp;     /* energy dissipated by the damper [J]                               */
    double e_fric;     /* energy dissipated by friction [J]                                 */
    double fn;         /* normal force at the last step [N]                                 */
    double depth;      /* penetration at the last step [m]                                  */
    double ft[3];      /* friction force on a at the last step, world [N]                    */
    mb_mesh_latch latch; /* facets: triangles whose contact began over the cap (mb_facet.h)  */
} mb_pair_state;

typedef struct mb_state mb_state;

/* timer slots of the step's sub-stages */
#define MB_STEP_STAGES(X)                                                                          \
    X(contact)                                                                                     \
    X(restraint)                                                                                   \
    X(external)                                                                                    \
    X(integrate)                                                                                   \
    X(detect)                                                                                      \
    X(sensors)                                                                                     \
    X(energy)

typedef enum {
#define MB_X_ENUM(n) MB_T_##n,
    MB_STEP_STAGES(MB_X_ENUM)
#undef MB_X_ENUM
        MB_NTIMER
} mb_timer;

struct mb_state {
    mb_world *world;          /* ODE world (opaque)                                         */
    long step;                /* steps taken                                                */
    double t;                 /* simulated time [s]                                         */
    mb_pair_state *pair;      /* (npair)                                                    */
    mb_restraint_state *r1;   /* (nrestraint1)                                              */
    mb_restraint3_state *r3;  /* (nrestraint3)                                              */
    mb_attach_state *att;     /* (nattach)                                                  */
    mb_energy e;              /* energies now                                               */
    double e_total0;          /* total energy at t = 0 [J]                                  */
    double e_ref;             /* largest kinetic + stored energy so far [J]                 */
    double drift_abs;         /* largest |total - total0| so far [J]                         */
    /* scratch (allocated once) */
    mb_body_kin *kin;         /* body poses and velocities at the start of the step (nbody)  */
    mb_contact *pc;           /* contact geometry of each pair this step (npair)            */
    double *vel_prev;         /* CG velocities before the step (nbody x 3) [m/s]            */
    double *angvel_prev;      /* angular velocities before the step (nbody x 3) [rad/s]     */
    double *acc;              /* CG accelerations of the last step (nbody x 3) [m/s^2]      */
    double *angacc;           /* angular accelerations of the last step (nbody x 3) [rad/s^2] */
    double *pos0;             /* initial CG positions (nbody x 3) [m]                       */
    double *rot0;             /* initial orientations (nbody x 9)                           */
    /* recorded output (nout rows, allocated once) */
    long nrec;                /* rows recorded                                              */
    double *rec_t;            /* time [s] (nout)                                            */
    double *rec_body;         /* (nout x nbody x MB_BODY_ROW)                               */
    double *rec_sensor;       /* (nout x nsensor x 3), SAE J211 local frame, SI             */
    double *rec_energy;       /* (nout x MB_NENERGY) [J]                                    */
    double timer[MB_NTIMER];  /* wall time per sub-stage [s]                                */
    int timing;               /* 1: read the clock around sub-stages                        */
    double *rec_chan;         /* contact and joint channels (nout x mb_channels_count) SI    */
    double *rec_loadcell;     /* (nout x nloadcell x 6), SAE J211, N and N m (mb_loadcell.h) */
    mb_ellipsoid *surf_ell;   /* ellipsoid surfaces placed in the world this step (nsurf)    */
    struct mb_couple_state *couple; /* FE state of m->couple (mb_couple.h), NULL none         */
    double *presc_next;       /* prescribed bodies: pose and velocities at t + h, pose at t
                                 (nbody x 20) (mb_prescribe.c), NULL none                   */
    double w_presc;           /* work of the prescribed bodies on the rest [J]              */
    struct mb_egroup_state *egroup; /* of m->egroup (mb_egroup.h), NULL none                  */
};

#define MB_NENERGY 7

mcs_status mb_state_create(const mb_model *m, mb_state **out, mcs_error *err);
void mb_state_destroy(mb_state **s);

/* one fixed step (mb_step.c). MCS_ERR_NUMERIC on NaN or energy growth: the message names the
 * body (or the contact) and the time. */
mcs_status mb_step(const mb_model *m, mb_state *s, mcs_error *err);

/* sub-stages (mb_contact.c, mb_joints.c, mb_energy.c, mb_sensor.c) */
void mb_contact_detect(const mb_model *m, mb_state *s);
void mb_contact_forces(const mb_model *m, mb_state *s);
void mb_restraints_apply(const mb_model *m, mb_state *s);
void mb_energy_update(const mb_model *m, mb_state *s);
/* body b's kinetic energy (translation + rotation) at s->kin [J] (mb_energy.c) */
double mb_body_kinetic(const mb_model *m, const mb_state *s, int b);
mcs_status mb_energy_check(const mb_model *m, mb_state *s, mcs_error *err);
/* every step, after the force stages: growth or NaN of the total from running sums */
mcs_status mb_energy_check_step(const mb_model *m, mb_state *s, mcs_error *err);
/* the energy error: largest |total - total0| over the largest kinetic + stored energy [-] */
double mb_energy_drift(const mb_model *m, const mb_state *s);
void mb_kinematics_update(const mb_model *m, mb_state *s);
void mb_record(const mb_model *m, mb_state *s);

/* ---- a whole run (mb_run.c) --------------------------------------------------------------- */

typedef struct {
    const char *out_path;      /* results file; NULL: do not write one                      */
    const char *scenario_text; /* for /meta/scenario                                        */
    int quiet;                 /* no progress line                                          */
    int append;                /* 1: add the stage's group to the existing file out_path    */
    /* more of the stage's output, written after the state's records and before the commit
     * (stage 2's /stage2/motion); NULL: none */
    mcs_status (*write_more)(void *ctx, const mb_model *m, const mb_state *s, mcs_results *r,
                             mcs_error *err);
    void *write_ctx;
} mb_run_opts;

typedef struct {
    long steps;         /* steps taken                                                      */
    int bodies;         /* bodies                                                           */
    double wall_time_s; /* wall time of the time loop and output [s]                        */
    double energy_drift; /* largest |total - total0| / reference energy [-]                 */
    double t_end;       /* simulated time reached [s]                                       */
    double timer[MB_NTIMER]; /* wall time per step sub-stage [s]                            */
} mb_run_summary;

/* name of a timer slot ("contact", "integrate", ...) */
const char *mb_timer_name(int k);

/* run the model to its end time and write the results (nothing is left on failure) */
mcs_status mb_run(const mb_model *m, const mb_run_opts *o, mb_run_summary *sum, mcs_error *err);

/* add /stage<stage>/injury to a committed results file from its channels (mb_injury.c); *ncrit
 * criteria written (0 when no known dummy channel exists) */
mcs_status mb_injury_write(const char *path, int stage, int *ncrit, mcs_error *err);

/* contact and joint channels (mb_channels.c): per contact <contact>_fn, _ft, _pen; per joint
 * with a one-axis restraint <joint>_angle|_disp and _moment|_force (docs/contracts.md) */
int mb_channels_count(const mb_model *m);
void mb_channels_sample(const mb_model *m, const mb_state *s, double *row);
mcs_status mb_channels_write(const mb_model *m, const mb_state *s, mcs_results *r, double *buf,
                             mcs_error *err);

/* the bodies' surfaces as triangles in the body frame, /stage1/outlines/<body>/{nodes,
 * elements} (mb_outline.c), for `mcrash export --xdmf` */
mcs_status mb_outline_write(const mb_model *m, mcs_results *r, mcs_error *err);

/* write /stage1 of the recorded state into an open results file (mb_output.c) */
mcs_status mb_output_write(const mb_model *m, const mb_state *s, mcs_results *r, mcs_error *err);

#endif

/* fe_state: everything an explicit FE run changes (STYLE.md §1). Many states per model work.
 *
 * Time centring (central difference): one fe_step goes from t_n to t_{n+1}. After it returns,
 * `time` is t_{n+1}, node_x is x(t_{n+1}), node_v and node_w are the velocities at
 * t_{n+1/2}; forces, accelerations, stresses and energies are those of t_n = energy_time.
 * Kinetic energy is m v_{n-1/2}.v_{n+1/2} / 2 and every work is summed with the trapezoidal
 * rule over the same intervals, so the balance closes to round-off for a linear elastic system
 * at a constant step (the modified energy that central differences conserve). */
#ifndef FE_STATE_H
#define FE_STATE_H

#include <stddef.h>

#include "core/mcs_arena.h"
#include "fe/fe_model.h"

/* energies, in the order and with the names of /stageN/energy (DESIGN.md) [J] */
#define FE_ENERGY_LIST(X)                                                                          \
    X(kinetic)       /* translational + rotational                                      */        \
    X(potential)     /* gravity (none yet: 0)                                            */        \
    X(internal)      /* stress power of the elements (elastic + plastic work)           */        \
    X(contact)       /* contact interfaces: elastic + frictional (fe_contact.h)          */        \
    X(hourglass)     /* work of the hourglass forces                                     */        \
    X(dissipated)    /* bulk viscosity and mass damping                                  */        \
    X(eroded)        /* internal energy of the elements deleted by erosion, at deletion  */        \
    X(external_work) /* loads, prescribed motion and rigid walls on the structure        */        \
    X(total)         /* kinetic + potential + internal + contact + hourglass + dissipated + eroded
                        - external_work */

typedef enum {
#define FE_X_EN(name) FE_E_##name,
    FE_ENERGY_LIST(FE_X_EN)
#undef FE_X_EN
        FE_NENERGY
} fe_energy_kind;

extern const char *const fe_energy_name[FE_NENERGY];

/* the sub-stages of fe_step, each with a timer slot */
#define FE_STAGE_LIST(X)                                                                           \
    X(internal)     /* element forces into slots, gathered per node               */               \
    X(contact)      /* penalty rigid walls (contact interfaces later)             */               \
    X(external)     /* nodal loads                                                 */               \
    X(accelerate)   /* a = f / m                                                   */               \
    X(integrate)    /* velocities, constraints, kinematic walls, positions, energies */            \
    X(timestep)     /* next stable step, energy check, history                     */

typedef enum {
#define FE_X_ST(name) FE_STAGE_##name,
    FE_STAGE_LIST(FE_X_ST)
#undef FE_X_ST
        FE_NSTAGE
} fe_stage;

extern const char *const fe_stage_name[FE_NSTAGE];

/* partial sums of one chunk of elements: threaded element loops reduce them in chunk order,
 * so results do not depend on the number of threads */
typedef struct {
    double e_int, e_hg, e_diss; /* internal, hourglass, dissipated energy this step [J]     */
    double dtmin;               /* smallest element step, no safety factor [s]              */
    int dtel, bad;              /* element giving dtmin; first inverted element, -1 none [-] */
    double e_erode;             /* internal energy of the elements eroded this step [J]     */
    int nerode;                 /* elements eroded this step [-]                            */
} fe_chunk_acc;

/* the state's arrays: X(type, name, count (a model size), components, unit, what) */
#define FE_STATE_ARRAYS(X)                                                                         \
    X(double, node_x, nnode, 3, "m", "position")                                                   \
    X(double, node_v, nnode, 3, "m/s", "velocity at t + dt/2")                                     \
    X(double, node_w, nnode, 3, "rad/s", "angular velocity at t + dt/2 (shell nodes)")             \
    X(double, node_a, nnode, 3, "m/s^2", "acceleration at t")                                      \
    X(double, node_fint, nnode, 3, "N", "internal force (resisting) at t")                         \
    X(double, node_mint, nnode, 3, "N m", "internal moment (resisting) at t")                      \
    X(double, node_fext, nnode, 3, "N", "external + contact force at t")                           \
    X(double, hex_sig, nhex, 6, "Pa", "Cauchy stress xx yy zz xy yz zx")                           \
    X(double, hex_epsp, nhex, 1, "-", "equivalent plastic strain")                                 \
    X(double, hex_rate, nhex, 1, "1/s", "filtered effective strain rate (rate factor)")           \
    X(double, hex_q, nhex, 1, "Pa", "bulk viscosity pressure")                                   \
    X(double, hex_hg, nhex, 12, "N", "hourglass forces (3 x 4 modes)")                   \
    X(double, shell_sig, nshell_ip, 3, "Pa", "local in-plane stress xx yy xy per point")          \
    X(double, shell_epsp, nshell_ip, 1, "-", "equivalent plastic strain per point")                \
    X(double, shell_rate, nshell_rate, 1, "1/s", "filtered effective strain rate per point")       \
    X(double, shell_tau, nshell, 2, "Pa", "local transverse shear stress xz yz")                   \
    X(double, shell_hg, nshell, 5, "N", "hourglass resultants (x, y, z, rx, ry)")        \
    X(double, truss_sig, ntruss, 1, "Pa", "axial stress")                                          \
    X(double, truss_epsp, ntruss, 1, "-", "plastic strain")                                        \
    X(double, slot_f, nslot, 3, "N", "element force at each element node (resisting)")            \
    X(double, shell_m, nshell, 12, "N m", "shell moment at each of its 4 nodes (resisting)")       \
    X(double, part_energy, npart, FE_NENERGY, "J", "energies per part")                           \
    X(double, part_dt, npart, 1, "s", "smallest element step of each part, no safety factor")     \
    X(int, part_dt_elem, npart, 1, "-", "element giving part_dt")                                  \
    X(int, part_bad_elem, npart, 1, "-", "first inverted element of the part, -1 none")           \
    X(double, wall_force, nwall, 3, "N", "force of the structure on each rigid wall")             \
    X(double, wall_disp, nwall, 1, "m", "rigid wall displacement along its velocity")            \
    X(double, wall_x, nwall, 3, "m", "rigid wall displacement from t = 0, at t (fe_wall.c)")      \
    X(double, wall_v, nwall, 3, "m/s", "rigid wall velocity at t + dt/2 (fe_wall.c)")             \
    X(double, wall_xn, nwall, 3, "m", "rigid wall displacement at t + dt, before the node update") \
    X(double, wall_vn, nwall, 3, "m/s", "kinematic wall with mass: velocity at t + dt/2 solved")  \
    X(double, wall_diss, nwall, 2, "J", "kinematic wall with mass: landing loss, halves at t")    \
    X(double, wall_scr, nwall_slave, 2, "-", "scratch of the kinematic wall solve (fe_wall_kin.c)") \
    X(double, wall_ft, nwall_slave, 3, "N", "penalty wall friction force on each slave at t")     \
    X(double, wall_part_f, nwall_part, 1, "N", "penalty wall normal force by part at t (w, part)") \
    X(double, hist_time, opts.history_capacity, 1, "s", "history sample times")                  \
    X(double, hist_energy, opts.history_capacity, FE_NENERGY, "J", "energies at samples")        \
    X(double, hist_wall_force, opts.history_capacity, FE_WALL_MAX, "N", "wall normal force")     \
    X(double, hist_wall_disp, opts.history_capacity, FE_WALL_MAX, "m", "wall displacement")     \
    X(double, spring_f, nspring, 1, "N", "spring force, tension positive")                         \
    X(double, spring_fd, nspring, 1, "N", "damper force, tension positive")                        \
    X(double, spring_d, nspring, 1, "m", "elongation at the last force evaluation")                \
    X(double, spring_part_energy, nspring_part, FE_NENERGY, "J", "energies of each spring part")   \
    X(double, node_dm, nms_node, 1, "kg", "mass added to the node during the run (mass scaling)")  \
    X(double, node_din, nms_node, 1, "kg m^2", "rotary inertia added with it")                    \
    X(double, elem_ms, nms_elem, 1, "-", "run-time density factor of each element (1: none)")     \
    X(double, body_x, nbody, 3, "m", "rigid body centre of mass")                                  \
    X(double, body_v, nbody, 3, "m/s", "rigid body velocity at t + dt/2")                          \
    X(double, body_rot, nbody, 9, "-", "rigid body rotation from t = 0 (row-major)")              \
    X(double, body_l, nbody, 3, "N m s", "rigid body angular momentum at t + dt/2")                \
    X(double, body_w, nbody, 3, "rad/s", "rigid body angular velocity at t + dt/2")                \
    X(double, body_fm, nbody, 6, "N, N m", "force and moment on the body at t")                    \
    X(double, body_fj, nbody, 6, "N, N m", "joint force and moment on the body at t (fe_joint.h)") \
    X(double, joint_out, njoint, 10, "-", "joint loads, free coordinates, energies (FE_JOUT_*)")  \
    X(double, hex_gp, nhex_gp, 7, "Pa", "full hex: stress (6), plastic strain or foam history")   \
    X(double, tet10_gp, ntet10, 32, "Pa", "tet10: per point stress (6), plastic strain, bulk q") \
    X(double, tet10_sig, ntet10, 6, "Pa", "tet10: volume-mean Cauchy stress xx yy zz xy yz zx")  \
    X(double, tet10_epsp, ntet10, 1, "-", "tet10: mean equivalent plastic strain of the points")  \
    X(double, tet10_rate, ntet10, 1, "1/s", "tet10: filtered effective strain rate")              \
    X(fe_chunk_acc, chunk_acc, nchunk, 1, "-", "partial sums of each element chunk")             \
    X(unsigned char, elem_dead, nerode, 1, "-", "erosion: 1 once the element is deleted")        \
    X(unsigned char, elem_gone, nerode, 1, "-", "erosion: elem_dead as of the last step (contact)") \
    X(double, elem_eint, nerode, 1, "J", "erosion: internal energy of each element")             \
    X(double, node_acc, nnode_acc, 1, "-", "partial sums of each node chunk (fe_integrate)")     \
    X(double, chunk_cost, nchunk, 1, "s", "time of each element chunk, summed since the last balance") \
    X(double, foam_hist, nfoam_ip, 6, "-", "foam: largest-strain tensor, t = 0 frame (fe_foam.c)") \
    X(double, node_cost, nnode_chunk, 1, "s", "contact time of each node chunk, summed since the last balance")

struct fe_contact_state;

/* steps over which the stable step takes its smallest estimate (fe_stable_step) */
#define FE_DT_WINDOW 8

typedef struct fe_state {
    double time;                  /* t [s]                                                     */
    double dt;                    /* step from t to t + dt, used by the next fe_step [s]       */
    double dt_prev;               /* step from t - dt_prev to t [s]                            */
    double dt_win[FE_DT_WINDOW];  /* the last stable-step estimates, ring by nstep [s]         */
    long nstep;                   /* steps taken [-]                                           */
    double energy[FE_NENERGY];    /* global energies at t [J]                                  */
    double energy0;               /* total energy at t = 0 [J]                                 */
    double energy_ref;            /* largest of kinetic, internal and |external work| seen [J] */
    double wall_normal[FE_WALL_MAX]; /* normal force of each wall at t (>= 0 pushing) [N]     */
    double energy_time;           /* time of energy[] (t_n: one step behind `time`) [s]        */
    double work_pending[3];       /* forward halves of external, constraint, damping work [J]  */
    double work_ext;              /* external work up to energy_time, walls and constraints [J] */
    double work_damp;             /* mass damping dissipation up to energy_time [J]            */
    int bad_node;                 /* first node with a non-finite velocity, -1 none [-]        */
    int dt_part, dt_elem;         /* element controlling the stable step (part, index in kind) */
    int nhist;                    /* history samples written [-]                              */
    long hist_dropped;            /* samples that did not fit [-]                              */
    double hist_next;             /* time of the next sample [s]                               */
    double timer[FE_NSTAGE];      /* wall time spent in each sub-stage [s]                     */
    mcs_error err;                /* why the run stopped (MCS_ERR_NUMERIC ...), else MCS_OK     */
    mcs_arena *arena;             /* scratch for per-step temporaries                          */
    size_t bytes;                 /* memory held by the state, arena included [B]              */
    struct fe_restraint_state *restraint; /* gas and retractor states (fe_restraint.h); NULL none */

#define FE_X_DECL(T, name, n, k, unit, doc) T *name;
    FE_STATE_ARRAYS(FE_X_DECL)
#undef FE_X_DECL
    double free_energy[FE_NENERGY]; /* energies of what belongs to no part: springs and dampers
                                     (internal, dissipated) [J]                                */
    struct fe_contact_state *contact; /* contact interfaces (fe_contact.h), NULL if none */
    /* thread shares of the threaded loops (fe_parallel.h): team size, each thread's first
     * element chunk and first node chunk; par_cut[par_nt] = nchunk [-] */
    int par_nt;
    int par_cut[FE_PAR_MAX + 1], par_ncut[FE_PAR_MAX + 1];
    int par_steps;                /* steps summed in chunk_cost and node_cost since the last
                                     balance (fe_parallel.c) [-]                               */
    int par_nbal;                 /* balances since the team was formed [-]                  */
    double mass_added_run;        /* mass added by mass scaling during the run [kg]           */
    int neroded;                  /* elements deleted by erosion so far [-]                   */
    double erode_first, erode_last; /* times of the first and the last erosion [s]           */
    double dt_ms;                 /* smallest scaled step of the scaled parts at the last check,
                                     no safety factor [s]                                    */
    struct fe_slipring_state *slipring; /* slip rings (fe_slipring.h); NULL none            */
    const double *node_vkin;      /* prescribed velocities of the fixed translations this step,
                                     (nnode x 3), set by a coupling (stage1_mb/mb_couple.c);
                                     NULL: the model's node_vfix [m/s]                       */
    double *node_react;           /* set by a coupling (nnode x 3): fe_integrate writes the
                                     constraint (and kinematic wall) reaction on each node at t,
                                     r = (m + dm) (v_new - v_free) (1 + c dth/2) / dth, the force
                                     the constraint applies, mass damping c and run-time mass
                                     scaling dm included; rigid-body nodes are not written;
                                     NULL: not recorded [N]                                  */
} fe_state;

/* the velocities of the fixed translations this step: a coupling's (node_vkin) or the
 * model's (node_vfix) (nnode x 3) [m/s] */
static inline const double *fe_node_vfix(const fe_model *m, const fe_state *s)
{
    return s->node_vkin ? s->node_vkin : m->node_vfix;
}

/* allocate every array once (and the scratch arena), then fe_state_reset */
mcs_status fe_state_create(const fe_model *m, fe_state **out, mcs_error *err);
void fe_state_destroy(fe_state **p);
/* back to t = 0: initial positions and velocities, zero stresses, first stable step */
void fe_state_reset(const fe_model *m, fe_state *s);

/* advance one step; MCS_ERR_NUMERIC (NaN, inverted element, step collapse, energy growth)
 * stops the run, with s->err naming the node or element and the time */
mcs_status fe_step(const fe_model *m, fe_state *s);
/* steps until time >= t_end (the last step is not shortened) */
mcs_status fe_run(const fe_model *m, fe_state *s, double t_end);

/* the sub-stages (fe_step calls them in order; exposed for tests and benchmarks) */
void fe_internal_forces(const fe_model *m, fe_state *s);
void fe_contact_forces(const fe_model *m, fe_state *s);
void fe_external_forces(const fe_model *m, fe_state *s);
void fe_accelerations(const fe_model *m, fe_state *s);
void fe_integrate(const fe_model *m, fe_state *s);
mcs_status fe_stable_step(const fe_model *m, fe_state *s);

/* threads of the element and node loops: OMP_NUM_THREADS, or fe_set_threads (> 0); 1 when
 * built without OpenMP. Results do not depend on it (fe_parallel.c). */
int fe_threads(void);
void fe_set_threads(int n);

/* smallest stable step of the current geometry, safety factor applied [s] */
double fe_stable_dt(const fe_model *m, const fe_state *s);
/* energies of one part [J] (FE_E_* index) */
double fe_part_energy(const fe_model *m, const fe_state *s, int part, fe_energy_kind k);
/* energies of one spring part (internal: elastic, dissipated: dampers) [J] (fe_discrete.c) */
double fe_spring_part_energy(const fe_model *m, const fe_state *s, int sp, fe_energy_kind k);

#endif

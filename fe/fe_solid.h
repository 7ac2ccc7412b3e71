/* fe_solid: private interface of the discrete springs and dampers, point masses, gravity,
 * foam, rigid bodies, the fully integrated hex and mass scaling (fe_discrete.c, fe_gravity.c,
 * fe_foam.c, fe_rigid.c, fe_hex_full.c, fe_massscale.c) and the hooks the kernel calls.
 * Not a public header. */
#ifndef FE_SOLID_H
#define FE_SOLID_H

#include "fe/fe_builder_impl.h"
#include "fe/fe_state.h"

/* a discrete spring/damper of the frozen model */
typedef struct fe_spring {
    int node[2];                   /* nodes; -1: the end is the fixed anchor [-]              */
    double anchor[2][3];           /* fixed ends [m]                                          */
    double length0;                /* length at t = 0 [m]                                     */
    double stiffness;              /* [N/m]                                                   */
    int ncurve;                    /* > 0: tabulated force [-]                                */
    double curve[FE_CURVE_MAX][2]; /* (elongation [m], force [N])                             */
    double damping;                /* [N s/m]                                                 */
    char name[FE_NAME_MAX];
    int part;                      /* its spring part (m->spring_part) [-]                    */
} fe_spring;

/* a rigid body: one rigid part's nodes moving as one 6-DOF body */
typedef struct fe_body {
    char name[FE_NAME_MAX];   /* its rigid part's, or the nodal rigid body's (fe_joint.h)    */
    int part;                 /* the rigid part; -1: a nodal rigid body [-]                  */
    int node_begin, node_end; /* its nodes in m->body_node / m->body_r0 [-]                  */
    double mass;              /* sum of the nodal masses [kg]                                */
    double x0[3];             /* centre of mass at t = 0 [m]                                 */
    double inertia0[3][3];    /* inertia about x0 in the t = 0 axes [kg m^2]                  */
    double inertia0_inv[3][3];/* its inverse [1/(kg m^2)]                                    */
    unsigned fix;             /* FE_DOF_* held (from boundaries on its nodes) [-]             */
    double vfix[3];           /* prescribed velocity of the held translations [m/s]           */
} fe_body;

/* ---- model building (fe_model_create calls fe_solid_build after lumping the masses) ---- */

/* point masses, springs, mass scaling, rigid bodies, fully integrated hex Gauss points */
mcs_status fe_solid_build(const fe_builder *b, fe_model *m, mcs_error *err);
/* frees what fe_solid_build allocated */
void fe_solid_free(fe_model *m);
/* builder-side checks of the foam keys and the rigid/full-hex section (fe_builder_add_part) */
mcs_status fe_foam_check(const fe_part_desc *d, mcs_error *err);
/* derived constants of a foam part (wave speed from the stiffest curve) */
void fe_foam_derive(fe_part *p);

mcs_status fe_discrete_build(const fe_builder *b, fe_model *m, mcs_error *err);
/* stable step of the springs (m->dt_discrete) from the final nodal masses */
mcs_status fe_discrete_steps(fe_model *m, mcs_error *err);
mcs_status fe_rigid_build(const fe_builder *b, fe_model *m, mcs_error *err);
/* fe_model_create calls this last: checks and constraints that need boundaries and walls */
mcs_status fe_solid_finish(fe_model *m, mcs_error *err);
mcs_status fe_rigid_finish(fe_model *m, mcs_error *err);
void fe_rigid_reset(const fe_model *m, fe_state *s);
/* m->elem_dt_factor, all 1, unless it exists already (mass scaling, fe_hex_dt.c) */
mcs_status fe_dt_factors_alloc(fe_model *m, mcs_error *err);
mcs_status fe_massscale_build(fe_model *m, mcs_error *err);
/* run-time mass scaling (opts.mass_scaling_interval > 0): state reset; and, in the stable-step
 * stage, the re-check every interval cycles: elements whose step fell below the target get mass
 * (node_dm, node_din, elem_ms), its kinetic energy goes into the external work; returns the
 * smallest step (no safety factor) of the whole model with the scaled elements' own */
void fe_massscale_reset(const fe_model *m, fe_state *s);
double fe_massscale_run(const fe_model *m, fe_state *s, double dtmin);
/* step factors of lightly held one-point hexes (fe_hex_dt.c), after mass scaling */
mcs_status fe_hex_dt_build(fe_model *m, mcs_error *err);

/* tetrahedra and pentahedra as degenerate hexahedra (fe_tet.c). Shape of a hex connectivity:
 * 8 (8 distinct nodes), 4 (tetrahedron, slots n1 n2 n3 n3 n4 n4 n4 n4), 6 (pentahedron,
 * n1 n2 n3 n4 n5 n5 n6 n6), 0 (another degenerate pattern) */
int fe_hex_shape(const int c[8]);
/* LS-DYNA's *ELEMENT_SOLID list (tetrahedron n1 n2 n3 n4 n4 n4 n4 n4) into hex slots; the
 * shape (8, 4, 6) or 0 for an unsupported pattern */
int fe_solid_from_lsdyna(const int in[8], int out[8]);
/* hex slots back into LS-DYNA's list */
void fe_solid_to_lsdyna(const int c[8], int out[8]);
/* the distinct nodes of hex slots, in slot order; their count */
int fe_hex_distinct(const int c[8], int u[8]);
/* largest omega^2 of a lone linear tetrahedron with lumped mass rho V / 4 [1/s^2] */
double fe_tet_omega2(const double x[4][3], double rho, double lambda, double mu);
/* step factors of the tetrahedra from their own highest frequency (before mass scaling) */
mcs_status fe_tet_dt_build(fe_model *m, mcs_error *err);

/* moving rigid walls with mass (fe_wall.c): descriptor check (fe_builder_add_wall), model
 * checks (fe_solid_finish), state reset, and the wall update after the node update (reads
 * wall_force at t, writes wall_x (t + dt), wall_v (t + dt/2), kinetic energy and works) */
mcs_status fe_wall_check(const fe_wall_desc *d, mcs_error *err);
mcs_status fe_wall_finish(fe_model *m, mcs_error *err);
void fe_wall_reset(const fe_model *m, fe_state *s);
void fe_wall_integrate(const fe_model *m, fe_state *s);

/* constants of one node update (fe_integrate) the wall solve needs */
typedef struct {
    double dt, dth, hb;   /* step, velocity-update step, weight of the interval before t [s] */
    double d0, d1;        /* mass-damping factors of the velocity update [-]                 */
} fe_wall_step;
/* before the node update: every wall's displacement at t + dt (wall_xn); kinematic walls with
 * mass solved with their slaves (fe_wall_kin.c) */
void fe_wall_predict(const fe_model *m, fe_state *s, const fe_wall_step *P);
/* a kinematic wall with mass (fe_wall_kin.c) */
static inline int fe_wall_kin_mass(const fe_wall *W)
{
    return W->mass > 0 && W->method == FE_WALL_KINEMATIC;
}
void fe_wall_kin_solve(const fe_model *m, fe_state *s, int w, const fe_wall_step *P);
mcs_status fe_wall_kin_finish(fe_model *m, mcs_error *err);
/* wall friction (fe_wall_fric.c): a landed node's tangential velocity change on kinematic
 * wall w (dvn its normal velocity change; vn updated, the reaction added to wacc, the
 * dissipation before/after t added to diss); the penalty walls' friction forces (after the
 * penalty forces) and their dissipation after t (after the node update) */
void fe_wall_kin_friction(const fe_model *m, const fe_state *s, int w, double mass, double dvn,
                          const double vo[3], double vn[3], double hb, double dth, double dt,
                          double *wacc, double diss[2]);
void fe_wall_penalty_friction(const fe_model *m, fe_state *s);
void fe_wall_penalty_friction_after(const fe_model *m, fe_state *s);
/* walls moved by curves (fe_wall_motion.c): checks of the motion and friction fields, unit
 * directions, a component's displacement at t [m], the wall's displacement at t [m] */
mcs_status fe_wall_motion_check(const fe_wall_desc *d, mcs_error *err);
void fe_wall_motion_unit(fe_wall_motion *mo);
double fe_wall_motion_disp(const fe_wall_motion *mo, double t);
void fe_wall_motion_x(const fe_wall *W, double t, double x[3]);

/* ---- the time loop ---- */

/* state reset: bodies at rest at t = 0 with the nodes' initial velocities */
void fe_solid_reset(const fe_model *m, fe_state *s);
/* reads x, v (t - dt/2); adds spring/damper forces to node_fint, energies to free_energy */
void fe_discrete_forces(const fe_model *m, fe_state *s);
/* adds m g to node_fext of every node with mass */
void fe_gravity_forces(const fe_model *m, fe_state *s);
/* after the node update: moves the rigid bodies and their nodes, kinetic energy and works */
void fe_rigid_integrate(const fe_model *m, fe_state *s);
/* elements e0..e1-1 of a fully integrated hex part (fe_hex_range hands over) */
void fe_hex_full_range(const fe_model *m, fe_state *s, int ip, int e0, int e1,
                       fe_chunk_acc *acc);
/* foam stress from the deformation gradient F (t = 0 -> t) and the velocity gradient L:
 * Cauchy stress sig (xx yy zz xy yz zx) written; hist (the point's largest-strain tensor in
 * the t = 0 frame, xx yy zz xy yz zx; zero at t = 0), *emax (largest compressive strain seen
 * in any direction, reported) and *rate (filtered engineering strain rate) updated */
void fe_foam_stress(const fe_part *p, const double F[3][3], const double L[3][3], double sig[6],
                    double hist[6], double *emax, double *rate);
/* the same for a one-point hex: F at the centre from the t = 0 and current node positions */
void fe_foam_hex(const fe_model *m, const fe_part *p, const int *conn, const double xe[8][3],
                 const double L[3][3], double sig[6], double hist[6], double *emax,
                 double *rate);
/* deformation gradient at the centre of a hex: x (current) against x0 (t = 0) */
void fe_hex_deformation(const double x0[8][3], const double x[8][3], double F[3][3]);

#endif

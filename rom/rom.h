/* rom.h: the reduced-order model (thesis ch. 3, "the contact model"; the 2023 paper's model
 * category (i)): lumped masses of motorcycle and rider joined by nonlinear spring-dampers with
 * load/unload hysteresis (core/mcs_hysteresis.h, as stage 1's contact characteristics), in one
 * dimension along the barrier's normal, integrated by CVODE. docs/rom.md has the equations,
 * the parameters with their sources, the calibration from stage 1 and its error.
 *
 * Masses (x positive towards the barrier):  rider (3) -- frame (2) -- front (1) | wall or
 * opponent (4). Elements, each a one-sided hysteretic spring with a parallel damper (thesis
 * §3.1: m x'' + d x' + k x = 0, the force acting along the line between the two bodies):
 *   tyre   front against the wall: tyre, then rim (bilinear), initial gap = impact gap
 *   fork   front against frame: elastic, yield, hardening, then the wheel on the engine (stop)
 *   frame  frame against the wall after frame_gap (engine and fairing on the barrier)
 *   rider  rider against frame after rider_gap (knees on the tank, hands on the bars)
 *   head   rider against the wall after rider_wall_gap
 * The wall is rigid unless opponent_mass > 0 (a free mass at rest). Results: /stage0
 * (docs/contracts.md "Stage 0: the reduced-order model"). */
#ifndef ROM_H
#define ROM_H

#include "core/mcs_error.h"
#include "core/mcs_hysteresis.h"
#include "core/mcs_results.h"
#include "core/mcs_scenario.h"

#include <stddef.h>

#define ROM_STAGE 0 /* the results group /stage0 */

enum { ROM_FRONT, ROM_FRAME, ROM_RIDER, ROM_OPP, ROM_NMASS };
enum { ROM_TYRE, ROM_FORK, ROM_FRAMEWALL, ROM_RIDERFRAME, ROM_RIDERWALL, ROM_NELEM };

/* the parameters (SI); the `rom:` block's keys of the same names (core/mcs_schema.c) */
typedef struct {
    double tyre_stiffness;   /* tyre slope up to tyre_travel [N/m]                          */
    double tyre_travel;      /* tyre crush where the rim takes over [m]                     */
    double rim_stiffness;    /* slope beyond tyre_travel (rim, wheel) [N/m]                 */
    double tyre_unload;      /* unloading slope [N/m]                                       */
    double tyre_damping;     /* [N s/m]                                                     */
    double fork_stiffness;   /* elastic slope of the fork's rearward bending [N/m]          */
    double fork_yield;       /* force at the elastic limit [N]                              */
    double fork_hardening;   /* slope after yield [N/m]                                     */
    double fork_stop;        /* fork travel where the wheel meets the engine [m]            */
    double stop_stiffness;   /* slope beyond fork_stop [N/m]                                */
    double fork_unload;      /* unloading slope [N/m]                                       */
    double fork_damping;     /* [N s/m]                                                     */
    double frame_gap;        /* frame travel before it meets the wall [m]                   */
    double frame_stiffness;  /* frame (engine, fairing) against the wall [N/m]              */
    double frame_unload;     /* [N/m]                                                       */
    double frame_damping;    /* [N s/m]                                                     */
    double rider_gap;        /* rider travel on the seat before the restraint acts [m]      */
    double rider_stiffness;  /* rider against the frame (tank, bars, belt) [N/m]            */
    double rider_limit;      /* force where the rider slides on over the tank (plateau) [N] */
    double rider_unload;     /* unloading slope beyond 5 mm [N/m]                           */
    double rider_damping;    /* [N s/m]                                                     */
    double rider_wall_gap;   /* rider travel before the rider meets the wall [m]            */
    double rider_wall_stiffness; /* [N/m]                                                   */
    double rider_wall_unload;    /* unloading slope beyond 5 mm (the dummy's own losses) [N/m] */
    double rider_wall_damping;   /* [N s/m]                                                 */
    double opponent_mass;    /* 0: rigid wall, else a free opponent mass [kg]               */
    double rtol;             /* CVODE relative tolerance [-]                                */
    int adams;               /* 1: Adams-Moulton (functional iteration), 0: BDF (Newton)    */
} rom_params;

/* the defaults: the stage-1 sport motorcycle's characteristics carried over (docs/rom.md) */
rom_params rom_params_default(void);

/* the parameters a fit may change, by name (rom_param_ptr: NULL for an unknown name) */
double *rom_param_ptr(rom_params *p, const char *name);
extern const char *const rom_param_names[]; /* NULL-terminated, the rom: keys */

/* one element: masses a (behind) and b (ahead; -1 the wall), deflection
 * d = x_a - x_b - gap; a one-sided hysteretic spring with a damper */
typedef struct {
    int a, b;             /* masses (b = -1: the rigid wall)                               */
    double gap;           /* [m]                                                           */
    double damping;       /* [N s/m]                                                       */
    mcs_curve *loading;   /* force vs. deflection [N] vs. [m] (owned)                      */
    mcs_hyst_model hyst;  /* its load/unload rule                                          */
} rom_elem;

typedef struct {
    rom_params p;
    double mass[ROM_NMASS]; /* [kg]; 0: the mass is absent (its elements too)               */
    double v0;              /* initial speed of the motorcycle and rider along the normal [m/s] */
    double vinit[ROM_NMASS]; /* initial velocities: v0, the opponent's 0 (tests set others) [m/s] */
    double gap0;            /* initial front-to-wall gap along the normal [m]               */
    double normal[3];       /* the barrier normal in the world frame (motion axis) [-]      */
    double end_time;        /* [s]                                                          */
    double out_dt;          /* output interval [s]                                          */
    rom_elem elem[ROM_NELEM];
} rom_model;

/* a model from masses, speed, gap and parameters (the verification cases build these) */
mcs_status rom_model_init(rom_model *m, const double mass[ROM_NMASS], double v0, double gap0,
                          const rom_params *p, double end_time, double out_dt, mcs_error *err);
/* from a scenario: masses from its bodies (moto_*fork*, moto_front_wheel: front; other moto_*:
 * frame; rider_*: rider), speed and gap along the barrier normal from impact:, parameters from
 * the rom: block over the defaults */
mcs_status rom_model_from_scenario(rom_model *m, const mcs_scenario *scn, mcs_error *err);
/* the same with p replacing the rom: block's parameters (the fit) */
mcs_status rom_model_rebuild(rom_model *m, const rom_params *p, mcs_error *err);
void rom_model_deinit(rom_model *m);

/* a run's histories at the output times (nt samples) */
typedef struct {
    int nt;
    double *t;                 /* [s] (nt)                                                   */
    double *x[ROM_NMASS];      /* displacement along the normal [m] (nt)                     */
    double *v[ROM_NMASS];      /* velocity [m/s] (nt)                                        */
    double *a[ROM_NMASS];      /* acceleration [m/s^2] (nt)                                  */
    double *f[ROM_NELEM];      /* element force, compression > 0 [N] (nt)                   */
    double *d[ROM_NELEM];      /* element deflection [m] (nt)                                */
    double *wall_force;        /* force on the wall (or opponent): tyre + frame + head [N]   */
    double *kinetic, *internal, *dissipated, *total; /* energies [J] (nt)                   */
    long steps;                /* CVODE steps (one-step returns, roots included)             */
    long rhs_evals;            /* right-hand side evaluations                                */
    double energy_drift;       /* max |total - total(0)| / total(0) [-]                      */
} rom_result;

/* integrate from t = 0 to the model's end time; r is allocated here (rom_result_free) */
mcs_status rom_run(const rom_model *m, rom_result *r, mcs_error *err);
void rom_result_free(rom_result *r);

/* the right-hand side (rom_step.c): accelerations acc[ROM_NMASS] and element forces f and
 * deflections d at positions x and velocities v, for the committed hysteresis states hs */
void rom_forces(const rom_model *m, const mcs_hyst_state *hs, const double *x, const double *v,
                double *acc, double *f, double *d);

/* /stage0 of an open results file (rom_out.c): time, channels, bodies, energies */
mcs_status rom_write(const rom_model *m, const rom_result *r, mcs_results *res, mcs_error *err);

#endif

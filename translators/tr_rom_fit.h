/* tr_rom_fit.h: the reduced-order model (rom/rom.h) calibrated from a stage-1 run, and its
 * error against stage-1 runs (docs/rom.md "Calibration"). The target of a barrier case: the
 * barrier's normal force (the stage-1 *_barrier_fn channels summed) and the frame's velocity
 * and acceleration along the barrier normal (/stage1/bodies/moto_frame), on a uniform grid. */
#ifndef TR_ROM_FIT_H
#define TR_ROM_FIT_H

#include "core/mcs_scenario.h"
#include "rom/rom.h"
#include "translators/tr_lm.h"

/* stage-1 signals on the grid t_i = i dt, i = 0 .. n-1 (the stage-1 file's time origin) */
typedef struct {
    int n;
    double dt;     /* [s]                                                                   */
    double v0;     /* the frame's initial speed along the normal [m/s]                      */
    double *force; /* barrier normal force [N] (n)                                          */
    double *vel;   /* frame velocity along the normal [m/s] (n)                             */
    double *acc;   /* frame acceleration along the normal, CFC 60 [m/s^2] (n)               */
    int rider;     /* 1: the run has a rider (rider_* bodies), the fields below are set     */
    double *rider_vel;   /* the rider's centre-of-mass velocity along the normal [m/s] (n)  */
    double *rider_force; /* the rider's barrier contacts (rider_*_barrier_fn) summed [N] (n) */
    double *chest_acc;   /* rider_upper_torso's acceleration along the normal, CFC 180 [m/s^2] */
} tr_rom_target;

/* read a stage-1 file over [0, t_end] at step dt; normal: the barrier normal (world); scn: the
 * run's scenario (the rider bodies' masses) */
mcs_status tr_rom_target_read(const char *h5, const mcs_scenario *scn, const double normal[3],
                              double t_end, double dt, tr_rom_target *t, mcs_error *err);
void tr_rom_target_free(tr_rom_target *t);

/* the fitted parameters: names (rom_param_names), start in m->p, bounds [lo, hi] */
typedef struct {
    int n;
    const char *const *name;
    const double *lo, *hi;
    int rider; /* 0: fit the barrier force and frame velocity; 1: the rider's barrier force and
                  centre-of-mass velocity */
} tr_rom_free;

/* the default free sets with the bounds of docs/rom.md "Calibration": the motorcycle (tyre,
 * rim, fork yield and stop, frame gap and stiffness), the rider (restraint gap and stiffness,
 * barrier gap and stiffness) */
tr_rom_free tr_rom_free_default(void);
tr_rom_free tr_rom_free_rider(void);

/* fit m's parameters to the target (two signals, equal weight) by tr_lm; m is rebuilt with the
 * fitted values */
mcs_status tr_rom_fit(rom_model *m, const tr_rom_target *t, const tr_rom_free *f,
                      tr_lm_result *res, mcs_error *err);

/* the model's error against a target */
typedef struct {
    double iso_force, iso_vel, iso_acc; /* ISO/TS 18571 ratings R [-]                     */
    double peak_force_err;              /* (max F_rom - max F_1) / max F_1 [-]            */
    double peak_acc_err;                /* (max |a_rom| - max |a_1|) / max |a_1| [-]       */
    double rebound_err;                 /* v_rom(t_end) - v_1(t_end) [m/s]                */
    /* with a rider (NAN without) */
    double iso_rider_vel, iso_rider_force, iso_chest; /* ratings of the rider's velocity and
                                                         barrier force, its acceleration (CFC
                                                         180) against the chest's [-]        */
    double peak_chest_err; /* (max |a_rider| - max |a_chest|) / max |a_chest| [-]           */
} tr_rom_error;

/* run m over the target's span and rate it against the target */
mcs_status tr_rom_error_eval(const rom_model *m, const tr_rom_target *t, tr_rom_error *e,
                             mcs_error *err);

#endif

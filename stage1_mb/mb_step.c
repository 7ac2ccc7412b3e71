/* mb_step.c: one fixed step of stage 1. The contact geometry is detected right after the ODE
 * step, at the new poses, so that the energy of this step and the forces of the next one use
 * the same geometry (mb_state_create detects once before the first step). */
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_egroup.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_prescribe.h"

#include <time.h>

static double wall(const mb_state *s)
{
    if (!s->timing) return 0;
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* close timer slot k: add the wall time since *t0 and restart it */
static void lap(mb_state *s, mb_timer k, double *t0)
{
    if (!s->timing) return;
    double t = wall(s);
    s->timer[k] += t - *t0;
    *t0 = t;
}

mcs_status mb_step(const mb_model *m, mb_state *s, mcs_error *err)
{
    double t0 = wall(s);
    /* contact: pair geometry and velocities -> contact forces on bodies, pair histories */
    mb_contact_forces(m, s);
    lap(s, MB_T_contact, &t0);
    /* restraint: joint positions and rates -> restraint and attachment loads, histories */
    mb_restraints_apply(m, s);
    lap(s, MB_T_restraint, &t0);
    /* external: gravity is ODE's world gravity (model gravity); the mean reactions of the
     * coupled FE parts' last subcycle (mb_couple.c) */
    if (m->presc) mb_prescribe_loads(m, s); /* the prescribed bodies' before the FE parts' */
    if (m->couple) mb_couple_apply(m, s);
    lap(s, MB_T_external, &t0);
    /* energy check: the committed works and s->kin -> growth or NaN stops the run (each step) */
    mcs_status st = mb_energy_check_step(m, s, err);
    if (st) return st;
    lap(s, MB_T_energy, &t0);
    /* prescribed bodies: callback at t + h -> secant velocities, the loads' work on them */
    if (m->presc && (st = mb_prescribe_begin(m, s, err))) return st;
    /* integrate: forces -> new velocities and poses (dWorldStep, checked for NaN) */
    st = mb_world_step(s->world, m->h, err);
    if (st) return st;
    s->step++;
    s->t = (double)s->step * m->h;
    /* prescribed bodies: exactly on the callback's pose and velocities at the new time */
    if (m->presc) mb_prescribe_end(m, s);
    /* energy groups: the loads of the step and the mean velocities -> the partners' work */
    if (m->egroup) mb_egroup_step(m, s);
    /* FE parts: subcycle to the new time with the attached nodes on the bodies' motion */
    if (m->couple && (st = mb_couple_advance(m, s, err))) return st;
    lap(s, MB_T_integrate, &t0);
    /* detect: new poses -> body kinematics (s->kin) and pair geometry (s->pc) */
    mb_contact_detect(m, s);
    lap(s, MB_T_detect, &t0);
    /* sensors: new velocities -> accelerations of the step */
    mb_kinematics_update(m, s);
    lap(s, MB_T_sensors, &t0);
    /* energy: kinematics and histories -> balance, growth check and output record, at the
     * output samples (and after the first step, whose accelerations t = 0 takes) */
    if (s->step % m->out_every == 0 || s->step == 1) {
        mb_energy_update(m, s);
        st = mb_energy_check(m, s, err);
        if (!st) mb_record(m, s);
    }
    lap(s, MB_T_energy, &t0);
    return st;
}

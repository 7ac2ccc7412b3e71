/* mb_couple_rx.h: restraints of the coupled FE parts that answer to the stage-1 bodies (issue 12,
 * DESIGN.md "Coupling bodies and FE parts"; docs/stage1_engine.md "Coupling to FE parts"):
 * - triggers (mb_couple_trigger.c): fe.airbags[].inflator.trigger and fe.retractors[].trigger
 *   {contact, force, delay} fire the inflator / pretensioner at t_c + delay, t_c the first ODE
 *   step time at which the named stage-1 contact's normal force (its pairs summed, the
 *   <contact>_fn channel) exceeds `force` (default: any force > 0). The contact forces are
 *   those of the step's start, so t_c is the first ODE sample at or after the true first
 *   contact: t_c - t_true in [0, h) (h the ODE step). The FE states' fire_time is set then
 *   (INFINITY until it fires); the time it fired is the attribute fire_time of
 *   /stage1/airbag/<name> and /stage1/retractor/<name>.
 * - anchors on bodies (mb_couple_anchor.c): fe.retractors[].anchor_body carries the retractor
 *   anchor (given in the world at t = 0) rigidly with the body: it moves per FE subcycle on
 *   the straight line between its body points at the ODE step's ends (as the attached nodes),
 *   and the segment's reaction on it, summed as impulses over the subcycle, loads the body in
 *   the next ODE step (the mean force, extrapolated as the attached nodes' are). Its work on
 *   the body is external work of the coupled balance, like the retractor's work on the belt
 *   node is in the FE kernel's (the retractor is outside the structure, fe/fe_restraint.h).
 *   fe.sliprings[].body is an attached node (fe/scn/fe_scn_build.c): mb_couple.c carries it. */
#ifndef MB_COUPLE_RX_H
#define MB_COUPLE_RX_H

#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "stage1_mb/mb_model.h"

enum { MB_TRIG_BAG, MB_TRIG_RETRACTOR };

typedef struct {
    int kind;     /* MB_TRIG_BAG | MB_TRIG_RETRACTOR                          */
    int index;    /* bag / retractor index in the FE model [-]                */
    int contact;  /* stage-1 contact (mb_model.contact) [-]                   */
    double force; /* normal force it must exceed [N] (0: any force > 0)      */
    double delay; /* firing delay after that [s]                              */
} mb_couple_trig;

typedef struct mb_couple_rx {
    int ntrig;
    mb_couple_trig *trig; /* (ntrig)                                                        */
    int nanchor;
    int *anchor_ret;      /* retractor of each body-carried anchor (nanchor)                */
    int *anchor_body;     /* carrying body (nanchor)                                        */
    double *anchor_local; /* anchor in the body frame, about the CG (nanchor x 3) [m]       */
} mb_couple_rx;

typedef struct mb_couple_rx_state {
    double *trig_time;    /* first time the contact carried more than `force`; INFINITY not
                             yet (ntrig) [s]                                                */
    double *xa;           /* anchors in the world at the ODE step's start (nanchor x 3) [m] */
    double *x1;           /* ... at its end (nanchor x 3) [m]                               */
    double *imp;          /* reaction impulse on each anchor this ODE step (nanchor x 3) [N s] */
    double *force;        /* its mean force, applied to the body in the next step (nanchor x 3) */
    double *fmean;        /* mean force of the last subcycle (nanchor x 3) [N]              */
    double w_anchor;      /* work of the anchor reactions on the bodies [J]                 */
    double w_anchor_presc; /* the part of it on prescribed bodies (mb_prescribe.h) [J]      */
} mb_couple_rx_state;

/* model: triggers and anchors of the scenario's fe: block (m->couple built, its FE model
 * made); errors at FILE:LINE:COL of the key (unknown contact, fire_time with trigger) */
mcs_status mb_couple_anchor_build(const mcs_node *fe, mb_model *m, mb_couple_rx *rx,
                                  mcs_error *err);
mcs_status mb_couple_rx_build(const mcs_scenario *scn, mb_model *m, mcs_error *err);
void mb_couple_rx_destroy(mb_couple_rx **p);
/* state: allocate cs->rx (after cs->fe), and unfire the triggered bags and retractors of the
 * FE state */
struct mb_couple_state;
mcs_status mb_couple_rx_state_create(const mb_model *m, struct mb_couple_state *cs,
                                     mcs_error *err);
void mb_couple_rx_state_destroy(mb_couple_rx_state **p);

/* triggers: at the start of mb_couple_advance (s->t the step's end, the pair forces those of
 * its start): fire what the contacts call for */
void mb_couple_trigger_check(const mb_model *m, mb_state *s);
/* the time it fired [s] (INFINITY: not fired) of bag / retractor i */
double mb_couple_fire_time(const mb_model *m, const mb_state *s, int kind, int i);
/* the attribute fire_time on /stage1/airbag/<name> and /stage1/retractor/<name> of every bag
 * and retractor whose group exists (NaN: not fired by the run's end s->t) */
mcs_status mb_couple_trigger_write(const mb_model *m, const mb_state *s, mcs_results *r,
                                   mcs_error *err);

/* anchors, from mb_couple.c: apply the mean reactions (ODE step start) */
void mb_couple_anchor_apply(const mb_model *m, mb_state *s);
/* at the start of mb_couple_advance: the anchors' body points at the step's end, the work of
 * the last forces over the step; zero the impulses */
void mb_couple_anchor_begin(const mb_model *m, mb_state *s);
/* before an FE step from t0 + tau h (tau in [0, 1)): the anchors of the FE state there */
void mb_couple_anchor_move(const mb_model *m, mb_state *s, double tau);
/* after that FE step: its reaction impulses (force at its start times dth) */
void mb_couple_anchor_collect(const mb_model *m, mb_state *s, double dth);
/* after the subcycle: mean forces over h, extrapolated by alpha (mb_couple.c) */
void mb_couple_anchor_end(const mb_model *m, mb_state *s, double h, double alpha, int started);

#endif

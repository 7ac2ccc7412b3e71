/* fe_retractor: a belt retractor with pretensioner and load limiter at the outer end of a belt
 * (the 2023 paper, §2.3.1: pretensioner pay-in Eq. 3, load limit 2 kN, firing at 12 ms).
 *
 * The retractor sets how much webbing it has given out: the payout L [m] (positive out of
 * the retractor, negative pulled in). The adjacent belt segment's unstretched length grows by
 * L, so its tension is F = k_b (stretch - L) with k_b its axial stiffness EA/l0. Each step the
 * kernel passes the force the segment would carry with the current payout at the new node
 * positions (signed: negative is slack, -k_b times the slack length) and k_b; the retractor
 * returns the payout change and the force it lets through. In order, per step:
 *   1. unlocked (before locking): the spool reels in or pays out so that the tension equals
 *      the small spool (comfort) force;
 *   2. pretensioner (t >= t_fire): prescribed pull-in, Eq. 3:
 *        L_pay-in(t) = 0 (t < t_fire); -(100/15 mm/ms)(t - t_fire) (t_fire <= t <= t_fire +
 *        15 ms); -100 mm afterwards
 *      (a table in time since firing; the default is Eq. 3), stalled when the tension
 *      reaches the pretensioner's maximum force (0: never);
 *   3. locked: the spool locks at firing, at the lock time, or when the payout rate exceeds
 *      the webbing-sensor rate; then the film spool gives an elastic payout F / k_spool in
 *      series with the belt (k_spool = 0: rigid);
 *   4. load limiter (locked only): the tension cannot exceed F_limit; the excess is paid out
 *      irreversibly and F_limit x payout is absorbed (torsion bar).
 * No allocation after fe_retractor_model_create. Units SI. */
#ifndef FE_RETRACTOR_H
#define FE_RETRACTOR_H

#include "core/mcs_curve.h"
#include "core/mcs_error.h"

#define FE_RETRACTOR_TABLE_MAX 32 /* most points in the pay-in table */

typedef struct {
    double fire_time; /* pretensioner firing time [s] (0.012, paper)            */
    int npayin;       /* points in the pay-in table; 0 = Eq. 3 of the paper     */
    double payin_time[FE_RETRACTOR_TABLE_MAX];   /* time since firing [s]                   */
    double payin_length[FE_RETRACTOR_TABLE_MAX]; /* payout, <= 0 is pulled in [m]           */
    double pretensioner_max_force; /* stall force of the pretensioner; 0 = none [N]         */
    double load_limit;             /* load-limiter force [N] (2000, paper); 0 = no limiter   */
    double spool_stiffness;        /* film-spool stiffness once locked; 0 = rigid [N/m]      */
    double spool_force;            /* tension kept by the unlocked spool [N] (5)             */
    double lock_time;              /* locks at this time even without firing; < 0 never [s] */
    double lock_payout_rate;       /* webbing sensor: locks when the payout rate exceeds
                                      this; 0 = no sensor [m/s]                              */
} fe_retractor_desc;

fe_retractor_desc fe_retractor_desc_default(void);

typedef struct {
    char name[64];                 /* used in messages                                       */
    double fire_time;              /* [s]                                                    */
    mcs_curve *payin;              /* payout vs. time since firing [m]                       */
    double pretensioner_max_force; /* [N]                                                   */
    double load_limit;             /* [N]; 0 none                                            */
    double spool_stiffness;        /* [N/m]; 0 rigid                                         */
    double spool_force;            /* [N]                                                    */
    double lock_time;              /* [s]; < 0 never                                         */
    double lock_payout_rate;       /* [m/s]; 0 none                                          */
} fe_retractor_model;

/* what changes; the scalar fields declared once, X(name, unit, what), also the channels */
#define FE_RETRACTOR_STATE_FIELDS(X)                                                               \
    X(time, "s", "time")                                                                           \
    X(payout, "m", "total webbing given out since t0 (< 0 pulled in)")                             \
    X(payout_pretensioner, "m", "pulled in by the pretensioner (<= 0)")                            \
    X(payout_limiter, "m", "paid out by the load limiter (>= 0)")                                  \
    X(payout_spool, "m", "elastic film-spool payout F / k_spool")                                  \
    X(payout_unlocked, "m", "given out or reeled in while unlocked")                               \
    X(payout_rate, "m/s", "payout rate over the last step")                                        \
    X(force, "N", "belt tension at the retractor (>= 0)")                                          \
    X(energy_limiter, "J", "energy absorbed by the load limiter")                                  \
    X(energy_pretensioner, "J", "work done by the pretensioner on the belt")

typedef struct {
#define FE_RETRACTOR_X_DECL(name, unit, what) double name;
    FE_RETRACTOR_STATE_FIELDS(FE_RETRACTOR_X_DECL)
#undef FE_RETRACTOR_X_DECL
    int locked;       /* spool locked [-]                          */
    int fired;        /* pretensioner fired [-]                    */
    int stalled;      /* pretensioner stalled in the last step [-] */
    double fire_time; /* pretensioner firing time of this run: the model's at init; a coupling
                         may set it while not fired (a trigger, INFINITY until it fires;
                         stage1_mb/mb_couple_trigger.c) [s] */
} fe_retractor_state;

enum {
#define FE_RETRACTOR_X_COUNT(name, unit, what) FE_RETRACTOR_CH_##name,
    FE_RETRACTOR_STATE_FIELDS(FE_RETRACTOR_X_COUNT)
#undef FE_RETRACTOR_X_COUNT
        FE_RETRACTOR_NCHANNEL
};
extern const char *const fe_retractor_channel_name[FE_RETRACTOR_NCHANNEL];
extern const char *const fe_retractor_channel_unit[FE_RETRACTOR_NCHANNEL];
double fe_retractor_channel(const fe_retractor_state *s, int channel);

mcs_status fe_retractor_model_create(const char *name, const fe_retractor_desc *d,
                                     fe_retractor_model **out, mcs_error *err);
void fe_retractor_model_destroy(fe_retractor_model **p);

void fe_retractor_state_init(const fe_retractor_model *m, fe_retractor_state *s, double t);

/* pretensioner payout (<= 0) prescribed at absolute time t [m] (Eq. 3 by default), for the
 * model's firing time; fe_retractor_payin_at for a firing time tf [s] */
double fe_retractor_payin(const fe_retractor_model *m, double t);
double fe_retractor_payin_at(const fe_retractor_model *m, double tf, double t);

/* advance from s->time to s->time + dt. force_trial: tension of the adjacent segment at the
 * new positions with the current payout, signed (slack < 0) [N]; k_belt: its axial stiffness
 * EA/l0 > 0 [N/m]. Afterwards the segment's unstretched length must grow by the change of
 * s->payout, and its tension is s->force. Returns MCS_ERR_NUMERIC on a non-finite input. */
mcs_status fe_retractor_advance(const fe_retractor_model *m, fe_retractor_state *s, double dt,
                                double force_trial, double k_belt, mcs_error *err);

#endif

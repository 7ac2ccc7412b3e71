/* fe_retractor: belt retractor with pretensioner (paper Eq. 3) and load limiter. The update is
 * algebraic per step (a projection of the belt tension onto what the retractor admits), so no
 * ODE integrator is needed: the belt dynamics live in the FE kernel. */
#include "fe/fe_retractor.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

fe_retractor_desc fe_retractor_desc_default(void)
{
    fe_retractor_desc d;
    memset(&d, 0, sizeof(d));
    d.fire_time = 0.012;   /* paper §2.3.1: 12 ms after first contact */
    d.load_limit = 2000.0; /* paper: F_load-limit = 2 kN */
    d.spool_force = 5.0;   /* small comfort tension (assumed, not in the paper) */
    d.lock_time = -1.0;
    return d;
}

static mcs_status check_desc(const char *name, const fe_retractor_desc *d, mcs_error *err)
{
    if (!isfinite(d->fire_time) || !isfinite(d->lock_time))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: fire_time and lock_time must be finite", name);
    if (!(d->load_limit >= 0.0 && d->spool_stiffness >= 0.0 && d->spool_force >= 0.0 &&
          d->pretensioner_max_force >= 0.0 && d->lock_payout_rate >= 0.0) ||
        !isfinite(d->load_limit + d->spool_stiffness + d->spool_force + d->pretensioner_max_force +
                  d->lock_payout_rate))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: load_limit, spool_stiffness, spool_force, pretensioner_max_force "
                       "and lock_payout_rate must be finite and >= 0",
                       name);
    if (d->load_limit > 0.0 && d->spool_force >= d->load_limit)
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: spool_force %g N must be below load_limit %g N",
                       name, d->spool_force, d->load_limit);
    if (d->npayin < 0 || d->npayin > FE_RETRACTOR_TABLE_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: %d pay-in points (0..%d)", name, d->npayin,
                       FE_RETRACTOR_TABLE_MAX);
    for (int i = 0; i < d->npayin; i++)
        if (!(d->payin_length[i] <= 0.0 && isfinite(d->payin_length[i])))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%s: pay-in point %d: length %g m must be <= 0 (pulled in)", name, i,
                           d->payin_length[i]);
    return MCS_OK;
}

mcs_status fe_retractor_model_create(const char *name, const fe_retractor_desc *d,
                                     fe_retractor_model **out, mcs_error *err)
{
    *out = NULL;
    mcs_status st = check_desc(name, d, err);
    if (st != MCS_OK) return st;
    fe_retractor_model *m = calloc(1, sizeof(*m));
    if (!m) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: retractor model", name);
    snprintf(m->name, sizeof(m->name), "%s", name);
    m->fire_time = d->fire_time;
    m->pretensioner_max_force = d->pretensioner_max_force;
    m->load_limit = d->load_limit;
    m->spool_stiffness = d->spool_stiffness;
    m->spool_force = d->spool_force;
    m->lock_time = d->lock_time;
    m->lock_payout_rate = d->lock_payout_rate;
    /* paper Eq. 3: -100/15 mm/ms for 15 ms, then -100 mm held */
    const double eq3_t[2] = {0.0, 0.015}, eq3_l[2] = {0.0, -0.100};
    char cname[96];
    snprintf(cname, sizeof(cname), "%s pay-in", name);
    st = d->npayin > 0 ? mcs_curve_create(cname, d->npayin, d->payin_time, d->payin_length,
                                          MCS_EXTRAP_CONSTANT, MCS_EXTRAP_CONSTANT, &m->payin, err)
                       : mcs_curve_create(cname, 2, eq3_t, eq3_l, MCS_EXTRAP_CONSTANT,
                                          MCS_EXTRAP_CONSTANT, &m->payin, err);
    if (st != MCS_OK) {
        free(m);
        return st;
    }
    *out = m;
    return MCS_OK;
}

void fe_retractor_model_destroy(fe_retractor_model **p)
{
    if (!p || !*p) return;
    mcs_curve_destroy(&(*p)->payin);
    free(*p);
    *p = NULL;
}

void fe_retractor_state_init(const fe_retractor_model *m, fe_retractor_state *s, double t)
{
    memset(s, 0, sizeof(*s));
    s->time = t;
    s->force = m->spool_force;
    s->fire_time = m->fire_time;
    s->fired = t >= m->fire_time;
    s->locked = s->fired || (m->lock_time >= 0.0 && t >= m->lock_time);
}

double fe_retractor_payin_at(const fe_retractor_model *m, double tf, double t)
{
    /* the table's first point is taken at firing; nothing before (Eq. 3, first case) */
    return t < tf ? 0.0 : mcs_curve_eval(m->payin, t - tf);
}

double fe_retractor_payin(const fe_retractor_model *m, double t)
{
    return fe_retractor_payin_at(m, m->fire_time, t);
}

/* locked spool: pretensioner, film spool in series, load limiter; F is the trial tension */
static void advance_locked(const fe_retractor_model *m, fe_retractor_state *s, double t0, double t1,
                           double F, double kb)
{
    /* pretensioner: the prescribed increment, stalled at its maximum force */
    double dlp = fe_retractor_payin_at(m, s->fire_time, t1) - fe_retractor_payin_at(m, s->fire_time, t0);
    s->stalled = 0;
    if (dlp < 0.0 && m->pretensioner_max_force > 0.0 && F - kb * dlp > m->pretensioner_max_force) {
        dlp = fmin(0.0, (F - m->pretensioner_max_force) / kb);
        s->stalled = 1;
    }
    double F1 = F - kb * dlp;
    /* film spool in series: F2 = F1 - kb (F2 / ks - Ls_old) while in tension */
    double ls_old = s->payout_spool, F2 = F1, ls_new = 0.0;
    if (m->spool_stiffness > 0.0) {
        double ks = m->spool_stiffness;
        F2 = (F1 + kb * ls_old) / (1.0 + kb / ks);
        if (F2 < 0.0) F2 = F1 + kb * ls_old; /* the spool recoils fully; the belt goes slack */
        ls_new = fmax(F2, 0.0) / ks;
    }
    /* load limiter: tension capped, the excess paid out irreversibly */
    double dll = 0.0;
    if (m->load_limit > 0.0 && F2 > m->load_limit) {
        F2 = m->load_limit;
        if (m->spool_stiffness > 0.0) ls_new = F2 / m->spool_stiffness;
        dll = (F1 - F2) / kb - (ls_new - ls_old);
        s->energy_limiter += m->load_limit * dll;
    }
    /* pretensioner work: pull-in times the mean of the tensions before and after the step */
    s->energy_pretensioner += -dlp * 0.5 * (fmax(F, 0.0) + fmax(F2, 0.0));
    s->payout += dlp + (ls_new - ls_old) + dll;
    s->payout_pretensioner += dlp;
    s->payout_spool = ls_new;
    s->payout_limiter += dll;
    s->force = fmax(F2, 0.0);
}

mcs_status fe_retractor_advance(const fe_retractor_model *m, fe_retractor_state *s, double dt,
                                double force_trial, double k_belt, mcs_error *err)
{
    if (!(dt > 0.0 && isfinite(dt)) || !isfinite(force_trial) || !(k_belt > 0.0) ||
        !isfinite(k_belt))
        return MCS_ERR(err, MCS_ERR_NUMERIC,
                       "%s: at t = %.9g s: step %g s, belt force %g N, belt stiffness %g N/m "
                       "(step and stiffness must be > 0, all finite)",
                       m->name, s->time, dt, force_trial, k_belt);
    double t0 = s->time, t1 = t0 + dt, L0 = s->payout;
    if (!s->fired && t1 >= s->fire_time) s->fired = s->locked = 1;
    if (!s->locked && m->lock_time >= 0.0 && t1 >= m->lock_time) s->locked = 1;
    if (!s->locked) {
        /* the spool keeps its comfort tension; the webbing sensor locks on a fast pull-out */
        double dl = (force_trial - m->spool_force) / k_belt;
        if (m->lock_payout_rate > 0.0 && dl / dt > m->lock_payout_rate) {
            s->locked = 1;
        } else {
            s->payout += dl;
            s->payout_unlocked += dl;
            s->force = m->spool_force;
        }
    }
    if (s->locked) advance_locked(m, s, t0, t1, force_trial, k_belt);
    s->payout_rate = (s->payout - L0) / dt;
    s->time = t1;
    return MCS_OK;
}

const char *const fe_retractor_channel_name[FE_RETRACTOR_NCHANNEL] = {
#define FE_RETRACTOR_X_NAME(name, unit, what) #name,
    FE_RETRACTOR_STATE_FIELDS(FE_RETRACTOR_X_NAME)
#undef FE_RETRACTOR_X_NAME
};

const char *const fe_retractor_channel_unit[FE_RETRACTOR_NCHANNEL] = {
#define FE_RETRACTOR_X_UNIT(name, unit, what) unit,
    FE_RETRACTOR_STATE_FIELDS(FE_RETRACTOR_X_UNIT)
#undef FE_RETRACTOR_X_UNIT
};

double fe_retractor_channel(const fe_retractor_state *s, int channel)
{
    switch (channel) {
#define FE_RETRACTOR_X_CASE(name, unit, what)                                                      \
    case FE_RETRACTOR_CH_##name:                                                                   \
        return s->name;
        FE_RETRACTOR_STATE_FIELDS(FE_RETRACTOR_X_CASE)
#undef FE_RETRACTOR_X_CASE
    }
    return NAN;
}

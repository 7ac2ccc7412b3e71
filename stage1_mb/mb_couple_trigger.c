/* mb_couple_trigger.c: inflators and pretensioners fired by a stage-1 contact (mb_couple_rx.h).
 * Resolution: the pair forces are evaluated once per ODE step, at its start t_n; the first t_n
 * at which the contact's summed normal force exceeds `force` is taken as the contact time t_c,
 * so t_c lies within one ODE step h after the true crossing ([t_true, t_true + h)), and the
 * FE state's fire_time is set to t_c + delay before the FE subcycles from t_n, which therefore
 * see it (delay 0: the inflator's table starts at t_n). */
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_rx.h"
#include "fe/fe_restraint.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int find_contact(const mb_model *m, const char *name)
{
    for (int c = 0; name && c < m->ncontact; c++)
        if (strcmp(m->contact[c].name, name) == 0) return c;
    return -1;
}

/* one trigger map t of a bag / retractor item (whose fire_time key is `fire`) */
static mcs_status add_trig(const mb_model *m, mb_couple_rx *rx, const mcs_node *t,
                           const mcs_node *fire, int kind, int index, mcs_error *err)
{
    if (mcs_node_kind(fire) != MCS_NODE_NULL)
        return mcs_node_error(fire, err, MCS_ERR_KEY,
                              "fire_time and trigger exclude each other: give one");
    const mcs_node *cn = mcs_node_get(t, "contact");
    int c = find_contact(m, mcs_node_str(cn));
    if (c < 0)
        return mcs_node_error(cn, err, MCS_ERR_KEY,
                              "unknown stage-1 contact '%s' (contacts[].name, or <a>-<b>)",
                              mcs_node_str(cn) ? mcs_node_str(cn) : "");
    mb_couple_trig *g = &rx->trig[rx->ntrig++];
    g->kind = kind;
    g->index = index;
    g->contact = c;
    g->force = mcs_node_num_or(t, "force", 0);
    g->delay = mcs_node_num_or(t, "delay", 0);
    return MCS_OK;
}

static mcs_status build_triggers(const mcs_node *fe, mb_model *m, mb_couple_rx *rx, mcs_error *err)
{
    const fe_model *fm = m->couple->fe.model;
    const mcs_node *bags = mcs_node_get(fe, "airbags"), *rets = mcs_node_get(fe, "retractors");
    int n = mcs_node_len(bags) + mcs_node_len(rets);
    rx->trig = calloc((size_t)(n ? n : 1), sizeof *rx->trig);
    if (!rx->trig) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    mcs_status st = MCS_OK;
    for (int i = 0; i < mcs_node_len(bags) && !st; i++) {
        const mcs_node *b = mcs_node_at(bags, i), *inf = mcs_node_get(b, "inflator");
        const mcs_node *t = mcs_node_get(inf, "trigger");
        if (mcs_node_kind(t) != MCS_NODE_MAP) continue;
        int k = fe_airbag_find(fm, mcs_node_str(mcs_node_get(b, "name")));
        if (k >= 0) st = add_trig(m, rx, t, mcs_node_get(inf, "fire_time"), MB_TRIG_BAG, k, err);
    }
    for (int i = 0; i < mcs_node_len(rets) && !st; i++) {
        const mcs_node *r = mcs_node_at(rets, i), *t = mcs_node_get(r, "trigger");
        if (mcs_node_kind(t) != MCS_NODE_MAP) continue;
        int k = fe_retractor_find(fm, mcs_node_str(mcs_node_get(r, "name")));
        if (k >= 0)
            st = add_trig(m, rx, t, mcs_node_get(r, "fire_time"), MB_TRIG_RETRACTOR, k, err);
    }
    return st;
}

mcs_status mb_couple_rx_build(const mcs_scenario *scn, mb_model *m, mcs_error *err)
{
    mb_couple_rx *rx = calloc(1, sizeof *rx);
    if (!rx) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    m->couple->rx = rx;
    const mcs_node *fe = mcs_node_get(mcs_scenario_root(scn), "fe");
    mcs_status st = build_triggers(fe, m, rx, err);
    if (!st) st = mb_couple_anchor_build(fe, m, rx, err);
    return st;
}

void mb_couple_rx_destroy(mb_couple_rx **p)
{
    mb_couple_rx *rx = p ? *p : NULL;
    if (!rx) return;
    free(rx->trig), free(rx->anchor_ret), free(rx->anchor_body), free(rx->anchor_local);
    free(rx);
    *p = NULL;
}

mcs_status mb_couple_rx_state_create(const mb_model *m, mb_couple_state *cs, mcs_error *err)
{
    const mb_couple *c = m->couple;
    const mb_couple_rx *rx = c->rx;
    mb_couple_rx_state *q = calloc(1, sizeof *q);
    if (!q) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    cs->rx = q;
    size_t nt = (size_t)(rx->ntrig ? rx->ntrig : 1),
           na = 3 * (size_t)(rx->nanchor ? rx->nanchor : 1);
    q->trig_time = calloc(nt, sizeof *q->trig_time);
    q->xa = calloc(na, sizeof *q->xa);
    q->x1 = calloc(na, sizeof *q->x1);
    q->imp = calloc(na, sizeof *q->imp);
    q->force = calloc(na, sizeof *q->force);
    q->fmean = calloc(na, sizeof *q->fmean);
    if (!q->trig_time || !q->xa || !q->x1 || !q->imp || !q->force || !q->fmean)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    /* the triggered bags and retractors wait for their contact */
    struct fe_restraint_state *fr = cs->fe->restraint;
    for (int i = 0; i < rx->ntrig; i++) {
        const mb_couple_trig *g = &rx->trig[i];
        q->trig_time[i] = INFINITY;
        if (g->kind == MB_TRIG_BAG) {
            fr->bag[g->index].fire_time = INFINITY;
            fr->bag[g->index].mass_flow_in = 0;
        } else {
            const fe_retractor_model *rm = c->fe.model->restraints->retractor[g->index].model;
            fe_retractor_state *r = &fr->retractor[g->index];
            r->fire_time = INFINITY;
            r->fired = 0;
            r->locked = rm->lock_time >= 0 && r->time >= rm->lock_time;
        }
    }
    /* the anchors at t = 0: the model's (the body poses of t = 0 carry them) */
    const struct fe_restraints *r = c->fe.model->restraints;
    for (int a = 0; a < rx->nanchor; a++)
        for (int i = 0; i < 3; i++)
            q->xa[3 * a + i] = q->x1[3 * a + i] = r->retractor[rx->anchor_ret[a]].anchor[i];
    return MCS_OK;
}

void mb_couple_rx_state_destroy(mb_couple_rx_state **p)
{
    mb_couple_rx_state *q = p ? *p : NULL;
    if (!q) return;
    free(q->trig_time), free(q->xa), free(q->x1), free(q->imp), free(q->force), free(q->fmean);
    free(q);
    *p = NULL;
}

/* the FE state's firing time of a trigger's bag or retractor */
static double *fire_slot(const mb_couple_trig *g, fe_state *f)
{
    return g->kind == MB_TRIG_BAG ? &f->restraint->bag[g->index].fire_time
                                  : &f->restraint->retractor[g->index].fire_time;
}

void mb_couple_trigger_check(const mb_model *m, mb_state *s)
{
    const mb_couple_rx *rx = m->couple->rx;
    mb_couple_rx_state *q = s->couple->rx;
    fe_state *f = s->couple->fe;
    for (int i = 0; i < rx->ntrig; i++) {
        if (q->trig_time[i] < INFINITY) continue;
        const mb_couple_trig *g = &rx->trig[i];
        const mb_contact_def *d = &m->contact[g->contact];
        double fn = 0;
        for (int p = d->pair0; p < d->pair0 + d->npair; p++)
            fn += s->pair[p].fn;
        if (!(fn > g->force)) continue;
        /* the forces are those of the step's start, where the FE subcycle begins */
        q->trig_time[i] = f->time;
        *fire_slot(g, f) = f->time + g->delay;
    }
}

double mb_couple_fire_time(const mb_model *m, const mb_state *s, int kind, int i)
{
    const struct fe_restraint_state *r = s->couple->fe->restraint;
    (void)m;
    return kind == MB_TRIG_BAG ? r->bag[i].fire_time : r->retractor[i].fire_time;
}

mcs_status mb_couple_trigger_write(const mb_model *m, const mb_state *s, mcs_results *r,
                                   mcs_error *err)
{
    if (!m->couple) return MCS_OK;
    const struct fe_restraints *fr = m->couple->fe.model->restraints;
    mcs_status st = MCS_OK;
    char path[256];
    for (int k = 0; fr && k < 2 && !st; k++) {
        int n = k == MB_TRIG_BAG ? fr->nbag : fr->nretractor;
        for (int i = 0; i < n && !st; i++) {
            snprintf(path, sizeof path, "/stage%d/%s/%s", mb_out_stage(m),
                     k == MB_TRIG_BAG ? "airbag" : "retractor",
                     k == MB_TRIG_BAG ? fr->bag[i].name : fr->retractor[i].name);
            if (!mcs_results_exists(r, path)) continue;
            /* a firing time past the run's end (or a trigger that never came): NaN */
            double t = mb_couple_fire_time(m, s, k, i);
            st = mcs_results_set_attr_double(r, path, "fire_time", t <= s->t ? t : NAN, err);
        }
    }
    return st;
}

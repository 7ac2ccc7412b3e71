/* fe_state: allocation (once), reset, energy names and per-part energies. */
#include "fe/fe_contact.h"
#include "fe/fe_elem.h"
#include "fe/fe_restraint.h"
#include "fe/fe_slipring.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *const fe_energy_name[FE_NENERGY] = {
#define FE_X_NAME(name) #name,
    FE_ENERGY_LIST(FE_X_NAME)
#undef FE_X_NAME
};

const char *const fe_stage_name[FE_NSTAGE] = {
#define FE_X_NAME(name) #name,
    FE_STAGE_LIST(FE_X_NAME)
#undef FE_X_NAME
};

/* scratch arena for per-step temporaries of later modules (contact buckets) [B] */
#define FE_ARENA_BYTES (64 * 1024)

void fe_state_destroy(fe_state **p)
{
    if (!p || !*p) return;
    fe_state *s = *p;
#define FE_X_FREE(T, name, n, k, unit, doc) free(s->name);
    FE_STATE_ARRAYS(FE_X_FREE)
#undef FE_X_FREE
    mcs_arena_destroy(&s->arena);
    fe_restraint_state_destroy(&s->restraint);
    fe_slipring_state_destroy(&s->slipring);
    fe_contact_state_destroy(&s->contact);
    free(s);
    *p = NULL;
}

mcs_status fe_state_create(const fe_model *m, fe_state **out, mcs_error *err)
{
    *out = NULL;
    fe_state *s = calloc(1, sizeof *s);
    if (!s) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (state)");
    s->bytes = sizeof *s + FE_ARENA_BYTES;
#define FE_X_ALLOC(T, name, n, k, unit, doc)                                                       \
    {                                                                                              \
        size_t cnt = (size_t)(m->n) * (k);                                                         \
        s->name = calloc(cnt ? cnt : 1, sizeof(T));                                                \
        if (!s->name) {                                                                            \
            fe_state_destroy(&s);                                                                  \
            return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (state %s)", #name);            \
        }                                                                                          \
        s->bytes += cnt * sizeof(T);                                                               \
    }
    FE_STATE_ARRAYS(FE_X_ALLOC)
#undef FE_X_ALLOC
    mcs_status st = mcs_arena_create(FE_ARENA_BYTES, &s->arena, err);
    if (st == MCS_OK) st = fe_restraint_state_create(m, &s->restraint, &s->bytes, err);
    if (st == MCS_OK) st = fe_slipring_state_create(m, &s->slipring, &s->bytes, err);
    if (st == MCS_OK && m->contact) {
        st = fe_contact_state_create(m, &s->contact, err);
        if (st == MCS_OK) s->bytes += s->contact->bytes;
    }
    if (st != MCS_OK) {
        fe_state_destroy(&s);
        return st;
    }
    fe_state_reset(m, s);
    *out = s;
    return MCS_OK;
}

void fe_state_reset(const fe_model *m, fe_state *s)
{
#define FE_X_ZERO(T, name, n, k, unit, doc) memset(s->name, 0, (size_t)(m->n) * (k) * sizeof(T));
    FE_STATE_ARRAYS(FE_X_ZERO)
#undef FE_X_ZERO
    memcpy(s->node_x, m->node_x0, sizeof(double) * 3 * (size_t)m->nnode);
    memcpy(s->node_v, m->node_v0, sizeof(double) * 3 * (size_t)m->nnode);
    memcpy(s->node_w, m->node_w0, sizeof(double) * 3 * (size_t)m->nnode);
    for (int ip = 0; ip < m->npart; ip++) s->part_bad_elem[ip] = -1;
    s->time = s->dt_prev = s->energy_time = 0;
    s->dt = m->dt_initial;
    for (int k = 0; k < FE_DT_WINDOW; k++) s->dt_win[k] = INFINITY;
    s->nstep = 0;
    memset(s->energy, 0, sizeof s->energy);
    memset(s->work_pending, 0, sizeof s->work_pending);
    memset(s->wall_normal, 0, sizeof s->wall_normal);
    memset(s->timer, 0, sizeof s->timer);
    s->work_ext = s->work_damp = s->energy0 = s->energy_ref = 0;
    s->bad_node = -1;
    s->neroded = 0;
    s->erode_first = s->erode_last = 0;
    s->dt_part = s->dt_elem = -1;
    s->nhist = 0;
    s->hist_dropped = 0;
    s->hist_next = 0;
    mcs_error_clear(&s->err);
    mcs_arena_reset(s->arena, 0);
    fe_restraint_state_reset(m, s);
    fe_slipring_state_reset(m, s);
    fe_solid_reset(m, s);
    if (s->contact) fe_contact_state_reset(m, s->contact);
}

double fe_part_energy(const fe_model *m, const fe_state *s, int part, fe_energy_kind k)
{
    if (part < 0 || part >= m->npart || k < 0 || k >= FE_NENERGY) return NAN;
    if (k == FE_E_kinetic && s->nstep == 0) { /* before the first step: the initial velocities' */
        double e = 0;
        for (int n = 0; n < m->nnode; n++) {
            if (m->node_part[n] != part) continue;
            const double *v = s->node_v + 3 * n, *w = s->node_w + 3 * n;
            e += 0.5 * m->node_mass[n] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            e += 0.5 * m->node_inertia[n] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        }
        return e;
    }
    return s->part_energy[FE_NENERGY * part + k];
}

double fe_stable_dt(const fe_model *m, const fe_state *s)
{
    double dt = INFINITY;
    for (int ip = 0; ip < m->npart; ip++) {
        int e;
        dt = fmin(dt, fe_part_dt(m, ip, s->node_x, &e));
    }
    dt *= m->opts.dt_scale;
    if (m->opts.dt_max > 0) dt = fmin(dt, m->opts.dt_max);
    return dt;
}

/* fe_slipring: builder list, model build (ring node, the two sides, checks) and state
 * lifecycle of the belt slip rings (fe_slipring.h). The per-step return map is
 * fe_slipring_step.c. */
#include "fe/fe_slipring.h"
#include "fe/fe_builder_impl.h"
#include "fe/fe_restraint.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct fe_slipring_list {
    int n, cap;
    fe_slipring_desc *d;
};

fe_slipring_desc fe_slipring_desc_default(void)
{
    fe_slipring_desc d;
    memset(&d, 0, sizeof d);
    d.node = -1;
    d.lock_time = -1;
    return d;
}

void fe_slipring_list_free(fe_builder *b)
{
    if (!b->sliprings) return;
    free(b->sliprings->d);
    free(b->sliprings);
    b->sliprings = NULL;
}

static int named(const char *name)
{
    return name[0] && memchr(name, 0, FE_NAME_MAX) != NULL;
}

double *fe_builder_slipring_point(fe_builder *b, const char *name)
{
    struct fe_slipring_list *l = b->sliprings;
    for (int i = 0; l && name && i < l->n; i++)
        if (strcmp(l->d[i].name, name) == 0) return l->d[i].point;
    return NULL;
}

mcs_status fe_builder_add_slipring(fe_builder *b, const fe_slipring_desc *d, mcs_error *err)
{
    if (!b->sliprings) b->sliprings = calloc(1, sizeof *b->sliprings);
    struct fe_slipring_list *l = b->sliprings;
    if (!l) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding a slip ring");
    if (!named(d->name))
        return MCS_ERR(err, MCS_ERR_KEY, "fe: a slip ring needs a name (< %d characters)",
                       FE_NAME_MAX);
    for (int i = 0; i < l->n; i++)
        if (strcmp(l->d[i].name, d->name) == 0)
            return MCS_ERR(err, MCS_ERR_KEY, "fe: slip ring '%s' is defined twice", d->name);
    if (!(d->friction >= 0) || !isfinite(d->friction) || !isfinite(d->lock_time) ||
        !(d->min_length >= 0) || !isfinite(d->min_length) ||
        !isfinite(d->point[0] + d->point[1] + d->point[2]))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: slip ring '%s': friction and min_length must be finite and >= 0, "
                       "lock_time and point finite",
                       d->name);
    if (!memchr(d->part, 0, FE_NAME_MAX) || !memchr(d->retractor, 0, FE_NAME_MAX))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: slip ring '%s': part or retractor name too long",
                       d->name);
    if (l->n == l->cap) {
        int nc = l->cap ? 2 * l->cap : 4;
        fe_slipring_desc *q = realloc(l->d, (size_t)nc * sizeof *q);
        if (!q) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding a slip ring");
        l->d = q;
        l->cap = nc;
    }
    l->d[l->n++] = *d;
    return MCS_OK;
}

/* the ring node: given, or the node of the part nearest to the point */
static mcs_status ring_node(const fe_builder *b, const fe_model *m, const fe_slipring_desc *d,
                            int *node, mcs_error *err)
{
    if (d->node >= 0) {
        if (d->node >= m->nnode)
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: slip ring '%s': node %d does not exist",
                           d->name, d->node);
        *node = d->node;
        return MCS_OK;
    }
    unsigned char *mark = malloc((size_t)m->nnode + 1);
    if (!mark) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (slip ring)");
    char what[FE_NAME_MAX + 16];
    snprintf(what, sizeof what, "slip ring '%s'", d->name);
    *node = fe_builder_nearest_node(b, m, d->part, d->point, mark, what, err);
    free(mark);
    return *node >= 0 ? MCS_OK : err->status;
}

static double elem_length0(const fe_model *m, int e)
{
    const double *a = m->node_x0 + 3 * m->truss_node[2 * e];
    const double *b = m->node_x0 + 3 * m->truss_node[2 * e + 1];
    double d2 = 0;
    for (int i = 0; i < 3; i++)
        d2 += (b[i] - a[i]) * (b[i] - a[i]);
    return sqrt(d2);
}

/* the truss elements at the ring node: elastic, deformable, not another ring's side */
static mcs_status find_sides(const fe_model *m, const fe_slipring_desc *d, fe_slipring *r, int need,
                             mcs_error *err)
{
    int cnt = 0, el[2] = {-1, -1};
    for (int e = 0; e < m->ntruss; e++) {
        if (m->truss_node[2 * e] != r->node && m->truss_node[2 * e + 1] != r->node) continue;
        if (cnt < 2) el[cnt] = e;
        cnt++;
    }
    if (cnt != need)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: slip ring '%s': node %d must join exactly %d belt (truss) element%s "
                       "%s, it joins %d",
                       d->name, r->node, need, need > 1 ? "s" : "",
                       need > 1 ? "(the two sides)" : "(with the retractor's segment)", cnt);
    for (int k = 0; k < need; k++) {
        const fe_part *p = &m->part[m->truss_part[el[k]]];
        if (p->material.model != FE_MAT_ELASTIC || p->body >= 0)
            return MCS_ERR(err, MCS_ERR_TYPE,
                           "fe: slip ring '%s': belt part '%s' must be elastic (the webbing "
                           "flowing through the ring carries no plastic history)",
                           d->name, p->name);
    }
    int off = need == 1 ? 1 : 0; /* side 0 is the retractor segment */
    for (int k = 0; k < need; k++) {
        int e = el[k];
        r->elem[off + k] = e;
        r->far[off + k] =
            m->truss_node[2 * e] == r->node ? m->truss_node[2 * e + 1] : m->truss_node[2 * e];
        r->l0[off + k] = elem_length0(m, e);
    }
    if (need == 2 && r->far[1] < r->far[0]) { /* side 0: the lower far node */
        int t = r->elem[0];
        r->elem[0] = r->elem[1], r->elem[1] = t;
        t = r->far[0];
        r->far[0] = r->far[1], r->far[1] = t;
        double l = r->l0[0];
        r->l0[0] = r->l0[1], r->l0[1] = l;
    }
    return MCS_OK;
}

static mcs_status make_ring(const fe_builder *b, fe_model *m, const fe_slipring_desc *d,
                            fe_slipring *r, mcs_error *err)
{
    memcpy(r->name, d->name, FE_NAME_MAX);
    r->mu = d->friction;
    r->lock_time = d->lock_time;
    r->retractor = -1;
    r->elem[0] = r->elem[1] = r->far[0] = r->far[1] = -1;
    mcs_status st = ring_node(b, m, d, &r->node, err);
    if (st != MCS_OK) return st;
    if (d->retractor[0]) {
        r->retractor = fe_retractor_find(m, d->retractor);
        if (r->retractor < 0)
            return MCS_ERR(err, MCS_ERR_KEY, "fe: slip ring '%s': unknown retractor '%s'", d->name,
                           d->retractor);
        const fe_belt_retractor *rt = &m->restraints->retractor[r->retractor];
        if (rt->node != r->node)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: slip ring '%s': retractor '%s' pulls node %d, not the ring node "
                           "%d (its belt end must be the ring)",
                           d->name, d->retractor, rt->node, r->node);
        r->l0[0] = rt->l0;
    }
    st = find_sides(m, d, r, r->retractor >= 0 ? 1 : 2, err);
    if (st != MCS_OK) return st;
    double lmin = fmin(r->l0[0], r->l0[1]);
    if (r->retractor >= 0) lmin = r->l0[1];
    r->min_length = d->min_length > 0 ? d->min_length : 0.05 * lmin;
    if (!(r->min_length < lmin))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: slip ring '%s': min_length %g m must be below the shorter side's "
                       "length %g m",
                       d->name, r->min_length, lmin);
    return MCS_OK;
}

mcs_status fe_sliprings_create(const fe_builder *b, fe_model *m, mcs_error *err)
{
    const struct fe_slipring_list *l = b->sliprings;
    m->sliprings = NULL;
    if (!l || l->n == 0) return MCS_OK;
    struct fe_sliprings *r = calloc(1, sizeof *r);
    if (r) r->ring = calloc((size_t)l->n, sizeof *r->ring);
    m->sliprings = r;
    if (!r || !r->ring) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (slip rings)");
    m->bytes += sizeof *r + sizeof *r->ring * (size_t)l->n;
    for (int i = 0; i < l->n; i++, r->n++) {
        mcs_status st = make_ring(b, m, &l->d[i], &r->ring[i], err);
        if (st != MCS_OK) return st;
        for (int j = 0; j < i; j++) /* an element's unstretched length has one owner */
            for (int k = 0; k < 2; k++)
                for (int q = 0; q < 2; q++)
                    if (r->ring[i].elem[k] >= 0 && r->ring[i].elem[k] == r->ring[j].elem[q])
                        return MCS_ERR(err, MCS_ERR_RANGE,
                                       "fe: slip rings '%s' and '%s' share a belt element; "
                                       "give each ring an element of its own between them",
                                       r->ring[j].name, r->ring[i].name);
    }
    return MCS_OK;
}

void fe_sliprings_destroy(struct fe_sliprings **p)
{
    if (!p || !*p) return;
    free((*p)->ring);
    free(*p);
    *p = NULL;
}

mcs_status fe_slipring_state_create(const fe_model *m, struct fe_slipring_state **out,
                                    size_t *bytes, mcs_error *err)
{
    *out = NULL;
    const struct fe_sliprings *r = m->sliprings;
    if (!r) return MCS_OK;
    struct fe_slipring_state *s = calloc(1, sizeof *s);
    if (s) s->ring = calloc((size_t)r->n, sizeof *s->ring);
    if (!s || !s->ring) {
        fe_slipring_state_destroy(&s);
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (slip ring state)");
    }
    *bytes += sizeof *s + sizeof *s->ring * (size_t)r->n;
    *out = s;
    return MCS_OK;
}

void fe_slipring_state_destroy(struct fe_slipring_state **p)
{
    if (!p || !*p) return;
    free((*p)->ring);
    free(*p);
    *p = NULL;
}

void fe_slipring_state_reset(const fe_model *m, fe_state *s)
{
    const struct fe_sliprings *r = m->sliprings;
    if (!r || !s->slipring) return;
    for (int i = 0; i < r->n; i++) {
        fe_slipring_ring_state *g = &s->slipring->ring[i];
        memset(g, 0, sizeof *g);
        g->length0 = r->ring[i].l0[0];
        g->length1 = r->ring[i].l0[1];
    }
}

int fe_slipring_find(const fe_model *m, const char *name)
{
    const struct fe_sliprings *r = m->sliprings;
    for (int i = 0; r && i < r->n; i++)
        if (strcmp(r->ring[i].name, name) == 0) return i;
    return -1;
}

const char *const fe_slipring_channel_name[FE_SLIPRING_NCHANNEL] = {
#define FE_SLIPRING_X_NAME(name, unit, what) #name,
    FE_SLIPRING_STATE_FIELDS(FE_SLIPRING_X_NAME)
#undef FE_SLIPRING_X_NAME
};

const char *const fe_slipring_channel_unit[FE_SLIPRING_NCHANNEL] = {
#define FE_SLIPRING_X_UNIT(name, unit, what) unit,
    FE_SLIPRING_STATE_FIELDS(FE_SLIPRING_X_UNIT)
#undef FE_SLIPRING_X_UNIT
};

double fe_slipring_channel(const fe_slipring_ring_state *s, int channel)
{
    switch (channel) {
#define FE_SLIPRING_X_CASE(name, unit, what)                                                       \
    case FE_SLIPRING_CH_##name:                                                                    \
        return s->name;
        FE_SLIPRING_STATE_FIELDS(FE_SLIPRING_X_CASE)
#undef FE_SLIPRING_X_CASE
    default:
        return NAN;
    }
}

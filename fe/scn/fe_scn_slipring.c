/* fe_scn_slipring.c: scenario keys -> slip rings, and their /stage<N> results
 * (fe_scn_slipring.h). The kernel's descriptor carries the key names (docs/fe.md); kernel
 * errors are relocated to the scenario node. */
#include "fe/scn/fe_scn_slipring.h"
#include "fe/scn/fe_scn_node.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static mcs_status name_into(const mcs_node *n, char *dst, mcs_error *err)
{
    const char *s = mcs_node_str(n);
    if (!s) s = "";
    if (strlen(s) >= FE_NAME_MAX)
        return mcs_node_error(n, err, MCS_ERR_RANGE, "longer than %d characters", FE_NAME_MAX - 1);
    snprintf(dst, FE_NAME_MAX, "%s", s);
    return MCS_OK;
}

static mcs_status read_ring(const mcs_node *r, fe_slipring_desc *d, mcs_error *err)
{
    mcs_status st = name_into(fe_scn_get(r, "name"), d->name, err);
    if (!st) st = name_into(fe_scn_get(r, "part"), d->part, err);
    if (!st && fe_scn_given(r, "retractor"))
        st = name_into(fe_scn_get(r, "retractor"), d->retractor, err);
    if (!st) st = mcs_node_vec3(fe_scn_get(r, "point"), d->point, err);
    d->friction = mcs_node_num_or(r, "friction", 0);
    d->lock_time = mcs_node_num_or(r, "lock_time", -1);
    d->min_length = mcs_node_num_or(r, "min_length", 0);
    return st;
}

mcs_status fe_scn_add_sliprings(fe_builder *b, const mcs_node *fe, mcs_error *err)
{
    const mcs_node *rings = fe_scn_get(fe, "sliprings");
    for (int i = 0; i < mcs_node_len(rings); i++) {
        const mcs_node *r = mcs_node_at(rings, i);
        fe_slipring_desc d = fe_slipring_desc_default();
        mcs_status st = read_ring(r, &d, err);
        if (st) return st;
        mcs_error kerr = {0};
        st = fe_builder_add_slipring(b, &d, &kerr);
        if (st) return fe_scn_relocate(st, r, &kerr, err);
    }
    return MCS_OK;
}

const mcs_node *fe_scn_slipring_node(const mcs_node *fe, const char *msg, const mcs_node *fallback)
{
    const mcs_node *l = fe_scn_get(fe, "sliprings");
    /* "slip rings 'a' and 'b' ...": the second, the one that came in conflict */
    for (int i = 0; i < mcs_node_len(l) && strstr(msg, "slip rings '"); i++) {
        const mcs_node *it = mcs_node_at(l, i);
        char needle[FE_NAME_MAX + 32];
        snprintf(needle, sizeof needle, "' and '%s'", mcs_node_str(fe_scn_get(it, "name")));
        if (strstr(msg, needle)) return it;
    }
    for (int i = 0; i < mcs_node_len(l); i++) {
        const mcs_node *it = mcs_node_at(l, i);
        char needle[FE_NAME_MAX + 32];
        snprintf(needle, sizeof needle, "slip ring '%s'", mcs_node_str(fe_scn_get(it, "name")));
        if (strstr(msg, needle)) return it;
    }
    return fallback;
}

mcs_status fe_out_slipring_open(mcs_results *r, int stage, const fe_model *m, fe_out_slipring *o,
                                mcs_error *err)
{
    memset(o, 0, sizeof *o);
    const struct fe_sliprings *rs = m->sliprings;
    if (!rs) return MCS_OK;
    o->ch = calloc((size_t)rs->n * FE_SLIPRING_NCHANNEL, sizeof *o->ch);
    if (!o->ch) return MCS_ERR(err, MCS_ERR_NOMEM, "stage %d: out of memory", stage);
    o->n = rs->n;
    char path[256];
    mcs_status st = MCS_OK;
    for (int i = 0; i < rs->n && !st; i++)
        for (int c = 0; c < FE_SLIPRING_NCHANNEL && !st; c++) {
            snprintf(path, sizeof path, "/stage%d/slipring/%s/%s", stage, rs->ring[i].name,
                     fe_slipring_channel_name[c]);
            st = mcs_results_series_create(r, path, 1, NULL, fe_slipring_channel_unit[c], 0,
                                           &o->ch[FE_SLIPRING_NCHANNEL * i + c], err);
        }
    return st;
}

mcs_status fe_out_slipring_sample(const fe_state *s, const fe_out_slipring *o, mcs_error *err)
{
    mcs_status st = MCS_OK;
    for (int i = 0; i < o->n && !st; i++)
        for (int c = 0; c < FE_SLIPRING_NCHANNEL && !st; c++) {
            double v = fe_slipring_channel(&s->slipring->ring[i], c);
            st = mcs_results_series_append(o->ch[FE_SLIPRING_NCHANNEL * i + c], &v, err);
        }
    return st;
}

void fe_out_slipring_free(fe_out_slipring *o)
{
    free(o->ch);
    memset(o, 0, sizeof *o);
}

/* fe_scn_keyword.c: keyword meshes of fe: parts (see fe_scn_keyword.h). */
#include "fe/fe_scn_keyword.h"

#include "fe/fe_keyword.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    char path[1024];
    char units[32];
    fe_kw_deck *deck;
    int *node_map; /* deck node -> builder node (-1: not added yet) */
} fe_scn_kw_entry;

struct fe_scn_kw_cache {
    int n;
    fe_scn_kw_entry e[16];
};

void fe_scn_kw_cache_free(fe_scn_kw_cache **cache)
{
    if (!cache || !*cache) return;
    for (int i = 0; i < (*cache)->n; i++) {
        fe_kw_deck_destroy(&(*cache)->e[i].deck);
        free((*cache)->e[i].node_map);
    }
    free(*cache);
    *cache = NULL;
}

/* the deck of `name` relative to the YAML file of node `at`, read once */
static mcs_status deck_of(fe_scn_kw_cache **cache, const mcs_node *mesh, fe_scn_kw_entry **out,
                          mcs_error *err)
{
    const mcs_node *kn = mcs_node_get(mesh, "keyword");
    const char *name = mcs_node_str(kn), *from = mcs_node_file(kn);
    const char *units = mcs_node_str(mcs_node_get(mesh, "units"));
    const char *unk = mcs_node_str(mcs_node_get(mesh, "unknown_keywords"));
    char path[1024];
    const char *slash = from ? strrchr(from, '/') : NULL;
    if (!name) return mcs_node_error(kn, err, MCS_ERR_TYPE, "a file name is expected");
    if (name[0] == '/' || !slash)
        snprintf(path, sizeof path, "%s", name);
    else
        snprintf(path, sizeof path, "%.*s/%s", (int)(slash - from), from, name);
    if (!units) units = "m-s-kg";
    if (!*cache && !(*cache = calloc(1, sizeof **cache)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    fe_scn_kw_cache *c = *cache;
    for (int i = 0; i < c->n; i++)
        if (strcmp(c->e[i].path, path) == 0 && strcmp(c->e[i].units, units) == 0) {
            *out = &c->e[i];
            return MCS_OK;
        }
    if (c->n >= (int)(sizeof c->e / sizeof c->e[0]))
        return mcs_node_error(kn, err, MCS_ERR_RANGE, "at most %d keyword files per scenario",
                              (int)(sizeof c->e / sizeof c->e[0]));
    fe_kw_opts o = fe_kw_opts_default();
    o.units = units;
    o.strict = unk && strcmp(unk, "error") == 0;
    mcs_error kerr = {0};
    fe_kw_deck *d = NULL;
    mcs_status st = fe_kw_read(path, &o, &d, &kerr);
    if (st) return mcs_node_error(kn, err, st, "%s", kerr.msg);
    fe_scn_kw_entry *e = &c->e[c->n];
    e->node_map = malloc(sizeof(int) * (size_t)(d->nnode ? d->nnode : 1));
    if (!e->node_map) {
        fe_kw_deck_destroy(&d);
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    }
    for (int i = 0; i < d->nnode; i++) e->node_map[i] = -1;
    snprintf(e->path, sizeof e->path, "%s", path);
    snprintf(e->units, sizeof e->units, "%s", units);
    e->deck = d;
    c->n++;
    *out = e;
    return MCS_OK;
}

mcs_status fe_scn_kw_add_part(fe_scn_kw_cache **cache, fe_builder *b, const mcs_node *part,
                          const fe_part_desc *d, mcs_error *err)
{
    const mcs_node *mesh = mcs_node_get(part, "mesh"), *pn = mcs_node_get(mesh, "part");
    fe_scn_kw_entry *e = NULL;
    mcs_status st = deck_of(cache, mesh, &e, err);
    if (st) return st;
    int pid = (int)mcs_node_num(pn);
    fe_part_desc desc = *d;
    int has_sec = mcs_node_kind(mcs_node_get(part, "section")) == MCS_NODE_MAP;
    int has_mat = mcs_node_kind(mcs_node_get(part, "material")) == MCS_NODE_MAP;
    mcs_error kerr = {0};
    if (!has_sec || !has_mat) {
        fe_part_desc deck = desc;
        st = fe_kw_part_props(e->deck, pid, &deck, &kerr);
        if (st) return mcs_node_error(pn, err, st, "%s", kerr.msg);
        if (!has_sec) {
            /* the scenario's hourglass defaults stay; the deck gives the element data */
            fe_hourglass hg = desc.section.hourglass;
            double q = desc.section.hourglass_coefficient;
            desc.section = deck.section;
            desc.section.hourglass = hg;
            desc.section.hourglass_coefficient = q;
        }
        if (!has_mat) desc.material = deck.material;
    }
    st = fe_kw_add_part(b, e->deck, pid, &desc, 0, e->node_map, NULL, &kerr);
    if (st) return mcs_node_error(pn, err, st, "%s", kerr.msg);
    return MCS_OK;
}

/* the maps under n that name a keyword deck, depth first */
static mcs_status check_node(fe_scn_kw_cache **cache, const mcs_node *n, const mcs_node *parent,
                             fe_scn_kw_visit fn, void *user, mcs_error *err)
{
    mcs_kind k = mcs_node_kind(n);
    if (k != MCS_NODE_MAP && k != MCS_NODE_SEQ) return MCS_OK;
    if (k == MCS_NODE_MAP && mcs_node_kind(mcs_node_get(n, "keyword")) == MCS_NODE_STR) {
        int before = *cache ? (*cache)->n : 0;
        fe_scn_kw_entry *e = NULL;
        mcs_status st = deck_of(cache, n, &e, err);
        if (st) return st;
        const mcs_node *pn = mcs_node_get(n, "part");
        if (pn) {
            int pid = (int)mcs_node_num(pn), found = 0;
            const fe_kw_deck *d = e->deck;
            /* as the build: the deck's section and material when the scenario's part lacks one */
            if (mcs_node_kind(mcs_node_get(parent, "section")) != MCS_NODE_MAP ||
                mcs_node_kind(mcs_node_get(parent, "material")) != MCS_NODE_MAP) {
                fe_part_desc pd = fe_part_desc_default();
                mcs_error kerr = {0};
                st = fe_kw_part_props(d, pid, &pd, &kerr);
                if (st) return mcs_node_error(pn, err, st, "%s", kerr.msg);
            }
            for (int t = 0; t < FE_KW_NETYPE && !found; t++)
                for (int i = 0; i < d->elem[t].n && !found; i++) found = d->elem[t].pid[i] == pid;
            char skip[400];
            if (!found)
                return mcs_node_error(pn, err, MCS_ERR_KEY, "%s: no element has part ID %d%s",
                                      e->path, pid,
                                      fe_kw_skipped(d, "ELEMENT_", skip, sizeof skip));
        }
        if (fn && (*cache)->n > before) fn(e->path, n, e->deck, user);
    }
    for (int i = 0; i < mcs_node_len(n); i++) {
        mcs_status st = check_node(cache, mcs_node_at(n, i), n, fn, user, err);
        if (st) return st;
    }
    return MCS_OK;
}

mcs_status fe_scn_kw_check(const mcs_node *root, fe_scn_kw_visit fn, void *user, mcs_error *err)
{
    fe_scn_kw_cache *cache = NULL;
    mcs_status st = check_node(&cache, root, NULL, fn, user, err);
    fe_scn_kw_cache_free(&cache);
    return st;
}

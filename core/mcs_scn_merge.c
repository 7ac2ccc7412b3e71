/* mcs_scn_merge.c: a scenario with one of its blocks merged into another (mcs_scenario_merged,
 * mcs_scenario.h): stage 2 adds its stage-only FE parts to the scenario's fe: block */
#include "core/mcs_scn_internal.h"

#include <stdlib.h>
#include <string.h>

typedef struct {
    scn_arena *a;
    const char *file_from[8], *file_to[8]; /* recently copied file names (most share one) */
    int nfile;
} copy_ctx;

static const char *copy_file(copy_ctx *c, const char *f)
{
    if (!f) return NULL;
    for (int i = 0; i < c->nfile; i++)
        if (c->file_from[i] == f) return c->file_to[i];
    const char *t = scn_strndup(c->a, f, strlen(f));
    int k = c->nfile < 8 ? c->nfile++ : 7;
    c->file_from[k] = f;
    c->file_to[k] = t;
    return t;
}

static const char *copy_str(scn_arena *a, const char *s)
{
    return s ? scn_strndup(a, s, strlen(s)) : NULL;
}

/* deep copy into c->a; NULL out of memory */
static mcs_node *copy_node(copy_ctx *c, const mcs_node *n)
{
    mcs_node *r = scn_node_new(c->a, n->kind, copy_file(c, n->file), n->line, n->col);
    if (!r) return NULL;
    r->text = copy_str(c->a, n->text);
    r->path = copy_str(c->a, n->path);
    r->num = n->num;
    r->quoted = n->quoted;
    if ((n->text && !r->text) || (n->path && !r->path)) return NULL;
    for (int i = 0; i < n->n; i++) {
        mcs_node *k = n->kind == MCS_NODE_MAP ? copy_node(c, n->keys[i]) : NULL;
        mcs_node *v = copy_node(c, n->items[i]);
        if (!v || (n->kind == MCS_NODE_MAP && !k) || scn_node_push(c->a, r, k, v)) return NULL;
    }
    return r;
}

/* the map holding the last key of a dotted path, and that key's index (-1: absent) */
static mcs_node *parent_of(mcs_node *root, const char *path, const char **last, int *idx)
{
    char part[128];
    mcs_node *m = root;
    for (;;) {
        const char *dot = strchr(path, '.');
        size_t len = dot ? (size_t)(dot - path) : strlen(path);
        if (len >= sizeof part) return NULL;
        memcpy(part, path, len);
        part[len] = 0;
        int i = m && m->kind == MCS_NODE_MAP ? scn_map_find(m, part) : -1;
        if (!dot) {
            *last = path;
            *idx = i;
            return m;
        }
        if (i < 0) return NULL;
        m = m->items[i];
        path = dot + 1;
    }
}

static mcs_status merge_into(mcs_scenario *s, const char *from, const char *into, mcs_error *err)
{
    const char *last;
    int i;
    mcs_node *holder = parent_of(s->root, from, &last, &i);
    if (!holder || i < 0) return MCS_OK; /* nothing to merge */
    mcs_node *over = holder->items[i];
    scn_map_remove(holder, i);
    int j = scn_map_find(s->root, into);
    if (j < 0) {
        mcs_node *k = scn_node_new(&s->arena, MCS_NODE_STR, over->file, over->line, over->col);
        if (!k || !(k->text = copy_str(&s->arena, into)) ||
            scn_node_push(&s->arena, s->root, k, over))
            return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
        return MCS_OK;
    }
    mcs_node *m = scn_merge(&s->arena, s->root->items[j], over);
    if (!m) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    s->root->items[j] = m;
    return MCS_OK;
}

/* a copy of scn's tree and texts (not validated); NULL out of memory */
static mcs_scenario *copy_of(const mcs_scenario *scn)
{
    mcs_scenario *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    copy_ctx c = {.a = &s->arena};
    s->root = copy_node(&c, scn->root);
    if (scn->text) {
        s->text = malloc(scn->text_len + 1);
        if (s->text) memcpy(s->text, scn->text, scn->text_len + 1);
        s->text_len = s->text_cap = s->text ? scn->text_len : 0;
    }
    s->nfiles = scn->nfiles;
    if (!s->root) mcs_scenario_destroy(&s);
    return s;
}

/* validate s; on error destroy it */
static mcs_status finish(mcs_scenario *s, mcs_scenario **out, mcs_error *err)
{
    mcs_status st = scn_validate(s, err);
    if (st) {
        mcs_scenario_destroy(&s);
        return st;
    }
    *out = s;
    return MCS_OK;
}

mcs_status mcs_scenario_merged(const mcs_scenario *scn, const char *from, const char *into,
                               mcs_scenario **out, mcs_error *err)
{
    *out = NULL;
    mcs_scenario *s = copy_of(scn);
    if (!s) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    mcs_status st = merge_into(s, from, into, err);
    if (st) {
        mcs_scenario_destroy(&s);
        return st;
    }
    return finish(s, out, err);
}

mcs_status mcs_scenario_replaced(const mcs_scenario *scn, const char *from, const char *into,
                                 const char *const *drop, int ndrop, mcs_scenario **out,
                                 mcs_error *err)
{
    *out = NULL;
    mcs_scenario *s = copy_of(scn);
    if (!s) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    int i = scn_map_find(s->root, into);
    if (i >= 0) scn_map_remove(s->root, i);
    mcs_status st = merge_into(s, from, into, err); /* into is absent now: from moves there */
    for (int k = 0; k < ndrop && !st; k++)
        if ((i = scn_map_find(s->root, drop[k])) >= 0) scn_map_remove(s->root, i);
    if (st) {
        mcs_scenario_destroy(&s);
        return st;
    }
    return finish(s, out, err);
}

/* mcs_scn_include.c: loading a scenario: include: resolution and the merge rule
 * (documented in mcs_scenario.h), then validation */
#include "core/mcs_scn_internal.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#define MAX_INCLUDE_DEPTH 32

typedef struct {
    mcs_scenario *scn;
    mcs_error *err;
    const char *name[MAX_INCLUDE_DEPTH]; /* files being loaded, outermost first */
    char *real[MAX_INCLUDE_DEPTH];       /* their canonical paths (cycle check) */
    int depth;
} inc_ctx;

static mcs_status load_tree(inc_ctx *c, const char *path, const mcs_node *from, mcs_node **out);

/* the include rule (mcs_scenario.h): maps merge key by key; entity lists merge by name when
 * by_name (an entry whose name is already in the base merges into that entry, others are
 * appended), else concatenate; inside an entry merged by name a list of unnamed entries is a
 * value; anything else: over wins. err set: a bad override is reported there. */
typedef struct {
    scn_arena *a;
    mcs_error *err; /* NULL: no merge error is possible (by_name 0) */
    int by_name;    /* entity lists merge by name (include:), else concatenate */
    mcs_status st;  /* first failure */
    char path[512]; /* dotted path of the node being merged, for messages */
    size_t plen;
} merge_ctx;

static mcs_node *merge(merge_ctx *c, mcs_node *base, mcs_node *over, int in_entry);

static size_t push_path(merge_ctx *c, const char *key, int index)
{
    char seg[128];
    size_t old = c->plen;
    int k = key ? snprintf(seg, sizeof seg, "%s%.100s", c->plen ? "." : "", key)
                : snprintf(seg, sizeof seg, "[%d]", index);
    if (k > 0 && c->plen + (size_t)k < sizeof c->path) {
        memcpy(c->path + c->plen, seg, (size_t)k + 1);
        c->plen += (size_t)k;
    }
    return old;
}

static void pop_path(merge_ctx *c, size_t old)
{
    c->plen = old;
    c->path[old] = 0;
}

static mcs_node *oom(merge_ctx *c)
{
    if (!c->st) c->st = MCS_ERR_NOMEM;
    return NULL;
}

static mcs_node *merge_maps(merge_ctx *c, mcs_node *base, mcs_node *over, int in_entry)
{
    mcs_node *r = scn_node_new(c->a, MCS_NODE_MAP, over->file, over->line, over->col);
    if (!r) return oom(c);
    r->path = over->path;
    for (int i = 0; i < base->n; i++) {
        int j = scn_map_find(over, base->keys[i]->text);
        mcs_node *v = base->items[i], *k = base->keys[i];
        if (j >= 0) {
            size_t old = push_path(c, over->keys[j]->text, 0);
            v = merge(c, base->items[i], over->items[j], in_entry);
            pop_path(c, old);
            k = over->keys[j];
        }
        if (!v) return NULL;
        if (scn_node_push(c->a, r, k, v)) return oom(c);
    }
    for (int j = 0; j < over->n; j++) {
        if (scn_map_find(base, over->keys[j]->text) >= 0) continue;
        if (scn_node_push(c->a, r, over->keys[j], over->items[j])) return oom(c);
    }
    return r;
}

/* a list of entities (every item a mapping, or empty); vectors and curves are values */
static int is_entity_list(const mcs_node *n)
{
    if (n->kind != MCS_NODE_SEQ) return 0;
    for (int i = 0; i < n->n; i++)
        if (n->items[i]->kind != MCS_NODE_MAP) return 0;
    return 1;
}

static int has_names(const mcs_node *list)
{
    for (int i = 0; i < list->n; i++)
        if (scn_map_find(list->items[i], "name") >= 0) return 1;
    return 0;
}

/* the name an entry merges by: NULL when it has none (or null); a map or list: an error */
static const char *entry_name(merge_ctx *c, const mcs_node *e, int index)
{
    int i = scn_map_find(e, "name");
    if (i < 0 || e->items[i]->kind == MCS_NODE_NULL) return NULL;
    const mcs_node *n = e->items[i];
    if (n->text) return n->text;
    if (c->err && !c->st) {
        size_t old = push_path(c, NULL, index);
        push_path(c, "name", 0);
        c->st = scn_fail(c->err, MCS_ERR_TYPE, n, c->path,
                         "entries of an included list merge by name: expected a name, got a %s",
                         mcs_node_kind_str(n->kind));
        pop_path(c, old);
    }
    return NULL;
}

/* base's index of the entry named nm (the first), -1 if none */
static int find_named(const mcs_node *base, const char *nm)
{
    for (int i = 0; i < base->n; i++) {
        int k = scn_map_find(base->items[i], "name");
        const mcs_node *n = k < 0 ? NULL : base->items[i]->items[k];
        if (n && n->kind != MCS_NODE_NULL && n->text && strcmp(n->text, nm) == 0) return i;
    }
    return -1;
}

static mcs_node *merge_list(merge_ctx *c, mcs_node *base, mcs_node *over)
{
    mcs_node *r = scn_node_new(c->a, MCS_NODE_SEQ, over->file, over->line, over->col);
    if (!r) return oom(c);
    for (int i = 0; i < base->n; i++)
        if (scn_node_push(c->a, r, NULL, base->items[i])) return oom(c);
    for (int j = 0; j < over->n; j++) {
        const char *nm = c->by_name ? entry_name(c, over->items[j], j) : NULL;
        if (c->st) return NULL;
        int i = nm ? find_named(base, nm) : -1;
        if (i < 0) {
            if (scn_node_push(c->a, r, NULL, over->items[j])) return oom(c);
            continue;
        }
        size_t old = push_path(c, NULL, j);
        mcs_node *m = merge_maps(c, base->items[i], over->items[j], 1);
        pop_path(c, old);
        if (!m) return NULL;
        r->items[i] = m;
    }
    return r;
}

static mcs_node *merge(merge_ctx *c, mcs_node *base, mcs_node *over, int in_entry)
{
    if (base->kind == MCS_NODE_MAP && over->kind == MCS_NODE_MAP)
        return merge_maps(c, base, over, in_entry);
    if (!is_entity_list(base) || !is_entity_list(over)) return over;
    if (in_entry && c->by_name && !has_names(base) && !has_names(over)) return over;
    return merge_list(c, base, over);
}

/* merge for include: (by name); NULL with *st set on failure (err holds the message) */
static mcs_node *include_merge(inc_ctx *ic, mcs_node *base, mcs_node *over, mcs_status *st)
{
    merge_ctx c = {.a = &ic->scn->arena, .err = ic->err, .by_name = 1};
    mcs_node *r = merge(&c, base, over, 0);
    *st = r ? MCS_OK : c.st ? c.st : MCS_ERR_NOMEM;
    return r;
}

/* include path relative to the directory of the including file */
static const char *include_path(scn_arena *a, const char *file, const char *inc)
{
    if (inc[0] == '/') return scn_strndup(a, inc, strlen(inc));
    const char *slash = strrchr(file, '/');
    size_t dl = slash ? (size_t)(slash - file + 1) : 0;
    size_t il = strlen(inc);
    char *p = scn_alloc(a, dl + il + 1);
    if (!p) return NULL;
    memcpy(p, file, dl);
    memcpy(p + dl, inc, il + 1);
    return p;
}

static mcs_status cycle_fail(inc_ctx *c, const mcs_node *from, const char *path)
{
    char chain[600];
    size_t k = 0;
    chain[0] = 0;
    for (int i = 0; i < c->depth && k < sizeof chain; i++)
        k += (size_t)snprintf(chain + k, sizeof chain - k, "%s -> ", c->name[i]);
    if (k < sizeof chain) snprintf(chain + k, sizeof chain - k, "%s", path);
    return scn_fail(c->err, MCS_ERR_INCLUDE, from, "include", "include cycle: %s", chain);
}

/* the include: entries of root, removed from it; NULL list when there is none */
static mcs_status take_includes(inc_ctx *c, mcs_node *root, mcs_node ***list, int *n)
{
    int i = scn_map_find(root, "include");
    *n = 0;
    if (i < 0) return MCS_OK;
    mcs_node *inc = root->items[i];
    scn_map_remove(root, i);
    if (inc->kind == MCS_NODE_SEQ) {
        *list = inc->items;
        *n = inc->n;
    } else {
        *list = scn_alloc(&c->scn->arena, sizeof **list);
        if (!*list) return MCS_ERR_NOMEM;
        (*list)[0] = inc;
        *n = 1;
    }
    for (int k = 0; k < *n; k++) {
        mcs_node *it = (*list)[k];
        if (it->kind != MCS_NODE_STR || !it->text[0])
            return scn_fail(c->err, MCS_ERR_TYPE, it, "include",
                            "expected a file path or a list of file paths, got a %s",
                            mcs_node_kind_str(it->kind));
    }
    return MCS_OK;
}

static mcs_status resolve(inc_ctx *c, const char *file, mcs_node *root, mcs_node **out)
{
    mcs_node **list = NULL;
    int n = 0;
    mcs_status st = take_includes(c, root, &list, &n);
    mcs_node *acc = NULL;
    for (int k = 0; k < n && !st; k++) {
        const char *p = include_path(&c->scn->arena, file, list[k]->text);
        mcs_node *sub = NULL;
        if (!p) return MCS_ERR_NOMEM;
        if ((st = load_tree(c, p, list[k], &sub))) break;
        acc = acc ? include_merge(c, acc, sub, &st) : sub;
    }
    if (st) return st;
    *out = acc ? include_merge(c, acc, root, &st) : root;
    return st;
}

/* parse text of file (already checked), resolve its includes */
static mcs_status load_parsed(inc_ctx *c, const char *file, const char *text, size_t len,
                              mcs_node **out)
{
    mcs_node *root = NULL;
    scn_add_source(c->scn, file, text, len);
    mcs_status st = scn_parse(c->scn, file, text, len, &root, c->err);
    if (!st) st = resolve(c, file, root, out);
    return st;
}

static mcs_status push_file(inc_ctx *c, const char *path, const mcs_node *from)
{
    if (c->depth >= MAX_INCLUDE_DEPTH)
        return scn_fail(c->err, MCS_ERR_INCLUDE, from, "include", "includes nested deeper than %d",
                        MAX_INCLUDE_DEPTH);
    if (++c->scn->nfiles > MCS_SCN_MAX_FILES)
        return scn_fail(c->err, MCS_ERR_INCLUDE, from, "include", "more than %d files included",
                        MCS_SCN_MAX_FILES);
    char *real = realpath(path, NULL);
    if (!real) real = strdup(path);
    if (!real) return MCS_ERR_NOMEM;
    for (int i = 0; i < c->depth; i++) {
        if (strcmp(c->real[i], real) == 0) {
            free(real);
            return cycle_fail(c, from, path);
        }
    }
    c->name[c->depth] = path;
    c->real[c->depth++] = real;
    return MCS_OK;
}

static void pop_file(inc_ctx *c)
{
    free(c->real[--c->depth]);
}

static mcs_status load_tree(inc_ctx *c, const char *path, const mcs_node *from, mcs_node **out)
{
    char *text = NULL;
    size_t len = 0;
    mcs_status st = scn_read_file(c->scn, path, from, &text, &len, c->err);
    if (st) return st;
    if (!(st = push_file(c, path, from))) {
        st = load_parsed(c, path, text, len, out);
        pop_file(c);
    }
    free(text);
    return st;
}

static mcs_status finish(inc_ctx *c, mcs_status st, mcs_node *root, mcs_scenario **out)
{
    while (c->depth)
        pop_file(c);
    if (st == MCS_ERR_NOMEM) MCS_ERR(c->err, st, "error: out of memory while loading a scenario");
    if (!st) {
        c->scn->root = root;
        st = scn_validate(c->scn, c->err);
    }
    if (st) {
        mcs_scenario_destroy(&c->scn);
        return st;
    }
    *out = c->scn;
    return MCS_OK;
}

static mcs_scenario *scn_create(void)
{
    return calloc(1, sizeof(mcs_scenario));
}

mcs_status mcs_scenario_load(const char *path, mcs_scenario **out, mcs_error *err)
{
    *out = NULL;
    inc_ctx c = {.scn = scn_create(), .err = err};
    if (!c.scn) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    const char *file = scn_strndup(&c.scn->arena, path, strlen(path));
    mcs_node *root = NULL;
    mcs_status st = file ? load_tree(&c, file, NULL, &root) : MCS_ERR_NOMEM;
    return finish(&c, st, root, out);
}

mcs_status mcs_scenario_load_text(const char *name, const char *text, size_t len,
                                  mcs_scenario **out, mcs_error *err)
{
    *out = NULL;
    inc_ctx c = {.scn = scn_create(), .err = err};
    if (!c.scn) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    const char *file = scn_strndup(&c.scn->arena, name, strlen(name));
    mcs_node *root = NULL;
    mcs_status st = file ? scn_check_bytes(file, text, len, err) : MCS_ERR_NOMEM;
    if (!st) st = push_file(&c, file, NULL);
    if (!st) st = load_parsed(&c, file, text, len, &root);
    return finish(&c, st, root, out);
}

void mcs_scenario_destroy(mcs_scenario **scn)
{
    if (!scn || !*scn) return;
    scn_arena_free(&(*scn)->arena);
    free((*scn)->text);
    free(*scn);
    *scn = NULL;
}

const mcs_node *mcs_scenario_root(const mcs_scenario *scn)
{
    return scn ? scn->root : NULL;
}

const char *mcs_scenario_text(const mcs_scenario *scn)
{
    return scn && scn->text ? scn->text : "";
}

mcs_node *scn_merge(scn_arena *a, mcs_node *base, mcs_node *over)
{
    merge_ctx c = {.a = a};
    return merge(&c, base, over, 0);
}

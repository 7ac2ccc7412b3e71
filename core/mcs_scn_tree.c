/* mcs_scn_tree.c: scenario nodes, their arena, and the public accessors */
#include "core/mcs_scn_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

struct scn_block {
    scn_block *next;
    size_t size, used;
    max_align_t data[];
};

#define SCN_BLOCK_BYTES (64 * 1024)

void *scn_alloc(scn_arena *a, size_t size)
{
    size = (size + sizeof(max_align_t) - 1) / sizeof(max_align_t) * sizeof(max_align_t);
    scn_block *b = a->head;
    if (!b || b->size - b->used < size) {
        size_t cap = size > SCN_BLOCK_BYTES ? size : SCN_BLOCK_BYTES;
        b = malloc(sizeof *b + cap);
        if (!b) return NULL;
        b->size = cap;
        b->used = 0;
        b->next = a->head;
        a->head = b;
    }
    void *p = (char *)b->data + b->used;
    b->used += size;
    a->used_total += size;
    memset(p, 0, size);
    return p;
}

char *scn_strndup(scn_arena *a, const char *s, size_t n)
{
    char *d = scn_alloc(a, n + 1);
    if (!d) return NULL;
    memcpy(d, s, n);
    d[n] = 0;
    return d;
}

void scn_arena_free(scn_arena *a)
{
    for (scn_block *b = a->head, *next; b; b = next) {
        next = b->next;
        free(b);
    }
    a->head = NULL;
    a->used_total = 0;
}

mcs_node *scn_node_new(scn_arena *a, mcs_kind kind, const char *file, int line, int col)
{
    mcs_node *n = scn_alloc(a, sizeof *n);
    if (!n) return NULL;
    n->kind = kind;
    n->file = file;
    n->line = line;
    n->col = col;
    n->num = NAN;
    return n;
}

mcs_status scn_node_push(scn_arena *a, mcs_node *parent, mcs_node *key, mcs_node *item)
{
    if (parent->n == parent->cap) {
        int cap = parent->cap ? 2 * parent->cap : 4;
        mcs_node **items = scn_alloc(a, (size_t)cap * sizeof *items);
        mcs_node **keys = key ? scn_alloc(a, (size_t)cap * sizeof *keys) : NULL;
        if (!items || (key && !keys)) return MCS_ERR_NOMEM;
        if (parent->n) memcpy(items, parent->items, (size_t)parent->n * sizeof *items);
        if (key && parent->n) memcpy(keys, parent->keys, (size_t)parent->n * sizeof *keys);
        parent->items = items;
        parent->keys = keys;
        parent->cap = cap;
    }
    if (key) parent->keys[parent->n] = key;
    parent->items[parent->n++] = item;
    return MCS_OK;
}

int scn_map_find(const mcs_node *map, const char *key)
{
    if (!map || map->kind != MCS_NODE_MAP) return -1;
    for (int i = 0; i < map->n; i++)
        if (strcmp(map->keys[i]->text, key) == 0) return i;
    return -1;
}

void scn_map_remove(mcs_node *map, int i)
{
    int tail = map->n - i - 1;
    memmove(map->keys + i, map->keys + i + 1, (size_t)tail * sizeof *map->keys);
    memmove(map->items + i, map->items + i + 1, (size_t)tail * sizeof *map->items);
    map->n--;
}

static mcs_status vfail(mcs_error *err, mcs_status st, const mcs_node *at, const char *path,
                        const char *fmt, va_list ap)
{
    char what[768];
    vsnprintf(what, sizeof what, fmt, ap);
    const char *file = at && at->file ? at->file : "?";
    int line = at ? at->line : 0, col = at ? at->col : 0;
    if (path && *path)
        return MCS_ERR(err, st, "%s:%d:%d: error: %s: %s", file, line, col, path, what);
    return MCS_ERR(err, st, "%s:%d:%d: error: %s", file, line, col, what);
}

mcs_status scn_fail(mcs_error *err, mcs_status st, const mcs_node *at, const char *path,
                    const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(err, st, at, path, fmt, ap);
    va_end(ap);
    return st;
}

mcs_status mcs_node_error(const mcs_node *n, mcs_error *err, mcs_status st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(err, st, n, n ? n->path : NULL, fmt, ap);
    va_end(ap);
    return st;
}

int scn_edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la > 63 || lb > 63) return 99;
    int d[64][64];
    for (size_t i = 0; i <= la; i++)
        d[i][0] = (int)i;
    for (size_t j = 0; j <= lb; j++)
        d[0][j] = (int)j;
    for (size_t i = 1; i <= la; i++) {
        for (size_t j = 1; j <= lb; j++) {
            int cost = a[i - 1] != b[j - 1];
            int v = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < v) v = d[i][j - 1] + 1;
            if (d[i - 1][j - 1] + cost < v) v = d[i - 1][j - 1] + cost;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
                d[i - 2][j - 2] + 1 < v)
                v = d[i - 2][j - 2] + 1;
            d[i][j] = v;
        }
    }
    return d[la][lb];
}

/* ---- public accessors ---- */

mcs_kind mcs_node_kind(const mcs_node *n)
{
    return n ? n->kind : MCS_NODE_NULL;
}

const char *mcs_node_kind_str(mcs_kind k)
{
    static const char *const s[] = {"null", "bool", "number", "string", "mapping", "sequence"};
    return (unsigned)k < sizeof s / sizeof s[0] ? s[k] : "?";
}

const mcs_node *mcs_node_get(const mcs_node *map, const char *key)
{
    int i = scn_map_find(map, key);
    return i < 0 ? NULL : map->items[i];
}

int mcs_node_len(const mcs_node *n)
{
    return n && (n->kind == MCS_NODE_MAP || n->kind == MCS_NODE_SEQ) ? n->n : 0;
}

const mcs_node *mcs_node_at(const mcs_node *n, int i)
{
    return i >= 0 && i < mcs_node_len(n) ? n->items[i] : NULL;
}

const char *mcs_node_key(const mcs_node *map, int i)
{
    if (!map || map->kind != MCS_NODE_MAP || i < 0 || i >= map->n) return NULL;
    return map->keys[i]->text;
}

double mcs_node_num(const mcs_node *n)
{
    return n && (n->kind == MCS_NODE_NUM || n->kind == MCS_NODE_BOOL) ? n->num : NAN;
}

double mcs_node_num_or(const mcs_node *map, const char *key, double dflt)
{
    const mcs_node *n = mcs_node_get(map, key);
    return n && n->kind == MCS_NODE_NUM ? n->num : dflt;
}

const char *mcs_node_str(const mcs_node *n)
{
    return n && n->kind == MCS_NODE_STR ? n->text : NULL;
}

const char *mcs_node_text(const mcs_node *n)
{
    return n ? n->text : NULL;
}

int mcs_node_bool(const mcs_node *n, int dflt)
{
    return n && n->kind == MCS_NODE_BOOL ? n->num != 0.0 : dflt;
}

const char *mcs_node_file(const mcs_node *n)
{
    return n ? n->file : NULL;
}

int mcs_node_line(const mcs_node *n)
{
    return n ? n->line : 0;
}

int mcs_node_col(const mcs_node *n)
{
    return n ? n->col : 0;
}

const char *mcs_node_path(const mcs_node *n)
{
    return n && n->path ? n->path : "";
}

mcs_status mcs_node_vec(const mcs_node *seq, double *v, int n, mcs_error *err)
{
    if (mcs_node_len(seq) != n || seq->kind != MCS_NODE_SEQ)
        return mcs_node_error(seq, err, MCS_ERR_TYPE, "expected a list of %d numbers", n);
    for (int i = 0; i < n; i++) {
        if (seq->items[i]->kind != MCS_NODE_NUM)
            return mcs_node_error(seq->items[i], err, MCS_ERR_TYPE, "expected a number");
        v[i] = seq->items[i]->num;
    }
    return MCS_OK;
}

mcs_status mcs_node_vec3(const mcs_node *seq, double v[3], mcs_error *err)
{
    return mcs_node_vec(seq, v, 3, err);
}

int mcs_node_curve_len(const mcs_node *curve)
{
    if (!curve || curve->kind != MCS_NODE_SEQ) return 0;
    for (int i = 0; i < curve->n; i++)
        if (mcs_node_len(curve->items[i]) != 2) return 0;
    return curve->n;
}

mcs_status mcs_node_curve(const mcs_node *curve, double *x, double *y, int cap, mcs_error *err)
{
    int n = mcs_node_curve_len(curve);
    if (n == 0) return mcs_node_error(curve, err, MCS_ERR_TYPE, "expected a curve [[x, y], ...]");
    if (n > cap)
        return mcs_node_error(curve, err, MCS_ERR_RANGE, "curve has %d points, room for %d", n,
                              cap);
    for (int i = 0; i < n; i++) {
        double xy[2];
        mcs_status st = mcs_node_vec(curve->items[i], xy, 2, err);
        if (st) return st;
        x[i] = xy[0];
        y[i] = xy[1];
    }
    return MCS_OK;
}

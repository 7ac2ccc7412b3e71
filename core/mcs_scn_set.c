/* mcs_scn_set.c: keys of a loaded scenario found and set by path (mcs_scenario_find,
 * mcs_scenario_set: a study's factors), and YAML files read without the schema (mcs_yaml_load:
 * the study file itself) */
#include "core/mcs_scn_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* one step of a path: a map key, or a sequence item by index or name */
typedef struct {
    char key[128]; /* map key, "" when the step is an item */
    char item[128];
    int is_item;
} path_step;

/* next step of *p ("a.b[3][x].c"); 0 at the end, -1 on a malformed path */
static int next_step(const char **p, path_step *st)
{
    const char *s = *p;
    if (!*s) return 0;
    memset(st, 0, sizeof *st);
    if (*s == '[') {
        const char *e = strchr(s, ']');
        if (!e || e == s + 1 || (size_t)(e - s - 1) >= sizeof st->item) return -1;
        memcpy(st->item, s + 1, (size_t)(e - s - 1));
        st->is_item = 1;
        s = e + 1;
    } else {
        size_t len = strcspn(s, ".[");
        if (!len || len >= sizeof st->key) return -1;
        memcpy(st->key, s, len);
        s += len;
    }
    if (*s == '.') {
        s++;
        if (!*s || *s == '.' || *s == '[') return -1;
    } else if (*s && *s != '[') {
        return -1;
    }
    *p = s;
    return 1;
}

/* index of the sequence item named by step (a number, or the entry whose name: is it), -1 */
static int item_index(const mcs_node *seq, const char *item)
{
    char *end;
    long i = strtol(item, &end, 10);
    if (!*end) return i >= 0 && i < seq->n ? (int)i : -1;
    for (int k = 0; k < seq->n; k++) {
        const mcs_node *nm = mcs_node_get(seq->items[k], "name");
        if (nm && nm->text && strcmp(nm->text, item) == 0) return k;
    }
    return -1;
}

/* the slot holding the node at path; with add, the last key of a path may be missing from its
 * map (it is added, its value NULL). NULL when the path names no node (or is malformed) */
static mcs_node **find_slot(scn_arena *a, mcs_node **root, const char *path, int add,
                            const mcs_node *at)
{
    mcs_node **slot = root;
    path_step st;
    int r;
    while ((r = next_step(&path, &st)) > 0) {
        mcs_node *n = *slot;
        if (!n) return NULL;
        if (st.is_item) {
            int i = n->kind == MCS_NODE_SEQ ? item_index(n, st.item) : -1;
            if (i < 0) return NULL;
            slot = &n->items[i];
            continue;
        }
        if (n->kind != MCS_NODE_MAP) return NULL;
        int i = scn_map_find(n, st.key);
        if (i < 0) {
            if (!add || *path) return NULL;
            mcs_node *k = scn_node_new(a, MCS_NODE_STR, at->file, at->line, at->col);
            if (!k || !(k->text = scn_strndup(a, st.key, strlen(st.key))) ||
                scn_node_push(a, n, k, NULL))
                return NULL;
            i = n->n - 1;
        }
        slot = &n->items[i];
    }
    return r < 0 ? NULL : slot;
}

const mcs_node *mcs_scenario_find(const mcs_node *root, const char *path)
{
    mcs_node *r = (mcs_node *)root; /* find_slot without add writes nothing */
    mcs_node **slot = r ? find_slot(NULL, &r, path, 0, NULL) : NULL;
    return slot ? *slot : NULL;
}

/* the new value of one setting, in s's arena */
static mcs_node *setting_value(mcs_scenario *s, const mcs_scn_setting *set)
{
    if (set->value) return scn_copy_node(&s->arena, set->value);
    const mcs_node *at = set->at;
    const char *file = at && at->file ? scn_strndup(&s->arena, at->file, strlen(at->file)) : "?";
    mcs_node *v = scn_node_new(&s->arena, set->str ? MCS_NODE_STR : MCS_NODE_NUM, file,
                               at ? at->line : 0, at ? at->col : 0);
    char txt[40];
    snprintf(txt, sizeof txt, "%.17g", set->num);
    const char *t = set->str ? set->str : txt;
    if (!v || !file || !(v->text = scn_strndup(&s->arena, t, strlen(t)))) return NULL;
    v->num = set->str ? NAN : set->num;
    v->quoted = set->str != NULL;
    return v;
}

mcs_status mcs_scenario_set(const mcs_scenario *scn, const mcs_scn_setting *set, int n,
                            mcs_scenario **out, mcs_error *err)
{
    *out = NULL;
    mcs_scenario *s = scn_copy(scn);
    if (!s) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    mcs_status st = MCS_OK;
    for (int i = 0; i < n && !st; i++) {
        mcs_node **slot = find_slot(&s->arena, &s->root, set[i].path, 1, set[i].at);
        mcs_node *v = slot ? setting_value(s, &set[i]) : NULL;
        if (!slot)
            st = scn_fail(err, MCS_ERR_KEY, set[i].at, NULL,
                          "'%s' names no key of the scenario", set[i].path);
        else if (!v)
            st = MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
        else
            *slot = v;
    }
    if (!st) st = scn_validate(s, err);
    if (st) {
        mcs_scenario_destroy(&s);
        return st;
    }
    *out = s;
    return MCS_OK;
}

mcs_status mcs_yaml_load(const char *path, mcs_scenario **out, mcs_error *err)
{
    *out = NULL;
    mcs_scenario *s = calloc(1, sizeof *s);
    if (!s) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    const char *file = scn_strndup(&s->arena, path, strlen(path));
    char *text = NULL;
    size_t len = 0;
    mcs_status st = file ? scn_read_file(s, file, NULL, &text, &len, err)
                         : MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    if (!st) {
        scn_add_source(s, file, text, len);
        st = scn_parse(s, file, text, len, &s->root, err);
    }
    free(text);
    if (st) {
        mcs_scenario_destroy(&s);
        return st;
    }
    *out = s;
    return MCS_OK;
}

/* mcs_scn_parse.c: one YAML document -> a tree of nodes (libyaml event API) */
#include "core/mcs_scn_internal.h"
#include "core/mcs_units.h"

#include <math.h>
#include <string.h>
#include <yaml.h>

typedef struct {
    mcs_scenario *scn;
    const char *file;
    mcs_error *err;
    mcs_node *stack[MCS_SCN_MAX_DEPTH + 1]; /* open maps and sequences */
    mcs_node *key[MCS_SCN_MAX_DEPTH + 1];   /* key waiting for its value, per open map */
    int depth;
    int ndocs;
    long nnodes;
    mcs_node *root;
} pstate;

static mcs_status pfail_at(pstate *ps, yaml_mark_t m, mcs_status st, const char *what,
                           const char *arg)
{
    char w[512];
    snprintf(w, sizeof w, what, arg);
    return MCS_ERR(ps->err, st, "%s:%zu:%zu: error: %s", ps->file, m.line + 1, m.column + 1, w);
}

static int is_null_word(const char *s)
{
    return !*s || !strcmp(s, "~") || !strcmp(s, "null") || !strcmp(s, "Null") || !strcmp(s, "NULL");
}

static int bool_word(const char *s)
{
    if (!strcmp(s, "true") || !strcmp(s, "True") || !strcmp(s, "TRUE")) return 1;
    if (!strcmp(s, "false") || !strcmp(s, "False") || !strcmp(s, "FALSE")) return 0;
    return -1;
}

/* YAML 1.2 core schema for plain scalars; non-finite numbers stay numbers (validation refuses) */
static void resolve_plain(mcs_node *n)
{
    const char *s = n->text;
    size_t len = strlen(s);
    double v;
    int b = bool_word(s);
    if (is_null_word(s)) {
        n->kind = MCS_NODE_NULL;
    } else if (b >= 0) {
        n->kind = MCS_NODE_BOOL;
        n->num = b;
    } else if (mcs_number_scan(s, &v) == len) {
        n->kind = MCS_NODE_NUM;
        n->num = v;
    } else if (mcs_is_nonfinite_word(s, len) && (s[0] == '.' || s[1] == '.')) {
        n->kind = MCS_NODE_NUM;
        n->num = NAN;
    }
}

static mcs_status new_scalar(pstate *ps, const yaml_event_t *ev, mcs_node **out)
{
    const char *v = (const char *)ev->data.scalar.value;
    size_t len = ev->data.scalar.length;
    if (memchr(v, 0, len))
        return pfail_at(ps, ev->start_mark, MCS_ERR_FORMAT, "NUL character in a string%s", "");
    mcs_node *n = scn_node_new(&ps->scn->arena, MCS_NODE_STR, ps->file,
                               (int)ev->start_mark.line + 1, (int)ev->start_mark.column + 1);
    if (!n || !(n->text = scn_strndup(&ps->scn->arena, v, len))) return MCS_ERR_NOMEM;
    const char *tag = (const char *)ev->data.scalar.tag;
    n->quoted =
        ev->data.scalar.style != YAML_PLAIN_SCALAR_STYLE || (tag && !strcmp(tag, YAML_STR_TAG));
    if (!n->quoted) resolve_plain(n);
    *out = n;
    return MCS_OK;
}

/* dotted path of the open containers ("bodies[0].surfaces") */
static void open_path(const pstate *ps, char *buf, size_t n)
{
    size_t k = 0;
    buf[0] = 0;
    for (int i = 0; i + 1 < ps->depth && k < n; i++) {
        const mcs_node *c = ps->stack[i];
        if (c->kind == MCS_NODE_MAP)
            k += (size_t)snprintf(buf + k, n - k, "%s%s", k ? "." : "", c->keys[c->n - 1]->text);
        else
            k += (size_t)snprintf(buf + k, n - k, "[%d]", c->n - 1);
    }
}

/* attach a new node (scalar or collection) to the open container */
static mcs_status attach(pstate *ps, mcs_node *n, yaml_mark_t m)
{
    if (++ps->nnodes > MCS_SCN_MAX_NODES)
        return pfail_at(ps, m, MCS_ERR_FORMAT, "too many nodes in one file%s", "");
    if (ps->depth == 0) {
        ps->root = n;
        return MCS_OK;
    }
    mcs_node *parent = ps->stack[ps->depth - 1];
    mcs_node **key = &ps->key[ps->depth - 1];
    if (parent->kind == MCS_NODE_SEQ) return scn_node_push(&ps->scn->arena, parent, NULL, n);
    if (*key) {
        mcs_status st = scn_node_push(&ps->scn->arena, parent, *key, n);
        *key = NULL;
        return st;
    }
    /* n is a key */
    if (n->kind == MCS_NODE_MAP || n->kind == MCS_NODE_SEQ)
        return pfail_at(ps, m, MCS_ERR_YAML, "a key must be a plain name, not a %s",
                        mcs_node_kind_str(n->kind));
    int i = scn_map_find(parent, n->text);
    if (i >= 0) {
        char path[256];
        open_path(ps, path, sizeof path);
        return MCS_ERR(ps->err, MCS_ERR_KEY,
                       "%s:%d:%d: error: %s%s%.80s: duplicate key (first at line %d)", ps->file,
                       n->line, n->col, path, *path ? "." : "", n->text, parent->keys[i]->line);
    }
    if (parent->n >= MCS_SCN_MAX_KEYS)
        return pfail_at(ps, m, MCS_ERR_FORMAT, "too many keys in one mapping%s", "");
    *key = n;
    return MCS_OK;
}

static mcs_status open_collection(pstate *ps, const yaml_event_t *ev, mcs_kind kind)
{
    if (ps->depth >= MCS_SCN_MAX_DEPTH)
        return pfail_at(ps, ev->start_mark, MCS_ERR_FORMAT, "nesting deeper than %s levels",
                        MCS_SCN_MAX_DEPTH == 64 ? "64" : "max");
    mcs_node *n = scn_node_new(&ps->scn->arena, kind, ps->file, (int)ev->start_mark.line + 1,
                               (int)ev->start_mark.column + 1);
    if (!n) return MCS_ERR_NOMEM;
    mcs_status st = attach(ps, n, ev->start_mark);
    if (st) return st;
    ps->stack[ps->depth] = n;
    ps->key[ps->depth] = NULL;
    ps->depth++;
    return MCS_OK;
}

static mcs_status on_event(pstate *ps, const yaml_event_t *ev)
{
    mcs_node *n = NULL;
    mcs_status st;
    switch (ev->type) {
    case YAML_DOCUMENT_START_EVENT:
        if (++ps->ndocs > 1)
            return pfail_at(ps, ev->start_mark, MCS_ERR_YAML,
                            "more than one YAML document in the file%s", "");
        return MCS_OK;
    case YAML_ALIAS_EVENT:
        return pfail_at(ps, ev->start_mark, MCS_ERR_YAML,
                        "aliases (*%.60s) are not supported: use include: or a named "
                        "characteristic",
                        (const char *)ev->data.alias.anchor);
    case YAML_SCALAR_EVENT:
        if ((st = new_scalar(ps, ev, &n))) return st;
        return attach(ps, n, ev->start_mark);
    case YAML_MAPPING_START_EVENT:
        return open_collection(ps, ev, MCS_NODE_MAP);
    case YAML_SEQUENCE_START_EVENT:
        return open_collection(ps, ev, MCS_NODE_SEQ);
    case YAML_MAPPING_END_EVENT:
    case YAML_SEQUENCE_END_EVENT:
        ps->depth--;
        return MCS_OK;
    default:
        return MCS_OK;
    }
}

static mcs_status syntax_fail(pstate *ps, const yaml_parser_t *p)
{
    yaml_mark_t m = p->problem_mark;
    const char *problem = p->problem ? p->problem : "unknown problem";
    if (p->context)
        return MCS_ERR(ps->err, MCS_ERR_YAML,
                       "%s:%zu:%zu: error: YAML syntax: %s %s (started at line %zu)", ps->file,
                       m.line + 1, m.column + 1, problem, p->context, p->context_mark.line + 1);
    return MCS_ERR(ps->err, MCS_ERR_YAML, "%s:%zu:%zu: error: YAML syntax: %s", ps->file,
                   m.line + 1, m.column + 1, problem);
}

static mcs_status run_events(pstate *ps, yaml_parser_t *p)
{
    for (;;) {
        yaml_event_t ev;
        if (!yaml_parser_parse(p, &ev)) return syntax_fail(ps, p);
        mcs_status st = on_event(ps, &ev);
        int done = ev.type == YAML_STREAM_END_EVENT;
        yaml_event_delete(&ev);
        if (st == MCS_ERR_NOMEM) return MCS_ERR(ps->err, st, "%s: error: out of memory", ps->file);
        if (st || done) return st;
    }
}

mcs_status scn_parse(mcs_scenario *scn, const char *file, const char *text, size_t len,
                     mcs_node **root, mcs_error *err)
{
    pstate ps = {.scn = scn, .file = file, .err = err};
    yaml_parser_t p;
    if (!yaml_parser_initialize(&p))
        return MCS_ERR(err, MCS_ERR_NOMEM, "%s: error: out of memory", file);
    yaml_parser_set_input_string(&p, (const unsigned char *)text, len);
    mcs_status st = run_events(&ps, &p);
    yaml_parser_delete(&p);
    if (st) return st;
    if (!ps.root || ps.root->kind == MCS_NODE_NULL)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s:1:1: error: empty scenario (no keys)", file);
    if (ps.root->kind != MCS_NODE_MAP)
        return scn_fail(err, MCS_ERR_TYPE, ps.root, NULL,
                        "a scenario must be a mapping of keys, not a %s",
                        mcs_node_kind_str(ps.root->kind));
    *root = ps.root;
    return MCS_OK;
}

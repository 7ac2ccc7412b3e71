/* mcs_scn_check.c: checks of scalar values against a schema key (quantities to SI in place),
 * paths and error messages of the schema walker (core/mcs_scn_walk.c) */
#include "core/mcs_schema.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* ---- paths and errors ---- */

size_t scn_walk_push_key(scn_walk *w, const char *key)
{
    size_t old = w->plen;
    int k = snprintf(w->path + w->plen, sizeof w->path - w->plen, "%s%s", w->plen ? "." : "", key);
    if (k > 0) w->plen += (size_t)k;
    if (w->plen >= sizeof w->path) w->plen = sizeof w->path - 1;
    return old;
}

size_t scn_walk_push_index(scn_walk *w, int i)
{
    size_t old = w->plen;
    int k = snprintf(w->path + w->plen, sizeof w->path - w->plen, "[%d]", i);
    if (k > 0) w->plen += (size_t)k;
    if (w->plen >= sizeof w->path) w->plen = sizeof w->path - 1;
    return old;
}

void scn_walk_pop(scn_walk *w, size_t old)
{
    w->plen = old;
    w->path[old] = 0;
}

mcs_status scn_walk_set_path(scn_walk *w, mcs_node *n)
{
    n->path = scn_strndup(&w->scn->arena, w->path, w->plen);
    return n->path ? MCS_OK : MCS_ERR(w->err, MCS_ERR_NOMEM, "error: out of memory");
}

mcs_status scn_walk_fail(scn_walk *w, const mcs_node *at, const char *key, mcs_status st,
                         const char *fmt, ...)
{
    char what[700];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    size_t old = key ? scn_walk_push_key(w, key) : w->plen;
    scn_fail(w->err, st, at, w->path, "%s", what);
    scn_walk_pop(w, old);
    return st;
}

#define FAIL(w, at, st, ...) scn_walk_fail((w), (at), NULL, (st), __VA_ARGS__)

/* ---- did you mean ---- */

static const char *closest(const char *word, const char *const *cands, int n)
{
    const char *best = NULL;
    int bd = 3;
    for (int i = 0; i < n; i++) {
        int d = scn_edit_distance(word, cands[i]);
        if (d < bd && d < (int)strlen(cands[i])) bd = d, best = cands[i];
    }
    return best;
}

void scn_suggest(char *buf, size_t n, const char *word, const char *const *cands, int nc)
{
    const char *c = closest(word, cands, nc);
    if (c)
        snprintf(buf, n, " (did you mean '%s'?)", c);
    else
        buf[0] = 0;
}

/* ---- scalars ---- */

const char *scn_got_str(const mcs_node *v, char *buf, size_t n)
{
    if (v->kind == MCS_NODE_MAP || v->kind == MCS_NODE_SEQ || v->kind == MCS_NODE_NULL)
        snprintf(buf, n, "a %s", mcs_node_kind_str(v->kind));
    else
        snprintf(buf, n, "'%.80s'", v->text);
    return buf;
}

static int is_scalar(const mcs_node *v)
{
    return v->kind == MCS_NODE_STR || v->kind == MCS_NODE_NUM || v->kind == MCS_NODE_BOOL;
}

mcs_status scn_range_check(scn_walk *w, const mcs_node *v, const mcs_skey *k, double x, mcs_dim d)
{
    unsigned f = k->flags;
    char u[48] = "", ub[40];
    if (!mcs_dim_eq(d, (mcs_dim)MCS_DIM_NONE)) {
        mcs_dim_si(d, ub, sizeof ub);
        snprintf(u, sizeof u, " %s", ub);
    }
    if ((f & MCS_SK_GT) && !(x > k->lo))
        return FAIL(w, v, MCS_ERR_RANGE, "must be > %g%s (got %g%s)", k->lo, u, x, u);
    if ((f & MCS_SK_GE) && !(x >= k->lo))
        return FAIL(w, v, MCS_ERR_RANGE, "must be >= %g%s (got %g%s)", k->lo, u, x, u);
    if ((f & MCS_SK_LT) && !(x < k->hi))
        return FAIL(w, v, MCS_ERR_RANGE, "must be < %g%s (got %g%s)", k->hi, u, x, u);
    if ((f & MCS_SK_LE) && !(x <= k->hi))
        return FAIL(w, v, MCS_ERR_RANGE, "must be <= %g%s (got %g%s)", k->hi, u, x, u);
    return MCS_OK;
}

/* one quantity of dimension d: plain number (SI) or "value unit"; converted in place */
mcs_status scn_quantity(scn_walk *w, mcs_node *v, mcs_dim d)
{
    char want[96], got[100];
    if (v->kind == MCS_NODE_NUM) {
        if (!isfinite(v->num))
            return FAIL(w, v, MCS_ERR_RANGE, "'%s' is not a finite number", v->text);
        return MCS_OK;
    }
    if (v->kind != MCS_NODE_STR) {
        mcs_dim_describe(d, want, sizeof want);
        return FAIL(w, v, MCS_ERR_TYPE, "expected %s, got %s", want,
                    scn_got_str(v, got, sizeof got));
    }
    char why[400];
    double si;
    mcs_status st = mcs_quantity_parse(v->text, d, &si, why, sizeof why);
    if (st == MCS_ERR_TYPE) {
        mcs_dim_describe(d, want, sizeof want);
        return FAIL(w, v, st, "expected %s, got %s", want, scn_got_str(v, got, sizeof got));
    }
    if (st) return FAIL(w, v, st, "%s", why);
    v->kind = MCS_NODE_NUM;
    v->num = si;
    return MCS_OK;
}

static mcs_status check_num(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    mcs_status st = scn_quantity(w, v, k->dim);
    return st ? st : scn_range_check(w, v, k, v->num, k->dim);
}

static mcs_status check_int(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    double x = 0;
    int ok = v->kind == MCS_NODE_NUM;
    if (v->kind == MCS_NODE_STR && mcs_number_scan(v->text, &x) == strlen(v->text)) ok = 1;
    if (ok && v->kind == MCS_NODE_NUM) x = v->num;
    char got[100];
    if (!ok || !isfinite(x) || x != floor(x) || fabs(x) > 1e9)
        return FAIL(w, v, MCS_ERR_TYPE, "expected an integer, got %s",
                    scn_got_str(v, got, sizeof got));
    v->kind = MCS_NODE_NUM;
    v->num = x;
    return scn_range_check(w, v, k, x, (mcs_dim)MCS_DIM_NONE);
}

static mcs_status check_str(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    char got[100];
    if (!is_scalar(v))
        return FAIL(w, v, MCS_ERR_TYPE, "expected a string, got %s",
                    scn_got_str(v, got, sizeof got));
    if (v->kind == MCS_NODE_NUM && !isfinite(v->num))
        return FAIL(w, v, MCS_ERR_RANGE, "'%s' is not a finite number", v->text);
    if ((k->flags & MCS_SK_NONEMPTY) && !v->text[0])
        return FAIL(w, v, MCS_ERR_RANGE, "must not be empty");
    v->kind = MCS_NODE_STR;
    return MCS_OK;
}

const char *scn_plural(const char *what, char *buf, size_t n)
{
    size_t len = strlen(what);
    if (len > 1 && what[len - 1] == 'y' && !strchr("aeiou", what[len - 2]))
        snprintf(buf, n, "%.*sies", (int)(len - 1), what);
    else
        snprintf(buf, n, "%ss", what);
    return buf;
}

/* split "a|b|c" into cands (pointers into buf) */
static int split_choices(const char *choices, char *buf, size_t n, const char **cands, int max)
{
    snprintf(buf, n, "%s", choices);
    int nc = 0;
    for (char *s = buf, *t; nc < max && s; s = t) {
        t = strchr(s, '|');
        if (t) *t++ = 0;
        cands[nc++] = s;
    }
    return nc;
}

static mcs_status check_enum(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    mcs_status st = check_str(w, v, k);
    if (st) return st;
    char buf[512], list[600], dym[96];
    const char *cands[32];
    int nc = split_choices(k->choices, buf, sizeof buf, cands, 32);
    for (int i = 0; i < nc; i++)
        if (strcmp(v->text, cands[i]) == 0) return MCS_OK;
    snprintf(list, sizeof list, "%s", k->choices);
    for (char *p = list; *p; p++)
        if (*p == '|') *p = '/';
    scn_suggest(dym, sizeof dym, v->text, cands, nc);
    return FAIL(w, v, MCS_ERR_RANGE, "'%.80s' is not one of %s%s", v->text, list, dym);
}

static mcs_status check_bool(scn_walk *w, mcs_node *v)
{
    char got[100];
    if (v->kind != MCS_NODE_BOOL)
        return FAIL(w, v, MCS_ERR_TYPE, "expected true or false, got %s",
                    scn_got_str(v, got, sizeof got));
    return MCS_OK;
}

mcs_status scn_check_scalar(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    switch (k->type) {
    case MCS_SK_NUM:
        return check_num(w, v, k);
    case MCS_SK_INT:
        return check_int(w, v, k);
    case MCS_SK_STR:
        return check_str(w, v, k);
    case MCS_SK_ENUM:
        return check_enum(w, v, k);
    case MCS_SK_BOOL:
        return check_bool(w, v);
    default:
        return FAIL(w, v, MCS_ERR_TYPE, "internal: not a scalar key type");
    }
}

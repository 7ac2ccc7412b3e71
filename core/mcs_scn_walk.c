/* mcs_scn_walk.c: the schema walker: maps (with variants), lists, vectors, curves, references */
#include "core/mcs_schema.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define FAIL(w, at, st, ...) scn_walk_fail((w), (at), NULL, (st), __VA_ARGS__)
#define MAX_NAMES 1024

static mcs_status walk_value(scn_walk *w, mcs_node *v, const mcs_skey *k);
static mcs_status walk_map(scn_walk *w, mcs_node *map, const mcs_smap *sm);

/* ---- free-form values: only paths and finiteness ---- */

static mcs_status walk_any(scn_walk *w, mcs_node *v)
{
    mcs_status st = scn_walk_set_path(w, v);
    if (st) return st;
    if (v->kind == MCS_NODE_NUM && !isfinite(v->num))
        return FAIL(w, v, MCS_ERR_RANGE, "'%s' is not a finite number", v->text);
    for (int i = 0; i < mcs_node_len(v) && !st; i++) {
        size_t old = v->kind == MCS_NODE_MAP ? scn_walk_push_key(w, v->keys[i]->text)
                                             : scn_walk_push_index(w, i);
        st = walk_any(w, v->items[i]);
        scn_walk_pop(w, old);
    }
    return st;
}

/* ---- references ---- */

/* names of the entities of kind ref in the resolved tree */
static int ref_names(const scn_walk *w, mcs_sref ref, const char **names, int max)
{
    int n = 0;
    const mcs_node *list = NULL;
    /* inside stage3: stage3.fe replaces fe: (stage 3 is compiled without it) */
    const mcs_node *fe = strncmp(w->path, "stage3.", 7) == 0
                             ? mcs_node_get(mcs_node_get(w->root, "stage3"), "fe")
                             : mcs_node_get(w->root, "fe");
    if (ref == MCS_REF_CHAR || ref == MCS_REF_BODY_LAW) {
        const mcs_node *c = ref == MCS_REF_CHAR ? mcs_node_get(w->root, "characteristics")
                                                : mcs_node_get(fe, "body_characteristics");
        for (int pass = 0; pass < 2; pass++) {
            for (int i = 0; i < mcs_node_len(c) && n < max && c->kind == MCS_NODE_MAP; i++)
                names[n++] = mcs_node_key(c, i);
            /* inside stage2: stage2.fe's too (merged into fe: for stage 2) */
            if (ref == MCS_REF_CHAR || strncmp(w->path, "stage2.", 7) != 0) break;
            fe = mcs_node_get(mcs_node_get(w->root, "stage2"), "fe");
            c = mcs_node_get(fe, "body_characteristics");
        }
        return n;
    }
    if (ref == MCS_REF_BODY_OR_GROUND) names[n++] = "ground";
    if (ref == MCS_REF_BODY || ref == MCS_REF_BODY_OR_GROUND)
        list = mcs_node_get(w->root, "bodies");
    if (ref == MCS_REF_FE_PART) list = mcs_node_get(fe, "parts");
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < mcs_node_len(list) && n < max && list->kind == MCS_NODE_SEQ; i++) {
            const mcs_node *nm = mcs_node_get(mcs_node_at(list, i), "name");
            if (nm && nm->text) names[n++] = nm->text;
        }
        /* inside stage2: the parts of stage2.fe too (merged into fe: for stage 2) */
        if (ref != MCS_REF_FE_PART || strncmp(w->path, "stage2.", 7) != 0) break;
        list = mcs_node_get(mcs_node_get(mcs_node_get(w->root, "stage2"), "fe"), "parts");
    }
    return n;
}

/* 1 when name is <entry>_<component> of an fe.parts entry whose generator makes several parts
 * so named (mesh: {generate: motorcycle | sedan_side}, stage3_fe/s3_moto.h, s3_sedan.h); the
 * component itself is the builder's to check (fe_builder: an unknown part at the key's entry) */
static int generated_part(const scn_walk *w, const char *name)
{
    const mcs_node *fe = strncmp(w->path, "stage3.", 7) == 0
                             ? mcs_node_get(mcs_node_get(w->root, "stage3"), "fe")
                             : mcs_node_get(w->root, "fe");
    const mcs_node *list = mcs_node_get(fe, "parts");
    for (int i = 0; i < mcs_node_len(list) && list->kind == MCS_NODE_SEQ; i++) {
        const mcs_node *p = mcs_node_at(list, i), *nm = mcs_node_get(p, "name");
        const char *g = mcs_node_str(mcs_node_get(mcs_node_get(p, "mesh"), "generate"));
        if (!nm || !nm->text || !g || (strcmp(g, "motorcycle") && strcmp(g, "sedan_side")))
            continue;
        const size_t k = strlen(nm->text);
        if (strncmp(name, nm->text, k) == 0 && name[k] == '_' && name[k + 1]) return 1;
    }
    return 0;
}

static const char *ref_what(mcs_sref ref)
{
    switch (ref) {
    case MCS_REF_CHAR:
        return "characteristic";
    case MCS_REF_FE_PART:
        return "FE part";
    case MCS_REF_BODY_LAW:
        return "body characteristic";
    default:
        return "body";
    }
}

static mcs_status check_ref(scn_walk *w, mcs_node *v, mcs_sref ref)
{
    mcs_skey sk = {.name = "", .type = MCS_SK_STR, .flags = MCS_SK_NONEMPTY};
    mcs_status st = scn_check_scalar(w, v, &sk);
    if (st) return st;
    const char *names[MAX_NAMES];
    int n = ref_names(w, ref, names, MAX_NAMES);
    for (int i = 0; i < n; i++)
        if (strcmp(names[i], v->text) == 0) return MCS_OK;
    if (ref == MCS_REF_FE_PART && generated_part(w, v->text)) return MCS_OK;
    char dym[96];
    scn_suggest(dym, sizeof dym, v->text, names, n);
    return FAIL(w, v, MCS_ERR_KEY, "unknown %s '%.80s'%s", ref_what(ref), v->text, dym);
}

/* ---- sequences ---- */

static mcs_status want_seq(scn_walk *w, const mcs_node *v, const char *what, int nmin, int nmax)
{
    char got[100];
    if (v->kind != MCS_NODE_SEQ)
        return FAIL(w, v, MCS_ERR_TYPE, "expected %s, got %s", what,
                    scn_got_str(v, got, sizeof got));
    if (v->n < nmin || (nmax && v->n > nmax)) {
        if (nmax == nmin) return FAIL(w, v, MCS_ERR_TYPE, "expected %d values, got %d", nmin, v->n);
        if (nmax)
            return FAIL(w, v, MCS_ERR_TYPE, "expected %d to %d values, got %d", nmin, nmax, v->n);
        return FAIL(w, v, MCS_ERR_TYPE, "expected at least %d value%s, got %d", nmin,
                    nmin == 1 ? "" : "s", v->n);
    }
    return MCS_OK;
}

/* each item of a sequence checked by fn */
typedef mcs_status (*item_fn)(scn_walk *w, mcs_node *item, const mcs_skey *k);

static mcs_status each_item(scn_walk *w, mcs_node *seq, const mcs_skey *k, item_fn fn)
{
    mcs_status st = MCS_OK;
    for (int i = 0; i < seq->n && !st; i++) {
        size_t old = scn_walk_push_index(w, i);
        st = scn_walk_set_path(w, seq->items[i]);
        if (!st) st = fn(w, seq->items[i], k);
        scn_walk_pop(w, old);
    }
    return st;
}

static mcs_status vec_item(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    mcs_status st = scn_quantity(w, v, k->dim);
    return st ? st : scn_range_check(w, v, k, v->num, k->dim);
}

static mcs_status int_item(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    mcs_skey ik = *k;
    ik.type = MCS_SK_INT;
    return scn_check_scalar(w, v, &ik);
}

static mcs_status ref_item(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    return check_ref(w, v, k->ref);
}

static mcs_status map_item(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    char got[100];
    if (v->kind != MCS_NODE_MAP)
        return FAIL(w, v, MCS_ERR_TYPE, "expected a mapping (a %s), got %s", k->sub->what,
                    scn_got_str(v, got, sizeof got));
    return walk_map(w, v, k->sub);
}

static mcs_status check_vec(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    char what[140], d[96];
    mcs_dim_describe(k->dim, d, sizeof d);
    snprintf(what, sizeof what, "a list of %s values", d);
    mcs_status st = want_seq(w, v, what, k->nmin, k->nmax);
    if (!st) st = each_item(w, v, k, vec_item);
    if (st || !(k->flags & MCS_SK_NONZERO)) return st;
    for (int i = 0; i < v->n; i++)
        if (v->items[i]->num != 0.0) return MCS_OK;
    return FAIL(w, v, MCS_ERR_RANGE, "must not be the zero vector (it is a direction)");
}

/* ---- curves [[x, y], ...] ---- */

static mcs_status curve_point(scn_walk *w, mcs_node *p, const mcs_skey *k)
{
    mcs_status st = want_seq(w, p, "a point [x, y]", 2, 2);
    if (st) return st;
    for (int j = 0; j < 2 && !st; j++) {
        size_t old = scn_walk_push_index(w, j);
        st = scn_walk_set_path(w, p->items[j]);
        if (!st) st = scn_quantity(w, p->items[j], j ? k->dim_y : k->dim);
        scn_walk_pop(w, old);
    }
    if (!st) st = scn_range_check(w, p->items[0], k, p->items[0]->num, k->dim);
    return st;
}

static mcs_status check_curve(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    int nmin = k->nmin > 0 ? k->nmin : 2;
    mcs_status st = want_seq(w, v, "a curve [[x, y], ...]", nmin, 0);
    if (!st) st = each_item(w, v, k, curve_point);
    for (int i = 1; i < v->n && !st; i++) {
        double x0 = v->items[i - 1]->items[0]->num, x1 = v->items[i]->items[0]->num;
        if (!(x1 > x0))
            st = mcs_node_error(v->items[i], w->err, MCS_ERR_RANGE,
                                "x must increase from point to point (%g after %g)", x1, x0);
    }
    return st;
}

/* ---- lists of maps, named maps ---- */

/* names (keys flagged UNIQUE) must differ across the items of a list */
static mcs_status check_unique(scn_walk *w, mcs_node *seq, const mcs_smap *sm)
{
    for (const mcs_skey *k = sm->keys; k->name; k++) {
        if (!(k->flags & MCS_SK_UNIQUE)) continue;
        for (int i = 0; i < seq->n; i++) {
            const mcs_node *a = mcs_node_get(seq->items[i], k->name);
            for (int j = 0; a && a->text && j < i; j++) {
                const mcs_node *b = mcs_node_get(seq->items[j], k->name);
                if (b && b->text && strcmp(a->text, b->text) == 0)
                    return mcs_node_error(a, w->err, MCS_ERR_KEY,
                                          "duplicate %s '%.80s' (first at %s:%d)", k->name, a->text,
                                          b->file, b->line);
            }
        }
    }
    return MCS_OK;
}

static mcs_status check_list(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    char what[120], pl[80];
    snprintf(what, sizeof what, "a list of %s", scn_plural(k->sub->what, pl, sizeof pl));
    mcs_status st = want_seq(w, v, what, (k->flags & MCS_SK_NONEMPTY) ? 1 : 0, 0);
    if (!st) st = each_item(w, v, k, map_item);
    if (!st) st = check_unique(w, v, k->sub);
    return st;
}

static mcs_status check_named(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    char got[100];
    if (v->kind != MCS_NODE_MAP)
        return FAIL(w, v, MCS_ERR_TYPE, "expected a mapping {<name>: %s}, got %s", k->sub->what,
                    scn_got_str(v, got, sizeof got));
    mcs_status st = MCS_OK;
    for (int i = 0; i < v->n && !st; i++) {
        size_t old = scn_walk_push_key(w, v->keys[i]->text);
        st = scn_walk_set_path(w, v->items[i]);
        if (!st) st = map_item(w, v->items[i], k);
        scn_walk_pop(w, old);
    }
    return st;
}

/* ---- maps ---- */

static const mcs_skey *find_key(const mcs_skey *keys, const char *name)
{
    for (; keys && keys->name; keys++)
        if (strcmp(keys->name, name) == 0) return keys;
    return NULL;
}

static int is_hidden_variant(const mcs_svariant *v)
{
    return v->value[0] == '(';
}

static const mcs_smap *variant_named(const mcs_smap *sm, const char *value, int hidden_ok)
{
    for (const mcs_svariant *v = sm->variants; v->value; v++)
        if ((hidden_ok || !is_hidden_variant(v)) && strcmp(v->value, value) == 0) return v->map;
    return NULL;
}

/* "a/b/c" (visible variants) and the closest one to word */
static void variant_list(const mcs_smap *sm, const char *word, char *list, size_t n, char *dym,
                         size_t nd)
{
    const char *cands[64] = {0};
    int nc = 0;
    size_t k = 0;
    list[0] = 0;
    for (const mcs_svariant *v = sm->variants; v->value && nc < 64; v++) {
        if (is_hidden_variant(v)) continue;
        cands[nc++] = v->value;
        k += (size_t)snprintf(list + k, k < n ? n - k : 0, "%s%s", k ? "/" : "", v->value);
    }
    scn_suggest(dym, nd, word ? word : "", cands, nc);
}

static mcs_status choose_variant(scn_walk *w, mcs_node *map, const mcs_smap *sm,
                                 const mcs_smap **vm)
{
    char list[400], dym[96];
    *vm = NULL;
    if (!sm->disc) return MCS_OK;
    const mcs_node *dv = mcs_node_get(map, sm->disc);
    if (!dv || dv->kind == MCS_NODE_NULL) {
        if (sm->disc_default) {
            *vm = variant_named(sm, sm->disc_default, 1);
            return MCS_OK;
        }
        variant_list(sm, NULL, list, sizeof list, dym, sizeof dym);
        return scn_walk_fail(w, map, sm->disc, MCS_ERR_KEY, "required key is missing (one of %s)",
                             list);
    }
    if (dv->kind == MCS_NODE_STR && (*vm = variant_named(sm, dv->text, 0))) return MCS_OK;
    variant_list(sm, dv->text, list, sizeof list, dym, sizeof dym);
    char got[100];
    return scn_walk_fail(w, dv, sm->disc, MCS_ERR_RANGE, "%s is not one of %s%s",
                         scn_got_str(dv, got, sizeof got), list, dym);
}

static mcs_status unknown_key(scn_walk *w, const mcs_node *key, const mcs_smap *sm,
                              const mcs_smap *vm)
{
    const char *cands[128] = {0};
    int nc = 0;
    for (const mcs_skey *k = vm ? vm->keys : NULL; k && k->name && nc < 128; k++)
        cands[nc++] = k->name;
    for (const mcs_skey *k = sm->keys; k->name && nc < 128; k++)
        cands[nc++] = k->name;
    char dym[96];
    scn_suggest(dym, sizeof dym, key->text, cands, nc);
    const char *what = vm ? vm->what : sm->what;
    return scn_walk_fail(w, key, key->text, MCS_ERR_KEY, "unknown key in a %s%s", what, dym);
}

static mcs_status walk_entries(scn_walk *w, mcs_node *map, const mcs_smap *sm, const mcs_smap *vm)
{
    mcs_status st = MCS_OK;
    for (int i = 0; i < map->n && !st; i++) {
        const char *name = map->keys[i]->text;
        const mcs_skey *k = vm ? find_key(vm->keys, name) : NULL;
        if (!k) k = find_key(sm->keys, name);
        if (!k && !sm->open) return unknown_key(w, map->keys[i], sm, vm);
        size_t old = scn_walk_push_key(w, name);
        st = scn_walk_set_path(w, map->items[i]);
        if (!st) st = k ? walk_value(w, map->items[i], k) : walk_any(w, map->items[i]);
        scn_walk_pop(w, old);
    }
    return st;
}

static mcs_status check_required(scn_walk *w, mcs_node *map, const mcs_skey *keys)
{
    for (const mcs_skey *k = keys; k && k->name; k++) {
        if (!(k->flags & MCS_SK_REQ)) continue;
        const mcs_node *v = mcs_node_get(map, k->name);
        if (!v)
            return scn_walk_fail(w, map, k->name, MCS_ERR_KEY, "required key is missing%s%s",
                                 k->doc ? ": " : "", k->doc ? k->doc : "");
        if (v->kind == MCS_NODE_NULL)
            return scn_walk_fail(w, v, k->name, MCS_ERR_TYPE, "required key has no value");
    }
    return MCS_OK;
}

static mcs_status walk_map(scn_walk *w, mcs_node *map, const mcs_smap *sm)
{
    const mcs_smap *vm = NULL;
    mcs_status st = choose_variant(w, map, sm, &vm);
    if (!st) st = walk_entries(w, map, sm, vm);
    if (!st) st = check_required(w, map, sm->keys);
    if (!st && vm) st = check_required(w, map, vm->keys);
    if (!st && sm->check) st = sm->check(w, map);
    if (!st && vm && vm->check) st = vm->check(w, map);
    return st;
}

static mcs_status walk_value(scn_walk *w, mcs_node *v, const mcs_skey *k)
{
    if (v->kind == MCS_NODE_NULL) return MCS_OK; /* null: not given (required: see above) */
    switch (k->type) {
    case MCS_SK_VEC:
        return check_vec(w, v, k);
    case MCS_SK_INTS: {
        mcs_status st = want_seq(w, v, "a list of integers", k->nmin, k->nmax);
        return st ? st : each_item(w, v, k, int_item);
    }
    case MCS_SK_REF:
        return check_ref(w, v, k->ref);
    case MCS_SK_REFS: {
        mcs_status st = want_seq(w, v, "a list of names", k->nmin, k->nmax);
        return st ? st : each_item(w, v, k, ref_item);
    }
    case MCS_SK_CURVE:
        return check_curve(w, v, k);
    case MCS_SK_MAP:
        /* a map key with a reference: a scalar is the name of one */
        if (k->ref && v->kind != MCS_NODE_MAP && v->kind != MCS_NODE_SEQ)
            return check_ref(w, v, k->ref);
        return map_item(w, v, k);
    case MCS_SK_LIST:
        return check_list(w, v, k);
    case MCS_SK_NAMED:
        return check_named(w, v, k);
    case MCS_SK_ANY:
        return walk_any(w, v);
    case MCS_SK_DISC:
        v->kind = MCS_NODE_STR;
        return MCS_OK; /* checked by choose_variant */
    default:
        return scn_check_scalar(w, v, k);
    }
}

mcs_status scn_validate(mcs_scenario *scn, mcs_error *err)
{
    scn_walk local = {.scn = scn, .err = err, .root = scn->root};
    mcs_status st = scn_walk_set_path(&local, scn->root);
    return st ? st : walk_map(&local, scn->root, &mcs_schema_root);
}

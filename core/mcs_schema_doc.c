/* mcs_schema_doc.c: the key reference (Markdown) written from the schema tables, so the
 * documentation cannot drift from what the reader accepts (docs/scenario_keys.md) */
#include "core/mcs_schema.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SECTIONS 128

typedef struct {
    const mcs_smap *map[MAX_SECTIONS];
    char title[MAX_SECTIONS][200];
    int n;
} doc_queue;

static void enqueue(doc_queue *q, const mcs_smap *m, const char *title)
{
    for (int i = 0; i < q->n; i++)
        if (q->map[i] == m) return; /* shared tables are written once */
    if (q->n == MAX_SECTIONS) return;
    q->map[q->n] = m;
    snprintf(q->title[q->n++], sizeof q->title[0], "%s", title);
}

static const char *ref_name(mcs_sref r)
{
    switch (r) {
    case MCS_REF_BODY:
        return "a body";
    case MCS_REF_BODY_OR_GROUND:
        return "a body or `ground`";
    case MCS_REF_CHAR:
        return "a characteristic";
    case MCS_REF_FE_PART:
        return "an FE part";
    case MCS_REF_BODY_LAW:
        return "a body characteristic";
    default:
        return "?";
    }
}

static void unit_of(mcs_dim d, char *buf, size_t n)
{
    char si[48];
    mcs_dim_si(d, si, sizeof si);
    snprintf(buf, n, "%s", si[0] ? si : "-");
}

/* "> 0", ">= 0 and < 0.5", "" */
static void range_of(const mcs_skey *k, char *buf, size_t n)
{
    size_t len = 0;
    buf[0] = 0;
    if (k->flags & (MCS_SK_GT | MCS_SK_GE))
        len += (size_t)snprintf(buf, n, "%s %g", (k->flags & MCS_SK_GT) ? ">" : ">=", k->lo);
    if (k->flags & (MCS_SK_LT | MCS_SK_LE))
        snprintf(buf + len, n - len, "%s%s %g", len ? " and " : "",
                 (k->flags & MCS_SK_LT) ? "<" : "<=", k->hi);
    if (k->flags & MCS_SK_NONZERO) snprintf(buf + len, n - len, "%snot zero", len ? ", " : "");
}

static void type_of(const mcs_skey *k, char *buf, size_t n)
{
    char ux[48], uy[48], pl[80];
    unit_of(k->dim, ux, sizeof ux);
    unit_of(k->dim_y, uy, sizeof uy);
    switch (k->type) {
    case MCS_SK_NUM:
        snprintf(buf, n, "number [%s]", ux);
        break;
    case MCS_SK_INT:
        snprintf(buf, n, "integer");
        break;
    case MCS_SK_VEC:
        if (k->nmin == k->nmax)
            snprintf(buf, n, "%d numbers [%s]", k->nmin, ux);
        else
            snprintf(buf, n, "%d to %d numbers [%s]", k->nmin, k->nmax, ux);
        break;
    case MCS_SK_INTS:
        snprintf(buf, n, "%d integers", k->nmin);
        break;
    case MCS_SK_STR:
        snprintf(buf, n, "string");
        break;
    case MCS_SK_BOOL:
        snprintf(buf, n, "true/false");
        break;
    case MCS_SK_ENUM:
        snprintf(buf, n, "one of `%s`", k->choices);
        break;
    case MCS_SK_REF:
        snprintf(buf, n, "name of %s", ref_name(k->ref));
        break;
    case MCS_SK_REFS:
        snprintf(buf, n, "list of names of %s", ref_name(k->ref));
        break;
    case MCS_SK_CURVE:
        snprintf(buf, n, "curve [[x %s, y %s], ...], >= %d points", ux, uy,
                 k->nmin > 0 ? k->nmin : 2);
        break;
    case MCS_SK_MAP:
        if (k->ref)
            snprintf(buf, n, "%s, or name of %s", k->sub->what, ref_name(k->ref));
        else
            snprintf(buf, n, "%s", k->sub->what);
        break;
    case MCS_SK_LIST:
        snprintf(buf, n, "list of %s", scn_plural(k->sub->what, pl, sizeof pl));
        break;
    case MCS_SK_NAMED:
        snprintf(buf, n, "{name: %s}", k->sub->what);
        break;
    case MCS_SK_ANY:
        snprintf(buf, n, "any");
        break;
    case MCS_SK_DISC:
        snprintf(buf, n, "chooses the variant");
        break;
    }
}

/* sections of the sub-maps; variant: the variant that holds them (NULL: every variant) */
static void queue_children(doc_queue *q, const mcs_skey *keys, const char *title,
                           const char *variant)
{
    char t[160];
    for (const mcs_skey *k = keys; k && k->name; k++) {
        if (!k->sub) continue;
        const char *sfx = k->type == MCS_SK_LIST ? "[]" : k->type == MCS_SK_NAMED ? ".<name>" : "";
        int v = variant && variant[0] != '(';
        snprintf(t, sizeof t, "%s%s%s%s%s%s%s", title, *title ? "." : "", k->name, sfx,
                 v ? " (" : "", v ? variant : "", v ? ")" : "");
        enqueue(q, k->sub, t);
    }
}

static void write_keys(FILE *f, const mcs_skey *keys)
{
    char type[200], range[96];
    for (const mcs_skey *k = keys; k && k->name; k++) {
        type_of(k, type, sizeof type);
        range_of(k, range, sizeof range);
        fprintf(f, "| `%s` | %s | %s | %s | %s |\n", k->name, type,
                (k->flags & MCS_SK_REQ) ? "yes" : "", range, k->doc ? k->doc : "");
    }
}

static void write_section(FILE *f, doc_queue *q, int i)
{
    const mcs_smap *m = q->map[i];
    fprintf(f, "\n## `%s` — %s\n\n", q->title[i][0] ? q->title[i] : "(top level)", m->what);
    if (m->open) fprintf(f, "Other keys are accepted and kept as written.\n\n");
    fprintf(f, "| key | type | required | range | what |\n|---|---|---|---|---|\n");
    write_keys(f, m->keys);
    queue_children(q, m->keys, q->title[i], NULL);
    for (const mcs_svariant *v = m->variants; v && v->value; v++) {
        int hidden = v->value[0] == '(';
        if (hidden)
            fprintf(f, "| *without `%s`* | | | | |\n", m->disc);
        else
            fprintf(f, "| *`%s: %s`* | | | | |\n", m->disc, v->value);
        write_keys(f, v->map->keys);
        queue_children(q, v->map->keys, q->title[i], v->value);
    }
    if (m->disc_default && m->disc_default[0] != '(')
        fprintf(f, "\nWithout `%s`, `%s: %s` is assumed.\n", m->disc, m->disc, m->disc_default);
}

mcs_status mcs_schema_write_markdown(FILE *f)
{
    doc_queue *q = calloc(1, sizeof *q);
    if (!q) return MCS_ERR_NOMEM;
    fprintf(f, "# Scenario keys\n\n"
               "Written by `mcrash check --schema` from `core/mcs_schema.c`; do not edit by hand.\n"
               "Numbers are SI; a string \"value unit\" (`\"48.5 km/h\"`, `\"12 ms\"`) is "
               "converted (see `core/mcs_units.h`).\n"
               "Cross-key rules (inertia, time step, ranges) are in `core/mcs_scn_rules.c`.\n");
    enqueue(q, &mcs_schema_root, "");
    for (int i = 0; i < q->n; i++)
        write_section(f, q, i);
    free(q);
    return ferror(f) ? MCS_ERR_IO : MCS_OK;
}

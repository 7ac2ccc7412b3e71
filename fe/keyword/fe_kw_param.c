/* fe_kw_param: *PARAMETER, *PARAMETER_EXPRESSION (with _LOCAL, _GLOBAL) and
 * *PARAMETER_DUPLICATION, and the `&NAME` / `-&NAME` references in numeric fields
 * (docs/keyword.md, Parameters).
 *
 * A parameter is visible from its definition on: a global one (no option, or _GLOBAL) in every
 * file read after it, a _LOCAL one in the file that defines it and the files it includes, until
 * that file ends; a local one hides a global one of the same name. Names are case-insensitive.
 * A second definition of a name in the same scope follows *PARAMETER_DUPLICATION's DFLAG:
 * 1 (the default) warn and keep the first, 2 warn and take the new, 3 refuse, 4 take the new
 * silently, 5 keep the first silently (the DFLAG values of ansys/pydyna's keyword class
 * ParameterDuplication, which quotes the LS-DYNA manual). */
#include "fe/fe_kw_impl.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define KW_PARAM_NAME 40

typedef struct {
    char name[KW_PARAM_NAME]; /* upper case */
    char type;                /* 'R', 'I' or 'C' */
    double v;                 /* R, I: the value as written (no unit conversion) */
    char str[84];             /* C: the text */
    int file;                 /* _LOCAL: the defining file; -1 global */
    fe_kw_loc loc;
} kw_param;

struct kw_params {
    int n, cap;
    kw_param *p;
    int dflag; /* *PARAMETER_DUPLICATION (1..5) */
};

void kw_param_free(kw_ctx *c)
{
    if (!c->par) return;
    free(c->par->p);
    free(c->par);
    c->par = NULL;
}

/* the visible parameter of that (upper-case) name: the newest definition */
static const kw_param *find(const kw_ctx *c, const char *name)
{
    if (!c->par) return NULL;
    for (int i = c->par->n - 1; i >= 0; i--)
        if (strcmp(c->par->p[i].name, name) == 0) return &c->par->p[i];
    return NULL;
}

mcs_status kw_param_file_done(kw_ctx *c, int file)
{
    if (!c->par) return MCS_OK;
    int k = 0;
    for (int i = 0; i < c->par->n; i++)
        if (c->par->p[i].file != file) c->par->p[k++] = c->par->p[i];
    c->par->n = k;
    return MCS_OK;
}

int kw_param_is_ref(const char *p, int n)
{
    return (n > 1 && p[0] == '&') || (n > 2 && p[0] == '-' && p[1] == '&');
}

static void upper_name(const char *p, int n, char *out)
{
    while (n > 0 && (*p == ' ' || *p == '\t')) p++, n--;
    while (n > 0 && (p[n - 1] == ' ' || p[n - 1] == '\t')) n--;
    int k = n < KW_PARAM_NAME - 1 ? n : KW_PARAM_NAME - 1;
    for (int i = 0; i < k; i++) out[i] = (char)toupper((unsigned char)p[i]);
    out[k] = 0;
}

mcs_status kw_param_num(kw_ctx *c, const kw_card *cd, const char *p, int n, const char *field,
                        int as_int, double *out)
{
    int neg = p[0] == '-', col = (int)(p - cd->s) + 1;
    char name[KW_PARAM_NAME];
    upper_name(p + 1 + neg, n - 1 - neg, name);
    const kw_param *q = find(c, name);
    if (!q)
        return kw_fail(c, cd->file, cd->line, col, MCS_ERR_FORMAT,
                       "field %s: parameter '%s' is not defined (by a *PARAMETER before it)",
                       field, name);
    double v = q->v;
    if (q->type == 'C' && kw_parse_real(q->str, (int)strlen(q->str), &v))
        return kw_fail(c, cd->file, cd->line, col, MCS_ERR_FORMAT,
                       "field %s: parameter '%s' = '%s' is not a number", field, name, q->str);
    if (as_int && (v != floor(v) || fabs(v) > 2147483647.0))
        return kw_fail(c, cd->file, cd->line, col, MCS_ERR_FORMAT,
                       "field %s: parameter '%s' = %.17g is not an integer", field, name, v);
    *out = neg ? -v : v;
    return MCS_OK;
}

/* a new parameter in the current scope, after the duplication rule; *slot NULL when ignored */
static mcs_status define(kw_ctx *c, const kw_card *cd, int col, const char *name, char type,
                         int local, kw_param **slot)
{
    *slot = NULL;
    if (!c->par && !(c->par = calloc(1, sizeof *c->par)))
        return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    int file = local ? cd->file : -1;
    kw_param *old = NULL;
    for (int i = 0; i < c->par->n && !old; i++)
        if (strcmp(c->par->p[i].name, name) == 0 && c->par->p[i].file == file)
            old = &c->par->p[i];
    int flag = c->par->dflag ? c->par->dflag : 1;
    if (old && flag == 3)
        return kw_fail(c, cd->file, cd->line, col, MCS_ERR_FORMAT,
                       "parameter '%s' defined twice (first at %s:%d; *PARAMETER_DUPLICATION 3)",
                       name, c->d->file[old->loc.file], old->loc.line);
    if (old && (flag == 1 || flag == 2) && !c->o->quiet)
        mcs_log(MCS_LOG_WARN,
                "%s:%d: warning: *%s: parameter '%s' defined again (first at %s:%d): the %s value "
                "is used",
                c->d->file[cd->file], cd->line, c->kw, name, c->d->file[old->loc.file],
                old->loc.line, flag == 1 ? "first" : "new");
    if (old && (flag == 1 || flag == 5)) return MCS_OK;
    kw_param *q = old;
    if (!q) q = kw_push((void **)&c->par->p, &c->par->n, &c->par->cap, sizeof *q);
    if (!q) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    memset(q, 0, sizeof *q);
    snprintf(q->name, sizeof q->name, "%s", name);
    q->type = type;
    q->file = file;
    q->loc = (fe_kw_loc){cd->file, cd->line};
    *slot = q;
    return MCS_OK;
}

/* PRMR: a type letter R, I or C, then the name ("RTHICK" or "R THICK") */
static mcs_status prmr(kw_ctx *c, const kw_card *cd, const char *txt, int col, char *type,
                       char *name)
{
    *type = (char)toupper((unsigned char)txt[0]);
    upper_name(txt + 1, (int)strlen(txt + 1), name);
    int ok = strchr("RIC", *type) && *type && name[0] && !isdigit((unsigned char)name[0]);
    for (const char *p = name; ok && *p; p++) ok = isalnum((unsigned char)*p) || *p == '_';
    if (!ok)
        return kw_fail(c, cd->file, cd->line, col, MCS_ERR_FORMAT,
                       "field PRMR: '%s' is not a type R, I or C followed by a name", txt);
    return MCS_OK;
}

/* *PARAMETER: up to four PRMR VAL pairs per card */
static mcs_status params(kw_ctx *c, const kw_card *cards, int ncard, int local)
{
    for (int i = 0; i < ncard; i++) {
        const kw_card *cd = &cards[i];
        for (int k = 0; k < 4; k++) {
            char txt[96], name[KW_PARAM_NAME], type;
            int col = kw_field_text(c, cd, &KW_L10, 2 * k, txt, sizeof txt);
            if (!txt[0]) continue;
            kw_param *q;
            mcs_status st = prmr(c, cd, txt, col, &type, name);
            if (!st) st = define(c, cd, col, name, type, local, &q);
            if (st) return st;
            if (!q) continue;
            int iv = 0;
            if (type == 'R') st = kw_real(c, cd, &KW_L10, 2 * k + 1, "VAL", 0, &q->v);
            if (type == 'I') st = kw_int(c, cd, &KW_L10, 2 * k + 1, "VAL", 0, &iv), q->v = iv;
            if (type == 'C') kw_field_text(c, cd, &KW_L10, 2 * k + 1, q->str, sizeof q->str);
            if (st) return st;
        }
    }
    return MCS_OK;
}

static int look(void *user, const char *name, double *v)
{
    const kw_param *q = find(user, name);
    if (!q) return -1;
    if (q->type == 'C') return kw_parse_real(q->str, (int)strlen(q->str), v);
    *v = q->v;
    return 0;
}

/* *PARAMETER_EXPRESSION: PRMR (one field) then the expression over the rest of the card; in
 * free format PRMR ends at the first comma */
static mcs_status expressions(kw_ctx *c, const kw_card *cards, int ncard, int local)
{
    int w = c->fmt == KW_FMT_LONG ? 20 : 10;
    for (int i = 0; i < ncard; i++) {
        const kw_card *cd = &cards[i];
        const char *comma = memchr(cd->s, ',', (size_t)cd->len), *paren = strchr(cd->s, '(');
        int split = comma && (!paren || comma < paren) ? (int)(comma - cd->s) : w;
        int at = split < cd->len ? split + (comma && split == comma - cd->s) : cd->len;
        char txt[96], name[KW_PARAM_NAME], type, ex[1024];
        kw_text(cd, 0, split, txt, sizeof txt);
        if (!txt[0]) continue;
        snprintf(ex, sizeof ex, "%s", cd->s + at);
        kw_param *q;
        mcs_status st = prmr(c, cd, txt, 1, &type, name);
        if (!st && type == 'C')
            return kw_fail(c, cd->file, cd->line, 1, MCS_ERR_FORMAT,
                           "parameter '%s': an expression gives R or I, not C", name);
        double v = 0;
        int pos = 0;
        char msg[160];
        if (!st && kw_expr_eval(ex, look, c, &v, &pos, msg, sizeof msg))
            return kw_fail(c, cd->file, cd->line, at + pos + 1, MCS_ERR_FORMAT,
                           "parameter '%s': %s", name, msg);
        if (!st) st = define(c, cd, 1, name, type, local, &q);
        if (st) return st;
        if (!q) continue;
        /* I: toward zero as Fortran's INT, after a rounding-noise guard */
        double r = round(v);
        q->v = type == 'R' ? v : fabs(v - r) <= 1e-9 * fmax(1.0, fabs(v)) ? r : trunc(v);
    }
    return MCS_OK;
}

int kw_param_block(kw_ctx *c, const kw_card *cards, int ncard, mcs_status *st)
{
    const char *k = c->kw;
    if (strncmp(k, "PARAMETER", 9) != 0 || c->has_id || c->has_title) return 0;
    k += 9;
    if (strcmp(k, "_DUPLICATION") == 0) {
        int flag = 1;
        *st = ncard ? kw_int(c, &cards[0], &KW_L10, 0, "DFLAG", 1, &flag) : MCS_OK;
        if (!*st && (flag < 1 || flag > 5))
            *st = kw_fail(c, cards[0].file, cards[0].line, 1, MCS_ERR_FORMAT,
                          "field DFLAG: %d is not 1..5", flag);
        if (!*st && !c->par && !(c->par = calloc(1, sizeof *c->par)))
            *st = MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        if (!*st) c->par->dflag = flag;
        return 1;
    }
    int expr = strncmp(k, "_EXPRESSION", 11) == 0;
    if (expr) k += 11;
    int local = strcmp(k, "_LOCAL") == 0;
    if (!local && *k && strcmp(k, "_GLOBAL") != 0) return 0;
    *st = expr ? expressions(c, cards, ncard, local) : params(c, cards, ncard, local);
    return 1;
}

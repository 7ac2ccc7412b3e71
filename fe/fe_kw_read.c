/* fe_kw_read: reading a keyword deck: files and *INCLUDE, comment lines, keyword lines with
 * their format options, the data cards of each keyword handed to its handler, unknown
 * keywords listed (see fe_keyword.h). */
#include "fe/fe_kw_impl.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define KW_INCLUDE_DEPTH 8
#define KW_FILE_MAX (1L << 30) /* largest deck file read [B] */

static const struct {
    const char *name;
    double si;
} units_len[] = {{"m", 1}, {"cm", 1e-2}, {"mm", 1e-3}},
  units_time[] = {{"s", 1}, {"ms", 1e-3}, {"us", 1e-6}},
  units_mass[] = {{"kg", 1}, {"g", 1e-3}, {"t", 1e3}, {"tonne", 1e3}};

mcs_status fe_kw_units(const char *units, double unit[3], mcs_error *err)
{
    unit[0] = unit[1] = unit[2] = 1;
    if (!units || !*units) return MCS_OK;
    char buf[64], *tok[3], *save = NULL;
    snprintf(buf, sizeof buf, "%s", units);
    int n = 0;
    for (char *t = strtok_r(buf, "-", &save); t && n < 4; t = strtok_r(NULL, "-", &save))
        tok[n < 3 ? n : 2] = t, n++;
    int ok = n == 3;
    for (int k = 0; k < 3 && ok; k++) {
        int found = 0;
        if (k == 0)
            for (size_t i = 0; i < sizeof units_len / sizeof units_len[0]; i++)
                if (strcmp(tok[k], units_len[i].name) == 0) unit[k] = units_len[i].si, found = 1;
        if (k == 1)
            for (size_t i = 0; i < sizeof units_time / sizeof units_time[0]; i++)
                if (strcmp(tok[k], units_time[i].name) == 0) unit[k] = units_time[i].si, found = 1;
        if (k == 2)
            for (size_t i = 0; i < sizeof units_mass / sizeof units_mass[0]; i++)
                if (strcmp(tok[k], units_mass[i].name) == 0) unit[k] = units_mass[i].si, found = 1;
        ok = found;
    }
    if (!ok)
        return MCS_ERR(err, MCS_ERR_UNIT,
                       "keyword: units '%s': expected LENGTH-TIME-MASS with length m|cm|mm, "
                       "time s|ms|us, mass kg|g|t (e.g. mm-ms-kg, mm-s-t, m-s-kg)",
                       units);
    return MCS_OK;
}

static mcs_status read_text(kw_ctx *c, int file, char *text, size_t len);

/* the whole file into memory (NUL-terminated) */
static mcs_status slurp(kw_ctx *c, const char *path, char **out, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return MCS_ERR(c->err, MCS_ERR_IO, "%s: cannot open the keyword file", path);
    char *buf = NULL;
    size_t n = 0, cap = 0;
    for (;;) {
        if (n + 65536 + 1 > cap) {
            size_t nc = cap ? 2 * cap : 65536 * 2;
            char *q = realloc(buf, nc);
            if (!q || nc > (size_t)KW_FILE_MAX) {
                free(q ? q : buf);
                fclose(f);
                return MCS_ERR(c->err, q ? MCS_ERR_FORMAT : MCS_ERR_NOMEM,
                               "%s: keyword file too large", path);
            }
            buf = q;
            cap = nc;
        }
        size_t k = fread(buf + n, 1, 65536, f);
        n += k;
        if (k < 65536) break;
    }
    int bad = ferror(f);
    fclose(f);
    if (bad) {
        free(buf);
        return MCS_ERR(c->err, MCS_ERR_IO, "%s: read error", path);
    }
    buf[n] = 0;
    *out = buf;
    *len = n;
    return MCS_OK;
}

static mcs_status read_file(kw_ctx *c, const char *path)
{
    int fi = kw_add_file(c->d, path);
    if (fi < 0) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    char *text = NULL;
    size_t len = 0;
    mcs_status st = slurp(c, path, &text, &len);
    if (!st) st = read_text(c, fi, text, len);
    free(text);
    return st;
}

/* *INCLUDE: the next card names a file, relative to the including file's folder */
static mcs_status do_include(kw_ctx *c, const kw_card *cards, int ncard)
{
    if (ncard < 1)
        return kw_fail(c, c->kwloc.file, c->kwloc.line, 0, MCS_ERR_FORMAT,
                       "the file name card is missing");
    if (c->depth >= KW_INCLUDE_DEPTH)
        return kw_fail(c, cards[0].file, cards[0].line, 1, MCS_ERR_FORMAT,
                       "includes nested deeper than %d (a loop?)", KW_INCLUDE_DEPTH);
    char name[1024], path[2048];
    kw_text(&cards[0], 0, 0, name, sizeof name);
    if (!name[0])
        return kw_fail(c, cards[0].file, cards[0].line, 1, MCS_ERR_FORMAT, "empty file name");
    const char *from = c->d->file[cards[0].file], *slash = strrchr(from, '/');
    if (name[0] == '/' || !slash)
        snprintf(path, sizeof path, "%s", name);
    else
        snprintf(path, sizeof path, "%.*s/%s", (int)(slash - from), from, name);
    int gfmt = c->gfmt, ended = c->ended;
    c->depth++;
    c->ended = 0;
    mcs_status st = read_file(c, path);
    if (st == MCS_ERR_IO) {
        mcs_error_clear(c->err);
        st = kw_fail(c, cards[0].file, cards[0].line, 1, MCS_ERR_IO, "cannot open '%s'", path);
    }
    c->depth--;
    c->gfmt = gfmt;
    c->ended = ended;
    return st;
}

/* *KEYWORD options: LONG=Y|S, I10=Y|N (memory sizes and the rest are ignored) */
static void keyword_options(kw_ctx *c, const char *rest)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", rest);
    for (char *p = buf; *p; p++) *p = (char)toupper((unsigned char)*p);
    if (strstr(buf, "LONG=Y")) c->gfmt = KW_FMT_LONG;
    else if (strstr(buf, "I10=Y")) c->gfmt = KW_FMT_I10;
    else if (strstr(buf, "LONG=S") || strstr(buf, "I10=N")) c->gfmt = KW_FMT_STD;
}

/* parse a keyword line into c->kw, c->fmt, c->has_title, c->has_id; rest = what follows */
static void keyword_line(kw_ctx *c, const char *s, const char **rest)
{
    const char *p = s + 1;
    size_t n = 0;
    while (p[n] && !isspace((unsigned char)p[n])) n++;
    *rest = p + n;
    size_t k = n < FE_KW_NAME_MAX - 1 ? n : FE_KW_NAME_MAX - 1;
    for (size_t i = 0; i < k; i++) c->kw[i] = (char)toupper((unsigned char)p[i]);
    c->kw[k] = 0;
    c->fmt = c->gfmt;
    /* a format suffix on the name or as the next word */
    char suffix = 0;
    if (k > 0 && strchr("+%-", c->kw[k - 1])) suffix = c->kw[--k], c->kw[k] = 0;
    const char *q = *rest;
    while (*q == ' ' || *q == '\t') q++;
    if (!suffix && strchr("+%-", *q) && *q && (q[1] == 0 || isspace((unsigned char)q[1])))
        suffix = *q;
    if (suffix == '+') c->fmt = KW_FMT_LONG;
    if (suffix == '%') c->fmt = KW_FMT_I10;
    if (suffix == '-') c->fmt = KW_FMT_STD;
    c->has_title = k > 6 && strcmp(c->kw + k - 6, "_TITLE") == 0;
    if (c->has_title) c->kw[k -= 6] = 0;
    c->has_id = k > 3 && strcmp(c->kw + k - 3, "_ID") == 0;
    if (c->has_id) c->kw[k -= 3] = 0;
}

static mcs_status unknown(kw_ctx *c)
{
    fe_kw_deck *d = c->d;
    fe_kw_unknown *u = kw_push((void **)&d->unknown, &d->nunknown, &d->cap_unknown, sizeof *u);
    if (!u) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    snprintf(u->name, sizeof u->name, "%s%s%s", c->kw, c->has_id ? "_ID" : "",
             c->has_title ? "_TITLE" : "");
    u->loc = c->kwloc;
    if (c->o->strict)
        return kw_fail(c, c->kwloc.file, c->kwloc.line, 1, MCS_ERR_FORMAT,
                       "keyword not supported (the supported subset is in docs/keyword.md)");
    return MCS_OK;
}

/* the cards of the keyword in c->kw */
static mcs_status block(kw_ctx *c, const kw_card *cards, int ncard)
{
    mcs_status st = MCS_OK;
    if (strcmp(c->kw, "INCLUDE") == 0 && !c->has_id && !c->has_title)
        return do_include(c, cards, ncard);
    if (strcmp(c->kw, "END") == 0) {
        c->ended = 1;
        return MCS_OK;
    }
    if (kw_dispatch(c, cards, ncard, &st)) return st;
    return unknown(c);
}

static mcs_status read_text(kw_ctx *c, int file, char *text, size_t len)
{
    int cap = 0, ncard = 0, line = 0, in_kw = 0;
    kw_card *cards = NULL;
    mcs_status st = MCS_OK;
    char *p = text, *end = text + len;
    if (memchr(text, 0, len))
        return MCS_ERR(c->err, MCS_ERR_FORMAT, "%s: a NUL byte: not a text file",
                       c->d->file[file]);
    while (p < end && !st && !c->ended) {
        char *nl = memchr(p, '\n', (size_t)(end - p));
        char *e = nl ? nl : end;
        line++;
        *e = 0;
        if (e > p && e[-1] == '\r') e[-1] = 0, e--;
        char *next = nl ? nl + 1 : end;
        if (p[0] == '$') {
            /* a comment */
        } else if (p[0] == '*') {
            if (in_kw) st = block(c, cards, ncard);
            if (st || c->ended) break;
            const char *rest;
            keyword_line(c, p, &rest);
            c->kwloc.file = file;
            c->kwloc.line = line;
            if (strcmp(c->kw, "KEYWORD") == 0) keyword_options(c, rest);
            in_kw = 1;
            ncard = 0;
        } else if (!in_kw) {
            const char *q = p;
            while (*q == ' ' || *q == '\t') q++;
            if (*q)
                st = MCS_ERR(c->err, MCS_ERR_FORMAT,
                             "%s:%d:%d: error: data before the first keyword (a deck starts "
                             "with *KEYWORD)",
                             c->d->file[file], line, (int)(q - p) + 1);
        } else {
            if (kw_grow((void **)&cards, &cap, ncard + 1, sizeof *cards)) {
                st = MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
                break;
            }
            cards[ncard++] = (kw_card){.s = p, .len = (int)(e - p), .line = line, .file = file};
        }
        p = next;
    }
    if (!st && in_kw && !c->ended) st = block(c, cards, ncard);
    free(cards);
    return st;
}

static void log_unknown(const fe_kw_deck *d)
{
    if (d->nunknown == 0) return;
    char list[900];
    size_t at = 0;
    list[0] = 0;
    for (int i = 0; i < d->nunknown && at + 80 < sizeof list; i++)
        at += (size_t)snprintf(list + at, sizeof list - at, "%s*%s (%s:%d)", i ? ", " : "",
                               d->unknown[i].name, d->file[d->unknown[i].loc.file],
                               d->unknown[i].loc.line);
    mcs_log(MCS_LOG_WARN, "%s: warning: %d keyword%s not supported and skipped: %s%s",
            d->file[0], d->nunknown, d->nunknown == 1 ? "" : "s", list,
            at + 80 >= sizeof list ? ", ..." : "");
}

static mcs_status read_any(const char *path, const char *text, size_t len,
                           const fe_kw_opts *opts, fe_kw_deck **out, mcs_error *err)
{
    *out = NULL;
    fe_kw_opts o = opts ? *opts : fe_kw_opts_default();
    fe_kw_deck *d = NULL;
    mcs_status st = fe_kw_deck_create(&d, err);
    if (st) return st;
    st = fe_kw_units(o.units, d->unit, err);
    kw_ctx c = {.d = d, .o = &o, .err = err};
    if (!st && text) {
        char *copy = malloc(len + 1);
        int fi = kw_add_file(d, path);
        if (!copy || fi < 0) st = MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
        if (!st) {
            memcpy(copy, text, len);
            copy[len] = 0;
            st = read_text(&c, fi, copy, len);
        }
        free(copy);
    } else if (!st) {
        st = read_file(&c, path);
    }
    if (!st) st = kw_finish(&c);
    free(c.node);
    if (st) {
        fe_kw_deck_destroy(&d);
        return st;
    }
    if (!o.quiet) log_unknown(d);
    *out = d;
    return MCS_OK;
}

mcs_status fe_kw_read(const char *path, const fe_kw_opts *opts, fe_kw_deck **out, mcs_error *err)
{
    return read_any(path, NULL, 0, opts, out, err);
}

mcs_status fe_kw_read_mem(const char *name, const char *text, size_t len, const fe_kw_opts *opts,
                          fe_kw_deck **out, mcs_error *err)
{
    return read_any(name ? name : "(memory)", text ? text : "", text ? len : 0, opts, out, err);
}

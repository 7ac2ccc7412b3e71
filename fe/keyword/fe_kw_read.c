/* fe_kw_read: reading a keyword deck: files and *INCLUDE, comment lines, keyword lines with
 * their format options, the data cards of each keyword handed to its handler, unknown
 * keywords listed (see fe_keyword.h). */
#include "fe/fe_kw_impl.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

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
    struct stat sb;
    if (fstat(fileno(f), &sb) == 0 && S_ISDIR(sb.st_mode)) {
        fclose(f);
        return MCS_ERR(c->err, MCS_ERR_IO, "%s: a directory, not a keyword file", path);
    }
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
    c->open[c->nopen++] = fi;
    if (!st) st = read_text(c, fi, text, len);
    if (!st) st = kw_param_file_done(c, fi);
    c->nopen--;
    free(text);
    return st;
}

/* folder of a path with its trailing '/' ("" when none) */
static void folder_of(const char *path, char *buf, size_t n)
{
    const char *slash = strrchr(path, '/');
    snprintf(buf, n, "%.*s", slash ? (int)(slash - path) + 1 : 0, path);
}

static int is_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f) fclose(f);
    return f != NULL;
}

/* an absolute name: /x, or a Windows drive (C:/x) */
static int is_absolute(const char *name)
{
    return name[0] == '/' || (isalpha((unsigned char)name[0]) && name[1] == ':');
}

/* the file an *INCLUDE name means: as written when absolute, else relative to the including
 * file's folder, the main deck's folder, then each *INCLUDE_PATH folder; 0 when found */
static int resolve_include(kw_ctx *c, int from, const char *name, char *path, size_t n)
{
    if (is_absolute(name)) {
        snprintf(path, n, "%s", name);
        return is_file(path) ? 0 : -1;
    }
    char dir[1024];
    folder_of(c->d->file[from], dir, sizeof dir);
    snprintf(path, n, "%s%s", dir, name);
    if (is_file(path)) return 0;
    char main_dir[1024];
    folder_of(c->d->file[0], main_dir, sizeof main_dir);
    char first[2048];
    snprintf(first, sizeof first, "%s", path);
    snprintf(path, n, "%s%s", main_dir, name);
    if (is_file(path)) return 0;
    for (int i = 0; i < c->npath; i++) {
        const char *p = c->path[i];
        if (is_absolute(p)) snprintf(path, n, "%s/%s", p, name);
        else snprintf(path, n, "%s%s/%s", main_dir, p, name);
        if (is_file(path)) return 0;
    }
    snprintf(path, n, "%s", first);
    return -1;
}

/* the file being read (or including it) that is the same file as path, -1 when none */
static int open_index(const kw_ctx *c, const char *path)
{
    char *rp = realpath(path, NULL);
    int found = -1;
    for (int i = 0; rp && i < c->nopen && found < 0; i++) {
        char *q = realpath(c->d->file[c->open[i]], NULL);
        if (q && strcmp(q, rp) == 0) found = i;
        free(q);
    }
    free(rp);
    return found;
}

/* the file name of an *INCLUDE card from *cd on: a name ending in " +" goes on over the next
 * card (LS-DYNA's long names); backslashes become slashes (Windows paths); *cd is advanced */
static void include_name(const kw_card *cards, int ncard, int *at, char *name, size_t n)
{
    size_t len = 0;
    name[0] = 0;
    while (*at < ncard) {
        char part[1024];
        kw_text(&cards[(*at)++], 0, 0, part, sizeof part);
        size_t k = strlen(part);
        int more = k >= 2 && part[k - 1] == '+' && part[k - 2] == ' ';
        if (more) part[k -= 2] = 0;
        while (k > 0 && part[k - 1] == ' ') part[--k] = 0;
        len += (size_t)snprintf(name + len, len < n ? n - len : 0, "%s", part);
        if (!more || len >= n) break;
    }
    for (char *p = name; *p; p++)
        if (*p == '\\') *p = '/';
}

/* *INCLUDE: each card names a file (see resolve_include); a card-less *INCLUDE (its names all
 * commented out) includes nothing, as LS-DYNA does */
static mcs_status do_include(kw_ctx *c, const kw_card *cards, int ncard)
{
    mcs_status st = MCS_OK;
    for (int at = 0; at < ncard && !st;) {
        const kw_card *cd = &cards[at];
        char name[1024], path[2048];
        include_name(cards, ncard, &at, name, sizeof name);
        if (!name[0]) continue;
        if (c->nopen > KW_INCLUDE_DEPTH)
            return kw_fail(c, cd->file, cd->line, 1, MCS_ERR_FORMAT,
                           "includes nested deeper than %d", KW_INCLUDE_DEPTH);
        if (resolve_include(c, cd->file, name, path, sizeof path))
            return kw_fail(c, cd->file, cd->line, 1, MCS_ERR_IO, "cannot open '%s'%s", path,
                           c->npath ? " (nor in the *INCLUDE_PATH folders)" : "");
        struct stat sb;
        if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode))
            return kw_fail(c, cd->file, cd->line, 1, MCS_ERR_IO,
                           "'%s' is a directory, not a keyword file", path);
        int loop = open_index(c, path);
        if (loop >= 0)
            return kw_fail(c, cd->file, cd->line, 1, MCS_ERR_FORMAT,
                           "circular include: '%s' is already being read (%s includes it)",
                           c->d->file[c->open[loop]], c->d->file[cd->file]);
        int gfmt = c->gfmt, ended = c->ended;
        c->depth++;
        c->ended = 0;
        st = read_file(c, path);
        c->depth--;
        c->gfmt = gfmt;
        c->ended = ended;
    }
    return st;
}

/* *INCLUDE_PATH, *INCLUDE_PATH_RELATIVE: each card a folder searched for included files
 * (absolute, or relative to the main deck's folder) */
static mcs_status do_include_path(kw_ctx *c, const kw_card *cards, int ncard)
{
    for (int at = 0; at < ncard;) {
        char name[1024];
        include_name(cards, ncard, &at, name, sizeof name);
        size_t k = strlen(name);
        while (k > 1 && name[k - 1] == '/') name[--k] = 0;
        if (!k) continue;
        char **slot = kw_push((void **)&c->path, &c->npath, &c->cap_path, sizeof *slot);
        if (!slot || !(*slot = strdup(name)))
            return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    }
    return MCS_OK;
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

/* keywords the kernel cannot honour and a model without them would be wrong: refused by name
 * even when unknown keywords are only warned of (a name ending in '*' is a prefix) */
static const struct {
    const char *name;
    const char *why;
} refused[] = {
    {"ELEMENT_SPH", "SPH particles: the kernel has no meshless particles"},
    {"SECTION_SPH*", "SPH particles: the kernel has no meshless particles"},
    {"SECTION_ALE*", "ALE: the kernel is Lagrangian only"},
    {"ALE_*", "ALE: the kernel is Lagrangian only"},
};

static mcs_status refuse_known(kw_ctx *c)
{
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        size_t k = strlen(refused[i].name);
        int prefix = refused[i].name[k - 1] == '*';
        if (prefix ? strncmp(c->kw, refused[i].name, k - 1) == 0
                   : strcmp(c->kw, refused[i].name) == 0)
            return kw_fail(c, c->kwloc.file, c->kwloc.line, 1, MCS_ERR_UNSUPPORTED,
                           "not supported (%s)", refused[i].why);
    }
    return MCS_OK;
}

/* an unknown keyword: counted under its name, first place kept */
static mcs_status unknown(kw_ctx *c)
{
    fe_kw_deck *d = c->d;
    char name[sizeof d->unknown[0].name];
    snprintf(name, sizeof name, "%s%s%s", c->kw, c->has_id ? "_ID" : "",
             c->has_title ? "_TITLE" : "");
    fe_kw_unknown *u = NULL;
    for (int i = 0; i < d->nunknown && !u; i++)
        if (strcmp(d->unknown[i].name, name) == 0) u = &d->unknown[i];
    if (!u) {
        u = kw_push((void **)&d->unknown, &d->nunknown, &d->cap_unknown, sizeof *u);
        if (!u) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        snprintf(u->name, sizeof u->name, "%s", name);
        u->loc = c->kwloc;
    }
    u->count++;
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
    if ((strcmp(c->kw, "INCLUDE_PATH") == 0 || strcmp(c->kw, "INCLUDE_PATH_RELATIVE") == 0) &&
        !c->has_id && !c->has_title)
        return do_include_path(c, cards, ncard);
    if (kw_param_block(c, cards, ncard, &st)) return st;
    if (strcmp(c->kw, "END") == 0) {
        c->ended = 1;
        return MCS_OK;
    }
    if (kw_dispatch(c, cards, ncard, &st)) return st;
    st = refuse_known(c);
    return st ? st : unknown(c);
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
    int total = 0;
    for (int i = 0; i < d->nunknown; i++) total += d->unknown[i].count;
    mcs_log(MCS_LOG_WARN, "%s: warning: %d keyword%s not supported and skipped (%d block%s):",
            d->file[0], d->nunknown, d->nunknown == 1 ? "" : "s", total, total == 1 ? "" : "s");
    for (int i = 0; i < d->nunknown; i++)
        mcs_log(MCS_LOG_WARN, "  *%s x%d, first at %s:%d", d->unknown[i].name,
                d->unknown[i].count, d->file[d->unknown[i].loc.file], d->unknown[i].loc.line);
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
            c.open[c.nopen++] = fi;
            st = read_text(&c, fi, copy, len);
        }
        free(copy);
    } else if (!st) {
        st = read_file(&c, path);
    }
    if (!st) st = kw_finish(&c);
    free(c.node);
    for (int i = 0; i < c.npath; i++) free(c.path[i]);
    free(c.path);
    kw_param_free(&c);
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

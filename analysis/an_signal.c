/* an_signal.c: channels, the CSV reader, and channel references (csv, mme, h5) */
#include "analysis/an_signal.h"
#include "analysis/an_mme.h"
#include "analysis/an_units.h"
#include "core/mcs_results.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

void an_signal_free(an_signal *s)
{
    if (!s) return;
    free(s->t);
    free(s->y);
    memset(s, 0, sizeof *s);
}

void an_signals_free(an_signal **cols, int ncols)
{
    if (!cols || !*cols) return;
    for (int i = 0; i < ncols; i++) an_signal_free(&(*cols)[i]);
    free(*cols);
    *cols = NULL;
}

/* whole file into a NUL-terminated buffer */
static mcs_status slurp(const char *path, char **buf, mcs_error *err)
{
    FILE *f = fopen(path, "rb");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    size_t cap = 1 << 16, len = 0;
    char *b = malloc(cap);
    while (b) {
        size_t k = fread(b + len, 1, cap - len - 1, f);
        len += k;
        if (len + 1 < cap) break;
        char *nb = realloc(b, cap * 2);
        if (!nb) {
            free(b);
            b = NULL;
            break;
        }
        b = nb;
        cap *= 2;
    }
    int bad = ferror(f);
    fclose(f);
    if (!b) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory reading the file", path);
    if (bad) {
        free(b);
        return MCS_ERR(err, MCS_ERR_IO, "%s: read error", path);
    }
    b[len] = 0;
    *buf = b;
    return MCS_OK;
}

/* growable columns of doubles while rows are read */
typedef struct {
    int ncol, nrow, cap;
    double **v; /* ncol arrays of cap */
} csv_table;

static int table_push_row(csv_table *tb)
{
    if (tb->nrow < tb->cap) return 1;
    int nc = tb->cap ? tb->cap * 2 : 1024;
    for (int c = 0; c < tb->ncol; c++) {
        double *p = realloc(tb->v[c], (size_t)nc * sizeof(double));
        if (!p) return 0;
        tb->v[c] = p;
    }
    tb->cap = nc;
    return 1;
}

static void table_free(csv_table *tb)
{
    if (tb->v)
        for (int c = 0; c < tb->ncol; c++) free(tb->v[c]);
    free(tb->v);
    memset(tb, 0, sizeof *tb);
}

/* header field "name [unit]" (unit optional) */
typedef struct {
    char name[64];
    char unit[32];
    double factor;
    const char *si;
} csv_head;

static mcs_status parse_head(const char *path, int line, int col, const char *s, size_t n,
                             csv_head *h, mcs_error *err)
{
    while (n && isspace((unsigned char)*s)) s++, n--, col++;
    while (n && isspace((unsigned char)s[n - 1])) n--;
    if (n >= 2 && s[0] == '"' && s[n - 1] == '"') s++, n -= 2, col++;
    const char *lb = memchr(s, '[', n);
    size_t nn = lb ? (size_t)(lb - s) : n;
    while (nn && isspace((unsigned char)s[nn - 1])) nn--;
    if (nn == 0)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d:%d: error: empty column name in the header",
                       path, line, col);
    if (nn >= sizeof h->name)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d:%d: error: column name longer than %d chars",
                       path, line, col, (int)sizeof h->name - 1);
    memcpy(h->name, s, nn);
    h->name[nn] = 0;
    h->unit[0] = 0;
    if (lb) {
        const char *rb = memchr(lb, ']', n - (size_t)(lb - s));
        if (!rb)
            return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d:%d: error: '[' without ']' in \"%.*s\"",
                           path, line, col + (int)(lb - s), (int)n, s);
        size_t un = (size_t)(rb - lb - 1);
        if (un >= sizeof h->unit)
            return MCS_ERR(err, MCS_ERR_UNIT, "%s:%d:%d: error: unit too long", path, line,
                           col + (int)(lb - s) + 1);
        memcpy(h->unit, lb + 1, un);
        h->unit[un] = 0;
    }
    if (!an_unit_to_si(h->unit, &h->factor, &h->si))
        return MCS_ERR(err, MCS_ERR_UNIT,
                       "%s:%d:%d: error: column \"%s\": unknown unit [%s] (known: g, m/s^2, "
                       "kN, N, N*m, Nm, mm, m, deg/s, rad/s, deg, rad, s, ms, ...)",
                       path, line, col + (int)(lb - s) + 1, h->name, h->unit);
    return MCS_OK;
}

static char pick_separator(const char *line, size_t n)
{
    if (memchr(line, ',', n)) return ',';
    if (memchr(line, ';', n)) return ';';
    if (memchr(line, '\t', n)) return '\t';
    return ',';
}

/* header line into heads; returns count through *nh */
static mcs_status read_header(const char *path, int line, const char *s, size_t n, char sep,
                              csv_head **heads, int *nh, mcs_error *err)
{
    int cnt = 1;
    for (size_t i = 0; i < n; i++) cnt += s[i] == sep;
    csv_head *h = calloc((size_t)cnt, sizeof *h);
    if (!h) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
    size_t a = 0;
    for (int k = 0; k < cnt; k++) {
        size_t b = a;
        while (b < n && s[b] != sep) b++;
        mcs_status st = parse_head(path, line, (int)a + 1, s + a, b - a, &h[k], err);
        if (st) {
            free(h);
            return st;
        }
        a = b + 1;
    }
    if (cnt < 2) {
        free(h);
        return MCS_ERR(err, MCS_ERR_FORMAT,
                       "%s:%d:1: error: the header needs a time column and at least one channel "
                       "(\"time [s], name [unit], ...\")",
                       path, line);
    }
    if (strcmp(h[0].si, "s") != 0 && strcmp(h[0].si, "-") != 0) {
        mcs_status st = MCS_ERR(err, MCS_ERR_UNIT,
                                "%s:%d:1: error: the first column is time; its unit [%s] is not "
                                "a time unit (s, ms, us)",
                                path, line, h[0].unit);
        free(h);
        return st;
    }
    *heads = h;
    *nh = cnt;
    return MCS_OK;
}

/* one data row into the table */
static mcs_status read_row(const char *path, int line, const char *s, size_t n, char sep,
                           const csv_head *h, csv_table *tb, mcs_error *err)
{
    if (!table_push_row(tb)) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
    size_t a = 0;
    for (int c = 0; c < tb->ncol; c++) {
        if (a > n)
            return MCS_ERR(err, MCS_ERR_FORMAT,
                           "%s:%d:%d: error: %d values on this line, the header has %d columns",
                           path, line, (int)n + 1, c, tb->ncol);
        size_t b = a;
        while (b < n && s[b] != sep) b++;
        char field[128];
        size_t fl = b - a;
        int col = (int)a + 1;
        while (fl && isspace((unsigned char)s[a])) a++, fl--, col++;
        while (fl && isspace((unsigned char)s[a + fl - 1])) fl--;
        if (fl == 0 || fl >= sizeof field)
            return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d:%d: error: column \"%s\": %s", path, line,
                           col, h[c].name, fl ? "value too long" : "empty value");
        memcpy(field, s + a, fl);
        field[fl] = 0;
        char *end;
        errno = 0;
        double v = strtod(field, &end);
        if (*end || end == field || !isfinite(v) || errno == ERANGE)
            return MCS_ERR(err, MCS_ERR_FORMAT,
                           "%s:%d:%d: error: column \"%s\": \"%s\" is not a finite number", path,
                           line, col, h[c].name, field);
        tb->v[c][tb->nrow] = v * h[c].factor;
        if (c == 0 && tb->nrow > 0 && !(tb->v[0][tb->nrow] > tb->v[0][tb->nrow - 1]))
            return MCS_ERR(err, MCS_ERR_FORMAT,
                           "%s:%d:%d: error: time %s is not after the previous row's time", path,
                           line, col, field);
        a = b + 1;
    }
    if (a <= n)
        return MCS_ERR(err, MCS_ERR_FORMAT,
                       "%s:%d:%d: error: more values on this line than the %d header columns", path,
                       line, (int)a, tb->ncol);
    tb->nrow++;
    return MCS_OK;
}

/* header + rows; blank lines and lines starting with '#' are skipped */
static mcs_status parse_csv(const char *path, const char *buf, csv_head **heads, csv_table *tb,
                            mcs_error *err)
{
    int line = 0, nh = 0;
    char sep = ',';
    *heads = NULL;
    const char *p = buf;
    while (*p) {
        const char *e = strchr(p, '\n');
        size_t n = e ? (size_t)(e - p) : strlen(p);
        line++;
        size_t m = n;
        if (m && p[m - 1] == '\r') m--;
        size_t k = 0;
        while (k < m && isspace((unsigned char)p[k])) k++;
        if (k < m && p[k] != '#') {
            mcs_status st;
            if (!*heads) {
                sep = pick_separator(p, m);
                st = read_header(path, line, p, m, sep, heads, &nh, err);
                if (!st) {
                    tb->ncol = nh;
                    tb->v = calloc((size_t)nh, sizeof(double *));
                    if (!tb->v) st = MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
                }
            } else {
                st = read_row(path, line, p, m, sep, *heads, tb, err);
            }
            if (st) return st;
        }
        p += n + (e ? 1 : 0);
    }
    if (!*heads) return MCS_ERR(err, MCS_ERR_FORMAT, "%s:1:1: error: no header line", path);
    if (tb->nrow < 2)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d:1: error: %d data rows, at least 2 needed",
                       path, line > 0 ? line : 1, tb->nrow);
    return MCS_OK;
}

mcs_status an_csv_read(const char *path, an_signal **cols, int *ncols, mcs_error *err)
{
    *cols = NULL;
    *ncols = 0;
    char *buf = NULL;
    mcs_status st = slurp(path, &buf, err);
    if (st) return st;
    csv_head *heads = NULL;
    csv_table tb = {0};
    st = parse_csv(path, buf, &heads, &tb, err);
    free(buf);
    an_signal *out = NULL;
    if (!st) {
        out = calloc((size_t)tb.ncol - 1, sizeof *out);
        if (!out) st = MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
    }
    for (int c = 1; !st && c < tb.ncol; c++) {
        an_signal *s = &out[c - 1];
        snprintf(s->name, sizeof s->name, "%s", heads[c].name);
        snprintf(s->unit, sizeof s->unit, "%s", heads[c].si);
        s->n = tb.nrow;
        s->t = malloc((size_t)tb.nrow * sizeof(double));
        s->y = malloc((size_t)tb.nrow * sizeof(double));
        if (!s->t || !s->y) {
            st = MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
            break;
        }
        memcpy(s->t, tb.v[0], (size_t)tb.nrow * sizeof(double));
        memcpy(s->y, tb.v[c], (size_t)tb.nrow * sizeof(double));
    }
    int n = tb.ncol - 1;
    free(heads);
    table_free(&tb);
    if (st) {
        if (out) an_signals_free(&out, n);
        return st;
    }
    *cols = out;
    *ncols = n;
    return MCS_OK;
}

mcs_status an_signal_copy(const an_signal *src, an_signal *dst, mcs_error *err)
{
    *dst = *src;
    dst->t = malloc((size_t)src->n * sizeof(double));
    dst->y = malloc((size_t)src->n * sizeof(double));
    if (!dst->t || !dst->y) {
        an_signal_free(dst);
        return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory copying channel %s", src->name);
    }
    memcpy(dst->t, src->t, (size_t)src->n * sizeof(double));
    memcpy(dst->y, src->y, (size_t)src->n * sizeof(double));
    return MCS_OK;
}

int an_signal_find(const an_signal *cols, int ncols, const char *name)
{
    for (int i = 0; i < ncols; i++)
        if (strcmp(cols[i].name, name) == 0) return i;
    for (int i = 0; i < ncols; i++)
        if (strcasecmp(cols[i].name, name) == 0) return i;
    return -1;
}

static int ends_with(const char *s, size_t n, const char *suf)
{
    size_t k = strlen(suf);
    return n >= k && strncasecmp(s + n - k, suf, k) == 0;
}

static mcs_status ref_csv(const char *file, const char *col, an_signal *out, mcs_error *err)
{
    an_signal *cols = NULL;
    int n = 0;
    mcs_status st = an_csv_read(file, &cols, &n, err);
    if (st) return st;
    int k = -1;
    if (col) {
        k = an_signal_find(cols, n, col);
        if (k < 0) {
            char names[512] = "";
            for (int i = 0; i < n; i++) {
                size_t l = strlen(names);
                snprintf(names + l, sizeof names - l, "%s%s", i ? ", " : "", cols[i].name);
            }
            st = MCS_ERR(err, MCS_ERR_KEY, "%s: no column \"%s\" (columns: %s)", file, col, names);
        }
    } else if (n == 1) {
        k = 0;
    } else {
        st = MCS_ERR(err, MCS_ERR_USAGE,
                     "%s: %d channel columns; name one as %s:COLUMN (first: %s)", file, n, file,
                     cols[0].name);
    }
    if (!st) {
        *out = cols[k];
        memset(&cols[k], 0, sizeof cols[k]);
    }
    an_signals_free(&cols, n);
    return st;
}

/* "/stageN/..." -> "/stageN/time"; "/path[k]" selects column k of an [nt, w] dataset */
static mcs_status ref_h5(const char *file, const char *sel, an_signal *out, mcs_error *err)
{
    if (!sel || sel[0] != '/')
        return MCS_ERR(err, MCS_ERR_USAGE, "%s: name a dataset as %s:/stageN/channels/NAME", file,
                       file);
    char path[1024], tpath[1024];
    snprintf(path, sizeof path, "%s", sel);
    long col = -1;
    size_t pl = strlen(path);
    if (pl > 2 && path[pl - 1] == ']') {
        char *lb = strrchr(path, '[');
        char *end;
        if (lb) {
            col = strtol(lb + 1, &end, 10);
            if (end != path + pl - 1 || col < 0)
                return MCS_ERR(err, MCS_ERR_USAGE, "%s: bad column index in %s", file, sel);
            *lb = 0;
        }
    }
    const char *slash = strchr(path + 1, '/');
    if (!slash)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: not inside a stage group (/stageN/...)", file,
                       sel);
    snprintf(tpath, sizeof tpath, "%.*s/time", (int)(slash - path), path);
    mcs_results *r = NULL;
    mcs_status st = mcs_results_open(&r, file, err);
    if (st) return st;
    mcs_array a = {0}, ta = {0};
    st = mcs_results_read(r, path, &a, err);
    if (!st) st = mcs_results_read(r, tpath, &ta, err);
    size_t nt = a.rank >= 1 ? a.dims[0] : 0, w = a.rank == 2 ? a.dims[1] : 1;
    if (!st && (a.rank < 1 || a.rank > 2 || (a.rank == 2 && col < 0) || (long)w <= col))
        st = MCS_ERR(err, MCS_ERR_FORMAT,
                     "%s:%s: shape [%zu%s] does not give one channel (use %s[k] for column k of "
                     "a two-dimensional dataset)",
                     file, path, nt, a.rank == 2 ? ", ..." : "", path);
    if (!st && (ta.rank != 1 || ta.dims[0] != nt))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s has %zu rows, %s has %zu", file, path, nt,
                     tpath, ta.rank == 1 ? ta.dims[0] : 0);
    double factor = 1;
    const char *si = "-";
    if (!st && !an_unit_to_si(a.unit, &factor, &si))
        st = MCS_ERR(err, MCS_ERR_UNIT, "%s:%s: unknown unit \"%s\"", file, path, a.unit);
    if (!st && nt < 2) st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: %zu samples", file, path, nt);
    if (!st) {
        out->t = malloc(nt * sizeof(double));
        out->y = malloc(nt * sizeof(double));
        if (!out->t || !out->y) st = MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", file);
    }
    if (!st) {
        for (size_t i = 0; !st && i < nt; i++) {
            out->t[i] = ta.v[i];
            out->y[i] = a.v[i * w + (col < 0 ? 0 : (size_t)col)] * factor;
            if (!isfinite(out->t[i]) || (i > 0 && !(out->t[i] > out->t[i - 1])))
                st = MCS_ERR(err, MCS_ERR_FORMAT,
                             "%s:%s[%zu] = %g: not finite or not after the one before (the time "
                             "of %s)",
                             file, tpath, i, out->t[i], sel);
            else if (!isfinite(out->y[i]))
                st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: sample %zu is not finite", file, sel, i);
            else if (i > 0 && !(out->t[i] > out->t[i - 1]))
                st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: time %zu (%g s) is not after %g s",
                             file, tpath, i, out->t[i], out->t[i - 1]);
        }
    }
    if (!st) {
        out->n = (int)nt;
        snprintf(out->unit, sizeof out->unit, "%s", si);
        const char *base = strrchr(sel, '/') + 1;
        snprintf(out->name, sizeof out->name, "%s", base);
        double cfc;
        mcs_error e2 = {0};
        if (mcs_results_has_attr(r, path, "cfc") &&
            mcs_results_attr_double(r, path, "cfc", &cfc, &e2) == MCS_OK)
            out->cfc = (int)cfc;
    }
    if (st) an_signal_free(out);
    mcs_array_free(&a);
    mcs_array_free(&ta);
    mcs_results_close(&r);
    return st;
}

mcs_status an_signal_read_ref(const char *ref, an_signal *out, mcs_error *err)
{
    memset(out, 0, sizeof *out);
    /* split "file.ext:selector" at the colon after a known extension */
    static const char *const exts[] = {".csv", ".h5", ".hdf5", ".mme"};
    size_t len = strlen(ref);
    char file[4096];
    const char *sel = NULL;
    int kind = -1;
    for (size_t i = 1; i <= len && kind < 0; i++) {
        if (ref[i] != ':' && ref[i] != 0) continue;
        for (int e = 0; e < 4; e++)
            if (ends_with(ref, i, exts[e])) {
                kind = e;
                if (i >= sizeof file)
                    return MCS_ERR(err, MCS_ERR_USAGE, "channel reference too long: %s", ref);
                memcpy(file, ref, i);
                file[i] = 0;
                sel = ref[i] == ':' && ref[i + 1] ? ref + i + 1 : NULL;
                break;
            }
    }
    if (kind < 0)
        return MCS_ERR(err, MCS_ERR_USAGE,
                       "%s: unknown channel reference (use file.csv[:column], file.h5:/path or "
                       "file.mme:channel)",
                       ref);
    if (kind == 0) return ref_csv(file, sel, out, err);
    if (kind == 3) {
        if (!sel)
            return MCS_ERR(err, MCS_ERR_USAGE, "%s: name a channel as %s:CHANNEL", ref, file);
        return an_mme_read_channel(file, sel, out, err);
    }
    return ref_h5(file, sel, out, err);
}

/* fe_kw_field: fields of keyword cards: fixed columns in the standard, I10 and long formats,
 * or comma-separated (free format); integers and Fortran-style reals; located errors. */
#include "fe/fe_kw_impl.h"

#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const kw_layout KW_L10 = {8, {10, 10, 10, 10, 10, 10, 10, 10}};
const kw_layout KW_L_NODE = {6, {8, 16, 16, 16, 8, 8}};
const kw_layout KW_L_ELEM = {10, {8, 8, 8, 8, 8, 8, 8, 8, 8, 8}};
const kw_layout KW_L_DISCR = {8, {8, 8, 8, 8, 8, 16, 8, 16}};
const kw_layout KW_L_CURVE = {2, {20, 20}};

mcs_status kw_fail(kw_ctx *c, int file, int line, int col, mcs_status st, const char *fmt, ...)
{
    char what[768];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    const char *fn = file >= 0 && file < c->d->nfile ? c->d->file[file] : "?";
    if (col > 0)
        return MCS_ERR(c->err, st, "%s:%d:%d: error: *%s: %s", fn, line, col, c->kw, what);
    return MCS_ERR(c->err, st, "%s:%d: error: *%s: %s", fn, line, c->kw, what);
}

/* field width in the current format (I10: under 10 become 10; long: all 20) */
static int fwidth(const kw_ctx *c, int w)
{
    if (c->fmt == KW_FMT_LONG) return 20;
    if (c->fmt == KW_FMT_I10 && w < 10) return 10;
    return w;
}

/* span of field i: start offset into the card and length (0 when past the end) */
static void span(const kw_ctx *c, const kw_card *cd, const kw_layout *l, int i, int *at, int *n)
{
    if (memchr(cd->s, ',', (size_t)cd->len)) { /* free format: the i-th comma-separated token */
        int k = 0, p = 0;
        while (k < i && p < cd->len) {
            if (cd->s[p] == ',') k++;
            p++;
        }
        int q = p;
        while (q < cd->len && cd->s[q] != ',') q++;
        *at = p;
        *n = k == i ? q - p : 0;
        return;
    }
    int col = 0;
    for (int k = 0; k < i && k < l->n; k++) col += fwidth(c, l->w[k]);
    int w = i < l->n ? fwidth(c, l->w[i]) : 0;
    *at = col < cd->len ? col : cd->len;
    *n = col + w <= cd->len ? w : cd->len > col ? cd->len - col : 0;
}

/* trim blanks (spaces, tabs in free format) around s[0..n) */
static const char *trim(const char *s, int *n)
{
    while (*n > 0 && (*s == ' ' || *s == '\t')) s++, (*n)--;
    while (*n > 0 && (s[*n - 1] == ' ' || s[*n - 1] == '\t')) (*n)--;
    return s;
}

int kw_parse_int(const char *s, int n, int *out)
{
    int i = 0, neg = 0;
    long long v = 0;
    if (i < n && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
    if (i >= n) return -1;
    for (; i < n; i++) {
        if (!isdigit((unsigned char)s[i])) return -1;
        v = v * 10 + (s[i] - '0');
        if (v > INT_MAX) return -1;
    }
    *out = (int)(neg ? -v : v);
    return 0;
}

/* [sign] digits [. digits] [(e|E|d|D)[sign]digits | sign digits] */
int kw_parse_real(const char *s, int n, double *out)
{
    char buf[64];
    int i = 0, k = 0, nd = 0;
    if (n <= 0 || n > 40) return -1;
    if (s[i] == '+' || s[i] == '-') buf[k++] = s[i++];
    while (i < n && isdigit((unsigned char)s[i])) buf[k++] = s[i++], nd++;
    if (i < n && s[i] == '.') {
        buf[k++] = s[i++];
        while (i < n && isdigit((unsigned char)s[i])) buf[k++] = s[i++], nd++;
    }
    if (nd == 0) return -1;
    if (i < n) {
        int ne = 0;
        if (s[i] == 'e' || s[i] == 'E' || s[i] == 'd' || s[i] == 'D') i++;
        buf[k++] = 'e';
        if (i < n && (s[i] == '+' || s[i] == '-')) buf[k++] = s[i++];
        while (i < n && isdigit((unsigned char)s[i])) buf[k++] = s[i++], ne++;
        if (ne == 0 || i < n) return -1;
    }
    buf[k] = 0;
    char *end;
    double v = strtod(buf, &end);
    if (*end || !isfinite(v)) return -1;
    *out = v;
    return 0;
}

int kw_blank(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i)
{
    int at, n;
    span(c, cd, l, i, &at, &n);
    trim(cd->s + at, &n);
    return n == 0;
}

static mcs_status bad(kw_ctx *c, const kw_card *cd, const char *p, int n, const char *name,
                      const char *what)
{
    return kw_fail(c, cd->file, cd->line, (int)(p - cd->s) + 1, MCS_ERR_FORMAT,
                   "field %s: '%.*s' is not %s", name, n, p, what);
}

mcs_status kw_int(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i, const char *name,
                  int dflt, int *out)
{
    int at, n;
    span(c, cd, l, i, &at, &n);
    const char *p = trim(cd->s + at, &n);
    if (n == 0) {
        *out = dflt;
        return MCS_OK;
    }
    if (kw_parse_int(p, n, out) == 0) return MCS_OK;
    if (kw_param_is_ref(p, n)) {
        double v;
        mcs_status st = kw_param_num(c, cd, p, n, name, 1, &v);
        if (!st && !(fabs(v) <= INT_MAX)) return bad(c, cd, p, n, name, "an integer of int range");
        if (!st) *out = (int)v;
        return st;
    }
    /* an integer written as a real ("12." or "12.0") is accepted */
    double v;
    if (kw_parse_real(p, n, &v) == 0 && v == floor(v) && fabs(v) <= INT_MAX) {
        *out = (int)v;
        return MCS_OK;
    }
    return bad(c, cd, p, n, name, "an integer");
}

mcs_status kw_real(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i, const char *name,
                   double dflt, double *out)
{
    int at, n;
    span(c, cd, l, i, &at, &n);
    const char *p = trim(cd->s + at, &n);
    if (n == 0) {
        *out = dflt;
        return MCS_OK;
    }
    if (kw_parse_real(p, n, out) == 0) return MCS_OK;
    if (kw_param_is_ref(p, n)) return kw_param_num(c, cd, p, n, name, 0, out);
    return bad(c, cd, p, n, name, "a number");
}

int kw_field_text(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i, char *buf, size_t n)
{
    int at, len;
    span(c, cd, l, i, &at, &len);
    const char *p = trim(cd->s + at, &len);
    if ((size_t)len >= n) len = (int)n - 1;
    memcpy(buf, p, (size_t)len);
    buf[len] = 0;
    return (int)(p - cd->s) + 1;
}

void kw_text(const kw_card *cd, int col0, int w, char *buf, size_t n)
{
    int at = col0 < cd->len ? col0 : cd->len;
    int len = w > 0 ? (at + w <= cd->len ? w : cd->len - at) : cd->len - at;
    const char *p = trim(cd->s + at, &len);
    if ((size_t)len >= n) len = (int)n - 1;
    memcpy(buf, p, (size_t)len);
    buf[len] = 0;
}

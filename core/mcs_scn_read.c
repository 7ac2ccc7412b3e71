/* mcs_scn_read.c: reading scenario files: size limit, binary garbage, UTF-8, the source text */
#include "core/mcs_scn_internal.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* length of the valid UTF-8 sequence at p (n bytes left), 0 if invalid */
static size_t utf8_len(const unsigned char *p, size_t n)
{
    unsigned char c = p[0];
    size_t k;
    unsigned lo = 0x80, hi = 0xBF; /* allowed range of the second byte */
    if (c < 0x80) return 1;
    if (c >= 0xC2 && c <= 0xDF)
        k = 2;
    else if (c >= 0xE0 && c <= 0xEF) {
        k = 3;
        if (c == 0xE0) lo = 0xA0; /* overlong */
        if (c == 0xED) hi = 0x9F; /* surrogates */
    } else if (c >= 0xF0 && c <= 0xF4) {
        k = 4;
        if (c == 0xF0) lo = 0x90; /* overlong */
        if (c == 0xF4) hi = 0x8F; /* > U+10FFFF */
    } else
        return 0;
    if (n < k || p[1] < lo || p[1] > hi) return 0;
    for (size_t i = 2; i < k; i++)
        if (p[i] < 0x80 || p[i] > 0xBF) return 0;
    return k;
}

static mcs_status byte_fail(const char *name, int line, int col, mcs_error *err, const char *what,
                            unsigned byte)
{
    char w[128];
    snprintf(w, sizeof w, what, byte);
    return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d:%d: error: %s", name, line, col, w);
}

mcs_status scn_check_bytes(const char *name, const char *text, size_t len, mcs_error *err)
{
    if (len == 0) return MCS_ERR(err, MCS_ERR_FORMAT, "%s:1:1: error: empty file", name);
    if (len > MCS_SCN_MAX_BYTES)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s:1:1: error: file too large (%zu bytes, limit %d)",
                       name, len, MCS_SCN_MAX_BYTES);
    const unsigned char *p = (const unsigned char *)text;
    int line = 1, col = 1;
    for (size_t i = 0; i < len;) {
        unsigned c = p[i];
        if (c == 0) return byte_fail(name, line, col, err, "binary data: NUL byte%.0u", c);
        if (c < 0x20 && c != '\n' && c != '\r' && c != '\t')
            return byte_fail(name, line, col, err, "binary data: control byte 0x%02X", c);
        size_t k = utf8_len(p + i, len - i);
        if (k == 0) return byte_fail(name, line, col, err, "not UTF-8 text (byte 0x%02X)", c);
        if (c == '\n')
            line++, col = 1;
        else
            col++;
        i += k;
    }
    return MCS_OK;
}

void scn_add_source(mcs_scenario *scn, const char *name, const char *text, size_t len)
{
    size_t need = scn->text_len + len + strlen(name) + 64;
    if (need > scn->text_cap) {
        size_t cap = need > 2 * scn->text_cap ? need : 2 * scn->text_cap;
        char *t = realloc(scn->text, cap);
        if (!t) return; /* the source text is informative; loading goes on without it */
        scn->text = t;
        scn->text_cap = cap;
    }
    int k = snprintf(scn->text + scn->text_len, scn->text_cap - scn->text_len,
                     "# === mcrash source: %s\n", name);
    scn->text_len += (size_t)k;
    memcpy(scn->text + scn->text_len, text, len);
    scn->text_len += len;
    if (len && text[len - 1] != '\n') scn->text[scn->text_len++] = '\n';
    scn->text[scn->text_len] = 0;
}

/* from: the include: node that named the file (NULL for the top file) */
static mcs_status open_fail(const char *path, const mcs_node *from, mcs_error *err,
                            const char *what)
{
    if (from)
        return scn_fail(err, MCS_ERR_INCLUDE, from, "include", "cannot read '%s': %s", path, what);
    return MCS_ERR(err, MCS_ERR_IO, "%s: error: cannot read: %s", path, what);
}

/* the whole file into a malloc'd buffer (NUL-terminated); files over the limit are refused */
static mcs_status slurp(FILE *f, const char *path, const mcs_node *from, char **text, size_t *len,
                        mcs_error *err)
{
    size_t cap = 64 * 1024, n = 0;
    char *buf = malloc(cap);
    while (buf) {
        n += fread(buf + n, 1, cap - 1 - n, f);
        if (n < cap - 1 || cap > MCS_SCN_MAX_BYTES) break;
        char *b = realloc(buf, 2 * cap);
        if (!b) free(buf);
        buf = b;
        cap *= 2;
    }
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: error: out of memory", path);
    if (ferror(f)) {
        free(buf);
        return open_fail(path, from, err, "read error (is it a directory?)");
    }
    buf[n] = 0;
    *text = buf;
    *len = n;
    return MCS_OK;
}

mcs_status scn_read_file(mcs_scenario *scn, const char *path, const mcs_node *from, char **text,
                         size_t *len, mcs_error *err)
{
    (void)scn;
    FILE *f = fopen(path, "rb");
    if (!f) return open_fail(path, from, err, strerror(errno));
    mcs_status st = slurp(f, path, from, text, len, err);
    fclose(f);
    if (!st) st = scn_check_bytes(path, *text, *len, err);
    if (st && *text) {
        free(*text);
        *text = NULL;
    }
    return st;
}

/* mcs_obj.c: the OBJ triangle-mesh reader (mcs_obj.h). Growing arrays, strtod/strtol parsing;
 * nothing is kept on failure. */
#include "core/mcs_obj.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    mcs_obj_mesh m;
    int cap_v, cap_t;
} obj_build;

static int grow(void **p, int *cap, int need, size_t item)
{
    if (need <= *cap) return 1;
    int c = *cap ? 2 * *cap : 64;
    while (c < need)
        c *= 2;
    void *q = realloc(*p, (size_t)c * item);
    if (!q) return 0;
    *p = q, *cap = c;
    return 1;
}

static mcs_status parse_v(obj_build *b, char *s, const char *path, int line, mcs_error *err)
{
    double x[3];
    for (int k = 0; k < 3; k++) {
        char *end;
        errno = 0;
        x[k] = strtod(s, &end);
        if (end == s || errno || !isfinite(x[k]))
            return MCS_ERR(err, MCS_ERR_FORMAT,
                           "%s:%d: error: a vertex needs three finite "
                           "coordinates (v x y z)",
                           path, line);
        s = end;
    }
    if (b->m.nvert >= MCS_OBJ_MAX_VERT)
        return MCS_ERR(err, MCS_ERR_RANGE, "%s:%d: error: more than %d vertices", path, line,
                       MCS_OBJ_MAX_VERT);
    if (!grow((void **)&b->m.vert, &b->cap_v, b->m.nvert + 1, 3 * sizeof(double)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
    memcpy(b->m.vert + 3 * b->m.nvert++, x, sizeof x);
    return MCS_OK;
}

static mcs_status parse_f(obj_build *b, char *s, const char *path, int line, mcs_error *err)
{
    int idx[3], n = 0;
    for (;;) {
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s || *s == '\n' || *s == '\r' || *s == '#') break;
        char *end;
        errno = 0;
        long i = strtol(s, &end, 10);
        if (end == s || errno || i == 0 || labs(i) > MCS_OBJ_MAX_VERT)
            return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d: error: bad vertex index in a face", path,
                           line);
        long k = i > 0 ? i - 1 : b->m.nvert + i;
        if (k < 0 || k >= b->m.nvert)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%s:%d: error: face uses vertex %ld, only %d defined so far", path, line,
                           i, b->m.nvert);
        s = end;
        while (*s && *s != ' ' && *s != '\t' && *s != '\n' && *s != '\r')
            s++; /* /t/n */
        if (n < 3) idx[n] = (int)k;
        if (n >= 2) { /* fan triangle idx[0], previous, this */
            if (b->m.ntri >= MCS_OBJ_MAX_TRI)
                return MCS_ERR(err, MCS_ERR_RANGE, "%s:%d: error: more than %d triangles", path,
                               line, MCS_OBJ_MAX_TRI);
            if (!grow((void **)&b->m.tri, &b->cap_t, b->m.ntri + 1, 3 * sizeof(int)))
                return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
            int *t = b->m.tri + 3 * b->m.ntri++;
            t[0] = idx[0], t[1] = idx[1], t[2] = (int)k;
            idx[1] = (int)k;
        }
        n++;
    }
    if (n < 3)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d: error: a face needs at least 3 vertices", path,
                       line);
    return MCS_OK;
}

mcs_status mcs_obj_read(const char *path, mcs_obj_mesh *out, mcs_error *err)
{
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "r");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    obj_build b = {0};
    char buf[4096];
    int line = 0;
    mcs_status st = MCS_OK;
    while (!st && fgets(buf, sizeof buf, f)) {
        line++;
        if (!strchr(buf, '\n') && !feof(f)) {
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d: error: line longer than %zu characters", path,
                         line, sizeof buf - 2);
            break;
        }
        char *s = buf;
        while (*s == ' ' || *s == '\t')
            s++;
        if (s[0] == 'v' && (s[1] == ' ' || s[1] == '\t'))
            st = parse_v(&b, s + 2, path, line, err);
        else if (s[0] == 'f' && (s[1] == ' ' || s[1] == '\t'))
            st = parse_f(&b, s + 2, path, line, err);
    }
    if (!st && ferror(f)) st = MCS_ERR(err, MCS_ERR_IO, "%s: read error", path);
    fclose(f);
    if (!st && b.m.ntri == 0)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: error: no faces (f lines)", path);
    if (st) {
        mcs_obj_free(&b.m);
        return st;
    }
    *out = b.m;
    return MCS_OK;
}

void mcs_obj_free(mcs_obj_mesh *m)
{
    if (!m) return;
    free(m->vert), free(m->tri);
    memset(m, 0, sizeof *m);
}

int mcs_obj_path(const char *scenario_file, const char *name, char *buf, size_t n)
{
    const char *slash = name[0] == '/' || !scenario_file ? NULL : strrchr(scenario_file, '/');
    int dl = slash ? (int)(slash - scenario_file + 1) : 0;
    int k = snprintf(buf, n, "%.*s%s", dl, scenario_file ? scenario_file : "", name);
    return k < 0 || (size_t)k >= n ? -1 : 0;
}

/* mcs_results_mesh.c: a part's mesh read back from a results file (see mcs_results_mesh.h). */
#include "core/mcs_results_mesh.h"

#include "core/mcs_results.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void mcs_mesh_free(mcs_mesh *m)
{
    if (!m) return;
    free(m->x);
    for (int i = 0; i < m->nblock; i++) free(m->block[i].elem);
    memset(m, 0, sizeof *m);
}

/* the node count a type's name ends in ("hex8": 8; mcs_results.h); 0 when none */
static int width_of(const char *type)
{
    size_t l = strlen(type), i = l;
    while (i > 0 && type[i - 1] >= '0' && type[i - 1] <= '9') i--;
    return i == 0 || i == l || l - i > 3 ? 0 : atoi(type + i);
}

/* one element block at gp/<name>: [ne,k] ints, every entry a row of the nn nodes */
static mcs_status read_block(mcs_results *r, const char *file, const char *gp, const char *name,
                             size_t nn, mcs_mesh_block *b, mcs_error *err)
{
    char p[1200];
    snprintf(p, sizeof p, "%s/%s", gp, name);
    mcs_array a = {0};
    mcs_status st = mcs_results_read_int(r, p, &a, err);
    if (st) return st;
    char *type = NULL;
    if (mcs_results_has_attr(r, p, "type")) st = mcs_results_attr_str(r, p, "type", &type, err);
    /* without `type`: the block's name says it (elements_<type>), else "" (the reader of the
     * mesh decides by the width: the cell types are the writer's, fe/fe_out_mesh.h) */
    const int named = strncmp(name, "elements_", 9) == 0;
    const char *t = type ? type : named ? name + 9 : "";
    if (!st && named && strcmp(name + 9, t) != 0)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: type \"%s\" differs from the name", file, p, t);
    if (!st && (a.rank != 2 || (*t && (size_t)width_of(t) != a.dims[1])))
        st = MCS_ERR(err, MCS_ERR_FORMAT,
                     "%s:%s: expected [ne, k] element nodes of a type whose name ends in k, got "
                     "rank %d, type \"%s\"",
                     file, p, a.rank, t);
    for (size_t i = 0; !st && i < a.n; i++)
        if (a.iv[i] < 0 || (size_t)a.iv[i] >= nn)
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: element %zu names node %d of %zu", file, p,
                         i / a.dims[1], a.iv[i], nn);
    if (!st) {
        snprintf(b->type, sizeof b->type, "%s", t);
        b->k = (int)a.dims[1];
        b->ne = a.dims[0];
        b->elem = a.iv;
        a.iv = NULL;
    }
    free(type);
    mcs_array_free(&a);
    return st;
}

/* the element blocks of group gp: `elements`, then each elements_<type> */
static mcs_status read_blocks(mcs_results *r, const char *file, const char *gp, mcs_mesh *m,
                              mcs_error *err)
{
    char **names = NULL;
    int n = 0;
    mcs_status st = mcs_results_list(r, gp, &names, &n, err);
    for (int pass = 0; pass < 2 && !st; pass++)
        for (int i = 0; i < n && !st; i++) {
            int main_block = strcmp(names[i], "elements") == 0;
            if (pass == 0 ? !main_block : main_block || strncmp(names[i], "elements_", 9) != 0)
                continue;
            if (m->nblock >= MCS_MESH_MAXBLOCK)
                st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: more than %d element blocks", file, gp,
                             MCS_MESH_MAXBLOCK);
            else
                st = read_block(r, file, gp, names[i], m->nn, &m->block[m->nblock++], err);
            if (st && m->nblock > 0 && !m->block[m->nblock - 1].elem) m->nblock--;
        }
    mcs_results_list_free(&names, n);
    if (!st && (m->nblock == 0 || m->block[0].ne == 0))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s/elements: missing or empty", file, gp);
    return st;
}

/* the output times of /stage<s>/fields/displacement: fields/time, else /stage<s>/time */
static mcs_status field_times(mcs_results *r, const char *file, int s, size_t nout,
                              mcs_array *t, mcs_error *err)
{
    char p[64];
    snprintf(p, sizeof p, "/stage%d/fields/time", s);
    if (mcs_results_kind(r, p) != MCS_RES_DATASET) snprintf(p, sizeof p, "/stage%d/time", s);
    mcs_status st = mcs_results_read(r, p, t, err);
    if (!st && (t->rank != 1 || t->n != nout))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: %zu times for %zu displacement rows", file, p,
                     t->n, nout);
    return st;
}

/* add the displacement at time `at` (or the last row) to the reference nodes */
static mcs_status deform(mcs_results *r, const char *file, int s, mcs_mesh_shape shape, double at,
                         mcs_mesh *m, mcs_error *err)
{
    char pd[64];
    snprintf(pd, sizeof pd, "/stage%d/fields/displacement", s);
    int rank = 0;
    size_t d[MCS_RESULTS_MAXRANK] = {0};
    if (mcs_results_kind(r, pd) != MCS_RES_DATASET)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: missing (a deformed shape needs the fields)",
                       file, pd);
    mcs_status st = mcs_results_shape(r, pd, &rank, d, err);
    if (!st && (rank != 3 || d[2] != 3 || d[0] == 0 || (size_t)m->node_offset + m->nn > d[1]))
        st = MCS_ERR(err, MCS_ERR_FORMAT,
                     "%s:%s: expected [nout >= 1, nnode >= %zu, 3], got rank %d [%zu, %zu, %zu]",
                     file, pd, (size_t)m->node_offset + m->nn, rank, d[0], d[1], d[2]);
    mcs_array t = {0};
    if (!st) st = field_times(r, file, s, d[0], &t, err);
    size_t i0 = d[0] - 1, i1 = i0;
    double w = 0;
    if (!st && shape == MCS_MESH_AT) {
        const double eps = 1e-9 * fmax(1.0, fabs(t.v[d[0] - 1]));
        if (!(at >= t.v[0] - eps && at <= t.v[d[0] - 1] + eps))
            st = MCS_ERR(err, MCS_ERR_RANGE, "%s:%s: time %g s outside the fields' %g .. %g s",
                         file, pd, at, t.v[0], t.v[d[0] - 1]);
        for (i0 = 0; !st && i0 + 1 < d[0] && t.v[i0 + 1] <= at + eps; i0++) {}
        i1 = i0 + 1 < d[0] ? i0 + 1 : i0;
        if (!st && i1 > i0 && fabs(at - t.v[i0]) > eps)
            w = (at - t.v[i0]) / (t.v[i1] - t.v[i0]); /* linear between two output rows */
    }
    if (!st) m->time = shape == MCS_MESH_AT ? at : t.v[d[0] - 1];
    mcs_array_free(&t);
    double *u0 = st ? NULL : malloc(sizeof(double) * 3 * d[1]);
    double *u1 = st ? NULL : malloc(sizeof(double) * 3 * d[1]);
    if (!st && (!u0 || !u1)) st = MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", file);
    if (!st) st = mcs_results_read_row(r, pd, i0, u0, 3 * d[1], err);
    if (!st) st = mcs_results_read_row(r, pd, i1, u1, 3 * d[1], err);
    const double *a = u0 + 3 * (size_t)m->node_offset, *b = u1 + 3 * (size_t)m->node_offset;
    for (size_t i = 0; !st && i < 3 * m->nn; i++) m->x[i] += (1 - w) * a[i] + w * b[i];
    free(u0);
    free(u1);
    return st;
}

/* "FILE:/stageN/mesh/<part>" -> file, group path, stage N */
static mcs_status split_ref(const char *ref, char *file, size_t nf, const char **gp, int *stage,
                            mcs_error *err)
{
    const char *sep = NULL;
    for (const char *p = ref ? strstr(ref, ":/") : NULL; p; p = strstr(p + 1, ":/")) sep = p;
    char part[2];
    if (!sep || sep == ref || (size_t)(sep - ref) >= nf ||
        sscanf(sep + 1, "/stage%d/mesh/%1s", stage, part) != 2 || *stage < 1 || *stage > 9)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s: expected FILE.h5:/stageN/mesh/<part>",
                       ref ? ref : "(null)");
    memcpy(file, ref, (size_t)(sep - ref));
    file[sep - ref] = 0;
    *gp = sep + 1;
    return MCS_OK;
}

mcs_status mcs_results_read_mesh(const char *ref, mcs_mesh_shape shape, double at, mcs_mesh *out,
                                 mcs_error *err)
{
    memset(out, 0, sizeof *out);
    out->time = -1;
    char file[4096], pn[1200];
    const char *gp = NULL;
    int s = 0;
    mcs_status st = split_ref(ref, file, sizeof file, &gp, &s, err);
    if (st) return st;
    mcs_results *r = NULL;
    mcs_error oe = {0};
    if ((st = mcs_results_open(&r, file, &oe)))
        return MCS_ERR(err, st, "%s:%s: %s", file, gp, oe.msg);
    snprintf(pn, sizeof pn, "%s/nodes", gp);
    mcs_array x = {0};
    if (mcs_results_kind(r, gp) != MCS_RES_GROUP)
        st = MCS_ERR(err, MCS_ERR_KEY, "%s:%s: no such part mesh", file, gp);
    if (!st) st = mcs_results_read(r, pn, &x, err);
    if (!st && (x.rank != 2 || x.dims[1] != 3 || x.dims[0] == 0))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: expected [nn >= 1, 3] node positions", file, pn);
    double off = 0;
    if (!st && mcs_results_has_attr(r, pn, "node_offset"))
        st = mcs_results_attr_double(r, pn, "node_offset", &off, err);
    if (!st && !(off >= 0 && off < 1e9 && off == floor(off)))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: node_offset %g", file, pn, off);
    if (!st) {
        out->nn = x.dims[0];
        out->x = x.v;
        out->node_offset = (int)off;
        x.v = NULL;
        st = read_blocks(r, file, gp, out, err);
    }
    if (!st && shape != MCS_MESH_REFERENCE) st = deform(r, file, s, shape, at, out, err);
    mcs_array_free(&x);
    mcs_results_close(&r);
    if (st) mcs_mesh_free(out);
    return st;
}

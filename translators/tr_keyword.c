/* tr_keyword.c: /stageN/mesh (+ the final displacement) -> keyword deck (see tr_keyword.h). */
#include "translators/tr_keyword.h"

#include "core/mcs_results_export.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

tr_kw_export_opts tr_kw_export_opts_default(void)
{
    tr_kw_export_opts o = {.stage = 0, .deformed = 0, .units = NULL, .fmt = FE_KW_FIXED};
    return o;
}

/* further element blocks of a part: /stageN/mesh/<part>/elements_<type> (mcs_results.h) */
#define TR_NBLK 4
static const char *const tr_blk[TR_NBLK] = {"tet4", "wedge6", "hex8", "tet10"};

typedef struct {
    char **names;
    int n;
    mcs_array *nodes, *elems;
    mcs_array (*blk)[TR_NBLK]; /* the blocks present (rank 0: absent) */
    int *offset;
    char (*type)[16];
} mesh_set;

static void mesh_free(mesh_set *m)
{
    for (int i = 0; i < m->n; i++) {
        if (m->nodes) mcs_array_free(&m->nodes[i]);
        if (m->elems) mcs_array_free(&m->elems[i]);
        for (int b = 0; m->blk && b < TR_NBLK; b++) mcs_array_free(&m->blk[i][b]);
    }
    free(m->nodes);
    free(m->elems);
    free(m->blk);
    free(m->offset);
    free(m->type);
    mcs_results_list_free(&m->names, m->n);
}

static mcs_status pick_stage(mcs_results *r, int want, int *stage, mcs_error *err)
{
    char path[64];
    if (want > 0) {
        snprintf(path, sizeof path, "/stage%d/mesh", want);
        if (mcs_results_kind(r, path) != MCS_RES_GROUP)
            return MCS_ERR(err, MCS_ERR_FORMAT, "%s: no %s (no FE mesh in stage %d)",
                           mcs_results_path(r), path, want);
        *stage = want;
        return MCS_OK;
    }
    int st[64], n = mcs_results_stages(r, st, 64);
    for (int i = n - 1; i >= 0; i--) {
        snprintf(path, sizeof path, "/stage%d/mesh", st[i]);
        if (mcs_results_kind(r, path) == MCS_RES_GROUP) {
            *stage = st[i];
            return MCS_OK;
        }
    }
    return MCS_ERR(err, MCS_ERR_FORMAT, "%s: no /stageN/mesh: the run wrote no FE mesh",
                   mcs_results_path(r));
}

static mcs_status read_meshes(mcs_results *r, int stage, mesh_set *m, mcs_error *err)
{
    char path[512];
    snprintf(path, sizeof path, "/stage%d/mesh", stage);
    mcs_status st = mcs_results_list(r, path, &m->names, &m->n, err);
    if (st) return st;
    m->nodes = calloc((size_t)m->n + 1, sizeof *m->nodes);
    m->elems = calloc((size_t)m->n + 1, sizeof *m->elems);
    m->offset = calloc((size_t)m->n + 1, sizeof *m->offset);
    m->type = calloc((size_t)m->n + 1, sizeof *m->type);
    m->blk = calloc((size_t)m->n + 1, sizeof *m->blk);
    if (!m->nodes || !m->elems || !m->offset || !m->type || !m->blk)
        return MCS_ERR(err, MCS_ERR_NOMEM, "export --k: out of memory");
    for (int i = 0; i < m->n && !st; i++) {
        snprintf(path, sizeof path, "/stage%d/mesh/%s/nodes", stage, m->names[i]);
        st = mcs_results_read(r, path, &m->nodes[i], err);
        double off = 0;
        if (!st && mcs_results_has_attr(r, path, "node_offset"))
            st = mcs_results_attr_double(r, path, "node_offset", &off, err);
        m->offset[i] = (int)off;
        if (!st && (m->nodes[i].rank != 2 || m->nodes[i].dims[1] != 3 || off < 0))
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s: expected [nn, 3] nodes", mcs_results_path(r),
                         path);
        snprintf(path, sizeof path, "/stage%d/mesh/%s/elements", stage, m->names[i]);
        if (!st) st = mcs_results_read_int(r, path, &m->elems[i], err);
        char *type = NULL;
        if (!st && mcs_results_has_attr(r, path, "type") &&
            mcs_results_attr_str(r, path, "type", &type, err) == MCS_OK)
            snprintf(m->type[i], sizeof m->type[i], "%s", type);
        free(type);
        if (!st && m->elems[i].rank != 2)
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s: expected [ne, k] elements",
                         mcs_results_path(r), path);
        for (int b = 0; b < TR_NBLK && !st; b++) {
            snprintf(path, sizeof path, "/stage%d/mesh/%s/elements_%s", stage, m->names[i],
                     tr_blk[b]);
            if (mcs_results_kind(r, path) != MCS_RES_DATASET) continue;
            st = mcs_results_read_int(r, path, &m->blk[i][b], err);
            if (!st && m->blk[i][b].rank != 2)
                st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s: expected [ne, k] elements",
                             mcs_results_path(r), path);
        }
    }
    return st;
}

/* deck element type and node list of one results element (k nodes, type text) */
static int map_elem(const char *type, int k, const int *in, int base, int *out, fe_kw_etype *t)
{
    if (!type[0]) type = k == 8 ? "hex8" : k == 4 ? "quad4" : k == 3 ? "tri3" : k == 2 ? "line2" : "";
    if (strcmp(type, "hex8") == 0 && k == 8) {
        for (int j = 0; j < 8; j++) out[j] = in[j] + base;
        *t = FE_KW_SOLID;
    } else if (strcmp(type, "tet4") == 0 && k == 4) {
        for (int j = 0; j < 8; j++) out[j] = in[j < 4 ? j : 3] + base;
        *t = FE_KW_SOLID;
    } else if (strcmp(type, "wedge6") == 0 && k == 6) {
        /* VTK wedge (a b c | d e f) -> LS-DYNA's n1 n2 n3 n4 n5 n5 n6 n6 (fe_out_mesh.c) */
        static const int w[8] = {0, 1, 4, 3, 2, 2, 5, 5};
        for (int j = 0; j < 8; j++) out[j] = in[w[j]] + base;
        *t = FE_KW_SOLID;
    } else if (strcmp(type, "tet10") == 0 && k == 10) {
        for (int j = 0; j < 10; j++) out[j] = in[j] + base;
        *t = FE_KW_TET10;
    } else if (strcmp(type, "quad4") == 0 && k == 4) {
        for (int j = 0; j < 4; j++) out[j] = in[j] + base;
        *t = FE_KW_SHELL;
    } else if (strcmp(type, "tri3") == 0 && k == 3) {
        for (int j = 0; j < 4; j++) out[j] = in[j < 3 ? j : 2] + base;
        *t = FE_KW_SHELL;
    } else if (strcmp(type, "line2") == 0 && k == 2) {
        out[0] = in[0] + base, out[1] = in[1] + base;
        *t = FE_KW_BEAM;
    } else {
        return -1;
    }
    return 0;
}

/* the final displacement [nn, 3] of the stage, or NULL when not asked / absent (error) */
static mcs_status final_disp(mcs_results *r, int stage, mcs_array *a, mcs_error *err)
{
    char path[64];
    snprintf(path, sizeof path, "/stage%d/fields/displacement", stage);
    if (!mcs_results_exists(r, path))
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: no %s to deform the mesh with",
                       mcs_results_path(r), path);
    mcs_status st = mcs_results_read(r, path, a, err);
    if (!st && (a->rank != 3 || a->dims[0] < 1 || a->dims[2] != 3))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s: expected [nout, nn, 3]", mcs_results_path(r),
                     path);
    return st;
}

mcs_status tr_kw_deck_from_results(mcs_results *r, const tr_kw_export_opts *o, fe_kw_deck **out,
                                   int *stage, mcs_error *err)
{
    *out = NULL;
    mesh_set m = {0};
    mcs_array disp = {0};
    fe_kw_deck *d = NULL;
    double *x = NULL;
    unsigned char *have = NULL;
    mcs_status st = pick_stage(r, o->stage, stage, err);
    if (!st) st = read_meshes(r, *stage, &m, err);
    if (!st && o->deformed) st = final_disp(r, *stage, &disp, err);
    if (!st) st = fe_kw_deck_create(&d, err);
    if (!st) st = fe_kw_units(o->units, d->unit, err);
    /* every node once, by its global index */
    long nn = 0;
    for (int i = 0; i < m.n && !st; i++) {
        long hi = (long)m.offset[i] + (long)m.nodes[i].dims[0];
        nn = hi > nn ? hi : nn;
    }
    if (!st && nn > (1L << 28)) st = MCS_ERR(err, MCS_ERR_FORMAT, "export --k: too many nodes");
    if (!st && o->deformed && (long)disp.dims[1] < nn)
        st = MCS_ERR(err, MCS_ERR_FORMAT,
                     "%s: the displacement field has %zu nodes, the meshes %ld", mcs_results_path(r),
                     disp.dims[1], nn);
    if (!st) {
        x = malloc(3 * sizeof(double) * (size_t)(nn ? nn : 1));
        have = calloc((size_t)(nn ? nn : 1), 1);
        if (!x || !have) st = MCS_ERR(err, MCS_ERR_NOMEM, "export --k: out of memory");
    }
    for (int i = 0; i < m.n && !st; i++)
        for (size_t j = 0; j < m.nodes[i].dims[0]; j++) {
            size_t g = (size_t)m.offset[i] + j;
            for (int k = 0; k < 3; k++) x[3 * g + k] = m.nodes[i].v[3 * j + k];
            have[g] = 1;
        }
    if (!st && o->deformed) {
        const double *u = disp.v + (disp.dims[0] - 1) * disp.dims[1] * 3;
        for (long g = 0; g < 3 * nn; g++) x[g] += u[g];
    }
    for (long g = 0; g < nn && !st; g++)
        if (have[g]) st = fe_kw_deck_add_node(d, (int)g + 1, x + 3 * g, err);
    int eid[FE_KW_NETYPE] = {0};
    for (int i = 0; i < m.n && !st; i++) {
        fe_kw_part p = {.id = i + 1};
        snprintf(p.title, sizeof p.title, "%s", m.names[i]);
        st = fe_kw_deck_add_part(d, &p, err);
        for (int b = -1; b < TR_NBLK && !st; b++) {
            const mcs_array *e = b < 0 ? &m.elems[i] : &m.blk[i][b];
            const char *etype = b < 0 ? m.type[i] : tr_blk[b];
            if (e->rank != 2) continue;
            int k = (int)e->dims[1];
            for (size_t j = 0; j < e->dims[0] && !st; j++) {
                int c[10] = {0};
                fe_kw_etype t = FE_KW_SOLID;
                const int *row = e->iv + (size_t)k * j;
                for (int q = 0; q < k && !st; q++)
                    if (row[q] < 0 || (size_t)row[q] >= m.nodes[i].dims[0])
                        st = MCS_ERR(err, MCS_ERR_FORMAT,
                                     "%s: part '%s': element %zu names row %d of %zu nodes",
                                     mcs_results_path(r), m.names[i], j, row[q],
                                     m.nodes[i].dims[0]);
                if (!st && map_elem(etype, k, row, m.offset[i] + 1, c, &t))
                    st = MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                                 "%s: part '%s': element type '%s' with %d nodes has no keyword "
                                 "counterpart here",
                                 mcs_results_path(r), m.names[i], etype, k);
                /* solids of every shape share *ELEMENT_SOLID's IDs */
                const int et = t == FE_KW_TET10 ? FE_KW_SOLID : t;
                if (!st) st = fe_kw_deck_add_elem(d, t, ++eid[et], i + 1, c, err);
            }
        }
    }
    free(x);
    free(have);
    mcs_array_free(&disp);
    mesh_free(&m);
    if (st) fe_kw_deck_destroy(&d);
    *out = d;
    return st;
}

mcs_status tr_kw_export(mcs_results *r, const char *path, const tr_kw_export_opts *o, int *nnode,
                        int *nelem, mcs_error *err)
{
    fe_kw_deck *d = NULL;
    int stage = 0;
    mcs_status st = tr_kw_deck_from_results(r, o, &d, &stage, err);
    if (!st) {
        snprintf(d->title, sizeof d->title, "mcrash stage %d mesh%s", stage,
                 o->deformed ? " (deformed, final output)" : "");
        st = fe_kw_write(d, path, o->fmt, err);
    }
    if (!st && nnode) *nnode = d->nnode;
    if (!st && nelem) {
        *nelem = 0;
        for (int t = 0; t < FE_KW_NETYPE; t++) *nelem += d->elem[t].n;
    }
    fe_kw_deck_destroy(&d);
    return st;
}

/* fe_out_mesh: a part's mesh with its cell types (see fe_out_mesh.h). */
#include "fe/fe_out_mesh.h"

#include <stdlib.h>
#include <string.h>

enum { SH_HEX, SH_WEDGE, SH_TET, SH_N };

const mcs_cell_type *fe_out_cell_types(int *n)
{
    /* XDMF's names of the VTK cells (the node orders put_solid writes); a part's further
     * blocks are exported in this order */
    static const mcs_cell_type t[] = {
        {"line2", 2, "Polyline", 1},      {"tri3", 3, "Triangle", 1},
        {"quad4", 4, "Quadrilateral", 1}, {"tet4", 4, "Tetrahedron", 0},
        {"wedge6", 6, "Wedge", 1},        {"hex8", 8, "Hexahedron", 1},
        {"tet10", 10, "Tetrahedron_10", 1}};
    *n = (int)(sizeof t / sizeof *t);
    return t;
}

/* shape of hex slots c (the builder admits only these three patterns) and the cell's nodes
 * in VTK / XDMF order: tetrahedron n1 n2 n3 n3 n4 n4 n4 n4 -> (n1 n2 n3 n4); pentahedron
 * n1 n2 n3 n4 n5 n5 n6 n6 (quad 1-2-3-4, ridge 5-6) -> wedge (n1 n2 n5 | n4 n3 n6): the
 * triangle n1 n2 n5 is the hex face 0-1-5-4, whose normal points out of the element, as VTK
 * wants of a wedge's first triangle */
static int shape(const int c[8], int out[8])
{
    int nd = 0;
    for (int i = 0; i < 8; i++) {
        int seen = 0;
        for (int j = 0; j < i; j++) seen |= c[j] == c[i];
        nd += !seen;
    }
    if (nd == 4) {
        const int t[4] = {c[0], c[1], c[2], c[4]};
        memcpy(out, t, sizeof t);
        return SH_TET;
    }
    if (nd == 6) {
        const int w[6] = {c[0], c[1], c[4], c[3], c[2], c[6]};
        memcpy(out, w, sizeof w);
        return SH_WEDGE;
    }
    memcpy(out, c, 8 * sizeof(int));
    return SH_HEX;
}

/* the part's nodes span rows lo..hi of the model's */
static void node_range(const int *c, size_t n, int nnode, int *lo, int *hi)
{
    *lo = nnode, *hi = -1;
    for (size_t i = 0; i < n; i++) {
        *lo = c[i] < *lo ? c[i] : *lo;
        *hi = c[i] > *hi ? c[i] : *hi;
    }
}

static mcs_status put_solid(mcs_results *r, int stage, const fe_model *m, const fe_part *p, int lo,
                            int hi, mcs_error *err)
{
    static const char *type[SH_N] = {"hex8", "wedge6", "tet4"};
    static const int width[SH_N] = {8, 6, 4};
    const int ne = p->elem_end - p->elem_begin;
    int *blk[SH_N] = {NULL}, cnt[SH_N] = {0};
    mcs_status st = MCS_OK;
    for (int s = 0; s < SH_N && !st; s++)
        if (!(blk[s] = malloc(sizeof(int) * (size_t)ne * (size_t)width[s])))
            st = MCS_ERR(err, MCS_ERR_NOMEM, "stage %d: out of memory writing part '%s'", stage,
                         p->name);
    for (int e = p->elem_begin; e < p->elem_end && !st; e++) {
        int c[8];
        const int s = shape(m->hex_node + 8 * (size_t)e, c);
        for (int j = 0; j < width[s]; j++) blk[s][(size_t)width[s] * cnt[s] + j] = c[j] - lo;
        cnt[s]++;
    }
    int first = -1;
    for (int s = 0; s < SH_N && first < 0; s++)
        if (cnt[s]) first = s;
    const size_t nn = (size_t)(hi - lo + 1);
    if (!st)
        st = mcs_results_put_mesh(r, stage, p->name, nn, m->node_x0 + 3 * (size_t)lo,
                                  (size_t)cnt[first], width[first], blk[first], type[first], lo,
                                  err);
    for (int s = first + 1; s < SH_N && !st; s++)
        if (cnt[s])
            st = mcs_results_put_mesh_block(r, stage, p->name, nn, (size_t)cnt[s], width[s], blk[s],
                                            type[s], err);
    for (int s = 0; s < SH_N; s++) free(blk[s]);
    return st;
}

mcs_status fe_out_part_mesh(mcs_results *r, int stage, const fe_model *m, const fe_part *p,
                           mcs_error *err)
{
    static const int width[FE_NKIND] = {8, 4, 2, 10};
    static const char *type[FE_NKIND] = {"hex8", "quad4", "line2", "tet10"};
    const int *conn[FE_NKIND] = {m->hex_node, m->shell_node, m->truss_node, m->tet10_node};
    const int k = width[p->elem_kind], ne = p->elem_end - p->elem_begin;
    const int *c = conn[p->elem_kind] + (size_t)k * (size_t)p->elem_begin;
    if (ne <= 0) return MCS_OK;
    int lo, hi;
    node_range(c, (size_t)k * (size_t)ne, m->nnode, &lo, &hi);
    if (p->elem_kind == FE_KIND_HEX) return put_solid(r, stage, m, p, lo, hi, err);
    int *el = malloc(sizeof(int) * (size_t)ne * (size_t)k);
    if (!el)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage %d: out of memory writing part '%s'", stage,
                       p->name);
    for (size_t i = 0; i < (size_t)k * (size_t)ne; i++) el[i] = c[i] - lo;
    mcs_status st = mcs_results_put_mesh(r, stage, p->name, (size_t)(hi - lo + 1),
                                         m->node_x0 + 3 * (size_t)lo, (size_t)ne, k, el,
                                         type[p->elem_kind], lo, err);
    free(el);
    return st;
}

mcs_status fe_out_meshes(mcs_results *r, int stage, const fe_model *m, mcs_error *err)
{
    mcs_status st = MCS_OK;
    for (int i = 0; i < m->npart && !st; i++) st = fe_out_part_mesh(r, stage, m, &m->part[i], err);
    return st;
}

mcs_status fe_out_field_open(mcs_results *r, int stage, const fe_model *m, fe_out_field *o,
                             mcs_error *err)
{
    memset(o, 0, sizeof *o);
    o->buf = malloc(sizeof(double) * 3 * (size_t)(m->nnode > 0 ? m->nnode : 1));
    if (!o->buf) return MCS_ERR(err, MCS_ERR_NOMEM, "stage %d: out of memory (fields)", stage);
    return mcs_results_field_series(r, stage, (size_t)m->nnode, &o->time, &o->disp, err);
}

mcs_status fe_out_field_sample(const fe_model *m, const fe_state *s, double t,
                               const fe_out_field *o, mcs_error *err)
{
    for (size_t i = 0; i < 3 * (size_t)m->nnode; i++) o->buf[i] = s->node_x[i] - m->node_x0[i];
    mcs_status st = mcs_results_series_append(o->time, &t, err);
    if (!st) st = mcs_results_series_append(o->disp, o->buf, err);
    return st;
}

void fe_out_field_free(fe_out_field *o)
{
    free(o->buf);
    memset(o, 0, sizeof *o);
}

/* fe_scn_from.c: a part's mesh from a results file (see fe_scn_from.h). */
#include "fe/scn/fe_scn_from.h"

#include "core/mcs_results_mesh.h"
#include "fe/fe_out_mesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fe_scn_from_is(const mcs_node *mesh)
{
    return mcs_node_kind(mcs_node_get(mesh, "from")) == MCS_NODE_STR;
}

/* the kernel's element kind of a results element type, and its section type; -1 unknown */
static int kind_of(const char *type, fe_section_type *sec)
{
    static const struct { const char *t; int kind; fe_section_type sec; } tab[] = {
        {"quad4", FE_KIND_SHELL, FE_SECTION_SHELL}, {"tri3", FE_KIND_SHELL, FE_SECTION_SHELL},
        {"line2", FE_KIND_TRUSS, FE_SECTION_TRUSS}, {"hex8", FE_KIND_HEX, FE_SECTION_SOLID},
        {"tet4", FE_KIND_HEX, FE_SECTION_SOLID},    {"wedge6", FE_KIND_HEX, FE_SECTION_SOLID},
        {"tet10", FE_KIND_TET10, FE_SECTION_SOLID}};
    for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++)
        if (strcmp(type, tab[i].t) == 0) {
            *sec = tab[i].sec;
            return tab[i].kind;
        }
    return -1;
}

/* an element of block b in the builder's slots (c: rows of the mesh); the inverse of
 * fe/out/fe_out_mesh.c's shape(): tri3 a quad with n3 = n4; tet4 (a b c d) the hex a b c c d d d d;
 * wedge6 (a b c | d e f) the pentahedron a b e d c c f f */
static int slots(const mcs_mesh_block *b, const int *c, int out[10])
{
    if (strcmp(b->type, "tri3") == 0) {
        const int s[4] = {c[0], c[1], c[2], c[2]};
        memcpy(out, s, sizeof s);
        return 4;
    }
    if (strcmp(b->type, "tet4") == 0) {
        const int s[8] = {c[0], c[1], c[2], c[2], c[3], c[3], c[3], c[3]};
        memcpy(out, s, sizeof s);
        return 8;
    }
    if (strcmp(b->type, "wedge6") == 0) {
        const int s[8] = {c[0], c[1], c[4], c[3], c[2], c[2], c[5], c[5]};
        memcpy(out, s, sizeof s);
        return 8;
    }
    memcpy(out, c, sizeof(int) * (size_t)b->k);
    return b->k;
}

/* the section the blocks need (one element kind per part) */
static mcs_status check_kinds(const mcs_mesh *m, const char *ref, fe_part_desc *d, mcs_error *err)
{
    fe_section_type want = FE_SECTION_SOLID, s = FE_SECTION_SOLID;
    int kind = kind_of(m->block[0].type, &want);
    for (int i = 1; i < m->nblock; i++)
        if (kind_of(m->block[i].type, &s) != kind)
            return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                           "%s: element types %s and %s in one part (a part holds one kind)", ref,
                           m->block[0].type, m->block[i].type);
    fe_section_type got = d->section.type;
    if (kind == FE_KIND_TET10 && got == FE_SECTION_SOLID) { /* as a keyword deck's ELFORM 16 */
        d->section.type = FE_SECTION_TET10;
        d->section.formulation = FE_HEX_ONE_POINT;
        return MCS_OK;
    }
    if (got == want || (want == FE_SECTION_SHELL && got == FE_SECTION_MEMBRANE)) return MCS_OK;
    return MCS_ERR(err, MCS_ERR_TYPE, "%s: %s elements; the part's section must be %s", ref,
                   m->block[0].type,
                   want == FE_SECTION_SHELL   ? "shell or membrane"
                   : want == FE_SECTION_TRUSS ? "truss"
                                              : "solid");
}

/* the part, its referenced nodes in row order (a part's own rows: every one of them) */
static mcs_status add_mesh(fe_builder *b, const mcs_mesh *m, const char *ref, fe_part_desc *d,
                           mcs_error *err)
{
    fe_part_desc pd = *d;
    pd.mesh.generate = FE_MESH_NONE;
    mcs_status st = check_kinds(m, ref, &pd, err);
    int ip = -1, *map = st ? NULL : malloc(sizeof(int) * m->nn);
    if (!st && !map) st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    for (size_t i = 0; !st && i < m->nn; i++) map[i] = -1;
    for (int k = 0; !st && k < m->nblock; k++)
        for (size_t i = 0; i < m->block[k].ne * (size_t)m->block[k].k; i++)
            map[m->block[k].elem[i]] = 0;
    if (!st) st = fe_builder_add_part(b, &pd, &ip, err);
    for (size_t i = 0; !st && i < m->nn; i++)
        if (map[i] == 0) st = fe_builder_add_node(b, m->x + 3 * i, &map[i], err);
    for (int k = 0; !st && k < m->nblock; k++) {
        const mcs_mesh_block *bl = &m->block[k];
        for (size_t e = 0; !st && e < bl->ne; e++) {
            int s[10], n = slots(bl, bl->elem + (size_t)bl->k * e, s);
            for (int j = 0; j < n; j++) s[j] = map[s[j]];
            st = fe_builder_add_elem(b, ip, s, err);
        }
    }
    free(map);
    return st;
}

/* the scenario's file name relative to the YAML file naming it */
static void resolve(const mcs_node *fn, char *out, size_t n)
{
    const char *name = mcs_node_str(fn), *yaml = mcs_node_file(fn);
    const char *slash = yaml ? strrchr(yaml, '/') : NULL;
    if (name[0] == '/' || !slash)
        snprintf(out, n, "%s", name);
    else
        snprintf(out, n, "%.*s/%s", (int)(slash - yaml), yaml, name);
}

mcs_status fe_scn_from_add_part(fe_builder *b, const mcs_node *part, const fe_part_desc *d,
                                mcs_error *err)
{
    const mcs_node *mesh = mcs_node_get(part, "mesh"), *fn = mcs_node_get(mesh, "from");
    const mcs_node *at = mcs_node_get(mesh, "at");
    char ref[4200];
    resolve(fn, ref, sizeof ref);
    mcs_mesh_shape shape = MCS_MESH_REFERENCE;
    if (mcs_node_kind(at) == MCS_NODE_STR && strcmp(mcs_node_str(at), "final") == 0)
        shape = MCS_MESH_FINAL;
    else if (mcs_node_kind(at) == MCS_NODE_NUM)
        shape = MCS_MESH_AT;
    mcs_mesh m = {0};
    mcs_error e = {0};
    fe_part_desc pd = *d;
    mcs_status st = mcs_results_read_mesh(ref, shape, mcs_node_num(at), &m, &e);
    /* a block without `type`: the cell type of its width (fe_out_cell_types: 4 = quad4) */
    int nct;
    const mcs_cell_type *ct = fe_out_cell_types(&nct);
    for (int i = 0; !st && i < m.nblock; i++) {
        for (int j = 0; !m.block[i].type[0] && j < nct; j++)
            if (ct[j].by_width && ct[j].nodes == m.block[i].k)
                snprintf(m.block[i].type, sizeof m.block[i].type, "%s", ct[j].name);
        if (!m.block[i].type[0])
            st = MCS_ERR(&e, MCS_ERR_FORMAT, "%s/elements: %d-node elements without a type "
                                             "(no cell type of that width)",
                         ref, m.block[i].k);
    }
    if (!st) st = add_mesh(b, &m, ref, &pd, &e);
    mcs_mesh_free(&m);
    return st ? mcs_node_error(shape == MCS_MESH_AT && st == MCS_ERR_RANGE ? at : fn, err, st, "%s",
                               e.msg)
              : MCS_OK;
}

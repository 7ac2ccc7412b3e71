/* test_s3_mesh: /stage3/mesh with each element's own cell type (fe/out/fe_out_mesh.c) and the
 * XDMF and keyword exports of it: a solid part holding a hexahedron, two pentahedra and six
 * tetrahedra (the kernel's degenerate hexes) and a tet10 part are written as hex8 + wedge6 +
 * tet4 blocks and tet10, the .xmf has the topologies Hexahedron (1), Wedge (2),
 * Tetrahedron (6) and Tetrahedron_10 (1), each cell with a positive volume in VTK's
 * convention, and `export --k` gives the same elements back. */
#include <math.h>
#include <stdlib.h>
#include <unistd.h>

#include "core/mcs_results.h"
#include "core/mcs_results_export.h"
#include "fe/fe_builder_impl.h"
#include "fe/fe_elem.h"
#include "fe/fe_out_mesh.h"
#include "tests/harness.h"
#include "tests/fe_test_util.h"
#include "translators/tr_keyword.h"

static double vol6(const double *a, const double *b, const double *c, const double *d)
{
    double u[3], v[3], w[3], x[3];
    for (int i = 0; i < 3; i++) u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = d[i] - a[i];
    fe_cross(u, v, x);
    return fe_dot(x, w);
}

/* a 1 x 1 x 3 column of unit cubes: z 0-1 one hexahedron, z 1-2 two pentahedra (prisms on
 * the triangles a0 a1 a2 and a0 a2 a3), z 2-3 six tetrahedra (Kuhn); then a separate tet10 */
static fe_model *build(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d = ft_part("mix", FE_SECTION_SOLID, 1e9, 0.3, 1000);
    fe_part_desc t = ft_part("quad", FE_SECTION_TET10, 1e9, 0.3, 1000);
    int ip, it;
    CHECK(fe_builder_add_part(b, &d, &ip, &err) == MCS_OK);
    CHECK(fe_builder_add_part(b, &t, &it, &err) == MCS_OK);
    /* node 4 z + i: (0,0) (1,0) (1,1) (0,1) at height z */
    for (int z = 0; z <= 3; z++)
        for (int i = 0; i < 4; i++) {
            const double x[3] = {i == 1 || i == 2, i >= 2, z};
            CHECK(fe_builder_add_node(b, x, NULL, &err) == MCS_OK);
        }
    const int hex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    CHECK(fe_builder_add_elem(b, ip, hex, &err) == MCS_OK);
    /* LS-DYNA pentahedra n1 n2 n3 n4 n5 n5 n6 n6: quad side face, ridge on the far edge */
    const int a0 = 4, a1 = 5, a2 = 6, a3 = 7, b0 = 8, b1 = 9, b2 = 10, b3 = 11;
    const int p1[8] = {a1, a0, b0, b1, a2, a2, b2, b2}, p2[8] = {a0, a3, b3, b0, a2, a2, b2, b2};
    CHECK(fe_builder_add_elem(b, ip, p1, &err) == MCS_OK);
    CHECK(fe_builder_add_elem(b, ip, p2, &err) == MCS_OK);
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int p = 0; p < 6; p++) {
        int ijk[3] = {0, 0, 0}, v[4];
        for (int s = 0; s < 4; s++) {
            if (s > 0) ijk[perm[p][s - 1]]++;
            static const int corner[2][2] = {{0, 3}, {1, 2}}; /* [x][y] -> i */
            v[s] = 4 * (2 + ijk[2]) + corner[ijk[0]][ijk[1]];
        }
        if (vol6(b->x + 3 * v[0], b->x + 3 * v[1], b->x + 3 * v[2], b->x + 3 * v[3]) < 0) {
            int q = v[1];
            v[1] = v[2], v[2] = q;
        }
        const int c[8] = {v[0], v[1], v[2], v[3], v[3], v[3], v[3], v[3]};
        CHECK(fe_builder_add_elem(b, ip, c, &err) == MCS_OK);
    }
    /* the tet10: corners at x = 3..4, mid-edge nodes at the middles */
    const double xc[4][3] = {{3, 0, 0}, {4, 0, 0}, {3, 1, 0}, {3, 0, 1}};
    static const int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    int c10[10];
    for (int n = 0; n < 10; n++) {
        double x[3];
        for (int i = 0; i < 3; i++)
            x[i] = n < 4 ? xc[n][i] : 0.5 * (xc[edge[n - 4][0]][i] + xc[edge[n - 4][1]][i]);
        CHECK(fe_builder_add_node(b, x, &c10[n], &err) == MCS_OK);
    }
    CHECK(fe_builder_add_elem(b, it, c10, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    fe_builder_destroy(&b);
    return m;
}

/* every cell of a block has a positive volume in VTK's node order (tetra: (0,1,2) turns
 * towards 3; wedge: (0,1,2) turns away from (3,4,5); hexahedron: bottom towards top) */
static int positive(const mcs_array *nodes, const mcs_array *el, const char *type)
{
    const double *x = nodes->v;
    const int k = (int)el->dims[1];
    for (size_t e = 0; e < el->dims[0]; e++) {
        const int *c = el->iv + (size_t)k * e;
        double v = 0;
        if (strcmp(type, "tet4") == 0 || strcmp(type, "tet10") == 0)
            v = vol6(x + 3 * c[0], x + 3 * c[1], x + 3 * c[2], x + 3 * c[3]);
        else if (strcmp(type, "wedge6") == 0) /* base triangle against the apex side */
            v = -vol6(x + 3 * c[0], x + 3 * c[1], x + 3 * c[2], x + 3 * c[3]);
        else
            v = vol6(x + 3 * c[0], x + 3 * c[1], x + 3 * c[3], x + 3 * c[4]);
        if (!(v > 0)) return 0;
    }
    return 1;
}

static void test_mesh_types(void)
{
    fe_model *m = build();
    if (!m) return;
    mcs_error err = {0};
    char dir[] = "/tmp/mcrash_s3mesh_XXXXXX", h5[128], xmf[128];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(h5, sizeof h5, "%s/m.h5", dir);
    snprintf(xmf, sizeof xmf, "%s/m.xmf", dir);
    mcs_results *r = NULL;
    CHECK(mcs_results_create(&r, h5, "", &err) == MCS_OK);
    for (int i = 0; r && i < m->npart; i++) CHECK(fe_out_part_mesh(r, 3, m, &m->part[i], &err) == MCS_OK);
    CHECK(mcs_results_commit(&r, &err) == MCS_OK);
    fe_model_destroy(&m);
    CHECK(mcs_results_open(&r, h5, &err) == MCS_OK);
    if (!r) return;
    /* the blocks and their shapes */
    static const struct {
        const char *path, *type;
        size_t ne, k;
    } want[] = {{"/stage3/mesh/mix/elements", "hex8", 1, 8},
                {"/stage3/mesh/mix/elements_wedge6", "wedge6", 2, 6},
                {"/stage3/mesh/mix/elements_tet4", "tet4", 6, 4},
                {"/stage3/mesh/quad/elements", "tet10", 1, 10}};
    for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
        mcs_array el = {0}, nodes = {0};
        char *type = NULL, np[128];
        CHECK(mcs_results_read_int(r, want[i].path, &el, &err) == MCS_OK);
        CHECK(el.rank == 2 && el.dims[0] == want[i].ne && el.dims[1] == want[i].k);
        CHECK(mcs_results_attr_str(r, want[i].path, "type", &type, &err) == MCS_OK);
        CHECK(type && strcmp(type, want[i].type) == 0);
        snprintf(np, sizeof np, "%.*s/nodes", (int)(strrchr(want[i].path, '/') - want[i].path),
                 want[i].path);
        CHECK(mcs_results_read(r, np, &nodes, &err) == MCS_OK);
        if (el.rank == 2 && nodes.rank == 2) CHECK(positive(&nodes, &el, want[i].type));
        free(type);
        mcs_array_free(&el);
        mcs_array_free(&nodes);
    }
    /* XDMF: one grid per block with its topology and count */
    mcs_xdmf_opts xo = mcs_xdmf_opts_default();
    xo.cells = fe_out_cell_types(&xo.ncells);
    CHECK(mcs_results_export_xdmf(r, xmf, &xo, &err) == MCS_OK);
    char *xml = th_slurp(xmf, NULL);
    CHECK_STR_CONTAINS(xml, "TopologyType=\"Hexahedron\" NumberOfElements=\"1\"");
    CHECK_STR_CONTAINS(xml, "TopologyType=\"Wedge\" NumberOfElements=\"2\"");
    CHECK_STR_CONTAINS(xml, "TopologyType=\"Tetrahedron\" NumberOfElements=\"6\"");
    CHECK_STR_CONTAINS(xml, "TopologyType=\"Tetrahedron_10\" NumberOfElements=\"1\"");
    CHECK_STR_CONTAINS(xml, "Name=\"mix.wedge6\"");
    CHECK_STR_CONTAINS(xml, "/stage3/mesh/mix/elements_tet4");
    free(xml);
    /* the export knows no cell type of its own (core/ does not know the FE kernel's) */
    mcs_xdmf_opts none = mcs_xdmf_opts_default();
    CHECK(mcs_results_export_xdmf(r, xmf, &none, &err) == MCS_ERR_UNSUPPORTED);
    CHECK_STR_CONTAINS(err.msg, "no cell types given");
    mcs_error_clear(&err);
    /* keyword export: 9 solids (the hexahedron, the pentahedra and tetrahedra in LS-DYNA's
       degenerate forms) and one 10-node tetrahedron */
    tr_kw_export_opts ko = tr_kw_export_opts_default();
    fe_kw_deck *dk = NULL;
    int stage = 0;
    CHECK(tr_kw_deck_from_results(r, &ko, &dk, &stage, &err) == MCS_OK);
    if (dk) {
        CHECK(dk->elem[FE_KW_SOLID].n == 9);
        CHECK(dk->elem[FE_KW_TET10].n == 1);
        /* the pentahedra come back as n1 n2 n3 n4 n5 n5 n6 n6 */
        int npenta = 0;
        for (int e = 0; e < dk->elem[FE_KW_SOLID].n; e++) {
            const int *c = dk->elem[FE_KW_SOLID].node + 8 * e;
            npenta += c[4] == c[5] && c[6] == c[7] && c[5] != c[6];
        }
        CHECK(npenta == 2);
        /* element IDs of *ELEMENT_SOLID are unique across the 8- and 10-node cards */
        CHECK(dk->elem[FE_KW_TET10].id[0] == 10);
        fe_kw_deck_destroy(&dk);
    }
    mcs_results_close(&r);
    unlink(h5);
    unlink(xmf);
    rmdir(dir);
}

int main(void)
{
    RUN(test_mesh_types);
    TEST_END();
}

/* test_mesh_exchange: meshes from a results file into another scenario (`mesh: {from:
 * OUT.h5:/stageN/mesh/<part>, at: ...}`, fe/scn/fe_scn_from.c, core/mcs_results_mesh.c):
 * - a model of every element shape (hexahedron, pentahedra, tetrahedra, a tet10, shells with a
 *   triangle, trusses) written by the FE writer and read back gives the same node coordinates
 *   and connectivity, bit for bit; the deformed shape at a time between two field rows is the
 *   linear interpolation, by hand;
 * - a bag reshaped in stage 2 is the one stage 1 uses: stage 1 of a plate on a closed bag,
 *   stage 2 on its motion, stage 1 again with the stage-2 bag at its final shape, whose first
 *   volume is the stage-2 bag's last (each run's gas bag computes it from its own nodes);
 *   stage 1 with its own reference bag read back runs the same bytes; the same bag through a
 *   keyword deck (`export --k --deformed`, read as a membrane part) is the same to its digits;
 * - bad input (missing file, part, a time beyond the fields, elements of the wrong shape, a
 *   section that does not fit the elements) exits 2 naming the file and the path. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli_util.h"
#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "fe/fe_builder_impl.h"
#include "fe/fe_out_mesh.h"
#include "fe/fe_scn_build.h"
#include "harness.h"
#include "fe_test_util.h"

static char dir[64];

static void path(char *out, size_t n, const char *name)
{
    snprintf(out, n, "%s/%s", dir, name);
}

static void write_text(const char *p, const char *text)
{
    FILE *f = fopen(p, "w");
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

/* six times the signed volume of tetrahedron a b c d */
static double vol6(const double *a, const double *b, const double *c, const double *d)
{
    double u[3], v[3], w[3];
    for (int i = 0; i < 3; i++) u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = d[i] - a[i];
    return w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) +
           w[2] * (u[0] * v[1] - u[1] * v[0]);
}

/* the volume a closed surface of quads (x: nodes, e: ne x 4) encloses, by the divergence
 * theorem: |sum over the triangles a b c, a c d of each quad of a . (b x c) / 6| */
static double enclosed(const double *x, const int *e, size_t ne)
{
    const double o[3] = {0, 0, 0};
    double v = 0;
    for (size_t i = 0; i < ne; i++) {
        const int *q = e + 4 * i;
        v += vol6(o, x + 3 * q[0], x + 3 * q[1], x + 3 * q[2]);
        v += vol6(o, x + 3 * q[0], x + 3 * q[2], x + 3 * q[3]);
    }
    return fabs(v) / 6;
}

/* parts: mix (a unit hexahedron, two pentahedra and six tetrahedra above it), quad (one tet10),
 * sheet (a quad and a triangle), rod (two trusses) */
static fe_model *build_all(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d[4] = {ft_part("mix", FE_SECTION_SOLID, 1e9, 0.3, 1000),
                         ft_part("quad", FE_SECTION_TET10, 1e9, 0.3, 1000),
                         ft_part("sheet", FE_SECTION_SHELL, 1e9, 0.3, 1000),
                         ft_part("rod", FE_SECTION_TRUSS, 1e9, 0.3, 1000)};
    d[2].section.thickness = 1e-3, d[3].section.area = 1e-4;
    int ip[4];
    for (int i = 0; i < 4; i++) CHECK(fe_builder_add_part(b, &d[i], &ip[i], &err) == MCS_OK);
    for (int z = 0; z <= 3; z++) /* node 4 z + i: (0,0) (1,0) (1,1) (0,1) at height z */
        for (int i = 0; i < 4; i++) {
            const double x[3] = {i == 1 || i == 2, i >= 2, z};
            CHECK(fe_builder_add_node(b, x, NULL, &err) == MCS_OK);
        }
    const int hex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    const int p1[8] = {5, 4, 8, 9, 6, 6, 10, 10}, p2[8] = {4, 7, 11, 8, 6, 6, 10, 10};
    CHECK(fe_builder_add_elem(b, ip[0], hex, &err) == MCS_OK);
    CHECK(fe_builder_add_elem(b, ip[0], p1, &err) == MCS_OK);
    CHECK(fe_builder_add_elem(b, ip[0], p2, &err) == MCS_OK);
    /* six tetrahedra of the top cube (Kuhn), each n1 n2 n3 n4 turned to a positive volume */
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                   {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    static const int corner[2][2] = {{0, 3}, {1, 2}}; /* [x][y] -> i */
    for (int p = 0; p < 6; p++) {
        int ijk[3] = {0, 0, 0}, v[4];
        for (int s = 0; s < 4; s++) {
            if (s > 0) ijk[perm[p][s - 1]]++;
            v[s] = 4 * (2 + ijk[2]) + corner[ijk[0]][ijk[1]];
        }
        if (vol6(b->x + 3 * v[0], b->x + 3 * v[1], b->x + 3 * v[2], b->x + 3 * v[3]) < 0) {
            int q = v[1];
            v[1] = v[2], v[2] = q;
        }
        const int c[8] = {v[0], v[1], v[2], v[3], v[3], v[3], v[3], v[3]};
        CHECK(fe_builder_add_elem(b, ip[0], c, &err) == MCS_OK);
    }
    const double xc[4][3] = {{3, 0, 0}, {4, 0, 0}, {3, 1, 0}, {3, 0, 1}};
    static const int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    int c10[10];
    for (int n = 0; n < 10; n++) {
        double x[3];
        for (int i = 0; i < 3; i++)
            x[i] = n < 4 ? xc[n][i] : 0.5 * (xc[edge[n - 4][0]][i] + xc[edge[n - 4][1]][i]);
        CHECK(fe_builder_add_node(b, x, &c10[n], &err) == MCS_OK);
    }
    CHECK(fe_builder_add_elem(b, ip[1], c10, &err) == MCS_OK);
    int s[5], r[3];
    for (int i = 0; i < 5; i++) {
        const double x[3] = {6 + (i % 3), i / 3, 0};
        CHECK(fe_builder_add_node(b, x, &s[i], &err) == MCS_OK);
    }
    const int q[4] = {s[0], s[1], s[4], s[3]}, tri[4] = {s[1], s[2], s[4], s[4]};
    CHECK(fe_builder_add_elem(b, ip[2], q, &err) == MCS_OK);
    CHECK(fe_builder_add_elem(b, ip[2], tri, &err) == MCS_OK);
    for (int i = 0; i < 3; i++) {
        const double x[3] = {10 + 0.5 * i, 0, 0};
        CHECK(fe_builder_add_node(b, x, &r[i], &err) == MCS_OK);
    }
    CHECK(fe_builder_add_elem(b, ip[3], r, &err) == MCS_OK);
    CHECK(fe_builder_add_elem(b, ip[3], r + 1, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    fe_builder_destroy(&b);
    return m;
}

/* u(x) = (0.01 x, -0.02 z, 0.03 y) [m] at t = 0.1 s, zero at t = 0 */
static void u_of(const double *x, double *u)
{
    u[0] = 0.01 * x[0], u[1] = -0.02 * x[2], u[2] = 0.03 * x[1];
}

/* the model's meshes in /stage2/mesh, two field rows at 0 and 0.1 s */
static void write_file(const fe_model *m, const char *h5)
{
    mcs_error err = {0};
    mcs_results *r = NULL;
    CHECK(mcs_results_create(&r, h5, "", &err) == MCS_OK);
    if (!r) return;
    CHECK(fe_out_meshes(r, 2, m, &err) == MCS_OK);
    mcs_results_series *t = NULL, *d = NULL;
    CHECK(mcs_results_field_series(r, 2, (size_t)m->nnode, &t, &d, &err) == MCS_OK);
    double *u = calloc(3 * (size_t)m->nnode, sizeof *u);
    const double t0 = 0, t1 = 0.1;
    CHECK(mcs_results_series_append(t, &t0, &err) == MCS_OK);
    CHECK(mcs_results_series_append(d, u, &err) == MCS_OK);
    for (int i = 0; i < m->nnode; i++) u_of(m->node_x0 + 3 * i, u + 3 * i);
    CHECK(mcs_results_series_append(t, &t1, &err) == MCS_OK);
    CHECK(mcs_results_series_append(d, u, &err) == MCS_OK);
    free(u);
    CHECK(mcs_results_commit(&r, &err) == MCS_OK);
}

static const char *const PARTS =
    "    - {name: mix, mesh: {from: \"%s:/stage2/mesh/mix\"%s}, section: {type: solid},\n"
    "       material: {model: elastic, density: 1000, youngs_modulus: 1e9, poisson: 0.3}}\n"
    "    - {name: quad, mesh: {from: \"%s:/stage2/mesh/quad\"%s}, section: {type: solid},\n"
    "       material: {model: elastic, density: 1000, youngs_modulus: 1e9, poisson: 0.3}}\n"
    "    - {name: sheet, mesh: {from: \"%s:/stage2/mesh/sheet\"%s},\n"
    "       section: {type: shell, thickness: 1 mm},\n"
    "       material: {model: elastic, density: 1000, youngs_modulus: 1e9, poisson: 0.3}}\n"
    "    - {name: rod, mesh: {from: \"%s:/stage2/mesh/rod\"%s},\n"
    "       section: {type: truss, area: 1e-4},\n"
    "       material: {model: elastic, density: 1000, youngs_modulus: 1e9, poisson: 0.3}}\n";

/* the four parts read from h5 with the mesh option `at` ("" or ", at: ...") */
static fe_model *read_back(const char *h5, const char *at, mcs_error *err)
{
    char text[4096], parts[3000];
    snprintf(parts, sizeof parts, PARTS, h5, at, h5, at, h5, at, h5, at);
    snprintf(text, sizeof text, "mcrash: 1\nname: back\nsimulation: {end_time: 1 ms}\nfe:\n"
                                "  parts:\n%s", parts);
    mcs_scenario *scn = NULL;
    fe_problem p = {0};
    char name[128];
    path(name, sizeof name, "back.yaml");
    mcs_status st = mcs_scenario_load_text(name, text, strlen(text), &scn, err);
    if (!st) st = fe_scn_build(scn, &p, err);
    fe_model *m = p.model;
    p.model = NULL;
    fe_problem_free(&p);
    mcs_scenario_destroy(&scn);
    return st ? NULL : m;
}

static int same_ints(const int *a, const int *b, int n)
{
    return n == 0 || memcmp(a, b, sizeof(int) * (size_t)n) == 0;
}

static void test_round_trip(void)
{
    fe_model *m = build_all();
    if (!m) return;
    char h5[128];
    path(h5, sizeof h5, "all.h5");
    write_file(m, h5);
    mcs_error err = {0};
    fe_model *b = read_back(h5, "", &err);
    if (!b) fprintf(stderr, "%s\n", err.msg);
    CHECK(b != NULL);
    if (b) {
        CHECK(b->nnode == m->nnode && b->nhex == m->nhex && b->nshell == m->nshell);
        CHECK(b->ntruss == m->ntruss && b->ntet10 == m->ntet10 && b->npart == m->npart);
        CHECK(b->nhex == 9 && b->ntet10 == 1 && b->nshell == 2 && b->ntruss == 2);
        CHECK(memcmp(b->node_x0, m->node_x0, sizeof(double) * 3 * (size_t)m->nnode) == 0);
        CHECK(same_ints(b->hex_node, m->hex_node, 8 * m->nhex));
        CHECK(same_ints(b->shell_node, m->shell_node, 4 * m->nshell));
        CHECK(same_ints(b->truss_node, m->truss_node, 2 * m->ntruss));
        CHECK(same_ints(b->tet10_node, m->tet10_node, 10 * m->ntet10));
        printf("  round trip: %d nodes, %d hex slots (1 hex, 2 wedges, 6 tets), 1 tet10, "
               "2 shells, 2 trusses identical\n", b->nnode, b->nhex);
    }
    fe_model_destroy(&b);
    /* at 0.05 s, half way between the rows at 0 and 0.1 s: x0 + u / 2; final: x0 + u */
    const char *at[2] = {", at: 50 ms", ", at: final"};
    const double w[2] = {0.5, 1.0};
    for (int k = 0; k < 2; k++) {
        b = read_back(h5, at[k], &err);
        CHECK(b != NULL && b->nnode == m->nnode);
        double e = 0;
        for (int i = 0; b && i < m->nnode; i++) {
            double u[3];
            u_of(m->node_x0 + 3 * i, u);
            for (int j = 0; j < 3; j++)
                e = fmax(e, fabs(b->node_x0[3 * i + j] - (m->node_x0[3 * i + j] + w[k] * u[j])));
        }
        CHECK(e < 1e-15);
        fe_model_destroy(&b);
    }
    fe_model_destroy(&m);
}

static void put_piston(const char *name, const char *mesh, const char *extra)
{
    char p[128], text[8192];
    path(p, sizeof p, name);
    FILE *f = fopen("scenarios/verification/coupled_bag_piston.yaml", "rb");
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    if (f) fclose(f);
    text[n] = 0;
    /* 20 ms: the plate compresses the bag */
    char *e = strstr(text, "end_time: 63 ms");
    if (e) memcpy(e, "end_time: 20 ms", 15);
    const char *gen = "mesh: {generate: cylinder_shell, diameter: 0.3 m, length: 0.2 m, "
                      "element_size: 25 mm,\n             axis: z, closed: true}";
    char *g = strstr(text, gen);
    CHECK(e && g);
    if (!g) return;
    char out[9000];
    snprintf(out, sizeof out, "%.*s%s%s%s", (int)(g - text), text, mesh, g + strlen(gen), extra);
    write_text(p, out);
}

static double *rd(const char *h5, const char *ds, size_t *n)
{
    mcs_results *r = NULL;
    mcs_error err = {0};
    mcs_array a = {0};
    double *v = NULL;
    if (mcs_results_open(&r, h5, &err) == MCS_OK && mcs_results_read(r, ds, &a, &err) == MCS_OK) {
        v = a.v, a.v = NULL, *n = a.n;
    }
    mcs_array_free(&a);
    mcs_results_close(&r);
    return v;
}

static int *rd_int(const char *h5, const char *ds, size_t *n)
{
    mcs_results *r = NULL;
    mcs_error err = {0};
    mcs_array a = {0};
    int *v = NULL;
    if (mcs_results_open(&r, h5, &err) == MCS_OK &&
        mcs_results_read_int(r, ds, &a, &err) == MCS_OK) {
        v = a.iv, a.iv = NULL, *n = a.n;
    }
    mcs_array_free(&a);
    mcs_results_close(&r);
    return v;
}

static cli_result *mcrash(const char *fmt, const char *a, const char *b)
{
    char args[1024], pa[128], pb[128];
    path(pa, sizeof pa, a);
    path(pb, sizeof pb, b);
    snprintf(args, sizeof args, fmt, pa, pb);
    return cli_run(args);
}

static void test_stage2_bag_in_stage1(void)
{
    put_piston("s1.yaml", "mesh: {generate: cylinder_shell, diameter: 0.3 m, length: 0.2 m, "
                          "element_size: 25 mm, axis: z, closed: true}", "");
    put_piston("s2.yaml", "mesh: {generate: cylinder_shell, diameter: 0.3 m, length: 0.2 m, "
                          "element_size: 25 mm, axis: z, closed: true}",
               "stage2: {prescribed: [{body: plate}]}\n");
    put_piston("back.yaml", "mesh: {from: \"s1.h5:/stage1/mesh/bag\"}", "");
    put_piston("s1b.yaml", "mesh: {from: \"s2.h5:/stage2/mesh/bag\", at: final}", "");
    CHECK(mcrash("run %s -o %s --quiet", "s1.yaml", "s1.h5")->status == 0);
    char args[512], y[128], m[128], o[128];
    path(y, sizeof y, "s2.yaml"), path(m, sizeof m, "s1.h5"), path(o, sizeof o, "s2.h5");
    snprintf(args, sizeof args, "stage2 %s --motion %s -o %s --quiet", y, m, o);
    CHECK(cli_run(args)->status == 0);
    CHECK(mcrash("run %s -o %s --quiet", "back.yaml", "back.h5")->status == 0);
    cli_result *r = mcrash("run %s -o %s --quiet", "s1b.yaml", "s1b.h5");
    CHECK(r->status == 0);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    char s1[128], s2[128], bk[128], sb[128];
    path(s1, sizeof s1, "s1.h5"), path(s2, sizeof s2, "s2.h5");
    path(bk, sizeof bk, "back.h5"), path(sb, sizeof sb, "s1b.h5");
    /* the reference bag read back: the same run, byte for byte in its pressure */
    double vol = 0; /* the stage-2 bag's last shape's volume, by the test [m^3] */
    size_t n1 = 0, n2 = 0, nx = 0, nu = 0, ne1 = 0, ne2 = 0, nv = 0, nw = 0;
    double *p1 = rd(s1, "/stage1/airbag/bag/pressure", &n1);
    double *p2 = rd(bk, "/stage1/airbag/bag/pressure", &n2);
    CHECK(p1 && p2 && n1 == n2 && n1 > 100 && memcmp(p1, p2, n1 * sizeof *p1) == 0);
    free(p1), free(p2);
    /* stage 1 on the stage-2 bag: its nodes are stage 2's last shape, its elements the same */
    double *x2 = rd(s2, "/stage2/mesh/bag/nodes", &nx);
    double *u2 = rd(s2, "/stage2/fields/displacement", &nu);
    double *xb = rd(sb, "/stage1/mesh/bag/nodes", &n1);
    int *e2 = rd_int(s2, "/stage2/mesh/bag/elements", &ne1);
    int *eb = rd_int(sb, "/stage1/mesh/bag/elements", &ne2);
    CHECK(x2 && u2 && xb && e2 && eb && nx == n1 && nu % nx == 0 && ne1 == ne2);
    if (x2 && u2 && xb && nx == n1 && nu % nx == 0) {
        const double *u = u2 + nu - nx; /* the last row; the bag is the only part: offset 0 */
        double e = 0, umax = 0;
        for (size_t i = 0; i < nx; i++) {
            e = fmax(e, fabs(xb[i] - (x2[i] + u[i])));
            umax = fmax(umax, fabs(u[i]));
        }
        CHECK(e == 0 && umax > 0.01); /* reshaped by more than 10 mm */
        double *xs = malloc(nx * sizeof *xs);
        for (size_t i = 0; xs && i < nx; i++) xs[i] = x2[i] + u[i];
        vol = xs && e2 && ne1 % 4 == 0 ? enclosed(xs, e2, ne1 / 4) : 0;
        free(xs);
        printf("  stage-2 bag in stage 1: %zu nodes, moved up to %.1f mm in stage 2\n", nx / 3,
               1e3 * umax);
    }
    CHECK(e2 && eb && ne1 == ne2 && memcmp(e2, eb, ne1 * sizeof *e2) == 0);
    double *v2 = rd(s2, "/stage2/airbag/bag/volume", &nv);
    double *vb = rd(sb, "/stage1/airbag/bag/volume", &nw);
    CHECK(v2 && vb && nv > 1 && nw > 1);
    if (v2 && vb && nv > 1 && nw > 1) {
        printf("  volume: stage 2 %.4f -> %.4f L (its last shape %.6f L by the divergence "
               "theorem), stage 1 on that bag starts at %.6f L\n",
               1e3 * v2[0], 1e3 * v2[nv - 1], 1e3 * vol, 1e3 * vb[0]);
        CHECK(v2[nv - 1] < 0.9 * v2[0]); /* compressed */
        CHECK_REL(vb[0], vol, 1e-9);     /* the stage-1 bag is stage 2's last shape */
        CHECK_REL(vb[0], v2[nv - 1], 1e-4); /* stage 2's last gas sample (one step before) */
    }
    /* the other route: the stage-2 bag in its last shape as a keyword deck, read as a
     * membrane part: the same nodes to the deck's digits, the same elements and volume */
    char k[128], kargs[400];
    path(k, sizeof k, "bag.k");
    snprintf(kargs, sizeof kargs, "export %s --k %s --stage 2 --deformed --long", s2, k);
    CHECK(cli_run(kargs)->status == 0);
    put_piston("s1k.yaml", "mesh: {keyword: bag.k, part: 1}", "");
    r = mcrash("run %s -o %s --quiet", "s1k.yaml", "s1k.h5");
    CHECK(r->status == 0);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    char sk[128];
    path(sk, sizeof sk, "s1k.h5");
    size_t nk = 0, nek = 0, nvk = 0;
    double *xk = rd(sk, "/stage1/mesh/bag/nodes", &nk);
    double *vk = rd(sk, "/stage1/airbag/bag/volume", &nvk);
    int *ek = rd_int(sk, "/stage1/mesh/bag/elements", &nek);
    CHECK(xk && xb && ek && eb && vk && vb && nk == n1 && nek == ne2);
    if (xk && xb && ek && eb && vk && vb && nk == n1 && nek == ne2) {
        double e = 0;
        for (size_t i = 0; i < nk; i++) e = fmax(e, fabs(xk[i] - xb[i]));
        printf("  the same bag through a keyword deck: nodes within %.1e m, volume %.6f L\n", e,
               1e3 * vk[0]);
        CHECK(e < 1e-12); /* 20-character fields: 14 digits of 0.3 m */
        CHECK(memcmp(ek, eb, nek * sizeof *ek) == 0);
        CHECK_REL(vk[0], vb[0], 1e-12);
    }
    free(xk), free(ek), free(vk);
    free(x2), free(u2), free(xb), free(e2), free(eb), free(v2), free(vb);
}

/* a results file whose part `bad` has 5-node elements */
static void write_bad(const char *h5)
{
    mcs_error err = {0};
    mcs_results *r = NULL;
    CHECK(mcs_results_create(&r, h5, "", &err) == MCS_OK);
    if (!r) return;
    const double x[15] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1};
    const int el[5] = {0, 1, 2, 3, 4};
    size_t dn[2] = {5, 3}, de[2] = {1, 5};
    CHECK(mcs_results_write(r, "/stage2/mesh/bad/nodes", 2, dn, x, "m", &err) == MCS_OK);
    CHECK(mcs_results_write_int(r, "/stage2/mesh/bad/elements", 2, de, el, "-", &err) == MCS_OK);
    CHECK(mcs_results_commit(&r, &err) == MCS_OK);
}

static void test_bad_input(void)
{
    char bad[128];
    path(bad, sizeof bad, "bad.h5");
    write_bad(bad);
    static const struct { const char *mesh, *say; } c[] = {
        {"mesh: {from: \"none.h5:/stage2/mesh/bag\"}", "none.h5:/stage2/mesh/bag"},
        {"mesh: {from: \"s2.h5:/stage2/mesh/bags\"}", "s2.h5:/stage2/mesh/bags: no such part"},
        {"mesh: {from: \"s2.h5:/stage2/mesh/bag\", at: 30 ms}", "time 0.03 s outside"},
        {"mesh: {from: \"bad.h5:/stage2/mesh/bad\"}", "bad.h5:/stage2/mesh/bad/elements"},
        {"mesh: {from: \"s2.h5:/stage2/mesh\"}", "expected FILE.h5:/stageN/mesh/<part>"},
        {"mesh: {from: \"s2.h5:/stage2/mesh/bag\", part: 3}", "goes with keyword:"},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        put_piston("bad.yaml", c[i].mesh, "");
        cli_result *r = mcrash("run %s -o %s --quiet", "bad.yaml", "bad_out.h5");
        CHECK(r->status == 2);
        CHECK_STR_CONTAINS(r->err, c[i].say);
        CHECK_STR_CONTAINS(r->err, "bad.yaml:");
    }
    /* shells into a solid section */
    char y[128], text[1024];
    path(y, sizeof y, "solid.yaml");
    snprintf(text, sizeof text,
             "mcrash: 1\nname: s\nsimulation: {end_time: 1 ms}\nfe:\n  parts:\n"
             "    - {name: p, mesh: {from: \"s2.h5:/stage2/mesh/bag\"}, section: {type: solid},\n"
             "       material: {model: elastic, density: 1000, youngs_modulus: 1e9, "
             "poisson: 0.3}}\n");
    write_text(y, text);
    cli_result *r = mcrash("stage3 %s -o %s --quiet", "solid.yaml", "solid.h5");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "s2.h5:/stage2/mesh/bag: quad4 elements; the part's section must "
                               "be shell or membrane");
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/mcrash_mx_XXXXXX");
    if (!mkdtemp(dir)) return 1;
    RUN(test_round_trip);
    RUN(test_stage2_bag_in_stage1);
    RUN(test_bad_input);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0) return 1;
    TEST_END();
}

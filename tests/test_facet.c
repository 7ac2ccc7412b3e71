/* test_facet.c: facet (triangle mesh) contact surfaces in the scenario and the stage-1 engine
 * (stage1_mb/mb_facet.h, core/mcs_obj.h): a sphere bouncing on a facet floor moves exactly as on
 * the ground plane with the same law (the face contact of a sphere is the plane's depth
 * R - distance); beside the facet's footprint it falls freely (z0 - g t^2 / 2); an OBJ file gives
 * the same mesh as the inline form; bad meshes are refused at the key. */
#include "harness.h"
#include "figures.h"
#include "stage1_mb/mb_model.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* a 1 kg sphere R 0.1 m at (x, 0, 0.3) falling on an elastic law of 1e5 N/m; `floor` is the
 * contact partner: the ground plane or a fixed body carrying a facet square of 2 x 2 m */
#define HEAD                                                                                       \
    "mcrash: 1\n"                                                                                  \
    "simulation: {end_time: 0.5 s, time_step: 10 us, output_rate: 1 kHz}\n"                        \
    "characteristics: {law: {loading: [[0, 0], [0.01, 1000]]}}\n"
#define SPHERE(x)                                                                                  \
    "  - {name: ball, mass: 1 kg, inertia: [0.004, 0.004, 0.004], position: [" x ", 0, 0.3],\n"    \
    "     velocity: [0, 0, 0], surfaces: [{type: ellipsoid, center: [0, 0, 0],\n"                  \
    "     semi_axes: [0.1, 0.1, 0.1]}]}\n"
#define ON_PLANE                                                                                   \
    HEAD "environment: {gravity: 9.81 m/s^2, ground: {height: 0 m}}\n"                             \
         "bodies:\n" SPHERE("0") "contacts: [{a: ball, b: ground, characteristic: law}]\n"
/* the floor body's CG 1 m below its face, the face at z = 0 */
#define FLOOR_BODY(surf)                                                                           \
    "  - {name: floor, mass: 1000 kg, inertia: [100, 100, 100], position: [0, 0, -1],\n"           \
    "     velocity: [0, 0, 0], surfaces: [" surf "]}\n"
#define INLINE_SQUARE                                                                              \
    "{type: facet, vertices: [[-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]],\n"                  \
    "      triangles: [[0, 1, 2], [0, 2, 3]]}"
#define TAIL                                                                                       \
    "joints: [{type: fixed, parent: ground, child: floor, anchor: [0, 0, -1]}]\n"                  \
    "contacts: [{a: ball, b: floor, characteristic: law}]\n"
#define ON_FACET(x, surf)                                                                          \
    HEAD "environment: {gravity: 9.81 m/s^2}\n"                                                    \
         "bodies:\n" SPHERE(x) FLOOR_BODY(surf) TAIL

static mb_model *build_text(const char *name, const char *txt, mcs_error *err)
{
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    if (mcs_scenario_load_text(name, txt, strlen(txt), &scn, err) == MCS_OK)
        mb_model_build(scn, NULL, &m, err);
    mcs_scenario_destroy(&scn);
    return m;
}

/* the ball's height every step (nsteps + 1 values, malloc), or NULL */
static double *trajectory(const char *name, const char *txt, long *n)
{
    mcs_error err = {0};
    mb_model *m = build_text(name, txt, &err);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        return NULL;
    }
    mb_state *s = NULL;
    double *z = NULL;
    if (mb_state_create(m, &s, &err) == MCS_OK && (z = malloc(sizeof *z * (m->nsteps + 1)))) {
        int b = mb_model_body(m, "ball");
        z[0] = s->kin[b].pos[2];
        while (s->step < m->nsteps && mb_step(m, s, &err) == MCS_OK)
            z[s->step] = s->kin[b].pos[2];
        *n = s->step;
    }
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    return z;
}

/* the same bounce on the plane and on the facet square (face contact, the sphere's centre over
 * the triangles' shared diagonal at first); the fixed floor moves by its joint's constraint
 * error only, so the heights agree to 1e-9 m over 0.5 s (two bounces) */
static void test_facet_equals_plane(void)
{
    long n1 = 0, n2 = 0;
    double *a = trajectory("plane.yaml", ON_PLANE, &n1);
    double *b = trajectory("facet.yaml", ON_FACET("0", INLINE_SQUARE), &n2);
    CHECK(a && b && n1 == 50000 && n2 == 50000);
    double dmax = 0, zmin = 1;
    for (long i = 0; a && b && i <= n1 && i <= n2; i++) {
        dmax = fmax(dmax, fabs(a[i] - b[i]));
        zmin = fmin(zmin, b[i]);
    }
    CHECK(dmax < 3e-10); /* 3x the 1.0e-10 the README states */
    FIG("contact_geometry.facet_vs_plane_height", "%.1e", dmax);
    CHECK(zmin < 0.1); /* it did touch (the sphere's bottom below the face) */
    CHECK(a && b && b[n2] > 0.1);
    printf("  facet vs plane: largest height difference %.2e m over %ld steps, lowest centre "
           "%.5f m\n",
           dmax, n2, zmin);
    free(a), free(b);
}

/* a tilted floor body (roll 0.2, pitch 0.1 rad): its facet square and its plane (the same face)
 * give the same 3-D path of the sphere (the mesh pose comes from the body's rotation) */
#define TILTED(surf)                                                                               \
    HEAD "environment: {gravity: 9.81 m/s^2}\n"                                                    \
         "bodies:\n" SPHERE(                                                                       \
             "0") "  - {name: floor, mass: 1000 kg, inertia: [100, 100, 100], position: [0, 0, "   \
                  "-1],\n"                                                                         \
                  "     orientation: [0.2, 0.1, 0], velocity: [0, 0, 0], surfaces: [" surf         \
                  "]}\n" TAIL

static double *path3(const char *txt, long *n)
{
    mcs_error err = {0};
    mb_model *m = build_text("tilted.yaml", txt, &err);
    mb_state *s = NULL;
    double *p = NULL;
    if (m && mb_state_create(m, &s, &err) == MCS_OK &&
        (p = malloc(sizeof *p * 3 * (m->nsteps + 1)))) {
        int b = mb_model_body(m, "ball");
        while (s->step < m->nsteps && mb_step(m, s, &err) == MCS_OK)
            memcpy(p + 3 * s->step, s->kin[b].pos, 3 * sizeof *p);
        *n = s->step;
    }
    if (!m) fprintf(stderr, "%s\n", err.msg);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    return p;
}

static void test_tilted(void)
{
    long n1 = 0, n2 = 0;
    double *a = path3(TILTED("{type: plane, point: [0, 0, 1], normal: [0, 0, 1]}"), &n1);
    double *b = path3(TILTED(INLINE_SQUARE), &n2);
    CHECK(a && b && n1 == n2 && n1 == 50000);
    double dmax = 0, ymin = 0;
    for (long i = 1; a && b && i <= n1; i++) {
        for (int k = 0; k < 3; k++)
            dmax = fmax(dmax, fabs(a[3 * i + k] - b[3 * i + k]));
        ymin = fmin(ymin, b[3 * i + 1]);
    }
    CHECK(dmax < 1e-9);
    CHECK(ymin < -0.01); /* the roll sent it sideways */
    printf("  tilted facet vs plane: largest position difference %.2e m\n", dmax);
    free(a), free(b);
}

/* beside the square (centre 1.15 m from the edge x = 1, more than R = 0.1 m): free fall, the
 * exact z0 - g t^2 / 2 of the symplectic Euler step is z0 - g h^2 n (n + 1) / 2 */
static void test_beside_falls_freely(void)
{
    long n = 0;
    double *z = trajectory("beside.yaml", ON_FACET("2.15", INLINE_SQUARE), &n);
    CHECK(z != NULL && n == 50000);
    if (!z) return;
    double h = 1e-5, g = 9.81;
    CHECK_NEAR(z[n], 0.3 - g * h * h * (double)n * (double)(n + 1) / 2, 1e-9);
    free(z);
}

/* an OBJ file (a quad: one face of four vertices, a fan of two triangles; comments, normals and
 * "a//n" indices skipped) gives the inline result */
static void test_obj_file(void)
{
    char dir[] = "/tmp/mcrash_facet_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char obj[128], yaml[128];
    snprintf(obj, sizeof obj, "%s/floor.obj", dir);
    snprintf(yaml, sizeof yaml, "%s/scn.yaml", dir);
    FILE *f = fopen(obj, "w");
    CHECK(f != NULL);
    if (!f) return;
    fprintf(f, "# a 2 x 2 m square, 1 m above the body's CG\no floor\n"
               "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nvn 0 0 1\n"
               "f 1//1 2//1 3//1 4//1\n");
    fclose(f);
    long n1 = 0, n2 = 0;
    double *a = trajectory("inline.yaml", ON_FACET("0.3", INLINE_SQUARE), &n1);
    double *b = trajectory(yaml, ON_FACET("0.3", "{type: facet, file: floor.obj}"), &n2);
    CHECK(a && b && n1 == n2);
    double dmax = 0;
    for (long i = 0; a && b && i <= n1; i++)
        dmax = fmax(dmax, fabs(a[i] - b[i]));
    CHECK(dmax == 0);
    free(a), free(b);
    /* a broken OBJ: the line is named */
    f = fopen(obj, "w");
    if (f) {
        fprintf(f, "v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n");
        fclose(f);
    }
    mcs_error err = {0};
    mb_model *m = build_text(yaml, ON_FACET("0.3", "{type: facet, file: floor.obj}"), &err);
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(err.msg, "floor.obj:3: error: a vertex needs three finite coordinates");
    CHECK_STR_CONTAINS(err.msg, "bodies[1].surfaces[0].file");
    mb_model_destroy(&m);
    remove(obj);
    rmdir(dir);
}

static void expect_error(const char *surf, mcs_status st, const char *what)
{
    char txt[4096];
    snprintf(txt, sizeof txt, "%s", ON_FACET("0", "%s"));
    char full[4096];
    snprintf(full, sizeof full, txt, surf);
    mcs_error err = {0};
    mb_model *m = build_text("bad.yaml", full, &err);
    CHECK(m == NULL);
    CHECK(err.status == st);
    CHECK_STR_CONTAINS(err.msg, what);
    mb_model_destroy(&m);
}

static void test_errors(void)
{
    expect_error(
        "{type: facet, vertices: [[0, 0, 1], [1, 0, 1], [0, 1, 1]], triangles: [[0, 1, 3]]}",
        MCS_ERR_RANGE, "bad.yaml:10:116: error: bodies[1].surfaces[0].");
    expect_error(
        "{type: facet, vertices: [[0, 0, 1], [1, 0, 1], [0, 1, 1]], triangles: [[0, 1, 3]]}",
        MCS_ERR_RANGE, "triangles[0][2]: vertex 3 does not exist (0 to 2)");
    expect_error(
        "{type: facet, vertices: [[0, 0, 1], [1, 0, 1], [2, 0, 1]], triangles: [[0, 1, 2]]}",
        MCS_ERR_RANGE, "zero area");
    expect_error("{type: facet, vertices: [[0, 0, 1], [1, 0, 1]], triangles: [[0, 1, 1]]}",
                 MCS_ERR_TYPE, "at least 3 points");
    expect_error("{type: facet, vertices: [[0, 0, \"1 furlong\"], [1, 0, 1], [0, 1, 1]], "
                 "triangles: [[0, 1, 2]]}",
                 MCS_ERR_UNIT, "vertices[0][2]");
    expect_error("{type: facet, file: none.obj, triangles: [[0, 1, 2]]}", MCS_ERR_KEY, "not both");
    expect_error("{type: facet, file: none.obj}", MCS_ERR_IO, "none.obj: cannot open");
    expect_error("{type: facet, vertices: [[0, 0, 1], [1, 0, 1], [0, 1, 1]]}", MCS_ERR_KEY,
                 "needs vertices and triangles");
}

int main(void)
{
    RUN(test_facet_equals_plane);
    RUN(test_tilted);
    RUN(test_beside_falls_freely);
    RUN(test_obj_file);
    RUN(test_errors);
    TEST_END();
}

/* Facet contact force = gradient of the contact energy (stage1_mb/mb_geom_facet.c).
 * For a penetration d(c) of an ellipsoid centred at c, a force f(d) along unit normal N with
 * magnitude gain is conservative for translations when -grad_c d = gain * N (the work
 * f dd = f grad d . dc). Checked here against central finite differences of the depth at
 * face, edge and vertex contacts, and the depth cap of mb_geom_ellipsoid_mesh_deepest_capped. */
#include "stage1_mb/mb_geom.h"
#include "tests/harness.h"

#include <math.h>

static const double V0[3] = {0, 0, 0}, V1[3] = {1, 0, 0}, V2[3] = {0, 1, 0};

static mb_ellipsoid ell(double x, double y, double z)
{
    mb_ellipsoid e = {.center = {x, y, z}, .semi = {0.12, 0.08, 0.1}};
    /* axes turned 30 deg about z and 20 deg about x: a general orientation */
    double a = 30 * M_PI / 180, b = 20 * M_PI / 180;
    double Rz[9] = {cos(a), -sin(a), 0, sin(a), cos(a), 0, 0, 0, 1};
    double Rx[9] = {1, 0, 0, 0, cos(b), -sin(b), 0, sin(b), cos(b)};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0;
            for (int k = 0; k < 3; k++) s += Rz[3 * i + k] * Rx[3 * k + j];
            e.rot[3 * i + j] = s;
        }
    return e;
}

static double depth_at(mb_ellipsoid e)
{
    mb_contact c;
    return mb_geom_ellipsoid_triangle(&e, V0, V1, V2, &c) ? c.depth : 0;
}

/* grad d by central differences vs -gain * normal; returns the feature */
static int check_gradient(double x, double y, double z)
{
    mb_ellipsoid e = ell(x, y, z);
    mb_contact c;
    CHECK(mb_geom_ellipsoid_triangle(&e, V0, V1, V2, &c));
    double gain = c.gain > 0 ? c.gain : 1, h = 1e-6;
    for (int k = 0; k < 3; k++) {
        mb_ellipsoid ep = e, em = e;
        ep.center[k] += h, em.center[k] -= h;
        double g = (depth_at(ep) - depth_at(em)) / (2 * h);
        CHECK_NEAR(g, -gain * c.normal[k], 1e-6);
    }
    CHECK_NEAR(c.normal[0] * c.normal[0] + c.normal[1] * c.normal[1] + c.normal[2] * c.normal[2],
               1.0, 1e-12);
    return c.feature;
}

static void test_face_gradient(void)
{
    CHECK(check_gradient(0.3, 0.3, 0.07) == MB_FEATURE_FACE);
}

static void test_edge_gradient(void)
{
    /* centre beyond the edge y = 0 (outside the triangle), overlapping it */
    CHECK(check_gradient(0.5, -0.04, 0.06) == MB_FEATURE_EDGE);
    /* beyond the hypotenuse */
    CHECK(check_gradient(0.55, 0.5, 0.05) == MB_FEATURE_EDGE);
}

static void test_vertex_gradient(void)
{
    CHECK(check_gradient(-0.05, -0.04, 0.05) == MB_FEATURE_VERTEX);
}

/* the cap: a contact deeper than max_depth is ignored, a shallower one kept */
static void test_depth_cap(void)
{
    double vert[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    int tri[3] = {0, 1, 2};
    mb_mesh *m = NULL;
    mcs_error err = {0};
    CHECK(mb_mesh_create(&m, 3, vert, 1, tri, &err) == MCS_OK);
    if (!m) return;
    mb_ellipsoid e = ell(0.3, 0.3, 0.07);
    mb_contact c;
    CHECK(mb_geom_ellipsoid_mesh_deepest_capped(&e, m, NULL, INFINITY, &c));
    double d = c.depth;
    CHECK(d > 0);
    CHECK(mb_geom_ellipsoid_mesh_deepest_capped(&e, m, NULL, 1.01 * d, &c) && c.depth == d);
    CHECK(!mb_geom_ellipsoid_mesh_deepest_capped(&e, m, NULL, 0.99 * d, &c));
    mb_mesh_destroy(&m);
}

int main(void)
{
    RUN(test_face_gradient);
    RUN(test_edge_gradient);
    RUN(test_vertex_gradient);
    RUN(test_depth_cap);
    TEST_END();
}

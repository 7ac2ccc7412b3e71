/* The depth cap of mb_geom_ellipsoid_mesh_deepest_capped (stage1_mb/mb_facet.h): a triangle
 * contact deeper than max_depth is ignored, a shallower one is returned unchanged. */
#include "stage1_mb/mb_geom.h"
#include "tests/harness.h"

#include <math.h>

static void test_depth_cap(void)
{
    double vert[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    int tri[3] = {0, 1, 2};
    mb_mesh *m = NULL;
    mcs_error err = {0};
    CHECK(mb_mesh_create(&m, 3, vert, 1, tri, &err) == MCS_OK);
    if (!m) return;
    /* a sphere of radius 0.1 m with its centre 0.07 m above the face: depth 0.03 m exactly */
    mb_ellipsoid e = {.center = {0.3, 0.3, 0.07}, .semi = {0.1, 0.1, 0.1},
                      .rot = {1, 0, 0, 0, 1, 0, 0, 0, 1}};
    mb_contact c;
    CHECK(mb_geom_ellipsoid_mesh_deepest_capped(&e, m, NULL, INFINITY, &c));
    CHECK_NEAR(c.depth, 0.03, 1e-12);
    CHECK(mb_geom_ellipsoid_mesh_deepest_capped(&e, m, NULL, 0.031, &c));
    CHECK_NEAR(c.depth, 0.03, 1e-12);
    CHECK(!mb_geom_ellipsoid_mesh_deepest_capped(&e, m, NULL, 0.029, &c));
    CHECK(c.depth == 0);
    mb_mesh_destroy(&m);
}

int main(void)
{
    RUN(test_depth_cap);
    TEST_END();
}

/* test_mb_wheel_ellipsoid.c: the wheel (cylinder surface: the filled tyre torus) against an
 * ellipsoid (mb_geom_wheel_ellipsoid, docs/contact_geometry.md) against closed forms, and the
 * engine's cylinder-ellipsoid pairs. */
#include "harness.h"
#include "figures.h"
#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <string.h>

static mb_ellipsoid sphere(double x, double y, double z, double rho)
{
    mb_ellipsoid e = {.center = {x, y, z}, .rot = {1, 0, 0, 0, 1, 0, 0, 0, 1}, .semi = {rho, rho, rho}};
    return e;
}

/* A sphere (radius rho, centre q) against the crown: the torus is the crown circle (radius R,
 * centre c, axis a) grown by the tube r, so for q outside the disc's faces (radial distance
 * from the axis s >= R) the distance from q to the torus' centre circle is
 * D = sqrt((s - R)^2 + y^2) (y along the axis) and the penetration is exactly r + rho - D,
 * along the line from q to the nearest crown point. The disc's half-thickness eps = 1e-4 R
 * changes its support by eps^2 (n.a)^2 / (2 R |P n|) at most: ~1e-9 m here. */
static void test_sphere_against_crown(void)
{
    const double R = 0.24, r = 0.06, rho = 0.1;
    mb_wheel w = {.center = {0, 0, 0}, .axis = {0, 1, 0}, .radius = R, .tube = r};
    const double q[][3] = {{0.38, 0.0, 0.0},  {0.0, 0.03, -0.37}, {0.25, -0.05, 0.2},
                           {-0.3, 0.08, 0.1}, {0.2, 0.1, -0.25},  {0.36, 0.02, 0.05}};
    double worst = 0, worst_n = 0;
    int hits = 0;
    for (int i = 0; i < 6; i++) {
        mb_ellipsoid e = sphere(q[i][0], q[i][1], q[i][2], rho);
        double s = hypot(q[i][0], q[i][2]), y = q[i][1];
        double D = hypot(s - R, y), depth = r + rho - D;
        mb_contact c;
        int in = mb_geom_wheel_ellipsoid(&w, &e, NULL, &c);
        CHECK(in == (depth > 0));
        if (!(depth > 0)) continue;
        hits++;
        worst = fmax(worst, fabs(c.depth - depth));
        /* normal from the sphere (b) into the wheel (a): from q toward the crown point */
        double crown[3] = {R * q[i][0] / s, 0, R * q[i][2] / s}, n[3];
        mb_sub(crown, q[i], n);
        mb_normalize(n);
        worst_n = fmax(worst_n, 1 - mb_dot(n, c.normal));
        /* the contact points lie on both surfaces */
        double da[3], pb[3];
        mb_sub(c.point_a, crown, da);
        mb_sub(c.point_b, e.center, pb);
        CHECK_NEAR(mb_norm(da), r, 1e-8);
        CHECK_NEAR(mb_norm(pb), rho, 1e-8);
    }
    printf("  sphere against the crown: %d contacts, depth error %.1e m, normal error %.1e\n",
           hits, worst, worst_n);
    CHECK(hits >= 4);
    CHECK(worst < 5e-9);
    CHECK(worst_n < 4e-8);
    FIG("contact_geometry.wheel_ell_depth_err", "%.1e", worst);
    FIG("contact_geometry.wheel_ell_normal_err", "%.1e", worst_n);
}

/* on the axis (face-on), the filled wheel's face is at r from the disc: depth r + rho - |y|,
 * over-estimated by at most the disc's half-thickness MB_WHEEL_EPS R; apart beyond */
static void test_sphere_on_the_face(void)
{
    const double R = 0.24, r = 0.06, rho = 0.1;
    mb_wheel w = {.center = {1, 2, 3}, .axis = {0, 0, 1}, .radius = R, .tube = r};
    mb_contact c;
    mb_ellipsoid e = sphere(1.05, 2.02, 3 + 0.15, rho);
    CHECK(mb_geom_wheel_ellipsoid(&w, &e, NULL, &c) == 1);
    double exact = r + rho - 0.15;
    printf("  sphere on the face: depth %.9f m (exact %.9f, bound +%.1e)\n", c.depth, exact,
           MB_WHEEL_EPS * R);
    CHECK(c.depth >= exact - 1e-12 && c.depth <= exact + MB_WHEEL_EPS * R);
    CHECK_NEAR(c.normal[2], -1, 1e-9);
    e = sphere(1.05, 2.02, 3 + r + rho + 2 * MB_WHEEL_EPS * R, rho);
    CHECK(mb_geom_wheel_ellipsoid(&w, &e, NULL, &c) == 0);
    e = sphere(1 + R + r + rho + 1e-6, 2, 3, rho);
    CHECK(mb_geom_wheel_ellipsoid(&w, &e, NULL, &c) == 0);
}

/* the engine: a wheel (cylinder surface) on a fixed axle, a ball falling onto its crown: the
 * cylinder-ellipsoid pair is built and carries the ball (its weight m g at rest) */
static void test_engine_pair(void)
{
    const char *y =
        "mcrash: 1\n"
        "simulation: {end_time: 0.5 s, time_step: 10 us}\n"
        "environment: {gravity: 9.81}\n"
        "characteristics: {pad: {loading: [[0, 0], [0.01, 1000]], damping: 200}}\n"
        "bodies:\n"
        "  - {name: wheel, mass: 10, inertia: [0.3, 0.5, 0.3], position: [0, 0, 0.3],\n"
        "     velocity: [0, 0, 0], surfaces: [{type: cylinder, center: [0, 0, 0], radius: 0.3,\n"
        "     length: 0.12, axis: [0, 1, 0]}]}\n"
        "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004], position: [0, 0, 0.702],\n"
        "     velocity: [0, 0, 0], surfaces: [{type: ellipsoid, center: [0, 0, 0],\n"
        "     semi_axes: [0.1, 0.1, 0.1]}]}\n"
        "joints: [{name: hub, type: fixed, parent: ground, child: wheel, anchor: [0, 0, 0.3]}]\n"
        "contacts: [{name: ball_wheel, a: ball, b: wheel, characteristic: pad}]\n";
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load_text("wheel.yaml", y, strlen(y), &scn, &err) == MCS_OK)
        mb_model_build(scn, NULL, &m, &err);
    mcs_scenario_destroy(&scn);
    CHECK(m != NULL);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK(m->npair == 1);
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    while (s->step < m->nsteps && mb_step(m, s, &err) == MCS_OK) {
    }
    CHECK(s->step == m->nsteps);
    /* at rest on the crown top (z = 0.3 + 0.3 = 0.6): 1000 N / 0.01 m, depth m g / k */
    double depth = 9.81 / 1e5;
    printf("  ball on a wheel: normal force %.4f N (m g 9.81), ball z %.6f m (exact %.6f)\n",
           s->pair[0].fn, s->kin[1].pos[2], 0.7 - depth);
    CHECK_NEAR(s->pair[0].fn, 9.81, 1e-4);
    CHECK_NEAR(s->kin[1].pos[2], 0.7 - depth, 1e-6);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_sphere_against_crown);
    RUN(test_sphere_on_the_face);
    RUN(test_engine_pair);
    TEST_END();
}

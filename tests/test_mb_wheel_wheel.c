/* test_mb_wheel_wheel.c: wheel-wheel (cylinder-cylinder) penetration (stage1_mb/mb_geom_wheel2.h)
 * against closed forms, and two wheels colliding in a scenario.
 *
 * A wheel (scenario `type: cylinder`, radius R0, length L) is the filled tyre: the flat disc of
 * crown radius R = R0 - L/2 grown by the tube t = L/2. Two of them penetrate by
 * t_a + t_b - distance(disc a, disc b) (swept spheres: the capsule construction with discs),
 * with the discs taken as flat ellipsoids of thickness MB_WHEEL_EPS R along their axes: exact
 * for normals in a disc's plane, at most MB_WHEEL_EPS R too deep along an axis (documented). */
#include "harness.h"
#include "figures.h"
#include "stage1_mb/mb_geom_wheel2.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <string.h>

static const double RA = 0.25, TA = 0.06, RB = 0.30, TB = 0.05;

static mb_wheel wheel(double R, double t, double cx, double cy, double cz, double ax, double ay,
                      double az)
{
    return (mb_wheel){.center = {cx, cy, cz}, .axis = {ax, ay, az}, .radius = R, .tube = t};
}

/* tol: depth tolerance; ntol: normal tolerance (the flat disc's curvature tilts its normal by
 * O(MB_WHEEL_EPS) when the contact lies on a face) */
static double check_contact(const char *what, const mb_wheel *a, const mb_wheel *b, double depth,
                            const double n[3], double tol, double ntol)
{
    mb_contact c;
    int hit = mb_geom_wheel_wheel(a, b, NULL, &c);
    CHECK(hit == 1);
    double dn[3];
    mb_sub(c.normal, n, dn);
    /* the points lie on the two surfaces, depth apart along the normal */
    double gap[3];
    mb_sub(c.point_b, c.point_a, gap);
    printf("  %s: depth %.9f m (closed form %.9f), normal error %.1e, |point_b - point_a| - depth "
           "%.1e\n",
           what, c.depth, depth, mb_norm(dn), mb_norm(gap) - c.depth);
    CHECK_NEAR(c.depth, depth, tol);
    CHECK(c.depth >= depth - 1e-9); /* never shallower than the exact solid's */
    CHECK(mb_norm(dn) < ntol);
    CHECK_NEAR(mb_norm(gap), c.depth, 1e-12);
    /* swapped: the same depth, the opposite normal */
    mb_contact s;
    CHECK(mb_geom_wheel_wheel(b, a, NULL, &s) == 1);
    CHECK_NEAR(s.depth, c.depth, 1e-7);
    double sum[3];
    mb_add(s.normal, c.normal, sum);
    CHECK(mb_norm(sum) < 1e-6);
    return c.depth - depth;
}

/* coplanar, rim to rim: depth = (R_a + t_a) + (R_b + t_b) - D, exact (in-plane normal) */
static void test_coplanar_rims(void)
{
    double D = RA + TA + RB + TB - 0.01;
    mb_wheel a = wheel(RA, TA, 0, 0, 0, 0, 0, 1), b = wheel(RB, TB, D, 0, 0, 0, 0, 1);
    double n[3] = {-1, 0, 0};
    check_contact("coplanar rims", &a, &b, 0.01, n, 1e-9, 1e-9);
    /* the same along a diagonal of the plane */
    double c45 = sqrt(0.5);
    b = wheel(RB, TB, D * c45, D * c45, 0, 0, 0, 1);
    double n2[3] = {-c45, -c45, 0};
    check_contact("coplanar rims, 45 deg", &a, &b, 0.01, n2, 1e-9, 1e-9);
    /* apart by 1 mm: no contact */
    b = wheel(RB, TB, D + 0.011, 0, 0, 0, 0, 1);
    mb_contact c;
    CHECK(mb_geom_wheel_wheel(&a, &b, NULL, &c) == 0);
    CHECK(c.depth == 0);
}

/* parallel discs side by side on one axis, s apart: depth = t_a + t_b - s, plus the flat
 * ellipsoids' thickness along the axis, MB_WHEEL_EPS (R_a + R_b) at most */
static void test_side_by_side(void)
{
    double s = TA + TB - 0.004;
    mb_wheel a = wheel(RA, TA, 0, 0, 0, 0, 0, 1), b = wheel(RB, TB, 0.02, -0.01, s, 0, 0, 1);
    double n[3] = {0, 0, -1};
    double ex = check_contact("side by side", &a, &b, 0.004, n, MB_WHEEL_EPS * (RA + RB) + 1e-9,
                              MB_WHEEL_EPS);
    FIG("contact_geometry.ww_side_excess", "%.1e", ex);
}

/* crossed discs: b's disc in the plane x = xb (axis x), facing a's rim point (R_a, 0, 0):
 * depth = t_a + t_b - (xb - R_a) (+ b's thickness); and b standing on a's face, its lowest
 * rim point h - R_b above it: depth = t_a + t_b - (h - R_b) (+ a's thickness) */
static void test_crossed(void)
{
    double xb = RA + TA + TB - 0.006;
    mb_wheel a = wheel(RA, TA, 0, 0, 0, 0, 0, 1), b = wheel(RB, TB, xb, 0, 0.05, 1, 0, 0);
    double n[3] = {-1, 0, 0};
    double ex = check_contact("crossed, rim on face", &a, &b, 0.006, n,
                              MB_WHEEL_EPS * RB + 1e-9, MB_WHEEL_EPS);
    FIG("contact_geometry.ww_crossed_excess", "%.1e", ex);
    double h = RB + TA + TB - 0.003;
    b = wheel(RB, TB, 0.05, 0, h, 1, 0, 0);
    double n2[3] = {0, 0, -1};
    ex = check_contact("crossed, rim on the other's face", &a, &b, 0.003, n2,
                       MB_WHEEL_EPS * RA + 1e-9, MB_WHEEL_EPS);
    FIG("contact_geometry.ww_crossed2_excess", "%.1e", ex);
}

/* two equal free wheels (10 kg) meeting rim to rim, coplanar, at +-1 m/s, linear elastic
 * contact k = 1e5 N/m, no gravity: a centric elastic impact of equal masses exchanges the
 * velocities (momentum exact: internal forces; energy to O(w h), w h = 1.4e-3) */
static void test_wheels_collide(void)
{
    const char *y =
        "mcrash: 1\n"
        "simulation: {end_time: 0.1 s, time_step: 10 us}\n"
        "environment: {gravity: 0}\n"
        "characteristics: {tyre: {loading: [[0, 0], [0.01, 1000]]}}\n"
        "bodies:\n"
        "  - {name: a, mass: 10, inertia: [0.5, 0.5, 0.8], position: [0, 0, 1],\n"
        "     velocity: [1, 0, 0], surfaces: [{type: cylinder, center: [0, 0, 0], radius: 0.3,\n"
        "     length: 0.1, axis: [0, 0, 1]}]}\n"
        "  - {name: b, mass: 10, inertia: [0.5, 0.5, 0.8], position: [0.62, 0, 1],\n"
        "     velocity: [-1, 0, 0], surfaces: [{type: cylinder, center: [0, 0, 0], radius: 0.3,\n"
        "     length: 0.1, axis: [0, 0, 1]}]}\n"
        "contacts: [{a: a, b: b, characteristic: tyre}]\n";
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mb_model *m = NULL;
    if (mcs_scenario_load_text("wheels.yaml", y, strlen(y), &scn, &err) == MCS_OK)
        mb_model_build(scn, NULL, &m, &err);
    mcs_scenario_destroy(&scn);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL);
    if (!m) return;
    CHECK(m->npair == 1);
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    double fpk = 0;
    while (s && s->step < m->nsteps && mb_step(m, s, &err) == MCS_OK)
        fpk = fmax(fpk, s->pair[0].fn);
    CHECK(s && s->step == m->nsteps);
    if (s) {
        double va = s->kin[0].vel[0], vb = s->kin[1].vel[0];
        /* peak force: m_red v_rel^2 / 2 = k x^2 / 2 -> F = v_rel sqrt(k m_red) = 2 sqrt(5e5) */
        double fe = 2 * sqrt(1e5 * 5);
        printf("  two wheels: after the impact va %.6f, vb %.6f m/s (exchange: -1, +1), momentum "
               "%.1e, peak force %.1f N (closed form %.1f N), energy drift %.1e\n",
               va, vb, 10 * va + 10 * vb, fpk, fe, mb_energy_drift(m, s));
        /* the docs show 6 digits of the speeds and 5 of the force: 3x their last unit */
        CHECK_NEAR(va, -1, 1.5e-6);
        CHECK_NEAR(vb, 1, 1.5e-6);
        CHECK(fabs(10 * va + 10 * vb) < 1e-9);
        CHECK_REL(fpk, fe, 1e-4);
        FIG("contact_geometry.ww_va", "%.6f", va);
        FIG("contact_geometry.ww_vb", "%.6f", vb);
        FIG("contact_geometry.ww_peak_force", "%.1f", fpk);
        CHECK(fabs(s->kin[0].vel[1]) < 1e-12 && fabs(s->kin[0].angvel[2]) < 1e-12);
    }
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_coplanar_rims);
    RUN(test_side_by_side);
    RUN(test_crossed);
    RUN(test_wheels_collide);
    TEST_END();
}

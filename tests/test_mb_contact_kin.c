/* tests for stage1_mb/mb_contact_kin and the energy helpers of mb_ode: contact point rates,
 * an elastic bounce that returns to its height, and a rotated-ellipsoid impact that keeps
 * linear and angular momentum (the contact law here is a plain linear spring for the test). */
#include "stage1_mb/mb_contact_kin.h"
#include "stage1_mb/mb_vec.h"
#include "tests/harness.h"
#include "tests/figures.h"

static const double G[3] = {0, 0, -9.81}, ZERO[3] = {0, 0, 0};

static mb_ellipsoid body_ellipsoid(const mb_world *w, int b, const double semi[3])
{
    mb_body_kin k;
    mb_body_get(w, b, &k);
    mb_ellipsoid e;
    mb_copy(k.pos, e.center);
    for (int i = 0; i < 9; i++)
        e.rot[i] = k.rot[i];
    mb_copy(semi, e.semi);
    return e;
}

/* closing rate and slip of a spinning sphere over the ground: rel = v + w x (p - c) */
static void test_contact_rates(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 1, 0, G, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d = {.name = "ball",
                      .mass = 1,
                      .inertia = {0.004, 0.004, 0.004},
                      .quat = {1},
                      .pos = {0, 0, 0.09},
                      .vel = {1, 0, -2},
                      .angvel = {0, 3, 0}};
    int b = mb_world_add_body(w, &d, &err);
    double semi[3] = {0.1, 0.1, 0.1};
    mb_ellipsoid e = body_ellipsoid(w, b, semi);
    mb_plane g = {{0, 0, 0}, {0, 0, 1}};
    mb_contact c;
    CHECK(mb_geom_ellipsoid_plane(&e, &g, &c) == 1);
    mb_contact_vel v;
    mb_contact_velocity(w, b, -1, &c, &v);
    double rho = 0.09 - c.point[2]; /* centre height above the contact point */
    CHECK_NEAR(v.depth_rate, 2, 1e-12);
    CHECK_NEAR(v.slip[0], 1 - 3 * rho, 1e-12);
    CHECK_NEAR(v.slip[1], 0, 1e-12);
    CHECK_NEAR(v.slip[2], 0, 1e-12);
    CHECK_NEAR(mb_body_mass(w, b), 1, 0);
    mb_world_destroy(&w);
}

/* free fall: after n steps E = E0 - m g^2 h t / 2 exactly (the step's x update uses v_{n+1}) */
static void test_energy_helpers(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 1, 0, G, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d = {.name = "box",
                      .mass = 3,
                      .inertia = {0.1, 0.2, 0.25, 0.01, 0, 0.02},
                      .quat = {1},
                      .pos = {0, 0, 2},
                      .angvel = {1, 2, -1}};
    int b = mb_world_add_body(w, &d, &err);
    (void)b;
    /* rotational energy w.I w / 2 with the full tensor */
    const double *I = d.inertia, *om = d.angvel;
    double Iw[3] = {I[0] * om[0] + I[3] * om[1] + I[4] * om[2],
                    I[3] * om[0] + I[1] * om[1] + I[5] * om[2],
                    I[4] * om[0] + I[5] * om[1] + I[2] * om[2]};
    double erot = 0.5 * mb_dot(om, Iw);
    CHECK_NEAR(mb_world_kinetic_energy(w), erot, 1e-12);
    CHECK_NEAR(mb_world_potential_energy(w), 3 * 9.81 * 2, 1e-12);
    double h = 1e-3, e0 = erot + 3 * 9.81 * 2;
    for (int i = 0; i < 500; i++)
        CHECK(mb_world_step(w, h, &err) == MCS_OK);
    double t = mb_world_time(w), et = mb_world_kinetic_energy(w) + mb_world_potential_energy(w);
    /* rotational energy of a free body is kept by ODE's step to O(h); translation exact */
    CHECK_NEAR(et, e0 - 0.5 * 3 * 9.81 * 9.81 * h * t, 2e-3 * erot);
    mb_world_destroy(&w);
}

/* a ball dropped from 0.5 m onto a linear contact spring bounces back to 0.5 m; kinetic +
 * potential + contact energy stays constant through the impact (symplectic step, O(h)) */
static void test_elastic_bounce(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 1, 0, G, &err) == MCS_OK);
    if (!w) return;
    double r = 0.1, k = 1e5, h = 1e-5, z0 = 0.5;
    mb_body_desc d = {.name = "ball",
                      .mass = 1,
                      .inertia = {0.004, 0.004, 0.004},
                      .quat = {1},
                      .pos = {0, 0, z0}};
    int b = mb_world_add_body(w, &d, &err);
    double semi[3] = {r, r, r};
    mb_plane g = {{0, 0, 0}, {0, 0, 1}};
    double e0 = mb_world_potential_energy(w), worst = 0, zmax_after = 0;
    int bounced = 0;
    for (int i = 0; i < 130000; i++) { /* 1.3 s: fall 0.28 s, fly up and back */
        mb_ellipsoid e = body_ellipsoid(w, b, semi);
        mb_contact c;
        double stored = 0;
        if (mb_geom_ellipsoid_plane(&e, &g, &c)) {
            mb_contact_apply(w, b, -1, &c, k * c.depth, NULL);
            stored = 0.5 * k * c.depth * c.depth;
            bounced = 1;
        }
        double et = mb_world_kinetic_energy(w) + mb_world_potential_energy(w) + stored;
        worst = fmax(worst, fabs(et - e0));
        CHECK(mb_world_step(w, h, &err) == MCS_OK);
        mb_body_kin kin;
        mb_body_get(w, b, &kin);
        if (bounced && kin.vel[2] > 0) zmax_after = fmax(zmax_after, kin.pos[2]);
    }
    printf("  bounce: back to %.6f m (dropped from %.6f m), energy error %.2e J of %.3f J\n",
           zmax_after, z0, worst, e0);
    CHECK_NEAR(zmax_after, z0, 1e-6); /* 3x what docs/contact_geometry.md states */
    FIG("contact_geometry.ball_rebound_err", "%.0e", fabs(zmax_after - z0));
    /* symplectic Euler's energy oscillates by ~ (wc h / 2) E in contact, wc = sqrt(k/m) */
    CHECK(worst < sqrt(k / 1.0) * h * e0);
    mb_world_destroy(&w);
}

/* two rotated ellipsoids collide off-centre: the equal and opposite force at one point keeps
 * the total linear momentum exactly and the angular momentum (ODE step drift only); energy
 * kinetic + spring stays constant */
static void test_ellipsoid_impact_momentum(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 2, 0, ZERO, &err) == MCS_OK);
    if (!w) return;
    double sa[3] = {0.12, 0.08, 0.1}, sb[3] = {0.15, 0.1, 0.07};
    double ax[3] = {0.3, 0.8, 0.5};
    mb_normalize(ax);
    double ca = cos(0.4), sn = sin(0.4);
    mb_body_desc a = {.name = "head",
                      .mass = 4.5,
                      .inertia = {0.02, 0.025, 0.018},
                      .quat = {ca, sn * ax[0], sn * ax[1], sn * ax[2]},
                      .pos = {0, 0.03, 0},
                      .vel = {3, 0, 0}};
    mb_body_desc bb = {.name = "tank",
                       .mass = 15,
                       .inertia = {0.1, 0.2, 0.15},
                       .quat = {1},
                       .pos = {0.4, 0, 0.02}};
    int ia = mb_world_add_body(w, &a, &err), ib = mb_world_add_body(w, &bb, &err);
    double k = 2e5, h = 1e-5, warm[3] = {0, 0, 0};
    double e0 = mb_world_kinetic_energy(w), worst = 0, p0 = 4.5 * 3;
    int hits = 0;
    for (int i = 0; i < 20000; i++) {
        mb_ellipsoid ea = body_ellipsoid(w, ia, sa), eb = body_ellipsoid(w, ib, sb);
        mb_contact c;
        double stored = 0;
        if (mb_geom_ellipsoid_ellipsoid(&ea, &eb, hits ? warm : NULL, &c)) {
            mb_contact_apply(w, ia, ib, &c, k * c.depth, NULL);
            stored = 0.5 * k * c.depth * c.depth;
            mb_copy(c.normal, warm);
            hits++;
        }
        worst = fmax(worst, fabs(mb_world_kinetic_energy(w) + stored - e0));
        CHECK(mb_world_step(w, h, &err) == MCS_OK);
    }
    mb_body_kin ka, kb;
    mb_body_get(w, ia, &ka);
    mb_body_get(w, ib, &kb);
    printf("  ellipsoid impact: %d contact steps, energy error %.2e of %.3f J, spin %.3f rad/s\n",
           hits, worst / e0, e0, mb_norm(kb.angvel));
    CHECK(hits > 10);
    CHECK(mb_norm(kb.angvel) > 0.1); /* off-centre: the tank was set spinning */
    for (int q = 0; q < 3; q++)
        CHECK_NEAR(4.5 * ka.vel[q] + 15 * kb.vel[q], q == 0 ? p0 : 0, 1e-9 * p0);
    CHECK(worst < 1e-3 * e0);
    FIG("contact_geometry.ell_impact_energy_err", "%.0e", worst / e0);
    mb_world_destroy(&w);
}

int main(void)
{
    RUN(test_contact_rates);
    RUN(test_energy_helpers);
    RUN(test_elastic_bounce);
    RUN(test_ellipsoid_impact_momentum);
    TEST_END();
}

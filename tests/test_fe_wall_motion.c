/* test_fe_wall_motion: rigid walls moved by curves (fe/step/fe_wall_motion.c; scenario
 * `rigid_walls: [{motion}]`, LS-DYNA *BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL) against closed
 * forms, and the keyword read, built, written and read back. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tests/harness.h"
#include "tests/figures.h"
#include "fe/fe_keyword.h"
#include "fe/fe_solid.h"
#include "tests/fe_test_util.h"

/* the exact integrals of a piecewise-linear curve: velocity v = 100 t up to 10 ms, then 1 m/s:
 * D = 50 t^2, then 0.005 + (t - 0.01); acceleration a = 20 m/s^2 from rest: D = 10 t^2 */
static void test_motion_integrals(void)
{
    fe_wall_motion v = {.kind = FE_MOTION_VELOCITY, .ncurve = 2,
                        .curve = {{0, 0}, {0.01, 1}}};
    fe_wall_motion a = {.kind = FE_MOTION_ACCELERATION, .ncurve = 1, .curve = {{0, 20}}};
    fe_wall_motion d = {.kind = FE_MOTION_DISPLACEMENT, .ncurve = 3,
                        .curve = {{0, 0}, {0.01, 0.005}, {0.02, 0.002}}};
    const double t[4] = {0.003, 0.01, 0.017, 0.05};
    for (int i = 0; i < 4; i++) {
        double Dv = t[i] <= 0.01 ? 50 * t[i] * t[i] : 0.005 + (t[i] - 0.01);
        double Dd = t[i] <= 0.01 ? 0.5 * t[i] : t[i] <= 0.02 ? 0.005 - 0.3 * (t[i] - 0.01) : 0.002;
        CHECK_NEAR(fe_wall_motion_disp(&v, t[i]), Dv, 1e-17);
        CHECK_NEAR(fe_wall_motion_disp(&a, t[i]), 10 * t[i] * t[i], 1e-17);
        CHECK_NEAR(fe_wall_motion_disp(&d, t[i]), Dd, 1e-17);
    }
    /* a curve starting after 0 is held at its first value before it */
    fe_wall_motion late = {.kind = FE_MOTION_VELOCITY, .ncurve = 2,
                           .curve = {{0.01, 2}, {0.02, 0}}};
    CHECK_NEAR(fe_wall_motion_disp(&late, 0.03), 0.02 + 0.01, 1e-17);
}

/* a point mass (gravity g down) resting on a floor that a displacement curve lifts at 0.5 m/s
 * for 10 ms and then holds: the kinematic wall keeps the node on the plane while it rises
 * (node z = d(t), to round-off); at the stop the node flies on, ballistic:
 *     z(t) = 0.005 + 0.5 (t - 0.01) - g (t - 0.01)^2 / 2. */
static void test_floor_lifts_mass(void)
{
    const double g = 9.81, dt = 1e-5;
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d = ft_part("dummy", FE_SECTION_SOLID, 1e6, 0.3, 1000);
    d.mesh.generate = FE_MESH_BOX;
    d.mesh.size[0] = d.mesh.size[1] = d.mesh.size[2] = 0.01;
    d.mesh.divisions[0] = d.mesh.divisions[1] = d.mesh.divisions[2] = 1;
    d.mesh.origin[2] = -10;
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    fe_boundary_desc bc = ft_bc("dummy", FE_WHERE_ALL, FE_DOF_ALL);
    CHECK(fe_builder_add_boundary(b, &bc, &err) == MCS_OK);
    int node;
    double p[3] = {1, 0, 0};
    CHECK(fe_builder_add_node(b, p, &node, &err) == MCS_OK);
    fe_mass_desc md = {.node = node, .mass = 2};
    CHECK(fe_builder_add_mass(b, &md, &err) == MCS_OK);
    fe_wall_desc w = {.normal = {0, 0, 1}, .nmotion = 1};
    snprintf(w.name, sizeof w.name, "lift");
    w.motion[0] = (fe_wall_motion){.kind = FE_MOTION_DISPLACEMENT, .direction = {0, 0, 2},
                                   .ncurve = 3, .curve = {{0, 0}, {0.01, 0.005}, {1, 0.005}}};
    CHECK(fe_builder_add_wall(b, &w, &err) == MCS_OK);
    fe_wall_desc bad = w;
    snprintf(bad.name, sizeof bad.name, "bad");
    bad.mass = 1;
    mcs_error e2 = {0};
    CHECK(fe_builder_add_wall(b, &bad, &e2) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e2.msg, "cannot also follow a motion curve");
    fe_opts o = fe_opts_default();
    o.dt_max = dt;
    o.gravity[2] = -g;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double follow = 0;
    while (s->time < 0.01 - 0.5 * dt && fe_step(m, s) == MCS_OK)
        follow = fmax(follow, fabs(s->node_x[3 * node + 2] - s->wall_x[2]));
    const double zw = s->wall_x[2], vw = s->wall_v[2];
    while (s->time < 0.03 - 0.5 * dt && fe_step(m, s) == MCS_OK) {}
    CHECK(s->err.status == MCS_OK);
    const double tb = s->time - 0.01, zb = 0.005 + 0.5 * tb - 0.5 * g * tb * tb;
    printf("  floor lifted by a displacement curve: node on the floor to %.2e m while it rises "
           "(floor %.6g m, %.6g m/s at 10 ms); 20 ms after the stop node z %.9f m (ballistic "
           "%.9f, %+.2e m)\n",
           follow, zw, vw, s->node_x[3 * node + 2], zb, s->node_x[3 * node + 2] - zb);
    FIG("fe.motion_follow_m", "%.0e", follow);
    FIG("fe.motion_ballistic_m", "%+.0e", s->node_x[3 * node + 2] - zb);
    CHECK(follow < 1e-18); /* 2e-19 m stated */
    CHECK_NEAR(zw, 0.005, 1e-15);
    CHECK_NEAR(vw, 0.5, 1e-9);
    CHECK_NEAR(s->node_x[3 * node + 2], zb, 2e-6); /* central difference: O(g dt t), -1e-6 */
    CHECK(s->wall_x[2] == 0.005);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a velocity curve v = 100 t (from rest) pushes a point mass up: the node stays on the wall,
 * z = 50 t^2 at every step to round-off */
static void test_velocity_curve_pushes(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d = ft_part("dummy", FE_SECTION_SOLID, 1e6, 0.3, 1000);
    d.mesh.generate = FE_MESH_BOX;
    d.mesh.size[0] = d.mesh.size[1] = d.mesh.size[2] = 0.01;
    d.mesh.divisions[0] = d.mesh.divisions[1] = d.mesh.divisions[2] = 1;
    d.mesh.origin[2] = -10;
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    int node;
    double p[3] = {1, 0, 1e-9};
    CHECK(fe_builder_add_node(b, p, &node, &err) == MCS_OK);
    fe_mass_desc md = {.node = node, .mass = 0.5};
    CHECK(fe_builder_add_mass(b, &md, &err) == MCS_OK);
    fe_wall_desc w = {.normal = {0, 0, 1}, .method = FE_WALL_KINEMATIC, .nmotion = 1};
    snprintf(w.name, sizeof w.name, "push");
    w.motion[0] = (fe_wall_motion){.kind = FE_MOTION_VELOCITY, .direction = {0, 0, 1},
                                   .ncurve = 2, .curve = {{0, 0}, {1, 100}}};
    CHECK(fe_builder_add_wall(b, &w, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-5;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double e = 0;
    while (s->time < 0.01 && fe_step(m, s) == MCS_OK) {
        const double t = s->time, z = 50 * t * t;
        CHECK_NEAR(s->wall_x[2], z, 1e-16);
        if (z > 1e-8) e = fmax(e, fabs(s->node_x[3 * node + 2] - z));
    }
    printf("  velocity curve 100 t: wall and node at 50 t^2 to %.2e m over 10 ms; the work the "
           "wall did %.6g J (1/2 m v^2 %.6g J)\n",
           e, s->energy[FE_E_external_work], 0.5 * 0.5 * 1.0 * 1.0);
    FIG("fe.motion_curve_m", "%.0e", e);
    CHECK(e < 2e-19); /* 5e-20 m stated */
    CHECK_NEAR(s->energy[FE_E_total], s->energy0, 1e-9);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* *BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL: read (mm-ms-kg), built onto the wall it names, written
 * and read back */
static void test_keyword_motion(void)
{
    static const char deck[] =
        "*KEYWORD\n"
        "*PART\nblock\n1,1,1\n"
        "*SECTION_SOLID\n1,1\n"
        "*MAT_ELASTIC\n1,1.0e-6,1.0e3,0.3\n"
        "*NODE\n1,0,0,1\n2,10,0,1\n3,10,10,1\n4,0,10,1\n5,0,0,11\n6,10,0,11\n7,10,10,11\n"
        "8,0,10,11\n"
        "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n"
        "*RIGIDWALL_PLANAR_ID\n"
        "         5floor\n"
        "0\n0.0,0.0,0.0,0.0,0.0,1.0\n"
        "*DEFINE_CURVE\n7\n0.0,0.0\n10.0,5.0\n"
        "*BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL\n"
        "$#      ID       DOF       VAD      LCID        SF\n"
        "         5         3         2         7       2.0\n"
        "*END\n";
    fe_kw_opts o = fe_kw_opts_default();
    o.units = "mm-ms-kg";
    o.strict = 1; /* the keyword is known */
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    CHECK(fe_kw_read_mem("motion.k", deck, sizeof deck - 1, &o, &d, &err) == MCS_OK);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK(d->nwmotion == 1 && d->nunknown == 0);
    CHECK(d->wmotion[0].wall == 5 && d->wmotion[0].dof == 3 && d->wmotion[0].vad == 2 &&
          d->wmotion[0].lcid == 7 && d->wmotion[0].sf == 2);
    /* built: the floor moves 10 mm along z over 10 ms */
    fe_builder *b = NULL;
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    CHECK(fe_kw_add_deck(b, d, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (m) {
        const fe_wall *W = &m->wall[0];
        CHECK(strcmp(W->name, "floor") == 0 && W->nmotion == 1);
        CHECK(W->motion[0].kind == FE_MOTION_DISPLACEMENT && W->motion[0].direction[2] == 1);
        CHECK_NEAR(fe_wall_motion_disp(&W->motion[0], 0.005), 0.005, 1e-17);
        CHECK_NEAR(fe_wall_motion_disp(&W->motion[0], 0.02), 0.010, 1e-17);
        fe_model_destroy(&m);
    }
    /* written and read back: the same motion on the same wall ID */
    char path[] = "/tmp/mcrash_wmotion_XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    if (fd >= 0) close(fd);
    CHECK(fe_kw_write(d, path, FE_KW_FIXED, &err) == MCS_OK);
    fe_kw_deck *e = NULL;
    CHECK(fe_kw_read(path, &o, &e, &err) == MCS_OK);
    if (e) {
        CHECK(e->nwall == 1 && e->wall[0].id == 5 && strcmp(e->wall[0].title, "floor") == 0);
        CHECK(e->nwmotion == 1 && memcmp(&e->wmotion[0].wall, &d->wmotion[0].wall,
                                          4 * sizeof(int)) == 0 &&
              e->wmotion[0].sf == d->wmotion[0].sf);
        fe_kw_deck_destroy(&e);
    }
    remove(path);
    /* errors at the card: an unknown wall, an unbuilt DOF */
    static const char bad[] = "*KEYWORD\n*BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL\n1,4,0,7\n*END\n";
    fe_kw_deck *f = NULL;
    mcs_error e3 = {0};
    CHECK(fe_kw_read_mem("bad.k", bad, sizeof bad - 1, &o, &f, &e3) == MCS_ERR_UNSUPPORTED);
    CHECK_STR_CONTAINS(e3.msg, "bad.k:3");
    CHECK_STR_CONTAINS(e3.msg, "DOF");
    fe_kw_deck_destroy(&f);
    fe_kw_deck_destroy(&d);
}

int main(void)
{
    RUN(test_motion_integrals);
    RUN(test_floor_lifts_mass);
    RUN(test_velocity_curve_pushes);
    RUN(test_keyword_motion);
    TEST_END();
}

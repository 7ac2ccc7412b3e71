/* test_fe_wall_fric: Coulomb friction on planar rigid walls (fe/step/fe_wall_fric.c; LS-DYNA
 * *RIGIDWALL_PLANAR FRIC) against the sliding block's closed form. */
#include <math.h>
#include <string.h>

#include "tests/harness.h"
#include "tests/figures.h"
#include "fe/fe_keyword.h"
#include "fe/fe_solid.h"
#include "tests/fe_test_util.h"

/* a point mass m on a floor (normal +z, gravity g down), sliding at v0 along x */
static fe_model *build_slider(fe_wall_method method, double mu, double dt, int *node)
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
    fe_boundary_desc bc = ft_bc("dummy", FE_WHERE_ALL, FE_DOF_ALL);
    CHECK(fe_builder_add_boundary(b, &bc, &err) == MCS_OK);
    double p[3] = {0, 0, 0};
    CHECK(fe_builder_add_node(b, p, node, &err) == MCS_OK);
    fe_mass_desc md = {.node = *node, .mass = 2};
    CHECK(fe_builder_add_mass(b, &md, &err) == MCS_OK);
    fe_wall_desc w = {.normal = {0, 0, 1}, .method = method, .friction = mu,
                      .penalty_scale = 0.1};
    snprintf(w.name, sizeof w.name, "floor");
    CHECK(fe_builder_add_wall(b, &w, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = dt;
    o.gravity[2] = -9.81;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    fe_builder_destroy(&b);
    return m;
}

/* Coulomb sliding (any dynamics text, e.g. Meriam & Kraige, Dynamics, sec. 3/4): the friction
 * force mu m g decelerates the block at mu g,
 *     v(t) = v0 - mu g t,  x(t) = v0 t - mu g t^2 / 2,  stop at t_s = v0 / (mu g),
 *     x_s = v0^2 / (2 mu g),
 * and all of 1/2 m v0^2 is dissipated. The kinematic wall gives the normal impulse m g dt_h
 * each step, so the deceleration is mu g to round-off (the start takes half a step). */
static void run_slide(fe_wall_method method, double mu, double vtol, double xtol,
                      double etol)
{
    const double v0 = 1.5, g = 9.81, dt = 1e-5, ts = v0 / (mu * g), m0 = 2;
    int node;
    fe_model *m = build_slider(method, mu, dt, &node);
    if (!m) return;
    mcs_error err = {0};
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    if (!s) return;
    s->node_v[3 * node] = v0;
    double vh = 0, th = 0;
    while (s->time < 1.3 * ts && fe_step(m, s) == MCS_OK)
        if (th == 0 && s->time >= 0.5 * ts) th = s->time - 0.5 * dt, vh = s->node_v[3 * node];
    CHECK(s->err.status == MCS_OK);
    const double xs = v0 * v0 / (2 * mu * g), E0 = 0.5 * m0 * v0 * v0;
    const double diss = s->energy[FE_E_dissipated];
    printf("  %s floor, mu %g: v(%.4f s) %.9f m/s (v0 - mu g t %.9f), stopped at x %.9f m "
           "(v0^2/(2 mu g) %.9f), v %.2e, dissipated %.9f J (1/2 m v0^2 %.9f), total drift %.2e "
           "of E0\n",
           method == FE_WALL_KINEMATIC ? "kinematic" : "penalty", mu, th, vh, v0 - mu * g * th,
           s->node_x[3 * node], xs, s->node_v[3 * node], diss, E0,
           (s->energy[FE_E_total] - s->energy0) / E0);
    const int kin = method == FE_WALL_KINEMATIC;
    FIG(kin ? "fe.fric_kin_v_err" : "fe.fric_pen_v_err", "%.1e", fabs(vh - (v0 - mu * g * th)));
    FIG(kin ? "fe.fric_kin_x_err" : "fe.fric_pen_x_err", "%.0e", fabs(s->node_x[3 * node] - xs));
    FIG(kin ? "fe.fric_kin_diss_err" : "fe.fric_pen_diss_err", "%.0e", fabs(diss / E0 - 1));
    FIG(kin ? "fe.fric_kin_drift" : "fe.fric_pen_drift", "%.0e",
        fabs(s->energy[FE_E_total] - s->energy0) / E0);
    CHECK_NEAR(vh, v0 - mu * g * th, vtol);
    CHECK_NEAR(s->node_x[3 * node], xs, xtol);
    CHECK(fabs(s->node_v[3 * node]) < 1e-12);
    CHECK_REL(diss, E0, etol);
    CHECK_NEAR(s->energy[FE_E_total], s->energy0, 1e-13 * E0); /* 4e-16, 2e-14 stated */
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* tolerances ~3x the figures docs/fe.md states for each method */
static void test_kinematic_slide(void) { run_slide(FE_WALL_KINEMATIC, 0.3, 5e-12, 3e-10, 3e-5); }
/* the penalty floor: the node rides the penalty spring, its mean normal force m g; the
 * regularised stick holds the stopped block */
static void test_penalty_slide(void) { run_slide(FE_WALL_PENALTY, 0.3, 4e-5, 3e-10, 6e-14); }

/* FRIC = 1: no sliding once in contact. The block, thrown along the floor (1.5, -0.5 m/s)
 * from 1 mm above it, stops dead in the step it lands and stays: the friction dissipates all
 * of its tangential kinetic energy, 1/2 m (vx^2 + vy^2) */
static void test_stick(void)
{
    int node;
    fe_model *m = build_slider(FE_WALL_KINEMATIC, 1, 1e-5, &node);
    if (!m) return;
    mcs_error err = {0};
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    if (!s) return;
    s->node_x[3 * node + 2] = 1e-3;
    s->node_v[3 * node] = 1.5;
    s->node_v[3 * node + 1] = -0.5;
    double xl = NAN, yl = NAN, tl = 0;
    int moved = 0;
    while (s->time < 0.03 && fe_step(m, s) == MCS_OK) {
        const double *x = s->node_x + 3 * node, *v = s->node_v + 3 * node;
        if (isnan(xl) && v[0] == 0) xl = x[0], yl = x[1], tl = s->time;
        if (!isnan(xl)) moved += v[0] != 0 || v[1] != 0 || x[0] != xl || x[1] != yl;
    }
    const double Et = 0.5 * 2 * (1.5 * 1.5 + 0.5 * 0.5);
    printf("  FRIC = 1: landed and stuck at %.5f s (free fall %.5f s) at x %.6f m (%.6f); "
           "friction dissipated %.12f J (1/2 m vt^2 %.12f)\n",
           tl, sqrt(2e-3 / 9.81), xl, 1.5 * sqrt(2e-3 / 9.81), s->energy[FE_E_dissipated], Et);
    CHECK(!isnan(xl) && moved == 0);
    FIG("fe.fric_stick_t_err", "%.0e", fabs(tl - sqrt(2e-3 / 9.81)));
    CHECK_NEAR(tl, sqrt(2e-3 / 9.81), 6e-6); /* 2e-6 s stated, in steps of 1e-5 s */
    CHECK_REL(s->energy[FE_E_dissipated], Et, 1e-12);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* *RIGIDWALL_PLANAR FRIC is read and built; welding (2, 3) is refused */
static void test_keyword_fric(void)
{
    static const char deck[] =
        "*KEYWORD\n"
        "*PART\nblock\n1,1,1\n"
        "*SECTION_SOLID\n1,1\n"
        "*MAT_ELASTIC\n1,1000.0,1.0e6,0.3\n"
        "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
        "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n"
        "*RIGIDWALL_PLANAR\n0\n0.0,0.0,0.0,0.0,0.0,1.0,0.25\n"
        "*END\n";
    fe_kw_opts o = fe_kw_opts_default();
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    CHECK(fe_kw_read_mem("fric.k", deck, sizeof deck - 1, &o, &d, &err) == MCS_OK);
    if (!d) return;
    fe_builder *b = NULL;
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    CHECK(fe_kw_add_deck(b, d, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (m) CHECK(m->wall[0].friction == 0.25);
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    d->wall[0].fric = 2;
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    mcs_error e2 = {0};
    CHECK(fe_kw_add_deck(b, d, &e2) == MCS_ERR_UNSUPPORTED);
    CHECK_STR_CONTAINS(e2.msg, "welding");
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
}

int main(void)
{
    RUN(test_kinematic_slide);
    RUN(test_penalty_slide);
    RUN(test_stick);
    RUN(test_keyword_fric);
    TEST_END();
}

/* test_fe_ellipsoid_shell: shell nodes meet a rigid ellipsoid at half the shell thickness
 * (fe/contact/fe_contact.c, the ellipsoid part), as they meet contact segments. */
#include <math.h>

#include "fe/fe_contact.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/fe_test_util.h"
#include "tests/fe_test_build.h"

/* a 20 mm steel plate, 2 mm thick, dropped from 0.2 mm onto a fixed rigid sphere of radius
 * 50 mm under 1000 m/s^2 with mass damping: it comes to rest with its mid-surface at t/2 above
 * the sphere's top (the shell's surface touches the sphere), less the penalty spring's
 * deflection: the whole weight W rests on the centre node, k = s m_c / dt0^2, so
 * gap = t/2 - W / k (1.6e-4 of t/2 here). */
static void test_plate_on_sphere(void)
{
    const double R = 0.05, t = 0.002, L = 0.02;
    fe_part_desc d = ft_part("plate", FE_SECTION_SHELL, 210e9, 0.3, 7850);
    d.section.thickness = t;
    d.section.integration_points = 3;
    d.mesh.generate = FE_MESH_PLATE;
    d.mesh.axis = 2;
    d.mesh.size[0] = d.mesh.size[1] = L;
    d.mesh.divisions[0] = d.mesh.divisions[1] = 4;
    d.mesh.origin[0] = d.mesh.origin[1] = -L / 2;
    d.mesh.origin[2] = R + t / 2 + 2e-4;
    fe_builder *b;
    mcs_error err = {0};
    CHECK(ft_builder(&b, &d, NULL, &err) == MCS_OK);
    fe_ellipsoid_desc e = {.semi_axes = {R, R, R}};
    snprintf(e.name, sizeof e.name, "ball");
    CHECK(fe_builder_add_ellipsoid(b, &e, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.gravity[2] = -1000;
    o.damping = 2000;
    fe_model *m;
    fe_state *s;
    CHECK(ft_model_state(&b, &o, &m, &s, &err) == MCS_OK);
    if (!m) return;
    int mid[1];
    CHECK(ft_nodes_at(m, 0, 0, 1e-12, NULL, 0) >= 1);
    mid[0] = -1;
    for (int n = 0; n < m->nnode; n++)
        if (fabs(m->node_x0[3 * n]) < 1e-12 && fabs(m->node_x0[3 * n + 1]) < 1e-12) mid[0] = n;
    CHECK(mid[0] >= 0);
    if (mid[0] < 0) return;
    while (s->time < 20e-3 && fe_step(m, s) == MCS_OK) {
    }
    CHECK(s->err.status == MCS_OK);
    double gap = s->node_x[3 * mid[0] + 2] - R, v = fabs(s->node_v[3 * mid[0] + 2]);
    printf("  plate on a sphere: centre node %.6g mm above the sphere (t/2 = %.6g mm), |v| %.2g "
           "m/s, force %.4g N (weight %.4g N)\n",
           1e3 * gap, 1e3 * t / 2, v, -s->contact->ell_force[2], m->mass_total * 1000);
    const double W = m->mass_total * 1000, k = 0.1 * m->node_mass[mid[0]] / (m->dt_initial * m->dt_initial);
    const double ref = t / 2 - W / k;
    printf("  closed form t/2 - W/k = %.6g mm: error %.2e of t/2\n", 1e3 * ref, (gap - ref) / (t / 2));
    FIG("fe.ell_shell_gap_err", "%.0e", fabs(gap - ref) / (t / 2));
    CHECK_NEAR(gap, ref, 1e-11 * t / 2); /* 3e-12 stated */
    CHECK(v < 1e-5);
    /* at rest: the sphere carries the plate's weight */
    CHECK_REL(-s->contact->ell_force[2], m->mass_total * 1000, 1e-3);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

int main(void)
{
    RUN(test_plate_on_sphere);
    TEST_END();
}

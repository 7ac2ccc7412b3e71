/* test_fe_massscale: selective mass scaling (fe_massscale.c): a column of hexes with one thin
 * element runs at the target step, and the added mass is that element's rho V (f^2 - 1). */
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/fe_test_util.h"
#include "tests/fe_test_build.h"

#include "fe/fe_elem.h"

#define A 0.01 /* cross-section edge [m] */

/* a column of 5 hexes along z, the third 1 mm thick, the others 10 mm */
static fe_model *column(double target, double vz, mcs_error *err)
{
    fe_builder *b;
    if (fe_builder_create(&b, err)) return NULL;
    fe_part_desc d = ft_part("col", FE_SECTION_SOLID, 210e9, 0.3, 7850);
    int ip;
    fe_builder_add_part(b, &d, &ip, err);
    const double z[6] = {0, 0.01, 0.02, 0.021, 0.031, 0.041};
    for (int k = 0; k < 6; k++) {
        double xy[4][2] = {{0, 0}, {A, 0}, {A, A}, {0, A}};
        for (int i = 0; i < 4; i++) {
            double x[3] = {xy[i][0], xy[i][1], z[k]};
            fe_builder_add_node(b, x, NULL, err);
        }
    }
    for (int k = 0; k < 5; k++) {
        int c[8];
        for (int i = 0; i < 4; i++) c[i] = 4 * k + i, c[4 + i] = 4 * (k + 1) + i;
        fe_builder_add_elem(b, ip, c, err);
    }
    for (int i = 0; i < 4; i++) fe_builder_fix_node(b, i, FE_DOF_TRANS, NULL, err);
    fe_opts o = fe_opts_default();
    o.mass_scaling_dt = target;
    o.bulk_q1 = o.bulk_q2 = 0;
    fe_model *m = NULL;
    mcs_status st = fe_model_create(b, &o, &m, err);
    fe_builder_destroy(&b);
    if (st) return NULL;
    for (int n = 4; n < m->nnode; n++) m->node_v0[3 * n + 2] = vz * m->node_x0[3 * n + 2] / 0.041;
    return m;
}

/* hex step L / c, L = V / largest face = the element's thickness here, c = sqrt((l + 2 mu)/rho):
 * the thin element's scaled step 0.9 * 0.001 / c is raised to the target 0.9 * 0.005 / c with
 * f = 5: its density becomes 25 rho, the added mass 24 rho (A^2 0.001) (LS-DYNA DT2MS < 0
 * semantics); the 10 mm elements (0.9 * 0.01 / c) stay as they are */
static void test_thin_element(void)
{
    mcs_error err = {0};
    const double rho = 7850, E = 210e9, nu = 0.3;
    const double c = sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho);
    const double target = 0.9 * 0.005 / c;
    fe_model *m = column(target, 0.5, &err);
    CHECK(m != NULL);
    if (!m) return;
    const double added = 24 * rho * A * A * 0.001, physical = rho * A * A * 0.041;
    CHECK_REL(m->mass_added, added, 1e-12);
    CHECK_REL(m->mass_total, physical + added, 1e-12);
    CHECK_REL(m->dt_initial, target, 1e-12);
    CHECK_REL(fe_dt_factor(m, FE_KIND_HEX, 2), 5, 1e-12);
    /* the others are not scaled; they may carry the lightly-held-hex factor of fe_hex_dt.c,
     * between 1 and sqrt((lambda + 2 mu)/(3 lambda + 2 mu)) = 0.734 at nu = 0.3 */
    for (int e = 0; e < 5; e += 4)
        CHECK(fe_dt_factor(m, FE_KIND_HEX, e) <= 1 && fe_dt_factor(m, FE_KIND_HEX, e) > 0.73);
    /* the thin element's nodes carry an eighth of its scaled mass more each */
    CHECK_REL(m->node_mass[8], rho * A * A * (0.01 + 0.001 * 25) / 8, 1e-12);
    /* it runs at the target step, the energy balance closes */
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double dtmin = INFINITY, dtmax = 0;
    for (int k = 0; k < 400; k++) {
        CHECK(fe_step(m, s) == MCS_OK);
        dtmin = fmin(dtmin, s->dt_prev), dtmax = fmax(dtmax, s->dt_prev);
    }
    printf("  mass scaling: added %.6g kg (%.1f %%), step %.6g..%.6g s, target %.6g s\n",
           m->mass_added, 100 * added / physical, dtmin, dtmax, target);
    FIG("fe.massscale_step_err", "%.0e", fmax(fabs(dtmin / target - 1), fabs(dtmax / target - 1)));
    FIG("fe.massscale_balance", "%.0e", fabs(s->energy[FE_E_total] / s->energy0 - 1));
    CHECK_REL(dtmin, target, 3e-4); /* 1e-4 stated */
    CHECK_REL(dtmax, target, 3e-4);
    CHECK_NEAR(s->energy[FE_E_total], s->energy0, 1e-3 * s->energy0);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    /* without mass scaling the thin element sets a five times smaller step */
    fe_model *m0 = column(0, 0.5, &err);
    CHECK(m0 != NULL);
    if (m0) {
        CHECK(m0->mass_added == 0);
        CHECK_REL(m0->dt_initial, target / 5, 1e-12);
        fe_model_destroy(&m0);
    }
    /* a target below every element's step adds nothing */
    fe_model *m1 = column(target / 10, 0.5, &err);
    CHECK(m1 != NULL);
    if (m1) {
        CHECK(m1->mass_added == 0);
        CHECK_REL(m1->dt_initial, target / 5, 1e-12);
        fe_model_destroy(&m1);
    }
}

/* mass scaling during the run: a 10 mm cube (nu = 0, c = sqrt(E/rho) = 100 m/s, no bulk
 * viscosity) crushed by its top face at 1 m/s. Its step is L/c with L = V / largest face = z
 * (the height), so it falls below the target dt_t once z < zs = dt_t c / dt_scale (8 mm here);
 * checked every cycle, the element's density factor becomes (zs/z)^2 and the added mass
 *     dM = rho h^3 ((zs/z)^2 - 1)
 * with z the height at the last check, the run's step stays dt_t, and the kinetic energy of
 * the mass added to the moving top nodes is counted, so the balance still closes. */
static void test_crush_rescaled(void)
{
    const double h = 0.01, E = 1e7, rho = 1000, v = 1, c = sqrt(E / rho);
    fe_part_desc d = ft_part("cube", FE_SECTION_SOLID, E, 0, rho);
    ft_box(&d, h, h, h, 1, 1, 1);
    fe_builder *b;
    mcs_error err = {0};
    CHECK(ft_builder(&b, &d, NULL, &err) == MCS_OK);
    fe_boundary_desc lo = ft_bc("cube", FE_WHERE_Z_MIN, FE_DOF_ALL);
    fe_boundary_desc hi = ft_bc("cube", FE_WHERE_Z_MAX, FE_DOF_TRANS);
    hi.velocity[2] = -v;
    CHECK(fe_builder_add_boundary(b, &lo, &err) == MCS_OK);
    CHECK(fe_builder_add_boundary(b, &hi, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.bulk_q1 = o.bulk_q2 = 0;
    const double zs = 0.008, target = zs / c * o.dt_scale;
    o.mass_scaling_dt = target;
    o.mass_scaling_interval = 1;
    fe_model *m;
    fe_state *s;
    CHECK(ft_model_state(&b, &o, &m, &s, &err) == MCS_OK);
    if (!m) return;
    CHECK(m->mass_added == 0); /* 10 mm: above the target at t = 0 */
    int top = -1;
    for (int n = 0; n < m->nnode; n++)
        if (m->node_x0[3 * n + 2] > 0.5 * h) top = n;
    double dtdev = 0, emax = 0, eref = 0;
    while (s->node_x[3 * top + 2] > 0.5 * h && fe_step(m, s) == MCS_OK) {
        if (s->node_x[3 * top + 2] < zs - 2e-4) dtdev = fmax(dtdev, fabs(s->dt - target) / target);
        emax = fmax(emax, fabs(s->energy[FE_E_total] - s->energy0));
        eref = fmax(eref, s->energy[FE_E_internal]);
    }
    CHECK(s->err.status == MCS_OK);
    const double z = s->node_x[3 * top + 2], dM = rho * h * h * h * ((zs / z) * (zs / z) - 1);
    printf("  crushed cube at z %.4g mm: added %.6g kg (rho h^3 ((zs/z)^2 - 1) = %.6g), step off the "
           "target by %.1e, energy balance %.1e of the internal energy\n",
           1e3 * z, s->mass_added_run, dM, dtdev, emax / eref);
    FIG("fe.massscale_run_added_kg", "%.5f", s->mass_added_run);
    FIG("fe.massscale_run_balance", "%.1e", emax / eref);
    CHECK_REL(s->mass_added_run, dM, 1e-9);
    CHECK(dtdev < 1e-12);
    CHECK(emax < 7e-5 * eref); /* 2.4e-5 stated */
    /* the mass went onto the element's 8 nodes */
    double sum = 0;
    for (int n = 0; n < m->nnode; n++) sum += s->node_dm[n];
    CHECK_REL(sum, dM, 1e-12);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

int main(void)
{
    RUN(test_thin_element);
    RUN(test_crush_rescaled);
    TEST_END();
}

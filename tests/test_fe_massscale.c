/* test_fe_massscale: selective mass scaling (fe_massscale.c): a column of hexes with one thin
 * element runs at the target step, and the added mass is that element's rho V (f^2 - 1). */
#include "tests/harness.h"
#include "tests/fe_test_util.h"

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
    CHECK_REL(dtmin, target, 1e-3);
    CHECK_REL(dtmax, target, 1e-3);
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

int main(void)
{
    RUN(test_thin_element);
    TEST_END();
}

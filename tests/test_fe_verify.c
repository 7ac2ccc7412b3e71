/* test_fe_verify: explicit FE verification against closed forms (each case cites its formula):
 * 1-D wave speed, elastic bar into a rigid wall, energy balance, shell cantilever, uniaxial
 * J2 plasticity (hex and shell), truss (tension-only), moving penalty wall, failure detection. */
#include "tests/harness.h"
#include "tests/fe_test_util.h"

#include "fe/fe_elem.h"

static const double E_ST = 210e9, RHO_ST = 7850;

/* a bar along x, length L, square section a, nx elements, nu = 0 (1-D: c = sqrt(E / rho)) */
static fe_builder *bar_builder(double L, double a, int nx, double v0)
{
    fe_builder *b;
    mcs_error err = {0};
    if (fe_builder_create(&b, &err) != MCS_OK) return NULL;
    fe_part_desc d = ft_part("bar", FE_SECTION_SOLID, E_ST, 0.0, RHO_ST);
    d.mesh.generate = FE_MESH_BOX;
    d.mesh.size[0] = L, d.mesh.size[1] = a, d.mesh.size[2] = a;
    d.mesh.divisions[0] = nx, d.mesh.divisions[1] = 1, d.mesh.divisions[2] = 1;
    d.initial_velocity[0] = v0;
    if (fe_builder_add_part(b, &d, NULL, &err) != MCS_OK) fe_builder_destroy(&b);
    return b;
}

/* Elastic bar of length L at speed v into a fixed rigid wall (1-D wave theory, e.g. Graff,
 * Wave Motion in Elastic Solids, 1975, §1.5; Johnson, Impact Strength of Materials, 1972):
 *   contact force F = rho c A v, contact time 2 L / c, rebound speed v, c = sqrt(E / rho);
 * the compressive front reaches x at t = x / c (checked at the middle of the bar). */
static void test_bar_impact(void)
{
    const double L = 1.0, a = 0.01, v0 = 5.0;
    const int nx = 100;
    fe_builder *b = bar_builder(L, a, nx, -v0);
    mcs_error err = {0};
    fe_wall_desc w;
    memset(&w, 0, sizeof w);
    snprintf(w.name, sizeof w.name, "wall");
    w.normal[0] = 1; /* stops what lies at x >= 0 */
    CHECK(fe_builder_add_wall(b, &w, &err) == MCS_OK);
    fe_model *m;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    fe_state *s;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    const double c = sqrt(E_ST / RHO_ST), tc = 2 * L / c, F = RHO_ST * c * a * a * v0;
    int mid[4];
    CHECK(ft_nodes_at(m, 0, L / 2, 1e-9, mid, 4) == 4);
    double t_front = -1, fsum = 0, wsum = 0, t_last = 0;
    double emax = 0;
    while (s->time < 1.5 * tc) {
        double t_prev = s->time;
        CHECK(fe_step(m, s) == MCS_OK);
        if (s->err.status) break;
        /* the mid node goes from -v0 to 0 as the front passes: half-way crossing */
        if (t_front < 0 && s->node_v[3 * mid[0]] > -0.5 * v0) t_front = t_prev + 0.5 * s->dt_prev;
        double t = s->energy_time, f = s->wall_normal[0];
        if (t > 0.1 * tc && t < 0.9 * tc) fsum += f * s->dt_prev, wsum += s->dt_prev;
        if (f > 0) t_last = t;
        emax = fmax(emax, fabs(s->energy[FE_E_total] - s->energy0));
    }
    double vmean = 0, mt = 0;
    for (int n = 0; n < m->nnode; n++) vmean += m->node_mass[n] * s->node_v[3 * n], mt += m->node_mass[n];
    vmean /= mt;
    printf("bar impact: front %.4g s (L/2c %.4g), force %.5g N (rho c A v %.5g), contact %.4g s "
           "(2L/c %.4g), rebound %.4g m/s, energy error %.2e\n",
           t_front, L / (2 * c), fsum / wsum, F, t_last, tc, vmean, emax / s->energy0);
    CHECK_REL(t_front, L / (2 * c), 0.02);
    CHECK_REL(fsum / wsum, F, 0.02);
    CHECK_REL(t_last, tc, 0.03);
    CHECK_REL(vmean, v0, 0.03);
    CHECK(emax < 0.01 * s->energy0);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
}

int main(void)
{
    RUN(test_bar_impact);
    TEST_END();
}

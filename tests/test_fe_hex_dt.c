/* Stable step of lightly held hexahedra (fe/elem/fe_hex_dt.c).
 * A lone one-point cube of side h has lumped nodal masses rho h^3/8 and a uniform-dilatation
 * mode omega^2 = 4 (3 lambda + 2 mu)/(rho h^2) (Rayleigh quotient of the exact one-point
 * stiffness; Flanagan & Belytschko 1981 give the b_I), faster than the L/c estimate's
 * 4 (lambda + 2 mu)/(rho h^2) when nu > 0. The step must be 0.9 * 2/omega; a mesh's interior
 * elements keep 0.9 L/c, the exact limit of a regular cube mesh's checkerboard mode. Both carry
 * the linear bulk viscosity's damped limit (fe_bulk_dt): with Q = q2 c, 2/omega becomes
 * (2/omega) (sqrt(1 + q2^2) - q2), q2 = 0.06 the default (LS-DYNA's Q2). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fe/fe_model.h"
#include "fe/fe_state.h"
#include "tests/fe_test_util.h"
#include "tests/harness.h"

static const double E = 210e9, NU = 0.3, RHO = 7850, H = 0.1;

static fe_model *cube_model(int div, double vx)
{
    fe_builder *b = NULL;
    mcs_error err = {0};
    if (fe_builder_create(&b, &err) != MCS_OK) return NULL;
    fe_part_desc d = ft_part("cube", FE_SECTION_SOLID, E, NU, RHO);
    d.mesh.generate = FE_MESH_BOX;
    d.mesh.size[0] = d.mesh.size[1] = d.mesh.size[2] = div * H;
    d.mesh.divisions[0] = d.mesh.divisions[1] = d.mesh.divisions[2] = div;
    d.initial_velocity[0] = vx, d.initial_velocity[2] = 0.3 * vx;
    fe_model *m = NULL;
    if (fe_builder_add_part(b, &d, NULL, &err) == MCS_OK) fe_model_create(b, NULL, &m, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    fe_builder_destroy(&b);
    return m;
}

static double lame_lambda(void) { return E * NU / ((1 + NU) * (1 - 2 * NU)); }
static double lame_mu(void) { return E / (2 * (1 + NU)); }
/* the damped limit of a mode at its undamped limit under the linear bulk viscosity q2 = 0.06 */
static double q2_factor(void) { return sqrt(1 + 0.06 * 0.06) - 0.06; }

/* the lone cube: step 0.9 h / sqrt((3 lambda + 2 mu)/rho), and it flies without deforming */
static void test_lone_cube(void)
{
    fe_model *m = cube_model(1, 10);
    CHECK(m != NULL);
    if (!m) return;
    fe_state *s = NULL;
    mcs_error err = {0};
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    if (!s) {
        fe_model_destroy(&m);
        return;
    }
    double dt_exact = 0.9 * H / sqrt((3 * lame_lambda() + 2 * lame_mu()) / RHO) * q2_factor();
    CHECK_REL(fe_stable_dt(m, s), dt_exact, 1e-9);
    /* 2000 steps (about 30 ms): without the factor it inverts within 40 steps */
    mcs_status st = MCS_OK;
    for (int i = 0; i < 2000 && st == MCS_OK; i++) st = fe_step(m, s);
    CHECK(st == MCS_OK);
    /* still a cube of side h: node 0 to node 6 (the body diagonal) */
    double d2 = 0;
    for (int k = 0; k < 3; k++) {
        double d = s->node_x[3 * m->hex_node[6] + k] - s->node_x[3 * m->hex_node[0] + k];
        d2 += d * d;
    }
    CHECK_REL(sqrt(d2), sqrt(3.0) * H, 1e-9);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a 4 x 4 x 4 block: the interior sets 0.9 h / c, c = sqrt((lambda + 2 mu)/rho) */
static void test_block_unchanged(void)
{
    fe_model *m = cube_model(4, 0);
    CHECK(m != NULL);
    if (!m) return;
    fe_state *s = NULL;
    mcs_error err = {0};
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    if (s)
        CHECK_REL(fe_stable_dt(m, s),
                  0.9 * H / sqrt((lame_lambda() + 2 * lame_mu()) / RHO) * q2_factor(), 1e-9);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

int main(void)
{
    RUN(test_lone_cube);
    RUN(test_block_unchanged);
    TEST_END();
}

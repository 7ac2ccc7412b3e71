/* test_s3_moto: the parametric FE motorcycle (stage3_fe/s3_moto.h) against the stage-1 model it
 * is built from: total mass, centre of gravity and inertia within 2 % (the requirement).
 * Reference: the stage-1 file's seven bodies summed here by hand (masses, mass-weighted centre,
 * each body's inertia moved to the common centre by the parallel-axis theorem), read with the
 * scenario reader only, never through the generator. The FE side: the frozen model's rigid
 * bodies (mass, centre, inertia as fe_rigid.c sums them) plus every node outside a body.
 * Element counts at the coarse (40 mm, the tests') and fine (10 mm, runs) sizes; a missing model
 * file (exit 2 at the model: key). */
#include "tests/harness.h"
#include "tests/figures.h"

#include "fe/fe_scn_build.h"
#include "fe/fe_solid.h"
#include "stage3_fe/s3_moto.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MODEL "scenarios/models/motorcycles/sport_208kg.yaml"

typedef struct {
    double m, c[3], I[3]; /* mass, centre, inertia about the centre (world axes, diagonal) */
} mprops;

/* the stage-1 bodies summed by the parallel-axis theorem */
static mprops stage1_props(void)
{
    mcs_scenario *s = NULL;
    mcs_error err = {0};
    mprops r = {0};
    CHECK(mcs_scenario_load(MODEL, &s, &err) == MCS_OK);
    if (!s) return r;
    const mcs_node *bodies = mcs_node_get(mcs_scenario_root(s), "bodies");
    double mx[3] = {0, 0, 0};
    for (int i = 0; i < mcs_node_len(bodies); i++) {
        const mcs_node *b = mcs_node_at(bodies, i);
        double m = mcs_node_num(mcs_node_get(b, "mass")), c[3];
        CHECK(mcs_node_vec3(mcs_node_get(b, "position"), c, &err) == MCS_OK);
        r.m += m;
        for (int k = 0; k < 3; k++) mx[k] += m * c[k];
    }
    for (int k = 0; k < 3; k++) r.c[k] = mx[k] / r.m;
    for (int i = 0; i < mcs_node_len(bodies); i++) {
        const mcs_node *b = mcs_node_at(bodies, i);
        double m = mcs_node_num(mcs_node_get(b, "mass")), c[3], I[3], d[3];
        CHECK(mcs_node_vec3(mcs_node_get(b, "position"), c, &err) == MCS_OK);
        CHECK(mcs_node_vec3(mcs_node_get(b, "inertia"), I, &err) == MCS_OK);
        for (int k = 0; k < 3; k++) d[k] = c[k] - r.c[k];
        for (int k = 0; k < 3; k++)
            r.I[k] += I[k] + m * (d[(k + 1) % 3] * d[(k + 1) % 3] + d[(k + 2) % 3] * d[(k + 2) % 3]);
    }
    mcs_scenario_destroy(&s);
    return r;
}

/* the FE model's: rigid bodies as wholes, free nodes as points */
static mprops fe_props(const fe_model *m)
{
    mprops r = {0};
    double mx[3] = {0, 0, 0};
    for (int b = 0; b < m->nbody; b++) {
        r.m += m->body[b].mass;
        for (int k = 0; k < 3; k++) mx[k] += m->body[b].mass * m->body[b].x0[k];
    }
    for (int n = 0; n < m->nnode; n++)
        if (m->node_body[n] < 0) {
            r.m += m->node_mass[n];
            for (int k = 0; k < 3; k++) mx[k] += m->node_mass[n] * m->node_x0[3 * n + k];
        }
    for (int k = 0; k < 3; k++) r.c[k] = mx[k] / r.m;
    for (int b = 0; b < m->nbody; b++) {
        double d[3];
        for (int k = 0; k < 3; k++) d[k] = m->body[b].x0[k] - r.c[k];
        for (int k = 0; k < 3; k++)
            r.I[k] += m->body[b].inertia0[k][k] +
                      m->body[b].mass * (d[(k + 1) % 3] * d[(k + 1) % 3] + d[(k + 2) % 3] * d[(k + 2) % 3]);
    }
    for (int n = 0; n < m->nnode; n++)
        if (m->node_body[n] < 0) {
            double d[3];
            for (int k = 0; k < 3; k++) d[k] = m->node_x0[3 * n + k] - r.c[k];
            for (int k = 0; k < 3; k++)
                r.I[k] += m->node_mass[n] * (d[(k + 1) % 3] * d[(k + 1) % 3] + d[(k + 2) % 3] * d[(k + 2) % 3]);
        }
    return r;
}

static fe_model *build(double h)
{
    char text[512];
    snprintf(text, sizeof text,
             "mcrash: 1\nname: moto\nsimulation: {end_time: 1 ms}\n"
             "fe:\n  parts:\n    - name: moto\n      mesh: {generate: motorcycle, model: "
             "models/motorcycles/sport_208kg.yaml, element_size: %g}\n",
             h);
    mcs_scenario *s = NULL;
    mcs_error err = {0};
    fe_problem p = {0};
    CHECK(mcs_scenario_load_text("scenarios/moto_test.yaml", text, strlen(text), &s, &err) ==
          MCS_OK);
    if (s) CHECK(fe_scn_build(s, &p, &err) == MCS_OK);
    if (err.msg[0]) printf("  %s\n", err.msg);
    mcs_scenario_destroy(&s);
    fe_model *m = p.model;
    p.model = NULL;
    fe_problem_free(&p);
    return m;
}

static void test_mass_properties(void)
{
    mprops ref = stage1_props();
    fe_model *m = build(0.04);
    CHECK(m != NULL);
    if (!m) return;
    mprops fe = fe_props(m);
    printf("  stage 1: m %.3f kg, c [%.4f %.4f %.4f] m, I [%.3f %.3f %.3f] kg m^2\n", ref.m,
           ref.c[0], ref.c[1], ref.c[2], ref.I[0], ref.I[1], ref.I[2]);
    printf("  FE     : m %.3f kg, c [%.4f %.4f %.4f] m, I [%.3f %.3f %.3f] kg m^2\n", fe.m,
           fe.c[0], fe.c[1], fe.c[2], fe.I[0], fe.I[1], fe.I[2]);
    CHECK_REL(fe.m, ref.m, 0.02);
    CHECK_REL(fe.c[0], ref.c[0], 0.02);
    CHECK_NEAR(fe.c[1], ref.c[1], 0.002);
    CHECK_REL(fe.c[2], ref.c[2], 0.02);
    for (int k = 0; k < 3; k++) CHECK_REL(fe.I[k], ref.I[k], 0.02);
    FIG("moto.stage1_mass", "%.1f", ref.m);
    FIG("moto.fe_mass", "%.1f", fe.m);
    FIG_TOL("moto.cg_x_err_mm", "%.1f", 1e3 * (fe.c[0] - ref.c[0]), 0.15);
    FIG_TOL("moto.cg_z_err_mm", "%.1f", 1e3 * (fe.c[2] - ref.c[2]), 0.15);
    FIG_TOL("moto.ixx_err_pct", "%.2f", 100 * (fe.I[0] / ref.I[0] - 1), 0.015);
    FIG_TOL("moto.iyy_err_pct", "%.2f", 100 * (fe.I[1] / ref.I[1] - 1), 0.015);
    FIG_TOL("moto.izz_err_pct", "%.2f", 100 * (fe.I[2] / ref.I[2] - 1), 0.015);
    /* the step is the shells' (the 43 x 2 mm stanchions' 16 mm edges: l / c = 16 mm / 5.2 km/s
       = 3 us, times the 0.9 safety factor), not the suspension springs' */
    CHECK(m->dt_discrete > 2 * m->dt_initial);
    CHECK(m->dt_initial > 1.5e-6);
    FIG_TOL("moto.dt_coarse_us", "%.2f", 1e6 * m->dt_initial, 0.015);
    FIG("moto.elements_coarse", "%.0f", (double)m->nelem);
    FIG("moto.bodies", "%.0f", (double)m->nbody);
    FIG("moto.joints", "%.0f", (double)m->njoint);
    fe_model_destroy(&m);
}

static void test_fine_mesh(void)
{
    fe_model *m = build(0.010);
    CHECK(m != NULL);
    if (!m) return;
    CHECK(m->nelem >= 30000 && m->nelem <= 100000); /* the run mesh: 30-100k */
    FIG("moto.elements_fine", "%.0f", (double)m->nelem);
    mprops ref = stage1_props(), fe = fe_props(m);
    CHECK_REL(fe.m, ref.m, 0.02);
    for (int k = 0; k < 3; k++) CHECK_REL(fe.I[k], ref.I[k], 0.02);
    fe_model_destroy(&m);
}

/* bad input: a model file that does not exist is named at the model: key (FILE:LINE:COL) */
static void test_bad_model(void)
{
    const char *text = "mcrash: 1\nname: moto\nsimulation: {end_time: 1 ms}\n"
                       "fe:\n  parts:\n    - name: moto\n      mesh: {generate: motorcycle, "
                       "model: nothere.yaml, element_size: 0.04}\n";
    mcs_scenario *s = NULL;
    mcs_error err = {0};
    fe_problem p = {0};
    CHECK(mcs_scenario_load_text("scenarios/moto_bad.yaml", text, strlen(text), &s, &err) ==
          MCS_OK);
    if (s) CHECK(fe_scn_build(s, &p, &err) == MCS_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "scenarios/moto_bad.yaml:7:");
    CHECK_STR_CONTAINS(err.msg, "nothere.yaml");
    CHECK(mcs_status_exit_code(MCS_ERR_IO) == 2);
    fe_problem_free(&p);
    mcs_scenario_destroy(&s);
}

int main(void)
{
    s3_moto_register();
    RUN(test_mass_properties);
    RUN(test_fine_mesh);
    RUN(test_bad_model);
    TEST_END();
}

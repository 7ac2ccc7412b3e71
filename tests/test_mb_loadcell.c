/* test_mb_loadcell.c: load-cell sensors (stage1_mb/mb_loadcell.h) on hand-made statics with
 * closed-form loads, in the SAE J211 sign convention (x forward, y right, z down; upper neck:
 * Fz > 0 tension, My > 0 flexion; the loads on the part above the cell):
 *   a head (m = 4.54 kg) held by its neck joint at a point h = 35 mm below its CG:
 *   gravity down  -> Fz = -m g (compression), moments m g d for a cell d behind the CG;
 *   gravity up    -> Fz = +m g (tension);
 *   gravity ahead -> Fx = -m g (the head pushed forward), My = +m g h (flexion);
 *   a restrained spherical neck under gravity ahead: at rest the moment is the restraint's,
 *   k theta = m g h cos(theta), which the cell must read (ODE's constraint gives none);
 *   the cell on the parent side reads the opposite (Newton's third law). */
#include "harness.h"
#include "stage1_mb/mb_loadcell.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MASS 4.54
#define G 9.81
#define H 0.035

static mb_model *build(const char *txt)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mb_model *m = NULL;
    if (mcs_scenario_load_text("loadcell.yaml", txt, strlen(txt), &scn, &err) ||
        mb_model_build(scn, NULL, &m, &err))
        fprintf(stderr, "loadcell.yaml: %s\n", err.msg);
    mcs_scenario_destroy(&scn);
    return m;
}

/* run n steps with gravity g (world) and return load cell i's six values */
static int run(mb_model *m, const double g[3], long n, int i, double out[6], mb_state **keep)
{
    mcs_error err = {0};
    mb_state *s = NULL;
    memcpy(m->gravity, g, sizeof m->gravity);
    if (mb_state_create(m, &s, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return -1;
    }
    for (long k = 0; k < n; k++)
        if (mb_step(m, s, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            mb_state_destroy(&s);
            return -1;
        }
    mb_loadcell_value(m, s, i, out);
    if (keep)
        *keep = s;
    else
        mb_state_destroy(&s);
    return 0;
}

static const char *const FIXED =
    "mcrash: 1\n"
    "simulation: {end_time: 10 ms, time_step: 10 us}\n"
    "bodies:\n"
    "  - {name: base, mass: 10, inertia: [0.1, 0.1, 0.1], position: [0, 0, 0.9], velocity: [0, 0, 0]}\n"
    "  - {name: head, mass: 4.54, inertia: [0.025, 0.027, 0.018], position: [0, 0, 1.0], velocity: [0, 0, 0]}\n"
    "joints:\n"
    "  - {name: base_fix, type: fixed, parent: ground, child: base, anchor: [0, 0, 0.9]}\n"
    "  - {name: upper_neck, type: fixed, parent: base, child: head, anchor: [0, 0, 0.965]}\n"
    "sensors:\n"
    "  - {name: neck, type: load_cell, body: head, joint: upper_neck, point: [0, 0, -0.035]}\n"
    "  - {name: behind, type: load_cell, body: head, joint: upper_neck, point: [-0.05, 0, 0]}\n"
    "  - {name: base_side, type: load_cell, body: base, frame: head, joint: upper_neck,\n"
    "     point: [0, 0, -0.035]}\n";

static void test_static_signs(void)
{
    mb_model *m = build(FIXED);
    CHECK(m != NULL);
    if (!m) return;
    CHECK(m->nloadcell == 3 && m->nsensor == 0);
    double v[6], w[6], mg = MASS * G;
    /* gravity down: the neck pushes the head up -> compression, Fz = -m g */
    static const double down[3] = {0, 0, -G}, up[3] = {0, 0, G}, ahead[3] = {G, 0, 0};
    CHECK(run(m, down, 1000, 0, v, NULL) == 0);
    printf("  gravity down: F = %.10g %.10g %.10g N (m g = %.10g), M = %.3g %.3g %.3g N m\n", v[0], v[1], v[2],
           mg, v[3], v[4], v[5]);
    CHECK_NEAR(v[2], -mg, 1e-6 * mg);
    CHECK_NEAR(v[0], 0, 1e-6 * mg);
    CHECK_NEAR(v[1], 0, 1e-6 * mg);
    for (int k = 3; k < 6; k++) CHECK_NEAR(v[k], 0, 1e-6 * mg * H);
    /* a cell d = 50 mm behind the CG: M = (c - P) x F = (d,0,0) x (0,0,mg) = -d m g about +y
     * (ISO, left) = +d m g about the J211 y (right) */
    CHECK(run(m, down, 1000, 1, v, NULL) == 0);
    printf("  cell 50 mm behind the CG: My = %.10g N m (d m g = %.10g)\n", v[4], 0.05 * mg);
    CHECK_NEAR(v[4], 0.05 * mg, 1e-6 * 0.05 * mg);
    CHECK_NEAR(v[3], 0, 1e-9);
    CHECK_NEAR(v[5], 0, 1e-9);
    /* gravity up: the head pulls away, the neck holds it -> tension, Fz = +m g */
    CHECK(run(m, up, 1000, 0, v, NULL) == 0);
    printf("  gravity up: Fz = %.10g N (+m g = %.10g)\n", v[2], mg);
    CHECK_NEAR(v[2], mg, 1e-6 * mg);
    /* gravity ahead: the head is pushed forward, the neck pulls it back: Fx = -m g; about the
     * cell h below the CG the neck resists the forward bending: My = +m g h (flexion) */
    CHECK(run(m, ahead, 1000, 0, v, NULL) == 0);
    printf("  gravity ahead: Fx = %.10g N, My = %.10g N m (m g h = %.10g)\n", v[0], v[4], mg * H);
    CHECK_NEAR(v[0], -mg, 1e-6 * mg);
    CHECK_NEAR(v[2], 0, 1e-6 * mg);
    CHECK_NEAR(v[4], mg * H, 1e-6 * mg * H);
    /* the same joint seen from the parent: the opposite loads */
    CHECK(run(m, ahead, 1000, 2, w, NULL) == 0);
    for (int k = 0; k < 6; k++) CHECK_NEAR(w[k], -v[k], 1e-9 * mg);
    mb_model_destroy(&m);
}

/* a spherical neck with a linear restraint k under gravity ahead: at rest k theta =
 * m g h cos theta; the constraint force passes through the joint, so the cell's moment about
 * the joint point is the restraint's alone */
static void test_restraint_moment(void)
{
    static const char *const txt =
        "mcrash: 1\n"
        "simulation: {end_time: 10 ms, time_step: 10 us}\n"
        "characteristics:\n"
        "  neck: {type: moment, loading: [[0, 0], [1 rad, 20 N*m]], damping: 0.5 N m s/rad}\n"
        "bodies:\n"
        "  - {name: head, mass: 4.54, inertia: [0.025, 0.027, 0.018], position: [0, 0, 1.0], velocity: [0, 0, 0]}\n"
        "joints:\n"
        "  - {name: upper_neck, type: spherical, parent: ground, child: head, anchor: [0, 0, 0.965],\n"
        "     restraint: neck}\n"
        "sensors:\n"
        "  - {name: neck, type: load_cell, body: head, joint: upper_neck, point: [0, 0, -0.035]}\n";
    mb_model *m = build(txt);
    CHECK(m != NULL);
    if (!m) return;
    static const double ahead[3] = {G, 0, 0};
    double v[6];
    mb_state *s = NULL;
    CHECK(run(m, ahead, 200000, 0, v, &s) == 0); /* 2 s: the damped swing settles */
    if (!s) {
        mb_model_destroy(&m);
        return;
    }
    /* the head's pitch: its z axis turned forward by theta */
    const double *R = s->kin[0].rot;
    double theta = atan2(R[2], R[8]);
    double mg = MASS * G, k = 20.0;
    printf("  restrained neck at rest: theta %.6f rad, My %.6f N m, k theta %.6f, m g h cos %.6f\n",
           theta, v[4], k * theta, mg * H * cos(theta));
    CHECK(theta > 0.005 && theta < 0.2);
    CHECK_NEAR(k * theta, mg * H * cos(theta), 1e-4 * mg * H);
    CHECK_NEAR(v[4], k * theta, 1e-4 * mg * H);
    /* the force in the head's axes: gravity ahead turned into the pitched head */
    CHECK_NEAR(v[0], -mg * cos(theta), 1e-5 * mg);
    CHECK_NEAR(v[2], mg * sin(theta), 1e-5 * mg); /* ISO -mg sin, J211 z flipped */
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* bad input is refused with the file position */
static void test_errors(void)
{
    static const char *const bad =
        "mcrash: 1\n"
        "simulation: {end_time: 1 ms}\n"
        "bodies:\n"
        "  - {name: head, mass: 4.54, inertia: [0.025, 0.027, 0.018], position: [0, 0, 1.0], velocity: [0, 0, 0]}\n"
        "  - {name: other, mass: 1, inertia: [0.01, 0.01, 0.01], position: [0, 0, 2.0], velocity: [0, 0, 0]}\n"
        "joints:\n"
        "  - {name: upper_neck, type: spherical, parent: ground, child: head, anchor: [0, 0, 0.965]}\n"
        "sensors:\n"
        "  - {name: neck, type: load_cell, body: %s, joint: %s}\n";
    char txt[1024];
    mcs_error err = {0};
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    snprintf(txt, sizeof txt, bad, "head", "lower_neck");
    CHECK(mcs_scenario_load_text("lc.yaml", txt, strlen(txt), &scn, &err) == 0);
    CHECK(scn && mb_model_build(scn, NULL, &m, &err) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(err.msg, "lc.yaml:9:");
    CHECK_STR_CONTAINS(err.msg, "lower_neck");
    mcs_scenario_destroy(&scn);
    err = (mcs_error){0};
    snprintf(txt, sizeof txt, bad, "other", "upper_neck");
    CHECK(mcs_scenario_load_text("lc.yaml", txt, strlen(txt), &scn, &err) == 0);
    CHECK(scn && mb_model_build(scn, NULL, &m, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "not connected");
    mcs_scenario_destroy(&scn);
    CHECK(m == NULL);
}

int main(void)
{
    RUN(test_static_signs);
    RUN(test_restraint_moment);
    RUN(test_errors);
    TEST_END();
}

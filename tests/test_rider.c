/* test_rider.c: the Hybrid III 50th-class rider (scenarios/models/riders/, docs/rider.md):
 * mass and segments against the H3 50th (78.2 kg, NHTSA) and de Leva (1996); the
 * positioning step (hands on the grips, feet on the pegs, pelvis on the seat: residuals
 * against the closed-form two-link solution); the seated rider under gravity; the neck and
 * the joint ranges. Figures measured are printed (they go into docs/rider.md). */
#include "harness.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_position.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RIDER "scenarios/models/riders/hybrid3_50th.yaml"
#define RIDER7 "scenarios/models/riders/hybrid3_50th_neck7.yaml"

static mb_model *build_text(const char *name, const char *txt, mcs_error *err)
{
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    if (mcs_scenario_load_text(name, txt, strlen(txt), &scn, err) == MCS_OK)
        mb_model_build(scn, NULL, &m, err);
    mcs_scenario_destroy(&scn);
    return m;
}

/* a runnable scenario around model files: the rider alone (free fall, no contacts) */
static mb_model *rider_alone(const char *file)
{
    char txt[1024];
    snprintf(txt, sizeof txt,
             "mcrash: 1\ninclude: [%s]\nsimulation: {end_time: 1 ms, time_step: 10 us}\n",
             file + strlen("scenarios/"));
    mcs_error err = {0};
    mb_model *m = build_text("scenarios/rider_alone.yaml", txt, &err);
    if (!m) fprintf(stderr, "%s: %s\n", file, err.msg);
    return m;
}

static double rider_mass(const mb_model *m, int *nseg)
{
    double tot = 0;
    *nseg = 0;
    for (int i = 0; i < m->nbody; i++)
        if (strncmp(m->body_name[i], "rider_", 6) == 0) tot += m->body[i].mass, (*nseg)++;
    return tot;
}

/* H3 50th: 78.2 kg (NHTSA); the issue asks 78 +- 2 kg and at least 17 segments */
static void test_mass_and_segments(void)
{
    static const char *const need[] = {
        "rider_head",        "rider_neck",        "rider_upper_torso", "rider_lower_torso",
        "rider_pelvis",      "rider_upper_arm_l", "rider_upper_arm_r", "rider_lower_arm_l",
        "rider_lower_arm_r", "rider_hand_l",      "rider_hand_r",      "rider_thigh_l",
        "rider_thigh_r",     "rider_lower_leg_l", "rider_lower_leg_r", "rider_foot_l",
        "rider_foot_r"};
    mb_model *m = rider_alone(RIDER);
    CHECK(m != NULL);
    if (!m) return;
    int n = 0;
    double mass = rider_mass(m, &n);
    printf("  rider: %d segments, %.4f kg, %d joints\n", n, mass, m->njoint);
    CHECK(n >= 17);
    CHECK_NEAR(mass, 78.0, 2.0);
    CHECK_NEAR(mass, 78.2, 1e-3); /* the H3 50th's mass itself, de Leva fractions sum to 1 */
    for (size_t k = 0; k < sizeof need / sizeof need[0]; k++) CHECK(mb_model_body(m, need[k]) >= 0);
    CHECK(m->njoint == 16); /* a tree: one joint per segment but the pelvis */
    /* every segment has a contact surface */
    for (int b = 0; b < m->nbody; b++) {
        int has = 0;
        for (int s = 0; s < m->nsurf; s++) has |= m->surf[s].body == b;
        CHECK(has);
    }
    /* the whole-body CG of the seated reference posture lies between the hips and the chest,
     * ahead of the H-point (thighs forward) and behind the knees */
    double cg[3] = {0, 0, 0};
    for (int b = 0; b < m->nbody; b++)
        for (int k = 0; k < 3; k++) cg[k] += m->body[b].mass * m->body[b].pos[k] / mass;
    printf("  whole-body CG (seated reference) %.4f %.4f %.4f m\n", cg[0], cg[1], cg[2]);
    CHECK(fabs(cg[1]) < 1e-9);
    CHECK(cg[0] > 0.52 && cg[0] < 0.52 + 0.42);
    CHECK(cg[2] > 0.955 && cg[2] < 0.955 + 0.4);
    mb_model_destroy(&m);

    /* the MYMOSA 7-vertebra neck: 23 segments, the same mass, 22 joints */
    m = rider_alone(RIDER7);
    CHECK(m != NULL);
    if (!m) return;
    mass = rider_mass(m, &n);
    printf("  rider with the 7-vertebra neck: %d segments, %.4f kg, %d joints\n", n, mass,
           m->njoint);
    CHECK(n == 23);
    CHECK_NEAR(mass, 78.2, 1e-3);
    CHECK(m->njoint == 22);
    for (int k = 1; k <= 7; k++) {
        char nm[32];
        snprintf(nm, sizeof nm, "rider_c%d", k);
        CHECK(mb_model_body(m, nm) >= 0);
    }
    mb_model_destroy(&m);
}

/* ---- seated on the motorcycle ---- */

#define SEATED_HEAD                                                                                \
    "mcrash: 1\n"                                                                                  \
    "include: [models/motorcycles/sport_208kg.yaml, models/riders/hybrid3_50th.yaml]\n"            \
    "environment: {gravity: 9.81 m/s^2, ground: {height: 0 m, friction: 0.9}}\n"

/* the rider seated on the motorcycle at rest on the ground: seat, tank and thigh contacts */
static mb_model *seated(const char *rider_block, double t_end, mcs_error *err)
{
    char txt[2048];
    snprintf(txt, sizeof txt,
             SEATED_HEAD "simulation: {end_time: %g s, time_step: 10 us, output_rate: 10 kHz}\n"
                         "rider: %s\n"
                         "contacts:\n"
                         "  - {a: rider_pelvis, b: moto_frame, characteristic: seat}\n"
                         "  - {a: rider_thigh_l, b: moto_frame, characteristic: tank}\n"
                         "  - {a: rider_thigh_r, b: moto_frame, characteristic: tank}\n"
                         "  - {a: rider_lower_torso, b: moto_frame, characteristic: tank}\n",
             t_end, rider_block);
    return build_text("scenarios/rider_seated.yaml", txt, err);
}

static double dist_mounts(const mcs_node *root, const mb_model *m, const char *a, const char *b)
{
    double pa[3], pb[3], d[3];
    if (mb_mount_world(root, m, a, pa) || mb_mount_world(root, m, b, pb)) return INFINITY;
    mb_sub(pa, pb, d);
    return mb_norm(d);
}

/* world point of a body-frame point */
static void world_of(const mb_model *m, int b, const double p[3], double out[3])
{
    double R[9];
    mb_quat_to_rot(m->body[b].quat, R);
    mb_mat_vec(R, p, out);
    mb_add(out, m->body[b].pos, out);
}

/* residuals of the seated posture: every rider mount point on its motorcycle mount point
 * (< 1 mm asked; the closed-form two-link solution gives round-off), every joint closed, the
 * segment lengths kept, the elbow and knee ranges moved by the posture */
static void test_positioning(void)
{
    static const char *const pairs[5][2] = {{"rider_h_point", "seat_h_point"},
                                            {"rider_grip_l", "grip_l"},
                                            {"rider_grip_r", "grip_r"},
                                            {"rider_peg_l", "peg_l"},
                                            {"rider_peg_r", "peg_r"}};
    char txt[2048];
    snprintf(txt, sizeof txt,
             SEATED_HEAD "simulation: {end_time: 1 ms}\nrider: {torso_lean: 40 deg}\n");
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    CHECK(mcs_scenario_load_text("scenarios/rider_seated.yaml", txt, strlen(txt), &scn, &err) == 0);
    mb_model *m = NULL;
    if (scn && mb_model_build(scn, NULL, &m, &err)) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL);
    if (!m) {
        mcs_scenario_destroy(&scn);
        return;
    }
    const mcs_node *root = mcs_scenario_root(scn);
    double worst = 0;
    for (int k = 0; k < 5; k++) worst = fmax(worst, dist_mounts(root, m, pairs[k][0], pairs[k][1]));
    printf("  seated at 40 deg: largest mount-point residual %.3g m (model %.3g m)\n", worst,
           m->rider_residual);
    CHECK(worst < 1e-3);
    CHECK(worst < 1e-12); /* closed form: round-off only */
    CHECK(m->rider_residual >= 0 && m->rider_residual < 1e-12);
    /* joints closed: the anchor is the same material point of parent and child */
    mb_model *m0 = rider_alone(RIDER);
    CHECK(m0 != NULL);
    double gap = 0;
    for (int j = 0; m0 && j < m->njoint; j++) {
        const mb_joint_def *jd = &m->joint[j];
        if (jd->parent < 0 || strncmp(m->body_name[jd->parent], "rider_", 6)) continue;
        for (int side = 0; side < 2; side++) {
            int b = side ? jd->child : jd->parent;
            int b0 = mb_model_body(m0, m->body_name[b]);
            /* the anchor in the body frame of the model file */
            double R0[9], d[3], loc[3], w[3];
            mb_quat_to_rot(m0->body[b0].quat, R0);
            mb_sub(m0->joint[j - (m->njoint - m0->njoint)].anchor, m0->body[b0].pos, d);
            mb_mat_tvec(R0, d, loc);
            world_of(m, b, loc, w);
            mb_sub(w, jd->anchor, d);
            gap = fmax(gap, mb_norm(d));
        }
    }
    printf("  largest joint gap after seating %.3g m\n", gap);
    CHECK(gap < 1e-12);
    /* the elbow's range: straight (flexion 0) sits at -flexion of the seated posture, which
     * the geometry gives: flexion = pi - angle(shoulder-elbow-grip) */
    for (int side = 0; side < 2; side++) {
        const char *sfx = side ? "r" : "l";
        char nm[64];
        snprintf(nm, sizeof nm, "rider_elbow_%s", sfx);
        int je = -1, js = -1;
        for (int j = 0; j < m->njoint; j++) {
            if (!strcmp(m->joint[j].name, nm)) je = j;
            char sh[64];
            snprintf(sh, sizeof sh, "rider_shoulder_%s", sfx);
            if (!strcmp(m->joint[j].name, sh)) js = j;
        }
        CHECK(je >= 0 && js >= 0 && m->joint[je].restraint >= 0);
        if (je < 0 || js < 0 || m->joint[je].restraint < 0) continue;
        double grip[3], u[3], f[3];
        snprintf(nm, sizeof nm, "grip_%s", sfx);
        CHECK(mb_mount_world(root, m, nm, grip) == 0);
        mb_sub(m->joint[js].anchor, m->joint[je].anchor, u);
        mb_sub(grip, m->joint[je].anchor, f);
        double flex = M_PI - acos(mb_dot(u, f) / (mb_norm(u) * mb_norm(f)));
        const mb_restraint_model *r = &m->restraint1[m->joint[je].restraint];
        printf("  elbow %s: flexion %.2f deg, range now [%.2f, %.2f] deg\n", sfx,
               flex * 180 / M_PI, r->lo * 180 / M_PI, r->hi * 180 / M_PI);
        CHECK_NEAR(r->lo, -flex, 1e-9);
        CHECK_NEAR(r->hi, 145 * M_PI / 180 - flex, 1e-9);
    }
    /* velocities: the motorcycle's (at rest in the model file) */
    for (int b = 0; b < m->nbody; b++) CHECK(mb_norm(m->body[b].vel) == 0);
    mb_model_destroy(&m0);
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);

    /* unreachable: upright, the grips are beyond the stretched arms */
    m = seated("{torso_lean: 0 deg}", 1e-3, &err);
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(err.msg, "cannot reach");
    CHECK_STR_CONTAINS(err.msg, "arm");
    printf("  refused: %s\n", err.msg);
    /* a missing mount point is named */
    err = (mcs_error){0};
    snprintf(txt, sizeof txt,
             "mcrash: 1\ninclude: [models/riders/hybrid3_50th.yaml]\n"
             "simulation: {end_time: 1 ms}\nrider: {torso_lean: 40 deg}\n");
    m = build_text("scenarios/rider_nobike.yaml", txt, &err);
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(err.msg, "seat_h_point");
    CHECK_STR_CONTAINS(err.msg, "rider_nobike.yaml");
}

/* under gravity the seated rider settles on the seat, pegs and grips: no energy growth (the
 * engine's growth stop would end the run), the energy balance closes, the attachments hold
 * and the H-point stays within a few cm of the seat point */
static void test_seated_settles(void)
{
    mcs_error err = {0};
    mb_model *m = seated("{torso_lean: 40 deg}", 0.2, &err);
    CHECK(m != NULL);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK(m->nattach == 5);
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    mcs_status st = MCS_OK;
    double e0 = s->e.total, emax = e0;
    while (s && !st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        emax = fmax(emax, s->e.total);
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    int broken = 0;
    for (int i = 0; s && i < m->nattach; i++) broken += s->att[i].broken;
    int pel = mb_model_body(m, "rider_pelvis"), fr = mb_model_body(m, "moto_frame");
    mb_body_kin kp, kf;
    mb_body_get(s->world, pel, &kp);
    mb_body_get(s->world, fr, &kf);
    double rel0[3], rel[3], d[3];
    mb_sub(m->body[pel].pos, m->body[fr].pos, rel0);
    mb_sub(kp.pos, kf.pos, rel);
    mb_sub(rel, rel0, d);
    printf("  seated 0.2 s: energy drift %.3g, total grew at most %.3g J of %.1f J kinetic+stored "
           "reference, pelvis moved %.1f mm relative to the frame, %d attachments broken\n",
           mb_energy_drift(m, s), emax - e0, s->e_ref, 1e3 * mb_norm(d), broken);
    CHECK(mb_energy_drift(m, s) < 1e-2);
    CHECK(broken == 0);
    CHECK(mb_norm(d) < 0.05);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_mass_and_segments);
    RUN(test_positioning);
    RUN(test_seated_settles);
    TEST_END();
}

/* test_rider.c: the Hybrid III 50th-class rider (scenarios/models/riders/, docs/rider.md):
 * mass and segments against the H3 50th (78.2 kg, NHTSA) and de Leva (1996); the
 * positioning step (hands on the grips, feet on the pegs, pelvis on the seat: residuals
 * against the closed-form two-link solution); the seated rider under gravity; the neck and
 * the joint ranges. The figures docs/rider.md states are asserted with FIG (tests/figures.h). */
#include "harness.h"
#include "tests/figures.h"
#include "tests/mb_test_util.h"
#include "stage1_mb/mb_loadcell.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_position.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RIDER "models/riders/hybrid3_50th.yaml" /* relative to scenarios/ */
#define RIDER7 "models/riders/hybrid3_50th_neck7.yaml"

/* H3 50th: 78.2 kg (NHTSA); the issue asks 78 +- 2 kg and at least 17 segments */
static void test_mass_and_segments(void)
{
    static const char *const need[] = {
        "rider_head",        "rider_neck",        "rider_upper_torso", "rider_lower_torso",
        "rider_pelvis",      "rider_upper_arm_l", "rider_upper_arm_r", "rider_lower_arm_l",
        "rider_lower_arm_r", "rider_hand_l",      "rider_hand_r",      "rider_thigh_l",
        "rider_thigh_r",     "rider_lower_leg_l", "rider_lower_leg_r", "rider_foot_l",
        "rider_foot_r"};
    mb_model *m = mt_rider_alone(RIDER);
    CHECK(m != NULL);
    if (!m) return;
    int n = 0;
    double mass = mt_rider_mass(m, &n);
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
    m = mt_rider_alone(RIDER7);
    CHECK(m != NULL);
    if (!m) return;
    mass = mt_rider_mass(m, &n);
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
    return mt_model_text("scenarios/rider_seated.yaml", txt, err);
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
    mb_model *m0 = mt_rider_alone(RIDER);
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
        if (side == 0) {
            FIG("rider.elbow_flex_deg", "%.1f", flex * 180 / M_PI);
            FIG("rider.elbow_hi_deg", "%.1f", r->hi * 180 / M_PI);
        }
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
    /* the distance and the chain's reach the message gives (docs/rider.md quotes it) */
    const char *at = strstr(err.msg, "target: ");
    double dist = 0, rmin = 0, rmax = 0;
    CHECK(at && sscanf(at, "target: %lf m away, the chain reaches %lf to %lf m", &dist, &rmin,
                       &rmax) == 3);
    CHECK(dist > rmax); /* refused because it is beyond the stretched arm */
    FIG("rider.reach_dist_m", "%.4f", dist);
    FIG("rider.reach_min_m", "%.4f", rmin);
    FIG("rider.reach_max_m", "%.4f", rmax);
    /* a missing mount point is named */
    err = (mcs_error){0};
    snprintf(txt, sizeof txt,
             "mcrash: 1\ninclude: [models/riders/hybrid3_50th.yaml]\n"
             "simulation: {end_time: 1 ms}\nrider: {torso_lean: 40 deg}\n");
    m = mt_model_text("scenarios/rider_nobike.yaml", txt, &err);
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
    /* no energy growth beyond the balance's own precision (its drift, 4e-5 of the reference):
     * the total at the output samples never rises above 1e-5 of the reference (1.2e-4 J here) */
    CHECK(emax - e0 <= 1e-5 * s->e_ref);
    CHECK(broken == 0);
    CHECK(mb_norm(d) < 0.05);
    FIG("rider.seated_drift", "%.1e", mb_energy_drift(m, s));
    FIG("rider.seated_pelvis_mm", "%.1f", 1e3 * mb_norm(d));
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the rider alone with one body fixed to the world, no gravity */
static mb_model *rider_fixed(const char *body, const char *file)
{
    char txt[1024];
    snprintf(txt, sizeof txt,
             "mcrash: 1\ninclude: [%s]\nsimulation: {end_time: 1 s, time_step: 10 us}\n"
             "environment: {gravity: 0 m/s^2}\n"
             "joints:\n"
             "  - {name: fix, type: fixed, parent: ground, child: %s, anchor: [0, 0, 0]}\n",
             file, body);
    mcs_error err = {0};
    mb_model *m = mt_model_text("scenarios/rider_fixed.yaml", txt, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    return m;
}

static int joint_named(const mb_model *m, const char *name)
{
    for (int j = 0; j < m->njoint; j++)
        if (!strcmp(m->joint[j].name, name)) return j;
    return -1;
}

/* give bodies a rigid rotation w about an axis point c: v = w x (p - c) */
static void spin(mb_model *m, const char *const *names, int n, const double w[3], const double c[3])
{
    for (int k = 0; k < n; k++) {
        int b = mb_model_body(m, names[k]);
        double r[3];
        mb_sub(m->body[b].pos, c, r);
        mb_cross(w, r, m->body[b].vel);
        mb_copy(w, m->body[b].angvel);
    }
}

/* the knee's range stops the lower leg: kicked into extension at 40 rad/s (kinetic energy E
 * about the knee) the restraint alone (30 N m at 0.2 rad, 60 N m at 1.5 rad, damping) cannot
 * hold it; the stop at the straight leg (-90 deg from the file's 90 deg flexion) does, within
 * sqrt(2 E / k_stop) with k_stop = 10 x 150 N m/rad (all of E into the stop: a bound); without
 * the stop the leg goes far past straight */
static void test_range_stops_limb(void)
{
    static const char *const leg[] = {"rider_lower_leg_l", "rider_foot_l"};
    double over[2] = {0, 0};
    for (int with_stop = 1; with_stop >= 0; with_stop--) {
        mb_model *m = rider_fixed("rider_thigh_l", RIDER);
        CHECK(m != NULL);
        if (!m) return;
        int jk = joint_named(m, "rider_knee_l");
        CHECK(jk >= 0 && m->joint[jk].restraint >= 0);
        if (jk < 0 || m->joint[jk].restraint < 0) {
            mb_model_destroy(&m);
            return;
        }
        mb_restraint_model *r = &m->restraint1[m->joint[jk].restraint];
        double lo = r->lo, kstop = r->stop_stiffness;
        if (!with_stop) r->stop_stiffness = 0, r->stop_damping = 0;
        double w[3] = {0, -40, 0}; /* about the knee axis +y: negative = extension */
        spin(m, leg, 2, w, m->joint[jk].anchor);
        m->nsteps = 30000; /* 0.3 s */
        mb_state *s = NULL;
        mcs_error err = {0};
        CHECK(mb_state_create(m, &s, &err) == MCS_OK);
        double qmin = 0, ke = s ? s->e.kinetic : 0;
        mcs_status st = MCS_OK;
        while (s && !st && s->step < m->nsteps) {
            st = mb_step(m, s, &err);
            qmin = fmin(qmin, s->r1[m->joint[jk].restraint].x);
        }
        CHECK(st == MCS_OK);
        over[with_stop] = lo - qmin;
        printf("  knee kicked into extension %s the stop: reaches %.3f rad (straight leg at %.3f "
               "rad), %.3f rad past it%s\n",
               with_stop ? "with" : "without", qmin, lo, lo - qmin,
               with_stop ? "" : " (no stop)");
        if (with_stop) {
            CHECK_NEAR(kstop, 1500, 1e-9);
            CHECK(lo - qmin > 0);                       /* it did reach the stop   */
            CHECK(lo - qmin < sqrt(2 * ke / kstop));    /* and the stop held it    */
            printf("  kick %.0f J; the stop alone would hold it within %.3f rad\n", ke,
                   sqrt(2 * ke / kstop));
            FIG("rider.knee_kick_j", "%.0f", ke);
            FIG("rider.knee_past_stop_rad", "%.2f", lo - qmin);
            FIG("rider.knee_stop_bound_rad", "%.2f", sqrt(2 * ke / kstop));
        }
        mb_state_destroy(&s);
        mb_model_destroy(&m);
    }
    CHECK(over[0] > 2 * over[1]);
    FIG("rider.knee_past_nostop_rad", "%.2f", over[0]);
}

/* neck flexion (the H3 neck-pendulum's direction and order of magnitude): the upper torso
 * held, the head and neck turning forward about T1 with the head CG at 6.89 m/s (the Part 572
 * flexion test's pendulum speed, taken whole as the head's speed relative to a stopped base:
 * an upper bound). The upper-neck cell must read flexion (My > 0) and tension-free shear of
 * the right sign; the head's largest forward rotation and the moment are printed against the
 * H3 flexion response, whose corridors were not retrieved (REFERENCES.md): of the order of
 * 70 deg and 100 N m. Asserted: the direction (flexion dominates) and the figures docs/rider.md
 * states, at the precision it shows (FIG); the comparison with the H3 stays in words */
static void test_neck_flexion(void)
{
    static const char *const hn[] = {"rider_neck", "rider_head"};
    mb_model *m = rider_fixed("rider_upper_torso", RIDER);
    CHECK(m != NULL);
    if (!m) return;
    int jl = joint_named(m, "rider_lower_neck"), head = mb_model_body(m, "rider_head");
    int cell = -1;
    for (int i = 0; i < m->nloadcell; i++) cell = i; /* find "neck" below */
    (void)cell;
    double r[3];
    mb_sub(m->body[head].pos, m->joint[jl].anchor, r);
    double w[3] = {0, 6.89 / mb_norm(r), 0}; /* +y turns z towards +x: forward */
    spin(m, hn, 2, w, m->joint[jl].anchor);
    m->nsteps = 20000; /* 0.2 s */
    mb_state *s = NULL;
    mcs_error err = {0};
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    double rot_max = 0, my_max = -1e30, my_min = 1e30, t_rot = 0;
    int neck_cell = 0; /* the rider file's load cells: neck first */
    mcs_status st = MCS_OK;
    while (s && !st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        const double *R = s->kin[head].rot;
        double pitch = atan2(R[2], R[8]);
        if (pitch > rot_max) rot_max = pitch, t_rot = s->t;
        double v[6];
        mb_loadcell_value(m, s, neck_cell, v);
        my_max = fmax(my_max, v[4]), my_min = fmin(my_min, v[4]);
    }
    CHECK(st == MCS_OK);
    printf("  neck flexion at 6.89 m/s: head turns forward %.1f deg at %.1f ms; upper-neck My "
           "%.1f ... %.1f N m (flexion > 0)\n",
           rot_max * 180 / M_PI, t_rot * 1e3, my_min, my_max);
    CHECK(rot_max > 0 && my_max > 0); /* the head turns forward, the cell reads flexion */
    CHECK(my_max > -my_min);          /* flexion dominates */
    FIG("rider.neck_flex_deg", "%.1f", rot_max * 180 / M_PI);
    FIG("rider.neck_flex_t_ms", "%.0f", t_rot * 1e3);
    FIG("rider.neck_my_max", "%.1f", my_max);
    FIG("rider.neck_my_min", "%.1f", my_min);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the helmet (MYMOSA's 3-mass model): 1.4 kg more, seated with the head (its couplings at
 * rest: the relative pose to the head kept exactly), settling on the motorcycle */
static void test_helmet(void)
{
    mb_model *m = mt_rider_alone("models/riders/hybrid3_50th_helmet.yaml");
    CHECK(m != NULL);
    if (!m) return;
    int n = 0;
    double mass = mt_rider_mass(m, &n);
    printf("  rider with the helmet: %d bodies, %.3f kg\n", n, mass);
    CHECK(n == 19);
    CHECK_NEAR(mass, 78.2 + 1.4, 1e-9);
    FIG("rider.helmet_mass_kg", "%.1f", mass);
    int h0 = mb_model_body(m, "rider_head"), s0 = mb_model_body(m, "rider_helmet_shell");
    double d0[3];
    mb_sub(m->body[s0].pos, m->body[h0].pos, d0);
    mb_model_destroy(&m);
    mcs_error err = {0};
    m = mt_rider_seated_helmet("scenarios/rider_helmet.yaml",
                               "models/riders/hybrid3_50th_helmet.yaml", &err);
    CHECK(m != NULL);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    double e = mt_helmet_offset_error(m, d0);
    printf("  seated with the helmet: shell offset from the head kept to %.2g m\n", e);
    CHECK(e < 1e-12);
    mb_state *s = NULL;
    CHECK(mt_run(m, &s, &err) == MCS_OK);
    if (s) {
        double f = mt_helmet_coupling_force(m, s);
        printf("  after 50 ms seated: largest helmet coupling force %.1f N (the helmet's weight "
               "%.1f N shared by three)\n", f, 1.4 * 9.81);
        CHECK(f < 1.4 * 9.81 * 2);
        FIG("rider.helmet_coupling_n", "%.1f", f);
    }
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_mass_and_segments);
    RUN(test_positioning);
    RUN(test_seated_settles);
    RUN(test_range_stops_limb);
    RUN(test_neck_flexion);
    RUN(test_helmet);
    TEST_END();
}

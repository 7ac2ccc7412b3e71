/* test_rider_sizes.c: the Hybrid III 5th female and 95th male class riders next to the 50th
 * (issue 13 item 6; scenarios/models/riders/hybrid3_05f.yaml, hybrid3_95m.yaml, written by
 * scripts/gen_rider.py; docs/rider.md "Sizes"): total and assembly masses and key dimensions
 * against the published values (sources at each number), the seated posture on sport_208kg by
 * the same rider: block (mount points at round-off, no rider contact penetrating at t = 0),
 * the 413 scenario pairs running, and the dummy-size selection of the injury evaluation (Nij
 * intercepts and limits per size, checked against Mertz's scaling law). */
#include "harness.h"
#include "analysis/an_criteria.h"
#include "analysis/an_injury.h"
#include "analysis/an_limits.h"
#include "core/mcs_scenario.h"
#include "fe/fe_model.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_model.h"
#include "stage2_fe/s2_scenario.h"
#include "stage1_mb/mb_position.h"
#include "stage1_mb/mb_vec.h"
#include "tests/figures.h"
#include "tests/mb_test_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define LB 0.45359237 /* [kg/lb] */
#define INCH 0.0254   /* [m/in] */

typedef struct {
    const char *tag;    /* figure key part: "05f", "50m", "95m" */
    const char *model;  /* rider model file, relative to scenarios/ */
    double mass;        /* published total mass [kg] */
    double stature;     /* published stature [m] */
    double sitting;     /* published erect sitting height [m], 0 = none retrieved */
    const char *fig[4]; /* figure keys (literal, tests/test_figures.c): mass, sitting height,
                           stature, thighs' clearance to the frame at t = 0 */
} size_ref;

/* NHTSA, "Hybrid III 5th Percentile Female" and "... 50th Percentile Male" physical data pages:
 * 108.0 lb / 172.3 lb, stature 59.1 / 69.0 in, sitting height 31.0 / 34.8 in (the 50th's
 * 78.2 kg of REFERENCES.md is the model's). 95th male: 223 lb, 188 cm (74 in) (Wikipedia
 * "Hybrid III"; secondary, [S] in docs/rider.md); its sitting height was not retrieved. */
static const size_ref sizes[3] = {
    {"05f",
     "models/riders/hybrid3_05f.yaml",
     108.0 * LB,
     59.1 * INCH,
     31.0 * INCH,
     {"rider.size_05f_mass_kg", "rider.size_05f_sit_m", "rider.size_05f_stature_m",
      "rider.size_05f_thigh_gap_mm"}},
    {"50m",
     "models/riders/hybrid3_50th.yaml",
     78.2,
     69.0 * INCH,
     34.8 * INCH,
     {"rider.size_50m_mass_kg", "rider.size_50m_sit_m", "rider.size_50m_stature_m",
      "rider.size_50m_thigh_gap_mm"}},
    {"95m",
     "models/riders/hybrid3_95m.yaml",
     223.0 * LB,
     74.0 * INCH,
     0,
     {"rider.size_95m_mass_kg", "rider.size_95m_sit_m", "rider.size_95m_stature_m",
      "rider.size_95m_thigh_gap_mm"}},
};

static double body_mass(const mb_model *m, const char *name)
{
    int b = mb_model_body(m, name);
    return b >= 0 ? m->body[b].mass : NAN;
}

/* the ellipsoid surface of body `name` (the rider files give one per segment) */
static const mb_surface *surf_of(const mb_model *m, const char *name)
{
    int b = mb_model_body(m, name);
    for (int s = 0; b >= 0 && s < m->nsurf; s++)
        if (m->surf[s].body == b) return &m->surf[s];
    return NULL;
}

/* a joint anchor of the reference posture (the file's), coordinate k [m] */
static double anchor_k(const mb_model *m, const char *joint, int k)
{
    for (int j = 0; j < m->njoint; j++)
        if (strcmp(m->joint[j].name, joint) == 0) return m->joint[j].anchor[k];
    return NAN;
}
static double anchor_z(const mb_model *m, const char *joint)
{
    return anchor_k(m, joint, 2);
}
static double anchor_x(const mb_model *m, const char *joint)
{
    return anchor_k(m, joint, 0);
}

/* key dimensions of the reference posture (seated upright, docs/rider.md): sitting height =
 * head top over the seat surface, the seat 0.09 m below the hip centres (the [A] of
 * docs/rider.md, for every size); stature = the same standing: head top over the hip centres
 * + thigh + shank + ankle height (ankle 70 mm x the leg factor above the heel) */
static void dims(const mb_model *m, double *sit, double *stat)
{
    const mb_surface *hs = surf_of(m, "rider_head");
    int h = mb_model_body(m, "rider_head");
    double top = m->body[h].pos[2] + hs->center[2] + hs->semi[2];
    double hip = anchor_z(m, "rider_hip_l");
    double thigh = anchor_x(m, "rider_knee_l") - anchor_x(m, "rider_hip_l");
    double shank = anchor_z(m, "rider_knee_l") - anchor_z(m, "rider_ankle_l");
    double ankle = 0.07 * shank / (0.4340 * 1.75 / 1.741); /* heel 70 mm x kl below the ankle */
    *sit = top - (hip - 0.09);
    *stat = top - hip + thigh + shank + ankle;
}

static void test_mass_and_dimensions(void)
{
    for (int k = 0; k < 3; k++) {
        const size_ref *z = &sizes[k];
        mb_model *m = mt_rider_alone(z->model);
        CHECK(m != NULL);
        if (!m) continue;
        int n;
        double mass = mt_rider_mass(m, &n), sit, stat;
        dims(m, &sit, &stat);
        printf("  %s: %d segments, %.4f kg (published %.3f), sitting height %.4f m (%.4f), "
               "stature %.4f m (%.4f)\n",
               z->tag, n, mass, z->mass, sit, z->sitting, stat, z->stature);
        CHECK(n == 17 && m->njoint == 16);
        /* published total mass: the 5th's assembly weights sum to 108.03 lb against the
         * 108.0 lb total, the 95th's 223 lb; within 0.1 % */
        CHECK(fabs(mass / z->mass - 1) < 1e-3);
        FIG(z->fig[0], "%.2f", mass);
        FIG(z->fig[1], "%.3f", sit);
        FIG(z->fig[2], "%.3f", stat);
        /* sitting height: the 5th's trunk factor is chosen for 31.0 in (so within 1 mm by
         * construction); the 50th's de Leva trunk gives 0.889 against 0.884 m (docs/rider.md);
         * the 95th's is the 50th's x 74/69 (Mertz's geometric scaling), no published value */
        if (k == 0) CHECK_NEAR(sit, z->sitting, 1e-3);
        if (k == 1) CHECK_NEAR(sit, z->sitting, 0.006);
        if (k == 2) CHECK_NEAR(sit, 0.884 * 74.0 / 69.0, 0.006);
        /* stature, never set directly (legs from de Leva's lengths x the leg factor): within
         * 2 % of the published value for each size */
        CHECK(fabs(stat / z->stature - 1) < 0.02);
        mb_model_destroy(&m);
    }
}

/* the 5th female's assembly weights [N5] (NHTSA H3 5th female page, lb): head 8.23, neck 2.0,
 * upper torso 26.5, lower torso 29.2 (the model's lower torso + pelvis), upper arms 5.2, lower
 * arms and hands 5.2, upper legs 13.8, lower legs and feet 17.9 (both sides) */
static void test_assemblies_05f(void)
{
    mb_model *m = mt_rider_alone(sizes[0].model);
    CHECK(m != NULL);
    if (!m) return;
    CHECK_NEAR(body_mass(m, "rider_head"), 8.23 * LB, 1e-6);
    CHECK_NEAR(body_mass(m, "rider_neck"), 2.0 * LB, 1e-6);
    CHECK_NEAR(body_mass(m, "rider_upper_torso"), 26.5 * LB, 1e-5);
    CHECK_NEAR(body_mass(m, "rider_lower_torso") + body_mass(m, "rider_pelvis"), 29.2 * LB, 1e-5);
    CHECK_NEAR(2 * body_mass(m, "rider_upper_arm_l"), 5.2 * LB, 1e-5);
    CHECK_NEAR(2 * (body_mass(m, "rider_lower_arm_l") + body_mass(m, "rider_hand_l")), 5.2 * LB,
               1e-5);
    CHECK_NEAR(2 * body_mass(m, "rider_thigh_l"), 13.8 * LB, 1e-5);
    CHECK_NEAR(2 * (body_mass(m, "rider_lower_leg_l") + body_mass(m, "rider_foot_l")), 17.9 * LB,
               1e-5);
    /* head width 5.6 in and depth 7.2 in [N5]: the head ellipsoid's */
    const mb_surface *hs = surf_of(m, "rider_head");
    CHECK_NEAR(2 * hs->semi[0], 7.2 * INCH, 1e-6);
    CHECK_NEAR(2 * hs->semi[1], 5.6 * INCH, 1e-6);
    mb_model_destroy(&m);
}

#define SEAT_HEAD                                                                                  \
    "mcrash: 1\n"                                                                                  \
    "include: [models/motorcycles/sport_208kg.yaml, %s]\n"                                         \
    "environment: {gravity: 9.81 m/s^2, ground: {height: 0 m, friction: 0.9}}\n"                   \
    "simulation: {end_time: %g s, time_step: 10 us, output_rate: 10 kHz}\n"                        \
    "rider: {torso_lean: 40 deg}\n"                                                                \
    "contacts:\n"                                                                                  \
    "  - {a: rider_pelvis, b: moto_frame, characteristic: seat}\n"                                 \
    "  - {a: rider_thigh_l, b: moto_frame, characteristic: tank}\n"                                \
    "  - {a: rider_thigh_r, b: moto_frame, characteristic: tank}\n"                                \
    "  - {a: rider_lower_torso, b: moto_frame, characteristic: tank}\n"                            \
    "  - {a: rider_upper_torso, b: moto_upper_fork, characteristic: handlebar_end}\n"              \
    "  - {a: rider_head, b: moto_upper_fork, characteristic: handlebar_end}\n"

/* clearance of two placed ellipsoids: the uniform growth of b's semi-axes at which they touch
 * (bisection to 0.01 mm; the distance itself for a sphere b) [m] */
static double ell_gap(const mb_ellipsoid *a, const mb_ellipsoid *b)
{
    double lo = 0, hi = 0.2;
    while (hi - lo > 1e-5) {
        double mid = 0.5 * (lo + hi);
        mb_ellipsoid e = *b;
        for (int k = 0; k < 3; k++)
            e.semi[k] += mid;
        mb_contact c = {0};
        mb_geom_ellipsoid_ellipsoid(a, &e, NULL, &c);
        if (c.depth > 0)
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

/* at t = 0 (after the positioning): the deepest penetration of any pair of a rider body [m]
 * (every pair's listed), and the thighs' smallest clearance to the motorcycle's frame
 * surfaces (seat, tank) [m] */
static int initial_depths(const mb_model *m, double *depth, double *thigh_gap)
{
    mb_state *s = NULL;
    mcs_error err = {0};
    *depth = 0, *thigh_gap = INFINITY;
    if (mb_state_create(m, &s, &err)) return -1;
    mb_contact_detect(m, s);
    for (int p = 0; p < m->npair; p++) {
        const char *name = m->contact[m->pair[p].contact].name;
        int ba = m->pair[p].ba, bb = m->pair[p].bb;
        if (strncmp(m->body_name[ba], "rider_", 6) != 0 &&
            (bb < 0 || strncmp(m->body_name[bb], "rider_", 6) != 0))
            continue;
        double d = s->pc[p].depth;
        if (d > 0) printf("    %s at t = 0: %.2f mm\n", name, d * 1e3);
        *depth = fmax(*depth, d);
        const mb_surface *sa = &m->surf[m->pair[p].sa], *sb = &m->surf[m->pair[p].sb];
        if (strncmp(name, "rider_thigh_", 12) == 0 && bb >= 0 &&
            strcmp(m->body_name[bb], "moto_frame") == 0 && sa->type == MB_SURF_ELLIPSOID &&
            sb->type == MB_SURF_ELLIPSOID && d <= 0)
            *thigh_gap =
                fmin(*thigh_gap, ell_gap(&s->surf_ell[m->pair[p].sa], &s->surf_ell[m->pair[p].sb]));
    }
    mb_state_destroy(&s);
    return 0;
}

/* seated by the same rider: block as the 50th (40 deg lean on sport_208kg): mount points at
 * round-off; at t = 0 no rider contact penetrates (the seat's nose once held 21-31 mm of each
 * thigh, docs/rider.md "Seating"), the thighs within a few mm of the seat or tank; 0.2 s seated
 * under gravity without breaking an attachment */
static void test_seated(void)
{
    static const int order[3] = {1, 0, 2}; /* the 50th first */
    for (int i = 0; i < 3; i++) {
        const size_ref *z = &sizes[order[i]];
        char txt[2048];
        snprintf(txt, sizeof txt, SEAT_HEAD, z->model, 0.2);
        mb_model *m = mt_model_text("scenarios/rider_sizes_seated.yaml", txt, NULL);
        CHECK(m != NULL);
        if (!m) continue;
        double depth = NAN, gap = NAN;
        CHECK(initial_depths(m, &depth, &gap) == 0);
        printf("  %s seated: mount-point residual %.3g m; at t = 0 deepest rider contact %.2f mm, "
               "thighs %.2f mm from the seat or tank\n",
               z->tag, m->rider_residual, depth * 1e3, gap * 1e3);
        CHECK(m->rider_residual >= 0 && m->rider_residual < 1e-12);
        CHECK(depth == 0);
        CHECK(gap > 0 && gap < 0.015); /* the thighs rest against the frame, not far off */
        FIG(z->fig[3], "%.1f", gap * 1e3);
        mb_state *s = NULL;
        mcs_error err = {0};
        mcs_status st = mt_run(m, &s, &err);
        if (st) fprintf(stderr, "%s\n", err.msg);
        CHECK(st == MCS_OK);
        int broken = 0;
        for (int a = 0; s && a < m->nattach; a++)
            broken += s->att[a].broken;
        CHECK(broken == 0);
        if (s)
            printf("    0.2 s seated: energy drift %.2e, %d attachments broken\n",
                   mb_energy_drift(m, s), broken);
        mb_state_destroy(&s);
        mb_model_destroy(&m);
    }
}

/* ---- injury limits per size (analysis/an_limits.c, an_nij.c) ---- */

/* the size-specific values against Mertz's scaling law (Mertz, Irwin, Prasad 2003, Stapp 47:
 * equal density and modulus, force ~ lambda^2, moment ~ lambda^3, length ~ lambda): the 5th's
 * FMVSS 208 neck values share one lambda (0.7937, from its flexion intercept 155 / 310 N m,
 * REFERENCES.md), its chest deflection and femur limits another (52 / 63 mm); the 95th's
 * intercepts (unverified) and its scaled tension and compression one lambda (1.0987, from the
 * tension intercept). An independent check of the table, not of the code's arithmetic. */
static void test_limits_scaling(void)
{
    an_nij_opts n50 = an_nij_opts_dummy(AN_DUMMY_H3_50M), n05 = an_nij_opts_dummy(AN_DUMMY_H3_05F),
                n95 = an_nij_opts_dummy(AN_DUMMY_H3_95M);
    CHECK(n50.fz_tension == 6806 && n05.fz_tension == 4287 && n95.fz_tension == 8216);
    double l05 = cbrt(n05.my_flexion / n50.my_flexion);
    printf("  lambda 5th (neck) %.4f\n", l05);
    CHECK(fabs(n05.fz_tension / n50.fz_tension / (l05 * l05) - 1) < 0.005);
    CHECK(fabs(n05.fz_compression / n50.fz_compression / (l05 * l05) - 1) < 0.005);
    CHECK(fabs(n05.my_extension / n50.my_extension / (l05 * l05 * l05) - 1) < 0.01);
    const char *keys[2] = {"neck_tension", "neck_compression"};
    for (int k = 0; k < 2; k++) {
        double r = an_limit_find_dummy(keys[k], AN_DUMMY_H3_05F)->limit /
                   an_limit_find_dummy(keys[k], AN_DUMMY_H3_50M)->limit;
        CHECK(fabs(r / (l05 * l05) - 1) < 0.005);
    }
    double lb = an_limit_find_dummy("chest_deflection", AN_DUMMY_H3_05F)->limit /
                an_limit_find_dummy("chest_deflection", AN_DUMMY_H3_50M)->limit;
    double rf = an_limit_find_dummy("femur_compression", AN_DUMMY_H3_05F)->limit /
                an_limit_find_dummy("femur_compression", AN_DUMMY_H3_50M)->limit;
    CHECK(fabs(rf / (lb * lb) - 1) < 0.005);
    double l95 = sqrt(n95.fz_tension / n50.fz_tension);
    printf("  lambda 95th (neck) %.4f\n", l95);
    CHECK(fabs(n95.fz_compression / n50.fz_compression / (l95 * l95) - 1) < 0.005);
    CHECK(fabs(n95.my_flexion / n50.my_flexion / (l95 * l95 * l95) - 1) < 0.01);
    CHECK(fabs(n95.my_extension / n50.my_extension / (l95 * l95 * l95) - 1) < 0.01);
    for (int k = 0; k < 2; k++) {
        double r = an_limit_find_dummy(keys[k], AN_DUMMY_H3_95M)->limit /
                   an_limit_find_dummy(keys[k], AN_DUMMY_H3_50M)->limit;
        CHECK(fabs(r / (l95 * l95) - 1) < 0.005);
    }
    /* a key without a size-specific row falls back to the 50th's; the names round-trip */
    CHECK(an_limit_find_dummy("hic15", AN_DUMMY_H3_05F) == an_limit_find("hic15"));
    for (int d = 0; d < AN_NDUMMY; d++) {
        an_dummy e = AN_NDUMMY;
        CHECK(an_dummy_parse(an_dummy_name((an_dummy)d), &e) == 0 && e == (an_dummy)d);
    }
    an_dummy e = AN_DUMMY_H3_95M;
    CHECK(an_dummy_parse("50th", &e) == -1 && e == AN_DUMMY_H3_95M);
}

/* ---- the 413 scenario pairs (scenarios/iso13232_413-0_13.4_sedan_rider*.yaml) ---- */

typedef struct {
    const char *file, *base; /* the size variant and the 50th's scenario it was copied from */
    const char *dummy;       /* its rider: {dummy: } */
    double t_short;          /* make test run [s]; the whole 300 ms under make verify */
    const char *fig[2];      /* verify-only figure keys: HIC15, Nij (the size's intercepts) */
} scn_pair;

static const scn_pair pairs[4] = {
    {"iso13232_413-0_13.4_sedan_rider_05f.yaml",
     "iso13232_413-0_13.4_sedan_rider.yaml",
     "5th_female",
     0.05,
     {"rider.v413_05f_hic15", "rider.v413_05f_nij"}},
    {"iso13232_413-0_13.4_sedan_rider_95m.yaml",
     "iso13232_413-0_13.4_sedan_rider.yaml",
     "95th_male",
     0.05,
     {"rider.v413_95m_hic15", "rider.v413_95m_nij"}},
    {"iso13232_413-0_13.4_sedan_rider_concept_05f.yaml",
     "iso13232_413-0_13.4_sedan_rider_concept.yaml",
     "5th_female",
     0.01,
     {"rider.v413c_05f_hic15", "rider.v413c_05f_nij"}},
    {"iso13232_413-0_13.4_sedan_rider_concept_95m.yaml",
     "iso13232_413-0_13.4_sedan_rider_concept.yaml",
     "95th_male",
     0.05, /* past the pretensioners' pay-in (12 + 15 ms): the belts routed for the 95th */
     {"rider.v413c_95m_hic15", "rider.v413c_95m_nij"}},
};

/* the row of criterion key, NULL when absent */
static const an_injury_row *row_of(const an_injury_row *r, int n, const char *key)
{
    for (int i = 0; i < n; i++)
        if (strcmp(r[i].key, key) == 0) return &r[i];
    return NULL;
}

/* each variant: the base's contacts (same names, same order: the copy is in step), seated with
 * no rider contact penetrating at t = 0, a run that finishes, a results file
 * carrying the dummy size, and `mcrash injury`'s rows for that size (Nij and limits) */
static void test_scenario_pairs(void)
{
    for (int k = 0; k < 4; k++) {
        const scn_pair *p = &pairs[k];
        char path[256], base[256], txt[512];
        snprintf(path, sizeof path, "scenarios/%s", p->file);
        snprintf(base, sizeof base, "scenarios/%s", p->base);
        mb_model *m = mt_model_file(path), *mb = mt_model_file(base);
        CHECK(m != NULL && mb != NULL);
        if (!m || !mb) {
            mb_model_destroy(&m), mb_model_destroy(&mb);
            continue;
        }
        CHECK(m->ncontact == mb->ncontact);
        for (int c = 0; c < m->ncontact && c < mb->ncontact; c++)
            CHECK(strcmp(m->contact[c].name, mb->contact[c].name) == 0);
        CHECK(strcmp(m->rider_dummy, p->dummy) == 0);
        CHECK(strcmp(mb->rider_dummy, "50th_male") == 0);
        double depth, gap;
        CHECK(initial_depths(m, &depth, &gap) == 0);
        CHECK(depth == 0);
        mb_model_destroy(&m), mb_model_destroy(&mb);

        /* the run: 300 ms under make verify, else a short one */
        double t_end = th_verify() ? 0.3 : p->t_short;
        snprintf(txt, sizeof txt, "mcrash: 1\ninclude: [%s]\nsimulation: {end_time: %g s}\n",
                 p->file, t_end);
        m = mt_model_text("scenarios/rider_sizes_run.yaml", txt, NULL);
        CHECK(m != NULL);
        if (!m) continue;
        char out[128];
        snprintf(out, sizeof out, "/tmp/mcrash_rider_sizes_%d_%d.h5", k, (int)getpid());
        mb_run_opts o = {.out_path = out, .quiet = 1};
        mb_run_summary sum;
        mcs_error err = {0};
        mcs_status st = mb_run(m, &o, &sum, &err);
        if (st) fprintf(stderr, "%s: %s\n", p->file, err.msg);
        CHECK(st == MCS_OK);
        printf("  %s: %.0f ms in %.2f s wall, energy drift %.2e\n", p->file, sum.t_end * 1e3,
               sum.wall_time_s, sum.energy_drift);
        CHECK_NEAR(sum.t_end, t_end, 1e-9);
        mb_model_destroy(&m);
        if (st) continue;
        /* injury rows with the file's dummy size; Nij against the size's intercepts */
        an_injury_row *rows = NULL;
        int n = 0, used = 0;
        an_dummy d = AN_NDUMMY, want;
        CHECK(an_dummy_parse(p->dummy, &want) == 0);
        st = an_injury_evaluate_as(out, 1, -1, &rows, &n, &used, &d, &err);
        CHECK(st == MCS_OK && d == want);
        const an_injury_row *r = row_of(rows, n, "neck_tension");
        CHECK(r != NULL);
        if (r) CHECK_NEAR(r->limit, an_limit_find_dummy("neck_tension", want)->limit, 0);
        if (r && want == AN_DUMMY_H3_05F) CHECK_NEAR(r->limit, 2620, 0);
        const an_injury_row *hic = row_of(rows, n, "hic15"), *nij = row_of(rows, n, "nij");
        CHECK(hic && nij);
        if (hic && nij) printf("    HIC15 %.1f, %s %.3f\n", hic->value, nij->label, nij->value);
        if (th_verify() && hic && nij) {
            FIG(p->fig[0], "%.0f", hic->value);
            FIG(p->fig[1], "%.2f", nij->value);
        }
        free(rows);
        remove(out);
    }
}

/* the concept 95th includes the concept motorcycle and overrides the belts' routing by name
 * (core/mcs_scenario.h, the include rule): the overridden keys are its own (the values written
 * in the scenario), every other key of the belts and retractors is the model's (the values
 * written in models/motorcycles/sport_208kg_concept.yaml), and no entity was added */
static void test_concept_95m_overrides(void)
{
    mcs_scenario *s = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load("scenarios/iso13232_413-0_13.4_sedan_rider_concept_95m.yaml", &s, &err))
        fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    if (!s) return;
    const mcs_node *fe = mcs_node_get(mcs_scenario_root(s), "fe");
    const mcs_node *parts = mcs_node_get(fe, "parts"), *ret = mcs_node_get(fe, "retractors");
    CHECK(mcs_node_len(parts) == 5 && mcs_node_len(ret) == 2);
    const double y0[2] = {0.037, -0.264}, y1[2] = {0.264, -0.037}, ya[2] = {0.274, -0.274};
    for (int k = 0; k < 2 && mcs_node_len(parts) >= 2 && mcs_node_len(ret) == 2; k++) {
        const mcs_node *b = mcs_node_at(parts, k), *m = mcs_node_get(b, "mesh");
        const mcs_node *r = mcs_node_at(ret, k);
        CHECK(strcmp(mcs_node_str(mcs_node_get(b, "name")), k ? "belt_r" : "belt_l") == 0);
        double o[3], e[3], a[3];
        CHECK(!mcs_node_vec3(mcs_node_get(m, "origin"), o, &err) &&
              !mcs_node_vec3(mcs_node_get(m, "end"), e, &err) &&
              !mcs_node_vec3(mcs_node_get(r, "anchor"), a, &err));
        CHECK_NEAR(o[0], 0.66, 1e-15);
        CHECK_NEAR(o[1], y0[k], 1e-15);
        CHECK_NEAR(o[2], 0.921, 1e-15);
        CHECK_NEAR(e[1], y1[k], 1e-15);
        CHECK_NEAR(a[0], 0.66, 1e-15);
        CHECK_NEAR(a[1], ya[k], 1e-15);
        CHECK_NEAR(a[2], 0.62, 1e-15);
        /* from the model: mesh generator and divisions, section, retractor limit and payin */
        CHECK(strcmp(mcs_node_str(mcs_node_get(m, "generate")), "line") == 0);
        CHECK_NEAR(mcs_node_num(mcs_node_get(m, "divisions")), 10, 0);
        CHECK_NEAR(mcs_node_num(mcs_node_get(mcs_node_get(b, "section"), "area")), 60e-6, 1e-18);
        CHECK_NEAR(mcs_node_num(mcs_node_get(r, "load_limit")), 2000, 0);
        CHECK(mcs_node_curve_len(mcs_node_get(r, "payin")) == 2);
        CHECK_STR_CONTAINS(mcs_node_file(mcs_node_get(m, "divisions")), "sport_208kg_concept.yaml");
        CHECK_STR_CONTAINS(mcs_node_file(mcs_node_get(m, "origin")), "concept_95m.yaml");
    }
    mcs_scenario_destroy(&s);
}

/* ---- stage 2 of the concept case with the 5th female and the 95th male ---- */

/* iso13232_413-0_13.4_sedan_rider_concept_{05f,95m}_stage2.yaml: compiles
 * (stage2_fe/s2_scenario.h) and builds with the size seated, its dummy size kept (mass: the
 * published total, sizes[] above, within 0.1 %); the tank foam pads (placed for the 50th's
 * thighs, 22 mm clear) clear its thighs at t = 0 too (thigh ellipsoid to the pads' outer
 * nodes). The stage-2 runs: tests/test_stage2_verify.c. */
static void test_stage2_sizes(void)
{
    static const struct {
        const char *file, *dummy;
        const size_ref *size;
        const char *fig; /* pad gap [mm] */
    } s2[2] = {
        {"scenarios/iso13232_413-0_13.4_sedan_rider_concept_05f_stage2.yaml", "5th_female",
         &sizes[0], "rider.size_05f_pad_gap_mm"},
        {"scenarios/iso13232_413-0_13.4_sedan_rider_concept_95m_stage2.yaml", "95th_male",
         &sizes[2], "rider.size_95m_pad_gap_mm"},
    };
    for (int z = 0; z < 2; z++) {
        mcs_scenario *sc = NULL, *c2 = NULL;
        mcs_error err = {0};
        mb_model *m = NULL;
        if (mcs_scenario_load(s2[z].file, &sc, &err)) fprintf(stderr, "%s\n", err.msg);
        CHECK(sc != NULL);
        if (sc) CHECK(s2_scenario_compile(sc, &c2, &err) == MCS_OK);
        if (c2 && mb_model_build(c2, NULL, &m, &err)) fprintf(stderr, "%s\n", err.msg);
        CHECK(m != NULL && m->couple != NULL);
        if (m && m->couple) {
            CHECK(strcmp(m->rider_dummy, s2[z].dummy) == 0);
            CHECK(fabs(mt_rider_mass(m, &(int){0}) / s2[z].size->mass - 1) < 1e-3);
            const fe_model *fm = m->couple->fe.model;
            const char *pads[2] = {"pad_tank_l", "pad_tank_r"},
                       *thigh[2] = {"rider_thigh_l", "rider_thigh_r"};
            double gap = INFINITY;
            for (int k = 0; k < 2; k++) {
                int ip = -1;
                double g = mt_hex_face_gap(m, fm, pads[k], thigh[k], &ip);
                CHECK(ip >= 0);
                if (ip >= 0) gap = fmin(gap, g);
            }
            printf("  %s stage 2: tank pads %.1f mm from the thighs at t = 0\n", s2[z].dummy,
                   gap * 1e3);
            FIG(s2[z].fig, "%.0f", gap * 1e3);
            CHECK(gap > 0);
        }
        mb_model_destroy(&m);
        mcs_scenario_destroy(&c2);
        mcs_scenario_destroy(&sc);
    }
}

int main(void)
{
    RUN(test_mass_and_dimensions);
    RUN(test_assemblies_05f);
    RUN(test_seated);
    RUN(test_limits_scaling);
    RUN(test_scenario_pairs);
    RUN(test_concept_95m_overrides);
    RUN(test_stage2_sizes);
    TEST_END();
}

/* test_validation_stage1.c: the figures of docs/validation_stage1.md (issue 11), each from its
 * own run of a shipped scenario. Nothing in these scenarios is fitted to the runs below: the
 * MYMOSA car side is FMVSS 214's door crush minimum law, sized against MYMOSA's Eq. 4.1 by hand
 * in the doc; the attachment forces come from grip-strength data and stated assumptions. So
 * every comparison with a seed here is VALIDATION (held out), never a calibration check:
 *
 * 1. MYMOSA's lateral case, motorcycle only [seed 002 Sec. 4]: the energy the motorcycle-car
 *    system loses (against the hand value of Eq. 4.1 at the common velocity, 15.70 kJ, an upper
 *    bound), the fork's plastic work, the car's speed (<= the common velocity
 *    m1 v / (m1 + m2) = 208 x 13.4 / 1308 = 2.131 m/s while the motorcycle pushes), the
 *    contact forces the doc turns into the car's crush by hand.
 * 2. MYMOSA's lateral case with MYMOSA's rider (73.25 kg, 7-vertebra neck, helmet): the event
 *    times against MYMOSA's Fig. 5.2 (fork ~20 ms, wheel against the engine ~30 ms, detachment
 *    ~60 ms, head peak starting ~130 ms) with their errors; the tolerance the doc states for
 *    each figure is one unit of its last digit (FIG); the mechanism of the head peak (what the
 *    helmet strikes, when, at what speed).
 * 3. The 413-0/13.4 sedan cases: the motorcycle's pitch at 201 ms, reported next to the paper's
 *    15.1 deg [seed 001, Sec. 4: its stage-3 FE concept motorcycle, maximum at 201 ms]. */
#include "harness.h"
#include "analysis/an_cfc.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SMYM "scenarios/mymosa_lateral_car_1100kg.yaml"
#define SMYM_RIDER "scenarios/mymosa_lateral_car_1100kg_rider.yaml"
#define S413 "scenarios/iso13232_413-0_13.4_sedan.yaml"
#define S413_RIDER "scenarios/iso13232_413-0_13.4_sedan_rider.yaml"

typedef struct {
    double t_yield, t_stop, phi_max; /* fork: past its elastic limit, at 0.2 rad [s], [rad] */
    double w_fork;                   /* work of the fork restraint's load on the hinge [J] */
    double ke0, ke_vmax;             /* kinetic energy at t = 0, at the car's peak speed [J] */
    double w_moto_car;               /* work of the motorcycle-car contacts [J] */
    double f_tyre, f_frame;          /* peak normal force, front_tyre_car / frame_car [N] */
    double vcar_max, t_vcar_max;     /* car speed along the heading [m/s], when [s] */
    double pitch201;                 /* motorcycle frame pitch at 201 ms, nose down + [deg] */
    double pitch_max, t_pitch_max;   /* its largest over the run [deg], when [s] */
    double t_break[8];               /* attachment failures [s] */
    int nattach;
    double t_head, v_head;        /* helmet/head's first strike on the car [s], its speed [m/s] */
    double d_head, d_car, z_head; /* head CG and car travel along the heading to then, head
                                     CG height then [m] */
    char head_surf[64];           /* the surface it strikes */
    double t_road;                /* helmet/head's first contact with the road [s] */
    double head_g, t_head_g;      /* head resultant acceleration peak, CFC 1000 [g], [s] */
    double head_g2, t_head_g2;    /* the largest after 110 ms [g], [s] */
    double v_head130, z_head130;  /* head CG speed along the heading, height at 130 ms */
    double drift;
} run_figs;

static int prefixed(const char *name, const char *p)
{
    return strncmp(name, p, strlen(p)) == 0;
}

static int is_car(const mb_model *m, int b)
{
    return b >= 0 && prefixed(m->body_name[b], "car");
}

/* the head resultant acceleration [g] (CFC 1000, each axis filtered) of the recorded run */
static void head_peaks(const mb_model *m, const mb_state *s, run_figs *f)
{
    int hs = -1;
    for (int i = 0; i < m->nsensor; i++)
        if (strcmp(m->sensor[i].name, "head") == 0) hs = i;
    long n = s->nrec;
    if (hs < 0 || n < 16) return;
    double *x = malloc(sizeof(double) * (size_t)n * 4), *r = x + 3 * n;
    double dt = s->rec_t[2] - s->rec_t[1];
    mcs_error err = {0};
    for (int k = 0; k < 3; k++) {
        for (long i = 0; i < n; i++)
            x[k * n + i] = s->rec_sensor[(i * m->nsensor + hs) * 3 + k];
        /* the first sample (t = 0) precedes step 1's; filter from sample 1 */
        CHECK(an_cfc_filter(x + k * n + 1, (int)n - 1, dt, 1000, x + k * n + 1, &err) == MCS_OK);
    }
    for (long i = 1; i < n; i++) {
        r[i] = sqrt(x[i] * x[i] + x[n + i] * x[n + i] + x[2 * n + i] * x[2 * n + i]) / 9.80665;
        if (r[i] > f->head_g) f->head_g = r[i], f->t_head_g = s->rec_t[i];
        if (s->rec_t[i] > 0.11 && r[i] > f->head_g2) f->head_g2 = r[i], f->t_head_g2 = s->rec_t[i];
    }
    free(x);
}

/* run a scenario file, or (txt not NULL) a scenario text named path */
static mcs_status run_src(const char *path, const char *txt, run_figs *f)
{
    memset(f, 0, sizeof *f);
    f->t_yield = f->t_stop = f->t_head = f->t_road = NAN;
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mb_model *m = NULL;
    mb_state *s = NULL;
    mcs_status st = txt ? mcs_scenario_load_text(path, txt, strlen(txt), &scn, &err)
                        : mcs_scenario_load(path, &scn, &err);
    if (!st) st = mb_model_build(scn, NULL, &m, &err);
    mcs_scenario_destroy(&scn);
    if (!st) st = mb_state_create(m, &s, &err);
    if (st) {
        fprintf(stderr, "%s: %s\n", path, err.msg);
        mb_state_destroy(&s);
        mb_model_destroy(&m);
        return st;
    }
    int fk = -1, fr = mb_model_body(m, "moto_frame"), car = -1;
    for (int i = 0; i < m->nrestraint1; i++)
        if (strcmp(m->restraint1_name[i], "moto_fork_deformation") == 0) fk = i;
    for (int b = 0; b < m->nbody; b++)
        if (!strcmp(m->body_name[b], "car") || !strcmp(m->body_name[b], "sedan")) car = b;
    int head = mb_model_body(m, "rider_helmet_shell");
    if (head < 0) head = mb_model_body(m, "rider_head");
    int hcg = mb_model_body(m, "rider_head");
    double h[3] = {s->kin[fr].rot[0], s->kin[fr].rot[3], 0};
    mb_normalize(h);
    double *dprev = calloc((size_t)m->npair, sizeof(double)), xprev = 0;
    double ph0[3] = {0}, pc0[3] = {0};
    if (hcg >= 0) mb_copy(s->kin[hcg].pos, ph0);
    if (car >= 0) mb_copy(s->kin[car].pos, pc0);
    double *wp = calloc((size_t)m->npair * 2, sizeof(double)), *fp = wp + m->npair;
    f->ke0 = s->e.kinetic;
    while (!st && s->step < m->nsteps && !(st = mb_step(m, s, &err))) {
        if (fk >= 0) {
            double phi = fabs(s->r1[fk].x);
            f->w_fork -= s->r1[fk].load * (s->r1[fk].x - xprev);
            xprev = s->r1[fk].x;
            if (phi > f->phi_max) f->phi_max = phi;
            if (phi > m->restraint1[fk].spring.pos.elastic_limit && isnan(f->t_yield))
                f->t_yield = s->t;
            if (phi >= 0.2 && isnan(f->t_stop)) f->t_stop = s->t;
        }
        for (int p = 0; p < m->npair; p++) {
            const mb_pair *pr = &m->pair[p];
            double fn = s->pair[p].fn, d = s->pair[p].depth;
            int moto_car =
                pr->ba >= 0 && prefixed(m->body_name[pr->ba], "moto_") && is_car(m, pr->bb);
            if (moto_car) {
                /* work of the normal force on the penetration (both sides' deformation) */
                if (fn > 0 || dprev[p] > 0) f->w_moto_car += fn * (d - dprev[p]);
                if (fn > 0 || dprev[p] > 0) wp[p] += fn * (d - dprev[p]);
                if (fn > fp[p]) fp[p] = fn;
                const char *sa = m->surf[pr->sa].name;
                if (!strcmp(m->body_name[pr->ba], "moto_lower_fork") && fn > f->f_tyre)
                    f->f_tyre = fn;
                if (!strcmp(m->body_name[pr->ba], "moto_frame") && fn > f->f_frame) f->f_frame = fn;
                (void)sa;
            }
            dprev[p] = fn > 0 ? d : 0;
            if (head >= 0 && pr->ba == head && fn > 100) {
                if (is_car(m, pr->bb) && isnan(f->t_head)) {
                    f->t_head = s->t;
                    f->v_head = mb_dot(s->kin[hcg].vel, h);
                    double dh[3], dc[3];
                    mb_sub(s->kin[hcg].pos, ph0, dh);
                    mb_sub(s->kin[car].pos, pc0, dc);
                    f->d_head = mb_dot(dh, h), f->d_car = mb_dot(dc, h);
                    f->z_head = s->kin[hcg].pos[2];
                    snprintf(f->head_surf, sizeof f->head_surf, "%s", m->surf[pr->sb].name);
                }
                if (pr->bb < 0 && isnan(f->t_road)) f->t_road = s->t;
            }
        }
        double vc = car >= 0 ? mb_dot(s->kin[car].vel, h) : 0;
        if (vc > f->vcar_max) f->vcar_max = vc, f->t_vcar_max = s->t, f->ke_vmax = s->e.kinetic;
        if (hcg >= 0 && fabs(s->t - 0.130) < 0.5 * m->h)
            f->v_head130 = mb_dot(s->kin[hcg].vel, h), f->z_head130 = s->kin[hcg].pos[2];
        double pitch = -asin(s->kin[fr].rot[6]) * 180 / M_PI; /* x axis down: nose down + */
        if (fabs(s->t - 0.201) < 0.5 * m->h) f->pitch201 = pitch;
        if (pitch > f->pitch_max) f->pitch_max = pitch, f->t_pitch_max = s->t;
    }
    for (int p = 0; p < m->npair; p++)
        if (m->pair[p].ba >= 0 && prefixed(m->body_name[m->pair[p].ba], "moto_") &&
            is_car(m, m->pair[p].bb))
            f->w_moto_car += s->pair[p].e_damp + s->pair[p].e_fric;
    if (fk >= 0) f->w_fork += s->r1[fk].e_damp;
    if (getenv("VS1_DEBUG"))
        for (int p = 0; p < m->npair; p++)
            if (fp[p] > 0)
                printf("    pair %s/%s: peak %.1f kN, work %.0f J, damp %.0f, fric %.0f\n",
                       m->surf[m->pair[p].sa].name, m->surf[m->pair[p].sb].name, fp[p] / 1e3, wp[p],
                       s->pair[p].e_damp, s->pair[p].e_fric);
    free(wp);
    /* the rider's five (the helmet's couplings never break) */
    for (int i = 0; i < m->nattach && f->nattach < 8; i++)
        if (!strstr(m->attach_name[i], "helmet")) f->t_break[f->nattach++] = s->att[i].t_break;
    head_peaks(m, s, f);
    f->drift = mb_energy_drift(m, s);
    if (st) fprintf(stderr, "%s: %s\n", path, err.msg);
    free(dprev);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    return st;
}

static mcs_status run(const char *path, run_figs *f)
{
    return run_src(path, NULL, f);
}

/* relative error against a seed's time [%] */
static double err_pct(double t, double t_seed)
{
    return 100 * (t / t_seed - 1);
}

/* 1. motorcycle only. Eq. 4.1 by hand (docs/validation_stage1.md): 1/2 m1 v^2 = 18.67 kJ,
 * common velocity 2.131 m/s, kinetic energy left 2.97 kJ: at most 15.70 kJ lost. The run must
 * lose no more (the motorcycle still pushes into the car at 300 ms), the car must stay at or
 * below the common velocity (momentum: the road's friction only takes some), the balance close. */
static void test_mymosa_energy(void)
{
    run_figs f;
    CHECK(run(SMYM, &f) == MCS_OK);
    double common = 208 * 13.4 / 1308.0, eloss = (f.ke0 - f.ke_vmax) / 1e3;
    printf("  MYMOSA, motorcycle only: KE %.2f -> %.2f kJ at the car's peak speed (lost %.2f); "
           "fork work %.0f J, motorcycle-car contacts %.2f kJ; peak force tyre %.1f kN, frame "
           "%.1f kN; car %.3f m/s at %.1f ms (common %.3f); fork %.1f / %.1f ms; drift %.1e\n",
           f.ke0 / 1e3, f.ke_vmax / 1e3, eloss, f.w_fork, f.w_moto_car / 1e3, f.f_tyre / 1e3,
           f.f_frame / 1e3, f.vcar_max, f.t_vcar_max * 1e3, common, f.t_yield * 1e3, f.t_stop * 1e3,
           f.drift);
    /* 1/2 m1 v^2 = 18.67 kJ plus the wheels' spin (front 0.6, rear 0.9 kg m^2 [sport_208kg] at
     * v / r, r ~0.3 m: ~1.4 kJ) */
    CHECK(f.ke0 > 18674 && f.ke0 < 18674 + 1600);
    /* at most all but the common-velocity translational energy (2.97 kJ) goes */
    CHECK(f.ke_vmax >= 2970 - 10);
    CHECK(f.vcar_max <= common + 1e-3);
    CHECK(f.drift < 1e-3);
    FIG("validation_stage1.mym_ke0_kj", "%.2f", f.ke0 / 1e3);
    FIG("validation_stage1.mym_ke_lost_kj", "%.2f", eloss);
    FIG("validation_stage1.mym_t_vcar_max_ms", "%.1f", f.t_vcar_max * 1e3);
    FIG("validation_stage1.mym_fork_work_j", "%.0f", f.w_fork);
    FIG("validation_stage1.mym_contact_work_kj", "%.1f", f.w_moto_car / 1e3);
    FIG("validation_stage1.mym_f_tyre_kn", "%.1f", f.f_tyre / 1e3);
    FIG("validation_stage1.mym_f_frame_kn", "%.1f", f.f_frame / 1e3);
    FIG("validation_stage1.mym_vcar_max", "%.2f", f.vcar_max);
    FIG("validation_stage1.mym_moto_yield_ms", "%.1f", f.t_yield * 1e3);
    FIG("validation_stage1.mym_moto_stop_ms", "%.1f", f.t_stop * 1e3);
}

/* 2. MYMOSA's rider case, held out: event times against MYMOSA's Fig. 5.2 readings and the
 * mechanism of the head peak. Checked only for MYMOSA's order (fork yield, stop; all five
 * attachments fail; the helmet strikes the car after) and the energy balance: the figures and
 * their errors are stated in the doc (FIG: one unit of the last digit shown). */
static void test_mymosa_rider(void)
{
    run_figs f;
    CHECK(run(SMYM_RIDER, &f) == MCS_OK);
    double t_first = INFINITY, t_last = 0;
    for (int i = 0; i < f.nattach; i++) {
        CHECK(isfinite(f.t_break[i]));
        t_first = fmin(t_first, f.t_break[i]);
        t_last = fmax(t_last, f.t_break[i]);
    }
    printf(
        "  MYMOSA rider: fork %.1f / %.1f ms (~20 / ~30); attachments fail %.1f-%.1f ms (~60); "
        "helmet strikes %s at %.1f ms, head %.2f m/s along the heading, %.3f m travelled "
        "(car %.3f m), z %.3f m; road %.1f ms; head "
        "peak %.0f g at %.1f ms, after 110 ms %.0f g at %.1f ms (~130); head at 130 ms %.2f m/s, "
        "z %.3f m; car %.3f m/s; drift %.1e\n",
        f.t_yield * 1e3, f.t_stop * 1e3, t_first * 1e3, t_last * 1e3, f.head_surf, f.t_head * 1e3,
        f.v_head, f.d_head, f.d_car, f.z_head, f.t_road * 1e3, f.head_g, f.t_head_g * 1e3,
        f.head_g2, f.t_head_g2 * 1e3, f.v_head130, f.z_head130, f.vcar_max, f.drift);
    CHECK(f.t_yield < f.t_stop && f.nattach == 5);
    CHECK(isfinite(f.t_head) && f.t_head > t_last);
    CHECK(f.drift < 1e-3);
    FIG("validation_stage1.mymr_yield_ms", "%.1f", f.t_yield * 1e3);
    FIG("validation_stage1.mymr_yield_err", "%.0f", err_pct(f.t_yield, 0.020));
    FIG("validation_stage1.mymr_stop_ms", "%.1f", f.t_stop * 1e3);
    FIG("validation_stage1.mymr_stop_err", "%.0f", err_pct(f.t_stop, 0.030));
    FIG("validation_stage1.mymr_detach_first_ms", "%.1f", t_first * 1e3);
    FIG("validation_stage1.mymr_detach_last_ms", "%.1f", t_last * 1e3);
    FIG("validation_stage1.mymr_detach_first_err", "%.0f", err_pct(t_first, 0.060));
    FIG("validation_stage1.mymr_detach_last_err", "%.0f", err_pct(t_last, 0.060));
    FIG("validation_stage1.mymr_helmet_strike_ms", "%.1f", f.t_head * 1e3);
    FIG("validation_stage1.mymr_head_speed", "%.1f", f.v_head);
    FIG("validation_stage1.mymr_head_travel", "%.2f", f.d_head);
    FIG("validation_stage1.mymr_car_travel", "%.2f", f.d_car);
    FIG("validation_stage1.mymr_head_z", "%.2f", f.z_head);
    FIG("validation_stage1.mymr_head_g", "%.0f", f.head_g);
    FIG("validation_stage1.mymr_head_g_ms", "%.1f", f.t_head_g * 1e3);
    FIG("validation_stage1.mymr_head_g_err", "%.0f", err_pct(f.t_head_g, 0.130));
    FIG("validation_stage1.mymr_head_g2", "%.0f", f.head_g2);
    FIG("validation_stage1.mymr_head_g2_ms", "%.1f", f.t_head_g2 * 1e3);
    FIG("validation_stage1.mymr_head130_speed", "%.1f", f.v_head130);
}

/* 2b. Sensitivity of the head strike (the doc's mechanism section; not shipped scenarios): the
 * same MYMOSA rider case with the earlier fitted values put back one at a time -- the
 * attachments (grip 1000, peg 1000, seat 3000 N), the car side (10 kN at 150 mm), both -- and
 * the rider more upright (torso lean 30 deg instead of 40). */
static void test_mymosa_head_sensitivity(void)
{
    static const char *att = "rider: {torso_lean: 40 deg, grip_failure_force: 1000 N, "
                             "peg_failure_force: 1000 N, seat_failure_force: 3000 N}\n";
    static const char *side =
        "characteristics:\n"
        "  car_sill: {loading: [[0, 0], [150 mm, 10 kN], [300 mm, 24 kN], [450 mm, 32 kN], "
        "[550 mm, 120 kN]], unloading_slope: 2e6 N/m, elastic_limit: 10 mm, damping: 500 N s/m}\n"
        "  car_door: {loading: [[0, 0], [150 mm, 10 kN], [300 mm, 24 kN], [450 mm, 32 kN], "
        "[550 mm, 120 kN]], unloading_slope: 2e6 N/m, elastic_limit: 10 mm, damping: 500 N s/m}\n";
    static const char *upright = "rider: {torso_lean: 30 deg, grip_failure_force: 500 N, "
                                 "peg_failure_force: 500 N, seat_failure_force: 320 N}\n";
    const char *keys[4] = {"att", "side", "both", "lean30"};
    /* the figures' keys, literal (tests/test_figures.c finds them in the source) */
    const char *kd[4] = {"validation_stage1.sens_att_detach_last_ms",
                         "validation_stage1.sens_side_detach_last_ms",
                         "validation_stage1.sens_both_detach_last_ms",
                         "validation_stage1.sens_lean30_detach_last_ms"};
    const char *ks[4] = {
        "validation_stage1.sens_att_strike_ms", "validation_stage1.sens_side_strike_ms",
        "validation_stage1.sens_both_strike_ms", "validation_stage1.sens_lean30_strike_ms"};
    const char *kg[4] = {
        "validation_stage1.sens_att_head_g_ms", "validation_stage1.sens_side_head_g_ms",
        "validation_stage1.sens_both_head_g_ms", "validation_stage1.sens_lean30_head_g_ms"};
    for (int k = 0; k < 4; k++) {
        char txt[2048];
        snprintf(txt, sizeof txt,
                 "mcrash: 1\ninclude: [mymosa_lateral_car_1100kg_rider.yaml]\n%s%s",
                 k == 3   ? upright
                 : k != 1 ? att
                          : "",
                 k == 1 || k == 2 ? side : "");
        run_figs f;
        CHECK(run_src("scenarios/mymosa_sensitivity.yaml", txt, &f) == MCS_OK);
        double t0 = INFINITY, t1 = 0;
        for (int i = 0; i < f.nattach; i++)
            t0 = fmin(t0, f.t_break[i]), t1 = fmax(t1, f.t_break[i]);
        printf("  sensitivity %s: fork %.1f / %.1f ms; attachments %.1f-%.1f ms; helmet strikes %s "
               "at %.1f ms (%.2f m/s, z %.3f m); head peak %.0f g at %.1f ms\n",
               keys[k], f.t_yield * 1e3, f.t_stop * 1e3, t0 * 1e3, t1 * 1e3, f.head_surf,
               f.t_head * 1e3, f.v_head, f.z_head, f.head_g, f.t_head_g * 1e3);
        FIG(kd[k], "%.1f", t1 * 1e3);
        FIG(ks[k], "%.1f", f.t_head * 1e3);
        FIG(kg[k], "%.1f", f.t_head_g * 1e3);
        if (k == 1) {
            FIG("validation_stage1.sens_side_yield_ms", "%.1f", f.t_yield * 1e3);
            FIG("validation_stage1.sens_side_stop_ms", "%.1f", f.t_stop * 1e3);
        }
        if (k == 3) FIG("validation_stage1.sens_lean30_head_z", "%.2f", f.z_head);
    }
}

/* 3. The 413-0/13.4 pitch at 201 ms, without and with the rider, next to the paper's 15.1 deg
 * [seed 001 Sec. 4, Fig. 26 text: its stage-3 FE concept motorcycle, maximum at 201 ms]. A
 * report, not a match: a different motorcycle (crash box, high contact point). */
static void test_413_pitch(void)
{
    run_figs a, b;
    CHECK(run(S413, &a) == MCS_OK);
    CHECK(run(S413_RIDER, &b) == MCS_OK);
    printf("  413 pitch at 201 ms (nose down): %.1f deg alone, %.1f deg with the rider (paper "
           "15.1); largest %.1f deg at %.0f ms, %.1f deg at %.0f ms\n",
           a.pitch201, b.pitch201, a.pitch_max, a.t_pitch_max * 1e3, b.pitch_max,
           b.t_pitch_max * 1e3);
    CHECK(a.pitch201 > 0 && b.pitch201 > 0);
    FIG("validation_stage1.p413_pitch201", "%.1f", a.pitch201);
    FIG("validation_stage1.p413r_pitch201", "%.1f", b.pitch201);
    FIG("validation_stage1.p413_pitch_max", "%.1f", a.pitch_max);
    FIG("validation_stage1.p413_pitch_max_ms", "%.0f", a.t_pitch_max * 1e3);
    FIG("validation_stage1.p413r_pitch_max", "%.1f", b.pitch_max);
    FIG("validation_stage1.p413r_pitch_max_ms", "%.0f", b.t_pitch_max * 1e3);
    double t0 = INFINITY, t1 = 0;
    for (int i = 0; i < b.nattach; i++)
        t0 = fmin(t0, b.t_break[i]), t1 = fmax(t1, b.t_break[i]);
    FIG("validation_stage1.p413r_detach_first_ms", "%.1f", t0 * 1e3);
    FIG("validation_stage1.p413r_detach_last_ms", "%.1f", t1 * 1e3);
    FIG("validation_stage1.p413r_head_g", "%.0f", b.head_g);
    FIG("validation_stage1.p413r_head_g_ms", "%.1f", b.t_head_g * 1e3);
    FIG("validation_stage1.p413r_drift", "%.1e", b.drift);
}

int main(void)
{
    RUN(test_mymosa_energy);
    RUN(test_mymosa_rider);
    RUN(test_mymosa_head_sensitivity);
    RUN(test_413_pitch);
    TEST_END();
}

/* test_models.c: the shipped motorcycle and barrier models (scenarios/models/, docs/models.md)
 * and the thesis' rigid-barrier impacts (scenarios/thesis_*_barrier_13.4.yaml) on the stage-1
 * engine. Checks against the model's data sources (MYMOSA Table 1.1: 208 kg, wheelbase
 * 1420 mm, 7 bodies / 12 DOF), static equilibrium on the wheels, and the barrier impact:
 * completes, the motorcycle stops or rebounds, the fork keeps a permanent set (paper Fig. 7),
 * the energy balance closes. Figures measured are printed (they go into docs/models.md). */
#include "cli_util.h"
#include "core/mcs_results.h"
#include "harness.h"
#include "stage1_mb/mb_model.h"
#include "analysis/an_cfc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MOTO "scenarios/models/motorcycles/sport_208kg.yaml"
#define FRONTAL "scenarios/thesis_frontal_barrier_13.4.yaml"
#define OBLIQUE "scenarios/thesis_oblique_barrier_30deg_13.4.yaml"

static mb_model *build(mcs_scenario *scn)
{
    mcs_error err = {0};
    mb_model *m = NULL;
    if (scn && mb_model_build(scn, NULL, &m, &err)) fprintf(stderr, "build: %s\n", err.msg);
    return m;
}

static mb_model *load_model(const char *path)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load(path, &scn, &err)) fprintf(stderr, "%s: %s\n", path, err.msg);
    mb_model *m = build(scn);
    mcs_scenario_destroy(&scn);
    return m;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)n + 4096);
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) n = 0;
    if (buf) buf[n] = 0;
    fclose(f);
    return buf;
}

/* replace every occurrence of `from` in buf by `to` (to no longer than from) */
static int replace_all(char *buf, const char *from, const char *to)
{
    size_t lf = strlen(from), lt = strlen(to);
    int n = 0;
    for (char *p = strstr(buf, from); p; p = strstr(p + lt, from), n++) {
        memmove(p + lt, p + lf, strlen(p + lf) + 1);
        memcpy(p, to, lt);
    }
    return n;
}

static int find_body(const mb_model *m, const char *name)
{
    return mb_model_body(m, name);
}

static int find_restraint(const mb_model *m, const char *name)
{
    for (int i = 0; i < m->nrestraint1; i++)
        if (strcmp(m->restraint1_name[i], name) == 0) return i;
    return -1;
}

/* MYMOSA Table 1.1: 208 kg without dummy, wheelbase 1420 mm; Sec. 2: seven rigid bodies */
static mb_model *load_moto_at_rest(double end_time);

static void test_mass_wheelbase_bodies(void)
{
    mb_model *m = load_moto_at_rest(0.5);
    CHECK(m != NULL);
    if (!m) return;
    double mass = 0;
    for (int b = 0; b < m->nbody; b++)
        mass += m->body[b].mass;
    CHECK(m->nbody == 7);
    CHECK_NEAR(mass, 208, 1e-9); /* [M] Table 1.1 */
    int fw = find_body(m, "moto_front_wheel"), rw = find_body(m, "moto_rear_wheel");
    CHECK(fw >= 0 && rw >= 0);
    if (fw < 0 || rw < 0) {
        mb_model_destroy(&m);
        return;
    }
    double wb = m->body[fw].pos[0] - m->body[rw].pos[0];
    CHECK_NEAR(wb, 1.420, 1e-9); /* [M] Table 1.1: 1420 mm */
    /* 12 DOF: 6 (frame) + 6 one-DOF joints (steering, fork deformation, front suspension,
     * swing arm, two wheel spins); every other body is attached by exactly one of them */
    int one_dof = 0;
    for (int j = 0; j < m->njoint; j++)
        one_dof += m->joint[j].type == MB_J_REVOLUTE || m->joint[j].type == MB_J_TRANSLATIONAL;
    CHECK(m->njoint == 6 && one_dof == 6);
    CHECK(6 + one_dof == 12);
    printf("  motorcycle: %d bodies, %.1f kg, wheelbase %.4f m, %d DOF\n", m->nbody, mass, wb,
           6 + one_dof);
    FIG("models.moto_mass", "%.0f", mass);
    FIG("models.moto_wheelbase", "%.2f", wb);
    FIG("models.moto_dof", "%.0f", 6 + one_dof);
    mb_model_destroy(&m);
}

/* the model file (at rest) plus a simulation block */
static mb_model *load_moto_at_rest(double end_time)
{
    char *txt = slurp(MOTO);
    CHECK(txt != NULL);
    if (!txt) return NULL;
    /* the model file is at rest (the scenarios' impact: blocks give the speed) */
    CHECK(replace_all(txt, "\"13.4 m/s\"", "0") == 0);
    char sim[256];
    snprintf(sim, sizeof sim,
             "\nsimulation: {end_time: %g s, time_step: 10 us, output_rate: 1 kHz}\n"
             "environment: {gravity: 9.81 m/s^2, ground: {height: 0 m, friction: 0.9}}\n",
             end_time);
    strcat(txt, sim);
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load_text(MOTO, txt, strlen(txt), &scn, &err))
        fprintf(stderr, "static: %s\n", err.msg);
    free(txt);
    mb_model *m = build(scn);
    mcs_scenario_destroy(&scn);
    return m;
}

/* the pair of body a against body b (b may be MB_GROUND); -1 if none */
static int find_pair(const mb_model *m, int a, int b)
{
    for (int p = 0; p < m->npair; p++)
        if ((m->pair[p].ba == a && m->pair[p].bb == b) ||
            (m->pair[p].ba == b && m->pair[p].bb == a))
            return p;
    return -1;
}

/* Static equilibrium: the model at rest settles on its tyres and suspensions under gravity in
 * 0.5 s. Hand statics (rigid geometry, small deflections), from the model's masses and CGs:
 * wheel loads N_f = W x_G / L, N_r = W - N_f (W = 208 g, x_G the CG's distance from the rear
 * contact, L = 1.42 m); tyre deflections N / k (k = 180 and 200 kN/m in their first 10 mm);
 * front fork travel from the model's position (the top-out unloaded) = the top-out's 600 N /
 * 2e6 N/m + the spring beyond the 600 N preload, ((N_f - m_uf g) cos 24 deg - 600) / 18 kN/m,
 * m_uf = lower fork + front wheel (the force along the fork tubes; the joint carries the
 * rest); swing-arm angle = 350 N m / 2e5 N m/rad + (N_r 0.58 - g (m_arm 0.29 + m_rw 0.58) -
 * 350) / 6245 N m/rad (moments about the pivot at x = 0.58 m). Checked: wheel loads and tyre
 * deflections to 1 %, suspension travels to 2 % (the fork also bends at its hinge and the
 * frame pitches by 0.1 deg); steady over the last 0.1 s (< 0.05 mm, |vz| < 0.5 mm/s), no
 * roll. The sag figures are asserted as printed. */
static void test_static_equilibrium(void)
{
    mcs_error err = {0};
    mb_model *m = load_moto_at_rest(0.5);
    CHECK(m != NULL);
    if (!m) return;
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    int fr = find_body(m, "moto_frame"), fw = find_body(m, "moto_front_wheel");
    int rw = find_body(m, "moto_rear_wheel"), lf = find_body(m, "moto_lower_fork");
    int sa = find_body(m, "moto_swing_arm");
    int fk = find_restraint(m, "moto_fork_deformation");
    int sf = find_restraint(m, "moto_front_suspension"),
        sr = find_restraint(m, "moto_swing_arm_pivot");
    int pf = find_pair(m, fw, MB_GROUND), pr = find_pair(m, rw, MB_GROUND);
    CHECK(fr >= 0 && fw >= 0 && rw >= 0 && lf >= 0 && sa >= 0 && fk >= 0 && sf >= 0 && sr >= 0);
    CHECK(pf >= 0 && pr >= 0);
    if (pf < 0 || pr < 0 || sf < 0 || sr < 0 || fk < 0) goto out;
    /* hand statics */
    const double g = 9.81;
    double mass = 0, mx = 0;
    for (int b = 0; b < m->nbody; b++)
        mass += m->body[b].mass, mx += m->body[b].mass * m->body[b].pos[0];
    double L = m->body[fw].pos[0] - m->body[rw].pos[0], xg = mx / mass - m->body[rw].pos[0];
    double nf = mass * g * xg / L, nr = mass * g - nf;
    double c24 = cos(24 * M_PI / 180);
    double travel_f =
        600 / 2e6 + ((nf - (m->body[lf].mass + m->body[fw].mass) * g) * c24 - 600) / 18e3;
    double theta_r =
        350 / 2e5 +
        (nr * 0.58 - g * (m->body[sa].mass * 0.29 + m->body[rw].mass * 0.58) - 350) / 6245;
    double z0 = m->body[fr].pos[2], z_at_04 = 0;
    mcs_status st = MCS_OK;
    while (s->step < m->nsteps && !(st = mb_step(m, s, &err)))
        if (fabs(s->t - 0.4) < 0.5 * m->h) z_at_04 = s->kin[fr].pos[2];
    CHECK(st == MCS_OK);
    double z1 = s->kin[fr].pos[2], sag = z0 - z1;
    double vz = s->kin[fr].vel[2];
    const double *q = s->kin[fr].quat; /* pitch from the quaternion (w, x, y, z) */
    double pitch = asin(2 * (q[0] * q[2] - q[3] * q[1]));
    double roll = atan2(2 * (q[0] * q[1] + q[2] * q[3]), 1 - 2 * (q[1] * q[1] + q[2] * q[2]));
    double xf = s->r1[sf].x, xr = s->r1[sr].x;
    printf("  static: roll %.4f deg, vx %.2e m/s, y %.2e m\n", roll * 180 / M_PI, s->kin[fr].vel[0],
           s->kin[fr].pos[1]);
    printf("  static: frame sag %.2f mm, change over last 0.1 s %.3f mm, vz %.2e m/s, "
           "pitch %.3f deg, fork angle %.2e rad, drift %.2e\n",
           sag * 1e3, (z_at_04 - z1) * 1e3, vz, pitch * 180 / M_PI, s->r1[fk].x,
           mb_energy_drift(m, s));
    printf("  static: wheel loads %.1f / %.1f N (hand %.1f / %.1f); tyre depth %.2f / %.2f mm "
           "(hand %.2f / %.2f); front spring %.2f mm (hand %.2f), swing arm %.4f rad (hand "
           "%.4f)\n",
           s->pair[pf].fn, s->pair[pr].fn, nf, nr, s->pair[pf].depth * 1e3, s->pair[pr].depth * 1e3,
           nf / 180, nr / 200, xf * 1e3, travel_f * 1e3, xr, theta_r);
    CHECK_REL(s->pair[pf].fn, nf, 0.01);
    CHECK_REL(s->pair[pr].fn, nr, 0.01);
    CHECK_REL(s->pair[pf].depth, nf / 180e3, 0.01);
    CHECK_REL(s->pair[pr].depth, nr / 200e3, 0.01);
    CHECK_REL(fabs(xf), travel_f, 0.02);
    CHECK_REL(fabs(xr), theta_r, 0.02);
    CHECK(fabs(z_at_04 - z1) < 5e-5);
    CHECK(fabs(vz) < 5e-4);
    CHECK(fabs(roll) < 1e-6);
    CHECK(fabs(s->r1[fk].x) < m->restraint1[fk].spring.pos.elastic_limit); /* still elastic */
    FIG("models.static_sag_mm", "%.1f", sag * 1e3);
    FIG("models.static_sag_change_mm", "%.3f", (z_at_04 - z1) * 1e3);
    FIG("models.static_pitch_deg", "%.2f", pitch * 180 / M_PI);
    FIG("models.static_load_front_kn", "%.2f", s->pair[pf].fn / 1e3);
    FIG("models.static_load_rear_kn", "%.2f", s->pair[pr].fn / 1e3);
    FIG("models.static_fork_mm", "%.1f", fabs(xf) * 1e3);
    FIG("models.static_swing_arm_rad", "%.4f", fabs(xr));
    FIG("models.static_swing_arm_wheel_mm", "%.0f", fabs(xr) * 589);
out:
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

typedef struct {
    double f_peak, t_f_peak;     /* peak total barrier contact force [N] and its time [s] */
    double t_first;              /* first barrier contact [s] */
    double t_tyre60, t_tyre80;   /* front tyre-barrier depth past 60 and 80 mm [s] */
    double t_plastic;            /* fork beyond its elastic limit (the characteristic's) [s] */
    double t_stop;               /* fork at the wheel-engine stop (0.2 rad) [s] */
    double phi_max, phi_end;     /* largest fork angle and the angle at the end [rad] */
    double phi_set;              /* permanent set of the loaded branch [rad] */
    double phi_e;                /* the fork characteristic's elastic limit [rad] */
    double vx_min, vx_end;       /* frame CG velocity along x: smallest and at the end [m/s] */
    double t_vx0;                /* frame forward velocity first <= 0 [s] */
    double pitch_max, pitch_min; /* frame pitch extremes (nose up > 0) [deg] */
    double rear_lift;            /* largest rise of the rear wheel centre [m] */
    double vn_min, vn_end;       /* frame velocity along -(barrier normal): smallest, end [m/s] */
    double yaw_end;              /* frame yaw at the end [deg] */
    double ax_peak, t_ax_peak;   /* largest |x| frame acceleration, CFC 60 [m/s^2], when [s] */
    double drift;                /* energy drift [-] */
    double e_kin0, e_diss;       /* initial kinetic, dissipated at the end [J] */
    double dp_err; /* horizontal momentum change less the contacts' impulse, largest [N s] */
    long steps;
    double *f_out; /* barrier force at the output samples (nout), or NULL [N] */
    long nout;
} impact_figs;

/* the motorcycle group's linear momentum (bodies moto_*) [kg m/s] */
static void group_momentum(const mb_model *m, const mb_state *s, double p[3])
{
    p[0] = p[1] = p[2] = 0;
    for (int b = 0; b < m->nbody; b++)
        if (strncmp(m->body_name[b], "moto_", 5) == 0)
            for (int i = 0; i < 3; i++)
                p[i] += m->body[b].mass * s->kin[b].vel[i];
}

/* adds h times the force of the last step's contacts between the motorcycle group and a plane
 * (barrier, ground) on the group: fn along the plane's outward normal plus the friction force
 * on the motorcycle's surface (a); the planes do not move, so the normal is the model's */
static void add_external_impulse(const mb_model *m, const mb_state *s, double j[3])
{
    for (int p = 0; p < m->npair; p++) {
        const mb_pair *pr = &m->pair[p];
        const mb_surface *sb = &m->surf[pr->sb];
        if (sb->type != MB_SURF_PLANE || pr->ba < 0 ||
            strncmp(m->body_name[pr->ba], "moto_", 5) != 0)
            continue;
        double n[3];
        for (int i = 0; i < 3; i++)
            n[i] = pr->bb < 0 ? sb->normal[i]
                              : s->kin[pr->bb].rot[3 * i] * sb->normal[0] +
                                    s->kin[pr->bb].rot[3 * i + 1] * sb->normal[1] +
                                    s->kin[pr->bb].rot[3 * i + 2] * sb->normal[2];
        for (int i = 0; i < 3; i++)
            j[i] += m->h * (s->pair[p].fn * n[i] + s->pair[p].ft[i]);
    }
}

/* the largest |x| acceleration of the frame sensor "moto_frame", filtered CFC 60 as
 * `mcrash run` writes it (mb_output.c) */
static void frame_acc_peak(const mb_model *m, const mb_state *s, impact_figs *f)
{
    int se = -1;
    for (int i = 0; i < m->nsensor; i++)
        if (strcmp(m->sensor[i].name, "moto_frame") == 0) se = i;
    CHECK(se >= 0 && m->sensor[se].cfc == 60);
    if (se < 0 || s->nrec < 2) return;
    double *a = malloc((size_t)s->nrec * sizeof *a);
    for (long t = 0; t < s->nrec; t++)
        a[t] = s->rec_sensor[(t * m->nsensor + se) * 3 + 0];
    mcs_error err = {0};
    CHECK(an_cfc_filter(a, (int)s->nrec, 1.0 / m->output_rate, 60, a, &err) == MCS_OK);
    for (long t = 0; t < s->nrec; t++)
        if (fabs(a[t]) > f->ax_peak) f->ax_peak = fabs(a[t]), f->t_ax_peak = s->rec_t[t];
    free(a);
}

/* d: unit direction into the barrier (minus its normal), to measure the approach speed;
 * keep_force: record the barrier force at the output samples (f->f_out, freed by the caller) */
static mcs_status run_impact(const char *path, const double d[3], impact_figs *f, int keep_force)
{
    memset(f, 0, sizeof *f);
    f->t_first = f->t_plastic = f->t_stop = f->t_vx0 = f->t_tyre60 = f->t_tyre80 = NAN;
    f->vx_min = f->vn_min = INFINITY;
    f->pitch_min = INFINITY, f->pitch_max = -INFINITY;
    mb_model *m = load_model(path);
    if (!m) return MCS_ERR_USAGE;
    mb_state *s = NULL;
    mcs_error err = {0};
    mcs_status st = mb_state_create(m, &s, &err);
    if (st) {
        mb_model_destroy(&m);
        return st;
    }
    int fr = find_body(m, "moto_frame"), bar = find_body(m, "barrier");
    int fk = find_restraint(m, "moto_fork_deformation");
    int rw = find_body(m, "moto_rear_wheel");
    int ptyre = find_pair(m, find_body(m, "moto_front_wheel"), bar);
    f->phi_e = m->restraint1[fk].spring.pos.elastic_limit;
    double z_rw0 = m->body[rw].pos[2];
    f->e_kin0 = s->e.kinetic;
    double p0[3] = {0, 0, 0}, jx[3] = {0, 0, 0};
    group_momentum(m, s, p0);
    if (keep_force) f->f_out = calloc((size_t)m->nout, sizeof *f->f_out), f->nout = m->nout;
    while (s->step < m->nsteps && !(st = mb_step(m, s, &err))) {
        double fsum = 0;
        for (int p = 0; p < m->npair; p++)
            if (m->pair[p].bb == bar || m->pair[p].ba == bar) fsum += s->pair[p].fn;
        if (f->f_out && s->step % m->out_every == 0 && s->step / m->out_every < f->nout)
            f->f_out[s->step / m->out_every] = fsum;
        add_external_impulse(m, s, jx);
        if (fsum > 0 && isnan(f->t_first)) f->t_first = s->t;
        if (fsum > f->f_peak) f->f_peak = fsum, f->t_f_peak = s->t;
        double pen = ptyre >= 0 ? s->pair[ptyre].depth : 0;
        if (pen >= 0.060 && isnan(f->t_tyre60)) f->t_tyre60 = s->t;
        if (pen >= 0.080 && isnan(f->t_tyre80)) f->t_tyre80 = s->t;
        double phi = fabs(s->r1[fk].x);
        if (phi > f->phi_max) f->phi_max = phi;
        if (phi > f->phi_e && isnan(f->t_plastic)) f->t_plastic = s->t;
        if (phi >= 0.2 && isnan(f->t_stop)) f->t_stop = s->t;
        double vx = s->kin[fr].vel[0];
        if (vx < f->vx_min) f->vx_min = vx;
        if (vx <= 0 && isnan(f->t_vx0)) f->t_vx0 = s->t;
        const double *q = s->kin[fr].quat;
        double pitch = -asin(2 * (q[0] * q[2] - q[3] * q[1])) * 180 / M_PI;
        f->pitch_max = fmax(f->pitch_max, pitch), f->pitch_min = fmin(f->pitch_min, pitch);
        f->rear_lift = fmax(f->rear_lift, s->kin[rw].pos[2] - z_rw0);
        const double *v = s->kin[fr].vel;
        f->vn_min = fmin(f->vn_min, v[0] * d[0] + v[1] * d[1] + v[2] * d[2]);
    }
    {
        const double *q = s->kin[fr].quat, *v = s->kin[fr].vel;
        f->yaw_end = atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] * q[2] + q[3] * q[3])) *
                     180 / M_PI;
        f->vn_end = v[0] * d[0] + v[1] * d[1] + v[2] * d[2];
    }
    if (st) fprintf(stderr, "%s: %s\n", path, err.msg);
    {
        double p1[3];
        group_momentum(m, s, p1);
        for (int i = 0; i < 2; i++)
            f->dp_err = fmax(f->dp_err, fabs(p1[i] - p0[i] - jx[i]));
    }
    f->phi_end = s->r1[fk].x;
    f->phi_set = fmax(s->r1[fk].h.pos.x_set, s->r1[fk].h.neg.x_set);
    f->vx_end = s->kin[fr].vel[0];
    f->drift = mb_energy_drift(m, s);
    f->e_diss = s->e.dissipated;
    f->steps = s->step;
    frame_acc_peak(m, s, f);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    return st;
}

static void print_figs(const char *what, const impact_figs *f)
{
    printf("  %s: %ld steps; first barrier contact %.2f ms; peak barrier force %.1f kN at "
           "%.2f ms; front tyre 60 mm at %.2f ms, 80 mm at %.2f ms; fork past its elastic "
           "limit (%.4f rad) at %.2f ms, at the stop (0.2 rad) at %.2f ms, "
           "max %.4f rad, end %.4f rad, permanent set %.4f rad; frame vx min %.2f m/s, end "
           "%.2f m/s, vx <= 0 at %.1f ms; along -normal min %.2f m/s, end %.2f m/s; pitch "
           "%.1f..%.1f deg; rear wheel lift %.0f mm; yaw at end %.1f deg; frame |ax| CFC 60 "
           "%.1f g at %.1f ms; kinetic %.0f J, dissipated %.0f J; energy drift %.2e\n",
           what, f->steps, f->t_first * 1e3, f->f_peak / 1e3, f->t_f_peak * 1e3, f->t_tyre60 * 1e3,
           f->t_tyre80 * 1e3, f->phi_e, f->t_plastic * 1e3, f->t_stop * 1e3, f->phi_max, f->phi_end,
           f->phi_set, f->vx_min, f->vx_end, f->t_vx0 * 1e3, f->vn_min, f->vn_end, f->pitch_min,
           f->pitch_max, f->rear_lift * 1e3, f->yaw_end, f->ax_peak / 9.80665, f->t_ax_peak * 1e3,
           f->e_kin0, f->e_diss, f->drift);
}

/* the figures both barrier cases state (docs/models.md, README.md), keys in this order */
static const char *const fb_keys[] = {
    "models.fb_t_first_ms",   "models.fb_f_peak_kn",     "models.fb_t_f_peak_ms",
    "models.fb_t_plastic_ms", "models.fb_t_stop_ms",     "models.fb_phi_max_rad",
    "models.fb_phi_set_rad",  "models.fb_t_vx0_ms",      "models.fb_v_rebound",
    "models.fb_v_end",        "models.fb_pitch_min_deg", "models.fb_pitch_max_deg",
    "models.fb_rear_lift_mm", "models.fb_yaw_end_deg",   "models.fb_ax_peak_g",
    "models.fb_t_ax_peak_ms", "models.fb_e_diss_j",      "models.fb_drift"};

static const char *const ob_keys[] = {
    "models.ob_t_first_ms",   "models.ob_f_peak_kn",     "models.ob_t_f_peak_ms",
    "models.ob_t_plastic_ms", "models.ob_t_stop_ms",     "models.ob_phi_max_rad",
    "models.ob_phi_set_rad",  "models.ob_t_vx0_ms",      "models.ob_v_rebound",
    "models.ob_v_end",        "models.ob_pitch_min_deg", "models.ob_pitch_max_deg",
    "models.ob_rear_lift_mm", "models.ob_yaw_end_deg",   "models.ob_ax_peak_g",
    "models.ob_t_ax_peak_ms", "models.ob_e_diss_j",      "models.ob_drift"};

static void fig_barrier(const char *const key[18], const impact_figs *f)
{
    FIG(key[0], "%.2f", f->t_first * 1e3);
    FIG(key[1], "%.1f", f->f_peak / 1e3);
    FIG(key[2], "%.1f", f->t_f_peak * 1e3);
    FIG(key[3], "%.1f", f->t_plastic * 1e3);
    FIG(key[4], "%.1f", f->t_stop * 1e3);
    FIG(key[5], "%.3f", f->phi_max);
    FIG(key[6], "%.3f", f->phi_set);
    FIG(key[7], "%.1f", f->t_vx0 * 1e3);
    FIG(key[8], "%.2f", f->vn_min);
    FIG(key[9], "%.2f", f->vn_end);
    FIG(key[10], "%.1f", f->pitch_min);
    FIG(key[11], "%.1f", f->pitch_max);
    FIG(key[12], "%.0f", f->rear_lift * 1e3);
    FIG(key[13], "%.0f", f->yaw_end);
    FIG(key[14], "%.0f", f->ax_peak / 9.80665);
    FIG(key[15], "%.1f", f->t_ax_peak * 1e3);
    FIG(key[16], "%.0f", f->e_diss);
    FIG(key[17], "%.1e", f->drift);
}

/* kinetic energy at impact: (1/2) m v^2 + wheel spin (1/2) I (v/R)^2, 208 kg, I = 0.6 and
 * 0.9 kg m^2, R = 0.300 and 0.315 m (docs/models.md), v = 13.4 m/s */
static double ke_13_4(void)
{
    return 0.5 * 208 * 13.4 * 13.4 + 0.5 * 0.6 * pow(13.4 / 0.30, 2) +
           0.5 * 0.9 * pow(13.4 / 0.315, 2);
}

static impact_figs frontal; /* the frontal run, also for the channel check below */

/* Frontal rigid-barrier impact at 13.4 m/s (thesis): runs to the end; first contact after the
 * 5 mm gap at 13.4 m/s (0.373 ms, within two steps); the frame's forward velocity reaches 0;
 * the fork passes its elastic limit and keeps a permanent set; the motion stays in the plane
 * of symmetry (yaw 0); kinetic energy at t = 0 by hand; the horizontal momentum of the
 * motorcycle changes by the impulse of its contacts with the barrier and the road (Newton,
 * to 1e-8 of m v); the figures asserted as printed. */
static void test_frontal_barrier(void)
{
    const double d[3] = {1, 0, 0};
    CHECK(run_impact(FRONTAL, d, &frontal, 1) == MCS_OK);
    impact_figs *f = &frontal;
    print_figs("frontal 13.4 m/s", f);
    printf("  frontal: momentum change less the contacts' impulse %.3g N s (m v = %.0f N s)\n",
           f->dp_err, 208 * 13.4);
    /* Newton: the group's momentum changes by the impulse of its external contacts (the
     * joints' forces are internal; gravity is vertical) */
    CHECK(f->dp_err < 1e-8 * 208 * 13.4);
    FIG_TOL("models.frontal_dp_err", "%.0e", f->dp_err, 1e-8 * 208 * 13.4); /* round-off */
    CHECK_NEAR(f->t_first, 0.005 / 13.4, 2e-5);
    CHECK(!isnan(f->t_vx0));     /* stops or rebounds */
    CHECK(!isnan(f->t_plastic)); /* beyond the elastic limit */
    /* the fork went into its stop (wheel against the engine, > 0.2 rad): unloading goes back
     * down the stop, then parallel to the elastic slope from where the stop begins
     * (docs/hysteresis.md), so the set is 0.2 - M(0.2) / k_e = 0.2 - 4700 / 60000 rad:
     * MYMOSA's "blocked in that position considering also the elastic restitution" */
    CHECK(f->phi_max > 0.2);
    CHECK_NEAR(f->phi_set, 0.2 - 4700.0 / 60000.0, 1e-9);
    /* symmetric model and barrier: no yaw */
    CHECK(fabs(f->yaw_end) < 1e-3);
    CHECK(f->drift < 0.02);
    CHECK_REL(f->e_kin0, ke_13_4(), 1e-9);
    fig_barrier(fb_keys, f);
    FIG("models.fb_t_tyre60_ms", "%.1f", f->t_tyre60 * 1e3);
    FIG("models.fb_t_tyre80_ms", "%.1f", f->t_tyre80 * 1e3);
    FIG("models.fb_e_kin0_j", "%.0f", f->e_kin0);
    FIG("models.fb_restitution", "%.2f", -f->vn_min / 13.4);
    FIG("models.fb_phi_end_rad", "%.3f", f->phi_end);
    FIG("models.fork_elastic_limit", "%.4f", f->phi_e);
}

/* Oblique impact (barrier normal at 30 deg to the heading): first contact after the 5 mm gap
 * along the normal at the normal speed 13.4 cos 30 (0.431 ms, within two steps), the approach
 * speed along the barrier normal is reversed (rebound) or stopped, the fork deforms
 * plastically to the same set as the frontal case, the energy balance closes. */
static void test_oblique_barrier(void)
{
    impact_figs f;
    const double d[3] = {0.8660254, 0.5, 0};
    CHECK(run_impact(OBLIQUE, d, &f, 0) == MCS_OK);
    print_figs("oblique 30 deg 13.4 m/s", &f);
    printf("  oblique: momentum change less the contacts' impulse %.3g N s (m v = %.0f N s)\n",
           f.dp_err, 208 * 13.4);
    CHECK(f.dp_err < 1e-8 * 208 * 13.4);
    FIG_TOL("models.oblique_dp_err", "%.0e", f.dp_err, 1e-8 * 208 * 13.4); /* round-off */
    CHECK_NEAR(f.t_first, 0.005 / (13.4 * cos(M_PI / 6)), 2e-5);
    CHECK(f.vn_min <= 0);
    CHECK(!isnan(f.t_plastic));
    CHECK(f.phi_max > 0.2);
    CHECK_NEAR(f.phi_set, 0.2 - 4700.0 / 60000.0, 1e-9);
    CHECK(f.drift < 0.02);
    CHECK_REL(f.e_kin0, ke_13_4(), 1e-9);
    fig_barrier(ob_keys, &f);
    FIG("models.ob_phi_end_rad", "%.3f", f.phi_end);
}

/* the barrier force from `mcrash run`: the sum of the barrier contacts' <contact>_fn channels
 * equals, at every output sample, the sum over the barrier's pairs of the in-process run
 * (s->pair[p].fn; test_frontal_barrier) */
static void barrier_force_channels(const char *h5)
{
    static const char *const names[] = {"front_tyre_barrier", "frame_barrier", "handlebar_barrier",
                                        "fork_barrier", "rear_tyre_barrier"};
    mcs_results *r = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&r, h5, &err) == MCS_OK);
    if (!r) return;
    mcs_array a[5] = {{0}};
    for (int c = 0; c < 5; c++) {
        char ds[128];
        snprintf(ds, sizeof ds, "/stage1/channels/%s_fn", names[c]);
        CHECK(mcs_results_read(r, ds, &a[c], &err) == MCS_OK);
    }
    mcs_results_close(&r);
    CHECK(frontal.f_out != NULL && (long)a[0].n == frontal.nout);
    int bad = 0;
    double peak = 0;
    long row = 1;
    for (; frontal.f_out && row < frontal.nout && row < (long)a[0].n; row++) {
        double fch = 0, fsum = frontal.f_out[row];
        for (int c = 0; c < 5; c++)
            fch += a[c].n == a[0].n ? a[c].v[row] : NAN;
        if (!(fabs(fch - fsum) <= 1e-9 * (1 + fsum))) bad++;
        peak = fmax(peak, fch);
    }
    printf("  barrier force channels: %ld samples, peak %.1f kN (10 kHz samples), %d differ from "
           "the pairs' sum\n",
           row, peak / 1e3, bad);
    CHECK(bad == 0 && peak > 0);
    FIG("models.fb_channel_samples", "%.0f", (double)row);
    for (int c = 0; c < 5; c++)
        mcs_array_free(&a[c]);
}

static void test_frontal_barrier_cli(void)
{
    cli_result *r = cli_run("run " FRONTAL " --stage 1 --quiet --json -o /tmp/mcrash_models_fb.h5");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"steps\": 25000");
    /* the same run: the same drift as the in-process one */
    const char *d = strstr(r->out, "\"energy_drift\": ");
    CHECK(d != NULL);
    if (d) CHECK_REL(atof(d + 16), frontal.drift, 1e-5); /* printed %.6g */
    barrier_force_channels("/tmp/mcrash_models_fb.h5");
    remove("/tmp/mcrash_models_fb.h5");
    free(frontal.f_out);
    frontal.f_out = NULL;
}

/* The 1100 kg car (MYMOSA) stands on four corner springs of 30 kN/m, placed at the static
 * deflection m g / (4 k) = 1100 * 9.81 / 120000 = 89.9 mm: it must stay there (CG within
 * 1 mm over 0.3 s, all four corners carrying m g / 4 = 2698 N within 1 %). */
static void test_car_static(void)
{
    const char *txt = "mcrash: 1\n"
                      "include: opponents/car_1100kg.yaml\n"
                      "simulation: {end_time: 0.3 s, time_step: 10 us}\n"
                      "environment: {gravity: 9.81 m/s^2, ground: {height: 0 m, friction: 0.8}}\n";
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load_text("scenarios/models/car_static.yaml", txt, strlen(txt), &scn, &err))
        fprintf(stderr, "car: %s\n", err.msg);
    mb_model *m = build(scn);
    mcs_scenario_destroy(&scn);
    CHECK(m != NULL);
    if (!m) return;
    CHECK(m->nbody == 1 && m->body[0].mass == 1100);
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    double z0 = m->body[0].pos[2], dz = 0;
    while (s->step < m->nsteps && mb_step(m, s, &err) == MCS_OK)
        dz = fmax(dz, fabs(s->kin[0].pos[2] - z0));
    CHECK(s->step == m->nsteps);
    CHECK(dz < 1e-3);
    int loaded = 0; /* the four corner spheres carry the car; the side structures do not */
    for (int p = 0; p < m->npair; p++)
        if (s->pair[p].fn > 0) {
            loaded++;
            CHECK(strncmp(m->surf[m->pair[p].sa].name, "car_wheel_", 10) == 0);
            CHECK_REL(s->pair[p].fn, 1100 * 9.81 / 4, 0.01);
        }
    CHECK(loaded == 4);
    printf("  car static: CG moved at most %.3f mm; %d corners loaded (m g / 4 = %.0f N)\n",
           dz * 1e3, loaded, 1100 * 9.81 / 4);
    FIG("models.car_static_dz_mm", "%.2f", dz * 1e3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* The motorcycle at 13.4 m/s into the side of the stationary 1100 kg car at 90 deg (MYMOSA's
 * lateral impact, ISO 13232 413-0/13.4 geometry), motorcycle only, the car free on its corner
 * springs. Momentum along the heading: the two bodies reach the common velocity
 * m1 v / (m1 + m2) = 208 x 13.4 / 1308 = 2.1309 m/s at the end of the push (a mostly plastic
 * impact), the elastic parts' rebound adding a little, the road friction taking a little:
 * the car's largest speed within 1 % of it, and below the elastic two-body value (twice it).
 * The fork sequence is printed against MYMOSA Fig. 5.2 (deforming from ~20 ms, maximum
 * ~30 ms). */
static void test_car_side_impact(void)
{
    const char *txt =
        "mcrash: 1\n"
        "include: [motorcycles/sport_208kg.yaml, opponents/car_1100kg.yaml]\n"
        "simulation: {end_time: 200 ms, time_step: 10 us}\n"
        "environment: {gravity: 9.81 m/s^2, ground: {height: 0 m, friction: 0.9}}\n"
        "impact: {opponent_heading: [0, 1, 0], heading_angle: -90 deg, motorcycle_speed: "
        "13.4 m/s, motorcycle_contact: [1.72, 0, 0.30], opponent_contact: [1.725, 0, 0.30], "
        "initial_gap: 5 mm}\n"
        "contacts:\n"
        "  - {a: moto_lower_fork, b: car, characteristic: tyre_front, friction: 0.5}\n"
        "  - {a: moto_frame, b: car, characteristic: engine, friction: 0.5}\n"
        "  - {a: moto_upper_fork, b: car, characteristic: handlebar_end, friction: 0.5}\n"
        "  - {a: moto_fork_deform, b: car, characteristic: fork_tube, friction: 0.5}\n";
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load_text("scenarios/models/car_impact.yaml", txt, strlen(txt), &scn, &err))
        fprintf(stderr, "car impact: %s\n", err.msg);
    mb_model *m = build(scn);
    mcs_scenario_destroy(&scn);
    CHECK(m != NULL);
    if (!m) return;
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    int car = find_body(m, "car"), fk = find_restraint(m, "moto_fork_deformation");
    double vcar = 0, phi_max = 0, t_phi_max = 0, t_plastic = NAN, m1 = 0;
    for (int b = 0; b < m->nbody; b++)
        if (b != car) m1 += m->body[b].mass;
    double phi_e = m->restraint1[fk].spring.pos.elastic_limit;
    mcs_status st = MCS_OK;
    while (s->step < m->nsteps && !(st = mb_step(m, s, &err))) {
        vcar = fmax(vcar, s->kin[car].vel[0]);
        double phi = fabs(s->r1[fk].x);
        if (phi > phi_e && isnan(t_plastic)) t_plastic = s->t;
        if (phi > phi_max) phi_max = phi, t_phi_max = s->t;
    }
    CHECK(st == MCS_OK);
    double drift = mb_energy_drift(m, s);
    double common = 208 * 13.4 / (208 + 1100.0);
    printf("  car side impact: car peak vx %.4f m/s (common velocity %.4f); fork plastic at "
           "%.1f ms, max %.3f rad at %.1f ms, set %.3f rad; energy drift %.2e\n",
           vcar, common, t_plastic * 1e3, phi_max, t_phi_max * 1e3,
           fmax(s->r1[fk].h.pos.x_set, s->r1[fk].h.neg.x_set), drift);
    CHECK_NEAR(m1, 208, 1e-9);
    CHECK(vcar < 2 * common); /* the elastic two-body value */
    CHECK_REL(vcar, common, 0.01);
    CHECK(!isnan(t_plastic));
    CHECK(drift < 0.02);
    FIG("models.side_vcar", "%.2f", vcar);
    FIG("models.side_t_plastic_ms", "%.1f", t_plastic * 1e3);
    FIG("models.side_phi_max_rad", "%.3f", phi_max);
    FIG("models.side_t_phi_max_ms", "%.1f", t_phi_max * 1e3);
    FIG("models.side_early_yield", "%.1f", 0.020 / t_plastic); /* MYMOSA ~20 ms */
    FIG("models.side_early_max", "%.1f", 0.030 / t_phi_max);   /* MYMOSA ~30 ms */
    FIG("models.side_drift", "%.1e", drift);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_mass_wheelbase_bodies);
    RUN(test_static_equilibrium);
    RUN(test_frontal_barrier);
    RUN(test_frontal_barrier_cli);
    RUN(test_oblique_barrier);
    RUN(test_car_static);
    RUN(test_car_side_impact);
    TEST_END();
}

/* test_rider_cert.c: the Hybrid III head drop (49 CFR Part 572 Subpart E) run on the shipped
 * rider's head (docs/rider.md). What each check is:
 *  - the 225-275 g corridor: a calibration check (the head skin's stiffness in
 *    scripts/gen_rider.py was chosen so this drop lands in it), not a validation;
 *  - the closed form of the same spring-damper: verification of the integration (numerics);
 *  - a drop rolled 5 deg: the lateral channel against the closed form of its direction (the
 *    symmetric drop's lateral channel is zero by symmetry and could not fail);
 *  - unimodality is not asserted: one rigid head on one spring-damper has a single pulse.
 *
 * Head drop, 49 CFR 572.32 (text of the Oct. 2006 CFR edition, GPO, 49CFR572.32): the head
 * dropped from 14.8 in (376 mm) onto a rigidly supported flat horizontal steel plate, forehead
 * first (lowest point of the forehead 0.5 in below the lowest point of the nose); the peak
 * resultant acceleration at the head CG accelerometers "shall not be less than 225g, and not
 * more than 275g"; the curve unimodal: "oscillations occurring after the main acceleration
 * pulse are less than ten percent (zero to peak) of the main pulse"; "the lateral acceleration
 * vector shall not exceed 15g (zero to peak)". Filtering per 572.36: CFC 1000 (the rider's
 * head sensor's class).
 * The scenario scenarios/verification/h3_head_drop_572_32.yaml is written by
 * scripts/gen_rider.py from the same numbers as the rider files; the first check here is that
 * its head is the rider's head (mass, inertia, ellipsoid, skin characteristic).
 *
 * The neck pendulum of 572.33 is not run: its corridors (head rotation and moment vs. time,
 * and the pendulum's deceleration pulse) were not retrieved from a source here. */
#include "core/mcs_results.h"
#include "harness.h"
#include "tests/figures.h"
#include "tests/mb_test_util.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DROP "scenarios/verification/h3_head_drop_572_32.yaml"
#define G0 9.80665 /* standard gravity: accelerations in g [m/s^2] */

static int surf_of(const mb_model *m, int b)
{
    for (int s = 0; s < m->nsurf; s++)
        if (m->surf[s].body == b) return s;
    return -1;
}

/* the drop's head is the rider's head: same mass, inertia, ellipsoid and loading curve */
static void test_drop_head_is_rider_head(void)
{
    mb_model *r = mt_rider_alone("models/riders/hybrid3_50th.yaml"), *d = mt_model_file(DROP);
    CHECK(r != NULL && d != NULL);
    if (r && d) {
        int hr = mb_model_body(r, "rider_head"), hd = mb_model_body(d, "rider_head");
        CHECK(hr >= 0 && hd >= 0);
        CHECK(r->body[hr].mass == d->body[hd].mass);
        for (int k = 0; k < 3; k++) CHECK(r->body[hr].inertia[k] == d->body[hd].inertia[k]);
        int sr = surf_of(r, hr), sd = surf_of(d, hd);
        CHECK(sr >= 0 && sd >= 0);
        if (sr >= 0 && sd >= 0) {
            for (int k = 0; k < 3; k++) {
                CHECK(r->surf[sr].semi[k] == d->surf[sd].semi[k]);
                CHECK(r->surf[sr].center[k] == d->surf[sd].center[k]);
            }
            const mcs_curve *cr = r->chr[r->surf[sr].chr].loading;
            const mcs_curve *cd = d->chr[d->surf[sd].chr].loading;
            CHECK(cr->n == cd->n);
            for (int i = 0; i < cr->n && i < cd->n; i++)
                CHECK(cr->x[i] == cd->x[i] && cr->y[i] == cd->y[i]);
            CHECK(r->chr[r->surf[sr].chr].damping == d->chr[d->surf[sd].chr].damping);
        }
        printf("  drop head = rider head: %.3f kg, I = %.5f %.5f %.5f kg m^2\n", d->body[hd].mass,
               d->body[hd].inertia[0], d->body[hd].inertia[1], d->body[hd].inertia[2]);
    }
    mb_model_destroy(&r);
    mb_model_destroy(&d);
}

/* 572.32 on the CFC 1000 head channels. The sensor gives the kinematic acceleration in the head's
 * axes, J211 (gravity not included: -1 g in free fall, the accelerometer's reading less 1 g in
 * contact); the 1 g is counted against the corridor's bounds below (a 0.4 % effect). */
typedef struct {
    double peak;     /* largest resultant [m/s^2]                                     */
    double t_peak;   /* its time [s]                                                   */
    double lat;      /* largest |lateral| (J211 y) [m/s^2]                             */
    double lat_pk;   /* lateral at the resultant's peak [m/s^2]                        */
    double above;    /* time above 100 g [s]                                           */
    double contact;  /* time in contact (penetration > 0) [s]                         */
    double pmax;     /* largest skin compression [m]                                   */
} drop_result;

/* the lowest point of the head's ellipsoid relative to the CG, world axes (its normal is
 * vertical there): support point c - M z / sqrt(z' M z), M = R diag(s^2) R', c = R centre */
static void lowest_point(const mb_model *m, double u[3])
{
    double R[9], c0[3], Mz[3];
    const mb_surface *sf = &m->surf[surf_of(m, 0)];
    mb_quat_to_rot(m->body[0].quat, R);
    mb_mat_vec(R, sf->center, c0);
    for (int i = 0; i < 3; i++) {
        Mz[i] = 0;
        for (int k = 0; k < 3; k++)
            Mz[i] += R[3 * i + k] * sf->semi[k] * sf->semi[k] * R[3 * 2 + k];
    }
    for (int i = 0; i < 3; i++) u[i] = c0[i] - Mz[i] / sqrt(Mz[2]);
}

/* the file's posture rolled by roll [rad] about the world x axis, then lowered or raised so the
 * lowest point is again 376 mm above the plate */
static void roll_head(mb_model *m, double roll)
{
    double q[4], *p = m->body[0].quat, c = cos(roll / 2), s = sin(roll / 2), u[3];
    q[0] = c * p[0] - s * p[1], q[1] = c * p[1] + s * p[0];
    q[2] = c * p[2] - s * p[3], q[3] = c * p[3] + s * p[2];
    memcpy(p, q, sizeof q);
    lowest_point(m, u);
    m->body[0].pos[2] = 0.376 - u[2];
}

/* Closed form of the contact pulse: the head stops on the skin curve's first segment
 * (k = 3.7 MN/m up to 5 mm; 1/2 m v^2 = 16.7 J < 46 J there), a linear spring-damper
 * (c = 200 N s/m) on the effective mass of the contact point along the vertical normal n,
 * 1/m_eff = 1/m + w' I^-1 w, w = R' (r x n), r from the CG to the lowest point (the rigid-body
 * impulse response; for the symmetric posture w' I^-1 w = d^2 / I_yy, d the CG's horizontal
 * offset from the normal); penetration x = (v/wd) exp(-z w t) sin(wd t), v = sqrt(2 g h),
 * w = sqrt(k / m_eff), z = c / (2 sqrt(k m_eff)); the force k x + c x' (never tensile)
 * accelerates the CG by F / m. Its peak, less 1 g, against the simulation. It integrates the
 * same spring as the run: it verifies the integration (numerics), not the skin's stiffness.
 * The head turns in contact: the impulse so far, P = m_eff (v - x'), spins it at I^-1 w P, so
 * by the force peak t_p it has turned (body axes, small angles) theta = I^-1 w m_eff (v t_p - x);
 * the lateral/resultant ratio there is -(R0 (1 + [theta]x))[2][1] (J211 y is -body y). */
typedef struct {
    double a;     /* peak kinematic acceleration [m/s^2] */
    double d;     /* CG's horizontal offset from the normal [m] */
    double ratio; /* lateral (J211 y) / resultant at the peak [-] */
} closed_form;

static closed_form closed_form_peak(const mb_model *m)
{
    double R[9], u[3], w[3], wb[3], n[3] = {0, 0, 1};
    mb_quat_to_rot(m->body[0].quat, R);
    lowest_point(m, u);
    mb_cross(u, n, w);
    mb_mat_tvec(R, w, wb);
    const double *I = m->body[0].inertia;
    double mass = m->body[0].mass, winv = 0;
    for (int k = 0; k < 3; k++) winv += wb[k] * wb[k] / I[k];
    double k = 18.5e3 / 0.005, c = 200, meff = 1 / (1 / mass + winv), v = sqrt(2 * 9.81 * 0.376);
    double om = sqrt(k / meff), z = c / (2 * sqrt(k * meff)), wd = om * sqrt(1 - z * z), fpk = 0;
    double tp = 0, xp = 0;
    for (int i = 0; i <= 100000; i++) {
        double t = M_PI / wd * i / 100000, e = exp(-z * om * t);
        double x = v / wd * e * sin(wd * t), xd = v * e * (cos(wd * t) - z * om / wd * sin(wd * t));
        if (k * x + c * xd > fpk) fpk = k * x + c * xd, tp = t, xp = x;
    }
    double th[3], Rt[9];
    for (int i = 0; i < 3; i++) th[i] = wb[i] / I[i] * meff * (v * tp - xp);
    /* R0 (1 + [th]x): row 2, column 1 */
    Rt[7] = R[7] - R[6] * th[2] + R[8] * th[0];
    return (closed_form){fpk / mass - G0, sqrt(u[0] * u[0] + u[1] * u[1]), -Rt[7]};
}

/* runs the drop of m and reads the head channels into r; 0 on success */
static int run_drop(const mb_model *m, drop_result *r)
{
    const char *out = "/tmp/mcrash_test_h3_head_drop.h5";
    mcs_error err = {0};
    mb_run_opts o = {.out_path = out, .quiet = 1};
    mb_run_summary sum = {0};
    int bad = mb_run(m, &o, &sum, &err) != MCS_OK;
    if (bad) fprintf(stderr, "%s\n", err.msg);
    size_t n[4] = {0};
    double *ax = mt_read_channel(out, "head_ax", &n[0], NULL, NULL);
    double *ay = mt_read_channel(out, "head_ay", &n[1], NULL, NULL);
    double *az = mt_read_channel(out, "head_az", &n[2], NULL, NULL);
    double *pen = mt_read_channel(out, "head_plate_pen", &n[3], NULL, NULL);
    bad |= !(ax && ay && az && pen && n[0] == n[1] && n[1] == n[2] && n[2] == n[3] && n[0] > 100);
    *r = (drop_result){0};
    double dt = 1.0 / 20e3; /* the scenario's output rate */
    for (size_t i = 0; !bad && i < n[0]; i++) {
        double res = sqrt(ax[i] * ax[i] + ay[i] * ay[i] + az[i] * az[i]);
        if (res > r->peak) r->peak = res, r->t_peak = i * dt, r->lat_pk = ay[i];
        r->lat = fmax(r->lat, fabs(ay[i]));
        if (res > 100 * G0) r->above += dt;
        if (pen[i] > 0) r->contact += dt;
        r->pmax = fmax(r->pmax, pen[i]);
    }
    free(ax), free(ay), free(az), free(pen);
    remove(out);
    return bad;
}

/* The drop as the regulation poses it (symmetric, forehead first). The corridor check is a
 * calibration check: the skin's 3.7 MN/m was chosen so this drop peaks in 225-275 g
 * (scripts/gen_rider.py, docs/rider.md). The closed form above verifies the integration. */
static void test_head_drop_572_32(void)
{
    mb_model *m = mt_model_file(DROP);
    CHECK(m != NULL);
    if (!m) return;
    drop_result r;
    CHECK(run_drop(m, &r) == 0);
    closed_form cf = closed_form_peak(m);
    double a_cf = cf.a, d = cf.d;
    double acc = r.peak + G0; /* what an accelerometer reads: kinematic + 1 g */
    double err_pct = 100 * (r.peak - a_cf) / a_cf;
    printf("  572.32 head drop: peak resultant %.1f g at %.2f ms (accelerometer %.1f g; corridor "
           "225-275 g, the calibration target); closed form %.1f g with the CG %.1f mm off the "
           "contact normal, simulation %+.2f %%; above 100 g for %.2f ms, contact %.2f ms, skin "
           "compression %.2f mm\n",
           r.peak / G0, r.t_peak * 1e3, acc / G0, a_cf / G0, d * 1e3, err_pct, r.above * 1e3,
           r.contact * 1e3, r.pmax * 1e3);
    /* calibration target (572.32(b)) */
    CHECK(acc >= 225 * G0 && acc <= 275 * G0);
    /* verification of the integration against the closed form: 1.2 % allowed (3x the 0.4 %
     * the doc states; the rest is the CFC 1000 filter and the head's rotation in contact) */
    CHECK_REL(r.peak, a_cf, 0.012);
    CHECK(r.pmax < 0.005); /* stayed on the first segment, as the closed form assumes */
    /* free fall: sqrt(2 h / g) = 276.9 ms to the plate, the peak about half a contact later */
    CHECK_NEAR(r.t_peak, sqrt(2 * 0.376 / 9.81) + r.contact / 2, 0.5e-3);
    FIG("rider.drop_peak_g", "%.1f", r.peak / G0);
    FIG("rider.drop_acc_g", "%.1f", acc / G0);
    FIG("rider.drop_t_peak_ms", "%.1f", r.t_peak * 1e3);
    FIG("rider.drop_cf_g", "%.1f", a_cf / G0);
    FIG("rider.drop_cf_d_mm", "%.1f", d * 1e3);
    FIG("rider.drop_cf_err_pct", "%.1f", err_pct);
    FIG("rider.drop_above100_ms", "%.2f", r.above * 1e3);
    FIG("rider.drop_contact_ms", "%.2f", r.contact * 1e3);
    FIG("rider.drop_compression_mm", "%.2f", r.pmax * 1e3);
    mb_model_destroy(&m);
}

/* The same drop rolled 5 deg about the forward axis (one side of the forehead first). A plate
 * without friction pushes along its normal, so the head's acceleration is vertical and the
 * lateral (J211 y) channel reads -R[2][1] times the resultant: R[2][1] = sin(roll) for this
 * posture, -0.0872 (hand calculation: the body y axis rolled 5 deg up). This checks the sensor's
 * axes and sign, and the regulation's lateral limit: <= 15 g holds only for rolls below
 * asin(15 g / peak) (3.6 deg for 240 g), so 5 deg must exceed it. The symmetric drop cannot
 * test either: its lateral channel is zero by symmetry. */
static void test_head_drop_rolled(void)
{
    mb_model *m = mt_model_file(DROP);
    CHECK(m != NULL);
    if (!m) return;
    double roll = 5 * M_PI / 180, R[9];
    roll_head(m, roll);
    mb_quat_to_rot(m->body[0].quat, R);
    CHECK_NEAR(R[7], sin(roll), 1e-12); /* the posture is the one the comment works out */
    drop_result r;
    CHECK(run_drop(m, &r) == 0);
    closed_form cf = closed_form_peak(m);
    double a_cf = cf.a, d = cf.d, ratio = r.lat_pk / r.peak;
    printf("  rolled 5 deg: peak resultant %.1f g (closed form %.1f g, CG %.1f mm off the "
           "normal); lateral %.1f g at the peak, lateral/resultant %.4f (closed form %.4f; "
           "-sin 5 deg = %.4f before the contact turns the head); largest lateral %.1f g "
           "(572.32: <= 15 g); limit roll %.2f deg\n",
           r.peak / G0, a_cf / G0, d * 1e3, r.lat_pk / G0, ratio, cf.ratio, -sin(roll), r.lat / G0,
           asin(15 * G0 / (r.peak + G0)) * 180 / M_PI);
    /* the closed form takes the head's turn in contact to first order: 0.5 % allowed */
    CHECK_REL(ratio, cf.ratio, 0.005);
    CHECK_REL(r.peak, a_cf, 0.012);
    CHECK(r.lat > 15 * G0); /* the regulation's lateral limit rejects this posture */
    FIG("rider.drop_roll_lat_g", "%.1f", r.lat / G0);
    FIG("rider.drop_roll_ratio", "%.4f", ratio);
    FIG("rider.drop_roll_ratio_cf", "%.4f", cf.ratio);
    FIG("rider.drop_roll_limit_deg", "%.1f", asin(15 * G0 / (r.peak + G0)) * 180 / M_PI);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_drop_head_is_rider_head);
    RUN(test_head_drop_572_32);
    RUN(test_head_drop_rolled);
    TEST_END();
}

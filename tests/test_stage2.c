/* test_stage2.c: stage 2 (stage2_fe/s2_run.h, `mcrash stage2`, `mcrash run --stage all`).
 * - replay: the pendulum striking a block (scenarios/verification/pendulum_strike.yaml) run in
 *   stage 1, then in stage 2 with every body prescribed from that file: the stage-2 bodies are
 *   the file's at every common sample time (reference: the file's own samples, not the
 *   interpolation), for both motion methods and for a stage-2 time step and output rate
 *   unlike stage 1's;
 * - analytic motions written as a stage-1 file: a constant spin about a skew axis and a
 *   uniform acceleration, both methods exact to round-off at stage-2 times between samples;
 * - a free ball sliding on a prescribed plate accelerating at a: the closed form of a sphere
 *   under sliding friction (v = mu g t, w = 5 mu g t / (2 r));
 * - the refusals (exit 2, the file and body named, no results file) and the results commands
 *   on a stage-2 file (injury --stage 2, export --xdmf, compare /stage1 against /stage2). */
#include "tests/cli_util.h"
#include "tests/harness.h"
#include "tests/mb_test_util.h"
#include "tests/s2_test_util.h"

#include <sys/stat.h>
#include <unistd.h>

#define STRIKE "scenarios/verification/pendulum_strike.yaml"

static char tdir[64];

static void tpath(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "%s/%s", tdir, name);
}

static int file_exists(const char *p)
{
    struct stat sb;
    return stat(p, &sb) == 0;
}

static char strike_h5[128];

/* stage 2 of the strike with both bodies prescribed by `method`, at `sim` (a simulation line) */
static void replay_one(const char *method, const char *sim, double *dp, double *da, int *nc)
{
    char blk[256], out[128];
    snprintf(blk, sizeof blk, "stage2: {method: %s, prescribed: [{body: arm}, {body: block}]}\n",
             method);
    char *y = text_with(STRIKE,
                        "simulation: {end_time: 300 ms, time_step: 20 us, output_rate: 10 "
                        "kHz}",
                        sim, blk);
    tpath(out, sizeof out, "replay.h5");
    mcs_error err = {0};
    s2_summary sum = {0};
    CHECK(y && run_s2(STRIKE, y, strike_h5, out, &sum, &err) == MCS_OK);
    CHECK(sum.prescribed == 2);
    double a1, a2, b1, b2;
    int n1 = 0, n2 = 0;
    replay_error(strike_h5, out, "arm", &a1, &b1, &n1);
    replay_error(strike_h5, out, "block", &a2, &b2, &n2);
    *dp = fmax(a1, a2), *da = fmax(b1, b2), *nc = n1 < n2 ? n1 : n2;
    unlink(out);
    free(y);
}

static void test_replay(void)
{
    const char *same = "simulation: {end_time: 300 ms, time_step: 20 us, output_rate: 10 kHz}";
    /* 25 us steps, 4 kHz output: stage 2's samples meet stage 1's every 0.5 ms */
    const char *other = "simulation: {end_time: 300 ms, time_step: 25 us, output_rate: 4 kHz}";
    double dp[4], da[4];
    int nc[4];
    replay_one("pose", same, &dp[0], &da[0], &nc[0]);
    replay_one("pulse", same, &dp[1], &da[1], &nc[1]);
    replay_one("pose", other, &dp[2], &da[2], &nc[2]);
    replay_one("pulse", other, &dp[3], &da[3], &nc[3]);
    printf("replay, every body prescribed (pendulum strike, 300 ms): position | angle error\n"
           "  pose  10 kHz/20 us: %.3g m | %.3g rad (%d samples)\n"
           "  pulse 10 kHz/20 us: %.3g m | %.3g rad\n"
           "  pose   4 kHz/25 us: %.3g m | %.3g rad (%d samples)\n"
           "  pulse  4 kHz/25 us: %.3g m | %.3g rad\n",
           dp[0], da[0], nc[0], dp[1], da[1], dp[2], da[2], nc[2], dp[3], da[3]);
    CHECK(nc[0] == 3001 && nc[1] == 3001 && nc[2] == 601 && nc[3] == 601);
    /* pose: the curve passes through the samples (round-off); pulse: the bounds,
     * 1 mm and 0.1 deg */
    CHECK(dp[0] < 1e-9 && da[0] < 1e-9 && dp[2] < 1e-9 && da[2] < 1e-9);
    CHECK(dp[1] < 1e-3 && da[1] < 0.1 * M_PI / 180);
    CHECK(dp[3] < 1e-3 && da[3] < 0.1 * M_PI / 180);
    FIG("stage2.replay_strike_pulse_mm", "%.2g", 1e3 * fmax(dp[1], dp[3]));
    FIG("stage2.replay_strike_pulse_deg", "%.2g", 180 / M_PI * fmax(da[1], da[3]));
}

/* ---- analytic motions ---- */

static const double SPIN_W = 20;                               /* rad/s            */
static const double SPIN_N[3] = {3. / 13, -4. / 13, 12. / 13}; /* unit axis */
static const double SLED_P0[3] = {0.5, -0.2, 0.8}, SLED_V0[3] = {13.4, 0, 0.5},
                    SLED_A[3] = {-30, 5, 2};

static void spin_at(double t, double *q, double *w)
{
    double h = 0.5 * SPIN_W * t;
    q[0] = cos(h);
    for (int k = 0; k < 3; k++) {
        q[k + 1] = sin(h) * SPIN_N[k];
        if (w) w[k] = SPIN_W * SPIN_N[k];
    }
}

static void sled_at(double t, double *p, double *v)
{
    for (int k = 0; k < 3; k++) {
        p[k] = SLED_P0[k] + SLED_V0[k] * t + 0.5 * SLED_A[k] * t * t;
        if (v) v[k] = SLED_V0[k] + SLED_A[k] * t;
    }
}

static void analytic_at(const void *ctx, int body, double t, double p[3], double q[4],
                        double v[3], double om[3], double a[3])
{
    (void)ctx;
    if (body == 0) spin_at(t, q, om);
    if (body == 1) sled_at(t, p, v);
    if (body == 1) memcpy(a, SLED_A, 3 * sizeof *a);
    if (body == 0) memcpy(p, SLED_P0, 3 * sizeof *p), p[1] += 1;
}

/* a stage-1 file of the two closed-form bodies sampled at 1 kHz over [0, t_end] */
static int write_analytic(const char *path, double t_end)
{
    const char *names[] = {"spin", "sled"};
    return write_s1_motion(path, t_end, 2, names, analytic_at, NULL);
}

static const char ANALYTIC[] =
    "mcrash: 1\nname: analytic prescribed motions\n"
    "simulation: {end_time: 100 ms, time_step: 20 us, output_rate: 5 kHz}\n"
    "environment: {gravity: 0}\n"
    "bodies:\n"
    "  - {name: spin, mass: 2 kg, inertia: [0.01, 0.02, 0.03], position: [0.5, 0.8, 0.8],\n"
    "     velocity: [0, 0, 0], angular_velocity: [0, 0, 0]}\n"
    "  - {name: sled, mass: 50 kg, inertia: [1, 2, 3], position: [0.5, -0.2, 0.8],\n"
    "     velocity: [13.4, 0, 0.5], angular_velocity: [0, 0, 0]}\n";

static void analytic_one(const char *method, const char *motion, double *ep, double *eq, double *ev,
                         double *ew)
{
    char y[2048], out[128];
    snprintf(y, sizeof y, "%sstage2: {method: %s, prescribed: [{body: spin}, {body: sled}]}\n",
             ANALYTIC, method);
    tpath(out, sizeof out, "analytic2.h5");
    mcs_error err = {0};
    s2_summary sum = {0};
    CHECK(run_s2("analytic.yaml", y, motion, out, &sum, &err) == MCS_OK);
    size_t nt = 0, n;
    double *t = read_ds(out, "/stage2/time", &nt);
    double *qs = read_ds(out, "/stage2/bodies/spin/orientation", &n);
    double *ws = read_ds(out, "/stage2/bodies/spin/angular_velocity", &n);
    double *ps = read_ds(out, "/stage2/bodies/sled/position", &n);
    double *vs = read_ds(out, "/stage2/bodies/sled/velocity", &n);
    *ep = *eq = *ev = *ew = 0;
    CHECK(t && qs && ws && ps && vs && nt == 501);
    for (size_t i = 0; t && qs && ws && ps && vs && i < nt; i++) {
        double q[4], w[3], p[3], v[3];
        spin_at(t[i], q, w);
        sled_at(t[i], p, v);
        *eq = fmax(*eq, qangle(q, qs + 4 * i));
        for (int k = 0; k < 3; k++) {
            *ep = fmax(*ep, fabs(p[k] - ps[3 * i + k]));
            *ev = fmax(*ev, fabs(v[k] - vs[3 * i + k]));
            *ew = fmax(*ew, fabs(w[k] - ws[3 * i + k]));
        }
    }
    free(t), free(qs), free(ws), free(ps), free(vs);
    unlink(out);
}

static void test_analytic(void)
{
    char motion[128];
    tpath(motion, sizeof motion, "analytic1.h5");
    CHECK(write_analytic(motion, 0.1));
    const char *methods[] = {"pose", "pulse"};
    for (int m = 0; m < 2; m++) {
        double ep, eq, ev, ew;
        analytic_one(methods[m], motion, &ep, &eq, &ev, &ew);
        printf("analytic, %s: |dp| %.3g m, angle %.3g rad, |dv| %.3g m/s, |dw| %.3g rad/s\n",
               methods[m], ep, eq, ev, ew);
        /* round-off of positions ~1 m, speeds ~13 m/s, angles ~2 rad (double: 2.2e-16) */
        CHECK(ep < 1e-12 && eq < 1e-12 && ev < 1e-11 && ew < 1e-11);
    }
    unlink(motion);
}

/* ---- a free ball sliding on a prescribed plate ---- */

static void test_ball_on_plate(void)
{
    const double a = 20, mu = 0.2, g = 9.80665, r = 0.05, t_end = 0.2, slip_ramp = 0.01;
    char motion[128], out[128], y[2048];
    tpath(motion, sizeof motion, "plate1.h5");
    tpath(out, sizeof out, "plate2.h5");
    CHECK(write_sled(motion, "plate", (const double[3]){0, 0, 0}, a, t_end)); /* from rest at 0 */
    /* linear contact 1e7 N/m (1 um static sink of the 1 kg ball), damped */
    snprintf(y, sizeof y,
             "mcrash: 1\nname: ball on an accelerating plate\n"
             "simulation: {end_time: 200 ms, time_step: 10 us, output_rate: 1 kHz}\n"
             "environment: {gravity: 1 g}\n"
             "characteristics:\n"
             "  pad: {loading: [[0, 0], [1 mm, 10 kN]], damping: 3000 N s/m, friction: %g}\n"
             "bodies:\n"
             "  - name: plate\n    mass: 100 kg\n    inertia: [10, 10, 10]\n"
             "    position: [0, 0, 0]\n    velocity: [0, 0, 0]\n    angular_velocity: [0, 0, 0]\n"
             "    surfaces: [{type: plane, point: [0, 0, 0], normal: [0, 0, 1]}]\n"
             "  - name: ball\n    mass: 1 kg\n    inertia: [0.001, 0.001, 0.001]\n"
             "    position: [0, 0, %g]\n    velocity: [0, 0, 0]\n    angular_velocity: [0, 0, 0]\n"
             "    surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [%g, %g, %g]}]\n"
             "contacts: [{a: ball, b: plate, characteristic: pad}]\n"
             "stage2: {prescribed: [{body: plate}]}\n",
             mu, r - 0.98e-6, r, r, r);
    mcs_error err = {0};
    s2_summary sum = {0};
    CHECK(run_s2("plate.yaml", y, motion, out, &sum, &err) == MCS_OK);
    size_t n = 0;
    double *v = read_ds(out, "/stage2/bodies/ball/velocity", &n);
    double *w = read_ds(out, "/stage2/bodies/ball/angular_velocity", &n);
    CHECK(v && w && n == 3 * 201);
    if (!v || !w || n != 3 * 201) goto done;
    /* sliding throughout: the contact point moves at 3.5 mu g t < a t. Friction mu m g once the
     * slip passes the stick ramp (slip_speed 0.01 m/s, friction linear in the slip below it,
     * docs/stage1_engine.md): the ramp lasts t_r = 0.01 / (a - 3.5 mu g) and costs half of
     * it, so v = mu g (t - t_r / 2), w_y = -5 mu g (t - t_r / 2) / (2 r) (torque of the
     * friction at the contact point, r below the centre; I = 2/5 m r^2) */
    const double tr = slip_ramp / (a - 3.5 * mu * g), te = t_end - tr / 2;
    const double v_ref = mu * g * te, w_ref = -2.5 * mu * g * te / r;
    double ev = fabs(v[3 * 200] - v_ref) / v_ref, ew = fabs(w[3 * 200 + 1] - w_ref) / fabs(w_ref);
    printf("ball on a plate at %g m/s^2: v %.6g m/s (closed form %.6g), w_y %.6g rad/s (%.6g): "
           "%.2g, %.2g relative\n",
           a, v[3 * 200], v_ref, w[3 * 200 + 1], w_ref, ev, ew);
    CHECK(ev < 2e-3 && ew < 2e-3);
    FIG("stage2.ball_plate_v_err_pct", "%.2f", 100 * ev);
    CHECK(fabs(v[3 * 200 + 1]) < 1e-6 && fabs(w[3 * 200]) < 1e-6);
done:
    free(v), free(w);
    unlink(motion), unlink(out);
}

/* ---- coupled FE parts under a prescribed body ---- */

#define FOAM "scenarios/verification/coupled_foam_contact.yaml"

/* the body striking the foam block, prescribed from its stage-1 run: the foam is loaded the
 * same way, so its energies and the contact force repeat stage 1's (the reference: the stage-1
 * file), to the pose interpolation between the FE substeps' times */
static void test_fe_replay(void)
{
    char h1[128], h2[128];
    tpath(h1, sizeof h1, "foam1.h5");
    tpath(h2, sizeof h2, "foam2.h5");
    mb_model *m = mt_model_file(FOAM);
    mcs_error err = {0};
    mb_run_opts o = {.out_path = h1, .quiet = 1};
    CHECK(m && mb_run(m, &o, NULL, &err) == MCS_OK);
    mb_model_destroy(&m);
    char *y = text_with(FOAM, NULL, NULL, "stage2: {prescribed: [{body: mass}]}\n");
    s2_summary sum = {0};
    CHECK(y && run_s2(FOAM, y, h1, h2, &sum, &err) == MCS_OK);
    free(y);
    const char *ds[] = {"parts/foam/energy/internal", "parts/foam/energy/dissipated",
                        "contact/contact0/force"};
    for (int i = 0; i < 3; i++) {
        char p1[128], p2[128];
        snprintf(p1, sizeof p1, "/stage1/%s", ds[i]);
        snprintf(p2, sizeof p2, "/stage2/%s", ds[i]);
        size_t n1 = 0, n2 = 0;
        double *a = read_ds(h1, p1, &n1), *b = read_ds(h2, p2, &n2), peak = 0, diff = 0;
        CHECK(a && b && n1 == n2 && n1 > 100);
        for (size_t k = 0; a && b && k < n1 && n1 == n2; k++) {
            peak = fmax(peak, fabs(a[k]));
            diff = fmax(diff, fabs(a[k] - b[k]));
        }
        printf("foam struck by a prescribed body: %s: peak %.4g, largest stage-2 difference "
               "%.3g (%.2g)\n",
               ds[i], peak, diff, diff / peak);
        /* energies within 0.1 % of their peak; the contact force, a step's ODE secant
         * velocity of the kinematic body against the free body's, within 0.5 % */
        CHECK(peak > 0 && diff < (i == 2 ? 5e-3 : 1e-3) * peak);
        if (i == 2) FIG("stage2.foam_force_diff_pct", "%.2f", 100 * diff / peak);
        free(a), free(b);
    }
    unlink(h1), unlink(h2);
}

/* ---- commands ---- */

static char strike_yaml[128];

/* the strike scenario in tdir with a head sensor on the arm and a stage2: block `blk` */
static void write_strike(const char *blk)
{
    char inc[4200], cwd[4096];
    snprintf(inc, sizeof inc, "include: %s/scenarios/models/pendulum_arm.yaml",
             getcwd(cwd, sizeof cwd) ? cwd : ".");
    char *y = text_with(STRIKE, "include: ../models/pendulum_arm.yaml", inc, "");
    FILE *f = fopen(strike_yaml, "wb");
    if (!f || !y) return;
    fprintf(f, "%s%s", y, blk);
    fprintf(f, "sensors:\n  - {name: head, body: arm, type: acceleration, point: [0.25 m, 0, 0], "
               "cfc: 1000}\n");
    fclose(f);
    free(y);
}

static void test_commands(void)
{
    char all[128], s2[128], cmd[1024], xmf[128];
    tpath(strike_yaml, sizeof strike_yaml, "strike.yaml");
    tpath(all, sizeof all, "all.h5");
    tpath(s2, sizeof s2, "s2.h5");
    tpath(xmf, sizeof xmf, "all.xmf");
    /* relative stage2.motion: the scenario's directory */
    write_strike("stage2: {motion: all.h5, prescribed: [{body: block}]}\n");
    snprintf(cmd, sizeof cmd, "run %s --stage all -o %s --json --quiet", strike_yaml, all);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"stage1\"");
    CHECK_STR_CONTAINS(r->out, "\"stage2\"");
    CHECK_STR_CONTAINS(r->out, "\"prescribed\": 1");
    /* stage 2 alone from the same scenario: motion from stage2.motion (relative) */
    snprintf(cmd, sizeof cmd, "stage2 %s -o %s --quiet", strike_yaml, s2);
    CHECK(cli_run(cmd)->status == 0);
    CHECK(file_exists(s2));
    size_t n1 = 0, n2 = 0;
    double *a1 = read_ds(all, "/stage2/channels/head_ax", &n1);
    double *a2 = read_ds(s2, "/stage2/channels/head_ax", &n2);
    CHECK(a1 && a2 && n1 == n2 && n1 == 3001);
    if (a1 && a2 && n1 == n2) CHECK(memcmp(a1, a2, n1 * sizeof *a1) == 0);
    free(a1), free(a2);
    double *pe = read_ds(all, "/stage2/motion/block/position_error", &n1);
    CHECK(pe && n1 == 3001);
    free(pe);
    /* results commands */
    snprintf(cmd, sizeof cmd, "injury %s --stage 2 --json", all);
    r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "HIC");
    snprintf(cmd, sizeof cmd,
             "compare %s:/stage1/channels/head_ax %s:/stage2/channels/head_ax "
             "--json",
             all, all);
    r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "rating");
    /* every channel the stages share: the free arm hits the same (prescribed) block */
    snprintf(cmd, sizeof cmd, "compare %s --stages 1,2 --json", all);
    r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"stages\": [1, 2]");
    CHECK_STR_CONTAINS(r->out, "{\"name\": \"head_ax\", \"kind\": \"channel\"");
    CHECK_STR_CONTAINS(r->out, "{\"name\": \"arm_tip_acc_ax\", \"kind\": \"channel\"");
    snprintf(cmd, sizeof cmd, "compare %s --stages 1,3", all);
    CHECK(cli_run(cmd)->status == 2);
    snprintf(cmd, sizeof cmd, "export %s --xdmf %s --stage 2", all, xmf);
    r = cli_run(cmd);
    CHECK(r->status == 0);
    /* the bodies of both stages: free (arm, an outline) and prescribed (block: a plane, a
     * point) */
    char *x = calloc(1 << 23, 1);
    if (x) cli_slurp(xmf, x, 1 << 23);
    CHECK(x && strstr(x, "stage2_bodies") && strstr(x, "stage1_bodies"));
    CHECK(x && strstr(x, "/stage2/outlines/arm/nodes") && strstr(x, "Grid Name=\"block\""));
    free(x);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    unlink(s2);
    /* refusals: exit 2, the file and body named, no results file */
    const char *bad[] = {"stage2: {motion: all.h5, prescribed: [{body: block, from: zz}]}\n",
                         "stage2: {motion: none.h5, prescribed: [{body: block}]}\n",
                         "stage2: {motion: text.h5, prescribed: [{body: block}]}\n",
                         "stage2: {motion: cut.h5, prescribed: [{body: block}]}\n",
                         "stage2: {motion: s3.h5, prescribed: [{body: block}]}\n",
                         "stage2: {motion: short.h5, prescribed: [{body: block}]}\n",
                         ""};
    const char *named[] = {"zz", "none.h5", "text.h5", "cut.h5", "s3.h5", "short.h5", "stage2"};
    char p[160];
    tpath(p, sizeof p, "text.h5");
    FILE *f = fopen(p, "wb");
    if (f) fputs("not a results file\n", f), fclose(f);
    { /* an HDF5 file cut short */
        char src[65536 * 4];
        FILE *in = fopen(all, "rb");
        size_t k = in ? fread(src, 1, sizeof src, in) : 0;
        if (in) fclose(in);
        tpath(p, sizeof p, "cut.h5");
        f = fopen(p, "wb");
        if (f) fwrite(src, 1, k / 2, f), fclose(f);
    }
    { /* a results file without /stage1 */
        mcs_results *rr = NULL;
        mcs_error e = {0};
        tpath(p, sizeof p, "s3.h5");
        CHECK(!mcs_results_create(&rr, p, NULL, &e) && !mcs_results_commit(&rr, &e));
    }
    { /* a stage-1 file shorter than the run: the strike to 100 ms */
        char sh[128], y2[160];
        tpath(sh, sizeof sh, "short.h5");
        tpath(y2, sizeof y2, "short.yaml");
        char *y = text_with(strike_yaml, "end_time: 300 ms", "end_time: 100 ms", "");
        f = fopen(y2, "wb");
        if (f && y) fputs(y, f);
        if (f) fclose(f);
        free(y);
        snprintf(cmd, sizeof cmd, "stage1 %s -o %s --quiet", y2, sh);
        CHECK(cli_run(cmd)->status == 0);
        unlink(y2);
    }
    for (int i = 0; i < 7; i++) {
        write_strike(bad[i]);
        snprintf(cmd, sizeof cmd, "stage2 %s -o %s --quiet", strike_yaml, s2);
        r = cli_run(cmd);
        printf("refusal %d: exit %d: %s", i, r->status, r->err);
        CHECK(r->status == 2);
        CHECK_STR_CONTAINS(r->err, named[i]);
        if (i != 6 && i != 0) CHECK_STR_CONTAINS(r->err, "block");
        CHECK(!file_exists(s2));
    }
    /* --motion wins over stage2.motion */
    write_strike("stage2: {motion: none.h5, prescribed: [{body: block}]}\n");
    snprintf(cmd, sizeof cmd, "stage2 %s --motion %s -o %s --quiet", strike_yaml, all, s2);
    CHECK(cli_run(cmd)->status == 0);
    const char *rm[] = {"text.h5", "cut.h5", "s3.h5",   "short.h5",
                        "s2.h5",   "all.h5", "all.xmf", "strike.yaml"};
    for (int i = 0; i < 8; i++)
        tpath(p, sizeof p, rm[i]), unlink(p);
}

int main(void)
{
    snprintf(tdir, sizeof tdir, "/tmp/mcs_s2_XXXXXX");
    if (!mkdtemp(tdir)) return perror("mkdtemp"), 1;
    tpath(strike_h5, sizeof strike_h5, "strike1.h5");
    mb_model *m = mt_model_file(STRIKE);
    mcs_error err = {0};
    mb_run_opts o = {.out_path = strike_h5, .quiet = 1};
    if (!m || mb_run(m, &o, NULL, &err)) return fprintf(stderr, "stage 1: %s\n", err.msg), 1;
    mb_model_destroy(&m);
    RUN(test_replay);
    RUN(test_analytic);
    RUN(test_ball_on_plate);
    RUN(test_fe_replay);
    RUN(test_commands);
    unlink(strike_h5);
    rmdir(tdir);
    TEST_END();
}

/* tests for `mcrash injury OUT.h5` on synthetic results files written here with the
 * core/mcs_results.h API; expected values are the closed forms of test_criteria.c */
#include "core/mcs_results.h"
#include "tests/cli_util.h"
#include "tests/harness.h"

#include <math.h>

#define G 9.80665

static char tmpdir[64];

/* field `field` of the criterion `key` in the JSON output; NaN if absent */
static double crit(const char *json, const char *key, const char *field)
{
    char pat[96];
    snprintf(pat, sizeof pat, "\"criterion\": \"%s\"", key);
    const char *p = strstr(json, pat);
    if (!p) return NAN;
    const char *end = strchr(p, '}');
    snprintf(pat, sizeof pat, "\"%s\": ", field);
    const char *q = strstr(p, pat);
    if (!q || (end && q > end)) return NAN;
    return strtod(q + strlen(pat), NULL);
}

/* half-sine head pulse A = 100 g, T = 12 ms starting at 10 ms, split 0.6/0.8 over ax/ay
 * (resultant = the pulse), upper-neck loads with the four hand-computed Nij points of
 * test_criteria.c, chest deflection D = -(0.002 + 1.5 t - 20 t^2 + 60 t^3 - 150 t^4)
 * (compression negative: V D > 0 as for a positive D), femur and tibia peaks, head angular
 * velocity, and an unfiltered pelvis body acceleration of a constant 30 g. The head pulse's
 * amplitude A [g] is the caller's. */
static void write_run_as(const char *path, int nt, double h, double A, const char *dummy)
{
    double *t = calloc((size_t)nt, sizeof(double)), *buf = calloc((size_t)nt * 3, sizeof(double));
    double *z = calloc((size_t)nt, sizeof(double));
    mcs_results *r = NULL;
    mcs_error e = {0};
    if (!t || !buf || !z || mcs_results_create(&r, path, NULL, &e)) goto done;
    for (int i = 0; i < nt; i++) t[i] = i * h;
    mcs_results_put_time(r, 1, (size_t)nt, t, &e);
    double T = 0.012;
    for (int k = 0; k < 2; k++) {
        for (int i = 0; i < nt; i++) {
            double s = t[i] - 0.01;
            buf[i] = (s > 0 && s < T) ? (k ? 0.8 : 0.6) * A * G * sin(M_PI * s / T) : 0;
        }
        mcs_results_put_channel(r, 1, k ? "head_ay" : "head_ax", (size_t)nt, buf, "m/s^2",
                                "SAE J211 local", 1000, "head", &e);
    }
    mcs_results_put_channel(r, 1, "head_az", (size_t)nt, z, "m/s^2", NULL, 1000, "head", &e);
    /* neck: the hand points at samples 100..103 */
    double fx[4] = {0, 0, -1000, 500}, fz[4] = {3403, 1000, -3080, -1232}, my[4] = {155, -54, 0, -100};
    const double *nk[3] = {fx, fz, my};
    const char *nn[3] = {"neck_fx", "neck_fz", "neck_my"}, *nu[3] = {"N", "N", "N*m"};
    for (int k = 0; k < 3; k++) {
        memset(buf, 0, (size_t)nt * sizeof(double));
        for (int j = 0; j < 4; j++) buf[100 + j] = nk[k][j];
        mcs_results_put_channel(r, 1, nn[k], (size_t)nt, buf, nu[k], NULL, 600, "neck", &e);
    }
    for (int i = 0; i < nt; i++) {
        double x = t[i];
        buf[i] = -(0.002 + 1.5 * x - 20 * x * x + 60 * x * x * x - 150 * x * x * x * x);
    }
    mcs_results_put_channel(r, 1, "chest_d", (size_t)nt, buf, "m", NULL, 180, "chest", &e);
    memset(buf, 0, (size_t)nt * sizeof(double));
    buf[200] = -7000;
    mcs_results_put_channel(r, 1, "femur_left_fz", (size_t)nt, buf, "N", NULL, 600, NULL, &e);
    buf[200] = 0, buf[300] = -5000;
    mcs_results_put_channel(r, 1, "femur_right_fz", (size_t)nt, buf, "N", NULL, 600, NULL, &e);
    const char *tn[3] = {"tibia_left_mx", "tibia_left_my", "tibia_left_fz"};
    const double tv[3] = {135, 180, -17950};
    for (int k = 0; k < 3; k++) {
        memset(buf, 0, (size_t)nt * sizeof(double));
        buf[400] = tv[k];
        mcs_results_put_channel(r, 1, tn[k], (size_t)nt, buf, k < 2 ? "N*m" : "N", NULL, 600,
                                NULL, &e);
    }
    const char *wn[3] = {"head_wx", "head_wy", "head_wz"};
    const double wv[3] = {33.15, -53.8, 0};
    for (int k = 0; k < 3; k++) {
        memset(buf, 0, (size_t)nt * sizeof(double));
        buf[500] = wv[k];
        mcs_results_put_channel(r, 1, wn[k], (size_t)nt, buf, "rad/s", NULL, 0, "head", &e);
    }
    for (int i = 0; i < nt; i++) buf[3 * i] = 0, buf[3 * i + 1] = 0, buf[3 * i + 2] = 30 * G;
    mcs_results_put_body(r, 1, "pelvis", "acceleration", (size_t)nt, buf, &e);
    if (dummy) mcs_results_set_attr_str(r, "/stage1", "dummy", dummy, &e);
    mcs_results_commit(&r, &e);
done:
    if (e.status) fprintf(stderr, "write_run: %s\n", e.msg);
    mcs_results_abort(&r);
    free(t), free(buf), free(z);
}

static void write_run(const char *path, int nt, double h, double A)
{
    write_run_as(path, nt, h, A, NULL);
}

/* HIC of the half-sine: tan x = 5x/3 (see test_criteria.c); with h = 2e-5 s the run gives
 * -5.8e-6 relative (trapezoid 2.5 (pi h / T)^2 / 12 = 5.7e-6): tolerance 1.5e-5 */
static double hic_half_sine(double A, double T, double W)
{
    double x = 1.05;
    for (int k = 0; k < 50; k++) x -= (tan(x) - 5 * x / 3) / (1 / (cos(x) * cos(x)) - 5.0 / 3);
    if (2 * x * T / M_PI > W) x = M_PI * W / (2 * T);
    return pow(2 * A * T / M_PI, 2.5) * pow(sin(x), 2.5) / pow(2 * x * T / M_PI, 1.5);
}

static void test_injury_table(void)
{
    char path[128], args[256];
    snprintf(path, sizeof path, "%s/run.h5", tmpdir);
    int nt = 4001;
    double h = 2e-5;
    write_run(path, nt, h, 100);
    snprintf(args, sizeof args, "injury %s --json", path);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    const char *o = r->out;
    CHECK_REL(crit(o, "hic15", "value"), hic_half_sine(100, 0.012, 0.015), 1.5e-5);
    CHECK_REL(crit(o, "hic36", "value"), hic_half_sine(100, 0.012, 0.036), 1.5e-5);
    CHECK_REL(crit(o, "hic15", "fraction"), hic_half_sine(100, 0.012, 0.015) / 700, 1.5e-5);
    /* a3ms: the 3 ms window ends on samples, exact to the 10 digits printed */
    CHECK_REL(crit(o, "head_a3ms", "value"), 100 * cos(M_PI * 0.0015 / 0.012), 1e-9);
    CHECK_REL(crit(o, "nij", "value"), 0.2 + 108.89 / 135, 1e-9);
    CHECK_NEAR(crit(o, "nij", "t1"), 103 * h, 1e-12);
    CHECK_REL(crit(o, "neck_tension", "value"), 3403, 1e-9);
    CHECK_REL(crit(o, "neck_compression", "value"), 3080, 1e-9);
    CHECK_REL(crit(o, "neck_extension", "value"), 108.89, 1e-9);
    CHECK_REL(crit(o, "neck_shear", "value"), 1000, 1e-9);
    CHECK_REL(crit(o, "bric", "value"), sqrt(1.25), 1e-9);
    CHECK_REL(crit(o, "femur_compression", "value"), 7000, 1e-9);
    CHECK_REL(crit(o, "tibia_index", "value"), 1.5, 1e-9);
    /* VC: polynomial of degree 4, exact difference; max of 1.3 D' D / 0.229 over the samples
     * (D and D' both negative here, product as for positive D) */
    double best = -1e300, dmax = 0;
    for (int i = 2; i < nt - 2; i++) {
        double x = i * h, d = 0.002 + 1.5 * x - 20 * x * x + 60 * x * x * x - 150 * x * x * x * x;
        double dp = 1.5 - 40 * x + 180 * x * x - 600 * x * x * x;
        best = fmax(best, 1.3 * dp * d / 0.229);
    }
    for (int i = 0; i < nt; i++) {
        double x = i * h;
        dmax = fmax(dmax, fabs(0.002 + 1.5 * x - 20 * x * x + 60 * x * x * x - 150 * x * x * x * x));
    }
    CHECK_REL(crit(o, "vc", "value"), best, 1e-9);
    CHECK_REL(crit(o, "chest_deflection", "value"), dmax, 1e-9);
    /* pelvis from the body's acceleration, unfiltered in the file: filtered with CFC 1000
     * (a constant passes unchanged), a3ms = 30 g */
    CHECK_REL(crit(o, "pelvis_a3ms", "value"), 30, 1e-9);
    CHECK_NEAR(crit(o, "pelvis_a3ms", "cfc"), 1000, 0);
    CHECK_STR_CONTAINS(o, "\"stage\": 1");
    /* the readable table */
    snprintf(args, sizeof args, "injury %s", path);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "HIC15");
    CHECK_STR_CONTAINS(r->out, "Tibia index");
    CHECK_STR_CONTAINS(r->out, "Nij (CE)");
    /* a stage that is not there */
    snprintf(args, sizeof args, "injury %s --stage 2", path);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "stage2");
}

/* two files side by side (`mcrash injury A.h5 B.h5`): one column per file, each the value of
 * its own file; head pulses of 100 g and 50 g: HIC scales as A^2.5 (Eq. 7 of the 2023 paper),
 * so B's HIC15 is A's / 2^2.5 = 0.1768 of it; JSON: {"files": [A's object, B's object]} */
static void test_injury_two_files(void)
{
    char a[128], b[128], args[512];
    snprintf(a, sizeof a, "%s/a.h5", tmpdir);
    snprintf(b, sizeof b, "%s/b.h5", tmpdir);
    write_run(a, 4001, 2e-5, 100);
    write_run(b, 4001, 2e-5, 50);
    snprintf(args, sizeof args, "injury %s %s --json", a, b);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "{\"files\": [{\"file\": ");
    const char *second = strstr(r->out, "}]}, {\"file\": ");
    CHECK(second != NULL);
    if (!second) return;
    double h1 = crit(r->out, "hic15", "value"), h2 = crit(second, "hic15", "value");
    CHECK_REL(h1, hic_half_sine(100, 0.012, 0.015), 1.5e-5);
    CHECK_REL(h2 / h1, pow(0.5, 2.5), 1e-9);
    CHECK_REL(crit(second, "neck_tension", "value"), 3403, 1e-9);
    /* the table: one row per criterion, A's then B's value on it */
    snprintf(args, sizeof args, "injury %s %s", a, b);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "[1] ");
    CHECK_STR_CONTAINS(r->out, "[2] ");
    const char *row = strstr(r->out, "\nHIC15 ");
    CHECK(row != NULL);
    if (!row) return;
    char label[16], unit[8];
    double lim = 0, v1 = 0, v2 = 0, f1 = 0, f2 = 0;
    int got = sscanf(row, " %15s %7s %lf %lf (%lf) %lf (%lf)", label, unit, &lim, &v1, &f1, &v2,
                     &f2);
    CHECK(got == 7);
    CHECK_REL(v1, h1, 1e-3); /* 4 digits printed */
    CHECK_REL(v2, h2, 1e-3);
    CHECK_NEAR(f2, h2 / lim, 5e-4); /* 3 decimals printed */
    /* a missing file among several: exit 2 naming it */
    snprintf(args, sizeof args, "injury %s /nonexistent/b.h5", a);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "/nonexistent/b.h5");
}

static void test_injury_errors(void)
{
    cli_result *r = cli_run("injury /nonexistent/run.h5");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "/nonexistent/run.h5");
    r = cli_run("injury");
    CHECK(r->status == 2);
    r = cli_run("injury x.h5 --stage 7");
    CHECK(r->status == 2);
    /* a results file without dummy channels */
    char path[128], args[256];
    snprintf(path, sizeof path, "%s/empty.h5", tmpdir);
    mcs_results *w = NULL;
    mcs_error e = {0};
    double t[3] = {0, 1e-3, 2e-3}, y[3] = {1, 2, 3};
    CHECK(mcs_results_create(&w, path, NULL, &e) == MCS_OK);
    mcs_results_put_time(w, 1, 3, t, &e);
    mcs_results_put_channel(w, 1, "motorcycle_ax", 3, y, "m/s^2", NULL, 60, NULL, &e);
    CHECK(mcs_results_commit(&w, &e) == MCS_OK);
    snprintf(args, sizeof args, "injury %s", path);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "head_ax");
}

/* the dummy size (analysis/an_dummy.h): a file whose /stage1 attribute dummy is 5th_female is
 * rated with the Hybrid III 5th female's Nij intercepts (FMVSS 208: 4287 / 3880 N, 155 / 67
 * N m, REFERENCES.md) and neck tension limit (2620 N, FMVSS 208 S15.3, unverified); --dummy
 * overrides the file. Hand calculation on the four neck points of write_run: with the 5th's
 * intercepts the largest is CE at the 4th point, 1232/3880 + (100 + 0.01778 x 500)/67 = 1.9427;
 * with the 50th's, 1232/6160 + 108.89/135 = 1.0066 (also CE) */
static void test_injury_dummy(void)
{
    char path[128], args[256];
    snprintf(path, sizeof path, "%s/f05.h5", tmpdir);
    write_run_as(path, 4001, 2e-5, 100, "5th_female");
    double ce05 = 1232 / 3880.0 + (100 + 0.01778 * 500) / 67.0;
    double ce50 = 1232 / 6160.0 + (100 + 0.01778 * 500) / 135.0;
    snprintf(args, sizeof args, "injury %s --json", path);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"dummy\": \"5th_female\"");
    CHECK_NEAR(crit(r->out, "nij", "value"), ce05, 1e-9);
    CHECK_NEAR(crit(r->out, "neck_tension", "limit"), 2620, 0);
    CHECK_NEAR(crit(r->out, "femur_compression", "limit"), 6805, 0);
    CHECK_NEAR(crit(r->out, "hic15", "limit"), 700, 0); /* the same for both sizes */
    snprintf(args, sizeof args, "injury %s --dummy 50th_male --json", path);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_NEAR(crit(r->out, "nij", "value"), ce50, 1e-9);
    CHECK_NEAR(crit(r->out, "neck_tension", "limit"), 4170, 0);
    snprintf(args, sizeof args, "injury %s", path);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "stage 1, Hybrid III 5th_female");
    snprintf(args, sizeof args, "injury %s --dummy 10th_child", path);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "50th_male|5th_female|95th_male");
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_injcli_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_injury_table);
    RUN(test_injury_two_files);
    RUN(test_injury_errors);
    RUN(test_injury_dummy);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tmpdir);
    TEST_END();
}

/* tests for `mcrash signal`: on hand-written CSV files (tests/data/signals/) and on CSV files
 * generated here, against the closed forms of test_criteria.c; and its errors */
#include "analysis/an_mme.h"
#include "analysis/an_signal.h"
#include "tests/cli_util.h"
#include "tests/harness.h"

#include <math.h>

static char tmpdir[64];

/* number after "key": in a JSON line; NaN if absent */
static double json_num(const char *json, const char *key)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *p = strstr(json, pat);
    return p ? strtod(p + strlen(pat), NULL) : NAN;
}

/* a path in the test's temporary folder; each call site keeps its own copy */
#define TMP_PATH(var, name)                                                                        \
    char var[256];                                                                                 \
    snprintf(var, sizeof var, "%s/%s", tmpdir, name)

/* JSON numbers are printed with 10 significant digits: 1e-9 relative covers the rounding */
#define JREL 1e-9

/* head_square.csv: 10 ms at 80 g resultant (48, 64, 0 g), 1 kHz, time in ms.
 * HIC = tau A^2.5 = 0.010 * 80^2.5 on [10, 20] ms for both windows (see test_criteria.c);
 * a3ms = 80 g (a 10 ms plateau) */
static void test_hand_head(void)
{
    cli_result *r = cli_run("signal hic tests/data/signals/head_square.csv --json");
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "hic"), 0.010 * pow(80, 2.5), JREL);
    CHECK_NEAR(json_num(r->out, "t1"), 0.010, 1e-12);
    CHECK_NEAR(json_num(r->out, "t2"), 0.020, 1e-12);
    CHECK_REL(json_num(r->out, "fraction"), 0.010 * pow(80, 2.5) / 700, JREL);
    r = cli_run("signal hic --window 36ms tests/data/signals/head_square.csv --json");
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "hic"), 0.010 * pow(80, 2.5), JREL);
    CHECK_NEAR(json_num(r->out, "limit"), 1000, 0);
    r = cli_run("signal a3ms tests/data/signals/head_square.csv --json");
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "a3ms"), 80, JREL);
    r = cli_run("signal hic tests/data/signals/head_square.csv");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "HIC");
    CHECK_STR_CONTAINS(r->out, "572.4");
}

/* neck.csv (kN): the four hand-computed Nij points of test_criteria.c; max CE 1.006593 */
static void test_hand_neck(void)
{
    cli_result *r = cli_run("signal nij tests/data/signals/neck.csv --json");
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "nij"), 0.2 + 108.89 / 135, JREL);
    CHECK_STR_CONTAINS(r->out, "\"mode\": \"CE\"");
    CHECK_NEAR(json_num(r->out, "time"), 0.004, 1e-12);
    CHECK_REL(json_num(r->out, "TF"), 1.0, JREL);
    CHECK_REL(json_num(r->out, "TE"), 1000.0 / 6806 + 0.4, JREL);
    CHECK_REL(json_num(r->out, "CF"), 0.5 + 17.78 / 310, JREL);
    r = cli_run("signal nij tests/data/signals/neck.csv");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "mode CE");
}

/* tibia.csv: TI = 1.5; head_rotation.csv: BrIC = sqrt(1.25); chest.csv: VC = 1.3*0.008/0.229 */
static void test_hand_others(void)
{
    cli_result *r = cli_run("signal ti tests/data/signals/tibia.csv --json");
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "ti"), 1.5, JREL);
    r = cli_run("signal bric tests/data/signals/head_rotation.csv --json");
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "bric"), sqrt(1.25), JREL);
    r = cli_run("signal vc tests/data/signals/chest.csv --json");
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "vc"), 1.3 * 0.008 / 0.229, JREL);
    CHECK_NEAR(json_num(r->out, "time"), 0.008, 1e-12);
}

/* a generated half-sine head pulse (one column, g, 20 kHz, T = 12 ms, A = 100 g), closed
 * form of test_criteria.c: tan x = 5x/3 -> x* = 1.05165 (width 0.6696 T = 8.04 ms < 15 ms),
 * HIC = (2AT/pi)^2.5 sin(x*)^2.5 / (2 x* T / pi)^1.5. h = 5e-5 s: the trapezoid alone costs
 * 2.5 (pi h / T)^2 / 12 = 3.6e-5 and the window's ends lie on the 50 us grid (8.00 ms for
 * 8.04 ms); measured -6.6e-5, tolerance 1e-4. a3ms = A cos(pi 1.5 ms / T): the 3 ms window's
 * ends fall on samples, exact to the 10 digits printed (1e-9). */
static void test_generated_half_sine(void)
{
    TMP_PATH(p, "half_sine.csv");
    FILE *f = fopen(p, "w");
    if (!f) return;
    fprintf(f, "time [s], head_res [g]\n");
    double A = 100, T = 0.012, h = 5e-5;
    for (int i = 0; i <= 1000; i++) {
        double t = i * h, s = t - 0.01;
        fprintf(f, "%.12g, %.12g\n", t, (s > 0 && s < T) ? A * sin(M_PI * s / T) : 0.0);
    }
    fclose(f);
    double x = 1.05;
    for (int k = 0; k < 50; k++) x -= (tan(x) - 5 * x / 3) / (1 / (cos(x) * cos(x)) - 5.0 / 3);
    double hic = pow(2 * A * T / M_PI, 2.5) * pow(sin(x), 2.5) / pow(2 * x * T / M_PI, 1.5);
    char args[400];
    snprintf(args, sizeof args, "signal hic %s --json", p);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "hic"), hic, 1e-4);
    snprintf(args, sizeof args, "signal a3ms %s --json", p);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "a3ms"), A * cos(M_PI * 0.0015 / T), JREL);
}

/* `cfc` writes the filtered CSV on stdout: a unit sine at 2.0775 CFC comes out at amplitude
 * 1/2 (-6.02 dB; the filter itself to 1e-12 in test_cfc.c). Fit over the middle half of 60
 * cycles: the 12 digits written and the end transients there leave 2e-12 (measured);
 * tolerance 1e-9. */
static void test_cfc_stdout(void)
{
    TMP_PATH(p, "sine.csv");
    FILE *f = fopen(p, "w");
    if (!f) return;
    double fs = 10000, fr = 2.0775 * 180;
    int n = 1600;
    fprintf(f, "time [s], chest_ax [m/s^2]\n");
    for (int i = 0; i < n; i++) fprintf(f, "%.12g, %.12g\n", i / fs, sin(2 * M_PI * fr * i / fs));
    fclose(f);
    char args[400];
    snprintf(args, sizeof args, "signal cfc --class 180 %s", p);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "time [s], chest_ax [m/s^2]");
    TMP_PATH(q, "filtered.csv");
    f = fopen(q, "w");
    if (!f) return;
    fputs(r->out, f);
    fclose(f);
    an_signal *c = NULL;
    int nc = 0;
    mcs_error e = {0};
    CHECK(an_csv_read(q, &c, &nc, &e) == MCS_OK);
    if (nc == 1 && c[0].n == n) {
        double ss = 0, cc = 0, sc = 0, ys = 0, yc = 0;
        for (int i = n / 4; i < 3 * n / 4; i++) {
            double s = sin(2 * M_PI * fr * c[0].t[i]), co = cos(2 * M_PI * fr * c[0].t[i]);
            ss += s * s, cc += co * co, sc += s * co, ys += c[0].y[i] * s, yc += c[0].y[i] * co;
        }
        double det = ss * cc - sc * sc, a = (ys * cc - yc * sc) / det, b = (yc * ss - ys * sc) / det;
        CHECK_NEAR(sqrt(a * a + b * b), 0.5, 1e-9);
    } else {
        CHECK(!"filtered CSV has the wrong shape");
    }
    an_signals_free(&c, nc);
    /* without --class the class comes from the column name (chest -> 180): same output */
    snprintf(args, sizeof args, "signal cfc %s", p);
    cli_result *r2 = cli_run(args);
    CHECK(r2->status == 0);
    f = fopen(q, "r");
    if (f) {
        static char prev[65536];
        size_t k = fread(prev, 1, sizeof prev - 1, f);
        prev[k] = 0;
        fclose(f);
        CHECK(strcmp(prev, r2->out) == 0);
    }
    /* CFC 1000 at 10 kHz is fine; CFC 3000 needs more than 12.5 kHz: refused */
    snprintf(args, sizeof args, "signal cfc --class 3000 %s", p);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "too low");
}

/* one channel by reference: the hand-written square pulse resultant written as ISO-MME and
 * rated from `file.mme:channel` and `file.csv:column` gives the same HIC (tau A^2.5) */
static void test_channel_refs(void)
{
    double t[31], y[31];
    for (int i = 0; i <= 30; i++) t[i] = i * 1e-3, y[i] = (i >= 10 && i <= 20) ? 80 * 9.80665 : 0;
    an_signal s = {.n = 31, .t = t, .y = y};
    snprintf(s.name, sizeof s.name, "HEADRES");
    snprintf(s.unit, sizeof s.unit, "m/s^2");
    TMP_PATH(dir, "mme");
    mcs_error e = {0};
    CHECK(an_mme_write(dir, "SQ", &s, 1, &e) == MCS_OK);
    char args[400];
    snprintf(args, sizeof args, "signal hic %s/SQ.mme:HEADRES --json", dir);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "hic"), 0.010 * pow(80, 2.5), JREL);
    snprintf(args, sizeof args, "signal hic %s/SQ.mme:NOPE", dir);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "NOPE");
    r = cli_run("signal a3ms tests/data/signals/head_square.csv:ay --json");
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "a3ms"), 64, JREL);
}

/* bad input: file:line:col and exit 2; missing columns listed; usage errors */
/* stage-1 exports name the axes with the sensor as prefix (head_ax head_ay head_az) and write
 * z down (SAE J211), so a drop is negative: the same 80 g square pulse as head_square.csv,
 * written as prefixed columns and as one negative column, must give the same HIC (resultant
 * and |a| of one axis are the same magnitude) */
static void test_prefixed_and_signed(void)
{
    TMP_PATH(p, "prefixed.csv");
    TMP_PATH(q, "single.csv");
    FILE *f = fopen(p, "w"), *g = fopen(q, "w");
    CHECK(f && g);
    if (!f || !g) return;
    fprintf(f, "time [s], head_ax [g], head_ay [g], head_az [g], pelvis_ax [g]\n");
    fprintf(g, "time [s], head_az [g]\n");
    for (int i = 0; i <= 40; i++) {
        int on = i >= 10 && i <= 20;
        fprintf(f, "%g, %g, %g, 0, 1\n", i * 1e-3, on ? 48.0 : 0.0, on ? 64.0 : 0.0);
        fprintf(g, "%g, %g\n", i * 1e-3, on ? -80.0 : 0.0);
    }
    fclose(f);
    fclose(g);
    char args[600];
    snprintf(args, sizeof args, "signal hic %s --json", p);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "hic"), 0.010 * pow(80, 2.5), JREL);
    snprintf(args, sizeof args, "signal hic %s --json", q);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_REL(json_num(r->out, "hic"), 0.010 * pow(80, 2.5), JREL);
}

static void test_errors(void)
{
    TMP_PATH(p, "bad.csv");
    FILE *f = fopen(p, "w");
    if (!f) return;
    fputs("time [s], ax [g]\n0, 1\n0.001, x1\n", f);
    fclose(f);
    char args[400];
    snprintf(args, sizeof args, "signal hic %s", p);
    cli_result *r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "bad.csv:3:8:");
    CHECK(r->out[0] == 0);
    f = fopen(p, "w");
    if (!f) return;
    fputs("time [s], ax [stone]\n0, 1\n0.001, 1\n", f);
    fclose(f);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "bad.csv:1:15:");
    CHECK_STR_CONTAINS(r->err, "stone");
    r = cli_run("signal nij tests/data/signals/tibia.csv");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "Fx");
    CHECK_STR_CONTAINS(r->err, "Mx [N*m]");
    r = cli_run("signal hic tests/data/signals/neck.csv");
    CHECK(r->status == 2);
    r = cli_run("signal frob tests/data/signals/neck.csv");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "usage");
    r = cli_run("signal hic");
    CHECK(r->status == 2);
    r = cli_run("signal hic tests/data/signals/head_square.csv --window -3");
    CHECK(r->status == 2);
    r = cli_run("signal hic /nonexistent.csv");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "/nonexistent.csv");
    /* an acceleration column without a unit is refused, not guessed */
    f = fopen(p, "w");
    if (!f) return;
    fputs("time, a\n0, 1\n0.001, 1\n0.002, 1\n0.003, 1\n0.004, 1\n", f);
    fclose(f);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "a [-]");
    r = cli_run("signal --help");
    CHECK(r->status == 0);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_sigcli_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_hand_head);
    RUN(test_hand_neck);
    RUN(test_hand_others);
    RUN(test_generated_half_sine);
    RUN(test_cfc_stdout);
    RUN(test_channel_refs);
    RUN(test_prefixed_and_signed);
    RUN(test_errors);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tmpdir);
    TEST_END();
}

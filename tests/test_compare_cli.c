/* tests for `mcrash compare` on the files in tests/data/compare (run from the repository root).
 * ref.csv / cmp.csv, 10 kHz, 0..0.1 s (1001 samples):
 *   ax [g]:  ref 50 g on samples 300..699, cmp 60 g on the same samples (scale s = 1.2);
 *   fz [kN]: ref 4 kN half-sine on samples 300..500, cmp the same pulse 15 samples later.
 * zero.csv: one channel that is zero everywhere. Expected values derived in the comments. */
#include <stdlib.h>

#include "analysis/an_mme.h"
#include "analysis/an_signal.h"
#include "tests/cli_util.h"
#include "tests/harness.h"

#define D "tests/data/compare/"

/* JSON numbers have 10 significant digits; the closed forms below are met to that (measured
 * differences <= 5e-11 on values <= 1) */
#define JTOL 1e-9

/* the number after "key": in a JSON object, NAN when absent */
static double json_num(const char *js, const char *key)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *p = strstr(js, pat);
    return p ? strtod(p + strlen(pat), NULL) : NAN;
}

static void test_iso_scaled_square(void)
{
    /* ISO 18571 of a rectangle scaled by s = 1.2 (derivation in tests/test_iso18571.c,
     * check_scaled_square): N = 1001, p = 400 plateau samples, |d| = 0.2 A:
     * Z = (1001 - 400 + 400 (0.3/0.45)^2)/1001, E_P = 1, E_M = 1 - 2(0.2) = 0.6,
     * E_S = (2 - 0.2)/2 = 0.9, R = 0.4 Z + 0.2 + 0.12 + 0.18. The g -> m/s^2 conversion scales
     * both channels alike and changes nothing. */
    cli_result *r = cli_run("compare " D "ref.csv:ax " D "cmp.csv:ax --json");
    CHECK(r->status == 0);
    double z = (601 + 400 * 4.0 / 9.0) / 1001;
    CHECK_NEAR(json_num(r->out, "corridor"), z, JTOL);
    CHECK_NEAR(json_num(r->out, "phase"), 1.0, 1e-9);
    CHECK_NEAR(json_num(r->out, "magnitude"), 0.6, JTOL);
    CHECK_NEAR(json_num(r->out, "slope"), 0.9, JTOL);
    CHECK_NEAR(json_num(r->out, "rating"), 0.4 * z + 0.5, JTOL);
    CHECK_STR_CONTAINS(r->out, "\"grade\": \"good\"");
    CHECK_STR_CONTAINS(r->out, "\"method\": \"iso18571\"");
    /* the table says the same */
    r = cli_run("compare " D "ref.csv:ax " D "cmp.csv:ax");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "ISO/TS 18571");
    CHECK_STR_CONTAINS(r->out, "0.6000    0.20   DTW error 0.2000");
    CHECK_STR_CONTAINS(r->out, "good");
}

static void test_iso_time_shift(void)
{
    /* a pure shift of 15 samples: E_P = (0.2 N - 15)/(0.2 N), 0.2 N = 200.2; the shifted pair is
     * identical, E_M = E_S = 1; the shift is 1.5 ms */
    cli_result *r = cli_run("compare " D "ref.csv:fz " D "cmp.csv:fz --method iso18571 --json");
    CHECK(r->status == 0);
    CHECK_NEAR(json_num(r->out, "phase"), (200.2 - 15) / 200.2, 1e-9);
    CHECK_NEAR(json_num(r->out, "magnitude"), 1.0, 1e-9);
    CHECK_NEAR(json_num(r->out, "slope"), 1.0, 1e-9);
    CHECK_NEAR(json_num(r->out, "shift_s"), 1.5e-3, 1e-12);
}

static void test_cora(void)
{
    /* CORA of the scaled rectangle (tests/test_cora.c, check_scaled): interval samples 297..778
     * (482, 400 on the plateau), Z = (82 + 400 (4/9))/482, E_G = 1/1.44, E_V = E_P = 1,
     * CORA = 0.5 Z + 0.5 (0.5 + 0.25/1.44 + 0.25) */
    cli_result *r = cli_run("compare " D "ref.csv:ax " D "cmp.csv:ax --method=cora --json");
    CHECK(r->status == 0);
    double z = (82 + 400 * 4.0 / 9.0) / 482;
    CHECK_NEAR(json_num(r->out, "corridor"), z, JTOL);
    CHECK_NEAR(json_num(r->out, "size"), 1 / 1.44, JTOL);
    CHECK_NEAR(json_num(r->out, "progression"), 1.0, 1e-9);
    CHECK_NEAR(json_num(r->out, "phase"), 1.0, 1e-9);
    CHECK_NEAR(json_num(r->out, "rating"), 0.5 * z + 0.5 * (0.75 + 0.25 / 1.44), JTOL);
    CHECK_STR_CONTAINS(r->out, "\"method\": \"cora\"");
    /* the shifted half-sine: interval 301..533 (T = 232 samples), D_MIN T = 2.32,
     * D_MAX T = 27.84 samples: E_P = (27.84 - 15)/(27.84 - 2.32) */
    r = cli_run("compare " D "ref.csv:fz " D "cmp.csv:fz --method cora --json");
    CHECK(r->status == 0);
    CHECK_NEAR(json_num(r->out, "phase"), (27.84 - 15) / (27.84 - 2.32), 1e-9);
    CHECK_NEAR(json_num(r->out, "size"), 1.0, 1e-9);
    CHECK_NEAR(json_num(r->out, "progression"), 1.0, 1e-9);
    r = cli_run("compare " D "ref.csv:fz " D "cmp.csv:fz --method cora");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "progression");
    CHECK_STR_CONTAINS(r->out, "shift 1.5 ms");
}

static void test_identical_and_across_formats(void)
{
    /* a channel against itself rates 1 with both methods */
    cli_result *r = cli_run("compare " D "ref.csv:fz " D "ref.csv:fz --json");
    CHECK(r->status == 0);
    CHECK_NEAR(json_num(r->out, "rating"), 1.0, 1e-12);
    r = cli_run("compare " D "ref.csv:fz " D "ref.csv:fz --method cora --json");
    CHECK(r->status == 0);
    CHECK_NEAR(json_num(r->out, "rating"), 1.0, 1e-12);

    /* the same channel written as ISO-MME (10 significant digits) and read back rates 1
     * against the CSV: measured 1 to the 10 digits printed */
    an_signal s;
    mcs_error err = {0};
    CHECK(an_signal_read_ref(D "ref.csv:fz", &s, &err) == MCS_OK);
    char dir[] = "/tmp/mcrash_cmp_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    CHECK(an_mme_write(dir, "T1", &s, 1, &err) == MCS_OK);
    char args[512];
    snprintf(args, sizeof args, "compare " D "ref.csv:fz %s/T1.mme:1 --json", dir);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_NEAR(json_num(r->out, "rating"), 1.0, JTOL);
    an_signal_free(&s);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
}

static void test_bad_input(void)
{
    /* every bad reference: a clear message on stderr, exit status 2, nothing on stdout */
    cli_result *r = cli_run("compare " D "zero.csv " D "cmp.csv:ax");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "zero everywhere");
    CHECK(r->out[0] == 0);
    r = cli_run("compare " D "ref.csv:nope " D "cmp.csv:ax");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "no column \"nope\"");
    r = cli_run("compare " D "missing.csv:ax " D "cmp.csv:ax");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "missing.csv");
    r = cli_run("compare " D "ref.csv " D "cmp.csv:ax");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "name one");
    r = cli_run("compare " D "ref.csv:ax " D "cmp.csv:fz");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "units differ");
    r = cli_run("compare " D "ref.csv:ax " D "cmp.csv:ax --method wiac");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "unknown method");
    r = cli_run("compare " D "ref.csv:ax");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "usage");
    r = cli_run("compare notes.txt " D "cmp.csv:ax");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "unknown channel reference");
    r = cli_run("compare --help");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "--method");
}

int main(void)
{
    RUN(test_iso_scaled_square);
    RUN(test_iso_time_shift);
    RUN(test_cora);
    RUN(test_identical_and_across_formats);
    RUN(test_bad_input);
    TEST_END();
}

/* test_study_cli.c: `mcrash study` (cli/cmd_study.c): a 2x2 study of the headform drop run
 * with 1 and 2 processes gives the same study file byte for byte; its responses against the
 * closed form; a failed case recorded and the study going on; bad study files exit 2 with
 * FILE:LINE:COL before any run; `--analyze --json` in DESIGN.md's shape */
#include "cli_util.h"
#include "core/mcs_results.h"
#include "harness.h"

#include <sys/stat.h>

#define DATA "tests/data/study/"

static char tmp[64];

/* the headform (m, v) on a linear pad k = 4.5e5 N/m without damping: a half sine of peak
 * deceleration v sqrt(k/m) (scenarios/verification/head_drop.yaml) */
static void test_study_2x2(void)
{
    char cmd[512], a[128], b[128];
    snprintf(a, sizeof a, "%s/j1.h5", tmp);
    snprintf(b, sizeof b, "%s/j2.h5", tmp);
    snprintf(cmd, sizeof cmd, "study " DATA "head_drop_2x2.yaml -o %s -j 1 --quiet", a);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    snprintf(cmd, sizeof cmd, "study " DATA "head_drop_2x2.yaml -o %s -j 2 --quiet", b);
    r = cli_run(cmd);
    CHECK(r->status == 0);
    size_t na = 0, nb = 0;
    char *fa = th_slurp(a, &na), *fb = th_slurp(b, &nb);
    CHECK(fa && fb && na == nb && na > 0 && memcmp(fa, fb, na) == 0); /* whatever N */
    free(fa), free(fb);

    mcs_array d, s, peak, hic, hic2;
    cli_read_dataset(a, "/study/design", &d);
    cli_read_dataset(a, "/study/status", &s);
    cli_read_dataset(a, "/study/responses/peak:stage1.channels.head_az", &peak);
    cli_read_dataset(a, "/study/responses/HIC15", &hic);
    cli_read_dataset(a, "/study/responses/hic15_dataset", &hic2);
    CHECK(d.rank == 2 && d.dims[0] == 4 && d.dims[1] == 2 && s.n == 4 && peak.n == 4);
    /* full factorial, first factor fastest: (4.5, -3), (6, -3), (4.5, -4), (6, -4) in SI */
    static const double m[4] = {4.5, 6, 4.5, 6}, v[4] = {-3, -3, -4, -4};
    for (size_t c = 0; c < 4 && d.n == 8 && peak.n == 4 && hic.n == 4 && hic2.n == 4; c++) {
        CHECK(d.v[2 * c] == m[c] && d.v[2 * c + 1] == v[c]);
        CHECK(s.v[c] == 0);
        CHECK_REL(peak.v[c], fabs(v[c]) * sqrt(4.5e5 / m[c]), 2e-3);
        CHECK(hic.v[c] > 0 && hic.v[c] == hic2.v[c]); /* criterion and its dataset agree */
    }
    CHECK(!strcmp(peak.unit, "m/s^2"));
    mcs_array_free(&d), mcs_array_free(&s), mcs_array_free(&peak);
    mcs_array_free(&hic), mcs_array_free(&hic2);

    char csv[128];
    snprintf(csv, sizeof csv, "%s/j1.csv", tmp);
    size_t n;
    char *t = th_slurp(csv, &n);
    CHECK_STR_CONTAINS(t, "case,status,bodies[head].mass,bodies[head].velocity[2],HIC15,");
    CHECK_STR_CONTAINS(t, "\n3,0,6,-4,");
    free(t);

    /* the analysis: DESIGN.md's JSON keys; t^2 = F for a 2-level factor of an orthogonal
     * design (one-df contrast: regression t and ANOVA F test the same effect) */
    snprintf(cmd, sizeof cmd, "study --analyze %s --json", a);
    r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "{\"regression\": {\"HIC15\": {\"coefficients\": {\"intercept\": ");
    CHECK_STR_CONTAINS(r->out, "\"anova\": {\"HIC15\": {\"bodies[head].mass\": {\"F\": ");
    CHECK_STR_CONTAINS(r->out, "\"r2\": ");
    const char *tk = strstr(r->out, "\"t\": {\"intercept\": ");
    const char *fk = strstr(r->out, "\"anova\": {\"HIC15\": {\"bodies[head].mass\": {\"F\": ");
    double tv = NAN, fv = NAN;
    if (tk && (tk = strstr(tk, "\"bodies[head].mass\": "))) tv = atof(tk + 21);
    if (fk) fv = atof(fk + strlen("\"anova\": {\"HIC15\": {\"bodies[head].mass\": {\"F\": "));
    CHECK_REL(tv * tv, fv, 1e-8);
}

/* the 2^(3-1) design of resolution III: C = AB (Montgomery Table 8.14), A fastest; a Latin
 * hypercube: one sample in each fifth of every factor's range */
static void test_study_frac_lhs(void)
{
    char cmd[512], out[128];
    snprintf(out, sizeof out, "%s/frac.h5", tmp);
    snprintf(cmd, sizeof cmd, "study " DATA "head_drop_frac_lhs.yaml -o %s --quiet", out);
    CHECK(cli_run(cmd)->status == 0);
    mcs_array d;
    cli_read_dataset(out, "/study/design", &d);
    CHECK(d.rank == 2 && d.dims[0] == 4 && d.dims[1] == 3);
    for (size_t c = 0; c < 4 && d.n == 12; c++) {
        int a = d.v[3 * c] > 5 ? 1 : -1, b = d.v[3 * c + 1] > -3.5 ? 1 : -1;
        int cc = d.v[3 * c + 2] > 25 ? 1 : -1;
        CHECK(cc == a * b);
        CHECK(a == (c & 1 ? 1 : -1) && b == (c & 2 ? 1 : -1));
    }
    mcs_array_free(&d);
    snprintf(out, sizeof out, "%s/lhs.h5", tmp);
    snprintf(cmd, sizeof cmd, "study " DATA "head_drop_lhs.yaml -o %s --quiet", out);
    CHECK(cli_run(cmd)->status == 0);
    cli_read_dataset(out, "/study/design", &d);
    static const double lo[3] = {4.5, -4, 0}, hi[3] = {6, -3, 50};
    for (int j = 0; j < 3 && d.n == 15; j++) {
        int seen[5] = {0};
        for (int c = 0; c < 5; c++) {
            double u = (d.v[3 * c + j] - lo[j]) / (hi[j] - lo[j]);
            CHECK(u >= 0 && u < 1);
            if (u >= 0 && u < 1) seen[(int)(u * 5)]++;
        }
        for (int m = 0; m < 5; m++)
            CHECK(seen[m] == 1);
    }
    CHECK(d.n == 15);
    mcs_array_free(&d);
}

static void test_study_failed_case(void)
{
    char cmd[512], out[128], csv[128];
    snprintf(out, sizeof out, "%s/fail.h5", tmp);
    snprintf(csv, sizeof csv, "%s/fail.csv", tmp);
    snprintf(cmd, sizeof cmd, "study " DATA "head_drop_oat_fail.yaml -o %s -j 2", out);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->err, "case 1 failed (exit 1)");
    size_t n;
    char *t = th_slurp(csv, &n);
    /* the base case at the scenario's 10 us, then 4 ms: energy growth, exit 1, NaN */
    CHECK_STR_CONTAINS(t, "\n0,0,1.0000000000000001e-05,");
    CHECK_STR_CONTAINS(t, "\n1,1,0.0040000000000000001,NaN\n");
    free(t);
}

static void test_study_bad_input(void)
{
    struct {
        const char *file, *where, *what;
    } bad[] = {
        {"bad_unit.yaml", DATA "bad_unit.yaml:5:52: error: ", "expected a mass (kg)"},
        {"bad_path.yaml", DATA "bad_path.yaml:5:14: error: ", "names no key of the scenario"},
        {"bad_response.yaml", DATA "bad_response.yaml:6:22: error: ", "'HIC17' is no injury"},
        /* a level outside the key's range (a mass > 0), a range bound in a wrong unit, a
         * path's last key that its block does not know */
        {"bad_range.yaml", DATA "bad_range.yaml:5:52: error: ", "must be > 0 kg (got -6 kg)"},
        {"bad_range_unit.yaml", DATA "bad_range_unit.yaml:5:58: error: ",
         "'-3 kg' is a mass (kg), expected a velocity (m/s)"},
        {"bad_key.yaml", DATA "bad_key.yaml:5:14: error: ", "unknown key in a simulation block"},
        /* no design: the place is the study: block (it was "?:0:0") */
        {"no_design.yaml", DATA "no_design.yaml:2:3: error: ", "study.design: missing"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char cmd[512], dir[128];
        snprintf(cmd, sizeof cmd, "study " DATA "%s -o %s/bad%zu.h5", bad[i].file, tmp, i);
        cli_result *r = cli_run(cmd);
        CHECK(r->status == 2);
        CHECK_STR_CONTAINS(r->err, bad[i].where);
        CHECK_STR_CONTAINS(r->err, bad[i].what);
        snprintf(dir, sizeof dir, "%s/bad%zu_cases", tmp, i);
        struct stat st;
        CHECK(stat(dir, &st) != 0); /* before any run */
    }
    /* a channel the base scenario's stage 1 does not write: a two-step probe run finds it, and
     * no case runs */
    char cmd[512], h5[160];
    snprintf(cmd, sizeof cmd, "study " DATA "bad_channel.yaml -o %s/badch.h5", tmp);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, DATA "bad_channel.yaml:6:22: error: study.responses: no dataset "
                               "/stage1/channels/neck_fz");
    snprintf(h5, sizeof h5, "%s/badch_cases/case_00000.h5", tmp);
    struct stat st;
    CHECK(stat(h5, &st) != 0);
    /* the same for max: of a channel (a one-at-a-time design) */
    snprintf(cmd, sizeof cmd, "study " DATA "bad_channel_max.yaml -o %s/badmax.h5", tmp);
    r = cli_run(cmd);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, DATA "bad_channel_max.yaml:6:22: error: study.responses: no "
                               "dataset /stage1/channels/chest_az");
    snprintf(h5, sizeof h5, "%s/badmax_cases/case_00000.h5", tmp);
    CHECK(stat(h5, &st) != 0);
    CHECK(cli_run("study")->status == 2);
    CHECK(cli_run("study --analyze no_such.h5")->status == 2);
}

int main(void)
{
    setenv("SOURCE_DATE_EPOCH", "0", 1); /* /meta/created: the same in both runs */
    snprintf(tmp, sizeof tmp, "/tmp/mcrash_study_XXXXXX");
    if (!mkdtemp(tmp)) return 1;
    RUN(test_study_2x2);
    RUN(test_study_frac_lhs);
    RUN(test_study_failed_case);
    RUN(test_study_bad_input);
    char rm[128];
    snprintf(rm, sizeof rm, "rm -rf %s", tmp);
    if (system(rm)) fprintf(stderr, "could not remove %s\n", tmp);
    TEST_END();
}

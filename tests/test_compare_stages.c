/* test_compare_stages: `mcrash compare OUT.h5 --stages A,B` (translators/tr_stages.c,
 * cli/cmd_compare_stages.c) on a results file written here with known curves:
 * - stage 2's channels are stage 1's: ISO/TS 18571 and CORA rate 1.0;
 * - stage 3's head_ax and body velocity are stage 1's half-sine delayed by tau = 1 ms: the
 *   ISO/TS 18571 rating by hand (REFERENCES.md "Objective rating"): the shifted pair is the
 *   same curve, so magnitude (DTW error 0) and slope score 1; the phase shift is tau / dt = 10
 *   samples of N = 2001, E_P = (0.2 N - 10) / (0.2 N); the unshifted difference is at most
 *   2 A sin(pi tau / (2 T)) = 0.0314 A, inside the inner corridor 0.05 A, so Z = 1; R = 0.4 +
 *   0.2 E_P + 0.2 + 0.2 = 0.995002;
 *   CORA rates it 1 (its phase tolerance D_MIN T exceeds the shift);
 * - a channel zero in both stages gets its reason, not a rating;
 * - the injury criteria of both stages side by side: HIC15 of the delayed pulse is the same;
 * - the JSON keys are the fixed ones of docs/contracts.md; bad input exits 2. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli_util.h"
#include "core/mcs_results.h"
#include "harness.h"
#include "translators/tr_stages.h"

#define NT 2001
static const double DT = 1e-4, T0 = 0.05, TP = 0.1, A = 600, TAU = 1e-3;

/* a half-sine of A [m/s^2] over [T0 + d, T0 + d + TP], zero elsewhere */
static double pulse(double t, double d)
{
    double s = (t - T0 - d) / TP;
    return s > 0 && s < 1 ? A * sin(M_PI * s) : 0;
}

static void write_stage(mcs_results *r, int s, double d, mcs_error *err)
{
    double t[NT], y[NT], z[NT] = {0}, v[3 * NT] = {0};
    for (int i = 0; i < NT; i++) {
        t[i] = i * DT;
        y[i] = pulse(t[i], d);
        v[3 * i] = 0.01 * y[i];
    }
    CHECK(mcs_results_put_time(r, s, NT, t, err) == MCS_OK);
    const char *frame = "SAE J211 local";
    CHECK(mcs_results_put_channel(r, s, "head_ax", NT, y, "m/s^2", frame, 0, "head", err) == 0);
    CHECK(mcs_results_put_channel(r, s, "head_ay", NT, z, "m/s^2", frame, 0, "head", err) == 0);
    CHECK(mcs_results_put_channel(r, s, "head_az", NT, z, "m/s^2", frame, 0, "head", err) == 0);
    CHECK(mcs_results_put_body(r, s, "frame", "velocity", NT, v, err) == MCS_OK);
}

static char dir[64], h5[128];

static void write_file(void)
{
    snprintf(h5, sizeof h5, "%s/stages.h5", dir);
    mcs_results *r = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_create(&r, h5, "", &err) == MCS_OK);
    if (!r) return;
    write_stage(r, 1, 0, &err);
    write_stage(r, 2, 0, &err);
    write_stage(r, 3, TAU, &err);
    CHECK(mcs_results_commit(&r, &err) == MCS_OK);
}

static const tr_stage_rating *find(const tr_stage_compare *c, const char *name)
{
    for (int i = 0; i < c->nrating; i++)
        if (strcmp(c->rating[i].name, name) == 0) return &c->rating[i];
    return NULL;
}

static const tr_stage_criterion *crit(const tr_stage_compare *c, const char *key)
{
    for (int i = 0; i < c->ncrit; i++)
        if (strcmp(c->crit[i].key, key) == 0) return &c->crit[i];
    return NULL;
}

static void test_identical(void)
{
    tr_stage_compare c;
    mcs_error err = {0};
    CHECK(tr_compare_stages(h5, 1, 2, &c, &err) == MCS_OK);
    /* head_ax, head_ay, head_az, frame/{position (absent), velocity, ...}_x y z */
    CHECK(c.nrating == 6);
    const tr_stage_rating *r = find(&c, "head_ax"), *z = find(&c, "head_ay");
    const tr_stage_rating *v = find(&c, "frame/velocity_x");
    CHECK(r && r->iso_ok && r->cora_ok && v && v->iso_ok && v->cora_ok);
    if (r && v) {
        CHECK_NEAR(r->iso.rating, 1.0, 1e-12);
        CHECK_NEAR(r->cora.rating, 1.0, 1e-12);
        CHECK_NEAR(v->iso.rating, 1.0, 1e-12);
        CHECK(!r->body && v->body && strcmp(r->unit, "m/s^2") == 0);
    }
    CHECK(z && !z->iso_ok && !z->cora_ok && strstr(z->iso_error, "zero everywhere"));
    const tr_stage_criterion *h = crit(&c, "hic15");
    CHECK(h && h->value[0] > 0 && h->value[0] == h->value[1]);
    tr_stage_compare_free(&c);
}

static void test_shift_by_hand(void)
{
    tr_stage_compare c;
    mcs_error err = {0};
    CHECK(tr_compare_stages(h5, 1, 3, &c, &err) == MCS_OK);
    const double ep = (0.2 * NT - TAU / DT) / (0.2 * NT), want = 0.4 + 0.2 * ep + 0.4;
    const char *names[2] = {"head_ax", "frame/velocity_x"};
    for (int k = 0; k < 2; k++) {
        const tr_stage_rating *r = find(&c, names[k]);
        CHECK(r && r->iso_ok);
        if (!r || !r->iso_ok) continue;
        printf("  %s delayed 1 ms: ISO %.6f (by hand %.6f: Z %.6f E_P %.6f E_M %.6f E_S %.6f), "
               "CORA %.4f\n",
               names[k], r->iso.rating, want, r->iso.corridor, r->iso.phase, r->iso.magnitude,
               r->iso.slope, r->cora.rating);
        CHECK(r->iso.n == NT && r->iso.shift == 10);
        CHECK_NEAR(r->iso.shift_time, TAU, 1e-12);
        CHECK_NEAR(r->iso.corridor, 1.0, 1e-12);
        CHECK_NEAR(r->iso.phase, ep, 1e-12);
        CHECK_NEAR(r->iso.magnitude, 1.0, 1e-9);
        CHECK_NEAR(r->iso.slope, 1.0, 1e-9);
        CHECK_NEAR(r->iso.rating, want, 1e-9);
        /* CORA: the interval from 3 % to 7.5 % of the peak (t 50.95 .. 147.61 ms), widened by
         * 1 % before and 20 % after, is T = 116.95 ms; the 1 ms shift is below D_MIN T =
         * 1.17 ms (phase 1), the shifted curves are the same (size, progression 1) and the
         * corridor is the inner one throughout (1) */
        CHECK_NEAR(r->cora.t_end - r->cora.t_start, 0.11695, 2e-4);
        CHECK_NEAR(r->cora.rating, 1.0, 1e-9);
    }
    /* HIC does not see a delay: the same value, its window 1 ms later */
    const tr_stage_criterion *h = crit(&c, "hic15");
    CHECK(h && h->value[0] > 0);
    if (h) CHECK_REL(h->value[1], h->value[0], 1e-6);
    tr_stage_compare_free(&c);
}

/* the value after `key` in s from position `from`, NAN when absent */
static double after(const char *s, const char *from, const char *key)
{
    const char *p = from ? strstr(s, from) : s;
    p = p ? strstr(p, key) : NULL;
    return p ? strtod(p + strlen(key), NULL) : NAN;
}

static void test_cli_json(void)
{
    char args[300];
    snprintf(args, sizeof args, "compare %s --stages 1,3 --json", h5);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    const char *o = r->out;
    /* the fixed keys, in order (docs/contracts.md "compare --stages") */
    static const char *const keys[] = {
        "{\"file\": ", ", \"stages\": [1, 3], \"reference\": 1, \"ratings\": [{\"name\": ",
        ", \"kind\": \"channel\", \"unit\": \"m/s^2\", \"iso18571\": {\"rating\": ",
        ", \"grade\": ", ", \"corridor\": ", ", \"phase\": ", ", \"magnitude\": ",
        ", \"slope\": ", ", \"shift_time\": ", "}, \"cora\": {\"rating\": ", ", \"corridor\": ",
        ", \"cross\": ", ", \"phase\": ", ", \"size\": ", ", \"progression\": ",
        ", \"shift_time\": ", "}}, {\"name\": ", "\"injury\": [{\"key\": ", ", \"label\": ",
        ", \"unit\": ", ", \"limit\": ", ", \"value\": [", "], \"fraction\": [", "]}"};
    const char *p = o;
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
        const char *q = p ? strstr(p, keys[i]) : NULL;
        if (!q) fprintf(stderr, "key %zu missing: %s\n", i, keys[i]);
        CHECK(q != NULL);
        p = q ? q + strlen(keys[i]) : p;
    }
    CHECK_STR_CONTAINS(o, "\"kind\": \"body\"");
    CHECK_STR_CONTAINS(o, "{\"name\": \"head_ay\", \"kind\": \"channel\", \"unit\": \"m/s^2\", "
                          "\"iso18571\": {\"error\": ");
    const double ep = (0.2 * NT - TAU / DT) / (0.2 * NT);
    CHECK_NEAR(after(o, "\"name\": \"head_ax\"", "\"iso18571\": {\"rating\": "),
               0.8 + 0.2 * ep, 1e-9);
    CHECK_NEAR(after(o, "\"name\": \"head_ax\"", "\"shift_time\": "), TAU, 1e-12);
    snprintf(args, sizeof args, "compare %s --stages 1,2", h5);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "head_ax");
    CHECK_STR_CONTAINS(r->out, "1.0000    1.0000");
    CHECK_STR_CONTAINS(r->out, "HIC15");
    /* bad input: a stage the file lacks, a missing file, a bad spelling */
    snprintf(args, sizeof args, "compare %s --stages 1,4", h5);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "no /stage4");
    snprintf(args, sizeof args, "compare %s/none.h5 --stages 1,2", dir);
    CHECK(cli_run(args)->status == 2);
    snprintf(args, sizeof args, "compare %s --stages 1-2", h5);
    CHECK(cli_run(args)->status == 2);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/mcrash_cs_XXXXXX");
    if (!mkdtemp(dir)) return 1;
    write_file();
    RUN(test_identical);
    RUN(test_shift_by_hand);
    RUN(test_cli_json);
    unlink(h5);
    rmdir(dir);
    TEST_END();
}

/* test_mme_export.c: `mcrash export OUT.h5 --mme DIR` (translators/tr_mme.c) -- one ISO-MME test
 * per stage that reads back identical through the ISO-MME reader (analysis/an_mme.c).
 * References: the results file itself, read with mcs_results_read (not the writer or reader
 * under test): every sample bit for bit (written with 17 significant digits, which round-trip
 * any double, C17 5.2.4.2.2 DECIMAL_DIG), the unit, the cfc; the times from ISO-MME's first
 * sample and interval within 1e-12 s of the stored ones (the stored ones are i * dt rounded).
 * Bad input exits 2 and leaves nothing: no such stage, a DIR that cannot be made, a stage that
 * is not uniformly sampled, a stage whose folder cannot be written (the stages written before
 * it are removed again). */
#include "analysis/an_mme.h"
#include "analysis/an_units.h"
#include "core/mcs_results.h"
#include "tests/cli_util.h"
#include "tests/harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char tmpdir[64];

static const char *tp(const char *name)
{
    static char buf[8][512];
    static int k;
    k = (k + 1) % 8;
    snprintf(buf[k], sizeof buf[k], "%s/%s", tmpdir, name);
    return buf[k];
}

static int exists(const char *p)
{
    struct stat sb;
    return stat(p, &sb) == 0;
}

/* the value after "key :" in a channel file, "" when absent */
static void header(const char *path, const char *key, char *out, size_t n)
{
    out[0] = 0;
    FILE *f = fopen(path, "r");
    char line[512];
    while (f && fgets(line, sizeof line, f)) {
        if (strncmp(line, key, strlen(key)) == 0 && strchr(line, ':')) {
            snprintf(out, n, "%s", strchr(line, ':') + 1);
            out[strcspn(out, "\n")] = 0;
            break;
        }
    }
    if (f) fclose(f);
}

/* a short stage-1 run (the head drop), exported; every channel read back through an_mme */
static void test_stage1_roundtrip(void)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "run scenarios/verification/head_drop.yaml -o %s --stage 1 --quiet",
             tp("hd.h5"));
    cli_result *res = cli_run(cmd);
    CHECK(res->status == 0);
    if (res->status) return;
    snprintf(cmd, sizeof cmd, "export %s --mme %s", tp("hd.h5"), tp("mme"));
    res = cli_run(cmd);
    CHECK(res->status == 0);
    CHECK_STR_CONTAINS(res->out, "wrote 1 ISO-MME test (");
    CHECK(exists(tp("mme/stage1/stage1.mme")));
    CHECK(exists(tp("mme/stage1/Channel/stage1.chn")));

    mcs_results *r = NULL;
    mcs_error e = {0};
    CHECK(mcs_results_open(&r, tp("hd.h5"), &e) == MCS_OK);
    if (!r) return;
    char **names = NULL;
    int nn = 0;
    CHECK(mcs_results_list(r, "/stage1/channels", &names, &nn, &e) == MCS_OK);
    CHECK(nn >= 3);
    mcs_array t = {0};
    CHECK(mcs_results_read(r, "/stage1/time", &t, &e) == MCS_OK);
    int checked = 0, axes = 0;
    for (int c = 0; c < nn; c++) {
        char path[256];
        snprintf(path, sizeof path, "/stage1/channels/%s", names[c]);
        mcs_array a = {0};
        CHECK(mcs_results_read(r, path, &a, &e) == MCS_OK);
        an_signal s = {0};
        mcs_error e2 = {0};
        CHECK(an_mme_read_channel(tp("mme/stage1/stage1.mme"), names[c], &s, &e2) == MCS_OK);
        if (e2.status) fprintf(stderr, "%s\n", e2.msg);
        CHECK(strcmp(s.name, names[c]) == 0);
        /* the results file's unit is SI already: the same name, factor 1 */
        double f = 0;
        const char *si = NULL;
        CHECK(an_unit_to_si(a.unit, &f, &si) && f == 1 && strcmp(s.unit, si) == 0);
        double cfc = 0;
        if (mcs_results_has_attr(r, path, "cfc")) mcs_results_attr_double(r, path, "cfc", &cfc, &e);
        CHECK(s.cfc == (int)cfc);
        CHECK(s.n == (int)a.n && a.n == t.n);
        int same = s.n == (int)a.n;
        double tworst = 0;
        for (int i = 0; same && i < s.n; i++) {
            same = memcmp(&s.y[i], &a.v[i], sizeof(double)) == 0;
            tworst = fmax(tworst, fabs(s.t[i] - t.v[i]));
        }
        CHECK(same);
        CHECK(tworst <= 1e-12);
        checked += same;
        /* the J211 axis of an acceleration channel */
        char chan[512], dir[16], ref[128];
        snprintf(chan, sizeof chan, "%s/mme/stage1/Channel/stage1.%03d", tmpdir, c + 1);
        header(chan, "Direction", dir, sizeof dir);
        header(chan, "Reference system", ref, sizeof ref);
        if (strcmp(names[c], "head_ax") == 0 || strcmp(names[c], "head_az") == 0) {
            CHECK(dir[0] == (names[c][6] == 'x' ? 'X' : 'Z'));
            CHECK(strstr(ref, "J211") != NULL);
            axes++;
        }
        an_signal_free(&s);
        mcs_array_free(&a);
    }
    CHECK(checked == nn);
    CHECK(axes == 2);
    printf("stage 1 head drop: %d channels of %zu samples read back bit for bit\n", checked, t.n);
    mcs_array_free(&t);
    mcs_results_list_free(&names, nn);
    mcs_results_close(&r);

    /* compare takes the exported channel by name: the same signal rates 1 */
    snprintf(cmd, sizeof cmd, "compare %s:head_az %s:/stage1/channels/head_az --json",
             tp("mme/stage1/stage1.mme"), tp("hd.h5"));
    res = cli_run(cmd);
    CHECK(res->status == 0);
    CHECK_STR_CONTAINS(res->out, "\"rating\": 1,");
}

/* a results file with stages 1 and 3 (stage 3 non-uniform when bad) */
static void write_two_stages(const char *path, int bad)
{
    mcs_results *r = NULL;
    mcs_error e = {0};
    CHECK(mcs_results_create(&r, path, "mcrash: 1\n", &e) == MCS_OK);
    double t[50], y[50], t3[20], y3[20];
    for (int i = 0; i < 50; i++)
        t[i] = i * 1e-4, y[i] = 9.81 * sin(i * 0.2);
    for (int i = 0; i < 20; i++)
        t3[i] = i * 2e-3 + (bad && i == 7 ? 1e-4 : 0), y3[i] = 1e3 * i;
    CHECK(mcs_results_put_time(r, 1, 50, t, &e) == MCS_OK);
    CHECK(mcs_results_put_channel(r, 1, "pelvis_ay", 50, y, "m/s^2", "SAE J211 local", 1000,
                                  "pelvis", &e) == MCS_OK);
    CHECK(mcs_results_put_time(r, 3, 20, t3, &e) == MCS_OK);
    CHECK(mcs_results_put_channel(r, 3, "wall_force", 20, y3, "N", "world", 0, NULL, &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
}

static void test_stages_and_bad_input(void)
{
    char cmd[1024];
    write_two_stages(tp("two.h5"), 0);
    write_two_stages(tp("bad.h5"), 1);
    snprintf(cmd, sizeof cmd, "export %s --mme %s", tp("two.h5"), tp("two"));
    cli_result *res = cli_run(cmd);
    CHECK(res->status == 0);
    CHECK_STR_CONTAINS(res->out, "wrote 2 ISO-MME tests (2 channels)");
    an_signal s = {0};
    mcs_error e = {0};
    CHECK(an_mme_read_channel(tp("two/stage3/stage3.mme"), "wall_force", &s, &e) == MCS_OK);
    CHECK(s.n == 20 && s.y[19] == 19e3 && strcmp(s.unit, "N") == 0 && s.cfc == 0);
    an_signal_free(&s);
    CHECK(an_mme_read_channel(tp("two/stage1/stage1.mme"), "pelvis_ay", &s, &e) == MCS_OK);
    CHECK(s.n == 50 && s.cfc == 1000 && strcmp(s.unit, "m/s^2") == 0);
    an_signal_free(&s);
    char dir[16];
    header(tp("two/stage1/Channel/stage1.001"), "Direction", dir, sizeof dir);
    CHECK(strcmp(dir, "Y") == 0);
    header(tp("two/stage3/Channel/stage3.001"), "Direction", dir, sizeof dir);
    CHECK(strcmp(dir, "0") == 0);

    /* --stage 3 alone */
    snprintf(cmd, sizeof cmd, "export %s --mme %s --stage 3", tp("two.h5"), tp("s3"));
    res = cli_run(cmd);
    CHECK(res->status == 0);
    CHECK(exists(tp("s3/stage3/stage3.mme")) && !exists(tp("s3/stage1")));
    /* no such stage: exit 2, nothing made */
    snprintf(cmd, sizeof cmd, "export %s --mme %s --stage 2", tp("two.h5"), tp("s2"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "no channels in /stage2");
    CHECK(!exists(tp("s2")));
    /* a DIR that cannot be made (under a regular file) */
    snprintf(cmd, sizeof cmd, "export %s --mme %s/x", tp("two.h5"), tp("two.h5"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "cannot create");
    /* stage 3 not uniformly sampled: refused before anything is written */
    snprintf(cmd, sizeof cmd, "export %s --mme %s", tp("bad.h5"), tp("b"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "not uniformly sampled");
    CHECK(!exists(tp("b")));
    /* stage 3's folder is a file: stage 1, written first, is removed again; the file stays */
    mkdir(tp("p"), 0700);
    FILE *f = fopen(tp("p/stage3"), "w");
    if (f) fclose(f);
    snprintf(cmd, sizeof cmd, "export %s --mme %s", tp("two.h5"), tp("p"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK(!exists(tp("p/stage1")));
    CHECK(exists(tp("p/stage3")));
    /* a missing DIR argument */
    snprintf(cmd, sizeof cmd, "export %s --mme", tp("two.h5"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_mme_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_stage1_roundtrip);
    RUN(test_stages_and_bad_input);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) return 1;
    TEST_END();
}

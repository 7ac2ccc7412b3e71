/* tests for channel exchange: CSV reader with units, ISO-MME read/write, channel references */
#include "analysis/an_mme.h"
#include "analysis/an_signal.h"
#include "analysis/an_units.h"
#include "core/mcs_results.h"
#include "tests/harness.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char tmpdir[64];

static const char *tmp_file(const char *name, const char *text)
{
    static char path[256];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    return path;
}

/* exact conversions: g is 9.80665 m/s^2 by definition, k = 1e3, m = 1e-3, deg = pi/180 */
static void test_csv_units(void)
{
    const char *p = tmp_file("u.csv", "time [ms], a [g], F [kN], M [N*m], M2 [Nm], d [mm], "
                                      "w [deg/s], x\n"
                                      "0, 1, 2, 3, 4, 5, 180, 7\n"
                                      "0.5, -1, 0.5, 0, 0, 0, 0, 0\n");
    an_signal *c = NULL;
    int n = 0;
    mcs_error e = {0};
    CHECK(an_csv_read(p, &c, &n, &e) == MCS_OK);
    CHECK(n == 7);
    if (n != 7) return;
    CHECK_NEAR(c[0].t[1], 0.5e-3, 1e-18);
    CHECK(strcmp(c[0].name, "a") == 0 && strcmp(c[0].unit, "m/s^2") == 0);
    CHECK_NEAR(c[0].y[0], 9.80665, 1e-15);
    CHECK_NEAR(c[0].y[1], -9.80665, 1e-15);
    CHECK(strcmp(c[1].unit, "N") == 0);
    CHECK_NEAR(c[1].y[0], 2000, 1e-12);
    CHECK(strcmp(c[2].unit, "N*m") == 0 && strcmp(c[3].unit, "N*m") == 0);
    CHECK_NEAR(c[3].y[0], 4, 0);
    CHECK(strcmp(c[4].unit, "m") == 0);
    CHECK_NEAR(c[4].y[0], 5e-3, 1e-18);
    CHECK(strcmp(c[5].unit, "rad/s") == 0);
    CHECK_NEAR(c[5].y[0], M_PI, 1e-15);
    CHECK(strcmp(c[6].name, "x") == 0 && strcmp(c[6].unit, "-") == 0);
    CHECK(c[6].n == 2);
    an_signals_free(&c, n);
    CHECK(c == NULL);
}

/* comments, blank lines, CRLF, semicolons and a time column without unit (seconds) */
static void test_csv_formats(void)
{
    const char *p = tmp_file("f.csv", "# a comment\r\n\r\ntime; ax [m/s^2]\r\n0;1\r\n"
                                      "0.001; 2\r\n\r\n0.002;3\r\n");
    an_signal *c = NULL;
    int n = 0;
    mcs_error e = {0};
    CHECK(an_csv_read(p, &c, &n, &e) == MCS_OK);
    CHECK(n == 1 && c && c[0].n == 3);
    if (c) CHECK_NEAR(c[0].y[2], 3, 0);
    if (c) CHECK_NEAR(c[0].t[2], 0.002, 0);
    an_signals_free(&c, n);
}

/* each bad input names the file, line and column */
static void check_csv_error(const char *text, mcs_status want, const char *where, const char *what)
{
    const char *p = tmp_file("bad.csv", text);
    an_signal *c = NULL;
    int n = 0;
    mcs_error e = {0};
    mcs_status st = an_csv_read(p, &c, &n, &e);
    CHECK(st == want);
    CHECK(c == NULL && n == 0);
    char loc[300];
    snprintf(loc, sizeof loc, "bad.csv:%s", where);
    CHECK_STR_CONTAINS(e.msg, loc);
    CHECK_STR_CONTAINS(e.msg, what);
}

static void test_csv_errors(void)
{
    check_csv_error("time [s], a [furlong]\n0, 1\n1, 2\n", MCS_ERR_UNIT, "1:14:", "furlong");
    check_csv_error("time [s], a [g]\n0, 1\n1, abc\n", MCS_ERR_FORMAT, "3:4:", "abc");
    check_csv_error("time [s], a [g]\n0, 1\n1\n", MCS_ERR_FORMAT, "3:2:", "values");
    check_csv_error("time [s], a [g]\n0, 1\n1, 2, 3\n", MCS_ERR_FORMAT, "3:", "more values");
    check_csv_error("time [s], a [g]\n0, 1\n0, 2\n", MCS_ERR_FORMAT, "3:1:", "not after");
    check_csv_error("time [s], a [g]\n0, 1\n1, \n", MCS_ERR_FORMAT, "3:", "empty value");
    check_csv_error("time [s], a [g]\n0, 1\n1, nan\n", MCS_ERR_FORMAT, "3:4:", "finite");
    check_csv_error("time [g], a [g]\n0, 1\n1, 2\n", MCS_ERR_UNIT, "1:1:", "time unit");
    check_csv_error("time [s], a [g\n0, 1\n1, 2\n", MCS_ERR_FORMAT, "1:", "without");
    check_csv_error("time [s], a [g]\n0, 1\n", MCS_ERR_FORMAT, "", "at least 2");
    check_csv_error("", MCS_ERR_FORMAT, "1:1:", "no header");
    check_csv_error("time [s]\n0\n1\n", MCS_ERR_FORMAT, "1:1:", "at least one channel");
    an_signal *c = NULL;
    int n = 0;
    mcs_error e = {0};
    CHECK(an_csv_read("/nonexistent/x.csv", &c, &n, &e) == MCS_ERR_IO);
    CHECK_STR_CONTAINS(e.msg, "/nonexistent/x.csv");
}

static void test_unit_table(void)
{
    double f;
    const char *si;
    CHECK(an_unit_to_si(" kN ", &f, &si) && f == 1e3 && strcmp(si, "N") == 0);
    CHECK(an_unit_to_si("m/s**2", &f, &si) && f == 1 && strcmp(si, "m/s^2") == 0);
    CHECK(!an_unit_to_si("kg*m", &f, &si));
}

/* write ISO-MME, read it back by number, code and through a reference: values survive the
 * text round trip to the 10 significant digits written (%.10g: half a unit of the 10th digit,
 * at most 5e-10 of the value) */
#define MME_TOL(y) (5e-10 * fabs(y) * (1 + 1e-9))
static void test_mme_roundtrip(void)
{
    an_signal ch[2] = {0};
    double t[100], y0[100], y1[100];
    for (int i = 0; i < 100; i++) {
        t[i] = -0.01 + i * 1e-4;
        y0[i] = 100 * sin(i * 0.1);
        y1[i] = 2000 * cos(i * 0.05);
    }
    snprintf(ch[0].name, sizeof ch[0].name, "11HEAD0000H3ACXP");
    snprintf(ch[0].unit, sizeof ch[0].unit, "m/s^2");
    ch[0].cfc = 1000, ch[0].n = 100, ch[0].t = t, ch[0].y = y0;
    snprintf(ch[1].name, sizeof ch[1].name, "11NECKUP00H3FOZB");
    snprintf(ch[1].unit, sizeof ch[1].unit, "N");
    ch[1].n = 100, ch[1].t = t, ch[1].y = y1;
    char dir[128];
    snprintf(dir, sizeof dir, "%s/mme", tmpdir);
    mcs_error e = {0};
    CHECK(an_mme_write(dir, "T001", ch, 2, &e) == MCS_OK);
    char mme[200];
    snprintf(mme, sizeof mme, "%s/T001.mme", dir);
    an_signal r = {0};
    CHECK(an_mme_read_channel(mme, "2", &r, &e) == MCS_OK);
    CHECK(r.n == 100 && strcmp(r.name, "11NECKUP00H3FOZB") == 0 && strcmp(r.unit, "N") == 0);
    for (int i = 0; i < r.n; i++) {
        CHECK_NEAR(r.y[i], y1[i], MME_TOL(y1[i]));
        CHECK_NEAR(r.t[i], t[i], 1e-15); /* t0 + i dt, both written exactly (%.12g) */
    }
    an_signal_free(&r);
    /* the channel file itself, read as text (not by our reader): ISO/TS 13499's header
     * fields, 28 columns then ':', and one sample a line after "Number of samples" */
    char chn[200], line[256];
    snprintf(chn, sizeof chn, "%s/Channel/T001.002", dir);
    FILE *cf = fopen(chn, "r");
    CHECK(cf != NULL);
    int nhead = 0, nval = 0, bad = 0;
    for (int in_data = 0; cf && fgets(line, sizeof line, cf);) {
        if (in_data) {
            bad += nval >= 100 || fabs(strtod(line, NULL) - y1[nval]) > MME_TOL(y1[nval]);
            nval++;
            continue;
        }
        nhead += !strcmp(line, "Name of the channel         :11NECKUP00H3FOZB\n") ||
                 !strcmp(line, "Unit                        :N\n") ||
                 !strcmp(line, "Time of first sample        :-0.01\n") ||
                 !strcmp(line, "Sampling interval           :0.0001\n");
        in_data = !strcmp(line, "Number of samples           :100\n");
    }
    if (cf) fclose(cf);
    CHECK(nhead == 4 && nval == 100 && bad == 0);
    char ref[256];
    snprintf(ref, sizeof ref, "%s:11head0000h3acxp", mme);
    CHECK(an_signal_read_ref(ref, &r, &e) == MCS_OK);
    CHECK(r.cfc == 1000 && strcmp(r.unit, "m/s^2") == 0);
    if (r.n == 100) CHECK_NEAR(r.y[37], y0[37], MME_TOL(y0[37]));
    an_signal_free(&r);
    snprintf(ref, sizeof ref, "%s:nope", mme);
    CHECK(an_signal_read_ref(ref, &r, &e) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(e.msg, "nope");
    /* non-uniform sampling is refused before anything is written */
    t[50] += 3e-5;
    mcs_error e2 = {0};
    char dir2[128];
    snprintf(dir2, sizeof dir2, "%s/mme2", tmpdir);
    CHECK(an_mme_write(dir2, "T002", ch, 2, &e2) == MCS_ERR_RANGE);
    CHECK(access(dir2, F_OK) != 0);
}

/* a hand-written ISO-MME channel file, with a bad sample count */
static void test_mme_read_errors(void)
{
    const char *p = tmp_file("X.001", "Name of the channel         :Head acc / x\n"
                                      "Unit                        :g\n"
                                      "Time of first sample        :0\n"
                                      "Sampling interval           :0.001\n"
                                      "Number of samples           :3\n"
                                      "1\n2\n");
    an_signal r = {0};
    mcs_error e = {0};
    CHECK(an_mme_read_file(p, &r, &e) == MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(e.msg, "2 samples");
    p = tmp_file("Y.001", "Name of the channel         :Head acc / x\n"
                          "Unit                        :g\n"
                          "Time of first sample        :0.002\n"
                          "Sampling interval           :0.001\n"
                          "Number of samples           :3\n"
                          " 1.0\n 2.0\n -3\n");
    mcs_error e2 = {0};
    CHECK(an_mme_read_file(p, &r, &e2) == MCS_OK);
    CHECK(strcmp(r.name, "Head acc") == 0);
    if (r.n == 3) {
        CHECK_NEAR(r.y[2], -3 * 9.80665, 1e-12);
        CHECK_NEAR(r.t[2], 0.004, 1e-15);
    }
    an_signal_free(&r);
}

static void test_ref_csv(void)
{
    const char *p = tmp_file("r.csv", "time [s], ax [g], ay [g]\n0, 1, 2\n1, 3, 4\n");
    char ref[300];
    an_signal s;
    mcs_error e = {0};
    snprintf(ref, sizeof ref, "%s:ay", p);
    CHECK(an_signal_read_ref(ref, &s, &e) == MCS_OK);
    CHECK(s.n == 2 && strcmp(s.name, "ay") == 0);
    if (s.n == 2) CHECK_NEAR(s.y[1], 4 * 9.80665, 1e-12);
    an_signal_free(&s);
    mcs_error e2 = {0};
    CHECK(an_signal_read_ref(p, &s, &e2) == MCS_ERR_USAGE); /* two columns, none named */
    mcs_error e3 = {0};
    snprintf(ref, sizeof ref, "%s:az", p);
    CHECK(an_signal_read_ref(ref, &s, &e3) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(e3.msg, "ax, ay");
    mcs_error e4 = {0};
    CHECK(an_signal_read_ref("x.txt", &s, &e4) == MCS_ERR_USAGE);
}

/* channels from a results file: /stageN/channels/<name> with /stageN/time, a column of a
 * body quantity with [k], the cfc attribute, and errors for a missing dataset */
static void test_ref_h5(void)
{
    char path[200], ref[300];
    snprintf(path, sizeof path, "%s/run.h5", tmpdir);
    double t[50], y[50], acc[150];
    for (int i = 0; i < 50; i++) {
        t[i] = i * 1e-4, y[i] = 100 * i;
        acc[3 * i] = 1, acc[3 * i + 1] = -2.0 * i, acc[3 * i + 2] = 3;
    }
    mcs_results *r = NULL;
    mcs_error e = {0};
    CHECK(mcs_results_create(&r, path, NULL, &e) == MCS_OK);
    CHECK(mcs_results_put_time(r, 1, 50, t, &e) == MCS_OK);
    CHECK(mcs_results_put_channel(r, 1, "head_ax", 50, y, "m/s^2", NULL, 1000, "head", &e) ==
          MCS_OK);
    CHECK(mcs_results_put_body(r, 1, "head", "acceleration", 50, acc, &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    an_signal s;
    snprintf(ref, sizeof ref, "%s:/stage1/channels/head_ax", path);
    CHECK(an_signal_read_ref(ref, &s, &e) == MCS_OK);
    CHECK(s.n == 50 && s.cfc == 1000 && strcmp(s.name, "head_ax") == 0);
    CHECK(strcmp(s.unit, "m/s^2") == 0);
    if (s.n == 50) {
        CHECK_NEAR(s.y[7], 700, 0);
        CHECK_NEAR(s.t[7], 7e-4, 0);
    }
    an_signal_free(&s);
    snprintf(ref, sizeof ref, "%s:/stage1/bodies/head/acceleration[1]", path);
    CHECK(an_signal_read_ref(ref, &s, &e) == MCS_OK);
    if (s.n == 50) CHECK_NEAR(s.y[10], -20, 0);
    an_signal_free(&s);
    mcs_error e2 = {0};
    snprintf(ref, sizeof ref, "%s:/stage1/bodies/head/acceleration", path);
    CHECK(an_signal_read_ref(ref, &s, &e2) == MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(e2.msg, "[k]");
    mcs_error e3 = {0};
    snprintf(ref, sizeof ref, "%s:/stage1/channels/nope", path);
    CHECK(an_signal_read_ref(ref, &s, &e3) != MCS_OK);
    CHECK_STR_CONTAINS(e3.msg, "nope");
    CHECK(s.t == NULL && s.y == NULL);
    /* a NaN in a results file is refused with the sample index */
    snprintf(path, sizeof path, "%s/nan.h5", tmpdir);
    y[20] = NAN;
    mcs_error e4 = {0};
    CHECK(mcs_results_create(&r, path, NULL, &e4) == MCS_OK);
    CHECK(mcs_results_put_time(r, 1, 50, t, &e4) == MCS_OK);
    CHECK(mcs_results_put_channel(r, 1, "x", 50, y, "m", NULL, 0, NULL, &e4) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e4) == MCS_OK);
    snprintf(ref, sizeof ref, "%s:/stage1/channels/x", path);
    CHECK(an_signal_read_ref(ref, &s, &e4) == MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(e4.msg, "sample 20");
    CHECK(s.t == NULL && s.y == NULL);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_sigio_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_csv_units);
    RUN(test_csv_formats);
    RUN(test_csv_errors);
    RUN(test_unit_table);
    RUN(test_mme_roundtrip);
    RUN(test_mme_read_errors);
    RUN(test_ref_csv);
    RUN(test_ref_h5);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tmpdir);
    TEST_END();
}

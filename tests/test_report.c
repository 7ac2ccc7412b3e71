/* test_report: `mcrash report` (translators/tr_report.c) on a sample file with every section
 * (tests/report_sample.h): the sections and what they name, numbers that SVG can read, the
 * sections left out of a file that lacks their data, and bad input (a missing file, a file
 * that is not HDF5, an HDF5 file without a stage) exiting 2 with the file named and no page
 * left behind. The page in a browser: tests/test_report_page.c */
#include "tests/cli_util.h"
#include "tests/harness.h"
#include "tests/report_sample.h"
#include "translators/tr_report.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char tdir[64];

#define tpath(name) th_path(tdir, (name))

static int count(const char *s, const char *needle)
{
    int n = 0;
    for (const char *p = s; (p = strstr(p, needle)); p += strlen(needle)) n++;
    return n;
}

/* a "nan" or "inf" printed as a number (after a space, quote, comma, sign or path letter) */
static int has_bad_number(const char *s)
{
    for (const char *p = s; *p; p++) {
        if (strncasecmp(p, "nan", 3) && strncasecmp(p, "inf", 3)) continue;
        char b = p > s ? p[-1] : ' ';
        if (isalpha((unsigned char)p[3])) continue;
        if (b == ' ' || b == '"' || b == ',' || b == '-' || b == 'M' || b == 'L' || b == '>')
            return 1;
    }
    return 0;
}

static void test_sections(void)
{
    CHECK(rs_write(tpath("sample.h5")) == 0);
    tr_report_summary sum;
    mcs_error e = {0};
    CHECK(tr_report_write(tpath("sample.h5"), tpath("sample.html"), NULL, &sum, &e) == MCS_OK);
    char *s = th_slurp(tpath("sample.html"), NULL);
    CHECK(s != NULL);
    if (!s) return;
    CHECK(sum.bytes == strlen(s));
    /* every section of the sample, in the page's order */
    CHECK(strcmp(sum.sections, "energy,injury,dummy,restraints,crush,parts,stages,kinematics") ==
          0);
    CHECK(sum.skipped[0] == 0);
    CHECK(count(s, "<svg") == sum.nsvg);
    CHECK(count(s, "<svg") == count(s, "</svg>"));
    CHECK(sum.nsvg >= 20);
    CHECK_STR_CONTAINS(s, "<title>mcrash report: report sample</title>");
    /* no network: nothing is fetched */
    CHECK(!strstr(s, "http://") || count(s, "http://") == count(s, "xmlns=\"http://www.w3.org"));
    CHECK(!strstr(s, "https://"));
    CHECK(!strstr(s, "<script"));
    CHECK(!strstr(s, "<link"));
    CHECK(!has_bad_number(s));
    /* the dummy channels name their filter classes; units on the axes */
    CHECK_STR_CONTAINS(s, "Head acceleration, CFC 1000");
    CHECK_STR_CONTAINS(s, "Chest acceleration, CFC 180");
    CHECK_STR_CONTAINS(s, "Upper neck forces, CFC 600");
    CHECK_STR_CONTAINS(s, "acceleration [g]");
    CHECK_STR_CONTAINS(s, "time [ms]");
    CHECK_STR_CONTAINS(s, "crush [mm]");
    /* the injury table: HIC against its 700 limit, and the bar chart's limit line */
    CHECK_STR_CONTAINS(s, "<td>HIC15</td>");
    CHECK_STR_CONTAINS(s, ">limit</text>");
    CHECK_STR_CONTAINS(s, "FMVSS 208 S6.2");
    /* restraints, parts, the energy group's categories, the stage ratings */
    CHECK_STR_CONTAINS(s, "Belt force at the retractor");
    CHECK_STR_CONTAINS(s, "Airbag pressure");
    CHECK_STR_CONTAINS(s, "Foam internal energy");
    CHECK_STR_CONTAINS(s, ">airbags</text>");
    CHECK_STR_CONTAINS(s, ">opponent</text>");
    CHECK_STR_CONTAINS(s, "<h3>Stage 2 against stage 1</h3>");
    CHECK_STR_CONTAINS(s, "head_ax: R = ");
    CHECK_STR_CONTAINS(s, "rider_head/position_x");
    /* snapshots: 0 to 300 ms every 20 ms (16 frames) in two views of stages 1 and 2, stage
     * 3's 0 to 150 ms (8 frames) */
    CHECK_STR_CONTAINS(s, "Stage 1, side view (x forward, z up), every 20 ms");
    CHECK_STR_CONTAINS(s, "Stage 3, top view (x forward, y left), every 20 ms");
    CHECK(count(s, "<clipPath") == 2 * 16 + 2 * 16 + 2 * 8);
    CHECK_STR_CONTAINS(s, ">300 ms</text>");
    free(s);
    /* a second run writes the same bytes (deterministic page) */
    CHECK(tr_report_write(tpath("sample.h5"), tpath("again.html"), NULL, NULL, &e) == MCS_OK);
    char *a = th_slurp(tpath("sample.html"), NULL), *b = th_slurp(tpath("again.html"), NULL);
    CHECK(a && b && strcmp(a, b) == 0);
    free(a);
    free(b);
}

/* a file with energies only: the other sections are left out and listed */
static void test_sections_left_out(void)
{
    mcs_results *r = NULL;
    mcs_error e = {0};
    double t[3] = {0, 0.01, 0.02}, ek[3] = {3, 2, 1};
    CHECK(mcs_results_create(&r, tpath("energy_only.h5"), NULL, &e) == MCS_OK);
    CHECK(mcs_results_put_time(r, 1, 3, t, &e) == MCS_OK);
    CHECK(mcs_results_put_energy(r, 1, "kinetic", 3, ek, &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    tr_report_summary sum;
    CHECK(tr_report_write(tpath("energy_only.h5"), tpath("energy_only.html"), NULL, &sum, &e) ==
          MCS_OK);
    CHECK(strcmp(sum.sections, "energy") == 0);
    CHECK(strcmp(sum.skipped, "injury,dummy,restraints,crush,parts,stages,kinematics") == 0);
    char *s = th_slurp(tpath("energy_only.html"), NULL);
    CHECK_STR_CONTAINS(s, "not in this file: injury,dummy,restraints,crush,parts,stages,");
    CHECK(s && count(s, "<svg") == 1);
    free(s);
}

static void test_bad_input(void)
{
    mcs_error e = {0};
    /* missing */
    CHECK(tr_report_write(tpath("missing.h5"), tpath("missing.html"), NULL, NULL, &e) ==
          MCS_ERR_IO);
    CHECK_STR_CONTAINS(e.msg, "missing.h5");
    CHECK(access(tpath("missing.html"), F_OK) != 0);
    /* not HDF5 */
    FILE *f = fopen(tpath("text.h5"), "w");
    if (f) {
        fputs("not a results file\n", f);
        fclose(f);
    }
    mcs_error_clear(&e);
    CHECK(tr_report_write(tpath("text.h5"), tpath("text.html"), NULL, NULL, &e) ==
          MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(e.msg, "text.h5");
    CHECK(access(tpath("text.html"), F_OK) != 0);
    /* HDF5 without a stage: an earlier page of that name stays as it was */
    mcs_results *r = NULL;
    CHECK(mcs_results_create(&r, tpath("nostage.h5"), NULL, &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    f = fopen(tpath("nostage.html"), "w");
    if (f) {
        fputs("earlier", f);
        fclose(f);
    }
    mcs_error_clear(&e);
    CHECK(tr_report_write(tpath("nostage.h5"), tpath("nostage.html"), NULL, NULL, &e) ==
          MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(e.msg, "not an mcrash results file");
    char *s = th_slurp(tpath("nostage.html"), NULL);
    CHECK(s && strcmp(s, "earlier") == 0);
    free(s);
}

static void test_cli(void)
{
    char args[1024];
    /* missing file: exit 2, named, no folder made, no page */
    snprintf(args, sizeof args, "report %s -o %s", tpath("none.h5"), tpath("outdir"));
    cli_result *res = cli_run(args);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "none.h5");
    CHECK(access(tpath("outdir"), F_OK) != 0);
    snprintf(args, sizeof args, "report %s -o %s", tpath("text.h5"), tpath("outdir"));
    res = cli_run(args);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "text.h5");
    /* a good file: DIR/<name>.html, DIR created */
    snprintf(args, sizeof args, "report %s -o %s", tpath("sample.h5"), tpath("outdir/sub"));
    res = cli_run(args);
    CHECK(res->status == 0);
    CHECK(access(tpath("outdir/sub/sample.html"), R_OK) == 0);
    CHECK_STR_CONTAINS(res->out, "sample.html");
    /* without -o: beside the results file */
    snprintf(args, sizeof args, "report %s", tpath("energy_only.h5"));
    remove(tpath("energy_only.html"));
    res = cli_run(args);
    CHECK(res->status == 0);
    CHECK(access(tpath("energy_only.html"), R_OK) == 0);
    /* usage */
    res = cli_run("report");
    CHECK(res->status == 2);
    res = cli_run("report a.h5 b.h5");
    CHECK(res->status == 2);
}

int main(void)
{
    snprintf(tdir, sizeof tdir, "/tmp/mcrash_report_XXXXXX");
    if (!mkdtemp(tdir)) return 1;
    RUN(test_sections);
    RUN(test_sections_left_out);
    RUN(test_bad_input);
    RUN(test_cli);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tdir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tdir);
    TEST_END();
}

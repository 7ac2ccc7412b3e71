/* test_report_study.c: `mcrash report STUDY.h5`, the study page (translators/tr_report_study.c):
 * the 2x2 head-drop study's page has a main-effect plot per factor and response and the
 * interaction plot, and each point's value is the mean of the cases at that level (or cell),
 * computed here from the study file's design and responses; a file with neither /stageN nor
 * /study is still refused */
#include "cli_util.h"
#include "core/mcs_results.h"
#include "harness.h"

static char tmp[64];

static void read_dataset(const char *h5, const char *path, mcs_array *a)
{
    mcs_results *r = NULL;
    mcs_error err = {0};
    memset(a, 0, sizeof *a);
    if (!mcs_results_open(&r, h5, &err)) mcs_results_read(r, path, a, &err);
    mcs_results_close(&r);
}

static int count(const char *hay, const char *needle)
{
    int n = 0;
    for (const char *p = hay; p && (p = strstr(p, needle)); p++)
        n++;
    return n;
}

static void test_study_page(void)
{
    char cmd[512], h5[128], html[128];
    snprintf(h5, sizeof h5, "%s/s.h5", tmp);
    snprintf(html, sizeof html, "%s/page/s.html", tmp);
    snprintf(cmd, sizeof cmd, "study tests/data/study/head_drop_2x2.yaml -o %s --quiet", h5);
    CHECK(cli_run(cmd)->status == 0);
    snprintf(cmd, sizeof cmd, "report %s -o %s/page", h5, tmp);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "sections: study");
    char *t = th_slurp(html, NULL);
    CHECK(t != NULL);
    if (!t) return;
    CHECK_STR_CONTAINS(t, "<section id=\"study\">");
    CHECK_STR_CONTAINS(t, "design full_factorial, 4 cases (0 failed");
    /* 4 responses x (2 main effects + 1 interaction) */
    CHECK(count(t, "<svg") == 12);
    CHECK(count(t, "main effect of bodies[head].mass: HIC15") == 2); /* aria-label and title */
    CHECK(count(t, "interaction bodies[head].mass x bodies[head].velocity[2]: HIC15") == 2);

    /* the means: design (4 x 2, first factor fastest), each response's values */
    static const char *const resp[4] = {"HIC15", "Head a3ms", "peak:stage1.channels.head_az",
                                        "hic15_dataset"};
    mcs_array d;
    read_dataset(h5, "/study/design", &d);
    CHECK(d.n == 8);
    for (int i = 0; i < 4 && d.n == 8; i++) {
        char path[128], want[160];
        snprintf(path, sizeof path, "/study/responses/%s", resp[i]);
        mcs_array y;
        read_dataset(h5, path, &y);
        CHECK(y.n == 4);
        for (int j = 0; j < 2 && y.n == 4; j++) {
            /* the two levels of factor j: mean over the 2 cases at each */
            double lv[2] = {fmin(d.v[j], d.v[6 + j]), fmax(d.v[j], d.v[6 + j])};
            for (int l = 0; l < 2; l++) {
                double s = 0;
                int n = 0;
                for (int c = 0; c < 4; c++)
                    if (d.v[2 * c + j] == lv[l]) s += y.v[c], n++;
                CHECK(n == 2);
                snprintf(want, sizeof want, "<title>mean %.6g at %.6g (2 cases)</title>", s / n,
                         lv[l]);
                CHECK_STR_CONTAINS(t, want);
            }
        }
        /* the interaction: every cell one case */
        for (int c = 0; c < 4 && y.n == 4; c++) {
            snprintf(want, sizeof want, "<title>mean %.6g at %.6g, %.6g (1 cases)</title>",
                     y.v[c], d.v[2 * c], d.v[2 * c + 1]);
            CHECK_STR_CONTAINS(t, want);
        }
        mcs_array_free(&y);
    }
    mcs_array_free(&d);
    free(t);
}

int main(void)
{
    snprintf(tmp, sizeof tmp, "/tmp/mcrash_rps_XXXXXX");
    if (!mkdtemp(tmp)) return 1;
    RUN(test_study_page);
    char rm[128];
    snprintf(rm, sizeof rm, "rm -rf %s", tmp);
    if (system(rm)) fprintf(stderr, "could not remove %s\n", tmp);
    TEST_END();
}

/* test_study_iso.c: the iso13232 design of `mcrash study` (cli/study_iso.c) with compare: three
 * configurations given by code, each run on the conventional and the concept motorcycle (cut to
 * 10 ms): codes <-> geometry against values written here by hand from the code tables of
 * tests/data/study/iso_pairs.yaml, the motorcycle placed where the code says (closed form of
 * docs/models.md "Placing and speeding the vehicles"), the pairs file and its differences.
 * `make verify`: the 200 configurations x 2 motorcycles of studies/iso13232_sweep.yaml. */
#include "cli_util.h"
#include "core/mcs_results.h"
#include "harness.h"

#define DATA "tests/data/study/"

static char tmp[64];

static void read_dataset(const char *h5, const char *path, mcs_array *a)
{
    mcs_results *r = NULL;
    mcs_error err = {0};
    memset(a, 0, sizeof *a);
    if (!mcs_results_open(&r, h5, &err)) mcs_results_read(r, path, a, &err);
    mcs_results_close(&r);
}

static char *read_attr(const char *h5, const char *name)
{
    mcs_results *r = NULL;
    mcs_error err = {0};
    char *s = NULL;
    if (!mcs_results_open(&r, h5, &err)) mcs_results_attr_str(r, "/study", name, &s, &err);
    mcs_results_close(&r);
    return s;
}

/* the three configurations by hand: the code's digits looked up in the study file's tables
 * (opponent 4: (1.7424, 0, 0.30) m, 2: (1.7830, -0.45, 0.30) m, 6: (1.7448, 0.70, 0.30) m;
 * motorcycle 1: (1.72, 0, 0.30) m; heading 1: 45 deg, 3: 90 deg, 5: 135 deg), the speeds
 * from the code's tail */
static const struct {
    const char *code;
    double opp[3], moto[3], deg, vo, vm;
} cfg[3] = {
    {"413-0/13.4", {1.7424, 0, 0.30}, {1.72, 0, 0.30}, 90, 0, 13.4},
    {"215-6.7/9.8", {1.7830, -0.45, 0.30}, {1.72, 0, 0.30}, 135, 6.7, 9.8},
    {"611-0/17.9", {1.7448, 0.70, 0.30}, {1.72, 0, 0.30}, 45, 0, 17.9},
};

/* the motorcycle frame at t = 0 (docs/models.md): its heading h is the opponent's (0, -1)
 * turned by the angle counter-clockwise, h = (sin a, -cos a); the model (x forward) turned to
 * h and moved so that its contact point lands gap = 50 mm short of the opponent's along h,
 * heights kept: the frame's model point (0.68, 0, 0.58) m (sport_208kg.yaml) goes to
 * opp - (gap + 1.72 - 0.68) h at z 0.58; its yaw is a - 90 deg; its speed vm along h. The
 * sedan (not moved) gets vo along (0, -1, 0). */
static void check_case(const char *dir, long c, int k)
{
    char h5[160];
    snprintf(h5, sizeof h5, "%s/case_%05ld.h5", dir, c);
    double a = cfg[k].deg * M_PI / 180, hx = sin(a), hy = -cos(a), back = 0.050 + 1.72 - 0.68;
    mcs_array p, q, v, vs;
    read_dataset(h5, "/stage1/bodies/moto_frame/position", &p);
    read_dataset(h5, "/stage1/bodies/moto_frame/orientation", &q);
    read_dataset(h5, "/stage1/bodies/moto_frame/velocity", &v);
    read_dataset(h5, "/stage1/bodies/sedan/velocity", &vs);
    CHECK(p.n >= 3 && q.n >= 4 && v.n >= 3 && vs.n >= 3);
    if (p.n >= 3 && q.n >= 4 && v.n >= 3 && vs.n >= 3) {
        CHECK_NEAR(p.v[0], cfg[k].opp[0] - back * hx, 1e-9);
        CHECK_NEAR(p.v[1], cfg[k].opp[1] - back * hy, 1e-9);
        CHECK_NEAR(p.v[2], 0.58, 1e-9);
        double yaw = a - M_PI / 2, s = q.v[0] < 0 ? -1 : 1; /* q and -q: the same rotation */
        CHECK_NEAR(s * q.v[0], cos(yaw / 2), 1e-9);
        CHECK_NEAR(s * q.v[3], sin(yaw / 2), 1e-9);
        CHECK_NEAR(v.v[0], cfg[k].vm * hx, 1e-9);
        CHECK_NEAR(v.v[1], cfg[k].vm * hy, 1e-9);
        CHECK_NEAR(vs.v[1], -cfg[k].vo, 1e-9);
    }
    mcs_array_free(&p), mcs_array_free(&q), mcs_array_free(&v), mcs_array_free(&vs);
}

static void test_iso_pairs(void)
{
    char cmd[512], h5[128], dir[128];
    snprintf(h5, sizeof h5, "%s/iso.h5", tmp);
    snprintf(dir, sizeof dir, "%s/iso_cases", tmp);
    snprintf(cmd, sizeof cmd, "study " DATA "iso_pairs.yaml -o %s -j 2", h5);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "compare - base over 3 rows");

    char *codes = read_attr(h5, "codes");
    CHECK(codes && !strcmp(codes, "413-0/13.4\n215-6.7/9.8\n611-0/17.9"));
    free(codes);
    mcs_array d, var, st;
    read_dataset(h5, "/study/design", &d);
    read_dataset(h5, "/study/variant", &var);
    read_dataset(h5, "/study/status", &st);
    CHECK(d.rank == 2 && d.dims[0] == 6 && d.dims[1] == 9 && var.n == 6 && st.n == 6);
    /* case 2k: configuration k, conventional; 2k + 1: the same, concept */
    for (int c = 0; c < 6 && d.n == 54 && var.n == 6 && st.n == 6; c++) {
        int k = c / 2;
        const double *x = d.v + 9 * c;
        for (int j = 0; j < 3; j++)
            CHECK(x[j] == cfg[k].opp[j] && x[3 + j] == cfg[k].moto[j]);
        CHECK_NEAR(x[6], cfg[k].deg * M_PI / 180, 1e-15);
        CHECK(x[7] == cfg[k].vo && x[8] == cfg[k].vm);
        CHECK(var.v[c] == c % 2 && st.v[c] == 0);
        check_case(dir, c, k);
    }
    mcs_array_free(&d), mcs_array_free(&var), mcs_array_free(&st);

    /* the difference per configuration is concept - conventional of the responses */
    mcs_array hic, dh;
    read_dataset(h5, "/study/responses/peak:stage1.channels.head_ax", &hic);
    read_dataset(h5, "/study/difference/peak:stage1.channels.head_ax", &dh);
    CHECK(hic.n == 6 && dh.n == 3);
    for (int k = 0; k < 3 && hic.n == 6 && dh.n == 3; k++) {
        CHECK(dh.v[k] == hic.v[2 * k + 1] - hic.v[2 * k]);
        CHECK(hic.v[2 * k] > 0);
    }
    mcs_array_free(&hic), mcs_array_free(&dh);
    char csv[128];
    snprintf(csv, sizeof csv, "%s/iso_pairs.csv", tmp);
    char *t = th_slurp(csv, NULL);
    CHECK_STR_CONTAINS(t, "row,code,status_base,status_compare,HIC15.base,HIC15.compare,"
                          "HIC15.difference,");
    CHECK_STR_CONTAINS(t, "\n1,215-6.7/9.8,0,0,");
    free(t);

    /* the study page: the variant is a factor; its main effect is the mean over each
     * motorcycle's three cases */
    snprintf(cmd, sizeof cmd, "report %s", h5);
    CHECK(cli_run(cmd)->status == 0);
    snprintf(csv, sizeof csv, "%s/iso.html", tmp);
    t = th_slurp(csv, NULL);
    CHECK_STR_CONTAINS(t, "main effect of variant (0 scenario, 1 compare): HIC15");
    read_dataset(h5, "/study/responses/HIC15", &hic);
    for (int v = 0; v < 2 && hic.n == 6; v++) {
        char want[160];
        double m = (hic.v[v] + hic.v[2 + v] + hic.v[4 + v]) / 3;
        snprintf(want, sizeof want, "<title>mean %.6g at %d (3 cases)</title>", m, v);
        CHECK_STR_CONTAINS(t, want);
    }
    mcs_array_free(&hic);
    free(t);

    /* --analyze: the columns no configuration changes (the opponent point's height, the
     * motorcycle's point) left out, the variant added: 9 - 4 + 1 factors */
    snprintf(cmd, sizeof cmd, "study --analyze %s", h5);
    r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "6 cases, design iso13232, 6 factors (SI)");
}

/* a configuration whose digit no table holds, and a speed out of its key's range: exit 2 at
 * the code's FILE:LINE:COL, before any run */
static void test_iso_bad(void)
{
    static const char *const bad[][2] = {
        {"\"713-0/13.4\"", "a code the opponent contact table lacks"},
        {"\"413-0/-13.4\"", "impact.motorcycle_speed"},
        {"\"41-0/13.4\"", "expected a code OMH-VO/VM"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char yaml[160], out[160], cmd[512];
        snprintf(yaml, sizeof yaml, "%s/bad%zu.yaml", tmp, i);
        FILE *f = fopen(yaml, "w");
        CHECK(f != NULL);
        if (!f) continue;
        fprintf(f, "study:\n"
                   "  scenario: %s/scenarios/iso13232_413-0_13.4_sedan_rider.yaml\n"
                   "  design:\n"
                   "    type: iso13232\n"
                   "    opponent_contacts: [{code: 4, point: [1.7424 m, 0, 0.30 m]}]\n"
                   "    motorcycle_contacts: [{code: 1, point: [1.72 m, 0, 0.30 m]}]\n"
                   "    headings: [{code: 3, angle: 90 deg}]\n"
                   "    configurations: [%s]\n"
                   "  responses: [HIC15]\n",
                getenv("PWD") ? getenv("PWD") : ".", bad[i][0]);
        fclose(f);
        snprintf(out, sizeof out, "%s/bad%zu.h5", tmp, i);
        snprintf(cmd, sizeof cmd, "study %s -o %s", yaml, out);
        cli_result *r = cli_run(cmd);
        char where[200];
        snprintf(where, sizeof where, "%s:8:22: error: ", yaml);
        CHECK(r->status == 2);
        CHECK_STR_CONTAINS(r->err, where);
        CHECK_STR_CONTAINS(r->err, bad[i][1]);
    }
}

/* make verify: the 200 configurations on both motorcycles, every case run to its end */
static void test_iso_sweep(void)
{
    char cmd[512], h5[128];
    snprintf(h5, sizeof h5, "%s/sweep.h5", tmp);
    snprintf(cmd, sizeof cmd, "study studies/iso13232_sweep.yaml -o %s -j 2", h5);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    printf("%s", r->out);
    mcs_array st, d;
    read_dataset(h5, "/study/status", &st);
    read_dataset(h5, "/study/difference/HIC15", &d);
    CHECK(st.n == 400 && d.n == 200);
    int failed = 0;
    for (size_t c = 0; c < st.n; c++)
        failed += st.v[c] != 0;
    printf("iso13232 sweep: %zu cases, %d failed\n", st.n, failed);
    CHECK(failed == 0);
    mcs_array_free(&st), mcs_array_free(&d);
}

int main(void)
{
    setenv("SOURCE_DATE_EPOCH", "0", 1);
    snprintf(tmp, sizeof tmp, "/tmp/mcrash_iso_XXXXXX");
    if (!mkdtemp(tmp)) return 1;
    RUN(test_iso_pairs);
    RUN(test_iso_bad);
    if (th_verify()) RUN(test_iso_sweep);
    char rm[128];
    snprintf(rm, sizeof rm, "rm -rf %s", tmp);
    if (system(rm)) fprintf(stderr, "could not remove %s\n", tmp);
    TEST_END();
}

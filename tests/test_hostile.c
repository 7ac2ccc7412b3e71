/* test_hostile: hostile and broken input files (issue 18, item 2). Each file is written here in
 * a temporary directory, fed to bin/mcrash, and must be refused with exit 2 and a message that
 * names the file and the place (dataset path or line), without a crash or a sanitizer report.
 * Readers covered: the results file as motion input (`stage2 --motion`), a dataset reference
 * (`compare F.h5:/path`), keyword decks (`check` of a scenario with mesh: {keyword:}), and
 * scenarios (`check`). The table of cases and how each ended is docs/reliability.md's. */
#include <errno.h>
#include <hdf5.h>
#include <sys/stat.h>
#include <time.h>

#include "core/mcs_results.h"
#include "tests/cli_util.h"
#include "tests/harness.h"
#include "tests/figures.h"

static char tdir[64], cwd[512];
static int n_tried, n_refused;

static void tpath(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "%s/%s", tdir, name);
}

static void put_text(const char *name, const char *text, size_t len)
{
    char p[256];
    tpath(p, sizeof p, name);
    FILE *f = fopen(p, "wb");
    if (f) fwrite(text, 1, len, f), fclose(f);
    CHECK(f != NULL);
}

static void put_str(const char *name, const char *text)
{
    put_text(name, text, strlen(text));
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* run `mcrash ARGS` (%s in args: the temporary directory) and check the refusal: exit 2, the
 * message names `file` and `place` */
static void expect_refused(const char *what, const char *args, const char *file, const char *place)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, args, tdir, tdir, tdir);
    double t0 = now();
    cli_result *r = cli_run(cmd);
    double dt = now() - t0;
    const char *nl = strchr(r->err, '\n');
    int len = nl ? (int)(nl - r->err) : (int)strlen(r->err);
    printf("hostile | %-44s | exit %d | %.2f s | %.*s\n", what, r->status, dt, len > 160 ? 160 : len,
           r->err);
    n_tried++;
    n_refused += r->status == 2;
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, file);
    if (place) CHECK_STR_CONTAINS(r->err, place);
    CHECK(!strstr(r->err, "AddressSanitizer") && !strstr(r->err, "runtime error"));
}

/* ---- results files --------------------------------------------------------------------- */

#define NT 301 /* 0 .. 0.3 s at 1 ms: the strike scenario's end time */

enum {
    GOOD,
    NO_BODIES,
    TIME_2D,
    TIME_STRING,
    TIME_NAN,
    TIME_INF,
    TIME_BACK,
    POS_NAN,
    POS_SHAPE,
    CHAN_STRING,
    CHAN_INF,
    CHAN_HUGE,
    CHAN_OVERFLOW,
    TIME_HUGE,
    TIME_MID,
    TIME_OVER,
};

/* a string dataset at path */
static void h5_string(hid_t f, const char *path)
{
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, 8);
    hsize_t d = 2;
    hid_t sp = H5Screate_simple(1, &d, NULL);
    hid_t lc = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(lc, 1);
    hid_t ds = H5Dcreate2(f, path, t, sp, lc, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(ds, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, "abcdefg\0hijklmn");
    H5Dclose(ds), H5Pclose(lc), H5Sclose(sp), H5Tclose(t);
}

/* a chunked double dataset declaring `rank` dims but holding no chunk */
static void h5_declared(hid_t f, const char *path, int rank, const hsize_t *dims)
{
    hsize_t ch[3] = {1, 1, 1}, mx[3] = {H5S_UNLIMITED, H5S_UNLIMITED, H5S_UNLIMITED};
    hid_t sp = H5Screate_simple(rank, dims, mx);
    hid_t dc = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(dc, rank, ch);
    hid_t lc = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(lc, 1);
    hid_t ds = H5Dcreate2(f, path, H5T_IEEE_F64LE, sp, lc, dc, H5P_DEFAULT);
    CHECK(ds >= 0);
    H5Dclose(ds), H5Pclose(lc), H5Pclose(dc), H5Sclose(sp);
}

/* a stage-1 results file with body "block" (at rest) and channel head_ax, broken by `kind` */
static void write_results(const char *name, int kind)
{
    char p[256];
    tpath(p, sizeof p, name);
    mcs_results *r = NULL;
    mcs_error e = {0};
    CHECK(mcs_results_create(&r, p, "", &e) == MCS_OK);
    if (!r) return;
    static double t[NT], pos[NT * 3], q[NT * 4], z[NT * 3], ax[NT];
    for (int i = 0; i < NT; i++) {
        t[i] = 1e-3 * i;
        pos[3 * i] = 0.6, pos[3 * i + 1] = 0, pos[3 * i + 2] = 0.8;
        q[4 * i] = 1, q[4 * i + 1] = q[4 * i + 2] = q[4 * i + 3] = 0;
        ax[i] = 0;
    }
    if (kind == TIME_NAN) t[7] = NAN;
    if (kind == TIME_INF) t[NT - 1] = INFINITY;
    if (kind == TIME_BACK) t[100] = t[98];
    if (kind == POS_NAN) pos[3 * 50 + 2] = NAN;
    if (kind == CHAN_INF) ax[20] = -INFINITY;
    size_t d1 = NT, d2[2] = {NT, 3}, d4[2] = {NT, 4}, dt2[2] = {NT, 1}, dp[2] = {NT, 2};
    if (kind == TIME_2D)
        mcs_results_write(r, "/stage1/time", 2, dt2, t, "s", &e);
    else if (kind != TIME_STRING && kind < TIME_HUGE)
        mcs_results_write(r, "/stage1/time", 1, &d1, t, "s", &e);
    if (kind != NO_BODIES) {
        mcs_results_write(r, "/stage1/bodies/block/position", 2, kind == POS_SHAPE ? dp : d2,
                          pos, "m", &e);
        mcs_results_write(r, "/stage1/bodies/block/orientation", 2, d4, q, "", &e);
        mcs_results_write(r, "/stage1/bodies/block/velocity", 2, d2, z, "m/s", &e);
        mcs_results_write(r, "/stage1/bodies/block/angular_velocity", 2, d2, z, "rad/s", &e);
    }
    if (kind != CHAN_STRING && kind != CHAN_HUGE && kind != CHAN_OVERFLOW)
        mcs_results_write(r, "/stage1/channels/head_ax", 1, &d1, ax, "m/s^2", &e);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    if (kind != TIME_STRING && kind != CHAN_STRING && kind < CHAN_HUGE) return;
    /* the cases the writer refuses to make: raw HDF5 */
    hid_t f = H5Fopen(p, H5F_ACC_RDWR, H5P_DEFAULT);
    CHECK(f >= 0);
    if (kind == TIME_STRING) h5_string(f, "/stage1/time");
    if (kind == CHAN_STRING) h5_string(f, "/stage1/channels/head_ax");
    /* 2^40 values declared (8 TiB), none held */
    hsize_t huge = (hsize_t)1 << 40, over[3] = {(hsize_t)1 << 30, (hsize_t)1 << 30, 1 << 6};
    if (kind == CHAN_HUGE) h5_declared(f, "/stage1/channels/head_ax", 1, &huge);
    if (kind == TIME_HUGE) h5_declared(f, "/stage1/time", 1, &huge);
    /* 2^28 values (2 GiB): an allocation that succeeds, of data the file does not hold */
    hsize_t mid = (hsize_t)1 << 28;
    if (kind == TIME_MID) h5_declared(f, "/stage1/time", 1, &mid);
    if (kind == TIME_OVER) h5_declared(f, "/stage1/time", 3, over);
    /* 2^66 values: the count overflows size_t */
    if (kind == CHAN_OVERFLOW) h5_declared(f, "/stage1/channels/head_ax", 3, over);
    H5Fclose(f);
}

/* a copy of `src` cut to `keep` bytes */
static void truncated_copy(const char *src, const char *dst, double keep)
{
    char a[256], b[256];
    tpath(a, sizeof a, src);
    tpath(b, sizeof b, dst);
    FILE *in = fopen(a, "rb");
    size_t n = 0, cap = 1 << 22;
    char *buf = malloc(cap);
    if (in && buf) n = fread(buf, 1, cap, in);
    if (in) fclose(in);
    FILE *out = fopen(b, "wb");
    if (out && buf) fwrite(buf, 1, (size_t)(keep * (double)n), out);
    if (out) fclose(out);
    free(buf);
    CHECK(n > 1000);
}

static void test_results_files(void)
{
    static const char *names[] = {
        "good.h5",  "nobodies.h5", "time2d.h5", "timestr.h5", "timenan.h5",  "timeinf.h5",
        "back.h5",  "posnan.h5",   "posshp.h5", "chanstr.h5", "chaninf.h5",  "chanhuge.h5",
        "over.h5",  "timehuge.h5", "timemid.h5", "timeover.h5"};
    for (int k = 0; k <= TIME_OVER; k++) write_results(names[k], k);
    truncated_copy("good.h5", "cut.h5", 0.5);
    truncated_copy("good.h5", "cut9.h5", 0.9);

    /* the pendulum strike with its block prescribed from the motion file */
    char text[1024];
    snprintf(text, sizeof text,
             "mcrash: 1\ninclude: %s/scenarios/models/pendulum_arm.yaml\n"
             "simulation: {end_time: 300 ms, time_step: 20 us, output_rate: 10 kHz}\n"
             "environment: {gravity: 1 g, ground: {height: 0 m, friction: 0.5}}\n"
             "bodies:\n  - {name: block, mass: 10 kg, inertia: [0.04, 0.04, 0.04], "
             "position: [0.6 m, 0, 0.8 m], velocity: [0, 0, 0]}\n"
             "stage2: {prescribed: [{body: block}]}\n",
             cwd);
    put_str("s2.yaml", text);
#define S2 "stage2 %s/s2.yaml -o %s/out.h5 --quiet --motion %s/"
    expect_refused("motion: no /stage1/bodies", S2 "nobodies.h5", "nobodies.h5",
                   "/stage1/bodies");
    expect_refused("motion: 2-D /stage1/time", S2 "time2d.h5", "time2d.h5", "/stage1/time");
    expect_refused("motion: string /stage1/time", S2 "timestr.h5", "timestr.h5",
                   "/stage1/time");
    expect_refused("motion: NaN in /stage1/time", S2 "timenan.h5", "timenan.h5",
                   "/stage1/time[7]");
    expect_refused("motion: Inf in /stage1/time", S2 "timeinf.h5", "timeinf.h5",
                   "/stage1/time[300]");
    expect_refused("motion: time not increasing", S2 "back.h5", "back.h5", "/stage1/time[100]");
    expect_refused("motion: NaN in a position", S2 "posnan.h5", "posnan.h5", "row 50");
    expect_refused("motion: position [nt, 2]", S2 "posshp.h5", "posshp.h5", "position");
    expect_refused("motion: 2^40 time values declared", S2 "timehuge.h5", "timehuge.h5",
                   "/stage1/time");
    expect_refused("motion: 2^28 time values declared", S2 "timemid.h5", "timemid.h5",
                   "/stage1/time");
    expect_refused("motion: 2^66 time values declared", S2 "timeover.h5", "timeover.h5",
                   "/stage1/time");
    expect_refused("motion: truncated to 50 %", S2 "cut.h5", "cut.h5", NULL);
    expect_refused("motion: truncated to 90 %", S2 "cut9.h5", "cut9.h5", NULL);
    /* a dataset by reference (compare): the same reader of datasets */
#define CMP "compare %s/good.h5:/stage1/channels/head_ax %s/"
    expect_refused("dataset ref: missing group", CMP "nobodies.h5:/stage1/nobody/x",
                   "nobodies.h5", "/stage1/nobody/x");
    expect_refused("dataset ref: string dataset", CMP "chanstr.h5:/stage1/channels/head_ax",
                   "chanstr.h5", "/stage1/channels/head_ax");
    expect_refused("dataset ref: -Inf in a channel", CMP "chaninf.h5:/stage1/channels/head_ax",
                   "chaninf.h5", "/stage1/channels/head_ax");
    expect_refused("dataset ref: NaN in its time", CMP "timenan.h5:/stage1/channels/head_ax",
                   "timenan.h5", "/stage1/time[7]");
    expect_refused("dataset ref: time not increasing", CMP "back.h5:/stage1/channels/head_ax",
                   "back.h5", "/stage1/time[100]");
    expect_refused("dataset ref: 2^40 values declared", CMP "chanhuge.h5:/stage1/channels/head_ax",
                   "chanhuge.h5", "/stage1/channels/head_ax");
    expect_refused("dataset ref: 2^66 values declared", CMP "over.h5:/stage1/channels/head_ax",
                   "over.h5", "/stage1/channels/head_ax");
    expect_refused("dataset ref: truncated file", CMP "cut.h5:/stage1/channels/head_ax",
                   "cut.h5", NULL);
}

/* ---- keyword decks --------------------------------------------------------------------- */

#define DECK_HEAD "*KEYWORD\n*PART\nbox\n         1         1         1\n"
#define DECK_HEX                                                                                   \
    "*ELEMENT_SOLID\n       1       1       1       2       3       4       5       6       7"    \
    "       8\n"

/* a scenario reading part 1 of `deck` */
static void kw_scenario(const char *yaml, const char *deck)
{
    char text[512];
    snprintf(text, sizeof text,
             "mcrash: 1\nsimulation: {end_time: 1 us}\nfe:\n  parts:\n    - name: p\n"
             "      mesh: {keyword: %s, part: 1}\n",
             deck);
    put_str(yaml, text);
}

static void test_keyword_decks(void)
{
    char text[2048];
    /* node ids past 2^31 */
    snprintf(text, sizeof text, DECK_HEAD "*NODE %%\n%10s%16s%16s%16s\n*END\n", "3000000000",
             "0", "0", "0");
    put_str("bigid.k", text);
    kw_scenario("bigid.yaml", "bigid.k");
    expect_refused("deck: *NODE id 3e9 (past 2^31)", "check %s/bigid.yaml", "bigid.k", ":6:");
    /* node ids near 2^31 on a small deck: no allocation by id */
    char nodes[1024] = "";
    for (int i = 0; i < 8; i++) {
        size_t l = strlen(nodes);
        snprintf(nodes + l, sizeof nodes - l, "%10d%16d%16d%16d\n", 2147483000 + i, i & 1,
                 (i >> 1) & 1, i >> 2);
    }
    snprintf(text, sizeof text,
             DECK_HEAD "*NODE %%\n%s*ELEMENT_SOLID %%\n         1         1%10d%10d%10d%10d"
                       "%10d%10d%10d%10d\n         2         1         9         9         9"
                       "         9         9         9         9         9\n*END\n",
             nodes, 2147483000, 2147483001, 2147483003, 2147483002, 2147483004, 2147483005,
             2147483007, 2147483006);
    put_str("nearmax.k", text);
    kw_scenario("nearmax.yaml", "nearmax.k");
    expect_refused("deck: ids near 2^31, a missing node", "check %s/nearmax.yaml", "nearmax.k",
                   ":16:");
    /* *KEYWORD declaring 10^9 words of memory (the format's only count) and a missing node */
    put_str("memory.k", "*KEYWORD 1000000000\n*PART\nbox\n         1         1         1\n"
                        "*NODE\n       1             0.0             0.0             0.0\n"
                        DECK_HEX "*END\n");
    kw_scenario("memory.yaml", "memory.k");
    expect_refused("deck: *KEYWORD 10^9 words, node missing", "check %s/memory.yaml",
                   "memory.k", ":8:");
    /* circular *INCLUDE */
    put_str("a.k", "*KEYWORD\n*INCLUDE\nb.k\n*END\n");
    put_str("b.k", "*KEYWORD\n*INCLUDE\na.k\n*END\n");
    kw_scenario("circ.yaml", "a.k");
    expect_refused("deck: circular *INCLUDE", "check %s/circ.yaml", "a.k", ":3");
    /* *INCLUDE of a directory */
    char p[256];
    tpath(p, sizeof p, "kdir");
    mkdir(p, 0700);
    put_str("incdir.k", "*KEYWORD\n*INCLUDE\nkdir\n*END\n");
    kw_scenario("incdir.yaml", "incdir.k");
    expect_refused("deck: *INCLUDE of a directory", "check %s/incdir.yaml", "kdir", "incdir.k:3");
    /* the deck a directory */
    kw_scenario("isdir.yaml", "kdir");
    expect_refused("deck: the deck a directory", "check %s/isdir.yaml", "kdir", "isdir.yaml:6");
    /* symlink loop: the deck, and an *INCLUDE */
    char q[256];
    tpath(p, sizeof p, "loop1.k"), tpath(q, sizeof q, "loop2.k");
    CHECK(symlink("loop2.k", p) == 0 || errno == EEXIST);
    CHECK(symlink("loop1.k", q) == 0 || errno == EEXIST);
    kw_scenario("kloop.yaml", "loop1.k");
    expect_refused("deck: a symlink loop", "check %s/kloop.yaml", "loop1.k", "kloop.yaml:6");
    put_str("incloop.k", "*KEYWORD\n*INCLUDE\nloop1.k\n*END\n");
    kw_scenario("incloop.yaml", "incloop.k");
    expect_refused("deck: *INCLUDE of a symlink loop", "check %s/incloop.yaml", "loop1.k",
                   "incloop.k:3");
}

/* ---- scenarios -------------------------------------------------------------------------- */

static void test_scenarios(void)
{
    /* circular include */
    put_str("ca.yaml", "mcrash: 1\ninclude: cb.yaml\n");
    put_str("cb.yaml", "mcrash: 1\ninclude: ca.yaml\n");
    expect_refused("scenario: circular include", "check %s/ca.yaml", "ca.yaml", ":2");
    /* a list of 10^6 elements */
    size_t n = 1000000, cap = 64 + 3 * n;
    char *big = malloc(cap);
    if (big) {
        size_t l = (size_t)snprintf(big, cap, "mcrash: 1\nname: [");
        for (size_t i = 0; i < n; i++) big[l++] = '0', big[l++] = ',';
        l--;
        l += (size_t)snprintf(big + l, cap - l, "]\n");
        put_text("biglist.yaml", big, l);
        free(big);
    }
    expect_refused("scenario: a list of 10^6 elements", "check %s/biglist.yaml", "biglist.yaml",
                   ":2:");
    /* nesting 10^4 deep (flow and block) */
    int depth = 10000;
    big = malloc(64 + 2 * (size_t)depth);
    if (big) {
        size_t l = (size_t)sprintf(big, "mcrash: 1\nname: ");
        for (int i = 0; i < depth; i++) big[l++] = '[';
        for (int i = 0; i < depth; i++) big[l++] = ']';
        big[l++] = '\n';
        put_text("deep.yaml", big, l);
        free(big);
    }
    expect_refused("scenario: [[[...]]] 10^4 deep", "check %s/deep.yaml", "deep.yaml", ":2:");
    big = malloc((size_t)depth * (size_t)depth / 2 + 64);
    if (big) {
        /* a: b: c: ... one level per line, indented by its depth (1000 levels: 0.5 MB) */
        size_t l = (size_t)sprintf(big, "mcrash: 1\n");
        for (int i = 0; i < 1000; i++) {
            for (int j = 0; j < i; j++) big[l++] = ' ';
            l += (size_t)sprintf(big + l, "k:\n");
        }
        put_text("deepblock.yaml", big, l);
        free(big);
    }
    expect_refused("scenario: block maps 10^3 deep", "check %s/deepblock.yaml", "deepblock.yaml",
                   ":");
    /* non-UTF-8 bytes in a key and in a value */
    put_str("badkey.yaml", "mcrash: 1\nna\xff\xfeme: x\n");
    expect_refused("scenario: bytes ff fe in a key", "check %s/badkey.yaml", "badkey.yaml", ":2");
    put_str("badval.yaml", "mcrash: 1\nname: \"a\xc3\x28 b\"\n");
    expect_refused("scenario: bytes c3 28 in a value", "check %s/badval.yaml", "badval.yaml",
                   ":2");
    put_str("badval2.yaml", "mcrash: 1\nname: a\xed\xa0\x80 b\n");
    expect_refused("scenario: a UTF-16 surrogate in a value", "check %s/badval2.yaml",
                   "badval2.yaml", ":2");
    /* an empty file */
    put_str("empty.yaml", "");
    expect_refused("scenario: an empty file", "check %s/empty.yaml", "empty.yaml", NULL);
    /* symlink loops: the scenario, and an include */
    char p[256], q[256];
    tpath(p, sizeof p, "sl1.yaml"), tpath(q, sizeof q, "sl2.yaml");
    CHECK(symlink("sl2.yaml", p) == 0 || errno == EEXIST);
    CHECK(symlink("sl1.yaml", q) == 0 || errno == EEXIST);
    expect_refused("scenario: a symlink loop", "check %s/sl1.yaml", "sl1.yaml", NULL);
    put_str("incsl.yaml", "mcrash: 1\ninclude: sl1.yaml\n");
    expect_refused("scenario: include of a symlink loop", "check %s/incsl.yaml", "sl1.yaml",
                   "incsl.yaml:2");
    /* include of a directory */
    tpath(p, sizeof p, "sdir");
    mkdir(p, 0700);
    put_str("incsdir.yaml", "mcrash: 1\ninclude: sdir\n");
    expect_refused("scenario: include of a directory", "check %s/incsdir.yaml", "sdir",
                   "incsdir.yaml:2");
}

static void test_count(void)
{
    printf("hostile files: %d tried, %d refused with exit 2\n", n_tried, n_refused);
    FIG("reliability.hostile_files", "%.0f", n_tried);
    FIG("reliability.hostile_refused", "%.0f", n_refused);
}

int main(void)
{
    snprintf(tdir, sizeof tdir, "/tmp/mcs_hostile_XXXXXX");
    if (!mkdtemp(tdir)) return perror("mkdtemp"), 1;
    if (!getcwd(cwd, sizeof cwd)) return perror("getcwd"), 1;
    RUN(test_results_files);
    RUN(test_keyword_decks);
    RUN(test_scenarios);
    RUN(test_count);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tdir);
    if (!getenv("HOSTILE_KEEP") && system(cmd)) fprintf(stderr, "cannot remove %s\n", tdir);
    TEST_END();
}

/* test_layers: the layering of DESIGN.md's Layout table, read from the sources' #include lines.
 * Arrows point one way: core <- analysis, fe <- stages <- translators <- cli. Each folder may
 * include the folders of its row below (its own always); the headers private to a folder
 * (fe/'s subfolders, docs/contracts.md "Layout of fe/"; *_internal.h; stage1_mb/'s *_impl.h)
 * only from that folder, tests/ and bench/. The reference is the table itself (DESIGN.md
 * "Layout", its "may use" column), not what the code does; a checker test on synthetic lines
 * shows that a breach is found. */
#include "harness.h"

#include <dirent.h>
#include <sys/stat.h>

typedef struct {
    const char *dir, *may; /* folder, the folders it may include (space-separated) */
} layer;

/* DESIGN.md "Layout": core uses libc, HDF5, libyaml only; analysis core; fe core (SUNDIALS);
 * rom (the reduced-order model, stage 0: docs/contracts.md "Layout: rom/") core, analysis
 * (SUNDIALS), used by translators and cli only;
 * stage1_mb core, analysis, fe; the stages 2 and 3 core, analysis, fe and stage 1's public
 * headers (stage 2's rider surrogate); translators everything above; cli everything */
static const layer layers[] = {
    {"core", "core"},
    {"analysis", "core analysis"},
    {"fe", "core fe"},
    {"rom", "core analysis rom"},
    {"stage1_mb", "core analysis fe stage1_mb"},
    {"stage2_fe", "core analysis fe stage1_mb stage2_fe"},
    {"stage3_fe", "core analysis fe stage1_mb stage3_fe"},
    {"translators", "core analysis fe rom stage1_mb stage2_fe stage3_fe translators"},
    {"cli", "core analysis fe rom stage1_mb stage2_fe stage3_fe translators cli"},
};

/* known breaches, each with its reason; an entry no source needs any more fails the test, so
 * the list only shrinks. "from-folder included-header" */
static const char *const known[] = {
    /* stage 2's model owns the prescribed motion that translators/ builds from a stage-1 file
     * (issue 13): s2_run.h carries a tr_stage2_motion; moving the motion's type below the
     * stages is left to do */
    "stage2_fe translators/tr_stage2_motion.h",
};
enum { NKNOWN = sizeof known / sizeof *known };
static int known_used[NKNOWN];

static int word_in(const char *w, size_t n, const char *list)
{
    for (const char *p = list; *p;) {
        size_t l = strcspn(p, " ");
        if (l == n && strncmp(p, w, n) == 0) return 1;
        p += l;
        p += *p == ' ';
    }
    return 0;
}

/* a header only its own folder may include */
static int private_header(const char *inc)
{
    const char *slash = strchr(inc, '/');
    size_t l = strlen(inc);
    if (!slash) return 0;
    if (strncmp(inc, "fe/", 3) == 0 && strchr(slash + 1, '/')) return 1; /* fe/<sub>/x.h */
    if (l > 11 && strcmp(inc + l - 11, "_internal.h") == 0) return 1;
    if (strncmp(inc, "stage1_mb/", 10) == 0 && l > 7 && strcmp(inc + l - 7, "_impl.h") == 0)
        return 1;
    return 0;
}

/* the breach of one `#include "inc"` in a file of folder dir (NULL: allowed); why gets the
 * reason */
static int breach(const char *dir, const char *inc, char *why, size_t nwhy)
{
    const char *slash = strchr(inc, '/');
    if (!slash) return 0; /* a header beside the file (tests/harness.h style) */
    size_t n = (size_t)(slash - inc);
    const int own = strlen(dir) == n && strncmp(dir, inc, n) == 0;
    for (size_t i = 0; i < sizeof layers / sizeof *layers; i++)
        if (strcmp(layers[i].dir, dir) == 0) {
            if (!own && private_header(inc)) {
                snprintf(why, nwhy, "private header of %.*s", (int)n, inc);
                return 1;
            }
            if (word_in(inc, n, layers[i].may)) return 0;
            snprintf(why, nwhy, "%s may use %s only", dir, layers[i].may);
            return 1;
        }
    return 0; /* tests/, bench/: anything */
}

static int nfiles, nincludes, nbreach;

static void check_file(const char *top, const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) return;
    nfiles++;
    char line[1024];
    for (int ln = 1; fgets(line, sizeof line, f); ln++) {
        const char *p = line;
        while (*p == ' ' || *p == '\t') p++;
        if (strncmp(p, "#include \"", 10)) continue;
        char inc[512];
        if (sscanf(p + 10, "%511[^\"]", inc) != 1) continue;
        nincludes++;
        char why[256];
        if (!breach(top, inc, why, sizeof why)) continue;
        char key[600];
        snprintf(key, sizeof key, "%s %s", top, inc);
        int k = -1;
        for (int i = 0; i < NKNOWN; i++)
            if (strcmp(known[i], key) == 0) k = i;
        if (k >= 0) {
            known_used[k] = 1;
            continue;
        }
        nbreach++;
        fprintf(stderr, "%s:%d: includes %s: %s\n", path, ln, inc, why);
    }
    fclose(f);
}

/* every .c and .h under dir (subfolders too) */
static void walk(const char *top, const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return;
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.') continue;
        char p[1024];
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        struct stat sb;
        if (stat(p, &sb)) continue;
        size_t l = strlen(e->d_name);
        if (S_ISDIR(sb.st_mode))
            walk(top, p);
        else if (l > 2 && (!strcmp(e->d_name + l - 2, ".c") || !strcmp(e->d_name + l - 2, ".h")))
            check_file(top, p);
    }
    closedir(d);
}

/* the checker on synthetic includes (a breach per row of the table, and allowed ones) */
static void test_checker(void)
{
    char why[256];
    CHECK(breach("core", "fe/fe_model.h", why, sizeof why));
    CHECK_STR_CONTAINS(why, "core may use core only");
    CHECK(!breach("core", "core/mcs_error.h", why, sizeof why));
    CHECK(breach("analysis", "fe/fe_state.h", why, sizeof why));
    CHECK(breach("fe", "stage1_mb/mb_model.h", why, sizeof why));
    CHECK(!breach("fe", "fe/scn/fe_scn_pad.h", why, sizeof why));
    CHECK(breach("stage3_fe", "fe/scn/fe_scn_pad.h", why, sizeof why));
    CHECK_STR_CONTAINS(why, "private header of fe");
    CHECK(!breach("stage3_fe", "fe/fe_scn_build.h", why, sizeof why));
    CHECK(breach("stage1_mb", "stage2_fe/s2_run.h", why, sizeof why));
    CHECK(breach("stage2_fe", "stage1_mb/mb_egroup_impl.h", why, sizeof why));
    CHECK(breach("stage2_fe", "stage1_mb/mb_build_internal.h", why, sizeof why));
    CHECK(!breach("stage2_fe", "stage1_mb/mb_model.h", why, sizeof why));
    CHECK(breach("stage3_fe", "stage2_fe/s2_run.h", why, sizeof why));
    CHECK(breach("stage2_fe", "translators/tr_keyword.h", why, sizeof why));
    CHECK(breach("translators", "cli/cli_common.h", why, sizeof why));
    CHECK(!breach("translators", "stage1_mb/mb_model.h", why, sizeof why));
    CHECK(!breach("cli", "translators/tr_keyword.h", why, sizeof why));
    CHECK(!breach("tests", "fe/scn/fe_scn_pad.h", why, sizeof why));
    /* rom/: core and analysis below it; the stages do not use it, translators and cli do */
    CHECK(breach("rom", "fe/fe_model.h", why, sizeof why));
    CHECK(breach("rom", "stage1_mb/mb_model.h", why, sizeof why));
    CHECK(!breach("rom", "analysis/an_cfc.h", why, sizeof why));
    CHECK(breach("stage1_mb", "rom/rom.h", why, sizeof why));
    CHECK(breach("fe", "rom/rom.h", why, sizeof why));
    CHECK(!breach("translators", "rom/rom.h", why, sizeof why));
    CHECK(!breach("cli", "rom/rom.h", why, sizeof why));
}

/* every source folder of the library and the command */
static void test_sources(void)
{
    for (size_t i = 0; i < sizeof layers / sizeof *layers; i++) walk(layers[i].dir, layers[i].dir);
    printf("layers: %d files, %d includes, %d breaches\n", nfiles, nincludes, nbreach);
    CHECK(nfiles > 250); /* the folders were read */
    CHECK(nbreach == 0);
    for (int i = 0; i < NKNOWN; i++) {
        if (!known_used[i]) fprintf(stderr, "known breach no longer needed: %s\n", known[i]);
        CHECK(known_used[i]);
    }
}

int main(void)
{
    RUN(test_checker);
    RUN(test_sources);
    TEST_END();
}

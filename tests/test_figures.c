/* test_figures.c: the figure markers of README.md and docs/<name>.md (tests/figures.h).
 * Every marker is well formed, holds a plain number, and names a key some test states with
 * FIG/FIG_TOL (the key appears as a literal string in tests/); the checker itself is tested on
 * a synthetic doc. */
#include "harness.h"

#include <dirent.h>

/* every tests/<name>.c and .h text, concatenated */
static char *tests_text(void)
{
    char *all = calloc(1, 1);
    size_t n = 0;
    DIR *d = opendir("tests");
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t l = strlen(e->d_name);
        if (l < 3 || (strcmp(e->d_name + l - 2, ".c") && strcmp(e->d_name + l - 2, ".h")))
            continue;
        char p[512];
        snprintf(p, sizeof p, "tests/%s", e->d_name);
        FILE *f = fopen(p, "rb");
        if (!f)
            continue;
        fseek(f, 0, SEEK_END);
        long m = ftell(f);
        fseek(f, 0, SEEK_SET);
        all = realloc(all, n + (size_t)m + 2);
        n += fread(all + n, 1, (size_t)m, f);
        all[n++] = '\n';
        all[n] = '\0';
        fclose(f);
    }
    if (d)
        closedir(d);
    return all;
}

static int key_char(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
}

/* each marker: a key of [a-z0-9_.-], a number and nothing else, a closing marker, and a
 * test that states the key */
static void test_markers(void)
{
    const char *docs = th_docs();
    char *src = tests_text();
    int nmark = 0;
    for (const char *p = strstr(docs, "<!--fig:"); p; p = strstr(p + 1, "<!--fig:")) {
        if (p > docs && p[-1] == '`')
            continue; /* the syntax quoted as code, not a marker */
        const char *k = p + 8, *ke = k;
        while (key_char(*ke) && strncmp(ke, "-->", 3))
            ke++;
        char key[160];
        snprintf(key, sizeof key, "%.*s", (int)(ke - k), k);
        CHECK(ke > k && !strncmp(ke, "-->", 3));
        const char *s = ke + 3, *end = strstr(s, "<!--/fig-->");
        char *num_end;
        strtod(s, &num_end);
        if (!end || num_end != end || num_end == s) {
            fprintf(stderr, "marker %s: not a plain number before <!--/fig-->\n", key);
            CHECK(0);
        }
        char quoted[170];
        snprintf(quoted, sizeof quoted, "\"%s\"", key);
        if (!strstr(src, quoted)) {
            fprintf(stderr, "marker %s: no test states it (FIG(\"%s\", ...))\n", key, key);
            CHECK(0);
        }
        nmark++;
    }
    printf("figure markers in README.md and docs/<name>.md: %d\n", nmark);
    free(src);
}

/* the last digit's unit of a number's text, by hand */
static void test_unit(void)
{
    const char *cases[] = {"0.122", "3.5e-4", "2232", "-3.12", "1.0E+3", "7e-7"};
    double want[] = {1e-3, 1e-5, 1, 1e-2, 1e2, 1e-7};
    for (int i = 0; i < 6; i++) {
        const char *s = cases[i];
        CHECK_REL(th_fig_unit(s, s + strlen(s)), want[i], 1e-12);
    }
}

/* the checker against a synthetic doc: within one unit passes, beyond fails, an explicit
 * tolerance overrides, every marker of a key counts, junk after the number fails */
static void test_checker(void)
{
    const char *saved_docs = th_docs();
    char *saved = th_docs_text;
    th_docs_text = strdup("a <!--fig:x.a-->0.122<!--/fig--> b <!--fig:x.b-->2.5e-4<!--/fig-->"
                          " <!--fig:x.a-->0.122<!--/fig--> <!--fig:x.c-->12 %<!--/fig-->");
    CHECK(th_fig_check("x.a", "0.1225", 0.1225, -1) == 0);
    CHECK(th_fig_check("x.a", "0.1229", 0.1229, -1) == 0);
    CHECK(th_fig_check("x.a", "0.1235", 0.1235, -1) == 1);
    CHECK(th_fig_check("x.a", "0.1235", 0.1235, 0.002) == 0);
    CHECK(th_fig_check("x.b", "2.58e-4", 2.58e-4, -1) == 0);
    CHECK(th_fig_check("x.b", "2.62e-4", 2.62e-4, -1) == 1);
    CHECK(th_fig_check("x.c", "12", 12.0, -1) == 1);
    CHECK(th_fig_check("x.none", "1", 1.0, -1) == 0);
    free(th_docs_text);
    th_docs_text = saved;
    CHECK(th_docs() == saved_docs);
}

int main(void)
{
    RUN(test_markers);
    RUN(test_unit);
    RUN(test_checker);
    TEST_END();
}

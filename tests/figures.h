/* figures.h: the figures the README and the docs state, checked against a test's own run.
 *
 * A doc writes a figure between markers, the text a plain ASCII number (no unit, no unicode):
 *     fork set <!--fig:models.barrier_fork_set-->0.122<!--/fig--> rad
 * and the test that computes it states it from its run:
 *     FIG("models.barrier_fork_set", "%.3f", fork_set);
 *     FIG_TOL("fe.bar_force_err_pct", "%.2f", err, 0.02);
 * FIG prints "FIGURE key text" (text: fmt applied to the value). Where README.md or docs/<name>.md
 * hold the key's marker, it checks the value against each marker's number: within one unit of
 * the marker's last digit (FIG), or within tol (FIG_TOL). `make figures` runs the tests with
 * MCRASH_FIGURES_OUT set, which appends "key<TAB>text" lines to that file instead of checking,
 * and scripts/figures.pl rewrites the markers from them; it runs the tests as `make test` and as
 * `make verify` do, and a key stated in both must read the same (else give each mode a key). Keys are literal strings in the test
 * source ([a-z0-9_.-]): tests/test_figures.c checks that every marker has one. */
#ifndef MCS_FIGURES_H
#define MCS_FIGURES_H

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the docs' text: README.md then docs/<name>.md of the repository root (the tests run there) */
static char *th_docs_text;

static inline void th_docs_append(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return;
    size_t old = th_docs_text ? strlen(th_docs_text) : 0;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *t = (n >= 0) ? realloc(th_docs_text, old + (size_t)n + 2) : NULL;
    if (t) {
        size_t got = fread(t + old, 1, (size_t)n, f);
        t[old + got] = '\n';
        t[old + got + 1] = '\0';
        th_docs_text = t;
    }
    fclose(f);
}

static inline int th_docs_cmp(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static inline const char *th_docs(void)
{
    if (th_docs_text)
        return th_docs_text;
    th_docs_text = calloc(1, 1);
    th_docs_append("README.md");
    if (!*th_docs_text) {
        /* the figures cannot be checked: a failure, not a silent pass */
        fprintf(stderr, "figures.h: README.md not found: run the tests from the repository root\n");
        th_checks_failed++;
    }
    DIR *d = opendir("docs");
    char *names[256];
    int nn = 0;
    for (struct dirent *e; d && (e = readdir(d)) && nn < 256;) {
        size_t l = strlen(e->d_name);
        if (l > 3 && !strcmp(e->d_name + l - 3, ".md"))
            names[nn++] = strdup(e->d_name);
    }
    if (d)
        closedir(d);
    qsort(names, (size_t)nn, sizeof *names, th_docs_cmp);
    for (int i = 0; i < nn; i++) {
        char p[512];
        snprintf(p, sizeof p, "docs/%s", names[i]);
        th_docs_append(p);
        free(names[i]);
    }
    return th_docs_text;
}

/* one unit of the last digit a number's text shows: "0.122" 1e-3, "3.5e-4" 1e-5, "2232" 1 */
static inline double th_fig_unit(const char *s, const char *end)
{
    int frac = 0, in_frac = 0, ex = 0;
    for (const char *p = s; p < end; p++) {
        if (*p == '.')
            in_frac = 1;
        else if (*p == 'e' || *p == 'E') {
            ex = atoi(p + 1);
            break;
        } else if (in_frac && *p >= '0' && *p <= '9')
            frac++;
    }
    return pow(10.0, ex - frac);
}

/* checks the value against every marker of key in the docs; 0 when all agree (or none) */
static inline int th_fig_check(const char *key, const char *text, double v, double tol)
{
    char open[160];
    snprintf(open, sizeof open, "<!--fig:%s-->", key);
    int bad = 0;
    for (const char *p = strstr(th_docs(), open); p; p = strstr(p + 1, open)) {
        const char *s = p + strlen(open), *end = strstr(s, "<!--/fig-->");
        char *num_end;
        double doc = strtod(s, &num_end);
        double t = tol >= 0 ? tol : th_fig_unit(s, num_end);
        if (!end || num_end != end || !(fabs(v - doc) <= t * (1 + 1e-9))) {
            int len = end ? (int)(end - s) : 20;
            fprintf(stderr,
                    "figure %s: the run gives %s (%.10g), a doc says \"%.*s\" (tol %.3g); "
                    "`make figures` rewrites the docs\n",
                    key, text, v, len, s, t);
            bad = 1;
        }
    }
    return bad;
}

static inline void th_fig(const char *file, int line, const char *key, const char *fmt, double v,
                   double tol)
{
    char text[64];
    snprintf(text, sizeof text, fmt, v);
    printf("FIGURE %s %s\n", key, text);
    const char *out = getenv("MCRASH_FIGURES_OUT");
    if (out && *out) {
        FILE *f = fopen(out, "a");
        if (f) {
            fprintf(f, "%s\t%s\n", key, text);
            fclose(f);
        }
        return;
    }
    if (th_fig_check(key, text, v, tol)) {
        th_checks_failed++;
        fprintf(stderr, "%s:%d: %s: FIG failed: %s\n", file, line, th_current, key);
    }
}

#define FIG(key, fmt, value) th_fig(__FILE__, __LINE__, (key), (fmt), (double)(value), -1.0)
#define FIG_TOL(key, fmt, value, tol)                                                              \
    th_fig(__FILE__, __LINE__, (key), (fmt), (double)(value), (double)(tol))

#endif

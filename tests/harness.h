/* harness.h: the small macro test harness (STYLE.md §10).
 * A test is a function; it passes when every CHECK in it holds. main() runs them with RUN()
 * and ends with TEST_END(), which prints "<binary>: N passed, N failed" for tests/run_tests.sh. */
#ifndef MCS_HARNESS_H
#define MCS_HARNESS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int th_tests_passed, th_tests_failed, th_checks_failed;
static const char *th_current = "";

#define CHECK(cond)                                                                                \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            th_checks_failed++;                                                                    \
            fprintf(stderr, "%s:%d: %s: CHECK failed: %s\n", __FILE__, __LINE__, th_current,       \
                    #cond);                                                                        \
        }                                                                                          \
    } while (0)

/* |a - b| <= tol, and neither is NaN */
#define CHECK_NEAR(a, b, tol)                                                                      \
    do {                                                                                           \
        double th_a = (double)(a), th_b = (double)(b), th_t = (double)(tol);                       \
        if (!(fabs(th_a - th_b) <= th_t)) {                                                        \
            th_checks_failed++;                                                                    \
            fprintf(stderr, "%s:%d: %s: CHECK_NEAR failed: %s = %.12g, %s = %.12g, tol %.3g\n",    \
                    __FILE__, __LINE__, th_current, #a, th_a, #b, th_b, th_t);                     \
        }                                                                                          \
    } while (0)

/* relative tolerance: |a - b| <= rel * |b| */
#define CHECK_REL(a, b, rel) CHECK_NEAR((a), (b), fabs((double)(rel) * (double)(b)))

#define CHECK_STR_CONTAINS(hay, needle)                                                            \
    do {                                                                                           \
        const char *th_h = (hay), *th_n = (needle);                                                \
        if (!th_h || !strstr(th_h, th_n)) {                                                        \
            th_checks_failed++;                                                                    \
            fprintf(stderr, "%s:%d: %s: expected \"%s\" in \"%s\"\n", __FILE__, __LINE__,        \
                    th_current, th_n, th_h ? th_h : "(null)");                                     \
        }                                                                                          \
    } while (0)

#define RUN(fn)                                                                                    \
    do {                                                                                           \
        int th_before = th_checks_failed;                                                          \
        th_current = #fn;                                                                          \
        fn();                                                                                      \
        if (th_checks_failed == th_before)                                                         \
            th_tests_passed++;                                                                     \
        else {                                                                                     \
            th_tests_failed++;                                                                     \
            fprintf(stderr, "FAIL %s\n", #fn);                                                     \
        }                                                                                          \
    } while (0)

#define TEST_END()                                                                                 \
    do {                                                                                           \
        printf("%s: %d passed, %d failed\n", __FILE__, th_tests_passed, th_tests_failed);          \
        return th_tests_failed ? 1 : 0;                                                            \
    } while (0)

/* true when `make verify` runs the tests (longer verification cases) */
static inline int th_verify(void)
{
    const char *v = getenv("MCRASH_VERIFY");
    return v && *v && *v != '0';
}

/* dir/name in one of 8 rotating buffers (a test's scratch paths: up to 8 live at once) */
static inline const char *th_path(const char *dir, const char *name)
{
    static char buf[8][512];
    static int k;
    k = (k + 1) % 8;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

/* the whole file at path, NUL-terminated (malloc'ed; NULL when it cannot be opened or read);
 * *n, when n is not NULL, gets its length in bytes */
static inline char *th_slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *s = NULL;
    long len = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (len >= 0 && fseek(f, 0, SEEK_SET) == 0) s = malloc((size_t)len + 1);
    size_t k = s ? fread(s, 1, (size_t)len, f) : 0;
    if (s) s[k] = 0;
    if (n) *n = k;
    fclose(f);
    return s;
}

#include "figures.h"

#endif

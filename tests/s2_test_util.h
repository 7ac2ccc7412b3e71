/* s2_test_util.h: set-up shared by the stage-2 tests (test_stage2*.c): scenario text with a
 * stage2: block, a stage-2 run of it, datasets of a results file, and the replay error of the
 * stage-2 bodies against a stage-1 file at the times both wrote */
#ifndef S2_TEST_UTIL_H
#define S2_TEST_UTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mcs_results.h"
#include "stage2_fe/s2_run.h"

/* the text of a file followed by `extra`, with the first `from` replaced by `to` (malloc'ed) */
static inline char *text_with(const char *path, const char *from, const char *to, const char *extra)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    const size_t cap = 1 << 16;
    size_t nt = cap + (to ? strlen(to) : 0) + strlen(extra) + 1;
    char *raw = calloc(cap, 1), *t = calloc(nt, 1);
    size_t n = raw ? fread(raw, 1, cap - 1, f) : 0;
    fclose(f);
    if (!raw || !t) return free(raw), free(t), NULL;
    raw[n] = 0;
    char *at = from ? strstr(raw, from) : NULL;
    if (at)
        snprintf(t, nt, "%.*s%s%s%s", (int)(at - raw), raw, to, at + strlen(from), extra);
    else
        snprintf(t, nt, "%s%s", raw, extra);
    free(raw);
    return t;
}

/* stage 2 of scenario text `text` (read as the file `name`) into out; 0 on success */
static inline mcs_status run_s2(const char *name, const char *text, const char *motion,
                                const char *out, s2_summary *sum, mcs_error *err)
{
    mcs_scenario *scn = NULL;
    s2_model *m = NULL;
    mcs_status st = mcs_scenario_load_text(name, text, strlen(text), &scn, err);
    if (!st) st = s2_model_build(scn, motion, &m, err);
    s2_run_opts o = {.out_path = out, .quiet = 1};
    if (!st) st = s2_run(m, &o, sum, err);
    if (st) fprintf(stderr, "stage 2: %s\n", err->msg);
    s2_model_destroy(&m);
    mcs_scenario_destroy(&scn);
    return st;
}

/* rotation angle between unit quaternions a, b (w x y z) [rad]: 2 atan2(|v|, |w|) of a* b */
static inline double qangle(const double *a, const double *b)
{
    double w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    double v[3] = {a[0] * b[1] - b[0] * a[1] - (a[2] * b[3] - a[3] * b[2]),
                   a[0] * b[2] - b[0] * a[2] - (a[3] * b[1] - a[1] * b[3]),
                   a[0] * b[3] - b[0] * a[3] - (a[1] * b[2] - a[2] * b[1])};
    return 2 * atan2(sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), fabs(w));
}

static inline double *read_ds(const char *file, const char *ds, size_t *n)
{
    mcs_results *r = NULL;
    mcs_error e = {0};
    mcs_array a = {0};
    double *v = NULL;
    if (!mcs_results_open(&r, file, &e) && !mcs_results_read(r, ds, &a, &e)) {
        v = malloc(a.n * sizeof *v);
        memcpy(v, a.v, a.n * sizeof *v);
        *n = a.n;
    } else {
        fprintf(stderr, "%s:%s: %s\n", file, ds, e.msg);
    }
    mcs_array_free(&a);
    mcs_results_close(&r);
    return v;
}

/* largest distance and angle of /stage2/bodies/<body> from /stage1/bodies/<body> of f1 at the
 * times the two share (within 1 ns); *ncommon of them */
static inline void replay_error(const char *f1, const char *f2, const char *body, double *dp,
                                double *da, int *ncommon)
{
    size_t n1 = 0, n2 = 0, k;
    char ds[128];
    double *t1 = read_ds(f1, "/stage1/time", &n1), *t2 = read_ds(f2, "/stage2/time", &n2);
    snprintf(ds, sizeof ds, "/stage1/bodies/%s/position", body);
    double *p1 = read_ds(f1, ds, &k);
    snprintf(ds, sizeof ds, "/stage1/bodies/%s/orientation", body);
    double *q1 = read_ds(f1, ds, &k);
    snprintf(ds, sizeof ds, "/stage2/bodies/%s/position", body);
    double *p2 = read_ds(f2, ds, &k);
    snprintf(ds, sizeof ds, "/stage2/bodies/%s/orientation", body);
    double *q2 = read_ds(f2, ds, &k);
    *dp = *da = 0;
    *ncommon = 0;
    if (!t1 || !t2 || !p1 || !q1 || !p2 || !q2) {
        *dp = *da = 1e9;
        goto done;
    }
    for (size_t j = 0, i = 0; j < n2; j++) {
        while (i < n1 && t1[i] < t2[j] - 1e-9)
            i++;
        if (i >= n1 || fabs(t1[i] - t2[j]) > 1e-9) continue;
        double d[3] = {p2[3 * j] - p1[3 * i], p2[3 * j + 1] - p1[3 * i + 1],
                       p2[3 * j + 2] - p1[3 * i + 2]};
        *dp = fmax(*dp, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
        *da = fmax(*da, qangle(q1 + 4 * i, q2 + 4 * j));
        (*ncommon)++;
    }
done:
    free(t1), free(t2), free(p1), free(q1), free(p2), free(q2);
}

#endif

/* study_file.c: STUDY.h5 (DESIGN.md "Studies", docs/contracts.md) and STUDY.csv beside it */
#include "cli/study.h"
#include "core/mcs_results.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* the unit of response i: that of the first case that has a value */
static const char *resp_unit(const study *s, const study_result *res, int i)
{
    for (long c = 0; c < s->ncase; c++)
        if (!isnan(res[c].v[i]) && res[c].unit[i][0]) return res[c].unit[i];
    return "-";
}

/* the i-th name of a list: factor paths (0), response names (1), configuration codes (2) */
static const char *name_of(const study *s, int what, long i)
{
    return what == 0 ? s->f[i].path : what == 1 ? s->r[i].name : s->code[i];
}

/* names joined by newlines (the attributes naming factors, responses and codes) */
static char *joined(const study *s, int what)
{
    size_t n = 1;
    long m = what == 0 ? s->nfactor : what == 1 ? s->nresp : s->nrow;
    for (long i = 0; i < m; i++)
        n += strlen(name_of(s, what, i)) + 1;
    char *t = calloc(n, 1), *o = t;
    for (long i = 0; t && i < m; i++)
        o += sprintf(o, "%s%s", i ? "\n" : "", name_of(s, what, i));
    return t;
}

/* compare: /study/variant and, per response, /study/difference/<name> (compare - base per
 * row) */
static mcs_status write_pairs_h5(mcs_results *r, const study *s, const study_result *res,
                                 double *v, int *iv, mcs_error *err)
{
    size_t dims[1] = {(size_t)s->ncase}, drow[1] = {(size_t)s->nrow};
    for (long c = 0; c < s->ncase; c++)
        iv[c] = (int)(c % s->nvar);
    mcs_status st = mcs_results_write_int(r, "/study/variant", 1, dims, iv, "-", err);
    if (!st) st = mcs_results_set_attr_str(r, "/study", "compare", s->alt_path, err);
    for (int i = 0; !st && i < s->nresp; i++) {
        char p[256];
        snprintf(p, sizeof p, "/study/difference/%s", s->r[i].name);
        for (long w = 0; w < s->nrow; w++)
            v[w] = res[2 * w + 1].v[i] - res[2 * w].v[i];
        st = mcs_results_write(r, p, 1, drow, v, resp_unit(s, res, i), err);
    }
    return st;
}

static mcs_status write_h5(const study *s, const study_result *res, const char *out,
                           mcs_error *err)
{
    mcs_results *r = NULL;
    mcs_status st = mcs_results_create(&r, out, mcs_scenario_text(s->file), err);
    size_t dims[2] = {(size_t)s->ncase, (size_t)s->nfactor};
    double *v = malloc((size_t)s->ncase * sizeof *v);
    int *status = malloc((size_t)s->ncase * sizeof *status);
    char *fn = joined(s, 0), *rn = joined(s, 1), *cn = s->code ? joined(s, 2) : NULL;
    if (!st && (!v || !status || !fn || !rn || (s->code && !cn)))
        st = MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    if (!st) st = mcs_results_write(r, "/study/design", 2, dims, s->x, "SI", err);
    for (long c = 0; !st && c < s->ncase; c++)
        status[c] = res[c].status;
    if (!st) st = mcs_results_write_int(r, "/study/status", 1, dims, status, "-", err);
    if (!st) st = mcs_results_set_attr_str(r, "/study", "design", s->design_name, err);
    if (!st) st = mcs_results_set_attr_str(r, "/study", "factors", fn, err);
    if (!st) st = mcs_results_set_attr_str(r, "/study", "responses", rn, err);
    if (!st) st = mcs_results_set_attr_str(r, "/study", "scenario", s->scenario, err);
    if (!st) st = mcs_results_set_attr_str(r, "/study", "stage", s->stage, err);
    if (!st && cn) st = mcs_results_set_attr_str(r, "/study", "codes", cn, err);
    if (!st && s->nvar == 2) st = write_pairs_h5(r, s, res, v, status, err);
    if (!st && s->design == STUDY_LHS)
        st = mcs_results_set_attr_double(r, "/study", "seed", (double)s->seed, err);
    for (int i = 0; !st && i < s->nresp; i++) {
        char p[256];
        snprintf(p, sizeof p, "/study/responses/%s", s->r[i].name);
        for (long c = 0; c < s->ncase; c++)
            v[c] = res[c].v[i];
        st = mcs_results_write(r, p, 1, dims, v, resp_unit(s, res, i), err);
        if (!st) st = mcs_results_set_attr_str(r, p, "source", s->r[i].spec, err);
    }
    free(v), free(status), free(fn), free(rn), free(cn);
    if (!st) return mcs_results_commit(&r, err);
    mcs_results_abort(&r);
    return st;
}

/* a CSV field: quoted when it holds a comma, a quote or a newline */
static void csv_field(FILE *f, const char *s)
{
    if (!strpbrk(s, ",\"\n")) {
        fputs(s, f);
        return;
    }
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"') fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

static int write_csv(const study *s, const study_result *res, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    fprintf(f, "case,status%s%s", s->code ? ",code" : "", s->nvar == 2 ? ",variant" : "");
    for (int j = 0; j < s->nfactor; j++)
        fputc(',', f), csv_field(f, s->f[j].path);
    for (int i = 0; i < s->nresp; i++)
        fputc(',', f), csv_field(f, s->r[i].name);
    fputc('\n', f);
    for (long c = 0; c < s->ncase; c++) {
        fprintf(f, "%ld,%d", c, res[c].status);
        if (s->code) fprintf(f, ",%s", s->code[c / s->nvar]);
        if (s->nvar == 2) fprintf(f, ",%ld", c % s->nvar);
        for (int j = 0; j < s->nfactor; j++)
            fprintf(f, ",%.17g", s->x[c * s->nfactor + j]);
        for (int i = 0; i < s->nresp; i++)
            isnan(res[c].v[i]) ? fprintf(f, ",NaN") : fprintf(f, ",%.17g", res[c].v[i]);
        fputc('\n', f);
    }
    return fclose(f);
}

int study_write(const study *s, const study_result *res, const char *out)
{
    mcs_error err = {0};
    if (write_h5(s, res, out, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(err.status);
    }
    char csv[4200];
    size_t n = strlen(out);
    int h5 = n > 3 && !strcmp(out + n - 3, ".h5");
    snprintf(csv, sizeof csv, "%.*s.csv", (int)(h5 ? n - 3 : n), out);
    if (write_csv(s, res, csv)) {
        fprintf(stderr, "study: cannot write %s\n", csv);
        return 2;
    }
    snprintf(csv, sizeof csv, "%.*s_pairs.csv", (int)(h5 ? n - 3 : n), out);
    if (s->nvar == 2 && study_write_pairs(s, res, csv)) {
        fprintf(stderr, "study: cannot write %s\n", csv);
        return 2;
    }
    return 0;
}

/* DIR: the output's name without .h5, and _cases */
int study_cases_dir(const char *out, char *dir, size_t n)
{
    size_t len = strlen(out);
    int h5 = len > 3 && !strcmp(out + len - 3, ".h5");
    snprintf(dir, n, "%.*s_cases", (int)(h5 ? len - 3 : len), out);
    if (mkdir(dir, 0755) && errno != EEXIST) {
        fprintf(stderr, "study: cannot create %s: %s\n", dir, strerror(errno));
        return 2;
    }
    return 0;
}

/* Shared set-up of the stage-3 tests (test_s3_run.c, test_s3_solid.c, test_s3_wall.c, ...):
 * write a scenario file, run one through the library, read a results dataset. */
#ifndef S3_TEST_UTIL_H
#define S3_TEST_UTIL_H

#include <math.h>
#include <stdio.h>

#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "stage3_fe/s3_run.h"

static inline void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

/* run a scenario file through the library into out; returns the status */
static inline mcs_status run_file(const char *scenario, const char *out, s3_summary *sum,
                                  mcs_error *err)
{
    mcs_scenario *scn = NULL;
    mcs_status st = mcs_scenario_load(scenario, &scn, err);
    fe_problem p = {0};
    if (!st) st = fe_scn_build(scn, &p, err);
    if (!st) {
        s3_run_opts o = {.out_path = out, .scenario_text = mcs_scenario_text(scn), .quiet = 1};
        st = s3_run(&p, &o, sum, err);
    }
    fe_problem_free(&p);
    mcs_scenario_destroy(&scn);
    return st;
}

/* read a dataset of the results file into a; 1 on success */
static inline int rd(mcs_results *h, const char *path, mcs_array *a)
{
    mcs_error err = {0};
    return mcs_results_read(h, path, a, &err) == MCS_OK;
}

/* the last value of a results dataset; NaN if it cannot be read or is empty */
static inline double last_of(mcs_results *h, const char *path)
{
    mcs_array a = {0};
    double v = rd(h, path, &a) && a.n > 0 ? a.v[a.n - 1] : NAN;
    mcs_array_free(&a);
    return v;
}

#endif

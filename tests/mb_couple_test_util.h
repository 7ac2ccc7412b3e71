/* mb_couple_test_util.h: the preamble the coupled stage-1 tests (tests/test_mb_couple*.c) share:
 * a model from scenario text, a run to its end, a `mcrash` run whose results file is then read;
 * each a failed CHECK (with the error printed) when it does not work. Include after harness.h;
 * every test is its own binary, so these are static inline. */
#ifndef MB_COUPLE_TEST_UTIL_H
#define MB_COUPLE_TEST_UTIL_H

#include "core/mcs_results.h"
#include "tests/mb_test_util.h"

/* the model of scenario text y read as the file `name`; NULL (and a failed CHECK) on failure */
static inline mb_model *mc_model(const char *name, const char *y)
{
    mb_model *m = mt_model_text(name, y, NULL); /* (prints the error) */
    CHECK(m != NULL);
    return m;
}

/* a new state *s of m run to the model's end; its status (a failed CHECK unless MCS_OK) */
static inline mcs_status mc_run(const mb_model *m, mb_state **s)
{
    mcs_error err = {0};
    mcs_status st = mt_run(m, s, &err);
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    return st;
}

#endif

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

/* a probe of the state after an ODE step (mc_run_record) */
typedef double (*mc_probe)(const mb_state *s);

/* a new state *s of m run to its end, probe(s) after each ODE step into v[1..nsteps] (v[0] = 0:
 * the tests' bodies start there), their extremes with v[0] into *lo, *hi; its status (a failed
 * CHECK unless MCS_OK) */
static inline mcs_status mc_run_record(const mb_model *m, mb_state **s, mc_probe probe, double *v,
                                       double *lo, double *hi)
{
    mcs_error err = {0};
    mcs_status st = mb_state_create(m, s, &err);
    v[0] = *lo = *hi = 0;
    while (!st && (*s)->step < m->nsteps) {
        st = mb_step(m, *s, &err);
        const double x = probe(*s);
        v[(*s)->step] = x;
        *lo = fmin(*lo, x), *hi = fmax(*hi, x);
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    return st;
}

/* the mean spacing of the upward crossings of level `mid` by v[0..n] sampled every h (each
 * crossing time interpolated linearly) [s], their number into *ncross; 0 with fewer than two */
static inline double mc_up_period(const double *v, long n, double mid, double h, int *ncross)
{
    double t_first = -1, t_last = -1;
    *ncross = 0;
    for (long i = 1; i <= n; i++) {
        double a = v[i - 1] - mid, b = v[i] - mid;
        if (a < 0 && b >= 0) {
            double t = ((double)(i - 1) + a / (a - b)) * h;
            if (t_first < 0) t_first = t;
            t_last = t;
            (*ncross)++;
        }
    }
    return *ncross > 1 ? (t_last - t_first) / (*ncross - 1) : 0;
}

/* the bar with an end mass (test_mb_couple.c, test_mb_couple_damp.c; Rao, Mechanical
 * Vibrations, Sec. 8.4): the first root of beta tan(beta) = r in (0, pi/2), by bisection */
static inline double mc_end_mass_root(double r)
{
    double lo = 0, hi = 1.5707963267948966;
    for (int i = 0; i < 200; i++) {
        double b = 0.5 * (lo + hi);
        if (b * tan(b) < r)
            lo = b;
        else
            hi = b;
    }
    return 0.5 * (lo + hi);
}

#endif

/* an_resample.h: bring two sampled channels onto one uniform time grid over their common span
 * (linear interpolation), as the objective ratings need (ISO/TS 18571: 10 kHz, common span). */
#ifndef AN_RESAMPLE_H
#define AN_RESAMPLE_H

#include "core/mcs_error.h"

/* two channels sampled on the same uniform grid t0 + k*dt, k = 0..n-1 */
typedef struct {
    int n;       /* number of samples on the common grid */
    double t0;   /* time of the first sample [s] */
    double dt;   /* sample interval [s] */
    double *ref; /* reference values [unit] (n), owned */
    double *cmp; /* comparison values [unit] (n), owned */
} an_pair;

void an_pair_free(an_pair *p); /* frees ref and cmp, zeroes the struct */

/* check that t (n) is finite and strictly increasing and y (n) finite; what names the channel
 * in the message */
mcs_status an_samples_check(const double *t, const double *y, int n, const char *what,
                            mcs_error *err);

/* value of the piecewise-linear interpolant of (t, y) at tq; t strictly increasing, n >= 1;
 * tq outside [t[0], t[n-1]] takes the end value (callers stay inside the span) */
double an_interp_linear(const double *t, const double *y, int n, double tq);

/* resample (t1, y1) and (t2, y2) to rate [Hz] by linear interpolation on the grid that starts at
 * the later first sample and ends at or before the earlier last sample (the common span).
 * Errors: a channel with fewer than 2 samples, non-increasing or non-finite times, non-finite
 * values, rate <= 0, or a common span shorter than min_samples samples at that rate. */
mcs_status an_resample_pair(const double *t1, const double *y1, int n1, const double *t2,
                            const double *y2, int n2, double rate, int min_samples, an_pair *out,
                            mcs_error *err);

#endif

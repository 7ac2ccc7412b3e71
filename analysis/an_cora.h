/* an_cora.h: CORA objective rating (CORrelation and Analysis; Gehre, Gades, Wernicke, ESV 2009,
 * paper 09-0407) with the CORAplus 4.0.x default parameters (REFERENCES.md "Objective rating"):
 * corridor rating and cross-correlation rating (phase, size, progression). */
#ifndef AN_CORA_H
#define AN_CORA_H

#include "analysis/an_signal.h"
#include "core/mcs_error.h"

typedef struct {
    double sample_rate; /* resampling rate [Hz] (10 kHz, as for ISO 18571) */
    /* interval of evaluation (automatic unless t_min / t_max are finite) */
    double a_thres;     /* start: |ref| first reaches a_thres max|ref| [-] (0.03) */
    double b_thres;     /* end: |ref| last reaches b_thres max|ref| [-] (0.075) */
    double a_eval;      /* start moved earlier by a_eval (t_b - t_a) [-] (0.01) */
    double b_delta_end; /* end moved later by b_delta_end (t_b - t_a) [-] (0.2) */
    double t_min;       /* explicit start of the interval [s], NAN = automatic */
    double t_max;       /* explicit end of the interval [s], NAN = automatic */
    /* corridor method */
    double k;  /* corridor exponent [-] (2) */
    double g1; /* weight of the corridor rating [-] (0.5) */
    double a0; /* inner corridor half-width, fraction of max|ref| [-] (0.05) */
    double b0; /* outer corridor half-width, fraction of max|ref| [-] (0.5) */
    /* cross-correlation method */
    double d_min;   /* shift below d_min T rates 1 [-] (0.01) */
    double d_max;   /* shift beyond d_max T rates 0 [-] (0.12) */
    double int_min; /* least overlap of the shifted signals, fraction of the interval [-] (0.8) */
    double k_v;     /* progression exponent [-] (10) */
    double k_g;     /* size exponent [-] (1) */
    double k_p;     /* phase exponent [-] (1) */
    double g_v;     /* weight of progression [-] (0.5) */
    double g_g;     /* weight of size [-] (0.25) */
    double g_p;     /* weight of phase [-] (0.25) */
    double g2;      /* weight of the cross-correlation rating [-] (0.5) */
} an_cora_opts;

an_cora_opts an_cora_opts_default(void);

typedef struct {
    double rating;      /* CORA = g1 corridor + g2 cross [-] */
    double corridor;    /* corridor rating Z [-] */
    double cross;       /* cross-correlation rating g_v E_V + g_g E_G + g_p E_P [-] */
    double phase;       /* E_P [-] */
    double size;        /* E_G [-] */
    double progression; /* E_V [-] */
    double xcorr;       /* normalised cross-correlation at the best shift [-] */
    int shift;          /* best shift [samples]; > 0: the comparison lags */
    double shift_time;  /* shift [s] */
    int i_start, i_end; /* interval of evaluation, sample indices (inclusive) */
    double t_start, t_end; /* interval of evaluation [s] */
    int n;              /* samples on the compared grid */
    double t0, dt;      /* first sample time and interval of the compared grid [s] */
} an_cora_result;

/* interval of evaluation [*i0, *i1] of ref (n samples at t0 + k dt) */
mcs_status an_cora_interval(const double *ref, int n, double t0, double dt, const an_cora_opts *o,
                            int *i0, int *i1, mcs_error *err);

/* rating of cmp against ref, both n samples at t0 + k dt (already uniform and aligned).
 * Errors (MCS_ERR_RANGE, never NaN): fewer than 10 samples in the interval, non-finite
 * samples, a reference that is zero everywhere, bad options. */
mcs_status an_cora_arrays(const double *ref, const double *cmp, int n, double t0, double dt,
                          const an_cora_opts *o, an_cora_result *r, mcs_error *err);

/* resample both channels to o->sample_rate over their common time span, then rate them */
mcs_status an_cora(const an_signal *ref, const an_signal *cmp, const an_cora_opts *o,
                   an_cora_result *r, mcs_error *err);

#endif

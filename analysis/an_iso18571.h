/* an_iso18571.h: objective rating of a comparison signal against a reference, ISO/TS 18571
 * (corridor, phase, magnitude by dynamic time warping, slope; R = 0.4 Z + 0.2 E_P + 0.2 E_M +
 * 0.2 E_S). Parameters as in REFERENCES.md "Objective rating". */
#ifndef AN_ISO18571_H
#define AN_ISO18571_H

#include "analysis/an_signal.h"
#include "core/mcs_error.h"

typedef struct {
    double sample_rate; /* resampling rate [Hz] (ISO: 10 kHz) */
    double a0;          /* inner corridor half-width, fraction of max|ref| [-] (0.05) */
    double b0;          /* outer corridor half-width, fraction of max|ref| [-] (0.5) */
    double k_z;         /* corridor exponent [-] (2) */
    double max_shift;   /* largest phase shift, fraction of N [-] (0.2) */
    double k_p;         /* phase exponent [-] (1) */
    double eps_m;       /* magnitude error at which E_M reaches 0 [-] (0.5) */
    double k_m;         /* magnitude exponent [-] (1) */
    double band;        /* DTW band: |i - j| <= ceil(band M) - 1, M the shifted length [-] (0.1) */
    double eps_s;       /* slope error at which E_S reaches 0 [-] (2) */
    int smooth;         /* moving-average length of the derivatives, odd [samples] (9) */
    double w_z, w_p, w_m, w_s; /* weights of Z, E_P, E_M, E_S [-] (0.4, 0.2, 0.2, 0.2) */
} an_iso_opts;

an_iso_opts an_iso_opts_default(void);

typedef struct {
    double rating;      /* R [-] */
    double corridor;    /* Z [-] */
    double phase;       /* E_P [-] */
    double magnitude;   /* E_M [-] */
    double slope;       /* E_S [-] */
    int shift;          /* phase shift n [samples]; > 0: the comparison lags the reference */
    double shift_time;  /* n * dt [s] */
    double rho;         /* Pearson correlation at that shift [-] */
    double mag_error;   /* e_M = |c_w - r_w|_1 / |r_w|_1 [-] */
    double slope_error; /* e_S = |c' - r'|_1 / |r'|_1 [-] */
    int n;              /* samples compared (after resampling) */
    int n_warp;         /* length of the warping path */
    double t0, dt;      /* first sample time and interval of the compared grid [s] */
} an_iso_result;

/* rating of cmp against ref, both n samples at interval dt [s] (already uniform and aligned).
 * Errors (MCS_ERR_RANGE, no NaN ever returned): n < 10, non-finite samples, a reference that is
 * zero or constant (corridor, phase and slope are undefined), bad options. */
mcs_status an_iso18571_arrays(const double *ref, const double *cmp, int n, double dt,
                              const an_iso_opts *o, an_iso_result *r, mcs_error *err);

/* resample both channels to o->sample_rate over their common time span, then rate them */
mcs_status an_iso18571(const an_signal *ref, const an_signal *cmp, const an_iso_opts *o,
                       an_iso_result *r, mcs_error *err);

/* ISO/TS 18571 grade: "excellent" R > 0.94, "good" > 0.80, "fair" > 0.58, else "poor" */
const char *an_iso_grade(double rating);

/* --- the parts, exposed for tests and for other metrics --- */

/* corridor score Z: mean over i of ((outer - |d|)/(outer - inner))^k, 1 inside the inner
 * corridor, 0 outside the outer; inner = a0 max|ref|, outer = b0 max|ref| */
double an_iso_corridor(const double *ref, const double *cmp, int n, double a0, double b0,
                       double k);

/* Pearson correlation of x and y (n); 0 when either has zero variance */
double an_pearson(const double *x, const double *y, int n);

/* shift n in [-max_shift, max_shift] maximising the Pearson correlation of the overlap
 * (ref[i] with cmp[i + n]); the smallest |n| wins ties, +n before -n. *rho gets the maximum. */
int an_iso_phase_shift(const double *ref, const double *cmp, int n, int max_shift, double *rho);

/* dynamic time warping of c against r (both m samples), squared-difference cost, steps
 * (1,0), (0,1), (1,1), Sakoe-Chiba band |i - j| <= w. Returns e = sum|c_i - r_j| / sum|r_j|
 * over the optimal path (its length in *path_len). Memory O(m (2w + 1)) bytes.
 * MCS_ERR_RANGE if sum|r_j| is zero, MCS_ERR_NOMEM if the band does not fit. */
mcs_status an_dtw_error(const double *c, const double *r, int m, int w, double *e,
                        int *path_len, mcs_error *err);

/* smoothed derivative of y (n) at interval dt: central differences (one-sided at the ends),
 * then a centred moving average of `len` points, shortened symmetrically near the ends */
void an_iso_derivative(const double *y, int n, double dt, int len, double *dy);

#endif

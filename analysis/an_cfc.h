/* an_cfc.h: SAE J211-1 Appendix C channel frequency class (CFC) filters.
 * A 2-pole Butterworth low-pass designed by the bilinear transform with pre-warping at
 * fd = 2.0775·CFC, run forward then backward (zero phase, 4 poles in all): DC gain 1,
 * -6.02 dB at 2.0775·CFC, about -3 dB at 1.667·CFC. */
#ifndef AN_CFC_H
#define AN_CFC_H

#include "analysis/an_signal.h"

/* coefficients of one pass: y[i] = a0 x[i] + a1 x[i-1] + a2 x[i-2] + b1 y[i-1] + b2 y[i-2] */
typedef struct {
    double a0, a1, a2; /* feed-forward [-] */
    double b1, b2;     /* feedback [-] */
} an_cfc_coef;

/* coefficients for class `cfc` [Hz] at sample step dt [s]; MCS_ERR_RANGE when the design
 * frequency 2.0775·CFC is not below the Nyquist frequency 1/(2 dt) */
mcs_status an_cfc_design(double cfc, double dt, an_cfc_coef *c, mcs_error *err);

/* filter x (n >= 2 samples at uniform step dt) into y (may alias x). The ends are padded by
 * point (odd) mirroring about the end samples, x[-k] = 2 x[0] - x[k], over max(10 ms, 10
 * filter time constants) limited to n - 1 samples, so level and slope continue through the
 * end and a constant or a straight line passes unchanged. */
mcs_status an_cfc_filter(const double *x, int n, double dt, double cfc, double *y,
                         mcs_error *err);

/* the thesis' ch. 7 Butterworth low-pass: the same 2-pole section with its -3 dB corner at
 * fc [Hz] for one pass, run forward-backward (-6.02 dB at fc, zero phase); this is
 * an_cfc_filter with CFC = fc / 2.0775 */
mcs_status an_butterworth_filter(const double *x, int n, double dt, double fc, double *y,
                                 mcs_error *err);

/* filter a channel in place (must be uniformly sampled to 1e-6 of a step); sets s->cfc */
mcs_status an_cfc_signal(an_signal *s, int cfc, mcs_error *err);

/* amplitude gain of the forward-backward filter at f [Hz]: the one-pass |H(f)|^2 of the
 * bilinear-transform Butterworth, 1 / (1 + (tan(pi f dt) / tan(pi 2.0775 CFC dt))^4) */
double an_cfc_gain(double cfc, double dt, double f);

/* J211-1 recommended class for a channel kind: "head_acceleration" 1000, "neck_force" /
 * "neck_moment" 600, "chest_acceleration" 180, "chest_deflection" 180, "femur" / "tibia" 600,
 * "pelvis_acceleration" 1000, "vehicle" 60; 0 if unknown */
int an_cfc_default(const char *kind);

/* mean step of t and whether it is uniform to `rel` of a step */
int an_signal_uniform(const an_signal *s, double rel, double *dt);

#endif

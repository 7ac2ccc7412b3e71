/* an_integrate.h: integration of sampled accelerations to velocity and displacement (the
 * thesis' ch. 7). Trapezoid rule: global error O(h^2) for smooth signals (the error is
 * -(h^2/12) [f'(t) - f'(0)] to leading order); it integrates constants and straight lines
 * exactly. An offset e in the acceleration (sensor zero error) is integrated faithfully: it
 * becomes a velocity drift e t and a displacement drift e t^2 / 2, which no step size
 * removes; filter or remove the offset first. */
#ifndef AN_INTEGRATE_H
#define AN_INTEGRATE_H

#include "core/mcs_error.h"

/* out[0] = y0, out[i] = out[i-1] + (f[i] + f[i-1]) (t[i] - t[i-1]) / 2; out may not alias f */
void an_integrate_trapz(const double *t, const double *f, int n, double y0, double *out);

/* v = v0 + int a, x = x0 + int v (both by trapezoids); t strictly increasing, n >= 2 */
mcs_status an_integrate_accel(const double *t, const double *a, int n, double v0, double x0,
                              double *v, double *x, mcs_error *err);

#endif

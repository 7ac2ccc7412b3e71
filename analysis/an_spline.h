/* an_spline.h: natural cubic spline interpolation and its derivatives (the thesis' ch. 7
 * film analysis: digitised positions at frame times -> smooth position, velocity,
 * acceleration). Natural end conditions: second derivative 0 at both ends. For a smooth f
 * with f'' = 0 at the ends the error is O(h^4) in the value and O(h^3) in the first
 * derivative; otherwise the end condition limits it to O(h^2) near the ends. */
#ifndef AN_SPLINE_H
#define AN_SPLINE_H

#include "core/mcs_error.h"

typedef struct {
    int n;     /* knots */
    double *x; /* knot abscissae, increasing (n), owned */
    double *y; /* knot values (n), owned */
    double *m; /* second derivatives at the knots (n), owned */
} an_spline;

/* build through (x_i, y_i), n >= 2, x strictly increasing */
mcs_status an_spline_natural(const double *x, const double *y, int n, an_spline *s,
                             mcs_error *err);
void an_spline_free(an_spline *s);

/* value, first and second derivative at x (cubic extension of the end pieces outside) */
double an_spline_eval(const an_spline *s, double x);
double an_spline_deriv(const an_spline *s, double x);
double an_spline_deriv2(const an_spline *s, double x);

#endif

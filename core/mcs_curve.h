/* mcs_curve: piecewise-linear x-y tables (force vs. penetration, torque vs. angle, ...).
 *
 * A curve is immutable once built; building validates it (n >= 1, finite values, x strictly
 * increasing) and reports the offending point. Evaluation never allocates: O(log n) bisection,
 * or O(1) with a segment hint the caller keeps in its state (the time loop evaluates curves
 * millions of times).
 *
 * Extrapolation is chosen per end:
 *   MCS_EXTRAP_LINEAR    the end segment's straight line continues (DESIGN.md: loading curves are
 *                        "straight line through the points, extrapolated");
 *   MCS_EXTRAP_CONSTANT  the end value is held (slope 0 beyond the end).
 * A one-point curve is a constant and must use MCS_EXTRAP_CONSTANT at both ends.
 * Slope at a breakpoint is the slope of the segment to its right (right derivative). */
#ifndef MCS_CURVE_H
#define MCS_CURVE_H

#include "core/mcs_error.h"

typedef enum { MCS_EXTRAP_LINEAR, MCS_EXTRAP_CONSTANT } mcs_extrap;

typedef struct {
    int n;             /* number of points [-]                                          */
    const double *x;   /* abscissae, strictly increasing [x unit] (n)                    */
    const double *y;   /* ordinates [y unit] (n)                                         */
    const double *cum; /* running integral: cum[i] = int_{x[0]}^{x[i]} y dx [x*y unit] (n) */
    mcs_extrap lo;     /* extrapolation below x[0]                                       */
    mcs_extrap hi;     /* extrapolation above x[n-1]                                     */
    int monotone;      /* +1 y strictly increasing, -1 strictly decreasing, 0 neither [-] */
    char name[64];     /* name used in messages (e.g. the characteristic's key)          */
} mcs_curve;

/* build from separate x and y arrays (copied) */
mcs_status mcs_curve_create(const char *name, int n, const double *x, const double *y,
                            mcs_extrap lo, mcs_extrap hi, mcs_curve **out, mcs_error *err);
/* build from n (x, y) pairs, the layout of `loading: [[0, 0], [0.01, 1000]]` */
mcs_status mcs_curve_create_xy(const char *name, int n, const double (*xy)[2], mcs_extrap lo,
                               mcs_extrap hi, mcs_curve **out, mcs_error *err);
void mcs_curve_destroy(mcs_curve **p);

/* segment i (0..n-2) whose line gives the value at x: x[i] <= x < x[i+1], 0 below x[0],
 * n-2 at and above x[n-1] (0 for a one-point curve). `hint` is a previous answer or -1. */
int mcs_curve_segment(const mcs_curve *c, double x, int hint);

double mcs_curve_eval(const mcs_curve *c, double x);
/* same, using and updating *hint (a segment index kept by the caller; start with -1) */
double mcs_curve_eval_hint(const mcs_curve *c, double x, int *hint);
/* dy/dx at x (right derivative at breakpoints; 0 in a constant-hold region) */
double mcs_curve_slope(const mcs_curve *c, double x);
/* exact integral of the curve from a to b (b < a gives the negative), extrapolation included */
double mcs_curve_integral(const mcs_curve *c, double a, double b);
/* x with y(x) = y for a strictly monotone curve (c->monotone != 0; NaN otherwise).
 * Beyond a constant-hold end no x reaches y: the end abscissa is returned (clamped). */
double mcs_curve_inverse(const mcs_curve *c, double y);

/* new curve with points (sx * x, sy * y); sx > 0, sy finite; extrapolation kept */
mcs_status mcs_curve_create_scaled(const mcs_curve *src, const char *name, double sx, double sy,
                                   mcs_curve **out, mcs_error *err);
/* new curve x(y) of a strictly monotone curve; extrapolation kept per end of the new x axis */
mcs_status mcs_curve_create_inverse(const mcs_curve *src, const char *name, mcs_curve **out,
                                    mcs_error *err);
/* two deformable bodies in series contact (thesis §3.2: both carry the same force, their
 * deflections add): the combined force-deflection curve x(F) = x1(F) + x2(F), exact for
 * piecewise-linear inputs (breakpoints at the union of both force levels). Both curves must be
 * strictly increasing. A constant-hold (plateau) end caps the force the pair can carry; the
 * result then holds that force too. */
mcs_status mcs_curve_create_series(const mcs_curve *a, const mcs_curve *b, const char *name,
                                   mcs_curve **out, mcs_error *err);

#endif

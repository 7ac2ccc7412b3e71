#include "core/mcs_curve.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* one allocation: the struct, then x, y, cum */
static mcs_curve *curve_alloc(int n)
{
    mcs_curve *c = calloc(1, sizeof *c + 3 * (size_t)n * sizeof(double));
    if (!c) return NULL;
    double *d = (double *)(c + 1);
    c->n = n;
    c->x = d;
    c->y = d + n;
    c->cum = d + 2 * n;
    return c;
}

/* validate x, y into a fresh curve; the message names the curve and the (1-based) point */
static mcs_status curve_build(const char *name, int n, const double *x, const double *y,
                              size_t stride, mcs_extrap lo, mcs_extrap hi, mcs_curve **out,
                              mcs_error *err)
{
    *out = NULL;
    if (!name) name = "curve";
    if (n < 1) return MCS_ERR(err, MCS_ERR_RANGE, "%s: a curve needs at least one point", name);
    if (n == 1 && (lo != MCS_EXTRAP_CONSTANT || hi != MCS_EXTRAP_CONSTANT))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: a one-point curve is a constant; linear extrapolation needs two points",
                       name);
    for (int i = 0; i < n; i++) {
        double xi = x[i * stride], yi = y[i * stride];
        if (!isfinite(xi) || !isfinite(yi))
            return MCS_ERR(err, MCS_ERR_RANGE, "%s: point %d of %d (%g, %g) is not finite", name,
                           i + 1, n, xi, yi);
        if (i > 0 && !(xi > x[(i - 1) * stride]))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%s: point %d of %d has x = %g, not greater than x = %g of point %d: "
                           "x must increase strictly",
                           name, i + 1, n, xi, x[(i - 1) * stride], i);
    }
    mcs_curve *c = curve_alloc(n);
    if (!c) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory for %d points", name, n);
    double *cx = (double *)c->x, *cy = (double *)c->y, *cc = (double *)c->cum;
    int up = 1, down = 1;
    for (int i = 0; i < n; i++) {
        cx[i] = x[i * stride];
        cy[i] = y[i * stride];
        if (i > 0) {
            /* trapezoid: exact for a straight segment */
            cc[i] = cc[i - 1] + 0.5 * (cy[i] + cy[i - 1]) * (cx[i] - cx[i - 1]);
            up &= cy[i] > cy[i - 1];
            down &= cy[i] < cy[i - 1];
        }
    }
    c->monotone = n < 2 ? 0 : up ? 1 : down ? -1 : 0;
    c->lo = lo;
    c->hi = hi;
    snprintf(c->name, sizeof c->name, "%s", name);
    *out = c;
    return MCS_OK;
}

mcs_status mcs_curve_create(const char *name, int n, const double *x, const double *y,
                            mcs_extrap lo, mcs_extrap hi, mcs_curve **out, mcs_error *err)
{
    return curve_build(name, n, x, y, 1, lo, hi, out, err);
}

mcs_status mcs_curve_create_xy(const char *name, int n, const double (*xy)[2], mcs_extrap lo,
                               mcs_extrap hi, mcs_curve **out, mcs_error *err)
{
    if (n < 1) return curve_build(name, n, NULL, NULL, 2, lo, hi, out, err);
    return curve_build(name, n, &xy[0][0], &xy[0][1], 2, lo, hi, out, err);
}

void mcs_curve_destroy(mcs_curve **p)
{
    if (!p) return;
    free(*p);
    *p = NULL;
}

int mcs_curve_segment(const mcs_curve *c, double x, int hint)
{
    int last = c->n - 2;
    if (last <= 0) return 0;
    const double *xs = c->x;
    /* the hint and its neighbours first: time histories move little per step */
    if (hint >= 0 && hint <= last) {
        if (x >= xs[hint] && (x < xs[hint + 1] || hint == last)) return hint;
        if (hint < last && x >= xs[hint + 1] && (x < xs[hint + 2] || hint + 1 == last))
            return hint + 1;
        if (hint > 0 && x >= xs[hint - 1] && x < xs[hint]) return hint - 1;
    }
    if (!(x >= xs[1])) return 0; /* also NaN */
    if (x >= xs[last]) return last;
    int lo = 1, hi = last; /* xs[lo] <= x < xs[hi] */
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (xs[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* value at x on segment i, honouring a constant-hold end */
static double eval_seg(const mcs_curve *c, int i, double x)
{
    if (c->n == 1) return c->y[0];
    if (x < c->x[0] && c->lo == MCS_EXTRAP_CONSTANT) return c->y[0];
    if (x > c->x[c->n - 1] && c->hi == MCS_EXTRAP_CONSTANT) return c->y[c->n - 1];
    double s = (c->y[i + 1] - c->y[i]) / (c->x[i + 1] - c->x[i]);
    return c->y[i] + s * (x - c->x[i]);
}

double mcs_curve_eval(const mcs_curve *c, double x)
{
    return eval_seg(c, mcs_curve_segment(c, x, -1), x);
}

double mcs_curve_eval_hint(const mcs_curve *c, double x, int *hint)
{
    int i = mcs_curve_segment(c, x, *hint);
    *hint = i;
    return eval_seg(c, i, x);
}

double mcs_curve_slope(const mcs_curve *c, double x)
{
    if (c->n == 1) return 0.0;
    if (x < c->x[0] && c->lo == MCS_EXTRAP_CONSTANT) return 0.0;
    if (x >= c->x[c->n - 1] && c->hi == MCS_EXTRAP_CONSTANT) return 0.0;
    int i = mcs_curve_segment(c, x, -1);
    return (c->y[i + 1] - c->y[i]) / (c->x[i + 1] - c->x[i]);
}

/* primitive P(x) = int_{x[0]}^{x} y dt, exact for the piecewise-linear curve */
static double primitive(const mcs_curve *c, double x)
{
    int n = c->n;
    if (x < c->x[0] && (c->lo == MCS_EXTRAP_CONSTANT || n == 1)) return c->y[0] * (x - c->x[0]);
    if (x > c->x[n - 1] && (c->hi == MCS_EXTRAP_CONSTANT || n == 1))
        return c->cum[n - 1] + c->y[n - 1] * (x - c->x[n - 1]);
    int i = mcs_curve_segment(c, x, -1);
    double d = x - c->x[i];
    double s = (c->y[i + 1] - c->y[i]) / (c->x[i + 1] - c->x[i]);
    return c->cum[i] + c->y[i] * d + 0.5 * s * d * d;
}

double mcs_curve_integral(const mcs_curve *c, double a, double b)
{
    return primitive(c, b) - primitive(c, a);
}

double mcs_curve_inverse(const mcs_curve *c, double y)
{
    if (c->monotone == 0) return NAN;
    int n = c->n, sgn = c->monotone;
    const double *xs = c->x, *ys = c->y;
    /* below the first / beyond the last ordinate (in the direction of increasing x) */
    if (sgn * (y - ys[0]) < 0) {
        if (c->lo == MCS_EXTRAP_CONSTANT) return xs[0];
        return xs[0] + (y - ys[0]) * (xs[1] - xs[0]) / (ys[1] - ys[0]);
    }
    if (sgn * (y - ys[n - 1]) > 0) {
        if (c->hi == MCS_EXTRAP_CONSTANT) return xs[n - 1];
        return xs[n - 1] + (y - ys[n - 1]) * (xs[n - 1] - xs[n - 2]) / (ys[n - 1] - ys[n - 2]);
    }
    if (!(y == y)) return NAN;
    int lo = 0, hi = n - 1; /* sgn*ys[lo] <= sgn*y <= sgn*ys[hi] */
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (sgn * (ys[mid] - y) <= 0)
            lo = mid;
        else
            hi = mid;
    }
    return xs[lo] + (y - ys[lo]) * (xs[hi] - xs[lo]) / (ys[hi] - ys[lo]);
}

mcs_status mcs_curve_create_scaled(const mcs_curve *src, const char *name, double sx, double sy,
                                   mcs_curve **out, mcs_error *err)
{
    *out = NULL;
    if (!(sx > 0) || !isfinite(sx) || !isfinite(sy))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: scale factors must be finite with x scale > 0 (got %g, %g)",
                       name ? name : src->name, sx, sy);
    mcs_curve *c = curve_alloc(src->n);
    if (!c) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", src->name);
    double *cx = (double *)c->x, *cy = (double *)c->y, *cc = (double *)c->cum;
    for (int i = 0; i < src->n; i++) {
        cx[i] = sx * src->x[i];
        cy[i] = sy * src->y[i];
        cc[i] = sx * sy * src->cum[i];
    }
    c->lo = src->lo;
    c->hi = src->hi;
    c->monotone = sy > 0 ? src->monotone : sy < 0 ? -src->monotone : 0;
    snprintf(c->name, sizeof c->name, "%s", name ? name : src->name);
    *out = c;
    return MCS_OK;
}

mcs_status mcs_curve_create_inverse(const mcs_curve *src, const char *name, mcs_curve **out,
                                    mcs_error *err)
{
    *out = NULL;
    if (!name) name = src->name;
    if (src->monotone == 0)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: only a strictly monotone curve has an inverse (y must increase or "
                       "decrease strictly)",
                       name);
    int n = src->n;
    double *buf = malloc(2 * (size_t)n * sizeof(double));
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", name);
    double *ix = buf, *iy = buf + n;
    int up = src->monotone > 0;
    for (int i = 0; i < n; i++) {
        int j = up ? i : n - 1 - i;
        ix[i] = src->y[j];
        iy[i] = src->x[j];
    }
    mcs_extrap lo = up ? src->lo : src->hi, hi = up ? src->hi : src->lo;
    mcs_status st = curve_build(name, n, ix, iy, 1, lo, hi, out, err);
    free(buf);
    return st;
}

/* force range [*fmin, *fmax] a curve can carry: capped at a constant-hold end */
static void force_range(const mcs_curve *c, double *fmin, double *fmax)
{
    if (c->lo == MCS_EXTRAP_CONSTANT && c->y[0] > *fmin) *fmin = c->y[0];
    if (c->hi == MCS_EXTRAP_CONSTANT && c->y[c->n - 1] < *fmax) *fmax = c->y[c->n - 1];
}

static int cmp_double(const void *a, const void *b)
{
    double u = *(const double *)a, v = *(const double *)b;
    return (u > v) - (u < v);
}

mcs_status mcs_curve_create_series(const mcs_curve *a, const mcs_curve *b, const char *name,
                                   mcs_curve **out, mcs_error *err)
{
    *out = NULL;
    if (!name) name = "series";
    const mcs_curve *cs[2] = {a, b};
    for (int k = 0; k < 2; k++)
        if (cs[k]->monotone != 1)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%s: curve '%s' must have strictly increasing force to be combined in "
                           "series",
                           name, cs[k]->name);
    double fmin = -INFINITY, fmax = INFINITY;
    force_range(a, &fmin, &fmax);
    force_range(b, &fmin, &fmax);
    if (!(fmax > fmin))
        return MCS_ERR(
            err, MCS_ERR_RANGE,
            "%s: curves '%s' and '%s' share no force range (plateaus cap it to [%g, %g])", name,
            a->name, b->name, fmin, fmax);
    /* breakpoints: every force level of either curve inside the range, plus the caps */
    int cap = a->n + b->n + 2, m = 0;
    double *buf = malloc(2 * (size_t)cap * sizeof(double));
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", name);
    double *f = buf, *x = buf + cap;
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < cs[k]->n; i++)
            if (cs[k]->y[i] > fmin && cs[k]->y[i] < fmax) f[m++] = cs[k]->y[i];
    if (isfinite(fmin)) f[m++] = fmin;
    if (isfinite(fmax)) f[m++] = fmax;
    qsort(f, (size_t)m, sizeof *f, cmp_double);
    int u = 0; /* drop duplicates */
    for (int i = 0; i < m; i++)
        if (u == 0 || f[i] > f[u - 1]) f[u++] = f[i];
    for (int i = 0; i < u; i++)
        x[i] = mcs_curve_inverse(a, f[i]) + mcs_curve_inverse(b, f[i]);
    mcs_extrap lo = isfinite(fmin) ? MCS_EXTRAP_CONSTANT : MCS_EXTRAP_LINEAR;
    mcs_extrap hi = isfinite(fmax) ? MCS_EXTRAP_CONSTANT : MCS_EXTRAP_LINEAR;
    mcs_status st = curve_build(name, u, x, f, 1, lo, hi, out, err);
    free(buf);
    return st;
}

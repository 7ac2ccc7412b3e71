/* fe_contact_geom: closed-form nearest point on a triangle, the point-ellipsoid distance, and
 * the elastic-stick friction update. */
#include "fe/fe_contact_impl.h"
#include "fe/fe_elem.h"

#include <math.h>

/* Ericson, Real-Time Collision Detection (2005), sec. 5.1.5: the Voronoi regions of the
 * vertices, edges and face, tested in turn with dot products only */
double fe_tri_nearest(const double p[3], const double a[3], const double b[3], const double c[3],
                      double w[3])
{
    double ab[3], ac[3], ap[3];
    for (int i = 0; i < 3; i++) ab[i] = b[i] - a[i], ac[i] = c[i] - a[i], ap[i] = p[i] - a[i];
    double d1 = fe_dot(ab, ap), d2 = fe_dot(ac, ap);
    double u, v; /* weights of b and c */
    if (d1 <= 0 && d2 <= 0) {
        u = v = 0;
    } else {
        double bp[3], cp[3];
        for (int i = 0; i < 3; i++) bp[i] = p[i] - b[i], cp[i] = p[i] - c[i];
        double d3 = fe_dot(ab, bp), d4 = fe_dot(ac, bp), d5 = fe_dot(ab, cp), d6 = fe_dot(ac, cp);
        double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
        if (d3 >= 0 && d4 <= d3) {
            u = 1, v = 0;
        } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            u = d1 / (d1 - d3), v = 0;
        } else if (d6 >= 0 && d5 <= d6) {
            u = 0, v = 1;
        } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            u = 0, v = d2 / (d2 - d6);
        } else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
            v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            u = 1 - v;
        } else {
            double den = 1 / (va + vb + vc);
            u = vb * den, v = vc * den;
        }
    }
    w[0] = 1 - u - v, w[1] = u, w[2] = v;
    double d2s = 0;
    for (int i = 0; i < 3; i++) {
        double q = a[i] + u * ab[i] + v * ac[i] - p[i];
        d2s += q * q;
    }
    return d2s;
}

/* Point-ellipsoid distance (Eberly, "Distance from a point to an ellipse, an ellipsoid, or a
 * hyperellipsoid", Geometric Tools, 2013): the nearest point is q_i = a_i^2 p_i / (a_i^2 + t)
 * where t is the root of F(t) = sum (a_i p_i / (a_i^2 + t))^2 - 1, which decreases
 * monotonically on t > -a_min^2; F(0) < 0 inside, > 0 outside. Newton's method from a bracket,
 * each iterate kept inside the bracket by bisection, to round-off (at most 60 iterations). */
double fe_ellipsoid_nearest(const double a[3], const double p[3], double q[3])
{
    double amin2 = fmin(a[0] * a[0], fmin(a[1] * a[1], a[2] * a[2]));
    double f0 = -1, r = 0;
    for (int i = 0; i < 3; i++) {
        double s = p[i] / a[i];
        f0 += s * s;
        r += p[i] * p[i];
    }
    r = sqrt(r);
    if (f0 == -1) { /* the centre: nearest is the end of the shortest axis */
        int k = a[0] * a[0] == amin2 ? 0 : a[1] * a[1] == amin2 ? 1 : 2;
        q[0] = q[1] = q[2] = 0;
        q[k] = a[k];
        return -a[k];
    }
    /* bracket: F(lo) > 0 > F(hi) */
    double lo, hi;
    if (f0 > 0) {
        lo = 0;
        double amax = fmax(a[0], fmax(a[1], a[2]));
        hi = amax * r; /* (a p / (a^2 + t))^2 summed < a^2 r^2 / t^2 <= 1 at t = a_max r */
    } else {
        hi = 0;
        lo = -amin2;
    }
    double t = f0 > 0 ? 0 : 0.5 * (lo + hi);
    for (int it = 0; it < 60; it++) {
        double F = -1, dF = 0;
        for (int i = 0; i < 3; i++) {
            double d = a[i] * a[i] + t, g = a[i] * p[i] / d;
            F += g * g;
            dF -= 2 * g * g / d;
        }
        if (F > 0) lo = t;
        else hi = t;
        double tn = dF < 0 ? t - F / dF : 0.5 * (lo + hi);
        if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
        if (fabs(tn - t) <= 1e-15 * (fabs(t) + amin2)) {
            t = tn;
            break;
        }
        t = tn;
    }
    double d2 = 0;
    for (int i = 0; i < 3; i++) {
        double den = a[i] * a[i] + t;
        q[i] = den > 0 ? a[i] * a[i] * p[i] / den : (p[i] < 0 ? -a[i] : a[i]);
        d2 += (q[i] - p[i]) * (q[i] - p[i]);
    }
    return f0 > 0 ? sqrt(d2) : -sqrt(d2);
}

/* elastic predictor, radial return onto |ft| <= fmax; *taken = -(ft_old + ft_new) . du / 2,
 * the work the interface takes from the nodes over the increment (trapezoidal) */
double fe_friction_update(double ft[3], const double n[3], const double du[3], double k,
                          double fmax, double *taken)
{
    /* the history rotated into the current tangent plane, magnitude kept */
    double fo = sqrt(fe_dot(ft, ft)), fnrm = fe_dot(ft, n), old[3];
    for (int i = 0; i < 3; i++) ft[i] -= fnrm * n[i];
    double fp = sqrt(fe_dot(ft, ft));
    if (fp > 0)
        for (int i = 0; i < 3; i++) ft[i] *= fo / fp;
    for (int i = 0; i < 3; i++) {
        old[i] = ft[i];
        ft[i] -= k * du[i];
    }
    double f = sqrt(fe_dot(ft, ft));
    if (f > fmax) {
        double sc = f > 0 ? fmax / f : 0;
        for (int i = 0; i < 3; i++) ft[i] *= sc;
        f = fmax;
    }
    *taken = 0;
    for (int i = 0; i < 3; i++) *taken -= 0.5 * (old[i] + ft[i]) * du[i];
    return k > 0 ? 0.5 * f * f / k : 0;
}

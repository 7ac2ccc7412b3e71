/* mb_geom_nearest: the nearest boundary point of an ellipse or ellipsoid to a point inside it;
 * its distance is the penetration of a facet vertex (3-D) or edge line (2-D, the ellipsoid's
 * shadow along the edge) into an ellipsoid (mb_geom_facet.c, docs/contact_geometry.md).
 * Lagrange condition of min |x - y|^2 with sum x_i^2/a_i^2 = 1 (principal frame):
 * x_i = a_i^2 y_i / (a_i^2 + t), and t is the root of
 *   F(t) = sum (a_i y_i / (a_i^2 + t))^2 - 1
 * on (-a_min^2, 0] for an interior y (D. Eberly, "Distance from a point to an ellipse, an
 * ellipsoid, or a hyperellipsoid", Geometric Tools, 2013). F is decreasing there; F >= 0 at the
 * start below, F(0) <= 0 inside, so the root stays bracketed. */
#include "stage1_mb/mb_geom_internal.h"

#include <math.h>

double mb_ell_nearest_inside(int dim, const double *a, const double *y, double *x)
{
    double ay[3], amin2 = INFINITY, lo = -INFINITY, hi = 0;
    /* |y_i| floored: y on a principal plane is the medial-axis limit, still well defined */
    for (int i = 0; i < dim; i++) {
        ay[i] = fmax(fabs(y[i]), 1e-12 * a[i]);
        amin2 = fmin(amin2, a[i] * a[i]);
        /* term i alone reaches 1 at t = a_i |y_i| - a_i^2, so F >= 0 at the largest of these */
        lo = fmax(lo, a[i] * ay[i] - a[i] * a[i]);
    }
    /* Newton on psi = (F + 1)^(-1/2) - 1 (same root, nearly linear near the pole where F is
     * not), kept inside the bracket [lo, hi] by bisection */
    double t = lo;

    for (int it = 0; it < 100 && lo < hi; it++) {
        double S = 0, dS = 0;
        for (int i = 0; i < dim; i++) {
            double den = a[i] * a[i] + t, r = a[i] * ay[i] / den;
            S += r * r;
            dS -= 2 * r * r / den;
        }
        double q = 1 / sqrt(S), psi = q - 1, dpsi = -0.5 * q * q * q * dS;
        if (psi < 0)
            lo = t;
        else if (psi > 0)
            hi = t;
        else
            break;
        double tn = t - psi / dpsi;
        if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
        double step = fabs(tn - t);
        t = tn;
        if (step <= 1e-15 * (fabs(t) + amin2)) break;
    }
    double d2 = 0;
    for (int i = 0; i < dim; i++) {
        x[i] = copysign(a[i] * a[i] * ay[i] / (a[i] * a[i] + t), y[i]);
        d2 += (x[i] - y[i]) * (x[i] - y[i]);
    }
    return sqrt(d2);
}

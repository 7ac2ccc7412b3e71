/* mb_geom_cull.c: cheap tests that two placed ellipsoids are apart, run before the
 * ellipsoid-ellipsoid Newton iteration (docs/contact_geometry.md, "Culling"):
 *   1. bounding spheres (largest semi-axis);
 *   2. each centre against the other's box grown by its bounding radius: the ellipsoid lies in
 *      its box |x_i| <= a_i (own axes), so a centre beyond a_i + r on any axis is apart;
 *   3. a remembered separating direction n (the pair's last normal): the support-function gap
 *      g(n) = n.(cA - cB) - hA(n) - hB(n), h(n) = |diag(a) R^T n|, is a lower bound of the
 *      distance; g > 0 proves the pair apart (separating-axis theorem).
 * Each test only ever answers "apart" when the pair is: the Newton result is unchanged. */
#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>

static double bound_radius(const mb_ellipsoid *e)
{
    return fmax(e->semi[0], fmax(e->semi[1], e->semi[2]));
}

/* p (world) beyond e's box grown by r */
static int outside_box(const mb_ellipsoid *e, const double p[3], double r)
{
    double d[3], l[3];
    mb_sub(p, e->center, d);
    mb_mat_tvec(e->rot, d, l);
    for (int k = 0; k < 3; k++)
        if (fabs(l[k]) > e->semi[k] + r) return 1;
    return 0;
}

/* support extent of e along unit n: sqrt(n' R diag(a^2) R' n) */
static double support(const mb_ellipsoid *e, const double n[3])
{
    double l[3];
    mb_mat_tvec(e->rot, n, l);
    double x = e->semi[0] * l[0], y = e->semi[1] * l[1], z = e->semi[2] * l[2];
    return sqrt(x * x + y * y + z * z);
}

double mb_ellipsoid_gap(const mb_ellipsoid *a, const mb_ellipsoid *b, const double n[3])
{
    double d[3];
    mb_sub(a->center, b->center, d);
    return mb_dot(n, d) - support(a, n) - support(b, n);
}

int mb_ellipsoids_apart(const mb_ellipsoid *a, const mb_ellipsoid *b, const double *n)
{
    double d[3], ra = bound_radius(a), rb = bound_radius(b);
    mb_sub(a->center, b->center, d);
    if (mb_dot(d, d) >= (ra + rb) * (ra + rb)) return 1;
    if (outside_box(a, b->center, rb) || outside_box(b, a->center, ra)) return 1;
    return n && mb_ellipsoid_gap(a, b, n) > 0;
}

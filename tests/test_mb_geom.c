/* tests for stage1_mb/mb_geom: penetration geometry against closed forms and against
 * brute-force sampling that shares no code with the library (docs/contact_geometry.md). */
#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_vec.h"
#include "tests/harness.h"
#include "tests/figures.h"

/* ---- independent helpers ------------------------------------------------------------------ */

static unsigned long long rng_state = 88172645463325252ull;
static double urand(void) /* xorshift64, in [0, 1) */
{
    rng_state ^= rng_state << 13, rng_state ^= rng_state >> 7, rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

static void random_rot(double R[9])
{
    double ax[3] = {urand() - 0.5, urand() - 0.5, urand() - 0.5};
    mb_normalize(ax);
    mb_rot_axis_angle(ax, 2 * M_PI * urand(), R);
}

static mb_ellipsoid ell(double cx, double cy, double cz, double a, double b, double c)
{
    mb_ellipsoid e = {{cx, cy, cz}, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {a, b, c}};
    return e;
}

/* implicit function f(x) = |diag(1/s) R^T (x - c)|^2 - 1 and its gradient direction */
static double implicit(const mb_ellipsoid *e, const double x[3], double grad[3])
{
    double r[3], l[3], gl[3];
    mb_sub(x, e->center, r);
    mb_mat_tvec(e->rot, r, l);
    double f = -1;
    for (int k = 0; k < 3; k++) {
        f += l[k] * l[k] / (e->semi[k] * e->semi[k]);
        gl[k] = l[k] / (e->semi[k] * e->semi[k]);
    }
    if (grad) {
        mb_mat_vec(e->rot, gl, grad);
        mb_normalize(grad);
    }
    return f;
}

/* surface samples on a (theta, phi) grid of the parametric form c + R diag(s) (unit sphere) */
enum { NTH = 60, NPH = 120, NSAMP = NTH * NPH };
static void sample_surface(const mb_ellipsoid *e, double *pts)
{
    for (int i = 0; i < NTH; i++)
        for (int j = 0; j < NPH; j++) {
            double th = M_PI * (i + 0.5) / NTH, ph = 2 * M_PI * j / NPH;
            double l[3] = {e->semi[0] * sin(th) * cos(ph), e->semi[1] * sin(th) * sin(ph),
                           e->semi[2] * cos(th)};
            double w[3];
            mb_mat_vec(e->rot, l, w);
            mb_add(w, e->center, pts + 3 * (i * NPH + j));
        }
}

/* overlap of the projections of two point clouds on n (>0 overlapping): the separating-axis
 * penetration along n; minimised over n it is the penetration depth */
static double proj_overlap(const double *pa, const double *pb, const double n[3])
{
    double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
    for (int i = 0; i < NSAMP; i++) {
        double x = mb_dot(n, pa + 3 * i), y = mb_dot(n, pb + 3 * i);
        amin = fmin(amin, x), amax = fmax(amax, x), bmin = fmin(bmin, y), bmax = fmax(bmax, y);
    }
    return fmin(bmax - amin, amax - bmin);
}

/* brute force: coarse Fibonacci directions, then a shrinking pattern search on the sphere */
static double brute_depth(const mb_ellipsoid *a, const mb_ellipsoid *b, double nbest[3])
{
    static double pa[3 * NSAMP], pb[3 * NSAMP];
    sample_surface(a, pa);
    sample_surface(b, pb);
    double best = 1e300;
    int nd = 800;
    for (int i = 0; i < nd; i++) {
        double z = 1 - 2 * (i + 0.5) / nd, r = sqrt(1 - z * z), ph = i * M_PI * (3 - sqrt(5.0));
        double n[3] = {r * cos(ph), r * sin(ph), z};
        double o = proj_overlap(pa, pb, n);
        if (o < best) best = o, mb_copy(n, nbest);
    }
    for (double step = 0.08; step > 2e-4; step *= 0.5) {
        int moved = 1;
        while (moved) {
            moved = 0;
            double t1[3], t2[3], ref[3] = {0.3, 0.5, 0.8};
            mb_cross(nbest, ref, t1);
            mb_normalize(t1);
            mb_cross(nbest, t1, t2);
            for (int k = 0; k < 4; k++) {
                double s1 = (k == 0) - (k == 1), s2 = (k == 2) - (k == 3), n[3];
                for (int j = 0; j < 3; j++)
                    n[j] = nbest[j] + step * (s1 * t1[j] + s2 * t2[j]);
                mb_normalize(n);
                double o = proj_overlap(pa, pb, n);
                if (o < best - 1e-15) best = o, mb_copy(n, nbest), moved = 1;
            }
        }
    }
    return best;
}

/* the common-normal conditions at a returned contact, checked with the implicit functions */
static void check_common_normal(const mb_ellipsoid *a, const mb_ellipsoid *b, const mb_contact *c)
{
    double ga[3], gb[3], d[3];
    CHECK_NEAR(implicit(a, c->point_a, ga), 0, 1e-9);
    CHECK_NEAR(implicit(b, c->point_b, gb), 0, 1e-9);
    CHECK_NEAR(mb_dot(ga, c->normal), -1, 1e-9); /* a's outward normal at point_a is -n */
    CHECK_NEAR(mb_dot(gb, c->normal), 1, 1e-9);  /* b's outward normal at point_b is +n */
    mb_sub(c->point_b, c->point_a, d);
    CHECK_NEAR(mb_dot(d, c->normal), c->depth, 1e-12);
    CHECK_NEAR(mb_norm(d), c->depth, 1e-9);
    CHECK_NEAR(mb_norm(c->normal), 1, 1e-12);
}

/* ---- ellipsoid-plane ------------------------------------------------------------------------ */

/* axis-aligned: depth = c - z (semi-axis along the normal minus centre height) */
static void test_ellipsoid_plane_axis(void)
{
    mb_ellipsoid e = ell(0.1, -0.2, 0.25, 0.1, 0.2, 0.3);
    mb_plane g = {{0, 0, 0}, {0, 0, 1}};
    mb_contact c;
    CHECK(mb_geom_ellipsoid_plane(&e, &g, &c) == 1);
    CHECK_NEAR(c.depth, 0.05, 1e-15);
    CHECK_NEAR(c.point_a[0], 0.1, 1e-15);
    CHECK_NEAR(c.point_a[1], -0.2, 1e-15);
    CHECK_NEAR(c.point_a[2], -0.05, 1e-15);
    CHECK_NEAR(c.point_b[2], 0, 1e-15);
    CHECK_NEAR(c.point[2], -0.025, 1e-15);
    CHECK_NEAR(c.normal[2], 1, 0);
    e.center[2] = 0.3000001;
    CHECK(mb_geom_ellipsoid_plane(&e, &g, &c) == 0);
    CHECK(c.depth == 0);
}

/* rotated ellipsoid on a tilted barrier vs the sampled surface's lowest point along -n */
static void test_ellipsoid_plane_rotated(void)
{
    static double pts[3 * NSAMP];
    for (int trial = 0; trial < 5; trial++) {
        mb_ellipsoid e =
            ell(0.3, 0.1, 0.2, 0.05 + 0.1 * urand(), 0.05 + 0.1 * urand(), 0.05 + 0.1 * urand());
        random_rot(e.rot);
        double n[3] = {urand() - 0.5, urand() - 0.5, urand() - 0.5};
        mb_normalize(n);
        double hmax = fmax(e.semi[0], fmax(e.semi[1], e.semi[2]));
        mb_plane p;
        mb_copy(n, p.normal);
        mb_axpy(e.center, -0.6 * hmax, n, p.point); /* plane 0.6 * largest semi-axis below */
        mb_contact c;
        int hit = mb_geom_ellipsoid_plane(&e, &p, &c);
        sample_surface(&e, pts);
        double lowest = 1e300;
        for (int i = 0; i < NSAMP; i++) {
            double r[3];
            mb_sub(pts + 3 * i, p.point, r);
            lowest = fmin(lowest, mb_dot(n, r));
        }
        double smax = hmax;
        /* grid of 3 deg: the sampled minimum is high by at most smax (1 - cos 1.5 deg) */
        CHECK(hit == (lowest < 0));
        if (hit) {
            CHECK(c.depth >= -lowest - 1e-12);
            CHECK(c.depth <= -lowest + smax * 4e-4);
            double grad[3], r[3];
            CHECK_NEAR(implicit(&e, c.point_a, grad), 0, 1e-12);
            CHECK_NEAR(mb_dot(grad, n), -1, 1e-12);
            mb_sub(c.point_b, p.point, r);
            CHECK_NEAR(mb_dot(r, n), 0, 1e-15);
        }
    }
}

/* ---- sphere-sphere and ellipsoid-ellipsoid ----------------------------------------------------
 */

static void test_sphere_sphere(void)
{
    double ca[3] = {0.1, 0.2, 0.3}, cb[3] = {0.1 + 0.06, 0.2 + 0.08, 0.3}; /* distance 0.1 */
    mb_contact c;
    CHECK(mb_geom_sphere_sphere(ca, 0.07, cb, 0.05, &c) == 1);
    CHECK_NEAR(c.depth, 0.02, 1e-15);
    CHECK_NEAR(c.normal[0], -0.6, 1e-15);
    CHECK_NEAR(c.normal[1], -0.8, 1e-15);
    CHECK_NEAR(c.point_a[0], 0.1 + 0.6 * 0.07, 1e-15);
    CHECK_NEAR(c.point_b[1], 0.28 - 0.8 * 0.05, 1e-15);
    CHECK(mb_geom_sphere_sphere(ca, 0.05, cb, 0.05, &c) == 0);
    CHECK(mb_geom_sphere_sphere(ca, 0.05, ca, 0.02, &c) == 1);
    CHECK(c.status == MB_GEOM_DEGENERATE);
    CHECK_NEAR(c.depth, 0.07, 1e-15);
}

/* spheres through the ellipsoid path, rotated frames: exact depth ra + rb - |d| */
static void test_ee_spheres(void)
{
    mb_ellipsoid a = ell(0.01, 0.02, 0.03, 0.1, 0.1, 0.1),
                 b = ell(0.12, -0.05, 0.1, 0.07, 0.07, 0.07);
    random_rot(a.rot);
    random_rot(b.rot);
    mb_contact c, s;
    CHECK(mb_geom_ellipsoid_ellipsoid(&a, &b, NULL, &c) == 1);
    CHECK(mb_geom_sphere_sphere(a.center, 0.1, b.center, 0.07, &s) == 1);
    CHECK_NEAR(c.depth, s.depth, 1e-14);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(c.normal[k], s.normal[k], 1e-12);
    CHECK(c.status == MB_GEOM_OK);
    CHECK(c.iterations <= 20); /* deep (> smin / 4): 1 + 6 multistart runs of <= 3 steps */
}

/* sphere on an ellipsoid's principal axis: the pole is nearest, depth = r + c - z exactly */
static void test_ee_sphere_on_axis(void)
{
    mb_ellipsoid a = ell(0, 0, 0.33, 0.05, 0.05, 0.05), b = ell(0, 0, 0, 0.12, 0.2, 0.3);
    mb_contact c;
    CHECK(mb_geom_ellipsoid_ellipsoid(&a, &b, NULL, &c) == 1);
    CHECK_NEAR(c.depth, 0.05 + 0.3 - 0.33, 1e-14);
    CHECK_NEAR(c.normal[2], 1, 1e-14);
    CHECK_NEAR(c.point_b[2], 0.3, 1e-14);
    /* along x, with b rotated 90 deg about z so its 0.2 axis lies on world x */
    double z[3] = {0, 0, 1};
    mb_rot_axis_angle(z, M_PI / 2, b.rot);
    a.center[0] = -0.24, a.center[2] = 0;
    CHECK(mb_geom_ellipsoid_ellipsoid(&a, &b, NULL, &c) == 1);
    CHECK_NEAR(c.depth, 0.05 + 0.2 - 0.24, 1e-14);
    CHECK_NEAR(c.normal[0], -1, 1e-14);
    check_common_normal(&a, &b, &c);
}

/* coaxial ellipsoids offset along a common axis, shallow (depth below the curvature radius
 * a1^2/c1 + a2^2/c2 of the Minkowski sum at its pole): depth = c1 + c2 - z */
static void test_ee_aligned(void)
{
    mb_ellipsoid a = ell(0, 0, 0, 0.15, 0.1, 0.08), b = ell(0, 0, 0.17, 0.2, 0.12, 0.1);
    mb_contact c;
    CHECK(mb_geom_ellipsoid_ellipsoid(&b, &a, NULL, &c) == 1);
    CHECK_NEAR(c.depth, 0.08 + 0.1 - 0.17, 1e-14);
    CHECK_NEAR(c.normal[2], 1, 1e-14);
    b.center[2] = 0, b.center[1] = -0.2;
    CHECK(mb_geom_ellipsoid_ellipsoid(&b, &a, NULL, &c) == 1);
    CHECK_NEAR(c.depth, 0.1 + 0.12 - 0.2, 1e-14);
    CHECK_NEAR(c.normal[1], -1, 1e-14);
    b.center[1] = -0.23; /* apart by 1 cm */
    CHECK(mb_geom_ellipsoid_ellipsoid(&b, &a, NULL, &c) == 0);
}

/* rotated ellipsoids in shallow and moderate contact against the brute-force depth */
static void test_ee_rotated_brute(void)
{
    int ncase = th_verify() ? 12 : 4;
    double worst = 0, worst4 = 0; /* over all cases, over make test's first 4 */
    for (int trial = 0; trial < ncase; trial++) {
        mb_ellipsoid a =
            ell(0, 0, 0, 0.06 + 0.1 * urand(), 0.06 + 0.1 * urand(), 0.06 + 0.1 * urand());
        mb_ellipsoid b = a;
        for (int k = 0; k < 3; k++)
            b.semi[k] = 0.05 + 0.1 * urand();
        random_rot(a.rot);
        random_rot(b.rot);
        /* place b along a random direction, then move it in until the depth is 5-25 mm */
        double u[3] = {urand() - 0.5, urand() - 0.5, urand() - 0.5};
        mb_normalize(u);
        double target = 0.005 + 0.02 * urand(), dist = 0.6;
        mb_contact c = {0};
        for (int it = 0; it < 60; it++) { /* bisection on the centre distance */
            mb_scale(u, dist, b.center);
            mb_geom_ellipsoid_ellipsoid(&a, &b, NULL, &c);
            dist += (c.depth > target ? 1 : -1) * 0.3 * pow(0.5, it);
        }
        CHECK(c.depth > 0);
        CHECK(c.status == MB_GEOM_OK);
        check_common_normal(&a, &b, &c);
        double nb[3];
        double bd = brute_depth(&a, &b, nb);
        double smax = fmax(fmax(a.semi[0], a.semi[1]),
                           fmax(a.semi[2], fmax(b.semi[0], fmax(b.semi[1], b.semi[2]))));
        /* sampled supports are low by <= smax (1 - cos(1.5 deg)) each: brute depth may be
         * smaller than the true one by up to 2 of them, never larger */
        CHECK(bd <= c.depth + 1e-12);
        CHECK(bd >= c.depth - 2 * smax * 3.5e-4);
        CHECK(fabs(mb_dot(nb, c.normal)) > 0.99);
        worst = fmax(worst, c.depth - bd);
        if (trial < 4)
            worst4 = worst;
    }
    printf("  ellipsoid-ellipsoid vs brute force: worst depth difference %.3g m\n", worst);
    FIG("contact_geometry.ee_brute_worst", "%.0e", worst4);
    if (ncase > 4)
        FIG("contact_geometry.ee_brute_worst_verify", "%.0e", worst);
}

/* concentric (deep, degenerate): the depth is the smallest h_A + h_B over the axes */
static void test_ee_deep_multistart(void)
{
    mb_ellipsoid a = ell(0, 0, 0, 0.3, 0.1, 0.12), b = ell(0, 0, 0, 0.05, 0.05, 0.05);
    mb_contact c;
    CHECK(mb_geom_ellipsoid_ellipsoid(&a, &b, NULL, &c) == 1);
    CHECK(c.status == MB_GEOM_DEGENERATE);
    CHECK_NEAR(c.depth, 0.15, 1e-12);
    CHECK_NEAR(fabs(c.normal[1]), 1, 1e-9);
    /* off-centre along the long axis: the line of centres gives the 0.35 - 0.1 exit, the
     * shallow y exit (0.15) must still be found */
    b.center[0] = 0.1;
    CHECK(mb_geom_ellipsoid_ellipsoid(&b, &a, NULL, &c) == 1);
    double nb[3];
    double bd = brute_depth(&b, &a, nb);
    CHECK_NEAR(c.depth, bd, 2 * 0.3 * 3.5e-4);
    CHECK(c.depth < 0.2);
}

/* warm start from last step's normal converges in fewer iterations */
static void test_ee_warm_start(void)
{
    mb_ellipsoid a = ell(0, 0, 0, 0.1, 0.15, 0.08), b = ell(0.05, 0.1, 0.2, 0.12, 0.06, 0.09);
    random_rot(a.rot);
    random_rot(b.rot);
    mb_contact c0, c1;
    for (double z = 0.25; z > 0; z -= 0.005) {
        b.center[2] = z;
        if (mb_geom_ellipsoid_ellipsoid(&b, &a, NULL, &c0)) break;
    }
    CHECK(c0.depth > 0);
    b.center[2] -= 0.001;
    mb_contact cold;
    mb_geom_ellipsoid_ellipsoid(&b, &a, NULL, &cold);
    CHECK(mb_geom_ellipsoid_ellipsoid(&b, &a, c0.normal, &c1) == 1);
    CHECK_NEAR(c1.depth, cold.depth, 1e-14);
    CHECK(c1.iterations <= cold.iterations);
}

/* ---- facets --------------------------------------------------------------------------------- */

/* face: a large triangle under a rotated ellipsoid gives the plane answer */
static void test_triangle_face(void)
{
    mb_ellipsoid e = ell(0.2, 0.1, 0.05, 0.08, 0.12, 0.1);
    random_rot(e.rot);
    double v0[3] = {-5, -5, 0}, v1[3] = {5, -5, 0}, v2[3] = {0, 5, 0};
    mb_plane g = {{0, 0, 0}, {0, 0, 1}};
    mb_contact c, p;
    CHECK(mb_geom_ellipsoid_triangle(&e, v0, v1, v2, &c) == 1);
    CHECK(mb_geom_ellipsoid_plane(&e, &g, &p) == 1);
    CHECK(c.feature == MB_FEATURE_FACE);
    CHECK_NEAR(c.depth, p.depth, 1e-15);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(c.point[k], p.point[k], 1e-15);
    CHECK_NEAR(c.normal[2], 1, 0);
    /* reversed winding: the ellipsoid centre is behind the facet, no contact */
    CHECK(mb_geom_ellipsoid_triangle(&e, v0, v2, v1, &c) == 0);
}

/* edge and vertex with a sphere of radius r: the penetration is r minus the distance from the
 * centre to the edge's line or to the vertex (docs/contact_geometry.md), along that distance */
static void test_triangle_edge_vertex_sphere(void)
{
    double r = 0.1, z0 = 0.06;
    double v0[3] = {-1, -1, 0}, v1[3] = {0, -1, 0}, v2[3] = {0, 1, 0}; /* edge v1-v2 on x = 0 */
    mb_ellipsoid e = ell(0.05, 0.2, z0, r, r, r);
    mb_contact c;
    CHECK(mb_geom_ellipsoid_triangle(&e, v0, v1, v2, &c) == 1);
    CHECK(c.feature == MB_FEATURE_EDGE);
    double rho = sqrt(0.05 * 0.05 + z0 * z0);
    CHECK_NEAR(c.depth, r - rho, 1e-14);
    CHECK_NEAR(c.normal[0], 0.05 / rho, 1e-13);
    CHECK_NEAR(c.normal[2], z0 / rho, 1e-13);
    CHECK_NEAR(c.point_b[0], 0, 1e-14);
    CHECK_NEAR(c.point_b[1], 0.2, 1e-14);
    /* vertex v2 = (0, 1): centre beyond it in x and y */
    e.center[0] = 0.03, e.center[1] = 1.04;
    CHECK(mb_geom_ellipsoid_triangle(&e, v0, v1, v2, &c) == 1);
    CHECK(c.feature == MB_FEATURE_VERTEX);
    CHECK_NEAR(c.depth, r - sqrt(0.03 * 0.03 + 0.04 * 0.04 + z0 * z0), 1e-14);
    CHECK_NEAR(c.point_b[1], 1, 0);
    /* beyond the edge by more than the footprint radius sqrt(r^2 - z0^2) = 0.08 */
    e.center[0] = 0.081, e.center[1] = 0;
    CHECK(mb_geom_ellipsoid_triangle(&e, v0, v1, v2, &c) == 0);
}

/* the penetration of the point P (vertex, dim 3) or of the line through P along unit t (edge)
 * into e, by separating axes: min over unit u (normal to t for a line) of the overlap
 * h(u) - u.(c - P), h(u) = |diag(s) R^T u| the support function; sampled directions, then a
 * shrinking pattern search (no code shared with the library). *best_u: the minimiser. */
static double sat_overlap(const mb_ellipsoid *e, const double P[3], const double u[3])
{
    double l[3], w[3], h = 0;
    mb_mat_tvec(e->rot, u, l);
    for (int k = 0; k < 3; k++)
        h += e->semi[k] * e->semi[k] * l[k] * l[k];
    mb_sub(e->center, P, w);
    return sqrt(h) - mb_dot(u, w);
}

static void sat_dir(const double b1[3], const double b2[3], const double b3[3], double th,
                    double ph, double u[3])
{
    for (int k = 0; k < 3; k++)
        u[k] = cos(th) * (cos(ph) * b1[k] + sin(ph) * b2[k]) + sin(th) * b3[k];
}

static double brute_penetration(const mb_ellipsoid *e, const double P[3], const double *t,
                                double best_u[3])
{
    /* basis: b1, b2 normal to t (or x, y), b3 = t (or z); th = 0 for a line */
    double b1[3] = {1, 0, 0}, b2[3] = {0, 1, 0}, b3[3] = {0, 0, 1};
    if (t) {
        double a[3] = {fabs(t[0]) < 0.6 ? 1 : 0, fabs(t[0]) < 0.6 ? 0 : 1, 0};
        mb_cross(t, a, b1);
        mb_normalize(b1);
        mb_cross(t, b1, b2);
        mb_copy(t, b3);
    }
    int nth = t ? 1 : 181, nph = 720;
    double best = INFINITY, bth = 0, bph = 0, u[3];
    for (int i = 0; i < nth; i++)
        for (int j = 0; j < nph; j++) {
            double th = t ? 0 : -M_PI / 2 + M_PI * i / (nth - 1), ph = 2 * M_PI * j / nph;
            sat_dir(b1, b2, b3, th, ph, u);
            double g = sat_overlap(e, P, u);
            if (g < best) best = g, bth = th, bph = ph;
        }
    for (double step = 0.01; step > 1e-10; step *= 0.5)
        for (int moved = 1; moved;) {
            moved = 0;
            for (int k = 0; k < (t ? 2 : 4); k++) {
                double th = bth + (k == 2 ? step : k == 3 ? -step : 0);
                double ph = bph + (k == 0 ? step : k == 1 ? -step : 0);
                sat_dir(b1, b2, b3, th, ph, u);
                double g = sat_overlap(e, P, u);
                if (g < best) best = g, bth = th, bph = ph, moved = 1;
            }
        }
    sat_dir(b1, b2, b3, bth, bph, best_u);
    return best;
}

/* rotated ellipsoids over a triangle's face, edge and vertex regions: the face depth is the
 * plane's; an edge's or vertex's penetration is the separating-axis minimum above, and the
 * normal its minimising direction */
static void test_triangle_rotated_brute(void)
{
    double v0[3] = {0, 0, 0}, v1[3] = {0.3, 0, 0}, v2[3] = {0.1, 0.25, 0};
    const double *v[3] = {v0, v1, v2};
    int nfeat[4] = {0};
    double worst = 0;
    for (int trial = 0; trial < 30; trial++) {
        mb_ellipsoid e = ell(-0.1 + 0.5 * urand(), -0.1 + 0.45 * urand(), 0, 0.04 + 0.08 * urand(),
                             0.04 + 0.08 * urand(), 0.04 + 0.08 * urand());
        random_rot(e.rot);
        double g[3] = {0, 0, 1}, s[3];
        mb_ellipsoid_support(&e, g, s);
        e.center[2] += -0.02 - s[2]; /* lowest point 2 cm below the plane */
        mb_contact c;
        if (!mb_geom_ellipsoid_triangle(&e, v0, v1, v2, &c)) continue;
        nfeat[c.feature]++;
        double bu[3], bd;
        if (c.feature == MB_FEATURE_FACE) {
            mb_plane pl = {{0, 0, 0}, {0, 0, 1}};
            mb_contact p;
            mb_geom_ellipsoid_plane(&e, &pl, &p);
            bd = p.depth, bu[0] = bu[1] = 0, bu[2] = 1;
        } else if (c.feature == MB_FEATURE_EDGE) {
            /* the edge whose line holds point_b */
            int i = 0;
            for (; i < 3; i++) {
                double t[3], w[3], x[3];
                mb_sub(v[(i + 1) % 3], v[i], t);
                mb_normalize(t);
                mb_sub(c.point_b, v[i], w);
                mb_cross(t, w, x);
                if (mb_norm(x) < 1e-9) break;
            }
            CHECK(i < 3);
            if (i == 3) continue;
            double t[3];
            mb_sub(v[(i + 1) % 3], v[i], t);
            mb_normalize(t);
            bd = brute_penetration(&e, v[i], t, bu);
        } else {
            bd = brute_penetration(&e, c.point_b, NULL, bu);
        }
        worst = fmax(worst, fabs(c.depth - bd));
        CHECK_NEAR(c.depth, bd, 1e-16); /* the docs state the worst: 3e-17 */
        for (int k = 0; k < 3; k++)
            CHECK_NEAR(c.normal[k], bu[k], 1e-4);
        double gr[3];
        CHECK_NEAR(implicit(&e, c.point_a, gr), 0, 1e-9);
        /* the force line: point_b - point_a along the normal, |.| = depth */
        double ab[3];
        mb_sub(c.point_b, c.point_a, ab);
        CHECK_NEAR(mb_dot(ab, c.normal), c.depth, 1e-9);
        CHECK(mb_norm(ab) < c.depth + 1e-9);
    }
    printf("  triangle features hit: face %d, edge %d, vertex %d; worst depth error %.1e m\n",
           nfeat[1], nfeat[2], nfeat[3], worst);
    FIG("contact_geometry.tri_brute_depth_err", "%.0e", worst);
    CHECK(nfeat[MB_FEATURE_FACE] > 0 && nfeat[MB_FEATURE_EDGE] > 0 && nfeat[MB_FEATURE_VERTEX] > 0);
}

/* a flat grid of nx x ny squares (2 triangles each) in z = 0, x, y in [0, L] */
static void grid_mesh(int nx, int ny, double L, double *vert, int *tri)
{
    for (int j = 0; j <= ny; j++)
        for (int i = 0; i <= nx; i++) {
            double *p = vert + 3 * (j * (nx + 1) + i);
            p[0] = L * i / nx, p[1] = L * j / ny,
            p[2] = 0.002 * sin(7.0 * i / nx) * cos(5.0 * j / ny);
        }
    int t = 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
            int *q = tri + 3 * t;
            q[0] = a, q[1] = b, q[2] = d, q[3] = a, q[4] = d, q[5] = c;
            t += 2;
        }
}

/* the AABB tree finds exactly what a loop over all 5000 triangles finds, with a pose */
static void test_mesh_vs_loop(void)
{
    enum { NX = 50, NY = 50, NV = (NX + 1) * (NY + 1), NT = 2 * NX * NY };
    static double vert[3 * NV], wv[3 * NV];
    static int tri[3 * NT];
    grid_mesh(NX, NY, 2.0, vert, tri);
    mb_mesh *m = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_mesh_create(&m, NV, vert, NT, tri, &err) == MCS_OK);
    if (!m) return;
    CHECK(mb_mesh_ntri(m) == NT);
    mb_pose pose = {{0.5, -1.0, 0.3}, {0}};
    double ax[3] = {0.2, 1, 0.3};
    mb_normalize(ax);
    mb_rot_axis_angle(ax, 0.7, pose.rot);
    for (int i = 0; i < NV; i++) {
        mb_mat_vec(pose.rot, vert + 3 * i, wv + 3 * i);
        mb_add(wv + 3 * i, pose.pos, wv + 3 * i);
    }
    static mb_contact all[64];
    for (int trial = 0; trial < 10; trial++) {
        double loc[3] = {2.2 * urand() - 0.1, 2.2 * urand() - 0.1, 0.03 + 0.05 * urand()};
        mb_ellipsoid e =
            ell(0, 0, 0, 0.05 + 0.05 * urand(), 0.05 + 0.05 * urand(), 0.05 + 0.05 * urand());
        random_rot(e.rot);
        mb_mat_vec(pose.rot, loc, e.center);
        mb_add(e.center, pose.pos, e.center);
        mb_contact deep;
        int n = mb_geom_ellipsoid_mesh(&e, m, &pose, &deep, all, 64);
        int nl = 0;
        double dl = 0;
        int tl = -1;
        for (int t = 0; t < NT; t++) {
            mb_contact c;
            if (mb_geom_ellipsoid_triangle(&e, wv + 3 * tri[3 * t], wv + 3 * tri[3 * t + 1],
                                           wv + 3 * tri[3 * t + 2], &c)) {
                nl++;
                if (c.depth > dl) dl = c.depth, tl = t;
            }
        }
        CHECK(n == nl);
        CHECK_NEAR(deep.depth, dl, 1e-12);
        CHECK(deep.tri == tl);
        mb_contact d2;
        CHECK(mb_geom_ellipsoid_mesh_deepest(&e, m, &pose, &d2) == (nl > 0));
        CHECK_NEAR(d2.depth, dl, 1e-12);
        if (nl > 0)
            for (int k = 0; k < 3; k++) {
                CHECK_NEAR(d2.point[k], deep.point[k], 1e-12);
                CHECK_NEAR(d2.normal[k], deep.normal[k], 1e-12);
            }
        for (int i = 0; i < n && i < 64; i++)
            CHECK(all[i].depth > 0 && all[i].depth <= deep.depth);
    }
    mb_mesh_destroy(&m);
    CHECK(m == NULL);
}

static void test_mesh_errors(void)
{
    double v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, vcol[9] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
    int t[3] = {0, 1, 2}, tbad[3] = {0, 1, 3};
    mb_mesh *m = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_mesh_create(&m, 3, v, 1, tbad, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "triangle 0 uses vertex 3");
    CHECK(m == NULL);
    mcs_error_clear(&err);
    CHECK(mb_mesh_create(&m, 3, vcol, 1, t, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "zero area");
    mcs_error_clear(&err);
    v[4] = NAN;
    CHECK(mb_mesh_create(&m, 3, v, 1, t, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "vertex 1 is not finite");
    CHECK(m == NULL);
}

/* ---- wheel-road ----------------------------------------------------------------------------- */

/* upright: depth = R - height; cambered by gamma: depth = R cos(gamma) + tube - height */
static void test_wheel_plane(void)
{
    mb_plane g = {{0, 0, 0}, {0, 0, 1}};
    mb_wheel w = {{1, 2, 0.29}, {0, 1, 0}, 0.3, 0};
    mb_wheel_contact wc;
    CHECK(mb_geom_wheel_plane(&w, &g, &wc) == 1);
    CHECK_NEAR(wc.c.depth, 0.01, 1e-15);
    CHECK_NEAR(wc.c.point_b[0], 1, 1e-15);
    CHECK_NEAR(wc.c.point_b[2], 0, 1e-15);
    CHECK_NEAR(wc.camber, 0, 0);
    CHECK_NEAR(wc.forward[0], 1, 1e-15);
    CHECK_NEAR(wc.lateral[1], 1, 1e-15);
    w.center[2] = 0.31;
    CHECK(mb_geom_wheel_plane(&w, &g, &wc) == 0);

    /* cambered 30 deg with a tyre tube: check against sampled torus surface */
    double gam = 30 * M_PI / 180, R = 0.24, rt = 0.06;
    mb_wheel t = {{0, 0, 0.25}, {0, cos(gam), -sin(gam)}, R, rt};
    CHECK(mb_geom_wheel_plane(&t, &g, &wc) == 1);
    CHECK_NEAR(wc.c.depth, R * cos(gam) + rt - 0.25, 1e-15);
    CHECK_NEAR(wc.camber, -gam, 1e-15);
    double e1[3] = {1, 0, 0}, e2[3];
    mb_cross(t.axis, e1, e2); /* e1, e2 span the wheel plane */
    double lowest = 1e300, low_pt[3] = {0};
    for (int i = 0; i < 3600; i++)
        for (int j = 0; j < 360; j++) {
            double a = 2 * M_PI * i / 3600, b = 2 * M_PI * j / 360, radial[3], p[3];
            for (int k = 0; k < 3; k++)
                radial[k] = cos(a) * e1[k] + sin(a) * e2[k];
            for (int k = 0; k < 3; k++)
                p[k] = t.center[k] + (R + rt * cos(b)) * radial[k] + rt * sin(b) * t.axis[k];
            if (p[2] < lowest) lowest = p[2], mb_copy(p, low_pt);
        }
    CHECK_NEAR(wc.c.depth, -lowest, 2e-5);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(wc.c.point_a[k], low_pt[k], 2e-3);
    CHECK_NEAR(mb_dot(wc.forward, t.axis), 0, 1e-15);
    CHECK_NEAR(mb_dot(wc.forward, g.normal), 0, 1e-15);
    CHECK_NEAR(mb_norm(wc.lateral), 1, 1e-15);
    /* the rim point lies in the wheel plane, R from the centre */
    double rim[3], d[3];
    mb_axpy(wc.c.point_a, rt, g.normal, rim);
    mb_sub(rim, t.center, d);
    CHECK_NEAR(mb_dot(d, t.axis), 0, 1e-15);
    CHECK_NEAR(mb_norm(d), R, 1e-15);
}

int main(void)
{
    RUN(test_ellipsoid_plane_axis);
    RUN(test_ellipsoid_plane_rotated);
    RUN(test_sphere_sphere);
    RUN(test_ee_spheres);
    RUN(test_ee_sphere_on_axis);
    RUN(test_ee_aligned);
    RUN(test_ee_rotated_brute);
    RUN(test_ee_deep_multistart);
    RUN(test_ee_warm_start);
    RUN(test_triangle_face);
    RUN(test_triangle_edge_vertex_sphere);
    RUN(test_triangle_rotated_brute);
    RUN(test_mesh_vs_loop);
    RUN(test_mesh_errors);
    RUN(test_wheel_plane);
    TEST_END();
}

/* Ellipsoid-facet contact at edges and vertices (stage1_mb/mb_geom_facet.c,
 * docs/contact_geometry.md): the penetration is a distance that is continuous across face, edge
 * and vertex regions, and the force along its direction derives from a potential.
 * Analytic answers: a sphere of radius R with centre c against a convex edge line or a vertex
 * q penetrates by R - |c - q_perp| along (c - q_perp)/|c - q_perp| (the distance from a point to
 * a line or a point); against a plane by R - n.(c - p0). For an ellipsoid with a principal axis
 * along the edge, the penetration of a line through the shadow ellipse's minor axis at depth
 * delta below the pole is delta while delta < b^2/c (the pole's curvature radius, b the
 * other semi-axis: the pole is then the nearest boundary point). */
#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_vec.h"
#include "tests/harness.h"
#include "tests/figures.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static mb_ellipsoid ell(double x, double y, double z, double a, double b, double c)
{
    return (mb_ellipsoid){
        .center = {x, y, z}, .rot = {1, 0, 0, 0, 1, 0, 0, 0, 1}, .semi = {a, b, c}};
}

static mb_mesh *make_mesh(int nv, const double *v, int nt, const int *t)
{
    mb_mesh *m = NULL;
    mcs_error err = {0};
    CHECK(mb_mesh_create(&m, nv, v, nt, t, &err) == MCS_OK);
    return m;
}

/* a roof-like ridge along y: face A z = tan(al) x (x < 0), face B z = -tan(al) x (x > 0), the
 * ridge line (0, y, 0) shared; outward normals (-+sin al, 0, cos al) */
static mb_mesh *ridge(double al)
{
    double t = tan(al);
    double v[12] = {0, -1, 0, 0, 1, 0, -1, 0, -t, 1, 0, -t};
    int tri[6] = {0, 1, 2, 1, 0, 3};
    return make_mesh(4, v, 2, tri);
}

/* sphere against the ridge edge: depth R - rho, normal along the perpendicular to the edge,
 * point on the edge; in a face region R - n.c */
static void test_sphere_edge(void)
{
    double al = 30 * M_PI / 180, R = 0.1;
    mb_mesh *m = ridge(al);
    if (!m) return;
    mb_contact c;
    for (int k = -2; k <= 2; k++) {
        double phi = k * 12 * M_PI / 180, rho = R - 0.01 - 0.003 * k;
        mb_ellipsoid s = ell(rho * sin(phi), 0.05 * k, rho * cos(phi), R, R, R);
        CHECK(mb_geom_ellipsoid_mesh_deepest(&s, m, NULL, &c) == 1);
        CHECK(c.feature == MB_FEATURE_EDGE);
        CHECK_NEAR(c.depth, R - rho, 1e-14);
        CHECK_NEAR(c.normal[0], sin(phi), 1e-12);
        CHECK_NEAR(c.normal[1], 0, 1e-12);
        CHECK_NEAR(c.normal[2], cos(phi), 1e-12);
        CHECK_NEAR(c.point_b[0], 0, 1e-12);
        CHECK_NEAR(c.point_b[1], 0.05 * k, 1e-12);
        CHECK_NEAR(c.point_b[2], 0, 1e-12);
    }
    /* beyond the normals' wedge (phi = 40 deg > 30): face B, depth R - n_B.c */
    double phi = 40 * M_PI / 180, rho = 0.09;
    mb_ellipsoid s = ell(rho * sin(phi), 0, rho * cos(phi), R, R, R);
    CHECK(mb_geom_ellipsoid_mesh_deepest(&s, m, NULL, &c) == 1);
    CHECK(c.feature == MB_FEATURE_FACE);
    CHECK_NEAR(c.depth, R - rho * cos(phi - al), 1e-14);
    CHECK_NEAR(c.normal[0], sin(al), 1e-14);
    mb_mesh_destroy(&m);
}

/* ellipsoid with its x axis along the edge, centre above the ridge: depth delta exactly while
 * delta < b^2/c; the normal is vertical and the deepest point is the lower pole */
static void test_ellipsoid_edge_pole(void)
{
    mb_mesh *m = ridge(20 * M_PI / 180);
    if (!m) return;
    double a = 0.15, b = 0.1, cz = 0.07, delta = 0.012; /* b^2/c = 0.14 */
    mb_ellipsoid e = ell(0, 0.1, cz - delta, b, a, cz); /* semi along x, y, z: edge along y */
    mb_contact c;
    CHECK(mb_geom_ellipsoid_mesh_deepest(&e, m, NULL, &c) == 1);
    CHECK(c.feature == MB_FEATURE_EDGE);
    CHECK_NEAR(c.depth, delta, 1e-14);
    CHECK_NEAR(c.normal[2], 1, 1e-12);
    CHECK_NEAR(c.point_a[2], -delta, 1e-13);
    mb_mesh_destroy(&m);
}

/* sphere against the apex of a square pyramid (apex at the origin, slopes 45 deg): depth
 * R - |c|, normal c/|c|, point_b the apex */
static void test_sphere_vertex(void)
{
    double v[15] = {0, 0, 0, -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1};
    int tri[12] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1};
    mb_mesh *m = make_mesh(5, v, 4, tri);
    if (!m) return;
    double R = 0.1, dir[3] = {0.2, -0.15, 1};
    mb_normalize(dir);
    for (int k = 0; k < 4; k++) {
        double rho = R - 0.002 - 0.005 * k;
        mb_ellipsoid s = ell(rho * dir[0], rho * dir[1], rho * dir[2], R, R, R);
        mb_contact c;
        CHECK(mb_geom_ellipsoid_mesh_deepest(&s, m, NULL, &c) == 1);
        CHECK(c.feature == MB_FEATURE_VERTEX);
        CHECK_NEAR(c.depth, R - rho, 1e-14);
        for (int i = 0; i < 3; i++) {
            CHECK_NEAR(c.normal[i], dir[i], 1e-12);
            CHECK_NEAR(c.point_b[i], 0, 1e-15);
        }
    }
    mb_mesh_destroy(&m);
}

static void random_rot(double R[9], unsigned *seed)
{
    double ax[3];
    for (int k = 0; k < 3; k++)
        ax[k] = (double)rand_r(seed) / RAND_MAX - 0.5;
    mb_normalize(ax);
    mb_rot_axis_angle(ax, 3.0 * rand_r(seed) / RAND_MAX, R);
}

/* a rotated ellipsoid (and a sphere) slid across a flat square of two triangles, over the
 * shared diagonal: depth and force constant (the plane answer), no jump at the edge */
static void test_flat_two_triangles(void)
{
    double v[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    int tri[6] = {0, 1, 2, 0, 2, 3};
    mb_mesh *m = make_mesh(4, v, 2, tri);
    if (!m) return;
    unsigned seed = 7;
    for (int shape = 0; shape < 2; shape++) {
        mb_ellipsoid e = shape ? ell(0, 0, 0, 0.12, 0.09, 0.07) : ell(0, 0, 0, 0.1, 0.1, 0.1);
        if (shape) random_rot(e.rot, &seed);
        double up[3] = {0, 0, 1}, low[3];
        mb_ellipsoid_support(&e, up, low);
        double zc = -low[2] - 0.01, worst = 0, prev = -1;
        int tris[2] = {0, 0};
        for (int i = 0; i <= 400; i++) {
            /* the support point's projection crosses the diagonal x = y at i = 200 */
            e.center[0] = 0.3 + 0.4 * i / 400.0 - low[0];
            e.center[1] = 0.5 - low[1];
            e.center[2] = zc;
            mb_contact c;
            CHECK(mb_geom_ellipsoid_mesh_deepest(&e, m, NULL, &c) == 1);
            CHECK(c.feature == MB_FEATURE_FACE);
            CHECK_NEAR(c.normal[2], 1, 1e-15);
            tris[c.tri]++;
            worst = fmax(worst, fabs(c.depth - 0.01));
            if (prev >= 0) CHECK_NEAR(c.depth, prev, 1e-15);
            prev = c.depth;
        }
        CHECK(worst < 1e-15);
        CHECK(tris[0] > 0 && tris[1] > 0);
    }
    mb_mesh_destroy(&m);
}

/* linear contact force k d along the contact normal on the ellipsoid, at the contact point */
static double force_torque(const mb_ellipsoid *e, const mb_mesh *m, double k, double F[3],
                           double T[3], int *feature)
{
    mb_contact c;
    F[0] = F[1] = F[2] = T[0] = T[1] = T[2] = 0;
    *feature = 0;
    if (!mb_geom_ellipsoid_mesh_deepest(e, m, NULL, &c)) return 0;
    double r[3];
    mb_scale(c.normal, k * c.depth, F);
    mb_sub(c.point, e->center, r);
    mb_cross(r, F, T);
    *feature = c.feature;
    return c.depth;
}

/* the rotation vector of R1 R0^T (small) */
static void rot_delta(const double R0[9], const double R1[9], double w[3])
{
    double D[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0;
            for (int l = 0; l < 3; l++)
                s += R1[3 * i + l] * R0[3 * j + l];
            D[3 * i + j] = s;
        }
    double ang = acos(fmax(-1, fmin(1, 0.5 * (D[0] + D[4] + D[8] - 1))));
    double f = ang > 1e-12 ? ang / (2 * sin(ang)) : 0.5;
    w[0] = f * (D[7] - D[5]), w[1] = f * (D[2] - D[6]), w[2] = f * (D[3] - D[1]);
}

/* the work of the contact force and moment around a closed path of poses (translation and
 * rotation) that crosses face, edge and face regions of the ridge: zero for a force that derives
 * from a potential U = k d^2 / 2 (midpoint rule: O(h^2)); relative to the largest U met. The
 * docs state the smallest and largest of the three paths; tolerance 2e-7 (3x the largest) */
static void test_closed_path_work(void)
{
    mb_mesh *m = ridge(25 * M_PI / 180);
    if (!m) return;
    unsigned seed = 3;
    double k = 1e5;
    int nfeat[4] = {0};
    double rel_min = INFINITY, rel_max = 0;
    for (int trial = 0; trial < 3; trial++) {
        double ax[3] = {0.3, 1, 0.2 * trial}, R0[9];
        mb_normalize(ax);
        random_rot(R0, &seed);
        enum { N = 20000 };
        double W = 0, umax = 0;
        mb_ellipsoid prev = ell(0, 0, 0, 0.12, 0.09, 0.07);
        for (int i = 0; i <= N; i++) {
            /* centre on an ellipse in the x-z plane around the ridge, with a wobble in y; the
             * orientation turns back and forth about ax (closed at i = N) */
            double s = 2 * M_PI * i / N;
            mb_ellipsoid e =
                ell(0.12 * cos(s), 0.03 * sin(2 * s), 0.075 + 0.02 * sin(s), 0.12, 0.09, 0.07);
            double Ra[9];
            mb_rot_axis_angle(ax, 0.4 * sin(s), Ra);
            mb_mat_mul(Ra, R0, e.rot);
            if (i > 0) {
                /* midpoint pose */
                mb_ellipsoid mid = e;
                double dw[3], dc[3], Rh[9], ang;
                rot_delta(prev.rot, e.rot, dw);
                mb_sub(e.center, prev.center, dc);
                for (int j = 0; j < 3; j++)
                    mid.center[j] = 0.5 * (e.center[j] + prev.center[j]);
                ang = mb_norm(dw);
                double wa[3] = {1, 0, 0};
                if (ang > 0) mb_scale(dw, 1 / ang, wa);
                mb_rot_axis_angle(wa, 0.5 * ang, Rh);
                mb_mat_mul(Rh, prev.rot, mid.rot);
                double F[3], T[3];
                int f;
                double d = force_torque(&mid, m, k, F, T, &f);
                nfeat[f]++;
                umax = fmax(umax, 0.5 * k * d * d);
                /* work done on the ellipsoid by the contact = -dU */
                W += mb_dot(F, dc) + mb_dot(T, dw);
            }
            prev = e;
        }
        printf("  closed path %d: work %.3e J, max potential %.3e J (relative %.1e)\n", trial, W,
               umax, W / umax);
        CHECK(umax > 1);
        CHECK(fabs(W) < 2e-7 * umax);
        rel_min = fmin(rel_min, fabs(W / umax)), rel_max = fmax(rel_max, fabs(W / umax));
    }
    FIG("contact_geometry.closed_path_work_min", "%.0e", rel_min);
    FIG("contact_geometry.closed_path_work_max", "%.0e", rel_max);
    printf("  features on the paths: face %d, edge %d, vertex %d\n", nfeat[1], nfeat[2], nfeat[3]);
    CHECK(nfeat[MB_FEATURE_FACE] > 0 && nfeat[MB_FEATURE_EDGE] > 0);
    mb_mesh_destroy(&m);
}

/* an elastic sphere (linear spring k, no friction, no damping) thrown at the ridge's edge
 * leaves with the kinetic energy it came with (velocity Verlet: O(dt^2)); the docs state the
 * largest relative change of the three shots, tolerance 2e-7 (3x) */
static void test_sphere_bounce_energy(void)
{
    mb_mesh *m = ridge(30 * M_PI / 180);
    if (!m) return;
    double R = 0.1, k = 2e5, mass = 1, dt = 2e-6, worst = 0;
    for (int shot = 0; shot < 3; shot++) {
        mb_ellipsoid s = ell(-0.25, 0, 0.29 + 0.01 * shot, R, R, R);
        double vel[3] = {4, 0.5, -3.2}, F[3], T[3];
        int f, nedge = 0, touched = 0, free_steps = 0;
        double ke0 = 0.5 * mass * mb_dot(vel, vel), dmax = 0;
        double d = force_torque(&s, m, k, F, T, &f);
        for (int it = 0; it < 200000; it++) {
            for (int j = 0; j < 3; j++) {
                vel[j] += 0.5 * dt * F[j] / mass;
                s.center[j] += dt * vel[j];
            }
            d = force_torque(&s, m, k, F, T, &f);
            for (int j = 0; j < 3; j++)
                vel[j] += 0.5 * dt * F[j] / mass;
            nedge += f == MB_FEATURE_EDGE;
            dmax = fmax(dmax, d);
            if (d > 0) touched = 1, free_steps = 0;
            if (touched && d == 0 && ++free_steps > 2000) break;
        }
        double ke1 = 0.5 * mass * mb_dot(vel, vel);
        printf("  bounce %d: max depth %.4f m, %d edge steps, KE %.6f -> %.6f J (%.1e)\n", shot,
               dmax, nedge, ke0, ke1, (ke1 - ke0) / ke0);
        CHECK(touched && nedge > 0 && d == 0);
        CHECK(fabs(ke1 - ke0) < 2e-7 * ke0);
        worst = fmax(worst, fabs(ke1 - ke0) / ke0);
    }
    FIG("contact_geometry.edge_bounce_ke_err", "%.0e", worst);
    mb_mesh_destroy(&m);
}

/* the deepest-only query (face tests first, edges pruned by their plane depth and an overlap
 * bound) returns the same contact as evaluating every triangle, on a curved panel where the
 * deepest contact is often an edge's (convex and concave folds of 4 cm triangles) */
static void test_deepest_vs_all_curved(void)
{
    enum { N = 30, NV = (N + 1) * (N + 1), NT = 2 * N * N };
    static double v[3 * NV];
    static int t[3 * NT];
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            double *p = v + 3 * (j * (N + 1) + i), x = 1.2 * i / N, y = 1.2 * j / N;
            p[0] = x, p[1] = y, p[2] = 0.04 * sin(9 * x) * cos(7 * y);
        }
    int k = 0;
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            int a = j * (N + 1) + i, b = a + 1, c = a + N + 1, d = c + 1;
            int q[6] = {a, b, d, a, d, c};
            for (int l = 0; l < 6; l++)
                t[k++] = q[l];
        }
    mb_mesh *m = make_mesh(NV, v, NT, t);
    if (!m) return;
    unsigned seed = 11;
    int nfeat[4] = {0};
    for (int trial = 0; trial < 300; trial++) {
        double x = 0.2 + 0.8 * rand_r(&seed) / RAND_MAX, y = 0.2 + 0.8 * rand_r(&seed) / RAND_MAX;
        mb_ellipsoid e =
            ell(x, y, 0, 0.05 + 0.07 * rand_r(&seed) / RAND_MAX,
                0.05 + 0.07 * rand_r(&seed) / RAND_MAX, 0.04 + 0.05 * rand_r(&seed) / RAND_MAX);
        random_rot(e.rot, &seed);
        double up[3] = {0, 0, 1}, low[3];
        mb_ellipsoid_support(&e, up, low);
        e.center[2] = 0.04 * sin(9 * x) * cos(7 * y) - low[2] - 0.03 * rand_r(&seed) / RAND_MAX;
        mb_contact all, deep;
        int n = mb_geom_ellipsoid_mesh(&e, m, NULL, &all, NULL, 0);
        CHECK(mb_geom_ellipsoid_mesh_deepest(&e, m, NULL, &deep) == (n > 0));
        CHECK_NEAR(deep.depth, all.depth, 1e-15);
        if (n == 0) continue;
        nfeat[all.feature]++;
        for (int i = 0; i < 3; i++) {
            CHECK_NEAR(deep.normal[i], all.normal[i], 1e-12);
            CHECK_NEAR(deep.point[i], all.point[i], 1e-12);
        }
    }
    printf("  curved panel, deepest contact: face %d, edge %d, vertex %d\n", nfeat[1], nfeat[2],
           nfeat[3]);
    CHECK(nfeat[MB_FEATURE_EDGE] > 0);
    mb_mesh_destroy(&m);
}

int main(void)
{
    RUN(test_sphere_edge);
    RUN(test_ellipsoid_edge_pole);
    RUN(test_sphere_vertex);
    RUN(test_flat_two_triangles);
    RUN(test_closed_path_work);
    RUN(test_sphere_bounce_energy);
    RUN(test_deepest_vs_all_curved);
    TEST_END();
}

/* bench_mb_geom: nanoseconds per penetration query (prints figures, never fails on time). */
#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_vec.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static mb_ellipsoid ell(double x, double y, double z, double a, double b, double c, double ang)
{
    mb_ellipsoid e = {{x, y, z}, {0}, {a, b, c}};
    double ax[3] = {0.3, 0.5, 0.8};
    mb_normalize(ax);
    mb_rot_axis_angle(ax, ang, e.rot);
    return e;
}

/* a gently curved 50 x 50 grid of 5000 triangles over 2 m x 2 m (a car side panel) */
static mb_mesh *panel(void)
{
    enum { N = 50, NV = (N + 1) * (N + 1), NT = 2 * N * N };
    static double v[3 * NV];
    static int t[3 * NT];
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            double *p = v + 3 * (j * (N + 1) + i), x = 2.0 * i / N, y = 2.0 * j / N;
            p[0] = x, p[1] = y, p[2] = 0.05 * sin(2 * x) * cos(1.5 * y);
        }
    int k = 0;
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            int a = j * (N + 1) + i, b = a + 1, c = a + N + 1, d = c + 1;
            int q[6] = {a, b, d, a, d, c};
            for (int m = 0; m < 6; m++)
                t[k++] = q[m];
        }
    mb_mesh *m = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    if (mb_mesh_create(&m, NV, v, NT, t, &err) != MCS_OK) fprintf(stderr, "%s\n", err.msg);
    return m;
}

/* an ellipsoid over panel point (x, y), its lowest point 15 mm below the surface there */
static mb_ellipsoid into_panel(double x, double y, double ang)
{
    mb_ellipsoid e = ell(x, y, 0, 0.1, 0.15, 0.08, ang);
    double up[3] = {0, 0, 1}, low[3];
    mb_ellipsoid_support(&e, up, low); /* lowest point, centre at z = 0 */
    e.center[2] = 0.05 * sin(2 * x) * cos(1.5 * y) - low[2] - 0.015;
    return e;
}

int main(void)
{
    enum { N = 2000000 };
    double sum = 0, t0;
    mb_contact c;
    mb_plane g = {{0, 0, 0}, {0, 0, 1}};

    t0 = now();
    for (int i = 0; i < N; i++) {
        mb_ellipsoid e = ell(0, 0, 0.09 + 1e-9 * i, 0.1, 0.15, 0.08, 0.3 + 1e-7 * i);
        mb_geom_ellipsoid_plane(&e, &g, &c);
        sum += c.depth;
    }
    printf("ellipsoid-plane:                      %7.1f ns/query\n", 1e9 * (now() - t0) / N);

    int ne = N / 10;
    long iters = 0;
    mb_ellipsoid b = ell(0, 0, 0, 0.12, 0.09, 0.1, 1.1);
    t0 = now();
    for (int i = 0; i < ne; i++) {
        mb_ellipsoid a = ell(0.05, 0.04, 0.17 - 2e-8 * i, 0.1, 0.15, 0.08, 0.3 + 1e-6 * i);
        mb_geom_ellipsoid_ellipsoid(&a, &b, NULL, &c);
        sum += c.depth, iters += c.iterations;
    }
    printf("ellipsoid-ellipsoid, contact, cold:   %7.1f ns/query (%.1f Newton iterations)\n",
           1e9 * (now() - t0) / ne, (double)iters / ne);
    double warm[3] = {0, 0, 1};
    iters = 0;
    t0 = now();
    for (int i = 0; i < ne; i++) {
        mb_ellipsoid a = ell(0.05, 0.04, 0.17 - 2e-8 * i, 0.1, 0.15, 0.08, 0.3 + 1e-6 * i);
        if (mb_geom_ellipsoid_ellipsoid(&a, &b, warm, &c)) mb_copy(c.normal, warm);
        sum += c.depth, iters += c.iterations;
    }
    printf("ellipsoid-ellipsoid, contact, warm:   %7.1f ns/query (%.1f Newton iterations)\n",
           1e9 * (now() - t0) / ne, (double)iters / ne);
    t0 = now();
    for (int i = 0; i < ne; i++) {
        mb_ellipsoid a = ell(0.15, 0.1, 0.2 - 1e-9 * i, 0.1, 0.15, 0.08, 0.3 + 1e-6 * i);
        mb_geom_ellipsoid_ellipsoid(&a, &b, NULL, &c);
        sum += c.depth;
    }
    printf("ellipsoid-ellipsoid, near but apart:  %7.1f ns/query\n", 1e9 * (now() - t0) / ne);

    mb_mesh *m = panel();
    if (!m) return 1;
    int nm = N / 20, nhit = 0;
    static mb_contact all[256];
    t0 = now();
    for (int i = 0; i < nm; i++) {
        double x = 0.2 + 1.6 * (i % 997) / 997.0, y = 0.2 + 1.6 * (i % 991) / 991.0;
        mb_ellipsoid e = into_panel(x, y, 0.3 + 1e-6 * i);
        nhit += mb_geom_ellipsoid_mesh(&e, m, NULL, &c, all, 256);
        sum += c.depth;
    }
    printf("ellipsoid-mesh (5000 tri), 15 mm in:  %7.1f ns/query (%.1f triangles in contact, "
           "%d tree nodes)\n",
           1e9 * (now() - t0) / nm, (double)nhit / nm, mb_mesh_nnode(m));
    t0 = now();
    for (int i = 0; i < nm; i++) {
        double x = 0.2 + 1.6 * (i % 997) / 997.0, y = 0.2 + 1.6 * (i % 991) / 991.0;
        mb_ellipsoid e = into_panel(x, y, 0.3 + 1e-6 * i);
        mb_geom_ellipsoid_mesh_deepest(&e, m, NULL, &c);
        sum += c.depth;
    }
    printf("ellipsoid-mesh (5000 tri), deepest:   %7.1f ns/query\n", 1e9 * (now() - t0) / nm);
    t0 = now();
    for (int i = 0; i < nm; i++) {
        mb_ellipsoid e = ell(1.0, 1.0, 0.4 + 1e-9 * i, 0.1, 0.15, 0.08, 0.3);
        mb_geom_ellipsoid_mesh(&e, m, NULL, &c, NULL, 0);
        sum += c.depth;
    }
    printf("ellipsoid-mesh (5000 tri), apart:     %7.1f ns/query\n", 1e9 * (now() - t0) / nm);
    mb_mesh_destroy(&m);
    mb_wheel w = {{0, 0, 0.29}, {0, 0.99, 0.141}, 0.25, 0.06};
    mb_wheel_contact wc;
    t0 = now();
    for (int i = 0; i < N; i++) {
        w.center[2] = 0.29 + 1e-9 * i;
        mb_geom_wheel_plane(&w, &g, &wc);
        sum += wc.c.depth;
    }
    printf("wheel-plane:                          %7.1f ns/query\n", 1e9 * (now() - t0) / N);
    printf("(checksum %.6g)\n", sum);
    return 0;
}

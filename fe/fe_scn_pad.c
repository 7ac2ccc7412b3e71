/* fe_scn_pad.c: foam pads on a body's ellipsoid and the nodes on a body's surfaces
 * (fe_scn_pad.h) */
#include "fe/fe_scn_pad.h"

#include "fe/fe_builder_impl.h"
#include "fe/fe_scn_node.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ARC_SAMPLES 256 /* points of the numerical arc lengths [-] */

/* an ellipsoid surface in the world at t = 0: x = c + R diag(s) u, |u| = 1 */
typedef struct {
    double c[3]; /* centre [m] */
    double R[9]; /* ellipsoid frame to world, row-major [-] */
    double s[3]; /* semi-axes [m] */
} pad_ellipsoid;

static void mat_mul(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

static void mat_vec(const double A[9], const double v[3], double r[3])
{
    for (int i = 0; i < 3; i++)
        r[i] = A[3 * i] * v[0] + A[3 * i + 1] * v[1] + A[3 * i + 2] * v[2];
}

static void rot_axis(int axis, double a, double R[9])
{
    double c = cos(a), s = sin(a);
    memset(R, 0, 9 * sizeof *R);
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    R[4 * axis] = 1;
    R[3 * i + i] = c, R[3 * i + j] = -s;
    R[3 * j + i] = s, R[3 * j + j] = c;
}

/* roll, pitch, yaw (z-y-x Cardan, as stage 1: R = Rz Ry Rx) or a quaternion w, x, y, z */
static void orientation(const mcs_node *o, double R[9])
{
    static const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double v[4] = {0};
    memcpy(R, I, sizeof I);
    int n = mcs_node_len(o);
    for (int i = 0; i < n && i < 4; i++)
        v[i] = mcs_node_num(mcs_node_at(o, i));
    if (n == 3) {
        double Rx[9], Ry[9], Rz[9], T[9];
        rot_axis(0, v[0], Rx), rot_axis(1, v[1], Ry), rot_axis(2, v[2], Rz);
        mat_mul(Rz, Ry, T);
        mat_mul(T, Rx, R);
    } else if (n == 4) {
        double q = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
        double w = v[0] / q, x = v[1] / q, y = v[2] / q, z = v[3] / q;
        R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
        R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
        R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
    }
}

static const mcs_node *named(const mcs_node *list, const char *name)
{
    for (int i = 0; i < mcs_node_len(list); i++) {
        const char *n = mcs_node_str(fe_scn_get(mcs_node_at(list, i), "name"));
        if (n && name && strcmp(n, name) == 0) return mcs_node_at(list, i);
    }
    return NULL;
}

static int is_ellipsoid(const mcs_node *surf)
{
    const char *t = mcs_node_str(fe_scn_get(surf, "type"));
    return t && strcmp(t, "ellipsoid") == 0;
}

/* the world ellipsoid of surface node `surf` of body node `body` */
static void world_ellipsoid(const mcs_node *body, const mcs_node *surf, pad_ellipsoid *e)
{
    double Rb[9], Rs[9], pos[3], cb[3], t[3];
    orientation(fe_scn_get(body, "orientation"), Rb);
    orientation(fe_scn_get(surf, "orientation"), Rs);
    for (int i = 0; i < 3; i++) {
        pos[i] = mcs_node_num(mcs_node_at(fe_scn_get(body, "position"), i));
        cb[i] = mcs_node_num(mcs_node_at(fe_scn_get(surf, "center"), i));
        e->s[i] = mcs_node_num(mcs_node_at(fe_scn_get(surf, "semi_axes"), i));
    }
    mat_vec(Rb, cb, t);
    for (int i = 0; i < 3; i++)
        e->c[i] = pos[i] + t[i];
    mat_mul(Rb, Rs, e->R);
}

/* point and unit outward normal at (lon, lat), world */
static void pad_point(const pad_ellipsoid *e, double lon, double lat, double x[3], double n[3])
{
    double u[3] = {cos(lat) * cos(lon), cos(lat) * sin(lon), sin(lat)};
    double p[3], g[3], w[3];
    for (int i = 0; i < 3; i++) {
        p[i] = e->s[i] * u[i];
        g[i] = u[i] / e->s[i]; /* gradient of |x / s|^2 / 2 at p */
    }
    mat_vec(e->R, p, w);
    for (int i = 0; i < 3; i++)
        x[i] = e->c[i] + w[i];
    mat_vec(e->R, g, n);
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; i++)
        n[i] /= l;
}

/* the longest arc of the patch along one direction (dir 0: longitude, 1: latitude) [m] */
static double longest_arc(const pad_ellipsoid *e, const double lon[2], const double lat[2], int dir)
{
    double best = 0;
    for (int k = 0; k <= 8; k++) { /* 9 lines across the patch */
        double across =
            dir ? lon[0] + (lon[1] - lon[0]) * k / 8 : lat[0] + (lat[1] - lat[0]) * k / 8;
        double arc = 0, xp[3], n[3];
        for (int i = 0; i <= ARC_SAMPLES; i++) {
            double along = dir ? lat[0] + (lat[1] - lat[0]) * i / ARC_SAMPLES
                               : lon[0] + (lon[1] - lon[0]) * i / ARC_SAMPLES;
            double x[3];
            pad_point(e, dir ? across : along, dir ? along : across, x, n);
            if (i)
                arc += sqrt((x[0] - xp[0]) * (x[0] - xp[0]) + (x[1] - xp[1]) * (x[1] - xp[1]) +
                            (x[2] - xp[2]) * (x[2] - xp[2]));
            memcpy(xp, x, sizeof xp);
        }
        best = fmax(best, arc);
    }
    return best;
}

int fe_scn_pad_is(const mcs_node *mesh)
{
    const char *g = mcs_node_str(fe_scn_get(mesh, "generate"));
    return g && strcmp(g, "foam_pad") == 0;
}

static mcs_status pad_nodes(fe_builder *b, const pad_ellipsoid *e, const double lon[2],
                            const double lat[2], int nu, int nv, int nring, int nl, double t,
                            mcs_error *err)
{
    mcs_status st = MCS_OK;
    for (int k = 0; k <= nl && !st; k++)
        for (int j = 0; j <= nv && !st; j++)
            for (int i = 0; i < nring && !st; i++) {
                double x[3], n[3];
                pad_point(e, lon[0] + (lon[1] - lon[0]) * i / nu,
                          lat[0] + (lat[1] - lat[0]) * j / nv, x, n);
                for (int c = 0; c < 3; c++)
                    x[c] += t * k / nl * n[c];
                st = fe_builder_add_node(b, x, NULL, err);
            }
    return st;
}

mcs_status fe_scn_pad_add(fe_builder *b, const mcs_node *root, const mcs_node *mesh,
                          const fe_part_desc *d, mcs_error *err)
{
    const mcs_node *bodies = fe_scn_get(root, "bodies");
    const mcs_node *body = named(bodies, mcs_node_str(fe_scn_get(mesh, "body")));
    const mcs_node *surf =
        named(fe_scn_get(body, "surfaces"), mcs_node_str(fe_scn_get(mesh, "surface")));
    if (!body || !surf || !is_ellipsoid(surf)) /* mcs_rule_foam_pad checked it */
        return mcs_node_error(fe_scn_get(mesh, "surface"), err, MCS_ERR_KEY,
                              "no ellipsoid surface of that name on the body");
    double lon[2], lat[2];
    mcs_status st = mcs_node_vec(fe_scn_get(mesh, "longitude"), lon, 2, err);
    if (!st) st = mcs_node_vec(fe_scn_get(mesh, "latitude"), lat, 2, err);
    if (st) return st;
    if (fabs(lat[0]) >= M_PI / 2 - 1e-9 || fabs(lat[1]) >= M_PI / 2 - 1e-9)
        return mcs_node_error(fe_scn_get(mesh, "latitude"), err, MCS_ERR_UNSUPPORTED,
                              "a pad reaching a pole (latitude +-90 deg) is not built: its "
                              "elements there would be wedges; stop short of it");
    pad_ellipsoid e;
    world_ellipsoid(body, surf, &e);
    double h = mcs_node_num(fe_scn_get(mesh, "element_size"));
    double t = mcs_node_num(fe_scn_get(mesh, "thickness"));
    int nl = (int)mcs_node_num_or(mesh, "layers", 1);
    int nu = (int)fmax(1, ceil(longest_arc(&e, lon, lat, 0) / h - 1e-9));
    int nv = (int)fmax(1, ceil(longest_arc(&e, lon, lat, 1) / h - 1e-9));
    int ring = lon[1] - lon[0] >= 2 * M_PI - 1e-9; /* a full turn: the last column is the first */
    if (ring && nu < 3) nu = 3;
    int nring = ring ? nu : nu + 1;
    fe_part_desc pd = *d;
    pd.mesh.generate = FE_MESH_NONE;
    int ip = -1;
    mcs_error kerr = {0};
    st = fe_builder_add_part(b, &pd, &ip, &kerr);
    if (st) return mcs_node_error(mesh, err, st, "%s", kerr.msg);
    int base = b->nnode;
    st = pad_nodes(b, &e, lon, lat, nu, nv, nring, nl, t, &kerr);
#define NID(i, j, k) (base + ((i) % nring) + nring * ((j) + (nv + 1) * (k)))
    for (int k = 0; k < nl && !st; k++)
        for (int j = 0; j < nv && !st; j++)
            for (int i = 0; i < nu && !st; i++) {
                /* inner face counter-clockwise seen from outside (east x north = outward) */
                int c[8] = {NID(i, j, k),
                            NID(i + 1, j, k),
                            NID(i + 1, j + 1, k),
                            NID(i, j + 1, k),
                            NID(i, j, k + 1),
                            NID(i + 1, j, k + 1),
                            NID(i + 1, j + 1, k + 1),
                            NID(i, j + 1, k + 1)};
                st = fe_builder_add_elem(b, ip, c, &kerr);
            }
#undef NID
    return st ? mcs_node_error(mesh, err, st, "%s", kerr.msg) : MCS_OK;
}

/* distance of x from the ellipsoid, to first order: (f - 1) / |grad f|, f = |R^T (x - c) / s| */
static double ellipsoid_distance(const pad_ellipsoid *e, const double x[3])
{
    double d[3] = {x[0] - e->c[0], x[1] - e->c[1], x[2] - e->c[2]}, l[3];
    for (int i = 0; i < 3; i++)
        l[i] = e->R[i] * d[0] + e->R[3 + i] * d[1] + e->R[6 + i] * d[2];
    double f2 = 0, g2 = 0;
    for (int i = 0; i < 3; i++) {
        f2 += l[i] * l[i] / (e->s[i] * e->s[i]);
        g2 += l[i] * l[i] / (e->s[i] * e->s[i] * e->s[i] * e->s[i]);
    }
    double f = sqrt(f2);
    if (!(f > 0)) return INFINITY; /* the centre */
    return fabs(f - 1) / (sqrt(g2) / f);
}

int fe_scn_surface_nodes(const fe_builder *b, const mcs_node *root, int part, const char *body,
                         int *idx, int cap)
{
    const mcs_node *bn = named(fe_scn_get(root, "bodies"), body);
    if (!bn || part < 0 || part >= b->npart || b->nnode == 0) return 0;
    unsigned char *mark = malloc((size_t)b->nnode);
    if (!mark) return -1;
    fe_builder_part_nodes(b, part, mark);
    const double *x = b->x_sel ? b->x_sel : b->x;
    const mcs_node *surfs = fe_scn_get(bn, "surfaces");
    int cnt = 0;
    for (int n = 0; n < b->nnode; n++) {
        if (!mark[n]) continue;
        int on = 0;
        for (int s = 0; s < mcs_node_len(surfs) && !on; s++) {
            if (!is_ellipsoid(mcs_node_at(surfs, s))) continue;
            pad_ellipsoid e;
            world_ellipsoid(bn, mcs_node_at(surfs, s), &e);
            on = ellipsoid_distance(&e, x + 3 * n) <= FE_SCN_SURFACE_TOL;
        }
        if (on) {
            if (cnt < cap) idx[cnt] = n;
            cnt++;
        }
    }
    free(mark);
    return cnt;
}

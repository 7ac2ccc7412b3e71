/* fe_scn_pad.c: foam pads on a body's ellipsoid and the nodes on a body's surfaces
 * (fe_scn_pad.h) */
#include "fe/scn/fe_scn_pad.h"

#include "fe/fe_builder_impl.h"
#include "fe/scn/fe_scn_node.h"

#include "core/mcs_obj.h"

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
    return g && (strcmp(g, "foam_pad") == 0 || strcmp(g, "surface_shell") == 0);
}

/* ---- facet surfaces ---- */

/* a facet surface in the world at t = 0: vertices (nvert x 3) [m] and triangles (ntri x 3) */
typedef struct {
    int nvert, ntri;
    double *x;
    int *tri;
} pad_facet;

static void facet_free(pad_facet *f)
{
    free(f->x);
    free(f->tri);
    memset(f, 0, sizeof *f);
}

static int is_facet(const mcs_node *surf)
{
    const char *t = mcs_node_str(fe_scn_get(surf, "type"));
    return t && strcmp(t, "facet") == 0;
}

/* the facet surface `surf` of `body` in the world (inline or its OBJ file: mcs_obj.h) */
static mcs_status world_facet(const mcs_node *body, const mcs_node *surf, pad_facet *f,
                              mcs_error *err)
{
    memset(f, 0, sizeof *f);
    mcs_obj_mesh obj = {0};
    const mcs_node *file = fe_scn_get(surf, "file");
    if (fe_scn_given(surf, "file")) {
        char path[4096];
        if (mcs_obj_path(mcs_node_file(file), mcs_node_str(file), path, sizeof path))
            return mcs_node_error(file, err, MCS_ERR_RANGE, "file name too long");
        mcs_error e2 = {0};
        if (mcs_obj_read(path, &obj, &e2))
            return mcs_node_error(file, err, e2.status, "%s", e2.msg);
    } else {
        const mcs_node *v = fe_scn_get(surf, "vertices"), *t = fe_scn_get(surf, "triangles");
        obj.nvert = mcs_node_len(v), obj.ntri = mcs_node_len(t);
        obj.vert = malloc(sizeof(double) * 3 * (size_t)obj.nvert);
        obj.tri = malloc(sizeof(int) * 3 * (size_t)(obj.ntri ? obj.ntri : 1));
        for (int i = 0; obj.vert && i < obj.nvert; i++)
            for (int k = 0; k < 3; k++)
                obj.vert[3 * i + k] = mcs_node_num(mcs_node_at(mcs_node_at(v, i), k));
        for (int i = 0; obj.tri && i < obj.ntri; i++)
            for (int k = 0; k < 3; k++)
                obj.tri[3 * i + k] = (int)mcs_node_num(mcs_node_at(mcs_node_at(t, i), k));
        if (!obj.vert || !obj.tri) {
            mcs_obj_free(&obj);
            return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
        }
    }
    double Rb[9], pos[3];
    orientation(fe_scn_get(body, "orientation"), Rb);
    for (int i = 0; i < 3; i++)
        pos[i] = mcs_node_num(mcs_node_at(fe_scn_get(body, "position"), i));
    for (int i = 0; i < obj.nvert; i++) {
        double w[3];
        mat_vec(Rb, obj.vert + 3 * i, w);
        for (int k = 0; k < 3; k++)
            obj.vert[3 * i + k] = pos[k] + w[k];
    }
    f->nvert = obj.nvert, f->ntri = obj.ntri, f->x = obj.vert, f->tri = obj.tri;
    return MCS_OK;
}

/* unit vertex normals: the area-weighted mean of the adjacent triangles' (counter-clockwise
 * seen from outside: outward); NULL out of memory */
static double *vertex_normals(const pad_facet *f)
{
    double *n = calloc(3 * (size_t)f->nvert, sizeof *n);
    for (int t = 0; n && t < f->ntri; t++) {
        const int *c = f->tri + 3 * t;
        double a[3], b[3], cr[3];
        for (int k = 0; k < 3; k++) {
            a[k] = f->x[3 * c[1] + k] - f->x[3 * c[0] + k];
            b[k] = f->x[3 * c[2] + k] - f->x[3 * c[0] + k];
        }
        cr[0] = a[1] * b[2] - a[2] * b[1], cr[1] = a[2] * b[0] - a[0] * b[2];
        cr[2] = a[0] * b[1] - a[1] * b[0]; /* twice the area times the unit normal */
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++)
                n[3 * c[i] + k] += cr[k];
    }
    for (int i = 0; n && i < f->nvert; i++) {
        double l =
            sqrt(n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] + n[3 * i + 2] * n[3 * i + 2]);
        for (int k = 0; k < 3 && l > 0; k++)
            n[3 * i + k] /= l;
    }
    return n;
}

/* the facet's layers of nodes (k = 0..nl along the vertex normals to t) and, for solids,
 * prisms as LS-DYNA's degenerate hexahedra n1 n2 n3 n4 n5 n5 n6 n6 (quad a b b' a', ridge c
 * c': fe_tet.c), for shells the triangles (a b c c) */
static mcs_status facet_mesh(fe_builder *b, int ip, const pad_facet *f, int solid, int nl, double t,
                             mcs_error *err)
{
    double *n = vertex_normals(f);
    if (!n) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    int base = b->nnode, layers = solid ? nl : 0;
    mcs_status st = MCS_OK;
    for (int k = 0; k <= layers && !st; k++)
        for (int i = 0; i < f->nvert && !st; i++) {
            double x[3];
            for (int c = 0; c < 3; c++)
                x[c] = f->x[3 * i + c] + (layers ? t * k / layers : 0) * n[3 * i + c];
            st = fe_builder_add_node(b, x, NULL, err);
        }
    free(n);
    for (int e = 0; e < f->ntri && !st; e++) {
        const int *c = f->tri + 3 * e;
        if (!solid) {
            int q[4] = {base + c[0], base + c[1], base + c[2], base + c[2]};
            st = fe_builder_add_elem(b, ip, q, err);
            continue;
        }
        for (int k = 0; k < layers && !st; k++) {
            int lo = base + k * f->nvert, hi = lo + f->nvert;
            /* quad b a a' b' (counter-clockwise seen from c: the ridge c c' on its inside) */
            int q[8] = {lo + c[1], lo + c[0], hi + c[0], hi + c[1],
                        lo + c[2], lo + c[2], hi + c[2], hi + c[2]};
            st = fe_builder_add_elem(b, ip, q, err);
        }
    }
    return st;
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
                for (int c = 0; c < 3 && nl > 0; c++)
                    x[c] += t * k / nl * n[c];
                st = fe_builder_add_node(b, x, NULL, err);
            }
    return st;
}

/* the ellipsoid patch: hexahedra (solid: nl layers to t) or quads (shells on the surface: the
 * hexahedra's inner faces, their first 4 nodes) */
static mcs_status ellipsoid_mesh(fe_builder *b, int ip, const mcs_node *mesh,
                                 const pad_ellipsoid *e, int solid, int nl, double t,
                                 mcs_error *err)
{
    double lon[2], lat[2];
    mcs_status st = mcs_node_vec(fe_scn_get(mesh, "longitude"), lon, 2, err);
    if (!st) st = mcs_node_vec(fe_scn_get(mesh, "latitude"), lat, 2, err);
    if (st) return st;
    double h = mcs_node_num(fe_scn_get(mesh, "element_size"));
    int nu = (int)fmax(1, ceil(longest_arc(e, lon, lat, 0) / h - 1e-9));
    int nv = (int)fmax(1, ceil(longest_arc(e, lon, lat, 1) / h - 1e-9));
    int ring = lon[1] - lon[0] >= 2 * M_PI - 1e-9; /* a full turn: the last column is the first */
    if (ring && nu < 3) nu = 3;
    int nring = ring ? nu : nu + 1, layers = solid ? nl : 0;
    int base = b->nnode;
    st = pad_nodes(b, e, lon, lat, nu, nv, nring, layers, t, err); /* shells: one layer */
#define NID(i, j, k) (base + ((i) % nring) + nring * ((j) + (nv + 1) * (k)))
    for (int k = 0; k < (solid ? layers : 1) && !st; k++)
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
                st = fe_builder_add_elem(b, ip, c, err);
            }
#undef NID
    return st;
}

mcs_status fe_scn_pad_add(fe_builder *b, const mcs_node *root, const mcs_node *mesh,
                          const fe_part_desc *d, mcs_error *err)
{
    const mcs_node *bodies = fe_scn_get(root, "bodies");
    const mcs_node *body = named(bodies, mcs_node_str(fe_scn_get(mesh, "body")));
    const mcs_node *surf =
        named(fe_scn_get(body, "surfaces"), mcs_node_str(fe_scn_get(mesh, "surface")));
    if (!body || !surf || !(is_ellipsoid(surf) || is_facet(surf))) /* mcs_rule_surface_mesh */
        return mcs_node_error(fe_scn_get(mesh, "surface"), err, MCS_ERR_KEY,
                              "no ellipsoid or facet surface of that name on the body");
    int solid = strcmp(mcs_node_str(fe_scn_get(mesh, "generate")), "foam_pad") == 0;
    int st_ok = solid
                    ? d->section.type == FE_SECTION_SOLID
                    : d->section.type == FE_SECTION_SHELL || d->section.type == FE_SECTION_MEMBRANE;
    if (!st_ok)
        return mcs_node_error(fe_scn_get(mesh, "generate"), err, MCS_ERR_KEY,
                              "%s makes %s elements: give section type %s",
                              solid ? "foam_pad" : "surface_shell", solid ? "solid" : "shell",
                              solid ? "solid" : "shell or membrane");
    double t = mcs_node_num_or(mesh, "thickness", 0);
    int nl = (int)mcs_node_num_or(mesh, "layers", 1);
    fe_part_desc pd = *d;
    pd.mesh.generate = FE_MESH_NONE;
    int ip = -1;
    mcs_error kerr = {0};
    mcs_status st = fe_builder_add_part(b, &pd, &ip, &kerr);
    if (!st && is_ellipsoid(surf)) {
        pad_ellipsoid e;
        world_ellipsoid(body, surf, &e);
        st = ellipsoid_mesh(b, ip, mesh, &e, solid, nl, t, &kerr);
    } else if (!st) {
        pad_facet f;
        st = world_facet(body, surf, &f, err);
        if (st) return st;
        st = facet_mesh(b, ip, &f, solid, nl, t, &kerr);
        facet_free(&f);
    }
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

/* squared distance of p from triangle abc (Ericson, Real-Time Collision Detection, 5.1.5) */
static double tri_dist2(const double *p, const double *a, const double *b, const double *c)
{
    double ab[3], ac[3], ap[3], q[3];
    for (int k = 0; k < 3; k++)
        ab[k] = b[k] - a[k], ac[k] = c[k] - a[k], ap[k] = p[k] - a[k];
#define DOT(u, v) ((u)[0] * (v)[0] + (u)[1] * (v)[1] + (u)[2] * (v)[2])
    double d1 = DOT(ab, ap), d2 = DOT(ac, ap), bp[3], cp[3];
    for (int k = 0; k < 3; k++)
        bp[k] = p[k] - b[k], cp[k] = p[k] - c[k];
    double d3 = DOT(ab, bp), d4 = DOT(ac, bp), d5 = DOT(ab, cp), d6 = DOT(ac, cp);
    double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
    if (d1 <= 0 && d2 <= 0)
        memcpy(q, a, sizeof q);
    else if (d3 >= 0 && d4 <= d3)
        memcpy(q, b, sizeof q);
    else if (d6 >= 0 && d5 <= d6)
        memcpy(q, c, sizeof q);
    else if (vc <= 0 && d1 >= 0 && d3 <= 0)
        for (int k = 0; k < 3; k++)
            q[k] = a[k] + d1 / (d1 - d3) * ab[k];
    else if (vb <= 0 && d2 >= 0 && d6 <= 0)
        for (int k = 0; k < 3; k++)
            q[k] = a[k] + d2 / (d2 - d6) * ac[k];
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int k = 0; k < 3; k++)
            q[k] = b[k] + w * (c[k] - b[k]);
    } else {
        double den = 1 / (va + vb + vc), v = vb * den, w = vc * den;
        for (int k = 0; k < 3; k++)
            q[k] = a[k] + ab[k] * v + ac[k] * w;
    }
    double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
    return DOT(d, d);
#undef DOT
}

static int on_facet(const pad_facet *f, const double *x)
{
    for (int t = 0; t < f->ntri; t++) {
        const int *c = f->tri + 3 * t;
        if (tri_dist2(x, f->x + 3 * c[0], f->x + 3 * c[1], f->x + 3 * c[2]) <=
            FE_SCN_SURFACE_TOL * FE_SCN_SURFACE_TOL)
            return 1;
    }
    return 0;
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
    int cnt = 0, nfac = 0;
    pad_facet fac[16]; /* the body's facet surfaces in the world (the first 16) */
    for (int s = 0; s < mcs_node_len(surfs) && nfac < 16; s++) {
        mcs_error e2 = {0};
        if (is_facet(mcs_node_at(surfs, s)) &&
            world_facet(bn, mcs_node_at(surfs, s), &fac[nfac], &e2) == MCS_OK)
            nfac++;
    }
    for (int n = 0; n < b->nnode; n++) {
        if (!mark[n]) continue;
        int on = 0;
        for (int s = 0; s < mcs_node_len(surfs) && !on; s++) {
            if (!is_ellipsoid(mcs_node_at(surfs, s))) continue;
            pad_ellipsoid e;
            world_ellipsoid(bn, mcs_node_at(surfs, s), &e);
            on = ellipsoid_distance(&e, x + 3 * n) <= FE_SCN_SURFACE_TOL;
        }
        for (int s = 0; s < nfac && !on; s++)
            on = on_facet(&fac[s], x + 3 * n);
        if (on) {
            if (cnt < cap) idx[cnt] = n;
            cnt++;
        }
    }
    free(mark);
    for (int s = 0; s < nfac; s++)
        facet_free(&fac[s]);
    return cnt;
}

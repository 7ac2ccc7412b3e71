/* fe_surface_volume: enclosed volume, its gradient and pressure forces (see the header). */
#include "fe/fe_surface_volume.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

static inline void sub3(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

static inline void cross3(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static inline double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* nodes of face i: 3 or 4 */
static inline int face_nn(const int *fn)
{
    return fn[3] < 0 ? 3 : 4;
}

/* (a-o).((b-o) x (c-o)), six times the signed tetrahedron volume */
static double triple_o(const double *a, const double *b, const double *c, const double *o)
{
    double ao[3], bo[3], co[3], bc[3];
    sub3(a, o, ao);
    sub3(b, o, bo);
    sub3(c, o, co);
    cross3(bo, co, bc);
    return dot3(ao, bc);
}

static void centroid4(const double *x, const int *fn, double *c)
{
    for (int d = 0; d < 3; d++)
        c[d] = 0.25 * (x[3 * fn[0] + d] + x[3 * fn[1] + d] + x[3 * fn[2] + d] + x[3 * fn[3] + d]);
}

double fe_surface_volume(int nface, const int *face_node, const double *x)
{
    if (nface <= 0) return 0.0;
    /* a point on the surface as origin keeps the tetrahedra small (less cancellation) */
    const double *o = x + 3 * face_node[0];
    double six_v = 0.0;
    for (int i = 0; i < nface; i++) {
        const int *fn = face_node + 4 * i;
        if (face_nn(fn) == 3) {
            six_v += triple_o(x + 3 * fn[0], x + 3 * fn[1], x + 3 * fn[2], o);
        } else {
            double c[3];
            centroid4(x, fn, c);
            for (int k = 0; k < 4; k++)
                six_v += triple_o(x + 3 * fn[k], x + 3 * fn[(k + 1) & 3], c, o);
        }
    }
    return six_v / 6.0;
}

/* dV/dx of each node of one face (g: 4 x 3; rows beyond the face's nodes untouched) */
static void face_grad(const double *x, const int *fn, double g[4][3])
{
    if (face_nn(fn) == 3) {
        const double *a = x + 3 * fn[0], *b = x + 3 * fn[1], *c = x + 3 * fn[2];
        double ab[3], ac[3], n2[3];
        sub3(b, a, ab);
        sub3(c, a, ac);
        cross3(ab, ac, n2); /* 2 A n */
        for (int k = 0; k < 3; k++)
            for (int d = 0; d < 3; d++)
                g[k][d] = n2[d] / 6.0;
        return;
    }
    double c[3], d13[3], d24[3], s2[3];
    centroid4(x, fn, c);
    sub3(x + 3 * fn[2], x + 3 * fn[0], d13);
    sub3(x + 3 * fn[3], x + 3 * fn[1], d24);
    cross3(d13, d24, s2); /* 2 S */
    for (int k = 0; k < 4; k++) {
        const double *xk = x + 3 * fn[k];
        const double *xm = x + 3 * fn[(k + 3) & 3], *xp = x + 3 * fn[(k + 1) & 3];
        double ck[3], mp[3], t[3];
        sub3(c, xk, ck);
        sub3(xm, xp, mp);
        cross3(ck, mp, t);
        for (int d = 0; d < 3; d++)
            g[k][d] = t[d] / 6.0 + s2[d] / 24.0;
    }
}

double fe_surface_pressure_forces(int nface, const int *face_node, const double *x, double p,
                                  double *f)
{
    for (int i = 0; i < nface; i++) {
        const int *fn = face_node + 4 * i;
        double g[4][3];
        face_grad(x, fn, g);
        for (int k = 0; k < face_nn(fn); k++)
            for (int d = 0; d < 3; d++)
                f[3 * fn[k] + d] += p * g[k][d];
    }
    return fe_surface_volume(nface, face_node, x);
}

double fe_surface_volume_rate(int nface, const int *face_node, const double *x, const double *v)
{
    double rate = 0.0;
    for (int i = 0; i < nface; i++) {
        const int *fn = face_node + 4 * i;
        double g[4][3];
        face_grad(x, fn, g);
        for (int k = 0; k < face_nn(fn); k++)
            rate += dot3(g[k], v + 3 * fn[k]);
    }
    return rate;
}

/* vector area of one face (2 A n / 2) */
static void face_vector_area(const double *x, const int *fn, double *s)
{
    double d1[3], d2[3], n2[3];
    if (face_nn(fn) == 3) {
        sub3(x + 3 * fn[1], x + 3 * fn[0], d1);
        sub3(x + 3 * fn[2], x + 3 * fn[0], d2);
    } else {
        sub3(x + 3 * fn[2], x + 3 * fn[0], d1);
        sub3(x + 3 * fn[3], x + 3 * fn[1], d2);
    }
    cross3(d1, d2, n2);
    for (int d = 0; d < 3; d++)
        s[d] = 0.5 * n2[d];
}

double fe_surface_area(int nface, const int *face_node, const double *x)
{
    double area = 0.0;
    for (int i = 0; i < nface; i++) {
        const int *fn = face_node + 4 * i;
        if (face_nn(fn) == 3) {
            double s[3];
            face_vector_area(x, fn, s);
            area += sqrt(dot3(s, s));
            continue;
        }
        double c[3];
        centroid4(x, fn, c);
        for (int k = 0; k < 4; k++) {
            double d1[3], d2[3], n2[3];
            sub3(x + 3 * fn[k], c, d1);
            sub3(x + 3 * fn[(k + 1) & 3], c, d2);
            cross3(d1, d2, n2);
            area += 0.5 * sqrt(dot3(n2, n2));
        }
    }
    return area;
}

void fe_surface_vector_area(int nface, const int *face_node, const double *x, double out[3])
{
    out[0] = out[1] = out[2] = 0.0;
    for (int i = 0; i < nface; i++) {
        double s[3];
        face_vector_area(x, face_node + 4 * i, s);
        for (int d = 0; d < 3; d++)
            out[d] += s[d];
    }
}

/* ---- validation ------------------------------------------------------------------------ */

/* directed edge a->b as a key; the undirected pair sorts together, direction in the low bit */
typedef struct {
    uint64_t key; /* (min << 32 | max) */
    int dir;      /* +1 a<b, -1 a>b */
    int face;
} edge_rec;

static int edge_cmp(const void *pa, const void *pb)
{
    const edge_rec *a = pa, *b = pb;
    if (a->key != b->key) return a->key < b->key ? -1 : 1;
    if (a->dir != b->dir) return a->dir < b->dir ? -1 : 1;
    return a->face - b->face;
}

static mcs_status check_faces(const char *name, int nnode, int nface, const int *face_node,
                              mcs_error *err)
{
    for (int i = 0; i < nface; i++) {
        const int *fn = face_node + 4 * i;
        int nn = face_nn(fn);
        for (int k = 0; k < nn; k++) {
            if (fn[k] < 0 || fn[k] >= nnode)
                return MCS_ERR(err, MCS_ERR_RANGE,
                               "%s: face %d: node index %d out of range [0, %d)", name, i, fn[k],
                               nnode);
            for (int j = 0; j < k; j++)
                if (fn[j] == fn[k])
                    return MCS_ERR(err, MCS_ERR_RANGE, "%s: face %d: node %d repeated", name, i,
                                   fn[k]);
        }
    }
    return MCS_OK;
}

mcs_status fe_surface_check(const char *name, int nnode, int nface, const int *face_node,
                            mcs_error *err)
{
    if (nface < 4 || nnode < 4)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: a closed surface needs at least 4 faces and 4 nodes (got %d, %d)", name,
                       nface, nnode);
    mcs_status st = check_faces(name, nnode, nface, face_node, err);
    if (st != MCS_OK) return st;
    size_t ne = 0;
    edge_rec *e = malloc(sizeof(*e) * 4 * (size_t)nface);
    if (!e) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: edge list of %d faces", name, nface);
    for (int i = 0; i < nface; i++) {
        const int *fn = face_node + 4 * i;
        int nn = face_nn(fn);
        for (int k = 0; k < nn; k++) {
            int a = fn[k], b = fn[(k + 1) % nn];
            uint64_t lo = (uint64_t)(a < b ? a : b), hi = (uint64_t)(a < b ? b : a);
            e[ne++] = (edge_rec){lo << 32 | hi, a < b ? 1 : -1, i};
        }
    }
    qsort(e, ne, sizeof(*e), edge_cmp);
    for (size_t i = 0; i < ne && st == MCS_OK;) {
        size_t j = i;
        while (j < ne && e[j].key == e[i].key)
            j++;
        int a = (int)(e[i].key >> 32), b = (int)(e[i].key & 0xffffffffu);
        if (j - i != 2)
            st = MCS_ERR(err, MCS_ERR_RANGE,
                         "%s: edge %d-%d (face %d) is shared by %d faces, not 2: the surface is "
                         "not closed",
                         name, a, b, e[i].face, (int)(j - i));
        else if (e[i].dir == e[i + 1].dir)
            st = MCS_ERR(err, MCS_ERR_RANGE,
                         "%s: faces %d and %d run edge %d-%d the same way: inconsistent "
                         "orientation",
                         name, e[i].face, e[i + 1].face, a, b);
        i = j;
    }
    free(e);
    return st;
}

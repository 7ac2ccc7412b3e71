/* mb_geom_facet: ellipsoid against triangles and triangle meshes (docs/contact_geometry.md).
 * The penetration through a triangle is a distance, continuous in the pose across the face,
 * edge and vertex regions: the depth below the plane while the ellipsoid's support point along
 * -n projects inside the triangle (face); otherwise the penetration of the nearest edge's line
 * (the distance of its trace to the boundary of the ellipsoid's shadow along the edge) or, past
 * the edge's ends, of the vertex (its distance to the ellipsoid's surface). The contact normal
 * is the direction of that distance, which is the gradient of the depth with respect to the
 * ellipsoid's translation, so a force along it derives from a potential of the depth. */
#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_geom_internal.h"
#include "stage1_mb/mb_vec.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

/* an ellipsoid expressed in the frame the triangles are given in */
typedef struct {
    double c[3];  /* centre [m] */
    double R[9];  /* principal axes -> frame rotation (columns = axes) */
    double s[3];  /* semi-axes [m] */
    double Q[9];  /* R diag(s^2) R^T [m^2]   */
    double Qi[9]; /* R diag(1/s^2) R^T [1/m^2] */
} ell_frame;

static void ell_frame_make(const double c[3], const double R[9], const double s[3], ell_frame *e)
{
    mb_copy(c, e->c);
    mb_copy(s, e->s);
    for (int i = 0; i < 9; i++)
        e->R[i] = R[i];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double q = 0, qi = 0;
            for (int k = 0; k < 3; k++) {
                double rr = R[3 * i + k] * R[3 * j + k];
                q += rr * s[k] * s[k];
                qi += rr / (s[k] * s[k]);
            }
            e->Q[3 * i + j] = q, e->Qi[3 * i + j] = qi;
        }
}

/* vertex V inside the ellipsoid: the penetration is its distance to the nearest surface point
 * x, the force pushes the ellipsoid along u = -(outward surface normal at x) */
static int vertex_contact(const ell_frame *e, const double V[3], const double n[3], mb_contact *c)
{
    double w[3], Qiw[3], y[3], x[3], u[3];
    mb_sub(V, e->c, w);
    mb_mat_vec(e->Qi, w, Qiw);
    if (!(mb_dot(w, Qiw) < 1)) return 0;
    mb_mat_tvec(e->R, w, y);
    double d = mb_ell_nearest_inside(3, e->s, y, x);
    for (int k = 0; k < 3; k++)
        x[k] = -x[k] / (e->s[k] * e->s[k]);
    mb_mat_vec(e->R, x, u);
    mb_normalize(u);
    /* one-sided: a push into the facet's back is not this facet's contact */
    if (!(d > 0) || !(mb_dot(u, n) > 0)) return 0;
    c->depth = d;
    mb_copy(V, c->point_b);
    mb_axpy(V, -d, u, c->point_a);
    mb_copy(u, c->normal);
    c->feature = MB_FEATURE_VERTEX;
    return 1;
}

/* edge P->R with unit in-plane outward normal m: the penetration of the edge's line, i.e. the
 * distance of the line's trace to the boundary of the ellipsoid's shadow along the edge (an
 * ellipse with Q2 = [n m]^T Q [n m] in the plane spanned by n and m). Its nearest point gives
 * the direction u (in that plane); the ellipsoid's support point along -u lies d u below the
 * line. Beyond the segment's ends the contact is the nearer vertex's. */
static int edge_contact(const ell_frame *e, const double P[3], const double Rv[3],
                        const double n[3], const double m[3], double Qnn, mb_contact *c)
{
    double w[3], Qm[3];
    mb_sub(P, e->c, w);
    mb_mat_vec(e->Q, m, Qm);
    double A = Qnn, B = mb_dot(n, Qm), C = mb_dot(m, Qm);
    double p0 = mb_dot(w, n), p1 = mb_dot(w, m), det = A * C - B * B;
    if (!(C * p0 * p0 - 2 * B * p0 * p1 + A * p1 * p1 < det)) return 0; /* line misses it */
    /* principal axes of the shadow ellipse: eigenvalues l1 >= l2, eigenvector (cs, sn) of l1 */
    double hd = 0.5 * (A - C), r = sqrt(hd * hd + B * B);
    double l1 = 0.5 * (A + C) + r, l2 = det / l1;
    double cs = hd >= 0 ? r + hd : B, sn = hd >= 0 ? B : r - hd, len = sqrt(cs * cs + sn * sn);
    if (len > 0)
        cs /= len, sn /= len;
    else
        cs = 1, sn = 0;
    double a[2] = {sqrt(l1), sqrt(l2)}, y[2] = {cs * p0 + sn * p1, -sn * p0 + cs * p1}, x[2];
    double d = mb_ell_nearest_inside(2, a, y, x);
    double g0 = x[0] / l1, g1 = x[1] / l2; /* outward normal at x, principal */
    double un = -(cs * g0 - sn * g1), um = -(sn * g0 + cs * g1), u[3];
    for (int k = 0; k < 3; k++)
        u[k] = un * n[k] + um * m[k];
    mb_normalize(u);
    if (!(d > 0) || !(mb_dot(u, n) > 0)) return 0;
    /* support point along -u and the point of the line opposite it */
    double Qu[3], ys[3], q[3], qr[3], E[3];
    mb_mat_vec(e->Q, u, Qu);
    mb_axpy(e->c, -1.0 / sqrt(mb_dot(u, Qu)), Qu, ys);
    mb_axpy(ys, d, u, q);
    mb_sub(q, P, qr);
    mb_sub(Rv, P, E);
    double s = mb_dot(qr, E) / mb_dot(E, E);
    if (s < 0) return vertex_contact(e, P, n, c);
    if (s > 1) return vertex_contact(e, Rv, n, c);
    c->depth = d;
    mb_copy(ys, c->point_a);
    mb_axpy(P, s, E, c->point_b);
    mb_copy(u, c->normal);
    c->feature = MB_FEATURE_EDGE;
    return 1;
}

/* one triangle with unit outward normal n and unit outward in-plane edge normals m (row i for
 * the edge v[i] -> v[i+1]), everything in the frame of e. The face test: -1 no contact through
 * the plane, 1 face contact (c filled), 0 the support point projects outside (edge region:
 * *Qnn = n'Qn and out[i] = how far outside edge i it is, for tri_edges). *dp: the plane depth
 * [m], an upper bound of the triangle's contact depth. */
static int tri_face(const ell_frame *e, const double *v[3], const double n[3], const double m[9],
                    mb_contact *c, double *Qnn, double out[3], double *dp)
{
    double rel[3], Qn[3];
    mb_sub(e->c, v[0], rel);
    double sd = mb_dot(n, rel);
    if (!(sd > 0)) return -1; /* centre behind the facet: not this facet's contact */
    mb_mat_vec(e->Q, n, Qn);
    *Qnn = mb_dot(n, Qn);
    double h = sqrt(*Qnn), depth = h - sd;
    *dp = depth;
    if (!(depth > 0)) return -1;
    double p[3], pb[3];
    mb_axpy(e->c, -1.0 / h, Qn, p);
    mb_axpy(p, depth, n, pb);
    for (int i = 0; i < 3; i++) {
        double W[3];
        mb_sub(pb, v[i], W);
        out[i] = mb_dot(m + 3 * i, W);
    }
    if (!(out[0] <= 0 && out[1] <= 0 && out[2] <= 0)) return 0;
    c->depth = depth;
    mb_copy(p, c->point_a);
    mb_copy(pb, c->point_b);
    mb_copy(n, c->normal);
    c->feature = MB_FEATURE_FACE;
    return 1;
}

/* an upper bound of edge P->R's penetration (a minimum over directions u normal to the edge):
 * its value h(u) - u.(c - P) at u = the direction from the edge line to the centre, which is
 * the minimum for a sphere */
static double edge_bound(const ell_frame *e, const double P[3], const double Rv[3])
{
    double w[3], E[3], u[3], Qu[3];
    mb_sub(e->c, P, w);
    mb_sub(Rv, P, E);
    mb_axpy(w, -mb_dot(w, E) / mb_dot(E, E), E, u);
    double l = mb_norm(u);
    if (!(l > 0)) return INFINITY;
    mb_scale(u, 1.0 / l, u);
    mb_mat_vec(e->Q, u, Qu);
    return sqrt(mb_dot(u, Qu)) - l;
}

/* edge region: the nearest feature is an edge that has the support point on its outer side,
 * or one of its vertices; the deepest (nearest) of those edges' contacts. Edges that cannot
 * beat floor [m] (nor the best edge so far) are skipped. */
static int tri_edges(const ell_frame *e, const double *v[3], const double n[3], const double m[9],
                     double Qnn, const double out[3], double floor, mb_contact *c)
{
    mb_contact t;
    int hit = 0;
    for (int i = 0; i < 3; i++) {
        if (out[i] <= 0) continue;
        const double *P = v[i], *Rv = v[(i + 1) % 3];
        if (edge_bound(e, P, Rv) <= fmax(floor, c->depth)) continue;
        mb_contact_clear(&t);
        if (edge_contact(e, P, Rv, n, m + 3 * i, Qnn, &t) && t.depth > c->depth) {
            *c = t;
            hit = 1;
        }
    }
    return hit;
}

/* the contact through one triangle; edge contacts not deeper than floor [m] are not sought */
static int tri_contact(const ell_frame *e, const double *v[3], const double n[3], const double m[9],
                       double floor, mb_contact *c)
{
    double Qnn, out[3], dp;
    int f = tri_face(e, v, n, m, c, &Qnn, out, &dp);
    return f == 0 ? tri_edges(e, v, n, m, Qnn, out, floor, c) : f > 0;
}

/* unit outward in-plane normals of the three edges: (v[i+1] - v[i]) x n, normalised */
static void edge_normals(const double *v[3], const double n[3], double m[9])
{
    for (int i = 0; i < 3; i++) {
        double E[3];
        mb_sub(v[(i + 1) % 3], v[i], E);
        mb_cross(E, n, m + 3 * i);
        mb_normalize(m + 3 * i);
    }
}

static int tri_normal(const double *v0, const double *v1, const double *v2, double n[3])
{
    double e1[3], e2[3];
    mb_sub(v1, v0, e1);
    mb_sub(v2, v0, e2);
    mb_cross(e1, e2, n);
    double l = mb_norm(n), s = mb_norm(e1) + mb_norm(e2);
    if (!(l > 1e-12 * s * s)) return 0;
    mb_scale(n, 1.0 / l, n);
    return 1;
}

static void finish(mb_contact *c)
{
    for (int k = 0; k < 3; k++)
        c->point[k] = 0.5 * (c->point_a[k] + c->point_b[k]);
}

int mb_geom_ellipsoid_triangle(const mb_ellipsoid *a, const double v0[3], const double v1[3],
                               const double v2[3], mb_contact *c)
{
    mb_contact_clear(c);
    double n[3];
    if (!tri_normal(v0, v1, v2, n)) return 0;
    ell_frame e;
    ell_frame_make(a->center, a->rot, a->semi, &e);
    const double *v[3] = {v0, v1, v2};
    double m[9];
    edge_normals(v, n, m);
    if (!tri_contact(&e, v, n, m, 0, c)) {
        mb_contact_clear(c);
        return 0;
    }
    finish(c);
    return 1;
}

/* ---- meshes: AABB tree over triangles, median split on the longest axis -------------------- */

/* a triangle index with its centroid coordinate on the split axis (build only) */
typedef struct {
    double key;
    int tri;
} keyed_tri;

typedef struct {
    double lo[3], hi[3]; /* box [m], mesh frame */
    int first;           /* leaf: first index into tri_order; inner: left child (right = +1) */
    int count;           /* leaf: number of triangles; inner: 0 */
} bvh_node;

struct mb_mesh {
    int nvert, ntri, nnode;
    double *vert;       /* vertex coordinates, mesh frame [m] (nvert x 3) */
    int *tri;           /* vertex indices (ntri x 3) */
    double *tri_n;      /* unit outward normals (ntri x 3) */
    double *tri_m;      /* unit outward in-plane edge normals (ntri x 3 x 3) */
    double *tri_c;      /* centroids, build only [m] (ntri x 3) */
    int *tri_order;     /* triangle indices in leaf order (ntri) */
    bvh_node *node;     /* tree nodes (nnode), root 0 */
    keyed_tri *scratch; /* sort buffer, build only (ntri) */
};

enum { BVH_LEAF = 4, BVH_STACK = 64 };

static const double *mesh_v(const mb_mesh *m, int t, int k)
{
    return m->vert + 3 * m->tri[3 * t + k];
}

static void node_bounds(mb_mesh *m, bvh_node *nd)
{
    for (int k = 0; k < 3; k++)
        nd->lo[k] = DBL_MAX, nd->hi[k] = -DBL_MAX;
    for (int i = nd->first; i < nd->first + nd->count; i++)
        for (int j = 0; j < 3; j++) {
            const double *p = mesh_v(m, m->tri_order[i], j);
            for (int k = 0; k < 3; k++)
                nd->lo[k] = fmin(nd->lo[k], p[k]), nd->hi[k] = fmax(nd->hi[k], p[k]);
        }
}

static int cmp_keyed(const void *x, const void *y)
{
    double a = ((const keyed_tri *)x)->key, b = ((const keyed_tri *)y)->key;
    return (a > b) - (a < b);
}

/* split node i (already bounded) recursively; depth is bounded by log2(ntri) + 1 */
static void bvh_split(mb_mesh *m, int i)
{
    bvh_node *nd = &m->node[i];
    if (nd->count <= BVH_LEAF) return;
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (nd->hi[k] - nd->lo[k] > nd->hi[axis] - nd->lo[axis]) axis = k;
    for (int i = 0; i < nd->count; i++) {
        int t = m->tri_order[nd->first + i];
        m->scratch[i] = (keyed_tri){.key = m->tri_c[3 * t + axis], .tri = t};
    }
    qsort(m->scratch, (size_t)nd->count, sizeof(keyed_tri), cmp_keyed);
    for (int i = 0; i < nd->count; i++)
        m->tri_order[nd->first + i] = m->scratch[i].tri;
    int half = nd->count / 2, first = nd->first, count = nd->count;
    int l = m->nnode;
    m->nnode += 2;
    m->node[l] = (bvh_node){.first = first, .count = half};
    m->node[l + 1] = (bvh_node){.first = first + half, .count = count - half};
    m->node[i].first = l, m->node[i].count = 0;
    node_bounds(m, &m->node[l]);
    node_bounds(m, &m->node[l + 1]);
    bvh_split(m, l);
    bvh_split(m, l + 1);
}

mcs_status mb_mesh_create(mb_mesh **out, int nvert, const double *vert, int ntri, const int *tri,
                          mcs_error *err)
{
    *out = NULL;
    if (nvert < 3 || ntri < 1 || !vert || !tri)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "facet mesh: needs >= 3 vertices and >= 1 triangle "
                       "(got %d, %d)",
                       nvert, ntri);
    for (int i = 0; i < 3 * nvert; i++)
        if (!isfinite(vert[i]))
            return MCS_ERR(err, MCS_ERR_RANGE, "facet mesh: vertex %d is not finite", i / 3);
    for (int t = 0; t < ntri; t++)
        for (int k = 0; k < 3; k++)
            if (tri[3 * t + k] < 0 || tri[3 * t + k] >= nvert)
                return MCS_ERR(err, MCS_ERR_RANGE,
                               "facet mesh: triangle %d uses vertex %d (mesh has %d)", t,
                               tri[3 * t + k], nvert);
    mb_mesh *m = calloc(1, sizeof *m);
    if (!m) return MCS_ERR(err, MCS_ERR_NOMEM, "facet mesh: out of memory");
    m->nvert = nvert, m->ntri = ntri;
    m->vert = malloc(sizeof(double) * 3 * (size_t)nvert);
    m->tri = malloc(sizeof(int) * 3 * (size_t)ntri);
    m->tri_n = malloc(sizeof(double) * 3 * (size_t)ntri);
    m->tri_m = malloc(sizeof(double) * 9 * (size_t)ntri);
    m->tri_c = malloc(sizeof(double) * 3 * (size_t)ntri);
    m->tri_order = malloc(sizeof(int) * (size_t)ntri);
    m->node = malloc(sizeof(bvh_node) * (2 * (size_t)ntri));
    m->scratch = malloc(sizeof(keyed_tri) * (size_t)ntri);
    if (!m->vert || !m->tri || !m->tri_n || !m->tri_m || !m->tri_c || !m->tri_order || !m->node ||
        !m->scratch) {
        mb_mesh_destroy(&m);
        return MCS_ERR(err, MCS_ERR_NOMEM, "facet mesh: out of memory (%d triangles)", ntri);
    }
    for (int i = 0; i < 3 * nvert; i++)
        m->vert[i] = vert[i];
    for (int i = 0; i < 3 * ntri; i++)
        m->tri[i] = tri[i];
    for (int t = 0; t < ntri; t++) {
        const double *a = mesh_v(m, t, 0), *b = mesh_v(m, t, 1), *c = mesh_v(m, t, 2);
        if (!tri_normal(a, b, c, m->tri_n + 3 * t)) {
            mb_mesh_destroy(&m);
            return MCS_ERR(err, MCS_ERR_RANGE, "facet mesh: triangle %d has zero area", t);
        }
        const double *v[3] = {a, b, c};
        edge_normals(v, m->tri_n + 3 * t, m->tri_m + 9 * t);
        for (int k = 0; k < 3; k++)
            m->tri_c[3 * t + k] = (a[k] + b[k] + c[k]) / 3.0;
        m->tri_order[t] = t;
    }
    m->nnode = 1;
    m->node[0] = (bvh_node){.first = 0, .count = ntri};
    node_bounds(m, &m->node[0]);
    bvh_split(m, 0);
    free(m->scratch);
    m->scratch = NULL;
    *out = m;
    return MCS_OK;
}

void mb_mesh_destroy(mb_mesh **pm)
{
    if (!pm || !*pm) return;
    mb_mesh *m = *pm;
    free(m->vert), free(m->tri), free(m->tri_n), free(m->tri_m), free(m->tri_c), free(m->tri_order),
        free(m->node);
    free(m->scratch);
    free(m);
    *pm = NULL;
}

const double *mb_mesh_vert(const mb_mesh *m, int *nvert)
{
    *nvert = m->nvert;
    return m->vert;
}

const int *mb_mesh_tri(const mb_mesh *m)
{
    return m->tri;
}

int mb_mesh_ntri(const mb_mesh *m)
{
    return m->ntri;
}
int mb_mesh_nnode(const mb_mesh *m)
{
    return m->nnode;
}

/* mesh-frame contact -> world */
static void to_world(const mb_pose *pose, mb_contact *c)
{
    if (!pose) return;
    double *v[4] = {c->point, c->point_a, c->point_b, NULL};
    for (int i = 0; v[i]; i++) {
        double w[3];
        mb_mat_vec(pose->rot, v[i], w);
        mb_add(w, pose->pos, v[i]);
    }
    double w[3];
    mb_mat_vec(pose->rot, c->normal, w);
    mb_copy(w, c->normal);
}

/* the ellipsoid in the mesh frame (c' = Rm^T (c - pos), R' = Rm^T Re) and its exact
 * axis-aligned box there (half extent sqrt(Q_kk)) */
static void ell_in_mesh(const mb_ellipsoid *a, const mb_pose *pose, ell_frame *e, double lo[3],
                        double hi[3])
{
    if (pose) {
        double rel[3], cl[3], Rl[9];
        mb_sub(a->center, pose->pos, rel);
        mb_mat_tvec(pose->rot, rel, cl);
        mb_mat_tmul(pose->rot, a->rot, Rl);
        ell_frame_make(cl, Rl, a->semi, e);
    } else {
        ell_frame_make(a->center, a->rot, a->semi, e);
    }
    for (int k = 0; k < 3; k++) {
        double h = sqrt(e->Q[4 * k]);
        lo[k] = e->c[k] - h, hi[k] = e->c[k] + h;
    }
}

static int box_apart(const bvh_node *nd, const double lo[3], const double hi[3])
{
    return nd->lo[0] > hi[0] || nd->hi[0] < lo[0] || nd->lo[1] > hi[1] || nd->hi[1] < lo[1] ||
           nd->lo[2] > hi[2] || nd->hi[2] < lo[2];
}

/* the next leaf of the tree overlapping the box; *sp/stack carry the walk (start: sp = 1,
 * stack[0] = 0); NULL when done */
static const bvh_node *next_leaf(const mb_mesh *m, int *stack, int *sp, const double lo[3],
                                 const double hi[3])
{
    while (*sp > 0) {
        const bvh_node *nd = &m->node[stack[--*sp]];
        if (box_apart(nd, lo, hi)) continue;
        if (nd->count > 0) return nd;
        stack[(*sp)++] = nd->first;
        stack[(*sp)++] = nd->first + 1;
    }
    return NULL;
}

int mb_geom_ellipsoid_mesh(const mb_ellipsoid *a, const mb_mesh *m, const mb_pose *pose,
                           mb_contact *deepest, mb_contact *all, int max_all)
{
    mb_contact_clear(deepest);
    ell_frame e;
    double lo[3], hi[3];
    ell_in_mesh(a, pose, &e, lo, hi);
    int stack[BVH_STACK], sp = 1, nhit = 0;
    stack[0] = 0;
    const bvh_node *nd;
    while ((nd = next_leaf(m, stack, &sp, lo, hi))) {
        for (int i = nd->first; i < nd->first + nd->count; i++) {
            int t = m->tri_order[i];
            const double *v[3] = {mesh_v(m, t, 0), mesh_v(m, t, 1), mesh_v(m, t, 2)};
            mb_contact c;
            mb_contact_clear(&c);
            if (!tri_contact(&e, v, m->tri_n + 3 * t, m->tri_m + 9 * t, 0, &c)) continue;
            c.tri = t;
            finish(&c);
            to_world(pose, &c);
            if (all && nhit < max_all) all[nhit] = c;
            if (c.depth > deepest->depth) *deepest = c;
            nhit++;
        }
    }
    return nhit;
}

/* deepest only: a triangle's depth never exceeds its plane depth h(n) - n.(c - v0) (the edge and
 * vertex penetrations are minima over directions that include n), so a triangle's edges are
 * evaluated only while its plane depth beats the best contact found so far */
int mb_geom_ellipsoid_mesh_deepest(const mb_ellipsoid *a, const mb_mesh *m, const mb_pose *pose,
                                   mb_contact *deepest)
{
    return mb_geom_ellipsoid_mesh_deepest_capped(a, m, pose, INFINITY, deepest);
}

int mb_geom_ellipsoid_mesh_deepest_capped(const mb_ellipsoid *a, const mb_mesh *m,
                                          const mb_pose *pose, double max_depth,
                                          mb_contact *deepest)
{
    return mb_geom_ellipsoid_mesh_deepest_latched(a, m, pose, max_depth, NULL, deepest);
}

static int latched(const mb_mesh_latch *l, int t)
{
    for (int i = 0; l && i < l->n; i++)
        if (l->tri[i] == t) return 1;
    return 0;
}

/* a contact over the cap: skipped now, and latched while there is room */
static void latch_add(mb_mesh_latch *l, int t)
{
    if (l && l->n < MB_LATCH_MAX && !latched(l, t)) l->tri[l->n++] = t;
}

/* release the latched triangles that are out of contact (their whole contact, uncapped) */
static void latch_release(const ell_frame *e, const mb_mesh *m, mb_mesh_latch *l)
{
    int k = 0;
    for (int i = 0; l && i < l->n; i++) {
        int t = l->tri[i];
        const double *v[3] = {mesh_v(m, t, 0), mesh_v(m, t, 1), mesh_v(m, t, 2)};
        mb_contact c;
        mb_contact_clear(&c);
        if (tri_contact(e, v, m->tri_n + 3 * t, m->tri_m + 9 * t, 0, &c)) l->tri[k++] = t;
    }
    if (l) l->n = k;
}

int mb_geom_ellipsoid_mesh_deepest_latched(const mb_ellipsoid *a, const mb_mesh *m,
                                           const mb_pose *pose, double max_depth,
                                           mb_mesh_latch *latch, mb_contact *deepest)
{
    enum { NCAND = 512 };
    mb_contact_clear(deepest);
    ell_frame e;
    double lo[3], hi[3], dp[NCAND], qnn[NCAND], out[NCAND][3];
    int cand[NCAND], nc = 0;
    ell_in_mesh(a, pose, &e, lo, hi);
    latch_release(&e, m, latch);
    int stack[BVH_STACK], sp = 1;
    stack[0] = 0;
    const bvh_node *nd;
    /* face contacts first (cheap): the deepest one bounds the rest from below; the triangles
     * in their edge regions are kept with their plane depth (an upper bound of their contact) */
    while ((nd = next_leaf(m, stack, &sp, lo, hi))) {
        for (int i = nd->first; i < nd->first + nd->count; i++) {
            int t = m->tri_order[i];
            if (latched(latch, t)) continue;
            const double *v[3] = {mesh_v(m, t, 0), mesh_v(m, t, 1), mesh_v(m, t, 2)};
            mb_contact c;
            mb_contact_clear(&c);
            double d;
            int f = tri_face(&e, v, m->tri_n + 3 * t, m->tri_m + 9 * t, &c, qnn + nc, out[nc], &d);
            if (f == 0) {
                if (nc == NCAND) /* more candidates than the buffer: evaluate them all */
                    return mb_geom_ellipsoid_mesh(a, m, pose, deepest, NULL, 0) > 0;
                cand[nc] = t, dp[nc++] = d;
            }
            if (f > 0 && c.depth > max_depth) latch_add(latch, t);
            if (f <= 0 || !(c.depth > deepest->depth) || c.depth > max_depth) continue;
            c.tri = t;
            finish(&c);
            *deepest = c;
        }
    }
    /* then the edge regions whose plane depth can still beat the best by more than rounding
     * (coplanar neighbours of the face triangle cannot) */
    for (int i = 0; i < nc; i++) {
        if (dp[i] <= deepest->depth * (1 + 1e-12)) continue;
        int t = cand[i];
        const double *v[3] = {mesh_v(m, t, 0), mesh_v(m, t, 1), mesh_v(m, t, 2)};
        mb_contact c;
        mb_contact_clear(&c);
        if (!tri_edges(&e, v, m->tri_n + 3 * t, m->tri_m + 9 * t, qnn[i], out[i], deepest->depth,
                       &c) ||
            !(c.depth > deepest->depth))
            continue;
        if (c.depth > max_depth) {
            latch_add(latch, t);
            continue;
        }
        c.tri = t;
        finish(&c);
        *deepest = c;
    }
    if (deepest->depth > 0) to_world(pose, deepest);
    return deepest->depth > 0;
}

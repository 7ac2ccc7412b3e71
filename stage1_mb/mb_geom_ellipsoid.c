/* mb_geom_ellipsoid: ellipsoid-plane, sphere-sphere, ellipsoid-ellipsoid and wheel-plane
 * penetration (docs/contact_geometry.md). */
#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_geom_internal.h"
#include "stage1_mb/mb_vec.h"

#include <float.h>
#include <stddef.h>
#include <math.h>

void mb_contact_clear(mb_contact *c)
{
    *c = (mb_contact){.depth = 0, .tri = -1, .feature = MB_FEATURE_NONE};
}

/* Q = R diag(s^2) R^T (symmetric, world): the support extent along unit u is sqrt(u'Qu) */
void mb_ellipsoid_q(const mb_ellipsoid *e, double Q[9])
{
    const double *R = e->rot;
    double s2[3] = {e->semi[0] * e->semi[0], e->semi[1] * e->semi[1], e->semi[2] * e->semi[2]};
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            double v = R[3 * i] * s2[0] * R[3 * j] + R[3 * i + 1] * s2[1] * R[3 * j + 1] +
                       R[3 * i + 2] * s2[2] * R[3 * j + 2];
            Q[3 * i + j] = Q[3 * j + i] = v;
        }
}

void mb_ellipsoid_support(const mb_ellipsoid *e, const double dir[3], double out[3])
{
    double Q[9], Qn[3];
    mb_ellipsoid_q(e, Q);
    mb_mat_vec(Q, dir, Qn);
    double h = sqrt(mb_dot(dir, Qn));
    mb_axpy(e->center, -1.0 / h, Qn, out);
}

static void finish_midpoint(mb_contact *c)
{
    for (int k = 0; k < 3; k++)
        c->point[k] = 0.5 * (c->point_a[k] + c->point_b[k]);
}

/* support function along -n: p = c - Q n / sqrt(n'Qn); depth = sqrt(n'Qn) - n.(c - p0) */
int mb_geom_ellipsoid_plane(const mb_ellipsoid *a, const mb_plane *b, mb_contact *c)
{
    mb_contact_clear(c);
    double Q[9], Qn[3], rel[3];
    mb_ellipsoid_q(a, Q);
    mb_mat_vec(Q, b->normal, Qn);
    double h = sqrt(mb_dot(b->normal, Qn));
    mb_sub(a->center, b->point, rel);
    double depth = h - mb_dot(b->normal, rel);
    if (!(depth > 0)) return 0;
    c->depth = depth;
    mb_copy(b->normal, c->normal);
    mb_axpy(a->center, -1.0 / h, Qn, c->point_a);
    mb_axpy(c->point_a, depth, b->normal, c->point_b);
    finish_midpoint(c);
    return 1;
}

int mb_geom_sphere_sphere(const double ca[3], double ra, const double cb[3], double rb,
                          mb_contact *c)
{
    mb_contact_clear(c);
    double d[3];
    mb_sub(ca, cb, d);
    double dist = mb_norm(d);
    double depth = ra + rb - dist;
    if (!(depth > 0)) return 0;
    c->depth = depth;
    if (dist > 0) {
        mb_scale(d, 1.0 / dist, c->normal);
    } else {
        c->normal[0] = 0, c->normal[1] = 0, c->normal[2] = 1; /* concentric: any direction */
        c->status = MB_GEOM_DEGENERATE;
    }
    mb_axpy(ca, -ra, c->normal, c->point_a);
    mb_axpy(cb, rb, c->normal, c->point_b);
    finish_midpoint(c);
    return 1;
}

/* ---- ellipsoid-ellipsoid: maximise g(n) = n.d - hA(n) - hB(n) over unit n ------------------
 * d = cA - cB, h(n) = sqrt(n'Qn). max g is the signed distance (separating-axis form of the
 * distance between convex sets; its negative is the minimum translational penetration). At the
 * maximum the support points have antiparallel normals +-n and lie on a common normal. */

typedef struct {
    double QA[9], QB[9], d[3];
    double off; /* A's support offset (a ball of this radius added to A: the tyre tube) [m] */
} ee_pair;

/* g, its R^3 gradient and Hessian at unit n */
static double ee_eval(const ee_pair *p, const double n[3], double grad[3], double H[9])
{
    double qa[3], qb[3];
    mb_mat_vec(p->QA, n, qa);
    mb_mat_vec(p->QB, n, qb);
    double ha = sqrt(mb_dot(n, qa)), hb = sqrt(mb_dot(n, qb));
    double g = mb_dot(n, p->d) - ha - hb - p->off;
    if (grad)
        for (int k = 0; k < 3; k++)
            grad[k] = p->d[k] - qa[k] / ha - qb[k] / hb;
    if (H) {
        double ia = 1.0 / ha, ib = 1.0 / hb, ia3 = ia * ia * ia, ib3 = ib * ib * ib;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                H[3 * i + j] = -(p->QA[3 * i + j] * ia - qa[i] * qa[j] * ia3) -
                               (p->QB[3 * i + j] * ib - qb[i] * qb[j] * ib3);
    }
    return g;
}

/* an orthonormal pair spanning the plane normal to unit n */
static void tangent_basis(const double n[3], double t1[3], double t2[3])
{
    double ref[3] = {1, 0, 0};
    if (fabs(n[0]) > 0.6) ref[0] = 0, ref[1] = 1;
    mb_cross(n, ref, t1);
    mb_normalize(t1);
    mb_cross(n, t1, t2);
}

enum { EE_MAX_ITER = 60 };

/* damped Newton ascent on the sphere from n (in/out); returns g at the end, *iters, *conv.
 * Stops early (returns g > 0) once the pair is found apart. */
static double ee_ascend(const ee_pair *p, double n[3], double tol, int *iters, int *conv)
{
    double grad[3], H[9], t1[3], t2[3], Ht[3];
    double g = ee_eval(p, n, grad, H);
    *conv = 0;
    int it;
    for (it = 0; it < EE_MAX_ITER && g <= 0; it++) {
        tangent_basis(n, t1, t2);
        double g1 = mb_dot(t1, grad), g2 = mb_dot(t2, grad);
        if (sqrt(g1 * g1 + g2 * g2) <= tol) {
            *conv = 1;
            break;
        }
        /* Riemannian Hessian on the sphere: P H P - (n.grad) P, and n.grad = g (Euler) */
        mb_mat_vec(H, t1, Ht);
        double h11 = mb_dot(t1, Ht) - g, h12 = mb_dot(t2, Ht);
        mb_mat_vec(H, t2, Ht);
        double h22 = mb_dot(t2, Ht) - g;
        /* shift to negative definite (ascent direction) when it is not */
        double tr = 0.5 * (h11 + h22), disc = sqrt(0.25 * (h11 - h22) * (h11 - h22) + h12 * h12);
        double lmax = tr + disc, scale = fabs(tr) + disc + tol;
        double mu = lmax < -1e-3 * scale ? 0 : lmax + 0.1 * scale;
        h11 -= mu, h22 -= mu;
        double det = h11 * h22 - h12 * h12;
        double v1 = -(h22 * g1 - h12 * g2) / det, v2 = -(-h12 * g1 + h11 * g2) / det;
        double vl = sqrt(v1 * v1 + v2 * v2);
        if (vl > 0.5) v1 *= 0.5 / vl, v2 *= 0.5 / vl; /* at most ~0.5 rad per step */
        /* backtrack until g does not decrease */
        double nn[3], gn = -DBL_MAX;
        for (int ls = 0; ls < 40; ls++) {
            for (int k = 0; k < 3; k++)
                nn[k] = n[k] + v1 * t1[k] + v2 * t2[k];
            mb_normalize(nn);
            gn = ee_eval(p, nn, NULL, NULL);
            if (gn >= g - 1e-15 * (fabs(g) + scale)) break;
            v1 *= 0.5, v2 *= 0.5;
        }
        if (!(gn >= g - 1e-15 * (fabs(g) + scale))) break; /* no progress possible */
        mb_copy(nn, n);
        g = ee_eval(p, n, grad, H);
    }
    if (g > 0) *conv = 1; /* a separating direction is a final answer */
    *iters += it;
    return g;
}

/* A (grown by a ball of radius off) against B */
static int ee_solve(const mb_ellipsoid *a, double off, const mb_ellipsoid *b,
                    const double *warm_normal, mb_contact *c)
{
    mb_contact_clear(c);
    ee_pair p = {.off = off};
    mb_sub(a->center, b->center, p.d);
    double dist = mb_norm(p.d);
    double ra = fmax(a->semi[0], fmax(a->semi[1], a->semi[2])) + off;
    double rb = fmax(b->semi[0], fmax(b->semi[1], b->semi[2]));
    if (dist >= ra + rb) { /* bounding spheres apart: the line of centres separates */
        if (dist > 0) mb_scale(p.d, 1.0 / dist, c->normal);
        return 0;
    }
    mb_ellipsoid_q(a, p.QA);
    mb_ellipsoid_q(b, p.QB);
    double tol = 1e-13 * (dist + ra + rb);

    /* starts: last normal, line of centres; deep cases add both bodies' principal axes */
    double starts[8][3];
    int ns = 0;
    if (warm_normal && isfinite(mb_norm(warm_normal)) && mb_norm(warm_normal) > 0) {
        mb_copy(warm_normal, starts[ns]);
        mb_normalize(starts[ns++]);
    }
    if (dist > 0) {
        mb_scale(p.d, 1.0 / dist, starts[ns++]);
    } else {
        starts[ns][0] = 0, starts[ns][1] = 0, starts[ns][2] = 1, ns++;
        c->status = MB_GEOM_DEGENERATE;
    }
    double best_n[3] = {0, 0, 1}, best_g = -DBL_MAX;
    int best_conv = 0, iters = 0, warm_conv = 0;
    for (int pass = 0; pass < 2; pass++) {
        for (int s = 0; s < ns; s++) {
            double n[3];
            int conv;
            mb_copy(starts[s], n);
            double g = ee_ascend(&p, n, tol, &iters, &conv);
            if (g > best_g) best_g = g, best_conv = conv, mb_copy(n, best_n);
            if (g > 0) { /* a separating axis: apart (kept as the next warm start) */
                mb_copy(n, c->normal);
                return 0;
            }
            if (pass == 0 && s == 0 && warm_normal && conv) { /* warm start converged: the */
                warm_conv = 1; /* maximum followed from the last step; nothing else is tried */
                break;
            }
        }
        double smin = fmin(fmin(fmin(a->semi[0], a->semi[1]), a->semi[2]) + off,
                           fmin(fmin(b->semi[0], b->semi[1]), b->semi[2]));
        if (pass == 1 || warm_conv || -best_g < 0.25 * smin) break;
        /* deep penetration: other local maxima may be shallower; try principal axes */
        ns = 0;
        for (int k = 0; k < 3; k++) {
            double ax[3] = {a->rot[k], a->rot[3 + k], a->rot[6 + k]};
            double bx[3] = {b->rot[k], b->rot[3 + k], b->rot[6 + k]};
            mb_scale(ax, mb_dot(ax, p.d) < 0 ? -1 : 1, starts[ns++]);
            mb_scale(bx, mb_dot(bx, p.d) < 0 ? -1 : 1, starts[ns++]);
        }
    }
    c->depth = -best_g;
    c->iterations = iters;
    if (!best_conv) c->status = MB_GEOM_NOT_CONVERGED;
    mb_copy(best_n, c->normal);
    double q[3];
    mb_mat_vec(p.QA, best_n, q);
    mb_axpy(a->center, -1.0 / sqrt(mb_dot(best_n, q)), q, c->point_a);
    mb_axpy(c->point_a, -off, best_n, c->point_a);
    mb_mat_vec(p.QB, best_n, q);
    mb_axpy(b->center, 1.0 / sqrt(mb_dot(best_n, q)), q, c->point_b);
    finish_midpoint(c);
    return 1;
}

int mb_geom_ellipsoid_ellipsoid(const mb_ellipsoid *a, const mb_ellipsoid *b,
                                const double *warm_normal, mb_contact *c)
{
    return ee_solve(a, 0.0, b, warm_normal, c);
}

/* ---- wheel-ellipsoid: the filled wheel (convex hull of the tyre torus) is the flat disc of
 * radius R (crown circle) grown by the tube ball r; its support function is R |P n| + r with
 * P = I - a a'. The disc is the ellipsoid (R, R, eps) with eps = MB_WHEEL_EPS R (its support
 * exceeds the disc's by at most eps: only for normals along the axis), so the ellipsoid-
 * ellipsoid maximisation of g(n) = n.(cW - cE) - hW(n) - hE(n) applies with hW offset by r. */
void mb_wheel_disc(const mb_wheel *w, mb_ellipsoid *disc)
{
    double t1[3], t2[3];
    tangent_basis(w->axis, t1, t2);
    mb_copy(w->center, disc->center);
    for (int i = 0; i < 3; i++) {
        disc->rot[3 * i] = t1[i], disc->rot[3 * i + 1] = t2[i], disc->rot[3 * i + 2] = w->axis[i];
    }
    disc->semi[0] = disc->semi[1] = w->radius;
    disc->semi[2] = MB_WHEEL_EPS * w->radius;
}

int mb_geom_wheel_ellipsoid(const mb_wheel *w, const mb_ellipsoid *e, const double *warm_normal,
                            mb_contact *c)
{
    mb_ellipsoid disc;
    mb_wheel_disc(w, &disc);
    return ee_solve(&disc, w->tube, e, warm_normal, c);
}

/* ---- wheel-plane: lowest point of the crown circle, then the tube (torus = circle + ball) --
 * u = -(n - (n.a) a)/|n - (n.a) a| is the in-plane direction nearest to -n; the lowest crown
 * point is c + R u and its height is n.(c - p0) - R cos(camber); depth = tube - that height. */
int mb_geom_wheel_plane(const mb_wheel *w, const mb_plane *b, mb_wheel_contact *wc)
{
    mb_contact *c = &wc->c;
    mb_contact_clear(c);
    const double *n = b->normal, *ax = w->axis;
    double na = mb_dot(n, ax);
    wc->camber = asin(fmax(-1.0, fmin(1.0, na)));
    double u[3], rel[3];
    mb_axpy(n, -na, ax, u);
    double ul = mb_norm(u); /* = cos(camber) */
    mb_cross(ax, n, wc->forward);
    if (mb_normalize(wc->forward) == 0) {
        /* wheel lying flat: any rim point is lowest; report below the centre */
        double t1[3], t2[3];
        tangent_basis(n, t1, t2);
        mb_copy(t1, wc->forward);
        u[0] = u[1] = u[2] = 0;
        c->status = MB_GEOM_DEGENERATE;
    } else {
        mb_scale(u, -1.0 / ul, u);
    }
    mb_cross(n, wc->forward, wc->lateral);
    mb_sub(w->center, b->point, rel);
    double low = mb_dot(n, rel) - w->radius * ul - w->tube;
    if (!(low < 0)) return 0;
    c->depth = -low;
    mb_copy(n, c->normal);
    double crown[3];
    mb_axpy(w->center, w->radius, u, crown);
    mb_axpy(crown, -w->tube, n, c->point_a);
    mb_axpy(c->point_a, c->depth, n, c->point_b);
    finish_midpoint(c);
    return 1;
}

/* mb_contact.c: the contact sub-stages of mb_step.
 *   detect: every surface pair's penetration geometry (mb_geom) from the bodies' poses: an
 *     ellipsoid against a plane or an ellipsoid, a cylinder (a wheel: torus of crown radius
 *     R - L/2 and tube L/2, the rounded tyre profile) against a plane;
 *   forces: per pair in contact, normal force F = max(0, F_h(x) + d x') with F_h the hysteresis
 *     element on the penetration x (loading/unloading, never tensile) and x' the penetration
 *     rate; Coulomb friction |F_t| = mu F min(1, u / u_s) against the slip velocity u: a linear
 *     stick ramp below the slip speed u_s (opts.slip_speed), raised where needed so that the
 *     ramp's viscous coefficient mu F / u_s times the step stays below the effective mass of
 *     the pair at the contact point along the slip (the explicit update of a stiff viscous
 *     term is stable for c h / m < 2; free-body effective masses bound it). Equal and
 *     opposite forces at the one contact point (mb_body_add_force_at_pos), so linear and
 *     angular momentum are kept.
 * Energy: the hysteresis element integrates its work exactly in x; the damper dissipates
 * (F - F_h) x' h per step, friction mu_eff F u h. */
#include "stage1_mb/mb_contact_wheel2.h"
#include "stage1_mb/mb_facet.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>

/* an ellipsoid surface placed in the world by its body's pose */
static void place_ellipsoid(const mb_surface *sf, const mb_body_kin *k, mb_ellipsoid *e)
{
    for (int i = 0; i < 3; i++) e->semi[i] = sf->semi[i];
    if (!k) {
        mb_copy(sf->center, e->center);
        for (int i = 0; i < 9; i++) e->rot[i] = sf->rot[i];
        return;
    }
    mb_mat_vec(k->rot, sf->center, e->center);
    mb_add(e->center, k->pos, e->center);
    mb_mat_mul(k->rot, sf->rot, e->rot);
}

static void place_plane(const mb_surface *sf, const mb_body_kin *k, mb_plane *p)
{
    if (!k) {
        mb_copy(sf->center, p->point), mb_copy(sf->normal, p->normal);
        return;
    }
    mb_mat_vec(k->rot, sf->center, p->point);
    mb_add(p->point, k->pos, p->point);
    mb_mat_vec(k->rot, sf->normal, p->normal);
}

static const mb_body_kin *kin_of(const mb_state *s, int b)
{
    return b == MB_GROUND ? NULL : &s->kin[b];
}

/* a wheel against an ellipsoid (mb_geom_wheel_ellipsoid), culled first: the wheel's box and
 * bounding sphere (R + r, R + r, r), then the last normal's gap (a lower bound) */
static void wheel_ellipsoid(mb_state *s, int i, const mb_wheel *w, const mb_ellipsoid *e,
                            mb_contact *c)
{
    mb_pair_state *ps = &s->pair[i];
    mb_ellipsoid disc, box;
    mb_wheel_disc(w, &disc);
    box = disc;
    box.semi[0] = box.semi[1] = w->radius + w->tube, box.semi[2] = w->tube + disc.semi[2];
    if (mb_ellipsoids_apart(&box, e, NULL) ||
        (ps->has_normal && mb_ellipsoid_gap(&disc, e, ps->normal) - w->tube > 0)) {
        c->depth = 0;
        return;
    }
    mb_geom_wheel_ellipsoid(w, e, ps->has_normal ? ps->normal : NULL, c);
    if (mb_dot(c->normal, c->normal) > 0) {
        mb_copy(c->normal, ps->normal);
        ps->has_normal = 1;
    }
}

/* a cylinder (wheel) against a plane (the torus geometry of mb_geom_wheel_plane) or an
 * ellipsoid */
static void detect_wheel(mb_state *s, int i, const mb_pair *p, const mb_surface *sa,
                         const mb_surface *sb, mb_contact *c)
{
    mb_wheel w;
    mb_plane pl;
    mb_wheel_place(sa, kin_of(s, p->ba), &w);
    if (sb->type == MB_SURF_ELLIPSOID) {
        wheel_ellipsoid(s, i, &w, &s->surf_ell[p->sb], c);
        return;
    }
    if (sb->type == MB_SURF_CYLINDER) { /* wheel against wheel (mb_geom_wheel2.h) */
        mb_wheel_wheel_detect(sb, kin_of(s, p->bb), &w, &s->pair[i], c);
        return;
    }
    place_plane(sb, kin_of(s, p->bb), &pl);
    mb_wheel_contact wc;
    mb_geom_wheel_plane(&w, &pl, &wc);
    *c = wc.c;
}

static void detect_pair(const mb_model *m, mb_state *s, int i)
{
    const mb_pair *p = &m->pair[i];
    const mb_surface *sa = &m->surf[p->sa], *sb = &m->surf[p->sb];
    mb_contact *c = &s->pc[i];
    if (sa->type == MB_SURF_CYLINDER) {
        detect_wheel(s, i, p, sa, sb, c);
        return;
    }
    const mb_ellipsoid ea = s->surf_ell[p->sa]; /* placed once per step (mb_contact_detect) */
    if (sb->type == MB_SURF_FACET) {
        mb_facet_detect(&ea, sb, kin_of(s, p->bb), s->pair[i].depth, &s->pair[i].latch, c);
        return;
    }
    if (sb->type == MB_SURF_PLANE) {
        mb_plane pl;
        place_plane(sb, kin_of(s, p->bb), &pl);
        mb_geom_ellipsoid_plane(&ea, &pl, c);
        return;
    }
    const mb_ellipsoid eb = s->surf_ell[p->sb];
    mb_pair_state *ps = &s->pair[i];
    /* culling: bounding spheres, boxes, the last separating normal -> no Newton iterations */
    if (mb_ellipsoids_apart(&ea, &eb, ps->has_normal ? ps->normal : NULL)) {
        c->depth = 0;
        return;
    }
    if (sa->sphere && sb->sphere) {
        mb_geom_sphere_sphere(ea.center, ea.semi[0], eb.center, eb.semi[0], c);
        return;
    }
    /* the normal in contact, or a separating direction when apart: next step's warm start */
    mb_geom_ellipsoid_ellipsoid(&ea, &eb, ps->has_normal ? ps->normal : NULL, c);
    if (mb_dot(c->normal, c->normal) > 0) {
        mb_copy(c->normal, ps->normal);
        ps->has_normal = 1;
    }
}

/* detect: reads body poses (s->kin), writes the geometry of every pair (s->pc) */
void mb_contact_detect(const mb_model *m, mb_state *s)
{
    for (int b = 0; b < m->nbody; b++) mb_body_get(s->world, b, &s->kin[b]);
    for (int i = 0; i < m->nsurf; i++)
        if (m->surf[i].type == MB_SURF_ELLIPSOID)
            place_ellipsoid(&m->surf[i], kin_of(s, m->surf[i].body), &s->surf_ell[i]);
    for (int i = 0; i < m->npair; i++) detect_pair(m, s, i);
}

static void point_velocity(const mb_state *s, int b, const double p[3], double v[3])
{
    if (b == MB_GROUND) {
        v[0] = v[1] = v[2] = 0;
        return;
    }
    const mb_body_kin *k = &s->kin[b];
    double r[3], wr[3];
    mb_sub(p, k->pos, r);
    mb_cross(k->angvel, r, wr);
    mb_add(k->vel, wr, v);
}

/* 1 / (effective mass) of body b at point p along unit direction t, as a free body:
 * 1/m + (r x t) . I^-1 (r x t). Joints only add inertia, so this bounds it from above. */
static double inv_mass_at(const mb_model *m, const mb_state *s, int b, const double p[3],
                          const double t[3])
{
    if (b == MB_GROUND) return 0;
    const mb_body_kin *k = &s->kin[b];
    double r[3], rt[3], rb[3], y[3];
    mb_sub(p, k->pos, r);
    mb_cross(r, t, rt);
    mb_mat_tvec(k->rot, rt, rb);
    mb_mat_vec(m->body_iinv[b], rb, y);
    return 1.0 / m->body[b].mass + mb_dot(rb, y);
}

/* friction force on a [N] for normal force fn and slip velocity u (a relative to b) at the
 * contact point */
static void friction(const mb_model *m, const mb_state *s, const mb_pair *p, const double at[3],
                     double fn, const double slip[3], double ft[3], double *power)
{
    double u = mb_norm(slip);
    ft[0] = ft[1] = ft[2] = 0;
    *power = 0;
    if (p->friction <= 0 || fn <= 0 || u <= 0) return;
    double t[3];
    mb_scale(slip, 1.0 / u, t);
    double inv_m = inv_mass_at(m, s, p->ba, at, t) + inv_mass_at(m, s, p->bb, at, t);
    double us = fmax(m->opts.slip_speed, p->friction * fn * m->h * inv_m);
    double mag = p->friction * fn * fmin(1.0, u / us);
    mb_scale(slip, -mag / u, ft);
    *power = mag * u;
}

static void pair_force(const mb_model *m, mb_state *s, int i)
{
    const mb_pair *p = &m->pair[i];
    mb_pair_state *ps = &s->pair[i];
    const mb_contact *c = &s->pc[i];
    double x = c->depth > 0 ? c->depth : 0;
    double fs = mcs_hyst_update(&p->hyst, &ps->h, x);
    ps->depth = x, ps->fn = 0;
    ps->ft[0] = ps->ft[1] = ps->ft[2] = 0;
    if (!(x > 0)) return;
    double va[3], vb[3], rel[3], slip[3], ft[3], pf;
    point_velocity(s, p->ba, c->point, va);
    point_velocity(s, p->bb, c->point, vb);
    mb_sub(va, vb, rel);
    double vn = mb_dot(rel, c->normal), rate = -vn;
    double fn = mcs_hyst_damped(fs, p->damping, rate, 1);
    ps->e_damp += (fn - fs) * rate * m->h;
    mb_axpy(rel, -vn, c->normal, slip);
    friction(m, s, p, c->point, fn, slip, ft, &pf);
    ps->e_fric += pf * m->h;
    ps->fn = fn;
    mb_copy(ft, ps->ft);
    double f[3];
    mb_axpy(ft, fn, c->normal, f);
    mb_body_add_force_at_pos(s->world, p->ba, f, c->point);
    if (p->bb != MB_GROUND) {
        mb_scale(f, -1, f);
        mb_body_add_force_at_pos(s->world, p->bb, f, c->point);
    }
}

/* forces: reads the pair geometry and velocities, writes forces on the bodies and the pair
 * histories and energies */
void mb_contact_forces(const mb_model *m, mb_state *s)
{
    for (int i = 0; i < m->npair; i++) pair_force(m, s, i);
}

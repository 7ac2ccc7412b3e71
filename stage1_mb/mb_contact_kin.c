/* mb_contact_kin: contact point velocities and force application (see the header). */
#include "stage1_mb/mb_contact_kin.h"
#include "stage1_mb/mb_vec.h"

static void point_vel(const mb_world *w, int b, const double p[3], double v[3])
{
    if (b < 0) {
        v[0] = v[1] = v[2] = 0;
        return;
    }
    mb_body_point_vel(w, b, p, v);
}

void mb_contact_velocity(const mb_world *w, int body_a, int body_b, const mb_contact *c,
                         mb_contact_vel *out)
{
    double va[3], vb[3], rel[3];
    point_vel(w, body_a, c->point, va);
    point_vel(w, body_b, c->point, vb);
    mb_sub(va, vb, rel);
    double vn = mb_dot(rel, c->normal);
    out->depth_rate = -vn;
    mb_axpy(rel, -vn, c->normal, out->slip);
}

void mb_contact_apply(mb_world *w, int body_a, int body_b, const mb_contact *c, double fn,
                      const double ft[3])
{
    double f[3];
    mb_scale(c->normal, fn, f);
    if (ft) mb_add(f, ft, f);
    if (body_a >= 0) mb_body_add_force_at_pos(w, body_a, f, c->point);
    if (body_b >= 0) {
        mb_scale(f, -1, f);
        mb_body_add_force_at_pos(w, body_b, f, c->point);
    }
}

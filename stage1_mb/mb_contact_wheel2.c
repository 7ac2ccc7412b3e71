/* mb_contact_wheel2: the wheel-wheel pair of the contact stage (see the header). */
#include "stage1_mb/mb_contact_wheel2.h"
#include "stage1_mb/mb_geom_wheel2.h"
#include "stage1_mb/mb_vec.h"

void mb_wheel_place(const mb_surface *sf, const mb_body_kin *k, mb_wheel *w)
{
    w->radius = sf->radius, w->tube = sf->tube;
    if (k) {
        mb_mat_vec(k->rot, sf->center, w->center);
        mb_add(w->center, k->pos, w->center);
        mb_mat_vec(k->rot, sf->normal, w->axis);
    } else {
        mb_copy(sf->center, w->center), mb_copy(sf->normal, w->axis);
    }
}

void mb_wheel_wheel_detect(const mb_surface *sb, const mb_body_kin *kb, const mb_wheel *a,
                           mb_pair_state *ps, mb_contact *c)
{
    mb_wheel b;
    mb_wheel_place(sb, kb, &b);
    /* bounding spheres: each wheel lies within radius + tube of its centre */
    double d[3];
    mb_sub(a->center, b.center, d);
    if (mb_norm(d) >= a->radius + a->tube + b.radius + b.tube) {
        c->depth = 0;
        return;
    }
    mb_geom_wheel_wheel(a, &b, ps->has_normal ? ps->normal : NULL, c);
    if (mb_dot(c->normal, c->normal) > 0) {
        mb_copy(c->normal, ps->normal);
        ps->has_normal = 1;
    }
}

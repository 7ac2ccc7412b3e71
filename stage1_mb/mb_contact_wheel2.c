/* mb_contact_wheel2: the wheel-wheel pair of the contact stage (see the header). */
#include "stage1_mb/mb_contact_wheel2.h"
#include "stage1_mb/mb_geom_wheel2.h"
#include "stage1_mb/mb_vec.h"

void mb_wheel_wheel_detect(const mb_surface *sb, const mb_body_kin *kb, const mb_wheel *a,
                           mb_pair_state *ps, mb_contact *c)
{
    mb_wheel b = {.radius = sb->radius, .tube = sb->tube};
    if (kb) {
        mb_mat_vec(kb->rot, sb->center, b.center);
        mb_add(b.center, kb->pos, b.center);
        mb_mat_vec(kb->rot, sb->normal, b.axis);
    } else {
        mb_copy(sb->center, b.center), mb_copy(sb->normal, b.axis);
    }
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

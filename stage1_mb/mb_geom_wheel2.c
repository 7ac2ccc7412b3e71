/* mb_geom_wheel2: wheel-wheel penetration (see the header). */
#include "stage1_mb/mb_geom_wheel2.h"
#include "stage1_mb/mb_vec.h"

int mb_geom_wheel_wheel(const mb_wheel *a, const mb_wheel *b, const double *warm_normal,
                        mb_contact *c)
{
    mb_wheel grown = *a;
    grown.tube = a->tube + b->tube;
    mb_ellipsoid disc_b;
    mb_wheel_disc(b, &disc_b);
    if (!mb_geom_wheel_ellipsoid(&grown, &disc_b, warm_normal, c)) return 0;
    /* point_a lies tube_b inside A's own surface and point_b on B's disc: both move by tube_b
     * along the normal (from b into a), which keeps the depth and their midpoint's offset */
    mb_axpy(c->point_a, b->tube, c->normal, c->point_a);
    mb_axpy(c->point_b, b->tube, c->normal, c->point_b);
    for (int k = 0; k < 3; k++) c->point[k] = 0.5 * (c->point_a[k] + c->point_b[k]);
    return 1;
}

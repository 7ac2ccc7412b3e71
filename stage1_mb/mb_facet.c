/* mb_facet.c: ellipsoid against a body's facet surface, each step (mb_facet.h). */
#include "stage1_mb/mb_facet.h"

#include <math.h>
#include <string.h>

void mb_facet_detect(const mb_ellipsoid *ea, const mb_surface *sf, const mb_body_kin *k,
                     double prev_depth, mb_mesh_latch *latch, mb_contact *c)
{
    mb_pose pose = {.pos = {0, 0, 0}, .rot = {1, 0, 0, 0, 1, 0, 0, 0, 1}};
    if (k) {
        memcpy(pose.pos, k->pos, sizeof pose.pos);
        memcpy(pose.rot, k->rot, sizeof pose.rot);
    }
    double smin = fmin(ea->semi[0], fmin(ea->semi[1], ea->semi[2]));
    mb_geom_ellipsoid_mesh_deepest_latched(ea, sf->mesh, &pose, prev_depth + 0.25 * smin, latch, c);
}

/* mb_impact.h: the scenario's impact: block applied to a built stage-1 model (issue 4 item 6).
 *
 * Groups. The motorcycle group is the bodies named by impact.motorcycle_bodies (names or
 * fnmatch patterns; default "moto_*" and "rider_*": the motorcycle model's bodies and the
 * rider's). The opponent group is impact.opponent_bodies (default: every other body).
 *
 * Placement (ISO 13232-2 style: a contact point on each vehicle and a relative heading angle).
 * The opponent stays where its model file puts it; opponent_heading (world, default +x) is its
 * forward direction. The motorcycle model (x forward, z up) is
 *   1. rolled by roll_angle about its x axis through the model origin (positive: lean to the
 *      right, ISO 8855),
 *   2. turned about the vertical to the heading h_mc = the opponent's heading turned by
 *      heading_angle counter-clockwise seen from above,
 *   3. translated horizontally so that motorcycle_contact (a point in the motorcycle model
 *      frame, e.g. the front tyre's foremost point) lands on opponent_contact - initial_gap h_mc
 *      in plan view (x, y). Heights are not changed: the motorcycle stays on the ground, so give
 *      both points at the same height (a difference is logged).
 * Without the two contact points steps 1-2 turn the motorcycle about the model origin.
 * Every motorcycle body's pose and velocity, the anchors and axes of the joints between them and
 * world attachment points move with it (a rigid motion); so do the FE parts carried by its
 * bodies (fe.parts[].attach and the rest, fe/fe_scn_build.h fe_scn_place), placed by
 * mb_couple_build after this from m->place_R, place_t and body_group.
 *
 * Speeds. Motorcycle bodies get motorcycle_speed along h_mc added to their (rotated) model
 * velocity; opponent bodies opponent_speed along the opponent's heading. A body of either group
 * carrying a cylinder surface (a wheel) also rolls: spin v/R about its axle, signed so that the
 * wheel's lowest point is at rest, and its CG velocity includes the spin about the cylinder's
 * centre. R is the rolling radius: the cylinder's radius, or for a tyre loaded into the road
 * (its centre at h < R from the road in the wheel plane) (h + R) / 2, the distance to the point
 * where the engine applies the road friction (midway between the tyre's deepest point and the
 * road), so that no point slips at t = 0.
 *
 * Errors (FILE:LINE:COL and key): a joint or an attachment between the motorcycle group and a
 * body outside it, a moving opponent fixed to the ground, a wheel whose axle is not across its
 * heading. */
#ifndef MB_IMPACT_H
#define MB_IMPACT_H

#include "stage1_mb/mb_model.h"

/* apply root's impact: block (nothing without one): the bodies' poses and velocities, and
 * m->body_group, place_R, place_t; called by mb_model_build before mb_couple_build */
mcs_status mb_impact_apply(const mcs_node *root, mb_model *m, mcs_error *err);

#endif

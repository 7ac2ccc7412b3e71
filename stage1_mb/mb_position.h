/* mb_position.h: seating the rider on the motorcycle before the run (issue 4 item 4;
 * docs/rider.md "Positioning"). Driven by the scenario's rider: block; nothing without one.
 *
 * Mount points (root key mount_points: name, body, point in the body frame): on the motorcycle
 * seat_h_point, grip_l, grip_r, peg_l, peg_r; on the rider rider_h_point (pelvis),
 * rider_grip_l/r (hands), rider_peg_l/r (feet). Rider segments are the bodies named rider_*,
 * connected by joints into a tree rooted at rider_pelvis (rider_helmet* bodies, which hang on
 * attachments, follow the head).
 *
 * Posture, in the motorcycle's model frame (mb_impact places the whole group afterwards):
 *   - the pelvis and the torso are pitched forward by torso_lean about the H-point, which is
 *     put on seat_h_point;
 *   - the neck segments share the pitch back to head_pitch (0: the head upright as in the file);
 *   - each arm is a two-link chain shoulder -> elbow -> grip (forearm and hand rigid together),
 *     each leg shoulder-like hip -> knee -> ankle with the foot pitched by foot_pitch and the
 *     ankle placed so that the peg point lands on the peg; the closed-form solution
 *     (triangle of the link lengths) with the elbow bent down and out, the knee forward, up
 *     and out. Unreachable targets (farther than the stretched chain, or nearer than the
 *     folded one) are refused with the distances in the message.
 *   - revolute joints keep their axes (both links turn the hinge axis alike) and their
 *     ranges move with the posture (the ranges are given about the file's posture); a posture
 *     outside a range is refused.
 *   - every rider body gets the velocity of the seat's body at its position (rigid motion).
 * Then (mb_position_attach, after the scenario's attachments) five breakable attachments at
 * rest: rider_seat (pelvis-seat), rider_grip_l/r, rider_peg_l/r (MYMOSA's five spring-damper
 * elements). m->rider_residual is the largest distance between a rider mount point and its
 * motorcycle mount point after positioning [m]. */
#ifndef MB_POSITION_H
#define MB_POSITION_H

#include "stage1_mb/mb_model.h"

/* seat the rider (before mb_build_attachments) */
mcs_status mb_position_rider(const mcs_node *root, mb_model *m, mcs_error *err);
/* add the five breakable attachments (after mb_build_attachments) */
mcs_status mb_position_attach(const mcs_node *root, mb_model *m, mcs_error *err);

/* a mount point's world position in the model's initial pose; -1 if there is no such mount
 * point, else 0 */
int mb_mount_world(const mcs_node *root, const mb_model *m, const char *name, double out[3]);

#endif

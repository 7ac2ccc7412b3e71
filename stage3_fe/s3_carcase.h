/* s3_carcase: what stage 3 adds to its results for a generated motorcycle (stage3_fe/s3_moto.h)
 * meeting a generated sedan side (stage3_fe/s3_sedan.h), the ISO 13232 413 car case
 * (docs/validation_stage3.md "The 413 car case", docs/contracts.md "Stage 3"). Switched on when
 * the model has a motorcycle (bodies <m>_frame and <m>_upper_fork) and a sedan (rigid body
 * <s>_body and parts <s>_door_outer, <s>_door_inner). At the times of /stage3/time:
 *   /stage3/channels/<m>_pitch [nt] rad: the frame's pitch, nose down > 0: -asin of the z
 *     component of its x axis (stage 1's definition, tests/test_validation_stage1.c);
 *   /stage3/channels/<m>_velocity, <s>_velocity [nt, 3] m/s: each vehicle's centre-of-mass
 *     velocity (its free nodes' and rigid bodies' momentum over its mass; velocities at
 *     t + dt/2), attribute mass [kg];
 *   /stage3/channels/<s>_door_intrusion, <s>_door_inner_intrusion [nt] m: the largest inward
 *     displacement (along the car's +x axis, the struck side facing -x) of a node of the door's
 *     outer skin <s>_door_outer (inner panel <s>_door_inner) relative to the car's rigid rest
 *     <s>_body (where the rest's motion carries the node's initial place); attributes part, node
 *     (the node reaching the run's largest). */
#ifndef S3_CARCASE_H
#define S3_CARCASE_H

#include "core/mcs_results.h"
#include "fe/fe_state.h"

typedef struct s3_carcase s3_carcase;

/* NULL in *out (and MCS_OK) when the model is not a motorcycle-into-sedan case */
mcs_status s3_carcase_open(mcs_results *r, const fe_model *m, s3_carcase **out, mcs_error *err);
/* a row at the kernel's energy time (with /stage3/time) */
mcs_status s3_carcase_sample(const fe_model *m, const fe_state *s, s3_carcase *c,
                             mcs_error *err);
/* attributes into r; frees c (NULL: nothing) */
mcs_status s3_carcase_finish(mcs_results *r, s3_carcase **c, mcs_error *err);
void s3_carcase_free(s3_carcase **c);

#endif

/* s3_wallcase: what stage 3 adds to its results for a generated motorcycle (stage3_fe/s3_moto.h)
 * against a rigid wall, the thesis' frontal impact (docs/validation_stage3.md "The rigid-wall
 * impact", docs/contracts.md "Stage 3"). Switched on when the model has the motorcycle's bodies
 * <pre>_upper_fork and <pre>_lower_fork; the impact wall is the penalty wall whose normal is
 * most against the heaviest body's initial velocity (the ground's is normal to it).
 *   /stage3/channels/<pre>_fork_deformation_angle [nt] rad: the fork bending angle as stage 1
 *     defines its hinge moto_fork_deformation (child fork about +y relative to the upper fork,
 *     rearward bending > 0): the lower fork's rotation relative to the upper fork about the
 *     upper fork's y axis, at the times of /stage3/time;
 *   /stage3/rigidwall/<wall>/parts/<part>/force [nt] N: each part's share of a penalty wall's
 *     normal force, the mean over the output interval as force_mean (stage3_fe/s3_run.h) (parts
 *     with a node the wall stops; a point mass counts for its rigid part);
 *   /stage3/rigidwall/<impact wall>/crush [nt] m: the heaviest body's (the frame's) travel
 *     along -normal since the wall's first contact (0 before);
 *   /stage3/phases/<phase>/{start_time [s], crush [m], peak_force [N]} (scalars; NaN when the
 *     phase did not begin) for the phases of the 2023 paper's Fig. 25, in order: tyre (the
 *     front tyre touches the wall), rim (the first plastic strain in the front rim or spokes,
 *     or they or the hub touch the wall), fork (the first plastic strain in a stanchion), engine (the front wheel meets the frame/fairing through the
 *     contact <pre>_wheel_engine, or a frame part touches the wall), each at the first row
 *     whose interval saw it; peak_force: the largest force_mean from its start to the next phase's (the last: to the end); group attribute
 *     `wall` (the impact wall's name), also as the attribute `impact_wall` of /stage3/rigidwall
 *     (mcrash retune fits that wall's force, translators/tr_retune.h). */
#ifndef S3_WALLCASE_H
#define S3_WALLCASE_H

#include "core/mcs_results.h"
#include "fe/fe_state.h"

#define S3_NPHASE 4

typedef struct s3_wallcase s3_wallcase;

/* NULL in *out (and MCS_OK) when the model is not a motorcycle case */
mcs_status s3_wallcase_open(mcs_results *r, const fe_model *m, s3_wallcase **out,
                            mcs_error *err);
/* after each step: the parts' wall impulses (c NULL: nothing) */
void s3_wallcase_step(const fe_model *m, const fe_state *s, s3_wallcase *c);
/* a row at the kernel's energy time (with /stage3/time) */
mcs_status s3_wallcase_sample(const fe_model *m, const fe_state *s, s3_wallcase *c,
                              mcs_error *err);
/* the phases into r; frees c (NULL: nothing) */
mcs_status s3_wallcase_finish(mcs_results *r, s3_wallcase **c, mcs_error *err);
void s3_wallcase_free(s3_wallcase **c);

/* the phase names, in order: tyre, rim, fork, engine */
extern const char *const s3_phase_name[S3_NPHASE];

#endif

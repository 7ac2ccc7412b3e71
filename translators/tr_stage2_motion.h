/* tr_stage2_motion: the scenario's stage2: block (DESIGN.md "Stage 2") made into prescribed
 * bodies of a stage-1-engine model: stage2.motion (or the command line's file) read with
 * stage2.method, each stage2.prescribed[] body moved as the file's body of its name or
 * `from` (tr_motion, tr_prescribe); the other bodies stay free. A relative stage2.motion is
 * taken from the scenario file's directory (as include: and mesh files). */
#ifndef TR_STAGE2_MOTION_H
#define TR_STAGE2_MOTION_H

#include "core/mcs_scenario.h"
#include "translators/tr_prescribe.h"

typedef struct tr_stage2_motion tr_stage2_motion; /* the motion and its callbacks (owned) */

/* motion_path: the file, overriding stage2.motion (NULL: the block's). Errors (exit-2 class):
 * no stage2: block or no file named (MCS_ERR_KEY, with the scenario's location), the file's
 * (tr_motion_open: naming file and body), a prescribed body the file lacks or a file shorter
 * than the run (tr_prescribe_create). */
mcs_status tr_stage2_motion_create(tr_stage2_motion **out, const mcs_scenario *scn, mb_model *m,
                                   const char *motion_path, mcs_error *err);
void tr_stage2_motion_destroy(tr_stage2_motion **p);
const tr_motion *tr_stage2_motion_get(const tr_stage2_motion *p);
/* the motion file read (stage2.motion is taken relative to the scenario file) */
const char *tr_stage2_motion_path(const tr_stage2_motion *p);
/* the prescribed bodies: their count, and the i-th's model body (*from: the file's body) */
int tr_stage2_motion_count(const tr_stage2_motion *p);
const char *tr_stage2_motion_body(const tr_stage2_motion *p, int i, const char **from);

#endif

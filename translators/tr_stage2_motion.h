/* tr_stage2_motion: the scenario's stage2: block (DESIGN.md "Stage 2") made into prescribed
 * bodies of a stage-1-engine model: stage2.motion (or the command line's file) read with
 * stage2.method, each stage2.prescribed[] body moved as the file's body of its name or
 * `from` (tr_motion, tr_prescribe); the other bodies stay free. */
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

#endif

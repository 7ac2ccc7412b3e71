/* tr_prescribe: stage-1 trajectories as prescribed bodies of a stage-1-engine model (issue 13,
 * DESIGN.md "Stage 2"): each named body of the model moves as a body of a tr_motion (the
 * file's body of the same name, or `from`), through the engine's prescribed-motion callback
 * (stage1_mb/mb_prescribe.h). The model's end time must lie in the file's span. */
#ifndef TR_PRESCRIBE_H
#define TR_PRESCRIBE_H

#include "core/mcs_error.h"
#include "stage1_mb/mb_model.h"
#include "translators/tr_motion.h"

typedef struct tr_prescribe tr_prescribe; /* the callbacks' context (owns nothing else) */

/* prescribe bodies[i] of m (n of them) from the motion's body from[i] (from NULL or from[i]
 * NULL: the same name). mo must outlive the runs of m. MCS_ERR_KEY naming a body missing
 * from the model or the motion; MCS_ERR_RANGE when the motion ends before m->t_end or its
 * pose at t = 0 is not the body's initial pose. */
mcs_status tr_prescribe_create(tr_prescribe **out, mb_model *m, const tr_motion *mo,
                               const char *const *bodies, const char *const *from, int n,
                               mcs_error *err);
void tr_prescribe_destroy(tr_prescribe **p);

/* the message of the last callback failure (a time outside the span), "" none */
const char *tr_prescribe_error(const tr_prescribe *p);

#endif

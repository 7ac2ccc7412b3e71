/* an_stages.h: stage against stage in one results file (DESIGN.md `compare OUT.h5 --stages A,B`):
 * every channel /stageA/channels and /stageB/channels share, the stage-B curve rated against the
 * stage-A one by ISO/TS 18571 or CORA. Used by `mcrash compare --stages` and `mcrash loop`. */
#ifndef AN_STAGES_H
#define AN_STAGES_H

#include "core/mcs_error.h"

typedef struct {
    char name[128];   /* the channel                                                  */
    double rating;    /* its rating [0, 1], NaN when it could not be rated            */
    char error[1024]; /* why not (a constant curve, units that differ), "" when rated */
} an_stage_rating;

/* the shared channels in /stageA/channels order into *out (malloc'd, *n of them); no shared
 * channel, or a stage without channels, is an error (MCS_ERR_FORMAT) */
mcs_status an_stages_rate(const char *h5, int sa, int sb, int cora, an_stage_rating **out, int *n,
                          mcs_error *err);

#endif

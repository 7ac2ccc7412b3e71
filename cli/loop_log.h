/* loop_log.h: what `mcrash loop` keeps of each iteration and writes to DIR/loop.json and
 * DIR/loop.csv (docs/loop.md, docs/contracts.md "Retune and loop") */
#ifndef MCS_LOOP_LOG_H
#define MCS_LOOP_LOG_H

#include "translators/tr_retune.h"
#include "translators/tr_stages.h"

typedef struct {
    int k;                          /* iteration, from 1                                 */
    char results[4096];             /* its results file (iter_<k>.h5)                    */
    char curves[4096];              /* its retuned characteristics (curves_<k>.yaml)     */
    double p[TR_RT_NPAR];           /* retune's parameters                               */
    int nrun;                       /* retune's stage-1 runs                             */
    double iso_force, iso_angle;    /* stage 1 against stage 3 after retune (ISO 18571)  */
    tr_stage_compare cmp;           /* stage 2 against stage 1: shared channels and body
                                     * components (ISO/TS 18571 taken), both stages' criteria */
} loop_iter;

void loop_iter_free(loop_iter *it);

/* the largest change of a rating from a to b (a channel rated in one only: 1) */
double loop_rating_change(const loop_iter *a, const loop_iter *b);

/* DIR/loop.json and DIR/loop.csv of iterations it[0..n-1]; 0 on success */
int loop_log_write(const char *dir, const char *scenario, const loop_iter *it, int n,
                   int converged, const char *reason);

#endif

/* tr_stages: one stage of a results file against another (`mcrash compare OUT.h5 --stages A,B`,
 * cli/cmd_compare_stages.c, docs/contracts.md "compare --stages"): every channel the two stages
 * share (/stageN/channels/<name>) and every component of the bodies they share
 * (/stageN/bodies/<body>/{position,velocity,acceleration,angular_velocity}, x y z) rated by
 * ISO/TS 18571 and by CORA, stage B against the reference stage A, and the injury criteria of
 * both stages side by side (analysis/an_injury.h). */
#ifndef TR_STAGES_H
#define TR_STAGES_H

#include "analysis/an_cora.h"
#include "analysis/an_injury.h"
#include "analysis/an_iso18571.h"
#include "core/mcs_error.h"

typedef struct {
    char name[160];       /* channel name, or <body>/<quantity>_<x|y|z> */
    int body;             /* 0 a channel, 1 a body component */
    char unit[16];        /* SI unit of both curves */
    int iso_ok, cora_ok;  /* 1 when rated, 0: the reason is in *_error */
    an_iso_result iso;    /* ISO/TS 18571 rating of B against A */
    an_cora_result cora;  /* CORA rating of B against A */
    char iso_error[256];  /* why it was not rated (a constant reference, units differ) */
    char cora_error[256];
} tr_stage_rating;

typedef struct {
    char key[32], label[48], unit[8]; /* as an_injury_row */
    double limit;                     /* [unit], NaN none */
    double value[2];                  /* stage A, stage B [unit]; NaN when the stage lacks it */
    double fraction[2];               /* value / limit, NaN without a limit or a value */
} tr_stage_criterion;

typedef struct {
    int stage[2];             /* A (reference), B */
    int nrating;              /* shared channels and body components [-] */
    tr_stage_rating *rating;  /* (nrating): channels first, in stage A's order, then bodies */
    int ncrit;                /* criteria of either stage [-] */
    tr_stage_criterion *crit; /* (ncrit): stage A's order, then those only B has */
} tr_stage_compare;

/* compare stages a and b of results file h5. Errors (exit 2): the file or a stage group
 * missing, nothing shared (no channel and no body). A curve that cannot be rated gets its
 * reason, not an error. */
mcs_status tr_compare_stages(const char *h5, int a, int b, tr_stage_compare *out,
                             mcs_error *err);
void tr_stage_compare_free(tr_stage_compare *c);

#endif

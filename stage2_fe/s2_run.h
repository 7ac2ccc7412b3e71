/* s2_run: stage 2 of a scenario (DESIGN.md "Stage 2", issue 13): the scenario's multibody +
 * FE model, the one stage 1 runs (bodies, contacts, joints, restraints, coupled FE parts), with
 * the bodies of stage2.prescribed moved as a stage-1 results file's (translators/
 * tr_stage2_motion.h, method pose or pulse) and every other body free. Results go to /stage2 in
 * the /stage1 layout (stage1_mb/mb_output.c, mb_couple_out.h: time, bodies, channels, energy,
 * injury, outlines, mesh, fields, parts, airbag, retractor, slipring, contact), plus
 *   /stage2/motion/<body>/{time [n] s, position_error [n] m, angle_error [n] rad}: the
 *   prescribed pose (the motion the run was given) against the file's written pose at the
 *   file's sample times up to the run's end; attributes file, from (the file's body), method.
 * Refused (exit-2 class, nothing written): no stage2: block, a file that is not HDF5, corrupt
 * or without /stage1, a prescribed body the file lacks, a file shorter than the run; the
 * message names the file and the body. */
#ifndef S2_RUN_H
#define S2_RUN_H

#include "core/mcs_scenario.h"
#include "stage1_mb/mb_model.h"
#include "translators/tr_stage2_motion.h"

typedef struct {
    mcs_scenario *scn;        /* the compiled stage-2 scenario (s2_scenario.h) (owned)     */
    mb_model *mb;             /* the coupled model, writing /stage2 (owned)                */
    tr_stage2_motion *motion; /* the prescribed bodies' motion (owned)                     */
} s2_model;

/* build the stage-2 model of a scenario: motion_path overrides stage2.motion (NULL: the
 * block's, relative to the scenario file). The stage-2-only FE parts (stage2.fe) are merged
 * into fe: first (s2_scenario_compile). */
mcs_status s2_model_build(const mcs_scenario *scn, const char *motion_path, s2_model **out,
                          mcs_error *err);
void s2_model_destroy(s2_model **m);

typedef struct {
    const char *out_path;      /* results file                                            */
    const char *scenario_text; /* stored in /meta of a new file (may be NULL)             */
    int quiet;                 /* no progress line                                         */
    int append;                /* 1: add /stage2 to the existing out_path (run --stage all) */
} s2_run_opts;

typedef struct {
    mb_run_summary mb;     /* steps, bodies, wall time, energy drift, end time, timers    */
    int prescribed;        /* prescribed bodies [-]                                       */
    double position_error; /* largest /stage2/motion/<b>/position_error [m]              */
    double angle_error;    /* largest angle_error [rad]                                   */
} s2_summary;

/* run to the model's end time and write /stage2 (nothing is left on failure) */
mcs_status s2_run(const s2_model *m, const s2_run_opts *o, s2_summary *sum, mcs_error *err);

#endif

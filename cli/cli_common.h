/* cli_common.h: what several subcommands share — the run arguments, loading a scenario with
 * its error printed, the default results file, and JSON strings */
#ifndef MCS_CLI_COMMON_H
#define MCS_CLI_COMMON_H

#include <stddef.h>

#include "core/mcs_scenario.h"
#include "fe/fe_scn_build.h"
#include "stage1_mb/mb_model.h"
#include "stage3_fe/s3_run.h"

/* "SCENARIO [-o OUT.h5] [--quiet] [--json] [--stage 1|2|3|all]" */
typedef struct {
    const char *path;   /* the scenario file */
    const char *out;    /* -o, or the default results file (def_out) */
    const char *stage;  /* --stage, "all" when not given */
    const char *motion; /* --motion (stage2, run), NULL when not given */
    int quiet, json;    /* --quiet, --json */
    char def_out[4096]; /* "<scenario basename>.h5" when -o is absent */
} cli_run_args;

/* parse argv (argv[0] is the subcommand); with_stage accepts --stage. Returns -1 when the
 * arguments are good, otherwise the exit status to return (0 after --help, 2 on bad usage) */
int cli_parse_run_args(int argc, char **argv, int with_stage, cli_run_args *a);

/* load a scenario; on error print its FILE:LINE:COL message, set *rc and return NULL */
mcs_scenario *cli_load_scenario(const char *path, int *rc);

/* the default results file of a scenario: "<basename without .yaml/.yml>.h5" in the current
 * directory */
void cli_default_output(const char *scenario, char *out, size_t n);

/* print s on stdout as a JSON string (quotes, backslashes and control characters escaped) */
void cli_json_string(const char *s);

/* the stage runs of a loaded scenario into out_path: print the error (stderr) or, with json,
 * the summary object on stdout; return the exit status (0, 1 numerical, 2 bad input) */
int cli_stage1_scenario(const mcs_scenario *scn, const char *out_path, int quiet, int json);
int cli_stage3_scenario(const mcs_scenario *scn, const char *out_path, int quiet, int json);
/* the reduced-order model (cmd_rom.c) into out_path's /stage0; append: add to that file */
int cli_rom_exec(const mcs_scenario *scn, const char *out_path, int append, int quiet, int json);
/* `compare OUT.h5 --stages A,B` (cmd_compare_stages.c): "A,B" parsed (1 when good), and the
 * ratings of every channel the two stages share (cora: CORA, else ISO/TS 18571) */
int cli_parse_stages(const char *s, int *a, int *b);
int cli_compare_stages(const char *h5, int sa, int sb, int cora, int json);

/* stage 1's run without the summary printed (its error is), and its JSON summary object */
int cli_stage1_exec(const mcs_scenario *scn, const char *out_path, int quiet,
                    mb_run_summary *sum);
void cli_stage1_json(const mb_run_summary *sum);
/* stage 2 (cmd_stage2.c): motion overrides stage2.motion; append adds /stage2 to out_path */
int cli_stage2_scenario(const mcs_scenario *scn, const char *motion, const char *out_path,
                        int append, int quiet, int json);
/* stage 1 then stage 2 into one file, reading the motion from the stage-1 run (run --stage all
 * of a scenario with a stage2: block) */
int cli_stage12_scenario(const mcs_scenario *scn, const char *out_path, int quiet, int json);

/* the stage-3 model of a scenario as `mcrash stage3` builds it: its stage3: block compiled
 * into *s3 (NULL without one; the caller destroys it after p), else the scenario as it is (a
 * stage-1-only key of the fe: block refused at its FILE:LINE:COL); `mcrash check` builds it */
mcs_status cli_stage3_build(const mcs_scenario *scn, mcs_scenario **s3, fe_problem *p,
                            mcs_error *err);
/* stage 3's run into out_path (append: add /stage3 to an existing file) without its summary
 * printed (its error is); the summary as a JSON object, or as a line on stderr */
int cli_stage3_exec(const mcs_scenario *scn, const char *out_path, int append, int quiet,
                    s3_summary *sum);
void cli_stage3_json(const s3_summary *sum);
void cli_stage3_note(const s3_summary *sum, const char *out_path);
/* run --stage all: stage 1, stage 2 when the scenario has a stage2: block, stage 3 when it has
 * a stage3: block, into one file (one JSON object with a member per stage) */
int cli_stage_all_scenario(const mcs_scenario *scn, const char *out_path, int quiet, int json);

#endif

/* cli_stage1.h: the stage-1 run shared by `mcrash stage1` and `mcrash run` */
#ifndef MCS_CLI_STAGE1_H
#define MCS_CLI_STAGE1_H

#include "core/mcs_scenario.h"

/* the default results file of a scenario: "<basename without .yaml/.yml>.h5" in the current
 * directory */
void cli_default_output(const char *scenario, char *out, size_t n);

/* run stage 1 of a loaded scenario into out_path; prints the error (stderr) or, with json,
 * the summary object on stdout; returns the exit status (0, 1 numerical, 2 bad input) */
int cli_stage1_scenario(const mcs_scenario *scn, const char *out_path, int quiet, int json);

#endif

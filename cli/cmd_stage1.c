/* cmd_stage1.c: `mcrash stage1 SCENARIO.yaml [-o OUT.h5] [--quiet] [--json]`: the multibody
 * model (stage1_mb) from a scenario to a results file. Without -o the file is
 * <scenario basename>.h5 in the current directory. --json prints
 * {"output": ..., "stage1": {"steps", "bodies", "wall_time_s", "energy_drift"}}. */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "stage1_mb/mb_model.h"

#include <stdio.h>
#include <string.h>

int cli_stage1_exec(const mcs_scenario *scn, const char *out_path, int quiet, mb_run_summary *sum)
{
    mcs_error err = {0};
    mb_model *m = NULL;
    mcs_status st = mb_model_build(scn, NULL, &m, &err);
    if (!st) {
        mb_run_opts o = {
            .out_path = out_path, .scenario_text = mcs_scenario_text(scn), .quiet = quiet};
        st = mb_run(m, &o, sum, &err);
    }
    mb_model_destroy(&m);
    if (st) fprintf(stderr, "%s\n", err.msg);
    return mcs_status_exit_code(st);
}

void cli_stage1_json(const mb_run_summary *sum)
{
    printf("{\"steps\": %ld, \"bodies\": %d, \"wall_time_s\": %.6g, \"energy_drift\": %.6g, "
           "\"end_time_s\": %.9g, \"timers_s\": {",
           sum->steps, sum->bodies, sum->wall_time_s, sum->energy_drift, sum->t_end);
    for (int k = 0; k < MB_NTIMER; k++)
        printf("%s\"%s\": %.4g", k ? ", " : "", mb_timer_name(k), sum->timer[k]);
    printf("}}");
}

int cli_stage1_scenario(const mcs_scenario *scn, const char *out_path, int quiet, int json)
{
    mb_run_summary sum = {0};
    int rc = cli_stage1_exec(scn, out_path, quiet, &sum);
    if (rc) return rc;
    if (json) {
        printf("{\"output\": ");
        cli_json_string(out_path);
        printf(", \"stage1\": ");
        cli_stage1_json(&sum);
        printf("}\n");
    } else if (!quiet) {
        fprintf(stderr, "stage 1: %ld steps, %d bodies, %.3g s wall, energy drift %.3g -> %s\n",
                sum.steps, sum.bodies, sum.wall_time_s, sum.energy_drift, out_path);
    }
    return fflush(stdout) ? 2 : 0;
}

int cli_stage1(int argc, char **argv)
{
    cli_run_args a;
    int rc = cli_parse_run_args(argc, argv, 0, &a);
    if (rc >= 0) return rc;
    mcs_scenario *scn = cli_load_scenario(a.path, &rc);
    if (!scn) return rc;
    rc = cli_stage1_scenario(scn, a.out, a.quiet, a.json);
    mcs_scenario_destroy(&scn);
    return rc;
}

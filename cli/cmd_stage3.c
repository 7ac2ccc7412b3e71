/* cmd_stage3.c: `mcrash stage3 SCENARIO.yaml [-o OUT.h5] [--quiet] [--json]`: an FE-only
 * scenario (its fe: block, stage3_fe) to a results file. `mcrash run` hands FE-only scenarios
 * here. Without -o the file is <scenario basename>.h5 in the current directory. --json prints
 * {"output": ..., "stage3": {"steps", "elements", "wall_time_s", "energy_drift", ...}}.
 * Exit status: 0 done, 1 numerical failure (no results file left), 2 bad input. */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "fe/fe_scn_restraints.h"
#include "stage3_fe/s3_run.h"

#include <stdio.h>
#include <string.h>

mcs_status cli_stage3_build(const mcs_scenario *scn, fe_problem *p, mcs_error *err)
{
    const mcs_node *k1 = fe_scn_stage1_key(mcs_node_get(mcs_scenario_root(scn), "fe"));
    if (k1)
        return mcs_node_error(k1, err, MCS_ERR_UNSUPPORTED,
                              "needs the stage-1 bodies (a coupled stage-1 run): not in a "
                              "stage-3 run");
    return fe_scn_build(scn, p, err);
}

int cli_stage3_scenario(const mcs_scenario *scn, const char *out, int quiet, int json)
{
    mcs_error err = {0};
    fe_problem p = {0};
    s3_summary sum = {0};
    mcs_status st = cli_stage3_build(scn, &p, &err);
    if (!st) {
        s3_run_opts o = {.out_path = out, .scenario_text = mcs_scenario_text(scn), .quiet = quiet};
        st = s3_run(&p, &o, &sum, &err);
    }
    fe_problem_free(&p);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    if (json) {
        printf("{\"output\": ");
        cli_json_string(out);
        printf(", \"stage3\": {\"steps\": %ld, \"elements\": %d, \"nodes\": %d, "
               "\"wall_time_s\": %.6g, \"energy_drift\": %.6g, \"end_time_s\": %.9g, "
               "\"dt_initial_s\": %.6g, \"mass_added_kg\": %.6g, \"mass_added_fraction\": %.6g, "
               "\"timers_s\": {",
               sum.steps, sum.elements, sum.nodes, sum.wall_time_s, sum.energy_drift, sum.t_end,
               sum.dt_initial, sum.mass_added, sum.mass_added_fraction);
        for (int k = 0; k < FE_NSTAGE; k++)
            printf("%s\"%s\": %.4g", k ? ", " : "", fe_stage_name[k], sum.timer[k]);
        printf("}}}\n");
    } else if (!quiet) {
        fprintf(stderr, "stage 3: %ld steps, %d elements, %.3g s wall, energy drift %.3g -> %s\n",
                sum.steps, sum.elements, sum.wall_time_s, sum.energy_drift, out);
        if (sum.mass_added > 0)
            fprintf(stderr, "stage 3: mass scaling added %.6g kg (%.3g %% of the model)\n",
                    sum.mass_added, 100 * sum.mass_added_fraction);
    }
    return fflush(stdout) ? 2 : 0;
}

int cli_stage3(int argc, char **argv)
{
    cli_run_args a;
    int rc = cli_parse_run_args(argc, argv, 0, &a);
    if (rc >= 0) return rc;
    mcs_scenario *scn = cli_load_scenario(a.path, &rc);
    if (!scn) return rc;
    rc = cli_stage3_scenario(scn, a.out, a.quiet, a.json);
    mcs_scenario_destroy(&scn);
    return rc;
}

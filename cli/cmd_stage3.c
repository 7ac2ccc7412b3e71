/* cmd_stage3.c: `mcrash stage3 SCENARIO.yaml [-o OUT.h5] [--quiet] [--json]`: the scenario's
 * FE model (its stage3: block compiled, stage3_fe/s3_scenario.h, or an fe:-only scenario as it
 * is) to a results file. `mcrash run` hands FE-only scenarios and --stage 3 here, and adds
 * stage 3 after stages 1 and 2 for --stage all of a scenario with a stage3: block. Without -o
 * the file is <scenario basename>.h5 in the current directory. --json prints
 * {"output": ..., "stage3": {"steps", "elements", "wall_time_s", "energy_drift", ...}}.
 * Exit status: 0 done, 1 numerical failure (no results file left), 2 bad input. */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "fe/fe_scn_restraints.h"
#include "stage3_fe/s3_run.h"
#include "stage3_fe/s3_scenario.h"

#include <stdio.h>
#include <string.h>

mcs_status cli_stage3_build(const mcs_scenario *scn, mcs_scenario **s3, fe_problem *p,
                            mcs_error *err)
{
    *s3 = NULL;
    mcs_status st = s3_scenario_has_block(scn) ? s3_scenario_compile(scn, s3, err) : MCS_OK;
    if (st) return st;
    const mcs_scenario *use = *s3 ? *s3 : scn;
    const mcs_node *k1 = fe_scn_stage1_key(mcs_node_get(mcs_scenario_root(use), "fe"));
    if (k1)
        return mcs_node_error(k1, err, MCS_ERR_UNSUPPORTED,
                              "needs the stage-1 bodies (a coupled stage-1 run): not in a "
                              "stage-3 run");
    return fe_scn_build(use, p, err);
}

void cli_stage3_json(const s3_summary *sum)
{
    printf("{\"steps\": %ld, \"elements\": %d, \"nodes\": %d, \"wall_time_s\": %.6g, "
           "\"energy_drift\": %.6g, \"end_time_s\": %.9g, \"dt_initial_s\": %.6g, "
           "\"mass_added_kg\": %.6g, \"mass_added_fraction\": %.6g, \"timers_s\": {",
           sum->steps, sum->elements, sum->nodes, sum->wall_time_s, sum->energy_drift,
           sum->t_end, sum->dt_initial, sum->mass_added, sum->mass_added_fraction);
    for (int k = 0; k < FE_NSTAGE; k++)
        printf("%s\"%s\": %.4g", k ? ", " : "", fe_stage_name[k], sum->timer[k]);
    printf("}}");
}

int cli_stage3_exec(const mcs_scenario *scn, const char *out, int append, int quiet,
                    s3_summary *sum)
{
    mcs_error err = {0};
    fe_problem p = {0};
    mcs_scenario *s3 = NULL;
    *sum = (s3_summary){0};
    mcs_status st = cli_stage3_build(scn, &s3, &p, &err);
    if (!st) {
        s3_run_opts o = {.out_path = out,
                         .scenario_text = mcs_scenario_text(scn),
                         .quiet = quiet,
                         .append = append};
        st = s3_run(&p, &o, sum, &err);
    }
    fe_problem_free(&p);
    mcs_scenario_destroy(&s3);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    return 0;
}

void cli_stage3_note(const s3_summary *sum, const char *out)
{
    fprintf(stderr, "stage 3: %ld steps, %d elements, %.3g s wall, energy drift %.3g -> %s\n",
            sum->steps, sum->elements, sum->wall_time_s, sum->energy_drift, out);
    if (sum->mass_added > 0)
        fprintf(stderr, "stage 3: mass scaling added %.6g kg (%.3g %% of the model)\n",
                sum->mass_added, 100 * sum->mass_added_fraction);
}

int cli_stage3_scenario(const mcs_scenario *scn, const char *out, int quiet, int json)
{
    s3_summary sum;
    int rc = cli_stage3_exec(scn, out, 0, quiet, &sum);
    if (rc) return rc;
    if (json) {
        printf("{\"output\": ");
        cli_json_string(out);
        printf(", \"stage3\": ");
        cli_stage3_json(&sum);
        printf("}\n");
    } else if (!quiet)
        cli_stage3_note(&sum, out);
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

/* cmd_run.c: `mcrash run SCENARIO.yaml [-o OUT.h5] [--stage 1|2|3|all] [--quiet] [--json]`.
 * A scenario with an fe: block and no bodies is a stage-3 run, as is --stage 3. Otherwise
 * --stage 1 runs stage 1; --stage 2 stage 2 (as `mcrash stage2`, --motion or stage2.motion);
 * all (the default) stage 1 and, when the scenario has a stage2: block, stage 2 after it into
 * the same file (/stage1 and /stage2), its motion read from that stage-1 run (when stage 2
 * then fails, the file keeps the complete /stage1 and has no /stage2), then, when it has a
 * stage3: block, stage 3 into the same file (/stage3). Without -o the results
 * file is <scenario basename>.h5 in the current directory. */
#include "cli/cli.h"
#include "cli/cli_common.h"

#include <string.h>

int cli_run(int argc, char **argv)
{
    cli_run_args a;
    int rc = cli_parse_run_args(argc, argv, 1, &a);
    if (rc >= 0) return rc;
    mcs_scenario *scn = cli_load_scenario(a.path, &rc);
    if (!scn) return rc;
    const mcs_node *root = mcs_scenario_root(scn);
    int fe_only = mcs_node_kind(mcs_node_get(root, "fe")) == MCS_NODE_MAP &&
                  mcs_node_len(mcs_node_get(root, "bodies")) == 0;
    if (fe_only || strcmp(a.stage, "3") == 0)
        rc = cli_stage3_scenario(scn, a.out, a.quiet, a.json);
    else if (strcmp(a.stage, "2") == 0)
        rc = cli_stage2_scenario(scn, a.motion, a.out, 0, a.quiet, a.json);
    else if (strcmp(a.stage, "all") == 0)
        rc = cli_stage_all_scenario(scn, a.out, a.quiet, a.json);
    else
        rc = cli_stage1_scenario(scn, a.out, a.quiet, a.json);
    mcs_scenario_destroy(&scn);
    return rc;
}

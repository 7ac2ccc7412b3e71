/* cmd_run.c: `mcrash run SCENARIO.yaml [-o OUT.h5] [--stage 1|2|3|all] [--quiet] [--json]`.
 * A scenario with an fe: block and no bodies is a stage-3 run (handed to `mcrash stage3` with
 * the same arguments, --stage removed). Otherwise --stage 1 or all (the default) runs stage 1;
 * stage 2 is not built yet. Without -o the results file is <scenario basename>.h5 in the
 * current directory. */
#include "cli/cli.h"
#include "cli/cli_stage1.h"
#include "core/mcs_scenario.h"

#include <stdio.h>
#include <string.h>

/* argv for stage 3: "stage3" and every argument but --stage X */
static int stage3_args(int argc, char **argv, char **out)
{
    int n = 0;
    out[n++] = "stage3";
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--stage") == 0) {
            i++;
            continue;
        }
        out[n++] = argv[i];
    }
    out[n] = NULL;
    return n;
}

int cli_run(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *path = NULL, *out = NULL, *stage = "all";
    int quiet = 0, json = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0)
            json = 1;
        else if (strcmp(argv[i], "--quiet") == 0)
            quiet = 1;
        else if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
            out = argv[++i];
        else if (strcmp(argv[i], "--stage") == 0 && i + 1 < argc)
            stage = argv[++i];
        else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "mcrash run: unknown option '%s'\n", argv[i]);
            return cli_usage(argv[0]);
        } else if (path)
            return cli_usage(argv[0]);
        else
            path = argv[i];
    }
    if (!path) return cli_usage(argv[0]);
    if (strcmp(stage, "1") && strcmp(stage, "2") && strcmp(stage, "3") && strcmp(stage, "all")) {
        fprintf(stderr, "mcrash run: --stage takes 1, 2, 3 or all (got '%s')\n", stage);
        return 2;
    }
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mcs_status st = mcs_scenario_load(path, &scn, &err);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    const mcs_node *root = mcs_scenario_root(scn);
    int fe_only = mcs_node_kind(mcs_node_get(root, "fe")) == MCS_NODE_MAP &&
                  mcs_node_len(mcs_node_get(root, "bodies")) == 0;
    int rc;
    if (fe_only || strcmp(stage, "3") == 0) {
        mcs_scenario_destroy(&scn);
        char *args[argc + 2];
        int n = stage3_args(argc, argv, args);
        return cli_stage3(n, args);
    }
    if (strcmp(stage, "2") == 0) {
        rc = cli_not_built("run --stage 2", "stage 2, issue #6");
    } else {
        char def[4096];
        if (!out) cli_default_output(path, def, sizeof def), out = def;
        rc = cli_stage1_scenario(scn, out, quiet, json);
    }
    mcs_scenario_destroy(&scn);
    return rc;
}

/* cmd_check.c: `mcrash check [--json] SCENARIO.yaml` — validate a scenario; with --json print
 * it resolved (includes merged, every quantity in SI) */
#include "cli/cli.h"
#include "core/mcs_scenario.h"

#include <stdio.h>
#include <string.h>

int cli_check(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *path = NULL;
    int json = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0)
            json = 1;
        else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "mcrash check: unknown option '%s'\n", argv[i]);
            return cli_usage(argv[0]);
        } else if (path)
            return cli_usage(argv[0]);
        else
            path = argv[i];
    }
    if (!path) return cli_usage(argv[0]);
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mcs_status st = mcs_scenario_load(path, &scn, &err);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    if (json)
        st = mcs_scenario_write_json(scn, stdout);
    else
        printf("%s: ok\n", path);
    mcs_scenario_destroy(&scn);
    if (st || fflush(stdout)) {
        fprintf(stderr, "mcrash check: cannot write the output\n");
        return 2;
    }
    return 0;
}

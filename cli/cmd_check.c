/* cmd_check.c: `mcrash check [--json] SCENARIO.yaml...` — validate scenarios; with --json print
 * one resolved (includes merged, every quantity in SI); `--schema` prints the key reference */
#include "cli/cli.h"
#include "core/mcs_scenario.h"

#include <stdio.h>
#include <string.h>

/* check one file; 0 ok, else the exit status */
static int check_one(const char *path, int json)
{
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
    return st ? 2 : 0;
}

static int finish(int status)
{
    if (fflush(stdout) != 0) {
        fprintf(stderr, "mcrash check: cannot write the output\n");
        return 2;
    }
    return status;
}

int cli_check(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    int json = 0, schema = 0, nfiles = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0)
            json = 1;
        else if (strcmp(argv[i], "--schema") == 0)
            schema = 1;
        else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "mcrash check: unknown option '%s'\n", argv[i]);
            return cli_usage(argv[0]);
        } else
            nfiles++;
    }
    if (schema && nfiles == 0 && !json) return finish(mcs_schema_write_markdown(stdout) ? 2 : 0);
    if (nfiles == 0 || schema || (json && nfiles > 1)) return cli_usage(argv[0]);
    int status = 0;
    for (int i = 1; i < argc; i++) {
        if (argv[i][0] == '-' && argv[i][1]) continue;
        int s = check_one(argv[i], json);
        if (s > status) status = s;
    }
    return finish(status);
}

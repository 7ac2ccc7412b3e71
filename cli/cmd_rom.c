/* cmd_rom.c: `mcrash rom SCENARIO.yaml [-o OUT.h5] [--append] [--quiet] [--json]`: the
 * reduced-order model (rom/rom.h, docs/rom.md) of a scenario into /stage0 of a results file.
 * --append adds /stage0 to an existing file (a stage-1 run of the same scenario, so that
 * `mcrash compare OUT.h5 --stages 0,1` rates one against the other). --json prints
 * {"output": ..., "stage0": {"steps", "rhs_evals", "wall_time_s", "energy_drift"}}. */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "rom/rom.h"

#include <stdio.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int cli_rom_exec(const mcs_scenario *scn, const char *out, int append, int quiet, int json)
{
    mcs_error err = {0};
    rom_model m;
    rom_result r = {0};
    mcs_results *res = NULL;
    double t0 = now();
    mcs_status st = rom_model_from_scenario(&m, scn, &err);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    st = rom_run(&m, &r, &err);
    double wall = now() - t0;
    if (!st && append) st = mcs_results_append(&res, out, &err);
    else if (!st) st = mcs_results_create(&res, out, mcs_scenario_text(scn), &err);
    if (!st && append) st = mcs_results_remove(res, "/stage0", &err);
    if (!st) st = rom_write(&m, &r, res, &err);
    if (!st) st = mcs_results_commit(&res, &err);
    mcs_results_abort(&res);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
    } else if (json) {
        printf("{\"output\": ");
        cli_json_string(out);
        printf(", \"stage0\": {\"steps\": %ld, \"rhs_evals\": %ld, \"wall_time_s\": %.6g, "
               "\"energy_drift\": %.6g}}\n",
               r.steps, r.rhs_evals, wall, r.energy_drift);
    } else if (!quiet) {
        fprintf(stderr, "stage 0 (rom): %ld CVODE steps, %.3g s wall, energy drift %.3g -> %s\n",
                r.steps, wall, r.energy_drift, out);
    }
    rom_result_free(&r);
    rom_model_deinit(&m);
    return st ? mcs_status_exit_code(st) : (fflush(stdout) ? 2 : 0);
}

int cli_rom(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *path = NULL, *out = NULL;
    int append = 0, quiet = 0, json = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) out = argv[++i];
        else if (strcmp(argv[i], "--append") == 0) append = 1;
        else if (strcmp(argv[i], "--quiet") == 0) quiet = 1;
        else if (strcmp(argv[i], "--json") == 0) json = 1;
        else if (argv[i][0] != '-' && !path) path = argv[i];
        else return cli_usage(argv[0]);
    }
    if (!path || (append && !out)) return cli_usage(argv[0]);
    char def[4096];
    if (!out) cli_default_output(path, def, sizeof def), out = def;
    int rc;
    mcs_scenario *scn = cli_load_scenario(path, &rc);
    if (!scn) return rc;
    rc = cli_rom_exec(scn, out, append, quiet, json);
    mcs_scenario_destroy(&scn);
    return rc;
}

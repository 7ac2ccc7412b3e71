/* cmd_stage1.c: `mcrash stage1 SCENARIO.yaml [-o OUT.h5] [--quiet] [--json]`: the multibody
 * model (stage1_mb) from a scenario to a results file. Without -o the file is
 * <scenario basename>.h5 in the current directory. --json prints
 * {"output": ..., "stage1": {"steps", "bodies", "wall_time_s", "energy_drift"}}. */
#include "cli/cli.h"
#include "cli/cli_stage1.h"
#include "stage1_mb/mb_model.h"

#include <stdio.h>
#include <string.h>

void cli_default_output(const char *scenario, char *out, size_t n)
{
    const char *base = strrchr(scenario, '/');
    base = base ? base + 1 : scenario;
    size_t len = strlen(base);
    const char *ext[] = {".yaml", ".yml"};
    for (int i = 0; i < 2; i++) {
        size_t k = strlen(ext[i]);
        if (len > k && strcmp(base + len - k, ext[i]) == 0) {
            len -= k;
            break;
        }
    }
    snprintf(out, n, "%.*s.h5", (int)len, base);
}

static void json_string(const char *s)
{
    putchar('"');
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            printf("\\%c", *s);
        else if ((unsigned char)*s < 0x20)
            printf("\\u%04x", (unsigned char)*s);
        else
            putchar(*s);
    }
    putchar('"');
}

int cli_stage1_scenario(const mcs_scenario *scn, const char *out_path, int quiet, int json)
{
    mcs_error err = {0};
    mb_model *m = NULL;
    mcs_status st = mb_model_build(scn, NULL, &m, &err);
    mb_run_summary sum = {0};
    if (!st) {
        mb_run_opts o = {.out_path = out_path, .scenario_text = mcs_scenario_text(scn),
                         .quiet = quiet};
        st = mb_run(m, &o, &sum, &err);
    }
    mb_model_destroy(&m);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    if (json) {
        printf("{\"output\": ");
        json_string(out_path);
        printf(", \"stage1\": {\"steps\": %ld, \"bodies\": %d, \"wall_time_s\": %.6g, "
               "\"energy_drift\": %.6g, \"end_time_s\": %.9g, \"timers_s\": {",
               sum.steps, sum.bodies, sum.wall_time_s, sum.energy_drift, sum.t_end);
        for (int k = 0; k < MB_NTIMER; k++)
            printf("%s\"%s\": %.4g", k ? ", " : "", mb_timer_name(k), sum.timer[k]);
        printf("}}}\n");
    } else if (!quiet) {
        fprintf(stderr, "stage 1: %ld steps, %d bodies, %.3g s wall, energy drift %.3g -> %s\n",
                sum.steps, sum.bodies, sum.wall_time_s, sum.energy_drift, out_path);
    }
    return fflush(stdout) ? 2 : 0;
}

int cli_stage1(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *path = NULL, *out = NULL;
    int quiet = 0, json = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0)
            json = 1;
        else if (strcmp(argv[i], "--quiet") == 0)
            quiet = 1;
        else if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
            out = argv[++i];
        else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "mcrash %s: unknown option '%s'\n", argv[0], argv[i]);
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
    char def[4096];
    if (!out) cli_default_output(path, def, sizeof def), out = def;
    int rc = cli_stage1_scenario(scn, out, quiet, json);
    mcs_scenario_destroy(&scn);
    return rc;
}

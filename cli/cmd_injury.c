/* cmd_injury.c: `mcrash injury OUT.h5 [--stage N] [--json]`: the injury criteria of a results
 * file against their limits (the channel names are listed in analysis/an_injury.h) */
#include "analysis/an_injury.h"
#include "cli/cli.h"
#include "cli/cli_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void json_num(double v)
{
    if (isfinite(v)) printf("%.10g", v);
    else printf("null");
}

static void print_json(const char *file, int stage, const an_injury_row *r, int n)
{
    printf("{\"file\": ");
    cli_json_string(file);
    printf(", \"stage\": %d, \"criteria\": [", stage);
    for (int i = 0; i < n; i++) {
        printf("%s{\"criterion\": ", i ? ", " : "");
        cli_json_string(r[i].key);
        printf(", \"label\": ");
        cli_json_string(r[i].label);
        printf(", \"value\": ");
        json_num(r[i].value);
        printf(", \"unit\": ");
        cli_json_string(r[i].unit);
        printf(", \"limit\": ");
        json_num(r[i].limit);
        printf(", \"fraction\": ");
        json_num(r[i].fraction);
        printf(", \"t1\": ");
        json_num(r[i].t1);
        printf(", \"t2\": ");
        json_num(r[i].t2);
        printf(", \"channel\": ");
        cli_json_string(r[i].channel);
        printf(", \"cfc\": %d}", r[i].cfc);
    }
    printf("]}\n");
}

static void print_table(const char *file, int stage, const an_injury_row *r, int n)
{
    printf("%s, stage %d\n", file, stage);
    printf("%-22s %11s %-4s %9s %8s  %-21s %s\n", "criterion", "value", "unit", "limit",
           "fraction", "time [s]", "channel (CFC)");
    for (int i = 0; i < n; i++) {
        char lim[32] = "-", frac[32] = "-", when[48];
        if (isfinite(r[i].limit)) snprintf(lim, sizeof lim, "%.6g", r[i].limit);
        if (isfinite(r[i].fraction)) snprintf(frac, sizeof frac, "%.3f", r[i].fraction);
        if (r[i].t1 == r[i].t2) snprintf(when, sizeof when, "%.5f", r[i].t1);
        else snprintf(when, sizeof when, "%.5f-%.5f", r[i].t1, r[i].t2);
        printf("%-22s %11.4g %-4s %9s %8s  %-21s %s (%d)\n", r[i].label, r[i].value, r[i].unit,
               lim, frac, when, r[i].channel, r[i].cfc);
    }
}

int cli_injury(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *file = NULL;
    int stage = 0, json = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0) {
            json = 1;
        } else if (strcmp(argv[i], "--stage") == 0 && i + 1 < argc) {
            char *end;
            long s = strtol(argv[++i], &end, 10);
            if (*end || s < 1 || s > 3) {
                fprintf(stderr, "mcrash injury: --stage %s: 1, 2 or 3\n", argv[i]);
                return 2;
            }
            stage = (int)s;
        } else if (argv[i][0] == '-' || file) {
            fprintf(stderr, "mcrash injury: unexpected argument %s\n", argv[i]);
            return cli_usage(argv[0]);
        } else {
            file = argv[i];
        }
    }
    if (!file) return cli_usage(argv[0]);
    an_injury_row *rows = NULL;
    int n = 0, used = 0;
    mcs_error e = {0};
    if (an_injury_evaluate(file, stage, &rows, &n, &used, &e)) {
        fprintf(stderr, "mcrash injury: %s\n", e.msg);
        return mcs_status_exit_code(e.status);
    }
    if (n == 0) {
        fprintf(stderr,
                "mcrash injury: %s: stage %d has none of the dummy channels (head_ax/ay/az, "
                "head_wx/wy/wz, neck_fx/fz/my, chest_ax/ay/az, chest_d, pelvis_ax/ay/az, "
                "femur_left_fz, femur_right_fz, tibia_left_mx/my/fz, ...) nor a head body\n",
                file, used);
        free(rows);
        return 2;
    }
    if (json) print_json(file, used, rows, n);
    else print_table(file, used, rows, n);
    free(rows);
    return 0;
}

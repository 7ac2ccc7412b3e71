/* cmd_compare_stages.c: `mcrash compare OUT.h5 --stages A,B [--method iso18571|cora] [--json]`
 * (DESIGN.md "The command"): every channel /stageA/channels and /stageB/channels of one results
 * file share, the stage-B curve rated against the stage-A one. Prints one line per channel, or
 * {"file", "stages": [A, B], "method", "channels": {NAME: {"rating": r} or {"error": msg}}}
 * with --json. A channel that cannot be rated (a constant curve, units that differ) gets its
 * message instead of a rating; no shared channel is an error (exit 2). The ratings:
 * analysis/an_stages.c (also `mcrash loop`'s). */
#include "analysis/an_stages.h"
#include "cli/cli_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* "A,B" with A, B stage numbers 1..9 */
int cli_parse_stages(const char *s, int *a, int *b)
{
    char c;
    return s && sscanf(s, "%d,%d%c", a, b, &c) == 2 && *a >= 1 && *a <= 9 && *b >= 1 && *b <= 9;
}

int cli_compare_stages(const char *h5, int sa, int sb, int cora, int json)
{
    mcs_error err = {0};
    an_stage_rating *v = NULL;
    int n = 0;
    mcs_status st = an_stages_rate(h5, sa, sb, cora, &v, &n, &err);
    if (st) {
        fprintf(stderr, "mcrash compare: %s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    if (json) {
        printf("{\"file\": ");
        cli_json_string(h5);
        printf(", \"stages\": [%d, %d], \"method\": \"%s\", \"channels\": {", sa, sb,
               cora ? "cora" : "iso18571");
    } else {
        printf("%s: stage %d against stage %d (%s)\n", h5, sb, sa, cora ? "CORA" : "ISO/TS 18571");
    }
    for (int i = 0; i < n; i++) {
        if (json) {
            printf("%s", i ? ", " : "");
            cli_json_string(v[i].name);
            if (v[i].error[0]) {
                printf(": {\"error\": ");
                cli_json_string(v[i].error);
                printf("}");
            } else {
                printf(": {\"rating\": %.10g}", v[i].rating);
            }
        } else if (v[i].error[0]) {
            printf("  %-32s  -       %s\n", v[i].name, v[i].error);
        } else {
            printf("  %-32s  %.4f\n", v[i].name, v[i].rating);
        }
    }
    if (json) printf("}}\n");
    free(v);
    return fflush(stdout) ? 2 : 0;
}

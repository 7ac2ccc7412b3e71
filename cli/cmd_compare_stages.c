/* cmd_compare_stages.c: `mcrash compare OUT.h5 --stages A,B [--method iso18571|cora] [--json]`
 * (DESIGN.md "The command"): every channel /stageA/channels and /stageB/channels of one results
 * file share, the stage-B curve rated against the stage-A one. Prints one line per channel, or
 * {"file", "stages": [A, B], "method", "channels": {NAME: {"rating": r} or {"error": msg}}}
 * with --json. A channel that cannot be rated (a constant curve, units that differ) gets its
 * message instead of a rating; no shared channel is an error (exit 2). */
#include "analysis/an_cora.h"
#include "analysis/an_iso18571.h"
#include "analysis/an_signal.h"
#include "cli/cli_common.h"
#include "core/mcs_results.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* "A,B" with A, B stage numbers 1..9 */
int cli_parse_stages(const char *s, int *a, int *b)
{
    char c;
    return s && sscanf(s, "%d,%d%c", a, b, &c) == 2 && *a >= 1 && *a <= 9 && *b >= 1 && *b <= 9;
}

/* rate /stage<sb>/channels/name against /stage<sa>/...: *rating, or the error in err */
static mcs_status rate(const char *h5, int sa, int sb, const char *name, int cora, double *rating,
                       mcs_error *err)
{
    char ra[4200], rb[4200];
    snprintf(ra, sizeof ra, "%s:/stage%d/channels/%s", h5, sa, name);
    snprintf(rb, sizeof rb, "%s:/stage%d/channels/%s", h5, sb, name);
    an_signal a = {0}, b = {0};
    mcs_status st = an_signal_read_ref(ra, &a, err);
    if (!st) st = an_signal_read_ref(rb, &b, err);
    if (!st && a.unit[0] && b.unit[0] && strcmp(a.unit, b.unit) != 0)
        st = MCS_ERR(err, MCS_ERR_UNIT, "units differ: %s against %s", b.unit, a.unit);
    if (!st && cora) {
        an_cora_opts o = an_cora_opts_default();
        an_cora_result r;
        st = an_cora(&a, &b, &o, &r, err);
        *rating = r.rating;
    } else if (!st) {
        an_iso_opts o = an_iso_opts_default();
        an_iso_result r;
        st = an_iso18571(&a, &b, &o, &r, err);
        *rating = r.rating;
    }
    an_signal_free(&a);
    an_signal_free(&b);
    return st;
}

int cli_compare_stages(const char *h5, int sa, int sb, int cora, int json)
{
    mcs_results *r = NULL;
    mcs_error err = {0};
    char **na = NULL, **nb = NULL, ga[32], gb[32];
    int ka = 0, kb = 0;
    snprintf(ga, sizeof ga, "/stage%d/channels", sa);
    snprintf(gb, sizeof gb, "/stage%d/channels", sb);
    mcs_status st = mcs_results_open(&r, h5, &err);
    if (!st && mcs_results_kind(r, ga) != MCS_RES_GROUP)
        st = MCS_ERR(&err, MCS_ERR_FORMAT, "%s: no %s", h5, ga);
    if (!st && mcs_results_kind(r, gb) != MCS_RES_GROUP)
        st = MCS_ERR(&err, MCS_ERR_FORMAT, "%s: no %s", h5, gb);
    if (!st) st = mcs_results_list(r, ga, &na, &ka, &err);
    if (!st) st = mcs_results_list(r, gb, &nb, &kb, &err);
    mcs_results_close(&r);
    int shared = 0;
    for (int i = 0; !st && i < ka; i++) {
        int in_b = 0;
        for (int j = 0; j < kb && !in_b; j++)
            in_b = strcmp(na[i], nb[j]) == 0;
        if (!in_b) continue;
        if (json && shared == 0) {
            printf("{\"file\": ");
            cli_json_string(h5);
            printf(", \"stages\": [%d, %d], \"method\": \"%s\", \"channels\": {", sa, sb,
                   cora ? "cora" : "iso18571");
        } else if (!json && shared == 0) {
            printf("%s: stage %d against stage %d (%s)\n", h5, sb, sa,
                   cora ? "CORA" : "ISO/TS 18571");
        }
        double v = 0;
        mcs_error e = {0};
        mcs_status s2 = rate(h5, sa, sb, na[i], cora, &v, &e);
        if (json) {
            printf("%s", shared ? ", " : "");
            cli_json_string(na[i]);
            if (s2) {
                printf(": {\"error\": ");
                cli_json_string(e.msg);
                printf("}");
            } else {
                printf(": {\"rating\": %.10g}", v);
            }
        } else if (s2) {
            printf("  %-32s  -       %s\n", na[i], e.msg);
        } else {
            printf("  %-32s  %.4f\n", na[i], v);
        }
        shared++;
    }
    if (!st && shared == 0)
        st = MCS_ERR(&err, MCS_ERR_FORMAT, "%s: %s and %s share no channel", h5, ga, gb);
    if (!st && json) printf("}}\n");
    mcs_results_list_free(&na, ka);
    mcs_results_list_free(&nb, kb);
    if (st) {
        fprintf(stderr, "mcrash compare: %s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    return fflush(stdout) ? 2 : 0;
}

/* cmd_compare.c: `mcrash compare REF CMP [--method iso18571|cora] [--json]` -- objective rating
 * of one channel against another, across files and formats (file.csv[:column], file.h5:/path,
 * file.mme:channel). Prints a table, or one JSON object with --json. `mcrash compare OUT.h5
 * --stages A,B` rates every channel two stages share (cmd_compare_stages.c). */
#include <stdio.h>
#include <string.h>

#include "analysis/an_cora.h"
#include "analysis/an_iso18571.h"
#include "analysis/an_signal.h"
#include "cli/cli.h"
#include "cli/cli_common.h"

typedef enum { METHOD_ISO, METHOD_CORA } compare_method;

static void print_channel(const char *label, const char *ref, const an_signal *s)
{
    printf("%-11s %s  [%s]  %d samples, %.6g .. %.6g s\n", label, ref, s->unit[0] ? s->unit : "-",
           s->n, s->t[0], s->t[s->n - 1]);
}

static void iso_json(const char *a, const char *b, const an_iso_result *r)
{
    printf("{\"method\": \"iso18571\", \"reference\": ");
    cli_json_string(a);
    printf(", \"comparison\": ");
    cli_json_string(b);
    printf(", \"rating\": %.10g, \"grade\": \"%s\", \"corridor\": %.10g, \"phase\": %.10g, "
           "\"magnitude\": %.10g, \"slope\": %.10g, \"shift_s\": %.10g, \"magnitude_error\": "
           "%.10g, \"slope_error\": %.10g, \"samples\": %d, \"sample_rate_hz\": %.10g, "
           "\"t_start\": %.10g, \"t_end\": %.10g}\n",
           r->rating, an_iso_grade(r->rating), r->corridor, r->phase, r->magnitude, r->slope,
           r->shift_time, r->mag_error, r->slope_error, r->n, 1.0 / r->dt, r->t0,
           r->t0 + (r->n - 1) * r->dt);
}

static void iso_table(const an_iso_result *r, const an_iso_opts *o)
{
    printf("%-11s ISO/TS 18571 at %g kHz over %.6g .. %.6g s (%d samples)\n\n", "method",
           o->sample_rate / 1000, r->t0, r->t0 + (r->n - 1) * r->dt, r->n);
    printf("  %-12s %7s  %6s\n", "sub-rating", "value", "weight");
    printf("  %-12s %7.4f  %6.2f\n", "corridor", r->corridor, o->w_z);
    printf("  %-12s %7.4f  %6.2f   shift %.4g ms (correlation %.4f)\n", "phase", r->phase,
           o->w_p, r->shift_time * 1000, r->rho);
    printf("  %-12s %7.4f  %6.2f   DTW error %.4f\n", "magnitude", r->magnitude, o->w_m,
           r->mag_error);
    printf("  %-12s %7.4f  %6.2f   slope error %.4f\n", "slope", r->slope, o->w_s,
           r->slope_error);
    printf("  %-12s %7.4f           %s\n", "rating", r->rating, an_iso_grade(r->rating));
}

static void cora_json(const char *a, const char *b, const an_cora_result *r)
{
    printf("{\"method\": \"cora\", \"reference\": ");
    cli_json_string(a);
    printf(", \"comparison\": ");
    cli_json_string(b);
    printf(", \"rating\": %.10g, \"corridor\": %.10g, \"cross_correlation\": %.10g, "
           "\"phase\": %.10g, \"size\": %.10g, \"progression\": %.10g, \"shift_s\": %.10g, "
           "\"samples\": %d, \"sample_rate_hz\": %.10g, \"t_start\": %.10g, \"t_end\": %.10g}\n",
           r->rating, r->corridor, r->cross, r->phase, r->size, r->progression, r->shift_time,
           r->i_end - r->i_start + 1, 1.0 / r->dt, r->t_start, r->t_end);
}

static void cora_table(const an_cora_result *r, const an_cora_opts *o)
{
    printf("%-11s CORA (CORAplus defaults) at %g kHz, interval %.6g .. %.6g s (%d samples)\n\n",
           "method", o->sample_rate / 1000, r->t_start, r->t_end, r->i_end - r->i_start + 1);
    printf("  %-16s %7s  %6s\n", "sub-rating", "value", "weight");
    printf("  %-16s %7.4f  %6.2f\n", "corridor", r->corridor, o->g1);
    printf("  %-16s %7.4f  %6.2f\n", "cross-correlation", r->cross, o->g2);
    printf("    %-14s %7.4f  %6.2f   shift %.4g ms\n", "phase", r->phase, o->g_p,
           r->shift_time * 1000);
    printf("    %-14s %7.4f  %6.2f\n", "size", r->size, o->g_g);
    printf("    %-14s %7.4f  %6.2f   cross-correlation %.4f\n", "progression", r->progression,
           o->g_v, r->xcorr);
    printf("  %-16s %7.4f\n", "rating", r->rating);
}

/* parse the arguments; returns 0 or the usage exit status */
static int parse(int argc, char **argv, const char **a, const char **b, compare_method *m,
                 int *json, int stages[2])
{
    *a = *b = NULL;
    stages[0] = stages[1] = -1; /* -1: no --stages (0 is the reduced-order model) */
    *m = METHOD_ISO;
    *json = 0;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i], *val = NULL;
        if (strcmp(s, "--json") == 0) {
            *json = 1;
            continue;
        }
        if (strcmp(s, "--stages") == 0) {
            if (i + 1 >= argc || !cli_parse_stages(argv[i + 1], &stages[0], &stages[1])) {
                fprintf(stderr, "mcrash compare: --stages needs A,B (stage numbers, e.g. 1,2)\n");
                return 2;
            }
            i++;
            continue;
        }
        if (strncmp(s, "--method=", 9) == 0)
            val = s + 9;
        else if (strcmp(s, "--method") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "mcrash compare: --method needs a value (iso18571 or cora)\n");
                return cli_usage(argv[0]);
            }
            val = argv[++i];
        }
        if (val) {
            if (strcmp(val, "iso18571") == 0 || strcmp(val, "iso") == 0)
                *m = METHOD_ISO;
            else if (strcmp(val, "cora") == 0)
                *m = METHOD_CORA;
            else {
                fprintf(stderr, "mcrash compare: unknown method \"%s\" (iso18571 or cora)\n", val);
                return 2;
            }
            continue;
        }
        if (s[0] == '-' && s[1]) {
            fprintf(stderr, "mcrash compare: unknown option %s\n", s);
            return cli_usage(argv[0]);
        }
        if (!*a)
            *a = s;
        else if (!*b)
            *b = s;
        else {
            fprintf(stderr, "mcrash compare: one reference and one comparison only (extra: %s)\n",
                    s);
            return cli_usage(argv[0]);
        }
    }
    if (stages[0] >= 0 && (!*a || *b)) {
        fprintf(stderr, "mcrash compare: --stages takes one results file\n");
        return cli_usage(argv[0]);
    }
    if (stages[0] < 0 && (!*a || !*b)) {
        fprintf(stderr, "mcrash compare: needs a reference and a comparison channel\n");
        return cli_usage(argv[0]);
    }
    return 0;
}

static int fail(const mcs_error *err)
{
    fprintf(stderr, "mcrash compare: %s\n", err->msg);
    return mcs_status_exit_code(err->status);
}

int cli_compare(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *ra, *rb;
    compare_method method;
    int json, stages[2], rc = parse(argc, argv, &ra, &rb, &method, &json, stages);
    if (rc) return rc;
    if (stages[0] >= 0)
        return cli_compare_stages(ra, stages[0], stages[1], method == METHOD_CORA, json);

    an_signal a = {0}, b = {0};
    mcs_error err = {0};
    if (an_signal_read_ref(ra, &a, &err) || an_signal_read_ref(rb, &b, &err)) {
        an_signal_free(&a);
        an_signal_free(&b);
        return fail(&err);
    }
    if (a.unit[0] && b.unit[0] && strcmp(a.unit, b.unit) != 0) {
        MCS_ERR(&err, MCS_ERR_UNIT, "units differ: %s is in %s, %s in %s", ra, a.unit, rb, b.unit);
        an_signal_free(&a);
        an_signal_free(&b);
        return fail(&err);
    }

    mcs_status st;
    if (method == METHOD_ISO) {
        an_iso_opts o = an_iso_opts_default();
        an_iso_result r;
        st = an_iso18571(&a, &b, &o, &r, &err);
        if (!st && json) iso_json(ra, rb, &r);
        if (!st && !json) {
            print_channel("reference", ra, &a);
            print_channel("comparison", rb, &b);
            iso_table(&r, &o);
        }
    } else {
        an_cora_opts o = an_cora_opts_default();
        an_cora_result r;
        st = an_cora(&a, &b, &o, &r, &err);
        if (!st && json) cora_json(ra, rb, &r);
        if (!st && !json) {
            print_channel("reference", ra, &a);
            print_channel("comparison", rb, &b);
            cora_table(&r, &o);
        }
    }
    an_signal_free(&a);
    an_signal_free(&b);
    if (st) {
        fprintf(stderr, "mcrash compare: %s against %s: %s\n", rb, ra, err.msg);
        return mcs_status_exit_code(st);
    }
    return 0;
}

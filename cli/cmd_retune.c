/* cmd_retune.c: `mcrash retune STAGE3.h5 --scenario STAGE1.yaml [-o CURVES.yaml]
 * [--end-time T] [-j N] [--csv FILE] [--svg PREFIX] [--json]` (translators/tr_retune.h,
 * docs/retune.md): fits the stage-1 front characteristics so that stage 1 reproduces the
 * target's wall force and fork angle; writes CURVES.yaml (default: curves.yaml) and
 * /curves/<characteristic>/{loading,unloading} into STAGE3.h5; prints the parameters and the ISO/TS 18571 ratings before and after. The
 * scenario's retune: block names the characteristics and the target's datasets; -j N runs N
 * stage-1 runs at once (default: the online processors); --csv writes the compared curves
 * (target, before, after); --svg the same as two plots, PREFIX_force.svg and
 * PREFIX_angle.svg. */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "translators/tr_retune.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int usage_err(const char *msg)
{
    fprintf(stderr,
            "retune: %s\nusage: mcrash retune STAGE3.h5 --scenario STAGE1.yaml "
            "[-o CURVES.yaml] [--end-time T] [-j N] [--csv FILE] [--svg PREFIX] [--json]\n",
            msg);
    return 2;
}

static void print_text(const tr_rt_result *r, const char *out)
{
    printf("retune: %d iterations, %d stage-1 runs, stopped on %s; objective %.4g -> %.4g\n",
           r->iter, r->nfev, r->why, r->cost0, r->cost);
    for (int i = 0; i < TR_RT_NPAR; i++)
        printf("  %-20s %10.5g -> %10.5g  [%g, %g]\n", tr_rt_par_name(i), r->p0[i], r->p[i],
               r->lo[i], r->hi[i]);
    printf("ISO/TS 18571 wall force  %.3f -> %.3f\n", r->iso_force0, r->iso_force);
    printf("ISO/TS 18571 fork angle  %.3f -> %.3f\n", r->iso_angle0, r->iso_angle);
    printf("curves -> %s\n", out);
}

static void print_json(const tr_rt_result *r, const char *out)
{
    printf("{\"output\": ");
    cli_json_string(out);
    printf(", \"iterations\": %d, \"stage1_runs\": %d, \"stopped\": \"%s\", "
           "\"objective\": {\"before\": %.9g, \"after\": %.9g}, \"parameters\": {",
           r->iter, r->nfev, r->why, r->cost0, r->cost);
    for (int i = 0; i < TR_RT_NPAR; i++)
        printf("%s\"%s\": {\"before\": %.9g, \"after\": %.9g, \"lower\": %.9g, \"upper\": "
               "%.9g}",
               i ? ", " : "", tr_rt_par_name(i), r->p0[i], r->p[i], r->lo[i], r->hi[i]);
    printf("}, \"iso18571\": {\"wall_force\": {\"before\": %.6f, \"after\": %.6f}, "
           "\"fork_angle\": {\"before\": %.6f, \"after\": %.6f}}}\n",
           r->iso_force0, r->iso_force, r->iso_angle0, r->iso_angle);
}

int cli_retune(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *h5 = NULL, *out = "curves.yaml", *csv = NULL, *svg = NULL;
    tr_rt_opts o = tr_rt_opts_default();
    int json = 0, jobs = 0;
    double end_time = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--scenario") && i + 1 < argc)
            o.scenario = argv[++i];
        else if (!strcmp(a, "-o") && i + 1 < argc)
            out = argv[++i];
        else if (!strcmp(a, "--csv") && i + 1 < argc)
            csv = argv[++i];
        else if (!strcmp(a, "--svg") && i + 1 < argc)
            svg = argv[++i];
        else if (!strcmp(a, "--end-time") && i + 1 < argc) {
            char *end = NULL;
            end_time = strtod(argv[++i], &end);
            if (!end || *end || !(end_time > 0)) return usage_err("--end-time: seconds > 0");
        } else if (!strcmp(a, "-j") && i + 1 < argc) {
            char *end = NULL;
            long j = strtol(argv[++i], &end, 10);
            if (!end || *end || j < 1 || j > 64) return usage_err("-j: 1 to 64 processes");
            jobs = (int)j;
        } else if (!strcmp(a, "--json"))
            json = 1;
        else if (a[0] == '-')
            return usage_err("unknown option or missing value");
        else if (!h5)
            h5 = a;
        else
            return usage_err("one results file");
    }
    if (!h5) return usage_err("no results file");
    if (!o.scenario) return usage_err("--scenario STAGE1.yaml is required");
    mcs_error err = {0};
    tr_rt_target t = {0};
    tr_rt_base b;
    tr_rt_result r;
    mcs_status st = tr_rt_read_opts(&o, &err);
    if (end_time > 0) o.end_time = end_time; /* the option wins over retune.end_time */
    o.jobs = jobs;
    if (!st) st = tr_rt_read_target(h5, &o, &t, &err);
    if (!st) st = tr_rt_read_base(&o, &b, &err);
    if (!st) st = tr_rt_fit(&o, &b, &t, &r, &err);
    tr_rt_target_free(&t);
    if (!st) {
        FILE *f = fopen(out, "w");
        if (!f)
            st = MCS_ERR(&err, MCS_ERR_IO, "%s: cannot write", out);
        else {
            fprintf(f,
                    "# mcrash retune of %s against %s (docs/retune.md): include this file "
                    "after the motorcycle model\nmcrash: 1\n",
                    o.scenario, h5);
            tr_rt_write_yaml(f, &o, &b, r.p);
            if (fclose(f)) st = MCS_ERR(&err, MCS_ERR_IO, "%s: cannot write", out);
        }
    }
    if (!st) st = tr_rt_write_curves(h5, &o, &b, r.p, &err);
    if (!st && csv) {
        FILE *f = fopen(csv, "w");
        if (!f || tr_rt_write_csv(f, &r) || fclose(f))
            st = MCS_ERR(&err, MCS_ERR_IO, "%s: cannot write", csv);
    }
    for (int k = 0; k < 2 && !st && svg; k++) {
        char path[4096];
        snprintf(path, sizeof path, "%s_%s.svg", svg, k ? "angle" : "force");
        FILE *f = fopen(path, "w");
        if (f)
            tr_rt_write_svg(f, &r, k,
                            k ? "Fork angle: stage 1 before and after retune, and stage 3"
                              : "Wall force: stage 1 before and after retune, and stage 3");
        if (!f || ferror(f) | fclose(f)) st = MCS_ERR(&err, MCS_ERR_IO, "%s: cannot write", path);
    }
    if (!st) tr_rt_result_free(&r);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    if (json)
        print_json(&r, out);
    else
        print_text(&r, out);
    return fflush(stdout) ? 2 : 0;
}

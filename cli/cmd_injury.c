/* cmd_injury.c: `mcrash injury A.h5 [B.h5 ...] [--stage N] [--dummy SIZE] [--json]`: the
 * injury criteria of
 * results files against their limits (the channel names are listed in analysis/an_injury.h;
 * the Hybrid III size, for the Nij intercepts and limits: the file's, or --dummy, an_dummy.h);
 * with several files one column per file (the ISO 13232 pairing: conventional and concept) */
#include "analysis/an_injury.h"
#include "cli/cli.h"
#include "cli/cli_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define INJ_MAXFILES 8

/* one file's criteria */
typedef struct {
    const char *file;
    int stage;          /* the stage evaluated */
    an_dummy dummy;     /* the Hybrid III size evaluated */
    an_injury_row *row; /* (n) */
    int n;
} inj_file;

static void json_num(double v)
{
    if (isfinite(v)) printf("%.10g", v);
    else printf("null");
}

static void print_json(const char *file, int stage, an_dummy d, const an_injury_row *r, int n)
{
    printf("{\"file\": ");
    cli_json_string(file);
    printf(", \"stage\": %d, \"dummy\": \"%s\", \"criteria\": [", stage, an_dummy_name(d));
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
    printf("]}");
}

static void print_table(const char *file, int stage, an_dummy d, const an_injury_row *r, int n)
{
    if (d == AN_DUMMY_H3_50M) printf("%s, stage %d\n", file, stage);
    else printf("%s, stage %d, Hybrid III %s\n", file, stage, an_dummy_name(d));
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

/* the row of criterion key in f, NULL when that file has none */
static const an_injury_row *find_row(const inj_file *f, const char *key)
{
    for (int i = 0; i < f->n; i++)
        if (strcmp(f->row[i].key, key) == 0) return &f->row[i];
    return NULL;
}

/* one row per criterion found in any file (in the order first seen), one column per file:
 * value and fraction of the limit */
static void print_columns(const inj_file *f, int nf)
{
    printf("injury criteria, one column per file (value, fraction of the limit)\n");
    for (int k = 0; k < nf; k++) {
        printf("  [%d] %s, stage %d", k + 1, f[k].file, f[k].stage);
        if (f[k].dummy != AN_DUMMY_H3_50M) printf(", Hybrid III %s", an_dummy_name(f[k].dummy));
        printf("\n");
    }
    printf("(the limit column is file [1]'s; each fraction is of its own file's dummy's limit)\n");
    printf("%-22s %-4s %9s", "criterion", "unit", "limit");
    for (int k = 0; k < nf; k++) printf("  %18s[%d]", "", k + 1);
    printf("\n");
    for (int k = 0; k < nf; k++) {
        for (int i = 0; i < f[k].n; i++) {
            const an_injury_row *r = &f[k].row[i];
            int seen = 0;
            for (int j = 0; j < k && !seen; j++) seen = find_row(&f[j], r->key) != NULL;
            if (seen) continue;
            char lim[32] = "-";
            if (isfinite(r->limit)) snprintf(lim, sizeof lim, "%.6g", r->limit);
            printf("%-22s %-4s %9s", r->label, r->unit, lim);
            for (int j = 0; j < nf; j++) {
                const an_injury_row *q = find_row(&f[j], r->key);
                char frac[32] = "";
                if (q && isfinite(q->fraction)) snprintf(frac, sizeof frac, "(%.3f)", q->fraction);
                if (q) printf("  %11.4g %9s", q->value, frac);
                else printf("  %11s %9s", "-", "");
            }
            printf("\n");
        }
    }
}

int cli_injury(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *file[INJ_MAXFILES];
    int nfile = 0, stage = AN_STAGE_AUTO, json = 0, dummy = -1;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0) {
            json = 1;
        } else if (strcmp(argv[i], "--stage") == 0 && i + 1 < argc) {
            char *end;
            long s = strtol(argv[++i], &end, 10);
            if (*end || s < 0 || s > 3) {
                fprintf(stderr, "mcrash injury: --stage %s: 0 (rom), 1, 2 or 3\n", argv[i]);
                return 2;
            }
            stage = (int)s;
        } else if (strcmp(argv[i], "--dummy") == 0 && i + 1 < argc) {
            an_dummy d;
            if (an_dummy_parse(argv[++i], &d)) {
                fprintf(stderr, "mcrash injury: --dummy %s: one of %s\n", argv[i],
                        AN_DUMMY_CHOICES);
                return 2;
            }
            dummy = (int)d;
        } else if (argv[i][0] == '-') {
            fprintf(stderr, "mcrash injury: unexpected argument %s\n", argv[i]);
            return cli_usage(argv[0]);
        } else if (nfile == INJ_MAXFILES) {
            fprintf(stderr, "mcrash injury: at most %d files\n", INJ_MAXFILES);
            return 2;
        } else {
            file[nfile++] = argv[i];
        }
    }
    if (!nfile) return cli_usage(argv[0]);
    inj_file f[INJ_MAXFILES] = {{0}};
    int rc = 0, k;
    for (k = 0; k < nfile && !rc; k++) {
        mcs_error e = {0};
        f[k].file = file[k];
        if (an_injury_evaluate_as(file[k], stage, dummy, &f[k].row, &f[k].n, &f[k].stage,
                                  &f[k].dummy, &e)) {
            fprintf(stderr, "mcrash injury: %s\n", e.msg);
            rc = mcs_status_exit_code(e.status);
        } else if (f[k].n == 0) {
            fprintf(stderr,
                    "mcrash injury: %s: stage %d has none of the dummy channels (head_ax/ay/az, "
                    "head_wx/wy/wz, neck_fx/fz/my, chest_ax/ay/az, chest_d, pelvis_ax/ay/az, "
                    "femur_left_fz, femur_right_fz, tibia_left_mx/my/fz, ...) nor a head body\n",
                    file[k], f[k].stage);
            rc = 2;
        }
    }
    if (!rc && json && nfile == 1) {
        print_json(f[0].file, f[0].stage, f[0].dummy, f[0].row, f[0].n);
        printf("\n");
    } else if (!rc && json) {
        printf("{\"files\": [");
        for (k = 0; k < nfile; k++) {
            if (k) printf(", ");
            print_json(f[k].file, f[k].stage, f[k].dummy, f[k].row, f[k].n);
        }
        printf("]}\n");
    } else if (!rc && nfile == 1) {
        print_table(f[0].file, f[0].stage, f[0].dummy, f[0].row, f[0].n);
    } else if (!rc) {
        print_columns(f, nfile);
    }
    for (k = 0; k < nfile; k++) free(f[k].row);
    return rc;
}

/* cmd_study.c: `mcrash study STUDY.yaml [-o STUDY.h5] [-j N] [--quiet]` runs every case of a
 * design of experiments (cases in DIR = STUDY_cases/ beside the output, up to N at once) and
 * writes STUDY.h5 and STUDY.csv; `mcrash study --analyze STUDY.h5 [--json]` prints its
 * regression and ANOVA tables. The exit status is 0 when the study file is written, failed
 * cases included (their status is in it); 2 on a bad study file, before any case runs. */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "cli/study.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *path, *out, *analyze;
    int jobs, json, quiet;
    char def_out[4096];
} study_args;

static int parse_args(int argc, char **argv, study_args *a)
{
    memset(a, 0, sizeof *a);
    a->jobs = 1;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (!strcmp(s, "-o") && i + 1 < argc)
            a->out = argv[++i];
        else if (!strcmp(s, "-j") && i + 1 < argc) {
            char *end;
            long j = strtol(argv[++i], &end, 10);
            if (*end || j < 1 || j > 1024) return cli_usage(argv[0]);
            a->jobs = (int)j;
        } else if (!strcmp(s, "--analyze") && i + 1 < argc)
            a->analyze = argv[++i];
        else if (!strcmp(s, "--json"))
            a->json = 1;
        else if (!strcmp(s, "--quiet"))
            a->quiet = 1;
        else if (s[0] != '-' && !a->path)
            a->path = s;
        else
            return cli_usage(argv[0]);
    }
    if (!a->analyze == !a->path) return cli_usage(argv[0]);
    if (a->path && !a->out) {
        cli_default_output(a->path, a->def_out, sizeof a->def_out);
        a->out = a->def_out;
    }
    return -1;
}

int cli_study(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    study_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc >= 0) return rc;
    if (a.analyze) return study_analyze(a.analyze, a.json);
    if ((rc = study_mpi(argc, argv, a.path, a.out, a.jobs, a.quiet)) >= 0) return rc;
    study s;
    if ((rc = study_load(a.path, &s))) {
        study_free(&s);
        return rc;
    }
    char dir[4200];
    study_result *res = calloc((size_t)s.ncase, sizeof *res);
    rc = res ? study_cases_dir(a.out, dir, sizeof dir) : 2;
    if (!rc) rc = study_probe(&s, dir);
    if (!rc) {
        if (!a.quiet)
            fprintf(stderr, "study: %ld cases of %s, %d at once, in %s\n", s.ncase, a.path,
                    a.jobs, dir);
        study_run_cases(&s, dir, a.jobs, 0, 1, res);
        rc = study_write(&s, res, a.out);
    }
    long nfail = 0;
    for (long c = 0; res && c < s.ncase; c++)
        nfail += res[c].status != 0;
    if (!rc && !a.quiet) {
        fprintf(stderr, "study: %ld cases, %ld failed -> %s\n", s.ncase, nfail, a.out);
        study_pairs_summary(&s, res, stdout);
    }
    free(res);
    study_free(&s);
    return rc;
}

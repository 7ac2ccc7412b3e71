/* study_run.c: the cases of a study, each run in a child process (fork; the case's scenario
 * built there from the base one) into DIR/case_NNNNN.h5 with its messages in case_NNNNN.log,
 * then its responses read from that file. A failed case keeps its exit status and NaN
 * responses; the others go on. */
#include "analysis/an_injury.h"
#include "cli/cli_common.h"
#include "cli/study.h"
#include "core/mcs_results.h"

#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/wait.h>
#include <unistd.h>

static void case_file(const char *dir, long c, const char *ext, char *out, size_t n)
{
    snprintf(out, n, "%s/case_%05ld.%s", dir, c, ext);
}

/* the stages of a case's scenario, as `mcrash run --stage` runs them */
static int run_stages(const mcs_scenario *scn, const char *stage, const char *out)
{
    const mcs_node *root = mcs_scenario_root(scn);
    int fe_only = mcs_node_kind(mcs_node_get(root, "fe")) == MCS_NODE_MAP &&
                  mcs_node_len(mcs_node_get(root, "bodies")) == 0;
    int has2 = mcs_node_kind(mcs_node_get(root, "stage2")) == MCS_NODE_MAP;
    if (fe_only || !strcmp(stage, "3")) return cli_stage3_scenario(scn, out, 1, 0);
    if ((!strcmp(stage, "2") || !strcmp(stage, "all")) && has2)
        return cli_stage12_scenario(scn, out, 1, 0);
    if (!strcmp(stage, "2")) {
        fprintf(stderr, "study: stage 2 needs the scenario's stage2: block\n");
        return 2;
    }
    return cli_stage1_scenario(scn, out, 1, 0);
}

int study_case_start(const study *s, long c, const char *dir)
{
    char h5[4200], log[4200];
    case_file(dir, c, "h5", h5, sizeof h5);
    case_file(dir, c, "log", log, sizeof log);
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid != 0) return (int)pid;
    int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        dup2(fd, 1);
        dup2(fd, 2);
        close(fd);
    }
    remove(h5); /* no stale file of an earlier study is read as this case's */
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    int rc = 2;
    if (study_case_scenario(s, c, &scn, &err))
        fprintf(stderr, "%s\n", err.msg);
    else
        rc = run_stages(scn, s->stage, h5);
    mcs_scenario_destroy(&scn);
    fflush(stdout);
    fflush(stderr);
    _exit(rc);
}

/* peak |x|, max, min of a dataset, or a scalar */
static double reduce(const mcs_array *a, study_rkind k)
{
    if (k == STUDY_R_SCALAR) return a->n == 1 ? a->v[0] : NAN;
    double r = NAN;
    for (size_t i = 0; i < a->n; i++) {
        double v = k == STUDY_R_PEAK ? fabs(a->v[i]) : a->v[i];
        if (isnan(r) || (k == STUDY_R_MIN ? v < r : v > r)) r = v;
    }
    return r;
}

static int stage_number(const char *stage)
{
    return !strcmp(stage, "all") ? 0 : atoi(stage);
}

static void eval_responses(const study *s, long c, const char *h5, study_result *res)
{
    an_injury_row *rows = NULL;
    int nrow = 0, used = 0;
    mcs_error err = {0};
    for (int i = 0; i < s->nresp; i++) {
        const study_response *r = &s->r[i];
        res->v[i] = NAN;
        if (r->kind == STUDY_R_INJURY) {
            if (!rows && !nrow &&
                an_injury_evaluate(h5, stage_number(s->stage), &rows, &nrow, &used, &err))
                nrow = -1;
            for (int q = 0; q < nrow; q++)
                if (!strcasecmp(r->spec, rows[q].key) || !strcasecmp(r->spec, rows[q].label)) {
                    res->v[i] = rows[q].value;
                    snprintf(res->unit[i], STUDY_UNIT, "%s", rows[q].unit);
                }
        } else {
            mcs_array a = {0};
            mcs_results *f = NULL;
            mcs_error e2 = {0};
            if (!mcs_results_open(&f, h5, &e2) && !mcs_results_read(f, r->target, &a, &e2)) {
                res->v[i] = reduce(&a, r->kind);
                snprintf(res->unit[i], STUDY_UNIT, "%s", a.unit[0] ? a.unit : "-");
            }
            mcs_array_free(&a);
            mcs_results_close(&f);
        }
        if (isnan(res->v[i]))
            fprintf(stderr, "study: case %ld: response '%s': no value in %s\n", c, r->spec, h5);
    }
    free(rows);
}

void study_case_finish(const study *s, long c, const char *dir, int wstatus, study_result *res)
{
    char h5[4200];
    case_file(dir, c, "h5", h5, sizeof h5);
    memset(res, 0, sizeof *res);
    res->status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
    for (int i = 0; i < s->nresp; i++)
        res->v[i] = NAN;
    if (res->status == 0)
        eval_responses(s, c, h5, res);
    else
        fprintf(stderr, "study: case %ld failed (exit %d): see %s/case_%05ld.log\n", c,
                res->status, dir, c);
}

void study_run_cases(const study *s, const char *dir, int jobs, long first, long stride,
                     study_result *res)
{
    long next = first, *running = calloc((size_t)jobs, sizeof *running);
    int *pids = calloc((size_t)jobs, sizeof *pids), nrun = 0;
    if (!running || !pids) { /* out of memory: every case failed */
        for (long c = first; c < s->ncase; c += stride) {
            res[c].status = 125;
            for (int i = 0; i < s->nresp; i++) res[c].v[i] = NAN;
        }
        free(running), free(pids);
        return;
    }
    while (next < s->ncase || nrun > 0) {
        while (nrun < jobs && next < s->ncase) {
            int pid = study_case_start(s, next, dir);
            if (pid < 0) {
                res[next].status = 125; /* fork failed */
                for (int i = 0; i < s->nresp; i++) res[next].v[i] = NAN;
                fprintf(stderr, "study: case %ld: fork failed\n", next);
            } else {
                pids[nrun] = pid, running[nrun++] = next;
            }
            next += stride;
        }
        if (!nrun) break;
        int ws = 0;
        pid_t pid = wait(&ws);
        if (pid < 0) break;
        for (int q = 0; q < nrun; q++) {
            if (pids[q] != pid) continue;
            study_case_finish(s, running[q], dir, ws, &res[running[q]]);
            pids[q] = pids[nrun - 1], running[q] = running[nrun - 1], nrun--;
            break;
        }
    }
    free(running), free(pids);
}

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
    /* the reduced-order model: the study's fast stage (docs/rom.md) */
    if (!strcmp(stage, "rom")) return cli_rom_exec(scn, out, 0, 1, 0);
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
    if (!strcmp(stage, "rom")) return 0; /* /stage0 */
    return !strcmp(stage, "all") ? AN_STAGE_AUTO : atoi(stage);
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

/* a response the probe checks: a channel, body or energy series of stage 1 (of stage 0 for a
 * study of the reduced-order model; criteria need the whole run) */
static int probed(const study_response *r, int rom)
{
    static const char *const pre[] = {"/stage1/channels/", "/stage1/bodies/", "/stage1/energy/",
                                      "/stage0/channels/", "/stage0/bodies/", "/stage0/energy/"};
    for (int i = 0; r->kind != STUDY_R_INJURY && i < 3; i++)
        if (!strncmp(r->target, pre[i + 3 * rom], strlen(pre[i + 3 * rom]))) return 1;
    return 0;
}

/* a run of the base scenario cut to two time steps into DIR/probe_<pid>.h5: its datasets are
 * the cases' (the channels of a stage-1 model do not depend on the factors' values), so a
 * response naming a missing dataset fails here, before any case runs. Stage 1 only; a probe
 * that fails checks nothing (the cases report) */
int study_probe(const study *s, const char *dir)
{
    const mcs_node *root = mcs_scenario_root(s->base);
    int rom = !strcmp(s->stage, "rom");
    int stage1 = !strcmp(s->stage, "1") || rom ||
                 (!strcmp(s->stage, "all") &&
                  mcs_node_kind(mcs_node_get(root, "stage2")) != MCS_NODE_MAP);
    int any = 0;
    for (int i = 0; i < s->nresp; i++)
        any |= probed(&s->r[i], rom);
    if (!stage1 || !any || mcs_node_len(mcs_node_get(root, "bodies")) == 0) return 0;
    double dt = mcs_node_num(mcs_scenario_find(root, "simulation.time_step"));
    mcs_scn_setting set = {.path = "simulation.end_time", .num = isfinite(dt) ? 2 * dt : 1e-4,
                           .at = mcs_node_get(mcs_node_get(mcs_scenario_root(s->file), "study"),
                                              "scenario")};
    char h5[4200], log[4200];
    snprintf(h5, sizeof h5, "%s/probe_%ld.h5", dir, (long)getpid());
    snprintf(log, sizeof log, "%s/probe_%ld.log", dir, (long)getpid());
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid == 0) {
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) dup2(fd, 1), dup2(fd, 2), close(fd);
        mcs_scenario *scn = NULL;
        mcs_error err = {0};
        int rc = mcs_scenario_set(s->base, &set, 1, &scn, &err)
                     ? 2
                     : run_stages(scn, rom ? "rom" : "1", h5);
        mcs_scenario_destroy(&scn);
        _exit(rc);
    }
    int ws = 0, rc = 0;
    if (pid < 0 || waitpid(pid, &ws, 0) < 0 || !WIFEXITED(ws) || WEXITSTATUS(ws)) ws = -1;
    mcs_results *f = NULL;
    mcs_error err = {0};
    for (int i = 0; ws == 0 && i < s->nresp && !rc; i++) {
        if (!probed(&s->r[i], rom)) continue;
        if (!f && mcs_results_open(&f, h5, &err)) break;
        if (mcs_results_kind(f, s->r[i].target) != MCS_RES_DATASET) {
            mcs_node_error(s->r[i].at, &err, MCS_ERR_KEY,
                           "study.responses: no dataset %s in the results of the base scenario",
                           s->r[i].target);
            fprintf(stderr, "%s\n", err.msg);
            rc = 2;
        }
    }
    mcs_results_close(&f);
    remove(h5);
    remove(log);
    return rc;
}

/* cmd_loop.c: `mcrash loop SCENARIO.yaml [--max-iter N] [-o DIR] [-j N]` (docs/loop.md): the
 * scenario's loop: block names a stage-3 wall case, the stage-1 scenario of the same case
 * (retuned) and a stage-1/2 crash scenario. Iteration k: stage 3 of the wall case (run once,
 * k = 1: nothing in the loop changes it) -> retune (from iteration k-1's parameters) -> stage 1
 * and stage 2 (on that motion) of the crash scenario with the retuned curves merged over it (DIR/iter_<k>.h5) ->
 * ratings (stage 1 against 3 after retune, stage 2 against 1 per shared channel and body
 * component, translators/tr_stages.h) and injury criteria. Stops when no rating changes by more than the tolerance, after --max-iter, or when
 * a stage fails (its exit status), and says why in DIR/loop.json. The stages run as child
 * processes of this executable (their OpenMP threads never live in this process, whose retune
 * forks its own stage-1 runs). */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "cli/loop_log.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <libgen.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

typedef struct {
    char wall[PATH_MAX], retune[PATH_MAX], crash[PATH_MAX]; /* absolute paths */
    int max_iter;
    double tol;
} loop_cfg;

static int usage_err(const char *msg)
{
    fprintf(stderr,
            "loop: %s\nusage: mcrash loop SCENARIO.yaml [--max-iter N] [-o DIR] [-j N]\n", msg);
    return 2;
}

/* loop.<key>: a file relative to the file that names it, made absolute */
static mcs_status loop_path(const mcs_node *blk, const char *key, char *out, mcs_error *err)
{
    const mcs_node *n = mcs_node_get(blk, key);
    const char *v = mcs_node_str(n);
    char buf[PATH_MAX * 2], file[PATH_MAX];
    snprintf(file, sizeof file, "%s", mcs_node_file(n));
    if (v[0] == '/')
        snprintf(buf, sizeof buf, "%s", v);
    else
        snprintf(buf, sizeof buf, "%s/%s", dirname(file), v);
    if (!realpath(buf, out))
        return mcs_node_error(n, err, MCS_ERR_IO, "loop.%s: %s: %s", key, buf, strerror(errno));
    return MCS_OK;
}

static mcs_status read_cfg(const char *path, loop_cfg *c, mcs_error *err)
{
    mcs_scenario *scn = NULL;
    mcs_status st = mcs_scenario_load(path, &scn, err);
    if (st) return st;
    const mcs_node *blk = mcs_node_get(mcs_scenario_root(scn), "loop");
    if (!blk)
        st = MCS_ERR(err, MCS_ERR_KEY, "%s: loop: not in the scenario (docs/loop.md)", path);
    if (!st) st = loop_path(blk, "wall", c->wall, err);
    if (!st) st = loop_path(blk, "retune", c->retune, err);
    if (!st) st = loop_path(blk, "crash", c->crash, err);
    if (!st) {
        c->max_iter = (int)mcs_node_num_or(blk, "max_iter", 5);
        c->tol = mcs_node_num_or(blk, "tolerance", 0.01);
    }
    mcs_scenario_destroy(&scn);
    return st;
}

/* the crash scenario must have a stage2: block and the characteristics retune writes */
static mcs_status check_crash(const loop_cfg *c, const tr_rt_opts *o, mcs_error *err)
{
    mcs_scenario *scn = NULL;
    mcs_status st = mcs_scenario_load(c->crash, &scn, err);
    if (st) return st;
    const mcs_node *root = mcs_scenario_root(scn), *ch = mcs_node_get(root, "characteristics");
    if (!mcs_node_get(root, "stage2"))
        st = MCS_ERR(err, MCS_ERR_KEY, "%s: stage2: not in the crash scenario (the loop rates "
                     "stage 2 against stage 1)", c->crash);
    const char *need[2] = {o->tyre_char, o->fork_char};
    for (int i = 0; i < 2 && !st; i++)
        if (!mcs_node_get(ch, need[i]))
            st = MCS_ERR(err, MCS_ERR_KEY, "%s: characteristics.%s: not in the crash scenario "
                         "(retune's curves would change nothing)", c->crash, need[i]);
    mcs_scenario_destroy(&scn);
    return st;
}

/* run this executable with args (stdout to log, stderr kept); its exit status */
static int run_stage(char *const *args, const char *log)
{
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) return 2;
    exe[n] = 0;
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) return 2;
    if (pid == 0) {
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) dup2(fd, 1), close(fd);
        execv(exe, args);
        _exit(127);
    }
    int ws = 0;
    while (waitpid(pid, &ws, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
}

/* retune of iteration k (it->p from prev's when k > 1): CURVES.yaml, ratings */
static mcs_status retune(const loop_cfg *c, const char *wall_h5, const loop_iter *prev, int jobs,
                         tr_rt_opts *o, tr_rt_base *b, loop_iter *it, mcs_error *err)
{
    *o = tr_rt_opts_default();
    o->scenario = c->retune;
    o->jobs = jobs;
    mcs_status st = tr_rt_read_opts(o, err);
    if (!st && prev) {
        o->has_start = 1, o->scan = 0;
        memcpy(o->start, prev->p, sizeof o->start);
    }
    tr_rt_target t = {0};
    tr_rt_result r;
    if (!st) st = tr_rt_read_target(wall_h5, o, &t, err);
    if (!st) st = tr_rt_read_base(o, b, err);
    if (!st) st = tr_rt_fit(o, b, &t, &r, err);
    tr_rt_target_free(&t);
    if (st) return st;
    /* the compared curves beside the characteristics: curves_<k>.csv */
    char csv[sizeof it->curves + 8];
    snprintf(csv, sizeof csv, "%.*s.csv", (int)strlen(it->curves) - 5, it->curves);
    FILE *fc = fopen(csv, "w");
    int bad = !fc || tr_rt_write_csv(fc, &r);
    bad |= fc && fclose(fc);
    tr_rt_result_free(&r);
    if (bad) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot write", csv);
    memcpy(it->p, r.p, sizeof it->p);
    it->nrun = r.nfev, it->iso_force = r.iso_force, it->iso_angle = r.iso_angle;
    FILE *f = fopen(it->curves, "w");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot write", it->curves);
    fprintf(f, "# mcrash loop iteration %d: retune of %s against %s\nmcrash: 1\n", it->k,
            c->retune, wall_h5);
    tr_rt_write_yaml(f, o, b, r.p);
    return fclose(f) ? MCS_ERR(err, MCS_ERR_IO, "%s: cannot write", it->curves) : MCS_OK;
}

/* the crash scenario with the curves merged over it (its characteristics by name) */
static int write_crash(const loop_cfg *c, const char *dir, const loop_iter *it, char *out,
                       size_t n)
{
    snprintf(out, n, "%s/crash_%d.yaml", dir, it->k);
    FILE *f = fopen(out, "w");
    if (!f) return -1;
    fprintf(f, "# mcrash loop iteration %d: the crash scenario with retune's curves\n"
               "mcrash: 1\ninclude: [\"%s\", \"%s\"]\n",
            it->k, c->crash, it->curves);
    return fclose(f) ? -1 : 0;
}


typedef struct {
    const char *scenario, *dir;
    int jobs;
} loop_args;

/* the iterations; returns the exit status, *reason says why it stopped */
static int iterate(const loop_args *a, const loop_cfg *c, loop_iter *its, int *nit,
                   int *converged, char *reason, size_t nr)
{
    char wall_h5[PATH_MAX + 32], log[PATH_MAX + 32], crash[PATH_MAX + 32];
    size_t lw = strlen(c->wall);
    int rc = 0;
    mcs_error err = {0};
    if (lw > 3 && !strcmp(c->wall + lw - 3, ".h5")) { /* a stage-3 run done before */
        snprintf(wall_h5, sizeof wall_h5, "%s", c->wall);
    } else {
        snprintf(wall_h5, sizeof wall_h5, "%s/wall_stage3.h5", a->dir);
        snprintf(log, sizeof log, "%s/wall_stage3.log", a->dir);
        char *args[] = {"mcrash", "stage3", (char *)c->wall, "-o", wall_h5, "--quiet", NULL};
        printf("loop: stage 3 of %s\n", c->wall);
        fflush(stdout);
        rc = run_stage(args, log);
        if (rc) {
            snprintf(reason, nr, "stage 3 of the wall case failed (exit status %d)", rc);
            return rc;
        }
    }
    for (int k = 1; k <= c->max_iter; k++) {
        loop_iter *it = &its[k - 1], *prev = k > 1 ? &its[k - 2] : NULL;
        *it = (loop_iter){.k = k};
        *nit = k;
        snprintf(it->curves, sizeof it->curves, "%s/curves_%d.yaml", a->dir, k);
        snprintf(it->results, sizeof it->results, "%s/iter_%d.h5", a->dir, k);
        tr_rt_opts o;
        tr_rt_base b;
        mcs_status st = retune(c, wall_h5, prev, a->jobs, &o, &b, it, &err);
        if (!st) st = check_crash(c, &o, &err);
        if (st) {
            snprintf(reason, nr, "retune failed (exit status %d): %s", mcs_status_exit_code(st),
                     err.msg);
            return mcs_status_exit_code(st);
        }
        if (write_crash(c, a->dir, it, crash, sizeof crash)) {
            snprintf(reason, nr, "%s: cannot write", crash);
            return 2;
        }
        /* stage 1, then stage 2 on its motion into the same file (not run --stage all: a
         * crash scenario's stage3: block is not the loop's) */
        for (int stage = 1; stage <= 2; stage++) {
            snprintf(log, sizeof log, "%s/iter_%d_stage%d.log", a->dir, k, stage);
            char *a1[] = {"mcrash", "stage1", crash, "-o", it->results, "--quiet", NULL};
            char *a2[] = {"mcrash", "stage2",    crash, "--motion", it->results,
                          "-o",     it->results, "--quiet", NULL};
            rc = run_stage(stage == 1 ? a1 : a2, log);
            if (rc) {
                snprintf(reason, nr, "stage %d of the crash scenario failed in iteration %d "
                         "(exit status %d)", stage, k, rc);
                return rc;
            }
        }
        st = tr_rt_write_curves(it->results, &o, &b, it->p, &err);
        if (!st) st = tr_compare_stages(it->results, 1, 2, &it->cmp, &err);
        if (st) {
            snprintf(reason, nr, "rating iteration %d failed: %s", k, err.msg);
            return mcs_status_exit_code(st);
        }
        double d = prev ? loop_rating_change(prev, it) : INFINITY;
        printf("loop: iteration %d: stage 1 vs 3 wall force %.3f, fork angle %.3f; stage 2 vs 1: "
               "%d curves; %d retune runs; largest rating change %.4g\n",
               k, it->iso_force, it->iso_angle, it->cmp.nrating, it->nrun, d);
        fflush(stdout);
        if (d <= c->tol) {
            *converged = 1;
            snprintf(reason, nr, "converged: no rating changed by more than %g from iteration %d "
                     "to %d", c->tol, k - 1, k);
            return 0;
        }
        loop_log_write(a->dir, a->scenario, its, k, 0, "running");
        if (k == c->max_iter && prev)
            snprintf(reason, nr, "max-iter: %d iterations, the ratings still changed by %.4g",
                     k, d);
        else if (k == c->max_iter)
            snprintf(reason, nr, "max-iter: %d iterations, none to compare the ratings with", k);
    }
    return 0;
}

int cli_loop(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *path = NULL, *dir = NULL;
    int max_iter = 0, jobs = 0;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        char *end = NULL;
        if (!strcmp(s, "--max-iter") && i + 1 < argc) {
            max_iter = (int)strtol(argv[++i], &end, 10);
            if (!end || *end || max_iter < 1 || max_iter > 100)
                return usage_err("--max-iter: 1 to 100");
        } else if (!strcmp(s, "-j") && i + 1 < argc) {
            jobs = (int)strtol(argv[++i], &end, 10);
            if (!end || *end || jobs < 1 || jobs > 64) return usage_err("-j: 1 to 64 processes");
        } else if (!strcmp(s, "-o") && i + 1 < argc) {
            dir = argv[++i];
        } else if (s[0] == '-') {
            return usage_err("unknown option or missing value");
        } else if (!path) {
            path = s;
        } else {
            return usage_err("one scenario");
        }
    }
    if (!path) return usage_err("no scenario");
    loop_cfg c;
    mcs_error err = {0};
    mcs_status st = read_cfg(path, &c, &err);
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    if (max_iter) c.max_iter = max_iter;
    char defdir[PATH_MAX];
    if (!dir) {
        cli_default_output(path, defdir, sizeof defdir);
        size_t n = strlen(defdir);
        snprintf(defdir + n - 3, sizeof defdir - n + 3, "_loop"); /* "<name>.h5" -> "<name>_loop" */
        dir = defdir;
    }
    if (mkdir(dir, 0755) && errno != EEXIST) {
        fprintf(stderr, "loop: %s: %s\n", dir, strerror(errno));
        return 2;
    }
    loop_iter *its = calloc((size_t)c.max_iter, sizeof *its);
    if (!its) return 2;
    loop_args a = {.scenario = path, .dir = dir, .jobs = jobs};
    int nit = 0, converged = 0;
    char reason[8192] = "";
    int rc = iterate(&a, &c, its, &nit, &converged, reason, sizeof reason);
    if (loop_log_write(dir, path, its, nit, converged, reason)) {
        fprintf(stderr, "loop: %s/loop.json: cannot write\n", dir);
        rc = rc ? rc : 2;
    }
    printf("loop: %s; log %s/loop.json\n", reason, dir);
    if (rc) fprintf(stderr, "loop: %s\n", reason);
    for (int i = 0; i < nit; i++)
        loop_iter_free(&its[i]);
    free(its);
    return fflush(stdout) && !rc ? 2 : rc;
}

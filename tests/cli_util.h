/* cli_util.h: run bin/mcrash from a test and capture its exit status, stdout and stderr */
#ifndef MCS_CLI_UTIL_H
#define MCS_CLI_UTIL_H

#include "core/mcs_results.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

typedef struct {
    int status;      /* exit status, or 128+signal */
    char out[65536]; /* stdout (truncated) */
    char err[16384]; /* stderr (truncated) */
} cli_result;

static const char *cli_bin(void)
{
    const char *b = getenv("MCRASH_BIN");
    return b && *b ? b : "bin/mcrash";
}

static void cli_slurp(const char *path, char *buf, size_t n)
{
    buf[0] = 0;
    FILE *f = fopen(path, "rb");
    if (!f) return;
    size_t k = fread(buf, 1, n - 1, f);
    buf[k] = 0;
    fclose(f);
}

/* run "mcrash ARGS" (ARGS is shell text) with a 120 s guard against hangs */
static cli_result *cli_run(const char *args)
{
    static cli_result r;
    char dir[] = "/tmp/mcrash_cli_XXXXXX";
    if (!mkdtemp(dir)) {
        r.status = -1;
        return &r;
    }
    char cmd[8192], outp[64], errp[64];
    snprintf(outp, sizeof outp, "%s/out", dir);
    snprintf(errp, sizeof errp, "%s/err", dir);
    /* a hung command is stopped; the long verification runs (MCRASH_VERIFY) get an hour */
    int limit = getenv("MCRASH_VERIFY") ? 3600 : 120;
    snprintf(cmd, sizeof cmd, "timeout %d %s %s >%s 2>%s </dev/null", limit, cli_bin(), args, outp,
             errp);
    int st = system(cmd);
    if (st == -1)
        r.status = -1;
    else if (WIFEXITED(st))
        r.status = WEXITSTATUS(st);
    else
        r.status = 128 + WTERMSIG(st);
    cli_slurp(outp, r.out, sizeof r.out);
    cli_slurp(errp, r.err, sizeof r.err);
    remove(outp);
    remove(errp);
    rmdir(dir);
    return &r;
}

/* the dataset at path of results file h5 into a (zeroed, empty when it cannot be read) */
static inline void cli_read_dataset(const char *h5, const char *path, mcs_array *a)
{
    mcs_results *r = NULL;
    mcs_error err = {0};
    memset(a, 0, sizeof *a);
    if (!mcs_results_open(&r, h5, &err)) mcs_results_read(r, path, a, &err);
    mcs_results_close(&r);
}

#endif

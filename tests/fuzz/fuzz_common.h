/* fuzz_common.h: what the reader harnesses of tests/fuzz/ share (docs/reliability.md "Fuzzing").
 * Each harness fuzz_<reader>.c defines fuzz_<reader>(data, size) and, unless FUZZ_REPLAY_ALL is
 * defined, LLVMFuzzerTestOneInput calling it (libFuzzer: `make fuzz`). tests/test_fuzz_replay.c
 * includes every harness with FUZZ_REPLAY_ALL and feeds each the files of its seeds/ and
 * regress/ folders (gcc, `make test`, `make check-asan`).
 *
 * The readers take paths, so an input is written to files in one temporary folder per process
 * (removed at exit). An input may hold several files: they are separated by a line "@@@"
 * (fuzz_split); part 0 is the file the reader is given, parts 1.. are the files it may
 * include, named by the harness. The first use also silences the log (mcs_log_set_handler). */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/mcs_error.h"

#define FUZZ_MAX_PARTS 4

static char fuzz_dir_[256];

/* the readers' warnings are formatted (that code is fuzzed too) but not printed */
static void fuzz_log_(mcs_log_level lvl, const char *msg, void *user)
{
    (void)lvl, (void)msg, (void)user;
}

static void fuzz_rmdir_(void)
{
    if (!fuzz_dir_[0]) return;
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", fuzz_dir_);
    if (system(cmd) != 0) fprintf(stderr, "fuzz: cannot remove %s\n", fuzz_dir_);
}

/* the process's temporary folder (created on first use) */
static inline const char *fuzz_dir(void)
{
    if (fuzz_dir_[0]) return fuzz_dir_;
    const char *tmp = getenv("TMPDIR");
    snprintf(fuzz_dir_, sizeof fuzz_dir_, "%s/mcrash-fuzz-XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(fuzz_dir_)) {
        perror("fuzz: mkdtemp");
        abort();
    }
    atexit(fuzz_rmdir_);
    mcs_log_set_handler(fuzz_log_, NULL);
    return fuzz_dir_;
}

/* buf = the temporary folder / name */
static inline void fuzz_path(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "%s/%s", fuzz_dir(), name);
}

/* write len bytes to the temporary folder's file `name` (its folder made when it has one) */
static inline void fuzz_write(const char *name, const uint8_t *data, size_t len)
{
    char p[512];
    fuzz_path(p, sizeof p, name);
    const char *slash = strrchr(name, '/');
    if (slash) {
        char d[512];
        snprintf(d, sizeof d, "%s/%.*s", fuzz_dir(), (int)(slash - name), name);
        mkdir(d, 0700);
    }
    FILE *f = fopen(p, "wb");
    if (!f || (len && fwrite(data, 1, len, f) != len)) {
        perror(p);
        abort();
    }
    fclose(f);
}

/* remove the temporary folder's file `name` (absent: nothing) */
static inline void fuzz_unlink(const char *name)
{
    char p[512];
    fuzz_path(p, sizeof p, name);
    unlink(p);
}

/* split data at the lines "@@@" into at most FUZZ_MAX_PARTS parts (the last takes the rest);
 * returns the number of parts; part i is start[i], len[i] */
static inline int fuzz_split(const uint8_t *data, size_t size, const uint8_t **start, size_t *len)
{
    int np = 0;
    size_t from = 0;
    for (size_t i = 0; np < FUZZ_MAX_PARTS - 1 && i + 4 <= size; i++) {
        if ((i == 0 || data[i - 1] == '\n') && memcmp(data + i, "@@@\n", 4) == 0) {
            start[np] = data + from, len[np] = i - from, np++;
            from = i + 4;
            i += 3;
        }
    }
    start[np] = data + from, len[np] = size - from, np++;
    return np;
}

#endif

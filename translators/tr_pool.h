/* tr_pool.h: n independent cases run in child processes, up to `jobs` at a time (fork; each
 * child computes one case and sends its fixed-size result and error back through a pipe).
 * Every case runs in a fresh copy of the caller's process, whatever `jobs`, so the results do
 * not depend on it. For evaluations that take much longer than a fork (retune's stage-1 runs,
 * docs/retune.md "Parallel runs"). The caller must not have started OpenMP threads. */
#ifndef TR_POOL_H
#define TR_POOL_H

#include "core/mcs_error.h"

#include <stddef.h>

/* case k: fill out[nbytes]; a non-zero return fails the batch with err */
typedef mcs_status (*tr_pool_fn)(void *ctx, int k, void *out, mcs_error *err);

/* the online processors (at least 1) */
int tr_pool_cpus(void);

/* cases 0..n-1 into out[k * nbytes]; jobs < 1: tr_pool_cpus(). On failure the error of the
 * lowest failing case (a child that died: its signal or exit status) */
mcs_status tr_pool_run(tr_pool_fn fn, void *ctx, int n, size_t nbytes, void *out, int jobs,
                       mcs_error *err);

#endif

/* fe_parallel: who runs which chunk of the threaded FE loops (fe_parallel.c).
 *
 * Each thread owns one contiguous run of element chunks and one contiguous run of node
 * chunks, the same in every loop of the step and from step to step, so the stresses of its
 * elements and the positions, velocities and forces of its nodes stay in its own core's
 * caches (on a machine whose cores do not share a cache, a loop that hands chunks out
 * dynamically moves most of the state between cores every step and runs slower on 2 threads
 * than a static split). The element runs are balanced on the time each chunk took in the
 * previous step (a yielding zone costs more than an elastic one); the node runs follow the
 * elements' nodes. Which thread runs a chunk never changes a result: every chunk writes only
 * its own slots and partial sums, reduced in chunk order. */
#ifndef FE_PARALLEL_H
#define FE_PARALLEL_H

#include "fe/fe_state.h"

/* one thread's share: element chunks c0..c1-1, node chunks nc0..nc1-1 = nodes n0..n1-1 */
typedef struct {
    int c0, c1;
    int nc0, nc1;
    int n0, n1;
} fe_par_range;

/* threads for this model's loops (1 for small models, see FE_PAR_MIN_CHUNKS); updates the
 * thread shares in s (balanced on the chunk times of the last step). Call once per step,
 * outside a parallel region, before fe_par_share. */
int fe_par_team(const fe_model *m, fe_state *s);
/* share t of the current team (fe_par_team; before the first call: one thread, everything) */
void fe_par_share(const fe_model *m, const fe_state *s, int t, fe_par_range *r);

/* the calling thread's index and the team size, 0 and 1 outside a parallel region */
int fe_par_tid(void);
int fe_par_nth(void);
/* wall clock for the chunk times [s] */
double fe_par_clock(void);

#endif

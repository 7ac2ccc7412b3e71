/* mcs_progress: one updating line on stderr during a long run
 *   "stage 1  42.0 %  t 84.0 / 200.0 ms  wall 3.2 s  ETA 4.4 s"
 * shown only when the stream is a terminal (or forced) and not quiet; redrawn at most every
 * min_interval of wall time; cheap to call every step (the clock is read every check_every
 * calls only); finish prints the last line and a newline. The stream, the terminal decision
 * and the clock are injectable for tests. */
#ifndef MCS_PROGRESS_H
#define MCS_PROGRESS_H

#include <stddef.h>
#include <stdio.h>

typedef double (*mcs_clock_fn)(void *user); /* wall clock [s], any origin */

typedef struct {
    FILE *out;           /* stream; NULL means stderr                                     */
    int quiet;           /* 1: print nothing (--quiet)                                     */
    int force;           /* 1: print even when out is not a terminal (tests, logs)         */
    double min_interval; /* wall time between redraws [s]; default 0.2 (5 per second)      */
    int check_every;     /* read the clock every this many updates [-]; default 64         */
    mcs_clock_fn clock;  /* wall clock; NULL means CLOCK_MONOTONIC                         */
    void *clock_user;    /* passed to clock                                                */
    const char *label;   /* line prefix, e.g. "stage 1"; NULL for none                     */
} mcs_progress_opts;

mcs_progress_opts mcs_progress_opts_default(void);

typedef struct {
    mcs_progress_opts o; /* options (copied at start)                      */
    int active;          /* 1 when lines are printed                       */
    double t_end;        /* simulated end time [s]                         */
    double wall0;        /* wall clock at start [s]                        */
    double wall_last;    /* wall clock at the last redraw [s]              */
    int calls;           /* updates since the clock was last read [-]      */
    int width;           /* length of the line on screen [chars]           */
    long redraws;        /* lines drawn so far [-]                         */
} mcs_progress;

void mcs_progress_start(mcs_progress *p, const mcs_progress_opts *o, double t_end);
/* call every step with the simulated time [s] */
void mcs_progress_update(mcs_progress *p, double t_sim);
/* last line (at t_sim) and a newline; nothing when inactive */
void mcs_progress_finish(mcs_progress *p, double t_sim);

/* the text of one line (no '\r'): fraction [-], simulated times [s], wall and ETA [s]
 * (eta < 0: unknown); returns the length as snprintf */
int mcs_progress_format(char *buf, size_t n, const char *label, double frac, double t_sim,
                        double t_end, double wall, double eta);

#endif

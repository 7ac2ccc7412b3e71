/* mcs_interrupt: how a run ends other than by reaching its end time (issue 18 item 4;
 * docs/reliability.md "Interrupts and failures", docs/contracts.md).
 *
 * Interrupts: the command line installs handlers for SIGINT and SIGTERM (mcs_interrupt_install).
 * The first signal only sets a flag; the time loops (stage1_mb/mb_run.c for stages 1 and 2,
 * stage3_fe/s3_run.c) look at it before each step, so the step under way finishes, then write
 * the results file up to that time with /meta attribute status = "interrupted" and return
 * MCS_INTERRUPTED (exit status 130). A second signal ends the process at once (exit 130) after
 * removing every results temporary still open (mcs_results registers them here), so no partial
 * file is left; an earlier OUT.h5 stays as it was.
 *
 * Failure records: a numerical failure (MCS_ERR_NUMERIC: exit 1, no results file) also leaves
 * OUT.h5.failure.txt, a few "key: value" lines (mcs_failure_record_write). */
#ifndef MCS_INTERRUPT_H
#define MCS_INTERRUPT_H

#include "core/mcs_error.h"

#include <stddef.h>

/* SIGINT and SIGTERM handlers as above (the CLI; a library user may install its own and call
 * mcs_interrupt_request) */
void mcs_interrupt_install(void);
/* the signal that asked the run to stop (SIGINT, SIGTERM, -1 for mcs_interrupt_request), or 0 */
int mcs_interrupt_pending(void);
/* ask the running loop to stop after its current step (async-signal-safe) */
void mcs_interrupt_request(void);
/* forget a request (a library user starting the next run) */
void mcs_interrupt_clear(void);

/* a temporary file a second signal removes: returns its slot (-1 when the table of
 * MCS_INTERRUPT_MAXTMP is full: the file is then not removed); path is copied */
#define MCS_INTERRUPT_MAXTMP 16
int mcs_interrupt_track(const char *path);
void mcs_interrupt_untrack(int slot);

/* the failure record OUT.h5.failure.txt beside the output out_path:
 *   mcrash failure record
 *   stage: 3
 *   time_s: 0.0123
 *   step: 1234
 *   where: element 17 (or body head, or the message's first part)
 *   message: <err->msg>
 *   energy_<name>_J: value (n of them)
 * Any earlier record of that name is replaced. Returns 0, or -1 when it cannot be written. */
int mcs_failure_record_write(const char *out_path, int stage, double time, long step,
                             const char *where, const char *message, const char *const *names,
                             const double *energies, int n);
/* the record's file name for out_path into buf; -1 when buf is too small */
int mcs_failure_record_path(const char *out_path, char *buf, size_t n);
/* the place a failure message names, for the record's `where`: "part 'P' element N",
 * "element N", "node N", "body B" (the first of these found in msg), else "" */
void mcs_failure_where(const char *msg, char *buf, size_t n);
/* remove the record of out_path (a run that ended well removes an earlier failure's record) */
void mcs_failure_record_remove(const char *out_path);

#endif

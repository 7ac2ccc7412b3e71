/* tr_mme: the channels of a results file as ISO-MME (ISO/TS 13499) tests, one per stage
 * (`mcrash export OUT.h5 --mme DIR`). Stage N becomes DIR/stageN/stageN.mme with
 * DIR/stageN/Channel/stageN.chn and one channel file stageN.NNN per /stageN/channels/<name>, in
 * the order of the results file: `Name of the channel` and `Channel code` are the name, `Unit`
 * its SI unit, `Channel frequency class` its cfc (NOVALUE when 0), `Reference system` its frame
 * attribute ("SAE J211 local", ...), `Direction` X/Y/Z from a name ending in x, y or z, R for a
 * resultant (ending in _r, _res or _resultant), else 0; time from /stageN/time (uniform
 * sampling required). Everything is read and checked before anything is written; a write that
 * fails removes what this call wrote. docs/signals.md. */
#ifndef TR_MME_H
#define TR_MME_H

#include "core/mcs_results.h"

/* stage 0: every stage that has channels; else that stage only (MCS_ERR_KEY when it has no
 * channels). *nstages and *nchannels (may be NULL): what was written. */
mcs_status tr_mme_export(mcs_results *r, const char *dir, int stage, int *nstages, int *nchannels,
                         mcs_error *err);

#endif

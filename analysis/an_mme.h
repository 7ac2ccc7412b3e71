/* an_mme.h: ISO/TS 13499 (ISO-MME) channels, read and write.
 * Layout: DIR/TEST.mme (test header), DIR/Channel/TEST.chn (channel list,
 * "Name of channel 001 :CODE / description"), DIR/Channel/TEST.001 ... (one file per channel:
 * "key :value" header lines, then one value per line). The channel header keys used are
 * `Name of the channel`, `Channel code`, `Unit`, `Channel frequency class`,
 * `Time of first sample` [s], `Sampling interval` [s] and `Number of samples`. */
#ifndef AN_MME_H
#define AN_MME_H

#include "analysis/an_signal.h"

/* read one channel of the test whose .mme file is `mme_path`; `channel` is the channel number
 * ("1", "001"), its channel code, or its name; values converted to SI */
mcs_status an_mme_read_channel(const char *mme_path, const char *channel, an_signal *out,
                               mcs_error *err);

/* read one channel file (DIR/Channel/TEST.NNN) */
mcs_status an_mme_read_file(const char *chan_path, an_signal *out, mcs_error *err);

/* write n channels as test `test` under directory `dir` (created if missing); every channel
 * must be uniformly sampled. Nothing is written when a channel is rejected. */
mcs_status an_mme_write(const char *dir, const char *test, const an_signal *ch, int n,
                        mcs_error *err);

/* a channel's axes for the channel file: `Reference system` (the frame's text, "" NOVALUE) and
 * `Direction` (X, Y, Z, R for a resultant, 0 for none) */
typedef struct {
    char frame[64];
    char direction;
} an_mme_axes;

/* the checks an_mme_write makes before writing: 1..999 channels, each of >= 2 uniform samples,
 * a unit that reads back as itself */
mcs_status an_mme_check(const an_signal *ch, int n, mcs_error *err);

/* an_mme_write with axes[c] (may be NULL) written into channel c's file */
mcs_status an_mme_write_axes(const char *dir, const char *test, const an_signal *ch,
                             const an_mme_axes *axes, int n, mcs_error *err);

#endif

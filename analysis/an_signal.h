/* an_signal.h: a sampled channel and the readers that bring channels in from files.
 * Shared by every analysis command (signal, injury, compare). Values are in SI. */
#ifndef AN_SIGNAL_H
#define AN_SIGNAL_H

#include <stddef.h>

#include "core/mcs_error.h"

/* one channel: n samples of y at times t (not necessarily uniform) */
typedef struct {
    char name[64];  /* channel name (CSV header without the unit, MME channel name, dataset) */
    char unit[16];  /* SI unit after conversion ("m/s^2", "N", "N*m", "m", "rad/s", "-") */
    int cfc;        /* filter class applied, 0 = unfiltered */
    int n;          /* number of samples */
    double *t;      /* time [s] (n), owned */
    double *y;      /* value [unit] (n), owned */
} an_signal;

void an_signal_free(an_signal *s); /* frees t and y, zeroes the struct */

/* read every data column of a CSV file (header line `time, name [unit], ...`; first column time
 * in s; units such as [g], [m/s^2], [kN], [N*m], [deg/s] converted to SI). *cols is an array of
 * *ncols signals, freed with an_signals_free. */
mcs_status an_csv_read(const char *path, an_signal **cols, int *ncols, mcs_error *err);
void an_signals_free(an_signal **cols, int ncols);

/* read one channel named by a reference: "file.csv[:column]", "file.h5:/path/to/dataset",
 * "file.mme:channel" (ISO/TS 13499). */
mcs_status an_signal_read_ref(const char *ref, an_signal *out, mcs_error *err);

/* deep copy of a channel (dst owns new arrays) */
mcs_status an_signal_copy(const an_signal *src, an_signal *dst, mcs_error *err);

/* index of the column named `name` (exact match first, then case-insensitive), or -1 */
int an_signal_find(const an_signal *cols, int ncols, const char *name);

#endif

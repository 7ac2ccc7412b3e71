/* fuzz_csv.c: the CSV channel reader (analysis/an_signal.c an_csv_read: header, units, rows) and a
 * column reference to it ("file.csv:column", an_signal_read_ref). Input: one CSV file. */
#include "analysis/an_signal.h"
#include "tests/fuzz/fuzz_common.h"

static int fuzz_csv(const uint8_t *data, size_t size)
{
    fuzz_write("c.csv", data, size);
    char p[512], ref[600];
    fuzz_path(p, sizeof p, "c.csv");
    an_signal *cols = NULL;
    int ncols = 0;
    mcs_error err = {0};
    if (an_csv_read(p, &cols, &ncols, &err) == MCS_OK) an_signals_free(&cols, ncols);
    an_signal s;
    snprintf(ref, sizeof ref, "%s:2", p);
    mcs_error e2 = {0};
    if (an_signal_read_ref(ref, &s, &e2) == MCS_OK) an_signal_free(&s);
    return 0;
}

#ifndef FUZZ_REPLAY_ALL
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_csv(data, size); }
#endif

/* fuzz_mme.c: the ISO-MME (ISO/TS 13499) channel reader (analysis/an_mme.c). Input: the channel
 * files T.001, then after "@@@" lines T.002 and T.003 of a test m/T.mme; read by number and by
 * name (the search through every channel file). */
#include "analysis/an_mme.h"
#include "tests/fuzz/fuzz_common.h"

static int fuzz_mme(const uint8_t *data, size_t size)
{
    static const char *const names[3] = {"m/Channel/T.001", "m/Channel/T.002",
                                         "m/Channel/T.003"};
    const uint8_t *part[FUZZ_MAX_PARTS];
    size_t len[FUZZ_MAX_PARTS];
    int np = fuzz_split(data, size, part, len);
    if (np > 3) np = 3;
    fuzz_write("m/T.mme", (const uint8_t *)"", 0);
    for (int i = 0; i < 3; i++) {
        if (i < np)
            fuzz_write(names[i], part[i], len[i]);
        else
            fuzz_unlink(names[i]);
    }
    char p[512];
    fuzz_path(p, sizeof p, "m/T.mme");
    static const char *const sel[] = {"1", "HEAD", "11CHST0000H3ACXC"};
    for (int i = 0; i < 3; i++) {
        an_signal s;
        mcs_error err = {0};
        if (an_mme_read_channel(p, sel[i], &s, &err) == MCS_OK) an_signal_free(&s);
    }
    return 0;
}

#ifndef FUZZ_REPLAY_ALL
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_mme(data, size); }
#endif

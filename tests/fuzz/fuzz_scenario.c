/* fuzz_scenario.c: the scenario reader (core/mcs_scn_*.c: YAML, includes, schema, units).
 * Input: main.yaml, then after "@@@" lines a.yaml, b.yaml and parts/c.yaml, which it may
 * include (tests/fuzz/fuzz_common.h). */
#include "core/mcs_scenario.h"
#include "tests/fuzz/fuzz_common.h"

static int fuzz_scenario(const uint8_t *data, size_t size)
{
    static const char *const names[FUZZ_MAX_PARTS] = {"s/main.yaml", "s/a.yaml", "s/b.yaml",
                                                      "s/parts/c.yaml"};
    const uint8_t *part[FUZZ_MAX_PARTS];
    size_t len[FUZZ_MAX_PARTS];
    int np = fuzz_split(data, size, part, len);
    for (int i = 0; i < FUZZ_MAX_PARTS; i++) {
        if (i < np)
            fuzz_write(names[i], part[i], len[i]);
        else
            fuzz_unlink(names[i]);
    }
    char p[512];
    fuzz_path(p, sizeof p, names[0]);
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load(p, &scn, &err) == MCS_OK) {
        /* a loaded scenario is usable: copy it and destroy both */
        mcs_scenario *copy = NULL;
        mcs_error e2 = {0};
        if (mcs_scenario_merged(scn, "stage2.fe", "fe", &copy, &e2) == MCS_OK)
            mcs_scenario_destroy(&copy);
        mcs_scenario_destroy(&scn);
    }
    return 0;
}

#ifndef FUZZ_REPLAY_ALL
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_scenario(data, size); }
#endif

/* fuzz_results.c: the results-file (HDF5) reader used for motion input (translators/tr_motion.c
 * over core/mcs_results_io.c) and for dataset references ("X.h5:/stage1/channels/head_ax",
 * an_signal_read_ref). Input: one HDF5 file. After each input no HDF5 object may stay open
 * (state that would leak into the next input). */
#include <hdf5.h>

#include "analysis/an_signal.h"
#include "tests/fuzz/fuzz_common.h"
#include "translators/tr_motion.h"

static int fuzz_results(const uint8_t *data, size_t size)
{
    fuzz_write("r.h5", data, size);
    char p[512], ref[600];
    fuzz_path(p, sizeof p, "r.h5");
    for (int method = 0; method < 2; method++) {
        tr_motion *m = NULL;
        mcs_error err = {0};
        if (tr_motion_open(&m, p, NULL, 0, method ? TR_MOTION_PULSE : TR_MOTION_POSE, &err))
            continue;
        double t0, t1;
        int nt;
        tr_motion_span(m, &t0, &t1, &nt);
        for (int b = 0; b < tr_motion_nbody(m); b++)
            for (int k = 0; k <= 4; k++) {
                tr_motion_kin kin;
                mcs_error e2 = {0};
                tr_motion_eval(m, b, t0 + 0.25 * k * (t1 - t0), &kin, &e2);
            }
        tr_motion_destroy(&m);
    }
    snprintf(ref, sizeof ref, "%s:/stage1/channels/head_ax", p);
    an_signal s;
    mcs_error e3 = {0};
    if (an_signal_read_ref(ref, &s, &e3) == MCS_OK) an_signal_free(&s);
    if (H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) > 0) {
        fprintf(stderr, "fuzz_results: HDF5 objects left open\n");
        abort();
    }
    H5garbage_collect(); /* HDF5's free lists back to malloc: memory stays flat */
    return 0;
}

#ifndef FUZZ_REPLAY_ALL
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_results(data, size); }
#endif

/* fuzz_obj.c: the Wavefront OBJ reader of facet surfaces (core/mcs_obj.c). Input: one OBJ file. */
#include "core/mcs_obj.h"
#include "tests/fuzz/fuzz_common.h"

static int fuzz_obj(const uint8_t *data, size_t size)
{
    fuzz_write("o.obj", data, size);
    char p[512];
    fuzz_path(p, sizeof p, "o.obj");
    mcs_obj_mesh m = {0};
    mcs_error err = {0};
    if (mcs_obj_read(p, &m, &err) == MCS_OK) {
        /* every index the reader returns is a vertex it returns */
        for (int i = 0; i < 3 * m.ntri; i++)
            if (m.tri[i] < 0 || m.tri[i] >= m.nvert) abort();
        mcs_obj_free(&m);
    }
    return 0;
}

#ifndef FUZZ_REPLAY_ALL
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_obj(data, size); }
#endif

/* fuzz_keyword.c: the keyword deck reader (fe/keyword/: files, *INCLUDE, fields, cards) and the
 * deck's translation into an FE model (fe_kw_add_deck). Input: main.k, then after "@@@" lines
 * a.k, b.k and inc/c.k, which it may *INCLUDE (tests/fuzz/fuzz_common.h). */
#include "fe/fe_keyword.h"
#include "fe/fe_model.h"
#include "tests/fuzz/fuzz_common.h"

static int fuzz_keyword(const uint8_t *data, size_t size)
{
    static const char *const names[FUZZ_MAX_PARTS] = {"k/main.k", "k/a.k", "k/b.k", "k/inc/c.k"};
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
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    fe_kw_deck *dk = NULL;
    mcs_error err = {0};
    if (fe_kw_read(p, &o, &dk, &err) == MCS_OK) {
        fe_builder *b = NULL;
        mcs_error e2 = {0};
        if (fe_builder_create(&b, &e2) == MCS_OK) {
            fe_kw_add_deck(b, dk, &e2);
            fe_builder_destroy(&b);
        }
        fe_kw_deck_destroy(&dk);
    }
    return 0;
}

#ifndef FUZZ_REPLAY_ALL
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_keyword(data, size); }
#endif

/* mb_initial.c: the surface pairs that penetrate at t = 0 (see mb_initial.h). */
#include "stage1_mb/mb_initial.h"
#include "core/mcs_hysteresis.h"

#include <stdlib.h>

static int deeper_first(const void *a, const void *b)
{
    double da = ((const mb_initial_pen *)a)->depth, db = ((const mb_initial_pen *)b)->depth;
    return (da < db) - (da > db);
}

mcs_status mb_initial_penetrations(const mb_model *m, double min_depth, mb_initial_pen **out,
                                   int *n, mcs_error *err)
{
    *out = NULL, *n = 0;
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, err);
    if (st) return st;
    /* the pair geometry of the initial poses, as the first step sees it */
    mb_contact_detect(m, s);
    mb_initial_pen *p = m->npair ? malloc(sizeof *p * (size_t)m->npair) : NULL;
    if (m->npair && !p) {
        mb_state_destroy(&s);
        return MCS_ERR(err, MCS_ERR_NOMEM, "initial penetrations: out of memory");
    }
    int k = 0;
    for (int i = 0; i < m->npair; i++) {
        double d = s->pc[i].depth;
        if (!(d > min_depth)) continue;
        mcs_hyst_state h;
        mcs_hyst_reset(&m->pair[i].hyst, &h);
        p[k++] = (mb_initial_pen){i, d, mcs_hyst_update(&m->pair[i].hyst, &h, d)};
    }
    mb_state_destroy(&s);
    if (k == 0) {
        free(p);
        return MCS_OK;
    }
    qsort(p, (size_t)k, sizeof *p, deeper_first);
    *out = p, *n = k;
    return MCS_OK;
}

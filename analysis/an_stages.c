/* an_stages.c: the channels two stages of a results file share, rated (an_stages.h) */
#include "analysis/an_stages.h"

#include "analysis/an_cora.h"
#include "analysis/an_iso18571.h"
#include "analysis/an_signal.h"
#include "core/mcs_results.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* rate /stage<sb>/channels/name against /stage<sa>/...: *rating, or the error in err */
static mcs_status rate(const char *h5, int sa, int sb, const char *name, int cora, double *rating,
                       mcs_error *err)
{
    char ra[4200], rb[4200];
    snprintf(ra, sizeof ra, "%s:/stage%d/channels/%s", h5, sa, name);
    snprintf(rb, sizeof rb, "%s:/stage%d/channels/%s", h5, sb, name);
    an_signal a = {0}, b = {0};
    mcs_status st = an_signal_read_ref(ra, &a, err);
    if (!st) st = an_signal_read_ref(rb, &b, err);
    if (!st && a.unit[0] && b.unit[0] && strcmp(a.unit, b.unit) != 0)
        st = MCS_ERR(err, MCS_ERR_UNIT, "units differ: %s against %s", b.unit, a.unit);
    if (!st && cora) {
        an_cora_opts o = an_cora_opts_default();
        an_cora_result r;
        st = an_cora(&a, &b, &o, &r, err);
        *rating = r.rating;
    } else if (!st) {
        an_iso_opts o = an_iso_opts_default();
        an_iso_result r;
        st = an_iso18571(&a, &b, &o, &r, err);
        *rating = r.rating;
    }
    an_signal_free(&a);
    an_signal_free(&b);
    return st;
}

mcs_status an_stages_rate(const char *h5, int sa, int sb, int cora, an_stage_rating **out, int *n,
                          mcs_error *err)
{
    *out = NULL, *n = 0;
    mcs_results *r = NULL;
    char **na = NULL, **nb = NULL, ga[32], gb[32];
    int ka = 0, kb = 0;
    snprintf(ga, sizeof ga, "/stage%d/channels", sa);
    snprintf(gb, sizeof gb, "/stage%d/channels", sb);
    mcs_status st = mcs_results_open(&r, h5, err);
    if (!st && mcs_results_kind(r, ga) != MCS_RES_GROUP)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: no %s", h5, ga);
    if (!st && mcs_results_kind(r, gb) != MCS_RES_GROUP)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: no %s", h5, gb);
    if (!st) st = mcs_results_list(r, ga, &na, &ka, err);
    if (!st) st = mcs_results_list(r, gb, &nb, &kb, err);
    mcs_results_close(&r);
    an_stage_rating *v = st || ka == 0 ? NULL : calloc((size_t)ka, sizeof *v);
    if (!st && ka > 0 && !v) st = MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    int k = 0;
    for (int i = 0; !st && i < ka; i++) {
        int in_b = 0;
        for (int j = 0; j < kb && !in_b; j++)
            in_b = strcmp(na[i], nb[j]) == 0;
        if (!in_b) continue;
        mcs_error e = {0};
        snprintf(v[k].name, sizeof v[k].name, "%s", na[i]);
        if (rate(h5, sa, sb, na[i], cora, &v[k].rating, &e)) {
            v[k].rating = NAN;
            snprintf(v[k].error, sizeof v[k].error, "%s", e.msg);
        }
        k++;
    }
    if (!st && k == 0)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s and %s share no channel", h5, ga, gb);
    mcs_results_list_free(&na, ka);
    mcs_results_list_free(&nb, kb);
    if (st) {
        free(v);
        return st;
    }
    *out = v, *n = k;
    return MCS_OK;
}

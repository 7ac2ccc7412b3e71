/* s2_energy.h: the energy balance of a stage-2 results file (issue 13 item 5; the 2023 paper's
 * Eq. 9, seed 001 Sec. 2.4: E_total = kinetic + internal + potential + contact + sliding
 * interface + hourglass, LS-DYNA's balance of a model or a set of parts), read from the file
 * alone (docs/contracts.md layout), for tests/test_s2_concept.c and tests/test_stage2_verify.c:
 * - the whole model, /stageN/energy: the written total is kinetic + potential + internal (FE
 *   hourglass and eroded energy included) + contact + dissipated - external_work (the work of
 *   the prescribed bodies on the rest: they are moved from outside) at every row, and its
 *   largest distance from its t = 0 value, over the reference energy: the largest
 *   kinetic + internal + contact of the run (the engine's own reference, stage1_mb/mb_energy.c,
 *   recomputed here from the datasets);
 * - the rider, /stageN/energy_groups/rider: each partner's transfer contact/<partner> (each
 *   belt, the bag, each foam part, pad and panel, each stage-1 contact and attachment) and
 *   their sum by category add up to contact_total, and kinetic + potential + internal +
 *   contact_total stays at its t = 0 value (Eq. 9 for the set of the rider's bodies) over the
 *   rider's initial energy. */
#ifndef S2_ENERGY_H
#define S2_ENERGY_H

#include "core/mcs_results.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* tolerances (measured and justified in docs/validation_stage2.md "Energy balance") */
#define S2_ENERGY_TOL 0.006 /* the model's drift over its reference [-] */
#define S2_RIDER_TOL 5e-5   /* the rider's balance over its initial energy [-] */

typedef struct {
    double sum_err;      /* largest |total - (K + P + I + C + D - W)| over the reference [-]  */
    double drift;        /* largest |total(t) - total(0)| over the reference [-]               */
    double ref;          /* the reference: largest K + I + C [J]                               */
    double rider_e0;     /* the rider's initial kinetic + potential [J]                        */
    double rider_drift;  /* largest |rider total(t) - total(0)| over rider_e0 [-]              */
    double partner_err;  /* largest |sum of partners - contact_total| over rider_e0 [-]        */
    double category_err; /* |sum by category - contact_total| at the end over rider_e0 [-]     */
    int npartner;        /* the rider's partners [-]                                           */
} s2_energy;

static inline int s2e_read(mcs_results *r, const char *path, mcs_array *a)
{
    mcs_error e = {0};
    if (mcs_results_read(r, path, a, &e)) {
        fprintf(stderr, "%s: %s\n", path, e.msg);
        return -1;
    }
    return 0;
}

/* the balance of /stage<stage> of `file`; 0 on success, -1 a dataset missing */
static inline int s2_energy_read(const char *file, int stage, s2_energy *out)
{
    static const char *const kind[7] = {"kinetic",    "potential",     "internal", "contact",
                                        "dissipated", "external_work", "total"};
    memset(out, 0, sizeof *out);
    mcs_results *r = NULL;
    mcs_error e = {0};
    if (mcs_results_open(&r, file, &e)) return -1;
    mcs_array a[7] = {{0}};
    int bad = 0;
    char p[256];
    for (int k = 0; k < 7 && !bad; k++) {
        snprintf(p, sizeof p, "/stage%d/energy/%s", stage, kind[k]);
        bad = s2e_read(r, p, &a[k]) || a[k].n != a[0].n || a[k].n < 2;
    }
    if (!bad) {
        size_t n = a[0].n;
        for (size_t t = 0; t < n; t++)
            out->ref = fmax(out->ref, a[0].v[t] + a[2].v[t] + a[3].v[t]);
        for (size_t t = 0; t < n; t++) {
            double sum = a[0].v[t] + a[1].v[t] + a[2].v[t] + a[3].v[t] + a[4].v[t] - a[5].v[t];
            out->sum_err = fmax(out->sum_err, fabs(a[6].v[t] - sum) / out->ref);
            out->drift = fmax(out->drift, fabs(a[6].v[t] - a[6].v[0]) / out->ref);
        }
    }
    for (int k = 0; k < 7; k++)
        mcs_array_free(&a[k]);
    /* the rider */
    static const char *const rk[4] = {"kinetic", "potential", "internal", "contact_total"};
    mcs_array g[4] = {{0}};
    for (int k = 0; k < 4 && !bad; k++) {
        snprintf(p, sizeof p, "/stage%d/energy_groups/rider/%s", stage, rk[k]);
        bad = s2e_read(r, p, &g[k]) || g[k].n != g[0].n || g[k].n < 2;
    }
    char **names = NULL;
    int np = 0;
    snprintf(p, sizeof p, "/stage%d/energy_groups/rider/contact", stage);
    if (!bad && mcs_results_list(r, p, &names, &np, &e)) bad = 1;
    if (!bad) {
        size_t n = g[0].n;
        double *sum = calloc(n, sizeof *sum), cat_sum = 0;
        out->rider_e0 = g[0].v[0] + g[1].v[0];
        out->npartner = np;
        /* the categories the partners carry (docs/contracts.md, mb_egroup*.c) */
        static const char *const cats[9] = {"belts", "airbags",   "foam",  "fe",    "cockpit",
                                            "motorcycle", "opponent", "ground", "bodies"};
        for (int i = 0; i < np && sum && !bad; i++) {
            char q[320], *c = NULL;
            mcs_array c1 = {0};
            snprintf(q, sizeof q, "%s/%s", p, names[i]);
            bad = s2e_read(r, q, &c1) || c1.n != n;
            for (size_t t = 0; t < n && !bad; t++)
                sum[t] += c1.v[t];
            if (!bad && !mcs_results_attr_str(r, q, "category", &c, &e))
                for (int k = 0; k < 9; k++)
                    if (!strcmp(c, cats[k])) cat_sum += c1.v[n - 1];
            free(c);
            mcs_array_free(&c1);
        }
        for (size_t t = 0; t < n && sum && !bad; t++) {
            double tot = g[0].v[t] + g[1].v[t] + g[2].v[t] + g[3].v[t];
            double tot0 = g[0].v[0] + g[1].v[0] + g[2].v[0] + g[3].v[0];
            out->rider_drift = fmax(out->rider_drift, fabs(tot - tot0) / out->rider_e0);
            out->partner_err = fmax(out->partner_err, fabs(sum[t] - g[3].v[t]) / out->rider_e0);
        }
        if (!bad) out->category_err = fabs(cat_sum - g[3].v[n - 1]) / out->rider_e0;
        if (!sum) bad = 1;
        free(sum);
    }
    mcs_results_list_free(&names, np);
    for (int k = 0; k < 4; k++)
        mcs_array_free(&g[k]);
    mcs_results_close(&r);
    return bad ? -1 : 0;
}

#endif

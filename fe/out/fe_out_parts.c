/* fe_out_parts: per-part energies (element and spring parts) into /stage<N> (fe_out_parts.h) */
#include "fe/out/fe_out_parts.h"

#include <stdio.h>
#include <stdlib.h>

static const fe_energy_kind kinds[FE_OUT_PART_KINDS] = {FE_E_kinetic, FE_E_internal, FE_E_contact,
                                                    FE_E_hourglass, FE_E_dissipated};

mcs_status fe_out_parts_open(mcs_results *r, int stage, const fe_model *m, fe_out_parts *o,
                             mcs_error *err)
{
    o->n = m->npart + m->nspring_part;
    o->ser = calloc((size_t)(o->n > 0 ? o->n : 1) * FE_OUT_PART_KINDS, sizeof *o->ser);
    if (!o->ser)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage %d: out of memory (part energies)", stage);
    mcs_status st = MCS_OK;
    if (m->nms_elem) {
        char ma[32];
        snprintf(ma, sizeof ma, "/stage%d/mass_added", stage);
        st = mcs_results_series_create(r, ma, 1, NULL, "kg", 0, &o->mass_added, err);
    }
    for (int i = 0; i < o->n && !st; i++) {
        const char *name = i < m->npart ? m->part[i].name : m->spring_part[i - m->npart];
        for (int k = 0; k < FE_OUT_PART_KINDS && !st; k++) {
            char path[256];
            snprintf(path, sizeof path, "/stage%d/parts/%s/energy/%s", stage, name,
                     fe_energy_name[kinds[k]]);
            st = mcs_results_series_create(r, path, 1, NULL, "J", 0,
                                           &o->ser[FE_OUT_PART_KINDS * i + k], err);
        }
    }
    return st;
}

mcs_status fe_out_parts_sample(const fe_model *m, const fe_state *s, const fe_out_parts *o,
                           mcs_error *err)
{
    mcs_status st = MCS_OK;
    if (o->mass_added) {
        double ma = m->mass_added + s->mass_added_run;
        st = mcs_results_series_append(o->mass_added, &ma, err);
    }
    for (int i = 0; i < o->n && !st; i++)
        for (int k = 0; k < FE_OUT_PART_KINDS && !st; k++) {
            double e = i < m->npart ? fe_part_energy(m, s, i, kinds[k])
                                    : fe_spring_part_energy(m, s, i - m->npart, kinds[k]);
            st = mcs_results_series_append(o->ser[FE_OUT_PART_KINDS * i + k], &e, err);
        }
    return st;
}

void fe_out_parts_free(fe_out_parts *o)
{
    free(o->ser);
    o->ser = NULL;
    o->mass_added = NULL;
    o->n = 0;
}

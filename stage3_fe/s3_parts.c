/* s3_parts: per-part energies (element parts and spring parts) into /stage3 (s3_parts.h). */
#include "stage3_fe/s3_parts.h"

#include <stdio.h>
#include <stdlib.h>

static const fe_energy_kind kinds[S3_PART_KINDS] = {FE_E_kinetic, FE_E_internal, FE_E_contact,
                                                    FE_E_hourglass, FE_E_dissipated};

mcs_status s3_parts_open(mcs_results *r, const fe_model *m, s3_part_out *o, mcs_error *err)
{
    o->n = m->npart + m->nspring_part;
    o->ser = calloc((size_t)(o->n > 0 ? o->n : 1) * S3_PART_KINDS, sizeof *o->ser);
    if (!o->ser) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 3: out of memory (part energies)");
    mcs_status st = MCS_OK;
    if (m->nms_elem)
        st = mcs_results_series_create(r, "/stage3/mass_added", 1, NULL, "kg", 0,
                                       &o->mass_added, err);
    for (int i = 0; i < o->n && !st; i++) {
        const char *name = i < m->npart ? m->part[i].name : m->spring_part[i - m->npart];
        for (int k = 0; k < S3_PART_KINDS && !st; k++) {
            char path[256];
            snprintf(path, sizeof path, "/stage3/parts/%s/energy/%s", name,
                     fe_energy_name[kinds[k]]);
            st = mcs_results_series_create(r, path, 1, NULL, "J", 0,
                                           &o->ser[S3_PART_KINDS * i + k], err);
        }
    }
    return st;
}

mcs_status s3_parts_sample(const fe_model *m, const fe_state *s, const s3_part_out *o,
                           mcs_error *err)
{
    mcs_status st = MCS_OK;
    if (o->mass_added) {
        double ma = m->mass_added + s->mass_added_run;
        st = mcs_results_series_append(o->mass_added, &ma, err);
    }
    for (int i = 0; i < o->n && !st; i++)
        for (int k = 0; k < S3_PART_KINDS && !st; k++) {
            double e = i < m->npart ? fe_part_energy(m, s, i, kinds[k])
                                    : fe_spring_part_energy(m, s, i - m->npart, kinds[k]);
            st = mcs_results_series_append(o->ser[S3_PART_KINDS * i + k], &e, err);
        }
    return st;
}

void s3_parts_free(s3_part_out *o)
{
    free(o->ser);
    o->ser = NULL;
    o->mass_added = NULL;
    o->n = 0;
}

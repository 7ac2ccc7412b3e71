/* fe_out_contact: contact force histories (fe_out_contact.h). */
#include "fe/out/fe_out_contact.h"

#include <stdio.h>
#include <string.h>

mcs_status fe_out_contact_open(mcs_results *r, int stage, const fe_model *m, fe_out_contact *o,
                               mcs_error *err)
{
    memset(o, 0, sizeof *o);
    const fe_contact_model *c = m->contact;
    char path[256];
    const size_t three = 3;
    mcs_status st = MCS_OK;
    for (int i = 0; c && i < c->nif && !st; i++) {
        snprintf(path, sizeof path, "/stage%d/contact/%s/force", stage, c->iface[i].name);
        st = mcs_results_series_create(r, path, 2, &three, "N", 0, &o->force[i], err);
        snprintf(path, sizeof path, "/stage%d/contact/%s/energy", stage, c->iface[i].name);
        if (!st) st = mcs_results_series_create(r, path, 1, NULL, "J", 0, &o->energy[i], err);
    }
    for (int i = 0; c && i < c->nell && !st; i++) {
        snprintf(path, sizeof path, "/stage%d/ellipsoid/%s/force", stage, c->ell[i].name);
        st = mcs_results_series_create(r, path, 2, &three, "N", 0, &o->ell_force[i], err);
    }
    for (int i = 0; c && i < c->nfac && !st; i++) {
        snprintf(path, sizeof path, "/stage%d/facets/%s/force", stage, c->fac[i].name);
        st = mcs_results_series_create(r, path, 2, &three, "N", 0, &o->fac_force[i], err);
    }
    return st;
}

mcs_status fe_out_contact_sample(const fe_model *m, const fe_state *s, const fe_out_contact *o,
                                 mcs_error *err)
{
    const fe_contact_model *c = m->contact;
    mcs_status st = MCS_OK;
    for (int i = 0; c && i < c->nif && !st; i++) {
        st = mcs_results_series_append(o->force[i], s->contact->if_force + 3 * i, err);
        if (!st) st = mcs_results_series_append(o->energy[i], s->contact->if_energy + i, err);
    }
    for (int i = 0; c && i < c->nell && !st; i++)
        st = mcs_results_series_append(o->ell_force[i], s->contact->ell_force + 3 * i, err);
    for (int i = 0; c && i < c->nfac && !st; i++)
        st = mcs_results_series_append(o->fac_force[i], s->contact->fac_force + 3 * i, err);
    return st;
}

/* fe_out_contact: contact force histories of a stage's FE model: /stage<N>/contact/<name>/
 * {force [nt,3] N, energy [nt] J} per fe.contacts interface (resultant on the slave side, zero
 * for self contact; elastic + frictional energy) and /stage<N>/ellipsoid/<name>/force [nt,3] N
 * per rigid ellipsoid (fe.rigid_ellipsoids, and a stage-1 body's ellipsoid in a bodies
 * contact) and /stage<N>/facets/<name>/force [nt,3] N per rigid facet surface (a stage-1 body's
 * facets in a bodies contact): the force of the structure on it, at the state's energy time
 * (docs/contracts.md). */
#ifndef FE_OUT_CONTACT_H
#define FE_OUT_CONTACT_H

#include "core/mcs_results.h"
#include "fe/fe_contact.h"
#include "fe/fe_state.h"

typedef struct {
    mcs_results_series *force[FE_CONTACT_MAX], *energy[FE_CONTACT_MAX];
    mcs_results_series *ell_force[FE_ELLIPSOID_MAX];
    mcs_results_series *fac_force[FE_FACETS_MAX];
} fe_out_contact;

/* into /stage<stage>/contact, /stage<stage>/ellipsoid and /stage<stage>/facets */
mcs_status fe_out_contact_open(mcs_results *r, int stage, const fe_model *m, fe_out_contact *o,
                               mcs_error *err);
/* one row */
mcs_status fe_out_contact_sample(const fe_model *m, const fe_state *s, const fe_out_contact *o,
                                 mcs_error *err);

#endif

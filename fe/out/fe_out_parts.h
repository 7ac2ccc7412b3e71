/* fe_out_parts: per-part energies in the results: /stage<N>/parts/<part>/energy/<kind>
 * [nt] J for kind kinetic, internal, contact, hourglass, dissipated, for every element part and
 * every spring part (discrete springs and dampers: internal = elastic, dissipated = dampers;
 * fe/elem/fe_discrete.c). The parts' sums plus what belongs to no part equal /stage<N>/energy.
 * With mass scaling during the run, also /stage<N>/mass_added [nt] kg: the mass added so far
 * (at t = 0 and since). */
#ifndef FE_OUT_PARTS_H
#define FE_OUT_PARTS_H

#include "core/mcs_results.h"
#include "fe/fe_state.h"

#define FE_OUT_PART_KINDS 5
typedef struct {
    int n;                    /* element parts + spring parts                        */
    mcs_results_series **ser; /* (n x FE_OUT_PART_KINDS)                                 */
    mcs_results_series *mass_added; /* /stage<N>/mass_added [nt] kg (run-time mass scaling) */
} fe_out_parts;

/* into /stage<stage>/parts (and /stage<stage>/mass_added) */
mcs_status fe_out_parts_open(mcs_results *r, int stage, const fe_model *m, fe_out_parts *o,
                             mcs_error *err);
/* one row at the state's energy time */
mcs_status fe_out_parts_sample(const fe_model *m, const fe_state *s, const fe_out_parts *o,
                           mcs_error *err);
void fe_out_parts_free(fe_out_parts *o);

#endif

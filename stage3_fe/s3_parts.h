/* s3_parts: per-part energies in the stage-3 results: /stage3/parts/<part>/energy/<kind>
 * [nt] J for kind kinetic, internal, contact, hourglass, dissipated, for every element part and
 * every spring part (discrete springs and dampers: internal = elastic, dissipated = dampers;
 * fe/fe_discrete.c). The parts' sums plus what belongs to no part equal /stage3/energy.
 * With mass scaling during the run, also /stage3/mass_added [nt] kg: the mass added so far
 * (at t = 0 and since). */
#ifndef S3_PARTS_H
#define S3_PARTS_H

#include "core/mcs_results.h"
#include "fe/fe_state.h"

#define S3_PART_KINDS 5
typedef struct {
    int n;                    /* element parts + spring parts                        */
    mcs_results_series **ser; /* (n x S3_PART_KINDS)                                 */
    mcs_results_series *mass_added; /* /stage3/mass_added [nt] kg (run-time mass scaling) */
} s3_part_out;

mcs_status s3_parts_open(mcs_results *r, const fe_model *m, s3_part_out *o, mcs_error *err);
/* one row at the state's energy time */
mcs_status s3_parts_sample(const fe_model *m, const fe_state *s, const s3_part_out *o,
                           mcs_error *err);
void s3_parts_free(s3_part_out *o);

#endif

/* mb_couple_out.h: the FE parts of a coupled stage-1 run in the results file, in the /stage3
 * layout under /stage1 (DESIGN.md "Coupling bodies and FE parts", docs/contracts.md):
 *   /stage1/mesh/<part>/{nodes, elements}, /stage1/fields/{time, displacement},
 *   /stage1/parts/<part>/energy/{kinetic, internal, contact, hourglass, dissipated},
 *   /stage1/airbag/<name>/{pressure, volume, temperature, mass},
 *   /stage1/retractor/<name>/{payout, force, payout_pretensioner, payout_limiter,
 *   energy_limiter}, /stage1/slipring/<name>/{slip, ...}, /stage1/contact/<name>/{force,
 *   energy}, /stage1/ellipsoid/<name>/force, /stage1/facets/<name>/force.
 * One row per stage-1 output row, at the times of /stage1/time: the FE state is the one at the
 * end of the ODE step (mb_couple_advance has subcycled it to s->t); energies, bag, retractor,
 * ring and contact values are those of its last FE step (fe_state.energy_time, one FE step
 * before s->t at most), the displacement that of s->t. With simulation.field_rate below
 * output_rate, /stage1/fields holds every k-th row only, k = round(output_rate / field_rate).
 * The groups /stage1/airbag/<name> and /stage1/retractor/<name> exist from mb_couple_out_open
 * on, so that attributes (fire_time) can be set on them before the file is committed. */
#ifndef MB_COUPLE_OUT_H
#define MB_COUPLE_OUT_H

#include "core/mcs_results.h"
#include "stage1_mb/mb_model.h"

typedef struct mb_couple_out mb_couple_out;

/* the meshes and the series of m->couple into r (*out = NULL and MCS_OK without coupling) */
mcs_status mb_couple_out_open(const mb_model *m, mcs_results *r, mb_couple_out **out,
                              mcs_error *err);
/* a row for every stage-1 output row recorded since the last call (s->nrec) */
mcs_status mb_couple_out_sample(const mb_model *m, const mb_state *s, mb_couple_out *o,
                                mcs_error *err);
void mb_couple_out_free(mb_couple_out **o);

#endif

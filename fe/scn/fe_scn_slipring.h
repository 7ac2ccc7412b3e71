/* fe_scn_slipring: the scenario's fe.sliprings (fe/fe_slipring.h) into the builder, and their
 * results: /stage<N>/slipring/<name>/{slip, slip_rate, force0, force1, wrap_angle,
 * length0, length1, energy_friction} (the channels of fe_slipring.h, at t_n). */
#ifndef FE_SCN_SLIPRING_H
#define FE_SCN_SLIPRING_H

#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "fe/fe_slipring.h"

/* fe.sliprings of the fe: block into the builder */
mcs_status fe_scn_add_sliprings(fe_builder *b, const mcs_node *fe, mcs_error *err);
/* the fe.sliprings item a kernel message names ("slip ring 'x'"), else fallback */
const mcs_node *fe_scn_slipring_node(const mcs_node *fe, const char *msg, const mcs_node *fallback);

typedef struct {
    int n;
    mcs_results_series **ch; /* (n x FE_SLIPRING_NCHANNEL) */
} fe_out_slipring;

/* into /stage<stage>/slipring */
mcs_status fe_out_slipring_open(mcs_results *r, int stage, const fe_model *m, fe_out_slipring *o,
                                mcs_error *err);
mcs_status fe_out_slipring_sample(const fe_state *s, const fe_out_slipring *o, mcs_error *err);
void fe_out_slipring_free(fe_out_slipring *o);

#endif

/* s3_slipring: the scenario's fe.sliprings (fe/fe_slipring.h) into the builder, and their
 * /stage3 results: /stage3/slipring/<name>/{slip, slip_rate, force0, force1, wrap_angle,
 * length0, length1, energy_friction} (the channels of fe_slipring.h, at t_n). */
#ifndef S3_SLIPRING_H
#define S3_SLIPRING_H

#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "fe/fe_slipring.h"

/* fe.sliprings of the fe: block into the builder */
mcs_status s3_add_sliprings(fe_builder *b, const mcs_node *fe, mcs_error *err);
/* the fe.sliprings item a kernel message names ("slip ring 'x'"), else fallback */
const mcs_node *s3_slipring_node(const mcs_node *fe, const char *msg, const mcs_node *fallback);

typedef struct {
    int n;
    mcs_results_series **ch; /* (n x FE_SLIPRING_NCHANNEL) */
} s3_slipring_out;

mcs_status s3_slipring_open(mcs_results *r, const fe_model *m, s3_slipring_out *o, mcs_error *err);
mcs_status s3_slipring_sample(const fe_state *s, const s3_slipring_out *o, mcs_error *err);
void s3_slipring_out_free(s3_slipring_out *o);

#endif

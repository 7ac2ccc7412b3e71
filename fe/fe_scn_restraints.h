/* fe_scn_restraints: the scenario keys of membranes and restraints of an fe: block (stage 3, or
 * coupled to stage 1) — sphere_shell and cylinder_shell meshes, fabric materials, fe.airbags and
 * fe.retractors (fe/fe_restraint.h), and their results under /stage<N> (3, or 1):
 * /stage<N>/airbag/<name>/{pressure, volume, temperature, mass} and
 * /stage<N>/retractor/<name>/{payout, force, payout_pretensioner, payout_limiter,
 * energy_limiter} (docs/contracts.md). */
#ifndef FE_SCN_RESTRAINTS_H
#define FE_SCN_RESTRAINTS_H

#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "fe/fe_restraint.h"

mcs_status fe_scn_read_shell_mesh(const mcs_node *mesh, const char *gen, fe_mesh_desc *d,
                              mcs_error *err);
mcs_status fe_scn_read_fabric(const mcs_node *mat, fe_material_desc *d, mcs_error *err);
/* fe.airbags and fe.retractors of the fe: block into the builder */
mcs_status fe_scn_add_restraints(fe_builder *b, const mcs_node *fe, mcs_error *err);

/* the fe.airbags / fe.retractors item a kernel message names ("gas bag 'x'", "retractor
 * 'x'"), else fe itself: where to locate a model-build error */
const mcs_node *fe_scn_restraint_node(const mcs_node *fe, const char *msg);

/* the first key of the fe: block that needs stage-1 bodies (an inflator or retractor
 * trigger, a retractor's anchor_body, a slip ring's body), NULL none: a stage-3 run refuses
 * it rather than drop it */
const mcs_node *fe_scn_stage1_key(const mcs_node *fe);

/* result series of every bag and retractor of the model */
#define FE_OUT_BAG_CHANNELS 9
#define FE_OUT_RETRACTOR_CHANNELS 6
typedef struct {
    int nbag, nretractor;
    mcs_results_series **bag;       /* (nbag x FE_OUT_BAG_CHANNELS)             */
    mcs_results_series **retractor; /* (nretractor x FE_OUT_RETRACTOR_CHANNELS) */
} fe_out_restraint;

/* into /stage<stage>/airbag and /stage<stage>/retractor */
mcs_status fe_out_restraint_open(mcs_results *r, int stage, const fe_model *m, fe_out_restraint *o,
                                 mcs_error *err);
/* one row at the state's energy time (the bag and retractor states are at t_n) */
mcs_status fe_out_restraint_sample(const fe_state *s, const fe_out_restraint *o, mcs_error *err);
void fe_out_restraint_free(fe_out_restraint *o);

#endif

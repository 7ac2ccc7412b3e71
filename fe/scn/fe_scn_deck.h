/* fe_scn_deck: a whole LS-DYNA keyword deck as the scenario's FE model (fe: {keyword: FILE.k,
 * units: LENGTH-TIME-MASS, unknown_keywords: warn|error}; docs/keyword.md). */
#ifndef FE_SCN_DECK_H
#define FE_SCN_DECK_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

/* read the deck fe.keyword names (relative to the YAML file) and add all of it to b; when sim
 * has no end_time, *end_time is the deck's *CONTROL_TERMINATION ENDTIM [s] (an error when it
 * has none); the deck's *CONTROL_TIMESTEP sets opts' step scale and mass scaling where the
 * scenario gives neither (simulation.time_step_scale, fe.mass_scaling). Errors name the
 * fe.keyword key and the deck's FILE:LINE. */
mcs_status fe_scn_deck_add(fe_builder *b, const mcs_node *fe, const mcs_node *sim, double *end_time,
                           fe_opts *opts, mcs_error *err);

#endif

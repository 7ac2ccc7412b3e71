/* fe_scn_deck: fe: {keyword: main.k, units: ..., unknown_keywords: ...}: a whole LS-DYNA deck
 * as the stage-3 model (docs/contracts.md "A whole keyword deck", docs/keyword.md): every part,
 * contact, constraint, prescribed motion, load, initial velocity and rigid wall of the deck
 * through fe_kw_add_deck, and the end time of its *CONTROL_TERMINATION unless the scenario's
 * simulation.end_time gives one. */
#include "fe/scn/fe_scn_deck.h"

#include "fe/fe_keyword.h"
#include "fe/scn/fe_scn_node.h"

#include <stdio.h>
#include <string.h>

mcs_status fe_scn_deck_add(fe_builder *b, const mcs_node *fe, const mcs_node *sim, double *end_time,
                           fe_opts *opts, mcs_error *err)
{
    const mcs_node *kn = fe_scn_get(fe, "keyword");
    const char *name = mcs_node_str(kn), *from = mcs_node_file(kn);
    const char *units = mcs_node_str(fe_scn_get(fe, "units"));
    const char *unk = mcs_node_str(fe_scn_get(fe, "unknown_keywords"));
    if (!name) return mcs_node_error(kn, err, MCS_ERR_TYPE, "a file name is expected");
    char path[1024];
    const char *slash = from ? strrchr(from, '/') : NULL;
    if (name[0] == '/' || !slash)
        snprintf(path, sizeof path, "%s", name);
    else
        snprintf(path, sizeof path, "%.*s/%s", (int)(slash - from), from, name);
    fe_kw_opts o = fe_kw_opts_default();
    o.units = units ? units : "m-s-kg";
    o.strict = unk && strcmp(unk, "error") == 0;
    fe_kw_deck *d = NULL;
    mcs_error kerr = {0};
    mcs_status st = fe_kw_read(path, &o, &d, &kerr);
    if (!st) st = fe_kw_add_deck(b, d, &kerr);
    fe_opts deck = *opts; /* *CONTROL_TIMESTEP, under the scenario's own keys */
    if (!st) st = fe_kw_deck_opts(d, &deck, &kerr);
    if (!st && !fe_scn_given(sim, "time_step_scale")) opts->dt_scale = deck.dt_scale;
    if (!st && !fe_scn_given(fe, "mass_scaling")) {
        opts->mass_scaling_dt = deck.mass_scaling_dt;
        opts->mass_scaling_interval = deck.mass_scaling_interval;
    }
    if (!st && !fe_scn_given(sim, "end_time")) {
        if (!(d->end_time > 0))
            st = MCS_ERR(&kerr, MCS_ERR_KEY,
                         "%s: no *CONTROL_TERMINATION with ENDTIM > 0: give simulation.end_time",
                         path);
        else
            *end_time = d->end_time;
    }
    fe_kw_deck_destroy(&d);
    if (st) return mcs_node_error(kn, err, st, "%s", kerr.msg);
    return MCS_OK;
}

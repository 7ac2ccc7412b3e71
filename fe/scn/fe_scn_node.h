/* fe_scn_node.h: the scenario-node helpers the FE scenario builder uses (fe_scn_build.c,
 * fe_scn_contact.c, fe_scn_solid.c, fe_scn_restraints.c): child lookup, "was this key given",
 * a kernel error re-recorded at the scenario node it concerns, and an axis name. */
#ifndef FE_SCN_NODE_H
#define FE_SCN_NODE_H

#include "core/mcs_scenario.h"

static inline const mcs_node *fe_scn_get(const mcs_node *m, const char *k)
{
    return mcs_node_get(m, k);
}

static inline int fe_scn_given(const mcs_node *m, const char *k)
{
    return mcs_node_kind(mcs_node_get(m, k)) != MCS_NODE_NULL;
}

/* a kernel error (no location) re-recorded at the scenario node it concerns */
static inline mcs_status fe_scn_relocate(mcs_status st, const mcs_node *n, mcs_error *kerr,
                                     mcs_error *err)
{
    if (st == MCS_OK) return MCS_OK;
    return mcs_node_error(n, err, st, "%s", kerr->msg);
}

/* "x"/"y"/anything else -> 0/1/2; no name -> dflt */
static inline int fe_scn_axis_of(const char *s, int dflt)
{
    if (!s) return dflt;
    return s[0] == 'x' ? 0 : s[0] == 'y' ? 1 : 2;
}

#endif

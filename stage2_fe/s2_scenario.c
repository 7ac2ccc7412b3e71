/* s2_scenario.c: the stage-2 scenario, stage2.fe merged into fe: (s2_scenario.h) */
#include "stage2_fe/s2_scenario.h"

mcs_status s2_scenario_compile(const mcs_scenario *scn, mcs_scenario **out, mcs_error *err)
{
    *out = NULL;
    const mcs_node *root = mcs_scenario_root(scn);
    if (mcs_node_kind(mcs_node_get(root, "stage2")) != MCS_NODE_MAP)
        return mcs_node_error(root, err, MCS_ERR_KEY,
                              "no stage2: block (stage 2 needs its prescribed bodies and motion)");
    return mcs_scenario_merged(scn, "stage2.fe", "fe", out, err);
}

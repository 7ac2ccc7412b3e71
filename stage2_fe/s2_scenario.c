/* s2_scenario.c: the stage-2 scenario, stage2.fe merged into fe:, stage2.energy_groups into
 * energy_groups (s2_scenario.h) */
#include "stage2_fe/s2_scenario.h"

mcs_status s2_scenario_compile(const mcs_scenario *scn, mcs_scenario **out, mcs_error *err)
{
    *out = NULL;
    const mcs_node *root = mcs_scenario_root(scn);
    if (mcs_node_kind(mcs_node_get(root, "stage2")) != MCS_NODE_MAP)
        return mcs_node_error(root, err, MCS_ERR_KEY,
                              "no stage2: block (stage 2 needs its prescribed bodies and motion)");
    mcs_scenario *fe = NULL;
    mcs_status st = mcs_scenario_merged(scn, "stage2.fe", "fe", &fe, err);
    /* stage2.energy_groups (partners of stage 2 only, e.g. the tank pads' contacts) */
    if (!st) st = mcs_scenario_merged(fe, "stage2.energy_groups", "energy_groups", out, err);
    mcs_scenario_destroy(&fe);
    return st;
}

/* s3_scenario.c: the stage-3 scenario of a scenario's stage3: block (s3_scenario.h) */
#include "stage3_fe/s3_scenario.h"

int s3_scenario_has_block(const mcs_scenario *scn)
{
    return mcs_node_kind(mcs_node_get(mcs_scenario_root(scn), "stage3")) == MCS_NODE_MAP;
}

mcs_status s3_scenario_compile(const mcs_scenario *scn, mcs_scenario **out, mcs_error *err)
{
    *out = NULL;
    if (!s3_scenario_has_block(scn))
        return mcs_node_error(mcs_scenario_root(scn), err, MCS_ERR_KEY,
                              "no stage3: block (stage 3 of a stage-1 scenario needs its FE "
                              "model there)");
    /* stage 1's keys: its bodies, their contacts and joints, the impact placement */
    static const char *const drop[] = {"bodies",  "contacts",     "joints",        "attachments",
                                       "sensors", "impact",       "rider",         "mount_points",
                                       "stage2",  "energy_groups", "stage3"};
    mcs_scenario *sim = NULL;
    mcs_status st = mcs_scenario_merged(scn, "stage3.simulation", "simulation", &sim, err);
    if (!st)
        st = mcs_scenario_replaced(sim, "stage3.fe", "fe", drop,
                                   (int)(sizeof drop / sizeof drop[0]), out, err);
    mcs_scenario_destroy(&sim);
    return st;
}

/* s2_model.c: the stage-2 model of a scenario (s2_run.h): the scenario's stage-1 model built
 * to write /stage2, then the stage2.prescribed bodies made kinematic from the motion file */
#include "stage2_fe/s2_run.h"

#include <stdlib.h>

/* the scenario stage 2 builds: the scenario itself. Stage-2-only FE parts (a cockpit under
 * stage2:) are merged into its fe: block here, before the model is built. */
static mcs_status s2_scenario_parts(const mcs_scenario *scn, const mcs_scenario **out,
                                    mcs_error *err)
{
    (void)err;
    *out = scn;
    return MCS_OK;
}

mcs_status s2_model_build(const mcs_scenario *scn, const char *motion_path, s2_model **out,
                          mcs_error *err)
{
    *out = NULL;
    const mcs_node *root = mcs_scenario_root(scn);
    if (mcs_node_kind(mcs_node_get(root, "stage2")) != MCS_NODE_MAP)
        return mcs_node_error(root, err, MCS_ERR_KEY, "stage 2 needs a stage2: block");
    s2_model *m = calloc(1, sizeof *m);
    if (!m) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 2: out of memory");
    const mcs_scenario *s2 = NULL;
    mcs_status st = s2_scenario_parts(scn, &s2, err);
    mb_opts o = mb_opts_default();
    o.stage = 2;
    if (!st) st = mb_model_build(s2, &o, &m->mb, err);
    if (!st) st = tr_stage2_motion_create(&m->motion, scn, m->mb, motion_path, err);
    if (st) {
        s2_model_destroy(&m);
        return st;
    }
    *out = m;
    return MCS_OK;
}

void s2_model_destroy(s2_model **pm)
{
    s2_model *m = pm ? *pm : NULL;
    if (!m) return;
    tr_stage2_motion_destroy(&m->motion);
    mb_model_destroy(&m->mb);
    free(m);
    *pm = NULL;
}

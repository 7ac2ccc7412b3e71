/* s2_model.c: the stage-2 model of a scenario (s2_run.h): the compiled stage-2 scenario
 * (stage2.fe merged, s2_scenario.h), its stage-1 model built to write /stage2, then the
 * stage2.prescribed bodies made kinematic from the motion file */
#include "stage2_fe/s2_run.h"
#include "stage2_fe/s2_scenario.h"

#include <stdlib.h>

mcs_status s2_model_build(const mcs_scenario *scn, const char *motion_path, s2_model **out,
                          mcs_error *err)
{
    *out = NULL;
    const mcs_node *root = mcs_scenario_root(scn);
    if (mcs_node_kind(mcs_node_get(root, "stage2")) != MCS_NODE_MAP)
        return mcs_node_error(root, err, MCS_ERR_KEY, "stage 2 needs a stage2: block");
    s2_model *m = calloc(1, sizeof *m);
    if (!m) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 2: out of memory");
    /* stage2.fe (the cockpit: stage-2-only FE parts) merged into fe: (s2_scenario.h) */
    mcs_status st = s2_scenario_compile(scn, &m->scn, err);
    mb_opts o = mb_opts_default();
    o.stage = 2;
    if (!st) st = mb_model_build(m->scn, &o, &m->mb, err);
    if (!st) st = tr_stage2_motion_create(&m->motion, m->scn, m->mb, motion_path, err);
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
    mcs_scenario_destroy(&m->scn);
    free(m);
    *pm = NULL;
}

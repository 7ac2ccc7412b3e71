/* tr_stage2_motion.c: the stage2: block -> prescribed bodies (tr_stage2_motion.h) */
#include "translators/tr_stage2_motion.h"

#include <stdlib.h>

struct tr_stage2_motion {
    tr_motion *mo;
    tr_prescribe *presc;
};

mcs_status tr_stage2_motion_create(tr_stage2_motion **out, const mcs_scenario *scn, mb_model *m,
                                   const char *motion_path, mcs_error *err)
{
    *out = NULL;
    const mcs_node *root = mcs_scenario_root(scn), *blk = mcs_node_get(root, "stage2");
    if (mcs_node_kind(blk) != MCS_NODE_MAP)
        return mcs_node_error(root, err, MCS_ERR_KEY, "stage 2 needs a stage2: block");
    const char *path = motion_path ? motion_path : mcs_node_str(mcs_node_get(blk, "motion"));
    if (!path || !*path)
        return mcs_node_error(blk, err, MCS_ERR_KEY,
                              "stage2: no motion file (stage2.motion or --motion FILE)");
    tr_motion_method method = TR_MOTION_POSE;
    const mcs_node *mn = mcs_node_get(blk, "method");
    mcs_status st = mn ? tr_motion_method_parse(mcs_node_str(mn), &method, err) : MCS_OK;
    if (st) return st;
    const mcs_node *list = mcs_node_get(blk, "prescribed");
    const int n = mcs_node_len(list);
    const char **body = calloc((size_t)(n > 0 ? n : 1), sizeof *body);
    const char **from = calloc((size_t)(n > 0 ? n : 1), sizeof *from);
    tr_stage2_motion *p = calloc(1, sizeof *p);
    if (!body || !from || !p) st = MCS_ERR(err, MCS_ERR_NOMEM, "stage 2: out of memory");
    for (int i = 0; !st && i < n; i++) {
        const mcs_node *e = mcs_node_at(list, i), *f = mcs_node_get(e, "from");
        body[i] = mcs_node_str(mcs_node_get(e, "body"));
        from[i] = f ? mcs_node_str(f) : body[i];
    }
    if (!st) st = tr_motion_open(&p->mo, path, from, n, method, err);
    if (!st) st = tr_prescribe_create(&p->presc, m, p->mo, body, from, n, err);
    free(body), free(from);
    if (st) {
        tr_stage2_motion_destroy(&p);
        return st;
    }
    *out = p;
    return MCS_OK;
}

void tr_stage2_motion_destroy(tr_stage2_motion **pp)
{
    tr_stage2_motion *p = pp ? *pp : NULL;
    if (!p) return;
    tr_prescribe_destroy(&p->presc);
    tr_motion_destroy(&p->mo);
    free(p);
    *pp = NULL;
}

const tr_motion *tr_stage2_motion_get(const tr_stage2_motion *p)
{
    return p->mo;
}

/* tr_stage2_motion.c: the stage2: block -> prescribed bodies (tr_stage2_motion.h) */
#include "translators/tr_stage2_motion.h"
#include "core/mcs_obj.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct tr_stage2_motion {
    tr_motion *mo;
    tr_prescribe *presc;
    char path[4096];     /* the motion file read                           */
    int n;               /* prescribed bodies                              */
    char **body, **from; /* model body and the file's body of each (n)   */
};

/* a failure of the motion named with its file and the prescribed bodies, when it does not
 * name them itself */
static mcs_status with_file(mcs_status st, const char *path, char *const *body, int n,
                            mcs_error *err)
{
    if (!st) return st;
    char msg[sizeof err->msg], who[256] = "";
    snprintf(msg, sizeof msg, "%s", err->msg);
    int named = 0;
    for (int i = 0; i < n; i++)
        named |= strstr(msg, body[i]) != NULL;
    for (int i = 0; i < n && !named; i++)
        snprintf(who + strlen(who), sizeof who - strlen(who), "%s%s", i ? ", " : "", body[i]);
    mcs_error_clear(err);
    if (!strstr(msg, path) && !named)
        MCS_ERR(err, st, "%s: stage 2, prescribed %s: %s", path, who, msg);
    else if (!strstr(msg, path))
        MCS_ERR(err, st, "%s: %s", path, msg);
    else if (!named)
        MCS_ERR(err, st, "stage 2, prescribed %s: %s", who, msg);
    else
        MCS_ERR(err, st, "%s", msg);
    return st;
}

mcs_status tr_stage2_motion_create(tr_stage2_motion **out, const mcs_scenario *scn, mb_model *m,
                                   const char *motion_path, mcs_error *err)
{
    *out = NULL;
    const mcs_node *root = mcs_scenario_root(scn), *blk = mcs_node_get(root, "stage2");
    if (mcs_node_kind(blk) != MCS_NODE_MAP)
        return mcs_node_error(root, err, MCS_ERR_KEY, "stage 2 needs a stage2: block");
    const mcs_node *pn = mcs_node_get(blk, "motion");
    const char *path = motion_path ? motion_path : mcs_node_str(pn);
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
    if (p) p->body = calloc((size_t)(n > 0 ? n : 1), sizeof *p->body);
    if (p) p->from = calloc((size_t)(n > 0 ? n : 1), sizeof *p->from);
    if (!body || !from || !p || !p->body || !p->from)
        st = MCS_ERR(err, MCS_ERR_NOMEM, "stage 2: out of memory");
    /* stage2.motion is relative to the scenario file (as include:), --motion to the cwd */
    if (!st && motion_path)
        snprintf(p->path, sizeof p->path, "%s", motion_path);
    else if (!st && mcs_obj_path(mcs_node_file(pn), path, p->path, sizeof p->path))
        st = mcs_node_error(pn, err, MCS_ERR_RANGE, "file name too long");
    for (int i = 0; !st && i < n; i++) {
        const mcs_node *e = mcs_node_at(list, i), *f = mcs_node_get(e, "from");
        body[i] = mcs_node_str(mcs_node_get(e, "body"));
        from[i] = f ? mcs_node_str(f) : body[i];
        p->body[i] = strdup(body[i] ? body[i] : "");
        p->from[i] = strdup(from[i] ? from[i] : "");
        if (!p->body[i] || !p->from[i]) st = MCS_ERR(err, MCS_ERR_NOMEM, "stage 2: out of memory");
        p->n = i + 1;
    }
    if (!st)
        st = with_file(tr_motion_open(&p->mo, p->path, from, n, method, err), p->path, p->body,
                       p->n, err);
    if (!st)
        st = with_file(tr_prescribe_create(&p->presc, m, p->mo, body, from, n, err), p->path,
                       p->body, p->n, err);
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
    for (int i = 0; i < p->n; i++)
        free(p->body[i]), free(p->from[i]);
    free(p->body), free(p->from);
    free(p);
    *pp = NULL;
}

const tr_motion *tr_stage2_motion_get(const tr_stage2_motion *p)
{
    return p->mo;
}

const char *tr_stage2_motion_path(const tr_stage2_motion *p)
{
    return p->path;
}

int tr_stage2_motion_count(const tr_stage2_motion *p)
{
    return p->n;
}

const char *tr_stage2_motion_body(const tr_stage2_motion *p, int i, const char **from)
{
    if (from) *from = p->from[i];
    return p->body[i];
}

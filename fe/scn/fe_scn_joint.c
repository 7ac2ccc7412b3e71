/* fe_scn_joint.c: see fe_scn_joint.h. */
#include "fe/scn/fe_scn_joint.h"
#include "fe/fe_joint.h"
#include "fe/scn/fe_scn_node.h"

#include <stdio.h>
#include <string.h>

static mcs_status read_joint(const mcs_node *n, fe_joint_desc *d, mcs_error *err)
{
    *d = fe_joint_desc_default();
    snprintf(d->name, sizeof d->name, "%s", mcs_node_str(fe_scn_get(n, "name")));
    const char *type = mcs_node_str(fe_scn_get(n, "type"));
    for (int t = 0; t < 4; t++)
        if (type && !strcmp(type, fe_joint_type_name[t])) d->type = (fe_joint_type)t;
    const mcs_node *parts = fe_scn_get(n, "parts");
    if (mcs_node_len(parts) > 2)
        return mcs_node_error(parts, err, MCS_ERR_RANGE,
                              "a joint joins two rigid parts (or one to the ground), got %d",
                              mcs_node_len(parts));
    for (int i = 0; i < mcs_node_len(parts); i++)
        snprintf(d->body[i], sizeof d->body[i], "%s", mcs_node_str(mcs_node_at(parts, i)));
    mcs_status st = mcs_node_vec3(fe_scn_get(n, "point"), d->point, err);
    if (!st && fe_scn_given(n, "axis")) st = mcs_node_vec3(fe_scn_get(n, "axis"), d->axis, err);
    if (st) return st;
    d->stiffness = mcs_node_num_or(n, "stiffness", 0);
    d->damping = mcs_node_num_or(n, "damping", 0);
    d->penalty_scale = mcs_node_num_or(n, "penalty_scale", 0);
    const mcs_node *r = fe_scn_get(n, "range");
    if (fe_scn_given(n, "range")) {
        d->has_range = 1;
        d->range[0] = mcs_node_num(mcs_node_at(r, 0));
        d->range[1] = mcs_node_num(mcs_node_at(r, 1));
    }
    return MCS_OK;
}

mcs_status fe_scn_add_joints(fe_builder *b, const mcs_node *fe, mcs_error *err)
{
    const mcs_node *list = fe_scn_get(fe, "joints");
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *n = mcs_node_at(list, i);
        fe_joint_desc d;
        mcs_status st = read_joint(n, &d, err);
        if (st) return st;
        mcs_error kerr = {0};
        st = fe_builder_add_joint(b, &d, &kerr);
        if (st)
            return fe_scn_relocate(st, fe_scn_given(n, "range") ? fe_scn_get(n, "range") : n, &kerr,
                                   err);
    }
    return MCS_OK;
}

const mcs_node *fe_scn_joint_node(const mcs_node *fe, const char *msg, const mcs_node *dflt)
{
    const mcs_node *list = fe_scn_get(fe, "joints");
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *it = mcs_node_at(list, i);
        char needle[FE_NAME_MAX + 16];
        snprintf(needle, sizeof needle, "joint '%s'", mcs_node_str(fe_scn_get(it, "name")));
        if (!strstr(msg, needle)) continue;
        if (strstr(msg, "rigid part") || strstr(msg, "itself") || strstr(msg, "held"))
            return fe_scn_get(it, "parts");
        if (strstr(msg, "stiffness"))
            return fe_scn_get(it, "stiffness") ? fe_scn_get(it, "stiffness") : it;
        return it;
    }
    return dflt;
}

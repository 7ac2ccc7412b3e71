/* fe_scn_contact.c: see fe_scn_contact.h. */
#include "fe/scn/fe_scn_contact.h"
#include "fe/scn/fe_scn_node.h"

#include "fe/fe_contact.h"

#include <stdio.h>
#include <string.h>

/* a list of part names into names (at most FE_CONTACT_PARTS) */
static mcs_status read_parts(const mcs_node *list, char (*names)[FE_NAME_MAX], int *n,
                             mcs_error *err)
{
    int len = mcs_node_len(list);
    if (len > FE_CONTACT_PARTS)
        return mcs_node_error(list, err, MCS_ERR_RANGE, "at most %d parts, got %d",
                              FE_CONTACT_PARTS, len);
    for (int i = 0; i < len; i++) {
        const char *s = mcs_node_str(mcs_node_at(list, i));
        if (!s || strlen(s) >= FE_NAME_MAX)
            return mcs_node_error(mcs_node_at(list, i), err, MCS_ERR_TYPE, "a part name");
        snprintf(names[i], FE_NAME_MAX, "%s", s);
    }
    *n = len;
    return MCS_OK;
}

static mcs_status add_contact(fe_builder *b, const mcs_node *c, int index, mcs_error *err)
{
    fe_contact_desc d = fe_contact_desc_default();
    const char *type = mcs_node_str(fe_scn_get(c, "type")),
               *name = mcs_node_str(fe_scn_get(c, "name"));
    snprintf(d.name, sizeof d.name, "%s", name ? name : "");
    if (!name) snprintf(d.name, sizeof d.name, "contact%d", index);
    if (name && strlen(name) >= FE_NAME_MAX)
        return mcs_node_error(fe_scn_get(c, "name"), err, MCS_ERR_RANGE,
                              "longer than %d characters", FE_NAME_MAX - 1);
    const char *ks = "a", *km = "b";
    mcs_status st = MCS_OK;
    if (type && strcmp(type, "single_surface") == 0) {
        d.type = FE_CONTACT_SINGLE_SURFACE;
        ks = "parts", km = NULL;
    } else if (type && strcmp(type, "two_surface") == 0) {
        d.type = FE_CONTACT_TWO_SURFACE;
        ks = "slave", km = "master";
    } else if (type && strcmp(type, "surface_to_surface") == 0) {
        d.type = FE_CONTACT_TWO_SURFACE;
    } else if (type && strcmp(type, "node_to_surface") == 0) {
        d.type = FE_CONTACT_NODE_TO_SURFACE;
    } else {
        return mcs_node_error(fe_scn_given(c, "type") ? fe_scn_get(c, "type") : c, err, MCS_ERR_KEY,
                              "unknown contact type '%s'", type ? type : "?");
    }
    st = read_parts(fe_scn_get(c, ks), d.slave, &d.nslave, err);
    if (!st && km) st = read_parts(fe_scn_get(c, km), d.master, &d.nmaster, err);
    if (st) return st;
    d.friction = mcs_node_num_or(c, "friction", 0);
    d.friction_dynamic = mcs_node_num_or(c, "friction_dynamic", -1);
    d.friction_decay = mcs_node_num_or(c, "friction_decay", 0);
    d.penalty_scale = mcs_node_num_or(c, "penalty_scale", 0);
    d.thickness_scale = mcs_node_num_or(c, "thickness_scale", 0);
    d.fabric_thickness = mcs_node_num_or(c, "fabric_thickness", 0);
    if (fe_scn_given(c, "friction_dynamic") && d.friction_dynamic > d.friction)
        return mcs_node_error(fe_scn_get(c, "friction_dynamic"), err, MCS_ERR_RANGE,
                              "must not exceed friction (%g)", d.friction);
    mcs_error kerr = {0};
    st = fe_builder_add_contact(b, &d, &kerr);
    return fe_scn_relocate(st, c, &kerr, err);
}

static mcs_status add_ellipsoid(fe_builder *b, const mcs_node *e, mcs_error *err)
{
    fe_ellipsoid_desc d;
    memset(&d, 0, sizeof d);
    const char *name = mcs_node_str(fe_scn_get(e, "name"));
    if (!name || strlen(name) >= FE_NAME_MAX)
        return mcs_node_error(fe_scn_given(e, "name") ? fe_scn_get(e, "name") : e, err,
                              MCS_ERR_RANGE, "a name shorter than %d characters", FE_NAME_MAX);
    snprintf(d.name, sizeof d.name, "%s", name);
    mcs_status st = mcs_node_vec3(fe_scn_get(e, "center"), d.center, err);
    if (!st) st = mcs_node_vec3(fe_scn_get(e, "semi_axes"), d.semi_axes, err);
    if (!st && fe_scn_given(e, "orientation"))
        st = mcs_node_vec(fe_scn_get(e, "orientation"), d.orientation, 4, err);
    if (!st && fe_scn_given(e, "velocity"))
        st = mcs_node_vec3(fe_scn_get(e, "velocity"), d.velocity, err);
    if (!st && fe_scn_given(e, "parts"))
        st = read_parts(fe_scn_get(e, "parts"), d.parts, &d.nparts, err);
    if (st) return st;
    d.friction = mcs_node_num_or(e, "friction", 0);
    d.penalty_scale = mcs_node_num_or(e, "penalty_scale", 0);
    mcs_error kerr = {0};
    st = fe_builder_add_ellipsoid(b, &d, &kerr);
    return fe_scn_relocate(st, e, &kerr, err);
}

mcs_status fe_scn_contact_add(fe_builder *b, const mcs_node *fe, int coupled, mcs_error *err)
{
    const mcs_node *list = fe_scn_get(fe, "contacts");
    if (mcs_node_len(list) > FE_CONTACT_MAX)
        return mcs_node_error(list, err, MCS_ERR_RANGE, "at most %d contacts, got %d",
                              FE_CONTACT_MAX, mcs_node_len(list));
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *c = mcs_node_at(list, i);
        const char *type = mcs_node_str(fe_scn_get(c, "type"));
        if (type && strcmp(type, "bodies") == 0) { /* the coupling's (fe_scn_build_with) */
            if (coupled) continue;
            return mcs_node_error(fe_scn_get(c, "type"), err, MCS_ERR_UNSUPPORTED,
                                  "type: bodies meets stage-1 bodies: only in a scenario with "
                                  "bodies (stage 1)");
        }
        mcs_status st = add_contact(b, c, i, err);
        if (st) return st;
    }
    list = fe_scn_get(fe, "rigid_ellipsoids");
    if (mcs_node_len(list) > FE_ELLIPSOID_MAX)
        return mcs_node_error(list, err, MCS_ERR_RANGE, "at most %d ellipsoids, got %d",
                              FE_ELLIPSOID_MAX, mcs_node_len(list));
    for (int i = 0; i < mcs_node_len(list); i++) {
        mcs_status st = add_ellipsoid(b, mcs_node_at(list, i), err);
        if (st) return st;
    }
    return MCS_OK;
}

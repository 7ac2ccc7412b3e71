/* mcs_scn_rule_pad.c: a foam_pad mesh (fe/fe_scn_pad.c) checked when the scenario is loaded:
 * `surface` names an ellipsoid surface of `body`; the patch is not empty, latitude inside
 * (-90, 90) deg and longitude spanning at most one turn. */
#include "core/mcs_schema.h"

#include <math.h>
#include <string.h>

static const mcs_node *given(const mcs_node *map, const char *key)
{
    const mcs_node *n = mcs_node_get(map, key);
    return n && n->kind != MCS_NODE_NULL ? n : NULL;
}

/* the body named `name` (NULL if none) */
static const mcs_node *body_named(const mcs_node *root, const char *name)
{
    const mcs_node *bodies = mcs_node_get(root, "bodies");
    for (int i = 0; i < mcs_node_len(bodies); i++) {
        const char *n = mcs_node_str(mcs_node_get(mcs_node_at(bodies, i), "name"));
        if (n && strcmp(n, name) == 0) return mcs_node_at(bodies, i);
    }
    return NULL;
}

static mcs_status check_surface(scn_walk *w, const mcs_node *body, const mcs_node *sn)
{
    const mcs_node *surfs = mcs_node_get(body, "surfaces");
    for (int i = 0; i < mcs_node_len(surfs); i++) {
        const mcs_node *s = mcs_node_at(surfs, i);
        const char *n = mcs_node_str(mcs_node_get(s, "name"));
        if (!n || strcmp(n, sn->text) != 0) continue;
        const char *type = mcs_node_str(mcs_node_get(s, "type"));
        if (type && strcmp(type, "ellipsoid") == 0) return MCS_OK;
        return mcs_node_error(sn, w->err, MCS_ERR_UNSUPPORTED,
                              "surface '%s' of body '%s' is a %s: a foam_pad covers an ellipsoid",
                              sn->text, mcs_node_str(mcs_node_get(body, "name")),
                              type ? type : "?");
    }
    return mcs_node_error(sn, w->err, MCS_ERR_KEY, "body '%s' has no surface named '%s'",
                          mcs_node_str(mcs_node_get(body, "name")), sn->text);
}

mcs_status mcs_rule_foam_pad(scn_walk *w, mcs_node *map)
{
    const mcs_node *bn = given(map, "body"), *sn = given(map, "surface");
    const mcs_node *body = bn ? body_named(w->root, bn->text) : NULL;
    if (body && sn) {
        mcs_status st = check_surface(w, body, sn);
        if (st) return st;
    }
    const mcs_node *lon = given(map, "longitude"), *lat = given(map, "latitude");
    if (lon && !(lon->items[0]->num < lon->items[1]->num &&
                 lon->items[1]->num - lon->items[0]->num <= 2 * M_PI + 1e-12))
        return mcs_node_error(lon, w->err, MCS_ERR_RANGE,
                              "expected [from, to] with from < to, at most one turn apart");
    /* the poles stay out: the elements there would be wedges */
    if (lat && !(lat->items[0]->num < lat->items[1]->num && lat->items[0]->num > -M_PI / 2 &&
                 lat->items[1]->num < M_PI / 2))
        return mcs_node_error(lat, w->err, MCS_ERR_RANGE,
                              "expected [from, to] with -90 deg < from < to < 90 deg");
    return MCS_OK;
}

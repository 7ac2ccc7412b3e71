/* mcs_scn_rule_pad.c: a mesh on a body's surface (generate: foam_pad | surface_shell,
 * fe/scn/fe_scn_pad.h) checked when the scenario is loaded: `surface` names an ellipsoid or facet
 * surface of `body`; an ellipsoid needs element_size and the patch (longitude spanning at most
 * one turn, latitude inside (-90, 90) deg: the poles stay out), a facet is covered whole (no
 * patch keys). */
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

/* the type of surface sn of body ("ellipsoid", "facet"), NULL after an error */
static const char *surface_type(scn_walk *w, const mcs_node *body, const mcs_node *sn,
                                mcs_status *st)
{
    const mcs_node *surfs = mcs_node_get(body, "surfaces");
    const char *bname = mcs_node_str(mcs_node_get(body, "name"));
    for (int i = 0; i < mcs_node_len(surfs); i++) {
        const mcs_node *s = mcs_node_at(surfs, i);
        const char *n = mcs_node_str(mcs_node_get(s, "name"));
        if (!n || strcmp(n, sn->text) != 0) continue;
        const char *type = mcs_node_str(mcs_node_get(s, "type"));
        if (type && (strcmp(type, "ellipsoid") == 0 || strcmp(type, "facet") == 0)) return type;
        *st = mcs_node_error(sn, w->err, MCS_ERR_UNSUPPORTED,
                             "surface '%s' of body '%s' is a %s: a mesh covers an ellipsoid or "
                             "a facet surface",
                             sn->text, bname, type ? type : "?");
        return NULL;
    }
    *st = mcs_node_error(sn, w->err, MCS_ERR_KEY, "body '%s' has no surface named '%s'", bname,
                         sn->text);
    return NULL;
}

static mcs_status check_patch(scn_walk *w, mcs_node *map)
{
    static const char *const keys[] = {"element_size", "longitude", "latitude"};
    for (int i = 0; i < 3; i++)
        if (!given(map, keys[i]))
            return scn_walk_fail(w, map, keys[i], MCS_ERR_KEY,
                                 "required key is missing (a mesh on an ellipsoid)");
    const mcs_node *lon = given(map, "longitude"), *lat = given(map, "latitude");
    if (!(lon->items[0]->num < lon->items[1]->num &&
          lon->items[1]->num - lon->items[0]->num <= 2 * M_PI + 1e-12))
        return mcs_node_error(lon, w->err, MCS_ERR_RANGE,
                              "expected [from, to] with from < to, at most one turn apart");
    /* the poles stay out: the elements there would be wedges */
    if (!(lat->items[0]->num < lat->items[1]->num && lat->items[0]->num > -M_PI / 2 &&
          lat->items[1]->num < M_PI / 2))
        return mcs_node_error(lat, w->err, MCS_ERR_RANGE,
                              "expected [from, to] with -90 deg < from < to < 90 deg");
    return MCS_OK;
}

mcs_status mcs_rule_surface_mesh(scn_walk *w, mcs_node *map)
{
    const mcs_node *bn = given(map, "body"), *sn = given(map, "surface");
    const mcs_node *body = bn ? body_named(w->root, bn->text) : NULL;
    if (!body || !sn) return MCS_OK; /* the reference check says what is missing */
    mcs_status st = MCS_OK;
    const char *type = surface_type(w, body, sn, &st);
    if (!type) return st;
    if (strcmp(type, "ellipsoid") == 0) return check_patch(w, map);
    static const char *const keys[] = {"element_size", "longitude", "latitude"};
    for (int i = 0; i < 3; i++)
        if (given(map, keys[i]))
            return mcs_node_error(given(map, keys[i]), w->err, MCS_ERR_KEY,
                                  "a mesh on a facet surface covers it whole, on its own "
                                  "vertices: no %s",
                                  keys[i]);
    return MCS_OK;
}

/* mcs_scn_rule_facet.c: the keys of a facet surface (a triangle mesh on a body, stage 1's
 * ellipsoid-facet contact) checked when the scenario is loaded:
 *   - either file: (an OBJ file, relative to the YAML file that names it; core/mcs_obj.h) or
 *     vertices: and triangles: inline, not both;
 *   - vertices: at least 3 points [x, y, z] in the body frame, each coordinate a length
 *     (converted to metres here); triangles: at least one [i, j, k] of 0-based vertex indices,
 *     counter-clockwise seen from outside (the outward normal by the right hand). */
#include "core/mcs_obj.h"
#include "core/mcs_schema.h"

#include <math.h>
#include <string.h>

static const mcs_node *given(const mcs_node *map, const char *key)
{
    const mcs_node *n = mcs_node_get(map, key);
    return n && n->kind != MCS_NODE_NULL ? n : NULL;
}

static mcs_status check_file(scn_walk *w, const mcs_node *f)
{
    char path[4096];
    if (f->kind != MCS_NODE_STR || !f->text[0])
        return mcs_node_error(f, w->err, MCS_ERR_TYPE, "expected the name of an OBJ file");
    if (mcs_obj_path(mcs_node_file(f), f->text, path, sizeof path))
        return mcs_node_error(f, w->err, MCS_ERR_RANGE, "file name too long");
    mcs_obj_mesh m;
    mcs_error e2 = {0};
    mcs_status st = mcs_obj_read(path, &m, &e2);
    mcs_obj_free(&m);
    return st ? mcs_node_error(f, w->err, st, "%s", e2.msg) : MCS_OK;
}

static mcs_status check_vertices(scn_walk *w, mcs_node *v)
{
    if (v->kind != MCS_NODE_SEQ || v->n < 3)
        return mcs_node_error(v, w->err, MCS_ERR_TYPE,
                              "expected a list of at least 3 points [x, y, z]");
    for (int i = 0; i < v->n; i++) {
        mcs_node *p = v->items[i];
        if (p->kind != MCS_NODE_SEQ || p->n != 3)
            return mcs_node_error(p, w->err, MCS_ERR_TYPE, "expected a point [x, y, z]");
        for (int k = 0; k < 3; k++) {
            mcs_node *c = p->items[k];
            if (c->kind == MCS_NODE_STR) {
                char why[400];
                double si;
                mcs_status st =
                    mcs_quantity_parse(c->text, (mcs_dim)MCS_DIM_LENGTH, &si, why, sizeof why);
                if (st) return mcs_node_error(c, w->err, st, "%s", why);
                c->kind = MCS_NODE_NUM, c->num = si;
            }
            if (c->kind != MCS_NODE_NUM || !isfinite(c->num))
                return mcs_node_error(c, w->err, MCS_ERR_TYPE, "expected a length [m]");
        }
    }
    return MCS_OK;
}

static mcs_status check_triangles(scn_walk *w, mcs_node *t, int nvert)
{
    if (t->kind != MCS_NODE_SEQ || t->n < 1)
        return mcs_node_error(t, w->err, MCS_ERR_TYPE,
                              "expected a list of triangles [i, j, k] (0-based vertex indices)");
    for (int i = 0; i < t->n; i++) {
        mcs_node *p = t->items[i];
        if (p->kind != MCS_NODE_SEQ || p->n != 3)
            return mcs_node_error(p, w->err, MCS_ERR_TYPE, "expected a triangle [i, j, k]");
        for (int k = 0; k < 3; k++) {
            const mcs_node *c = p->items[k];
            if (c->kind != MCS_NODE_NUM || c->num != floor(c->num))
                return mcs_node_error(c, w->err, MCS_ERR_TYPE, "expected a vertex index");
            if (c->num < 0 || c->num >= nvert)
                return mcs_node_error(c, w->err, MCS_ERR_RANGE,
                                      "vertex %g does not exist (0 to %d)", c->num, nvert - 1);
        }
    }
    return MCS_OK;
}

mcs_status mcs_rule_facet(scn_walk *w, mcs_node *map)
{
    const mcs_node *f = given(map, "file");
    mcs_node *v = (mcs_node *)given(map, "vertices"), *t = (mcs_node *)given(map, "triangles");
    if (f && (v || t))
        return mcs_node_error(f, w->err, MCS_ERR_KEY,
                              "give file or vertices and triangles, not both");
    if (f) return check_file(w, f);
    if (!v || !t)
        return mcs_node_error(map, w->err, MCS_ERR_KEY,
                              "a facet surface needs vertices and triangles (or file)");
    mcs_status st = check_vertices(w, v);
    return st ? st : check_triangles(w, t, v->n);
}

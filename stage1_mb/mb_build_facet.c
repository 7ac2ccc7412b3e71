/* mb_build_facet.c: a facet surface of the scenario -> its mesh (mb_facet.h). The schema
 * (core/mcs_scn_rule_facet.c) has checked the form, converted the lengths and the indices'
 * range; the mesh builder rejects zero-area triangles. */
#include "core/mcs_obj.h"
#include "stage1_mb/mb_build_internal.h"
#include "stage1_mb/mb_facet.h"

#include <stdlib.h>

static mcs_status from_inline(const mcs_node *n, mb_surface *s, mcs_error *err)
{
    const mcs_node *vl = mcs_node_get(n, "vertices"), *tl = mcs_node_get(n, "triangles");
    int nv = mcs_node_len(vl), nt = mcs_node_len(tl);
    double *v = malloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
    int *t = malloc(sizeof(int) * 3 * (size_t)(nt > 0 ? nt : 1));
    mcs_status st = v && t ? MCS_OK : MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int i = 0; !st && i < nv; i++)
        st = mcs_node_vec3(mcs_node_at(vl, i), v + 3 * i, err);
    for (int i = 0; !st && i < nt; i++)
        for (int k = 0; k < 3; k++)
            t[3 * i + k] = (int)mcs_node_num(mcs_node_at(mcs_node_at(tl, i), k));
    if (!st) {
        mcs_error e2 = {0};
        st = mb_mesh_create(&s->mesh, nv, v, nt, t, &e2);
        if (st) st = mcs_node_error(tl, err, st, "%s", e2.msg);
    }
    free(v), free(t);
    return st;
}

static mcs_status from_file(const mcs_node *f, mb_surface *s, mcs_error *err)
{
    char path[4096];
    if (mcs_obj_path(mcs_node_file(f), mcs_node_str(f), path, sizeof path))
        return mcs_node_error(f, err, MCS_ERR_RANGE, "file name too long");
    mcs_obj_mesh o;
    mcs_error e2 = {0};
    mcs_status st = mcs_obj_read(path, &o, &e2);
    if (!st) st = mb_mesh_create(&s->mesh, o.nvert, o.vert, o.ntri, o.tri, &e2);
    mcs_obj_free(&o);
    return st ? mcs_node_error(f, err, st, "%s", e2.msg) : MCS_OK;
}

mcs_status mb_build_facet(const mcs_node *n, mb_surface *s, mcs_error *err)
{
    s->type = MB_SURF_FACET;
    const mcs_node *f = mcs_node_get(n, "file");
    return mcs_node_kind(f) == MCS_NODE_STR ? from_file(f, s, err) : from_inline(n, s, err);
}

/* mcs_scn_rule_mesh.c: a mesh from a file (fe.parts[].mesh without generate:): a keyword deck's
 * part {keyword, part, units, unknown_keywords} or a results file's part {from, at}. */
#include "core/mcs_schema.h"

#include <string.h>

static mcs_node *given(mcs_node *map, const char *key)
{
    mcs_node *n = (mcs_node *)mcs_node_get(map, key);
    return n && n->kind != MCS_NODE_NULL ? n : NULL;
}

mcs_status mcs_rule_mesh_file(scn_walk *w, mcs_node *map)
{
    static const char *const kw_only[] = {"part", "units", "unknown_keywords"};
    mcs_node *kw = given(map, "keyword"), *from = given(map, "from"), *at = given(map, "at");
    if (!kw && !from)
        return scn_walk_fail(w, map, "keyword", MCS_ERR_KEY,
                             "required key is missing (a mesh needs generate:, keyword: or from:)");
    if (kw && from)
        return scn_walk_fail(w, from, "from", MCS_ERR_KEY, "give keyword: or from:, not both");
    if (kw && !given(map, "part"))
        return scn_walk_fail(w, map, "part", MCS_ERR_KEY, "required key is missing (keyword:)");
    if (kw && at) return scn_walk_fail(w, at, "at", MCS_ERR_KEY, "at: goes with from:");
    for (int i = 0; from && i < 3; i++)
        if (given(map, kw_only[i]))
            return scn_walk_fail(w, given(map, kw_only[i]), kw_only[i], MCS_ERR_KEY,
                                 "goes with keyword:, not from: (the part is in the path)");
    if (!at || (at->kind == MCS_NODE_STR && strcmp(at->text, "final") == 0)) return MCS_OK;
    size_t old = scn_walk_push_key(w, "at");
    mcs_status st = scn_quantity(w, at, (mcs_dim)MCS_DIM_TIME);
    scn_walk_pop(w, old);
    if (!st && !(at->num >= 0))
        return scn_walk_fail(w, at, "at", MCS_ERR_RANGE, "%g s: a time >= 0 or final", at->num);
    return st;
}

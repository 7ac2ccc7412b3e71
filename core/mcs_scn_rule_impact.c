/* mcs_scn_rule_impact.c: the cross-key rules of the impact: block (stage1_mb/mb_impact.c applies
 * it). Checked when a scenario is loaded, so `mcrash check` reports them:
 *   - motorcycle_contact and opponent_contact come together (a placement needs both points);
 *   - motorcycle_bodies / opponent_bodies: a body name or pattern (* and ?, fnmatch), or a
 *     non-empty list of them; every pattern matches at least one body;
 *   - the two groups share no body; the motorcycle group is not empty when the block asks for a
 *     placement, a rotation or a speed (its default patterns are moto_* and rider_*);
 *   - opponent_heading is not vertical (the opponent drives on the ground). */
#include "core/mcs_schema.h"

#include <fnmatch.h>
#include <math.h>
#include <string.h>

static const mcs_node *given(const mcs_node *map, const char *key)
{
    const mcs_node *n = mcs_node_get(map, key);
    return n && n->kind != MCS_NODE_NULL ? n : NULL;
}

static const char *const default_moto[] = {"moto_*", "rider_*"};

/* does body name match the patterns of node g (NULL: the motorcycle defaults)? */
static int in_group(const mcs_node *g, const char *name)
{
    if (!g) {
        for (int i = 0; i < 2; i++)
            if (fnmatch(default_moto[i], name, 0) == 0) return 1;
        return 0;
    }
    if (g->kind == MCS_NODE_STR) return fnmatch(g->text, name, 0) == 0;
    for (int i = 0; i < g->n; i++)
        if (fnmatch(g->items[i]->text, name, 0) == 0) return 1;
    return 0;
}

static const char *body_name(const mcs_node *b)
{
    const mcs_node *n = mcs_node_get(b, "name");
    return n && n->text ? n->text : "";
}

/* a pattern, or a list of them, each matching a body */
static mcs_status check_group(scn_walk *w, const mcs_node *g, const mcs_node *bodies)
{
    if (!g) return MCS_OK;
    if (g->kind != MCS_NODE_STR && g->kind != MCS_NODE_SEQ)
        return mcs_node_error(g, w->err, MCS_ERR_TYPE,
                              "expected a body name or pattern, or a list of them");
    if (g->kind == MCS_NODE_SEQ && g->n == 0)
        return mcs_node_error(g, w->err, MCS_ERR_RANGE, "the list of bodies is empty");
    int n = g->kind == MCS_NODE_STR ? 1 : g->n;
    for (int i = 0; i < n; i++) {
        const mcs_node *p = g->kind == MCS_NODE_STR ? g : g->items[i];
        if (p->kind != MCS_NODE_STR || !p->text || !p->text[0])
            return mcs_node_error(p, w->err, MCS_ERR_TYPE, "expected a body name or pattern");
        int hit = 0;
        for (int b = 0; b < mcs_node_len(bodies) && !hit; b++)
            hit = fnmatch(p->text, body_name(bodies->items[b]), 0) == 0;
        if (!hit) return mcs_node_error(p, w->err, MCS_ERR_KEY, "'%s' matches no body", p->text);
    }
    return MCS_OK;
}

mcs_status mcs_rule_impact(scn_walk *w, mcs_node *map)
{
    const mcs_node *mc = given(map, "motorcycle_contact"), *oc = given(map, "opponent_contact");
    if (!mc != !oc)
        return mcs_node_error(mc ? mc : oc, w->err, MCS_ERR_KEY,
                              "%s needs %s too (the placement brings the two points together)",
                              mc ? "motorcycle_contact" : "opponent_contact",
                              mc ? "opponent_contact" : "motorcycle_contact");
    const mcs_node *h = given(map, "opponent_heading");
    if (h && hypot(h->items[0]->num, h->items[1]->num) <= 1e-9 * fabs(h->items[2]->num))
        return mcs_node_error(h, w->err, MCS_ERR_RANGE,
                              "the opponent's heading must not be vertical");
    const mcs_node *bodies = mcs_node_get(w->root, "bodies");
    const mcs_node *gm = given(map, "motorcycle_bodies"), *go = given(map, "opponent_bodies");
    mcs_status st = check_group(w, gm, bodies);
    if (!st) st = check_group(w, go, bodies);
    if (st) return st;
    int nmoto = 0;
    for (int b = 0; b < mcs_node_len(bodies); b++) {
        const char *nm = body_name(bodies->items[b]);
        int m = in_group(gm, nm);
        nmoto += m;
        if (m && go && in_group(go, nm))
            return mcs_node_error(go, w->err, MCS_ERR_RANGE,
                                  "body '%s' is in both the motorcycle and the opponent group", nm);
    }
    int acts = mc || given(map, "heading_angle") || given(map, "motorcycle_speed") ||
               given(map, "roll_angle");
    if (acts && nmoto == 0)
        return mcs_node_error(map, w->err, MCS_ERR_KEY,
                              "the motorcycle group is empty: no body matches %s",
                              gm ? "motorcycle_bodies" : "moto_* or rider_* (motorcycle_bodies)");
    return MCS_OK;
}

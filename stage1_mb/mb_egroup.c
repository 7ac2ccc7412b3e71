/* mb_egroup.c: energy groups (mb_egroup.h): model (members, partners and the map of every
 * load source to its partner) and the step's work. */
#include "stage1_mb/mb_egroup_impl.h"
#include "fe/fe_restraint.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_contact.h"
#include "stage1_mb/mb_couple_rx.h"
#include "stage1_mb/mb_prescribe.h"
#include "stage1_mb/mb_vec.h"

#include <fnmatch.h>
#include <stdlib.h>
#include <string.h>

/* ---- model ------------------------------------------------------------------------------ */

static int partner_of(eg_group *g, const char *name, const char *cat)
{
    for (int p = 0; p < g->npartner; p++)
        if (strcmp(g->pname[p], name) == 0) return p;
    mb_name *nn = realloc(g->pname, sizeof *nn * (size_t)(g->npartner + 1));
    if (nn) g->pname = nn;
    char(*nc)[MB_EGROUP_CAT] = realloc(g->pcat, sizeof *nc * (size_t)(g->npartner + 1));
    if (nc) g->pcat = nc;
    if (!nn || !nc) return -3;
    snprintf(g->pname[g->npartner], MB_NAME, "%s", name);
    snprintf(g->pcat[g->npartner], MB_EGROUP_CAT, "%s", cat);
    return g->npartner++;
}

static int member(const mb_model *m, const eg_group *g, int b)
{
    (void)m;
    return b >= 0 && g->in[b];
}

/* category of an outside body (MB_GROUND: ground): its impact group; without an impact: block
 * the motorcycle model's moto_* bodies (a stage-2 model's prescribed motorcycle) */
static const char *body_category(const mb_model *m, int b)
{
    if (b < 0) return "ground";
    if (m->body_group && m->body_group[b] == MB_GROUP_MOTO) return "motorcycle";
    if (m->body_group && m->body_group[b] == MB_GROUP_OPP) return "opponent";
    if (!m->body_group && fnmatch("moto_*", m->body_name[b], 0) == 0) return "motorcycle";
    return "bodies";
}

/* a source between bodies a and b: its partner (named name, category of the outside body),
 * EG_INTERNAL or EG_NONE */
static int two_body(const mb_model *m, eg_group *g, int a, int b, const char *name)
{
    int ia = member(m, g, a), ib = member(m, g, b);
    if (ia && ib) return EG_INTERNAL;
    if (!ia && !ib) return EG_NONE;
    return partner_of(g, name, body_category(m, ia ? b : a));
}

/* category of an FE part by name: belts (trusses), airbags (fabric), foam, fe */
static const char *part_category(const fe_model *fm, const char *part)
{
    for (int i = 0; i < fm->npart; i++) {
        const fe_part *p = &fm->part[i];
        if (strcmp(p->name, part) != 0) continue;
        if (p->elem_kind == FE_KIND_TRUSS) return "belts";
        if (p->material.model == FE_MAT_FABRIC) return "airbags";
        if (p->material.model == FE_MAT_FOAM) return "foam";
        return "fe";
    }
    return "fe";
}

static int *alloc_map(int n)
{
    int *v = malloc(sizeof *v * (size_t)(n > 0 ? n : 1));
    for (int i = 0; v && i < n; i++)
        v[i] = EG_NONE;
    return v;
}

/* the FE sources: attached nodes, anchors, bodies-contact surfaces */
static int map_fe(const mb_model *m, eg_group *g)
{
    const mb_couple *c = m->couple;
    const fe_model *fm = c->fe.model;
    g->nnode = c->natt, g->nanchor = c->rx ? c->rx->nanchor : 0;
    g->nsurf = mb_couple_contact_nsurf(m);
    if (!(g->node = alloc_map(g->nnode)) || !(g->anchor = alloc_map(g->nanchor)) ||
        !(g->surf = alloc_map(g->nsurf)))
        return -1;
    for (int a = 0; a < c->natt; a++) {
        if (!member(m, g, c->body[a])) continue;
        const int ip = fm->node_part[c->node[a]];
        const char *pn = ip >= 0 ? fm->part[ip].name : "fe";
        g->node[a] = partner_of(g, pn, part_category(fm, pn));
    }
    for (int a = 0; a < g->nanchor; a++)
        if (member(m, g, c->rx->anchor_body[a]))
            g->anchor[a] =
                partner_of(g, fm->restraints->retractor[c->rx->anchor_ret[a]].name, "belts");
    for (int k = 0; k < g->nsurf; k++) {
        int ct;
        if (!member(m, g, mb_couple_contact_surf(m, k, &ct))) continue;
        const char *part0, *label = mb_couple_contact_label(m, ct, &part0);
        g->surf[k] = partner_of(g, label, part_category(fm, part0));
    }
    for (int i = 0; i < g->nnode; i++)
        if (g->node[i] < EG_INTERNAL) return -1;
    for (int i = 0; i < g->nanchor; i++)
        if (g->anchor[i] < EG_INTERNAL) return -1;
    for (int i = 0; i < g->nsurf; i++)
        if (g->surf[i] < EG_INTERNAL) return -1;
    return 0;
}

static int map_sources(const mb_model *m, eg_group *g)
{
    if (!(g->pair = alloc_map(m->npair)) || !(g->att = alloc_map(m->nattach)) ||
        !(g->joint = alloc_map(m->njoint)))
        return -1;
    for (int i = 0; i < m->npair; i++) {
        const mb_pair *p = &m->pair[i];
        g->pair[i] = two_body(m, g, p->ba, p->bb, m->contact[p->contact].name);
    }
    for (int i = 0; i < m->nattach; i++)
        g->att[i] = two_body(m, g, m->attach[i].body_a, m->attach[i].body_b, m->attach_name[i]);
    for (int j = 0; j < m->njoint; j++)
        g->joint[j] = two_body(m, g, m->joint[j].parent, m->joint[j].child, m->joint[j].name);
    for (int i = 0; i < m->npair; i++)
        if (g->pair[i] < EG_INTERNAL) return -1;
    for (int i = 0; i < m->nattach; i++)
        if (g->att[i] < EG_INTERNAL) return -1;
    for (int i = 0; i < m->njoint; i++)
        if (g->joint[i] < EG_INTERNAL) return -1;
    return m->couple ? map_fe(m, g) : 0;
}

static void group_free(eg_group *g)
{
    free(g->in), free(g->pname), free(g->pcat), free(g->pair), free(g->att), free(g->joint);
    free(g->node), free(g->anchor), free(g->surf);
}

mcs_status mb_egroup_add(mb_model *m, const char *name, const char *const *patterns, int npattern,
                         mcs_error *err)
{
    if (!m->egroup && !(m->egroup = calloc(1, sizeof *m->egroup)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    struct mb_egroup *e = m->egroup;
    eg_group *ng = realloc(e->g, sizeof *ng * (size_t)(e->ngroup + 1));
    if (!ng) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    e->g = ng;
    eg_group *g = &e->g[e->ngroup++];
    memset(g, 0, sizeof *g);
    snprintf(g->name, MB_NAME, "%s", name);
    if (!(g->in = calloc((size_t)(m->nbody > 0 ? m->nbody : 1), 1)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int b = 0; b < m->nbody; b++)
        for (int k = 0; k < npattern && !g->in[b]; k++)
            if (fnmatch(patterns[k], m->body_name[b], 0) == 0 && !mb_body_prescribed(m, b))
                g->in[b] = 1, g->nmember++;
    if (map_sources(m, g)) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    return MCS_OK;
}

/* a scenario group's categories: {<partner name or pattern>: <category>}, in order (a later
 * match wins); a key that matches no partner is an error at it */
static mcs_status categories(const mb_model *m, eg_group *g, const mcs_node *gn, mcs_error *err)
{
    (void)m;
    const mcs_node *c = mcs_node_get(gn, "categories");
    if (mcs_node_kind(c) == MCS_NODE_NULL) return MCS_OK;
    if (mcs_node_kind(c) != MCS_NODE_MAP)
        return mcs_node_error(c, err, MCS_ERR_TYPE, "a map {partner or pattern: category}");
    for (int i = 0; i < mcs_node_len(c); i++) {
        const char *key = mcs_node_key(c, i), *cat = mcs_node_str(mcs_node_at(c, i));
        if (!cat || !cat[0] || strlen(cat) >= MB_EGROUP_CAT)
            return mcs_node_error(mcs_node_at(c, i), err, MCS_ERR_TYPE,
                                  "a category name of 1 to %d characters", MB_EGROUP_CAT - 1);
        int hit = 0;
        for (int p = 0; p < g->npartner; p++)
            if (fnmatch(key, g->pname[p], 0) == 0)
                snprintf(g->pcat[p], MB_EGROUP_CAT, "%s", cat), hit = 1;
        if (!hit)
            return mcs_node_error(mcs_node_at(c, i), err, MCS_ERR_KEY,
                                  "'%s' matches no partner of group '%s'", key, g->name);
    }
    return MCS_OK;
}

/* the scenario's energy_groups: {<name>: {bodies: name or pattern | [names or patterns]}};
 * a name or pattern that matches no body is an error at it */
static mcs_status scenario_group(mb_model *m, const char *name, const mcs_node *g, mcs_error *err)
{
    const mcs_node *bl = mcs_node_get(g, "bodies");
    const int seq = mcs_node_kind(bl) == MCS_NODE_SEQ, n = seq ? mcs_node_len(bl) : 1;
    const char *pat[64];
    if (n > 64) return mcs_node_error(bl, err, MCS_ERR_RANGE, "at most 64 names or patterns");
    for (int k = 0; k < n; k++) {
        const mcs_node *pn = seq ? mcs_node_at(bl, k) : bl;
        int hit = 0;
        pat[k] = mcs_node_str(pn);
        if (!pat[k]) return mcs_node_error(pn, err, MCS_ERR_TYPE, "a body name or pattern");
        for (int b = 0; b < m->nbody && !hit; b++)
            hit = fnmatch(pat[k], m->body_name[b], 0) == 0;
        if (!hit) return mcs_node_error(pn, err, MCS_ERR_KEY, "no body matches '%s'", pat[k]);
    }
    mcs_status st = mb_egroup_add(m, name, pat, n, err);
    return st ? st : categories(m, &m->egroup->g[m->egroup->ngroup - 1], g, err);
}

mcs_status mb_egroup_build(const mcs_node *root, mb_model *m, mcs_error *err)
{
    static const char *const rider[] = {"rider_*"};
    const mcs_node *eg = mcs_node_get(root, "energy_groups");
    int has_rider = 0;
    for (int i = 0; i < mcs_node_len(eg); i++) {
        const char *name = mcs_node_key(eg, i);
        mcs_status st = scenario_group(m, name, mcs_node_at(eg, i), err);
        if (st) return st;
        has_rider |= strcmp(name, "rider") == 0;
    }
    for (int b = 0; b < m->nbody && !has_rider; b++)
        if (fnmatch(rider[0], m->body_name[b], 0) == 0)
            return mb_egroup_add(m, "rider", rider, 1, err);
    return MCS_OK;
}

void mb_egroup_destroy(struct mb_egroup **p)
{
    struct mb_egroup *e = p ? *p : NULL;
    if (!e) return;
    for (int i = 0; i < e->ngroup; i++)
        group_free(&e->g[i]);
    free(e->g), free(e);
    *p = NULL;
}

mcs_status mb_egroup_state_create(const mb_model *m, struct mb_egroup_state **out, mcs_error *err)
{
    *out = NULL;
    const struct mb_egroup *e = m->egroup;
    struct mb_egroup_state *s = calloc(1, sizeof *s);
    int ok = s != NULL;
    if (ok) {
        s->ngroup = e->ngroup;
        s->work = calloc((size_t)e->ngroup, sizeof *s->work);
        s->rec = calloc((size_t)e->ngroup, sizeof *s->rec);
        s->now = calloc((size_t)e->ngroup, sizeof *s->now);
        s->vbar = calloc(6 * (size_t)(m->nbody > 0 ? m->nbody : 1), sizeof *s->vbar);
        ok = s->work && s->rec && s->now && s->vbar;
    }
    for (int i = 0; ok && i < e->ngroup; i++) {
        const size_t w = (size_t)(MB_EGROUP_NSERIES + e->g[i].npartner);
        s->work[i] = calloc((size_t)e->g[i].npartner + 1, sizeof(double));
        s->rec[i] = calloc(w * (size_t)(m->nout > 0 ? m->nout : 1), sizeof(double));
        s->now[i] = calloc(w, sizeof(double));
        ok = s->work[i] && s->rec[i] && s->now[i];
    }
    if (!ok) {
        mb_egroup_state_destroy(&s);
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory for the energy groups");
    }
    *out = s;
    return MCS_OK;
}

void mb_egroup_state_destroy(struct mb_egroup_state **p)
{
    struct mb_egroup_state *s = p ? *p : NULL;
    if (!s) return;
    for (int i = 0; i < s->ngroup; i++) {
        if (s->work) free(s->work[i]);
        if (s->rec) free(s->rec[i]);
        if (s->now) free(s->now[i]);
    }
    free(s->work), free(s->rec), free(s->now), free(s->vbar), free(s);
    *p = NULL;
}

/* fe_restraint: gas bags and retractors — builder lists, model build (surfaces, anchors,
 * stiffnesses) and state lifecycle. The per-step coupling is fe_restraint_step.c. */
#include "fe/fe_restraint.h"
#include "fe/fe_builder_impl.h"
#include "fe/fe_surface_volume.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct fe_restraint_list {
    int nbag, cap_bag, nret, cap_ret;
    fe_airbag_desc *bag;
    fe_belt_retractor_desc *ret;
};

fe_airbag_desc fe_airbag_desc_default(void)
{
    fe_airbag_desc d;
    memset(&d, 0, sizeof d);
    d.gas = fe_gasbag_desc_default();
    return d;
}

fe_belt_retractor_desc fe_belt_retractor_desc_default(void)
{
    fe_belt_retractor_desc d;
    memset(&d, 0, sizeof d);
    d.node = -1;
    d.where = FE_WHERE_ALL;
    d.retractor = fe_retractor_desc_default();
    return d;
}

static int grow(void **p, int *cap, int need, size_t sz)
{
    if (need <= *cap) return 0;
    int nc = *cap ? 2 * *cap : 4;
    void *q = realloc(*p, (size_t)nc * sz);
    if (!q) return -1;
    *p = q;
    *cap = nc;
    return 0;
}

static struct fe_restraint_list *list_of(fe_builder *b)
{
    if (!b->restraints) b->restraints = calloc(1, sizeof *b->restraints);
    return b->restraints;
}

void fe_restraint_list_free(fe_builder *b)
{
    if (!b->restraints) return;
    free(b->restraints->bag);
    free(b->restraints->ret);
    free(b->restraints);
    b->restraints = NULL;
}

static int named(const char *name) { return name[0] && memchr(name, 0, FE_NAME_MAX) != NULL; }

mcs_status fe_builder_add_airbag(fe_builder *b, const fe_airbag_desc *d, mcs_error *err)
{
    struct fe_restraint_list *l = list_of(b);
    if (!l) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding a gas bag");
    if (!named(d->name))
        return MCS_ERR(err, MCS_ERR_KEY, "fe: a gas bag needs a name (< %d characters)",
                       FE_NAME_MAX);
    for (int i = 0; i < l->nbag; i++)
        if (strcmp(l->bag[i].name, d->name) == 0)
            return MCS_ERR(err, MCS_ERR_KEY, "fe: gas bag '%s' is defined twice", d->name);
    if (d->nparts < 1 || d->nparts > FE_RESTRAINT_PARTS_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: gas bag '%s': 1..%d parts", d->name,
                       FE_RESTRAINT_PARTS_MAX);
    if (!(d->initial_pressure >= 0) || !(d->initial_temperature >= 0) ||
        !isfinite(d->initial_pressure + d->initial_temperature))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: gas bag '%s': initial pressure and temperature must be >= 0", d->name);
    if (grow((void **)&l->bag, &l->cap_bag, l->nbag + 1, sizeof *l->bag))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding a gas bag");
    l->bag[l->nbag++] = *d;
    return MCS_OK;
}

mcs_status fe_builder_add_retractor(fe_builder *b, const fe_belt_retractor_desc *d,
                                    mcs_error *err)
{
    struct fe_restraint_list *l = list_of(b);
    if (!l) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding a retractor");
    if (!named(d->name))
        return MCS_ERR(err, MCS_ERR_KEY, "fe: a retractor needs a name (< %d characters)",
                       FE_NAME_MAX);
    for (int i = 0; i < l->nret; i++)
        if (strcmp(l->ret[i].name, d->name) == 0)
            return MCS_ERR(err, MCS_ERR_KEY, "fe: retractor '%s' is defined twice", d->name);
    if (!isfinite(d->anchor[0] + d->anchor[1] + d->anchor[2]) || !(d->stiffness >= 0) ||
        !isfinite(d->stiffness))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: retractor '%s': anchor must be finite and stiffness >= 0", d->name);
    if (grow((void **)&l->ret, &l->cap_ret, l->nret + 1, sizeof *l->ret))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding a retractor");
    l->ret[l->nret++] = *d;
    return MCS_OK;
}

double *fe_builder_retractor_anchor(fe_builder *b, const char *name)
{
    struct fe_restraint_list *l = b->restraints;
    for (int i = 0; l && name && i < l->nret; i++)
        if (strcmp(l->ret[i].name, name) == 0) return l->ret[i].anchor;
    return NULL;
}

/* the faces of a bag's parts: shells and membranes, degenerate shells as triangles */
static mcs_status bag_surface(const fe_builder *b, const fe_model *m, const fe_airbag_desc *d,
                              fe_airbag *bag, mcs_error *err)
{
    int n = 0, ip[FE_RESTRAINT_PARTS_MAX];
    for (int j = 0; j < d->nparts; j++) {
        ip[j] = fe_builder_find_part(b, d->parts[j]);
        if (ip[j] < 0)
            return MCS_ERR(err, MCS_ERR_KEY, "fe: gas bag '%s': unknown part '%s'", d->name,
                           d->parts[j]);
        const fe_part *p = &m->part[ip[j]];
        if (p->elem_kind != FE_KIND_SHELL)
            return MCS_ERR(err, MCS_ERR_TYPE,
                           "fe: gas bag '%s': part '%s' must be made of shells or membranes",
                           d->name, d->parts[j]);
        for (int k = 0; k < j; k++)
            if (ip[k] == ip[j])
                return MCS_ERR(err, MCS_ERR_KEY, "fe: gas bag '%s': part '%s' listed twice",
                               d->name, d->parts[j]);
        n += p->elem_end - p->elem_begin;
    }
    bag->face = malloc(sizeof(int) * 4 * (size_t)n);
    if (!bag->face) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (gas bag)");
    bag->nface = n;
    int *f = bag->face;
    for (int j = 0; j < d->nparts; j++) {
        const fe_part *p = &m->part[ip[j]];
        for (int e = p->elem_begin; e < p->elem_end; e++, f += 4) {
            memcpy(f, m->shell_node + 4 * e, 4 * sizeof(int));
            if (f[2] == f[3]) f[3] = -1;
        }
    }
    char label[FE_NAME_MAX + 16];
    snprintf(label, sizeof label, "fe: gas bag '%s'", d->name);
    mcs_status st = fe_surface_check(label, m->nnode, bag->nface, bag->face, err);
    if (st != MCS_OK) return st;
    bag->volume0 = fe_surface_volume(bag->nface, bag->face, m->node_x0);
    if (bag->volume0 < 0) { /* consistently inward: turn every face round */
        for (int i = 0; i < bag->nface; i++) {
            int *g = bag->face + 4 * i, t = g[1];
            if (g[3] < 0) {
                g[1] = g[2];
                g[2] = t;
            } else {
                g[1] = g[3];
                g[3] = t;
            }
        }
        bag->volume0 = -bag->volume0;
    }
    if (!(bag->volume0 > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: gas bag '%s': the surface encloses no volume",
                       d->name);
    return MCS_OK;
}

static mcs_status make_bag(const fe_builder *b, fe_model *m, const fe_airbag_desc *d,
                           fe_airbag *bag, mcs_error *err)
{
    memcpy(bag->name, d->name, FE_NAME_MAX);
    char label[FE_NAME_MAX + 16];
    snprintf(label, sizeof label, "fe: gas bag '%s'", d->name);
    mcs_status st = bag_surface(b, m, d, bag, err);
    if (st == MCS_OK) st = fe_gasbag_model_create(label, &d->gas, &bag->gas, err);
    if (st != MCS_OK) return st;
    bag->p0 = d->initial_pressure > 0 ? d->initial_pressure : bag->gas->ambient_pressure;
    bag->T0 = d->initial_temperature > 0 ? d->initial_temperature : bag->gas->ambient_temperature;
    m->bytes += sizeof(int) * 4 * (size_t)bag->nface + sizeof *bag->gas;
    return MCS_OK;
}

static mcs_status make_retractor(const fe_builder *b, fe_model *m,
                                 const fe_belt_retractor_desc *d, fe_belt_retractor *r,
                                 mcs_error *err)
{
    memcpy(r->name, d->name, FE_NAME_MAX);
    memcpy(r->anchor, d->anchor, sizeof r->anchor);
    int ip = -1;
    if (d->node >= 0) {
        if (d->node >= m->nnode)
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: retractor '%s': node %d does not exist",
                           d->name, d->node);
        r->node = d->node;
        ip = m->node_part[r->node];
    } else {
        ip = fe_builder_find_part(b, d->part);
        if (ip < 0)
            return MCS_ERR(err, MCS_ERR_KEY, "fe: retractor '%s': unknown part '%s'", d->name,
                           d->part);
        int idx[2];
        int cnt = fe_builder_select(b, ip, d->where, idx, 2);
        if (cnt != 1)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: retractor '%s': `where` must select one node of part '%s' (the "
                           "belt end), got %d",
                           d->name, d->part, cnt);
        r->node = idx[0];
    }
    double dx[3];
    for (int i = 0; i < 3; i++) dx[i] = m->node_x0[3 * r->node + i] - r->anchor[i];
    r->l0 = sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
    if (!(r->l0 > 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: retractor '%s': the anchor must lie away from the belt end node",
                       d->name);
    r->k = d->stiffness;
    if (!(r->k > 0)) {
        const fe_part *p = ip >= 0 ? &m->part[ip] : NULL;
        if (!p || p->elem_kind != FE_KIND_TRUSS)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: retractor '%s': give a stiffness (the node is not on a truss "
                           "belt part)",
                           d->name);
        r->k = p->material.youngs_modulus * p->section.area / r->l0;
    }
    if (!(m->node_mass[r->node] > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: retractor '%s': node %d has no mass", d->name,
                       r->node);
    /* the segment's step 2/w, w^2 = 2k/m (the node's other springs counted as stiff as it) */
    double dtr = m->opts.dt_scale * 2 * sqrt(m->node_mass[r->node] / (2 * r->k));
    m->opts.dt_max = m->opts.dt_max > 0 ? fmin(m->opts.dt_max, dtr) : dtr;
    char label[FE_NAME_MAX + 16];
    snprintf(label, sizeof label, "fe: retractor '%s'", d->name);
    mcs_status st = fe_retractor_model_create(label, &d->retractor, &r->model, err);
    if (st == MCS_OK) m->bytes += sizeof *r->model;
    return st;
}

mcs_status fe_restraints_create(const fe_builder *b, fe_model *m, mcs_error *err)
{
    const struct fe_restraint_list *l = b->restraints;
    m->restraints = NULL;
    if (!l || (l->nbag == 0 && l->nret == 0)) return MCS_OK;
    struct fe_restraints *r = calloc(1, sizeof *r);
    if (r) {
        r->bag = calloc((size_t)(l->nbag ? l->nbag : 1), sizeof *r->bag);
        r->retractor = calloc((size_t)(l->nret ? l->nret : 1), sizeof *r->retractor);
    }
    m->restraints = r;
    if (!r || !r->bag || !r->retractor)
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (restraints)");
    m->bytes += sizeof *r + sizeof *r->bag * (size_t)l->nbag +
                sizeof *r->retractor * (size_t)l->nret;
    mcs_status st = MCS_OK;
    for (int i = 0; i < l->nbag && st == MCS_OK; i++, r->nbag++)
        st = make_bag(b, m, &l->bag[i], &r->bag[i], err);
    for (int i = 0; i < l->nret && st == MCS_OK; i++, r->nretractor++)
        st = make_retractor(b, m, &l->ret[i], &r->retractor[i], err);
    return st;
}

void fe_restraints_destroy(struct fe_restraints **p)
{
    if (!p || !*p) return;
    struct fe_restraints *r = *p;
    for (int i = 0; i < r->nbag; i++) {
        fe_gasbag_model_destroy(&r->bag[i].gas);
        free(r->bag[i].face);
    }
    for (int i = 0; i < r->nretractor; i++) fe_retractor_model_destroy(&r->retractor[i].model);
    free(r->bag);
    free(r->retractor);
    free(r);
    *p = NULL;
}

mcs_status fe_restraint_state_create(const fe_model *m, struct fe_restraint_state **out,
                                     size_t *bytes, mcs_error *err)
{
    *out = NULL;
    const struct fe_restraints *r = m->restraints;
    if (!r) return MCS_OK;
    struct fe_restraint_state *s = calloc(1, sizeof *s);
    if (s) {
        s->bag = calloc((size_t)(r->nbag ? r->nbag : 1), sizeof *s->bag);
        s->retractor = calloc((size_t)(r->nretractor ? r->nretractor : 1), sizeof *s->retractor);
        s->retractor_length = calloc((size_t)(r->nretractor ? r->nretractor : 1), sizeof(double));
        s->retractor_ring = calloc((size_t)(r->nretractor ? r->nretractor : 1), sizeof(double));
        s->retractor_anchor = calloc(3 * (size_t)(r->nretractor ? r->nretractor : 1), sizeof(double));
        s->retractor_fanchor = calloc(3 * (size_t)(r->nretractor ? r->nretractor : 1), sizeof(double));
    }
    if (!s || !s->bag || !s->retractor || !s->retractor_length || !s->retractor_ring ||
        !s->retractor_anchor || !s->retractor_fanchor) {
        fe_restraint_state_destroy(&s);
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (restraint state)");
    }
    *bytes += sizeof *s + sizeof *s->bag * (size_t)r->nbag +
              (sizeof *s->retractor + 8 * sizeof(double)) * (size_t)r->nretractor;
    *out = s;
    return MCS_OK;
}

void fe_restraint_state_destroy(struct fe_restraint_state **p)
{
    if (!p || !*p) return;
    free((*p)->bag);
    free((*p)->retractor);
    free((*p)->retractor_length);
    free((*p)->retractor_ring);
    free((*p)->retractor_anchor);
    free((*p)->retractor_fanchor);
    free(*p);
    *p = NULL;
}

void fe_restraint_state_reset(const fe_model *m, fe_state *s)
{
    const struct fe_restraints *r = m->restraints;
    struct fe_restraint_state *rs = s->restraint;
    if (!r || !rs) return;
    for (int i = 0; i < r->nbag; i++) {
        const fe_airbag *bag = &r->bag[i];
        double A = fe_surface_area(bag->nface, bag->face, m->node_x0);
        mcs_error e = {0};
        /* the volume was checked > 0 at build, so this cannot fail */
        fe_gasbag_state_init_gas(bag->gas, &rs->bag[i], 0.0, bag->volume0, A, bag->p0, bag->T0,
                                 &e);
    }
    for (int i = 0; i < r->nretractor; i++) {
        fe_retractor_state_init(r->retractor[i].model, &rs->retractor[i], 0.0);
        rs->retractor_length[i] = r->retractor[i].l0;
        rs->retractor_ring[i] = 0;
        for (int j = 0; j < 3; j++) {
            rs->retractor_anchor[3 * i + j] = r->retractor[i].anchor[j];
            rs->retractor_fanchor[3 * i + j] = 0;
        }
    }
}

int fe_airbag_find(const fe_model *m, const char *name)
{
    const struct fe_restraints *r = m->restraints;
    for (int i = 0; r && i < r->nbag; i++)
        if (strcmp(r->bag[i].name, name) == 0) return i;
    return -1;
}

int fe_retractor_find(const fe_model *m, const char *name)
{
    const struct fe_restraints *r = m->restraints;
    for (int i = 0; r && i < r->nretractor; i++)
        if (strcmp(r->retractor[i].name, name) == 0) return i;
    return -1;
}

/* fe_scn_restraints.c: scenario keys -> membrane meshes, fabric, gas bags and retractors, and
 * their /stage<N> results (see fe_scn_restraints.h). The kernel's descriptors carry the key names
 * (docs/fe.md, docs/gasbag.md); kernel errors are relocated to the scenario node. */
#include "fe/fe_scn_restraints.h"
#include "fe/scn/fe_scn_node.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

mcs_status fe_scn_read_shell_mesh(const mcs_node *mesh, const char *gen, fe_mesh_desc *d,
                              mcs_error *err)
{
    mcs_status st = MCS_OK;
    d->element_size = mcs_node_num(fe_scn_get(mesh, "element_size"));
    if (fe_scn_given(mesh, "origin"))
        st = mcs_node_vec3(fe_scn_get(mesh, "origin"), d->origin, err);
    if (strcmp(gen, "sphere_shell") == 0) {
        d->generate = FE_MESH_SPHERE_SHELL;
        d->radius = mcs_node_num(fe_scn_get(mesh, "radius"));
        return st;
    }
    if (strcmp(gen, "flat_bag") == 0) {
        d->generate = FE_MESH_FLAT_BAG;
        if (!st) st = mcs_node_vec(fe_scn_get(mesh, "size"), d->size, 2, err);
        d->gap = mcs_node_num(fe_scn_get(mesh, "gap"));
        d->axis = fe_scn_axis_of(mcs_node_str(fe_scn_get(mesh, "axis")), 2);
        return st;
    }
    d->generate = FE_MESH_CYLINDER_SHELL;
    d->diameter = mcs_node_num(fe_scn_get(mesh, "diameter"));
    d->length = mcs_node_num(fe_scn_get(mesh, "length"));
    d->axis = fe_scn_axis_of(mcs_node_str(fe_scn_get(mesh, "axis")), 2);
    d->closed = mcs_node_bool(fe_scn_get(mesh, "closed"), 0);
    return st;
}

mcs_status fe_scn_read_fabric(const mcs_node *mat, fe_material_desc *d, mcs_error *err)
{
    d->model = FE_MAT_FABRIC;
    d->density = mcs_node_num(fe_scn_get(mat, "density"));
    d->youngs_modulus = mcs_node_num(fe_scn_get(mat, "youngs_modulus"));
    d->poisson = mcs_node_num(fe_scn_get(mat, "poisson"));
    d->fabric_e2 = mcs_node_num_or(mat, "youngs_modulus_b", 0);
    d->fabric_g12 = mcs_node_num_or(mat, "shear_modulus", 0);
    d->fabric_damping = mcs_node_num_or(mat, "damping", 0);
    if (fe_scn_given(mat, "direction"))
        return mcs_node_vec3(fe_scn_get(mat, "direction"), d->fabric_direction, err);
    return MCS_OK;
}

/* piecewise linear, constant beyond the ends */
static double lerp_table(int n, const double *x, const double *y, double t)
{
    if (t <= x[0]) return y[0];
    if (t >= x[n - 1]) return y[n - 1];
    int k = 0;
    while (t > x[k + 1]) k++;
    return y[k] + (t - x[k]) / (x[k + 1] - x[k]) * (y[k + 1] - y[k]);
}

/* the inflator's mass flow and temperature curves on the union of their breakpoints */
static mcs_status read_inflator(const mcs_node *inf, fe_gasbag_desc *g, mcs_error *err)
{
    enum { CAP = FE_GASBAG_TABLE_MAX };
    double xm[CAP], ym[CAP], xt[CAP], yt[CAP];
    const mcs_node *cm = fe_scn_get(inf, "mass_flow"), *ct = fe_scn_get(inf, "temperature");
    int nm = mcs_node_curve_len(cm), nt = mcs_node_curve_len(ct);
    if (nm > CAP || nt > CAP)
        return mcs_node_error(nm > CAP ? cm : ct, err, MCS_ERR_RANGE, "at most %d points", CAP);
    mcs_status st = mcs_node_curve(cm, xm, ym, CAP, err);
    if (!st) st = mcs_node_curve(ct, xt, yt, CAP, err);
    if (st) return st;
    for (int i = 1; i < nm; i++)
        if (!(xm[i] > xm[i - 1]))
            return mcs_node_error(cm, err, MCS_ERR_RANGE, "times must increase (point %d)", i);
    for (int i = 1; i < nt; i++)
        if (!(xt[i] > xt[i - 1]))
            return mcs_node_error(ct, err, MCS_ERR_RANGE, "times must increase (point %d)", i);
    int n = 0, i = 0, j = 0;
    while (i < nm || j < nt) {
        double t = j >= nt || (i < nm && xm[i] <= xt[j]) ? xm[i] : xt[j];
        if (i < nm && xm[i] == t) i++;
        if (j < nt && xt[j] == t) j++;
        if (n >= CAP)
            return mcs_node_error(inf, err, MCS_ERR_RANGE,
                                  "mass_flow and temperature together have more than %d distinct "
                                  "times",
                                  CAP);
        g->inflator_time[n] = t;
        g->inflator_mass_flow[n] = lerp_table(nm, xm, ym, t);
        g->inflator_temperature[n] = lerp_table(nt, xt, yt, t);
        n++;
    }
    g->ninflator = n;
    g->fire_time = mcs_node_num_or(inf, "fire_time", 0);
    return MCS_OK;
}

static mcs_status read_airbag(const mcs_node *a, fe_airbag_desc *d, mcs_error *err)
{
    snprintf(d->name, sizeof d->name, "%s", mcs_node_str(fe_scn_get(a, "name")));
    if (strlen(mcs_node_str(fe_scn_get(a, "name"))) >= sizeof d->name)
        return mcs_node_error(fe_scn_get(a, "name"), err, MCS_ERR_RANGE,
                              "longer than %d characters", FE_NAME_MAX - 1);
    const mcs_node *parts = fe_scn_get(a, "parts"), *vents = fe_scn_get(a, "vents");
    if (mcs_node_len(parts) > FE_RESTRAINT_PARTS_MAX)
        return mcs_node_error(parts, err, MCS_ERR_RANGE, "at most %d parts",
                              FE_RESTRAINT_PARTS_MAX);
    d->nparts = mcs_node_len(parts);
    for (int k = 0; k < d->nparts; k++)
        snprintf(d->parts[k], sizeof d->parts[k], "%s", mcs_node_str(mcs_node_at(parts, k)));
    fe_gasbag_desc *g = &d->gas;
    g->gamma = mcs_node_num_or(a, "gamma", g->gamma);
    g->gas_constant = mcs_node_num_or(a, "gas_constant", g->gas_constant);
    g->molar_mass = mcs_node_num_or(a, "molar_mass", 0);
    g->cp = mcs_node_num_or(a, "cp", 0);
    g->cv = mcs_node_num_or(a, "cv", 0);
    g->ambient_pressure = mcs_node_num_or(a, "ambient_pressure", g->ambient_pressure);
    g->ambient_temperature = mcs_node_num_or(a, "ambient_temperature", g->ambient_temperature);
    d->initial_pressure = mcs_node_num_or(a, "initial_pressure", 0);
    d->initial_temperature = mcs_node_num_or(a, "initial_temperature", 0);
    if (mcs_node_len(vents) > FE_GASBAG_VENT_MAX)
        return mcs_node_error(vents, err, MCS_ERR_RANGE, "at most %d vents", FE_GASBAG_VENT_MAX);
    g->nvent = mcs_node_len(vents);
    for (int k = 0; k < g->nvent; k++) {
        const mcs_node *v = mcs_node_at(vents, k);
        g->vent[k].area = mcs_node_num(fe_scn_get(v, "area"));
        g->vent[k].discharge_coefficient = mcs_node_num_or(v, "discharge_coefficient", 1);
        g->vent[k].open_pressure = mcs_node_num_or(v, "open_pressure", 0);
    }
    if (fe_scn_given(a, "leakage")) {
        const mcs_node *l = fe_scn_get(a, "leakage");
        g->leak_area = mcs_node_num_or(l, "area", 0);
        g->leak_porosity = mcs_node_num_or(l, "porosity", 0);
        g->leak_discharge_coefficient = mcs_node_num_or(l, "discharge_coefficient", 1);
    }
    if (fe_scn_given(a, "inflator")) return read_inflator(fe_scn_get(a, "inflator"), g, err);
    return MCS_OK;
}

static mcs_status read_retractor(const mcs_node *r, fe_belt_retractor_desc *d, mcs_error *err)
{
    static const char *names[] = {"all", "x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
    snprintf(d->name, sizeof d->name, "%s", mcs_node_str(fe_scn_get(r, "name")));
    if (strlen(mcs_node_str(fe_scn_get(r, "name"))) >= sizeof d->name)
        return mcs_node_error(fe_scn_get(r, "name"), err, MCS_ERR_RANGE,
                              "longer than %d characters", FE_NAME_MAX - 1);
    snprintf(d->part, sizeof d->part, "%s", mcs_node_str(fe_scn_get(r, "part")));
    const char *w = mcs_node_str(fe_scn_get(r, "where"));
    for (int i = 0; i < 7; i++)
        if (w && strcmp(w, names[i]) == 0) d->where = (fe_where)i;
    mcs_status st = mcs_node_vec3(fe_scn_get(r, "anchor"), d->anchor, err);
    if (st) return st;
    d->stiffness = mcs_node_num_or(r, "stiffness", 0);
    fe_retractor_desc *t = &d->retractor;
    t->fire_time = mcs_node_num_or(r, "fire_time", t->fire_time);
    t->pretensioner_max_force = mcs_node_num_or(r, "pretensioner_max_force", 0);
    t->load_limit = mcs_node_num_or(r, "load_limit", t->load_limit);
    t->spool_stiffness = mcs_node_num_or(r, "spool_stiffness", 0);
    t->spool_force = mcs_node_num_or(r, "spool_force", t->spool_force);
    t->lock_time = mcs_node_num_or(r, "lock_time", t->lock_time);
    t->lock_payout_rate = mcs_node_num_or(r, "lock_payout_rate", 0);
    if (fe_scn_given(r, "payin")) {
        const mcs_node *c = fe_scn_get(r, "payin");
        int n = mcs_node_curve_len(c);
        if (n > FE_RETRACTOR_TABLE_MAX)
            return mcs_node_error(c, err, MCS_ERR_RANGE, "at most %d points",
                                  FE_RETRACTOR_TABLE_MAX);
        st = mcs_node_curve(c, t->payin_time, t->payin_length, FE_RETRACTOR_TABLE_MAX, err);
        t->npayin = n;
        for (int i = 1; i < n && !st; i++)
            if (!(t->payin_time[i] > t->payin_time[i - 1]))
                return mcs_node_error(c, err, MCS_ERR_RANGE, "times must increase (point %d)", i);
    }
    return st;
}

/* a part in airbag i that an earlier airbag (or bag i itself) already holds: one bag per closed
 * surface, bags sharing fabric are not modelled (docs/gasbag.md) */
static mcs_status shared_bag_part(const mcs_node *bags, int i, mcs_error *err)
{
    const mcs_node *parts = fe_scn_get(mcs_node_at(bags, i), "parts");
    for (int k = 0; k < mcs_node_len(parts); k++) {
        const char *name = mcs_node_str(mcs_node_at(parts, k));
        for (int j = 0; j <= i; j++) {
            const mcs_node *bj = mcs_node_at(bags, j), *pj = fe_scn_get(bj, "parts");
            int n = j < i ? mcs_node_len(pj) : k;
            for (int l = 0; l < n; l++)
                if (strcmp(name, mcs_node_str(mcs_node_at(pj, l))) == 0)
                    return mcs_node_error(mcs_node_at(parts, k), err, MCS_ERR_KEY,
                                          "part '%s' is already in airbag '%s': one bag per "
                                          "closed surface (bags sharing fabric are not modelled)",
                                          name, mcs_node_str(fe_scn_get(bj, "name")));
        }
    }
    return MCS_OK;
}

mcs_status fe_scn_add_restraints(fe_builder *b, const mcs_node *fe, mcs_error *err)
{
    const mcs_node *bags = fe_scn_get(fe, "airbags"), *rets = fe_scn_get(fe, "retractors");
    for (int i = 0; i < mcs_node_len(bags); i++) {
        const mcs_node *a = mcs_node_at(bags, i);
        fe_airbag_desc d = fe_airbag_desc_default();
        mcs_status st = shared_bag_part(bags, i, err);
        if (!st) st = read_airbag(a, &d, err);
        if (st) return st;
        mcs_error kerr = {0};
        st = fe_builder_add_airbag(b, &d, &kerr);
        if (st) return fe_scn_relocate(st, a, &kerr, err);
    }
    for (int i = 0; i < mcs_node_len(rets); i++) {
        const mcs_node *r = mcs_node_at(rets, i);
        fe_belt_retractor_desc d = fe_belt_retractor_desc_default();
        mcs_status st = read_retractor(r, &d, err);
        if (st) return st;
        mcs_error kerr = {0};
        st = fe_builder_add_retractor(b, &d, &kerr);
        if (st) return fe_scn_relocate(st, r, &kerr, err);
    }
    return MCS_OK;
}

const mcs_node *fe_scn_restraint_node(const mcs_node *fe, const char *msg)
{
    static const char *const list[2] = {"airbags", "retractors"};
    static const char *const what[2] = {"gas bag", "retractor"};
    for (int k = 0; k < 2; k++) {
        const mcs_node *l = fe_scn_get(fe, list[k]);
        for (int i = 0; i < mcs_node_len(l); i++) {
            const mcs_node *it = mcs_node_at(l, i);
            char needle[FE_NAME_MAX + 32];
            snprintf(needle, sizeof needle, "%s '%s'", what[k],
                     mcs_node_str(fe_scn_get(it, "name")));
            if (!strstr(msg, needle)) continue;
            /* a gas bag's surface (not shells, not closed, not oriented, no volume): its parts */
            if (k == 0 && !strstr(msg, "initial pressure") && !strstr(msg, "defined twice"))
                return fe_scn_get(it, "parts");
            return it;
        }
    }
    return fe;
}

/* ---- results ----------------------------------------------------------------------------- */

/* the gas's energies (fe/fe_gasbag.h): internal m cv T, work on the fabric int p dV, the
 * inflator's enthalpy in, the enthalpy out through the vents and the fabric, so far */
static const char *const bag_ch[FE_OUT_BAG_CHANNELS] = {
    "pressure", "volume",      "temperature", "mass",       "energy",
    "work",     "energy_in",   "energy_vent", "energy_leak"};
static const char *const bag_unit[FE_OUT_BAG_CHANNELS] = {"Pa", "m^3", "K", "kg", "J",
                                                          "J",  "J",   "J", "J"};
static const char *const ret_ch[FE_OUT_RETRACTOR_CHANNELS] = {
    "payout",         "force",          "payout_pretensioner", "payout_limiter",
    "energy_limiter", "energy_pretensioner"};
static const char *const ret_unit[FE_OUT_RETRACTOR_CHANNELS] = {"m", "N", "m", "m", "J", "J"};

mcs_status fe_out_restraint_open(mcs_results *r, int stage, const fe_model *m,
                                 fe_out_restraint *o, mcs_error *err)
{
    memset(o, 0, sizeof *o);
    const struct fe_restraints *rs = m->restraints;
    if (!rs) return MCS_OK;
    o->bag = calloc((size_t)rs->nbag * FE_OUT_BAG_CHANNELS + 1, sizeof *o->bag);
    o->retractor =
        calloc((size_t)rs->nretractor * FE_OUT_RETRACTOR_CHANNELS + 1, sizeof *o->retractor);
    if (!o->bag || !o->retractor)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage %d: out of memory", stage);
    o->nbag = rs->nbag;
    o->nretractor = rs->nretractor;
    char path[256];
    mcs_status st = MCS_OK;
    for (int i = 0; i < rs->nbag && !st; i++)
        for (int c = 0; c < FE_OUT_BAG_CHANNELS && !st; c++) {
            snprintf(path, sizeof path, "/stage%d/airbag/%s/%s", stage, rs->bag[i].name, bag_ch[c]);
            st = mcs_results_series_create(r, path, 1, NULL, bag_unit[c], 0,
                                           &o->bag[FE_OUT_BAG_CHANNELS * i + c], err);
        }
    for (int i = 0; i < rs->nretractor && !st; i++)
        for (int c = 0; c < FE_OUT_RETRACTOR_CHANNELS && !st; c++) {
            snprintf(path, sizeof path, "/stage%d/retractor/%s/%s", stage,
                     rs->retractor[i].name,
                     ret_ch[c]);
            st = mcs_results_series_create(r, path, 1, NULL, ret_unit[c], 0,
                                           &o->retractor[FE_OUT_RETRACTOR_CHANNELS * i + c], err);
        }
    return st;
}

mcs_status fe_out_restraint_sample(const fe_state *s, const fe_out_restraint *o, mcs_error *err)
{
    mcs_status st = MCS_OK;
    for (int i = 0; i < o->nbag && !st; i++) {
        const fe_gasbag_state *g = &s->restraint->bag[i];
        const double v[FE_OUT_BAG_CHANNELS] = {
            g->pressure,  g->volume,    g->temperature, g->mass,       g->energy,
            g->work,      g->energy_in, g->energy_vent, g->energy_leak};
        for (int c = 0; c < FE_OUT_BAG_CHANNELS && !st; c++)
            st = mcs_results_series_append(o->bag[FE_OUT_BAG_CHANNELS * i + c], &v[c], err);
    }
    for (int i = 0; i < o->nretractor && !st; i++) {
        const fe_retractor_state *r = &s->restraint->retractor[i];
        const double v[FE_OUT_RETRACTOR_CHANNELS] = {r->payout, r->force, r->payout_pretensioner,
                                                 r->payout_limiter, r->energy_limiter,
                                                 r->energy_pretensioner};
        for (int c = 0; c < FE_OUT_RETRACTOR_CHANNELS && !st; c++)
            st = mcs_results_series_append(o->retractor[FE_OUT_RETRACTOR_CHANNELS * i + c], &v[c],
                                           err);
    }
    return st;
}

void fe_out_restraint_free(fe_out_restraint *o)
{
    free(o->bag);
    free(o->retractor);
    memset(o, 0, sizeof *o);
}

const mcs_node *fe_scn_stage1_key(const mcs_node *fe)
{
    const mcs_node *l = fe_scn_get(fe, "airbags");
    for (int i = 0; i < mcs_node_len(l); i++) {
        const mcs_node *t = fe_scn_get(fe_scn_get(mcs_node_at(l, i), "inflator"), "trigger");
        if (mcs_node_kind(t) != MCS_NODE_NULL) return t;
    }
    l = fe_scn_get(fe, "retractors");
    for (int i = 0; i < mcs_node_len(l); i++) {
        const mcs_node *r = mcs_node_at(l, i);
        if (fe_scn_given(r, "trigger")) return fe_scn_get(r, "trigger");
        if (fe_scn_given(r, "anchor_body")) return fe_scn_get(r, "anchor_body");
    }
    l = fe_scn_get(fe, "sliprings");
    for (int i = 0; i < mcs_node_len(l); i++)
        if (fe_scn_given(mcs_node_at(l, i), "body")) return fe_scn_get(mcs_node_at(l, i), "body");
    return NULL;
}

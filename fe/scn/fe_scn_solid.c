/* fe_scn_solid.c: see fe_scn_solid.h. */
#include "fe/scn/fe_scn_solid.h"
#include "fe/scn/fe_scn_node.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static fe_where where_of(const char *s)
{
    static const char *names[] = {"all", "x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
    for (int i = 0; i < 7; i++)
        if (s && strcmp(s, names[i]) == 0) return (fe_where)i;
    return FE_WHERE_ALL;
}

void fe_scn_solid_opts(const mcs_node *root, fe_opts *opts)
{
    /* DESIGN.md: z up, gravity a magnitude acting along -z */
    opts->gravity[2] = -mcs_node_num_or(fe_scn_get(root, "environment"), "gravity", 0);
    opts->mass_scaling_dt =
        mcs_node_num_or(fe_scn_get(fe_scn_get(root, "fe"), "mass_scaling"), "time_step", 0);
    opts->mass_scaling_interval = (int)mcs_node_num_or(
        fe_scn_get(fe_scn_get(root, "fe"), "mass_scaling"), "check_interval", 0);
}

/* a table [[x, y], ...] of at most FE_CURVE_MAX points into c */
static mcs_status read_table(const mcs_node *n, double (*c)[2], int *np, mcs_error *err)
{
    int len = mcs_node_curve_len(n);
    double x[FE_CURVE_MAX], y[FE_CURVE_MAX];
    if (len > FE_CURVE_MAX)
        return mcs_node_error(n, err, MCS_ERR_RANGE, "at most %d points, got %d", FE_CURVE_MAX,
                              len);
    mcs_status st = mcs_node_curve(n, x, y, FE_CURVE_MAX, err);
    if (st) return st;
    for (int i = 0; i < len; i++) c[i][0] = x[i], c[i][1] = y[i];
    *np = len;
    return MCS_OK;
}

static mcs_status read_end(const mcs_node *e, fe_spring_end *d, mcs_error *err)
{
    d->node = -1;
    const char *part = mcs_node_str(fe_scn_get(e, "part"));
    if (part) snprintf(d->part, sizeof d->part, "%s", part);
    return mcs_node_vec3(fe_scn_get(e, "point"), d->point, err);
}

static mcs_status add_springs(fe_builder *b, const mcs_node *list, mcs_error *err)
{
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *n = mcs_node_at(list, i);
        fe_spring_desc d;
        memset(&d, 0, sizeof d);
        const char *name = mcs_node_str(fe_scn_get(n, "name"));
        snprintf(d.name, sizeof d.name, "%s", name ? name : "");
        if (!name) snprintf(d.name, sizeof d.name, "springs[%d]", i);
        if (!fe_scn_given(n, "stiffness") && !fe_scn_given(n, "curve") &&
            !fe_scn_given(n, "damping"))
            return mcs_node_error(n, err, MCS_ERR_KEY,
                                  "a spring needs stiffness, curve or damping");
        if (fe_scn_given(n, "stiffness") && fe_scn_given(n, "curve"))
            return mcs_node_error(fe_scn_get(n, "curve"), err, MCS_ERR_KEY,
                                  "give stiffness or curve, not both");
        if (!fe_scn_given(fe_scn_get(n, "a"), "part") && !fe_scn_given(fe_scn_get(n, "b"), "part"))
            return mcs_node_error(n, err, MCS_ERR_KEY,
                                  "both ends are fixed anchors: give a part for a or b");
        mcs_status st = read_end(fe_scn_get(n, "a"), &d.end[0], err);
        if (!st) st = read_end(fe_scn_get(n, "b"), &d.end[1], err);
        d.stiffness = mcs_node_num_or(n, "stiffness", 0);
        d.damping = mcs_node_num_or(n, "damping", 0);
        const char *part = mcs_node_str(fe_scn_get(n, "part")); /* spring part (energies) */
        if (part) snprintf(d.part, sizeof d.part, "%s", part);
        if (!st && fe_scn_given(n, "curve"))
            st = read_table(fe_scn_get(n, "curve"), d.curve, &d.ncurve, err);
        if (st) return st;
        mcs_error kerr = {0};
        st = fe_builder_add_spring(b, &d, &kerr);
        if (st) return fe_scn_relocate(st, n, &kerr, err);
    }
    return MCS_OK;
}

static mcs_status add_masses(fe_builder *b, const mcs_node *list, mcs_error *err)
{
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *n = mcs_node_at(list, i);
        fe_mass_desc d;
        memset(&d, 0, sizeof d);
        d.node = -1;
        snprintf(d.part, sizeof d.part, "%s", mcs_node_str(fe_scn_get(n, "part")));
        d.mass = mcs_node_num(fe_scn_get(n, "mass"));
        if (fe_scn_given(n, "where") == fe_scn_given(n, "point"))
            return mcs_node_error(n, err, MCS_ERR_KEY, "give one of where or point");
        d.where = where_of(mcs_node_str(fe_scn_get(n, "where")));
        if (fe_scn_given(n, "point")) {
            d.at_point = 1;
            mcs_status st = mcs_node_vec3(fe_scn_get(n, "point"), d.point, err);
            if (st) return st;
        }
        mcs_error kerr = {0};
        mcs_status st = fe_builder_add_mass(b, &d, &kerr);
        if (st) return fe_scn_relocate(st, n, &kerr, err);
    }
    return MCS_OK;
}

mcs_status fe_scn_solid_add(fe_builder *b, const mcs_node *fe, mcs_error *err)
{
    mcs_status st = add_springs(b, fe_scn_get(fe, "springs"), err);
    if (!st) st = add_masses(b, fe_scn_get(fe, "masses"), err);
    return st;
}

/* foam: stress_strain (one rate-independent curve) or curves [{rate, points}] */
static mcs_status read_foam(const mcs_node *mat, fe_material_desc *d, mcs_error *err)
{
    if (fe_scn_given(mat, "damping"))
        return mcs_node_error(fe_scn_get(mat, "damping"), err, MCS_ERR_UNSUPPORTED,
                              "foam damping not supported yet (the curves carry the rate "
                              "effect)");
    if (fe_scn_given(mat, "stress_strain") == fe_scn_given(mat, "curves"))
        return mcs_node_error(mat, err, MCS_ERR_KEY, "give one of stress_strain or curves");
    d->poisson = mcs_node_num_or(mat, "poisson", 0);
    d->foam_hysteresis = mcs_node_num_or(mat, "hysteresis", 1);
    d->foam_shape = mcs_node_num_or(mat, "shape", 1);
    d->foam_tension_cutoff = mcs_node_num_or(mat, "tension_cutoff", 0);
    if (fe_scn_given(mat, "stress_strain")) {
        d->nfoam_curve = 1;
        return read_table(fe_scn_get(mat, "stress_strain"), d->foam_curve[0], &d->foam_npoint[0],
                          err);
    }
    const mcs_node *list = fe_scn_get(mat, "curves");
    int n = mcs_node_len(list);
    if (n < 1 || n > FE_FOAM_NCURVE)
        return mcs_node_error(list, err, MCS_ERR_RANGE, "1..%d curves, got %d", FE_FOAM_NCURVE, n);
    d->nfoam_curve = n;
    for (int c = 0; c < n; c++) {
        const mcs_node *cv = mcs_node_at(list, c);
        d->foam_rate[c] = mcs_node_num(fe_scn_get(cv, "rate"));
        if (c > 0 && !(d->foam_rate[c] > d->foam_rate[c - 1]))
            return mcs_node_error(fe_scn_get(cv, "rate"), err, MCS_ERR_RANGE,
                                  "rates must increase from curve to curve");
        if (n > 1 && !(d->foam_rate[c] > 0))
            return mcs_node_error(fe_scn_get(cv, "rate"), err, MCS_ERR_RANGE, "must be > 0");
        mcs_status st =
            read_table(fe_scn_get(cv, "points"), d->foam_curve[c], &d->foam_npoint[c], err);
        if (st) return st;
    }
    return MCS_OK;
}

mcs_status fe_scn_solid_material(const mcs_node *mat, fe_material_desc *d, mcs_error *err)
{
    const char *model = mcs_node_str(fe_scn_get(mat, "model"));
    d->density = mcs_node_num(fe_scn_get(mat, "density"));
    d->youngs_modulus = mcs_node_num(fe_scn_get(mat, "youngs_modulus"));
    if (model && strcmp(model, "foam") == 0) {
        d->model = FE_MAT_FOAM;
        return read_foam(mat, d, err);
    }
    if (model && strcmp(model, "rigid") == 0) {
        d->model = FE_MAT_RIGID;
        d->poisson = mcs_node_num(fe_scn_get(mat, "poisson"));
        return MCS_OK;
    }
    return mcs_node_error(fe_scn_get(mat, "model"), err, MCS_ERR_UNSUPPORTED,
                          "material model '%s' not supported yet", model ? model : "?");
}

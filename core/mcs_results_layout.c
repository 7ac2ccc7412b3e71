/* mcs_results_layout.c: writers for the paths of DESIGN.md "The results file (HDF5)". */
#include "core/mcs_results_impl.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* printf into a path buffer; names with '/' or empty names are refused */
static mcs_status fmt_path(char *buf, size_t n, mcs_error *err, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static mcs_status fmt_path(char *buf, size_t n, mcs_error *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(buf, n, fmt, ap);
    va_end(ap);
    if (k < 0 || (size_t)k >= n) return MCS_ERR(err, MCS_ERR_USAGE, "results: path too long");
    return MCS_OK;
}

static mcs_status check_name(const char *what, const char *name, mcs_error *err)
{
    if (!name || !*name || strchr(name, '/') || strcmp(name, ".") == 0 || strcmp(name, "..") == 0)
        return MCS_ERR(err, MCS_ERR_USAGE, "results: bad %s name \"%s\"", what,
                       name ? name : "(null)");
    return MCS_OK;
}

/* stage 0 is the reduced-order model (rom/rom.h, docs/contracts.md) */
static mcs_status check_stage(int stage, mcs_error *err)
{
    if (stage < 0 || stage > 3)
        return MCS_ERR(err, MCS_ERR_USAGE, "results: stage %d not in 0..3", stage);
    return MCS_OK;
}

mcs_status mcs_results_put_time(mcs_results *r, int stage, size_t nt, const double *t,
                                mcs_error *err)
{
    char p[64];
    mcs_status st = check_stage(stage, err);
    if (!st) st = fmt_path(p, sizeof p, err, "/stage%d/time", stage);
    if (!st) st = mcs_results_write(r, p, 1, &nt, t, "s", err);
    return st;
}

mcs_status mcs_results_put_channel(mcs_results *r, int stage, const char *name, size_t nt,
                                   const double *y, const char *unit, const char *frame, int cfc,
                                   const char *body, mcs_error *err)
{
    char p[1024];
    mcs_status st = check_stage(stage, err);
    if (!st) st = check_name("channel", name, err);
    if (!st) st = fmt_path(p, sizeof p, err, "/stage%d/channels/%s", stage, name);
    if (!st) st = mcs_results_write(r, p, 1, &nt, y, unit, err);
    if (!st && frame) st = mcs_results_set_attr_str(r, p, "frame", frame, err);
    if (!st) st = mcs_results_set_attr_int(r, p, "cfc", cfc, err);
    if (!st && body) st = mcs_results_set_attr_str(r, p, "body", body, err);
    return st;
}

static const char *const energy_kinds[] = {"kinetic",  "potential",  "internal",
                                           "contact",  "hourglass",  "dissipated",
                                           "external_work", "total"};

mcs_status mcs_results_put_energy(mcs_results *r, int stage, const char *kind, size_t nt,
                                  const double *e, mcs_error *err)
{
    int known = 0;
    for (size_t i = 0; kind && i < sizeof energy_kinds / sizeof *energy_kinds; i++)
        known |= strcmp(kind, energy_kinds[i]) == 0;
    if (!known)
        return MCS_ERR(err, MCS_ERR_USAGE, "results: unknown energy \"%s\" (kinetic, potential, "
                                           "internal, contact, hourglass, dissipated, "
                                           "external_work, total)",
                       kind ? kind : "(null)");
    char p[128];
    mcs_status st = check_stage(stage, err);
    if (!st) st = fmt_path(p, sizeof p, err, "/stage%d/energy/%s", stage, kind);
    if (!st) st = mcs_results_write(r, p, 1, &nt, e, "J", err);
    return st;
}

const char *mcs_results_body_unit(const char *quantity, int *width)
{
    static const struct {
        const char *name, *unit;
        int width;
    } q[] = {{"position", "m", 3},          {"orientation", "-", 4},
             {"velocity", "m/s", 3},        {"angular_velocity", "rad/s", 3},
             {"acceleration", "m/s^2", 3}};
    for (size_t i = 0; quantity && i < sizeof q / sizeof *q; i++)
        if (strcmp(quantity, q[i].name) == 0) {
            if (width) *width = q[i].width;
            return q[i].unit;
        }
    return NULL;
}

static mcs_status body_path(char *p, size_t n, int stage, const char *body, const char *quantity,
                            const char **unit, int *width, mcs_error *err)
{
    mcs_status st = check_stage(stage, err);
    if (!st) st = check_name("body", body, err);
    if (st) return st;
    *unit = mcs_results_body_unit(quantity, width);
    if (!*unit)
        return MCS_ERR(err, MCS_ERR_USAGE, "results: unknown body quantity \"%s\" (position, "
                                           "orientation, velocity, angular_velocity, "
                                           "acceleration)",
                       quantity ? quantity : "(null)");
    return fmt_path(p, n, err, "/stage%d/bodies/%s/%s", stage, body, quantity);
}

mcs_status mcs_results_put_body(mcs_results *r, int stage, const char *body,
                                const char *quantity, size_t nt, const double *v,
                                mcs_error *err)
{
    char p[1024];
    const char *unit;
    int w;
    mcs_status st = body_path(p, sizeof p, stage, body, quantity, &unit, &w, err);
    if (st) return st;
    size_t dims[2] = {nt, (size_t)w};
    return mcs_results_write(r, p, 2, dims, v, unit, err);
}

mcs_status mcs_results_body_series(mcs_results *r, int stage, const char *body,
                                   const char *quantity, mcs_results_series **out,
                                   mcs_error *err)
{
    char p[1024];
    const char *unit;
    int w;
    mcs_status st = body_path(p, sizeof p, stage, body, quantity, &unit, &w, err);
    if (st) return st;
    size_t row = (size_t)w;
    return mcs_results_series_create(r, p, 2, &row, unit, 0, out, err);
}

mcs_status mcs_results_put_injury(mcs_results *r, int stage, const char *criterion,
                                  double value, const char *unit, double limit, double t1,
                                  double t2, const char *channel, mcs_error *err)
{
    char p[1024];
    mcs_status st = check_stage(stage, err);
    if (!st) st = check_name("criterion", criterion, err);
    if (!st) st = fmt_path(p, sizeof p, err, "/stage%d/injury/%s", stage, criterion);
    if (!st) st = mcs_results_write_scalar(r, p, value, unit, err);
    if (!st) st = mcs_results_set_attr_double(r, p, "limit", limit, err);
    if (!st) st = mcs_results_set_attr_double(r, p, "t1", t1, err);
    if (!st) st = mcs_results_set_attr_double(r, p, "t2", t2, err);
    if (!st && channel) st = mcs_results_set_attr_str(r, p, "channel", channel, err);
    return st;
}

/* element width a type name states: its trailing number ("hex8": 8, "tet10": 10; the
 * convention of mcs_results.h); 0 when it ends in no number */
static int type_width(const char *type)
{
    size_t l = type ? strlen(type) : 0, i = l;
    while (i > 0 && type[i - 1] >= '0' && type[i - 1] <= '9') i--;
    if (i == 0 || i == l || l - i > 3) return 0;
    return atoi(type + i);
}

mcs_status mcs_results_put_mesh(mcs_results *r, int stage, const char *part, size_t nn,
                                const double *nodes, size_t ne, int k, const int *elements,
                                const char *type, int node_offset, mcs_error *err)
{
    mcs_status st = check_stage(stage, err);
    if (!st) st = check_name("part", part, err);
    if (st) return st;
    if (type && type_width(type) != k)
        return MCS_ERR(err, MCS_ERR_USAGE, "results: part %s: element type \"%s\" with %d nodes "
                                           "(a type's name ends in its node count)",
                       part, type, k);
    if (k < 2 || k > 10 || node_offset < 0)
        return MCS_ERR(err, MCS_ERR_USAGE, "results: part %s: %d nodes per element", part, k);
    for (size_t i = 0; i < ne * (size_t)k; i++)
        if (elements[i] < 0 || (size_t)elements[i] >= nn)
            return MCS_ERR(err, MCS_ERR_RANGE, "results: part %s: element %zu names node %d of %zu",
                           part, i / (size_t)k, elements[i], nn);
    char pn[1024], pe[1024];
    if ((st = fmt_path(pn, sizeof pn, err, "/stage%d/mesh/%s/nodes", stage, part))) return st;
    if ((st = fmt_path(pe, sizeof pe, err, "/stage%d/mesh/%s/elements", stage, part))) return st;
    size_t dn[2] = {nn, 3}, de[2] = {ne, (size_t)k};
    st = mcs_results_write(r, pn, 2, dn, nodes, "m", err);
    if (!st) st = mcs_results_set_attr_int(r, pn, "node_offset", node_offset, err);
    if (!st) st = mcs_results_write_int(r, pe, 2, de, elements, "-", err);
    if (!st && type) st = mcs_results_set_attr_str(r, pe, "type", type, err);
    return st;
}

mcs_status mcs_results_put_mesh_block(mcs_results *r, int stage, const char *part, size_t nn,
                                      size_t ne, int k, const int *elements, const char *type,
                                      mcs_error *err)
{
    mcs_status st = check_stage(stage, err);
    if (!st) st = check_name("part", part, err);
    if (st) return st;
    if (!type || type_width(type) != k)
        return MCS_ERR(err, MCS_ERR_USAGE, "results: part %s: element block of type \"%s\" with "
                                           "%d nodes",
                       part, type ? type : "(none)", k);
    for (size_t i = 0; i < ne * (size_t)k; i++)
        if (elements[i] < 0 || (size_t)elements[i] >= nn)
            return MCS_ERR(err, MCS_ERR_RANGE, "results: part %s: element %zu names node %d of %zu",
                           part, i / (size_t)k, elements[i], nn);
    char pe[1024];
    if ((st = fmt_path(pe, sizeof pe, err, "/stage%d/mesh/%s/elements_%s", stage, part, type)))
        return st;
    size_t de[2] = {ne, (size_t)k};
    st = mcs_results_write_int(r, pe, 2, de, elements, "-", err);
    if (!st) st = mcs_results_set_attr_str(r, pe, "type", type, err);
    return st;
}

mcs_status mcs_results_field_series(mcs_results *r, int stage, size_t nn,
                                    mcs_results_series **time, mcs_results_series **disp,
                                    mcs_error *err)
{
    char pt[64], pd[64];
    mcs_status st = check_stage(stage, err);
    if (!st) st = fmt_path(pt, sizeof pt, err, "/stage%d/fields/time", stage);
    if (!st) st = fmt_path(pd, sizeof pd, err, "/stage%d/fields/displacement", stage);
    if (!st) st = mcs_results_series_create(r, pt, 1, NULL, "s", 0, time, err);
    size_t row[2] = {nn, 3};
    if (!st) st = mcs_results_series_create(r, pd, 3, row, "m", 0, disp, err);
    return st;
}

mcs_status mcs_results_put_rigidwall(mcs_results *r, const char *wall, size_t nt,
                                     const double *force, const double *displacement,
                                     mcs_error *err)
{
    char pf[1024], pd[1024];
    mcs_status st = check_name("wall", wall, err);
    if (!st) st = fmt_path(pf, sizeof pf, err, "/stage3/rigidwall/%s/force", wall);
    if (!st) st = fmt_path(pd, sizeof pd, err, "/stage3/rigidwall/%s/displacement", wall);
    if (!st) st = mcs_results_write(r, pf, 1, &nt, force, "N", err);
    if (!st) st = mcs_results_write(r, pd, 1, &nt, displacement, "m", err);
    return st;
}

static mcs_status put_xy(mcs_results *r, const char *path, size_t n, const double *xy,
                         const char *x_unit, const char *y_unit, mcs_error *err)
{
    char unit[64];
    snprintf(unit, sizeof unit, "%s,%s", x_unit, y_unit);
    size_t dims[2] = {n, 2};
    mcs_status st = mcs_results_write(r, path, 2, dims, xy, unit, err);
    if (!st) st = mcs_results_set_attr_str(r, path, "x_unit", x_unit, err);
    if (!st) st = mcs_results_set_attr_str(r, path, "y_unit", y_unit, err);
    return st;
}

mcs_status mcs_results_put_curve(mcs_results *r, const char *name, size_t nload,
                                 const double *loading, size_t nunload, const double *unloading,
                                 const char *x_unit, const char *y_unit, mcs_error *err)
{
    char pl[1024], pu[1024];
    mcs_status st = check_name("curve", name, err);
    if (!st && (!x_unit || !*x_unit || !y_unit || !*y_unit))
        st = MCS_ERR(err, MCS_ERR_USAGE, "results: curve %s needs x and y units", name);
    if (!st) st = fmt_path(pl, sizeof pl, err, "/curves/%s/loading", name);
    if (!st) st = fmt_path(pu, sizeof pu, err, "/curves/%s/unloading", name);
    if (!st) st = put_xy(r, pl, nload, loading, x_unit, y_unit, err);
    if (!st && unloading) st = put_xy(r, pu, nunload, unloading, x_unit, y_unit, err);
    return st;
}

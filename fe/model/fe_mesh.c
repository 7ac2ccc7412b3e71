/* fe_mesh: generated primitives (DESIGN.md `fe:` mesh keys): box of hex8, plate of quads,
 * square and circular tubes of quads, line of trusses.
 * Tubes and plates use local (u, v, w) with w along `axis` and world[(axis+1)%3] = u,
 * world[(axis+2)%3] = v, world[axis] = w (right-handed for every axis). A tube runs from
 * w = 0 to w = length, centred on the axis; shell normals point outwards (tubes) or along
 * +axis (plates). */
#include "fe/fe_builder_impl.h"

#include <math.h>
#include <stdlib.h>

static void to_world(int axis, double u, double v, double w, const double o[3], double x[3])
{
    x[(axis + 1) % 3] = o[(axis + 1) % 3] + u;
    x[(axis + 2) % 3] = o[(axis + 2) % 3] + v;
    x[axis] = o[axis] + w;
}

static mcs_status gen_box(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err)
{
    const int nx = m->divisions[0], ny = m->divisions[1], nz = m->divisions[2];
    int base = b->nnode;
    mcs_status st = MCS_OK;
    for (int k = 0; k <= nz && st == MCS_OK; k++)
        for (int j = 0; j <= ny && st == MCS_OK; j++)
            for (int i = 0; i <= nx && st == MCS_OK; i++) {
                double x[3] = {m->origin[0] + m->size[0] * i / nx,
                               m->origin[1] + m->size[1] * j / ny,
                               m->origin[2] + m->size[2] * k / nz};
                st = fe_builder_add_node(b, x, NULL, err);
            }
#define NID(i, j, k) (base + (i) + (nx + 1) * ((j) + (ny + 1) * (k)))
    for (int k = 0; k < nz && st == MCS_OK; k++)
        for (int j = 0; j < ny && st == MCS_OK; j++)
            for (int i = 0; i < nx && st == MCS_OK; i++) {
                int c[8] = {NID(i, j, k),         NID(i + 1, j, k),     NID(i + 1, j + 1, k),
                            NID(i, j + 1, k),     NID(i, j, k + 1),     NID(i + 1, j, k + 1),
                            NID(i + 1, j + 1, k + 1), NID(i, j + 1, k + 1)};
                st = fe_builder_add_elem(b, ip, c, err);
            }
#undef NID
    return st;
}

/* a ring of nc points (u, v) per station, nl + 1 stations along w from 0 to length */
static mcs_status gen_rings(fe_builder *b, int ip, int axis, int nc, const double *u,
                            const double *v, int nl, double length, mcs_error *err)
{
    static const double zero[3] = {0, 0, 0};
    int base = b->nnode;
    mcs_status st = MCS_OK;
    for (int j = 0; j <= nl && st == MCS_OK; j++)
        for (int k = 0; k < nc && st == MCS_OK; k++) {
            double x[3];
            to_world(axis, u[k], v[k], length * j / nl, zero, x);
            st = fe_builder_add_node(b, x, NULL, err);
        }
    for (int j = 0; j < nl && st == MCS_OK; j++)
        for (int k = 0; k < nc && st == MCS_OK; k++) {
            int k1 = (k + 1) % nc;
            int c[4] = {base + nc * j + k, base + nc * j + k1, base + nc * (j + 1) + k1,
                        base + nc * (j + 1) + k};
            st = fe_builder_add_elem(b, ip, c, err);
        }
    return st;
}

static int divisions_of(double len, double h) { return (int)fmax(1.0, floor(len / h + 0.5)); }

static mcs_status gen_tube(fe_builder *b, int ip, const fe_mesh_desc *m, int square,
                           mcs_error *err)
{
    const char *name = b->part[ip].name;
    double perim = square ? 4 * m->side : M_PI * m->diameter;
    if (!(perim > 0) || !(m->length > 0) || !(m->element_size > 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': mesh: %s, length and element_size must be > 0", name,
                       square ? "side" : "diameter");
    int ns = square ? divisions_of(m->side, m->element_size) : 0;
    int nc = square ? 4 * ns : (int)fmax(3, floor(perim / m->element_size + 0.5));
    int nl = divisions_of(m->length, m->element_size);
    if ((double)nc * (nl + 1) > 5e7)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': mesh: too many elements", name);
    double *u = malloc(2 * sizeof(double) * (size_t)nc), *v = u ? u + nc : NULL;
    if (!u) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory meshing '%s'", name);
    for (int k = 0; k < nc; k++) {
        if (square) {
            /* counter-clockwise about +w from the corner (-a/2, -a/2) */
            double a = m->side, t = a * (k % ns) / ns - a / 2;
            int sidex = k / ns;
            double cu[4] = {t, a / 2, -t, -a / 2}, cv[4] = {-a / 2, t, a / 2, -t};
            u[k] = cu[sidex];
            v[k] = cv[sidex];
        } else {
            double th = 2 * M_PI * k / nc;
            u[k] = 0.5 * m->diameter * cos(th);
            v[k] = 0.5 * m->diameter * sin(th);
        }
    }
    mcs_status st = gen_rings(b, ip, m->axis, nc, u, v, nl, m->length, err);
    free(u);
    return st;
}

static mcs_status gen_plate(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err)
{
    const int nu = m->divisions[0], nv = m->divisions[1];
    int base = b->nnode;
    mcs_status st = MCS_OK;
    for (int j = 0; j <= nv && st == MCS_OK; j++)
        for (int i = 0; i <= nu && st == MCS_OK; i++) {
            double x[3];
            to_world(m->axis, m->size[0] * i / nu, m->size[1] * j / nv, 0, m->origin, x);
            st = fe_builder_add_node(b, x, NULL, err);
        }
    for (int j = 0; j < nv && st == MCS_OK; j++)
        for (int i = 0; i < nu && st == MCS_OK; i++) {
            int n0 = base + i + (nu + 1) * j;
            int c[4] = {n0, n0 + 1, n0 + nu + 2, n0 + nu + 1};
            st = fe_builder_add_elem(b, ip, c, err);
        }
    return st;
}

static mcs_status gen_line(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err)
{
    const int n = m->divisions[0];
    int base = b->nnode;
    mcs_status st = MCS_OK;
    for (int i = 0; i <= n && st == MCS_OK; i++) {
        double x[3];
        for (int d = 0; d < 3; d++) x[d] = m->origin[d] + (m->end[d] - m->origin[d]) * i / n;
        st = fe_builder_add_node(b, x, NULL, err);
    }
    for (int i = 0; i < n && st == MCS_OK; i++) {
        int c[2] = {base + i, base + i + 1};
        st = fe_builder_add_elem(b, ip, c, err);
    }
    return st;
}

mcs_status fe_mesh_generate(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err)
{
    const char *name = b->part[ip].name;
    fe_section_type t = b->part[ip].section.type;
    static const fe_section_type need[] = {
        [FE_MESH_BOX] = FE_SECTION_SOLID,         [FE_MESH_PLATE] = FE_SECTION_SHELL,
        [FE_MESH_SQUARE_TUBE] = FE_SECTION_SHELL, [FE_MESH_CIRCULAR_TUBE] = FE_SECTION_SHELL,
        [FE_MESH_LINE] = FE_SECTION_TRUSS};
    static const char *const gname[] = {"", "box", "plate", "square_tube", "circular_tube", "line"};
    if (m->generate == FE_MESH_SPHERE_SHELL || m->generate == FE_MESH_CYLINDER_SHELL ||
        m->generate == FE_MESH_FLAT_BAG) {
        if (t != FE_SECTION_SHELL && t != FE_SECTION_MEMBRANE)
            return MCS_ERR(err, MCS_ERR_TYPE,
                           "fe: part '%s': mesh.generate: sphere_shell, cylinder_shell and "
                           "flat_bag make shell or membrane elements",
                           name);
        if (m->axis < 0 || m->axis > 2)
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': mesh.axis must be x, y or z", name);
        if (m->generate == FE_MESH_FLAT_BAG) return fe_mesh_flat_bag(b, ip, m, err);
        return m->generate == FE_MESH_SPHERE_SHELL ? fe_mesh_sphere(b, ip, m, err)
                                                   : fe_mesh_cylinder(b, ip, m, err);
    }
    if (m->generate < FE_MESH_BOX || m->generate > FE_MESH_LINE)
        return MCS_ERR(err, MCS_ERR_KEY, "fe: part '%s': mesh.generate: unknown generator", name);
    if (need[m->generate] != t &&
        !(need[m->generate] == FE_SECTION_SHELL && t == FE_SECTION_MEMBRANE))
        return MCS_ERR(err, MCS_ERR_TYPE,
                       "fe: part '%s': mesh.generate: %s does not make elements of this "
                       "section.type",
                       name, gname[m->generate]);
    if (m->axis < 0 || m->axis > 2)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': mesh.axis must be x, y or z", name);
    int ndiv = m->generate == FE_MESH_BOX ? 3 : m->generate == FE_MESH_PLATE ? 2
               : m->generate == FE_MESH_LINE ? 1 : 0;
    double cells = 1;
    for (int i = 0; i < ndiv; i++) {
        if (m->divisions[i] < 1)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: part '%s': mesh.divisions[%d] must be >= 1, got %d", name, i,
                           m->divisions[i]);
        if (m->generate != FE_MESH_LINE && !(m->size[i] > 0))
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': mesh.size[%d] must be > 0", name,
                           i);
        cells *= m->divisions[i] + 1;
    }
    if (cells > 5e7)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': mesh: too many elements", name);
    switch (m->generate) {
    case FE_MESH_BOX: return gen_box(b, ip, m, err);
    case FE_MESH_PLATE: return gen_plate(b, ip, m, err);
    case FE_MESH_SQUARE_TUBE: return gen_tube(b, ip, m, 1, err);
    case FE_MESH_CIRCULAR_TUBE: return gen_tube(b, ip, m, 0, err);
    case FE_MESH_LINE: return gen_line(b, ip, m, err);
    default: return MCS_ERR(err, MCS_ERR_KEY, "fe: part '%s': mesh.generate: unknown", name);
    }
}

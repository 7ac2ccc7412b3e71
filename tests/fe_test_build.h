/* fe_test_build.h: set-up shared by the FE tests (every tests/test_*.c is its own binary, so
 * these are static inline): a generated box of hexes, the distorted 2 x 2 x 2 patch and the
 * load of the patch test, and the model and its state from a builder. */
#ifndef FE_TEST_BUILD_H
#define FE_TEST_BUILD_H

#include <math.h>
#include <stdio.h>

#include "fe/fe_builder_impl.h" /* the patch moves generated nodes */
#include "fe/fe_elem.h"
#include "fe/fe_model.h"
#include "fe/fe_state.h"
#include "tests/fe_test_util.h"

/* a new builder *b holding part d (its index in *ip unless ip is NULL) */
static inline mcs_status ft_builder(fe_builder **b, const fe_part_desc *d, int *ip, mcs_error *err)
{
    mcs_status st = fe_builder_create(b, err);
    return st != MCS_OK ? st : fe_builder_add_part(*b, d, ip, err);
}

/* part d meshed as a generated box sx x sy x sz [m] of nx x ny x nz hexes (from d's origin) */
static inline void ft_box(fe_part_desc *d, double sx, double sy, double sz, int nx, int ny, int nz)
{
    d->mesh.generate = FE_MESH_BOX;
    d->mesh.size[0] = sx, d->mesh.size[1] = sy, d->mesh.size[2] = sz;
    d->mesh.divisions[0] = nx, d->mesh.divisions[1] = ny, d->mesh.divisions[2] = nz;
}

/* the distorted patch (MacNeal & Harder 1985) from the 3 x 3 x 3 nodes of a 2 x 2 x 2 grid
 * (node i + 3 (j + 3 k), the builder's first nodes): the interior node 13 moved by dc, the face
 * centres 4 along x, 10 along z and 22 along y by df[0], df[1], df[2] [m] */
static inline void ft_distort_patch(fe_builder *b, const double dc[3], const double df[3])
{
    b->x[3 * 13 + 0] += dc[0], b->x[3 * 13 + 1] += dc[1], b->x[3 * 13 + 2] += dc[2];
    b->x[3 * 4 + 0] += df[0], b->x[3 * 10 + 2] += df[1], b->x[3 * 22 + 1] += df[2];
}

/* the model of builder *b with options o (NULL: the defaults) and a state of it; *b is
 * destroyed. On failure the error is printed, *m and *s are NULL and its status returned. */
static inline mcs_status ft_model_state(fe_builder **b, const fe_opts *o, fe_model **m,
                                        fe_state **s, mcs_error *err)
{
    *s = NULL;
    mcs_status st = fe_model_create(*b, o, m, err);
    fe_builder_destroy(b);
    if (st == MCS_OK && (st = fe_state_create(*m, s, err)) != MCS_OK) fe_model_destroy(m);
    if (st != MCS_OK) fprintf(stderr, "%s\n", err->msg);
    return st;
}

/* the distorted unit cube of 2 x 2 x 2 hexes of formulation form, steel (200 GPa, nu 0.3,
 * 7800 kg/m^3): the interior node moved by (0.13, -0.08, 0.11) m, the face centres by 0.07,
 * -0.09, 0.06 m (ft_distort_patch); its model and a state (ft_model_state) */
static inline mcs_status ft_patch_cube(fe_hex_formulation form, fe_model **m, fe_state **s,
                                       mcs_error *err)
{
    fe_part_desc d = ft_part("cube", FE_SECTION_SOLID, 200e9, 0.3, 7800);
    d.section.formulation = form;
    ft_box(&d, 1, 1, 1, 2, 2, 2);
    fe_builder *b;
    *m = NULL, *s = NULL;
    mcs_status st = ft_builder(&b, &d, NULL, err);
    if (st != MCS_OK) {
        fe_builder_destroy(&b);
        return st;
    }
    ft_distort_patch(b, (const double[3]){0.13, -0.08, 0.11}, (const double[3]){0.07, -0.09, 0.06});
    return ft_model_state(&b, NULL, m, s, err);
}

/* the patch test's load (Irons; MacNeal & Harder 1985): the linear velocity field v = G X on
 * every node (X the initial position), one internal-force evaluation over dt = 1 s, so that
 * the strain increment is sym(G) everywhere. ref: the stress C : sym(G) of part 0's isotropic
 * elasticity (Voigt xx yy zz xy yz zx) that every element must carry [Pa] (the Jaumann spin of
 * this first increment acts on a zero stress: C : sym(G) exactly). */
static inline void ft_patch_forces(const fe_model *m, fe_state *s, double ref[6])
{
    static const double G[3][3] = {{1e-3, 4e-4, -2e-4}, {1e-4, -5e-4, 3e-4}, {-3e-4, 2e-4, 7e-4}};
    for (int n = 0; n < m->nnode; n++)
        for (int i = 0; i < 3; i++) {
            double v = 0;
            for (int j = 0; j < 3; j++) v += G[i][j] * m->node_x0[3 * n + j];
            s->node_v[3 * n + i] = v;
        }
    s->dt_prev = 1.0;
    fe_internal_forces(m, s);
    const fe_part *p = &m->part[0];
    double de[6] = {G[0][0], G[1][1], G[2][2], 0.5 * (G[0][1] + G[1][0]),
                    0.5 * (G[1][2] + G[2][1]), 0.5 * (G[2][0] + G[0][2])};
    double tr = de[0] + de[1] + de[2];
    for (int i = 0; i < 3; i++) ref[i] = p->lambda * tr + 2 * p->mu * de[i];
    for (int i = 3; i < 6; i++) ref[i] = 2 * p->mu * de[i];
}

/* six times the signed volume of tetrahedron a b c d [m^3] */
static inline double ft_tet_volume6(const double *a, const double *b, const double *c,
                                    const double *d)
{
    double u[3], v[3], w[3], x[3];
    for (int i = 0; i < 3; i++) u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = d[i] - a[i];
    fe_cross(u, v, x);
    return fe_dot(x, w);
}

/* the grid nodes of tetrahedron p (0..5) of grid cube (i, j, k) in Kuhn's subdivision (6
 * tetrahedra along the cube's main diagonal: a conforming mesh), grid point (i, j, k) being node
 * base + i + (nx + 1) (j + (ny + 1) k), ordered so that its volume with the positions x is
 * positive */
static inline void ft_kuhn_tet(const double *x, int nx, int ny, int base, int i, int j, int k,
                               int p, int v[4])
{
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    int ijk[3] = {i, j, k};
    for (int s = 0; s < 4; s++) {
        if (s > 0) ijk[perm[p][s - 1]]++;
        v[s] = base + ijk[0] + (nx + 1) * (ijk[1] + (ny + 1) * ijk[2]);
    }
    if (ft_tet_volume6(x + 3 * v[0], x + 3 * v[1], x + 3 * v[2], x + 3 * v[3]) < 0) {
        int t = v[1];
        v[1] = v[2], v[2] = t;
    }
}

#endif

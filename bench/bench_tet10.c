/* bench_tet10: cost of the 10-node tetrahedron per element-cycle (the whole fe_step on one
 * thread) for a steel block of 8 x 8 x 8 cubes of 6 tet10 (3072 elements) hit at 10 m/s, and
 * the model-building cost of its stable step (one 30 x 30 eigenproblem per element).
 * Prints figures; never fails on time. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fe/fe_builder_impl.h"
#include "fe/fe_model.h"
#include "fe/fe_state.h"
#include "fe/fe_tet10.h"

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* mid-edge node of corners a-b of the grid: a table indexed by the lower corner and the
 * edge's direction (the 7 Kuhn edge directions) */
static int mid(fe_builder *b, int *tab, int g, int a, int c)
{
    const int lo = a < c ? a : c, hi = a < c ? c : a;
    /* the neighbour offsets of a Kuhn edge: +x, +y, +z and their sums */
    const int d = hi - lo, gy = g + 1, gz = (g + 1) * (g + 1);
    const int k = d == 1 ? 0 : d == gy ? 1 : d == gz ? 2 : d == 1 + gy ? 3 : d == 1 + gz ? 4
                  : d == gy + gz ? 5 : 6;
    int *slot = &tab[7 * lo + k];
    if (*slot >= 0) return *slot;
    double x[3];
    for (int i = 0; i < 3; i++) x[i] = 0.5 * (b->x[3 * lo + i] + b->x[3 * hi + i]);
    mcs_error err = {0};
    fe_builder_add_node(b, x, slot, &err);
    return *slot;
}

int main(void)
{
    const int g = 8;
    const double h = 0.005;
    fe_builder *b;
    mcs_error err = {0};
    if (fe_builder_create(&b, &err)) return 1;
    fe_part_desc d = fe_part_desc_default();
    snprintf(d.name, sizeof d.name, "block");
    d.section.type = FE_SECTION_TET10;
    d.material.model = FE_MAT_ELASTIC_PLASTIC;
    d.material.density = 7850, d.material.youngs_modulus = 210e9, d.material.poisson = 0.3;
    d.material.yield_stress = 250e6;
    d.initial_velocity[2] = -10;
    int ip;
    if (fe_builder_add_part(b, &d, &ip, &err)) return 1;
    const int n1 = g + 1, ncorner = n1 * n1 * n1;
    for (int k = 0; k <= g; k++)
        for (int j = 0; j <= g; j++)
            for (int i = 0; i <= g; i++) {
                const double x[3] = {i * h, j * h, k * h};
                fe_builder_add_node(b, x, NULL, &err);
            }
    int *tab = malloc(sizeof(int) * 7 * (size_t)ncorner);
    for (int i = 0; i < 7 * ncorner; i++) tab[i] = -1;
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int k = 0; k < g; k++)
        for (int j = 0; j < g; j++)
            for (int i = 0; i < g; i++)
                for (int p = 0; p < 6; p++) {
                    int ijk[3] = {i, j, k}, v[4];
                    for (int s = 0; s < 4; s++) {
                        if (s > 0) ijk[perm[p][s - 1]]++;
                        v[s] = ijk[0] + n1 * (ijk[1] + n1 * ijk[2]);
                    }
                    /* odd permutations are left-handed: swap two corners */
                    if (p == 1 || p == 2 || p == 5) {
                        int t = v[1];
                        v[1] = v[2], v[2] = t;
                    }
                    int c[10] = {v[0], v[1], v[2], v[3]};
                    for (int q = 0; q < 6; q++)
                        c[4 + q] = mid(b, tab, g, v[fe_tet10_edge[q][0]], v[fe_tet10_edge[q][1]]);
                    if (fe_builder_add_elem(b, ip, c, &err)) return 1;
                }
    free(tab);
    fe_boundary_desc bc;
    memset(&bc, 0, sizeof bc);
    snprintf(bc.part, sizeof bc.part, "block");
    bc.where = FE_WHERE_Z_MIN, bc.fix = FE_DOF_TRANS;
    fe_builder_add_boundary(b, &bc, &err);
    fe_model *m = NULL;
    const double t0 = cpu_now();
    if (fe_model_create(b, NULL, &m, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    const double tbuild = cpu_now() - t0;
    fe_builder_destroy(&b);
    fe_state *s = NULL;
    if (fe_state_create(m, &s, &err)) return 1;
    fe_set_threads(1);
    for (int i = 0; i < 5; i++) fe_step(m, s);
    const int cycles = 200;
    const double t1 = cpu_now();
    for (int i = 0; i < cycles && fe_step(m, s) == MCS_OK; i++) {
    }
    const double trun = cpu_now() - t1;
    printf("tet10: %d elements, %d nodes: %.0f ns per element-cycle (1 thread, whole step, "
           "J2), step %.3g s; model build %.3g s (%.1f us per element: stable-step "
           "eigenproblem), %.0f B per element\n",
           m->ntet10, m->nnode, 1e9 * trun / cycles / m->ntet10, s->dt, tbuild,
           1e6 * tbuild / m->ntet10, (double)(m->bytes + s->bytes) / m->ntet10);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    return 0;
}

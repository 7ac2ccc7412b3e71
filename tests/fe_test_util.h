/* fe_test_util: small helpers to build FE models in tests (steel-like defaults). */
#ifndef FE_TEST_UTIL_H
#define FE_TEST_UTIL_H

#include <string.h>

#include "fe/fe_model.h"
#include "fe/fe_state.h"

static inline fe_part_desc ft_part(const char *name, fe_section_type type, double E, double nu,
                                   double rho)
{
    fe_part_desc d = fe_part_desc_default();
    snprintf(d.name, sizeof d.name, "%s", name);
    d.section.type = type;
    d.material.model = FE_MAT_ELASTIC;
    d.material.youngs_modulus = E;
    d.material.poisson = nu;
    d.material.density = rho;
    return d;
}

static inline fe_boundary_desc ft_bc(const char *part, fe_where where, unsigned fix)
{
    fe_boundary_desc d;
    memset(&d, 0, sizeof d);
    snprintf(d.part, sizeof d.part, "%s", part);
    d.where = where;
    d.fix = fix;
    return d;
}

/* x-range of the nodes of the model with x coordinate within tol of x (count returned) */
static inline int ft_nodes_at(const fe_model *m, int axis, double c, double tol, int *idx, int cap)
{
    int n = 0;
    for (int i = 0; i < m->nnode; i++)
        if (fabs(m->node_x0[3 * i + axis] - c) <= tol) {
            if (n < cap) idx[n] = i;
            n++;
        }
    return n;
}

#endif

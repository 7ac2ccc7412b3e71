/* mb_geom_internal.h: helpers shared by the mb_geom_*.c files (not a public header). */
#ifndef MB_GEOM_INTERNAL_H
#define MB_GEOM_INTERNAL_H

#include "stage1_mb/mb_geom.h"

/* depth 0, tri -1, everything else zero */
void mb_contact_clear(mb_contact *c);

/* Q = R diag(semi^2) R^T, world (row-major, symmetric) */
void mb_ellipsoid_q(const mb_ellipsoid *e, double Q[9]);

/* the boundary point x of the centred ellipse (dim 2) or ellipsoid (dim 3) with principal
 * semi-axes a [m] nearest to the point y inside it, both in principal coordinates; returns
 * |x - y| [m] (mb_geom_nearest.c) */
double mb_ell_nearest_inside(int dim, const double *a, const double *y, double *x);

#endif

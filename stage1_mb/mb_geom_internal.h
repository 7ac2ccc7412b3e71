/* mb_geom_internal.h: helpers shared by the mb_geom_*.c files (not a public header). */
#ifndef MB_GEOM_INTERNAL_H
#define MB_GEOM_INTERNAL_H

#include "stage1_mb/mb_geom.h"

/* depth 0, tri -1, everything else zero */
void mb_contact_clear(mb_contact *c);

/* Q = R diag(semi^2) R^T, world (row-major, symmetric) */
void mb_ellipsoid_q(const mb_ellipsoid *e, double Q[9]);

#endif

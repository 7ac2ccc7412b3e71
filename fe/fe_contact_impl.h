/* fe_contact_impl: private helpers shared by the fe_contact*.c files. Not a public header. */
#ifndef FE_CONTACT_IMPL_H
#define FE_CONTACT_IMPL_H

#include "fe/fe_contact.h"
#include "fe/fe_state.h"

/* hash size of pass p's bucket table (a power of two) */
int fe_contact_hash_size(const fe_contact_model *c, int p);
/* rebuild every pass's bucket table from the current positions */
void fe_contact_search(const fe_model *m, fe_state *s);
/* the bucket of a point for pass p: its segments in cell_item[*begin .. *end) */
void fe_contact_bucket(const fe_contact_state *cs, int p, const double x[3], int *begin, int *end);

/* nearest point of triangle (a, b, c) to p: barycentric weights w[3], squared distance */
double fe_tri_nearest(const double p[3], const double a[3], const double b[3], const double c[3],
                      double w[3]);

/* elastic-stick Coulomb friction (return mapping): ft (in: history, out: new force on the
 * slave), n unit normal, du relative tangential slip increment [m], k stiffness [N/m],
 * fmax = mu fn [N]; returns the new tangential elastic energy [J], *taken the work the
 * interface took from the nodes over du [J] (dissipation = taken - change of elastic energy) */
double fe_friction_update(double ft[3], const double n[3], const double du[3], double k,
                          double fmax, double *taken);

#endif

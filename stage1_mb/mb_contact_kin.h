/* mb_contact_kin.h: the kinematics of a contact found by mb_geom on ODE bodies, and applying
 * its force: equal and opposite at one point, so linear and angular momentum are kept. The
 * force law itself (characteristic, hysteresis, damping, friction) is the caller's. */
#ifndef MB_CONTACT_KIN_H
#define MB_CONTACT_KIN_H

#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_ode.h"

typedef struct {
    double depth_rate; /* d(depth)/dt = (v_b - v_a) . normal at the point [m/s], > 0 closing */
    double slip[3];    /* tangential velocity of a relative to b at the point, world [m/s]  */
} mb_contact_vel;

/* body index -1 = a static surface (ground, fixed barrier) */
void mb_contact_velocity(const mb_world *w, int body_a, int body_b, const mb_contact *c,
                         mb_contact_vel *out);
/* fn [N] along +normal plus ft [N] (world, tangential; may be NULL) on a at c->point,
 * the opposite on b */
void mb_contact_apply(mb_world *w, int body_a, int body_b, const mb_contact *c, double fn,
                      const double ft[3]);

#endif

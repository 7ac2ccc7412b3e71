/* mb_contact_wheel2.h: the wheel-wheel (cylinder-cylinder) pair of the contact stage
 * (mb_contact.c): places wheel b and runs mb_geom_wheel_wheel with the pair's last normal as
 * the warm start, culled first by the wheels' bounding spheres. */
#ifndef MB_CONTACT_WHEEL2_H
#define MB_CONTACT_WHEEL2_H

#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_model.h"

/* a cylinder surface placed in the world by its body's kinematics k (NULL: the ground) */
void mb_wheel_place(const mb_surface *sf, const mb_body_kin *k, mb_wheel *w);

/* sb: b's cylinder surface, kb: its body's kinematics (NULL: the ground), a: wheel a placed
 * in the world; reads and updates ps's warm normal, writes c */
void mb_wheel_wheel_detect(const mb_surface *sb, const mb_body_kin *kb, const mb_wheel *a,
                           mb_pair_state *ps, mb_contact *c);

#endif

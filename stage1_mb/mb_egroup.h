/* mb_egroup.h: the energy balance of a group of bodies (the rider), the 2023 paper's Eq. 9 and
 * Fig. 24 (seed 001): kinetic + potential + internal + contact = the group's energy at t = 0,
 * with contact the energy the group transferred to its external partners, split by partner.
 *
 * Group: the free bodies a name selects; the default group "rider" is the bodies named
 * rider_* (prescribed bodies are never members). Internal: stored + dissipated energy of the
 * contacts, joint restraints and attachments between two members. A partner is each thing
 * outside that loads a member:
 *   - a stage-1 contact (its name), category by the other body: motorcycle / opponent (impact
 *     groups), ground, bodies;
 *   - an attachment (its name) and a joint crossing the boundary (constraint reaction and its
 *     one-axis restraint's load; a three-axis restraint across it is not counted), category as
 *     a contact's;
 *   - a type: bodies FE contact (its name, or its parts joined by '+'), category by its first
 *     part: belts (trusses), airbags (fabric), foam, fe;
 *   - an FE part with nodes attached to a member (its name), a retractor anchored on a member
 *     (its name, belts).
 * Work of a partner on the group: per ODE step h, the force it applied (at its point, or force
 * and moment about the CG) times the member's mean velocity over the step, (v_n + v_n+1) / 2 and
 * (w_n + w_n+1) / 2 (the kinetic energy change of a free body under that force, exactly for
 * translation); a type: bodies FE contact's from the FE side: minus the work its surfaces on
 * the members did on the FE nodes (the kernel's, fe_contact.h ell_work / fac_work), which the
 * members receive one subcycle later as a mean force (docs/stage1_engine.md). The partner's
 * contact energy is minus its work on the group (energy transferred to it). */
#ifndef MB_EGROUP_H
#define MB_EGROUP_H

#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "stage1_mb/mb_model.h"

#define MB_EGROUP_CAT 16 /* longest category name + 1 */

/* the group's series, in /stageN/energy_groups/<group>/ order (kinetic, potential, internal,
 * contact_total, total) */
#define MB_EGROUP_NSERIES 5

/* the scenario's energy_groups ({<name>: {bodies: [names or patterns]}}) and the default group
 * "rider" (bodies rider_*, unless energy_groups names one) into m->egroup; none without either.
 * A name or pattern that matches no body is an error at its key. Call after mb_couple_build. */
mcs_status mb_egroup_build(const mcs_node *root, mb_model *m, mcs_error *err);
/* a group of the bodies whose names match any of the fnmatch patterns (added to m->egroup) */
mcs_status mb_egroup_add(mb_model *m, const char *name, const char *const *patterns, int npattern,
                         mcs_error *err);
void mb_egroup_destroy(struct mb_egroup **p);
mcs_status mb_egroup_state_create(const mb_model *m, struct mb_egroup_state **out, mcs_error *err);
void mb_egroup_state_destroy(struct mb_egroup_state **p);

/* after the ODE step (new velocities in the world, s->kin and the loads still the step's
 * start's), before the FE subcycles: the partners' work of the step */
void mb_egroup_step(const mb_model *m, mb_state *s);
/* the balance now into output row `row` (< m->nout) */
void mb_egroup_record(const mb_model *m, mb_state *s, long row);
/* /stage<stage>/energy_groups/<group>/{kinetic, potential, internal, contact_total, total}
 * and contact/<partner> (attribute category) [nt] J; the group's bodies in its attribute
 * bodies */
mcs_status mb_egroup_write(const mb_model *m, const mb_state *s, mcs_results *r, int stage,
                           mcs_error *err);

/* queries (tests): groups, a group by name (-1 none), its partners, a partner by name (-1) */
int mb_egroup_count(const mb_model *m);
int mb_egroup_find(const mb_model *m, const char *name);
int mb_egroup_npartner(const mb_model *m, int g);
const char *mb_egroup_partner(const mb_model *m, int g, int p, const char **category);
int mb_egroup_partner_find(const mb_model *m, int g, const char *name);
/* the balance now: e[MB_EGROUP_NSERIES] and each partner's contact energy (npartner) [J] */
void mb_egroup_now(const mb_model *m, const mb_state *s, int g, double *e, double *partner);

#endif

/* mb_initial.h: the surface pairs that penetrate at t = 0 (`mcrash check`, docs/cli.md). A
 * model should start without initial penetrations: a pair that starts overlapped pushes its
 * bodies apart from the first step with the force its law gives at that depth. The contact
 * search and the force law are the run's (mb_contact_detect on a fresh state; the pair's
 * loading law from rest, mcs_hyst_update), so what the check lists is what the first step
 * feels. The bodies contacts of coupled FE parts (fe.contacts of type bodies) are not listed. */
#ifndef MB_INITIAL_H
#define MB_INITIAL_H

#include "stage1_mb/mb_model.h"

/* one penetrating surface pair at t = 0 */
typedef struct {
    int pair;     /* index into m->pair (its contact, surfaces and bodies) */
    double depth; /* penetration [m]                                       */
    double force; /* the pair's loading law at that depth, from rest [N]   */
} mb_initial_pen;

/* the pairs deeper than min_depth [m] at t = 0, deepest first, into *out (malloc'ed, *n of
 * them; NULL when none) */
mcs_status mb_initial_penetrations(const mb_model *m, double min_depth, mb_initial_pen **out,
                                   int *n, mcs_error *err);

#endif

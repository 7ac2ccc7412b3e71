/* mb_couple.h: stage-1 bodies coupled to the FE kernel (issue 12, DESIGN.md "Coupling bodies
 * and FE parts"): the scenario's fe: block is built by the shared FE builder
 * (fe/fe_scn_build.h) and stepped inside the ODE step; the nodes of fe.parts[].attach move
 * rigidly with their body and their constraint reactions load it. The step scheme is in
 * docs/stage1_engine.md ("Coupling to FE parts"). */
#ifndef MB_COUPLE_H
#define MB_COUPLE_H

#include "core/mcs_scenario.h"
#include "fe/fe_state.h"
#include "stage1_mb/mb_model.h"
#include "fe/fe_scn_build.h"

typedef struct mb_couple {
    fe_problem fe;      /* the FE model (owned)                                          */
    int natt;           /* attached nodes [-]                                            */
    int *node;          /* FE node of each (natt)                                        */
    int *body;          /* carrying body (natt)                                          */
    double *local;      /* node position in the body frame, about the CG (natt x 3) [m]  */
    struct mb_couple_rx *rx; /* triggers and body-carried anchors (mb_couple_rx.h)        */
    struct mb_couple_contact *contact; /* type: bodies contacts (mb_couple_contact.h), NULL none */
} mb_couple;

typedef struct mb_couple_state {
    fe_state *fe;       /* FE state (owned)                                              */
    double *vkin;       /* prescribed velocities of the fixed translations (nnode x 3)    */
    double *react;      /* constraint reactions the FE step records (fe_state.node_react)
                           (nnode x 3) [N]                                                */
    double *imp;        /* constraint impulse on each attached node this ODE step (natt x 3) */
    double *force;      /* its mean force, applied to the body in the next step (natt x 3) */
    double *xa;         /* attached points in the world at the step's start (natt x 3) [m] */
    double *fmean;      /* mean force of the last subcycle on the body (natt x 3) [N]      */
    double tc;          /* centre of the last subcycle's impulse interval [s]             */
    int started;        /* 1 after the first subcycle                                     */
    double *vold;       /* scratch: attached node velocities before an FE step (natt x 3) */
    double w_body;      /* work of the coupling forces on the bodies [J]                  */
    double w_fe;        /* work of the bodies on the attached nodes [J]                    */
    double w_fe_presc;  /* the part of it of prescribed bodies (mb_prescribe.h) [J]        */
    long substeps;      /* FE steps taken [-]                                             */
    struct mb_couple_rx_state *rx; /* triggers and anchors (mb_couple_rx.h)               */
    struct mb_couple_contact_state *contact; /* of m->couple->contact, NULL none          */
} mb_couple_state;

/* the fe: block of a scenario with bodies -> m->couple (NULL without fe:); call after the
 * impact placement (mb_impact.h): with an impact: block the parts carried by the motorcycle
 * group move with it, and every carried part starts with its body's velocity field v + w x r */
mcs_status mb_couple_build(const mcs_scenario *scn, mb_model *m, mcs_error *err);
void mb_couple_destroy(mb_couple **c);
mcs_status mb_couple_state_create(const mb_model *m, mb_couple_state **out,
                                  mcs_error *err);
void mb_couple_state_destroy(mb_couple_state **p);
/* before the ODE step: the mean reactions of the last FE subcycle onto the bodies */
void mb_couple_apply(const mb_model *m, mb_state *s);
/* after the ODE step: FE subcycle from its time to s->t with the attached nodes on the
 * bodies' motion; MCS_ERR_NUMERIC when the FE run fails */
mcs_status mb_couple_advance(const mb_model *m, mb_state *s, mcs_error *err);
/* energies of the FE parts at their last step into e, in /stage1/energy order (kinetic,
 * potential, internal (+ hourglass), contact, dissipated, external_work (loads on the FE
 * other than the bodies'), total); returns that total [J] */
double mb_couple_energy(const mb_model *m, const mb_state *s, double e[7]);

#endif

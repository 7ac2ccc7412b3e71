/* fe_restraint: gas bags and belt retractors coupled into the explicit FE kernel.
 *
 * Gas bag: the shell/membrane elements of one or more parts form a closed, outward-oriented
 * surface (checked at model build; a consistently inward surface is turned round). Every
 * step, in the external-force stage at t_n: the enclosed volume at x(t_n)
 * (fe_surface_volume), the gas (fe_gasbag: isentropic volume change, inflator, vents,
 * leakage) advanced from t_n-1 to t_n, and the gauge pressure p - p_amb applied to the fabric
 * as f = (p - p_amb) dV/dx (p A / 3 per node of a triangle, along its outward normal).
 * Energy: the gas is outside the structure. The pressure forces are external loads, so their
 * work (= the integral of (p - p_amb) dV, to second order in dt) enters `external_work` and the
 * kernel's total (kinetic + internal + ... - external work) stays constant; the gas keeps its
 * own balance (U - U0 = H_in - H_vent - H_leak - int p dV, fe_gasbag_energy_residual), and for
 * a closed adiabatic bag "gas + structure" is then conserved too: the external work equals
 * the loss of U less p_amb dV.
 *
 * Retractor: the belt end node (a node of a truss/cable part, or any node) is joined to a
 * fixed anchor (the retractor housing) by a webbing segment of stiffness k (default E A / l0
 * of the belt part, l0 = initial node-anchor distance). The retractor (fe_retractor: Eq. 3
 * pretensioner pay-in after firing, locking, load limiter) sets the payout L; the segment pulls
 * the node towards the anchor with F = retractor force from the trial k (l - l0 - L). Its work
 * is external work. The segment's own stable step, 2 sqrt(m_node / 2k), caps opts.dt_max.
 * The anchor is the model's (fixed) unless a coupling moves the state's copy
 * (retractor_anchor) before each step; the segment's reaction on it is kept
 * (retractor_fanchor) so the coupling can load what carries the anchor. */
#ifndef FE_RESTRAINT_H
#define FE_RESTRAINT_H

#include "fe/fe_gasbag.h"
#include "fe/fe_model.h"
#include "fe/fe_retractor.h"
#include "fe/fe_state.h"

#define FE_RESTRAINT_PARTS_MAX 8 /* most parts forming one gas bag */

typedef struct {
    char name[FE_NAME_MAX];                          /* results: /stage<N>/airbag/<name>    */
    int nparts;                                      /* parts forming the closed surface    */
    char parts[FE_RESTRAINT_PARTS_MAX][FE_NAME_MAX]; /* shell or membrane parts             */
    fe_gasbag_desc gas;                              /* the gas, inflator, vents, leakage   */
    double initial_pressure;    /* absolute pressure at t = 0; 0: ambient [Pa]              */
    double initial_temperature; /* gas temperature at t = 0; 0: ambient [K]                 */
} fe_airbag_desc;

typedef struct {
    char name[FE_NAME_MAX];  /* results: /stage<N>/retractor/<name>                         */
    char part[FE_NAME_MAX];  /* belt part whose node at `where` is pulled (one node)         */
    fe_where where;          /* which end                                                    */
    int node;                /* >= 0: this node instead of part/where [-]                   */
    double anchor[3];        /* retractor position (fixed) [m]                               */
    double stiffness;        /* webbing segment stiffness; 0: E A / l0 of the belt part [N/m] */
    fe_retractor_desc retractor; /* pretensioner, locking, load limiter                    */
} fe_belt_retractor_desc;

fe_airbag_desc fe_airbag_desc_default(void);
fe_belt_retractor_desc fe_belt_retractor_desc_default(void);

mcs_status fe_builder_add_airbag(fe_builder *b, const fe_airbag_desc *d, mcs_error *err);
mcs_status fe_builder_add_retractor(fe_builder *b, const fe_belt_retractor_desc *d,
                                    mcs_error *err);
/* the anchor of the retractor added as `name`, to move it with a placement (fe_scn_place.c);
 * NULL if none [m] */
double *fe_builder_retractor_anchor(fe_builder *b, const char *name);

/* ---- the frozen model's part ---------------------------------------------------------- */

typedef struct {
    char name[FE_NAME_MAX];
    fe_gasbag_model *gas; /* owned                                                       */
    int nface;            /* faces of the surface [-]                                    */
    int *face;            /* (nface x 4) node indices, -1 as the 4th of a triangle, outward */
    double p0, T0;        /* initial absolute pressure [Pa] and temperature [K]          */
    double volume0;       /* enclosed volume at t = 0 [m^3]                              */
} fe_airbag;

typedef struct {
    char name[FE_NAME_MAX];
    fe_retractor_model *model; /* owned                                                   */
    int node;                  /* pulled node [-]                                         */
    double anchor[3];          /* [m]                                                     */
    double l0;                 /* initial segment length [m]                              */
    double k;                  /* segment stiffness [N/m]                                 */
} fe_belt_retractor;

struct fe_restraints {
    int nbag, nretractor;
    fe_airbag *bag;               /* (nbag)                                                 */
    fe_belt_retractor *retractor; /* (nretractor)                                           */
};

/* what changes */
struct fe_restraint_state {
    fe_gasbag_state *bag;          /* (nbag): gas at energy_time... see fe_restraint_forces */
    fe_retractor_state *retractor; /* (nretractor)                                          */
    double *retractor_length;      /* (nretractor) segment length at the last force [m]     */
    double *retractor_ring;        /* (nretractor) unstretched length a slip ring moved into
                                      the segment (fe_slipring.h) [m]                       */
    double *retractor_anchor;      /* (nretractor x 3) anchor position now: the model's at
                                      reset; a coupling moves it (a retractor on a stage-1
                                      body, stage1_mb/mb_couple_anchor.c) [m]               */
    double *retractor_fanchor;     /* (nretractor x 3) force of the segment on its anchor at
                                      the last force evaluation (t_n), after the slip rings
                                      (minus the force on the belt node) [N]                */
};

/* model build (fe_model_create) and teardown */
mcs_status fe_restraints_create(const fe_builder *b, fe_model *m, mcs_error *err);
void fe_restraints_destroy(struct fe_restraints **p);
/* state: allocate (adds its bytes to *bytes), reset to t = 0, free */
mcs_status fe_restraint_state_create(const fe_model *m, struct fe_restraint_state **out,
                                     size_t *bytes, mcs_error *err);
void fe_restraint_state_reset(const fe_model *m, fe_state *s);
void fe_restraint_state_destroy(struct fe_restraint_state **p);

/* the per-step coupling at t_n = s->time (gas and retractors advanced over s->dt_prev,
 * forces added into node_fext); a failure is recorded in s->err */
void fe_restraint_forces(const fe_model *m, fe_state *s);

/* index of a bag / retractor by name, -1 none */
int fe_airbag_find(const fe_model *m, const char *name);
int fe_retractor_find(const fe_model *m, const char *name);

#endif

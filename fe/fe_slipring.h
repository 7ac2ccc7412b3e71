/* fe_slipring: belt slip rings (D-ring, buckle tongue) in the explicit FE kernel, after
 * LS-DYNA's *ELEMENT_SEATBELT_SLIPRING (SBID1, SBID2, FC, SBRNID, LTIME).
 *
 * A ring sits at one node (the ring node) shared by the two belt elements that pass through
 * it: two 2-node elements of elastic truss/cable parts, or one such element and the webbing
 * segment of a retractor whose belt end is the ring node (the retractor feeds through the
 * ring). Unstretched belt length flows through the ring towards the side in higher tension
 * (the higher-tension side pulls webbing round the ring), so that Coulomb friction over the
 * wrap obeys the capstan (Euler-Eytelwein) law
 *     T_low <= T_high <= T_low e^(mu theta)
 * with mu the ring's friction coefficient (LS-DYNA FC) and theta the wrap angle: pi minus the
 * angle between the two elements at the ring node (0: straight through; pi: a U-turn).
 *
 * Each step, after the element tensions of t_n are known (fe_external_forces, after the
 * retractors), the ring is a return map: if the trial tensions violate the law, the length
 * ds that moves from the low side to the high side is solved (safeguarded Newton) so that
 * T_high = e^(mu theta) T_low exactly; the two elements' unstretched lengths change by +-ds,
 * their stresses by -E ln(l0_new / l0_old) (sigma = E ln(l / l0), what the truss kernel
 * integrates), and their nodal forces with them. A frictionless ring equalises the tensions.
 * The retractor side's tension changes by its segment stiffness times the flow (0 while the
 * spool is unlocked: the spool takes the webbing at its comfort force).
 *
 * Conservation: the unstretched lengths of the two sides (and the retractor segment's ring
 * offset) sum to a constant. Energy: the elastic energy the flow releases at fixed geometry
 * is the ring's friction dissipation (>= 0; a frictionless ring dissipates only the O(dT ds)
 * of the step); the truss sides' share is moved from the belt part's internal to its
 * dissipated energy, so `internal` stays the stored elastic energy and the total balance
 * holds; the retractor segment's share is outside the structure (its force is external
 * work) and is counted only in the ring's energy_friction.
 *
 * Element handover is NOT built: when a side's unstretched length would fall below the
 * ring's minimum length (LS-DYNA's LMIN), the run stops with an error naming the ring, the
 * side and the time. Nodal masses do not follow the flowing webbing (belt mass is small).
 * Units SI. */
#ifndef FE_SLIPRING_H
#define FE_SLIPRING_H

#include "fe/fe_model.h"
#include "fe/fe_state.h"

typedef struct {
    char name[FE_NAME_MAX];      /* results: /stage<N>/slipring/<name>                      */
    int node;                    /* ring node; -1: the node of `part` nearest to `point` [-] */
    char part[FE_NAME_MAX];      /* belt part holding the ring node                         */
    double point[3];             /* ring position [m]                                       */
    double friction;             /* Coulomb coefficient mu round the ring (LS-DYNA FC) [-]  */
    double lock_time;            /* no flow from this time on (LS-DYNA LTIME); < 0 never [s] */
    double min_length;           /* smallest unstretched side length; 0: 5 % of the shorter
                                    side at t = 0 (LS-DYNA LMIN) [m]                        */
    char retractor[FE_NAME_MAX]; /* "" none; else this retractor's webbing segment is one
                                    side (its belt end must be the ring node)               */
} fe_slipring_desc;

fe_slipring_desc fe_slipring_desc_default(void);
mcs_status fe_builder_add_slipring(fe_builder *b, const fe_slipring_desc *d, mcs_error *err);
/* the point of the ring added as `name`, to move it with a placement (fe_scn_place.c); NULL if
 * none [m] */
double *fe_builder_slipring_point(fe_builder *b, const char *name);

/* one ring of the frozen model; side 0 and 1 (side 0 the retractor segment if any, else the
 * element whose far node has the lower index) */
typedef struct {
    char name[FE_NAME_MAX];
    int node;          /* ring node [-]                                                   */
    int elem[2];       /* truss element of each side; -1: the retractor segment [-]       */
    int far[2];        /* the other node of each side's element (retractor: -1) [-]       */
    int retractor;     /* index of the feeding retractor, -1 none [-]                     */
    double mu;         /* friction coefficient [-]                                        */
    double lock_time;  /* [s]; < 0 never                                                  */
    double min_length; /* [m]                                                             */
    double l0[2];      /* unstretched side lengths at t = 0 (retractor: its l0) [m]       */
} fe_slipring;

struct fe_sliprings {
    int n;
    fe_slipring *ring; /* (n) */
};

/* what changes per ring; the scalars declared once, X(name, unit, what), also the channels */
#define FE_SLIPRING_STATE_FIELDS(X)                                                                \
    X(slip, "m", "unstretched length moved from side 1 to side 0 since t = 0")                     \
    X(slip_rate, "m/s", "flow rate over the last step (> 0 towards side 0)")                       \
    X(force0, "N", "tension of side 0 after the ring")                                             \
    X(force1, "N", "tension of side 1 after the ring")                                             \
    X(wrap_angle, "rad", "wrap angle at the ring")                                                 \
    X(length0, "m", "unstretched length of side 0")                                                \
    X(length1, "m", "unstretched length of side 1")                                                \
    X(energy_friction, "J", "energy dissipated by the ring")

typedef struct {
#define FE_SLIPRING_X_DECL(name, unit, what) double name;
    FE_SLIPRING_STATE_FIELDS(FE_SLIPRING_X_DECL)
#undef FE_SLIPRING_X_DECL
    int sliding; /* the ring slid in the last step [-] */
} fe_slipring_ring_state;

enum {
#define FE_SLIPRING_X_COUNT(name, unit, what) FE_SLIPRING_CH_##name,
    FE_SLIPRING_STATE_FIELDS(FE_SLIPRING_X_COUNT)
#undef FE_SLIPRING_X_COUNT
        FE_SLIPRING_NCHANNEL
};
extern const char *const fe_slipring_channel_name[FE_SLIPRING_NCHANNEL];
extern const char *const fe_slipring_channel_unit[FE_SLIPRING_NCHANNEL];
double fe_slipring_channel(const fe_slipring_ring_state *s, int channel);

struct fe_slipring_state {
    fe_slipring_ring_state *ring; /* (n) */
};

/* model build (fe_model_create, after the retractors) and teardown */
mcs_status fe_sliprings_create(const fe_builder *b, fe_model *m, mcs_error *err);
void fe_sliprings_destroy(struct fe_sliprings **p);
void fe_slipring_list_free(fe_builder *b);
/* state: allocate (adds its bytes to *bytes), reset to t = 0, free */
mcs_status fe_slipring_state_create(const fe_model *m, struct fe_slipring_state **out,
                                    size_t *bytes, mcs_error *err);
void fe_slipring_state_reset(const fe_model *m, fe_state *s);
void fe_slipring_state_destroy(struct fe_slipring_state **p);

/* the per-step return map at t_n (after the element and retractor forces of t_n); corrects
 * stresses, node_fint, node_fext and the part energies; a failure is recorded in s->err */
void fe_slipring_forces(const fe_model *m, fe_state *s);

/* index of a ring by name, -1 none */
int fe_slipring_find(const fe_model *m, const char *name);

#endif

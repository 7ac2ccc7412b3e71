/* fe_scn_build: the `fe:` block of a scenario (DESIGN.md "The scenario (YAML)") compiled into an
 * fe_model: for a stage-3 (FE-only) run, and for the FE parts coupled to stage-1 bodies
 * (stage1_mb/mb_couple.c; every stage shares it).
 *
 * What it reads: simulation.{end_time, time_step (upper bound on the stable step),
 * time_step_scale (safety factor, default 0.9), output_rate (default 10 kHz), field_rate
 * (of the displacement fields, default FE_SCN_FIELD_FRAMES per run: fe_scn_field_rate)};
 * fe.parts with generated meshes (box,
 * plate, square_tube, circular_tube, cylinder_shell, sphere_shell, line),
 * keyword meshes (fe_scn_keyword.h: section and material may then come from the deck),
 * shell/solid/membrane/truss sections (hourglass form and coefficient, shear_factor,
 * tension_only), elastic, elastic_plastic (hardening curve or tangent_modulus, Cowper-Symonds)
 * and fabric materials, initial_velocity; fe.boundary (where, fix, velocity); fe.loads (where,
 * force, curve); fe.rigid_walls (point, normal, velocity, method, penalty_scale, parts);
 * fe.airbags and fe.retractors (fe_scn_restraints.c); fe.contacts and fe.rigid_ellipsoids
 * (fe_scn_contact.h); foam and rigid materials, solid formulation full, fe.springs,
 * fe.masses, fe.mass_scaling and environment.gravity (fe_scn_solid.h); fe.damping, bulk_q1,
 * bulk_q2 and energy_growth_limit (fe_opts).
 * What the kernel cannot do yet is refused with MCS_ERR_UNSUPPORTED at the key's
 * FILE:LINE:COL (wall friction and size, boundary tolerance, failure strain, foam damping);
 * nothing is silently dropped. */
#ifndef FE_SCN_BUILD_H
#define FE_SCN_BUILD_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

/* one FE node carried by a stage-1 body (fe.parts[].attach, fe.sliprings[].body;
 * stage1_mb/mb_couple.c) */
typedef struct {
    int node;              /* FE node index [-]                                      */
    const mcs_node *attach; /* a map with key `body`: the part's attach: or the slip
                               ring (scenario-owned)                                  */
} fe_attach;

/* a rigid placement of stage-1 bodies, applied to the FE parts they carry (stage 1's impact:
 * block, stage1_mb/mb_impact.h; fe/scn/fe_scn_place.c): a part is carried by the body of its
 * attach:, of a retractor's anchor_body or of a slip ring's body on it, or by the carrier of a
 * part it shares nodes with. The parts carried by a body of group `moved` move x' = R x + t
 * with it (`where` still selects on the positions before the move), and so do their
 * retractor anchors and slip-ring points on such bodies and the points that pick their nodes
 * (springs, masses). Refused (the meaning is ambiguous): a part carried by bodies of two groups,
 * a moved part held to the ground (translations in fe.boundary, a retractor anchor or a
 * slip-ring point without a body), initial_velocity on a carried part (it takes its body's). */
typedef struct fe_scn_place {
    double R[9], t[3]; /* x' = R x + t, R row-major [-], [m]                                 */
    int moved;         /* the group that moves; -1 none [-]                                   */
    int (*group)(void *ctx, const char *body); /* group (>= 0) of a body by name; -1 unknown */
    void *ctx;
} fe_scn_place;

typedef struct {
    fe_model *model;      /* owned                                                  */
    int natt;             /* nodes attached to bodies [-]                           */
    fe_attach *att;       /* (natt), owned; their translations are fixed in the model */
    const mcs_node **part_carrier; /* (model->npart), owned: the body-name node carrying each
                                      part (fe_scn_place above), NULL none; NULL without a
                                      placement                                        */
    double end_time;      /* simulated duration [s]                                 */
    double output_rate;   /* sampling rate of the results [Hz]                      */
    double field_rate;    /* sampling rate of the displacement fields; 0: the default [Hz] */
} fe_problem;

/* fields per run without simulation.field_rate (LS-DYNA's d3plot interval of a run: a few
 * hundred frames animate a crash; the channels and energies keep output_rate) */
#define FE_SCN_FIELD_FRAMES 200
/* the rate of p's displacement fields: simulation.field_rate, else FE_SCN_FIELD_FRAMES over
 * end_time, at most output_rate [Hz] */
double fe_scn_field_rate(const fe_problem *p);

/* build the model of a validated scenario; errors name FILE:LINE:COL and the key. A contact of
 * `type: bodies` (FE nodes against stage-1 bodies) needs the coupling: refused here */
mcs_status fe_scn_build(const mcs_scenario *scn, fe_problem *out, mcs_error *err);
/* the same with the parts carried by bodies placed by `place` (NULL: none) and a hook that adds
 * to the builder what the scenario's fe: block refers to outside it (the stage-1 coupling's
 * `type: bodies` contacts: stage1_mb/mb_couple_contact.c), called after every other
 * descriptor, before the model is frozen (NULL: none) */
typedef mcs_status (*fe_scn_hook)(fe_builder *b, const mcs_node *fe, void *ctx, mcs_error *err);
mcs_status fe_scn_build_with(const mcs_scenario *scn, const fe_scn_place *place,
                             fe_scn_hook hook, void *ctx, fe_problem *out, mcs_error *err);
void fe_problem_free(fe_problem *p);

/* a generator of several parts from one fe.parts entry (its mesh: {generate: <name>, ...}),
 * outside fe/ (stage3_fe/s3_moto.c: `motorcycle`); registered once at start-up (cli main, the
 * tests). An unregistered name is refused at its generate: key */
typedef mcs_status (*fe_scn_generator)(fe_builder *b, const mcs_node *root, const mcs_node *part,
                                       mcs_error *err);
void fe_scn_set_generator(const char *name, fe_scn_generator fn);

#endif

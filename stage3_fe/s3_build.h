/* s3_build: the `fe:` block of a scenario (DESIGN.md "The scenario (YAML)") compiled into an
 * fe_model for a stage-3 (FE-only) run.
 *
 * What it reads: simulation.{end_time, time_step (upper bound on the stable step),
 * time_step_scale (safety factor, default 0.9), output_rate (default 10 kHz)}; fe.parts with
 * generated meshes (box, plate, square_tube, circular_tube, cylinder_shell, sphere_shell, line),
 * keyword meshes (s3_keyword.h: section and material may then come from the deck),
 * shell/solid/membrane/truss sections (hourglass form and coefficient, shear_factor,
 * tension_only), elastic, elastic_plastic (hardening curve or tangent_modulus, Cowper-Symonds)
 * and fabric materials, initial_velocity; fe.boundary (where, fix, velocity); fe.loads (where,
 * force, curve); fe.rigid_walls (point, normal, velocity, method, penalty_scale, parts);
 * fe.airbags and fe.retractors (s3_restraints.c); fe.contacts and fe.rigid_ellipsoids
 * (s3_build_contact.h); foam and rigid materials, solid formulation full, fe.springs,
 * fe.masses, fe.mass_scaling and environment.gravity (s3_build_solid.h).
 * What the kernel cannot do yet is refused with MCS_ERR_UNSUPPORTED at the key's
 * FILE:LINE:COL (wall friction and size, boundary tolerance, failure strain, foam damping);
 * nothing is silently dropped. */
#ifndef S3_BUILD_H
#define S3_BUILD_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

/* one FE node carried by a stage-1 body (fe.parts[].attach; stage1_mb/mb_couple.c) */
typedef struct {
    int node;              /* FE node index [-]                                      */
    const mcs_node *attach; /* the part's attach: map (scenario-owned)               */
} s3_attach;

typedef struct {
    fe_model *model;      /* owned                                                  */
    int natt;             /* nodes attached to bodies [-]                           */
    s3_attach *att;       /* (natt), owned; their translations are fixed in the model */
    double end_time;      /* simulated duration [s]                                 */
    double output_rate;   /* sampling rate of the results [Hz]                      */
} s3_problem;

/* build the model of a validated scenario; errors name FILE:LINE:COL and the key */
mcs_status s3_build(const mcs_scenario *scn, s3_problem *out, mcs_error *err);
void s3_problem_free(s3_problem *p);

#endif

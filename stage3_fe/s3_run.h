/* s3_run: a stage-3 (FE-only) run of an fe_problem to its end time, written to /stage3 of a
 * results file (DESIGN.md "The results file"):
 *   /stage3/time [nt] s and /stage3/energy/<kind> [nt] J at the output rate (kind: the fe
 *     kernel's energies, DESIGN.md names; sampled at the kernel's energy time t_n);
 *   /stage3/rigidwall/<wall>/{force [nt] N (normal force of the structure on the wall, >= 0
 *     pushing it), displacement [nt] m} on the same times; force_mean [nt] N of a penalty wall:
 *     the mean normal force over the output interval ending at the row (the impulse of the
 *     steps since the last row over their duration; row 0: force), free of the aliasing of a
 *     penalty contact's step-to-step chatter;
 *   /stage3/mesh/<part>/{nodes [nn,3], elements [ne,k]} (initial geometry; attr node_offset);
 *   /stage3/fields/{time [nout] s, displacement [nout, nnode, 3] m} at the output rate
 *     (positions at the end of a step, so fields/time is one step ahead of /stage3/time).
 * Attributes of /stage3: steps, elements, nodes, energy_drift, output_rate [Hz], mass_added
 * [kg] and mass_added_fraction [-] (mass scaling: added / physical mass; 0 without),
 * hourglass_fraction (hourglass / internal energy at the end) and hourglass_fraction_max (the
 * largest over the rows whose internal energy is at least 1 % of the end's) [-].
 * A generated motorcycle adds its fork angle, wall forces by part, crush and impact phases
 * (stage3_fe/s3_wallcase.h); one meeting a generated sedan its pitch, the vehicles' velocities
 * and the door intrusion (stage3_fe/s3_carcase.h).
 * A numerical failure (MCS_ERR_NUMERIC: instability, inverted element, energy growth) aborts
 * the results writer: no file is left. */
#ifndef S3_RUN_H
#define S3_RUN_H

#include "fe/fe_state.h"
#include "fe/fe_scn_build.h"

typedef struct {
    const char *out_path;      /* results file                                      */
    const char *scenario_text; /* stored in /meta (may be NULL)                     */
    int quiet;                 /* no progress line                                   */
    int append;                /* add /stage3 to the existing out_path (run --stage all) */
} s3_run_opts;

typedef struct {
    long steps;                /* time steps taken [-]                               */
    int elements, nodes;       /* model size [-]                                     */
    double wall_time_s;        /* wall time of the time loop and output [s]          */
    double energy_drift;       /* |total(t_end) - total(0)| / largest energy [-]     */
    double t_end;              /* simulated time reached [s]                          */
    double dt_initial;         /* first stable step [s]                              */
    double mass_added;         /* mass added by mass scaling [kg]                    */
    double mass_added_fraction; /* that over the physical mass [-]                  */
    double hourglass_fraction; /* hourglass / internal energy at the end [-]        */
    double hourglass_fraction_max; /* largest over the rows with internal >= 1 % of the end's */
    double timer[FE_NSTAGE];   /* wall time per fe_step sub-stage [s]                */
} s3_summary;

mcs_status s3_run(const fe_problem *p, const s3_run_opts *o, s3_summary *sum, mcs_error *err);

#endif

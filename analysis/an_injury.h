/* an_injury.h: the injury criteria of one stage of a results file, against their limits
 * (`mcrash injury`, the paper's Fig. 22). Channels are found by name under
 * /stageN/channels (SAE J211 local frame, SI units):
 *   head_ax head_ay head_az [m/s^2]  -> HIC15, HIC36, head a3ms (resultant; fallback: the
 *                                       resultant of /stageN/bodies/head/acceleration)
 *   head_wx head_wy head_wz [rad/s]  -> BrIC
 *   neck_fx neck_fz [N], neck_my [N*m] (upper neck) -> Nij, tension, compression, extension,
 *                                       shear
 *   chest_ax chest_ay chest_az       -> chest a3ms (fallback: bodies chest, thorax, torso)
 *   chest_d [m]                      -> chest deflection (peak |D|), VC
 *   pelvis_ax pelvis_ay pelvis_az    -> pelvis a3ms (no limit; fallback: body pelvis)
 *   femur_left_fz femur_right_fz [N] -> femur compression (the larger side)
 *   tibia_left_mx/_my/_fz, tibia_right_mx/_my/_fz -> tibia index (the larger side)
 * A channel whose `cfc` attribute is 0 (or missing) is filtered first with J211's class for
 * its region (head and pelvis 1000, neck, femur, tibia 600, chest 180) when the sample rate
 * allows it; otherwise it is used as it is and the row says cfc 0. Angular velocities are
 * not filtered. */
#ifndef AN_INJURY_H
#define AN_INJURY_H

#include "analysis/an_dummy.h"
#include "core/mcs_error.h"

typedef struct {
    char key[32];      /* limits key (an_limits.h) or "pelvis_a3ms" */
    char label[48];    /* "HIC15", "Neck tension Fz", ... */
    double value;      /* value [unit] */
    char unit[8];      /* "-", "g", "N", "N*m", "m", "m/s" */
    double limit;      /* limit [unit], NaN when none */
    double fraction;   /* value / limit, NaN when no limit */
    double t1, t2;     /* time of the value, or its window [s] (t1 == t2 for an instant) */
    char channel[96];  /* the channels it came from */
    int cfc;           /* filter class of those channels, 0 = unfiltered */
} an_injury_row;

/* stage AN_STAGE_AUTO: the highest of stages 3, 2, 1 that has channels or bodies; stage 0 is the
 * reduced-order model's /stage0 (rom/rom.h), read only when asked for. *rows (malloc'd, *n of them) is
 * empty when no known channel is present (not an error). *stage_used receives the stage. */
#define AN_STAGE_AUTO (-1)
mcs_status an_injury_evaluate(const char *h5_path, int stage, an_injury_row **rows, int *n,
                              int *stage_used, mcs_error *err);

/* the same for a Hybrid III size (an_dummy.h): dummy >= 0 an an_dummy, -1 the file's (the
 * `dummy` attribute of /stageN or /stage1, written from the scenario's rider: block; the 50th
 * male when absent); *dummy_used receives the size used. The size selects the Nij intercepts
 * and the limits (an_limit_find_dummy). */
mcs_status an_injury_evaluate_as(const char *h5_path, int stage, int dummy, an_injury_row **rows,
                                 int *n, int *stage_used, an_dummy *dummy_used, mcs_error *err);

#endif

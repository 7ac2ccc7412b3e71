/* mcs_hysteresis: the load/unload hysteresis element of every contact, joint and fork
 * characteristic (MADYMO-style "hysteresis model"; thesis §5.3 "permanently deformed impacts";
 * paper Fig. 7, the fork's M_def(phi)). docs/hysteresis.md has the model with a figure.
 *
 * One-sided element: deflection x (penetration [m] or angle [rad]), force F >= 0 (force [N] or
 * torque [N m]); x <= 0 is an open gap (F = 0) and the element never pulls (F is clamped at 0).
 *   loading      F = F_L(x) while x reaches a new maximum x_max;
 *   unloading    below x_max along the unloading path P(x), which depends only on the history:
 *                elastic while x_max <= elastic_limit (P = F_L), otherwise per `unload` below;
 *                P never lies above the loading curve (P = min(F_L, U)), so no cycle creates
 *                energy, and it meets F_L again at x_max;
 *   reloading    back up the same path P until it meets the loading curve, then along F_L.
 * Force depends on x and the history only (rate-independent); velocity damping is the caller's
 * (mcs_hyst_damped). State holds the work done on the element; stored (recoverable) energy is
 * the area under the current unloading path from the zero-force point to x, and dissipated =
 * the area between loading curve and unloading path up to x_max; work = stored + dissipated.
 *
 * Joints use mcs_hyst2: two independent one-sided branches, one per direction (see below). */
#ifndef MCS_HYSTERESIS_H
#define MCS_HYSTERESIS_H

#include "core/mcs_curve.h"
#include "core/mcs_error.h"

typedef enum {
    /* unload along the loading curve (no permanent set) */
    MCS_UNLOAD_ELASTIC,
    /* straight line of slope unload_slope through the anchor: the plastic point reached with
     * the lowest such line (min of F_L(x') - k x'); from x_max down to the anchor the path is the
     * loading curve itself. Usually the anchor is x_max; loading into a stop stiffer than k
     * unloads elastically down the stop, then parallel to k from where the stop began (the fork
     * "blocked in that position", MYMOSA): any part of F_L steeper than k is elastic.
     * Dissipation never decreases. */
    MCS_UNLOAD_SLOPE,
    /* the unloading curve G, given as the unloading path from its last point (u_e, G(u_e) > 0),
     * scaled uniformly by s = F_max / G(u_e) (both axes, so its slopes are kept) and shifted so
     * that its last point lands on (x_max, F_max): U(x) = s G(u_e + (x - x_max) / s).
     * A straight G of slope k gives MCS_UNLOAD_SLOPE's line from (x_max, F_max). */
    MCS_UNLOAD_CURVE,
    /* paper Fig. 7: a line of slope unload_slope (as MCS_UNLOAD_SLOPE) down to the unloading
     * curve G given in absolute coordinates, then along G: U(x) = max(line(x), G(x)) */
    MCS_UNLOAD_SLOPE_CURVE
} mcs_unload;

/* the immutable model; curves are borrowed (the characteristic that owns them outlives it) */
typedef struct {
    const mcs_curve *loading;   /* F_L: force vs. deflection [N | N m] vs. [m | rad]          */
    const mcs_curve *unloading; /* G for MCS_UNLOAD_CURVE / _SLOPE_CURVE, else NULL            */
    mcs_unload unload;          /* unloading rule                                              */
    double unload_slope;        /* unloading slope k for _SLOPE / _SLOPE_CURVE [N/m | N m/rad] */
    double elastic_limit;       /* no permanent set while x_max <= this [m | rad]; >= 0,
                                   INFINITY: always elastic                                    */
} mcs_hyst_model;

/* the mutable state (small: one per contact pair / joint branch) */
typedef struct {
    double x;        /* deflection at the last update [m | rad]                                */
    double force;    /* force at the last update [N | N m]                                     */
    double x_max;    /* largest deflection reached [m | rad]                                   */
    double f_max;    /* loading force there, max(0, F_L(x_max)) [N | N m]                     */
    double x_set;    /* permanent set: largest deflection <= x_max where the unloading path
                        carries no force [m | rad]                                             */
    double line_c;   /* unloading line intercept, line = k x + line_c: min over plastic points
                        x' reached of F_L(x') - k x' (INFINITY while elastic) [N | N m]        */
    double x_anchor; /* the x' of that minimum: the path is F_L from here to x_max [m | rad] */
    double work;     /* work done on the element, integral of F dx over the history [J]       */
} mcs_hyst_state;

/* validate a model (name is used in messages: the characteristic's key) */
mcs_status mcs_hyst_model_check(const mcs_hyst_model *m, const char *name, mcs_error *err);
void mcs_hyst_reset(const mcs_hyst_model *m, mcs_hyst_state *s);

/* force at deflection x for the current history, without changing the state (solver stages) */
double mcs_hyst_force(const mcs_hyst_model *m, const mcs_hyst_state *s, double x);
/* tangent stiffness dF/dx at x (right derivative) for the current history [N/m | N m/rad] */
double mcs_hyst_stiffness(const mcs_hyst_model *m, const mcs_hyst_state *s, double x);
/* commit a step from s->x to x (assumed monotone within the step): updates the history and
 * the exact work integral; returns the force at x (NaN for a NaN x, the state untouched) */
double mcs_hyst_update(const mcs_hyst_model *m, mcs_hyst_state *s, double x);

/* energy bookkeeping [J], computed on demand (exact integrals of the piecewise-linear paths) */
double mcs_hyst_stored(const mcs_hyst_model *m, const mcs_hyst_state *s);
double mcs_hyst_dissipated(const mcs_hyst_model *m, const mcs_hyst_state *s);

/* thesis §3.1: F = F_spring + d * rate; with one_sided a contact never pulls (clamped at 0) */
static inline double mcs_hyst_damped(double f_spring, double damping, double rate, int one_sided)
{
    double f = f_spring + damping * rate;
    return (one_sided && f < 0) ? 0.0 : f;
}

/* Joints (torque vs. angle, both directions): two independent one-sided branches, `pos` for
 * x > 0 (deflection x) and `neg` for x < 0 (deflection -x); F = F_pos(x) - F_neg(-x).
 * Why independent branches: each direction is its own mechanism with its own curve (fork
 * bending rearward vs. forward, flexion vs. extension stops), as joint restraints are given
 * per side. With follow_set = 0 a history on one side does not move the other side's curve:
 * after a permanent set on one side the element carries no load between 0 and that set (free
 * play); a fork pushed back through its set meets the other branch only at x = 0.
 * With follow_set = 1 (kinematic shift, what stage-1 joints use) each branch has an origin:
 * the positive branch sees x - o_pos, the negative one o_neg - x. A new permanent set of one
 * side moves the other side's origin to that set, so a bent hinge is elastic about its set in
 * both directions (the fork stays bent; pushed forward it meets the forward characteristic
 * from the set on). The moved branch's history is cleared (it carried no load there: it was
 * on its open side) and its dissipated energy is kept in `banked`. */
typedef struct {
    mcs_hyst_model pos; /* branch for positive deflection */
    mcs_hyst_model neg; /* branch for negative deflection (given for -x, positive values) */
    int follow_set;     /* 1: each side's origin follows the other side's permanent set */
} mcs_hyst2_model;

typedef struct {
    mcs_hyst_state pos; /* state of the positive branch */
    mcs_hyst_state neg; /* state of the negative branch */
    double o_pos;       /* origin of the positive branch (follow_set) [m | rad]             */
    double o_neg;       /* origin of the negative branch (follow_set) [m | rad]             */
    double banked;      /* work of cleared branch histories, all dissipated [J]             */
} mcs_hyst2_state;

mcs_status mcs_hyst2_model_check(const mcs_hyst2_model *m, const char *name, mcs_error *err);
void mcs_hyst2_reset(const mcs_hyst2_model *m, mcs_hyst2_state *s);
double mcs_hyst2_force(const mcs_hyst2_model *m, const mcs_hyst2_state *s, double x);
double mcs_hyst2_stiffness(const mcs_hyst2_model *m, const mcs_hyst2_state *s, double x);
double mcs_hyst2_update(const mcs_hyst2_model *m, mcs_hyst2_state *s, double x);
double mcs_hyst2_work(const mcs_hyst2_state *s);
double mcs_hyst2_stored(const mcs_hyst2_model *m, const mcs_hyst2_state *s);
double mcs_hyst2_dissipated(const mcs_hyst2_model *m, const mcs_hyst2_state *s);

#endif

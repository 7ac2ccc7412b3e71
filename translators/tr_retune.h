/* tr_retune.h: stage-3 results -> stage-1 characteristics (`mcrash retune`, docs/retune.md).
 * The front's stage-1 characteristics are parameterised by six physical parameters
 *   p[0] tyre force scale   on the tyre characteristic's loading forces          [-]
 *   p[1] fork moment scale  on the fork hinge's elastic limit and plastic moments [-]
 *   p[2] elastic limit angle of the fork hinge (its elastic slope M_e / phi_e)     [rad]
 *   p[3] stop angle of the fork hinge: the wheel against the engine               [rad]
 *   p[4] rim force scale    on the tyre curve's rise beyond its elastic limit (the
 *        rim's collapse and the hub), on top of p[0]                              [-]
 *   p[5] stop stiffness     the fork hinge's slope beyond the stop angle (the wheel
 *        pressed into the engine)                                                 [N m/rad]
 * and fitted by bounded least squares (tr_lm.h) so that stage-1 runs of the scenario reproduce
 * the target's wall force and fork angle on a common CFC-filtered time grid. */
#ifndef TR_RETUNE_H
#define TR_RETUNE_H

#include "core/mcs_error.h"

#include <stdio.h>

#define TR_RT_NPAR 6
#define TR_RT_MAXPT 32

#define TR_RT_NAME 128

typedef struct {
    const char *scenario;            /* the stage-1 scenario file                          */
    char wall_body[TR_RT_NAME];      /* stage-1 body the wall force acts on ("barrier")    */
    char joint[TR_RT_NAME];          /* fork hinge joint ("moto_fork_deformation")         */
    char tyre_char[TR_RT_NAME];      /* tyre characteristic ("tyre_front")                 */
    char fork_char[TR_RT_NAME];      /* fork hinge characteristic ("fork_deformation")     */
    char target_force[2 * TR_RT_NAME]; /* target's wall force dataset or walls' group ("":
                                        * the default of tr_rt_read_target)              */
    char target_angle[2 * TR_RT_NAME]; /* target's fork angle [nt] ("": the default)      */
    double end_time;                 /* compared span [s]; 0: the target's and scenario's shorter */
    double cfc;                      /* filter class on both signals (60)                  */
    double dt;                       /* common grid interval [s] (1e-4)                    */
    int free_mask;                   /* bit i: p[i] is fitted (default the first four: 0xf) */
    int jobs;                        /* stage-1 runs at once, child processes (0: online CPUs) */
    int scan;                        /* 1: start from the best of a factorial scan (default) */
    int has_start;                   /* 1: start at `start` instead of the scenario's      */
    double start[TR_RT_NPAR];        /* that start (the loop's previous fit)               */
    int has_after;                   /* with no parameter free: rate the target at `after` */
    double after[TR_RT_NPAR];        /* (a case not in the fit, at another case's fit)     */
} tr_rt_opts;

/* the scenario's characteristics as read (SI) */
typedef struct {
    int ntyre;
    double tyre_x[TR_RT_MAXPT], tyre_y[TR_RT_MAXPT];
    double tyre_xe;                        /* the tyre's elastic limit (rim contact) [m]  */
    double m_e, phi_e, m_p, phi_s, k_stop; /* fork: elastic limit, plastic, stop, its slope  */
} tr_rt_base;

/* the target: wall force and fork angle on their own time grid */
typedef struct {
    int nt;
    double *t, *force, *angle;
} tr_rt_target;

typedef struct {
    double p0[TR_RT_NPAR], p[TR_RT_NPAR];  /* start (the scenario's) and fitted             */
    double lo[TR_RT_NPAR], hi[TR_RT_NPAR]; /* bounds                                       */
    double iso_force0, iso_angle0;         /* ISO/TS 18571 ratings before                  */
    double iso_force, iso_angle;           /* and after                                    */
    double cost0, cost;                    /* objective before / after                     */
    int iter, nfev;
    const char *why;
    /* the compared curves on the common grid (CFC-filtered): time from the target's first
     * [s], the target's force [N] and angle [rad], stage 1's before and after (nt each) */
    int nt;
    double *t, *tf, *ta, *f0, *a0, *f1, *a1;
} tr_rt_result;

void tr_rt_result_free(tr_rt_result *r);

/* the compared curves of the wall force (angle 0) or the fork angle (1) as one SVG plot: the
 * target, stage 1 before and after, their ISO/TS 18571 ratings in the legend
 * (translators/tr_retune_svg.c, analysis/an_svg.h) */
void tr_rt_write_svg(FILE *f, const tr_rt_result *r, int angle, const char *title);

/* the compared curves as CSV (time [s], then force [N] and angle [rad]: target, before, after) */
int tr_rt_write_csv(FILE *f, const tr_rt_result *r);

tr_rt_opts tr_rt_opts_default(void);
const char *tr_rt_par_name(int i);

/* the scenario's `retune:` block over o (names, target paths, free parameters, end time;
 * docs/retune.md "The retune: block"); a missing block leaves o as it is */
mcs_status tr_rt_read_opts(tr_rt_opts *o, mcs_error *err);

/* a parameter's index by name, -1 when unknown */
int tr_rt_par_index(const char *name);

/* read /stage3/time, the wall force and the fork angle; missing ones fail naming file and key.
 * Wall force: o->target_force (a dataset, or a group whose members' force are summed); by
 * default /stage3/rigidwall/<wall>/force_mean (a penalty wall's interval mean, else its force)
 * of the wall named by the attribute impact_wall of /stage3/rigidwall (a generated
 * motorcycle's run), else summed over every wall. Angle: o->target_angle; by default
 * /stage3/channels/<joint>_angle (a generated motorcycle's), else /stage3/joints/<joint>/angle */
mcs_status tr_rt_read_target(const char *h5, const tr_rt_opts *o, tr_rt_target *t,
                             mcs_error *err);
void tr_rt_target_free(tr_rt_target *t);

/* the scenario's tyre and fork characteristics; missing ones fail naming file and key */
mcs_status tr_rt_read_base(const tr_rt_opts *o, tr_rt_base *b, mcs_error *err);

/* the characteristics at p as YAML (`characteristics:` of a file the scenario includes) */
void tr_rt_write_yaml(FILE *f, const tr_rt_opts *o, const tr_rt_base *b, const double *p);

/* stage 1 at p, sampled on the target's grid (force, angle: nt values each, CFC-filtered) */
mcs_status tr_rt_stage1(const tr_rt_opts *o, const tr_rt_base *b, const double *p, int nt,
                        double dt, double *force, double *angle, mcs_error *err);

/* stage 1 at np parameter sets p[np x 4], up to o->jobs at once in child processes
 * (tr_pool.h): force, angle [np x nt] */
mcs_status tr_rt_stage1_many(const tr_rt_opts *o, const tr_rt_base *b, int np, const double *p,
                             int nt, double dt, double *force, double *angle, mcs_error *err);

/* the fit; r->p0 is filled from b (or o->start) */
mcs_status tr_rt_fit(const tr_rt_opts *o, const tr_rt_base *b, const tr_rt_target *t,
                     tr_rt_result *r, mcs_error *err);

/* /curves/<characteristic>/{loading,unloading} of the fitted characteristics into h5 */
mcs_status tr_rt_write_curves(const char *h5, const tr_rt_opts *o, const tr_rt_base *b,
                              const double *p, mcs_error *err);

#endif

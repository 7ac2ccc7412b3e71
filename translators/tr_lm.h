/* tr_lm.h: bounded nonlinear least squares, min_p 1/2 |r(p)|^2 with lo <= p <= hi, by
 * Levenberg-Marquardt (Marquardt's diagonal scaling) with a forward-difference Jacobian, each
 * trial step projected onto the bounds. The linear step solves
 * (J^T J + lambda diag(J^T J)) dp = -J^T r by LAPACK's Cholesky (dposv). docs/retune.md. */
#ifndef TR_LM_H
#define TR_LM_H

#include "core/mcs_error.h"

/* residuals r[m] at p[n]; a non-zero return fails the fit with err filled */
typedef mcs_status (*tr_lm_fn)(void *ctx, const double *p, double *r, mcs_error *err);

/* residuals R[k x m] at the k points P[k x n] (row-major), e.g. in parallel; a non-zero
 * return fails the fit */
typedef mcs_status (*tr_lm_many_fn)(void *ctx, int k, const double *P, double *R, mcs_error *err);

typedef struct {
    tr_lm_many_fn many; /* when set, the Jacobian's n columns in one call (default NULL)     */
    int max_iter;   /* outer iterations (Jacobians) (50)                                  */
    double fd_rel;  /* forward-difference step as a fraction of hi - lo (1e-4)            */
    double ftol;    /* stop when the cost falls by less than ftol * cost in an iteration (1e-10) */
    double xtol;    /* stop when every |dp_i| < xtol * (hi_i - lo_i) (1e-8)               */
    double lambda0; /* initial damping (1e-3)                                             */
} tr_lm_opts;

typedef struct {
    int iter;        /* iterations done                                                    */
    int nfev;        /* residual evaluations                                               */
    double cost0;    /* 1/2 |r|^2 at the start                                             */
    double cost;     /* 1/2 |r|^2 at the solution                                          */
    const char *why; /* why it stopped: "ftol", "xtol", "max_iter", "lambda"              */
} tr_lm_result;

tr_lm_opts tr_lm_opts_default(void);

/* p[n] in: start (clipped to the bounds), out: solution */
mcs_status tr_lm_solve(tr_lm_fn f, void *ctx, int n, int m, double *p, const double *lo,
                       const double *hi, const tr_lm_opts *o, tr_lm_result *res, mcs_error *err);

#endif

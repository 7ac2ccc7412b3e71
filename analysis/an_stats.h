/* an_stats: statistics of studies (`mcrash study --analyze`): distributions, multiple linear
 * regression and factorial ANOVA. The linear algebra is LAPACK's (dgels, dtrtri, dgelsy). */
#ifndef AN_STATS_H
#define AN_STATS_H

#include "core/mcs_error.h"

/* regularized incomplete beta function I_x(a, b), a, b > 0, 0 <= x <= 1: the continued
 * fraction DLMF 8.17.22 evaluated by the modified Lentz method (Numerical Recipes, 3rd ed.,
 * 6.4), on the side of x where it converges fast (I_x(a,b) = 1 - I_{1-x}(b,a)); NaN outside */
double an_betainc(double a, double b, double x);

/* two-sided p of Student's t with df degrees of freedom: P(|T| >= |t|) = I_{df/(df+t^2)}(df/2,
 * 1/2) (DLMF 8.17.2 with Abramowitz & Stegun 26.7.1) */
double an_t_p2(double t, double df);

/* upper tail of Fisher's F(d1, d2): P(F' >= f) = I_{d2/(d2+d1 f)}(d2/2, d1/2) (A&S 26.6.2) */
double an_f_sf(double f, double d1, double d2);

/* y = b0 + sum_j b_j x_j fitted by least squares (rows with a NaN left out) */
typedef struct {
    int n, k;          /* observations used, factors                                         */
    int df;            /* residual degrees of freedom n - k - 1                               */
    double *coef;      /* b0, b1..bk [unit of y / unit of x_j] (k+1)                         */
    double *se, *t, *p; /* standard errors, t = b/se and two-sided p of each coefficient (k+1) */
    double *std_coef;  /* standardized b_j sd(x_j) / sd(y) (sample sd) [-] (k)               */
    double *partial;   /* partial correlation of y and x_j given the other factors,
                          t_j / sqrt(t_j^2 + df) [-] (k)                                       */
    double r2, adj_r2; /* coefficient of determination, adjusted for df                     */
    double F, F_p;     /* overall F of the regression and its p                               */
    double sigma;      /* residual standard deviation sqrt(SSE / df) [unit of y]              */
} an_regression;

/* x[i * k + j]: factor j of observation i, y[i]: its response. Fewer than k+2 usable rows or
 * collinear factors (a constant one, say): MCS_ERR_NUMERIC with why in err. */
mcs_status an_regress(int n, int k, const double *x, const double *y, an_regression *r,
                      mcs_error *err);
void an_regression_free(an_regression *r);

/* stepwise selection (Efroymson 1960; Draper & Smith, Applied Regression Analysis, 3rd ed.,
 * 15.2): from no factor, each step adds the factor outside the model whose coefficient's p
 * (t test, in the model with it) is smallest if below p_enter, then removes the factor inside
 * whose p is largest if above p_remove; until neither happens. sel[j] = 1 for the factors of
 * the final model; order[] the steps (+j+1 entered, -(j+1) removed), *nstep of them */
mcs_status an_stepwise(int n, int k, const double *x, const double *y, double p_enter,
                       double p_remove, int *sel, int *order, int *nstep, mcs_error *err);

/* quadratic response surface y = b0 + sum b_j x_j + sum b_jj x_j^2 + sum_{i<j} b_ij x_i x_j
 * fitted by an_regress on the an_rsm_nterm(k) = 2k + k(k-1)/2 columns in that order (a factor
 * needs 3 levels or more for its square: with 2, x^2 is a line in x and the fit is refused as
 * collinear) */
int an_rsm_nterm(int k);
mcs_status an_rsm_fit(int n, int k, const double *x, const double *y, an_regression *r,
                      mcs_error *err);

/* ANOVA of a factorial design: each factor categorical on its distinct values (sum-to-zero
 * coding), terms the main effects in factor order, then (interactions = 1) the two-factor
 * interactions (0,1), (0,2), .., (1,2), ..; sequential (type I) sums of squares, which equal
 * the type II and III ones when the design is balanced (a full factorial). A term whose
 * columns add no rank (aliased in a fractional design) has df 0 and NaN F. When the
 * interactions would leave no residual degree of freedom (an unreplicated two-factor design)
 * they are left out of the model (pooled into the residual) and interactions is 0. */
#define AN_ANOVA_MAXTERM 64
typedef struct {
    int nterm;                      /* terms fitted                                       */
    int fa[AN_ANOVA_MAXTERM];       /* first factor of each term                          */
    int fb[AN_ANOVA_MAXTERM];       /* second factor, -1 for a main effect                */
    double ss[AN_ANOVA_MAXTERM];    /* sum of squares [unit of y ^2]                      */
    int df[AN_ANOVA_MAXTERM];       /* degrees of freedom                                  */
    double F[AN_ANOVA_MAXTERM], p[AN_ANOVA_MAXTERM];
    double ss_resid, ss_total;      /* residual and corrected total sums of squares       */
    int df_resid, n;                /* residual df, observations used                      */
    int interactions;               /* two-factor interactions are in the model           */
} an_anova;

mcs_status an_anova_fit(int n, int k, const double *x, const double *y, int interactions,
                        an_anova *a, mcs_error *err);

/* MANOVA of nr responses (y[i * nr + q]) on the same terms as an_anova_fit: per term Wilks'
 * lambda det(E) / det(E + H), E the full model's residual SSCP and H the term's sequential SSCP
 * drop, with Rao's F approximation (Rao 1951; the form of statsmodels' MANOVA.mv_test) and its
 * p. Rows with a NaN are left out; interactions are left out when they would leave fewer
 * residual df than responses. */
typedef struct {
    int nterm, fa[AN_ANOVA_MAXTERM], fb[AN_ANOVA_MAXTERM], df[AN_ANOVA_MAXTERM];
    double wilks[AN_ANOVA_MAXTERM];        /* Wilks' lambda [-]                  */
    double F[AN_ANOVA_MAXTERM], p[AN_ANOVA_MAXTERM];
    double df1[AN_ANOVA_MAXTERM], df2[AN_ANOVA_MAXTERM]; /* Rao's F degrees of freedom */
    int df_resid, n, nresp, interactions;
} an_manova;

mcs_status an_manova_fit(int n, int k, const double *x, int nr, const double *y,
                         int interactions, an_manova *a, mcs_error *err);

#endif

/* an_criteria.h: injury criteria of dummy channels. Inputs in SI (accelerations in m/s^2,
 * forces in N, moments in N*m, angular velocities in rad/s, deflections in m, times in s);
 * results in the criterion's customary unit (HIC and a3ms use g = 9.80665 m/s^2).
 * Sign conventions are SAE J211: neck Fz > 0 tension, My > 0 flexion. */
#ifndef AN_CRITERIA_H
#define AN_CRITERIA_H

#include "analysis/an_dummy.h"
#include "core/mcs_error.h"

#define AN_G0 9.80665 /* standard gravity [m/s^2] */

/* ---- head: HIC (an_hic.c) ---- */
typedef struct {
    double hic;    /* HIC [-] (g^2.5 s) */
    double t1, t2; /* window of the maximum [s] */
} an_hic_result;

/* HIC = max over sample pairs t1 < t2 with t2 - t1 <= window of
 * (t2 - t1) [(1/(t2 - t1)) int_t1^t2 a dt / g]^2.5, the integral by trapezoids (exact for
 * the piecewise-linear signal). a: resultant acceleration [m/s^2] (n), t increasing. Windows
 * whose mean is negative count as 0. Exact maximum over all pairs (no fixed-length shortcut):
 * blocks of 64 x 64 pairs whose upper bound cannot beat the best so far are skipped (an
 * unpruned search at 1 MHz over 0.3 s takes ~17 s, this ~0.1 s). Ties: earliest t1, t2. */
mcs_status an_hic(const double *t, const double *a, int n, double window, an_hic_result *r,
                  mcs_error *err);

/* ---- a3ms (an_a3ms.c) ---- */
typedef struct {
    double level;  /* level held [m/s^2] */
    double t1, t2; /* first interval where it is held (continuous variant) [s] */
} an_a3ms_result;

/* the paper's Eq. (8): max over t1 of min over [t1, t1 + dur] of a, for the piecewise-linear
 * signal through the samples (exact: the largest level whose superlevel set contains an
 * interval of length dur, found by bisection to 1e-12 of the range) */
mcs_status an_a3ms(const double *t, const double *a, int n, double dur, an_a3ms_result *r,
                   mcs_error *err);
/* cumulative variant: the largest level exceeded for a total time of dur */
mcs_status an_a3ms_cumulative(const double *t, const double *a, int n, double dur,
                              an_a3ms_result *r, mcs_error *err);

/* ---- neck: Nij (an_nij.c) ---- */
typedef enum { AN_NIJ_TF, AN_NIJ_TE, AN_NIJ_CF, AN_NIJ_CE, AN_NIJ_NMODES } an_nij_mode;

typedef struct {
    double fz_tension;     /* critical tension Fzc [N] */
    double fz_compression; /* critical compression [N] (positive number) */
    double my_flexion;     /* critical flexion moment Myc [N*m] */
    double my_extension;   /* critical extension moment [N*m] (positive number) */
    double condyle_offset; /* load cell to occipital condyle, M_oc = My - d Fx [m] */
} an_nij_opts;

an_nij_opts an_nij_opts_hybrid3_50m(void); /* 6806 / 6160 N, 310 / 135 N*m, 0.01778 m */
an_nij_opts an_nij_opts_hybrid3_05f(void); /* 4287 / 3880 N, 155 / 67 N*m, 0.01778 m */
an_nij_opts an_nij_opts_hybrid3_95m(void); /* 8216 / 7440 N, 415 / 179 N*m (unverified) */
/* the intercepts of a Hybrid III size (an_dummy.h) */
an_nij_opts an_nij_opts_dummy(an_dummy d);

typedef struct {
    double nij;                       /* max over time and modes [-] */
    an_nij_mode mode;                 /* mode of the maximum */
    double time;                      /* time of the maximum [s] */
    double mode_max[AN_NIJ_NMODES];   /* max of each mode [-] (0 if never active) */
    double mode_time[AN_NIJ_NMODES];  /* time of each mode's max [s] */
} an_nij_result;

const char *an_nij_mode_name(an_nij_mode m); /* "TF", "TE", "CF", "CE" */

/* Fx, Fz [N], My [N*m] upper-neck load cell at times t (n) */
mcs_status an_nij(const double *t, const double *fx, const double *fz, const double *my, int n,
                  const an_nij_opts *o, an_nij_result *r, mcs_error *err);

/* peaks of the upper-neck loads */
typedef struct {
    double fx_max, fx_min;     /* shear [N] */
    double fz_tension;         /* max Fz, >= 0 [N] */
    double fz_compression;     /* max -Fz, >= 0 [N] */
    double my_flexion;         /* max M_oc [N*m] */
    double my_extension;       /* max -M_oc, >= 0 [N*m] */
} an_neck_peaks;

mcs_status an_neck_peaks_compute(const double *fx, const double *fz, const double *my, int n,
                                 double condyle_offset, an_neck_peaks *p, mcs_error *err);

/* ---- brain: BrIC (an_bric.c) ---- */
/* critical angular velocities (MPS-based) about x, y, z [rad/s]: 66.3, 53.8, 41.5 */
typedef struct {
    double wc[3]; /* [rad/s] */
} an_bric_opts;
an_bric_opts an_bric_opts_default(void);

/* BrIC = sqrt(sum_i (max|w_i| / w_iC)^2) */
mcs_status an_bric(const double *wx, const double *wy, const double *wz, int n,
                   const an_bric_opts *o, double *bric, mcs_error *err);

/* ---- thorax: viscous criterion (an_vc.c) ---- */
typedef struct {
    double scale;  /* 1.3 for the Hybrid III 50th [-] */
    double depth;  /* chest depth for the compression ratio, 0.229 m [m] */
} an_vc_opts;
an_vc_opts an_vc_opts_hybrid3_50m(void);

/* VC = max_t scale * V(t) * D(t) / depth with V = dD/dt by the 4th-order central difference
 * (8(D[i+1] - D[i-1]) - (D[i+2] - D[i-2]))/(12 dt); uniform sampling, n >= 5; evaluated at
 * i = 2..n-3. vc_out (optional, n) receives the VC(t) history (0 at the two end samples). */
mcs_status an_vc(const double *t, const double *d, int n, const an_vc_opts *o, double *vc,
                 double *time, double *vc_out, mcs_error *err);

/* ---- lower extremity (an_ti.c) ---- */
typedef struct {
    double mc; /* critical resultant bending moment [N*m], 225 (H3 50th) */
    double fc; /* critical axial force [N], 35900 */
} an_ti_opts;
an_ti_opts an_ti_opts_hybrid3_50m(void);

/* TI = max_t |M_R / Mc| + |Fz / Fc|, M_R = sqrt(Mx^2 + My^2) */
mcs_status an_tibia_index(const double *t, const double *mx, const double *my, const double *fz,
                          int n, const an_ti_opts *o, double *ti, double *time, mcs_error *err);

/* ---- peaks and resultants (an_peaks.c) ---- */
/* r[i] = sqrt(x^2 + y^2 + z^2) */
void an_resultant(const double *x, const double *y, const double *z, int n, double *r);
/* max of |y| and its index */
double an_peak_abs(const double *y, int n, int *index);
/* femur: peak axial compression (max of -Fz, >= 0) [N] */
double an_femur_compression(const double *fz, int n, int *index);

#endif

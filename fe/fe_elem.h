/* fe_elem: private element kernels shared by the model (masses, stable step) and the element
 * loops: hex8 uniform gradients, shell local frames, materials. Not a public header. */
#ifndef FE_ELEM_H
#define FE_ELEM_H

#include "fe/fe_state.h"

/* natural coordinates of the hex8 nodes (0..7: bottom face counter-clockwise, then top) */
extern const double fe_hex_xi[8][3];

/* hex8 volume and uniform gradients b_I = (1/V) dV/dx_I (Flanagan & Belytschko 1981, exact
 * for the trilinear element); a[0..7] receive the vectors (1/8) sum_I h_k(I) x_I of the
 * base h = 1, xi, eta, zeta, xi eta, eta zeta, xi zeta, xi eta zeta. Returns V [m^3]. */
double fe_hex_gradients(const double xe[8][3], double b[8][3], double a[8][3]);
/* characteristic length V / largest face area [m] */
double fe_hex_length(const double xe[8][3], double vol);

/* shell local frame (e1 along side 1-2, e3 from the diagonals), local coordinates of the
 * nodes about the centroid, and area; returns the area [m^2] (<= 0: degenerate) */
double fe_shell_frame(const double xe[4][3], double e[3][3], double xl[4], double yl[4]);
/* characteristic length area / longest side [m] */
double fe_shell_length(const double xe[4][3], double area);

/* flow stress of the hardening curve at plastic strain epsp, and its slope [Pa] */
double fe_flow_stress(const fe_part *p, double epsp, double *slope);
/* Cowper-Symonds factor 1 + (rate/C)^(1/p) (1 when off) [-] */
double fe_rate_factor(const fe_part *p, double rate);

/* the effective strain rate that enters the rate factor: an exponential average over about
 * FE_RATE_CYCLES steps (as LS-DYNA averages MAT_024 rates over 12 cycles), so that element
 * vibrations do not feed back through the flow stress */
#define FE_RATE_CYCLES 12
static inline double fe_rate_filter(double filtered, double rate)
{
    return filtered + (rate - filtered) / FE_RATE_CYCLES;
}

/* 3-D J2 radial return: sig (xx yy zz xy yz zx) holds the rotated stress at t - dt and
 * receives the stress at t; de is the strain increment (tensor shear components). Returns
 * the plastic strain increment. rate: effective strain rate [1/s]. */
double fe_mat_3d(const fe_part *p, double sig[6], const double de[6], double epsp, double rate);
/* plane stress (xx yy xy, engineering shear increment), Simo-Taylor return */
double fe_mat_plane_stress(const fe_part *p, double sig[3], const double de[3], double epsp,
                           double rate);
/* uniaxial */
double fe_mat_1d(const fe_part *p, double *sig, double de, double epsp, double rate);

/* element loops of one part: stresses, slot forces, energies, smallest element step */
void fe_hex_part(const fe_model *m, fe_state *s, int ip);
void fe_shell_part(const fe_model *m, fe_state *s, int ip);
void fe_truss_part(const fe_model *m, fe_state *s, int ip);
/* element steps of the part at positions x (no safety factor); *elem gets the smallest */
double fe_part_dt(const fe_model *m, int ip, const double *x, int *elem);

static inline void fe_cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}
static inline double fe_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

#endif

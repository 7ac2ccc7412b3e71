/* fe_gasbag_impl.h: helpers shared by fe_gasbag.c and fe_gasbag_cvode.c (not public API). */
#ifndef FE_GASBAG_IMPL_H
#define FE_GASBAG_IMPL_H

#include "fe/fe_gasbag.h"

/* vent and leak mass flows [kg/s] of gas (mass [kg], U [J]) in volume V [m^3] */
void fe_gasbag_outflow_(const fe_gasbag_model *m, unsigned open, double area, double mass, double U,
                        double V, double *mv, double *ml);
/* inflator mass flow [kg/s] and gas temperature [K] at absolute time t for a bag fired at tf
 * [s]; 0 before firing */
void fe_gasbag_inflow_(const fe_gasbag_model *m, double tf, double t, double *mdot, double *Tin);
/* vents opened by the gauge pressure of absolute pressure p [Pa], added to `open` */
unsigned fe_gasbag_latch_vents_(const fe_gasbag_model *m, unsigned open, double p);

#endif

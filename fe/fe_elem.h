/* fe_elem: private element kernels shared by the model (masses, stable step) and the element
 * loops: hex8 uniform gradients, shell local frames, materials. Not a public header. */
#ifndef FE_ELEM_H
#define FE_ELEM_H

#include "fe/fe_state.h"

#include <math.h>

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

/* plane-stress constants of one part, computed once per part and step so that the element
 * loop does no divisions for them (fe_mat_plane_stress and the shell loop share them) */
typedef struct {
    const fe_part *p;
    double c, cnu, G;  /* E/(1-nu^2), nu E/(1-nu^2), shear modulus [Pa]              */
    double a;          /* E/(3(1-nu)): rate at which sxx + syy shrinks in the return [Pa] */
    int plastic;       /* J2 (else linear elastic) [-]                                  */
    int nseg;          /* hardening segments (0: constant flow stress) [-]              */
    double s0;         /* flow stress when nseg = 0 [Pa]                                */
    double slope[FE_CURVE_MAX]; /* slope of each hardening segment [Pa]                 */
} fe_ps_const;

void fe_ps_const_init(const fe_part *p, fe_ps_const *k);

/* flow stress and slope at epsp (as fe_flow_stress, without divisions); *seg gets the segment */
static inline double fe_ps_flow(const fe_ps_const *k, double epsp, double *slope, int *seg)
{
    if (k->nseg == 0) {
        *slope = 0, *seg = 0;
        return k->s0;
    }
    const double(*hd)[2] = k->p->material.hardening;
    int i = 0;
    while (i < k->nseg - 1 && epsp >= hd[i + 1][0]) i++;
    *seg = i;
    *slope = k->slope[i];
    return hd[i][1] + k->slope[i] * (epsp - hd[i][0]);
}

/* the plastic part of the plane-stress update: sig holds the elastic trial stress, q0sq its
 * von Mises stress squared, which exceeds the flow stress; rf the rate factor. Returns the
 * plastic strain increment and leaves the returned stress in sig. */
double fe_ps_return(const fe_ps_const *k, double sig[3], double q0sq, double epsp, double rf);

/* the static flow stress at a point's plastic strain, its slope and segment, as the trial
 * found them (fe_ps_flow), so that the return does not look them up again */
typedef struct {
    double y, h; /* flow stress, slope [Pa] */
    int seg;     /* hardening segment [-]   */
} fe_ps_flowpt;

/* fe_ps_return for n points at once (the same results; the iterations overlap); fl: each
 * point's fe_ps_flowpt from fe_ps_trial */
void fe_ps_return_batch(const fe_ps_const *k, int n, double (*sig)[3], const double *q0sq,
                        const double *epsp, const double *rf, const fe_ps_flowpt *fl,
                        double *dp);

/* the elastic trial stress (sig += C de); returns 1 when it exceeds the flow stress, with its
 * von Mises stress squared in *q0sq, the rate factor in *rf and the static flow stress in *fl.
 * The Cowper-Symonds factor is computed only when the trial exceeds the static flow stress
 * (the factor is >= 1). */
static inline int fe_ps_trial(const fe_ps_const *k, double sig[3], const double de[3],
                              double epsp, double rate, double *q0sq, double *rf,
                              fe_ps_flowpt *fl)
{
    sig[0] += k->c * de[0] + k->cnu * de[1];
    sig[1] += k->c * de[1] + k->cnu * de[0];
    sig[2] += k->G * de[2];
    if (!k->plastic) return 0;
    double pp = sig[0] + sig[1], mm = sig[0] - sig[1], tt = sig[2];
    double q2 = 0.25 * pp * pp + 0.75 * mm * mm + 3 * tt * tt;
    double h;
    int seg;
    double sy = fe_ps_flow(k, epsp, &h, &seg);
    if (q2 <= sy * sy) return 0; /* elastic at the static flow stress: no rate factor */
    double f = rate > 0 ? fe_rate_factor(k->p, rate) : 1; /* no call without a rate */
    if (f != 1 && q2 <= f * f * sy * sy) return 0;
    *q0sq = q2, *rf = f;
    fl->y = sy, fl->h = h, fl->seg = seg;
    return 1;
}

/* the whole plane-stress update with precomputed constants (fe_mat_plane_stress's result) */
static inline double fe_ps_update(const fe_ps_const *k, double sig[3], const double de[3],
                                  double epsp, double rate)
{
    double q0sq, rf;
    fe_ps_flowpt fl;
    if (!fe_ps_trial(k, sig, de, epsp, rate, &q0sq, &rf, &fl)) return 0;
    return fe_ps_return(k, sig, q0sq, epsp, rf);
}

/* element loops of one part: stresses, slot forces, energies, smallest element step */
void fe_hex_part(const fe_model *m, fe_state *s, int ip);
void fe_shell_part(const fe_model *m, fe_state *s, int ip);
void fe_truss_part(const fe_model *m, fe_state *s, int ip);
/* the same on elements e0..e1-1 of part ip, partial sums into *acc (threaded chunks) */
void fe_hex_range(const fe_model *m, fe_state *s, int ip, int e0, int e1, fe_chunk_acc *acc);
void fe_shell_range(const fe_model *m, fe_state *s, int ip, int e0, int e1, fe_chunk_acc *acc);
void fe_truss_range(const fe_model *m, fe_state *s, int ip, int e0, int e1, fe_chunk_acc *acc);
/* add a part's partial sums to its energies, step and first bad element */
void fe_chunk_commit(fe_state *s, int ip, const fe_chunk_acc *acc);
/* element chunks of the model (fe_model_create, after the elements are sorted by part) */
void fe_build_chunks(fe_model *m);
/* m->nelem_chunked: the elements of the parts in the chunk loops (fe_part_chunked; after the
 * rigid parts are known, fe_solid_build) */
void fe_count_chunked(fe_model *m);
/* add the partial sums of the next chunk of the same part (chunk order) */
void fe_chunk_merge(fe_chunk_acc *into, const fe_chunk_acc *a);
/* partial sums of a node chunk in fe_integrate: kinetic energy, works before and after t of
 * loads and constraints, damping before and after, first bad node; then the kinetic energy
 * of each part and the force on each wall */
enum { FE_ACC_KE, FE_ACC_WB, FE_ACC_WF, FE_ACC_DB, FE_ACC_DF, FE_ACC_BAD, FE_NACC_FIXED };

/* element steps of the part at positions x (no safety factor); *elem gets the smallest */
double fe_part_dt(const fe_model *m, int ip, const double *x, int *elem);

/* the step of a solid of length len [m] and wave speed c0 [m/s] under bulk viscosity, the
 * damped limit len / (Q + sqrt(Q^2 + c0^2)) with Q = q2 c0 + q1 len max(0, -ev) [m/s], ev the
 * volumetric strain rate [1/s]. The linear term counts at every sign of ev: the viscosity
 * switches on with compression, after the step it acts in was chosen, and a step that drops by
 * q2 (6 %) whenever an element turns to compression follows its highest mode (docs/fe.md). */
static inline double fe_bulk_dt(const fe_model *m, double len, double c0, double ev)
{
    const double q = m->opts.bulk_q2 * c0 + (ev < 0 ? m->opts.bulk_q1 * len * -ev : 0);
    return len / (q + sqrt(q * q + c0 * c0));
}

/* the connectivity of element kind FE_KIND_* (fe_kind_nnode nodes per element) */
static inline const int *fe_kind_conn(const fe_model *m, int kind)
{
    return kind == FE_KIND_HEX     ? m->hex_node
           : kind == FE_KIND_SHELL ? m->shell_node
           : kind == FE_KIND_TET10 ? m->tet10_node
                                   : m->truss_node;
}

/* element step factor of mass scaling (fe_massscale.c; 1 without); kind FE_KIND_*, e the
 * element's index in its kind */
static inline double fe_dt_factor(const fe_model *m, int kind, int e)
{
    if (!m->elem_dt_factor) return 1;
    int off = kind == FE_KIND_HEX     ? 0
              : kind == FE_KIND_SHELL ? m->nhex
              : kind == FE_KIND_TRUSS ? m->nhex + m->nshell
                                      : m->nhex + m->nshell + m->ntruss;
    return m->elem_dt_factor[off + e];
}

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

/* the spin increment W dt of the velocity gradient L (W skew: W01 = w01, W12 = w12,
 * W20 = w20); used by the one-point and the fully integrated hex */
static inline void fe_spin(const double L[3][3], double dt, double W[3][3])
{
    double w01 = 0.5 * (L[0][1] - L[1][0]) * dt, w12 = 0.5 * (L[1][2] - L[2][1]) * dt,
           w20 = 0.5 * (L[2][0] - L[0][2]) * dt;
    W[0][0] = 0, W[0][1] = w01, W[0][2] = -w20;
    W[1][0] = -w01, W[1][1] = 0, W[1][2] = w12;
    W[2][0] = w20, W[2][1] = -w12, W[2][2] = 0;
}

/* Jaumann rotation of sg (xx yy zz xy yz zx) by a spin increment W: sg += W sg - sg W */
static inline void fe_jaumann(double sg[6], const double W[3][3])
{
    double S[3][3] = {{sg[0], sg[3], sg[5]}, {sg[3], sg[1], sg[4]}, {sg[5], sg[4], sg[2]}};
    double R[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double r = 0;
            for (int k = 0; k < 3; k++) r += W[i][k] * S[k][j] - S[i][k] * W[k][j];
            R[i][j] = S[i][j] + r;
        }
    sg[0] = R[0][0], sg[1] = R[1][1], sg[2] = R[2][2], sg[3] = R[0][1], sg[4] = R[1][2],
    sg[5] = R[2][0];
}

/* a part whose elements run in the threaded chunk loops (fe_stages.c); membranes, rigid parts
 * and parts without elements run whole, on one thread */
static inline int fe_part_chunked(const fe_part *p)
{
    if (p->body >= 0) return 0; /* rigid part: no element work (fe_rigid.c) */
    if (p->material.model == FE_MAT_NULL) return 0; /* no stress, no step limit */
    return p->elem_kind == FE_KIND_HEX || p->elem_kind == FE_KIND_TRUSS ||
           p->elem_kind == FE_KIND_TET10 ||
           (p->elem_kind == FE_KIND_SHELL && p->section.type != FE_SECTION_MEMBRANE);
}

#endif

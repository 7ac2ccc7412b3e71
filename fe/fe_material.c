/* fe_material: linear elastic and J2 elastic-plastic with tabulated isotropic hardening and
 * the Cowper-Symonds rate factor (what users know as LS-DYNA MAT_024), in 3-D (radial return,
 * Wilkins 1964; Simo & Hughes 1998, Box 3.1), plane stress (Simo & Taylor 1986 return,
 * Simo & Hughes Box 3.3/3.4) and uniaxial form. Stresses are updated incrementally. */
#include "fe/fe_elem.h"

#include <math.h>

/* a return is converged when the yield condition holds to this fraction of the trial stress
 * (1e-12: far below any physical effect, above the round-off of the residual) */
#define FE_RETURN_TOL 1e-12

double fe_flow_stress(const fe_part *p, double epsp, double *slope)
{
    const fe_material_desc *mt = &p->material;
    int n = mt->nhardening;
    if (n == 0) {
        *slope = 0;
        return mt->yield_stress;
    }
    if (n == 1) {
        *slope = 0;
        return mt->hardening[0][1];
    }
    /* the last segment's slope continues beyond the table */
    int i = 0;
    while (i < n - 2 && epsp >= mt->hardening[i + 1][0]) i++;
    const double *a = mt->hardening[i], *b = mt->hardening[i + 1];
    *slope = (b[1] - a[1]) / (b[0] - a[0]);
    return a[1] + *slope * (epsp - a[0]);
}

double fe_rate_factor(const fe_part *p, double rate)
{
    double c = p->material.cowper_symonds_c;
    if (!(c > 0) || !(rate > 0)) return 1;
    return 1 + pow(rate / c, 1 / p->material.cowper_symonds_p);
}

double fe_mat_3d(const fe_part *p, double sig[6], const double de[6], double epsp, double rate)
{
    const double lam = p->lambda, mu = p->mu;
    double tr = de[0] + de[1] + de[2];
    for (int i = 0; i < 3; i++) sig[i] += lam * tr + 2 * mu * de[i];
    for (int i = 3; i < 6; i++) sig[i] += 2 * mu * de[i];
    if (p->material.model != FE_MAT_ELASTIC_PLASTIC) return 0;
    double pm = (sig[0] + sig[1] + sig[2]) / 3, s[6];
    for (int i = 0; i < 3; i++) s[i] = sig[i] - pm;
    for (int i = 3; i < 6; i++) s[i] = sig[i];
    double j2 = 0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) + s[3] * s[3] + s[4] * s[4] +
                s[5] * s[5];
    double q = sqrt(3 * j2), h, rf = fe_rate_factor(p, rate);
    double sy = rf * fe_flow_stress(p, epsp, &h);
    if (q <= sy) return 0;
    /* q - 3 mu dp = rf sy(epsp + dp): Newton, exact after the segments crossed */
    double dp = 0;
    for (int it = 0; it < 50; it++) {
        double g = q - 3 * mu * dp - rf * fe_flow_stress(p, epsp + dp, &h);
        if (fabs(g) <= FE_RETURN_TOL * q) break;
        dp += g / (3 * mu + rf * h);
        if (dp < 0) dp = 0;
    }
    double scale = 1 - 3 * mu * dp / q;
    for (int i = 0; i < 3; i++) sig[i] = pm + scale * s[i];
    for (int i = 3; i < 6; i++) sig[i] = scale * s[i];
    return dp;
}

/* von Mises stress of a plane stress state from p = sxx + syy, m = sxx - syy, t = sxy */
static double vm_ps(double pp, double mm, double t)
{
    return sqrt(0.25 * pp * pp + 0.75 * mm * mm + 3 * t * t);
}

double fe_mat_plane_stress(const fe_part *p, double sig[3], const double de[3], double epsp,
                           double rate)
{
    const double E = p->material.youngs_modulus, nu = p->material.poisson, G = p->mu;
    const double c = E / (1 - nu * nu);
    sig[0] += c * (de[0] + nu * de[1]);
    sig[1] += c * (de[1] + nu * de[0]);
    sig[2] += G * de[2];
    if (p->material.model != FE_MAT_ELASTIC_PLASTIC) return 0;
    double h, rf = fe_rate_factor(p, rate);
    double sy = rf * fe_flow_stress(p, epsp, &h);
    double p0 = sig[0] + sig[1], m0 = sig[0] - sig[1], t0 = sig[2];
    double q0sq = 0.25 * p0 * p0 + 0.75 * m0 * m0 + 3 * t0 * t0;
    if (q0sq <= sy * sy) return 0; /* elastic: no square root */
    double q0 = sqrt(q0sq);
    /* plastic multiplier dg: p, m, t shrink by 1/(1 + a dg), 1/(1 + 2 G dg), 1/(1 + 2 G dg)
     * with a = E / (3 (1 - nu)); plastic strain increment (2/3) dg q(dg) */
    const double a = E / (3 * (1 - nu));
    /* start from the exact answer of a purely deviatoric in-plane state, q0 / (1 + 2 G dg) =
     * sy + (2/3) h dg sy: Newton then needs two or three iterations */
    double dg = (q0 - sy) / (sy * (2 * G + 2.0 / 3.0 * rf * h));
    double fp = 1, fm = 1, q = q0;
    for (int it = 0;; it++) {
        fp = 1 / (1 + a * dg), fm = 1 / (1 + 2 * G * dg);
        double pp = p0 * fp, mm = m0 * fm, tt = t0 * fm;
        q = vm_ps(pp, mm, tt);
        double dq = (-0.25 * pp * pp * a * fp - (0.75 * mm * mm + 3 * tt * tt) * 2 * G * fm) / q;
        double g = q - rf * fe_flow_stress(p, epsp + 2.0 / 3.0 * dg * q, &h);
        /* converged (or out of iterations): fp, fm, q belong to this dg */
        if (fabs(g) <= FE_RETURN_TOL * q0 || it == 60) break;
        double step = -g / (dq - rf * h * 2.0 / 3.0 * (q + dg * dq));
        if (dg + step < 0) step = -0.5 * dg;
        dg += step;
    }
    double pp = p0 * fp, mm = m0 * fm;
    sig[0] = 0.5 * (pp + mm);
    sig[1] = 0.5 * (pp - mm);
    sig[2] = t0 * fm;
    return 2.0 / 3.0 * dg * q;
}

double fe_mat_1d(const fe_part *p, double *sig, double de, double epsp, double rate)
{
    const double E = p->material.youngs_modulus;
    *sig += E * de;
    if (p->material.model != FE_MAT_ELASTIC_PLASTIC) return 0;
    if (p->section.tension_only && *sig < 0) return 0; /* a slack cable does not yield */
    double h, rf = fe_rate_factor(p, rate), q = fabs(*sig);
    if (q <= rf * fe_flow_stress(p, epsp, &h)) return 0;
    double dp = 0;
    for (int it = 0; it < 50; it++) {
        double g = q - E * dp - rf * fe_flow_stress(p, epsp + dp, &h);
        if (fabs(g) <= FE_RETURN_TOL * q) break;
        dp += g / (E + rf * h);
        if (dp < 0) dp = 0;
    }
    *sig = copysign(q - E * dp, *sig);
    return dp;
}

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
    /* q - 3 mu dp = rf sy(epsp + dp): on the segment of epsp the flow stress is linear and
     * dp closed-form; when it ends beyond the segment, Newton, exact after the segments crossed */
    double dp = (q - sy) / (3 * mu + rf * h);
    const fe_material_desc *mt = &p->material;
    const int n = mt->nhardening;
    int seg = 0; /* fe_flow_stress's segment; the last one continues beyond the table */
    while (seg < n - 2 && epsp >= mt->hardening[seg + 1][0]) seg++;
    const int inseg = n < 2 || seg == n - 2 || epsp + dp < mt->hardening[seg + 1][0];
    if (!inseg) dp = 0;
    for (int it = 0; it < 50 && !inseg; it++) {
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

void fe_ps_const_init(const fe_part *p, fe_ps_const *k)
{
    const fe_material_desc *mt = &p->material;
    const double E = mt->youngs_modulus, nu = mt->poisson;
    k->p = p;
    k->c = E / (1 - nu * nu);
    k->cnu = nu * k->c;
    k->G = p->mu;
    k->a = E / (3 * (1 - nu));
    k->plastic = mt->model == FE_MAT_ELASTIC_PLASTIC;
    /* fe_flow_stress's table: n = 0 the yield stress, n = 1 its one value, else segments
     * with the last one's slope continuing beyond the table */
    k->nseg = mt->nhardening >= 2 ? mt->nhardening - 1 : 0;
    k->s0 = mt->nhardening == 1 ? mt->hardening[0][1] : mt->yield_stress;
    for (int i = 0; i < k->nseg; i++)
        k->slope[i] = (mt->hardening[i + 1][1] - mt->hardening[i][1]) /
                      (mt->hardening[i + 1][0] - mt->hardening[i][0]);
}

/* Plane-stress J2 return (Simo & Taylor 1986; Simo & Hughes 1998, Box 3.3/3.4). With
 * p = sxx + syy, m = sxx - syy, t = sxy the return scales the trial values as
 *     p = p0 / (1 + a x),  m = m0 / (1 + b x),  t = t0 / (1 + b x),
 *     a = E / (3 (1 - nu)),  b = 2 G,  x = plastic multiplier,
 * and the plastic strain increment is dp = (2/3) x q (q the von Mises stress). On a hardening
 * segment the flow stress is Y + H dp (Y: the segment's line at the start epsp, H its slope,
 * both times the rate factor); at the solution q = Y + H dp, so q (1 - c x) = Y, c = (2/3) H,
 * and x is the root of the square-root-free residual
 *     r(x) = (A fp^2 + B fm^2) (1 - c x)^2 - Y^2,  A = p0^2 / 4,  B = 3 m0^2 / 4 + 3 t0^2,
 *     fp = 1 / (1 + a x), fm = 1 / (1 + b x),
 * which is convex and decreasing (c >= 0), so Newton converges monotonically. The start is
 * the exact root when both rates are equal (one-rate model q0 / (1 + k x), k matched to the
 * slope of q at x = 0), which leaves an error of order ((a - b) x)^2: two Newton steps then
 * reach round-off. Newton stops when its step is below 1e-7 x (the error left is of the
 * order of the step squared). A crossed segment end restarts on the next segment. */
/* one Newton step on r(x) with a single division: with ua = 1 + a x, ub = 1 + b x,
 * D = ua ub, N = A ub^2 + B ua^2, g = 1 - c x:  r = (N g^2 - Y^2 D^2) / D^2 and
 * r' = -2 g ((a A ub^3 + b B ua^3) g + c N D) / D^3, so -r/r' is the ratio below.
 * *ok = 0 when r' is not negative (the Newton step is then 0). */
static inline double ps_newton(double a, double b, double A, double B, double Y, double c,
                               double x, int *ok)
{
    const double ua = 1 + a * x, ub = 1 + b * x, D = ua * ub, g = 1 - c * x;
    const double N = A * ub * ub + B * ua * ua, YD = Y * D;
    const double num = (N * g * g - YD * YD) * D;
    const double den = 2 * g * ((a * A * ub * ub * ub + b * B * ua * ua * ua) * g + c * N * D);
    *ok = den > 0;
    return *ok ? num / den : 0;
}

/* the returned stress and plastic strain increment at multiplier x: one division for both
 * 1/D and 1/(1 - c x) */
static inline double ps_finish(double a, double b, double Y, double c, double x, double sig[3])
{
    const double ua = 1 + a * x, ub = 1 + b * x, D = ua * ub, g = 1 - c * x;
    const double inv = 1 / (D * g), iD = g * inv;
    const double fp = ub * iD, fm = ua * iD;
    const double pp = (sig[0] + sig[1]) * fp, mm = (sig[0] - sig[1]) * fm;
    sig[0] = 0.5 * (pp + mm);
    sig[1] = 0.5 * (pp - mm);
    sig[2] *= fm;
    return 2.0 / 3.0 * x * Y * (D * inv);
}

double fe_ps_return(const fe_ps_const *k, double sig[3], double q0sq, double epsp, double rf)
{
    const double a = k->a, b = 2 * k->G;
    const double p0 = sig[0] + sig[1];
    const double A = 0.25 * p0 * p0, B = q0sq - A;
    double h;
    int seg;
    double Y = rf * fe_ps_flow(k, epsp, &h, &seg), c = 2.0 / 3.0 * rf * h;
    const double q0 = sqrt(q0sq);
    double x = (q0 - Y) * q0sq / (q0 * c * q0sq + Y * (a * A + b * B));
    if (!(x > 0)) x = 0;
    for (int it = 0; it < 60; it++) {
        int ok;
        double step = ps_newton(a, b, A, B, Y, c, x, &ok);
        if (x + step < 0) step = -0.5 * x;
        x += step;
        if (fabs(step) <= 1e-7 * x || !ok) {
            /* on the next segment when the plastic strain crossed this one's end */
            if (seg < k->nseg - 1) {
                double ep1 = k->p->material.hardening[seg + 1][0];
                if (epsp + 2.0 / 3.0 * x * Y / (1 - c * x) >= ep1) {
                    const double *hs = k->p->material.hardening[seg + 1];
                    seg++;
                    h = k->slope[seg];
                    Y = rf * (hs[1] + h * (epsp - hs[0]));
                    c = 2.0 / 3.0 * rf * h;
                    continue;
                }
            }
            break;
        }
    }
    return ps_finish(a, b, Y, c, x, sig);
}

void fe_ps_return_batch(const fe_ps_const *k, int n, double (*sig)[3], const double *q0sq,
                        const double *epsp, const double *rf, const fe_ps_flowpt *fl,
                        double *dp)
{
    /* the Newton iterations of fe_ps_return for all points together: independent chains that
     * the processor overlaps. A point whose plastic strain crosses its segment's end is redone
     * by fe_ps_return, which moves on to the next segment. */
    const double a = k->a, b = 2 * k->G;
    double x[FE_NIP_MAX], A[FE_NIP_MAX], B[FE_NIP_MAX], Y[FE_NIP_MAX], c[FE_NIP_MAX];
    int seg[FE_NIP_MAX], act[FE_NIP_MAX];
    for (int i = 0; i < n; i++) {
        const double p0 = sig[i][0] + sig[i][1];
        A[i] = 0.25 * p0 * p0, B[i] = q0sq[i] - A[i];
        Y[i] = rf[i] * fl[i].y;
        seg[i] = fl[i].seg;
        c[i] = 2.0 / 3.0 * rf[i] * fl[i].h;
        const double q0 = sqrt(q0sq[i]);
        x[i] = (q0 - Y[i]) * q0sq[i] / (q0 * c[i] * q0sq[i] + Y[i] * (a * A[i] + b * B[i]));
        if (!(x[i] > 0)) x[i] = 0;
        act[i] = 1;
    }
    for (int it = 0, left = n; it < 60 && left > 0; it++) {
        for (int i = 0; i < n; i++) {
            if (!act[i]) continue;
            int ok;
            double step = ps_newton(a, b, A[i], B[i], Y[i], c[i], x[i], &ok);
            if (x[i] + step < 0) step = -0.5 * x[i];
            x[i] += step;
            if (fabs(step) <= 1e-7 * x[i] || !ok) act[i] = 0, left--;
        }
    }
    for (int i = 0; i < n; i++) {
        /* crossed: epsp + (2/3) x Y / (1 - c x) >= the segment's end (1 - c x > 0) */
        if (seg[i] < k->nseg - 1 &&
            2.0 / 3.0 * x[i] * Y[i] >=
                (k->p->material.hardening[seg[i] + 1][0] - epsp[i]) * (1 - c[i] * x[i]))
            dp[i] = fe_ps_return(k, sig[i], q0sq[i], epsp[i], rf[i]);
        else
            dp[i] = ps_finish(a, b, Y[i], c[i], x[i], sig[i]);
    }
}

double fe_mat_plane_stress(const fe_part *p, double sig[3], const double de[3], double epsp,
                           double rate)
{
    fe_ps_const k;
    fe_ps_const_init(p, &k);
    return fe_ps_update(&k, sig, de, epsp, rate);
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

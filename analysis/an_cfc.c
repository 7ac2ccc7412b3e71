/* an_cfc.c: SAE J211-1 Appendix C CFC filters (forward-backward 2-pole Butterworth) */
#include "analysis/an_cfc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* J211-1 App. C design ratio: the 2-pole section is designed at fd = 2.0775·CFC, where
 * each pass is -3.01 dB, so the forward-backward pair is -6.02 dB there */
#define AN_CFC_RATIO 2.0775

mcs_status an_cfc_design(double cfc, double dt, an_cfc_coef *c, mcs_error *err)
{
    if (!(cfc > 0) || !(dt > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "CFC filter: class %g and step %g s must be positive",
                       cfc, dt);
    double fd = AN_CFC_RATIO * cfc;
    if (!(fd < 0.5 / dt))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "CFC %g: sample rate %g Hz is too low; the design frequency 2.0775*CFC "
                       "= %g Hz must be below half the sample rate (need > %g Hz)",
                       cfc, 1.0 / dt, fd, 2.0 * fd);
    /* pre-warped analogue corner, bilinear transform (J211-1 App. C, REFERENCES.md) */
    double wd = 2.0 * M_PI * fd;
    double wa = tan(wd * dt / 2.0);
    double d = 1.0 + M_SQRT2 * wa + wa * wa;
    c->a0 = wa * wa / d;
    c->a1 = 2.0 * c->a0;
    c->a2 = c->a0;
    c->b1 = -2.0 * (wa * wa - 1.0) / d;
    c->b2 = (-1.0 + M_SQRT2 * wa - wa * wa) / d;
    return MCS_OK;
}

double an_cfc_gain(double cfc, double dt, double f)
{
    /* one pass: |H|^2 = 1 / (1 + (tan(pi f dt) / wa)^4); forward-backward squares |H| */
    double wa = tan(M_PI * AN_CFC_RATIO * cfc * dt);
    double r = tan(M_PI * f * dt) / wa;
    double h2 = 1.0 / (1.0 + r * r * r * r);
    return h2;
}

/* one causal pass in place; the first two outputs start at the inputs (steady state of a
 * constant, since the DC gain is 1) */
static void cfc_pass(const an_cfc_coef *c, double *v, int m)
{
    if (m < 3) return;
    double x2 = v[0], x1 = v[1], y2 = v[0], y1 = v[1];
    for (int i = 2; i < m; i++) {
        double x = v[i];
        double y = c->a0 * x + c->a1 * x1 + c->a2 * x2 + c->b1 * y1 + c->b2 * y2;
        x2 = x1, x1 = x, y2 = y1, y1 = y;
        v[i] = y;
    }
}

static void reverse(double *v, int m)
{
    for (int i = 0, j = m - 1; i < j; i++, j--) {
        double t = v[i];
        v[i] = v[j];
        v[j] = t;
    }
}

mcs_status an_cfc_filter(const double *x, int n, double dt, double cfc, double *y,
                         mcs_error *err)
{
    an_cfc_coef c;
    mcs_status st = an_cfc_design(cfc, dt, &c, err);
    if (st) return st;
    if (n < 2) return MCS_ERR(err, MCS_ERR_RANGE, "CFC filter: %d samples, need 2", n);
    /* pad length: J211's 10 ms of lead-in, or 15 time constants 1/(zeta wd) of the section */
    double tau = 1.0 / (M_SQRT1_2 * 2.0 * M_PI * AN_CFC_RATIO * cfc);
    double tpad = fmax(0.010, 15.0 * tau);
    long p = (long)ceil(tpad / dt);
    if (p > n - 1) p = n - 1;
    int m = n + 2 * (int)p;
    double *v = malloc((size_t)m * sizeof(double));
    if (!v) return MCS_ERR(err, MCS_ERR_NOMEM, "CFC filter: out of memory (%d samples)", m);
    for (int k = 1; k <= p; k++) {
        v[p - k] = 2.0 * x[0] - x[k];
        v[p + n - 1 + k] = 2.0 * x[n - 1] - x[n - 1 - k];
    }
    memcpy(v + p, x, (size_t)n * sizeof(double));
    cfc_pass(&c, v, m);
    reverse(v, m);
    cfc_pass(&c, v, m);
    reverse(v, m);
    memcpy(y, v + p, (size_t)n * sizeof(double));
    free(v);
    return MCS_OK;
}

mcs_status an_butterworth_filter(const double *x, int n, double dt, double fc, double *y,
                                 mcs_error *err)
{
    return an_cfc_filter(x, n, dt, fc / AN_CFC_RATIO, y, err);
}

int an_signal_uniform(const an_signal *s, double rel, double *dt)
{
    if (s->n < 2) return 0;
    double h = (s->t[s->n - 1] - s->t[0]) / (s->n - 1);
    *dt = h;
    for (int i = 0; i < s->n; i++)
        if (!(fabs(s->t[i] - (s->t[0] + i * h)) <= rel * h)) return 0;
    return 1;
}

mcs_status an_cfc_signal(an_signal *s, int cfc, mcs_error *err)
{
    double dt;
    /* 1e-6 of a step: uniform times written as text with ~12 digits still pass */
    if (!an_signal_uniform(s, 1e-6, &dt))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "channel %s: CFC filtering needs uniform sampling (constant time step)",
                       s->name);
    mcs_status st = an_cfc_filter(s->y, s->n, dt, cfc, s->y, err);
    if (!st) s->cfc = cfc;
    return st;
}

int an_cfc_default(const char *kind)
{
    /* SAE J211-1 Table 1 as summarised in REFERENCES.md; chest, femur/tibia, vehicle and
     * pelvis classes are unverified there */
    static const struct {
        const char *kind;
        int cfc;
    } rows[] = {
        {"head_acceleration", 1000}, {"neck_force", 600},          {"neck_moment", 600},
        {"chest_acceleration", 180}, {"chest_deflection", 180},    {"femur", 600},
        {"tibia", 600},              {"pelvis_acceleration", 1000}, {"vehicle", 60},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++)
        if (strcasecmp(rows[i].kind, kind) == 0) return rows[i].cfc;
    return 0;
}

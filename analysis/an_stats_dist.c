/* an_stats_dist.c: the regularized incomplete beta function and the t and F tails (an_stats.h) */
#include "analysis/an_stats.h"

#include <math.h>

/* continued fraction of I_x(a,b) (DLMF 8.17.22), modified Lentz; converges for x < (a+1)/(a+b+2) */
static double beta_cf(double a, double b, double x)
{
    const double tiny = 1e-300, eps = 1e-16;
    double qab = a + b, qap = a + 1, qam = a - 1;
    double c = 1, d = 1 - qab * x / qap;
    if (fabs(d) < tiny) d = tiny;
    d = 1 / d;
    double h = d;
    for (int m = 1; m <= 10000; m++) {
        int m2 = 2 * m;
        double aa = m * (b - m) * x / ((qam + m2) * (a + m2)); /* even step d_2m */
        d = 1 + aa * d;
        if (fabs(d) < tiny) d = tiny;
        c = 1 + aa / c;
        if (fabs(c) < tiny) c = tiny;
        d = 1 / d;
        h *= d * c;
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2)); /* odd step d_2m+1 */
        d = 1 + aa * d;
        if (fabs(d) < tiny) d = tiny;
        c = 1 + aa / c;
        if (fabs(c) < tiny) c = tiny;
        d = 1 / d;
        double del = d * c;
        h *= del;
        if (fabs(del - 1) < eps) break;
    }
    return h;
}

/* Stirling's series of ln Gamma(x) beyond (x - 1/2) ln x - x + ln(2 pi)/2 (A&S 6.1.41) */
static double stirling_corr(double x)
{
    double x2 = x * x;
    return 1 / (12 * x) - 1 / (360 * x * x2) + 1 / (1260 * x * x2 * x2);
}

/* ln B(a, b); for a large beside b, ln Gamma(a+b) - ln Gamma(a) from Stirling's series in one
 * piece: the two lgamma values, each ~ a ln a, would cancel to a relative 1e-16 a ln a */
static double log_beta(double a, double b)
{
    if (a < b) {
        double t = a;
        a = b, b = t;
    }
    if (a < 1e3) return lgamma(a) + lgamma(b) - lgamma(a + b);
    double ratio = (a - 0.5) * log1p(b / a) + b * log(a + b) - b + stirling_corr(a + b) -
                   stirling_corr(a); /* ln Gamma(a+b) - ln Gamma(a) */
    return lgamma(b) - ratio;
}

double an_betainc(double a, double b, double x)
{
    if (!(a > 0) || !(b > 0) || !(x >= 0) || !(x <= 1)) return NAN;
    if (x == 0 || x == 1) return x;
    /* x^a (1-x)^b / B(a,b) */
    double lbt = a * log(x) + b * log1p(-x) - log_beta(a, b);
    if (x < (a + 1) / (a + b + 2)) return exp(lbt) * beta_cf(a, b, x) / a;
    return 1 - exp(lbt) * beta_cf(b, a, 1 - x) / b;
}

double an_t_p2(double t, double df)
{
    if (isnan(t) || !(df > 0)) return NAN;
    if (isinf(t)) return 0;
    return an_betainc(df / 2, 0.5, df / (df + t * t));
}

double an_f_sf(double f, double d1, double d2)
{
    if (isnan(f) || !(d1 > 0) || !(d2 > 0)) return NAN;
    if (f <= 0) return 1;
    if (isinf(f)) return 0;
    return an_betainc(d2 / 2, d1 / 2, d2 / (d2 + d1 * f));
}

/* an_peaks.c: resultants and peaks of channels */
#include "analysis/an_criteria.h"

#include <math.h>

void an_resultant(const double *x, const double *y, const double *z, int n, double *r)
{
    for (int i = 0; i < n; i++) r[i] = sqrt(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
}

double an_peak_abs(const double *y, int n, int *index)
{
    double m = 0;
    int k = 0;
    for (int i = 0; i < n; i++)
        if (fabs(y[i]) > m) m = fabs(y[i]), k = i;
    if (index) *index = k;
    return m;
}

/* J211 femur load cell: Fz < 0 is compression (the FMVSS 208 femur limit is on compression) */
double an_femur_compression(const double *fz, int n, int *index)
{
    double m = 0;
    int k = 0;
    for (int i = 0; i < n; i++)
        if (-fz[i] > m) m = -fz[i], k = i;
    if (index) *index = k;
    return m;
}

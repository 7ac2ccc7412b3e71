/* bench_hic.c: time of the exact HIC search (block-pruned all pairs) on a 0.3 s head pulse
 * (30 ms half-sine of 80 g plus ripple) at 10 kHz, 100 kHz and 1 MHz; prints figures only */
#include "analysis/an_criteria.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

int main(void)
{
    const double rates[] = {1e4, 1e5, 1e6};
    for (int k = 0; k < 3; k++) {
        double h = 1.0 / rates[k];
        int n = (int)(0.3 / h) + 1;
        double *t = malloc((size_t)n * sizeof(double)), *a = malloc((size_t)n * sizeof(double));
        if (!t || !a) return 1;
        for (int i = 0; i < n; i++) {
            t[i] = i * h;
            double s = t[i] - 0.05;
            a[i] = AN_G0 * ((s > 0 && s < 0.03) ? 80 * sin(M_PI * s / 0.03) : 0) +
                   AN_G0 * 3 * fabs(sin(2 * M_PI * 700 * t[i]));
        }
        for (int w = 0; w < 2; w++) {
            double W = w ? 0.036 : 0.015;
            an_hic_result r;
            mcs_error e = {0};
            struct timespec t0, t1;
            clock_gettime(CLOCK_MONOTONIC, &t0);
            an_hic(t, a, n, W, &r, &e);
            clock_gettime(CLOCK_MONOTONIC, &t1);
            printf("bench_hic: %7.0f Hz  n = %6d  HIC%.0f = %8.3f  [%.5f, %.5f] s  %.4f s\n",
                   rates[k], n, W * 1e3, r.hic, r.t1, r.t2,
                   (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec));
        }
        free(t), free(a);
    }
    return 0;
}

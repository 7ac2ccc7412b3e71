/* bench_rating.c: wall time of the ISO/TS 18571 and CORA ratings for signals of 0.1, 0.3 and
 * 1 s at 10 kHz (prints figures; never fails on time). The DTW and the phase search are both
 * O(N^2 / 5), the DTW back-pointers take N (0.2 N + 1) bytes. */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <time.h>

#include "analysis/an_cora.h"
#include "analysis/an_iso18571.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(void)
{
    const int sizes[] = {1001, 3001, 10001};
    printf("%8s %10s %10s %10s %8s\n", "samples", "iso [s]", "cora [s]", "dtw [MB]", "R_iso");
    for (int k = 0; k < 3; k++) {
        int n = sizes[k];
        double *r = malloc((size_t)n * sizeof(double)), *c = malloc((size_t)n * sizeof(double));
        if (!r || !c) return 1;
        /* a damped pulse and a late, larger, slightly noisy copy */
        for (int i = 0; i < n; i++) {
            double t = (double)i / (n - 1);
            r[i] = sin(3.14159265 * t) * exp(-2 * t);
            c[i] = 1.1 * sin(3.14159265 * (t - 0.02)) * exp(-2 * t) + 0.01 * sin(40 * t);
        }
        an_iso_result ri;
        an_cora_result rc;
        mcs_error err = {0};
        double t0 = now();
        if (an_iso18571_arrays(r, c, n, 1e-4, NULL, &ri, &err)) return 1;
        double t1 = now();
        if (an_cora_arrays(r, c, n, 0.0, 1e-4, NULL, &rc, &err)) return 1;
        double t2 = now();
        double mb = (double)(n - abs(ri.shift)) * (2 * floor(0.1 * (n - abs(ri.shift))) + 1) / 1e6;
        printf("%8d %10.4f %10.4f %10.1f %8.4f\n", n, t1 - t0, t2 - t1, mb, ri.rating);
        free(r);
        free(c);
    }
    return 0;
}

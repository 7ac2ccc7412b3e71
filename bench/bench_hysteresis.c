/* bench_hysteresis: cost of a curve lookup and of a hysteresis force evaluation / update, the
 * calls a time loop makes per contact per step. Prints figures; never fails on time. */
#include "core/mcs_hysteresis.h"

#include <math.h>
#include <stdio.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(void)
{
    enum { NPT = 32, N = 2000000 };
    double xy[NPT][2];
    for (int i = 0; i < NPT; i++) {
        xy[i][0] = 0.002 * i;
        xy[i][1] = 1e5 * xy[i][0] + 2e6 * xy[i][0] * xy[i][0];
    }
    mcs_error e;
    mcs_error_clear(&e);
    mcs_curve *L = NULL;
    if (mcs_curve_create_xy("bench", NPT, xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR, &L, &e)) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    mcs_hyst_model m = {
        .loading = L, .unload = MCS_UNLOAD_SLOPE, .unload_slope = 5e5, .elastic_limit = 0.002};
    mcs_hyst_state s;
    mcs_hyst_reset(&m, &s);
    volatile double sink = 0;
    /* a slow oscillation growing into the element, as a contact sees it step by step */
    double t0 = now();
    for (int i = 0; i < N; i++)
        sink += mcs_curve_eval(L, 0.03 * (1 - cos(1e-5 * i)));
    double t1 = now();
    int hint = -1;
    for (int i = 0; i < N; i++)
        sink += mcs_curve_eval_hint(L, 0.03 * (1 - cos(1e-5 * i)), &hint);
    double t2 = now();
    for (int i = 0; i < N; i++)
        sink += mcs_hyst_force(&m, &s, 0.03 * (1 - cos(1e-5 * i)) * (1 + 1e-6 * i));
    double t3 = now();
    for (int i = 0; i < N; i++)
        sink += mcs_hyst_update(&m, &s, 0.03 * (1 - cos(1e-5 * i)) * (1 + 1e-6 * i));
    double t4 = now();
    printf("bench_hysteresis (%d-point curve, %d calls each):\n", NPT, N);
    printf("  curve eval (bisection)   %6.1f ns/call\n", 1e9 * (t1 - t0) / N);
    printf("  curve eval (hinted)      %6.1f ns/call\n", 1e9 * (t2 - t1) / N);
    printf("  hysteresis force         %6.1f ns/call\n", 1e9 * (t3 - t2) / N);
    printf("  hysteresis update        %6.1f ns/call (with exact work integral)\n",
           1e9 * (t4 - t3) / N);
    printf("  final work %.6g J, dissipated %.6g J\n", s.work, mcs_hyst_dissipated(&m, &s));
    mcs_curve_destroy(&L);
    return sink == 12345.0; /* keep the loops */
}

/* bench_motion.c: stage-1 trajectories -> prescribed motion (translators/tr_motion.h) on the
 * shipped 413-0/13.4 rider case: the motorcycle frame and the car over 300 ms, pose against
 * pulse (largest position, angle and velocity difference on a grid of 4 points per output
 * interval), the pulse's drift from the written samples, both methods against the run's own
 * pose half-way between the 10 kHz samples (the same run written at 20 kHz), and the cost:
 * opening (read + the pulse integral) and ns per evaluation. Prints figures only. */
#include "core/mcs_scenario.h"
#include "stage1_mb/mb_model.h"
#include "translators/tr_motion.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define S413 "scenarios/iso13232_413-0_13.4_sedan_rider.yaml"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double dist3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* the 413 rider case at output rate `rate` into out; 0 on success */
static int run_413(const char *rate, const char *out)
{
    static char txt[65536], mod[65600];
    FILE *f = fopen(S413, "rb");
    if (!f) return fprintf(stderr, "bench_motion: %s not found\n", S413), 1;
    size_t n = fread(txt, 1, sizeof txt - 1, f);
    fclose(f);
    txt[n] = 0;
    char *p = strstr(txt, "output_rate: 10 kHz");
    if (!p) return fprintf(stderr, "bench_motion: no output_rate in %s\n", S413), 1;
    snprintf(mod, sizeof mod, "%.*soutput_rate: %s%s", (int)(p - txt), txt, rate,
             p + strlen("output_rate: 10 kHz"));
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mb_model *m = NULL;
    mcs_status st = mcs_scenario_load_text(S413, mod, strlen(mod), &scn, &err);
    if (!st) st = mb_model_build(scn, NULL, &m, &err);
    mcs_scenario_destroy(&scn);
    mb_run_opts o = {.out_path = out, .quiet = 1};
    if (!st) st = mb_run(m, &o, NULL, &err);
    mb_model_destroy(&m);
    if (st) fprintf(stderr, "bench_motion: %s\n", err.msg);
    return st != MCS_OK;
}

int main(void)
{
    char dir[64] = "/tmp/mcs_bench_motion_XXXXXX", out[128], fine[128];
    if (!mkdtemp(dir)) return perror("mkdtemp"), 1;
    snprintf(out, sizeof out, "%s/s413.h5", dir);
    snprintf(fine, sizeof fine, "%s/s413f.h5", dir);
    if (run_413("10 kHz", out) || run_413("20 kHz", fine)) return 1;
    const char *names[] = {"moto_frame", "sedan"};
    tr_motion *mo[2] = {NULL, NULL}, *tf = NULL;
    mcs_error err = {0};
    double t_open[2];
    for (int k = 0; k < 2; k++) {
        double t0 = now();
        if (tr_motion_open(&mo[k], out, names, 2, (tr_motion_method)k, &err))
            return fprintf(stderr, "bench_motion: %s\n", err.msg), 1;
        t_open[k] = now() - t0;
    }
    if (tr_motion_open(&tf, fine, names, 2, TR_MOTION_POSE, &err))
        return fprintf(stderr, "bench_motion: %s\n", err.msg), 1;
    double t0, t1;
    int nt, ntf;
    tr_motion_span(mo[0], &t0, &t1, &nt);
    tr_motion_span(tf, NULL, NULL, &ntf);
    printf("bench_motion: 413-0/13.4 rider, %d samples (10 kHz), 0-%.0f ms\n", nt, t1 * 1e3);
    for (int b = 0; b < 2; b++) {
        double dp = 0, da = 0, dv = 0, ep[2] = {0}, ea[2] = {0};
        for (int i = 0; i < 4 * (nt - 1); i++) {
            double t = t0 + (t1 - t0) * i / (4.0 * (nt - 1));
            tr_motion_kin a, c;
            if (tr_motion_eval(mo[0], b, t, &a, &err) || tr_motion_eval(mo[1], b, t, &c, &err))
                return fprintf(stderr, "bench_motion: %s\n", err.msg), 1;
            dp = fmax(dp, dist3(a.pos, c.pos));
            da = fmax(da, tr_quat_angle(a.quat, c.quat));
            dv = fmax(dv, dist3(a.vel, c.vel));
        }
        for (int i = 1; i < ntf; i += 2) {
            tr_motion_kin r, k;
            double t = tr_motion_time(tf, i);
            tr_motion_eval(tf, b, t, &r, &err);
            for (int j = 0; j < 2; j++) {
                tr_motion_eval(mo[j], b, t, &k, &err);
                ep[j] = fmax(ep[j], dist3(k.pos, r.pos));
                ea[j] = fmax(ea[j], tr_quat_angle(k.quat, r.quat));
            }
        }
        tr_motion_drift d = tr_motion_get_drift(mo[1], b);
        printf("bench_motion: %-10s pose - pulse: %.3g mm  %.3g deg  %.3g m/s\n", names[b],
               dp * 1e3, da * 180 / M_PI, dv);
        printf("bench_motion: %-10s pulse drift at the samples: %.3g mm (%.1f ms)  %.3g deg "
               "(%.1f ms)  %.3g m/s\n",
               names[b], d.pos * 1e3, d.t_pos * 1e3, d.angle * 180 / M_PI, d.t_angle * 1e3, d.vel);
        printf("bench_motion: %-10s half-way between samples vs the 20 kHz run: pose %.3g mm "
               "%.3g deg, pulse %.3g mm %.3g deg\n",
               names[b], ep[0] * 1e3, ea[0] * 180 / M_PI, ep[1] * 1e3, ea[1] * 180 / M_PI);
    }
    /* cost: 1e6 evaluations spread over the span, per method */
    for (int k = 0; k < 2; k++) {
        const int n = 1000000;
        volatile double sink = 0;
        double c0 = now();
        for (int i = 0; i < n; i++) {
            tr_motion_kin a;
            tr_motion_eval(mo[k], i & 1, t0 + (t1 - t0) * (double)(i % 9973) / 9973, &a, &err);
            sink = a.pos[0];
        }
        double c = now() - c0;
        (void)sink;
        printf("bench_motion: %-5s open %.2f ms (2 bodies), %.0f ns per evaluation\n",
               tr_motion_method_name((tr_motion_method)k), t_open[k] * 1e3, c / n * 1e9);
    }
    tr_motion_destroy(&mo[0]), tr_motion_destroy(&mo[1]), tr_motion_destroy(&tf);
    unlink(out), unlink(fine), rmdir(dir);
    return 0;
}

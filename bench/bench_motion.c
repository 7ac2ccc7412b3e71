/* bench_motion.c: stage-1 trajectories -> prescribed motion (translators/tr_motion.h) on the
 * shipped 413-0/13.4 rider case, every body of the file (the motorcycle, the car, the rider):
 * replay accuracy of both methods (largest position and angle error at the file's 10 kHz
 * samples, and on a 60 us stage-2 step against the run's own poses: the same run written at
 * 50 kHz), pose against pulse, and the cost: opening (read + the pulse integral) and ns per
 * query (one body at one time), in CPU time. Prints figures only (tests/test_tr_motion.c
 * asserts the accuracy). */
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

/* this thread's CPU time [s]: the cost on a shared machine, not its wall time */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
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
    if (run_413("10 kHz", out) || run_413("50 kHz", fine)) return 1;
    tr_motion *mo[2] = {NULL, NULL}, *tf = NULL;
    mcs_error err = {0};
    double t_open[2];
    for (int k = 0; k < 2; k++) {
        double t0 = now();
        if (tr_motion_open(&mo[k], out, NULL, 0, (tr_motion_method)k, &err))
            return fprintf(stderr, "bench_motion: %s\n", err.msg), 1;
        t_open[k] = now() - t0;
    }
    if (tr_motion_open(&tf, fine, NULL, 0, TR_MOTION_POSE, &err))
        return fprintf(stderr, "bench_motion: %s\n", err.msg), 1;
    double t0, t1;
    int nt, nb = tr_motion_nbody(mo[0]);
    tr_motion_span(mo[0], &t0, &t1, &nt);
    const double deg = 180 / M_PI, h2 = 60e-6;
    printf("bench_motion: 413-0/13.4 rider, %d bodies, %d samples (10 kHz), 0-%.0f ms\n", nb, nt,
           t1 * 1e3);
    /* accuracy: largest over every body; the 50 kHz file's sample 3 i is at t0 + i h2 */
    double sp[2] = {0}, sq[2] = {0}, gp[2] = {0}, gq[2] = {0}, dp = 0, dq = 0;
    for (int b = 0; b < nb; b++) {
        int bf = tr_motion_body(tf, tr_motion_body_name(mo[0], b));
        if (bf < 0) return fprintf(stderr, "bench_motion: bodies differ\n"), 1;
        tr_motion_kin k[2], r;
        for (int i = 0; i < nt; i++) {
            tr_motion_eval(tf, bf, tr_motion_time(tf, 5 * i), &r, &err);
            for (int j = 0; j < 2; j++) {
                tr_motion_eval(mo[j], b, tr_motion_time(mo[j], i), &k[j], &err);
                sp[j] = fmax(sp[j], dist3(k[j].pos, r.pos));
                sq[j] = fmax(sq[j], tr_quat_angle(k[j].quat, r.quat));
            }
        }
        for (int i = 0; i * h2 <= t1 - t0 + 1e-12; i++) {
            double t = tr_motion_time(tf, 3 * i);
            tr_motion_eval(tf, bf, t, &r, &err);
            for (int j = 0; j < 2; j++) {
                tr_motion_eval(mo[j], b, t, &k[j], &err);
                gp[j] = fmax(gp[j], dist3(k[j].pos, r.pos));
                gq[j] = fmax(gq[j], tr_quat_angle(k[j].quat, r.quat));
            }
            dp = fmax(dp, dist3(k[0].pos, k[1].pos));
            dq = fmax(dq, tr_quat_angle(k[0].quat, k[1].quat));
        }
    }
    for (int j = 0; j < 2; j++)
        printf("bench_motion: %-5s replay: at the samples %.3g mm %.3g deg; stage-2 step 60 us "
               "%.3g mm %.3g deg (limits 1 mm, 0.1 deg)\n",
               tr_motion_method_name((tr_motion_method)j), sp[j] * 1e3, sq[j] * deg,
               gp[j] * 1e3, gq[j] * deg);
    printf("bench_motion: pose - pulse: %.3g mm %.3g deg\n", dp * 1e3, dq * deg);
    /* cost, per method: as a stage-2 loop queries, every body at each step over the span
     * (about 1e6 queries: steps of 9 us), and the same number at random times and bodies */
    for (int k = 0; k < 2; k++) {
        int nstep = 1000000 / nb;
        volatile double sink = 0;
        double c0 = now();
        for (int i = 0; i < nstep; i++)
            for (int b = 0; b < nb; b++) {
                tr_motion_kin a;
                tr_motion_eval(mo[k], b, t0 + (t1 - t0) * i / (nstep - 1), &a, &err);
                sink = a.pos[0];
            }
        double c = now() - c0;
        unsigned r = 12345;
        double c1 = now();
        for (int i = 0; i < nstep * nb; i++) {
            tr_motion_kin a;
            r = r * 1103515245u + 12345u;
            tr_motion_eval(mo[k], (int)(r >> 8) % nb, t0 + (t1 - t0) * (r >> 16) / 65536.0, &a,
                           &err);
            sink = a.pos[0];
        }
        double cr = now() - c1;
        (void)sink;
        printf("bench_motion: %-5s open %.1f ms (%d bodies); %.0f ns per query in step order, "
               "%.0f ns at random times and bodies\n",
               tr_motion_method_name((tr_motion_method)k), t_open[k] * 1e3, nb,
               c / (nstep * nb) * 1e9, cr / (nstep * nb) * 1e9);
    }
    tr_motion_destroy(&mo[0]), tr_motion_destroy(&mo[1]), tr_motion_destroy(&tf);
    unlink(out), unlink(fine), rmdir(dir);
    return 0;
}

/* bench_retune: wall time of `mcrash retune`'s fit (translators/tr_retune.h) with one and with
 * two stage-1 runs at a time (-j 1, -j 2; docs/retune.md "Parallel runs"). The case is the
 * identifiability case of make test (tests/test_retune.c): the thesis barrier scenario's first
 * 150 ms, its target made by stage 1 with the tyre forces x 0.8 and the fork moments x 1.3,
 * the two scales free. Prints the runs, the wall time and the speed-up; checks that both give
 * the same parameters to the bit (the fit does not depend on -j). Never fails on time. */
#include "translators/tr_pool.h"
#include "translators/tr_retune.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#define SCN "scenarios/thesis_frontal_barrier_13.4.yaml"

/* CPU time of the reaped children (the stage-1 runs) [s] */
static double child_cpu(void)
{
    struct rusage u;
    getrusage(RUSAGE_CHILDREN, &u);
    return (double)u.ru_utime.tv_sec + 1e-6 * (double)u.ru_utime.tv_usec +
           (double)u.ru_stime.tv_sec + 1e-6 * (double)u.ru_stime.tv_usec;
}

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(void)
{
    tr_rt_opts o = tr_rt_opts_default();
    o.scenario = SCN;
    o.free_mask = 0x3;
    tr_rt_base b;
    mcs_error err = {0};
    if (tr_rt_read_base(&o, &b, &err)) {
        printf("bench_retune: %s\n", err.msg);
        return 1;
    }
    /* the target: stage 1 at known parameters, unfiltered (the fit filters it) */
    const int nt = 1501;
    tr_rt_target t = {.nt = nt};
    t.t = malloc(nt * sizeof(double));
    t.force = malloc(nt * sizeof(double));
    t.angle = malloc(nt * sizeof(double));
    tr_rt_opts ot = o;
    ot.cfc = 0;
    double pt[TR_RT_NPAR] = {0.8, 1.3, b.phi_e, b.phi_s, 1, b.k_stop};
    for (int i = 0; i < nt; i++)
        t.t[i] = i * o.dt;
    if (tr_rt_stage1(&ot, &b, pt, nt, o.dt, t.force, t.angle, &err)) {
        printf("bench_retune: %s\n", err.msg);
        return 1;
    }
    double p1[TR_RT_NPAR] = {0}, w1 = 0;
    int bad = 0;
    for (int jobs = 1; jobs <= 2; jobs++) {
        tr_rt_result r;
        o.jobs = jobs;
        double w0 = wall_now(), c0 = child_cpu();
        if (tr_rt_fit(&o, &b, &t, &r, &err)) {
            printf("bench_retune: %s\n", err.msg);
            return 1;
        }
        double w = wall_now() - w0, cpu = child_cpu() - c0;
        tr_rt_result_free(&r);
        if (jobs == 1) w1 = w, memcpy(p1, r.p, sizeof p1);
        bad |= jobs > 1 && memcmp(p1, r.p, sizeof p1) != 0;
        printf("bench_retune: thesis barrier 150 ms, 2 free, -j %d: %d stage-1 runs, wall %.2f s "
               "(speed-up %.2f), CPU %.2f s (%.3f s a run); p = %.6f %.6f, ISO force %.3f (%d CPUs "
               "online; on a loaded machine the wall time is the share it got)\n",
               jobs, r.nfev, w, w1 / w, cpu, cpu / r.nfev, r.p[0], r.p[1], r.iso_force,
               tr_pool_cpus());
    }
    if (bad) printf("bench_retune: -j 2 gave other parameters than -j 1\n");
    tr_rt_target_free(&t);
    return bad;
}

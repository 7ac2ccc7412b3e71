/* bench_fe_contact: cost per shell element-cycle of the whole fe_step on the tube
 * crush with single-surface self contact (6400 Belytschko-Tsay shells, 50 mm x 1.5 mm x
 * 200 mm, 2.5 mm elements, rigid wall at 10 m/s; OpenRadioss takes about 480 ns on this
 * problem). The run goes through the first folds (where the contact works), in chunks, so
 * the cost is seen as the folds form. Also prints the stable step with and without the
 * contact (the contact stiffness is capped so that it never sets the step) and the memory
 * per element. Prints figures; never fails on time. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "fe/fe_contact.h"
#include "fe/fe_model.h"
#include "fe/fe_state.h"
#include "bench/bench_fe_util.h"

static fe_builder *tube(int contact)
{
    mcs_error err = {0};
    fe_builder *b;
    if (fe_builder_create(&b, &err) != MCS_OK) return NULL;
    fe_part_desc t = fe_part_desc_default();
    bf_tube_part(&t);
    t.material.model = FE_MAT_ELASTIC_PLASTIC;
    t.material.density = 7850, t.material.youngs_modulus = 210e9, t.material.poisson = 0.3;
    t.material.nhardening = 3;
    t.material.hardening[0][0] = 0, t.material.hardening[0][1] = 250e6;
    t.material.hardening[1][0] = 0.05, t.material.hardening[1][1] = 300e6;
    t.material.hardening[2][0] = 1, t.material.hardening[2][1] = 400e6;
    bf_tube_crush(b, &t, &err);
    if (contact) {
        fe_contact_desc c = fe_contact_desc_default();
        c.type = FE_CONTACT_SINGLE_SURFACE;
        c.nslave = 1;
        snprintf(c.slave[0], FE_NAME_MAX, "tube");
        c.friction = 0.2;
        fe_builder_add_contact(b, &c, &err);
    }
    if (err.status) fprintf(stderr, "bench_fe_contact: %s\n", err.msg);
    return b;
}

/* the same run (the first folds, 5 x 1000 steps) on 1 and on 2 threads: wall clock per shell
 * element-cycle and the speed-up (the results are the same to the bit, tests/test_fe_parallel.c).
 * On a shared machine run it at real-time priority (chrt -f 50) so both threads get a core. */
static void two_threads(const fe_model *m, int steps)
{
    double wall[2] = {0, 0};
    for (int th = 1; th <= 2; th++) {
        mcs_error err = {0};
        fe_state *s = NULL;
        fe_set_threads(th);
        if (fe_state_create(m, &s, &err) != MCS_OK) return;
        double t0 = bf_now(CLOCK_MONOTONIC);
        for (int i = 0; i < steps && s->err.status == MCS_OK; i++) fe_step(m, s);
        wall[th - 1] = bf_now(CLOCK_MONOTONIC) - t0;
        fe_state_destroy(&s);
    }
    const double ec = (double)steps * m->nelem;
    printf("    threads, %d steps: 1 thread %.1f ns, 2 threads %.1f ns per shell element-cycle "
           "(wall), speed-up %.2fx\n", steps, 1e9 * wall[0] / ec, 1e9 * wall[1] / ec,
           wall[0] / wall[1]);
}

int main(void)
{
    mcs_error err = {0};
    fe_builder *b0 = tube(0), *b1 = tube(1);
    fe_model *m0 = NULL, *m = NULL;
    fe_state *s = NULL;
    /* the whole-run figure is one core's (CPU time of this thread), so run it on one thread */
    fe_set_threads(1);
    if (!b0 || !b1 || fe_model_create(b0, NULL, &m0, &err) != MCS_OK ||
        fe_model_create(b1, NULL, &m, &err) != MCS_OK || fe_state_create(m, &s, &err) != MCS_OK) {
        fprintf(stderr, "bench_fe_contact: %s\n", err.msg);
        return 1;
    }
    printf("tube crush, single-surface contact: %d shells, %d contact nodes, %d segments, "
           "search margin %.3g mm\n",
           m->nshell, m->contact->nent, m->contact->nseg, 1e3 * m->contact->margin);
    printf("    stable step: %.4g s with contact, %.4g s without (same elements)\n",
           m->dt_initial, m0->dt_initial);
    const int chunk = 1000, nchunk = 5;
    double cpu_all = 0, timer0[FE_NSTAGE];
    long cyc = 0;
    for (int k = 0; k < nchunk && s->err.status == MCS_OK; k++) {
        memcpy(timer0, s->timer, sizeof timer0);
        double c0 = bf_now(CLOCK_THREAD_CPUTIME_ID);
        int i = 0;
        for (; i < chunk && s->err.status == MCS_OK; i++) fe_step(m, s);
        double cpu = bf_now(CLOCK_THREAD_CPUTIME_ID) - c0;
        cpu_all += cpu;
        cyc += i;
        double dsum = 0, dcon = s->timer[FE_STAGE_contact] - timer0[FE_STAGE_contact];
        for (int j = 0; j < FE_NSTAGE; j++) dsum += s->timer[j] - timer0[j];
        double ns = 1e9 * cpu / ((double)i * m->nelem), share = dsum > 0 ? dcon / dsum : 0;
        printf("    t %.3g ms (crush %.3g mm): %6.1f ns/element-cycle CPU, of which contact %.1f "
               "(%.0f %%), contact energy %.3g J, %ld searches\n",
               1e3 * s->time, 1e4 * s->time, ns, ns * share, 100 * share,
               s->energy[FE_E_contact], s->contact->nrebuild);
    }
    printf("    whole run: %.1f ns per shell element-cycle CPU (target 250, OpenRadioss ~480), "
           "dt now %.3g s, %.0f B/element (model %.0f + state %.0f; of which contact %.0f + "
           "%.0f)%s%s\n",
           1e9 * cpu_all / ((double)cyc * m->nelem), s->dt,
           (double)(m->bytes + s->bytes) / m->nelem, (double)m->bytes / m->nelem,
           (double)s->bytes / m->nelem, (double)m->contact->bytes / m->nelem,
           (double)s->contact->bytes / m->nelem, s->err.status ? "  STOPPED: " : "",
           s->err.status ? s->err.msg : "");
    fe_state_destroy(&s);
    two_threads(m, chunk * nchunk);
    fe_model_destroy(&m);
    fe_model_destroy(&m0);
    fe_builder_destroy(&b0);
    fe_builder_destroy(&b1);
    return 0;
}

/* bench_fe: cost of the explicit FE kernel per element-cycle, shell (elastic and yielding) and
 * hex paths, on 1 and 2 threads (the whole fe_step: internal forces, walls, integration,
 * energies), the speed-up, the stable step and the memory per element. Prints figures; never
 * fails on time. The machine is shared: compare runs made when `uptime` shows a low load. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fe/fe_contact.h"
#include "fe/fe_model.h"
#include "fe/fe_state.h"
#include "bench/bench_fe_util.h"

static fe_part_desc steel(const char *name, fe_section_type type)
{
    fe_part_desc d = fe_part_desc_default();
    snprintf(d.name, sizeof d.name, "%s", name);
    d.section.type = type;
    d.material.model = FE_MAT_ELASTIC_PLASTIC;
    d.material.density = 7850;
    d.material.youngs_modulus = 210e9;
    d.material.poisson = 0.3;
    d.material.nhardening = 2;
    d.material.hardening[0][0] = 0, d.material.hardening[0][1] = 250e6;
    d.material.hardening[1][0] = 1, d.material.hardening[1][1] = 750e6;
    return d;
}

/* one timed run of `cycles` steps after 5 warm-up steps, on `threads` threads */
typedef struct {
    double wall, cpu;       /* wall and process CPU time of the timed cycles [s] */
    double timer[FE_NSTAGE];
    double dt, t, eerr;     /* last step, time reached, energy error [s, s, -] */
    int ok;
} timing;

static timing timed_run(const fe_model *m, int threads, int cycles)
{
    timing r = {0};
    mcs_error err = {0};
    fe_state *s = NULL;
    fe_set_threads(threads);
    if (fe_state_create(m, &s, &err) != MCS_OK) return r;
    for (int i = 0; i < 5; i++) fe_step(m, s); /* warm-up (and thread start-up) */
    memset(s->timer, 0, sizeof s->timer);
    double t0 = bf_now(CLOCK_MONOTONIC), c0 = bf_now(CLOCK_PROCESS_CPUTIME_ID);
    for (int i = 0; i < cycles && s->err.status == MCS_OK; i++) fe_step(m, s);
    r.wall = bf_now(CLOCK_MONOTONIC) - t0;
    r.cpu = bf_now(CLOCK_PROCESS_CPUTIME_ID) - c0;
    memcpy(r.timer, s->timer, sizeof r.timer);
    r.dt = s->dt, r.t = s->time;
    r.eerr = s->energy_ref > 0 ? (s->energy[FE_E_total] - s->energy0) / s->energy_ref : 0;
    r.ok = s->err.status == MCS_OK;
    if (!r.ok) fprintf(stderr, "bench_fe: stopped: %s\n", s->err.msg);
    fe_state_destroy(&s);
    return r;
}

/* the path on 1 and 2 threads: ns per element-cycle (wall clock, the whole fe_step), the
 * speed-up, the stable step and the memory per element (model + state) */
static int run(const char *label, fe_builder *b, int cycles)
{
    mcs_error err = {0};
    fe_model *m = NULL;
    if (fe_model_create(b, NULL, &m, &err) != MCS_OK) {
        fprintf(stderr, "bench_fe: %s: %s\n", label, err.msg);
        return 1;
    }
    fe_state *s = NULL;
    if (fe_state_create(m, &s, &err) != MCS_OK) {
        fprintf(stderr, "bench_fe: %s: %s\n", label, err.msg);
        fe_model_destroy(&m);
        return 1;
    }
    /* everything the run allocates: model and state arrays, the state's scratch arena, and the
     * contact model and state (segments, neighbour lists, bucket grid, boxes, candidate pool,
     * per-step slots, friction history) */
    double bytes = (double)(m->bytes + s->bytes) / m->nelem;
    double ms = (double)m->bytes / m->nelem, ss = (double)s->bytes / m->nelem;
    double mc = m->contact ? (double)m->contact->bytes / m->nelem : 0;
    double sc = s->contact ? (double)s->contact->bytes / m->nelem : 0;
    fe_state_destroy(&s);
    const double ec = (double)cycles * m->nelem;
    /* BENCH_FE_ONE_THREAD=1 skips the 2-thread run (for profiling: perf stat, perf record) */
    const char *one = getenv("BENCH_FE_ONE_THREAD");
    timing t1 = timed_run(m, 1, cycles), t2 = t1;
    if (!(one && *one == '1')) t2 = timed_run(m, 2, cycles);
    printf("%-34s %5d %8.3g  %6.1f  %6.1f   %5.2fx  %5.0f (model %.0f + state %.0f)\n", label,
           m->nelem, t1.dt, 1e9 * t1.wall / ec, 1e9 * t2.wall / ec, t1.wall / t2.wall, bytes, ms,
           ss);
    if (mc > 0) printf("    of which contact: model %.0f + state %.0f B/element\n", mc, sc);
    printf("    1 thread by sub-stage [ns/element-cycle]:");
    for (int k = 0; k < FE_NSTAGE; k++) printf(" %s %.1f", fe_stage_name[k], 1e9 * t1.timer[k] / ec);
    if (!(one && *one == '1')) {
        printf("\n    2 threads by sub-stage [ns/element-cycle]:");
        for (int k = 0; k < FE_NSTAGE; k++)
            printf(" %s %.1f", fe_stage_name[k], 1e9 * t2.timer[k] / ec);
    }
    printf("\n    1 thread CPU %.1f ns/element-cycle; %d cycles to t = %.3g ms, energy error %.2e\n",
           1e9 * t1.cpu / ec, cycles, 1e3 * t1.t, t1.eerr);
    fe_model_destroy(&m);
    return !(t1.ok && t2.ok);
}

int main(void)
{
    mcs_error err = {0};
    int rc = 0;
    printf("bench_fe: explicit FE kernel, whole fe_step per element-cycle (wall clock; OpenMP "
           "threads: %d available)\n", fe_threads());
    printf("reference: OpenRadioss ~480 ns per shell element-cycle (6400-shell square tube, "
           "self contact, one core; issue 5); target <= 250 ns, >= 1.7x on 2 threads, <= 1 KB/element\n");
    printf("%-34s %5s %8s  %6s  %6s  %7s  %s\n", "path", "elems", "dt [s]", "1 thr", "2 thr",
           "speedup", "B/element");
    /* shell path: the 6400-shell square tube (50 mm side, 200 mm, 2.5 mm elements,
     * 1.5 mm wall, 5 points) crushed by a rigid wall at 10 m/s; no self-contact yet */
    fe_builder *b;
    fe_builder_create(&b, &err);
    fe_part_desc t = steel("tube", FE_SECTION_SHELL);
    bf_tube_part(&t);
    bf_tube_crush(b, &t, &err);
    rc |= run("BT shell, yielding (J2), 5 pts", b, 400);
    /* the same tube with single-surface (self) contact on it: the comparison case */
    fe_contact_desc cd = fe_contact_desc_default();
    snprintf(cd.name, sizeof cd.name, "self");
    cd.type = FE_CONTACT_SINGLE_SURFACE;
    cd.nslave = 1;
    snprintf(cd.slave[0], sizeof cd.slave[0], "tube");
    fe_builder_add_contact(b, &cd, &err);
    rc |= run("BT shell, J2, + self contact", b, 400);
    fe_builder_destroy(&b);
    fe_builder_create(&b, &err);
    t.material.model = FE_MAT_ELASTIC;
    bf_tube_crush(b, &t, &err);
    rc |= run("BT shell, elastic, 5 pts", b, 400);
    fe_builder_destroy(&b);

    /* hex path: 20 x 20 x 10 block (4000 hexes) of J2 steel at 20 m/s onto its clamped base */
    fe_builder_create(&b, &err);
    fe_part_desc h = steel("block", FE_SECTION_SOLID);
    h.mesh.generate = FE_MESH_BOX;
    h.mesh.size[0] = h.mesh.size[1] = 0.1, h.mesh.size[2] = 0.05;
    h.mesh.divisions[0] = h.mesh.divisions[1] = 20, h.mesh.divisions[2] = 10;
    h.initial_velocity[2] = -20;
    fe_builder_add_part(b, &h, NULL, &err);
    bf_clamp_base(b, "block", &err);
    rc |= run("hex8 1 pt + FB hourglass, J2", b, 400);
    fe_builder_destroy(&b);
    return rc;
}

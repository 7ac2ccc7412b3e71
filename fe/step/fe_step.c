/* fe_step: one explicit central-difference step, t_n -> t_{n+1} (STYLE.md §2). */
#include "fe/fe_state.h"

#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#define TIMED(stage, call)                                                                         \
    do {                                                                                           \
        double t0_ = now();                                                                        \
        call;                                                                                      \
        s->timer[FE_STAGE_##stage] += now() - t0_;                                                 \
    } while (0)

mcs_status fe_step(const fe_model *m, fe_state *s)
{
    if (s->err.status != MCS_OK) return s->err.status; /* a stopped run stays stopped */
    mcs_status st = MCS_OK;
    /* x, v(t - dt/2), stresses -> stresses(t), element forces, node_fint/mint, element steps */
    TIMED(internal, fe_internal_forces(m, s));
    /* x, t -> node_fext := penalty rigid-wall forces */
    TIMED(contact, fe_contact_forces(m, s));
    /* t, load curves -> node_fext += nodal loads */
    TIMED(external, fe_external_forces(m, s));
    if (s->err.status != MCS_OK) return s->err.status; /* a gas bag or retractor failed */
    /* node_fext, node_fint, masses -> node_a */
    TIMED(accelerate, fe_accelerations(m, s));
    /* a, moments -> v, w (t + dt/2) with constraints and kinematic walls; x(t + dt); works */
    TIMED(integrate, fe_integrate(m, s));
    /* energies(t), checks, history; time += dt; next stable dt */
    TIMED(timestep, st = fe_stable_step(m, s));
    return st;
}

mcs_status fe_run(const fe_model *m, fe_state *s, double t_end)
{
    mcs_status st = s->err.status;
    while (st == MCS_OK && s->time < t_end) st = fe_step(m, s);
    return st;
}

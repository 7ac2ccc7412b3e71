/* tests for stage1_mb/mb_prescribe: bodies moved by a callback (the stage-2 vehicles).
 *
 * - analytic motions followed exactly: uniform acceleration x = x0 + v0 t + a t^2 / 2 and
 *   constant spin q(t) = exp(w t / 2) q0 (rigid-body kinematics), to round-off, with the
 *   step's finite-difference acceleration equal to a;
 * - a free body on a spherical joint at its CG, carried by a uniformly accelerated prescribed
 *   body: it follows with acceleration a (Newton: joint force m a) and the work of the
 *   prescribed body equals the free body's kinetic energy gain m (v1^2 - v0^2) / 2;
 * - a free ball (elastic contact, no damping, no friction) hitting a prescribed sphere that
 *   moves at constant velocity V: in the wall's frame the rebound reverses the relative
 *   velocity, so v' = 2 V - v (infinite-mass elastic impact, any mechanics text; e.g. Goldstein,
 *   Classical Mechanics, 3rd ed., Sec. 3.10 on collisions in the moving frame); the energy
 *   balance with the prescribed body's work as external work closes;
 * - an FE bar attached to a prescribed body: the attached node stays on the body point to
 *   round-off, and the balance (the body's work on the bar) closes. */
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_prescribe.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_test_util.h"

/* an analytic motion: p = p0 + v0 t + a t^2 / 2, q = exp(w t / 2) q0 (w constant, world) */
typedef struct {
    double p0[3], v0[3], a[3], q0[4], w[3];
} motion;

static void quat_mul(const double a[4], const double b[4], double o[4])
{
    o[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    o[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    o[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    o[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

static int analytic(void *ctx, int body, double t, double pos[3], double quat[4], double vel[3],
                    double omega[3])
{
    (void)body;
    const motion *mo = ctx;
    double wn = mb_norm(mo->w), ang = wn * t, e[4] = {1, 0, 0, 0};
    if (wn > 0) {
        e[0] = cos(0.5 * ang);
        for (int i = 0; i < 3; i++)
            e[i + 1] = sin(0.5 * ang) * mo->w[i] / wn;
    }
    quat_mul(e, mo->q0, quat);
    for (int i = 0; i < 3; i++) {
        pos[i] = mo->p0[i] + mo->v0[i] * t + 0.5 * mo->a[i] * t * t;
        vel[i] = mo->v0[i] + mo->a[i] * t;
        omega[i] = mo->w[i];
    }
    return 0;
}

/* largest differences of body b's state from the callback over a run */
typedef struct {
    double pos, quat, vel, angvel, acc;
} devs;

static void compare(const mb_model *m, const mb_state *s, int b, const motion *mo, devs *d)
{
    double p[3], q[4], v[3], w[3];
    analytic((void *)mo, b, s->t, p, q, v, w);
    mb_body_kin k;
    mb_body_get(s->world, b, &k);
    double dq = 0, sg = k.quat[0] * q[0] < 0 ? -1 : 1;
    for (int i = 0; i < 4; i++)
        dq = fmax(dq, fabs(k.quat[i] - sg * q[i]));
    for (int i = 0; i < 3; i++) {
        d->pos = fmax(d->pos, fabs(k.pos[i] - p[i]));
        d->vel = fmax(d->vel, fabs(k.vel[i] - v[i]));
        d->angvel = fmax(d->angvel, fabs(k.angvel[i] - w[i]));
        if (s->step > 0) d->acc = fmax(d->acc, fabs(s->acc[3 * b + i] - mo->a[i]));
    }
    d->quat = fmax(d->quat, dq);
    (void)m;
}

#define BOX_YAML                                                                                   \
    "mcrash: 1\nname: presc\n"                                                                     \
    "simulation: {end_time: 0.2 s, time_step: 50 us, output_rate: 1 kHz}\n"                        \
    "environment: {gravity: 9.81}\n"                                                               \
    "bodies:\n"                                                                                    \
    "  - {name: carrier, mass: 50, inertia: [2, 3, 4], position: [0.1, 0.2, 0.3],\n"               \
    "     orientation: [0.3, -0.2, 0.5], velocity: [5, -1, 0.5],\n"                                \
    "     angular_velocity: [1, -2, 12]}\n"                                                        \
    "  - {name: rider, mass: 2, inertia: [0.1, 0.1, 0.1], position: [0.1, 0.2, 0.3],\n"            \
    "     velocity: [5, -1, 0.5]}\n"                                                               \
    "joints:\n  - {name: hip, type: spherical, parent: carrier, child: rider, anchor: [0.1, 0.2, " \
    "0.3]}\n"

static void test_analytic_motion_exact(void)
{
    mcs_error err = {0};
    mb_model *m = mt_model_text("presc.yaml", BOX_YAML, &err);
    CHECK(m != NULL);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    motion mo = {{0.1, 0.2, 0.3}, {5, -1, 0.5}, {-80, 30, 20}, {0}, {1, -2, 12}};
    memcpy(mo.q0, m->body[0].quat, sizeof mo.q0);
    mcs_status st = mb_model_prescribe(m, 0, analytic, &mo, &err);
    CHECK(st == MCS_OK);
    CHECK(mb_body_prescribed(m, 0) && !mb_body_prescribed(m, 1));
    mb_state *s = NULL;
    if (!st) st = mb_state_create(m, &s, &err);
    CHECK(st == MCS_OK);
    devs d = {0}, dr = {0};
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        compare(m, s, 0, &mo, &d);
        /* the rider on the joint at its CG: translates with the carrier (rotation free) */
        motion rm = mo;
        memset(rm.w, 0, sizeof rm.w);
        double p[3], q[4], v[3], w[3];
        analytic(&rm, 1, s->t, p, q, v, w);
        mb_body_kin k;
        mb_body_get(s->world, 1, &k);
        for (int i = 0; i < 3; i++) {
            dr.pos = fmax(dr.pos, fabs(k.pos[i] - p[i]));
            dr.vel = fmax(dr.vel, fabs(k.vel[i] - v[i]));
        }
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    printf("carrier: |dp| %.3g m, |dq| %.3g, |dv| %.3g m/s, |dw| %.3g rad/s, |da| %.3g m/s^2\n",
           d.pos, d.quat, d.vel, d.angvel, d.acc);
    printf("rider on the joint: |dp| %.3g m, |dv| %.3g m/s\n", dr.pos, dr.vel);
    CHECK(d.pos < 1e-12 && d.quat < 1e-14 && d.vel < 1e-12 && d.angvel < 1e-12);
    CHECK(d.acc < 1e-8); /* (v1 - v0) / h: round-off of v over h */
    /* the joint holds the rider on the carrier's step (secant) velocity, which is the
     * carrier's end velocity less a h / 2 (uniform acceleration): the rider's velocity lags
     * by exactly that (the ODE step's symplectic Euler) while its position is exact */
    const double lag = 0.5 * 80 * m->h; /* largest |a_i| h / 2 */
    CHECK(dr.pos < 1e-8);
    CHECK_NEAR(dr.vel, lag, 1e-6);
    /* the carrier's work on the rider: its kinetic energy gain plus its potential energy
     * change, from the closed-form motion (x(t), v(t) of the carrier; gravity on the rider) */
    double v1[3], ke0 = 0.5 * 2 * mb_dot(mo.v0, mo.v0);
    for (int i = 0; i < 3; i++)
        v1[i] = mo.v0[i] + mo.a[i] * s->t;
    double gain = 0.5 * 2 * mb_dot(v1, v1) - ke0;
    gain += 2 * 9.81 * (mo.v0[2] * s->t + 0.5 * mo.a[2] * s->t * s->t);
    mb_energy_update(m, s);
    double drift = mb_energy_drift(m, s), werr = s->e.external_work / gain - 1;
    printf("carrier's work %.6g J, rider's kinetic + potential gain %.6g J (%+.2e), drift "
           "%.3g\n",
           s->e.external_work, gain, werr, drift);
    CHECK_NEAR(werr, 0, 1e-3);
    FIG_TOL("stage1_engine.presc_joint_drift", "%.5f", drift, 5e-5);
    CHECK(drift < 1e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the wall: a 0.5 m sphere moving at V = 2 m/s along x; the ball: 0.1 m, 1 kg, at -3 m/s,
 * 50 mm away; linear elastic contact k = 1e6 N/m (contact time pi sqrt(m / k) = 3.1 ms,
 * w h = 0.002). Printed with the wall's mass and both velocities. */
#define WALL_YAML                                                                                  \
    "mcrash: 1\nname: wall\n"                                                                      \
    "simulation: {end_time: 30 ms, time_step: 2 us, output_rate: 10 kHz}\n"                        \
    "environment: {gravity: 0}\n"                                                                  \
    "characteristics: {lin: {loading: [[0, 0], [0.01, 1e4]]}}\n"                                   \
    "bodies:\n"                                                                                    \
    "  - {name: wall, mass: %g, inertia: [1e6, 1e6, 1e6], position: [0, 0, 0],\n"                  \
    "     velocity: [%g, 0, 0],\n"                                                                 \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.5, 0.5, 0.5]}]}\n"         \
    "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004], position: [0.65, 0, 0],\n"          \
    "     velocity: [%g, 0, 0],\n"                                                                 \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"         \
    "contacts: [{a: ball, b: wall, characteristic: lin}]\n"

typedef struct {
    double v_end;  /* the ball's final velocity [m/s]                   */
    double offset; /* largest |total - total0| at the output samples [J] */
    double drift;  /* mb_energy_drift                                  */
    double w_ext;  /* external work at the end [J]                     */
} wall_run;

/* run the wall case; prescribed: the wall moves at V (the callback), else it is free */
static int run_wall(double mass, double V, double v, int prescribed, wall_run *r)
{
    char y[2048];
    snprintf(y, sizeof y, WALL_YAML, mass, V, v);
    mcs_error err = {0};
    mb_model *m = mt_model_text("wall.yaml", y, &err);
    motion mo = {{0, 0, 0}, {V, 0, 0}, {0}, {1, 0, 0, 0}, {0}};
    mcs_status st = m ? MCS_OK : MCS_ERR_KEY;
    if (!st && prescribed) st = mb_model_prescribe(m, 0, analytic, &mo, &err);
    mb_state *s = NULL;
    if (!st) st = mb_state_create(m, &s, &err);
    r->offset = 0;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        if (s->step % m->out_every == 0)
            r->offset = fmax(r->offset, fabs(s->e.total - s->e_total0));
    }
    if (st) fprintf(stderr, "%s\n", err.msg);
    if (!st) {
        mb_body_kin k;
        mb_body_get(s->world, 1, &k);
        r->v_end = k.vel[0], r->drift = mb_energy_drift(m, s), r->w_ext = s->e.external_work;
    }
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    return st == MCS_OK;
}

static void test_ball_on_moving_wall(void)
{
    const double V = 2, v = -3, vref = 2 * V - v; /* elastic rebound off an infinite mass */
    wall_run p = {0}, f = {0};
    CHECK(run_wall(100, V, v, 1, &p));
    /* the same impact in the wall's frame (Galilean: the contact force depends on relative
     * positions and velocities only): a free wall of 1e7 kg at rest, the ball at v - V */
    CHECK(run_wall(1e7, 0, v - V, 0, &f));
    double verr = p.v_end / vref - 1;
    /* the work the wall did: the ball's kinetic energy gain m (v'^2 - v^2) / 2 = 20 J */
    double wref = 0.5 * (vref * vref - v * v);
    printf("rebound %.7g m/s (closed form %.7g, %+.2e), wall's work %.6g J (closed form %.6g "
           "J), drift %.3g\n",
           p.v_end, vref, verr, p.w_ext, wref, p.drift);
    printf("largest balance offset in contact %.5g J; in the wall's frame (free wall) %.5g J\n",
           p.offset, f.offset);
    FIG("stage1_engine.presc_rebound_err", "%.1e", fabs(verr));
    FIG_TOL("stage1_engine.presc_wall_drift", "%.5f", p.drift, 5e-5);
    CHECK_NEAR(verr, 0, 1e-5);
    CHECK_NEAR(p.w_ext, wref, 1e-5 * wref);
    CHECK(p.drift < 1e-3);
    /* the offset is the engine's in-contact term, the same as the free impact's */
    CHECK_NEAR(p.offset / f.offset, 1, 1e-3);
}

/* a steel truss bar (1 m, 1 cm^2, 50 elements) fixed at its top, its lower end attached to
 * the carrier, whose CG is %g m beside the end (x), moving as the callback says */
#define BAR_YAML                                                                                   \
    "mcrash: 1\nname: bar\n"                                                                       \
    "simulation: {end_time: %g ms, time_step: 10 us, output_rate: 100 kHz}\n"                      \
    "environment: {gravity: 0}\n"                                                                  \
    "bodies:\n"                                                                                    \
    "  - {name: carrier, mass: 10, inertia: [0.1, 0.1, 0.1], position: [%g, 0, 0],\n"              \
    "     velocity: [0, 0, 0], angular_velocity: [0, 0, 0]}\n"                                     \
    "fe:\n  parts:\n    - name: bar\n"                                                             \
    "      mesh: {generate: line, origin: [0, 0, 0], end: [0, 0, 1], divisions: 50}\n"             \
    "      section: {type: truss, area: 1e-4}\n"                                                   \
    "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"     \
    "      attach: {body: carrier, where: z_min}\n"                                                \
    "  boundary: [{part: bar, where: z_max, fix: all}]\n"

static mb_model *bar_model(double t_end_ms, double cg_x)
{
    char y[2048];
    snprintf(y, sizeof y, BAR_YAML, t_end_ms, cg_x);
    mcs_error err = {0};
    mb_model *m = mt_model_text("bar.yaml", y, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    return m;
}

/* the attached node on the body point to round-off under spin and acceleration from rest;
 * the balance with the carrier's work on the bar closes */
static void test_fe_part_follows_prescribed_body(void)
{
    mb_model *m = bar_model(20, 0.05);
    CHECK(m != NULL && m->couple && m->couple->natt == 1);
    if (!m) return;
    mcs_error err = {0};
    motion mo = {{0.05, 0, 0}, {0}, {0, 0, -20}, {1, 0, 0, 0}, {0, 0, 3}};
    mcs_status st = mb_model_prescribe(m, 0, analytic, &mo, &err);
    mb_state *s = NULL;
    if (!st) st = mb_state_create(m, &s, &err);
    CHECK(st == MCS_OK);
    double dmax = 0;
    const int n = m->couple->node[0];
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        /* the body point: x_cg(t) + R(t) (-0.05, 0, 0), from the closed-form motion */
        double p[3], q[4], v[3], w[3], R[9], r[3], l[3] = {-0.05, 0, 0};
        analytic(&mo, 0, s->t, p, q, v, w);
        mb_quat_to_rot(q, R);
        mb_mat_vec(R, l, r);
        const double *x = s->couple->fe->node_x + 3 * n;
        for (int i = 0; i < 3; i++)
            dmax = fmax(dmax, fabs(x[i] - p[i] - r[i]));
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    double drift = s ? mb_energy_drift(m, s) : 1;
    printf("attached node off the body point: %.3g m; carrier's work %.5g J, drift %.3g\n", dmax,
           s ? s->e.external_work : 0, drift);
    CHECK(dmax < 1e-13);
    FIG_TOL("stage1_engine.presc_fe_drift", "%.1e", drift, 2e-7);
    CHECK(drift < 1e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the bar's end pulled down at constant V from rest: until the wave comes back (2 L / c =
 * 0.39 ms) the end force is rho c A V and the work rho c A V^2 t (1-D elastic wave, e.g.
 * Graff, Wave Motion in Elastic Solids, Sec. 2.1) */
static void test_fe_bar_pulled_by_prescribed_body(void)
{
    const double V = 1, T = 0.3e-3, c = sqrt(210e9 / 7850), wref = 7850 * c * 1e-4 * V * V * T;
    mb_model *m = bar_model(1e3 * T, 0);
    CHECK(m != NULL);
    if (!m) return;
    mcs_error err = {0};
    motion mo = {{0, 0, 0}, {0, 0, -V}, {0}, {1, 0, 0, 0}, {0}};
    mcs_status st = mb_model_prescribe(m, 0, analytic, &mo, &err);
    mb_state *s = NULL;
    if (!st) st = mt_run(m, &s, &err);
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    double werr = s ? s->e.external_work / wref - 1 : 1;
    printf("carrier's work on the bar %.5g J at %.3g ms (wave: %.5g J, %+.2f %%), drift %.3g\n",
           s ? s->e.external_work : 0, 1e3 * T, wref, 100 * werr, s ? mb_energy_drift(m, s) : 1);
    FIG_TOL("stage1_engine.presc_bar_work_err_pct", "%.2f", 100 * werr, 0.05);
    CHECK_NEAR(werr, 0, 0.02);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* a motion whose pose at t = 0 is not the body's initial pose is refused, naming the body */
static void test_mismatched_start_is_refused(void)
{
    mcs_error err = {0};
    mb_model *m = bar_model(1, 0);
    CHECK(m != NULL);
    if (!m) return;
    motion mo = {{0, 0, 0.01}, {0}, {0}, {1, 0, 0, 0}, {0}};
    CHECK(mb_model_prescribe(m, 0, analytic, &mo, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "carrier");
    CHECK(!mb_body_prescribed(m, 0));
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_analytic_motion_exact);
    RUN(test_ball_on_moving_wall);
    RUN(test_fe_part_follows_prescribed_body);
    RUN(test_fe_bar_pulled_by_prescribed_body);
    RUN(test_mismatched_start_is_refused);
    TEST_END();
}

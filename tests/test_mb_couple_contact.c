/* tests for stage1_mb/mb_couple_contact: fe.contacts[] of type bodies (FE nodes against the
 * ellipsoid and facet surfaces of stage-1 bodies) in a coupled stage-1 run.
 *
 * The plates that stand for fixed FE surfaces are heavy (density x 1000): every node is fixed,
 * so their mass does nothing but set the FE stable step (and with it the penalty stiffness
 * k = s m_node / dt0^2 = s E t / (c dt0 / a)^2-free: per node about s E t for a shell), which
 * keeps the subcycles few. */
#include "fe/fe_contact.h"
#include "fe/fe_state.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_contact.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_test_util.h"

/* a ball (sphere radius R, mass M) over a fixed square plate of quads in z = 0 */
#define DROP_YAML                                                                                  \
    "mcrash: 1\nname: drop\n"                                                                      \
    "simulation: {end_time: %g, time_step: %g, output_rate: 10 kHz}\n"                             \
    "environment: {gravity: %g}\n"                                                                 \
    "bodies:\n"                                                                                    \
    "  - {name: ball, mass: 1, inertia: [%g, %g, %g], position: [0, 0, %.9g],\n"                   \
    "     velocity: [%g, 0, %g], angular_velocity: [0, 0, 0],\n"                                   \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [%g, %g, %g]}]}\n"            \
    "fe:\n  parts:\n    - name: plate\n"                                                           \
    "      mesh: {generate: plate, size: [%g, %g], divisions: [%d, %d], origin: [%g, %g, 0]}\n"    \
    "      section: {type: shell, thickness: 2 mm}\n"                                              \
    "      material: {model: elastic, density: 7.85e6, youngs_modulus: 210 GPa, poisson: 0.3}\n"   \
    "  boundary: [{part: plate, where: all, fix: all}]\n"                                          \
    "  contacts: [{type: bodies, parts: [plate], bodies: [ball], friction: %g,\n"                  \
    "              penalty_scale: %g}]\n"

typedef struct {
    double end, h, g, inertia, z0, vx, vz, R, size[2], mu, scale;
    int div[2];
} drop_case;

static char yaml[4096];

static const char *drop_text(const drop_case *c)
{
    snprintf(yaml, sizeof yaml, DROP_YAML, c->end, c->h, c->g, c->inertia, c->inertia, c->inertia,
             c->z0, c->vx, c->vz, c->R, c->R, c->R, c->size[0], c->size[1], c->div[0], c->div[1],
             -0.5 * c->size[0], -0.5 * c->size[1], c->mu, c->scale);
    return yaml;
}

/* the penalty force of the fixed plate on the sphere pushed delta below its first touch: the
 * sum over the plate's nodes of k_n (delta - h_n), h_n = R - sqrt(R^2 - rho_n^2) the height of
 * the sphere above node n at rho_n from the axis, k_n = s m_n / dt0^2 (docs/fe.md "Contact");
 * its work w */
static double lattice_force(const fe_model *fm, double R, double scale, double delta, double *w)
{
    double f = 0, e = 0, dt0 = fm->contact->dt0;
    for (int n = 0; n < fm->nnode; n++) {
        const double *x = fm->node_x0 + 3 * n;
        double r2 = x[0] * x[0] + x[1] * x[1];
        if (r2 >= R * R) continue;
        double d = delta - (R - sqrt(R * R - r2));
        if (d <= 0) continue;
        double k = scale * fm->node_mass[n] / (dt0 * dt0);
        f += k * d, e += 0.5 * k * d * d;
    }
    *w = e;
    return f;
}

/* A ball dropped on a fixed plate, no gravity, v0 = 1 m/s: the penalty is elastic and the
 * plate does not move, so the ball is a conservative one-degree oscillator on the lattice
 * force F(delta) above: it rebounds at -v0, and the peak force is F(delta_max) with
 * W(delta_max) = M v0^2 / 2 (energy balance; no Hertz: the penalty is per node). The impulse
 * the body received equals the one the plate's nodes received (equal and opposite) and 2 M v0
 * (momentum). */
static void test_ball_drop_on_fixed_plate(void)
{
    const double R = 0.1, v0 = 1, t_half = 0.5 * 0.1e-3; /* half the plate's shell thickness */
    drop_case c = {.end = 0.01,
                   .h = 20e-6,
                   .g = 0,
                   .inertia = 0.004,
                   .z0 = R + t_half + 1e-3,
                   .vx = 0,
                   .vz = -v0,
                   .R = R,
                   .size = {0.08, 0.08},
                   .div = {32, 32},
                   .mu = 0,
                   .scale = 0.001};
    (void)t_half;
    mcs_error err = {0};
    mb_model *m = mt_model_text("drop.yaml", drop_text(&c), &err);
    CHECK(m != NULL);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    CHECK(st == MCS_OK);
    const fe_model *fm = m->couple->fe.model;
    double fpeak = 0, imp_body = 0, imp_fe = 0, vend = 0;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        const fe_contact_state *ks = s->couple->fe->contact;
        fpeak = fmax(fpeak, ks->ell_force[2]);
        mb_body_kin k;
        mb_body_get(s->world, 0, &k);
        vend = k.vel[2];
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    double jfe[6], jb[6];
    CHECK(mb_couple_contact_impulse(m, s, 0, jfe, jb) == 0);
    imp_fe = jfe[2], imp_body = jb[2];
    /* the closed form: delta_max from W = M v0^2 / 2 by bisection */
    double lo = 0, hi = 0.01, w = 0;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        lattice_force(fm, R, c.scale, mid, &w);
        if (w < 0.5 * 1 * v0 * v0)
            lo = mid;
        else
            hi = mid;
    }
    double fref = lattice_force(fm, R, c.scale, lo, &w);
    const double drift = mb_energy_drift(m, s), perr = 100 * (fpeak / fref - 1);
    const double verr = 100 * (vend / v0 - 1);
    printf("drop: rebound %.5f m/s (v0 = %.5f, %+.3f %%), peak force %.2f N (closed form %.2f N, "
           "delta %.3f mm, %+.3f %%), drift %.3g, FE steps %ld\n",
           vend, v0, verr, fpeak, fref, 1e3 * lo, perr, drift, s->couple->substeps);
    printf("drop: impulse given by the plate %.6f N s, received by the ball %.6f N s, "
           "2 M v0 = %.6f, M dv = %.6f\n",
           imp_fe, imp_body, 2 * v0, vend + v0);
    FIG("stage1_engine.contact_drop_rebound_err_pct", "%.3f", fabs(verr));
    FIG("stage1_engine.contact_drop_peak_err_pct", "%.2f", fabs(perr));
    FIG_TOL("stage1_engine.contact_drop_drift", "%.4f", drift, 3e-4);
    CHECK_NEAR(verr, 0, 0.1);
    CHECK_NEAR(perr, 0, 1.2);
    /* equal and opposite: what the plate's nodes received (minus it) is what the ball got;
     * the ball's momentum change is that impulse (ODE: M dv = J) */
    CHECK_NEAR(imp_body, imp_fe, 1e-6 * imp_fe);
    CHECK_NEAR(vend + v0, imp_body, 1e-9);
    CHECK_NEAR(imp_fe, 2 * v0, 1e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* bad input is refused at its FILE:LINE:COL: a bodies contact naming an unknown body (the
 * schema's body reference), or a body without an ellipsoid or facet surface */
static void test_bodies_contact_errors_are_located(void)
{
    drop_case c = {.end = 0.001,
                   .h = 20e-6,
                   .R = 0.1,
                   .z0 = 0.2,
                   .size = {0.1, 0.1},
                   .div = {2, 2},
                   .inertia = 0.004,
                   .scale = 0.001};
    char *y = malloc(8192);
    strcpy(y, drop_text(&c));
    char *p = strstr(y, "bodies: [ball]");
    memcpy(p, "bodies: [bal1]", 14);
    mcs_error err = {0};
    mb_model *m = mt_model_text("bad.yaml", y, &err);
    CHECK(m == NULL);
    CHECK(err.status != MCS_OK);
    printf("unknown body: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "bad.yaml:16:54");
    CHECK_STR_CONTAINS(err.msg, "bal1");
    mb_model_destroy(&m);
    /* a body without surfaces, beside one with an ellipsoid */
    const char *nosurf =
        "mcrash: 1\nname: bad\nsimulation: {end_time: 1 ms, time_step: 20 us}\n"
        "bodies:\n"
        "  - {name: ball, mass: 1, inertia: [1, 1, 1], position: [0, 0, 1], velocity: [0, 0, 0],\n"
        "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"
        "  - {name: bare, mass: 1, inertia: [1, 1, 1], position: [0, 0, 2], velocity: [0, 0, 0]}\n"
        "fe:\n  parts:\n    - name: plate\n"
        "      mesh: {generate: plate, size: [0.1, 0.1], divisions: [2, 2]}\n"
        "      section: {type: shell, thickness: 2 mm}\n"
        "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"
        "  contacts: [{type: bodies, parts: [plate], bodies: [ball, bare]}]\n";
    strcpy(y, nosurf);
    memset(&err, 0, sizeof err);
    m = mt_model_text("bad.yaml", y, &err);
    CHECK(m == NULL);
    printf("no surfaces: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "bad.yaml:14:60");
    CHECK_STR_CONTAINS(err.msg, "no ellipsoid or facet surfaces");
    mb_model_destroy(&m);
    free(y);
}

int main(void)
{
    fe_set_threads(1); /* small models: one thread is faster than a team's start-up */
    RUN(test_ball_drop_on_fixed_plate);
    RUN(test_bodies_contact_errors_are_located);
    TEST_END();
}

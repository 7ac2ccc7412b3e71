/* tests for stage1_mb/mb_couple: a stage-1 body carried by an FE part (fe.parts[].attach).
 *
 * A rigid body of mass M hangs on the lower end of a vertical steel truss bar (length L, area
 * A, modulus E, density rho, bar mass m = rho A L) whose upper end is fixed; released at rest
 * with the bar unstretched, under gravity g:
 * - static deflection of the lower end, tip load M g plus the bar's own weight (which loads
 *   the end as m g / 2): delta = (M + m/2) g L / (E A) (Timoshenko & Gere, Mechanics of
 *   Materials, axial bar under its own weight); the body oscillates about it from 0 to
 *   2 delta, so delta = -(z_max + z_min) / 2 of the body's displacement;
 * - period: the first root of beta tan(beta) = m / M, omega = beta c / L, c = sqrt(E / rho)
 *   (longitudinal bar fixed at one end with an end mass: Rao, Mechanical Vibrations, 5th ed.,
 *   Sec. 8.4); Rayleigh's estimate 2 pi sqrt((M + m/3) / k), k = E A / L, is within 1e-4 of it
 *   here;
 * - one energy balance of the body and the bar (docs/stage1_engine.md "Coupling to FE parts");
 * - the moment on the body: test_moment_on_a_hinged_body.
 * The FE stable step (3.5 us) is below the ODE step (10 us): the FE subcycles 3 times. */
#include "stage1_mb/mb_couple.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_couple_test_util.h"
#include "tests/mb_test_util.h"

#define L_BAR 1.0
#define A_BAR 1e-4
#define E_BAR 210e9
#define RHO 7850.0
#define M_BODY 10.0
#define G 9.81

/* the scenario: gravity g [m/s^2], initial body speed along z vz [m/s] */
#define HANG_YAML                                                                                  \
    "mcrash: 1\nname: hang\n"                                                                      \
    "simulation: {end_time: 22 ms, time_step: 10 us, output_rate: 10 kHz}\n"                       \
    "environment: {gravity: %g}\n"                                                                 \
    "bodies:\n"                                                                                    \
    "  - {name: weight, mass: 10, inertia: [0.1, 0.1, 0.1], position: [0, 0, 0],\n"                \
    "     velocity: [0, 0, %g], angular_velocity: [0, 0, 0]}\n"                                    \
    "fe:\n  parts:\n    - name: bar\n"                                                             \
    "      mesh: {generate: line, origin: [0, 0, 0], end: [0, 0, 1], divisions: 50}\n"             \
    "      section: {type: truss, area: 1e-4}\n"                                                   \
    "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"     \
    "      attach: {body: weight, where: z_min}\n"                                                 \
    "  boundary: [{part: bar, where: z_max, fix: all}]\n"

static char hang_yaml[2048];

static const char *hang(double g, double vz)
{
    snprintf(hang_yaml, sizeof hang_yaml, HANG_YAML, g, vz);
    return hang_yaml;
}

/* the body's height, and its rotation about z [rad] (a turn about the z axis only) */
static double body_z(const mb_state *s)
{
    mb_body_kin k;
    mb_body_get(s->world, 0, &k);
    return k.pos[2];
}

static double body_angle_z(const mb_state *s)
{
    mb_body_kin k;
    mb_body_get(s->world, 0, &k);
    return 2 * atan2(k.quat[3], k.quat[0]);
}

static void test_body_hanging_on_a_bar(void)
{
    mb_model *m = mc_model("hang.yaml", hang(G, 0));
    if (!m) return;
    CHECK(m->couple != NULL && m->couple->natt == 1);
    mb_state *s = NULL;
    const long n = m->nsteps;
    double *z = calloc((size_t)n + 1, sizeof *z), zmin, zmax;
    mc_run_record(m, &s, body_z, z, &zmin, &zmax);
    const double mb = RHO * A_BAR * L_BAR, k = E_BAR * A_BAR / L_BAR, c = sqrt(E_BAR / RHO);
    const double delta = (M_BODY + 0.5 * mb) * G / k;
    const double T = 2 * M_PI / (mc_end_mass_root(mb / M_BODY) * c / L_BAR);
    const double T_rayleigh = 2 * M_PI * sqrt((M_BODY + mb / 3) / k);
    double dmeas = -0.5 * (zmax + zmin);
    /* period: mean spacing of the upward crossings of the static position */
    int ncross;
    double Tmeas = mc_up_period(z, n, -dmeas, m->h, &ncross);
    double derr = 100 * (dmeas / delta - 1), terr = 100 * (Tmeas / T - 1);
    double drift = mb_energy_drift(m, s);
    printf("static deflection %.4g um (closed form %.4g um, %+.3f %%)\n", 1e6 * dmeas,
           1e6 * delta, derr);
    printf("period %.5g ms (closed form %.5g ms, Rayleigh %.5g ms, %+.3f %%), %d crossings\n",
           1e3 * Tmeas, 1e3 * T, 1e3 * T_rayleigh, terr, ncross);
    printf("energy drift %.3g, FE steps %ld, ODE steps %ld, exchange mismatch %.3g J\n", drift,
           s->couple->substeps, s->step, s->couple->w_body + s->couple->w_fe);
    CHECK(ncross >= 4);
    FIG("stage1_engine.couple_deflection_err_pct", "%.3f", fabs(derr)); /* 0.001 % */
    FIG("stage1_engine.couple_period_err_pct", "%.3f", fabs(terr));     /* 0.005 % */
    FIG_TOL("stage1_engine.couple_drift", "%.4f", drift, 3e-4);         /* 0.0021 */
    CHECK_NEAR(derr, 0, 0.05);
    CHECK_NEAR(terr, 0, 0.05);
    CHECK(drift < 5e-3);
    free(z);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the same bar without gravity, set oscillating by a 10 mm/s initial speed of the body: the
 * coupled balance (no external work) over 5 periods */
static void test_free_oscillation_energy(void)
{
    const char *y = hang(0, -0.01);
    mcs_error err = {0};
    mb_model *m = mt_model_text("free.yaml", y, &err);
    CHECK(m != NULL);
    mb_state *s = NULL;
    mcs_status st = m ? mt_run(m, &s, &err) : MCS_ERR_KEY;
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    /* reference: the initial kinetic energy M v0^2 / 2 = 5e-4 J */
    double drift = s ? mb_energy_drift(m, s) : 1;
    printf("free oscillation: energy drift %.3g of 5e-4 J\n", drift);
    FIG_TOL("stage1_engine.couple_free_drift", "%.3f", drift, 2e-3); /* 0.015 */
    CHECK(drift < 0.03);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the moment: a body of inertia I on a revolute hinge (z axis at its CG), the bar's end attached
 * at the lever r = 0.1 m along y, the bar along x (its far end fixed), no gravity, set turning
 * at 0.1 rad/s. Torsional spring k r^2 against I: the same end-mass root with the mass ratio
 * m / (I / r^2) (Rao, Sec. 8.4, with the body's mass replaced by I / r^2), period 2 pi / omega;
 * Rayleigh: 2 pi sqrt((I + m r^2 / 3) / (k r^2)). */
static void test_moment_on_a_hinged_body(void)
{
    const char *y =
        "mcrash: 1\nname: lever\n"
        "simulation: {end_time: 22 ms, time_step: 10 us, output_rate: 10 kHz}\n"
        "environment: {gravity: 0}\n"
        "bodies:\n"
        "  - {name: lever, mass: 10, inertia: [0.1, 0.1, 0.1], position: [0, 0, 0],\n"
        "     velocity: [0, 0, 0], angular_velocity: [0, 0, 0.1]}\n"
        "joints:\n"
        "  - {type: revolute, parent: ground, child: lever, anchor: [0, 0, 0], axis: [0, 0, 1]}\n"
        "fe:\n  parts:\n    - name: bar\n"
        "      mesh: {generate: line, origin: [0, 0.1, 0], end: [1, 0.1, 0], divisions: 50}\n"
        "      section: {type: truss, area: 1e-4}\n"
        "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"
        "      attach: {body: lever, where: x_min}\n"
        "  boundary: [{part: bar, where: x_max, fix: all}]\n";
    mb_model *m = mc_model("lever.yaml", y);
    if (!m) return;
    mb_state *s = NULL;
    double *ang = calloc((size_t)m->nsteps + 1, sizeof *ang), alo, ahi;
    mc_run_record(m, &s, body_angle_z, ang, &alo, &ahi);
    const double amax = fmax(ahi, -alo);
    int ncross; /* upward crossings of zero */
    double Tmeas = mc_up_period(ang, m->nsteps, 0, m->h, &ncross);
    const double r = 0.1, I = 0.1, mb = RHO * A_BAR * L_BAR, c = sqrt(E_BAR / RHO);
    const double kt = E_BAR * A_BAR / L_BAR * r * r;
    const double T = 2 * M_PI / (mc_end_mass_root(mb * r * r / I) * c / L_BAR);
    const double T_rayleigh = 2 * M_PI * sqrt((I + mb * r * r / 3) / kt);
    double terr = 100 * (Tmeas / T - 1);
    double drift = s ? mb_energy_drift(m, s) : 1;
    printf("lever: period %.5g ms (closed form %.5g ms, Rayleigh %.5g ms, %+.3f %%), amplitude "
           "%.4g rad, drift %.3g\n",
           1e3 * Tmeas, 1e3 * T, 1e3 * T_rayleigh, terr, amax, drift);
    CHECK(ncross >= 4);
    FIG("stage1_engine.couple_lever_period_err_pct", "%.3f", fabs(terr));
    CHECK_NEAR(terr, 0, 0.05);
    free(ang);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

static void test_attach_errors_are_located(void)
{
    char *y = malloc(2048);
    strcpy(y, hang(G, 0));
    char *p = strstr(y, "body: weight");
    memcpy(p, "body: wieght", 12);
    mcs_error err = {0};
    mb_model *m = mt_model_text("bad.yaml", y, &err);
    CHECK(m == NULL);
    CHECK(err.status != MCS_OK);
    CHECK_STR_CONTAINS(err.msg, "bad.yaml:14:22");
    CHECK_STR_CONTAINS(err.msg, "wieght");
    mb_model_destroy(&m);
    free(y);
}

int main(void)
{
    RUN(test_body_hanging_on_a_bar);
    RUN(test_free_oscillation_energy);
    RUN(test_moment_on_a_hinged_body);
    RUN(test_attach_errors_are_located);
    TEST_END();
}

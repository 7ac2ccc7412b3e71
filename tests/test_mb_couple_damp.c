/* tests for the coupling's reactions with FE mass damping and mass scaling (stage1_mb/
 * mb_couple.c: the constraint force of the attached nodes is the one the FE step records,
 * fe_state.node_react; docs/stage1_engine.md "Coupling to FE parts").
 *
 * The body of test_mb_couple.c: a rigid body M = 10 kg hanging on the lower end of a vertical
 * steel truss bar (L = 1 m, A = 1 cm^2, E = 210 GPa, rho = 7850 kg/m^3, bar mass m = rho A L),
 * the upper end fixed, released at rest with the bar unstretched under g = 9.81 m/s^2.
 * - With mass-proportional damping c (fe.damping, f = -c m v on every FE node) the motion dies
 *   out and the body comes to rest at the static deflection delta = (M + m/2) g L / (E A)
 *   (Timoshenko & Gere, Mechanics of Materials: axial bar under its own weight plus a tip
 *   load): damping forces vanish at rest, so the end state does not depend on c. The
 *   constraint force on the attached node includes its damping term: a reaction taken as
 *   m (v_new - v_free) / dth without the factor (1 + c dth / 2) (c dth / 2 = 0.05 here) loads
 *   the body with the wrong force and does not settle at delta.
 * - With mass scaling to a target step dt_t (fe.mass_scaling.time_step), every bar element
 *   (step L_e / c_bar, safety factor s = 0.9) has its density scaled by f^2,
 *   f = dt_t / (s L_e / c_bar) (fe_massscale.c's definition, LS-DYNA DT2MS < 0): the bar's
 *   mass becomes m' = f^2 m and its wave speed c_bar / f, its stiffness E A / L unchanged. The
 *   period follows the end-mass root beta tan(beta) = m' / M, omega = beta (c_bar / f) / L
 *   (Rao, Mechanical Vibrations, 5th ed., Sec. 8.4). */
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
#define NDIV 50

/* the scenario: end time, extra fe: keys (damping, mass_scaling) */
#define HANG_YAML                                                                                  \
    "mcrash: 1\nname: hang\n"                                                                      \
    "simulation: {end_time: %s, time_step: 10 us, output_rate: 10 kHz}\n"                          \
    "environment: {gravity: 9.81}\n"                                                               \
    "bodies:\n"                                                                                    \
    "  - {name: weight, mass: 10, inertia: [0.1, 0.1, 0.1], position: [0, 0, 0],\n"                \
    "     velocity: [0, 0, 0], angular_velocity: [0, 0, 0]}\n"                                     \
    "fe:\n  parts:\n    - name: bar\n"                                                             \
    "      mesh: {generate: line, origin: [0, 0, 0], end: [0, 0, 1], divisions: 50}\n"             \
    "      section: {type: truss, area: 1e-4}\n"                                                   \
    "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"     \
    "      attach: {body: weight, where: z_min}\n"                                                 \
    "  boundary: [{part: bar, where: z_max, fix: all}]\n"                                          \
    "%s"

static char yaml[4096];

static mb_model *hang(const char *end_time, const char *extra)
{
    snprintf(yaml, sizeof yaml, HANG_YAML, end_time, extra);
    mcs_error err = {0};
    mb_model *m = mt_model_text("hang.yaml", yaml, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    return m;
}

/* the body's height */
static double body_z(const mb_state *s)
{
    mb_body_kin k;
    mb_body_get(s->world, 0, &k);
    return k.pos[2];
}

static void test_static_deflection_with_damping(void)
{
    /* c = 3e4 1/s: c dth / 2 = 0.05 at the 3.3 us FE step; the fundamental decays by
     * ~exp(-11) in 30 ms */
    mb_model *m = hang("30 ms", "  damping: 30000\n");
    CHECK(m != NULL);
    if (!m) return;
    CHECK(m->couple->fe.model->opts.damping == 30000);
    mb_state *s = NULL;
    mc_run(m, &s);
    if (!s) return;
    mb_body_kin k;
    mb_body_get(s->world, 0, &k);
    const double mb = RHO * A_BAR * L_BAR,
                 delta = (M_BODY + 0.5 * mb) * G * L_BAR / (E_BAR * A_BAR);
    const double err_pct = 100 * (-k.pos[2] / delta - 1);
    printf("damped: body at rest %.6g um below (closed form %.6g um, %+.4f %%), speed %.3g m/s, "
           "drift %.3g\n",
           -1e6 * k.pos[2], 1e6 * delta, err_pct, fabs(k.vel[2]), mb_energy_drift(m, s));
    FIG("stage1_engine.couple_damped_deflection_err_pct", "%.4f", fabs(err_pct));
    CHECK_NEAR(err_pct, 0, 0.01);
    CHECK(fabs(k.vel[2]) < 1e-6);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

static void test_period_with_mass_scaling(void)
{
    /* dt_t = 8 us: the bar elements (L_e = 20 mm, step 3.87 us, 3.48 us with the safety
     * factor) get f = 2.3, f^2 = 5.3 times their mass */
    mb_model *m = hang("30 ms", "  mass_scaling: {time_step: 8 us}\n");
    CHECK(m != NULL);
    if (!m) return;
    const double c0 = sqrt(E_BAR / RHO), le = L_BAR / NDIV, dt_t = 8e-6, s_f = 0.9;
    const double f = dt_t / (s_f * le / c0), mb = RHO * A_BAR * L_BAR, mb1 = f * f * mb;
    const double T = 2 * M_PI / (mc_end_mass_root(mb1 / M_BODY) * (c0 / f) / L_BAR);
    const double T0 = 2 * M_PI / (mc_end_mass_root(mb / M_BODY) * c0 / L_BAR);
    const fe_model *fm = m->couple->fe.model;
    CHECK_REL(fm->mass_added, mb1 - mb, 1e-9);
    mb_state *s = NULL;
    const long n = m->nsteps;
    double *z = calloc((size_t)n + 1, sizeof *z), zmin, zmax;
    mc_run_record(m, &s, body_z, z, &zmin, &zmax);
    /* period: mean spacing of the upward crossings of the mid position */
    int ncross;
    const double Tm = mc_up_period(z, n, 0.5 * (zmax + zmin), m->h, &ncross);
    const double terr = 100 * (Tm / T - 1);
    printf("mass scaled: bar %.4g kg (was %.4g), period %.5g ms (closed form %.5g ms, %+.3f %%; "
           "unscaled %.5g ms), %d crossings, FE steps %ld\n",
           mb1, mb, 1e3 * Tm, 1e3 * T, terr, 1e3 * T0, ncross, s ? s->couple->substeps : 0);
    FIG("stage1_engine.couple_massscale_period_err_pct", "%.3f", fabs(terr));
    CHECK(ncross >= 4);
    CHECK_NEAR(terr, 0, 0.05);
    free(z);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_static_deflection_with_damping);
    RUN(test_period_with_mass_scaling);
    TEST_END();
}

/* tests for stage1_mb/mb_couple_trigger.c: inflators and pretensioners fired by a stage-1
 * contact (fe.airbags[].inflator.trigger, fe.retractors[].trigger; DESIGN.md "Coupling bodies
 * and FE parts").
 *
 * A 1 kg ball (radius 0.1 m) is released at rest with its surface h = 0.1 m above the ground,
 * under g = 9.81 m/s^2; the contact is linear, k = 1e5 N/m, undamped. References:
 * - free fall: the ball touches at t_c = sqrt(2 h / g) with v_c = sqrt(2 g h);
 * - in contact (tau = t - t_c, depth d, omega = sqrt(k / m)): m d'' = m g - k d, d(0) = 0,
 *   d'(0) = v_c, so d = (g / omega^2)(1 - cos omega tau) + (v_c / omega) sin omega tau and the
 *   normal force k d first reaches F at the root tau_F of k d(tau_F) = F (bisection here);
 * - the trigger sees the contact force at the ODE step's start, so the firing time lies in
 *   [t_c + tau_F + delay, t_c + tau_F + delay + h) of the integrated motion, h the ODE step
 *   (docs/stage1_engine.md); the integrator (semi-implicit Euler) runs h/2 ahead of the free
 *   fall (z_n = z_0 - g h^2 n (n + 1) / 2, the exact fall at t_n + h/2), so against the closed
 *   form the firing time is within [-h/2, h): tested |t_fire - t_ref| < h;
 * - a closed gas bag held fixed (volume constant) takes the inflator's mass only after firing:
 *   mass_in(t) = m_dot (t - t_fire) for a constant table (paper 2023 Eq. 4, no exhaust);
 * - the pretensioner's pay-in follows Eq. 3 from the state's firing time:
 *   L(t) = -(100 mm / 15 ms)(t - t_fire) within 15 ms of firing. */
#include "tests/cli_util.h"
#include "core/mcs_results.h"
#include "fe/fe_restraint.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_rx.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_couple_test_util.h"
#include "tests/mb_test_util.h"

#define G 9.81
#define H_DROP 0.1
#define K_CONTACT 1e5
#define M_BALL 1.0
#define H_ODE 10e-6

/* the scenario: bag trigger force and delay, retractor trigger force and delay, end time */
#define DROP_YAML                                                                                  \
    "mcrash: 1\nname: drop\n"                                                                      \
    "simulation: {end_time: %g, time_step: 10 us, output_rate: 10 kHz}\n"                          \
    "environment: {gravity: 9.81, ground: {height: 0}}\n"                                          \
    "characteristics:\n"                                                                           \
    "  pad: {loading: [[0, 0], [0.01, 1000]], damping: 0, friction: 0}\n"                          \
    "bodies:\n"                                                                                    \
    "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004], position: [0, 0, 0.2],\n"           \
    "     velocity: [0, 0, 0], angular_velocity: [0, 0, 0],\n"                                   \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"         \
    "contacts:\n"                                                                                  \
    "  - {name: ball_ground, a: ball, b: ground, characteristic: pad}\n"                           \
    "fe:\n"                                                                                        \
    "  parts:\n"                                                                                   \
    "    - name: fabric\n"                                                                         \
    "      mesh: {generate: sphere_shell, origin: [1, 0, 0.5], radius: 100 mm,\n"                  \
    "             element_size: 60 mm}\n"                                                          \
    "      section: {type: membrane, thickness: 0.5 mm}\n"                                         \
    "      material: {model: fabric, density: 1000, youngs_modulus: 500 MPa, poisson: 0.3}\n"      \
    "    - name: belt\n"                                                                           \
    "      mesh: {generate: line, origin: [1, 1, 0.5], end: [1.5, 1, 0.5], divisions: 1}\n"        \
    "      section: {type: truss, area: 1e-6, tension_only: true}\n"                               \
    "      material: {model: elastic, density: 1000, youngs_modulus: 1 GPa, poisson: 0}\n"         \
    "  boundary:\n"                                                                                \
    "    - {part: fabric, where: all, fix: all}\n"                                                 \
    "    - {part: belt, where: x_max, fix: all}\n"                                                 \
    "  airbags:\n"                                                                                 \
    "    - name: bag\n"                                                                            \
    "      parts: [fabric]\n"                                                                      \
    "      inflator: {mass_flow: [[0, 0.1], [1, 0.1]], temperature: [[0, 600 K]],\n"              \
    "                 trigger: {contact: ball_ground%s}}\n"                                        \
    "  retractors:\n"                                                                              \
    "    - {name: ret, part: belt, where: x_min, anchor: [0.5, 1, 0.5], load_limit: 0,\n"          \
    "       trigger: {contact: ball_ground%s}}\n"

static char drop_yaml[4096];

static const char *drop(double t_end, const char *bag_trig, const char *ret_trig)
{
    snprintf(drop_yaml, sizeof drop_yaml, DROP_YAML, t_end, bag_trig, ret_trig);
    return drop_yaml;
}

/* time after first contact at which the contact force k d first reaches F (closed form above) */
static double tau_force(double F)
{
    const double w = sqrt(K_CONTACT / M_BALL), vc = sqrt(2 * G * H_DROP);
    double lo = 0, hi = 0.5 * M_PI / w;
    for (int i = 0; i < 200; i++) {
        double t = 0.5 * (lo + hi);
        double d = G / (w * w) * (1 - cos(w * t)) + vc / w * sin(w * t);
        if (K_CONTACT * d < F) lo = t;
        else hi = t;
    }
    return 0.5 * (lo + hi);
}

static void test_fires_on_first_contact(void)
{
    const double tc = sqrt(2 * H_DROP / G), delay_bag = 0.012, delay_ret = 0.002, F_ret = 50;
    const double t_end = tc + 0.015; /* the pay-in still on its ramp */
    mb_model *m =
        mc_model("drop.yaml", drop(t_end, ", delay: 12 ms", ", force: 50 N, delay: 2 ms"));
    if (!m) return;
    mb_state *s = NULL;
    mc_run(m, &s);
    if (!s) return;
    const fe_state *f = s->couple->fe;
    const fe_gasbag_state *g = &f->restraint->bag[0];
    const fe_retractor_state *r = &f->restraint->retractor[0];
    double tb = mb_couple_fire_time(m, s, MB_TRIG_BAG, 0);
    double tr = mb_couple_fire_time(m, s, MB_TRIG_RETRACTOR, 0);
    double tb_ref = tc + delay_bag, tr_ref = tc + tau_force(F_ret) + delay_ret;
    /* the gas took its inflow from the state's firing time; the pay-in likewise (Eq. 3) */
    double mass_ref = 0.1 * (g->time - tb);
    double pay_ref = -(0.1 / 0.015) * fmin(r->time - tr, 0.015);
    double drift = mb_energy_drift(m, s);
    printf("contact at %.6f s (free fall %.6f s); bag fired %.6f s (ref %.6f s, +%.2f steps), "
           "retractor %.6f s (ref %.6f s, +%.2f steps)\n",
           s->couple->rx->trig_time[0], tc, tb, tb_ref, (tb - tb_ref) / H_ODE, tr, tr_ref,
           (tr - tr_ref) / H_ODE);
    printf("mass in %.9g kg (ref %.9g), pay-in %.6g m (ref %.6g), drift %.3g\n", g->mass_in,
           mass_ref, r->payout_pretensioner, pay_ref, drift);
    CHECK(fabs(tb - tb_ref) < H_ODE);
    CHECK(fabs(tr - tr_ref) < H_ODE);
    CHECK_NEAR(g->mass_in, mass_ref, 1e-12);
    CHECK(r->fired && r->locked);
    CHECK_NEAR(r->payout_pretensioner, pay_ref, 1e-12);
    FIG("stage1_engine.trigger_bag_late_steps", "%.2f", (tb - tb_ref) / H_ODE);
    FIG("stage1_engine.trigger_ret_late_steps", "%.2f", (tr - tr_ref) / H_ODE);
    FIG_TOL("stage1_engine.trigger_drift", "%.1e", drift, 1e-4);
    CHECK(drift < 1e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* before its contact comes, a triggered bag takes no gas and a triggered retractor stays
 * unfired, whatever its model default (the retractor's 12 ms) */
static void test_no_contact_no_fire(void)
{
    mcs_error err = {0};
    mb_model *m = mt_model_text("early.yaml", drop(0.02, "", ""), &err);
    CHECK(m != NULL);
    if (!m) return;
    mb_state *s = NULL;
    CHECK(mt_run(m, &s, &err) == MCS_OK);
    const fe_state *f = s->couple->fe;
    CHECK(f->restraint->bag[0].mass_in == 0);
    CHECK(!f->restraint->retractor[0].fired);
    CHECK(f->restraint->retractor[0].payout_pretensioner == 0);
    CHECK(isinf(mb_couple_fire_time(m, s, MB_TRIG_RETRACTOR, 0)));
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* bad input: exit 2 at FILE:LINE:COL of the key */
static void expect_error(const char *text, const char *where, const char *what)
{
    mcs_error err = {0};
    mb_model *m = mt_model_text("bad.yaml", text, &err);
    CHECK(m == NULL);
    CHECK(mcs_status_exit_code(err.status) == 2);
    CHECK_STR_CONTAINS(err.msg, where);
    CHECK_STR_CONTAINS(err.msg, what);
    if (!strstr(err.msg, where) || !strstr(err.msg, what)) fprintf(stderr, "  got: %s\n", err.msg);
    mb_model_destroy(&m);
}

/* text with the first `from` replaced by `to` (static buffer) */
static const char *replaced(const char *text, const char *from, const char *to)
{
    static char buf[8192];
    const char *p = strstr(text, from);
    if (!p) return text;
    snprintf(buf, sizeof buf, "%.*s%s%s", (int)(p - text), text, to, p + strlen(from));
    return buf;
}

static void test_bad_input_is_located(void)
{
    /* a trigger naming an unknown contact (line 31: the bag's trigger) */
    expect_error(replaced(drop(0.01, "", ""), "ball_ground}}", "ball_gruond}}"), "bad.yaml:31:37:",
                 "ball_gruond");
    /* fire_time beside a trigger */
    expect_error(replaced(drop(0.01, "", ""), "load_limit: 0,", "fire_time: 1 ms,"),
                 "bad.yaml:33:79:", "fire_time and trigger");
    /* an anchor body that does not exist */
    expect_error(replaced(drop(0.01, "", ""), "load_limit: 0,", "anchor_body: x,"),
                 "bad.yaml:33:81:", "unknown body 'x'");
    /* a slip ring's body likewise */
    expect_error(replaced(drop(0.01, "", ""), "  retractors:",
                          "  sliprings: [{name: r, part: belt, point: [1, 1, 0.5], body: y}]\n"
                          "  retractors:"),
                 "bad.yaml:32:63:", "unknown body 'y'");
}

/* through `mcrash stage1`: the attribute fire_time of /stage1/airbag/bag and
 * /stage1/retractor/ret (within one ODE step of the references above); `mcrash stage3` of
 * the same scenario refuses the trigger at its key (exit 2) */
static void test_fire_time_written(void)
{
    char dir[] = "/tmp/mcrash_trig_XXXXXX", path[96], out[96], args[256];
    if (!mkdtemp(dir)) return;
    snprintf(path, sizeof path, "%s/drop.yaml", dir);
    snprintf(out, sizeof out, "%s/drop.h5", dir);
    const double tc = sqrt(2 * H_DROP / G);
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(drop(tc + 0.015, ", delay: 12 ms", ", force: 50 N, delay: 2 ms"), f);
        fclose(f);
    }
    snprintf(args, sizeof args, "stage1 %s -o %s --quiet", path, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    mcs_results *h = NULL;
    mcs_error err = {0};
    double tb = NAN, tr = NAN;
    if (mcs_results_open(&h, out, &err) == MCS_OK) {
        CHECK(mcs_results_attr_double(h, "/stage1/airbag/bag", "fire_time", &tb, &err) == MCS_OK);
        CHECK(mcs_results_attr_double(h, "/stage1/retractor/ret", "fire_time", &tr, &err) ==
              MCS_OK);
        mcs_results_close(&h);
    }
    printf("fire_time attributes: bag %.6f s, retractor %.6f s\n", tb, tr);
    CHECK(fabs(tb - (tc + 0.012)) < H_ODE);
    CHECK(fabs(tr - (tc + tau_force(50) + 0.002)) < H_ODE);
    snprintf(args, sizeof args, "stage3 %s -o %s --quiet", path, out);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "drop.yaml:31:");
    CHECK_STR_CONTAINS(r->err, "stage-1 bodies");
    snprintf(args, sizeof args, "rm -rf %s", dir);
    if (system(args)) printf("  could not remove %s\n", dir);
}

int main(void)
{
    RUN(test_fires_on_first_contact);
    RUN(test_no_contact_no_fire);
    RUN(test_bad_input_is_located);
    RUN(test_fire_time_written);
    TEST_END();
}

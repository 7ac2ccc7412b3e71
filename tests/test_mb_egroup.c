/* tests for stage1_mb/mb_egroup.c: the energy balance of a group of bodies (the rider) and the
 * energy it transfers to each contact partner (the 2023 paper's Eq. 9 and Fig. 24b).
 * References, none computed by the code under test:
 * - a free body whose only loads are gravity and one partner: the energy it transferred to
 *   that partner is its own loss of kinetic + potential energy, M v^2 / 2 + I w^2 / 2 - M g.x
 *   from its state (the work-energy theorem);
 * - a belt through a load limiter (F_lim = 2 kN, paper Sec. 2.3.1) stopping a sled: what the
 *   sled transfers to the belt is F_lim times the limiter's payout plus the belt's elastic energy
 *   at F_lim, F_lim^2 / (2 k) (k = EA / l the series stiffness of segment and belt), up to the
 *   belt's own kinetic energy (its 20 g, bounded in the test);
 * - the split: the partners' series sum to contact_total, and kinetic + potential + internal +
 *   contact_total stays at its t = 0 value (written to and read back from a results file). */
#include "core/mcs_results.h"
#include "fe/fe_restraint.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_egroup.h"
#include "tests/cli_util.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_couple_test_util.h"
#include "tests/mb_test_util.h"

#include <stdlib.h>
#include <unistd.h>

/* the body's kinetic + potential energy from its state (gravity g along -z) */
static double body_energy(const mb_model *m, const mb_state *s, int b, double g)
{
    mb_body_kin k;
    mb_body_get(s->world, b, &k);
    const double *I = m->body[b].inertia; /* principal here: Ixx Iyy Izz */
    double w[3];
    for (int i = 0; i < 3; i++) /* body axes: R^T w */
        w[i] = k.rot[i] * k.angvel[0] + k.rot[3 + i] * k.angvel[1] + k.rot[6 + i] * k.angvel[2];
    const double M = m->body[b].mass;
    return 0.5 * M * (k.vel[0] * k.vel[0] + k.vel[1] * k.vel[1] + k.vel[2] * k.vel[2]) +
           0.5 * (I[0] * w[0] * w[0] + I[1] * w[1] * w[1] + I[2] * w[2] * w[2]) + M * g * k.pos[2];
}

/* run m; after every step compare the partner's contact energy with the body's loss of
 * kinetic + potential energy: the largest difference over the largest loss [-]; the loss at
 * the end and its largest value */
static double drop_check(const mb_model *m, const char *partner, double g, double *loss_end,
                         double *loss_max)
{
    mcs_error err = {0};
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const int gi = mb_egroup_find(m, "rider"), p = mb_egroup_partner_find(m, gi, partner);
    CHECK(gi == 0 && p >= 0);
    if (st || gi < 0 || p < 0) return INFINITY;
    const double e0 = body_energy(m, s, 0, g);
    double worst = 0, *pe = calloc((size_t)mb_egroup_npartner(m, gi), sizeof *pe), e[5];
    *loss_max = 0;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        mb_egroup_now(m, s, gi, e, pe);
        const double loss = e0 - body_energy(m, s, 0, g);
        worst = fmax(worst, fabs(pe[p] - loss));
        *loss_max = fmax(*loss_max, loss), *loss_end = loss;
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    free(pe);
    mb_state_destroy(&s);
    return worst / *loss_max;
}

/* A 5 kg ball (R 50 mm) falls at 3 m/s under gravity onto a fixed-bottom foam block (the
 * concept's leg-protector foam, fe/mat/fe_foam.c): the energy it transferred to the block equals
 * its loss of kinetic + potential energy at every step. */
#define FOAM_YAML                                                                                  \
    "mcrash: 1\nname: foam drop\n"                                                                 \
    "simulation: {end_time: 40 ms, time_step: 10 us, output_rate: 10 kHz}\n"                       \
    "environment: {gravity: 9.81 m/s^2}\n"                                                         \
    "bodies:\n"                                                                                    \
    "  - {name: rider_ball, mass: 5, inertia: [0.005, 0.005, 0.005], position: [0, 0, 0.051],\n"   \
    "     velocity: [0.5, 0, -3], angular_velocity: [0, 0, 0],\n"                                  \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.05, 0.05, 0.05]}]}\n"      \
    "fe:\n  parts:\n    - name: block\n"                                                           \
    "      mesh: {generate: box, size: [0.12, 0.12, 0.03], divisions: [6, 6, 2],\n"                \
    "             origin: [-0.06, -0.06, -0.03]}\n"                                                \
    "      section: {type: solid}\n"                                                               \
    "      material: {model: foam, density: 425 kg/m^3, youngs_modulus: 20 MPa,\n"                 \
    "        curves: [{rate: 1, points: [[0.05, 0.15 MPa], [0.5, 0.3 MPa], [0.7, 0.8 MPa],\n"      \
    "                                    [0.85, 4 MPa]]},\n"                                       \
    "                 {rate: 100, points: [[0.05, 0.6 MPa], [0.5, 1.0 MPa], [0.7, 2.0 MPa],\n"     \
    "                                      [0.85, 8 MPa]]}],\n"                                    \
    "        hysteresis: 0.2}\n"                                                                   \
    "  boundary: [{part: block, where: z_min, fix: all}]\n"                                        \
    "  contacts: [{type: bodies, parts: [block], bodies: [rider_ball], friction: 0.3}]\n"

static void test_drop_on_foam(void)
{
    mb_model *m = mc_model("foam.yaml", FOAM_YAML);
    if (!m) return;
    const char *cat = NULL;
    CHECK(mb_egroup_count(m) == 1 && mb_egroup_npartner(m, 0) == 1);
    CHECK(strcmp(mb_egroup_partner(m, 0, 0, &cat), "block") == 0 && strcmp(cat, "foam") == 0);
    double end, peak, rel = drop_check(m, "block", 9.81, &end, &peak);
    printf("foam: contact energy vs the ball's loss of kinetic + potential energy: largest "
           "difference %.2e of %.3f J (%.3f J at the end)\n",
           rel, peak, end);
    FIG_TOL("energy.foam_drop_err", "%.1e", rel, 1e-5);
    FIG("energy.foam_drop_peak_j", "%.1f", peak);
    CHECK(rel < 2e-4); /* the rolling ball: ODE's rotation update is not the mean velocity's */
    CHECK(peak > 0.5 * 5 * (0.25 + 9)); /* the ball stopped in the foam: all its kinetic energy
                                           and some potential energy went there */
    mb_model_destroy(&m);
}

/* A 2 kg ball falls at 4 m/s (no gravity) onto a fabric sheet held at its four edges (an
 * airbag's membrane, fe/mat/fe_fabric.c): the ball stretches it and rebounds; the energy it
 * transferred equals its kinetic energy loss at every step. */
#define SHEET_YAML                                                                                 \
    "mcrash: 1\nname: sheet drop\n"                                                                \
    "simulation: {end_time: 30 ms, time_step: 10 us, output_rate: 10 kHz}\n"                       \
    "environment: {gravity: 0}\n"                                                                  \
    "bodies:\n"                                                                                    \
    "  - {name: rider_ball, mass: 2, inertia: [0.002, 0.002, 0.002], position: [0, 0, 0.0505],\n"  \
    "     velocity: [0, 0, -4], angular_velocity: [0, 0, 0],\n"                                    \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.05, 0.05, 0.05]}]}\n"      \
    "fe:\n  parts:\n    - name: sheet\n"                                                           \
    "      mesh: {generate: plate, size: [0.3, 0.3], divisions: [20, 20],\n"                       \
    "             origin: [-0.15, -0.15, 0]}\n"                                                    \
    "      section: {type: membrane, thickness: 0.4 mm}\n"                                         \
    "      material: {model: fabric, density: 1000, youngs_modulus: 0.5 GPa, poisson: 0.3}\n"      \
    "  boundary: [{part: sheet, where: x_min, fix: all}, {part: sheet, where: x_max, fix: all},\n" \
    "             {part: sheet, where: y_min, fix: all}, {part: sheet, where: y_max, fix: all}]\n" \
    "  contacts: [{name: bag, type: bodies, parts: [sheet], bodies: [rider_ball]}]\n"

static void test_drop_on_membrane(void)
{
    mb_model *m = mc_model("sheet.yaml", SHEET_YAML);
    if (!m) return;
    const char *cat = NULL;
    CHECK(mb_egroup_npartner(m, 0) == 1);
    CHECK(strcmp(mb_egroup_partner(m, 0, 0, &cat), "bag") == 0 && strcmp(cat, "airbags") == 0);
    double end, peak, rel = drop_check(m, "bag", 0, &end, &peak);
    printf("membrane: contact energy vs the ball's kinetic energy loss: largest difference "
           "%.2e of %.3f J (%.3f J at the end)\n",
           rel, peak, end);
    CHECK(rel < 1e-12);               /* translation only: the mean velocity's work is exact */
    CHECK(peak > 0.5 * 0.5 * 2 * 16); /* the sheet took at least half the 16 J */
    mb_model_destroy(&m);
}

/* The belt: 0.5 m of truss (EA 4e5 N, 20 g) from the retractor's end at x = 0.5 m to its far
 * end attached to a 10 kg sled leaving at 10 m/s; the retractor at the world anchor x = 0 is
 * locked from t = 0 with a 2 kN limiter (test_mb_couple_anchor's sled, the belt the other way
 * round: here the sled pulls through an attached node). The segment (l0 0.5 m) and the belt
 * in series: k = EA / 1 m. */
#define EA 4e5
#define F_LIM 2000.0
static const char *belt_yaml =
    "mcrash: 1\nname: belt\n"
    "simulation: {end_time: 30 ms, time_step: 10 us, output_rate: 10 kHz}\n"
    "environment: {gravity: 0}\n"
    "bodies:\n"
    "  - {name: rider_sled, mass: 10, inertia: [0.1, 0.1, 0.1], position: [1, 0, 0],\n"
    "     velocity: [10, 0, 0], angular_velocity: [0, 0, 0]}\n"
    "fe:\n  parts:\n"
    "    - name: belt\n"
    "      mesh: {generate: line, origin: [0.5, 0, 0], end: [1, 0, 0], divisions: 1}\n"
    "      section: {type: truss, area: 40 mm^2, tension_only: true}\n"
    "      material: {model: elastic, density: 1000, youngs_modulus: 10 GPa, poisson: 0}\n"
    "      attach: {body: rider_sled, where: x_max}\n"
    "  retractors:\n"
    "    - {name: ret, part: belt, where: x_min, anchor: [0, 0, 0],\n"
    "       lock_time: 0, fire_time: 1 s, load_limit: 2 kN}\n";

static void test_belt_through_limiter(void)
{
    mb_model *m = mc_model("belt.yaml", belt_yaml);
    if (!m) return;
    const char *cat = NULL;
    CHECK(mb_egroup_npartner(m, 0) == 1);
    CHECK(strcmp(mb_egroup_partner(m, 0, 0, &cat), "belt") == 0 && strcmp(cat, "belts") == 0);
    double end, peak, rel = drop_check(m, "belt", 0, &end, &peak);
    mcs_error err = {0};
    mb_state *s = NULL;
    CHECK(mt_run(m, &s, &err) == MCS_OK);
    double e[5], pe[1];
    mb_egroup_now(m, s, 0, e, pe);
    const fe_retractor_state *r = &s->couple->fe->restraint->retractor[0];
    const double ref = F_LIM * r->payout_limiter + F_LIM * F_LIM / (2 * EA / 1.0);
    const double err_pct = 100 * (pe[0] / ref - 1);
    printf("belt: transferred %.3f J; F_lim x payout %.4f m + F_lim^2 / 2k = %.3f J (%+.3f %%); "
           "against the sled's own loss %.2e\n",
           pe[0], r->payout_limiter, ref, err_pct, rel);
    FIG_TOL("energy.belt_limiter_err_pct", "%.2f", fabs(err_pct), 0.02);
    CHECK(rel < 1e-6); /* the attached node's force at its point: exact for a translating body */
    /* the belt's kinetic energy (its 20 g at up to 10 m/s: <= 1 J of ~300 J) is the rest */
    CHECK(fabs(err_pct) < 0.5);
    CHECK(r->payout_limiter > 0.1);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Two balls, no gravity: b1 (1 kg, 2 m/s, a little sideways) strikes b2 (2 kg, at rest)
 * through a damped contact with friction. The group "one" (b1) transfers to its one partner,
 * the contact, its own loss of kinetic energy (spin included); the group "pair" (both) has no
 * partner: the contact is internal, and its kinetic + internal energy (the contact's stored +
 * dissipated) stays at b1's initial 2.045 J up to the engine's own balance error. */
#define BALLS_YAML                                                                                 \
    "mcrash: 1\nname: two balls\n"                                                                 \
    "simulation: {end_time: 20 ms, time_step: 10 us, output_rate: 10 kHz}\n"                       \
    "environment: {gravity: 0}\n"                                                                  \
    "characteristics:\n"                                                                           \
    "  pad: {loading: [[0, 0], [0.01, 10000]], damping: 20 N s/m}\n"                               \
    "bodies:\n"                                                                                    \
    "  - {name: b1, mass: 1, inertia: [0.004, 0.004, 0.004], position: [0, 0, 0],\n"               \
    "     velocity: [2, 0.3, 0], angular_velocity: [0, 0, 0],\n"                                   \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"         \
    "  - {name: b2, mass: 2, inertia: [0.008, 0.008, 0.008], position: [0.205, 0.05, 0],\n"        \
    "     velocity: [0, 0, 0], angular_velocity: [0, 0, 0],\n"                                     \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"         \
    "contacts: [{name: hit, a: b1, b: b2, characteristic: pad, friction: 0.2}]\n"                  \
    "energy_groups:\n"                                                                             \
    "  pair: {bodies: [b1, b2]}\n"                                                                 \
    "  one: {bodies: b1, categories: {h*: struck ball}}\n"

static void test_scenario_groups(void)
{
    mb_model *m = mc_model("balls.yaml", BALLS_YAML);
    if (!m) return;
    const int gp = mb_egroup_find(m, "pair"), g1 = mb_egroup_find(m, "one");
    const char *cat = NULL;
    CHECK(mb_egroup_count(m) == 2 && gp == 0 && g1 == 1 && mb_egroup_find(m, "rider") < 0);
    CHECK(mb_egroup_npartner(m, gp) == 0 && mb_egroup_npartner(m, g1) == 1);
    /* the category from the scenario's categories (derived: bodies) */
    CHECK(strcmp(mb_egroup_partner(m, g1, 0, &cat), "hit") == 0 &&
          strcmp(cat, "struck ball") == 0);
    mcs_error err = {0};
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const double e0 = st ? 0 : body_energy(m, s, 0, 0);
    double worst1 = 0, worstp = 0, peak = 0, e[5], pe[1];
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        mb_egroup_now(m, s, g1, e, pe);
        const double loss = e0 - body_energy(m, s, 0, 0);
        worst1 = fmax(worst1, fabs(pe[0] - loss)), peak = fmax(peak, loss);
        mb_egroup_now(m, s, gp, e, pe);
        worstp = fmax(worstp, fabs(e[0] + e[2] - e0));
        CHECK(e[3] == 0);
    }
    CHECK(st == MCS_OK);
    printf("two balls: b1's transfer to the contact vs its kinetic energy loss %.2e of %.3f J; "
           "the pair's kinetic + internal vs its initial %.4f J: %.2e J; the model's drift %.2e\n",
           worst1 / peak, peak, e0, worstp, mb_energy_drift(m, s));
    FIG("energy.balls_pair_drift", "%.0e", mb_energy_drift(m, s));
    CHECK(peak > 1.0);           /* b1 gave b2 most of its energy */
    CHECK(worst1 < 2e-4 * peak); /* test_drop_on_foam's: the spin */
    /* the contact's element energy (stored + damper + friction, as /stage1/energy takes it)
     * against the bodies' work: the engine's own balance error of this stiff contact (its
     * drift, the same two bodies and contact) and nothing more */
    CHECK(fabs(worstp / e0 - mb_energy_drift(m, s)) < 1e-6);
    CHECK(worstp < 1e-2 * e0);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    /* a name that matches no body: located */
    char y[4096];
    snprintf(y, sizeof y, "%s  bad: {bodies: [b1, rider_*]}\n", BALLS_YAML);
    mcs_error e2 = {0};
    mb_model *bad = mt_model_text("bad.yaml", y, &e2);
    CHECK(bad == NULL);
    CHECK_STR_CONTAINS(e2.msg, "no body matches 'rider_*'");
    CHECK_STR_CONTAINS(e2.msg, "bad.yaml:");
    mb_model_destroy(&bad);
    snprintf(y, sizeof y, "%s  bad: {bodies: [b1], categories: {miss: x}}\n", BALLS_YAML);
    e2 = (mcs_error){0};
    bad = mt_model_text("bad.yaml", y, &e2);
    CHECK(bad == NULL);
    CHECK_STR_CONTAINS(e2.msg, "'miss' matches no partner of group 'bad'");
    mb_model_destroy(&bad);
}

/* the results file: the series of the group, the partners' sum and the closure */
static void test_results_file(void)
{
    mb_model *m = mc_model("foam.yaml", FOAM_YAML);
    if (!m) return;
    char path[] = "/tmp/mcrash_egroup_XXXXXX.h5";
    int fd = mkstemps(path, 3);
    CHECK(fd >= 0);
    if (fd >= 0) close(fd);
    mb_run_opts o = {.out_path = path, .quiet = 1};
    mcs_error err = {0};
    CHECK(mb_run(m, &o, NULL, &err) == MCS_OK);
    mcs_results *r = NULL;
    CHECK(mcs_results_open(&r, path, &err) == MCS_OK);
    mcs_array a[6] = {0};
    static const char *const nm[6] = {"kinetic",       "potential", "internal",
                                      "contact_total", "total",     "contact/block"};
    for (int k = 0; k < 6; k++) {
        char p[128];
        snprintf(p, sizeof p, "/stage1/energy_groups/rider/%s", nm[k]);
        CHECK(mcs_results_read(r, p, &a[k], &err) == MCS_OK);
    }
    char *cat = NULL, *bodies = NULL;
    CHECK(mcs_results_attr_str(r, "/stage1/energy_groups/rider/contact/block", "category", &cat,
                               &err) == MCS_OK &&
          strcmp(cat, "foam") == 0);
    CHECK(mcs_results_attr_str(r, "/stage1/energy_groups/rider", "bodies", &bodies, &err) ==
              MCS_OK &&
          strcmp(bodies, "rider_ball") == 0);
    double worst_sum = 0, worst_total = 0;
    const size_t n = a[0].n;
    for (size_t t = 0; t < n && a[5].n == n; t++) {
        const double *v[6] = {a[0].v, a[1].v, a[2].v, a[3].v, a[4].v, a[5].v};
        worst_sum = fmax(worst_sum, fabs(v[5][t] - v[3][t]));
        worst_total = fmax(worst_total, fabs(v[0][t] + v[1][t] + v[2][t] + v[3][t] - v[4][0]));
    }
    printf("file: %zu rows; |sum of partners - contact_total| <= %.2e J, |K + P + I + C - E0| <= "
           "%.2e J of %.3f J\n",
           n, worst_sum, worst_total, a[4].n ? a[4].v[0] : 0.0);
    CHECK(n == (size_t)m->nout);
    CHECK(worst_sum == 0);
    CHECK(a[4].n && worst_total < 2e-4 * a[4].v[0]); /* test_drop_on_foam's */
    /* `mcrash energy`: the ranking's one category is the block's, the balance the file's */
    char args[128];
    snprintf(args, sizeof args, "energy %s --json", path);
    cli_result *c = cli_run(args);
    CHECK(c->status == 0);
    const char *key = "\"categories\": [{\"name\": \"foam\", \"energy\": ";
    const char *cf = strstr(c->out, key);
    CHECK(cf != NULL);
    if (cf && a[5].n == n && n)
        CHECK_NEAR(strtod(cf + strlen(key), NULL), a[5].v[n - 1], 1e-8 * a[4].v[0]);
    snprintf(args, sizeof args, "energy %s --group nobody", path);
    CHECK(cli_run(args)->status == 2);
    snprintf(args, sizeof args, "energy %s --stage 3", path);
    c = cli_run(args);
    CHECK(c->status == 2);
    CHECK_STR_CONTAINS(c->err, "no /stage3/energy_groups");
    free(cat), free(bodies);
    for (int k = 0; k < 6; k++)
        mcs_array_free(&a[k]);
    mcs_results_close(&r);
    unlink(path);
    mb_model_destroy(&m);
}

/* a model that writes stage 2 (mb_opts.stage, as a stage-2 run's): the group under /stage2,
 * which `mcrash energy` finds without --stage */
static void test_stage2_output(void)
{
    mcs_error err = {0};
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    mb_opts o = mb_opts_default();
    o.stage = 2;
    CHECK(mcs_scenario_load_text("s2.yaml", SHEET_YAML, strlen(SHEET_YAML), &scn, &err) == 0);
    CHECK(mb_model_build(scn, &o, &m, &err) == MCS_OK);
    mcs_scenario_destroy(&scn);
    if (!m) return;
    char path[] = "/tmp/mcrash_egroup2_XXXXXX.h5";
    int fd = mkstemps(path, 3);
    if (fd >= 0) close(fd);
    mb_run_opts ro = {.out_path = path, .quiet = 1};
    CHECK(mb_run(m, &ro, NULL, &err) == MCS_OK);
    mcs_results *r = NULL;
    CHECK(mcs_results_open(&r, path, &err) == MCS_OK);
    CHECK(r && mcs_results_kind(r, "/stage2/energy_groups/rider/contact/bag") == MCS_RES_DATASET);
    CHECK(r && mcs_results_kind(r, "/stage1/energy_groups") == MCS_RES_NONE);
    mcs_results_close(&r);
    char args[128];
    snprintf(args, sizeof args, "energy %s", path);
    cli_result *c = cli_run(args);
    CHECK(c->status == 0);
    CHECK_STR_CONTAINS(c->out, "stage 2, group rider");
    unlink(path);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_drop_on_foam);
    RUN(test_drop_on_membrane);
    RUN(test_belt_through_limiter);
    RUN(test_scenario_groups);
    RUN(test_results_file);
    RUN(test_stage2_output);
    TEST_END();
}

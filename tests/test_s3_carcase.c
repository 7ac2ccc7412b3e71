/* test_s3_carcase: ISO 13232 413-0/13.4 in stage 3, the generated FE motorcycle into the
 * generated FE side of the stationary sedan (scenarios/iso13232_413-0_13.4_sedan_stage3.yaml;
 * stage3_fe/s3_carcase.h; docs/validation_stage3.md "The 413 car case").
 * make test: the coarse models (motorcycle 40 mm, sedan 80 mm), the first 10 ms, the road
 * frictionless so that nothing outside the two vehicles pushes them along x. make verify: the
 * scenario's road friction, the coarse models for 60 ms. References, each independent of the
 * code under test:
 *   - the masses by hand from the stage-1 model files: motorcycle 149 + 10 + 5 + 8 + 12 + 9 +
 *     15 = 208 kg (sport_208kg.yaml), sedan 1548 + 40 + 4 x 20 = 1668 kg (sedan_1668kg.yaml);
 *   - the initial kinetic energy by hand, 20 087 J (test_s3_wallcase.c: 1/2 M v^2 + the
 *     wheels' spin);
 *   - momentum: with no horizontal force from outside, m1 v1 + m2 v2 = m1 v0 along x at every
 *     row (Newton's third law between the two vehicles);
 *   - the plastic impact of two free bodies (closed form): both end at v_c = m1 v0 / (m1 + m2)
 *     = 1.486 m/s; a coefficient of restitution e puts the struck body at (1 + e) v_c;
 *   - the first contact: the sill's outer face 22.4 mm ahead of the tyre (1.7424 - 1.72 m) at
 *     13.4 m/s, 1.67 ms;
 *   - energy conservation, hourglass energy < 10 % of internal and added mass < 2 % (the
 *     issue's bounds). */
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/s3_test_util.h"

#include "core/mcs_results.h"
#include "fe/fe_scn_build.h"
#include "stage3_fe/s3_moto.h"
#include "stage3_fe/s3_run.h"
#include "stage3_fe/s3_scenario.h"
#include "stage3_fe/s3_sedan.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define V0 13.4
#define M_MOTO 208.0  /* 149 + 10 + 5 + 8 + 12 + 9 + 15 kg, sport_208kg.yaml's bodies */
#define M_SEDAN 1668.0 /* 1548 + 40 + 4 x 20 kg, sedan_1668kg.yaml's bodies */
#define E_KIN0 (0.5 * 208 * V0 * V0 + 0.5 * 0.6 * pow(V0 / 0.30, 2) + 0.5 * 0.9 * pow(V0 / 0.315, 2))
#define T_CONTACT ((1.7424 - 1.72) / V0) /* the sill's outer face reached [s] */

static char tmpdir[64];

/* the car case with the element sizes, end time and (frictionless: 1) road replaced (include
 * merges by name), loaded as if it were a file in scenarios/ */
static mcs_scenario *load_case(double h_moto_mm, double h_sedan_mm, double end_ms, int frictionless)
{
    char text[1024];
    snprintf(text, sizeof text,
             "mcrash: 1\ninclude: [iso13232_413-0_13.4_sedan_stage3.yaml]\n"
             "stage3:\n  simulation: {end_time: %g ms}\n  fe:\n    parts:\n"
             "      - name: moto\n        mesh: {element_size: %g mm}\n"
             "      - name: sedan\n        mesh: {element_size: %g mm}\n%s",
             end_ms, h_moto_mm, h_sedan_mm,
             frictionless ? "    rigid_walls:\n      - {name: ground, friction: 0}\n" : "");
    mcs_scenario *s = NULL;
    mcs_error err = {0};
    CHECK(mcs_scenario_load_text("scenarios/car_case.yaml", text, strlen(text), &s, &err) ==
          MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    return s;
}

static int run_case(double hm, double hs, double end_ms, int frictionless, const char *out,
                    s3_summary *sum)
{
    mcs_scenario *scn = load_case(hm, hs, end_ms, frictionless), *s3 = NULL;
    mcs_error err = {0};
    fe_problem p = {0};
    mcs_status st = scn ? s3_scenario_compile(scn, &s3, &err) : MCS_ERR_KEY;
    if (!st) st = fe_scn_build(s3, &p, &err);
    if (!st) {
        s3_run_opts o = {.out_path = out, .scenario_text = mcs_scenario_text(scn), .quiet = 1};
        st = s3_run(&p, &o, sum, &err);
    }
    if (st) printf("  %s\n", err.msg);
    fe_problem_free(&p);
    mcs_scenario_destroy(&s3);
    mcs_scenario_destroy(&scn);
    return st == MCS_OK;
}

/* names of generated parts: <entry>_<component> passes the scenario check and the builder
 * refuses an unknown component at the entry naming it (exit-2 class, FILE:LINE:COL); a name
 * that no generating entry prefixes is refused by the check */
static void test_names(void)
{
    const char *bad[2] = {
        "mcrash: 1\ninclude: [iso13232_413-0_13.4_sedan_stage3.yaml]\nstage3:\n  fe:\n"
        "    contacts:\n      - {name: moto_front_sedan, a: [moto_front_tyer]}\n"
        "    parts:\n      - {name: moto, mesh: {element_size: 80 mm}}\n"
        "      - {name: sedan, mesh: {element_size: 160 mm}}\n",
        "mcrash: 1\ninclude: [iso13232_413-0_13.4_sedan_stage3.yaml]\nstage3:\n  fe:\n"
        "    contacts:\n      - {name: moto_front_sedan, a: [bike_front_tyre]}\n"};
    mcs_scenario *scn = NULL, *s3 = NULL;
    mcs_error err = {0};
    CHECK(mcs_scenario_load_text("scenarios/names.yaml", bad[0], strlen(bad[0]), &scn, &err) ==
          MCS_OK);
    fe_problem p = {0};
    mcs_status st = scn ? s3_scenario_compile(scn, &s3, &err) : MCS_ERR_KEY;
    if (!st) st = fe_scn_build(s3, &p, &err);
    CHECK(st != MCS_OK);
    printf("  %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "names.yaml:6:9: error:");
    CHECK_STR_CONTAINS(err.msg, "unknown part 'moto_front_tyer'");
    fe_problem_free(&p);
    mcs_scenario_destroy(&s3);
    mcs_scenario_destroy(&scn);
    mcs_error e2 = {0};
    CHECK(mcs_scenario_load_text("scenarios/names.yaml", bad[1], strlen(bad[1]), &scn, &e2) !=
          MCS_OK);
    CHECK_STR_CONTAINS(e2.msg, "unknown FE part 'bike_front_tyre'");
    mcs_scenario_destroy(&scn);
}

typedef struct {
    mcs_array t, ek, pitch, v1, v2, intr, intr2;
    double m1, m2, hg, ma, drift;
    int elements;
} run_data;

static int read_run(const char *out, run_data *d)
{
    mcs_results *h = NULL;
    mcs_error err = {0};
    if (mcs_results_open(&h, out, &err) != MCS_OK) return 0;
    int ok = rd(h, "/stage3/time", &d->t) && rd(h, "/stage3/energy/kinetic", &d->ek) &&
             rd(h, "/stage3/channels/moto_pitch", &d->pitch) &&
             rd(h, "/stage3/channels/moto_velocity", &d->v1) &&
             rd(h, "/stage3/channels/sedan_velocity", &d->v2) &&
             rd(h, "/stage3/channels/sedan_door_intrusion", &d->intr) &&
             rd(h, "/stage3/channels/sedan_door_inner_intrusion", &d->intr2);
    ok = ok && mcs_results_attr_double(h, "/stage3/channels/moto_velocity", "mass", &d->m1, &err) ==
                   MCS_OK;
    ok = ok && mcs_results_attr_double(h, "/stage3/channels/sedan_velocity", "mass", &d->m2,
                                       &err) == MCS_OK;
    mcs_results_attr_double(h, "/stage3", "hourglass_fraction_max", &d->hg, &err);
    mcs_results_attr_double(h, "/stage3", "mass_added_fraction", &d->ma, &err);
    mcs_results_attr_double(h, "/stage3", "energy_drift", &d->drift, &err);
    const size_t n = d->t.n;
    ok = ok && n > 10 && d->ek.n == n && d->pitch.n == n && d->v1.n == 3 * n &&
         d->v2.n == 3 * n && d->intr.n == n && d->intr2.n == n;
    mcs_results_close(&h);
    return ok;
}

static void free_run(run_data *d)
{
    mcs_array_free(&d->t), mcs_array_free(&d->ek), mcs_array_free(&d->pitch);
    mcs_array_free(&d->v1), mcs_array_free(&d->v2), mcs_array_free(&d->intr);
    mcs_array_free(&d->intr2);
}

/* make test: masses, momentum exchange, energies, the channels before and after the contact */
static void test_coarse(void)
{
    char out[128];
    snprintf(out, sizeof out, "%s/car_coarse.h5", tmpdir);
    s3_summary sum;
    CHECK(run_case(40, 80, 10, 1, out, &sum));
    run_data d = {0};
    CHECK(read_run(out, &d));
    const size_t n = d.t.n;
    if (n <= 10 || d.v1.n != 3 * n) goto done;
    printf("  %d elements, %ld steps (%.3g us), masses %.3f / %.3f kg (hand %.0f / %.0f)\n",
           sum.elements, sum.steps, 1e6 * sum.dt_initial, d.m1, d.m2, M_MOTO, M_SEDAN);
    CHECK_NEAR(d.m1, M_MOTO, 0.05);
    CHECK_NEAR(d.m2, M_SEDAN, 0.05);
    FIG("s3.car_coarse_elements", "%.0f", (double)sum.elements);
    /* momentum along x: the motorcycle's loss is the sedan's gain, to round-off */
    double dp = 0;
    for (size_t k = 0; k < n; k++)
        dp = fmax(dp, fabs(d.m1 * d.v1.v[3 * k] + d.m2 * d.v2.v[3 * k] - M_MOTO * V0));
    const double v1 = d.v1.v[3 * (n - 1)], v2 = d.v2.v[3 * (n - 1)];
    const double vc = M_MOTO * V0 / (M_MOTO + M_SEDAN);
    printf("  at %.1f ms: motorcycle %.3f m/s, sedan %.4f m/s along x (plastic impact's end: "
           "%.4f m/s); momentum m1 v1 + m2 v2 - m1 v0 within %.3g N s of %.0f\n",
           1e3 * d.t.v[n - 1], v1, v2, vc, dp, M_MOTO * V0);
    CHECK(dp < 1e-6 * M_MOTO * V0);
    CHECK(v2 > 0 && v2 < vc && v1 > vc && v1 < V0); /* the exchange under way, not ended */
    FIG("s3.car_coarse_v_sedan_ms", "%.3f", v2);
    FIG("s3.car_coarse_v_moto_ms", "%.2f", v1);
    /* energies */
    printf("  kinetic energy at t = 0: %.2f J (by hand %.2f J); drift %.3g; hourglass %.3g of "
           "internal at most; added mass %.3g\n",
           d.ek.v[0], E_KIN0, sum.energy_drift, sum.hourglass_fraction_max,
           sum.mass_added_fraction);
    CHECK_REL(d.ek.v[0], E_KIN0, 1e-4);
    CHECK(sum.energy_drift < 0.01);
    CHECK(sum.hourglass_fraction_max < 0.10 && sum.hourglass_fraction < 0.10);
    CHECK(sum.mass_added_fraction < 0.02);
    FIG("s3.car_coarse_hg_pct", "%.1f",
        100 * fmax(sum.hourglass_fraction, sum.hourglass_fraction_max));
    /* pitch and door intrusion: none before the first contact; the intrusion no more than the
     * motorcycle's travel towards the car since then */
    double pre = 0, rel = 0, imax = 0;
    for (size_t k = 0; k < n; k++) {
        if (d.t.v[k] < T_CONTACT) pre = fmax(pre, fmax(fabs(d.pitch.v[k]), d.intr.v[k]));
        if (k && d.t.v[k] > T_CONTACT)
            rel += (d.v1.v[3 * k] - d.v2.v[3 * k]) * (d.t.v[k] - d.t.v[k - 1]);
        imax = fmax(imax, d.intr.v[k]);
    }
    printf("  before %.2f ms: pitch and intrusion <= %.2g; at %.1f ms pitch %.4f rad, door "
           "intrusion %.1f mm (largest %.1f mm; travel towards the car since the contact %.0f "
           "mm)\n",
           1e3 * T_CONTACT, pre, 1e3 * d.t.v[n - 1], d.pitch.v[n - 1], 1e3 * d.intr.v[n - 1],
           1e3 * imax, 1e3 * rel);
    CHECK(pre < 1e-3);
    CHECK(imax <= rel);
    FIG("s3.car_coarse_intrusion_mm", "%.1f", 1e3 * imax);
    FIG("s3.car_coarse_pitch_deg", "%.2f", d.pitch.v[n - 1] * 180 / M_PI);
done:
    free_run(&d);
}

/* make verify: the scenario's road (friction 0.9 under the motorcycle), the coarse models for
 * 60 ms; the exchange against the plastic impact's closed form, pitch, intrusion, energies */
static void test_verify(void)
{
    if (!th_verify()) return;
    char out[128];
    snprintf(out, sizeof out, "%s/car_60.h5", tmpdir);
    s3_summary sum;
    CHECK(run_case(40, 80, 60, 0, out, &sum));
    run_data d = {0};
    CHECK(read_run(out, &d));
    const size_t n = d.t.n;
    if (n <= 10 || d.v1.n != 3 * n) goto done;
    const double vc = M_MOTO * V0 / (M_MOTO + M_SEDAN);
    const double v1 = d.v1.v[3 * (n - 1)], v2 = d.v2.v[3 * (n - 1)];
    double pmax = 0, tp = 0, imax = 0, ti = 0, imax2 = 0;
    for (size_t k = 0; k < n; k++) {
        if (d.pitch.v[k] > pmax) pmax = d.pitch.v[k], tp = d.t.v[k];
        if (d.intr.v[k] > imax) imax = d.intr.v[k], ti = d.t.v[k];
        imax2 = fmax(imax2, d.intr2.v[k]);
    }
    printf("  %d elements, %ld steps, %.0f s of wall time, drift %.3g, hourglass %.3g of "
           "internal at most, added mass %.3g\n",
           sum.elements, sum.steps, sum.wall_time_s, sum.energy_drift, sum.hourglass_fraction_max,
           sum.mass_added_fraction);
    printf("  at %.0f ms: motorcycle %.3f m/s, sedan %.3f m/s along x; plastic impact v_c = "
           "%.4f m/s: sedan / v_c = %.3f\n",
           1e3 * d.t.v[n - 1], v1, v2, vc, v2 / vc);
    printf("  pitch %.2f deg at %.0f ms (largest %.2f deg at %.1f ms); door intrusion largest "
           "%.0f mm at %.1f ms (inner panel %.0f mm)\n",
           d.pitch.v[n - 1] * 180 / M_PI, 1e3 * d.t.v[n - 1], pmax * 180 / M_PI, 1e3 * tp,
           1e3 * imax, 1e3 * ti, 1e3 * imax2);
    CHECK(sum.energy_drift < 0.02);
    CHECK(sum.hourglass_fraction_max < 0.10);
    CHECK(sum.mass_added_fraction < 0.02);
    CHECK(v2 > 0 && v2 < 2 * vc); /* between resting and an elastic impact's (1 + e) v_c */
    FIG("s3.car60_v_sedan_ms", "%.2f", v2);
    FIG("s3.car60_v_moto_ms", "%.2f", v1);
    FIG("s3.car60_pitch_deg", "%.1f", d.pitch.v[n - 1] * 180 / M_PI);
    FIG("s3.car60_pitch_max_deg", "%.1f", pmax * 180 / M_PI);
    FIG("s3.car60_intrusion_mm", "%.0f", 1e3 * imax);
    FIG("s3.car60_intrusion_inner_mm", "%.0f", 1e3 * imax2);
    FIG("s3.car60_hg_pct", "%.1f", 100 * sum.hourglass_fraction_max);
    mcs_results *h = NULL;
    mcs_error err = {0};
    char **parts = NULL;
    int np = 0;
    if (mcs_results_open(&h, out, &err) == MCS_OK &&
        mcs_results_list(h, "/stage3/parts", &parts, &np, &err) == MCS_OK) {
        for (int i = 0; i < np; i++) {
            char path[256];
            snprintf(path, sizeof path, "/stage3/parts/%s/energy/internal", parts[i]);
            const double e = last_of(h, path);
            if (e > 100) printf("  internal energy at the end: %-20s %6.0f J\n", parts[i], e);
        }
        mcs_results_list_free(&parts, np);
    }
    mcs_results_close(&h);
done:
    free_run(&d);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s3cc_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    s3_moto_register();
    s3_sedan_register();
    RUN(test_names);
    RUN(test_coarse);
    RUN(test_verify);
    char cmd[96];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) return 1;
    TEST_END();
}

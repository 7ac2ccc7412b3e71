/* test_s3_restraints.c: gas bags and retractors from the scenario keys (fe.airbags,
 * fe.retractors, sphere_shell, membrane sections, fabric) through `mcrash` stage 3 to
 * /stage3/airbag/<name>/... and /stage3/retractor/<name>/..., checked against closed forms;
 * bad input located at FILE:LINE:COL. */
#include "cli_util.h"
#include "core/mcs_results.h"
#include "harness.h"
#include "figures.h"
#include "s3_test_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char tmpdir[64];

/* scenarios/verification/airbag_sphere_inflation.yaml: a closed fabric sphere, ambient air
 * inside, an inflator of 0.2 kg/s at 600 K, no vents or leakage. Mass balance of a closed bag
 * (paper 2023 Eq. 4 without exhaust and leakage): m(t) = m0 + m_dot t, m0 = p_a V0 / (R T_a);
 * ideal gas p = m R T / V (Eq. 5). */
static void test_airbag_scenario(void)
{
    char out[128], args[512];
    snprintf(out, sizeof out, "%s/bag.h5", tmpdir);
    snprintf(args, sizeof args,
             "run scenarios/verification/airbag_sphere_inflation.yaml -o %s --quiet --json", out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"elements\": 768");
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array t = {0}, p = {0}, V = {0}, T = {0}, m = {0};
    CHECK(rd(h, "/stage3/time", &t) && rd(h, "/stage3/airbag/bag/pressure", &p) &&
          rd(h, "/stage3/airbag/bag/volume", &V) && rd(h, "/stage3/airbag/bag/temperature", &T) &&
          rd(h, "/stage3/airbag/bag/mass", &m));
    CHECK(strcmp(p.unit, "Pa") == 0 && strcmp(V.unit, "m^3") == 0 && strcmp(T.unit, "K") == 0 &&
          strcmp(m.unit, "kg") == 0);
    CHECK(p.n == t.n && m.n == t.n && t.n > 30);
    const double R = 287.05, m0 = 101325 * V.v[0] / (R * 293.15);
    double worst = 0, worst_gas = 0;
    for (size_t i = 0; i < t.n && i < m.n; i++) {
        worst = fmax(worst, fabs(m.v[i] - (m0 + 0.2 * t.v[i])) / m.v[i]);
        worst_gas = fmax(worst_gas, fabs(p.v[i] * V.v[i] - m.v[i] * R * T.v[i]) / (p.v[i] * V.v[i]));
    }
    printf("  airbag: m(t) = m0 + m_dot t within %.1e; p V = m R T within %.1e; end: %.0f Pa, "
           "V/V0 %.4f\n",
           worst, worst_gas, p.v[p.n - 1], V.v[V.n - 1] / V.v[0]);
    FIG("fe.s3_bag_mass_err", "%.0e", worst);
    CHECK(worst < 1e-14); /* 3e-15 stated */
    CHECK(worst_gas < 1e-14);
    CHECK(p.v[p.n - 1] > 101325 + 1e4 && V.v[V.n - 1] > V.v[0]);
    mcs_array_free(&t), mcs_array_free(&p), mcs_array_free(&V), mcs_array_free(&T);
    mcs_array_free(&m);
    mcs_results_close(&h);
    remove(out);
}

/* scenarios/verification/belt_retractor.yaml: a belt fixed at its far end, pretensioner fired
 * at 12 ms (paper 2023 Eq. 3: 100 mm in 15 ms), load limiter 2 kN. The pretensioner's payout
 * follows Eq. 3; once the tension reaches 2 kN (10 mm of pull on k_eff = 200 kN/m) it stays
 * there while the limiter pays out; limiter payout at the end = 100 mm - F_lim / k_eff. */
static void test_retractor_scenario(void)
{
    char out[128], args[512];
    snprintf(out, sizeof out, "%s/belt.h5", tmpdir);
    snprintf(args, sizeof args, "run scenarios/verification/belt_retractor.yaml -o %s --quiet", out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array t = {0}, pl = {0}, f = {0}, ll = {0};
    CHECK(rd(h, "/stage3/time", &t) &&
          rd(h, "/stage3/retractor/retractor/payout_pretensioner", &pl) &&
          rd(h, "/stage3/retractor/retractor/force", &f) &&
          rd(h, "/stage3/retractor/retractor/payout_limiter", &ll));
    CHECK(strcmp(f.unit, "N") == 0 && strcmp(pl.unit, "m") == 0 && f.n == t.n);
    double worst = 0, fmin_p = INFINITY, fmax_p = 0;
    for (size_t i = 0; i < t.n && i < pl.n && i < f.n; i++) {
        double tau = t.v[i] - 0.012;
        double eq3 = tau <= 0 ? 0 : tau < 0.015 ? -0.1 / 0.015 * tau : -0.1;
        worst = fmax(worst, fabs(pl.v[i] - eq3));
        if (t.v[i] > 0.015 && t.v[i] < 0.027) {
            fmin_p = fmin(fmin_p, f.v[i]);
            fmax_p = fmax(fmax_p, f.v[i]);
        }
    }
    double lim = ll.n ? ll.v[ll.n - 1] : 0, lim_x = 0.1 - 2000 / 2e5;
    printf("  retractor: |payout - Eq. 3| <= %.1e m; force %.1f..%.1f N in 15-27 ms; limiter "
           "payout %.2f mm (closed form %.2f mm)\n",
           worst, fmin_p, fmax_p, 1e3 * lim, 1e3 * lim_x);
    FIG("fe.s3_belt_limiter_payout_err_pct", "%+.1f", 100 * (lim / lim_x - 1));
    FIG("fe.s3_belt_plateau_min_n", "%.0f", fmin_p);
    CHECK(worst < 1e-12);
    CHECK(fmin_p > 0.98 * 2000 && fmax_p <= 2000 * (1 + 1e-12));
    CHECK_REL(lim, lim_x, 0.036); /* +1.2 % stated: the belt's own stretch beyond k_eff */
    mcs_array_free(&t), mcs_array_free(&pl), mcs_array_free(&f), mcs_array_free(&ll);
    mcs_results_close(&h);
    remove(out);
}

/* mesh.generate: flat_bag (fe/model/fe_mesh_shell.c), a 2D-design bag of two sewn panels: closed
 * (the airbag builder accepts it) and its volume at t = 0 by hand: the seam nodes at w = 0,
 * the panels' inner nodes at +-g/2, each membrane quad split into two triangles (volume under
 * a triangle: its area x the mean of its 3 heights). Inner cells enclose g du dv (both panels),
 * edge cells g/2 du dv (either diagonal: triangles with one and two raised nodes), corner cells
 * g/3 du dv (the diagonal through the inner node: both triangles hold it). With nu x nv cells:
 * V0 = g du dv ((nu - 2)(nv - 2) + (nu + nv - 4) + 4/3) = g du dv ((nu - 1)(nv - 1) + 1/3). */
static void test_flat_bag(void)
{
    char scn[128], out[128], args[512];
    snprintf(scn, sizeof scn, "%s/flat.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/flat.h5", tmpdir);
    write_text(scn, "mcrash: 1\nname: flat\nsimulation: {end_time: 0.2 ms, output_rate: 10 kHz}\n"
                    "fe:\n  parts:\n"
                    "    - name: bag\n"
                    "      mesh: {generate: flat_bag, size: [0.5, 0.4], gap: 10 mm,"
                    " element_size: 25 mm, axis: x, origin: [1, 0, 1]}\n"
                    "      section: {type: membrane, thickness: 0.4 mm}\n"
                    "      material: {model: fabric, density: 1000, youngs_modulus: 500 MPa,"
                    " poisson: 0.3}\n"
                    "  airbags:\n"
                    "    - {name: bag, parts: [bag], initial_pressure: 120 kPa}\n");
    snprintf(args, sizeof args, "run %s -o %s --quiet --json", scn, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    CHECK_STR_CONTAINS(r->out, "\"elements\": 1280"); /* 2 panels x 20 x 16 quads x 2 */
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array V = {0};
    CHECK(rd(h, "/stage3/airbag/bag/volume", &V) && V.n > 0);
    const double V0 = 0.010 * 0.025 * 0.025 * (19 * 15 + 1.0 / 3);
    printf("  flat_bag: V0 %.6e m^3 (closed form %.6e)\n", V.n ? V.v[0] : 0, V0);
    if (V.n) CHECK_REL(V.v[0], V0, 1e-12);
    mcs_array_free(&V);
    mcs_results_close(&h);
}

/* a gas bag on an open surface, and one on a part that does not exist, are refused at the
 * bag's line with what is wrong */
static void test_bad_bags_located(void)
{
    char scn[128], args[512];
    snprintf(scn, sizeof scn, "%s/open.yaml", tmpdir);
    write_text(scn, "mcrash: 1\nname: open\nsimulation: {end_time: 1 ms}\nfe:\n  parts:\n"
                    "    - name: can\n"
                    "      mesh: {generate: cylinder_shell, diameter: 0.2, length: 0.3,"
                    " element_size: 0.05}\n"
                    "      section: {type: membrane, thickness: 0.5 mm}\n"
                    "      material: {model: fabric, density: 1000, youngs_modulus: 500 MPa,"
                    " poisson: 0.3}\n"
                    "  airbags:\n"
                    "    - {name: bag, parts: [can]}\n");
    /* check builds the model as the run does: the same refusal */
    snprintf(args, sizeof args, "check %s", scn);
    cli_result *r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "open.yaml:11:");
    CHECK_STR_CONTAINS(r->err, "not closed");
    snprintf(args, sizeof args, "stage3 %s -o %s/open.h5", scn, tmpdir);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "open.yaml:11:");
    CHECK_STR_CONTAINS(r->err, "not closed");
    /* closed (an orthotropic fabric, a vent): runs */
    snprintf(scn, sizeof scn, "%s/closed.yaml", tmpdir);
    write_text(scn, "mcrash: 1\nname: closed\nsimulation: {end_time: 0.1 ms}\nfe:\n  parts:\n"
                    "    - name: can\n"
                    "      mesh: {generate: cylinder_shell, diameter: 0.2, length: 0.3,"
                    " element_size: 0.05, closed: true}\n"
                    "      section: {type: membrane, thickness: 0.5 mm}\n"
                    "      material: {model: fabric, density: 1000, youngs_modulus: 500 MPa,"
                    " poisson: 0.3, youngs_modulus_b: 300 MPa, shear_modulus: 20 MPa,"
                    " direction: [0, 0, 1], damping: 0.1}\n"
                    "  airbags:\n"
                    "    - {name: bag, parts: [can], initial_pressure: 150 kPa,"
                    " vents: [{area: 1 cm^2, discharge_coefficient: 0.7}]}\n");
    snprintf(args, sizeof args, "stage3 %s -o %s/closed.h5", scn, tmpdir);
    r = cli_run(args);
    CHECK(r->status == 0);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    snprintf(scn, sizeof scn, "%s/nopart.yaml", tmpdir);
    write_text(scn, "mcrash: 1\nname: nopart\nsimulation: {end_time: 1 ms}\nfe:\n  parts:\n"
                    "    - name: can\n"
                    "      mesh: {generate: sphere_shell, radius: 0.1, element_size: 0.05}\n"
                    "      section: {type: membrane, thickness: 0.5 mm}\n"
                    "      material: {model: fabric, density: 1000, youngs_modulus: 500 MPa,"
                    " poisson: 0.3}\n"
                    "  airbags:\n"
                    "    - {name: bag, parts: [tin]}\n");
    snprintf(args, sizeof args, "check %s", scn);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "nopart.yaml:11:");
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s3r_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_airbag_scenario);
    RUN(test_retractor_scenario);
    RUN(test_flat_bag);
    RUN(test_bad_bags_located);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd)) printf("  could not remove %s\n", tmpdir);
    TEST_END();
}

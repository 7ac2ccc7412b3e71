/* test_s3_solid.c: the stage-3 keys of springs, point masses and gravity (and later foam,
 * rigid parts, the fully integrated hex, mass scaling) from a scenario file to /stage3. */
#include "cli_util.h"
#include "core/mcs_results.h"
#include "harness.h"
#include "figures.h"
#include "s3_test_util.h"
#include "stage3_fe/s3_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char tmpdir[64];

/* a block with a 0.5 kg point mass falls under 1 g for 2 ms: the work of gravity is
 * M g^2 t^2 / 2 with M = rho V + 0.5 kg, all of it kinetic, the total constant; a spring
 * between two blocks at rest and with no gravity on them is not here (test_fe_discrete) */
static void test_free_fall_with_mass(void)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/fall.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/fall.h5", tmpdir);
    write_text(scn, "mcrash: 1\nname: fall\nsimulation: {end_time: 2 ms, output_rate: 50 kHz}\n"
                    "environment: {gravity: 9.81 m/s^2}\n"
                    "fe:\n  parts:\n    - name: block\n"
                    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [2, 2, 2]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000, youngs_modulus: 10 MPa, poisson: 0.3}\n"
                    "  masses: [{part: block, where: all, mass: 0.5 kg}]\n");
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    double t = last_of(h, "/stage3/time"), M = 1000 * 8e-6 + 0.5, g = 9.81;
    CHECK(t > 1.9e-3);
    CHECK_REL(last_of(h, "/stage3/energy/external_work"), 0.5 * M * g * g * t * t, 1e-3);
    CHECK_REL(last_of(h, "/stage3/energy/kinetic"), 0.5 * M * g * g * t * t, 1e-3);
    CHECK(fabs(last_of(h, "/stage3/energy/total")) < 1e-6 * 0.5 * M * g * g * t * t);
    mcs_results_close(&h);
}

/* two spring parts from a scenario: /stage3/parts/<part>/energy/internal is 1/2 k x^2 of each
 * (x from the block's displacement: the springs hold it from both sides) and the parts plus
 * the block add up to /stage3/energy/internal */
static void test_spring_parts_output(void)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/sparts.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/sparts.h5", tmpdir);
    write_text(scn, "mcrash: 1\nname: sparts\nsimulation: {end_time: 3 ms, output_rate: 10 kHz}\n"
                    "fe:\n  parts:\n    - name: block\n"
                    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [2, 2, 2]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000, youngs_modulus: 10 GPa, poisson: 0.3}\n"
                    "      initial_velocity: [0.2 m/s, 0, 0]\n"
                    "  springs:\n"
                    "    - {name: l, part: left, a: {part: block, point: [10 mm, 10 mm, 10 mm]},\n"
                    "       b: {point: [-0.1, 0.01, 0.01]},\n"
                    "       stiffness: 2 N/mm}\n"
                    "    - {name: r, part: right, a: {part: block, point: [10 mm, 10 mm, 10 mm]},\n"
                    "       b: {point: [0.12, 0.01, 0.01]},\n"
                    "       stiffness: 5 N/mm}\n");
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    double el = last_of(h, "/stage3/parts/left/energy/internal");
    double er = last_of(h, "/stage3/parts/right/energy/internal");
    double eb = last_of(h, "/stage3/parts/block/energy/internal");
    double et = last_of(h, "/stage3/energy/internal");
    printf("  spring parts in /stage3: left %.6g J, right %.6g J, block %.3g J, global %.6g J\n",
           el, er, eb, et);
    CHECK(el > 0 && er > 0);
    CHECK_REL(el + er + eb, et, 1e-12);
    /* both springs hold the block's centre node on one line: elongations u and -u, so
       E_left / E_right = (k_l u^2 / 2) / (k_r u^2 / 2) = k_l / k_r */
    FIG("fe.s3_spring_ratio_err", "%.0e", fabs(el / er / (2.0 / 5.0) - 1));
    CHECK_REL(el / er, 2.0 / 5.0, 6e-14); /* 2e-14 stated */
    mcs_results_close(&h);
}

/* bad spring and mass keys are located at FILE:LINE:COL */
static void test_spring_keys_located(void)
{
    char scn[128], args[512], out[128];
    snprintf(scn, sizeof scn, "%s/bad.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/bad.h5", tmpdir);
    write_text(scn, "mcrash: 1\nname: bad\nsimulation: {end_time: 1 ms}\n"
                    "fe:\n  parts:\n    - name: block\n"
                    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [1, 1, 1]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000, youngs_modulus: 10 MPa, poisson: 0.3}\n"
                    "  springs:\n"
                    "    - {name: s, a: {part: block, point: [0, 0, 0]}, b: {point: [0, 0, -1]},\n"
                    "       stiffness: 1 N/mm, curve: [[0, 0], [1 mm, 1 N]]}\n");
    snprintf(args, sizeof args, "stage3 %s -o %s", scn, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "bad.yaml:12:");
    CHECK_STR_CONTAINS(r->err, "give stiffness or curve, not both");
    write_text(scn, "mcrash: 1\nname: bad\nsimulation: {end_time: 1 ms}\n"
                    "fe:\n  parts:\n    - name: block\n"
                    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [1, 1, 1]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000, youngs_modulus: 10 MPa, poisson: 0.3}\n"
                    "  springs:\n"
                    "    - {name: s, a: {point: [0, 0, 0]}, b: {point: [0, 0, -1]}, stiffness: 1 N/mm}\n");
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "bad.yaml:11:");
    CHECK_STR_CONTAINS(r->err, "both ends are fixed anchors");
}

/* a 20 mm foam cube crushed to 50 % at 1/s (a prescribed top velocity) with two rate curves:
 * the internal energy is V0 int_0^0.5 S(e) de of the 1/s curve (the loading curve of that rate) */
static void foam_pad_crush(int full)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/foam.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/foam.h5", tmpdir);
    char text[2048];
    snprintf(text, sizeof text, "mcrash: 1\nname: foam\nsimulation: {end_time: 0.5 s, output_rate: 1 kHz}\n"
                    "fe:\n  parts:\n    - name: pad\n"
                    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [1, 1, 1]}\n"
                    "      section: {type: solid, formulation: %s}\n"
                    "      material:\n"
                    "        model: foam\n        density: 60 kg/m^3\n        youngs_modulus: 2 MPa\n"
                    "        curves:\n"
                    "          - {rate: 1, points: [[0.1, 0.1 MPa], [0.6, 0.2 MPa]]}\n"
                    "          - {rate: 1000, points: [[0.1, 0.2 MPa], [0.6, 0.4 MPa]]}\n"
                    "        hysteresis: 0.1\n"
                    "  boundary:\n"
                    "    - {part: pad, where: z_min, fix: all}\n"
                    "    - {part: pad, where: z_max, fix: all, velocity: [0, 0, -20 mm/s]}\n",
             full ? "full" : "one_point");
    write_text(scn, text);
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    double t = last_of(h, "/stage3/time"), e = 0.02 * t / 0.02;
    /* S = 1e6 e up to 0.1, then 0.1 MPa + 0.2 MPa (e - 0.1) */
    double w = 0.5 * 1e6 * 0.01 + 0.1e6 * (e - 0.1) + 0.5 * 0.2e6 * (e - 0.1) * (e - 0.1);
    w *= 8e-6;
    printf("  foam pad (%s hex): e %.4f, internal %.6g J, int S de %.6g J\n", full ? "full" : "one-point", e,
           last_of(h, "/stage3/energy/internal"), w);
    CHECK(e > 0.45);
    CHECK_REL(last_of(h, "/stage3/energy/internal"), w, 2e-3);
    mcs_results_close(&h);
}

static void test_foam_pad_crush(void)
{
    foam_pad_crush(0);
    foam_pad_crush(1); /* uniform strain: the eight points agree with the one */
}

/* a rigid steel block at 3 m/s onto a penalty floor (rigid
 * parts feel penalty walls): after the contact it leaves upwards; the energy balance holds */
static void test_rigid_block_drop(void)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/rigid.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/rigid.h5", tmpdir);
    write_text(scn, "mcrash: 1\nname: rigid\nsimulation: {end_time: 6 ms, time_step: 5 us}\n"
                    "fe:\n  parts:\n    - name: block\n"
                    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [2, 2, 2],"
                    " origin: [0, 0, 1 mm]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: rigid, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"
                    "      initial_velocity: [0, 0, -3 m/s]\n"
                    "  rigid_walls: [{name: floor, point: [0, 0, 0], normal: [0, 0, 1], method: penalty}]\n");
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    CHECK(sum.energy_drift < 0.01);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array f = {0};
    mcs_error e2 = {0};
    CHECK(mcs_results_read(h, "/stage3/rigidwall/floor/force", &f, &e2) == MCS_OK);
    double fmax_ = 0;
    for (size_t i = 0; i < f.n; i++) fmax_ = fmax(fmax_, f.v[i]);
    CHECK(fmax_ > 0);
    mcs_array_free(&f);
    /* after the bounce the kinetic energy is back (elastic penalty): 1/2 M v^2 within 2 % */
    double M = 7850 * 8e-6, ke = last_of(h, "/stage3/energy/kinetic");
    CHECK_REL(ke, 0.5 * M * 9, 0.02);
    mcs_results_close(&h);
}

/* fe.mass_scaling: the added mass is in the /stage3 attributes and the --json summary, and
 * the run goes at the target step */
static void test_mass_scaling_reported(void)
{
    char scn[128], out[128], args[512];
    snprintf(scn, sizeof scn, "%s/ms.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/ms.h5", tmpdir);
    /* a 10 x 10 x 10 mm block of 1 x 1 x 50 hexes (0.2 mm thick, step 0.2 mm / c times the
     * linear bulk viscosity's factor sqrt(1 + q2^2) - q2 = 0.94182, q2 = 0.06) scaled to a
     * 1 mm / c step x 0.9: every element gets f = 5 / 0.94182 = 5.3089, f^2 - 1 = 27.185 rho V
     * added (0.21341 kg of 7.85 g) */
    const double c = sqrt(210e9 * 0.7 / (1.3 * 0.4) / 7850), target = 0.9 * 1e-3 / c;
    char text[1024];
    snprintf(text, sizeof text,
             "mcrash: 1\nname: ms\nsimulation: {end_time: %.9g s}\n"
             "fe:\n  parts:\n    - name: blk\n"
             "      mesh: {generate: box, size: [10 mm, 10 mm, 10 mm], divisions: [1, 1, 50]}\n"
             "      section: {type: solid}\n"
             "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"
             "      initial_velocity: [0, 0, 1 m/s]\n"
             "  mass_scaling: {time_step: %.9g s}\n",
             100.5 * target, target);
    write_text(scn, text);
    snprintf(args, sizeof args, "stage3 %s -o %s --json", scn, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"mass_added_kg\": 0.21340");
    CHECK_STR_CONTAINS(r->out, "\"mass_added_fraction\": 27.18");
    CHECK_STR_CONTAINS(r->out, "\"dt_initial_s\": 1.4997");
    /* 101 steps at the target (the linear bulk viscosity is in the step at every sign of the
     * volume rate: round-off no longer shortens it) */
    const char *sp = strstr(r->out, "\"steps\": ");
    long steps = sp ? strtol(sp + 9, NULL, 10) : 0;
    CHECK(steps == 101);
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    double ma = 0, fr = 0;
    CHECK(mcs_results_attr_double(h, "/stage3", "mass_added", &ma, &err) == MCS_OK);
    CHECK(mcs_results_attr_double(h, "/stage3", "mass_added_fraction", &fr, &err) == MCS_OK);
    const double q2f = sqrt(1 + 0.06 * 0.06) - 0.06, f2 = 25 / (q2f * q2f);
    CHECK_REL(ma, (f2 - 1) * 7850 * 1e-6, 1e-6); /* the target went through 9 digits of text */
    CHECK_REL(fr, f2 - 1, 1e-6);
    mcs_results_close(&h);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s3s_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_spring_parts_output);
    RUN(test_free_fall_with_mass);
    RUN(test_spring_keys_located);
    RUN(test_foam_pad_crush);
    RUN(test_rigid_block_drop);
    RUN(test_mass_scaling_reported);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) return 1;
    TEST_END();
}

/* test_s3_wall: the stage-3 rigid-wall keys added with fe/step/fe_wall_motion.c (a wall `motion`
 * curve) from a scenario file to /stage3. */
#include "harness.h"
#include "s3_test_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char tmpdir[64];

/* a floor under a block, lifted by a velocity curve (a 0.5 m/s triangle over 2 ms: 0.5 mm,
 * then held): its displacement history ends at the curve's integral, 0.5 mm, it pushed the block (normal force > 0), and the block's
 * bottom rose with it */
static void test_wall_motion_scenario(void)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/lift.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/lift.h5", tmpdir);
    write_text(scn, "mcrash: 1\nname: lift\nsimulation: {end_time: 3 ms, output_rate: 20 kHz}\n"
                    "fe:\n  parts:\n    - name: block\n"
                    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [2, 2, 2]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000, youngs_modulus: 10 MPa, poisson: 0.3}\n"
                    "  rigid_walls:\n    - name: floor\n      point: [0, 0, 0]\n"
                    "      normal: [0, 0, 1]\n"
                    "      motion: {type: velocity, curve: [[0, 0], [1 ms, 0.5], [2 ms, 0]]}\n");
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array f = {0};
    double fmax_ = 0;
    if (mcs_results_read(h, "/stage3/rigidwall/floor/force", &f, &err) == MCS_OK)
        for (size_t i = 0; i < f.n; i++) fmax_ = fmax(fmax_, f.v[i]);
    mcs_array_free(&f);
    const double d = last_of(h, "/stage3/rigidwall/floor/displacement");
    printf("  scenario floor lifted by a curve: displacement %.9g m (0.5 mm), peak force %.4g N\n",
           d, fmax_);
    CHECK_NEAR(d, 0.5e-3, 1e-15);
    CHECK(fmax_ > 0);
    mcs_results_close(&h);
    /* a bad motion type is refused at its line */
    write_text(scn, "mcrash: 1\nname: lift\nsimulation: {end_time: 3 ms}\n"
                    "fe:\n  parts:\n    - name: block\n"
                    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [2, 2, 2]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000, youngs_modulus: 10 MPa, poisson: 0.3}\n"
                    "  rigid_walls:\n    - name: floor\n      point: [0, 0, 0]\n"
                    "      normal: [0, 0, 1]\n"
                    "      motion: {type: jerk, curve: [[0, 0], [2 ms, 1 mm]]}\n");
    mcs_error e2 = {0};
    CHECK(run_file(scn, out, &sum, &e2) != MCS_OK);
    CHECK_STR_CONTAINS(e2.msg, "lift.yaml:14:22: error: fe.rigid_walls[0].motion.type");
}

/* a block sliding on a floor with friction 0.5 (scenario key rigid_walls[].friction): the
 * friction dissipates the kinetic energy the deceleration mu g takes */
static void test_wall_friction_scenario(void)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/slide.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/slide.h5", tmpdir);
    write_text(scn, "mcrash: 1\nname: slide\nsimulation: {end_time: 5 ms, output_rate: 10 kHz}\n"
                    "environment: {gravity: 9.81 m/s^2}\n"
                    "fe:\n  parts:\n    - name: block\n"
                    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [2, 2, 2]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000, youngs_modulus: 10 MPa, poisson: 0.3}\n"
                    "      initial_velocity: [2, 0, 0]\n"
                    "  rigid_walls:\n    - name: floor\n      point: [0, 0, 0]\n"
                    "      normal: [0, 0, 1]\n      friction: 0.5\n");
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    const double diss = last_of(h, "/stage3/energy/dissipated");
    const double tot = last_of(h, "/stage3/energy/total"), ke = last_of(h, "/stage3/energy/kinetic");
    printf("  scenario block on a floor with friction 0.5: dissipated %.4g J, kinetic %.4g J, "
           "total %.3g J\n", diss, ke, tot);
    /* sliding at mu g: 1/2 m (v0^2 - (v0 - mu g t)^2) dissipated (the block lands on the
     * floor at once: it starts on it) */
    const double t = last_of(h, "/stage3/time"), dv = 0.5 * 9.81 * t, m = 8e-3;
    CHECK_REL(diss, 0.5 * m * (4 - (2 - dv) * (2 - dv)), 0.05);
    CHECK(ke < 0.5 * m * 4);
    mcs_results_close(&h);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s3w_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_wall_motion_scenario);
    RUN(test_wall_friction_scenario);
    char cmd[96];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) return 1;
    TEST_END();
}

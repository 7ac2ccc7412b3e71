/* test_s2_cockpit_run: stage 2 through `mcrash stage1` then `mcrash stage2` of a small scenario
 * with a stage-2 cockpit: a heavy body (`cockpit`, a sphere of radius 0.1 m) moving at V = 1 m/s,
 * in stage 2 prescribed from the stage-1 file and carrying a foam pad (stage2.fe, generate:
 * foam_pad, attach where: surface) on its front; a free ball (0.5 kg, radius 50 mm) at rest in
 * its path. Stage 1 has no pad and no contact: the ball stays, the cockpit keeps V. In stage 2
 * the pad meets the ball (a bodies contact). The foam has one loading curve and no hysteresis
 * (HU 1, an elastic nonlinear spring; bulk viscosity off), so the collision of the ball with a
 * body of infinite mass moving at V is elastic: the ball leaves at 2 V (closed form, Newton's
 * law of restitution with e = 1; what the pad's outer nodes keep ringing is lost to it). The pad
 * starts with the cockpit's velocity (initial_velocity: without an impact: block only its
 * attached nodes would, stage1_mb/mb_couple.c, and the rest would ring from the start). */
#include "core/mcs_results.h"
#include "tests/cli_util.h"
#include "tests/harness.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define V 1.0      /* cockpit speed [m/s] */
#define M_BALL 0.5 /* [kg] */

static char tmpdir[64];

static const char *yaml =
    "mcrash: 1\nname: cockpit and ball\n"
    "simulation: {end_time: 150 ms, time_step: 20 us, output_rate: 5 kHz}\n"
    "environment: {gravity: 0}\n"
    "bodies:\n"
    "  - {name: cockpit, mass: 200, inertia: [2, 2, 2], position: [0, 0, 0], velocity: [1, 0, 0],\n"
    "     surfaces: [{name: tank, type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, "
    "0.1]}]}\n"
    "  - {name: ball, mass: 0.5, inertia: [5e-4, 5e-4, 5e-4], position: [0.215, 0, 0],\n"
    "     velocity: [0, 0, 0],\n"
    "     surfaces: [{name: ball, type: ellipsoid, center: [0, 0, 0], semi_axes: [0.05, 0.05, "
    "0.05]}]}\n"
    "stage2:\n"
    "  method: pose\n"
    "  prescribed: [{body: cockpit}]\n"
    "  fe:\n"
    "    parts:\n"
    "      - name: pad\n"
    "        mesh: {generate: foam_pad, body: cockpit, surface: tank, thickness: 15 mm,\n"
    "               element_size: 10 mm, longitude: [-40 deg, 40 deg], latitude: [-40 deg, 40 "
    "deg]}\n"
    "        section: {type: solid}\n"
    "        material: {model: foam, density: 425 kg/m^3, youngs_modulus: 20 MPa,\n"
    "                   stress_strain: [[0.05, 0.6 MPa], [0.5, 1.0 MPa], [0.7, 2.0 MPa], [0.85, 8 "
    "MPa]]}\n"
    "        initial_velocity: [1, 0, 0]\n"
    "        attach: {body: cockpit, where: surface}\n"
    "    contacts: [{type: bodies, parts: [pad], bodies: [ball]}]\n"
    "    bulk_q1: 0\n"
    "    bulk_q2: 0\n";

static double last_row(mcs_results *h, const char *path, int col, int *ok)
{
    mcs_array a = {0};
    mcs_error err = {0};
    *ok = mcs_results_read(h, path, &a, &err) == MCS_OK && a.n > 0;
    if (!*ok) {
        fprintf(stderr, "%s: %s\n", path, err.msg);
        return NAN;
    }
    size_t w = a.rank == 2 ? a.dims[1] : 1;
    double v = a.v[(a.dims[0] - 1) * w + col];
    mcs_array_free(&a);
    return v;
}

static void test_stage2_pad_pushes_ball(void)
{
    char path[128], s1[128], s2[128], args[512];
    snprintf(path, sizeof path, "%s/cockpit.yaml", tmpdir);
    snprintf(s1, sizeof s1, "%s/s1.h5", tmpdir);
    snprintf(s2, sizeof s2, "%s/s2.h5", tmpdir);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fputs(yaml, f);
    fclose(f);
    snprintf(args, sizeof args, "stage1 %s -o %s --quiet", path, s1);
    cli_result *r = cli_run(args);
    if (r->status) fprintf(stderr, "%s", r->err);
    CHECK(r->status == 0);
    snprintf(args, sizeof args, "stage2 %s --motion %s -o %s --quiet --json", path, s1, s2);
    r = cli_run(args);
    if (r->status) fprintf(stderr, "%s", r->err);
    CHECK(r->status == 0);
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, s2, &err) == MCS_OK);
    if (!h) return;
    int ok1, ok2, ok3;
    double vb = last_row(h, "/stage2/bodies/ball/velocity", 0, &ok1);
    double vc = last_row(h, "/stage2/bodies/cockpit/velocity", 0, &ok2);
    double pe = last_row(h, "/stage2/motion/cockpit/position_error", 0, &ok3);
    CHECK(ok1 && ok2 && ok3);
    int okp;
    double eint = last_row(h, "/stage2/parts/pad/energy/internal", 0, &okp);
    CHECK(okp);
    mcs_results_close(&h);
    printf("stage 2: ball leaves at %.4f m/s (2 V = %.4f, %+.2f %%), cockpit %.6f m/s, "
           "motion error %.1e m, pad internal energy left %.2e J\n",
           vb, 2 * V, 100 * (vb / (2 * V) - 1), vc, pe, eint);
    CHECK_NEAR(vc, V, 1e-9);
    CHECK(pe < 1e-9);
    FIG("s2.pad_ball_restitution_pct", "%.2f", 100 * (vb / (2 * V) - 1));
    CHECK(fabs(vb / (2 * V) - 1) < 3e-4); /* 0.01 % stated */
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s2c_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_stage2_pad_pushes_ball);
    TEST_END();
}

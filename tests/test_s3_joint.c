/* test_s3_joint.c: `fe.joints` from a scenario file to /stage3/joints and /stage3/bodies
 * (fe_scn_joint.c, fe_out_joint.c): a rod released from the horizontal on a revolute joint
 * (the large-amplitude pendulum in closed form), and bad joints located at FILE:LINE:COL. */
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

static const char *const rod_yaml =
    "mcrash: 1\nname: pend\nsimulation: {end_time: 0.55 s, time_step: 0.1 ms, "
    "output_rate: 2 kHz}\n"
    "environment: {gravity: 9.81 m/s^2}\n"
    "fe:\n  parts:\n    - name: rod\n"
    "      mesh: {generate: box, size: [1 m, 20 mm, 20 mm], divisions: [4, 1, 1],"
    " origin: [0, -10 mm, -10 mm]}\n"
    "      section: {type: solid}\n"
    "      material: {model: rigid, density: 1000, youngs_modulus: 1 GPa, poisson: 0.3}\n"
    "    - name: soft\n"
    "      mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], divisions: [1, 1, 1],"
    " origin: [2, 0, 0]}\n"
    "      section: {type: solid}\n"
    "      material: {model: elastic, density: 1000, youngs_modulus: 1 MPa, poisson: 0.3}\n"
    "  boundary: [{part: soft, where: all, fix: all}]\n"
    "  joints:\n"
    "    - {name: pivot, type: revolute, parts: [%s], point: [0, 0, 0], axis: [0, 1, 0]}\n";

static int write_rod(const char *path, const char *parts)
{
    char text[2048];
    snprintf(text, sizeof text, rod_yaml, parts);
    write_text(path, text);
    return 1;
}

/* released from rest at theta0 = 90 deg, a physical pendulum reaches the bottom after a
 * quarter period T/4 = sqrt(I_p / (M g d)) K(sin 45 deg), K(1/sqrt 2) = 1.8540747 (complete
 * elliptic integral of the first kind; e.g. Abramowitz & Stegun 17.3, Table 17.1), with the
 * speed of energy conservation w = sqrt(2 M g d / I_p) there; I_p of the lumped rod
 * (test_fe_joint.c): M (L^2 (1/3 + 1/(6 n^2)) + a^2/4), d = L/2 */
static void test_pendulum_from_scenario(void)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/pend.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/pend.h5", tmpdir);
    write_rod(scn, "rod");
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    printf("  energy balance of the run: drift %.2e of the largest energy\n", sum.energy_drift);
    CHECK(sum.energy_drift < 1e-3); /* the joint's penalty energy is in internal/dissipated */
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    const double L = 1, a = 0.02, n = 4, M = 1000 * L * a * a, g = 9.81, d = 0.5;
    const double Ip = M * (L * L * (1.0 / 3 + 1 / (6 * n * n)) + a * a / 4);
    const double tq = sqrt(Ip / (M * g * d)) * 1.8540747, wb = sqrt(2 * M * g * d / Ip);
    mcs_array t = {0}, ang = {0}, v = {0}, q = {0}, f = {0}, x = {0};
    CHECK(rd(h, "/stage3/time", &t) && rd(h, "/stage3/joints/pivot/angle", &ang));
    CHECK(rd(h, "/stage3/bodies/rod/velocity", &v) && rd(h, "/stage3/bodies/rod/orientation", &q));
    CHECK(rd(h, "/stage3/joints/pivot/force", &f) && rd(h, "/stage3/bodies/rod/position", &x));
    CHECK(mcs_results_exists(h, "/stage3/bodies/rod/acceleration"));
    CHECK(mcs_results_exists(h, "/stage3/joints/pivot/time"));
    CHECK(!mcs_results_exists(h, "/stage3/joints/pivot/displacement"));
    CHECK(ang.n == t.n && v.n == 3 * t.n && q.n == 4 * t.n && f.n == 3 * t.n);
    double tb = NAN, vmax = 0, qerr = 1, fz = 0;
    for (size_t i = 1; i < t.n && i < ang.n; i++) {
        if (isnan(tb) && ang.v[i - 1] < M_PI / 2 && ang.v[i] >= M_PI / 2)
            tb = t.v[i - 1] +
                 (t.v[i] - t.v[i - 1]) * (M_PI / 2 - ang.v[i - 1]) / (ang.v[i] - ang.v[i - 1]);
        double s = sqrt(v.v[3 * i] * v.v[3 * i] + v.v[3 * i + 2] * v.v[3 * i + 2]);
        if (s > vmax) {
            vmax = s;
            /* at the bottom: turned 90 deg about y, q = (cos 45, 0, sin 45, 0); the pivot
             * holds the weight and the centripetal force, M g + M w^2 d = 3 M g + ... */
            qerr = fabs(q.v[4 * i] - sqrt(0.5)) + fabs(q.v[4 * i + 2] - sqrt(0.5));
            fz = f.v[3 * i + 2];
        }
    }
    double err_pct = 100 * fabs(tb / tq - 1);
    printf("  pendulum from 90 deg: bottom at %.5f s (closed form %.5f s, %.3f %%), speed "
           "%.4f m/s (%.4f), quaternion off by %.1e, pivot force %.4f N (%.4f N)\n",
           tb, tq, err_pct, vmax, wb * d, qerr, fz, M * g + M * wb * wb * d);
    /* the 2 kHz rows resolve the crossing to ~1e-4 of T/4 */
    CHECK(err_pct < 0.05);
    CHECK_REL(vmax, wb * d, 2e-3);
    CHECK(qerr < 2e-3);
    /* the force of the ground (B) on the rod (A) at the bottom: up, M g + M w^2 d */
    CHECK_REL(fz, M * g + M * wb * wb * d, 5e-3);
    FIG_TOL("fe.joint_scn_pendulum_err_pct", "%.3f", err_pct, 0.01);
    mcs_array_free(&t), mcs_array_free(&ang), mcs_array_free(&v), mcs_array_free(&q);
    mcs_array_free(&f), mcs_array_free(&x);
    mcs_results_close(&h);
}

/* a joint on a deformable part, naming one part twice, or an unknown part: exit 2 at the
 * FILE:LINE:COL of its parts */
static void test_bad_joints_located(void)
{
    const char *parts[3] = {"rod, soft", "rod, rod", "rod, frame"};
    const char *want[3] = {"'soft' is no rigid part", "joins 'rod' to itself", "frame"};
    for (int k = 0; k < 3; k++) {
        char scn[128], out[128];
        snprintf(scn, sizeof scn, "%s/bad%d.yaml", tmpdir, k);
        snprintf(out, sizeof out, "%s/bad%d.h5", tmpdir, k);
        write_rod(scn, parts[k]);
        s3_summary sum;
        mcs_error err = {0};
        CHECK(run_file(scn, out, &sum, &err) != MCS_OK);
        char loc[160];
        snprintf(loc, sizeof loc, "%s:17:", scn); /* the joint's line, parts' column */
        CHECK_STR_CONTAINS(err.msg, loc);
        CHECK_STR_CONTAINS(err.msg, want[k]);
        if (k == 2) printf("  unknown part: %s\n", err.msg);
    }
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s3j_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_pendulum_from_scenario);
    RUN(test_bad_joints_located);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) return 1;
    TEST_END();
}

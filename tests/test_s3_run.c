/* test_s3_run.c: stage-3 (FE-only) runs from a scenario to /stage3 of a results file:
 * the elastic bar into a rigid wall against 1-D wave theory, a small square tube crushed by a
 * moving wall (energy balance; Abramowicz-Jones mean force under `make verify`), the --json
 * summary of `mcrash stage3` and `mcrash run`, exit 1 with no file on a numerical failure,
 * exit 2 with FILE:LINE:COL for what the kernel cannot do yet. */
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

static int file_exists(const char *p)
{
    struct stat sb;
    return stat(p, &sb) == 0;
}

/* Elastic bar (L 0.1 m, A 1e-4 m^2, rho 8000, E 200 GPa, nu 0) into a fixed rigid wall at
 * v 5 m/s. 1-D elastic waves (Graff, Wave Motion in Elastic Solids, 1975, sec. 2.1.3):
 * c = sqrt(E/rho) = 5000 m/s, contact force F = rho c A v = 20 kN, contact time 2L/c = 40 us,
 * rebound velocity v (elastic). The rebound is measured by momentum: impulse I = m (v + v_r). */
static void test_bar_into_wall(void)
{
    const double rho = 8000, E = 200e9, A = 1e-4, L = 0.1, v = 5, c = sqrt(E / rho);
    const double F0 = rho * c * A * v, tc = 2 * L / c, mass = rho * A * L;
    char out[128];
    snprintf(out, sizeof out, "%s/bar.h5", tmpdir);
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file("scenarios/verification/bar_wall_impact.yaml", out, &sum, &err) == MCS_OK);
    CHECK(sum.elements == 50 && sum.nodes == 204);
    CHECK(sum.energy_drift < 1e-3);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array t = {0}, f = {0}, d = {0}, ek = {0}, tot = {0};
    CHECK(rd(h, "/stage3/time", &t) && rd(h, "/stage3/rigidwall/wall/force", &f) &&
          rd(h, "/stage3/rigidwall/wall/displacement", &d));
    CHECK(strcmp(f.unit, "N") == 0 && strcmp(t.unit, "s") == 0 && f.n == t.n && d.n == t.n);
    int first = -1, last = -1;
    for (size_t i = 0; i < f.n; i++)
        if (f.v[i] > 0.05 * F0) {
            if (first < 0) first = (int)i;
            last = (int)i;
        }
    CHECK(first > 0 && last > first);
    if (first > 0 && last > first) {
        double dur = t.v[last] - t.v[first], mean = 0, impulse = 0;
        int n0 = first + (last - first) / 10, n1 = last - (last - first) / 10, n = 0;
        for (int i = n0; i <= n1; i++, n++) mean += f.v[i];
        mean /= n;
        for (size_t i = 1; i < f.n; i++) impulse += 0.5 * (f.v[i] + f.v[i - 1]) * (t.v[i] - t.v[i - 1]);
        double vr = impulse / mass - v;
        printf("  bar: F %.4g N (rho c A v %.4g, %+.2f %%), contact %.4g us (2L/c %.4g, %+.2f %%), "
               "rebound %.4g m/s (%+.2f %%), drift %.2g, %ld steps\n",
               mean, F0, 100 * (mean / F0 - 1), 1e6 * dur, 1e6 * tc, 100 * (dur / tc - 1), vr,
               100 * (vr / v - 1), sum.energy_drift, sum.steps);
        /* README states these errors; tolerances ~3x of them */
        FIG("readme.s3_bar_force_err_pct", "%+.2f", 100 * (mean / F0 - 1));
        FIG("readme.s3_bar_contact_err_pct", "%+.2f", 100 * (dur / tc - 1));
        FIG("readme.s3_bar_rebound_err_pct", "%+.0f", 100 * (vr / v - 1));
        CHECK_REL(mean, F0, 1.5e-3); /* +0.04 % */
        CHECK_REL(dur, tc, 1e-2);    /* +0.74 % (the step at 0.85 of the bar's limit) */
        CHECK_REL(vr, v, 0.09);      /* -3 % */
    }
    for (size_t i = 0; i < d.n; i++) CHECK(d.v[i] == 0); /* a fixed wall */
    CHECK(rd(h, "/stage3/energy/kinetic", &ek) && rd(h, "/stage3/energy/total", &tot));
    CHECK_REL(ek.v[0], 0.5 * mass * v * v, 1e-9); /* t = 0: all kinetic, 1 J */
    CHECK_NEAR(tot.v[tot.n - 1], tot.v[0], 1e-3 * ek.v[0]);
    mcs_array_free(&t), mcs_array_free(&f), mcs_array_free(&d);
    mcs_array_free(&ek), mcs_array_free(&tot);
    /* mesh and fields for export --xdmf */
    mcs_array nodes = {0}, el = {0}, disp = {0}, ft = {0};
    mcs_error e2 = {0};
    CHECK(rd(h, "/stage3/mesh/bar/nodes", &nodes) &&
          mcs_results_read_int(h, "/stage3/mesh/bar/elements", &el, &e2) == MCS_OK &&
          rd(h, "/stage3/fields/displacement", &disp) && rd(h, "/stage3/fields/time", &ft));
    CHECK(nodes.dims[0] == 204 && nodes.dims[1] == 3 && el.dims[0] == 50 && el.dims[1] == 8);
    CHECK(disp.rank == 3 && disp.dims[0] == ft.n && disp.dims[1] == 204 && disp.dims[2] == 3);
    CHECK(ft.v[0] == 0 && disp.v[0] == 0);
    if (disp.rank == 3 && ft.n > 2) {
        /* before the wave reaches the free end (t < L/c) it moves at -v */
        size_t k = 0;
        while (k + 1 < ft.n && ft.v[k + 1] < 0.5 * L / c) k++;
        double xmax = -1;
        int nmax = 0;
        for (int n = 0; n < 204; n++)
            if (nodes.v[3 * n] > xmax) xmax = nodes.v[3 * n], nmax = n;
        CHECK_REL(disp.v[(k * 204 + (size_t)nmax) * 3], -v * ft.v[k], 1e-6);
    }
    mcs_array_free(&nodes), mcs_array_free(&el), mcs_array_free(&disp), mcs_array_free(&ft);
    mcs_results_close(&h);
}

/* Small square tube (20 mm, 1 mm, 40 mm, elastic-perfectly plastic 250 MPa) crushed 15 mm at
 * 10 m/s with single-surface self contact. Energy balance (kinetic + internal + contact +
 * hourglass + dissipated = wall work), the wall's prescribed travel, and the mean force from
 * 5 mm (after the first peak) to the end against Abramowicz & Jones (1984, Int. J. Impact
 * Eng. 2(2), static, rigid-perfectly plastic): P_m = 13.06 sigma_0 h^(5/3) c^(1/3) = 8.86 kN.
 * The formula is an approximate kinematic analysis of an empirical kind (A-J report
 * "reasonable agreement" with their 84 drop tests, no single scatter figure), the mesh has
 * 3.6 elements per fold half-wavelength H = 0.983 h^(1/3) c^(2/3) = 7.2 mm, and the wall's
 * speed adds inertia the static formula has not: the comparison with the formula is a band,
 * +-20 % (docs/fe.md states it). The run's own mean force, steps and drift are figures
 * asserted at the precision docs/fe.md shows (a regression of this model). */
static void test_square_tube_crush(void)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/tube.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/tube.h5", tmpdir);
    FILE *f = fopen("scenarios/verification/square_tube_crush_small.yaml", "r");
    CHECK(f != NULL);
    if (!f) return;
    static char text[8192];
    size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = 0;
    fclose(f);
    write_text(scn, text);
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    CHECK(sum.elements == 800);
    CHECK(sum.energy_drift < 6e-4); /* 2e-4 stated */
    FIG("fe.tube_small_steps", "%.0f", (double)sum.steps);
    FIG("fe.tube_small_drift", "%.0e", sum.energy_drift);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array t = {0}, F = {0}, d = {0}, ext = {0}, in = {0};
    CHECK(rd(h, "/stage3/time", &t) && rd(h, "/stage3/rigidwall/ram/force", &F) &&
          rd(h, "/stage3/rigidwall/ram/displacement", &d) &&
          rd(h, "/stage3/energy/external_work", &ext) && rd(h, "/stage3/energy/internal", &in));
    size_t k = t.n - 1;
    CHECK_REL(d.v[k], 10 * t.v[k], 0.01); /* travel along its normal -z at 10 m/s */
    double work = 0, peak = 0;
    for (size_t i = 1; i <= k; i++) {
        work += 0.5 * (F.v[i] + F.v[i - 1]) * (d.v[i] - d.v[i - 1]);
        peak = fmax(peak, F.v[i]);
    }
    /* the wall's work from its force history = the kernel's external work (sampling error) */
    CHECK_REL(ext.v[k], work, 0.05);
    CHECK(in.v[k] > 0.5 * ext.v[k]); /* mostly plastic work, little kinetic */
    const double sy = 250e6, hw = 1e-3, side = 20e-3;
    const double Pm = 13.06 * sy * pow(hw, 5.0 / 3) * cbrt(side);
    /* squash load of the section 4 c h sigma_0 bounds the first peak from below */
    CHECK(peak > 0.8 * 4 * side * hw * sy);
    size_t i0 = 0; /* mean force from 5 mm to the end */
    while (i0 < k && d.v[i0] < 5e-3) i0++;
    double w = 0;
    for (size_t i = i0 + 1; i <= k; i++) w += 0.5 * (F.v[i] + F.v[i - 1]) * (d.v[i] - d.v[i - 1]);
    double mean = w / (d.v[k] - d.v[i0]);
    CHECK(d.v[k] > 14e-3);
    CHECK_REL(mean, Pm, 0.20); /* the band of the empirical formula */
    FIG("fe.tube_small_mean_kn", "%.2f", 1e-3 * mean);
    FIG("fe.tube_small_aj_kn", "%.2f", 1e-3 * Pm);
    FIG("fe.tube_small_aj_err_pct", "%+.0f", 100 * (mean / Pm - 1));
    mcs_array ce = {0};
    CHECK(rd(h, "/stage3/contact/contact0/energy", &ce) && ce.n == t.n);
    if (ce.n == t.n) CHECK(ce.v[k] > 0); /* the folds did touch */
    mcs_array_free(&ce);
    printf("  tube: %ld steps, %d elements, crush %.3g mm, peak %.4g kN, mean %.4g kN "
           "(A-J %.4g kN), wall work %.4g J, external work %.4g J, drift %.2g, wall %.3g s\n",
           sum.steps, sum.elements, 1e3 * d.v[k], 1e-3 * peak, 1e-3 * mean, 1e-3 * Pm, work,
           ext.v[k], sum.energy_drift, sum.wall_time_s);
    mcs_array_free(&t), mcs_array_free(&F), mcs_array_free(&d), mcs_array_free(&ext);
    mcs_array_free(&in);
    mcs_results_close(&h);
}

/* make verify: scenarios/verification/tube_crush.yaml from `mcrash run` (50 mm x 1.5 mm x
 * 200 mm, 6400 shells, J2 with hardening 250 -> 300 MPa at 5 % -> 400 MPa at 100 %, self
 * contact, 80 mm of crush at 10 m/s). Abramowicz & Jones (1984), static, at sigma_0 = the
 * initial yield 250 MPa: P_m = 13.06 sigma_0 h^(5/3) c^(1/3) = 23.6 kN. Mean force from 15 mm
 * (one half-wavelength H = 0.983 h^(1/3) c^(2/3) = 15.3 mm) to the end. The material hardens
 * (flow stress 1.26 sigma_y at 20 % plastic strain) and the formula is empirical, so the
 * comparison is a band: 1.0 < P / P_m(sigma_y) < 1.6. The run's own figures (mean force,
 * ratio, fold spacing, drift, steps) are asserted at the precision docs/fe.md shows. Fold
 * spacing: the mean distance between the force's major peaks (maxima over +-5 mm of crush);
 * A-J's effective crushing distance 0.73 x 2H = 22.4 mm. */
static void test_tube_crush_full(void)
{
    if (!th_verify()) return;
    char out[128], args[512];
    snprintf(out, sizeof out, "%s/tc.h5", tmpdir);
    snprintf(args, sizeof args, "run scenarios/verification/tube_crush.yaml -o %s --quiet --json",
             out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"elements\": 6400");
    long steps = -1;
    const char *sj = strstr(r->out, "\"steps\": ");
    if (sj) sscanf(sj + 9, "%ld", &steps);
    FIG("fe.tube_full_steps", "%.0f", (double)steps);
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array F = {0}, d = {0};
    CHECK(rd(h, "/stage3/rigidwall/ram/force", &F) && rd(h, "/stage3/rigidwall/ram/displacement", &d));
    size_t k = d.n - 1, i0 = 0;
    while (i0 < k && d.v[i0] < 15e-3) i0++;
    double w = 0;
    for (size_t i = i0 + 1; i <= k; i++) w += 0.5 * (F.v[i] + F.v[i - 1]) * (d.v[i] - d.v[i - 1]);
    const double mean = w / (d.v[k] - d.v[i0]);
    const double Pm = 13.06 * 250e6 * pow(1.5e-3, 5.0 / 3) * cbrt(0.05);
    double drift = -1;
    const char *dj = strstr(r->out, "\"energy_drift\": ");
    if (dj) sscanf(dj + 16, "%lf", &drift);
    printf("  tube_crush.yaml: crush %.3g mm, mean force %.4g kN (A-J at sigma_y %.4g kN, x %.3f), "
           "energy drift %.2g\n",
           1e3 * d.v[k], 1e-3 * mean, 1e-3 * Pm, mean / Pm, drift);
    /* major force peaks: the largest force within +-5 mm of crush, past 15 mm */
    double first = -1, last = -1;
    int npk = 0;
    for (size_t i = i0; i <= k; i++) {
        int top = F.v[i] > mean;
        for (size_t j = i0; j <= k && top; j++)
            if (fabs(d.v[j] - d.v[i]) <= 5e-3 && F.v[j] > F.v[i]) top = 0;
        if (top && d.v[i] - d.v[i0] > 5e-3 && d.v[k] - d.v[i] > 5e-3) {
            if (first < 0) first = d.v[i];
            last = d.v[i], npk++;
        }
    }
    const double spacing = npk > 1 ? (last - first) / (npk - 1) : -1;
    printf("  tube_crush.yaml: %d major peaks, mean spacing %.3g mm (A-J 0.73 x 2H = 22.4 mm)\n",
           npk, 1e3 * spacing);
    FIG("fe.tube_full_mean_kn", "%.1f", 1e-3 * mean);
    FIG("fe.tube_full_aj_ratio", "%.2f", mean / Pm);
    FIG("fe.tube_full_fold_mm", "%.0f", 1e3 * spacing);
    FIG("fe.tube_full_drift_pct", "%.2f", 100 * drift);
    CHECK(d.v[k] > 0.075);
    CHECK(mean > Pm && mean < 1.6 * Pm); /* the band of the empirical formula */
    CHECK(drift >= 0 && drift < 0.008); /* 0.27 % stated */
    mcs_array_free(&F), mcs_array_free(&d);
    mcs_results_close(&h);
}

/* A steel rod (line mesh of trusses, L 1 m, A 1e-4 m^2) clamped at x = 0, a step load
 * F = 1 kN suddenly applied at its free end (fe.loads), beside a clamped circular tube that is
 * not loaded. 1-D waves (Graff 1975, sec. 2.1): the end displacement grows linearly and peaks
 * at t = 2L/c at twice the static value, u_max = 2 F L / (E A). */
static void test_line_mesh_step_load(void)
{
    char scn[128], out[128];
    snprintf(scn, sizeof scn, "%s/rod.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/rod.h5", tmpdir);
    write_text(scn, "mcrash: 1\nname: rod\nsimulation: {end_time: 0.6 ms, output_rate: 200 kHz}\n"
                    "fe:\n  parts:\n    - name: rod\n"
                    "      mesh: {generate: line, origin: [0, 0, 0], end: [1, 0, 0], divisions: 50}\n"
                    "      section: {type: truss, area: 1e-4}\n"
                    "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"
                    "    - name: tube\n"
                    "      mesh: {generate: circular_tube, diameter: 40 mm, length: 50 mm,"
                    " element_size: 5 mm, axis: x}\n"
                    "      section: {type: shell, thickness: 1 mm}\n"
                    "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"
                    "  boundary: [{part: rod, where: x_min, fix: all}, {part: tube, where: x_min}]\n"
                    "  loads: [{part: rod, where: x_max, force: [1000 N, 0, 0]}]\n");
    s3_summary sum;
    mcs_error err = {0};
    CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    mcs_results *h = NULL;
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array nodes = {0}, disp = {0}, el = {0}, tn = {0};
    mcs_error e2 = {0};
    CHECK(rd(h, "/stage3/mesh/rod/nodes", &nodes) && rd(h, "/stage3/fields/displacement", &disp) &&
          mcs_results_read_int(h, "/stage3/mesh/rod/elements", &el, &e2) == MCS_OK &&
          rd(h, "/stage3/mesh/tube/nodes", &tn));
    CHECK(el.dims[0] == 50 && el.dims[1] == 2 && nodes.dims[0] == 51);
    CHECK(tn.dims[0] == 25 * 11); /* 25 around (pi 40 / 5), 10 along + 1 */
    if (disp.rank == 3 && nodes.dims[0] == 51) {
        int tip = 0;
        for (int n = 0; n < 51; n++)
            if (nodes.v[3 * n] > nodes.v[3 * tip]) tip = n;
        double umax = 0, utube = 0;
        for (size_t k = 0; k < disp.dims[0]; k++) {
            umax = fmax(umax, disp.v[(k * disp.dims[1] + (size_t)tip) * 3]);
            for (size_t n = 51; n < disp.dims[1]; n++)
                utube = fmax(utube, fabs(disp.v[(k * disp.dims[1] + n) * 3]));
        }
        const double ref = 2 * 1000.0 * 1.0 / (210e9 * 1e-4);
        printf("  rod: u_max %.5g m (2FL/EA %.5g, %+.2f %%)\n", umax, ref, 100 * (umax / ref - 1));
        FIG("readme.s3_rod_err_pct", "%+.0f", 100 * (umax / ref - 1));
        CHECK_REL(umax, ref, 0.03); /* -1 % */
        CHECK(utube == 0); /* nothing acts on the tube */
    }
    mcs_array_free(&nodes), mcs_array_free(&disp), mcs_array_free(&el), mcs_array_free(&tn);
    mcs_results_close(&h);
}

/* issue 15 item 7: fields at their own rate, channels and energies at output_rate. A 2-element
 * bar, 10 ms at 100 kHz (1000 rows of /stage3/time, time_step 5 us): without field_rate the
 * fields are FE_SCN_FIELD_FRAMES = 200 per run, every 50 us (the first step at or after each),
 * with field_rate 1 kHz every 1 ms (11 frames with t = 0), with field_rate above output_rate
 * at their own rate all the same (one per step at 200 kHz: the steps + 1). Counted by hand. */
static void test_field_rate_default(void)
{
    const char *rates[3] = {"", ", field_rate: 1 kHz", ", field_rate: 200 kHz"};
    const size_t lo[3] = {200, 11, 0}, hi[3] = {201, 11, 0};
    for (int k = 0; k < 3; k++) {
        char scn[128], out[128], text[1024];
        snprintf(scn, sizeof scn, "%s/fr%d.yaml", tmpdir, k);
        snprintf(out, sizeof out, "%s/fr%d.h5", tmpdir, k);
        snprintf(text, sizeof text,
                 "mcrash: 1\nname: fields\n"
                 "simulation: {end_time: 10 ms, time_step: 5 us, output_rate: 100 kHz%s}\n"
                 "fe:\n  parts:\n    - name: bar\n"
                 "      mesh: {generate: line, origin: [0, 0, 0], end: [1, 0, 0], divisions: 2}\n"
                 "      section: {type: truss, area: 40 mm^2}\n"
                 "      material: {model: elastic, density: 1000, youngs_modulus: 10 GPa,"
                 " poisson: 0}\n"
                 "      initial_velocity: [1, 0, 0]\n",
                 rates[k]);
        write_text(scn, text);
        s3_summary sum;
        mcs_error err = {0};
        CHECK(run_file(scn, out, &sum, &err) == MCS_OK);
        mcs_results *h = NULL;
        CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
        if (!h) continue;
        mcs_array t = {0}, ft = {0}, d = {0};
        CHECK(rd(h, "/stage3/time", &t) && rd(h, "/stage3/fields/time", &ft) &&
              rd(h, "/stage3/fields/displacement", &d));
        printf("  fields%s: %zu frames, %zu rows of /stage3/time\n", rates[k], ft.n, t.n);
        CHECK(t.n >= 1000 && t.n <= 1001);
        if (k == 2) CHECK(ft.n == (size_t)sum.steps + 1);
        else CHECK(ft.n >= lo[k] && ft.n <= hi[k]);
        CHECK(d.dims[0] == ft.n);
        mcs_array_free(&t), mcs_array_free(&ft), mcs_array_free(&d);
        mcs_results_close(&h);
    }
}

static void test_cli_json_and_run(void)
{
    char args[512], out[128];
    snprintf(out, sizeof out, "%s/cli.h5", tmpdir);
    snprintf(args, sizeof args, "stage3 scenarios/verification/bar_wall_impact.yaml -o %s --json", out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"stage3\": {\"steps\": ");
    CHECK_STR_CONTAINS(r->out, "\"elements\": 50");
    CHECK_STR_CONTAINS(r->out, "\"wall_time_s\"");
    CHECK_STR_CONTAINS(r->out, "\"energy_drift\"");
    CHECK(file_exists(out));
    remove(out);
    snprintf(args, sizeof args, "run scenarios/verification/bar_wall_impact.yaml -o %s --quiet --json", out);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"stage3\": {\"steps\": ");
    CHECK(file_exists(out));
    remove(out);
}

static void test_numerical_failure_leaves_no_file(void)
{
    char scn[128], out[128], args[512];
    snprintf(scn, sizeof scn, "%s/smash.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/smash.h5", tmpdir);
    /* a very soft block thrown at 2 km/s: its first element turns inside out */
    write_text(scn, "mcrash: 1\nname: smash\nsimulation: {end_time: 100 us}\nfe:\n  parts:\n"
                    "    - name: bar\n"
                    "      mesh: {generate: box, size: [10 mm, 10 mm, 10 mm], divisions: [4, 1, 1]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000 kg/m^3, youngs_modulus: 1 MPa,"
                    " poisson: 0.3}\n"
                    "      initial_velocity: [-2000 m/s, 0, 0]\n"
                    "  rigid_walls: [{name: wall, point: [-1 um, 0, 0], normal: [1, 0, 0]}]\n");
    snprintf(args, sizeof args, "stage3 %s -o %s", scn, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 1);
    CHECK_STR_CONTAINS(r->err, "inverted");
    CHECK_STR_CONTAINS(r->err, "part 'bar'");
    CHECK(!file_exists(out));
    int left = 0; /* no temporary either */
    char cmd[256];
    snprintf(cmd, sizeof cmd, "ls %s | grep -c tmp > /dev/null", tmpdir);
    left = system(cmd) == 0;
    CHECK(!left);
}

static void test_unsupported_is_located(void)
{
    char out[128], args[512], scn[128];
    snprintf(out, sizeof out, "%s/unsupported.h5", tmpdir);
    /* a contact the kernel refuses: located at the key */
    snprintf(scn, sizeof scn, "%s/contact.yaml", tmpdir);
    write_text(scn, "mcrash: 1\nname: c\nsimulation: {end_time: 1 ms}\nfe:\n  parts:\n"
                    "    - name: a\n"
                    "      mesh: {generate: box, size: [1, 1, 1], divisions: [1, 1, 1]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: elastic, density: 1000, youngs_modulus: 1 MPa,"
                    " poisson: 0.3}\n"
                    "  contacts: [{type: two_surface, slave: [a], master: [a], friction: 0.1,\n"
                    "              friction_dynamic: 0.3}]\n");
    snprintf(args, sizeof args, "run %s -o %s", scn, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "contact.yaml:11:33:");
    CHECK_STR_CONTAINS(r->err, "friction_dynamic");
    CHECK_STR_CONTAINS(r->err, "must not exceed friction");
    CHECK(!file_exists(out));
    snprintf(scn, sizeof scn, "%s/foam.yaml", tmpdir);
    write_text(scn, "mcrash: 1\nname: foam\nsimulation: {end_time: 1 ms}\nfe:\n  parts:\n"
                    "    - name: pad\n"
                    "      mesh: {generate: box, size: [1, 1, 1], divisions: [1, 1, 1]}\n"
                    "      section: {type: solid}\n"
                    "      material: {model: foam, density: 30, youngs_modulus: 1 MPa,\n"
                    "                 stress_strain: [[0, 0], [0.5, 0.1 MPa]], damping: 0.1}\n");
    snprintf(args, sizeof args, "stage3 %s -o %s", scn, out);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "foam.yaml:10:68: error: fe.parts[0].material.damping");
    CHECK_STR_CONTAINS(r->err, "foam damping not supported yet");
    r = cli_run("stage3 scenarios/verification/no_such_file.yaml");
    CHECK(r->status == 2);
    r = cli_run("stage3");
    CHECK(r->status == 2);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s3_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_bar_into_wall);
    RUN(test_square_tube_crush);
    RUN(test_tube_crush_full);
    RUN(test_line_mesh_step_load);
    RUN(test_field_rate_default);
    RUN(test_cli_json_and_run);
    RUN(test_numerical_failure_leaves_no_file);
    RUN(test_unsupported_is_located);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd)) printf("  could not remove %s\n", tmpdir);
    TEST_END();
}

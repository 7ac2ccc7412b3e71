/* test_s3_wallcase: the thesis' frontal rigid-wall impact in stage 3
 * (scenarios/thesis_frontal_barrier_13.4.yaml's stage3: block; stage3_fe/s3_scenario.h,
 * stage3_fe/s3_wallcase.h; docs/validation_stage3.md "The rigid-wall impact").
 * make test: the coarse motorcycle (40 mm, ~3000 elements), the first 15 ms. make verify: the
 * scenario's run mesh for its 100 ms and a second element size (mesh convergence of the wall
 * force). References, each independent of the code under test:
 *   - the initial kinetic energy by hand: 1/2 M v^2 + sum 1/2 I_w (v/R)^2 = 20 087 J (stage 1's
 *     model, docs/models.md: M = 208 kg, the wheels' spin inertia 0.6 kg m^2 at R = 0.30 m and
 *     0.9 kg m^2 at 0.315 m);
 *   - the first contact: the 5 mm gap at 13.4 m/s, 0.373 ms;
 *   - the phase order of the 2023 paper's Fig. 25 text (tyre, rim, fork, then the frame);
 *   - energy conservation, hourglass energy < 10 % of internal and added mass < 2 % (the
 *     issue's bounds). */
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/cli_util.h"
#include "tests/s3_test_util.h"

#include "core/mcs_results.h"
#include "fe/fe_scn_build.h"
#include "stage3_fe/s3_moto.h"
#include "stage3_fe/s3_run.h"
#include "stage3_fe/s3_scenario.h"
#include "stage3_fe/s3_wallcase.h"
#include "translators/tr_retune.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define V0 13.4
#define E_KIN0 (0.5 * 208 * V0 * V0 + 0.5 * 0.6 * pow(V0 / 0.30, 2) + 0.5 * 0.9 * pow(V0 / 0.315, 2))

static char tmpdir[64];

/* the thesis scenario with stage 3's element size and end time replaced (include merges by
 * name), loaded as if it were a file in scenarios/ (its include resolves there) */
static mcs_scenario *load_case(double h_mm, double end_ms)
{
    char text[512], mesh[128] = "";
    if (h_mm > 0) /* else the scenario's run mesh */
        snprintf(mesh, sizeof mesh,
                 "  fe:\n    parts:\n      - name: moto\n        mesh: {element_size: %g mm}\n",
                 h_mm);
    snprintf(text, sizeof text,
             "mcrash: 1\ninclude: [thesis_frontal_barrier_13.4.yaml]\n"
             "stage3:\n  simulation: {end_time: %g ms}\n%s",
             end_ms, mesh);
    mcs_scenario *s = NULL;
    mcs_error err = {0};
    CHECK(mcs_scenario_load_text("scenarios/wall_case.yaml", text, strlen(text), &s, &err) ==
          MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    return s;
}

/* stage 3 of the case into out (append: added to the file); the summary */
static int run_case_into(double h_mm, double end_ms, const char *out, int append, s3_summary *sum)
{
    mcs_scenario *scn = load_case(h_mm, end_ms), *s3 = NULL;
    mcs_error err = {0};
    fe_problem p = {0};
    mcs_status st = scn ? s3_scenario_compile(scn, &s3, &err) : MCS_ERR_KEY;
    if (!st) st = fe_scn_build(s3, &p, &err);
    if (!st) {
        s3_run_opts o = {
            .out_path = out, .scenario_text = mcs_scenario_text(scn), .quiet = 1, .append = append};
        st = s3_run(&p, &o, sum, &err);
    }
    if (st) printf("  %s\n", err.msg);
    fe_problem_free(&p);
    mcs_scenario_destroy(&s3);
    mcs_scenario_destroy(&scn);
    return st == MCS_OK;
}

static int run_case(double h_mm, double end_ms, const char *out, s3_summary *sum)
{
    return run_case_into(h_mm, end_ms, out, 0, sum);
}

static double scalar(mcs_results *h, const char *path)
{
    mcs_array a = {0};
    mcs_error e = {0};
    double v = mcs_results_read(h, path, &a, &e) == MCS_OK && a.n ? a.v[0] : NAN;
    mcs_array_free(&a);
    return v;
}

/* the compiled stage-3 scenario: fe: is stage3.fe, simulation: has stage3's keys over it, the
 * stage-1 keys are gone; a wall naming a part outside stage3.fe is refused at its line */
static void test_compile(void)
{
    mcs_scenario *scn = load_case(40, 15), *s3 = NULL;
    mcs_error err = {0};
    CHECK(scn && s3_scenario_compile(scn, &s3, &err) == MCS_OK);
    if (!s3) {
        mcs_scenario_destroy(&scn);
        return;
    }
    const mcs_node *r = mcs_scenario_root(s3), *sim = mcs_node_get(r, "simulation");
    CHECK(mcs_node_get(r, "bodies") == NULL && mcs_node_get(r, "impact") == NULL);
    CHECK(mcs_node_get(r, "stage3") == NULL && mcs_node_get(r, "contacts") == NULL);
    CHECK_NEAR(mcs_node_num_or(sim, "end_time", 0), 0.015, 1e-15);
    CHECK_NEAR(mcs_node_num_or(sim, "output_rate", 0), 1e4, 1e-9);
    CHECK_NEAR(mcs_node_num_or(sim, "time_step", 0), 1e-5, 1e-15); /* stage 1's, kept */
    const mcs_node *part = mcs_node_at(mcs_node_get(mcs_node_get(r, "fe"), "parts"), 0);
    CHECK_STR_CONTAINS(mcs_node_str(mcs_node_get(part, "name")), "moto");
    CHECK_NEAR(mcs_node_num(mcs_node_get(mcs_node_get(part, "mesh"), "element_size")), 0.04,
               1e-15);
    mcs_scenario_destroy(&s3);
    mcs_scenario_destroy(&scn);
    /* stage 3's names are its own: a wall stopping a part of fe: (none here) is unknown (a
     * generated part <entry>_<component> of stage3.fe is known: test_s3_carcase.c) */
    const char *bad = "mcrash: 1\ninclude: [thesis_frontal_barrier_13.4.yaml]\n"
                      "stage3:\n  fe:\n    rigid_walls:\n"
                      "      - {name: barrier, parts: [front_tyre]}\n";
    mcs_error e2 = {0};
    CHECK(mcs_scenario_load_text("scenarios/wall_case.yaml", bad, strlen(bad), &scn, &e2) != 0);
    CHECK_STR_CONTAINS(e2.msg, "wall_case.yaml:6:33: error: stage3.fe.rigid_walls[1].parts[0]: "
                               "unknown FE part 'front_tyre'");
    mcs_scenario_destroy(&scn);
}

/* the coarse case: energies, the first contact, phases in order, fork angle, retune's reader */
static void test_coarse(void)
{
    char out[128];
    snprintf(out, sizeof out, "%s/wall40.h5", tmpdir);
    s3_summary sum;
    CHECK(run_case(40, 15, out, &sum));
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array t = {0}, ek = {0}, ei = {0}, eh = {0}, phi = {0}, f = {0}, fsum = {0}, d = {0};
    CHECK(mcs_results_read(h, "/stage3/time", &t, &err) == MCS_OK);
    CHECK(mcs_results_read(h, "/stage3/energy/kinetic", &ek, &err) == MCS_OK);
    CHECK(mcs_results_read(h, "/stage3/energy/internal", &ei, &err) == MCS_OK);
    CHECK(mcs_results_read(h, "/stage3/energy/hourglass", &eh, &err) == MCS_OK);
    CHECK(mcs_results_read(h, "/stage3/channels/moto_fork_deformation_angle", &phi, &err) ==
          MCS_OK);
    CHECK(mcs_results_read(h, "/stage3/rigidwall/barrier/force_mean", &f, &err) == MCS_OK);
    CHECK(mcs_results_read(h, "/stage3/rigidwall/barrier/crush", &d, &err) == MCS_OK);
    const size_t n = t.n;
    CHECK(n > 100 && ek.n == n && phi.n == n && f.n == n && d.n == n);
    if (!(n > 100 && ek.n == n && phi.n == n && f.n == n && d.n == n)) goto done;
    /* the parts' shares add up to the wall's force */
    fsum.v = calloc(n, sizeof(double));
    char **parts = NULL;
    int np = 0;
    CHECK(mcs_results_list(h, "/stage3/rigidwall/barrier/parts", &parts, &np, &err) == MCS_OK);
    for (int i = 0; i < np && fsum.v; i++) {
        char path[256];
        mcs_array a = {0};
        snprintf(path, sizeof path, "/stage3/rigidwall/barrier/parts/%s/force", parts[i]);
        CHECK(mcs_results_read(h, path, &a, &err) == MCS_OK && a.n == n);
        for (size_t k = 0; k < a.n && k < n; k++) fsum.v[k] += a.v[k];
        mcs_array_free(&a);
    }
    mcs_results_list_free(&parts, np);
    double fpk = 0, dsum = 0;
    for (size_t k = 0; k < n && fsum.v; k++) {
        fpk = fmax(fpk, f.v[k]);
        dsum = fmax(dsum, fabs(fsum.v[k] - f.v[k]));
    }
    printf("  %zu rows, wall force (interval means) up to %.4g N, parts' sum within %.3g N\n", n,
           fpk, dsum);
    CHECK(dsum <= 1e-9 * fpk);
    /* energies: the hand value at t = 0, conservation, hourglass and added mass bounds */
    printf("  kinetic energy at t = 0: %.2f J (by hand %.2f J); drift %.3g; hourglass %.3g "
           "(largest %.3g) of internal; added mass %.3g\n",
           ek.v[0], E_KIN0, sum.energy_drift, sum.hourglass_fraction, sum.hourglass_fraction_max,
           sum.mass_added_fraction);
    CHECK_REL(ek.v[0], E_KIN0, 1e-4); /* the FE wheels' spin inertia: the placement's residual */
    CHECK(sum.energy_drift < 0.01);
    CHECK(sum.hourglass_fraction_max < 0.10 && sum.hourglass_fraction < 0.10);
    CHECK(sum.mass_added_fraction < 0.02);
    FIG("s3.wall_coarse_e_kin0_j", "%.0f", ek.v[0]);
    FIG("s3.wall_coarse_elements", "%.0f", (double)sum.elements);
    FIG("s3.wall_coarse_hg_pct", "%.1f",
        100 * fmax(sum.hourglass_fraction, sum.hourglass_fraction_max));
    /* the first contact: the 5 mm gap closed at 13.4 m/s (0.373 ms), seen by the first row
     * after it (10 kHz rows) */
    const double t_tyre = scalar(h, "/stage3/phases/tyre/start_time");
    const double t_rim = scalar(h, "/stage3/phases/rim/start_time");
    const double t_fork = scalar(h, "/stage3/phases/fork/start_time");
    const double t_eng = scalar(h, "/stage3/phases/engine/start_time");
    printf("  phases: tyre %.2f ms, rim %.2f ms, fork %.2f ms, engine %.2f ms\n", 1e3 * t_tyre,
           1e3 * t_rim, 1e3 * t_fork, 1e3 * t_eng);
    CHECK(t_tyre >= 0.005 / V0 && t_tyre <= 0.005 / V0 + 1e-4 + 1e-6);
    CHECK(t_tyre < t_rim && t_rim < t_eng && t_fork < t_eng); /* Fig. 25's order */
    FIG("s3.wall_coarse_t_rim_ms", "%.1f", 1e3 * t_rim);
    FIG("s3.wall_coarse_t_fork_ms", "%.1f", 1e3 * t_fork);
    FIG("s3.wall_coarse_t_engine_ms", "%.1f", 1e3 * t_eng);
    /* the fork: still before the contact, bent rearward (> 0) after it */
    double phi_pre = 0;
    for (size_t k = 0; k < n && t.v[k] < 0.005 / V0; k++) phi_pre = fmax(phi_pre, fabs(phi.v[k]));
    double phi_eng = NAN; /* the fork angle when the wheel meets the engine */
    for (size_t k = 0; k < n; k++)
        if (fabs(t.v[k] - t_eng) < 1e-7) phi_eng = phi.v[k];
    FIG("s3.wall_coarse_phi_engine_rad", "%.2f", phi_eng);
    FIG("s3.wall_coarse_f_max_kn", "%.0f", 1e-3 * fpk);
    printf("  fork angle: %.2g rad before the contact, %.4f rad at %.1f ms; crush %.1f mm\n",
           phi_pre, phi.v[n - 1], 1e3 * t.v[n - 1], 1e3 * d.v[n - 1]);
    CHECK(phi_pre < 1e-4);
    CHECK(phi.v[n - 1] > 0.05);
    FIG("s3.wall_coarse_phi_end_rad", "%.2f", phi.v[n - 1]);
    /* mcrash retune reads this file: the barrier's force alone (not the ground's), the angle */
    tr_rt_target tg = {0};
    const tr_rt_opts ro = tr_rt_opts_default();
    CHECK(tr_rt_read_target(out, &ro, &tg, &err) == MCS_OK);
    CHECK(tg.nt == (int)n);
    double df = 0, da = 0;
    for (int k = 0; k < tg.nt && tg.nt == (int)n; k++) {
        df = fmax(df, fabs(tg.force[k] - f.v[k]));
        da = fmax(da, fabs(tg.angle[k] - phi.v[k]));
    }
    CHECK(df == 0 && da == 0);
    tr_rt_target_free(&tg);
done:
    free(fsum.v);
    mcs_array_free(&t), mcs_array_free(&ek), mcs_array_free(&ei), mcs_array_free(&eh);
    mcs_array_free(&phi), mcs_array_free(&f), mcs_array_free(&d);
    mcs_results_close(&h);
}

/* the commands: `run` (all stages) puts stage 1 and stage 3 into one file and one JSON object;
 * `stage3` and `run --stage 3` run the stage3: block alone */
static void test_commands(void)
{
    char scn[128], out[128], args[512];
    snprintf(scn, sizeof scn, "%s/two.yaml", tmpdir);
    snprintf(out, sizeof out, "%s/two.h5", tmpdir);
    write_text(scn, "mcrash: 1\nname: two stages\nsimulation: {end_time: 2 ms, output_rate: 5 kHz}\n"
                    "bodies:\n  - {name: ball, mass: 1 kg, inertia: [0.01, 0.01, 0.01], "
                    "position: [0, 0, 1 m], velocity: [1 m/s, 0, 0]}\n"
                    "stage3:\n  simulation: {end_time: 1 ms}\n  fe:\n    parts:\n"
                    "      - name: block\n"
                    "        mesh: {generate: box, size: [20 mm, 20 mm, 20 mm], "
                    "divisions: [2, 2, 2]}\n"
                    "        section: {type: solid}\n"
                    "        material: {model: elastic, density: 1000, youngs_modulus: 10 MPa, "
                    "poisson: 0.3}\n"
                    "        initial_velocity: [0, 0, -1 m/s]\n"
                    "    rigid_walls: [{name: floor, point: [0, 0, -10 mm], normal: [0, 0, 1]}]\n");
    snprintf(args, sizeof args, "run %s -o %s --json", scn, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"stage1\": {\"steps\"");
    CHECK_STR_CONTAINS(r->out, "\"stage3\": {\"steps\"");
    CHECK(strstr(r->out, "}}\n") != NULL && strchr(r->out, '\n') == strrchr(r->out, '\n'));
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    CHECK(h && mcs_results_exists(h, "/stage1/time") && mcs_results_exists(h, "/stage3/time"));
    CHECK(h && fabs(last_of(h, "/stage1/time") - 2e-3) < 1e-9); /* each stage its end time */
    CHECK(h && last_of(h, "/stage3/time") > 0.5e-3 && last_of(h, "/stage3/time") <= 1e-3);
    mcs_results_close(&h);
    snprintf(args, sizeof args, "stage3 %s -o %s --quiet", scn, out);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    CHECK(h && !mcs_results_exists(h, "/stage1") && mcs_results_exists(h, "/stage3/time"));
    mcs_results_close(&h);
    snprintf(args, sizeof args, "run %s -o %s --stage 3 --quiet", scn, out);
    CHECK(cli_run(args)->status == 0);
}

/* a run's curves: time, wall force (interval means), crush, fork angle */
typedef struct {
    mcs_array t, f, d, phi;
} curves;

static int read_curves(const char *h5, curves *c)
{
    mcs_results *h = NULL;
    mcs_error e = {0};
    int ok = mcs_results_open(&h, h5, &e) == MCS_OK &&
             mcs_results_read(h, "/stage3/time", &c->t, &e) == MCS_OK &&
             mcs_results_read(h, "/stage3/rigidwall/barrier/force_mean", &c->f, &e) == MCS_OK &&
             mcs_results_read(h, "/stage3/rigidwall/barrier/crush", &c->d, &e) == MCS_OK &&
             mcs_results_read(h, "/stage3/channels/moto_fork_deformation_angle", &c->phi, &e) ==
                 MCS_OK;
    mcs_results_close(&h);
    return ok && c->f.n == c->t.n && c->d.n == c->t.n && c->phi.n == c->t.n && c->t.n > 10;
}

static void free_curves(curves *c)
{
    mcs_array_free(&c->t), mcs_array_free(&c->f), mcs_array_free(&c->d), mcs_array_free(&c->phi);
}

/* the force over 5 ms windows (impulse / 5 ms) at crush d: the mean of the rows whose crush is
 * within 5 mm of d (NaN none); the curves of two meshes are compared on it */
static double force_at_crush(const curves *c, double d)
{
    double s = 0;
    int n = 0;
    for (size_t k = 0; k < c->t.n; k++)
        if (fabs(c->d.v[k] - d) < 5e-3) s += c->f.v[k], n++;
    return n ? s / n : NAN;
}

/* make verify: stage 1 of the scenario (`mcrash run --stage 1`), then its stage 3 at the run
 * mesh for its 100 ms added to the same file (as `mcrash run` does; in process: the command's
 * guard is 120 s) and the fork angles rated by `mcrash compare --stages 1,3`; 40 mm for the
 * same 100 ms: the wall force against crush at two element sizes */
static void test_run_mesh(void)
{
    if (!th_verify()) return;
    char out[128], out40[128], args[512];
    snprintf(out, sizeof out, "%s/full.h5", tmpdir);
    snprintf(out40, sizeof out40, "%s/wall40_100.h5", tmpdir);
    snprintf(args, sizeof args, "run scenarios/thesis_frontal_barrier_13.4.yaml -o %s --stage 1",
             out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    s3_summary sum, s40;
    CHECK(run_case_into(0, 100, out, 1, &sum));
    printf("  run mesh: %d elements, %ld steps, %.0f s of wall time, drift %.3g\n", sum.elements,
           sum.steps, sum.wall_time_s, sum.energy_drift);
    CHECK(sum.energy_drift < 0.02);
    CHECK(run_case(40, 100, out40, &s40));
    curves a = {0}, b = {0};
    CHECK(read_curves(out, &a) && read_curves(out40, &b));
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h || !a.t.n || !b.t.n) goto done;
    double fpk = 0, tpk = 0, dmax = 0, tdmax = 0, phimax = 0, imp = 0, fpk40 = 0;
    for (size_t k = 0; k < a.t.n; k++) {
        if (a.f.v[k] > fpk) fpk = a.f.v[k], tpk = a.t.v[k];
        if (a.d.v[k] > dmax) dmax = a.d.v[k], tdmax = a.t.v[k];
        phimax = fmax(phimax, a.phi.v[k]);
        if (k) imp += a.f.v[k] * (a.t.v[k] - a.t.v[k - 1]);
    }
    for (size_t k = 0; k < b.t.n; k++) fpk40 = fmax(fpk40, b.f.v[k]);
    printf("  run mesh: peak %.1f kN at %.1f ms, largest crush %.0f mm at %.1f ms, fork %.3f rad "
           "at most, impulse %.0f N s (m v = %.0f N s); 40 mm: peak %.1f kN\n",
           1e-3 * fpk, 1e3 * tpk, 1e3 * dmax, 1e3 * tdmax, phimax, imp, 208 * V0, 1e-3 * fpk40);
    FIG("s3.wall_f_peak_kn", "%.0f", 1e-3 * fpk);
    FIG("s3.wall_t_f_peak_ms", "%.1f", 1e3 * tpk);
    FIG("s3.wall_crush_max_mm", "%.0f", 1e3 * dmax);
    FIG("s3.wall_t_crush_max_ms", "%.0f", 1e3 * tdmax);
    FIG("s3.wall_phi_max_rad", "%.2f", phimax);
    FIG("s3.wall_f_peak40_kn", "%.0f", 1e-3 * fpk40);
    /* the mesh convergence of the force-crush curve: 5 ms means at crush 25, 50, ... mm */
    double dev = 0;
    printf("  crush [mm]  force run mesh / 40 mm [kN]\n");
    for (double d = 0.025; d < fmin(dmax, 0.5); d += 0.025) {
        double fa = force_at_crush(&a, d), fb = force_at_crush(&b, d);
        printf("  %5.0f  %7.1f  %7.1f\n", 1e3 * d, 1e-3 * fa, 1e-3 * fb);
        if (!isnan(fa) && !isnan(fb)) dev = fmax(dev, fabs(fa - fb));
    }
    FIG("s3.wall_mesh_dev_kn", "%.0f", 1e-3 * dev);
    /* the phases */
    const char *ph[4] = {"tyre", "rim", "fork", "engine"};
    for (int k = 0; k < 4; k++) {
        char path[128], key[64];
        snprintf(path, sizeof path, "/stage3/phases/%s/start_time", ph[k]);
        const double tk = scalar(h, path);
        snprintf(path, sizeof path, "/stage3/phases/%s/crush", ph[k]);
        const double dk = scalar(h, path);
        snprintf(path, sizeof path, "/stage3/phases/%s/peak_force", ph[k]);
        const double fk = scalar(h, path);
        printf("  phase %-6s from %5.1f ms, crush %4.0f mm, peak %6.1f kN\n", ph[k], 1e3 * tk,
               1e3 * dk, 1e-3 * fk);
        snprintf(key, sizeof key, "s3.wall_%s_ms", ph[k]);
        FIG(key, "%.1f", 1e3 * tk);
        snprintf(key, sizeof key, "s3.wall_%s_peak_kn", ph[k]);
        FIG(key, "%.0f", 1e-3 * fk);
    }
    /* energies: hourglass and added mass bounds, the parts that took the most */
    double hg = NAN, ma = NAN, elems = NAN;
    mcs_results_attr_double(h, "/stage3", "hourglass_fraction_max", &hg, &err);
    mcs_results_attr_double(h, "/stage3", "mass_added_fraction", &ma, &err);
    mcs_results_attr_double(h, "/stage3", "elements", &elems, &err);
    printf("  %.0f elements, hourglass %.3g of internal at most, added mass %.3g\n", elems, hg,
           ma);
    CHECK(hg < 0.10);
    CHECK(ma < 0.02);
    FIG("s3.wall_elements", "%.0f", elems);
    FIG("s3.wall_hg_pct", "%.1f", 100 * hg);
    char **parts = NULL;
    int np = 0;
    CHECK(mcs_results_list(h, "/stage3/parts", &parts, &np, &err) == MCS_OK);
    for (int i = 0; i < np; i++) {
        char path[256];
        snprintf(path, sizeof path, "/stage3/parts/%s/energy/internal", parts[i]);
        const double e = last_of(h, path);
        if (e > 200) printf("  internal energy at 100 ms: %-20s %6.0f J\n", parts[i], e);
    }
    mcs_results_list_free(&parts, np);
    /* stage 3's fork angle rated against stage 1's (ISO/TS 18571) */
    snprintf(args, sizeof args, "compare %s --stages 1,3", out);
    r = cli_run(args);
    printf("%s", r->out);
    CHECK_STR_CONTAINS(r->out, "moto_fork_deformation_angle");
done:
    mcs_results_close(&h);
    free_curves(&a), free_curves(&b);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s3wc_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    s3_moto_register();
    RUN(test_compile);
    RUN(test_commands);
    RUN(test_coarse);
    RUN(test_run_mesh);
    char cmd[96];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) return 1;
    TEST_END();
}

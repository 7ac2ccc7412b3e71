/* test_mb_couple_out.c: the results of a coupled stage-1 run (bodies + fe:) under /stage1 in the
 * /stage3 layout (stage1_mb/mb_couple_out.c, docs/contracts.md), through `mcrash stage1`.
 *
 * A 20 kg sled moving at 1 m/s carries a closed fabric sphere (attached at its lowest nodes) and
 * the far end of a belt whose other end runs through a slip ring into a retractor:
 * - the bag's gas mass is m0 + m_dot t (closed bag, paper 2023 Eq. 4 without exhaust or
 *   leakage; m0 = p_amb V0 / (R T_amb)) and the pretensioner's payout is Eq. 3 (fired at 1 ms,
 *   100 mm over 15 ms), both at the FE state's time, which is one FE step delta before the row's
 *   /stage1/time (the same delta in every row, 0 < delta <= the ODE step);
 * - the bag's attached node is where the sled's rigid motion puts it (position + rotation of
 *   its offset at t = 0, from /stage1/bodies/sled);
 * - `mcrash export --xdmf` references only datasets that exist, with their shapes, and shows
 *   the FE parts and the body at the same times;
 * - a head (a body) falling onto the bag through a bodies contact: the file has the same bytes
 *   on 1 and 2 OpenMP threads. */
#include "cli_util.h"
#include "core/mcs_results.h"
#include "harness.h"
#include "figures.h"
#include "s3_test_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static char tmpdir[64];

/* the sled scenario; element size of the bag [mm], end time [ms] */
#define SLED_YAML                                                                                  \
    "mcrash: 1\n"                                                                                  \
    "name: \"a sled carrying a bag and a belt\"\n"                                                 \
    "simulation: {end_time: %g ms, time_step: 10 us, output_rate: 5 kHz}\n"                        \
    "environment: {gravity: 9.81}\n"                                                               \
    "bodies:\n"                                                                                    \
    "  - {name: sled, mass: 20, inertia: [0.5, 0.5, 0.5], position: [0, 0, 0],\n"                  \
    "     velocity: [1, 0, 0], angular_velocity: [0, 0, 2],\n"                                     \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.2, 0.1, 0.05]}]}\n"       \
    "  - {name: head, mass: 4, inertia: [0.02, 0.02, 0.02], position: [0.05, 0, 0.383],\n"        \
    "     velocity: [0, 0, -5], surfaces: [{type: ellipsoid, center: [0, 0, 0],\n"               \
    "     semi_axes: [0.08, 0.08, 0.08]}]}\n"                                                     \
    "fe:\n"                                                                                        \
    "  parts:\n"                                                                                   \
    "    - name: fabric\n"                                                                         \
    "      mesh: {generate: sphere_shell, origin: [0.05, 0, 0.2], radius: 100 mm,\n"              \
    "             element_size: %g mm}\n"                                                          \
    "      section: {type: membrane, thickness: 0.5 mm}\n"                                         \
    "      material: {model: fabric, density: 1000, youngs_modulus: 500 MPa, poisson: 0.3,\n"      \
    "                 damping: 0.3}\n"                                                             \
    "      attach: {body: sled, where: z_min}\n"                                                   \
    "    - name: belt\n"                                                                           \
    "      mesh: {generate: line, origin: [0, 0, 0.5], end: [0.5, 0, 0.5], divisions: 2}\n"        \
    "      section: {type: truss, area: 40 mm^2, tension_only: true}\n"                            \
    "      material: {model: elastic, density: 1000, youngs_modulus: 10 GPa, poisson: 0}\n"        \
    "      attach: {body: sled, where: x_max}\n"                                                   \
    "  boundary: [{part: belt, where: x_min, fix: translations}]\n"                                \
    "  airbags:\n"                                                                                 \
    "    - {name: bag, parts: [fabric],\n"                                                         \
    "       inflator: {mass_flow: [[0, 0.2 kg/s], [10 ms, 0.2 kg/s]], temperature: [[0, 600 "     \
    "K]]}}\n"                                                                                      \
    "  retractors:\n"                                                                              \
    "    - {name: ret, part: belt, where: x_min, anchor: [0, 0, 0], fire_time: 1 ms,\n"            \
    "       load_limit: 2 kN}\n"                                                                   \
    "  sliprings:\n"                                                                               \
    "    - {name: ring, part: belt, point: [0, 0, 0.5], friction: 0.2, retractor: ret}\n"         \
    "  contacts: [{type: single_surface, parts: [fabric], friction: 0.2},\n"                   \
    "             {name: head_bag, type: bodies, parts: [fabric], bodies: [head]}]\n"

static const char *sled(const char *name, double elem_mm, double end_ms)
{
    static char path[128];
    char text[4096];
    snprintf(text, sizeof text, SLED_YAML, end_ms, elem_mm);
    snprintf(path, sizeof path, "%s/%s.yaml", tmpdir, name);
    write_text(path, text);
    return path;
}

/* paper 2023 Eq. 3: pay-in after firing at tf, 100 mm over 15 ms */
static double eq3(double t, double tf)
{
    double tau = t - tf;
    return tau <= 0 ? 0 : tau < 0.015 ? -0.1 / 0.015 * tau : -0.1;
}

/* quaternion w, x, y, z (body -> world) to a row-major rotation matrix */
static void quat_rot(const double *q, double R[9])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                   2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                   2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    memcpy(R, r, sizeof r);
}

static void test_layout_and_values(void)
{
    char out[128], args[512];
    snprintf(out, sizeof out, "%s/sled.h5", tmpdir);
    snprintf(args, sizeof args, "stage1 %s -o %s --quiet", sled("sled", 40, 4), out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array t = {0}, ft = {0}, d = {0}, nodes = {0}, m = {0}, pl = {0}, pos = {0}, ori = {0};
    mcs_array V = {0}, cf = {0};
    CHECK(rd(h, "/stage1/time", &t) && rd(h, "/stage1/fields/time", &ft) &&
          rd(h, "/stage1/fields/displacement", &d) && rd(h, "/stage1/mesh/fabric/nodes", &nodes) &&
          rd(h, "/stage1/airbag/bag/mass", &m) && rd(h, "/stage1/airbag/bag/volume", &V) &&
          rd(h, "/stage1/retractor/ret/payout_pretensioner", &pl) &&
          rd(h, "/stage1/bodies/sled/position", &pos) &&
          rd(h, "/stage1/bodies/sled/orientation", &ori) &&
          rd(h, "/stage1/contact/contact0/force", &cf));
    const char *more[] = {"/stage1/mesh/belt/elements", "/stage1/mesh/fabric/elements",
                          "/stage1/airbag/bag/pressure", "/stage1/airbag/bag/temperature",
                          "/stage1/retractor/ret/force", "/stage1/retractor/ret/payout",
                          "/stage1/slipring/ring/force0", "/stage1/slipring/ring/slip",
                          "/stage1/parts/fabric/energy/internal",
                          "/stage1/parts/belt/energy/kinetic", "/stage1/contact/contact0/energy"};
    for (size_t i = 0; i < sizeof more / sizeof *more; i++) {
        CHECK(mcs_results_kind(h, more[i]) == MCS_RES_DATASET);
        if (mcs_results_kind(h, more[i]) != MCS_RES_DATASET) fprintf(stderr, "  %s\n", more[i]);
    }
    /* one row per /stage1/time row, at the same times; 4 ms at 5 kHz */
    const size_t nt = t.n;
    CHECK(nt == 21 && ft.n == nt && m.n == nt && pl.n == nt && V.n == nt);
    CHECK(cf.rank == 2 && cf.dims[0] == nt && cf.dims[1] == 3);
    CHECK(d.rank == 3 && d.dims[0] == nt && d.dims[2] == 3);
    for (size_t i = 0; i < nt && i < ft.n; i++) CHECK(ft.v[i] == t.v[i]);
    /* the gas and the pretensioner at the FE time t - delta */
    const double R = 287.05, m0 = 101325 * V.v[0] / (R * 293.15), mdot = 0.2;
    double dmin = INFINITY, dmax = -INFINITY, worst_pl = 0;
    for (size_t i = 1; i < nt && i < m.n && i < pl.n; i++) {
        double delta = t.v[i] - (m.v[i] - m0) / mdot;
        dmin = fmin(dmin, delta), dmax = fmax(dmax, delta);
        worst_pl = fmax(worst_pl, fabs(pl.v[i] - eq3(t.v[i] - delta, 1e-3)));
    }
    printf("  bag and retractor lag /stage1/time by one FE step: %.4f..%.4f us; "
           "|payout - Eq. 3| <= %.1e m\n", 1e6 * dmin, 1e6 * dmax, worst_pl);
    CHECK(dmin > 0 && dmax <= 10e-6 * (1 + 1e-9)); /* within the ODE step */
    CHECK(dmax - dmin < 1e-10);                   /* the same FE step each time */
    CHECK(worst_pl < 1e-12);
    CHECK(pl.v[nt - 1] < -0.01); /* the pretensioner has pulled in (3 ms of 15) */
    /* the attached node (the sphere's lowest) moves with the sled: x0 + u(t) =
     * p(t) + R(t) R(0)^T (x0 - p(0)) */
    size_t low = 0;
    for (size_t j = 0; j < nodes.dims[0]; j++)
        if (nodes.v[3 * j + 2] < nodes.v[3 * low + 2]) low = j;
    double R0[9], Rt[9], worst_x = 0, travel = 0;
    quat_rot(ori.v, R0);
    const double *x0 = nodes.v + 3 * low, *p0 = pos.v;
    double l[3];
    for (int a = 0; a < 3; a++)
        l[a] = R0[a] * (x0[0] - p0[0]) + R0[3 + a] * (x0[1] - p0[1]) + R0[6 + a] * (x0[2] - p0[2]);
    for (size_t i = 0; i < nt && d.rank == 3; i++) {
        quat_rot(ori.v + 4 * i, Rt);
        for (int a = 0; a < 3; a++) {
            double xb = pos.v[3 * i + a] + Rt[3 * a] * l[0] + Rt[3 * a + 1] * l[1] +
                        Rt[3 * a + 2] * l[2];
            double xf = x0[a] + d.v[(i * d.dims[1] + low) * 3 + a]; /* fabric's offset is 0 */
            worst_x = fmax(worst_x, fabs(xf - xb));
            if (a == 0) travel = fabs(xf - x0[0]);
        }
    }
    printf("  attached node on the sled's rigid motion within %.1e m (travel %.2f mm)\n", worst_x,
           1e3 * travel);
    CHECK(worst_x < 1e-12);
    CHECK(travel > 2e-3); /* 1 m/s over 4 ms, braked by the belt */
    /* the parts' energies are the FE share of /stage1/energy: kinetic = the bodies' (1/2 m v^2
     * + 1/2 I w^2, isotropic inertias of the scenario) + the parts'; internal (no joints) = the
     * parts' internal + hourglass */
    const char *bn[2] = {"sled", "head"};
    const double bm[2] = {20, 4}, bi[2] = {0.5, 0.02};
    mcs_array ek = {0}, ei = {0}, pk[2] = {{0}}, pi[2] = {{0}}, ph[2] = {{0}}, bv[2] = {{0}};
    mcs_array bw[2] = {{0}};
    const char *pn[2] = {"fabric", "belt"};
    int ok = rd(h, "/stage1/energy/kinetic", &ek) && rd(h, "/stage1/energy/internal", &ei);
    for (int k = 0; k < 2 && ok; k++) {
        char path[128];
        snprintf(path, sizeof path, "/stage1/parts/%s/energy/kinetic", pn[k]);
        ok = rd(h, path, &pk[k]);
        snprintf(path, sizeof path, "/stage1/parts/%s/energy/internal", pn[k]);
        ok = ok && rd(h, path, &pi[k]);
        snprintf(path, sizeof path, "/stage1/parts/%s/energy/hourglass", pn[k]);
        ok = ok && rd(h, path, &ph[k]);
        snprintf(path, sizeof path, "/stage1/bodies/%s/velocity", bn[k]);
        ok = ok && rd(h, path, &bv[k]);
        snprintf(path, sizeof path, "/stage1/bodies/%s/angular_velocity", bn[k]);
        ok = ok && rd(h, path, &bw[k]);
    }
    CHECK(ok);
    double worst_k = 0, worst_i = 0, fe_k = 0;
    for (size_t i = 0; ok && i < nt; i++) {
        double kb = 0, kp = pk[0].v[i] + pk[1].v[i];
        for (int k = 0; k < 2; k++) {
            const double *v = bv[k].v + 3 * i, *w = bw[k].v + 3 * i;
            kb += 0.5 * bm[k] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
                  0.5 * bi[k] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        }
        worst_k = fmax(worst_k, fabs(ek.v[i] - kb - kp) / ek.v[i]);
        worst_i = fmax(worst_i, fabs(ei.v[i] - (pi[0].v[i] + pi[1].v[i] + ph[0].v[i] +
                                                 ph[1].v[i])));
        fe_k = fmax(fe_k, kp);
    }
    printf("  parts' energies: kinetic of bodies + parts within %.1e of /stage1/energy "
           "(parts up to %.3g J), internal within %.1e J\n", worst_k, fe_k, worst_i);
    CHECK(worst_k < 1e-12);
    CHECK(worst_i < 1e-12);
    mcs_array_free(&ek), mcs_array_free(&ei);
    for (int k = 0; k < 2; k++) {
        mcs_array_free(&pk[k]), mcs_array_free(&pi[k]), mcs_array_free(&ph[k]);
        mcs_array_free(&bv[k]), mcs_array_free(&bw[k]);
    }
    mcs_array_free(&t), mcs_array_free(&ft), mcs_array_free(&d), mcs_array_free(&nodes);
    mcs_array_free(&m), mcs_array_free(&pl), mcs_array_free(&pos), mcs_array_free(&ori);
    mcs_array_free(&V), mcs_array_free(&cf);
    mcs_results_close(&h);
}

/* simulation.field_rate: /stage1/fields at every k-th row of /stage1/time (k = 5 for 1 kHz
 * fields at 5 kHz output), the same frames as the full-rate file of test_layout_and_values;
 * stage 3 likewise (a 2-element bar, 1 ms at 10 kHz, fields at 2 kHz) */
static void test_field_rate(void)
{
    char scn[128], out[128], full[128], args[512], text[4096];
    snprintf(text, sizeof text, SLED_YAML, 4.0, 40.0);
    char *sim = strstr(text, "output_rate: 5 kHz}");
    CHECK(sim != NULL);
    if (!sim) return;
    char tail[4096];
    snprintf(tail, sizeof tail, "%s", sim + strlen("output_rate: 5 kHz}"));
    snprintf(sim, sizeof text - (size_t)(sim - text), "output_rate: 5 kHz, field_rate: 1 kHz}%s",
             tail);
    snprintf(scn, sizeof scn, "%s/rate.yaml", tmpdir);
    write_text(scn, text);
    snprintf(out, sizeof out, "%s/rate.h5", tmpdir);
    snprintf(full, sizeof full, "%s/sled.h5", tmpdir);
    snprintf(args, sizeof args, "stage1 %s -o %s --quiet", scn, out);
    CHECK(cli_run(args)->status == 0);
    mcs_results *h = NULL, *g = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK && mcs_results_open(&g, full, &err) == MCS_OK);
    mcs_array t = {0}, ft = {0}, d = {0}, dfull = {0};
    CHECK(h && g && rd(h, "/stage1/time", &t) && rd(h, "/stage1/fields/time", &ft) &&
          rd(h, "/stage1/fields/displacement", &d) && rd(g, "/stage1/fields/displacement", &dfull));
    CHECK(t.n == 21 && ft.n == 5 && d.dims[0] == 5 && dfull.dims[0] == 21);
    const size_t row = d.dims[1] * 3;
    for (size_t i = 0; i < ft.n && 5 * i < t.n && d.dims[0] == 5 && dfull.dims[0] == 21; i++) {
        CHECK(ft.v[i] == t.v[5 * i]);
        CHECK(memcmp(d.v + i * row, dfull.v + 5 * i * row, row * sizeof *d.v) == 0);
    }
    mcs_array_free(&t), mcs_array_free(&ft), mcs_array_free(&d), mcs_array_free(&dfull);
    mcs_results_close(&h);
    mcs_results_close(&g);
    /* stage 3 */
    snprintf(scn, sizeof scn, "%s/belt3.yaml", tmpdir);
    write_text(scn, "mcrash: 1\nname: belt\n"
                    "simulation: {end_time: 1 ms, time_step: 50 us, output_rate: 10 kHz,"
                    " field_rate: 2 kHz}\n"
                    "fe:\n  parts:\n    - name: belt\n"
                    "      mesh: {generate: line, origin: [0, 0, 0], end: [1, 0, 0],"
                    " divisions: 2}\n"
                    "      section: {type: truss, area: 40 mm^2}\n"
                    "      material: {model: elastic, density: 1000, youngs_modulus: 10 GPa,"
                    " poisson: 0}\n"
                    "      initial_velocity: [1, 0, 0]\n");
    snprintf(out, sizeof out, "%s/belt3.h5", tmpdir);
    snprintf(args, sizeof args, "stage3 %s -o %s --quiet", scn, out);
    CHECK(cli_run(args)->status == 0);
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    CHECK(h && rd(h, "/stage3/time", &t) && rd(h, "/stage3/fields/time", &ft));
    printf("  field_rate: stage 1 %zu of 21 rows; stage 3 %zu fields, %zu rows\n", (size_t)5,
           ft.n, t.n);
    CHECK(ft.n == 3 && t.n >= 10); /* 0, 0.5, 1 ms */
    for (size_t i = 0; i < ft.n; i++) /* the first step at or after each 0.5 ms */
        CHECK(ft.v[i] > 0.5e-3 * (double)i - 1e-12 && ft.v[i] < 0.5e-3 * (double)i + 50e-6);
    mcs_array_free(&t), mcs_array_free(&ft);
    mcs_results_close(&h);
}

/* a bodies contact's force (mb_couple_contact.c): a 1 kg ball at 1 m/s onto a fixed plate,
 * no gravity (the drop of test_mb_couple_contact): /stage1/contact/hit/force is the force on
 * the FE side, so its impulse is minus the ball's momentum change, M (v_end - v_0) from
 * /stage1/bodies/ball/velocity (impulse-momentum; trapezoids over the 20 us rows); the ball's
 * kernel ellipsoid is /stage1/ellipsoid/hit:<surface>/force, the force on the ball */
static void test_bodies_contact_force(void)
{
    char scn[128], out[128], args[512];
    snprintf(scn, sizeof scn, "%s/drop.yaml", tmpdir);
    write_text(scn,
               "mcrash: 1\nname: drop\n"
               "simulation: {end_time: 6 ms, time_step: 20 us, output_rate: 50 kHz}\n"
               "environment: {gravity: 0}\n"
               "bodies:\n"
               "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004],\n"
               "     position: [0, 0, 0.1015],\n"
               "     velocity: [0, 0, -1], angular_velocity: [0, 0, 0],\n"
               "     surfaces: [{type: ellipsoid, center: [0, 0, 0],\n"
               "                 semi_axes: [0.1, 0.1, 0.1]}]}\n"
               "fe:\n  parts:\n    - name: plate\n"
               "      mesh: {generate: plate, size: [0.08, 0.08], divisions: [32, 32],\n"
               "             origin: [-0.04, -0.04, 0]}\n"
               "      section: {type: shell, thickness: 2 mm}\n"
               "      material: {model: elastic, density: 7.85e6, youngs_modulus: 210 GPa,"
               " poisson: 0.3}\n"
               "  boundary: [{part: plate, where: all, fix: all}]\n"
               "  contacts: [{name: hit, type: bodies, parts: [plate], bodies: [ball],"
               " penalty_scale: 0.001}]\n");
    snprintf(out, sizeof out, "%s/drop.h5", tmpdir);
    snprintf(args, sizeof args, "stage1 %s -o %s --quiet", scn, out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    char **names = NULL;
    int n = 0;
    CHECK(mcs_results_list(h, "/stage1/ellipsoid", &names, &n, &err) == MCS_OK);
    CHECK(n == 1 && strncmp(names[0], "hit:", 4) == 0);
    char ep[256];
    snprintf(ep, sizeof ep, "/stage1/ellipsoid/%s/force", n == 1 ? names[0] : "?");
    mcs_results_list_free(&names, n);
    mcs_array t = {0}, f = {0}, fe = {0}, v = {0};
    CHECK(rd(h, "/stage1/time", &t) && rd(h, "/stage1/contact/hit/force", &f) && rd(h, ep, &fe) &&
          rd(h, "/stage1/bodies/ball/velocity", &v));
    CHECK(f.rank == 2 && f.dims[0] == t.n && f.dims[1] == 3 && fe.n == f.n);
    double J = 0, fpeak = 0, worst_sym = 0;
    for (size_t i = 1; i < t.n && f.n == 3 * t.n; i++)
        J += 0.5 * (f.v[3 * i + 2] + f.v[3 * i - 1]) * (t.v[i] - t.v[i - 1]);
    for (size_t i = 0; i < f.n && i < fe.n; i++) {
        fpeak = fmax(fpeak, fabs(f.v[i]));
        worst_sym = fmax(worst_sym, fabs(f.v[i] + fe.v[i]));
    }
    const double dp = 1.0 * (v.v[v.n - 1] - v.v[2]); /* M (v_end - v_0), z */
    printf("  bodies contact 'hit': impulse on the plate %.5f N s, ball's momentum change "
           "%.5f N s (%.2f %%), peak %.0f N\n",
           J, dp, 100 * (-J / dp - 1), fpeak);
    FIG("stage1_engine.couple_out_impulse_err_pct", "%.2f", fabs(100 * (-J / dp - 1)));
    CHECK(dp > 1.5);                 /* it bounced */
    CHECK_REL(-J, dp, 0.0012);       /* output-row trapezoids: 0.04 % measured */
    CHECK(worst_sym == 0);           /* the plate's force is minus the ball's */
    mcs_array_free(&t), mcs_array_free(&f), mcs_array_free(&fe), mcs_array_free(&v);
    mcs_results_close(&h);
}

/* ---- the XDMF file ---- */

static int parse_dims(const char *s, size_t *d, int max)
{
    int n = 0;
    char *end;
    while (n < max) {
        unsigned long long v = strtoull(s, &end, 10);
        if (end == s) break;
        d[n++] = (size_t)v;
        s = end;
    }
    return n;
}

/* every HDF DataItem of the .xmf names a dataset of h (or, for "<xmf>.h5:", of the
 * outlines file hs) with the shape it states (a block: the dataset's full shape and a block
 * inside it); returns the number checked */
static int check_items(mcs_results *h, mcs_results *hs, const char *xmf)
{
    int n = 0;
    for (const char *p = strstr(xmf, "Format=\"HDF\""); p; p = strstr(p + 1, "Format=\"HDF\"")) {
        const char *open = p;
        while (open > xmf && *open != '<') open--;
        const char *dm = strstr(open, "Dimensions=\"");
        const char *gt = strchr(p, '>'), *lt = gt ? strchr(gt, '<') : NULL;
        if (!dm || !gt || !lt) {
            CHECK(0);
            break;
        }
        size_t shown[3] = {0}, full[3] = {0}, start[3] = {0}, count[3] = {0}, ds[3] = {0};
        int rs = parse_dims(dm + 12, shown, 3);
        char ref[1024];
        snprintf(ref, sizeof ref, "%.*s", (int)(lt - gt - 1), gt + 1);
        char *colon = strchr(ref, ':'), *bar = strchr(ref, '|');
        CHECK(colon != NULL);
        if (!colon) break;
        if (bar) *bar = 0;
        const char *path = colon + 1;
        *colon = 0;
        mcs_results *in = strcmp(ref, "sled.xmf.h5") == 0 ? hs : h;
        int rk = 0;
        mcs_error err = {0};
        CHECK(in && mcs_results_shape(in, path, &rk, ds, &err) == MCS_OK);
        if (bar) { /* start:stride:count:dims */
            char *f[4], *save = NULL;
            int k = 0;
            for (char *tok = strtok_r(bar + 1, ":", &save); tok && k < 4;
                 tok = strtok_r(NULL, ":", &save))
                f[k++] = tok;
            CHECK(k == 4);
            if (k < 4) break;
            int r0 = parse_dims(f[0], start, 3), r2 = parse_dims(f[2], count, 3);
            int r3 = parse_dims(f[3], full, 3);
            CHECK(r0 == rk && r2 == rk && r3 == rk);
            size_t prod = 1, shown_n = 1;
            for (int a = 0; a < rk; a++) {
                CHECK(full[a] == ds[a]);
                CHECK(start[a] + count[a] <= ds[a]);
                prod *= count[a];
            }
            for (int a = 0; a < rs; a++) shown_n *= shown[a];
            CHECK(prod == shown_n);
        } else {
            CHECK(rs == rk);
            for (int a = 0; a < rk && a < rs; a++) CHECK(shown[a] == ds[a]);
        }
        n++;
    }
    return n;
}

/* the Time values of the temporal collection `name` (up to max) */
static int grid_times(const char *xmf, const char *name, double *t, int max)
{
    char key[128];
    snprintf(key, sizeof key, "<Grid Name=\"%s\" GridType=\"Collection\" "
                              "CollectionType=\"Temporal\">", name);
    const char *p = strstr(xmf, key);
    if (!p) return 0;
    const char *end = strstr(p, "\n    </Grid>");
    int n = 0;
    for (const char *q = strstr(p, "<Time Value=\""); q && q < end && n < max;
         q = strstr(q + 1, "<Time Value=\""))
        t[n++] = strtod(q + 13, NULL);
    return n;
}

static void test_xdmf_shows_parts_and_bodies(void)
{
    char out[128], xmf[128], args[512];
    snprintf(out, sizeof out, "%s/sled.h5", tmpdir);
    snprintf(xmf, sizeof xmf, "%s/sled.xmf", tmpdir);
    snprintf(args, sizeof args, "export %s --xdmf %s", out, xmf);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    size_t len = 0;
    char *x = th_slurp(xmf, &len);
    CHECK(x != NULL);
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!x || !h) {
        free(x);
        mcs_results_close(&h);
        return;
    }
    char side[160];
    snprintf(side, sizeof side, "%s.h5", xmf);
    mcs_results *hs = NULL;
    CHECK(mcs_results_open(&hs, side, &err) == MCS_OK);
    int items = check_items(h, hs, x);
    double tf[64], tb[64];
    int nf = grid_times(x, "stage1_fe", tf, 64), nb = grid_times(x, "stage1_bodies", tb, 64);
    mcs_array t = {0};
    CHECK(rd(h, "/stage1/time", &t));
    printf("  xdmf: %d HDF references checked; %d FE frames, %d body frames\n", items, nf, nb);
    CHECK(items > 100);
    CHECK(nf == (int)t.n && nb == (int)t.n);
    for (int i = 0; i < nf && i < nb && i < (int)t.n; i++)
        CHECK(tf[i] == t.v[i] && tb[i] == t.v[i]);
    CHECK(strstr(x, "<Grid Name=\"fabric\"") && strstr(x, "<Grid Name=\"belt\"") &&
          strstr(x, "<Grid Name=\"sled\""));
    /* the sled's outline in the world lies on its ellipsoid (semi-axes 0.2, 0.1, 0.05 m about
     * the centre of gravity, the scenario's) where /stage1/bodies/sled puts it */
    mcs_array xo = {0}, pos = {0}, ori = {0};
    CHECK(hs && rd(hs, "/stage1/outlines/sled/nodes", &xo) &&
          rd(h, "/stage1/bodies/sled/position", &pos) &&
          rd(h, "/stage1/bodies/sled/orientation", &ori));
    double worst = 0;
    CHECK(xo.rank == 3 && xo.dims[0] == t.n && xo.dims[1] == 62);
    for (size_t k = 0; xo.rank == 3 && k < xo.dims[0] && k < t.n; k++) {
        double R[9];
        quat_rot(ori.v + 4 * k, R);
        for (size_t j = 0; j < xo.dims[1]; j++) {
            const double *v = xo.v + 3 * (k * xo.dims[1] + j), *p = pos.v + 3 * k;
            const double semi[3] = {0.2, 0.1, 0.05};
            double e = 0;
            for (int a = 0; a < 3; a++) {
                double l = R[a] * (v[0] - p[0]) + R[3 + a] * (v[1] - p[1]) +
                           R[6 + a] * (v[2] - p[2]);
                e += (l / semi[a]) * (l / semi[a]);
            }
            worst = fmax(worst, fabs(e - 1));
        }
    }
    /* the parts' geometry is x0 + u (their positions in the same file): no filter needed */
    mcs_array xp = {0}, x0 = {0}, u = {0};
    CHECK(rd(hs, "/stage1/positions", &xp) && rd(h, "/stage1/mesh/fabric/nodes", &x0) &&
          rd(h, "/stage1/fields/displacement", &u));
    CHECK(xp.rank == 3 && xp.dims[0] == t.n && u.rank == 3 && xp.dims[1] == u.dims[1]);
    size_t bad = 0;
    for (size_t k = 0; xp.rank == 3 && xp.dims[1] == u.dims[1] && k < xp.dims[0]; k++)
        for (size_t j = 0; j < 3 * x0.dims[0]; j++) /* the fabric: node_offset 0 */
            bad += xp.v[3 * xp.dims[1] * k + j] != x0.v[j] + u.v[3 * u.dims[1] * k + j];
    CHECK(bad == 0);
    CHECK(strstr(x, "sled.xmf.h5:/stage1/positions|") != NULL);
    mcs_array_free(&xp), mcs_array_free(&x0), mcs_array_free(&u);
    printf("  sled outline on its ellipsoid within %.1e (x^2/a^2 + ... - 1); parts at x0 + u\n",
           worst);
    CHECK(worst < 1e-12);
    mcs_array_free(&xo), mcs_array_free(&pos), mcs_array_free(&ori);
    mcs_results_close(&hs);
    mcs_array_free(&t);
    mcs_results_close(&h);
    free(x);
}

/* the same bytes on 1 and 2 threads: a bag of > 8 chunks of 128 elements, so that the FE
 * loops run threaded (fe/step/fe_parallel.c); SOURCE_DATE_EPOCH fixes /meta created */
static void test_same_bytes_on_1_and_2_threads(void)
{
    const char *scn = sled("fine", 12, 1.5);
    char out[2][128], args[512];
    setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
    setenv("OMP_WAIT_POLICY", "PASSIVE", 1); /* a loaded machine: no spinning */
    for (int k = 0; k < 2; k++) {
        setenv("OMP_NUM_THREADS", k ? "2" : "1", 1);
        snprintf(out[k], sizeof out[k], "%s/fine%d.h5", tmpdir, k + 1);
        snprintf(args, sizeof args, "stage1 %s -o %s --quiet", scn, out[k]);
        CHECK(cli_run(args)->status == 0);
    }
    unsetenv("SOURCE_DATE_EPOCH");
    unsetenv("OMP_NUM_THREADS");
    unsetenv("OMP_WAIT_POLICY");
    size_t na = 0, nb = 0;
    char *a = th_slurp(out[0], &na), *b = th_slurp(out[1], &nb);
    CHECK(a && b && na == nb && na > 0 && memcmp(a, b, na) == 0);
    mcs_results *h = NULL;
    mcs_error err = {0};
    int rk = 0;
    size_t dims[3] = {0};
    CHECK(mcs_results_open(&h, out[0], &err) == MCS_OK);
    CHECK(h && mcs_results_shape(h, "/stage1/mesh/fabric/elements", &rk, dims, &err) == MCS_OK);
    mcs_array hf = {0};
    double fpeak = 0; /* the head has reached the bag: the bodies contact ran */
    CHECK(h && rd(h, "/stage1/contact/head_bag/force", &hf));
    for (size_t i = 0; i < hf.n; i++) fpeak = fmax(fpeak, fabs(hf.v[i]));
    mcs_array_free(&hf);
    printf("  1 and 2 threads: %zu bytes, identical; bag of %zu elements, head on the bag %.0f N\n",
           na, dims[0], fpeak);
    CHECK(fpeak > 10);
    CHECK(dims[0] >= 8 * 128);
    mcs_results_close(&h);
    free(a);
    free(b);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s1o_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_layout_and_values);
    RUN(test_xdmf_shows_parts_and_bodies);
    RUN(test_field_rate);
    RUN(test_bodies_contact_force);
    RUN(test_same_bytes_on_1_and_2_threads);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd)) printf("  could not remove %s\n", tmpdir);
    TEST_END();
}

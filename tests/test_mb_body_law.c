/* tests for the body-side contact law of fe.contacts[] of type bodies (body_characteristic:
 * fe/contact/fe_contact.c, docs/contracts.md "Soft body surfaces in bodies contacts"): the body's
 * surface yields by delta_b under the stress sigma(delta_b) over each FE node's tributary area,
 * in series with the node's penalty spring.
 *
 * The body is a very flat ellipsoid (semi-axes 10 x 10 x 0.05 m: radius of curvature at its
 * pole a^2 / c = 2000 m, so over the 80 mm plate its face lies within rho^2 / 2R = 0.8 um of a
 * plane): a flat punch over the whole plate, of area A = 80 x 80 mm^2. The closed forms take
 * the per-node penalty k_n = s m_n / dt0^2 from the model as an input (docs/fe.md "Contact"). */
#include "fe/fe_contact.h"
#include "fe/fe_state.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_contact.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_couple_test_util.h"
#include "tests/mb_test_util.h"

#define SEMI_C 0.05 /* the punch's half height [m] */
#define SIDE 0.08   /* the plate's and the block's side [m] */

/* the punch (1 kg) falling at v0 onto a fixed 2 mm shell plate in z = 0 (16 x 16 quads), the
 * body law `law` on the contact */
#define PLATE_YAML                                                                                 \
    "mcrash: 1\nname: punch\n"                                                                     \
    "simulation: {end_time: %g, time_step: 20 us, output_rate: 10 kHz}\n"                          \
    "environment: {gravity: 0}\n"                                                                  \
    "bodies:\n"                                                                                    \
    "  - {name: punch, mass: 1, inertia: [1, 1, 1], position: [0, 0, %.9g],\n"                     \
    "     velocity: [0, 0, %g], angular_velocity: [0, 0, 0],\n"                                    \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [10, 10, 0.05]}]}\n"          \
    "fe:\n  parts:\n    - name: plate\n"                                                           \
    "      mesh: {generate: plate, size: [0.08, 0.08], divisions: [16, 16],\n"                     \
    "             origin: [-0.04, -0.04, 0]}\n"                                                    \
    "      section: {type: shell, thickness: 2 mm}\n"                                              \
    "      material: {model: elastic, density: 7.85e6, youngs_modulus: 210 GPa, poisson: 0.3}\n"   \
    "  boundary: [{part: plate, where: all, fix: all}]\n"                                          \
    "  contacts: [{name: soft, type: bodies, parts: [plate], bodies: [punch],\n"                   \
    "              body_characteristic: %s}]\n"

/* the punch's z velocity */
static double punch_vz(const mb_state *s)
{
    mb_body_kin k;
    mb_body_get(s->world, 0, &k);
    return k.vel[2];
}

/* m run to its end (the status CHECKed, an error printed); *fpeak (NULL: none) raised to the
 * largest z force of the punch's contact at the ends of the FE steps */
static mb_state *run_punch(const mb_model *m, double *fpeak)
{
    mcs_error err = {0};
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    CHECK(st == MCS_OK);
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        if (fpeak) *fpeak = fmax(*fpeak, s->couple->fe->contact->ell_force[2]);
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    return s;
}

/* the stress curve of the first test, sigma(delta) [Pa] (linear between its points) */
static const double law_x[] = {0, 1e-3, 3e-3, 10e-3}, law_y[] = {0, 20e3, 150e3, 1.5e6};
static double sigma(double d)
{
    for (int i = 0; i < 3; i++)
        if (d <= law_x[i + 1])
            return law_y[i] +
                   (law_y[i + 1] - law_y[i]) * (d - law_x[i]) / (law_x[i + 1] - law_x[i]);
    return law_y[3];
}
/* its integral from 0 to d [J/m^2] */
static double sigma_int(double d)
{
    double w = 0;
    for (int i = 0; i < 3 && d > law_x[i]; i++) {
        double b = fmin(d, law_x[i + 1]);
        w += 0.5 * (sigma(law_x[i]) + sigma(b)) * (b - law_x[i]);
    }
    return w;
}

/* A flat punch pressed onto a fixed plate through the stress curve sigma: at every FE force
 * evaluation the body's force is sigma(delta) A, delta the punch's penetration of the plate's
 * contact surface (its mid-plane + t/2) (the penalty in series takes A sigma / sum k_n, a few
 * 1e-6 of delta); elastic law: the punch rebounds at v0, its deepest penetration is where
 * A int_0^delta sigma = M v0^2 / 2 (energy), the peak force A sigma there. */
static void test_flat_punch_force_is_stress_times_area(void)
{
    const double v0 = 1, A = SIDE * SIDE, ht = 1e-3;
    char y[4096];
    snprintf(y, sizeof y, PLATE_YAML, 0.012, SEMI_C + ht + 0.2e-3, -v0,
             "{stress: [[0, 0], [1 mm, 20 kPa], [3 mm, 150 kPa], [10 mm, 1.5 MPa]]}");
    mcs_error err = {0};
    mb_model *m = mc_model("punch.yaml", y);
    if (!m) return;
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    CHECK(st == MCS_OK);
    double emax = 0, fpeak = 0, dmax = 0;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        const fe_contact_state *ks = s->couple->fe->contact;
        /* the kernel's last force evaluation: the ellipsoid's centre then (it moved on by dt v
         * after it) */
        const double zc = ks->ell_c[2] - s->couple->fe->dt * ks->ell_v[2];
        const double d = ht - (zc - SEMI_C), f = ks->ell_force[2];
        if (d > 0) {
            emax = fmax(emax, fabs(f - A * sigma(d)));
            dmax = fmax(dmax, d);
        }
        fpeak = fmax(fpeak, f);
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    /* deepest penetration by the energy balance: A int sigma = M v0^2 / 2 (bisection) */
    double lo = 0, hi = 10e-3;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (A * sigma_int(mid) < 0.5 * v0 * v0)
            lo = mid;
        else
            hi = mid;
    }
    const double fref = A * sigma(lo), vend = punch_vz(s), drift = mb_energy_drift(m, s);
    const double ferr = 100 * emax / fref, perr = 100 * (fpeak / fref - 1);
    printf("punch: |F - sigma(delta) A| at most %.3g N (%.3g %% of the peak); peak %.2f N "
           "(closed form %.2f N at delta %.3f mm, %+.3f %%), deepest %.3f mm; rebound %.5f m/s; "
           "drift %.3g\n",
           emax, ferr, fpeak, fref, 1e3 * lo, perr, 1e3 * dmax, vend, drift);
    FIG("contact.body_law_force_err_pct", "%.2f", ferr);
    FIG("contact.body_law_peak_err_pct", "%.2f", fabs(perr));
    CHECK(ferr < 0.05);
    CHECK_NEAR(perr, 0, 0.5);
    CHECK_NEAR(vend, v0, 2e-3 * v0);
    CHECK(fabs(drift) < 0.01); /* the exchange's lag (docs/stage1_engine.md) */
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Loading and unloading: a linear law sigma = c delta unloading along a line of slope k_u = 4 c
 * (unloading_slope, elastic_limit 0). On the rigid plate the punch stops at A c delta_m^2 / 2 =
 * M v0^2 / 2 and gets back the triangle under the unloading line, F_m^2 / (2 A k_u) = M v0^2
 * c / (2 k_u): it rebounds at v0 sqrt(c / k_u) = v0 / 2, and the contact energy at the end is
 * what the law dissipated, M v0^2 (1 - c / k_u) / 2 (hand calculation). */
static void test_hysteresis_rebound_and_dissipation(void)
{
    const double v0 = 1, ht = 1e-3;
    char y[4096];
    /* c = 10 MPa/m: delta_m = v0 sqrt(M / (c A)) = 3.95 mm */
    snprintf(y, sizeof y, PLATE_YAML, 0.02, SEMI_C + ht + 0.2e-3, -v0,
             "{stress: [[0, 0], [10 mm, 100 kPa]], unloading_slope: 40 MPa/m}");
    mb_model *m = mc_model("punch_h.yaml", y);
    if (!m) return;
    mb_state *s = run_punch(m, NULL);
    const fe_model *fm = m->couple->fe.model;
    const double vend = punch_vz(s), ec = fe_contact_energy(fm, s->couple->fe);
    const double eref = 0.5 * v0 * v0 * (1 - 0.25), drift = mb_energy_drift(m, s);
    const double verr = 100 * (vend / (0.5 * v0) - 1), eerr = 100 * (ec / eref - 1);
    printf("punch, hysteresis: rebound %.5f m/s (closed form %.5f, %+.3f %%), contact energy "
           "%.5f J (dissipated, closed form %.5f J, %+.3f %%), drift %.3g\n",
           vend, 0.5 * v0, verr, ec, eref, eerr, drift);
    FIG("contact.body_law_rebound_err_pct", "%.2f", fabs(verr));
    FIG("contact.body_law_dissipation_err_pct", "%.2f", fabs(eerr));
    CHECK_NEAR(verr, 0, 0.5);
    CHECK_NEAR(eerr, 0, 0.5);
    CHECK(fabs(drift) < 0.01); /* the exchange's lag (docs/stage1_engine.md) */
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* Springs in series: the punch onto an elastic pad (40 mm, E = 4 MPa, poisson 0: in uniaxial
 * compression its stiffness is E A / L; 2 % strain at the peak, so the small-strain value)
 * fixed at its base, the law sigma = c delta (c = 100 MPa/m, A c = E A / L: equal
 * stiffnesses), the nodes' penalties (sum K_p over the top face) between them. Loading: one
 * spring of 1/K = L / (E A) + 1 / K_p + 1 / (c A) (series); the pad weighs 10 g against the
 * punch's 1 kg and its first period (4 L sqrt(rho / E) = 0.5 ms) is short of the contact's
 * (2 pi sqrt(M / K) = 11 ms), so quasi-static: peak force v0 sqrt(M K).
 * Unloading along k_u = 4 c: K_u of the same series with k_u A, rebound v0 sqrt(K / K_u). The
 * coupled energy balance closes (drift). */
static void test_series_pad_and_body_law(void)
{
    const double v0 = 1, M = 1, L = 0.04, E = 4e6, c = 1e8, ku = 4e8, A = SIDE * SIDE;
    char y[4096];
    snprintf(y, sizeof y,
             "mcrash: 1\nname: pad\n"
             "simulation: {end_time: 0.02, time_step: 20 us, output_rate: 10 kHz}\n"
             "environment: {gravity: 0}\n"
             "bodies:\n"
             "  - {name: punch, mass: 1, inertia: [1, 1, 1], position: [0, 0, %.9g],\n"
             "     velocity: [0, 0, %g], angular_velocity: [0, 0, 0],\n"
             "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [10, 10, 0.05]}]}\n"
             "fe:\n  parts:\n    - name: pad\n"
             "      mesh: {generate: box, size: [0.08, 0.08, 0.04], divisions: [8, 8, 2],\n"
             "             origin: [-0.04, -0.04, -0.04]}\n"
             "      section: {type: solid}\n"
             "      material: {model: elastic, density: 40, youngs_modulus: 4 MPa, "
             "poisson: 0}\n"
             "  boundary: [{part: pad, where: z_min, fix: all}]\n"
             "  contacts: [{type: bodies, parts: [pad], bodies: [punch],\n"
             "              body_characteristic: {stress: [[0, 0], [10 mm, 1 MPa]],\n"
             "                                    unloading_slope: 400 MPa/m}}]\n",
             SEMI_C + 0.2e-3, -v0);
    mb_model *m = mc_model("pad.yaml", y);
    if (!m) return;
    double fpeak = 0;
    mb_state *s = run_punch(m, &fpeak);
    /* the penalties of the top face's nodes (z = 0) */
    const fe_model *fm = m->couple->fe.model;
    double Kp = 0, dt0 = fm->contact->dt0;
    for (int n = 0; n < fm->nnode; n++)
        if (fabs(fm->node_x0[3 * n + 2]) < 1e-9) /* penalty_scale: the default 0.1 */
            Kp += 0.1 * fm->node_mass[n] / (dt0 * dt0);
    const double K = 1 / (L / (E * A) + 1 / Kp + 1 / (c * A));
    const double Ku = 1 / (L / (E * A) + 1 / Kp + 1 / (ku * A));
    const double fref = v0 * sqrt(M * K), vref = v0 * sqrt(K / Ku), vend = punch_vz(s);
    const double drift = mb_energy_drift(m, s);
    const double ferr = 100 * (fpeak / fref - 1), verr = 100 * (vend / vref - 1);
    printf("pad + body law in series: K_pad %.4g, K_p %.4g, K_law %.4g N/m -> K %.4g N/m; peak "
           "%.3f N (closed form %.3f N, %+.3f %%); rebound %.5f m/s (closed form %.5f, %+.3f %%); "
           "drift %.3g\n",
           E * A / L, Kp, c * A, K, fpeak, fref, ferr, vend, vref, verr, drift);
    FIG("contact.body_law_series_peak_err_pct", "%.1f", fabs(ferr));
    FIG("contact.body_law_series_rebound_err_pct", "%.1f", fabs(verr));
    CHECK_NEAR(ferr, 0, 1.5);
    CHECK_NEAR(verr, 0, 1.5);
    CHECK(fabs(drift) < 0.01);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* The stable step: a law far stiffer than the penalty (c = 1e15 Pa/m: c A_n dt0^2 / m_n ~ 6,
 * past the central difference's limit of 4 were it alone on a node) leaves the node the series
 * stiffness k_n c A_n / (k_n + c A_n) < k_n, which the FE step admits: the run is stable, the
 * punch rebounds at v0, and the peak force is the penalties' alone, v0 sqrt(M K) with
 * 1/K = 1/sum k_n + 1/(c A) (penalty_scale 1e-5, k_n from the model). */
static void test_stiff_law_keeps_the_step(void)
{
    const double v0 = 1, ht = 1e-3, c = 1e15, A = SIDE * SIDE;
    char y[4096];
    snprintf(y, sizeof y, PLATE_YAML, 0.012, SEMI_C + ht + 0.2e-3, -v0,
             "{stress: [[0, 0], [1 mm, 1e12 Pa]]}");
    char *ps = strstr(y, "bodies: [punch],");
    CHECK(ps != NULL);
    if (!ps) return;
    /* penalty_scale 1e-5 on the contact (the template has none): omega h = 0.03 */
    char tail[2048];
    snprintf(tail, sizeof tail, "%s", ps + strlen("bodies: [punch],"));
    snprintf(ps, sizeof y - (size_t)(ps - y), "bodies: [punch], penalty_scale: 1e-5,%s", tail);
    mb_model *m = mc_model("punch_stiff.yaml", y);
    if (!m) return;
    double fpeak = 0;
    mb_state *s = run_punch(m, &fpeak);
    const fe_model *fm = m->couple->fe.model;
    double Kp = 0, dt0 = fm->contact->dt0, kb_max = 0;
    for (int n = 0; n < fm->nnode; n++) {
        Kp += 1e-5 * fm->node_mass[n] / (dt0 * dt0);
        kb_max = fmax(kb_max, c * (A / 256) * dt0 * dt0 / fm->node_mass[n]);
    }
    const double K = 1 / (1 / Kp + 1 / (c * A)), fref = v0 * sqrt(K), vend = punch_vz(s);
    const double ferr = 100 * (fpeak / fref - 1);
    printf("stiff law: c A_n dt0^2 / m_n up to %.3g; peak %.3f N (closed form %.3f N, %+.3f %%); "
           "rebound %.5f m/s\n",
           kb_max, fpeak, fref, ferr, vend);
    FIG("contact.body_law_stiff_ratio", "%.0f", kb_max);
    FIG("contact.body_law_stiff_peak_err_pct", "%.2f", fabs(ferr));
    CHECK(kb_max > 4);
    CHECK_NEAR(ferr, 0, 0.5);
    CHECK_NEAR(vend, v0, 2e-3 * v0);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the law named once (fe.body_characteristics) and given by its name: the run of the law
 * written inline (the rebound case above), bit for bit; an unknown name is refused at its place
 * with the closest name (the reference: the name's line and column counted in the text) */
static void test_named_law(void)
{
    const char *law = "{stress: [[0, 0], [10 mm, 100 kPa]], unloading_slope: 40 MPa/m}";
    char y[2][4096], t[4096];
    double vend[2] = {0, 1}, ec[2] = {0, 1};
    snprintf(y[0], sizeof y[0], PLATE_YAML, 0.02, SEMI_C + 1.2e-3, -1.0, law);
    snprintf(t, sizeof t, PLATE_YAML, 0.02, SEMI_C + 1.2e-3, -1.0, "flesh");
    const char *fe = strstr(t, "fe:\n");
    CHECK(fe != NULL);
    if (!fe) return;
    snprintf(y[1], sizeof y[1], "%.*sfe:\n  body_characteristics: {flesh: %s}\n%s", (int)(fe - t),
             t, law, fe + 4);
    for (int k = 0; k < 2; k++) {
        mb_model *m = mc_model(k ? "punch_named.yaml" : "punch_inline.yaml", y[k]);
        if (!m) return;
        mb_state *s = run_punch(m, NULL);
        vend[k] = punch_vz(s);
        ec[k] = fe_contact_energy(m->couple->fe.model, s->couple->fe);
        mb_state_destroy(&s);
        mb_model_destroy(&m);
    }
    printf("named law: rebound %.9f m/s, contact energy %.9f J (inline: %.9f, %.9f)\n", vend[1],
           ec[1], vend[0], ec[0]);
    CHECK(vend[0] == vend[1] && ec[0] == ec[1]);
    char *at = strstr(y[1], "body_characteristic: flesh");
    CHECK(at != NULL);
    if (!at) return;
    at += strlen("body_characteristic: ");
    at[4] = 'c'; /* "flesh" -> "flesc" */
    int line = 1, col = 1;
    for (const char *q = y[1]; q < at; q++)
        col = *q == '\n' ? (line++, 1) : col + 1;
    char want[256];
    snprintf(want, sizeof want,
             "named_law.yaml:%d:%d: error: fe.contacts[0].body_characteristic: unknown body "
             "characteristic 'flesc' (did you mean 'flesh'?)",
             line, col);
    mcs_error err = {0};
    mb_model *m = mt_model_text("named_law.yaml", y[1], &err);
    CHECK(m == NULL);
    printf("unknown named law: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, want);
    mb_model_destroy(&m);
}

/* a body law on a facet surface is refused, naming the surface (the facet search reaches 10 mm
 * behind the mesh, short of a flesh's travel) */
static void test_body_law_errors(void)
{
    const char *y =
        "mcrash: 1\nname: facet\n"
        "simulation: {end_time: 1 ms, time_step: 20 us, output_rate: 10 kHz}\n"
        "bodies:\n"
        "  - {name: block, mass: 1, inertia: [0.01, 0.01, 0.01], position: [0, 0, 0.03],\n"
        "     velocity: [0, 0, 0], angular_velocity: [0, 0, 0],\n"
        "     surfaces: [{name: bottom, type: facet, vertices: [[-0.01, -0.01, -0.02],\n"
        "                 [0.01, -0.01, -0.02], [0.01, 0.01, -0.02]], triangles: [[0, 2, 1]]}]}\n"
        "fe:\n  parts:\n    - name: sheet\n"
        "      mesh: {generate: plate, size: [0.1, 0.1], divisions: [4, 4],\n"
        "             origin: [-0.05, -0.05, 0]}\n"
        "      section: {type: membrane, thickness: 0.4 mm}\n"
        "      material: {model: fabric, density: 1e3, youngs_modulus: 0.5 GPa, poisson: 0.3}\n"
        "  boundary: [{part: sheet, where: all, fix: all}]\n"
        "  contacts: [{type: bodies, parts: [sheet], bodies: [block],\n"
        "              body_characteristic: {stress: [[0, 0], [10 mm, 0.1 MPa]]}}]\n";
    mcs_error err = {0};
    mb_model *m = mt_model_text("facet_law.yaml", y, &err);
    CHECK(m == NULL);
    printf("facet with a body law: %s\n", err.msg);
    CHECK(strstr(err.msg, "ellipsoid surfaces only") && strstr(err.msg, "bottom"));
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_flat_punch_force_is_stress_times_area);
    RUN(test_hysteresis_rebound_and_dissipation);
    RUN(test_series_pad_and_body_law);
    RUN(test_stiff_law_keeps_the_step);
    RUN(test_named_law);
    RUN(test_body_law_errors);
    TEST_END();
}

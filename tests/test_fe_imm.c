/* test_fe_imm: the initial metric method (fe/elem/fe_imm.c, scenario key fe.parts[].mesh.initial):
 * a membrane part starts on a scaled-down copy of its mesh while its elements keep the unscaled
 * mesh as their stress-free reference (the 2023 paper, Sec. 2.3.2, Fig. 15). Each case gives its
 * closed form and source. */
#include "tests/harness.h"
#include "tests/fe_test_util.h"
#include "tests/figures.h"

#include "core/mcs_scenario.h"
#include "fe/fe_builder_impl.h"
#include "fe/fe_elem.h"
#include "fe/fe_restraint.h"
#include "fe/fe_scn_build.h"
#include "fe/fe_surface_volume.h"

#include <math.h>

static const double E_F = 5e8, NU_F = 0.3, RHO_F = 1000, T_F = 5e-4;

/* one triangle (0,0,0), (a,0,0), (0,a,0) of fabric, started on its copy scaled by (sx, sy, 1)
 * about the origin */
static fe_model *imm_triangle(double a, double sx, double sy)
{
    fe_builder *b;
    mcs_error err = {0};
    if (fe_builder_create(&b, &err) != MCS_OK) return NULL;
    fe_part_desc d = ft_part("f", FE_SECTION_MEMBRANE, E_F, NU_F, RHO_F);
    d.material.model = FE_MAT_FABRIC;
    d.section.thickness = T_F;
    int ip = -1, n[4];
    const double X[3][3] = {{0, 0, 0}, {a, 0, 0}, {0, a, 0}}, sc[3] = {sx, sy, 1}, o[3] = {0};
    fe_model *m = NULL;
    mcs_status st = fe_builder_add_part(b, &d, &ip, &err);
    for (int k = 0; k < 3 && !st; k++)
        st = fe_builder_add_node(b, X[k], &n[k], &err);
    n[3] = n[2];
    if (!st) st = fe_builder_add_elem(b, ip, n, &err);
    if (!st) st = fe_builder_imm(b, ip, sc, o, &err);
    if (!st) st = fe_model_create(b, NULL, &m, &err);
    if (st) fprintf(stderr, "imm_triangle: %s\n", err.msg);
    fe_builder_destroy(&b);
    return m;
}

/* (b) One element, reference a right triangle of legs a: started compressed in its plane to
 * scale s it carries no stress (Green strain E = (s^2 - 1)/2 < 0 in every direction: slack,
 * tension-field theory; Roddeman et al. 1987); opened to its reference size it carries none
 * either (E = 0); stretched equibiaxially beyond it by lambda, St. Venant-Kirchhoff plane
 * stress gives S = E_f/(1 - nu) (lambda^2 - 1)/2 in both directions (Bonet & Wood 2008, §6.5),
 * and the node at (a, 0) carries the first Piola-Kirchhoff traction of its edges,
 * f_x = A0 t lambda S b_1 = (a/2) t lambda S (b_1 = 1/a, A0 = a^2/2). The lumped masses are
 * those of the reference area: rho t (a^2/2) / 3 a node. */
static void test_one_element(void)
{
    const double a = 0.1, s = 0.3;
    const double sc[3][2] = {{s, s}, {s, 1}, {1, s}};
    double worst = 0;
    for (int c = 0; c < 3; c++) {
        fe_model *m = imm_triangle(a, sc[c][0], sc[c][1]);
        CHECK(m != NULL);
        if (!m) return;
        fe_state *st;
        mcs_error err = {0};
        CHECK(fe_state_create(m, &st, &err) == MCS_OK);
        /* the nodes start on the scaled copy, the reference keeps the design area */
        CHECK_NEAR(m->node_x0[3 * 1 + 0], sc[c][0] * a, 1e-15);
        CHECK_NEAR(m->node_x0[3 * 2 + 1], sc[c][1] * a, 1e-15);
        CHECK_REL(m->shell_mref[6], 0.5 * a * a, 1e-14);
        for (int k = 0; k < 3; k++)
            CHECK_REL(m->node_mass[k], RHO_F * T_F * a * a / 6, 1e-14);
        const double *f = st->slot_f + 3 * m->slot_base[FE_KIND_SHELL];
        for (int step = 0; step < 3; step++) {
            /* 0: as started (scaled); 1: at the reference; 2: stretched by lambda */
            const double lam = step == 2 ? 1.02 : 1;
            const double X[3][3] = {{0, 0, 0}, {a, 0, 0}, {0, a, 0}}; /* the reference */
            if (step > 0)
                for (int k = 0; k < 3; k++)
                    for (int i = 0; i < 3; i++)
                        st->node_x[3 * k + i] = lam * X[k][i];
            fe_internal_forces(m, st);
            double fmaxabs = 0;
            for (int i = 0; i < 9; i++)
                fmaxabs = fmax(fmaxabs, fabs(f[i]));
            if (step < 2) {
                CHECK(fmaxabs < 1e-12);
                CHECK(fabs(st->shell_sig[0]) + fabs(st->shell_sig[1]) + fabs(st->shell_sig[2]) <
                      1e-3); /* Pa: rounding of E = 0 */
                continue;
            }
            const double S = E_F / (1 - NU_F) * 0.5 * (lam * lam - 1);
            worst = fmax(worst, fabs(st->shell_sig[0] / S - 1));
            worst = fmax(worst, fabs(st->shell_sig[1] / S - 1));
            worst = fmax(worst, fabs(st->shell_sig[2]) / S);
            const double fx = 0.5 * a * T_F * lam * S;
            worst = fmax(worst, fabs(f[3] / fx - 1)); /* slots hold the internal force */
        }
        fe_state_destroy(&st);
        fe_model_destroy(&m);
    }
    printf("  one element: slack when scaled and at the reference; stretched 2 %%: stress and "
           "force to %.1e of the closed form\n",
           worst);
    FIG("fe.imm_element_err", "%.0e", worst);
    CHECK(worst < 1e-12);
}

/* a membrane sphere r = 100 mm (cube-sphere, 20 mm elements) started on its copy scaled by
 * (1, 1, sz) about its centre: a closed gas bag; fe block text with `extra` appended */
static const char *SPHERE =
    "mcrash: 1\n"
    "name: imm sphere\n"
    "simulation: {end_time: 10 ms, output_rate: 1 kHz, time_step_scale: %g}\n"
    "fe:\n"
    "  parts:\n"
    "    - name: fabric\n"
    "      mesh: {generate: sphere_shell, radius: 100 mm, element_size: 20 mm,\n"
    "             initial: {scale: [1, 1, %g], about: [0, 0, 0]}}\n"
    "      section: {type: membrane, thickness: 0.5 mm}\n"
    "      material: {model: fabric, density: 1000 kg/m^3, youngs_modulus: 500 MPa,\n"
    "                 poisson: 0.3, damping: %g}\n"
    "  airbags:\n"
    "    - {name: bag, parts: [fabric]%s}\n"
    "%s";

static int build_sphere(double tss, double sz, double zeta, const char *bag, const char *extra,
                        fe_problem *pb)
{
    char txt[2048];
    snprintf(txt, sizeof txt, SPHERE, tss, sz, zeta, bag, extra);
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    memset(pb, 0, sizeof *pb);
    mcs_status st = mcs_scenario_load_text("imm_sphere.yaml", txt, strlen(txt), &scn, &err);
    if (!st) st = fe_scn_build(scn, pb, &err);
    if (st) fprintf(stderr, "build_sphere: %s\n", err.msg);
    mcs_scenario_destroy(&scn);
    return st == MCS_OK;
}

/* (a) A closed bag started on its flattened copy (z scaled by sz, so its volume is exactly
 * sz V_d: an affine map scales volumes by its determinant) holding a known gas mass
 * m = p0 V_i / (R T0) opens to its design shape. The walls are adiabatic (the uniform-pressure
 * bag, docs/gasbag.md), so the gas expands isentropically: p V^gamma = p0 V_i^gamma and
 * p V = m R T with T = T0 (V_i/V)^(gamma-1) (Poisson; Cengel & Boles, ch. 7). At rest (mass
 * damping, dynamic relaxation) the fabric is taut and stretched by Laplace's law,
 * r = r_d (1 + p_g r_d (1 - nu)/(2 E t)) (Roark, 7th ed., Table 13.1 case 1a), so the volume
 * is V_d (1 + p_g r_d (1 - nu)/(2 E t))^3 with V_d the reference mesh's enclosed volume; the
 * final gauge pressure p_g solves p0 V_i^gamma = (p_a + p_g) V(p_g)^gamma (bisection here). */
static void test_scaled_sphere_opens(void)
{
    const double sz = 0.4, pa = 101325, g = 1.4, r = 0.1;
    const double p0 = 4.4e5; /* about 20 kPa gauge once open */
    fe_problem pb;
    char bag[64];
    snprintf(bag, sizeof bag, ", initial_pressure: %g Pa", p0);
    if (!build_sphere(0.9, sz, 0, bag, "  damping: 4000 1/s\n", &pb)) {
        CHECK(0);
        return;
    }
    fe_model *m = pb.model;
    const fe_airbag *ab = &m->restraints->bag[0];
    /* the reference mesh: positions at radius r */
    double *xr = malloc(3 * sizeof(double) * (size_t)m->nnode);
    double rmax0 = 0;
    for (int n = 0; n < m->nnode; n++) {
        const double *x = m->node_x0 + 3 * n;
        rmax0 = fmax(rmax0, fabs(x[2]));
        const double X[3] = {x[0], x[1], x[2] / sz};
        for (int i = 0; i < 3; i++)
            xr[3 * n + i] = X[i];
    }
    const double Vd = fe_surface_volume(ab->nface, ab->face, xr);
    free(xr);
    CHECK_NEAR(rmax0, sz * r, 1e-12);
    const double Vi = sz * Vd;
    CHECK_REL(ab->volume0, Vi, 1e-12); /* the gas bag starts at the current closed volume */
    fe_state *s;
    mcs_error err = {0};
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    CHECK(fe_run(m, s, 0.010) == MCS_OK);
    const fe_gasbag_state *gs = &s->restraint->bag[0];
    /* closed form: bisection on the gauge pressure */
    const double k = r * (1 - NU_F) / (2 * E_F * T_F), c = p0 * pow(Vi, g);
    double lo = 0, hi = 1e6;
    for (int it = 0; it < 200; it++) {
        double pg = 0.5 * (lo + hi), V = Vd * pow(1 + k * pg, 3);
        if ((pa + pg) * pow(V, g) > c)
            hi = pg;
        else
            lo = pg;
    }
    const double pg = 0.5 * (lo + hi), V = Vd * pow(1 + k * pg, 3);
    const double T = 293.15 * pow(Vi / V, g - 1), mgas = p0 * Vi / (287.05 * 293.15);
    const double V_err = gs->volume / V - 1, p_err = (gs->pressure - pa) / pg - 1;
    printf("  scaled sphere (z x %.1f, V_i %.3f l, design %.3f l): opens to %.4f l (closed form "
           "%.4f l, %+.1e), gauge %.0f Pa (closed form %.0f Pa, %+.1e); pV = mRT at T %.1f K: "
           "%+.1e; KE %.1e J\n",
           sz, 1e3 * Vi, 1e3 * Vd, 1e3 * gs->volume, 1e3 * V, V_err, gs->pressure - pa, pg, p_err,
           T, gs->pressure * gs->volume / (mgas * 287.05 * T) - 1, s->energy[FE_E_kinetic]);
    FIG("fe.imm_sphere_volume_err", "%.0e", fabs(V_err));
    FIG("fe.imm_sphere_pressure_err", "%.0e", fabs(p_err));
    CHECK(fabs(V_err) < 5e-5); /* 1.5e-5 stated */
    CHECK(fabs(p_err) < 4e-4); /* 1.3e-4 stated */
    CHECK_REL(gs->pressure * gs->volume, mgas * 287.05 * T, 1e-3);
    CHECK(s->energy[FE_E_kinetic] < 1e-6 * s->energy[FE_E_internal]);
    fe_state_destroy(&s);
    fe_problem_free(&pb);
}

/* (c) Energy balance of the inflation from the scaled copy (an inflator, 1 kg/s at 600 K for
 * 2.5 ms, no damping but the fabric's, a closed bag): the work of the gas on the fabric,
 * int (p - p_a) dV by the trapezoid rule over this test's pressure and volume histories, equals
 * what the structure holds, kinetic + strain energy + fabric damping (first law for the
 * structure). The fabric goes from slack to taut element by element as the bag opens, which
 * central differences integrate to O(dt^2) (an element snapping taut moves up to v dt into
 * its stiffness within one step, as a penalty contact does): the balance is checked at the
 * default step (time_step_scale 0.9) and its convergence at half that step (order ~2). */
static double inflation_balance(double tss, double *vol)
{
    fe_problem pb;
    const char *bag = ", inflator: {mass_flow: [[0, 0], [0.5 ms, 1 kg/s], [2.5 ms, 1 kg/s], "
                      "[3 ms, 0]], temperature: [[0, 600 K]]}";
    if (!build_sphere(tss, 0.4, 0.1, bag, "", &pb)) return NAN;
    fe_model *m = pb.model;
    fe_state *s;
    mcs_error err = {0};
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    const fe_gasbag_state *gs = &s->restraint->bag[0];
    const double pa = m->restraints->bag[0].gas->ambient_pressure;
    double wgas = 0, p_prev = gs->pressure, v_prev = gs->volume, ie_max = 0;
    while (s->time < 0.005 && fe_step(m, s) == MCS_OK) {
        wgas += 0.5 * (p_prev + gs->pressure - 2 * pa) * (gs->volume - v_prev);
        p_prev = gs->pressure, v_prev = gs->volume;
        ie_max = fmax(ie_max, s->energy[FE_E_internal]);
    }
    CHECK(s->err.status == MCS_OK);
    const double *en = s->energy;
    double held = en[FE_E_kinetic] + en[FE_E_internal] + en[FE_E_dissipated];
    printf("  inflation from the scaled copy (step scale %.2f): V %.3f l, gauge %.0f Pa, gas work "
           "on the fabric %.4f J, KE %.4f + IE %.4f + damping %.4f = %.4f J (%+.1e)\n",
           tss, 1e3 * gs->volume, gs->pressure - pa, wgas, en[FE_E_kinetic], en[FE_E_internal],
           en[FE_E_dissipated], held, held / wgas - 1);
    CHECK(ie_max > 0.1 * held); /* it did open to the reference and stretch */
    *vol = gs->volume;
    fe_state_destroy(&s);
    fe_problem_free(&pb);
    return held / wgas - 1;
}

static void test_inflation_energy(void)
{
    double v1, v2;
    const double e1 = inflation_balance(0.9, &v1), e2 = inflation_balance(0.45, &v2);
    const double order = log(fabs(e1 / e2)) / log(2);
    printf("  balance %.1e at the default step, %.1e at half of it: order %.2f\n", e1, e2, order);
    FIG("fe.imm_inflation_balance", "%.0e", fabs(e1));
    FIG("fe.imm_inflation_order", "%.1f", order);
    CHECK(fabs(e1) < 1e-2); /* 3.6e-3 stated */
    CHECK(order > 1.7);
    CHECK(v1 > 4.1e-3 && v2 > 4.1e-3); /* open: the design volume is 4.12 l */
}

/* bad input: the key on a part that is not a membrane, a scale factor outside (0, 1] */
static void test_errors(void)
{
    const char *bad[] = {
        "mcrash: 1\nname: x\nsimulation: {end_time: 1 ms}\nfe:\n  parts:\n"
        "    - name: p\n      mesh: {generate: plate, size: [0.1 m, 0.1 m], divisions: [2, 2],\n"
        "             initial: {scale: [0.5, 0.5, 1]}}\n"
        "      section: {type: shell, thickness: 1 mm}\n"
        "      material: {model: elastic, density: 7800 kg/m^3, youngs_modulus: 200 GPa,\n"
        "                 poisson: 0.3}\n",
        "mcrash: 1\nname: x\nsimulation: {end_time: 1 ms}\nfe:\n  parts:\n"
        "    - name: p\n      mesh: {generate: plate, size: [0.1 m, 0.1 m], divisions: [2, 2],\n"
        "             initial: {scale: [1.5, 0.5, 1]}}\n"
        "      section: {type: membrane, thickness: 1 mm}\n"
        "      material: {model: fabric, density: 1000 kg/m^3, youngs_modulus: 1 GPa,\n"
        "                 poisson: 0.3}\n"};
    const char *want[] = {"needs a membrane section", "must be in (0, 1]"};
    for (int i = 0; i < 2; i++) {
        mcs_scenario *scn = NULL;
        mcs_error err = {0};
        fe_problem pb = {0};
        mcs_status st = mcs_scenario_load_text("bad.yaml", bad[i], strlen(bad[i]), &scn, &err);
        if (!st) st = fe_scn_build(scn, &pb, &err);
        CHECK(st != MCS_OK);
        CHECK_STR_CONTAINS(err.msg, want[i]);
        CHECK_STR_CONTAINS(err.msg, "bad.yaml:8:");
        fe_problem_free(&pb);
        mcs_scenario_destroy(&scn);
    }
}

int main(void)
{
    RUN(test_one_element);
    RUN(test_scaled_sphere_opens);
    RUN(test_inflation_energy);
    RUN(test_errors);
    TEST_END();
}

/* test_fe_erosion: element erosion (material.failure_strain, fe_stages.c) against closed forms.
 * A perfectly plastic hex, and a shell, pulled in uniaxial tension at a constant end velocity
 * v are deleted when their plastic strain reaches the failure strain FS: the log strain is then
 * FS + SIGY / E, at t* = L0 (exp(FS + SIGY / E) - 1) / v; the energy balance closes with the
 * element's internal energy moved to `eroded`, V0 (SIGY^2 / (2 E) + SIGY FS) by hand (elastic
 * ramp, then flow at SIGY through the plastic log strain FS; volume change of order
 * (1 - 2 nu) SIGY / E neglected). A contact leaves an eroded segment out: a block falling on a
 * shell that eroded passes through it. The keyword decks' FS / FAIL give the same erosion. */
#include "tests/harness.h"
#include "tests/cli_util.h"
#include "tests/figures.h"
#include "tests/fe_test_util.h"

#include "core/mcs_results.h"

#include "fe/fe_contact.h"
#include "fe/fe_keyword.h"
#include "fe/fe_state.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define L0 0.01     /* element edge [m] */
#define SIGY 250e6  /* [Pa] */
#define EMOD 210e9  /* [Pa] */
#define FS 0.05     /* failure plastic strain [-] */
#define VPULL 0.05  /* end velocity [m/s]: strain rate 5/s, quasi-static for a 10 mm element */

static fe_part_desc plastic_part(const char *name, fe_section_type type)
{
    fe_part_desc d = ft_part(name, type, EMOD, 0.3, 7850);
    d.material.model = FE_MAT_ELASTIC_PLASTIC;
    d.material.yield_stress = SIGY;
    d.material.failure_strain = FS;
    if (type == FE_SECTION_SOLID) {
        d.mesh.generate = FE_MESH_BOX;
        d.mesh.size[0] = d.mesh.size[1] = d.mesh.size[2] = L0;
        d.mesh.divisions[0] = d.mesh.divisions[1] = d.mesh.divisions[2] = 1;
    } else {
        d.section.thickness = 0.001;
        d.mesh.generate = FE_MESH_PLATE;
        d.mesh.size[0] = d.mesh.size[1] = L0;
        d.mesh.divisions[0] = d.mesh.divisions[1] = 1;
        d.mesh.axis = 2;
    }
    return d;
}

/* the element pulled along x (hex: x = L0 face at +v; symmetry planes x, y, z = 0; the shell
 * in the z = 0 plane with z and the rotations held); with block_z > 0 a 2 mm steel cube over
 * the middle of the plate at that height falls at 1 m/s onto it (node-to-surface contact) */
static fe_model *pulled(fe_section_type type, double block_z, double fail)
{
    fe_builder *b;
    mcs_error err = {0};
    if (fe_builder_create(&b, &err)) return NULL;
    fe_part_desc d = plastic_part("bar", type);
    d.material.failure_strain = fail;
    fe_model *m = NULL;
    mcs_status st = fe_builder_add_part(b, &d, NULL, &err);
    const int solid = type == FE_SECTION_SOLID;
    fe_boundary_desc bc[4] = {ft_bc("bar", FE_WHERE_X_MIN, FE_DOF_X),
                              ft_bc("bar", FE_WHERE_X_MAX, FE_DOF_X),
                              ft_bc("bar", FE_WHERE_Y_MIN, FE_DOF_Y),
                              ft_bc("bar", solid ? FE_WHERE_Z_MIN : FE_WHERE_ALL,
                                    solid ? FE_DOF_Z : FE_DOF_Z | FE_DOF_ROT)};
    bc[1].velocity[0] = VPULL;
    for (int i = 0; i < 4 && !st; i++) st = fe_builder_add_boundary(b, &bc[i], &err);
    if (!st && block_z > 0) {
        fe_part_desc c = ft_part("block", FE_SECTION_SOLID, EMOD, 0.3, 7850);
        c.mesh.generate = FE_MESH_BOX;
        c.mesh.size[0] = c.mesh.size[1] = c.mesh.size[2] = 0.002;
        c.mesh.divisions[0] = c.mesh.divisions[1] = c.mesh.divisions[2] = 1;
        c.mesh.origin[0] = c.mesh.origin[1] = 0.004;
        c.mesh.origin[2] = block_z;
        c.initial_velocity[2] = -1;
        st = fe_builder_add_part(b, &c, NULL, &err);
        fe_contact_desc cd;
        memset(&cd, 0, sizeof cd);
        snprintf(cd.name, sizeof cd.name, "fall");
        cd.type = FE_CONTACT_NODE_TO_SURFACE;
        cd.nslave = cd.nmaster = 1;
        snprintf(cd.slave[0], FE_NAME_MAX, "block");
        snprintf(cd.master[0], FE_NAME_MAX, "bar");
        cd.friction_dynamic = -1;
        if (!st) st = fe_builder_add_contact(b, &cd, &err);
    }
    if (!st) st = fe_model_create(b, NULL, &m, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    fe_builder_destroy(&b);
    return m;
}

static void erodes_at_closed_form(fe_section_type type, const char *what)
{
    fe_model *m = pulled(type, 0, FS);
    CHECK(m != NULL);
    if (!m) return;
    fe_state *s = NULL;
    mcs_error err = {0};
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    const double tstar = L0 * (exp(FS + SIGY / EMOD) - 1) / VPULL;
    double e_before = 0, drift = 0;
    while (s && s->time < 1.2 * tstar && fe_step(m, s) == MCS_OK) {
        if (s->neroded == 0) e_before = s->energy[FE_E_internal];
        drift = fmax(drift, fabs(s->energy[FE_E_total] - s->energy0));
    }
    CHECK(s && s->err.status == MCS_OK);
    if (!s) return;
    const double V0 = type == FE_SECTION_SOLID ? L0 * L0 * L0 : L0 * L0 * 0.001;
    /* the shell keeps its thickness (docs/fe.md), so its volume grows with its area: with
     * plastic flow d eps_yy = -d eps_xx / 2 (plane stress, incompressible) and the elastic
     * lateral strain -nu SIGY / E, the flow work is SIGY V0 e^((1 - nu) SIGY / E)
     * int_0^FS e^(ep / 2) dep = SIGY V0 e^((1 - nu) SIGY / E) 2 (e^(FS / 2) - 1) */
    const double flow = type == FE_SECTION_SOLID
                            ? FS
                            : exp(0.7 * SIGY / EMOD) * 2 * (exp(FS / 2) - 1);
    const double w_ref = V0 * (SIGY * SIGY / (2 * EMOD) + SIGY * flow);
    printf("  %s: eroded %d at t = %.6g s (closed form %.6g s, dt %.3g s); eroded energy %.6g J "
           "(hand %.6g J); balance drift %.3g J\n",
           what, s->neroded, s->erode_first, tstar, s->dt, s->energy[FE_E_eroded], w_ref, drift);
    CHECK(s->neroded == 1);
    CHECK(fabs(s->erode_first - tstar) <= 2 * s->dt);
    CHECK_REL(s->energy[FE_E_eroded], w_ref, 1e-3);
    CHECK(fabs(s->energy[FE_E_internal]) < 1e-9 * w_ref); /* nothing left in the element */
    CHECK_REL(s->energy[FE_E_eroded], e_before, 1e-3);  /* what it held one step before */
    CHECK(drift < 1e-3 * w_ref);                          /* the balance closes */
    /* the element is gone: its end moves on with no force (the constraint's reaction 0) */
    const double k0 = s->energy[FE_E_eroded];
    for (int i = 0; i < 100; i++) fe_step(m, s);
    CHECK(s->energy[FE_E_eroded] == k0 && s->neroded == 1);
    if (type == FE_SECTION_SOLID) {
        /* the hand value neglects the volume change (1 - 2 nu) SIGY / E = 5e-4 */
        FIG("fe.erosion_hex_energy_diff", "%.0e", fabs(s->energy[FE_E_eroded] / w_ref - 1));
    }
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

static void test_hex_erosion(void) { erodes_at_closed_form(FE_SECTION_SOLID, "hex"); }
static void test_shell_erosion(void) { erodes_at_closed_form(FE_SECTION_SHELL, "shell"); }

/* a block 15 mm above the plate falls at 1 m/s: it reaches the plate at 15 ms, after the
 * plate eroded (t* = 10.5 ms), and passes through it at its speed (below z = -3 mm at 20 ms);
 * the same plate without erosion stops it (its lowest node stays above -1 mm) */
static double block_lowest(double fail)
{
    fe_model *m = pulled(FE_SECTION_SHELL, 0.015, fail);
    CHECK(m != NULL);
    if (!m) return NAN;
    fe_state *s = NULL;
    mcs_error err = {0};
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    while (s && s->time < 0.02 && fe_step(m, s) == MCS_OK) {
    }
    double zmin = INFINITY;
    for (int n = 0; s && n < m->nnode; n++)
        if (m->node_x0[3 * n + 2] > 0.01) zmin = fmin(zmin, s->node_x[3 * n + 2]);
    CHECK(s && s->err.status == MCS_OK && s->neroded == (fail > 0));
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    return zmin;
}

static void test_contact_skips_eroded(void)
{
    const double through = block_lowest(FS), stopped = block_lowest(0);
    printf("  block's lowest node at 20 ms: %.4g m over the eroded plate, %.4g m over the "
           "intact one\n",
           through, stopped);
    CHECK(through < -0.003 && stopped > -0.001);
}

/* *MAT_PLASTIC_KINEMATIC FS and *MAT_PIECEWISE_LINEAR_PLASTICITY FAIL are the failure strain */
static void test_keyword_failure_strain(void)
{
    static const char deck[] = "*KEYWORD\n*MAT_003\n1,7850,2.1e11,0.3,2.5e8,0,0\n0,0,0.05\n"
                               "*MAT_024\n2,7850,2.1e11,0.3,2.5e8,0,0.12\n\n\n\n"
                               "*SECTION_SOLID\n1\n*PART\na\n1,1,1\n*PART\nb\n2,1,2\n*END\n";
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    CHECK(fe_kw_read_mem("fs.k", deck, sizeof deck - 1, &o, &d, &err) == MCS_OK);
    fe_part_desc a = fe_part_desc_default(), b = fe_part_desc_default();
    if (d) {
        CHECK(fe_kw_part_props(d, 1, &a, &err) == MCS_OK);
        CHECK(fe_kw_part_props(d, 2, &b, &err) == MCS_OK);
    }
    CHECK(a.material.failure_strain == 0.05 && b.material.failure_strain == 0.12);
    fe_kw_deck_destroy(&d);
}

/* the same cube as a scenario (tests/data/erosion/cube_pull.yaml, failure_strain 0.05): the
 * results say how many eroded and when (/stage3/erosion), and the eroded energy is the hex's
 * hand value of test_hex_erosion */
static void test_scenario_results(void)
{
    char h5[64], cmd[256];
    snprintf(h5, sizeof h5, "/tmp/mcrash_erosion_%d.h5", (int)getpid());
    snprintf(cmd, sizeof cmd, "run tests/data/erosion/cube_pull.yaml -o %s --quiet", h5);
    CHECK(cli_run(cmd)->status == 0);
    mcs_results *r = NULL;
    mcs_error err = {0};
    mcs_array cnt = {0}, en = {0};
    double first = 0, n = 0;
    CHECK(mcs_results_open(&r, h5, &err) == MCS_OK);
    CHECK(r && mcs_results_read(r, "/stage3/erosion/count", &cnt, &err) == MCS_OK);
    CHECK(r && mcs_results_read(r, "/stage3/energy/eroded", &en, &err) == MCS_OK);
    CHECK(r && mcs_results_attr_double(r, "/stage3/erosion", "eroded", &n, &err) == MCS_OK);
    CHECK(r && mcs_results_attr_double(r, "/stage3/erosion", "first_time", &first, &err) ==
                   MCS_OK);
    const double tstar = L0 * (exp(FS + SIGY / EMOD) - 1) / VPULL;
    const double w_ref = L0 * L0 * L0 * (SIGY * SIGY / (2 * EMOD) + SIGY * FS);
    CHECK(cnt.n > 100 && cnt.v[0] == 0 && cnt.v[cnt.n - 1] == 1 && n == 1);
    CHECK(fabs(first - tstar) < 3e-6); /* two steps of 1.07 us */
    CHECK(en.n > 0 && fabs(en.v[en.n - 1] - w_ref) < 1e-3 * w_ref);
    mcs_array_free(&cnt);
    mcs_array_free(&en);
    mcs_results_close(&r);
    remove(h5);
}

int main(void)
{
    RUN(test_hex_erosion);
    RUN(test_shell_erosion);
    RUN(test_contact_skips_eroded);
    RUN(test_keyword_failure_strain);
    RUN(test_scenario_results);
    TEST_END();
}

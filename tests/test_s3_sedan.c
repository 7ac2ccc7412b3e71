/* test_s3_sedan: the sedan's side structure in FE (stage3_fe/s3_sedan.c, `generate:
 * sedan_side`; docs/validation_stage3.md "The sedan side"): the generated car's mass, centre of
 * gravity and inertia against the stage-1 model's, summed by hand from the file's numbers; a
 * rigid pole pushed quasi-statically into the door at its beam against the beam's plastic
 * collapse load in three-point bending. */
#include "harness.h"
#include "figures.h"
#include "s3_test_util.h"

#include "fe/fe_scn_build.h"
#include "fe/fe_solid.h"
#include "stage3_fe/s3_sedan.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char tmpdir[64];
#define MODEL "scenarios/models/opponents/sedan_1668kg.yaml"

/* the generated model's total: the rigid bodies' (given) mass properties plus every free node
 * (its lumped mass and rotary inertia) */
static void model_total(const fe_model *m, double *M, double c[3], double I[3][3])
{
    double mx[3] = {0, 0, 0};
    *M = 0;
    for (int b = 0; b < m->nbody; b++) {
        *M += m->body[b].mass;
        for (int k = 0; k < 3; k++)
            mx[k] += m->body[b].mass * m->body[b].x0[k];
    }
    for (int n = 0; n < m->nnode; n++)
        if (m->node_body[n] < 0) {
            *M += m->node_mass[n];
            for (int k = 0; k < 3; k++)
                mx[k] += m->node_mass[n] * m->node_x0[3 * n + k];
        }
    for (int k = 0; k < 3; k++)
        c[k] = mx[k] / *M;
    memset(I, 0, 9 * sizeof(double));
    for (int b = 0; b < m->nbody; b++) {
        const double *x = m->body[b].x0, mb = m->body[b].mass;
        double r[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
        double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        for (int a = 0; a < 3; a++)
            for (int e = 0; e < 3; e++)
                I[a][e] += m->body[b].inertia0[a][e] + mb * ((a == e) * rr - r[a] * r[e]);
    }
    for (int n = 0; n < m->nnode; n++)
        if (m->node_body[n] < 0) {
            const double *x = m->node_x0 + 3 * n;
            double r[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
            double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2], mn = m->node_mass[n];
            for (int a = 0; a < 3; a++) {
                I[a][a] += m->node_inertia[n];
                for (int e = 0; e < 3; e++)
                    I[a][e] += mn * ((a == e) * rr - r[a] * r[e]);
            }
        }
}

/* the stage-1 sedan by hand, from sedan_1668kg.yaml's numbers: sedan 1548 kg at
 * (2.6475, 0.30, 0.55) m, inertia (2700, 580, 2900) kg m^2; sedan_upper 40 kg at
 * (2.6475, 0.30, 1.35), (8, 4, 11); four wheels 20 kg at x 1.8575 / 3.4375, y -1.10 / 1.70,
 * z 0.22773, (0.9, 0.55, 0.55) each; parallel axes to the common centre */
static void stage1_by_hand(double *M, double c[3], double I[3])
{
    const double m[6] = {1548, 40, 20, 20, 20, 20};
    const double p[6][3] = {{2.6475, 0.30, 0.55},     {2.6475, 0.30, 1.35},
                            {1.8575, -1.10, 0.22773}, {3.4375, -1.10, 0.22773},
                            {1.8575, 1.70, 0.22773},  {3.4375, 1.70, 0.22773}};
    const double i0[6][3] = {{2700, 580, 2900}, {8, 4, 11},        {0.9, 0.55, 0.55},
                             {0.9, 0.55, 0.55}, {0.9, 0.55, 0.55}, {0.9, 0.55, 0.55}};
    *M = 0;
    c[0] = c[1] = c[2] = 0;
    for (int i = 0; i < 6; i++) {
        *M += m[i];
        for (int k = 0; k < 3; k++)
            c[k] += m[i] * p[i][k];
    }
    for (int k = 0; k < 3; k++)
        c[k] /= *M;
    for (int k = 0; k < 3; k++) {
        I[k] = 0;
        for (int i = 0; i < 6; i++) {
            double d1 = p[i][(k + 1) % 3] - c[(k + 1) % 3], d2 = p[i][(k + 2) % 3] - c[(k + 2) % 3];
            I[k] += i0[i][k] + m[i] * (d1 * d1 + d2 * d2);
        }
    }
}

static void test_mass(void)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    CHECK(mcs_scenario_load(MODEL, &scn, &err) == MCS_OK);
    if (!scn) return;
    fe_builder *b = NULL;
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    s3_sedan_opts o = {.element_size = 0.05};
    snprintf(o.name, sizeof o.name, "car");
    CHECK(s3_sedan_build(b, mcs_scenario_root(scn), &o, NULL, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    if (m) {
        double M, c[3], I[3][3], Mh, ch[3], Ih[3];
        model_total(m, &M, c, I);
        stage1_by_hand(&Mh, ch, Ih);
        double side = 0; /* the deformable parts' free mass */
        for (int n = 0; n < m->nnode; n++)
            if (m->node_body[n] < 0) side += m->node_mass[n];
        double eI = 0, ec = 0;
        for (int k = 0; k < 3; k++) {
            eI = fmax(eI, fabs(I[k][k] / Ih[k] - 1));
            ec = fmax(ec, fabs(c[k] - ch[k]));
        }
        printf("  %d nodes, %d shells; side %.2f kg free, total %.3f kg (hand %.3f), "
               "cg (%.4f %.4f %.4f) m (hand %.4f %.4f %.4f), I (%.1f %.1f %.1f) kg m^2 "
               "(hand %.1f %.1f %.1f), off-diagonal %.2g %.2g %.2g\n",
               m->nnode, m->nshell, side, M, Mh, c[0], c[1], c[2], ch[0], ch[1], ch[2], I[0][0],
               I[1][1], I[2][2], Ih[0], Ih[1], Ih[2], I[0][1], I[1][2], I[0][2]);
        /* the bound: mass and inertia within 2 %; the centre within 1 cm */
        CHECK(fabs(M / Mh - 1) < 0.02);
        CHECK(eI < 0.02);
        CHECK(ec < 0.01);
        CHECK(side > 10); /* the side is deformable steel, not a token */
        FIG("s3.sedan_side_mass", "%.1f", side);
        FIG_TOL("s3.sedan_inertia_err_pct", "%.3f", 100 * eI, 0.001);
    }
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    mcs_scenario_destroy(&scn);
}

/* the door at its beam (docs/validation_stage3.md "The sedan side"), by hand from the model
 * file: skin x 2.6475 - 0.7225 - 0.20 = 1.725 m; hinge end y 0.30 - 0.30 - 0.55 = -0.55 m,
 * latch end at the B-pillar's front face 0.30 + 0.25 - 0.07 = 0.48 m (span 1.03 m); sill top
 * z 0.55 - 0.26 + 0.11 = 0.40 m, beltline 0.55 + 0.15 + 0.30 = 1.00 m. The beam (s3_sedan.c's
 * design values): 31.8 x 2.0 mm tube (mid-surface 29.8 mm), sigma_y 1000 MPa, 15 mm behind the
 * skin, at the door's mid-height 0.70 m */
#define SKIN_X 1.725
#define SPAN 1.03
#define MID_Y (-0.035)
#define BEAM_Z 0.70
#define BEAM_DM 0.0298
#define BEAM_X (SKIN_X + 0.015 + BEAM_DM / 2)

/* a rigid pole (diameter 0.1 m, axis z, 0.3 m long) at mid-span pushed along +x at v into the
 * beam alone (panels 0) or into the door skin with the door's parts in contact (panels 1);
 * the pole's contact force along x: peak and at the end; the run's energy drift */
static void pole_push(int panels, double v, double t_end, double *peak, double *drift, long *steps,
                      double *fx, int *nfx)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    *peak = NAN;
    CHECK(mcs_scenario_load(MODEL, &scn, &err) == MCS_OK);
    if (!scn) return;
    fe_builder *b = NULL;
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    s3_sedan_opts o = {.element_size = 0.05};
    snprintf(o.name, sizeof o.name, "car");
    CHECK(s3_sedan_build(b, mcs_scenario_root(scn), &o, NULL, &err) == MCS_OK);
    const double rp = 0.05, gap = 0.002;
    fe_part_desc d = fe_part_desc_default();
    snprintf(d.name, sizeof d.name, "pole");
    d.mesh.generate = FE_MESH_CYLINDER_SHELL;
    d.mesh.diameter = 2 * rp, d.mesh.length = 0.3, d.mesh.element_size = 0.02, d.mesh.axis = 2;
    double x0 = panels ? SKIN_X - rp - gap : BEAM_X - BEAM_DM / 2 - rp - gap;
    d.mesh.origin[0] = x0, d.mesh.origin[1] = MID_Y, d.mesh.origin[2] = BEAM_Z - 0.15;
    d.section.type = FE_SECTION_SHELL, d.section.thickness = 0.002;
    d.material.model = FE_MAT_RIGID, d.material.density = 7850;
    d.material.youngs_modulus = 210e9, d.material.poisson = 0.3;
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    fe_boundary_desc bc = {.where = FE_WHERE_ALL, .fix = FE_DOF_ALL};
    snprintf(bc.part, sizeof bc.part, "car_body");
    CHECK(fe_builder_add_boundary(b, &bc, &err) == MCS_OK);
    snprintf(bc.part, sizeof bc.part, "pole");
    bc.velocity[0] = v;
    CHECK(fe_builder_add_boundary(b, &bc, &err) == MCS_OK);
    fe_contact_desc c = {.type = FE_CONTACT_NODE_TO_SURFACE, .nslave = 1, .nmaster = 1};
    snprintf(c.name, sizeof c.name, "pole");
    snprintf(c.slave[0], FE_NAME_MAX, panels ? "car_door_outer" : "car_door_beam");
    snprintf(c.master[0], FE_NAME_MAX, "pole");
    CHECK(fe_builder_add_contact(b, &c, &err) == MCS_OK);
    if (panels) { /* skin onto beam onto inner panel */
        fe_contact_desc s = {.type = FE_CONTACT_SINGLE_SURFACE, .nslave = 3};
        snprintf(s.name, sizeof s.name, "door");
        snprintf(s.slave[0], FE_NAME_MAX, "car_door_outer");
        snprintf(s.slave[1], FE_NAME_MAX, "car_door_beam");
        snprintf(s.slave[2], FE_NAME_MAX, "car_door_inner");
        CHECK(fe_builder_add_contact(b, &s, &err) == MCS_OK);
    }
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (err.status) printf("  %s\n", err.msg);
    if (m) {
        char out[128];
        snprintf(out, sizeof out, "%s/pole%d.h5", tmpdir, panels);
        fe_problem p = {.model = m, .end_time = t_end, .output_rate = 2000};
        s3_run_opts ro = {.out_path = out, .quiet = 1};
        s3_summary sum = {0};
        CHECK(s3_run(&p, &ro, &sum, &err) == MCS_OK);
        if (err.status) printf("  %s\n", err.msg);
        p.model = NULL;
        *drift = sum.energy_drift, *steps = sum.steps;
        mcs_results *h = NULL;
        mcs_array f = {0};
        if (mcs_results_open(&h, out, &err) == MCS_OK &&
            mcs_results_read(h, "/stage3/contact/pole/force", &f, &err) == MCS_OK) {
            *peak = 0;
            *nfx = 0;
            for (size_t i = 0; i + 2 < f.n; i += 3) {
                *peak = fmax(*peak, fabs(f.v[i]));
                if (*nfx < 256) fx[(*nfx)++] = fabs(f.v[i]);
            }
        }
        mcs_array_free(&f);
        mcs_results_close(&h);
    }
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    mcs_scenario_destroy(&scn);
}

/* the beam's plastic collapse in three-point bending: M_p = sigma_y Z_p, Z_p = D_m^2 t for a
 * thin-walled round tube (plastic section modulus; Jones, Structural Impact, 1989, ch. 1);
 * P = 4 M_p / L simply supported, 8 M_p / L with both ends built in (three hinges). The beam's
 * end rings are tied to the body: built in, and held axially, so that past the hinges the
 * force grows as a string's, 2 N_p sin(theta), N_p = sigma_y pi D_m t, tan(theta) = w / (L/2)
 * (Jones ch. 6: a fully clamped beam's membrane limit). The pole moves at 2 m/s for 40 ms
 * (80 mm): the beam's 1.5 kg at 2 m/s is quasi-static against kN (make verify: 21000 steps) */
static void test_pole_beam(void)
{
    if (!th_verify()) return;
    const double Mp = 1000e6 * BEAM_DM * BEAM_DM * 0.002, Np = 1000e6 * M_PI * BEAM_DM * 0.002;
    const double p_cl = 8 * Mp / SPAN, v = 2.0;
    double peak, drift = NAN, fx[256];
    long steps = 0;
    int n = 0;
    pole_push(0, v, 0.04, &peak, &drift, &steps, fx, &n);
    /* samples at 2 kHz: sample i at travel i mm; contact from the first force */
    int on = 0;
    while (on < n && !(fx[on] > 0))
        on++;
    double plateau = 0;
    for (int i = 28; i <= 32 && i < n; i++)
        plateau += fx[i] / 5;
    int last = n - 1;
    double w = (last - on) * 1e-3, th = atan(w / (SPAN / 2)), string = 2 * Np * sin(th);
    printf("  bare beam: contact at %d mm, force over 28-32 mm %.0f N (8 Mp/L %.0f N, "
           "4 Mp/L %.0f N); at %d mm (w %.3f m) %.0f N (2 N_p sin theta %.0f N); peak %.0f N, "
           "drift %.2g, %ld steps\n",
           on, plateau, p_cl, p_cl / 2, last, w, fx[last], string, peak, drift, steps);
    CHECK(n > 70);
    CHECK(fabs(plateau / p_cl - 1) < 0.3);
    CHECK(fabs(fx[last] / string - 1) < 0.15);
    CHECK(drift < 0.01);
    FIG("s3.sedan_beam_plateau_kn", "%.0f", plateau / 1e3);
    FIG("s3.sedan_beam_string_kn", "%.0f", fx[last] / 1e3);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s3_sedan_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    s3_sedan_register();
    RUN(test_mass);
    RUN(test_pole_beam);
    char cmd[96];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) return 1;
    TEST_END();
}

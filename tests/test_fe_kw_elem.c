/* test_fe_kw_elem.c: the element, section, part and control keywords of fe_kw_cards_elem.c
 * and fe_kw_build_elem.c (docs/keyword.md), each on a small deck in tests/data/keyword/corpus/
 * (rows of test_kw_corpus.c too): counts and values read, what is built checked against
 * closed forms (a plate's mass rho sum(A_e t_e), a rigid body's given mass, CG and torque-free
 * motion, the hex step TSSFAC L / c and the mass that mass scaling adds), refusals naming
 * keyword, file and line, the writer's round trip, and a whole deck's *CONTROL_TIMESTEP. */
#include "cli_util.h"
#include "fe/fe_keyword.h"
#include "fe/fe_solid.h"
#include "fe/fe_state.h"
#include "harness.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define KD "tests/data/keyword/corpus/"

static fe_kw_deck *read_deck(const char *path, const char *units)
{
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    o.units = units;
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    mcs_status st = fe_kw_read(path, &o, &d, &err);
    if (st) fprintf(stderr, "read %s: %s\n", path, err.msg);
    CHECK(st == MCS_OK && d);
    return d;
}

/* the whole deck into a model (opts NULL: the defaults); NULL with err set when refused */
static fe_model *build(const fe_kw_deck *d, const fe_opts *o, mcs_error *err)
{
    fe_builder *b = NULL;
    fe_model *m = NULL;
    mcs_status st = fe_builder_create(&b, err);
    if (!st) st = fe_kw_add_deck(b, d, err);
    if (!st) st = fe_model_create(b, o, &m, err);
    fe_builder_destroy(&b);
    return m;
}

/* write d in fmt to a temporary file and read it back */
static fe_kw_deck *round_trip(const fe_kw_deck *d, const char *units, fe_kw_format fmt)
{
    char path[64];
    snprintf(path, sizeof path, "/tmp/mcrash_kwelem_%ld.k", (long)getpid());
    mcs_error err = {0};
    mcs_status st = fe_kw_write(d, path, fmt, &err);
    if (st) fprintf(stderr, "write: %s\n", err.msg);
    CHECK(st == MCS_OK);
    fe_kw_deck *r = st ? NULL : read_deck(path, units);
    remove(path);
    return r;
}

/* a built model as a deck (fe_kw_from_model), written and read back */
static fe_kw_deck *model_round_trip(const fe_model *m)
{
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    CHECK(fe_kw_from_model(m, NULL, "model", &d, &err) == MCS_OK);
    fe_kw_deck *r = d ? round_trip(d, NULL, FE_KW_FIXED) : NULL;
    fe_kw_deck_destroy(&d);
    return r;
}

/* shell_thickness.k (mm-s-t): 100 mm squares with THIC 2 2 2 2, THIC 1 2 (blank -> T3 1.5) 4,
 * the section's 1.5 (plain *ELEMENT_SHELL), and a triangle of area 5000 mm^2 with THIC 3 3 3
 * (_BETA form). Each shell's thickness is the mean of its nodes' (docs/keyword.md):
 * 2, 2.125, 1.5, 3 mm; the mass is rho sum(A_e t_e) = 7850 kg/m^3 x (0.01 (0.002 + 0.002125
 * + 0.0015) + 0.005 x 0.003) m^3 = 0.5593125 kg (hand calculation). */
static void test_shell_thickness(void)
{
    fe_kw_deck *d = read_deck(KD "shell_thickness.k", "mm-s-t");
    if (!d) return;
    const fe_kw_elems *e = &d->elem[FE_KW_SHELL];
    CHECK(e->n == 4 && d->nunknown == 0);
    CHECK(e->thick && e->nthick >= 4);
    if (e->thick) {
        CHECK_NEAR(e->thick[0], 0.002, 1e-15);
        CHECK_NEAR(e->thick[4 + 2], 0, 0); /* blank: the section's T3 */
        CHECK_NEAR(e->thick[4 + 3], 0.004, 1e-15);
        CHECK_NEAR(e->thick[8], 0, 0); /* the plain *ELEMENT_SHELL */
        CHECK_NEAR(e->thick[12], 0.003, 1e-15);
        CHECK(e->node[12 + 2] == e->node[12 + 3]); /* the triangle */
    }
    mcs_error err = {0};
    fe_model *m = build(d, NULL, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL);
    if (m) {
        CHECK(m->nshell == 4);
        const double want[4] = {0.002, 0.002125, 0.0015, 0.003};
        for (int i = 0; i < 4; i++) CHECK_NEAR(m->shell_t[i], want[i], 1e-15);
        CHECK_REL(m->mass_total, 0.5593125, 1e-12);
        printf("shell plate of per-element thickness: mass %.10g kg (rho sum A t = 0.5593125)\n",
               m->mass_total);
        /* a step: the shells run with their own thickness */
        fe_state *s = NULL;
        CHECK(fe_state_create(m, &s, &err) == MCS_OK);
        for (int k = 0; s && k < 10; k++) CHECK(fe_step(m, s) == MCS_OK);
        fe_state_destroy(&s);
        /* the model's deck: the same thicknesses, so the same mass */
        fe_kw_deck *r = model_round_trip(m);
        fe_model *m2 = r ? build(r, NULL, &err) : NULL;
        CHECK(m2 && m2->nshell == 4);
        /* the same thicknesses (the writer puts the shells of their own thickness first) */
        for (int i = 0; m2 && i < 4; i++) {
            int found = 0;
            for (int j = 0; j < 4; j++) found += fabs(m2->shell_t[j] - want[i]) <= 1e-15;
            CHECK(found == 1);
        }
        if (m2) CHECK_REL(m2->mass_total, 0.5593125, 1e-12);
        fe_model_destroy(&m2);
        fe_kw_deck_destroy(&r);
    }
    fe_model_destroy(&m);
    /* the writer: *ELEMENT_SHELL_THICKNESS for the shells of their own thickness */
    fe_kw_deck *r = round_trip(d, "mm-s-t", FE_KW_FIXED);
    if (r) {
        CHECK(r->elem[FE_KW_SHELL].n == 4 && r->elem[FE_KW_SHELL].thick);
        int same = 1;
        for (int i = 0; i < 4 && r->elem[FE_KW_SHELL].thick; i++) {
            int ko = 0;
            while (ko < 4 && e->id[ko] != r->elem[FE_KW_SHELL].id[i]) ko++;
            for (int j = 0; j < 4 && ko < 4; j++) {
                double a = ko < e->nthick ? e->thick[4 * ko + j] : 0;
                double b = i < r->elem[FE_KW_SHELL].nthick ? r->elem[FE_KW_SHELL].thick[4 * i + j]
                                                           : 0;
                same &= fabs(a - b) <= 1e-15;
            }
        }
        CHECK(same);
    }
    fe_kw_deck_destroy(&r);
    fe_kw_deck_destroy(&d);
}

/* a cantilever strip of 4 shells (100 x 25 mm each, steel, mm-s-t) clamped at x = 0 and
 * started at 1 m/s out of its plane, once with the section's T1 = 2 mm and once with T1 =
 * 1 mm but every shell's THIC1..4 = 2 mm: the same model, so the same motion (another path to
 * the same answer: the per-element thickness must reach every shell term) */
static void strip_deck(char *buf, size_t n, int own)
{
    int at = snprintf(buf, n,
                      "*KEYWORD\n*PART\nstrip\n         1         1         1\n"
                      "*SECTION_SHELL\n         1         2                   3\n"
                      "%10s\n*MAT_ELASTIC\n         1   7.85e-9  210000.0       0.3\n"
                      "*SET_NODE_LIST\n         1\n         1         6\n"
                      "*BOUNDARY_SPC_SET\n         1         0         1         1         1"
                      "         1         1         1\n"
                      "*INITIAL_VELOCITY_GENERATION\n         1         2       0.0       0.0"
                      "       0.0    1000.0\n\n*NODE\n",
                      own ? "1.0" : "2.0");
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 5; i++)
            at += snprintf(buf + at, n - (size_t)at, "%8d%16.1f%16.1f%16.1f\n", 5 * j + i + 1,
                           100.0 * i, 25.0 * j, 0.0);
    at += snprintf(buf + at, n - (size_t)at, "*ELEMENT_SHELL%s\n", own ? "_THICKNESS" : "");
    for (int i = 0; i < 4; i++) {
        at += snprintf(buf + at, n - (size_t)at, "%8d%8d%8d%8d%8d%8d\n", i + 1, 1, i + 1, i + 2,
                       i + 7, i + 6);
        if (own) at += snprintf(buf + at, n - (size_t)at, "%16s%16s%16s%16s\n", "2.", "2.",
                                "2.", "2.");
    }
    snprintf(buf + at, n - (size_t)at, "*END\n");
}

static void test_shell_thickness_run(void)
{
    double tip[2] = {0, 0}, e_int[2] = {0, 0};
    for (int own = 0; own < 2; own++) {
        char deck[4096];
        strip_deck(deck, sizeof deck, own);
        fe_kw_opts o = fe_kw_opts_default();
        o.quiet = 1, o.units = "mm-s-t";
        fe_kw_deck *d = NULL;
        mcs_error err = {0};
        CHECK(fe_kw_read_mem("strip.k", deck, strlen(deck), &o, &d, &err) == MCS_OK);
        if (!d) fprintf(stderr, "%s\n", err.msg);
        fe_model *m = d ? build(d, NULL, &err) : NULL;
        fe_state *s = NULL;
        if (m && fe_state_create(m, &s, &err) == MCS_OK) {
            CHECK_NEAR(m->shell_t[0], 0.002, 0);
            for (int k = 0; k < 300; k++) CHECK(fe_step(m, s) == MCS_OK);
            tip[own] = s->node_x[3 * 4 + 2]; /* node 5, the free end */
            e_int[own] = s->energy[FE_E_internal];
        }
        CHECK(m != NULL);
        fe_state_destroy(&s);
        fe_model_destroy(&m);
        fe_kw_deck_destroy(&d);
    }
    printf("cantilever strip, section 2 mm vs own 2 mm: tip z %.9g / %.9g m, internal %.6g / "
           "%.6g J\n",
           tip[0], tip[1], e_int[0], e_int[1]);
    CHECK(tip[0] > 1e-5 && e_int[0] > 0); /* it moved and bent */
    CHECK_NEAR(tip[1], tip[0], 1e-15);
    CHECK_NEAR(e_int[1], e_int[0], 1e-12 * e_int[0]);
}

/* tshell.k: *ELEMENT_TSHELL and *SECTION_TSHELL (ICOMP 1: the angle card) read and counted;
 * building them is refused with the element's keyword, file and line */
static void test_tshell(void)
{
    fe_kw_deck *d = read_deck(KD "tshell.k", NULL);
    if (!d) return;
    CHECK(d->elem[FE_KW_TSHELL].n == 2 && d->nunknown == 0 && d->nsection == 1);
    CHECK(d->section[0].kind == FE_KW_SEC_TSHELL && d->section[0].nip == 3);
    CHECK(d->elem[FE_KW_TSHELL].node[8 + 7] == 11);
    mcs_error err = {0};
    fe_model *m = build(d, NULL, &err);
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(err.msg, "tshell.k:25: error: *ELEMENT_TSHELL 1 (part 1): thick shells");
    fe_model_destroy(&m);
    fe_kw_deck *r = round_trip(d, NULL, FE_KW_FIXED);
    if (r) CHECK(r->elem[FE_KW_TSHELL].n == 2 && r->section[0].kind == FE_KW_SEC_TSHELL);
    fe_kw_deck_destroy(&r);
    fe_kw_deck_destroy(&d);
}

/* solid_user.k: *SECTION_SOLID_TITLE ELFORM 102 with NIP 1 and LMC 10 (1 + 1 + 2 more cards)
 * then a plain section: two sections (not '0.0577' read as a SECID); the user element is
 * refused when built, by its section's line */
static void test_solid_user(void)
{
    fe_kw_deck *d = read_deck(KD "solid_user.k", NULL);
    if (!d) return;
    CHECK(d->nsection == 2);
    const fe_kw_section *s1 = fe_kw_find_section(d, 1), *s2 = fe_kw_find_section(d, 2);
    CHECK(s1 && s1->elform == 102 && s1->user);
    CHECK(s2 && s2->elform == 1 && !s2->user);
    mcs_error err = {0};
    fe_model *m = build(d, NULL, &err);
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(err.msg, "solid_user.k:11: error: *SECTION_SOLID 1: ELFORM 102");
    fe_model_destroy(&m);
    fe_kw_deck *r = round_trip(d, NULL, FE_KW_FIXED);
    if (r) CHECK(r->nsection == 2 && fe_kw_find_section(r, 1) && fe_kw_find_section(r, 1)->user);
    fe_kw_deck_destroy(&r);
    fe_kw_deck_destroy(&d);
}

/* beams.k (mm-s-t): ELFORM 2 (A 100 mm^2, ISS ITT J), ELFORM 1 tube (CST 1, outer 20, inner
 * 16 mm: A = pi/4 (20^2 - 16^2) = 113.097 mm^2), ELFORM 3 truss (A 50 mm^2). Refused by
 * default (bending and torsion), built as trusses of those areas with beams_as_trusses: each
 * 100 mm long, mass rho A L (hand calculation) */
static void test_beams(void)
{
    fe_kw_deck *d = read_deck(KD "beams.k", "mm-s-t");
    if (!d) return;
    const fe_kw_section *s1 = fe_kw_find_section(d, 1), *s2 = fe_kw_find_section(d, 2),
                        *s3 = fe_kw_find_section(d, 3);
    CHECK(d->elem[FE_KW_BEAM].n == 3 && s1 && s2 && s3);
    if (!s1 || !s2 || !s3) return;
    CHECK_REL(s1->area, 100e-6, 1e-12);
    CHECK_REL(s1->iss, 833.3e-12, 1e-12);
    CHECK_REL(s1->itt, 2083.3e-12, 1e-12);
    CHECK_REL(s1->jt, 1000e-12, 1e-12);
    CHECK(s2->cst == 1 && s2->irid == 2);
    CHECK_REL(s2->ts[1], 0.020, 1e-12);
    CHECK_REL(s2->tt[0], 0.016, 1e-12);
    CHECK_REL(s3->area, 50e-6, 1e-12);
    mcs_error err = {0};
    fe_model *m = build(d, NULL, &err);
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(err.msg, "beams.k:13: error: *SECTION_BEAM 1: ELFORM 2");
    CHECK_STR_CONTAINS(err.msg, "bending and torsion");
    fe_model_destroy(&m);
    d->beams_as_trusses = 1;
    err = (mcs_error){0};
    m = build(d, NULL, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m && m->ntruss == 3);
    if (m) {
        const double rho = 7850, L = 0.1, a[3] = {100e-6, M_PI / 4 * (400 - 256) * 1e-6, 50e-6};
        for (int p = 0; p < 3; p++) CHECK_REL(m->part[p].section.area, a[p], 1e-12);
        CHECK_REL(m->mass_total, rho * L * (a[0] + a[1] + a[2]), 1e-12);
    }
    fe_model_destroy(&m);
    fe_kw_deck *r = round_trip(d, "mm-s-t", FE_KW_FIXED);
    if (r) {
        const fe_kw_section *q1 = fe_kw_find_section(r, 1), *q2 = fe_kw_find_section(r, 2);
        CHECK(q1 && q2 && q1->elform == 2 && q2->cst == 1);
        if (q1 && q2) {
            CHECK_REL(q1->iss, s1->iss, 1e-12);
            CHECK_REL(q1->area, s1->area, 1e-12);
            CHECK_REL(q2->tt[1], s2->tt[1], 1e-12);
        }
    }
    fe_kw_deck_destroy(&r);
    fe_kw_deck_destroy(&d);
}

/* part_inertia.k (m-s-kg): a rigid unit cube whose *PART_INERTIA gives TM 10 kg, CG (0.6,
 * 0.5, 0.5), I = diag(1, 2, 3) kg m^2, VTX 2 m/s and VRZ 5 rad/s; an elastic cube (1000 kg)
 * with *PART_CONTACT. Free of loads, the body keeps V and (z a principal axis) w, so its CG
 * is at 0.6 + 2 t and each node at CG + Rz(5 t) (x0 - CG); kinetic energy 1/2 M V^2 +
 * 1/2 Izz w^2 = 20 + 37.5 = 57.5 J (rigid-body mechanics, closed form) */
static void test_part_inertia(void)
{
    fe_kw_deck *d = read_deck(KD "part_inertia.k", NULL);
    if (!d) return;
    const fe_kw_part *p1 = fe_kw_find_part(d, 1), *p2 = fe_kw_find_part(d, 2);
    CHECK(p1 && p2 && d->npart == 2);
    if (!p1 || !p2) return;
    CHECK(p1->inertia.given && p1->inertia.mass == 10 && p1->inertia.i[5] == 3);
    CHECK(p1->inertia.v[0] == 2 && p1->inertia.w[2] == 5 && p1->inertia.cg[0] == 0.6);
    CHECK(p2->contact.given && p2->contact.fs == 0.3 && p2->contact.fd == 0.2);
    CHECK(p2->contact.optt == 0.002 && p2->contact.sft == 1.5 && p2->contact.ssf == 2);
    mcs_error err = {0};
    fe_model *m = build(d, NULL, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m && m->nbody == 1);
    fe_state *s = NULL;
    if (m && fe_state_create(m, &s, &err) == MCS_OK) {
        CHECK_REL(m->mass_total, 1010, 1e-12);
        CHECK_NEAR(m->body[0].mass, 10, 0);
        while (s->time < 0.2)
            if (fe_step(m, s) != MCS_OK) break;
        const double t = s->time, c[3] = {0.6 + 2 * t, 0.5, 0.5};
        for (int i = 0; i < 3; i++) CHECK_NEAR(s->body_x[i], c[i], 1e-12);
        CHECK_NEAR(s->body_v[0], 2, 1e-12);
        CHECK_NEAR(s->body_w[2], 5, 1e-12);
        /* node 1 (the origin) about the given CG: r0 = (-0.6, -0.5, -0.5) */
        const double ph = 5 * t, r0[2] = {-0.6, -0.5};
        const double x = c[0] + cos(ph) * r0[0] - sin(ph) * r0[1];
        const double y = c[1] + sin(ph) * r0[0] + cos(ph) * r0[1];
        CHECK_NEAR(s->node_x[0], x, 1e-9);
        CHECK_NEAR(s->node_x[1], y, 1e-9);
        const double ke = 0.5 * 10 * 2 * 2 + 0.5 * 3 * 5 * 5;
        printf("*PART_INERTIA body at t = %.4f s: CG x %.12f (closed form %.12f), "
               "kinetic %.9g J (closed form %.9g)\n",
               t, s->body_x[0], c[0], s->energy[FE_E_kinetic], ke);
        CHECK_REL(s->energy[FE_E_kinetic], ke, 1e-9);
        fe_kw_deck *r = model_round_trip(m);
        const fe_kw_part *q = r ? fe_kw_find_part(r, 1) : NULL;
        CHECK(q && q->inertia.given && q->inertia.mass == 10 && q->inertia.i[3] == 2);
        CHECK(q && q->inertia.cg[0] == 0.6 && q->inertia.w[2] == 5);
        fe_kw_deck_destroy(&r);
    }
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    fe_kw_deck *r = round_trip(d, NULL, FE_KW_FIXED);
    if (r) {
        const fe_kw_part *q1 = fe_kw_find_part(r, 1), *q2 = fe_kw_find_part(r, 2);
        CHECK(q1 && q2 && q1->inertia.given && q2->contact.given);
        if (q1 && q2)
            CHECK(memcmp(&q1->inertia, &p1->inertia, sizeof q1->inertia) == 0 &&
                  memcmp(&q2->contact, &p2->contact, sizeof q2->contact) == 0);
    }
    fe_kw_deck_destroy(&r);
    /* on a deformable part: refused by name and line */
    fe_kw_part *pp = (fe_kw_part *)fe_kw_find_part(d, 2);
    pp->inertia = p1->inertia;
    err = (mcs_error){0};
    m = build(d, NULL, &err);
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(err.msg, "part_inertia.k:14: error: *PART_INERTIA 2: given mass");
    fe_model_destroy(&m);
    /* an equation of state: refused by the part's line */
    pp->inertia.given = 0, pp->eosid = 3;
    err = (mcs_error){0};
    m = build(d, NULL, &err);
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(err.msg, "part_inertia.k:14: error: *PART 2: EOSID 3: equations of state");
    fe_model_destroy(&m);
    fe_kw_deck_destroy(&d);
}

/* hourglass.k: HGID 1 IHQ 2 QM 0.08 -> viscous 0.08; HGID 2 IHQ 4 QM 0.03 -> stiffness 0.03;
 * HGID 3 IHQ 6 -> stiffness at the kernel's default (0, i.e. 0.05); HGID 0 ->
 * *CONTROL_HOURGLASS IHQ 5 QH 0.04 -> stiffness 0.04; HGID 4 IHQ 0 -> the control's type and
 * QH */
static void test_hourglass(void)
{
    fe_kw_deck *d = read_deck(KD "hourglass.k", NULL);
    if (!d) return;
    CHECK(d->nhg == 4 && d->ctl.hg_given && d->ctl.hg_ihq == 5 && d->nunknown == 0);
    const fe_hourglass form[5] = {FE_HG_VISCOUS, FE_HG_STIFFNESS, FE_HG_STIFFNESS,
                                  FE_HG_STIFFNESS, FE_HG_STIFFNESS};
    const double q[5] = {0.08, 0.03, 0, 0.04, 0.04};
    for (int p = 0; p < 5; p++) {
        fe_part_desc pd = fe_part_desc_default();
        mcs_error err = {0};
        CHECK(fe_kw_part_props(d, p + 1, &pd, &err) == MCS_OK);
        CHECK(pd.section.hourglass == form[p]);
        CHECK_NEAR(pd.section.hourglass_coefficient, q[p], 1e-15);
    }
    mcs_error err = {0};
    fe_model *m = build(d, NULL, &err);
    CHECK(m != NULL);
    if (m) {
        CHECK_NEAR(m->part[2].hg_coef, 0.05, 0); /* the kernel's stiffness default */
        /* the model's deck: *HOURGLASS IHQ 2 / 4 with the effective coefficients */
        fe_kw_deck *r = model_round_trip(m);
        CHECK(r && r->nhg == 5);
        for (int p = 0; r && p < 5; p++) {
            fe_part_desc pd = fe_part_desc_default();
            CHECK(fe_kw_part_props(r, p + 1, &pd, &err) == MCS_OK);
            CHECK(pd.section.hourglass == form[p]);
            CHECK_NEAR(pd.section.hourglass_coefficient, m->part[p].hg_coef, 1e-15);
        }
        fe_kw_deck_destroy(&r);
    }
    fe_model_destroy(&m);
    fe_kw_deck *r = round_trip(d, NULL, FE_KW_FIXED);
    if (r) {
        CHECK(r->nhg == 4 && r->ctl.hg_given && r->ctl.hg_qh == 0.04);
        CHECK(fe_kw_find_part(r, 2) && fe_kw_find_part(r, 2)->hgid == 2);
        const fe_kw_hourglass *h = fe_kw_find_hourglass(r, 2);
        CHECK(h && h->ihq == 4 && h->qm == 0.03 && h->q1 == 1.5);
    }
    fe_kw_deck_destroy(&r);
    /* an HGID that names no *HOURGLASS */
    ((fe_kw_part *)fe_kw_find_part(d, 1))->hgid = 9;
    fe_part_desc pd = fe_part_desc_default();
    err = (mcs_error){0};
    CHECK(fe_kw_part_props(d, 1, &pd, &err) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(err.msg, "*PART 1: HGID 9 is not an *HOURGLASS");
    fe_kw_deck_destroy(&d);
}

/* timestep.k: a steel cube of side a = 1 m (E 210 GPa, nu 0.3, rho 7850): c =
 * sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu) rho)), the one-point hex step with the linear bulk
 * viscosity Q2 = 0.06 (the kernel's default, LS-DYNA's formula): dt_e = a / (c (Q2 +
 * sqrt(1 + Q2^2))); TSSFAC 0.67 gives dt = 0.67 dt_e. DT2MS -3e-4 s asks TSSFAC |DT2MS| =
 * 2.01e-4 s: the density scales by f^2, f = 2.01e-4 / (0.67 dt_e), adding M (f^2 - 1)
 * (fe_massscale.c's rule, by hand); MS1ST 1: at t = 0 only */
static double cube_step(void)
{
    const double E = 2.1e11, nu = 0.3, rho = 7850, q2 = 0.06;
    const double c = sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho));
    return 1 / (c * (q2 + sqrt(1 + q2 * q2)));
}

static void test_timestep(void)
{
    fe_kw_deck *d = read_deck(KD "timestep.k", NULL);
    if (!d) return;
    CHECK(d->ctl.ts_given && d->ctl.tssfac == 0.67 && d->ctl.dt2ms == -3e-4 && d->ctl.ms1st == 1);
    fe_opts o = fe_opts_default();
    mcs_error err = {0};
    CHECK(fe_kw_deck_opts(d, &o, &err) == MCS_OK);
    CHECK(o.dt_scale == 0.67 && o.mass_scaling_interval == 0);
    CHECK_NEAR(o.mass_scaling_dt, 0.67 * 3e-4, 1e-18);
    const double E = 2.1e11, nu = 0.3, rho = 7850, dte = cube_step();
    const double f = 0.67 * 3e-4 / (0.67 * dte), added = rho * (f * f - 1);
    fe_model *m = build(d, &o, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL);
    if (m) {
        CHECK_REL(m->mass_added, added, 1e-9);
        CHECK_REL(m->dt_initial, 0.67 * 3e-4, 1e-9);
        printf("*CONTROL_TIMESTEP: mass added %.6g kg (closed form %.6g), step %.6g s\n",
               m->mass_added, added, m->dt_initial);
    }
    fe_model_destroy(&m);
    /* without DT2MS: dt = TSSFAC dt_e x sqrt((lambda + 2 mu) / (3 lambda + 2 mu)), the
     * factor of a lone cube's dilatation mode (fe_hex_dt.c, closed form) */
    d->ctl.dt2ms = 0;
    o = fe_opts_default();
    CHECK(fe_kw_deck_opts(d, &o, &err) == MCS_OK && o.mass_scaling_dt == 0);
    m = build(d, &o, &err);
    const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    CHECK(m != NULL);
    if (m) CHECK_REL(m->dt_initial, 0.67 * dte * sqrt((lam + 2 * mu) / (3 * lam + 2 * mu)), 1e-9);
    fe_model_destroy(&m);
    fe_kw_deck *r = round_trip(d, NULL, FE_KW_FIXED);
    if (r) CHECK(r->ctl.ts_given && r->ctl.tssfac == 0.67 && r->ctl.ms1st == 1);
    fe_kw_deck_destroy(&r);
    /* what the kernel does not build: refused with the card's line */
    d->ctl.dt2ms = 1e-4;
    err = (mcs_error){0};
    CHECK(fe_kw_deck_opts(d, &o, &err) == MCS_ERR_UNSUPPORTED);
    CHECK_STR_CONTAINS(err.msg, "timestep.k:5: error: *CONTROL_TIMESTEP: DT2MS > 0");
    d->ctl.dt2ms = 0, d->ctl.lctm = 3;
    err = (mcs_error){0};
    CHECK(fe_kw_deck_opts(d, &o, &err) == MCS_ERR_UNSUPPORTED);
    CHECK_STR_CONTAINS(err.msg, "LCTM");
    fe_kw_deck_destroy(&d);
}

/* timestep.k as a scenario's whole deck (fe: {keyword: ...}): its *CONTROL_TIMESTEP sets the
 * run's step scale and mass scaling, so the run starts at TSSFAC |DT2MS| = 2.01e-4 s with the
 * mass of test_timestep's closed form; the scenario's time_step_scale wins over TSSFAC */
static void test_timestep_whole_deck(void)
{
    char cwd[512], yaml[64], text[1024], args[256];
    if (!getcwd(cwd, sizeof cwd)) return;
    snprintf(yaml, sizeof yaml, "/tmp/mcrash_kwelem_%ld.yaml", (long)getpid());
    for (int pass = 0; pass < 2; pass++) {
        snprintf(text, sizeof text,
                 "mcrash: 1\nsimulation: {end_time: 1 ms, output_rate: 1 kHz%s}\n"
                 "fe: {keyword: %s/" KD "timestep.k}\n",
                 pass ? ", time_step_scale: 0.5" : "", cwd);
        FILE *f = fopen(yaml, "w");
        if (!f) return;
        fputs(text, f);
        fclose(f);
        snprintf(args, sizeof args, "run %s -o %s.h5 --quiet --json", yaml, yaml);
        cli_result *r = cli_run(args);
        CHECK(r->status == 0);
        const char *dt = strstr(r->out, "\"dt_initial_s\": ");
        const char *ma = strstr(r->out, "\"mass_added_kg\": ");
        CHECK(dt && ma);
        if (!dt || !ma) continue;
        const double rho = 7850, scale = pass ? 0.5 : 0.67;
        const double f2 = pow(0.67 * 3e-4 / (scale * cube_step()), 2);
        CHECK_REL(atof(dt + 16), 0.67 * 3e-4, 1e-5);
        CHECK_REL(atof(ma + 17), rho * (f2 - 1), 1e-5);
    }
    char h5[96];
    snprintf(h5, sizeof h5, "%s.h5", yaml);
    remove(yaml), remove(h5);
}

/* reading errors at the card: an offset shell, a negative thickness */
static void test_refused_cards(void)
{
    static const char *deck[] = {
        "*KEYWORD\n*ELEMENT_SHELL_THICKNESS_OFFSET\n       1       1       1       2       3"
        "       4\n             1.0             1.0             1.0             1.0\n"
        "             0.5\n*END\n",
        "*KEYWORD\n*ELEMENT_SHELL_THICKNESS\n       1       1       1       2       3       4\n"
        "            -1.0\n*END\n",
    };
    static const char *want[] = {"mem.k:5:1: error: *ELEMENT_SHELL_THICKNESS_OFFSET: field OFFSET",
                                 "mem.k:4:1: error: *ELEMENT_SHELL_THICKNESS: field THIC1"};
    for (int i = 0; i < 2; i++) {
        fe_kw_opts o = fe_kw_opts_default();
        o.quiet = 1;
        fe_kw_deck *d = NULL;
        mcs_error err = {0};
        CHECK(fe_kw_read_mem("mem.k", deck[i], strlen(deck[i]), &o, &d, &err) != MCS_OK);
        CHECK_STR_CONTAINS(err.msg, want[i]);
        fe_kw_deck_destroy(&d);
    }
}

int main(void)
{
    RUN(test_shell_thickness);
    RUN(test_shell_thickness_run);
    RUN(test_tshell);
    RUN(test_solid_user);
    RUN(test_beams);
    RUN(test_part_inertia);
    RUN(test_hourglass);
    RUN(test_timestep);
    RUN(test_timestep_whole_deck);
    RUN(test_refused_cards);
    TEST_END();
}

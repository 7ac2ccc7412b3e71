/* test_kw_corpus.c: the project's corpus of keyword decks (tests/data/keyword/corpus/), written
 * in the shapes users' LS-DYNA decks take (issue 14): parameters and expressions, nested,
 * relative and commented includes, include paths, thickness cards, contacts, hourglass cards,
 * materials, refusals by name. Each row gives what reading the deck must give: its counts, or
 * the refusal message and the file:line it names. A row may also build the deck (the whole
 * deck as fe_kw_add_deck does, or part 1 as a scenario's `mesh: {keyword:, part: 1}` does) and
 * add its own checks of the values read.
 *
 * Adding a deck: write it under tests/data/keyword/corpus/, add a row to `corpus` (counts by
 * hand from the deck's text), and if it reads, its values in a check function with the hand
 * calculation in a comment. The figure "N of M corpus decks read" (docs/keyword.md) follows:
 * run `make figures` (or edit the marker) after adding rows. */
#include "fe/fe_kw_impl.h" /* kw_expr_eval, the evaluator on its own */
#include "cli_util.h"
#include "harness.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CD "tests/data/keyword/corpus/"

enum { READ_ONLY, BUILD_DECK, BUILD_PART1 };

typedef struct {
    const char *file;              /* under CD                                                */
    const char *units;             /* the deck's units (NULL: m-s-kg)                          */
    int build;                     /* READ_ONLY | BUILD_DECK | BUILD_PART1                      */
    int nnode;                     /* nodes [-]                                                */
    int nelem[FE_KW_NETYPE];       /* elements per kind: shell, solid, beam, discrete, tet10   */
    int npart, nmat;               /* *PART and *MAT_ cards [-]                                 */
    const char *refusal;           /* expected message substring; NULL: the deck must read     */
    const char *at;                /* expected "file:line" in the refusal                       */
    void (*check)(const fe_kw_deck *d); /* further checks of a deck read (NULL: none)          */
} corpus_row;

static const double *node_at(const fe_kw_deck *d, int id)
{
    int i = fe_kw_node_index(d, id);
    return i >= 0 ? d->node_x + 3 * i : NULL;
}

/* param_basic.k (mm-s-t): LEN = 10 mm, PID = 7, SEC = 3, RHO = 7.85e-9 t/mm^3 = 7850 kg/m^3,
 * EMOD (type C) = 210000 MPa = 2.1e11 Pa, NU = 0.3; node 3 = (&len, &len, -&len) mm */
static void check_param_basic(const fe_kw_deck *d)
{
    const double *x = node_at(d, 3);
    CHECK(x && fabs(x[0] - 0.01) < 1e-15 && fabs(x[1] - 0.01) < 1e-15 &&
          fabs(x[2] + 0.01) < 1e-15);
    CHECK(d->npart == 1 && d->part[0].id == 7 && d->part[0].secid == 3 && d->part[0].mid == 4);
    CHECK(d->elem[FE_KW_SOLID].n == 1 && d->elem[FE_KW_SOLID].pid[0] == 7);
    const fe_kw_mat *m = fe_kw_find_mat(d, 4);
    CHECK(m && fabs(m->ro - 7850) < 1e-9 && fabs(m->e - 2.1e11) < 1 && m->pr == 0.3);
    CHECK(fe_kw_find_section(d, 3) != NULL);
}

/* param_expr.k (m-s-kg), by hand: HYP = sqrt(3^2 + 4^2) = 5; NEG = -(2^2) + (3 - 4) * 2 = -6;
 * TRIG = sin^2 + cos^2 + tan 0 = 1; MIX = 4/3 + |-4| - e^0 + ln 1 = 13/3; NPID = I(5 - 3) = 2;
 * DOUBLE = 2 * 5 = 10 (free-format card) */
static void check_param_expr(const fe_kw_deck *d)
{
    const double *x3 = node_at(d, 3), *x5 = node_at(d, 5);
    CHECK(x3 && fabs(x3[0] - 5) < 1e-15 && fabs(x3[1] - 13.0 / 3) < 1e-15);
    CHECK(x5 && fabs(x5[0] - 10) < 1e-15 && fabs(x5[2] + 6) < 1e-15);
    CHECK(d->npart == 1 && d->part[0].id == 2 && d->elem[FE_KW_SHELL].pid[0] == 2);
    const fe_kw_section *s = fe_kw_find_section(d, 1);
    CHECK(s && fabs(s->t[0] - 1) < 1e-15 && fabs(s->t[3] - 1) < 1e-15);
}

/* param_local.k: global X0 = 1; the include's local X0 = 2 gives its node 1 x = 2 and the
 * global X1 = 2 * 10 = 20; back in the main file X0 is the global 1 again (node 5) */
static void check_param_local(const fe_kw_deck *d)
{
    const double *x1 = node_at(d, 1), *x2 = node_at(d, 2), *x5 = node_at(d, 5);
    CHECK(x1 && x1[0] == 2 && x2 && x2[0] == 20 && x5 && x5[0] == 1);
}

/* include_path.k: nodes 11, 12, 13 from lib/ (by *INCLUDE_PATH_RELATIVE), a backslash path and
 * a name continued over two cards */
static void check_include_path(const fe_kw_deck *d)
{
    const double *a = node_at(d, 11), *b = node_at(d, 12), *c = node_at(d, 13);
    CHECK(a && a[2] == 5 && b && b[2] == 6 && c && c[2] == 7);
    CHECK(d->nfile == 4);
}

/* unknown_many.k: three distinct keywords, *DATABASE_GLSTAT three times (first on line 5) */
static void check_unknown_many(const fe_kw_deck *d)
{
    CHECK(d->nunknown == 3);
    if (d->nunknown != 3) return;
    CHECK(strcmp(d->unknown[0].name, "CONTROL_ENERGY") == 0 && d->unknown[0].count == 1);
    CHECK(strcmp(d->unknown[1].name, "DATABASE_GLSTAT") == 0 && d->unknown[1].count == 3);
    CHECK(d->unknown[1].loc.line == 5 && d->unknown[1].loc.file == 0);
    CHECK(strcmp(d->unknown[2].name, "DATABASE_MATSUM") == 0 && d->unknown[2].count == 1);
}

/* param_dup.k: X = 1 then 2: the first kept (node 1 x = 1); after DFLAG 2, X = 3 is taken
 * (node 2); after DFLAG 5, X = 4 is not (node 3 x = 3); after DFLAG 4, X = 5 is (node 4) */
static void check_param_dup(const fe_kw_deck *d)
{
    const double *x1 = node_at(d, 1), *x2 = node_at(d, 2), *x3 = node_at(d, 3),
                 *x4 = node_at(d, 4);
    CHECK(x1 && x1[0] == 1 && x2 && x2[0] == 3 && x3 && x3[0] == 3 && x4 && x4[0] == 5);
}

/* contact_plates.k (mm-s-t), by hand: three contacts (all parts, 2 on 1 with FS 0.3, nodes of
 * part 2 on part set 5 = parts 1..2); set 5 = {1, 2}, set 7 = {1, 2, 3, 4}; nodes 5..8 at
 * -1000 mm/s = -1 m/s; the motion on set 7: d = 1 mm/s t, v = 1e-3 m/s (SF 0 takes 1); node 6
 * loaded by -5 x 1 N; ENDTIM 1.5 ms */
static void check_contact_plates(const fe_kw_deck *d)
{
    CHECK(d->ncontact == 3);
    if (d->ncontact != 3) return;
    CHECK(d->contact[0].type == FE_KW_CT_SINGLE && d->contact[0].sstyp == 5 &&
          d->contact[0].id == 1 && strcmp(d->contact[0].title, "all parts") == 0);
    CHECK(d->contact[0].fs == 0.2 && d->contact[0].dt == 0);
    CHECK(d->contact[1].type == FE_KW_CT_S2S && d->contact[1].fs == 0.3 &&
          strcmp(d->contact[1].title, "upper on lower") == 0);
    CHECK(d->contact[2].type == FE_KW_CT_N2S && !d->contact[2].automatic &&
          d->contact[2].msid == 5 && d->contact[2].mstyp == 2);
    const fe_kw_set *s5 = fe_kw_find_set(d, 5, 1), *s7 = fe_kw_find_set(d, 7, 0);
    CHECK(s5 && s5->n == 2 && s7 && s7->n == 4 && s7->ids[3] == 4);
    CHECK(d->nnodevel == 4 && fabs(d->nodevel[3].v[2] + 1) < 1e-12);
    CHECK(d->npmotion == 1 && d->pmotion[0].sf == 1 && d->pmotion[0].vad == 2);
    CHECK(d->nload == 1 && d->load[0].nid == 6 && d->load[0].sf == -5);
    CHECK(fabs(d->end_time - 1.5e-3) < 1e-15);
}

/* param_formats.k: LONGX = 2.5, LONGN = 4 (long format), FREE = 1.25, K = 9 (free format):
 * node &longn = 4 at (2.5, 1.25, -9) */
static void check_param_formats(const fe_kw_deck *d)
{
    const double *x = node_at(d, 4);
    CHECK(x && x[0] == 2.5 && x[1] == 1.25 && x[2] == -9);
}

/* contact_segment_set.k: segment set 3 = the block's bottom face (5 6 7 8), node set 4 = its
 * nodes; three contacts on them (the model's passes: tests/test_kw_contact.c) */
static void check_contact_sets(const fe_kw_deck *d)
{
    CHECK(d->ncontact == 3 && d->nsegset == 1 && d->segset[0].n == 1);
    if (d->ncontact != 3) return;
    CHECK(d->contact[0].sstyp == 0 && d->contact[0].ssid == 3 && d->contact[1].sstyp == 4 &&
          d->contact[2].type == FE_KW_CT_SINGLE && d->contact[2].sstyp == 0);
}

/* contact_mpp.k (mm-s-t): SLSFAC 0.075, SHLTHK 1; contact 1000001 "all" (single surface, all
 * parts, FS 0.125) and 1000002 (nodes of part 1 on part 1), their MPP cards read over */
static void check_contact_mpp(const fe_kw_deck *d)
{
    CHECK(d->slsfac == 0.075 && d->shlthk == 1 && d->ncontact == 2);
    if (d->ncontact != 2) return;
    CHECK(d->contact[0].id == 1000001 && strcmp(d->contact[0].title, "all") == 0);
    CHECK(d->contact[0].sstyp == 5 && d->contact[0].fs == 0.125 && d->contact[0].dt == 0);
    CHECK(d->contact[1].id == 1000002 && d->contact[1].type == FE_KW_CT_N2S);
}

/* VDC 20 (% of critical) read as given (the kernel takes VDC / 100: fe_kw_build_contact.c) */
static void check_contact_damped(const fe_kw_deck *d)
{
    CHECK(d->ncontact == 1);
    if (d->ncontact == 1) CHECK(d->contact[0].vdc == 20 && d->contact[0].vc == 0);
}

/* materials.k (mm-s-t), by hand: 7.85e-9 t/mm^3 = 7850 kg/m^3, 210000 MPa = 2.1e11 Pa,
 * 350 MPa, 1200 MPa; SRC 40.4/s; foam 6e-11 t/mm^3 = 60 kg/m^3, E 5 MPa, TC 1e20 (none),
 * its curve's compressive points (0.05, 0.04 MPa), (0.5, 0.08 MPa), (0.8, 0.6 MPa) (the tension
 * point and (0, 0) left to E); null 1e-9 t/mm^3 = 1000 kg/m^3, YM 5 MPa; rigid CMO 1, 7, 7 */
static void check_materials(const fe_kw_deck *d)
{
    const fe_kw_mat *pk = fe_kw_find_mat(d, 1), *fo = fe_kw_find_mat(d, 2);
    const fe_kw_mat *nu = fe_kw_find_mat(d, 3), *ri = fe_kw_find_mat(d, 4);
    CHECK(pk && pk->type == FE_KW_MAT_PK && fabs(pk->ro - 7850) < 1e-9 &&
          fabs(pk->e - 2.1e11) < 1 && fabs(pk->sigy - 3.5e8) < 1e-3 &&
          fabs(pk->etan - 1.2e9) < 1e-3 && pk->beta == 1 && pk->c == 40.4 && pk->p == 5 &&
          pk->fail == 0.3);
    CHECK(fo && fo->type == FE_KW_MAT_LDF && fabs(fo->ro - 60) < 1e-9 && fabs(fo->e - 5e6) < 1e-6 &&
          fo->lcid == 10 && fo->tc == 0 && fo->hu == 0.25 && fo->shape == 4);
    CHECK(nu && nu->type == FE_KW_MAT_NULL && fabs(nu->ro - 1000) < 1e-9 &&
          fabs(nu->e - 5e6) < 1e-6 && nu->pr == 0.3);
    CHECK(ri && ri->type == FE_KW_MAT_RIGID && ri->cmo == 1 && ri->con1 == 7 && ri->con2 == 7);
    fe_part_desc a = fe_part_desc_default(), b = fe_part_desc_default();
    fe_part_desc c = fe_part_desc_default(), r = fe_part_desc_default();
    mcs_error err = {0};
    CHECK(fe_kw_part_props(d, 1, &a, &err) == MCS_OK && fe_kw_part_props(d, 2, &b, &err) == MCS_OK);
    CHECK(fe_kw_part_props(d, 3, &c, &err) == MCS_OK && fe_kw_part_props(d, 4, &r, &err) == MCS_OK);
    /* bilinear: H = E Et / (E - Et) = 210000 * 1200 / 208800 MPa = 1206.896552 MPa */
    CHECK(a.material.model == FE_MAT_ELASTIC_PLASTIC && a.material.failure_strain == 0.3 &&
          fabs(a.material.hardening[1][1] - 3.5e8 - 1206.896552e6) < 1);
    CHECK(b.material.model == FE_MAT_FOAM && b.material.foam_npoint[0] == 3 &&
          fabs(b.material.foam_curve[0][0][1] - 4e4) < 1e-9 && b.material.poisson == 0);
    CHECK(c.material.model == FE_MAT_NULL && r.material.rigid_fix == FE_DOF_ALL);
}

static const corpus_row corpus[] = {
    /* parameters */
    {"param_basic.k", "mm-s-t", BUILD_DECK, 8, {0, 1}, 1, 1, NULL, NULL, check_param_basic},
    {"param_expr.k", NULL, READ_ONLY, 5, {1}, 1, 1, NULL, NULL, check_param_expr},
    {"param_local.k", NULL, READ_ONLY, 3, {0}, 0, 0, NULL, NULL, check_param_local},
    {"param_undefined.k", NULL, READ_ONLY, 0, {0}, 0, 0,
     "*NODE: field X: parameter 'THIK' is not defined", "param_undefined.k:7:20:", NULL},
    {"param_bad_expr.k", NULL, READ_ONLY, 0, {0}, 0, 0, "*PARAMETER_EXPRESSION: parameter 'A'",
     "param_bad_expr.k:3:", NULL},
    {"param_formats.k", NULL, READ_ONLY, 1, {0}, 0, 0, NULL, NULL, check_param_formats},
    {"param_dup.k", NULL, READ_ONLY, 4, {0}, 0, 0, NULL, NULL, check_param_dup},
    {"param_dup_refused.k", NULL, READ_ONLY, 0, {0}, 0, 0,
     "parameter 'N' defined twice (first at " CD "param_dup_refused.k:6",
     "param_dup_refused.k:6:21:", NULL},
    {"param_not_int.k", NULL, READ_ONLY, 0, {0}, 0, 0,
     "*PART: field PID: parameter 'PID' = 1.5 is not an integer", "param_not_int.k:7:7:", NULL},
    /* includes */
    {"include_nested.k", NULL, BUILD_DECK, 6, {2}, 1, 1, NULL, NULL, NULL},
    {"include_missing_nested.k", NULL, READ_ONLY, 0, {0}, 0, 0, "*INCLUDE: cannot open",
     "inc/mid_missing.k:3:1:", NULL},
    {"include_commented.k", NULL, READ_ONLY, 1, {0}, 0, 0, NULL, NULL, NULL},
    {"include_path.k", NULL, READ_ONLY, 3, {0}, 0, 0, NULL, NULL, check_include_path},
    {"include_circular.k", NULL, READ_ONLY, 0, {0}, 0, 0, "circular include",
     "inc/circ_b.k:3:1:", NULL},
    /* contacts, boundary, loads */
    {"contact_plates.k", "mm-s-t", BUILD_DECK, 8, {2}, 2, 1, NULL, NULL, check_contact_plates},
    {"contact_segment_set.k", "mm-s-t", BUILD_DECK, 12, {1, 1}, 2, 1, NULL, NULL,
     check_contact_sets},
    {"contact_mpp.k", "mm-s-t", BUILD_DECK, 4, {1}, 1, 1, NULL, NULL, check_contact_mpp},
    {"contact_damped.k", NULL, READ_ONLY, 0, {0}, 0, 0, NULL, NULL, check_contact_damped},
    /* unknown and refused keywords */
    {"unknown_many.k", NULL, READ_ONLY, 1, {0}, 0, 0, NULL, NULL, check_unknown_many},
    {"sph_refused.k", NULL, READ_ONLY, 0, {0}, 0, 0, "*SECTION_SPH: not supported (SPH",
     "sph_refused.k:6:1:", NULL},
    {"skipped_set.k", NULL, BUILD_DECK, 8, {0, 1}, 1, 1,
     "node set 5 is not defined (skipped as not supported: *SET_NODE_GENERAL at",
     "skipped_set.k:11)", NULL},
    {"skipped_deck.k", NULL, BUILD_DECK, 2, {0}, 1, 1,
     "no *PART has elements (skipped as not supported: *ELEMENT_SEATBELT at",
     "skipped_deck.k:15)", NULL},
    {"skipped_element.k", NULL, BUILD_PART1, 2, {0}, 1, 1,
     "no element has part ID 1 (skipped as not supported: *ELEMENT_SEATBELT at",
     "skipped_element.k:14)", NULL},
    /* elements, sections, parts, controls (values and closed forms: test_fe_kw_elem.c) */
    {"shell_thickness.k", "mm-s-t", BUILD_DECK, 9, {4}, 1, 1, NULL, NULL, NULL},
    {"tshell.k", NULL, BUILD_DECK, 0, {0}, 0, 0, "*ELEMENT_TSHELL 1 (part 1): thick shells",
     "tshell.k:25:", NULL},
    {"solid_user.k", NULL, BUILD_DECK, 0, {0}, 0, 0, "*SECTION_SOLID 1: ELFORM 102",
     "solid_user.k:11:", NULL},
    {"beams.k", "mm-s-t", BUILD_DECK, 0, {0}, 0, 0, "*SECTION_BEAM 1: ELFORM 2",
     "beams.k:13:", NULL},
    {"part_inertia.k", NULL, BUILD_DECK, 16, {0, 2}, 2, 2, NULL, NULL, NULL},
    {"hourglass.k", NULL, BUILD_DECK, 40, {0, 5}, 5, 1, NULL, NULL, NULL},
    {"timestep.k", NULL, BUILD_DECK, 8, {0, 1}, 1, 1, NULL, NULL, NULL},
    /* materials (closed forms and refusals: test_kw_mat.c, test_fe_erosion.c) */
    {"materials.k", "mm-s-t", BUILD_DECK, 20, {2, 2}, 4, 4, NULL, NULL, check_materials},
    {"mooney_refused.k", "mm-s-t", READ_ONLY, 0, {0}, 0, 0,
     "*MAT_MOONEY-RIVLIN_RUBBER: material 1: the Mooney-Rivlin hyperelastic solid is not built",
     "mooney_refused.k:11:", NULL},
    {"foam_damped.k", "mm-s-t", READ_ONLY, 0, {0}, 0, 0,
     "*MAT_LOW_DENSITY_FOAM: field DAMP: 0.5: the foam's viscous damping is not built",
     "foam_damped.k:6:71:", NULL},
};

#define NROW ((int)(sizeof corpus / sizeof corpus[0]))

/* build a deck read: the whole deck into a model, or part 1 as a scenario part */
static mcs_status build(const corpus_row *r, const fe_kw_deck *d, mcs_error *err)
{
    fe_builder *b = NULL;
    fe_model *m = NULL;
    mcs_status st = fe_builder_create(&b, err);
    if (!st && r->build == BUILD_DECK) st = fe_kw_add_deck(b, d, err);
    if (!st && r->build == BUILD_PART1) {
        fe_part_desc base = fe_part_desc_default();
        snprintf(base.name, sizeof base.name, "part1");
        st = fe_kw_add_part(b, d, 1, &base, 1, NULL, NULL, err);
    }
    if (!st) st = fe_model_create(b, NULL, &m, err);
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    return st;
}

/* one row: 1 when the deck gave what the row expects */
static int run_row(const corpus_row *r, int *read_ok)
{
    char path[512];
    snprintf(path, sizeof path, CD "%s", r->file);
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    o.units = r->units;
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    int before = th_checks_failed;
    mcs_status st = fe_kw_read(path, &o, &d, &err);
    if (!st && r->build != READ_ONLY) st = build(r, d, &err);
    *read_ok = st == MCS_OK;
    if (r->refusal) {
        if (st == MCS_OK) fprintf(stderr, "%s: read, a refusal was expected\n", r->file);
        CHECK(st != MCS_OK);
        CHECK_STR_CONTAINS(err.msg, r->refusal);
        CHECK_STR_CONTAINS(err.msg, r->at);
    } else {
        if (st) fprintf(stderr, "%s: %s\n", r->file, err.msg);
        CHECK(st == MCS_OK);
    }
    if (d && !r->refusal) {
        CHECK(d->nnode == r->nnode);
        for (int t = 0; t < FE_KW_NETYPE; t++) CHECK(d->elem[t].n == r->nelem[t]);
        CHECK(d->npart == r->npart && d->nmat == r->nmat);
        if (r->check) r->check(d);
    }
    fe_kw_deck_destroy(&d);
    if (th_checks_failed != before) fprintf(stderr, "  in corpus row %s\n", r->file);
    return th_checks_failed == before;
}

static void test_corpus(void)
{
    int nread = 0, nrefused = 0;
    for (int i = 0; i < NROW; i++) {
        int read_ok = 0;
        int ok = run_row(&corpus[i], &read_ok);
        nread += ok && read_ok;
        nrefused += ok && !read_ok;
    }
    /* every row as expected: the read ones and the refused ones */
    CHECK(nread + nrefused == NROW);
    FIG("keyword.corpus_read", "%.0f", nread);
    FIG("keyword.corpus_decks", "%.0f", NROW);
}

/* the evaluator on its own, each value by hand */
static int no_names(void *user, const char *name, double *v)
{
    (void)user;
    if (strcmp(name, "X") == 0) return *v = 2, 0;
    return -1;
}

static void test_expressions(void)
{
    static const struct {
        const char *s;
        double v;
    } ok[] = {
        {"1 + 2 * 3", 7},           {"(1 + 2) * 3", 9},       {"2 ** 3 ** 2", 512},
        {"-2 ** 2", -4},            {"2 ^ -1", 0.5},          {"10 / 4 / 5", 0.5},
        {"1.5d1 + .5e1", 20},       {"max(1, x, -3)", 2},     {"min(4, 3.5)", 3.5},
        {"atan2(1, 1) * 4", M_PI},  {"sqrt(x) ** 2", 2},      {"-&x * -x", 4},
        {"int(-2.7) + nint(2.5)", 1}, {"mod(7, 3) + sign(2, -1)", -1}, {"log10(1000)", 3},
    };
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++) {
        double v = 0;
        int pos = 0;
        char msg[128];
        int r = kw_expr_eval(ok[i].s, no_names, NULL, &v, &pos, msg, sizeof msg);
        if (r) fprintf(stderr, "'%s': %s at %d\n", ok[i].s, msg, pos);
        CHECK(r == 0);
        CHECK_NEAR(v, ok[i].v, 1e-12 * fmax(1, fabs(ok[i].v)));
    }
    static const struct {
        const char *s;
        int pos;
        const char *msg;
    } bad[] = {
        {"1 +", 3, "unexpected end"},        {"2 * (3", 6, "')' expected"},
        {"y + 1", 0, "parameter 'Y'"},       {"foo(1)", 0, "unknown function 'FOO'"},
        {"sin(1, 2)", 0, "wrong number"},    {"1 2", 2, "unexpected '2'"},
        {"log(0)", 0, "not finite"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        double v = 0;
        int pos = -1;
        char msg[128] = "";
        CHECK(kw_expr_eval(bad[i].s, no_names, NULL, &v, &pos, msg, sizeof msg) != 0);
        CHECK(pos == bad[i].pos);
        CHECK_STR_CONTAINS(msg, bad[i].msg);
    }
}

/* mcrash check reads the decks a scenario names: a missing deck and a part ID the deck lacks
 * (no *PART 5, as the build would say) are errors (exit 2) at the scenario key; --json lists
 * each deck's unknown keywords once (check_deck.k: *USER_LOADING on lines 4 and 23,
 * *EOS_GRUNEISEN on line 14) */
static void test_check_cli(void)
{
    const char *scn = CD "scn/";
    char args[512];
    snprintf(args, sizeof args, "check %scheck_ok.yaml", scn);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->err, "*USER_LOADING x2, first at " CD "scn/check_deck.k:4");
    snprintf(args, sizeof args, "check --json %scheck_ok.yaml", scn);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"keyword_decks\": [");
    CHECK_STR_CONTAINS(r->out, "\"nodes\": 4, \"elements\": 1, \"parts\": 1");
    CHECK_STR_CONTAINS(r->out, "{\"keyword\": \"*USER_LOADING\", \"count\": 2, \"first\": \"" CD
                               "scn/check_deck.k:4\"}");
    CHECK_STR_CONTAINS(r->out, "{\"keyword\": \"*EOS_GRUNEISEN\", \"count\": 1");
    snprintf(args, sizeof args, "check %scheck_badpid.yaml", scn);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "check_badpid.yaml:7:43: error: fe.parts[0].mesh.part: ");
    CHECK_STR_CONTAINS(r->err, "check_deck.k: error: no *PART 5");
    snprintf(args, sizeof args, "check %scheck_nodeck.yaml", scn);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "check_nodeck.yaml:7:23: error: fe.parts[0].mesh.keyword: ");
    CHECK_STR_CONTAINS(r->err, "no_such_deck.k: cannot open");
}

int main(void)
{
    RUN(test_corpus);
    RUN(test_check_cli);
    RUN(test_expressions);
    TEST_END();
}

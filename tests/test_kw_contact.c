/* test_kw_contact.c: *CONTACT_* (six types, _ID/_TITLE, cards 1-3 and the optional cards),
 * *SET_SEGMENT, *SET_*_LIST_GENERATE, *INITIAL_VELOCITY_NODE, *BOUNDARY_PRESCRIBED_MOTION_*,
 * *LOAD_NODE_*, *LOAD_SEGMENT, *CONTROL_TERMINATION (fe/keyword/fe_kw_cards_contact.c,
 * fe/keyword/fe_kw_build_contact.c): values read, what the model gets, refusals naming the field or
 * keyword with FILE:LINE; and a whole deck run by `mcrash run` (fe: {keyword: ...}) against
 * 1-D impact theory. */
#include "cli_util.h"
#include "core/mcs_results.h"
#include "fe/fe_contact.h"
#include "fe/fe_keyword.h"
#include "fe/fe_state.h"
#include "harness.h"
#include "figures.h"
#include "s3_test_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define KD "tests/data/keyword/"

static char tmpdir[64];

static mcs_status read_text(const char *text, const char *units, fe_kw_deck **d, mcs_error *err)
{
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    o.units = units;
    return fe_kw_read_mem("deck.k", text, strlen(text), &o, d, err);
}

/* two 1 x 1 shells 1 mm apart (PID 1 at z = 0, PID 2 at z = 1), mm-s-t, then `tail` */
static char *plates(const char *tail)
{
    static const char head[] =
        "*KEYWORD\n"
        "*PART\nlower\n         1         1         1\n"
        "*PART\nupper\n         2         1         1\n"
        "*SECTION_SHELL\n         1         2\n       0.5       0.5       0.5       0.5\n"
        "*MAT_ELASTIC\n         1    7.8E-9  210000.0       0.3\n"
        "*NODE\n"
        "       1             0.0             0.0             0.0\n"
        "       2             1.0             0.0             0.0\n"
        "       3             1.0             1.0             0.0\n"
        "       4             0.0             1.0             0.0\n"
        "       5             0.0             0.0             1.0\n"
        "       6             1.0             0.0             1.0\n"
        "       7             1.0             1.0             1.0\n"
        "       8             0.0             1.0             1.0\n"
        "*ELEMENT_SHELL\n"
        "       1       1       1       2       3       4\n"
        "       2       2       5       6       7       8\n";
    size_t n = strlen(head) + strlen(tail) + 8;
    char *s = malloc(n);
    snprintf(s, n, "%s%s*END\n", head, tail);
    return s;
}

/* cards of every contact type: _ID and _TITLE cards, cards 1-3, optional cards A-D */
static void test_contact_cards(void)
{
    char *t = plates("*CONTACT_AUTOMATIC_SINGLE_SURFACE_ID\n"
                     "        11self contact\n"
                     "         0         0         5\n"
                     "       0.3       0.2       0.5\n"
                     "       2.0       2.0                           1.5       1.5       2.0\n"
                     "         0       0.1         0     1.025         2         2\n"
                     "       0.0         0         0         0         0         0\n"
                     "         0         0\n"
                     "         0\n"
                     "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TITLE\n"
                     "        12upper on lower\n"
                     "         2         1         3         3\n"
                     "*CONTACT_SURFACE_TO_SURFACE\n"
                     "         2        10         3         2\n"
                     "\n\n"
                     "*CONTACT_NODES_TO_SURFACE\n"
                     "         2         1         3         3\n"
                     "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n"
                     "         2         1         3         3\n"
                     "*CONTACT_AUTOMATIC_GENERAL\n"
                     "        10         0         2\n"
                     "*SET_PART_LIST\n        10\n         1         2\n");
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    mcs_status st = read_text(t, "mm-s-t", &d, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    CHECK(st == MCS_OK && d && d->ncontact == 6);
    if (d && d->ncontact == 6) {
        const fe_kw_contact *c = &d->contact[0];
        CHECK(c->type == FE_KW_CT_SINGLE && c->automatic && c->id == 11);
        CHECK(strcmp(c->title, "self contact") == 0 && c->sstyp == 5);
        /* DC 0.5 s/mm = 500 s/m; FSF scales FS, FD when built */
        CHECK(c->fs == 0.3 && c->fd == 0.2 && fabs(c->dc - 500) < 1e-9);
        CHECK(c->sfs == 2 && c->sfm == 2 && c->sfst == 1.5 && c->sfmt == 1.5 && c->fsf == 2);
        CHECK(d->contact[1].type == FE_KW_CT_S2S && d->contact[1].automatic &&
              d->contact[1].id == 12 && strcmp(d->contact[1].title, "upper on lower") == 0);
        /* cards 2 and 3 left out or blank: the defaults */
        CHECK(d->contact[1].sfs == 1 && d->contact[1].sfst == 1 && d->contact[1].fsf == 1);
        CHECK(d->contact[2].type == FE_KW_CT_S2S && !d->contact[2].automatic &&
              d->contact[2].mstyp == 2 && d->contact[2].msid == 10);
        CHECK(d->contact[3].type == FE_KW_CT_N2S && !d->contact[3].automatic);
        CHECK(d->contact[4].type == FE_KW_CT_N2S && d->contact[4].automatic);
        CHECK(d->contact[5].type == FE_KW_CT_GENERAL && d->contact[5].sstyp == 2);
        CHECK(d->contact[0].loc.line == 27); /* card 1 */
    }
    /* into a model: names, kinds of pass and the friction law */
    fe_builder *b = NULL;
    fe_model *m = NULL;
    if (d) {
        CHECK(fe_builder_create(&b, &err) == MCS_OK);
        st = fe_kw_add_deck(b, d, &err);
        if (st) fprintf(stderr, "%s\n", err.msg);
        CHECK(st == MCS_OK);
        st = st ? st : fe_model_create(b, NULL, &m, &err);
        if (st) fprintf(stderr, "%s\n", err.msg);
        CHECK(st == MCS_OK && m && m->contact && m->contact->nif == 6);
    }
    if (m && m->contact && m->contact->nif == 6) {
        const fe_contact_model *c = m->contact;
        CHECK(strcmp(c->iface[0].name, "self contact") == 0);
        CHECK(strcmp(c->iface[1].name, "upper on lower") == 0);
        CHECK(strcmp(c->iface[2].name, "contact_3") == 0); /* no ID: its number */
        /* mu = FD + (FS - FD) exp(-DC v), FS and FD x FSF 2 (LS-DYNA manual, *CONTACT card 2) */
        CHECK_NEAR(c->iface[0].mu_s, 0.6, 1e-12);
        CHECK_NEAR(c->iface[0].mu_d, 0.4, 1e-12);
        CHECK_NEAR(c->iface[0].decay, 500, 1e-9);
        /* passes: single 1, surface to surface 2 (symmetric), nodes to surface 1 */
        int np[6] = {0};
        for (int i = 0; i < c->npass; i++)
            np[c->pass[i].iface]++;
        CHECK(np[0] == 1 && np[1] == 2 && np[2] == 2 && np[3] == 1 && np[4] == 1 && np[5] == 1);
        CHECK(c->pass[0].self);
    }
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
    free(t);
}

static void expect_fail(const char *tail, int at_build, const char *w1, const char *w2);

/* segment and node set sides (corpus/contact_segment_set.k: a 1 x 1 shell plate, part 1, and a
 * hex block above it, part 2; segment set 3 = the block's bottom face, node set 4 = its four
 * nodes), counted by hand: the surface-to-surface contact has the face's 4 nodes on the plate's
 * 1 shell, then the plate's 4 nodes on that 1 face (of the block's 6 exterior faces); the
 * nodes-to-surface contact the set's 4 nodes on the shell; the single surface the face's 4 nodes
 * on the face itself */
static void test_set_sides(void)
{
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    o.units = "mm-s-t";
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    fe_builder *b = NULL;
    fe_model *m = NULL;
    mcs_status st = fe_kw_read(KD "corpus/contact_segment_set.k", &o, &d, &err);
    if (!st) st = fe_builder_create(&b, &err);
    if (!st) st = fe_kw_add_deck(b, d, &err);
    if (!st) st = fe_model_create(b, NULL, &m, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    CHECK(st == MCS_OK && m && m->contact && m->contact->npass == 4);
    if (m && m->contact && m->contact->npass == 4) {
        const fe_contact_model *c = m->contact;
        int ne[4], ns[4];
        for (int i = 0; i < 4; i++) {
            ne[i] = c->pass[i].ent_end - c->pass[i].ent_begin;
            ns[i] = c->pass[i].seg_end - c->pass[i].seg_begin;
        }
        CHECK(ne[0] == 4 && ns[0] == 1 && ne[1] == 4 && ns[1] == 1); /* two passes */
        CHECK(c->pass[1].reverse && c->seg_solid[c->pass[1].seg_begin] == 1);
        CHECK(ne[2] == 4 && ns[2] == 1 && c->seg_solid[c->pass[2].seg_begin] == 0);
        CHECK(ne[3] == 4 && ns[3] == 1 && c->pass[3].self);
        /* the face kept is the bottom one: its nodes are the block's first four (z = 0.1 mm) */
        const int *q = c->seg_node + 4 * c->pass[1].seg_begin;
        for (int k = 0; k < 4; k++)
            CHECK(fabs(m->node_x0[3 * q[k] + 2] - 1e-4) < 1e-12);
    }
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
    /* a node set is for nodes to surface; a segment must be an element's face */
    expect_fail("*SET_NODE_LIST\n         4\n         5         6\n"
                "*CONTACT_SURFACE_TO_SURFACE\n         4         1         4         3\n",
                1,
                "deck.k:29: error: *CONTACT_SURFACE_TO_SURFACE: the slave side is a node set "
                "(SSTYP 4): node sets are for nodes-to-surface contacts",
                NULL);
    expect_fail("*SET_SEGMENT\n         4\n         1         2         7         8\n"
                "*CONTACT_SURFACE_TO_SURFACE\n         4         1         0         3\n",
                1, "deck.k:26: error: *SET_SEGMENT 4: segment 1 2 7 8 is no face", NULL);
}

/* a deck that fails to read or build: the message holds each of want[] */
static void expect_fail(const char *tail, int at_build, const char *w1, const char *w2)
{
    char *t = plates(tail);
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    mcs_status st = read_text(t, "mm-s-t", &d, &err);
    if (at_build) {
        CHECK(st == MCS_OK);
        fe_builder *b = NULL;
        fe_builder_create(&b, &err);
        st = d && b ? fe_kw_add_deck(b, d, &err) : MCS_ERR_NOMEM;
        fe_builder_destroy(&b);
    }
    CHECK(st != MCS_OK);
    CHECK_STR_CONTAINS(err.msg, w1);
    if (w2) CHECK_STR_CONTAINS(err.msg, w2);
    fe_kw_deck_destroy(&d);
    free(t);
}

/* what the kernel cannot honour: refused with the field or keyword, file and line */
static void test_contact_refusals(void)
{
    /* the plates' head has 24 lines: the tail starts at line 25 */
    expect_fail("*CONTACT_AUTOMATIC_SINGLE_SURFACE\n         0         0         5\n"
                "       0.1       0.1       0.0      20.0\n",
                0, "deck.k:27:31: error: *CONTACT_AUTOMATIC_SINGLE_SURFACE: field VC", NULL);
    expect_fail("*CONTACT_AUTOMATIC_SINGLE_SURFACE\n         0         0         5\n"
                "       0.1       0.1       0.0       0.0     120.0\n",
                0, "deck.k:27:41: error: *CONTACT_AUTOMATIC_SINGLE_SURFACE: field VDC", NULL);
    expect_fail("*CONTACT_AUTOMATIC_SINGLE_SURFACE\n         0         0         5\n\n\n"
                "         1\n",
                0, "deck.k:29:1: error: *CONTACT_AUTOMATIC_SINGLE_SURFACE: field SOFT", NULL);
    expect_fail("*CONTACT_SURFACE_TO_SURFACE\n         1         2         3         3\n"
                "                                                                -0.001\n",
                0, "deck.k:27:61: error: *CONTACT_SURFACE_TO_SURFACE: field BT", NULL);
    expect_fail("*CONTACT_SURFACE_TO_SURFACE\n         1         2         3         3\n"
                "                                                  "
                "               0.002     0.001\n",
                0, "deck.k:27:71: error: *CONTACT_SURFACE_TO_SURFACE: field DT", NULL);
    expect_fail("*CONTACT_SURFACE_TO_SURFACE\n         1         2         3         3         7\n",
                0, "field SBOXID", NULL);
    expect_fail("*CONTACT_SURFACE_TO_SURFACE\n         1         2         3         3\n\n"
                "       1.0       2.0\n",
                0, "field SFS/SFM", NULL);
    expect_fail("*CONTACT_SURFACE_TO_SURFACE\n         1         2         1         3\n", 0,
                "field SSTYP/MSTYP: shell element sets", NULL);
    /* at build: a set that a skipped keyword would have defined is named with it */
    expect_fail("*SET_PART_ADD\n         9\n         1\n"
                "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n         2         9         3         2\n",
                1, "master side: part set 9 is not defined (skipped as not supported: "
                   "*SET_PART_ADD at deck.k:25",
                NULL);
    /* at build: a missing part, friction growing with speed */
    expect_fail("*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n         2         9         3         3\n",
                1,
                "deck.k:26: error: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE: master side: "
                "part 9 has no *PART card",
                NULL);
    expect_fail("*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n         2         1         3         3\n"
                "       0.1       0.3       1.0\n",
                1, "FD 0.3 > FS 0.1", NULL);
}

/* sets: generated lists and segments */
static void test_sets(void)
{
    char *t =
        plates("*SET_NODE_LIST_GENERATE\n         3\n         2         4         7         8\n"
               "*SET_PART_LIST_GENERATE_TITLE\nboth\n         4\n         1         2\n"
               "*SET_SEGMENT\n         5\n         1         2         3         4\n"
               "         5         6         7\n");
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    CHECK(read_text(t, "mm-s-t", &d, &err) == MCS_OK && d);
    if (d) {
        const fe_kw_set *s = fe_kw_find_set(d, 3, 0);
        CHECK(s && s->n == 5 && s->ids[0] == 2 && s->ids[2] == 4 && s->ids[3] == 7 &&
              s->ids[4] == 8);
        s = fe_kw_find_set(d, 4, 1);
        CHECK(s && s->n == 2 && s->ids[0] == 1 && s->ids[1] == 2);
        CHECK(d->nsegset == 1 && d->segset[0].id == 5 && d->segset[0].n == 2);
        CHECK(d->nsegset == 1 && d->segset[0].node[3] == 4 && d->segset[0].node[7] == 7);
    }
    fe_kw_deck_destroy(&d);
    free(t);
    expect_fail("*SET_NODE_LIST_GENERATE\n         3\n         4         2\n", 0,
                "deck.k:27:1: error: *SET_NODE_LIST_GENERATE: field B1BEG/B1END", NULL);
}

/* node velocities, prescribed motions, loads, the end time: what the model holds */
static void test_motion_loads(void)
{
    char *t = plates("*CONTROL_TERMINATION\n     0.002\n"
                     "*INITIAL_VELOCITY_NODE\n         5       0.0       0.0   -1000.0\n"
                     "*DEFINE_CURVE\n         1\n                 0.0              2000.0\n"
                     "                 1.0              2000.0\n"
                     "*DEFINE_CURVE\n         2\n                 0.0                 0.0\n"
                     "                 0.1                 5.0\n"
                     "*DEFINE_CURVE\n         3\n                 0.0                 0.0\n"
                     "                 0.1                 1.0\n"
                     "*SET_NODE_LIST\n         9\n         2         3\n"
                     "*BOUNDARY_PRESCRIBED_MOTION_NODE\n         1         1         0         1"
                     "       0.5\n"
                     "*BOUNDARY_PRESCRIBED_MOTION_SET_ID\n         1set\n         9         3"
                     "         2         2\n"
                     "*LOAD_NODE_POINT\n         8         3         3      -2.0\n");
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    mcs_status st = read_text(t, "mm-s-t", &d, &err);
    CHECK(st == MCS_OK && d);
    CHECK(d && fabs(d->end_time - 0.002) < 1e-15 && d->nnodevel == 1 && d->npmotion == 2 &&
          d->nload == 1);
    fe_builder *b = NULL;
    fe_model *m = NULL;
    if (d) {
        fe_builder_create(&b, &err);
        st = fe_kw_add_deck(b, d, &err);
        if (!st) st = fe_model_create(b, NULL, &m, &err);
        if (st) fprintf(stderr, "%s\n", err.msg);
        CHECK(st == MCS_OK && m);
    }
    if (m) { /* builder node = deck node - 1 (nodes in ascending ID order) */
        CHECK_NEAR(m->node_v0[3 * 4 + 2], -1.0, 1e-12); /* -1000 mm/s */
        CHECK_NEAR(m->node_v0[3 * 5 + 2], 0.0, 1e-12);
        /* VAD 0, constant 2000 mm/s x SF 0.5 = 1 m/s along x on node 1 */
        CHECK(m->node_fix[0] == FE_DOF_X && fabs(m->node_vfix[0] - 1.0) < 1e-12);
        /* VAD 2, d = 5 mm / 0.1 s t: 0.05 m/s along z on nodes 2 and 3 */
        CHECK(m->node_fix[1] == FE_DOF_Z && fabs(m->node_vfix[3 * 1 + 2] - 0.05) < 1e-12);
        CHECK(m->node_fix[2] == FE_DOF_Z && fabs(m->node_vfix[3 * 2 + 2] - 0.05) < 1e-12);
        CHECK(m->node_fix[3] == 0);
        /* LOAD_NODE_POINT: SF -2 N along z on node 8, curve 3 (t [s], scale) */
        CHECK(m->nnodal_load == 1 && m->nodal_load[0].node == 7);
        CHECK(m->nnodal_load == 1 && fabs(m->nodal_load[0].force[2] + 2.0) < 1e-12);
        CHECK(m->nload == 1 && m->load_curve[0].ncurve == 2 &&
              m->load_curve[0].curve[1][0] == 0.1 && m->load_curve[0].curve[1][1] == 1.0);
    }
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
    free(t);
    /* refusals */
    expect_fail("*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
                "                 1.0               100.0\n"
                "*BOUNDARY_PRESCRIBED_MOTION_NODE\n         1         1         0         1\n",
                1,
                "deck.k:30: error: *BOUNDARY_PRESCRIBED_MOTION_NODE: curve 1: a motion that "
                "varies in time is not built",
                NULL);
    expect_fail("*BOUNDARY_PRESCRIBED_MOTION_NODE\n         1         1         1         1\n", 0,
                "deck.k:26:21: error: *BOUNDARY_PRESCRIBED_MOTION_NODE: field VAD", NULL);
    expect_fail("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         1         1         0         1"
                "       1.0         0       0.5\n",
                0, "field BIRTH/DEATH", NULL);
    expect_fail("*DEFINE_CURVE\n         1\n                 0.0                 1.0\n"
                "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         1         1         0         1\n",
                1, "part 1 is not rigid", NULL);
    expect_fail("*INITIAL_VELOCITY_NODE\n         5       0.0       0.0       0.0       1.0\n", 1,
                "rotational velocity", NULL);
}

/* the first segment stiffness of a plates deck with `tail`, or NAN */
static double seg_k0(const char *tail)
{
    char *t = plates(tail);
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    fe_builder *b = NULL;
    fe_model *m = NULL;
    mcs_status st = read_text(t, "mm-s-t", &d, &err);
    if (!st) st = fe_builder_create(&b, &err);
    if (!st) st = fe_kw_add_deck(b, d, &err);
    if (!st) st = fe_model_create(b, NULL, &m, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    double k = m && m->contact && m->contact->nseg > 0 ? m->contact->seg_k[0] : NAN;
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
    free(t);
    return k;
}

/* the _MPP option in both orders (its cards read over, the '&' second card too) and
 * *CONTROL_CONTACT: SLSFAC scales every contact's penalty (LS-DYNA: k = SLSFAC x SFS x ...), so
 * 0.05 halves the default 0.1's stiffness; RWPNAL > 0 with a rigid wall refused */
static void test_mpp_control_contact(void)
{
    static const char mpp[] = "*CONTACT_AUTOMATIC_SINGLE_SURFACE_MPP_ID\n"
                              "         7single\n"
                              "         1       200         0         3         2    1.0005\n"
                              "&                  0       1.0\n"
                              "         0         0         5\n"
                              "       0.2\n"
                              "*CONTACT_SURFACE_TO_SURFACE_ID_MPP\n"
                              "         8\n"
                              "         0\n"
                              "         2         1         3         3\n";
    char *t = plates(mpp);
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    mcs_status st = read_text(t, "mm-s-t", &d, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    CHECK(st == MCS_OK && d && d->ncontact == 2);
    if (d && d->ncontact == 2) {
        CHECK(d->contact[0].id == 7 && strcmp(d->contact[0].title, "single") == 0);
        CHECK(d->contact[0].type == FE_KW_CT_SINGLE && d->contact[0].sstyp == 5);
        CHECK(d->contact[0].fs == 0.2 && d->contact[0].loc.line == 29);
        CHECK(d->contact[1].id == 8 && d->contact[1].type == FE_KW_CT_S2S &&
              !d->contact[1].automatic && d->contact[1].ssid == 2 && d->contact[1].msid == 1);
    }
    fe_kw_deck_destroy(&d);
    free(t);
    const char *c1 =
        "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n         2         1         3         3\n";
    char tail[512];
    snprintf(tail, sizeof tail, "*CONTROL_CONTACT\n      0.05       0.0         0         1\n%s",
             c1);
    double k1 = seg_k0(c1), k2 = seg_k0(tail);
    CHECK(isfinite(k1) && isfinite(k2));
    CHECK_NEAR(k2 / k1, 0.5, 1e-12);
    expect_fail("*CONTROL_CONTACT\n       0.1       1.0\n*RIGIDWALL_PLANAR\n\n"
                "       0.0       0.0      -1.0       0.0       0.0       0.0\n",
                1, "deck.k:26: error: *CONTROL_CONTACT: RWPNAL 1 asks penalty rigid walls", NULL);
}

/* the z velocity of the lower plate's node 1 after t_end of a plates deck with `tail` */
static double plate_vz(const char *tail, double t_end, double *work, double *tv)
{
    char *t = plates(tail);
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    fe_builder *b = NULL;
    fe_model *m = NULL;
    fe_state *s = NULL;
    mcs_status st = read_text(t, "mm-s-t", &d, &err);
    if (!st) st = fe_builder_create(&b, &err);
    if (!st) st = fe_kw_add_deck(b, d, &err);
    if (!st) st = fe_model_create(b, NULL, &m, &err);
    if (!st) st = fe_state_create(m, &s, &err);
    if (!st) st = fe_run(m, s, t_end);
    if (st) fprintf(stderr, "%s\n", err.msg);
    double vz = !st ? s->node_v[2] : NAN;
    if (work) *work = !st ? s->work_ext : NAN;
    if (tv) *tv = !st ? s->time - 0.5 * s->dt_prev : NAN; /* velocities are at half steps */
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
    free(t);
    return vz;
}

/* *LOAD_SEGMENT as a pressure on the free 1 x 1 mm lower plate (h 0.5 mm, rho 7800): p = 1 MPa
 * against the normal of N1..N4 (+z counter-clockwise, LS-DYNA's rule), so the plate translates:
 * v_z(t) = -p t / (rho h) (Newton's second law on the whole plate; it stays flat under the
 * equal node shares); the nodes given clockwise push the other way; external work
 * = (p A t)^2 / (2 m) */
static void test_load_segment(void)
{
    static const char ccw[] =
        "*DEFINE_CURVE\n         1\n                 0.0                 1.0\n"
        "*LOAD_SEGMENT\n         1       1.0       0.0         1         2"
        "         3         4\n";
    static const char cw[] = "*DEFINE_CURVE\n         1\n                 0.0                 1.0\n"
                             "*LOAD_SEGMENT\n         1       1.0       0.0         1         4"
                             "         3         2\n";
    const double p = 1e6, rho = 7800, h = 0.5e-3, A = 1e-6, t = 2e-5;
    double w = 0, tv = 0, vz = plate_vz(ccw, t, &w, &tv), v = -p * tv / (rho * h);
    CHECK_NEAR(vz, v, 1e-9 * fabs(v));
    CHECK_NEAR(plate_vz(cw, t, NULL, &tv), p * tv / (rho * h), 1e-9 * fabs(v));
    /* the work of the pressure = the kinetic energy; the velocities lag half a step (dt / t
     * = 0.6 %), the work is summed over whole steps: equal to 1 % */
    const double m = rho * h * A;
    CHECK_NEAR(w, 0.5 * m * vz * vz, 0.01 * 0.5 * m * vz * vz);
    printf("load segment: v_z %.9g m/s (p t / rho h: %.9g), work %.4g J of m v^2 / 2 %.4g J\n", vz,
           v, w, 0.5 * m * vz * vz);
    expect_fail("*DEFINE_CURVE\n         1\n                 0.0                 1.0\n"
                "*LOAD_SEGMENT\n         1       1.0      0.01         1         2         3\n",
                1, "deck.k:29: error: *LOAD_SEGMENT: field AT", NULL);
}

/* the writer: contacts, segment sets, node velocities, motions, loads and the end time read
 * back as written (fe_kw_write, the corpus decks, in each format) */
static void round_trip(const char *file)
{
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    o.units = "mm-s-t";
    fe_kw_deck *a = NULL, *b = NULL;
    mcs_error err = {0};
    char out[128];
    snprintf(out, sizeof out, "%s/rt.k", tmpdir);
    CHECK(fe_kw_read(file, &o, &a, &err) == MCS_OK);
    for (int f = 0; f < 3 && a; f++) {
        CHECK(fe_kw_write(a, out, (fe_kw_format)f, &err) == MCS_OK);
        mcs_status st = fe_kw_read(out, &o, &b, &err);
        if (st) fprintf(stderr, "%s\n", err.msg);
        CHECK(st == MCS_OK && b);
        if (!b) continue;
        CHECK(b->ncontact == a->ncontact && b->nsegset == a->nsegset && b->nload == a->nload);
        CHECK(b->nnodevel == a->nnodevel && b->npmotion == a->npmotion);
        CHECK(b->end_time == a->end_time && b->slsfac == a->slsfac && b->shlthk == a->shlthk);
        for (int i = 0; i < a->ncontact && b->ncontact == a->ncontact; i++) {
            const fe_kw_contact *x = &a->contact[i], *y = &b->contact[i];
            CHECK(x->type == y->type && x->automatic == y->automatic && x->id == y->id);
            CHECK(strcmp(x->title, y->title) == 0 && x->ssid == y->ssid && x->msid == y->msid);
            CHECK(x->sstyp == y->sstyp && x->mstyp == y->mstyp && x->fs == y->fs);
            CHECK(x->fd == y->fd && x->dc == y->dc && x->sfs == y->sfs && x->sfst == y->sfst);
        }
        for (int i = 0; i < a->nsegset && b->nsegset == a->nsegset; i++)
            CHECK(b->segset[i].n == a->segset[i].n &&
                  memcmp(b->segset[i].node, a->segset[i].node, 16 * (size_t)a->segset[i].n) == 0);
        for (int i = 0; i < a->nnodevel && b->nnodevel == a->nnodevel; i++)
            CHECK(b->nodevel[i].nid == a->nodevel[i].nid &&
                  b->nodevel[i].v[2] == a->nodevel[i].v[2]);
        for (int i = 0; i < a->npmotion && b->npmotion == a->npmotion; i++)
            CHECK(memcmp(&b->pmotion[i].on, &a->pmotion[i].on, sizeof(fe_kw_target)) == 0 &&
                  b->pmotion[i].id == a->pmotion[i].id && b->pmotion[i].sf == a->pmotion[i].sf);
        for (int i = 0; i < a->nload && b->nload == a->nload; i++)
            CHECK(b->load[i].nid == a->load[i].nid && b->load[i].sf == a->load[i].sf &&
                  b->load[i].dof == a->load[i].dof);
        fe_kw_deck_destroy(&b);
    }
    fe_kw_deck_destroy(&a);
}

static void test_write_round_trip(void)
{
    round_trip(KD "corpus/contact_plates.k");
    round_trip(KD "corpus/contact_segment_set.k");
    round_trip(KD "corpus/contact_mpp.k");
}

/* the whole deck through `mcrash run`: two equal steel bars (L 10 mm, 2 x 2 mm, E 210 GPa,
 * nu 0, rho 7850), the striker at v0 = 10 m/s (*INITIAL_VELOCITY_NODE) into the target at rest
 * across a 10 um gap, *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, end time 30 us from
 * *CONTROL_TERMINATION. 1-D impact theory (Goldsmith, Impact, 1960, sec. 4.2; Graff, Wave
 * Motion in Elastic Solids, 1975, sec. 2.1.3): equal bars exchange their velocities (the
 * striker stops, the target leaves at v0) once the 2L/c = 3.9 us contact ends; momentum
 * m v0 and energy m v0^2 / 2 = 15.7 mJ are conserved. The penalty contact is a spring of
 * finite stiffness, so the exchange is nearly, not exactly, complete. */
static void test_whole_deck_run(void)
{
    char out[128], args[512];
    snprintf(out, sizeof out, "%s/tb.h5", tmpdir);
    snprintf(args, sizeof args, "run " KD "two_bars.yaml -o %s --quiet --json", out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    CHECK_STR_CONTAINS(r->out, "\"elements\": 10");
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    const double v0 = 10, m = 7850 * 10e-3 * 2e-3 * 2e-3, e0 = 0.5 * m * v0 * v0;
    double vs = NAN, vt = NAN; /* x of the last rows (n x 3) */
    mcs_array a = {0};
    if (rd(h, "/stage3/parts/striker/motion/velocity", &a) && a.n >= 3) vs = a.v[a.n - 3];
    mcs_array_free(&a);
    if (rd(h, "/stage3/parts/target/motion/velocity", &a) && a.n >= 3) vt = a.v[a.n - 3];
    mcs_array_free(&a);
    double tend = NAN, etot = last_of(h, "/stage3/energy/total");
    const char *te = strstr(r->out, "\"end_time_s\": ");
    if (te) tend = atof(te + 14);
    /* momentum: the contact forces are equal and opposite */
    CHECK_NEAR(vs + vt, v0, 1e-6 * v0);
    /* velocity exchange (1-D theory: 100 %) */
    double ex = 100 * vt / v0;
    FIG("kw.two_bars_exchange_pct", "%.1f", ex);
    CHECK(ex > 99 && ex <= 100); /* 99.5 % */
    CHECK(fabs(vs) < 0.01 * v0);
    /* energy */
    double drift = 100 * (etot - e0) / e0;
    FIG_TOL("kw.two_bars_energy_drift_pct", "%.1f", drift, 0.1);
    CHECK(fabs(drift) < 0.5);
    /* the end time of the deck: 30 us (the run ends on the step that reaches it, dt 0.35 us) */
    CHECK(tend >= 30e-6 && tend < 30.4e-6);
    mcs_results_close(&h);
}

/* a rigid plate (*MAT_RIGID) driven by *BOUNDARY_PRESCRIBED_MOTION_RIGID (VAD 0, a constant
 * 5000 mm/s curve) against a steel bar (L 20 mm, 2 x 2 mm, E 210 GPa, nu 0, rho 7850) fixed at
 * its far end, through *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, for 7 us (< 2L/c = 7.7 us: the
 * wave has not come back). The plate moves as prescribed: x(t) = x0 + v t. 1-D wave theory
 * (Graff 1975, sec. 2.1.3): a rigid face driven at v into an elastic bar pushes with
 * rho c A v = 812 N until the reflection returns; the penalty spring in series only delays
 * the rise, so the force stays between 0 and that. */
static void test_rigid_push_run(void)
{
    char out[128], args[512];
    snprintf(out, sizeof out, "%s/rp.h5", tmpdir);
    snprintf(args, sizeof args, "run " KD "rigid_push.yaml -o %s --quiet", out);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    if (r->status) fprintf(stderr, "%s\n", r->err);
    mcs_results *h = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, out, &err) == MCS_OK);
    if (!h) return;
    mcs_array x = {0}, t = {0}, f = {0}, vel = {0};
    CHECK(rd(h, "/stage3/bodies/plate/position", &x) && rd(h, "/stage3/time", &t));
    CHECK(rd(h, "/stage3/bodies/plate/velocity", &vel));
    CHECK(rd(h, "/stage3/contact/plate on bar/force", &f));
    const double v = 5, x0 = -0.501e-3, Fmax = 7850 * sqrt(210e9 / 7850) * 4e-6 * v;
    size_t n = t.n;
    CHECK(n > 10 && x.n == 3 * n && f.n == 3 * n);
    CHECK(vel.n == 3 * n);
    double dx = 0, dv = 0, fpeak = 0, flow = 0;
    for (size_t i = 0; i < n && x.n == 3 * n && f.n == 3 * n; i++) {
        dx = fmax(dx, fabs(x.v[3 * i] - (x0 + v * t.v[i])));
        /* the prescribed velocity, reported as given (not V - h/2 F/M with the contact's
         * reaction in F: 5 -> 7.3 m/s before) */
        if (vel.n == 3 * n) dv = fmax(dv, fabs(vel.v[3 * i] - v));
        fpeak = fmax(fpeak, -f.v[3 * i]); /* on the slave side (the plate): along -x */
        flow = fmin(flow, -f.v[3 * i]);
    }
    CHECK(dx < 1e-12); /* [m], of 35 um travelled */
    CHECK(dv < 1e-9);  /* [m/s], of 5 */
    CHECK(fpeak > 0.3 * Fmax && fpeak <= 1.02 * Fmax && flow >= 0);
    printf("rigid push: plate off x0 + v t by %.2g m, velocity off v by %.2g m/s, peak force "
           "%.0f N of rho c A v %.0f N\n",
           dx, dv, fpeak, Fmax);
    mcs_array_free(&x), mcs_array_free(&t), mcs_array_free(&f), mcs_array_free(&vel);
    mcs_results_close(&h);
}

/* the whole-deck form's rules: end_time left out needs a deck with ENDTIM; simulation.end_time
 * wins over it; without fe.keyword end_time is required */
static void test_whole_deck_rules(void)
{
    char yaml[256], args[512], deck[256];
    snprintf(deck, sizeof deck, "%s/noterm.k", tmpdir);
    char *t = plates("");
    write_text(deck, t);
    free(t);
    snprintf(yaml, sizeof yaml, "%s/noterm.yaml", tmpdir);
    write_text(yaml, "mcrash: 1\nsimulation: {output_rate: 1 MHz}\n"
                     "fe: {keyword: noterm.k, units: mm-s-t}\n");
    snprintf(args, sizeof args, "run %s -o %s/n.h5 --quiet", yaml, tmpdir);
    cli_result *r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "noterm.yaml:3:15: error: fe.keyword:");
    CHECK_STR_CONTAINS(r->err, "no *CONTROL_TERMINATION with ENDTIM > 0");
    /* simulation.end_time given: it is the end */
    write_text(yaml, "mcrash: 1\nsimulation: {end_time: 2 us, output_rate: 1 MHz}\n"
                     "fe: {keyword: noterm.k, units: mm-s-t}\n");
    snprintf(args, sizeof args, "run %s -o %s/n.h5 --quiet --json", yaml, tmpdir);
    r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"elements\": 2");
    /* no fe.keyword: end_time is required */
    write_text(yaml, "mcrash: 1\nsimulation: {output_rate: 1 MHz}\nfe:\n  parts:\n"
                     "    - name: p\n      mesh: {keyword: noterm.k, part: 1, units: mm-s-t}\n");
    snprintf(args, sizeof args, "check %s", yaml);
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "noterm.yaml:2:13: error: end_time: required key is missing");
    /* units without a whole deck */
    write_text(yaml, "mcrash: 1\nsimulation: {end_time: 1 us}\nfe:\n  units: mm-s-t\n  parts:\n"
                     "    - name: p\n      mesh: {keyword: noterm.k, part: 1, units: mm-s-t}\n");
    r = cli_run(args);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "fe.units: belongs to a whole keyword deck");
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_kwc_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_contact_cards);
    RUN(test_contact_refusals);
    RUN(test_sets);
    RUN(test_set_sides);
    RUN(test_write_round_trip);
    RUN(test_mpp_control_contact);
    RUN(test_load_segment);
    RUN(test_motion_loads);
    RUN(test_whole_deck_run);
    RUN(test_rigid_push_run);
    RUN(test_whole_deck_rules);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd)) return 1;
    TEST_END();
}

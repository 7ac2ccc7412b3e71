/* test_kw_joint: the joint and constraint keywords (fe/keyword/fe_kw_cards_joint.c,
 * fe/keyword/fe_kw_build_joint.c, fe/keyword/fe_kw_joint_model.c; docs/keyword.md): a deck with
 * a revolute joint by node pairs, its generalized stiffness (curves and stops, in mm-ms-kg), extra nodes
 * and a nodal rigid body read into the kernel's joint; the writer's round trip of a model with
 * joints to the ground (the same motion, step by step); bad cards at FILE:LINE(:COL). */
#include "fe/fe_joint.h"
#include "fe/fe_keyword.h"
#include "fe/fe_solid.h"
#include "fe/fe_state.h"
#include "tests/harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static fe_kw_deck *read_mem(const char *text, const char *units, mcs_error *err)
{
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    o.units = units;
    fe_kw_deck *d = NULL;
    if (fe_kw_read_mem("j.k", text, strlen(text), &o, &d, err)) return NULL;
    return d;
}

static fe_model *deck_model(const fe_kw_deck *d, double dt, mcs_error *err)
{
    fe_builder *b = NULL;
    fe_model *m = NULL;
    fe_opts o = fe_opts_default();
    o.dt_max = dt;
    if (fe_builder_create(&b, err) == MCS_OK && fe_kw_add_deck(b, d, err) == MCS_OK)
        fe_model_create(b, &o, &m, err);
    fe_builder_destroy(&b);
    return m;
}

/* cubes A (nodes 1-8, x 0..1), B (9-16, x 1..2), C (21-28, x 3..4, elastic); joint nodes
 * 17, 19 on A (extra nodes) and 18, 20 on B at x = 1, z = 0.5, y = 0.5 and 1.5 (axis y) */
static const char *const deck_base =
    "*KEYWORD\n*NODE\n"
    "1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "9,1,0,0\n10,2,0,0\n11,2,1,0\n12,1,1,0\n13,1,0,1\n14,2,0,1\n15,2,1,1\n16,1,1,1\n"
    "17,1,0.5,0.5\n18,1,0.5,0.5\n19,1,1.5,0.5\n20,1,1.5,0.5\n"
    "21,3,0,0\n22,4,0,0\n23,4,1,0\n24,3,1,0\n25,3,0,1\n26,4,0,1\n27,4,1,1\n28,3,1,1\n"
    "*PART\npartA\n1,1,1\n*PART\npartB\n2,1,1\n*PART\npartC\n3,1,2\n"
    "*SECTION_SOLID\n1\n*MAT_RIGID\n1,1000,1000,0.3\n\n\n*MAT_ELASTIC\n2,1000,1,0.3\n"
    "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n2,2,9,10,11,12,13,14,15,16\n"
    "3,3,21,22,23,24,25,26,27,28\n"
    "*CONSTRAINED_EXTRA_NODES_NODE\n1,17\n1,19\n2,18\n2,20\n"
    "*SET_NODE_LIST\n99\n21,22,23,24,25,26,27,28\n";

static char *deck_text(const char *joint, int nrb)
{
    static char buf[4096];
    snprintf(buf, sizeof buf,
             "%s*CONSTRAINED_JOINT_REVOLUTE_ID\n         7hinge\n%s\n%s"
             "*DEFINE_CURVE\n5\n0,0\n1,200\n*DEFINE_CURVE\n6\n0,0\n2,6\n"
             "*CONSTRAINED_JOINT_STIFFNESS_GENERALIZED\n1,1,2,0,0,7\n5,0,0,6,0,0\n"
             "0,0,0,0,0,0\n-30,45,0,0,0,0\n*END\n",
             deck_base, joint, nrb ? "*CONSTRAINED_NODAL_RIGID_BODY\n50,0,99\n" : "");
    return buf;
}

/* the deck read: joint 'hinge' between partA and partB about y at (1, .5, .5) (in mm), the
 * stiffness the curves' slopes in the deck's units (mm-ms-kg: a moment of kg mm^2/ms^2 is
 * 1 N m; damping kg mm^2/ms per rad 1e-3 N m s), stops -30 and 45 degrees; the nodal rigid
 * body nrb_50 of partC's 8 nodes (1 mm^3 of 1000 kg/mm^3) */
static void test_read_revolute_deck(void)
{
    mcs_error err = {0};
    fe_kw_deck *d = read_mem(deck_text("17,18,19,20", 1), "mm-ms-kg", &err);
    CHECK(d != NULL);
    if (!d) {
        printf("  %s\n", err.msg);
        return;
    }
    CHECK(d->njoint == 1 && d->nnrb == 5 && d->njstiff == 1);
    fe_model *m = deck_model(d, 1e-4, &err);
    CHECK(m != NULL);
    if (!m) {
        printf("  %s\n", err.msg);
        fe_kw_deck_destroy(&d);
        return;
    }
    CHECK(m->njoint == 1 && m->nbody == 3);
    const fe_joint *J = &m->joint[0];
    CHECK(strcmp(J->name, "hinge") == 0 && J->type == FE_JOINT_REVOLUTE);
    CHECK(J->body[0] == fe_body_find(m, "partA") && J->body[1] == fe_body_find(m, "partB"));
    CHECK(fabs(J->axis[1] - 1) < 1e-12);
    CHECK_NEAR(m->body[J->body[0]].x0[0] + J->r[0][0], 1e-3, 1e-15);
    CHECK_REL(J->ks, 200, 1e-12);
    CHECK_REL(J->cs, 3e-3, 1e-12);
    CHECK(J->has_range);
    CHECK_REL(J->range[0], -M_PI / 6, 1e-12);
    CHECK_REL(J->range[1], M_PI / 4, 1e-12);
    int nb = fe_body_find(m, "nrb_50");
    CHECK(nb >= 0);
    if (nb >= 0) CHECK_REL(m->body[nb].mass, 1000, 1e-12);
    fe_model_destroy(&m);
    fe_kw_deck_destroy(&d);
}

/* a rigid pendulum hanging from the ground by a revolute joint (stiffness, damping, stops)
 * and a second one of elastic hexes made a nodal rigid body, hanging from a translational
 * joint with a spring: written (fe_kw_from_model, fe_kw_write) and read back, the model moves
 * as the original to round-off */
static void test_round_trip(void)
{
    mcs_error err = {0};
    fe_kw_deck *d0 = read_mem(deck_text("17,18,19,20", 1), NULL, &err);
    fe_builder *bl = NULL;
    fe_model *m0 = NULL;
    fe_joint_desc jd = fe_joint_desc_default();
    snprintf(jd.name, sizeof jd.name, "slider");
    jd.type = FE_JOINT_TRANSLATIONAL;
    snprintf(jd.body[0], sizeof jd.body[0], "nrb_50");
    jd.point[0] = 3.5, jd.point[1] = 0.5, jd.point[2] = 0.5, jd.stiffness = 2e4;
    jd.axis[0] = 1, jd.axis[1] = 0, jd.axis[2] = 1;
    fe_opts op = fe_opts_default();
    op.dt_max = 1e-4;
    if (d0 && fe_builder_create(&bl, &err) == MCS_OK && fe_kw_add_deck(bl, d0, &err) == MCS_OK &&
        fe_builder_add_joint(bl, &jd, &err) == MCS_OK)
        fe_model_create(bl, &op, &m0, &err);
    fe_builder_destroy(&bl);
    CHECK(m0 != NULL);
    if (!m0) printf("  %s\n", err.msg);
    fe_kw_deck_destroy(&d0);
    if (!m0) return;
    fe_kw_deck *w = NULL;
    CHECK(fe_kw_from_model(m0, NULL, "round trip", &w, &err) == MCS_OK);
    char path[64];
    snprintf(path, sizeof path, "/tmp/mcrash_kwj_%d.k", (int)getpid());
    CHECK(w && fe_kw_write(w, path, FE_KW_FIXED_I10, &err) == MCS_OK);
    fe_kw_deck_destroy(&w);
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    fe_kw_deck *d1 = NULL;
    CHECK(fe_kw_read(path, &o, &d1, &err) == MCS_OK);
    fe_model *m1 = d1 ? deck_model(d1, 1e-4, &err) : NULL;
    CHECK(m1 != NULL);
    if (!m1) printf("  %s\n", err.msg);
    remove(path);
    fe_kw_deck_destroy(&d1);
    if (!m1) {
        fe_model_destroy(&m0);
        return;
    }
    CHECK(m1->njoint == 2 && m1->nbody == 3);
    for (int j = 0; j < 2 && m1->njoint == 2; j++) {
        const fe_joint *a = &m0->joint[j], *b = &m1->joint[j];
        CHECK(strcmp(a->name, b->name) == 0 && a->type == b->type);
        CHECK(a->body[1] == b->body[1]);
        CHECK_REL(b->k, a->k, 1e-12);
        CHECK_REL(b->kr, a->kr, 1e-12);
        CHECK_NEAR(b->ks, a->ks, 1e-12 * a->ks);
        CHECK_NEAR(b->cs, a->cs, 1e-12 * a->cs);
        CHECK_NEAR(b->range[0], a->range[0], 1e-9);
        CHECK_NEAR(b->range[1], a->range[1], 1e-9);
    }
    for (int k = 0; k < 3; k++)
        CHECK_REL(m1->body[k].mass, m0->body[k].mass, 1e-12);
    /* B turning about the hinge, the nodal rigid body sliding: both models step alike */
    fe_model *ms[2] = {m0, m1};
    fe_state *s[2] = {NULL, NULL};
    for (int i = 0; i < 2; i++) {
        fe_model *m = ms[i];
        for (int n = 0; n < m->nnode; n++) {
            if (m->node_body[n] == fe_body_find(m, "partB")) /* 2 rad/s about the hinge */
                m->node_v0[3 * n + 2] = -2 * (m->node_x0[3 * n] - 1);
            if (m->node_body[n] == 2) m->node_v0[3 * n + 0] = m->node_v0[3 * n + 2] = 0.5;
        }
        CHECK(fe_state_create(m, &s[i], &err) == MCS_OK);
        for (int k = 0; k < 500 && s[i]; k++)
            fe_step(m, s[i]);
    }
    if (s[0] && s[1]) {
        double dx = 0;
        for (int k = 0; k < 9; k++)
            dx = fmax(dx, fabs(s[0]->body_x[k] - s[1]->body_x[k]));
        printf("  round trip: bodies apart by %.1e m after 500 steps; hinge at %.4f rad, slider "
               "at %.4f m\n",
               dx, s[0]->joint_out[FE_JOUT_ANGLE], s[0]->joint_out[FE_JOUT_N + FE_JOUT_SLIDE]);
        CHECK(dx < 1e-12);                                  /* round-off of the written reals */
        CHECK(fabs(s[0]->joint_out[FE_JOUT_ANGLE]) > 1e-3); /* it turned */
        CHECK(fabs(s[0]->joint_out[FE_JOUT_N + FE_JOUT_SLIDE]) > 1e-3); /* it slid */
    }
    fe_state_destroy(&s[0]), fe_state_destroy(&s[1]);
    fe_model_destroy(&m0), fe_model_destroy(&m1);
}

/* N3 blank, N4 undefined, N2 on a deformable part, an unknown JID: exit 2 at the card */
static void test_bad_cards(void)
{
    const char *joint[3] = {"17,18,,20", "17,18,19,77", "17,21,19,20"};
    const char *want[3] = {"j.k:62: error: *CONSTRAINED_JOINT_REVOLUTE: field N3: this joint "
                           "needs N1..N4, got 0",
                           "j.k:62: error: *CONSTRAINED_JOINT_REVOLUTE 7: N4: node 77 is not "
                           "defined",
                           "j.k:62: fe: joint 'hinge': node N2 is on no rigid part"};
    for (int k = 0; k < 3; k++) {
        mcs_error err = {0};
        fe_kw_deck *d = read_mem(deck_text(joint[k], 0), NULL, &err);
        fe_model *m = d ? deck_model(d, 1e-4, &err) : NULL;
        CHECK(m == NULL);
        CHECK(err.status == MCS_ERR_FORMAT || err.status == MCS_ERR_RANGE);
        CHECK_STR_CONTAINS(err.msg, want[k]);
        fe_model_destroy(&m);
        fe_kw_deck_destroy(&d);
    }
    mcs_error err = {0};
    char text[4096];
    snprintf(text, sizeof text, "%s", deck_text("17,18,19,20", 0));
    char *p = strstr(text, "1,1,2,0,0,7");
    if (p) p[10] = '8';
    fe_kw_deck *d = read_mem(text, NULL, &err);
    fe_model *m = d ? deck_model(d, 1e-4, &err) : NULL;
    CHECK(m == NULL);
    CHECK_STR_CONTAINS(err.msg, "joint JID 8 is not defined");
    fe_kw_deck_destroy(&d);
}

int main(void)
{
    RUN(test_read_revolute_deck);
    RUN(test_round_trip);
    RUN(test_bad_cards);
    TEST_END();
}

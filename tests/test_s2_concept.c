/* test_s2_concept: the concept 413 case's stage-2 scenario
 * (scenarios/iso13232_413-0_13.4_sedan_rider_concept_stage2.yaml) against its stage-1 scenario:
 * - one restraint definition: both resolve every retractor and airbag to the same lines of
 *   models/motorcycles/sport_208kg_concept.yaml with the same parameters (no copy);
 * - stage 2 compiled (stage2_fe/s2_scenario.h) adds the tank pads to the restraints and keeps
 *   everything else; its model builds, the pads' inner faces are carried by moto_frame and
 *   their outer faces clear the seated rider's thighs at t = 0 (distance from the thigh
 *   ellipsoid, computed here from the built model's seated poses). */
#include "core/mcs_scenario.h"
#include "fe/fe_model.h"
#include "stage1_mb/mb_couple.h"
#include "stage2_fe/s2_scenario.h"
#include "tests/harness.h"
#include "tests/mb_test_util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define S1 "scenarios/iso13232_413-0_13.4_sedan_rider_concept.yaml"
#define S2 "scenarios/iso13232_413-0_13.4_sedan_rider_concept_stage2.yaml"

static mcs_scenario *load(const char *path)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    if (mcs_scenario_load(path, &scn, &err)) fprintf(stderr, "%s\n", err.msg);
    CHECK(scn != NULL);
    return scn;
}

/* the two nodes are the same scenario text: same kind, file, line, column and value, all the
 * way down (a copy would sit on other lines or in another file) */
static int same_source(const mcs_node *a, const mcs_node *b)
{
    if (mcs_node_kind(a) != mcs_node_kind(b) || mcs_node_line(a) != mcs_node_line(b) ||
        mcs_node_col(a) != mcs_node_col(b) || mcs_node_len(a) != mcs_node_len(b))
        return 0;
    if (strcmp(mcs_node_file(a), mcs_node_file(b)) != 0) return 0;
    if (mcs_node_kind(a) == MCS_NODE_NUM && !(mcs_node_num(a) == mcs_node_num(b))) return 0;
    for (int i = 0; i < mcs_node_len(a); i++)
        if (!same_source(mcs_node_at(a, i), mcs_node_at(b, i))) return 0;
    return 1;
}

static void test_restraints_shared(void)
{
    mcs_scenario *s1 = load(S1), *s2 = load(S2), *c2 = NULL;
    mcs_error err = {0};
    if (s2) CHECK(s2_scenario_compile(s2, &c2, &err) == MCS_OK);
    if (!s1 || !c2) goto done;
    const mcs_node *fe1 = mcs_node_get(mcs_scenario_root(s1), "fe");
    const mcs_node *fe2 = mcs_node_get(mcs_scenario_root(c2), "fe");
    const char *lists[] = {"retractors", "airbags"};
    for (int l = 0; l < 2; l++) {
        const mcs_node *a = mcs_node_get(fe1, lists[l]), *b = mcs_node_get(fe2, lists[l]);
        CHECK(mcs_node_len(a) >= 1 && mcs_node_len(a) == mcs_node_len(b));
        for (int i = 0; i < mcs_node_len(a); i++) {
            CHECK(same_source(mcs_node_at(a, i), mcs_node_at(b, i)));
            CHECK(strstr(mcs_node_file(mcs_node_at(b, i)),
                         "models/motorcycles/sport_208kg_concept.yaml") != NULL);
        }
    }
    /* the retractor parameters themselves (model file: 2 kN limiter, 100 mm in 15 ms, fired
     * 12 ms after front_tyre_car) */
    const mcs_node *r = mcs_node_at(mcs_node_get(fe2, "retractors"), 0);
    CHECK_NEAR(mcs_node_num(mcs_node_get(r, "load_limit")), 2000, 1e-9);
    CHECK_NEAR(mcs_node_num(mcs_node_get(mcs_node_get(r, "trigger"), "delay")), 0.012, 1e-15);
    CHECK(strcmp(mcs_node_str(mcs_node_get(mcs_node_get(r, "trigger"), "contact")),
                 "front_tyre_car") == 0);
    /* the parts: stage 1's, then the pads; the fe: contacts likewise */
    const mcs_node *p1 = mcs_node_get(fe1, "parts"), *p2 = mcs_node_get(fe2, "parts");
    CHECK(mcs_node_len(p2) == mcs_node_len(p1) + 2);
    for (int i = 0; i < mcs_node_len(p1); i++)
        CHECK(same_source(mcs_node_at(p1, i), mcs_node_at(p2, i)));
    CHECK(strcmp(mcs_node_str(mcs_node_get(mcs_node_at(p2, mcs_node_len(p1)), "name")),
                 "pad_tank_l") == 0);
    CHECK(mcs_node_len(mcs_node_get(fe2, "contacts")) ==
          mcs_node_len(mcs_node_get(fe1, "contacts")) + 2);
done:
    mcs_scenario_destroy(&c2);
    mcs_scenario_destroy(&s2);
    mcs_scenario_destroy(&s1);
}

/* distance of x from the ellipsoid surface s of the built model, to first order */
static double surf_distance(const mb_model *m, const mb_surface *s, const double x[3])
{
    const mb_body_desc *b = &m->body[s->body];
    double R[9], c[3], d[3], e[3], l[3];
    mb_quat_to_rot(b->quat, R);
    for (int i = 0; i < 3; i++)
        c[i] = b->pos[i] + R[3 * i] * s->center[0] + R[3 * i + 1] * s->center[1] +
               R[3 * i + 2] * s->center[2];
    for (int i = 0; i < 3; i++)
        d[i] = x[i] - c[i];
    for (int i = 0; i < 3; i++)
        e[i] = R[i] * d[0] + R[3 + i] * d[1] + R[6 + i] * d[2];
    for (int i = 0; i < 3; i++)
        l[i] = s->rot[i] * e[0] + s->rot[3 + i] * e[1] + s->rot[6 + i] * e[2];
    double f2 = 0, g2 = 0;
    for (int i = 0; i < 3; i++) {
        f2 += l[i] * l[i] / (s->semi[i] * s->semi[i]);
        g2 += l[i] * l[i] / pow(s->semi[i], 4);
    }
    double f = sqrt(f2);
    return (f - 1) / (sqrt(g2) / f);
}

static void test_stage2_model_builds(void)
{
    mcs_scenario *s2 = load(S2), *c2 = NULL;
    mcs_error err = {0};
    mb_model *m = NULL;
    if (s2) CHECK(s2_scenario_compile(s2, &c2, &err) == MCS_OK);
    if (c2 && mb_model_build(c2, NULL, &m, &err)) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL && m->couple != NULL);
    if (!m || !m->couple) goto done;
    const fe_model *fm = m->couple->fe.model;
    int frame = mb_model_body(m, "moto_frame");
    const char *pads[2] = {"pad_tank_l", "pad_tank_r"},
               *thigh[2] = {"rider_thigh_l", "rider_thigh_r"};
    double gap_min = INFINITY;
    for (int k = 0; k < 2; k++) {
        int ip = -1, st = -1;
        for (int i = 0; i < fm->npart; i++)
            if (strcmp(fm->part[i].name, pads[k]) == 0) ip = i;
        for (int i = 0; i < m->nsurf; i++)
            if (strcmp(m->surf[i].name, thigh[k]) == 0) st = i;
        CHECK(ip >= 0 && st >= 0);
        if (ip < 0 || st < 0) continue;
        const fe_part *p = &fm->part[ip];
        int nhex = p->elem_end - p->elem_begin, carried = 0;
        /* its nodes carried by the frame: the inner face, (nu + 1) (nv + 1) of nu nv hexes */
        for (int a = 0; a < m->couple->natt; a++) {
            int n = m->couple->node[a];
            for (int e = p->elem_begin; e < p->elem_end; e++)
                if (fm->hex_node[8 * e] == n || fm->hex_node[8 * e + 1] == n ||
                    fm->hex_node[8 * e + 2] == n || fm->hex_node[8 * e + 3] == n) {
                    carried++;
                    CHECK(m->couple->body[a] == frame);
                    break;
                }
        }
        double gap = INFINITY;
        for (int e = p->elem_begin; e < p->elem_end; e++)
            for (int j = 4; j < 8; j++)
                gap = fmin(
                    gap, surf_distance(m, &m->surf[st], fm->node_x0 + 3 * fm->hex_node[8 * e + j]));
        printf(
            "%s: %d hexes, %d nodes carried by moto_frame, outer face %.1f mm from %s at t = 0\n",
            pads[k], nhex, carried, 1e3 * gap, thigh[k]);
        CHECK(nhex >= 9 && carried > nhex);
        gap_min = fmin(gap_min, gap);
    }
    FIG("s2.concept_pad_gap_mm", "%.0f", 1e3 * gap_min);
    CHECK(gap_min > 0.010);
done:
    mb_model_destroy(&m);
    mcs_scenario_destroy(&c2);
    mcs_scenario_destroy(&s2);
}

int main(void)
{
    RUN(test_restraints_shared);
    RUN(test_stage2_model_builds);
    TEST_END();
}

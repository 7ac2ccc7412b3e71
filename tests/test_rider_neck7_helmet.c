/* test_rider_neck7_helmet.c: the rider with MYMOSA's 7-vertebra neck wearing the helmet
 * (scenarios/models/riders/hybrid3_50th_neck7_helmet.yaml, written by scripts/gen_rider.py;
 * docs/rider.md): it builds, has the 23 rider segments plus the helmet's shell and liner, weighs
 * the H3 50th's 78.2 kg plus the 1.4 kg helmet, and sits on the motorcycle: seated by the
 * positioning step (hands on the grips, feet on the pegs, pelvis on the seat), the helmet keeps
 * its pose on the head, and 50 ms seated under gravity break nothing. */
#include "harness.h"
#include "tests/figures.h"
#include "tests/mb_test_util.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define FILE7H "models/riders/hybrid3_50th_neck7_helmet.yaml"

/* the shell's offset from the head in the model file (world = head axes there) [m] */
static double d0[3];

/* 23 segments (17 with the neck replaced by C7..C1) + shell + liner; 78.2 + 1.4 kg */
static void test_builds_and_mass(void)
{
    mb_model *m = mt_rider_alone(FILE7H);
    CHECK(m != NULL);
    if (!m) return;
    int n = 0;
    double mass = mt_rider_mass(m, &n);
    printf("  neck7 + helmet: %d bodies, %.9f kg, %d joints, %d attachments\n", n, mass, m->njoint,
           m->nattach);
    CHECK(n == 25);
    /* the files print masses to 7 digits: 23 roundings of at most 5e-7 relative each */
    CHECK_NEAR(mass, 78.2 + 1.4, 1e-5);
    FIG("rider.neck7_helmet_mass_kg", "%.7f", mass);
    CHECK(m->njoint == 22);
    CHECK(m->nattach == 6); /* the helmet's two three-point couplings */
    for (int k = 1; k <= 7; k++) {
        char nm[32];
        snprintf(nm, sizeof nm, "rider_c%d", k);
        CHECK(mb_model_body(m, nm) >= 0);
    }
    int h = mb_model_body(m, "rider_head"), s = mb_model_body(m, "rider_helmet_shell");
    CHECK(h >= 0 && s >= 0 && mb_model_body(m, "rider_helmet_liner") >= 0);
    if (h >= 0 && s >= 0) mb_sub(m->body[s].pos, m->body[h].pos, d0);
    mb_model_destroy(&m);
}

/* seated (40 deg lean, head pitched -10 deg) on sport_208kg with the seat contact, 50 ms */
static void test_seated(void)
{
    mcs_error err = {0};
    mb_model *m = mt_rider_seated_helmet("scenarios/rider_neck7_helmet.yaml", FILE7H, NULL);
    CHECK(m != NULL);
    if (!m) return;
    printf("  seated: mount-point residual %.3g m\n", m->rider_residual);
    CHECK(m->rider_residual >= 0 && m->rider_residual < 1e-12);
    double e = mt_helmet_offset_error(m, d0);
    printf("  shell offset from the head kept to %.2g m\n", e);
    CHECK(e < 1e-12);
    mb_state *s = NULL;
    CHECK(mt_run(m, &s, &err) == MCS_OK);
    if (s) {
        double f = mt_helmet_coupling_force(m, s);
        int broken = 0;
        for (int i = 0; i < m->nattach; i++) broken += s->att[i].broken;
        printf("  after 50 ms seated: %d attachments, none broken: %s; largest helmet coupling "
               "force %.1f N; energy drift %.2g\n",
               m->nattach, broken ? "no" : "yes", f, mb_energy_drift(m, s));
        CHECK(broken == 0);
        CHECK(m->nattach == 11); /* the five seat/grip/peg attachments and the six couplings */
        CHECK(f < 1.4 * 9.81 * 2);
        CHECK(mb_energy_drift(m, s) < 1e-2);
        FIG("rider.neck7_coupling_n", "%.1f", f);
        FIG("rider.neck7_drift", "%.1e", mb_energy_drift(m, s));
    }
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_builds_and_mass);
    RUN(test_seated);
    TEST_END();
}

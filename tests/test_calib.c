/* test_calib.c: CALIBRATION CHECKS of the stage-1 MYMOSA case (docs/validation_stage1.md,
 * "Calibration targets"). Nothing is fitted to a run (issue 11): each parameter below is set
 * from a published figure or a hand calculation, and this test checks the shipped scenarios
 * against those sources. The held-out results (event times against MYMOSA's Fig. 5.2) are
 * validation: tests/test_validation_stage1.c.
 *
 * 1. MYMOSA's car side (car_door and car_sill of both mymosa_lateral_car_1100kg*.yaml): the
 *    FMVSS 214 quasi-static door crush minimums (49 CFR 571.214, as quoted in docs/models.md:
 *    average force >= 2250 lbf = 10.01 kN over the first 6 in = 152.4 mm, >= 3500 lbf =
 *    15.57 kN over 12 in = 304.8 mm, peak >= min(2 x curb weight, 7000 lbf = 31.14 kN) within
 *    18 in = 457.2 mm; 2 x 1100 x 9.81 = 21.58 kN). The averages are the law's own trapezoids.
 * 2. MYMOSA's Eq. 4.1 [seed 002 Sec. 4] by hand: 1/2 m1 v^2 - 1/2 (m1 + m2) v_c^2 with
 *    m1 = 208 kg, m2 = 1100 kg, v = 13.4 m/s, v_c = m1 v / (m1 + m2) = 2.1309 m/s:
 *    18674.2 - 2969.7 = 15704.6 J; less the fork's 671 J (our run) and the tyre's 494 J (its
 *    law to 64.8 mm, the deflection at the run's 23.4 kN): E_d = 14.54 kJ. The crush at which
 *    the car law absorbs E_d in one zone, and in two equal zones, is found here by integrating
 *    the law's points (trapezoids).
 * 3. The rider's attachment failure forces of the three *_rider.yaml: grip 500 N (MYMOSA's
 *    definition, the largest grip on a cylinder: men 20-39, Mathiowetz et al. 1985, 115 lb =
 *    512 N), peg 500 N (assumed equal), seat 320 N (mu 0.5 x the seated weight, assumed).
 * 4. MYMOSA's rider in its rider case: 73.25 kg with the helmet [seed 002 Table 1.1] (the
 *    generated file prints masses to 7 digits: 25 roundings of at most 5e-7 relative each),
 *    the 7-vertebra neck (rider_c1..c7) and the helmet's shell. */
#include "harness.h"
#include "stage1_mb/mb_model.h"

#include <math.h>
#include <string.h>

#define SMYM "scenarios/mymosa_lateral_car_1100kg.yaml"
#define SMYM_RIDER "scenarios/mymosa_lateral_car_1100kg_rider.yaml"

static mb_model *build(const char *path)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mb_model *m = NULL;
    if (mcs_scenario_load(path, &scn, &err) || mb_model_build(scn, NULL, &m, &err))
        fprintf(stderr, "%s: %s\n", path, err.msg);
    mcs_scenario_destroy(&scn);
    return m;
}

static const mb_char *find_char(const mb_model *m, const char *name)
{
    for (int i = 0; i < m->nchar; i++)
        if (strcmp(m->chr[i].name, name) == 0) return &m->chr[i];
    return NULL;
}

/* energy under the law from 0 to x [J] (trapezoids of 0.1 mm: exact on a piecewise-linear law
 * whose points lie on the 0.1 mm grid) */
static double energy_to(const mcs_curve *c, double x)
{
    double e = 0, dx = 1e-4;
    for (double a = 0; a < x - 1e-12; a += dx) {
        double b = fmin(a + dx, x);
        e += 0.5 * (mcs_curve_eval(c, a) + mcs_curve_eval(c, b)) * (b - a);
    }
    return e;
}

/* the crush at which the law has absorbed e [m] (bisection) */
static double crush_for(const mcs_curve *c, double e)
{
    double lo = 0, hi = 0.55;
    for (int k = 0; k < 40; k++) {
        double mid = 0.5 * (lo + hi);
        if (energy_to(c, mid) < e)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

static void test_car_side_law(void)
{
    const char *paths[2] = {SMYM, SMYM_RIDER};
    for (int k = 0; k < 2; k++) {
        mb_model *m = build(paths[k]);
        CHECK(m != NULL);
        if (!m) continue;
        const mb_char *door = find_char(m, "car_door"), *sill = find_char(m, "car_sill");
        CHECK(door && sill);
        if (!door || !sill) {
            mb_model_destroy(&m);
            continue;
        }
        const mcs_curve *c = door->loading;
        double a152 = energy_to(c, 0.1524) / 0.1524, a305 = energy_to(c, 0.3048) / 0.3048;
        double peak = 0;
        for (double x = 0; x <= 0.4572 + 1e-12; x += 1e-4)
            peak = fmax(peak, mcs_curve_eval(c, x));
        double ed = 0.5 * 208 * 13.4 * 13.4 - 0.5 * 1308 * pow(208 * 13.4 / 1308, 2) - 671 - 494;
        double x1 = crush_for(c, ed), x2 = crush_for(c, ed / 2);
        printf("  %s: car side law averages %.2f kN (152 mm), %.2f kN (305 mm), peak %.1f kN "
               "(457 mm); E_d %.0f J absorbed at %.0f mm in one zone, %.0f mm in two\n",
               paths[k], a152 / 1e3, a305 / 1e3, peak / 1e3, ed, x1 * 1e3, x2 * 1e3);
        /* FMVSS 214 minimums */
        CHECK(a152 >= 10.01e3);
        CHECK(a305 >= 15.57e3);
        CHECK(peak >= fmin(2 * 1100 * 9.81, 31.14e3));
        /* one law for the sill and the door (MYMOSA's one spring) */
        for (double x = 0; x <= 0.55; x += 0.01)
            CHECK_NEAR(mcs_curve_eval(sill->loading, x), mcs_curve_eval(c, x), 1e-6);
        CHECK_NEAR(ed, 14539.6, 0.1); /* the hand value in the doc */
        FIG("validation_stage1.law_avg152_kn", "%.1f", a152 / 1e3);
        FIG("validation_stage1.law_avg305_kn", "%.1f", a305 / 1e3);
        FIG("validation_stage1.law_peak457_kn", "%.0f", peak / 1e3);
        FIG("validation_stage1.ed_crush_one_mm", "%.0f", x1 * 1e3);
        FIG("validation_stage1.ed_crush_two_mm", "%.0f", x2 * 1e3);
        mb_model_destroy(&m);
    }
}

static void test_attachment_forces(void)
{
    const char *paths[3] = {SMYM_RIDER, "scenarios/iso13232_413-0_13.4_sedan_rider.yaml",
                            "scenarios/moving_car_413-6.7_13.4_sedan_rider.yaml"};
    for (int k = 0; k < 3; k++) {
        mb_model *m = build(paths[k]);
        CHECK(m != NULL);
        if (!m) continue;
        int n = 0;
        for (int i = 0; i < m->nattach; i++) {
            const char *nm = m->attach_name[i];
            double ff = m->attach[i].fail_force;
            double want = strstr(nm, "grip") || strstr(nm, "peg") ? 500
                          : strstr(nm, "seat")                    ? 320
                                                                  : -1;
            if (want < 0) continue;
            CHECK_NEAR(ff, want, 1e-9);
            n++;
        }
        CHECK(n == 5);
        /* the grip within 3 % of its source, 512 N (115 lb x 4.448 N/lb) */
        CHECK(fabs(500 / (115 * 4.448) - 1) < 0.03);
        mb_model_destroy(&m);
    }
}

static void test_mymosa_rider(void)
{
    mb_model *m = build(SMYM_RIDER);
    CHECK(m != NULL);
    if (!m) return;
    double mass = 0;
    int n = 0;
    for (int b = 0; b < m->nbody; b++)
        if (!strncmp(m->body_name[b], "rider_", 6)) mass += m->body[b].mass, n++;
    printf("  MYMOSA rider: %d bodies, %.6f kg\n", n, mass);
    CHECK_NEAR(mass, 73.25, 73.25 * 25 * 5e-7);
    CHECK(n == 25);
    CHECK(mb_model_body(m, "rider_c7") >= 0 && mb_model_body(m, "rider_c1") >= 0);
    CHECK(mb_model_body(m, "rider_helmet_shell") >= 0);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_mymosa_rider);
    RUN(test_car_side_law);
    RUN(test_attachment_forces);
    TEST_END();
}

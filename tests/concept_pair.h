/* concept_pair.h: the checks of the ISO 13232 413-0/13.4 pair (the conventional motorcycle,
 * scenarios/iso13232_413-0_13.4_sedan_rider.yaml, and the 2023 paper's rider restraint concept,
 * ..._concept.yaml) on two results files of it, shared by tests/test_concept.c (the first 120 ms,
 * make test) and tests/test_validation_concept.c (the 300 ms runs, make verify, which therefore
 * run once). The references of each check are listed in test_concept.c's preamble: the paper's
 * t_fire = 12 ms after first contact and Eq. 3 (Sec. 2.3.1), the 2 kN limiter, the inflator
 * table's integral, the rider leaving the seat later, the head criteria lower (Fig. 22).
 * Include after harness.h and figures.h. */
#ifndef MCS_TESTS_CONCEPT_PAIR_H
#define MCS_TESTS_CONCEPT_PAIR_H

#include "core/mcs_results.h"
#include "tests/cli_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define F_LIM 2000.0  /* load limiter [N] (paper Sec. 2.3.1) */
#define T_DELAY 0.012 /* firing delay after the first contact [s] (paper Sec. 2.3.1) */
#define LEAVE 0.25    /* pelvis off its seated place [m] */

static int rd(mcs_results *h, const char *path, mcs_array *a)
{
    mcs_error err = {0};
    return mcs_results_read(h, path, a, &err) == MCS_OK;
}

/* first time the pelvis is more than LEAVE from its t = 0 place in the frame's coordinates
 * (INFINITY if never); *dmax the largest such distance [m] */
static double leave_time(mcs_results *h, double *dmax)
{
    mcs_array t = {0}, pf = {0}, qf = {0}, pp = {0};
    double tl = INFINITY;
    *dmax = 0;
    if (rd(h, "/stage1/time", &t) && rd(h, "/stage1/bodies/moto_frame/position", &pf) &&
        rd(h, "/stage1/bodies/moto_frame/orientation", &qf) &&
        rd(h, "/stage1/bodies/rider_pelvis/position", &pp)) {
        double r0[3] = {0};
        for (size_t i = 0; i < t.n; i++) {
            const double *q = qf.v + 4 * i,
                         d[3] = {pp.v[3 * i] - pf.v[3 * i], pp.v[3 * i + 1] - pf.v[3 * i + 1],
                                 pp.v[3 * i + 2] - pf.v[3 * i + 2]};
            /* d in the frame's axes: R(q)^T d, R of the unit quaternion (w, x, y, z) */
            double w = q[0], x = q[1], y = q[2], z = q[3], r[3];
            r[0] = (1 - 2 * (y * y + z * z)) * d[0] + 2 * (x * y + w * z) * d[1] +
                   2 * (x * z - w * y) * d[2];
            r[1] = 2 * (x * y - w * z) * d[0] + (1 - 2 * (x * x + z * z)) * d[1] +
                   2 * (y * z + w * x) * d[2];
            r[2] = 2 * (x * z + w * y) * d[0] + 2 * (y * z - w * x) * d[1] +
                   (1 - 2 * (x * x + y * y)) * d[2];
            if (i == 0) memcpy(r0, r, sizeof r0);
            double dist = sqrt((r[0] - r0[0]) * (r[0] - r0[0]) + (r[1] - r0[1]) * (r[1] - r0[1]) +
                               (r[2] - r0[2]) * (r[2] - r0[2]));
            *dmax = fmax(*dmax, dist);
            if (dist > LEAVE && !isfinite(tl)) tl = t.v[i];
        }
    }
    mcs_array_free(&t), mcs_array_free(&pf), mcs_array_free(&qf), mcs_array_free(&pp);
    return tl;
}

/* the criterion's value from `mcrash injury FILE --json` (NaN if absent) */
static double injury(const char *file, const char *key)
{
    char args[512], pat[96];
    snprintf(args, sizeof args, "injury %s --json", file);
    cli_result *r = cli_run(args);
    snprintf(pat, sizeof pat, "\"criterion\": \"%s\"", key);
    const char *p = r->status ? NULL : strstr(r->out, pat);
    const char *v = p ? strstr(p, "\"value\": ") : NULL;
    return v ? strtod(v + 9, NULL) : NAN;
}

/* Eq. 3 of the paper: pay-in [m] (negative: pulled in) at time tau after firing */
static double eq3(double tau)
{
    return tau <= 0 ? 0 : tau < 0.015 ? -0.1 / 0.015 * tau : -0.1;
}

/* the belt of retractor name: Eq. 3, the plateau at F_lim; returns the plateau's length [s] */
static double check_belt(mcs_results *h, const char *name, double t_fire, const mcs_array *t)
{
    char p1[128], p2[128], p3[128];
    snprintf(p1, sizeof p1, "/stage1/retractor/%s/payout_pretensioner", name);
    snprintf(p2, sizeof p2, "/stage1/retractor/%s/force", name);
    snprintf(p3, sizeof p3, "/stage1/retractor/%s/payout_limiter", name);
    mcs_array pre = {0}, f = {0}, lim = {0};
    double plateau = 0, run = 0, fpk = 0, slope_err = 0, end_err = 0, before = 0;
    if (rd(h, p1, &pre) && rd(h, p2, &f) && rd(h, p3, &lim) && pre.n == t->n && f.n == t->n) {
        const double dt = t->v[1] - t->v[0];
        for (size_t i = 1; i < t->n; i++) {
            double tau = t->v[i] - t_fire;
            if (tau < -dt) before = fmax(before, fabs(pre.v[i]));
            /* on the ramp, well inside it: Eq. 3's slope */
            if (tau > 0.002 && tau < 0.013)
                slope_err =
                    fmax(slope_err, fabs((pre.v[i] - pre.v[i - 1]) - (eq3(tau) - eq3(tau - dt))));
            if (tau > 0.0152) end_err = fmax(end_err, fabs(pre.v[i] - eq3(tau)));
            fpk = fmax(fpk, f.v[i]);
            /* a dip of one sample (>= 85 %: a belt node slipping over the thigh) keeps the run */
            int on =
                f.v[i] >= 0.95 * F_LIM || (f.v[i] >= 0.85 * F_LIM && f.v[i - 1] >= 0.95 * F_LIM &&
                                           i + 1 < f.n && f.v[i + 1] >= 0.95 * F_LIM);
            run = on ? run + dt : 0;
            plateau = fmax(plateau, run);
        }
        printf("  %s: pay-in before firing %.1e m, ramp slope error %.1e m per sample, "
               "-100 mm held to %.1e m; force max %.4f N, plateau >= 0.95 F_lim for %.1f ms, "
               "limiter payout %.1f mm\n",
               name, before, slope_err, end_err, fpk, 1e3 * plateau, 1e3 * lim.v[lim.n - 1]);
        CHECK(before == 0);
        /* a row holds the state of the last FE step before its time (docs/contracts.md), so it
         * lags the row by less than one ODE step (10 us); where the FE subcycle changes its
         * number of steps (k = 1 or 2 at 10 us while the bag unfolds), a sample's increment
         * differs from Eq. 3's by at most the pay-in over one ODE step, 100/15 mm/ms x 10 us */
        CHECK(slope_err < 0.1 / 0.015 * 10e-6);
        CHECK(end_err < 1e-12);
        CHECK(fpk <= F_LIM * (1 + 1e-9)); /* never above the limiter */
        CHECK(lim.v[lim.n - 1] > 0);      /* it paid webbing out */
    } else {
        CHECK(0);
    }
    mcs_array_free(&pre), mcs_array_free(&f), mcs_array_free(&lim);
    return plateau;
}

/* every check of the pair on the results files conv (conventional) and conc (concept); full:
 * the files run to 300 ms (make verify, test_validation_concept.c), else to 120 ms
 * (test_concept.c). Each mode states its own figures (tests/figures.h: a key reads the same in both
 * modes) */
static void concept_pair_check(const char *conv, const char *conc, int full)
{
    mcs_results *h = NULL, *hc = NULL;
    mcs_error err = {0};
    CHECK(mcs_results_open(&h, conc, &err) == MCS_OK);
    CHECK(mcs_results_open(&hc, conv, &err) == MCS_OK);
    if (!h || !hc) return;
    /* one energy balance */
    double drift = NAN, drift_conv = NAN;
    mcs_results_attr_double(h, "/stage1", "energy_drift", &drift, &err);
    mcs_results_attr_double(hc, "/stage1", "energy_drift", &drift_conv, &err);
    printf("  energy drift: concept %.2e, conventional %.2e\n", drift, drift_conv);
    CHECK(drift < 1e-3);
    /* the rider's own balance (stage1_mb/mb_egroup.c, paper Eq. 9): kinetic + potential +
     * internal + contact transfer at its t = 0 value (its rows written to the file) */
    mcs_array et = {0};
    CHECK(rd(h, "/stage1/energy_groups/rider/total", &et));
    double egw = 0;
    for (size_t i = 0; i < et.n; i++)
        egw = fmax(egw, fabs(et.v[i] - et.v[0]));
    printf("  rider balance: |total - total(0)| <= %.3g J of %.1f J\n", egw, et.n ? et.v[0] : 0.0);
    CHECK(et.n > 0 && egw < 1e-4 * et.v[0]);
    mcs_array_free(&et);
    /* the bag's gas energies as written: the first law of the gas, U - U0 = H_in - H_vent -
     * H_leak - int p dV, at every row (fe/fe_gasbag.h; each series its own column) */
    static const char *const gch[5] = {"energy", "energy_in", "energy_vent", "energy_leak", "work"};
    mcs_array ga[5] = {{0}};
    int gok = 1;
    for (int k = 0; k < 5; k++) {
        char gp[96];
        snprintf(gp, sizeof gp, "/stage1/airbag/front/%s", gch[k]);
        gok &= rd(h, gp, &ga[k]) && ga[k].n == ga[0].n;
    }
    CHECK(gok);
    double gw = 0;
    for (size_t i = 0; gok && i < ga[0].n; i++)
        gw = fmax(gw, fabs(ga[0].v[i] - ga[0].v[0] -
                           (ga[1].v[i] - ga[2].v[i] - ga[3].v[i] - ga[4].v[i])));
    printf("  bag gas: |U - U0 - (H_in - H_vent - H_leak - W)| <= %.2e J of U0 %.1f J\n", gw,
           gok ? ga[0].v[0] : 0.0);
    CHECK(gok && gw < 1e-6 * ga[0].v[0]);
    for (int k = 0; k < 5; k++)
        mcs_array_free(&ga[k]);
    /* firing: the first sample with a contact force, plus 12 ms */
    mcs_array t = {0}, fc = {0}, p = {0}, m = {0};
    CHECK(rd(h, "/stage1/time", &t) && rd(h, "/stage1/channels/front_tyre_car_fn", &fc));
    double t_c = NAN;
    for (size_t i = 0; i < fc.n && !isfinite(t_c); i++)
        if (fc.v[i] > 0) t_c = t.v[i];
    double fire_bag = NAN, fire_l = NAN, fire_r = NAN;
    mcs_results_attr_double(h, "/stage1/airbag/front", "fire_time", &fire_bag, &err);
    mcs_results_attr_double(h, "/stage1/retractor/thigh_l", "fire_time", &fire_l, &err);
    mcs_results_attr_double(h, "/stage1/retractor/thigh_r", "fire_time", &fire_r, &err);
    printf("  first contact sampled at %.4f ms; fired at %.4f ms (bag), %.4f / %.4f ms (belts)\n",
           1e3 * t_c, 1e3 * fire_bag, 1e3 * fire_l, 1e3 * fire_r);
    /* the true first contact lies within one output interval before the sample; the trigger
     * fires within one ODE step (10 us) after the delay */
    const double dto = t.v[1] - t.v[0];
    double fires[3] = {fire_bag, fire_l, fire_r};
    for (int k = 0; k < 3; k++)
        CHECK(fires[k] - (t_c + T_DELAY) > -dto - 1e-9 && fires[k] - (t_c + T_DELAY) < 1.1e-5);
    /* the belts */
    double pl = check_belt(h, "thigh_l", fire_l, &t), pr = check_belt(h, "thigh_r", fire_r, &t);
    CHECK(pl >= 0.010 && pr >= 0.010); /* measured 16 ms each */
    /* the bag: ambient until it fires, then pressurised; no more gas than the inflator gave */
    CHECK(rd(h, "/stage1/airbag/front/pressure", &p) && rd(h, "/stage1/airbag/front/mass", &m));
    mcs_array vol = {0};
    CHECK(rd(h, "/stage1/airbag/front/volume", &vol));
    const double box = 0.46 * 0.57 * 0.18; /* the panels' box [m^3] (model file) */
    double pre_dev = 0, peak = 0, dm_max = 0, t_open = INFINITY;
    for (size_t i = 0; i < p.n && i < t.n && i < vol.n; i++) {
        if (t.v[i] < fire_bag) pre_dev = fmax(pre_dev, fabs(p.v[i] - 101325));
        peak = fmax(peak, p.v[i] - 101325);
        dm_max = fmax(dm_max, m.v[i] - m.v[0]);
        if (vol.v[i] > 0.8 * box && !isfinite(t_open)) t_open = t.v[i];
    }
    printf("  bag: %.2f l at t = 0, more than 0.8 of the panels' box (%.1f l) %.1f ms after "
           "firing; |p - p_amb| <= %.0f Pa before firing; peak gauge %.1f kPa; gas taken in at "
           "most %.2f g (inflator 27.0 g)\n",
           1e3 * (vol.n ? vol.v[0] : NAN), 1e3 * box, 1e3 * (t_open - fire_bag), pre_dev,
           1e-3 * peak, 1e3 * dm_max);
    CHECK(vol.n > 0 && vol.v[0] < 0.1 * box); /* the scaled copy */
    CHECK(t_open - fire_bag < 0.020);          /* open (measured ~13 ms) */
    CHECK(pre_dev < 1000); /* the rider does not reach it before it fires */
    CHECK(peak > 20e3);    /* it is pressurised (measured ~57 kPa with the rider in it) */
    CHECK(dm_max <= 27.0e-3 * (1 + 1e-9) && dm_max > 0);
    mcs_array_free(&vol);
    /* the rider on the motorcycle */
    double dmax_c = 0, dmax_v = 0, tl_c = leave_time(h, &dmax_c), tl_v = leave_time(hc, &dmax_v);
    printf("  pelvis off its seated place by > %.2f m at %.1f ms (conventional), %.1f ms "
           "(concept); largest: %.3f / %.3f m\n",
           LEAVE, 1e3 * tl_v, 1e3 * tl_c, dmax_v, dmax_c);
    CHECK(isfinite(tl_v));
    CHECK(tl_c > tl_v);
    /* the head criteria (paper Fig. 22: lower with the restraints) */
    double hic_v = injury(conv, "hic15"), hic_c = injury(conc, "hic15");
    double a3_v = injury(conv, "head_a3ms"), a3_c = injury(conc, "head_a3ms");
    printf("  HIC15 %.1f -> %.1f, head a3ms %.2f -> %.2f g\n", hic_v, hic_c, a3_v, a3_c);
    CHECK(hic_c < hic_v);
    CHECK(a3_c < a3_v);
    if (!full) {
        FIG("concept.hic15_conv", "%.0f", hic_v);
        FIG("concept.hic15_concept", "%.0f", hic_c);
        FIG("concept.leave_conv_ms", "%.0f", 1e3 * tl_v);
        FIG("concept.bag_peak_kpa", "%.0f", 1e-3 * peak);
        FIG("concept.plateau_ms", "%.1f", 1e3 * fmin(pl, pr));
        FIG_TOL("concept.drift", "%.1e", drift, 1e-4);
    } else {
        FIG("concept.hic15_concept_300", "%.0f", hic_c);
        FIG_TOL("concept.drift_300", "%.1e", drift, 1e-4);
    }
    mcs_array_free(&t), mcs_array_free(&fc), mcs_array_free(&p), mcs_array_free(&m);
    mcs_results_close(&h);
    mcs_results_close(&hc);
}

#endif

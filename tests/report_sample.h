/* report_sample.h: a small results file with every section of `mcrash report` in it (stages 1,
 * 2 and 3: energies, dummy channels, a body with an outline and one without, an FE bag with a
 * displacement field, belt, airbag, foam, parts' energies, an energy group, a stage-3 rigid
 * wall and a hexahedral tube), for tests/test_report.c and tests/test_report_page.c */
#ifndef MCS_REPORT_SAMPLE_H
#define MCS_REPORT_SAMPLE_H

#include "core/mcs_results.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { RS_NT = 1501, RS_NOUT = 16 };
static const double RS_DT = 2e-4; /* output interval [s]: 0.3 s, 5 kHz */

/* a half-sine pulse of amplitude a over [t0, t0 + w] */
static double rs_pulse(double t, double a, double t0, double w)
{
    return t >= t0 && t <= t0 + w ? a * sin(M_PI * (t - t0) / w) : 0;
}

static int rs_channel(mcs_results *r, int s, const char *name, const double *t, double a,
                      double t0, const char *unit, int cfc, mcs_error *e)
{
    double y[RS_NT];
    for (int i = 0; i < RS_NT; i++)
        y[i] = rs_pulse(t[i], a, t0, 0.04) + 0.1 * rs_pulse(t[i], -a, t0 + 0.05, 0.06);
    return mcs_results_put_channel(r, s, name, RS_NT, y, unit, "SAE J211 local", cfc, "rider_head",
                                   e) != MCS_OK;
}

/* stage s's time, energies, dummy channels and bodies; shift delays the pulses [s] */
static int rs_stage_mb(mcs_results *r, int s, double shift, mcs_error *e)
{
    double t[RS_NT], ek[RS_NT], ei[RS_NT], et[RS_NT];
    int bad = 0;
    for (int i = 0; i < RS_NT; i++) {
        t[i] = i * RS_DT;
        double f = fmin(t[i] / 0.15, 1);
        ek[i] = 15000 * (1 - f) * (1 - f);
        ei[i] = 15000 - ek[i];
        et[i] = ek[i] + ei[i];
    }
    bad |= mcs_results_put_time(r, s, RS_NT, t, e) != MCS_OK;
    bad |= mcs_results_put_energy(r, s, "kinetic", RS_NT, ek, e) != MCS_OK;
    bad |= mcs_results_put_energy(r, s, "internal", RS_NT, ei, e) != MCS_OK;
    bad |= mcs_results_put_energy(r, s, "total", RS_NT, et, e) != MCS_OK;
    const double g = 9.80665;
    static const char *acc[] = {"head_ax", "head_ay", "head_az", "chest_ax", "chest_ay",
                                "chest_az", "pelvis_ax", "pelvis_ay", "pelvis_az"};
    for (int k = 0; k < 9; k++)
        bad |= rs_channel(r, s, acc[k], t, (k % 3 == 1 ? 5 : 40) * g * (k < 3 ? 1.5 : 1),
                          0.03 + shift + 0.002 * k, "m/s^2", k < 3 || k >= 6 ? 1000 : 180, e);
    bad |= rs_channel(r, s, "neck_fx", t, 900, 0.04 + shift, "N", 600, e);
    bad |= rs_channel(r, s, "neck_fy", t, 100, 0.04 + shift, "N", 600, e);
    bad |= rs_channel(r, s, "neck_fz", t, 2500, 0.045 + shift, "N", 600, e);
    bad |= rs_channel(r, s, "neck_mx", t, 5, 0.04 + shift, "N*m", 600, e);
    bad |= rs_channel(r, s, "neck_my", t, -30, 0.05 + shift, "N*m", 600, e);
    bad |= rs_channel(r, s, "neck_mz", t, 3, 0.04 + shift, "N*m", 600, e);
    /* rider_head with an octahedron outline thrown forward; moto_frame without one */
    double *pos = malloc(sizeof *pos * 3 * RS_NT), *ori = malloc(sizeof *ori * 4 * RS_NT);
    if (!pos || !ori) {
        free(pos);
        free(ori);
        return 1;
    }
    for (int i = 0; i < RS_NT; i++) {
        double a = 2.0 * t[i];
        pos[3 * i] = 1.0 + 8 * t[i];
        pos[3 * i + 1] = 0;
        pos[3 * i + 2] = 1.3 + 2 * t[i] - 4.9 * t[i] * t[i];
        ori[4 * i] = cos(a / 2);
        ori[4 * i + 1] = 0;
        ori[4 * i + 2] = sin(a / 2);
        ori[4 * i + 3] = 0;
    }
    bad |= mcs_results_put_body(r, s, "rider_head", "position", RS_NT, pos, e) != MCS_OK;
    bad |= mcs_results_put_body(r, s, "rider_head", "orientation", RS_NT, ori, e) != MCS_OK;
    for (int i = 0; i < RS_NT; i++) {
        pos[3 * i] = 0.8 + 4 * t[i];
        pos[3 * i + 2] = 0.6;
    }
    bad |= mcs_results_put_body(r, s, "moto_frame", "position", RS_NT, pos, e) != MCS_OK;
    bad |= mcs_results_put_body(r, s, "moto_frame", "orientation", RS_NT, ori, e) != MCS_OK;
    free(pos);
    free(ori);
    const double on[] = {0.1, 0, 0, -0.1, 0, 0, 0, 0.08, 0, 0, -0.08, 0, 0, 0, 0.12, 0, 0,
                         -0.12};
    const int tri[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    size_t dn[2] = {6, 3}, de[2] = {8, 3};
    char p[96];
    snprintf(p, sizeof p, "/stage%d/outlines/rider_head/nodes", s);
    bad |= mcs_results_write(r, p, 2, dn, on, "m", e) != MCS_OK;
    snprintf(p, sizeof p, "/stage%d/outlines/rider_head/elements", s);
    bad |= mcs_results_write_int(r, p, 2, de, tri, "-", e) != MCS_OK;
    bad |= mcs_results_set_attr_str(r, p, "type", "tri3", e) != MCS_OK;
    return bad;
}

/* a [RS_NT] dataset at path: a ramp to v at t1 (then held) */
static int rs_ramp(mcs_results *r, const char *path, double v, double t1, const char *unit,
                   mcs_error *e)
{
    double y[RS_NT];
    for (int i = 0; i < RS_NT; i++) y[i] = v * fmin(i * RS_DT / t1, 1);
    size_t d = RS_NT;
    return mcs_results_write(r, path, 1, &d, y, unit, e) != MCS_OK;
}

/* stage 1's restraints: a bag mesh (quad4) with its field, belt, airbag, foam, parts, group */
static int rs_restraints(mcs_results *r, mcs_error *e)
{
    int bad = 0;
    /* a 3 x 3 node square bag at x = 1.6 m, inflating along +x */
    double nodes[27];
    int quads[16];
    for (int j = 0, k = 0; j < 3; j++)
        for (int i = 0; i < 3; i++, k++) {
            nodes[3 * k] = 1.6;
            nodes[3 * k + 1] = -0.2 + 0.2 * i;
            nodes[3 * k + 2] = 0.9 + 0.2 * j;
        }
    for (int j = 0, q = 0; j < 2; j++)
        for (int i = 0; i < 2; i++, q++) {
            int n0 = 3 * j + i;
            quads[4 * q] = n0;
            quads[4 * q + 1] = n0 + 1;
            quads[4 * q + 2] = n0 + 4;
            quads[4 * q + 3] = n0 + 3;
        }
    bad |= mcs_results_put_mesh(r, 1, "bag_front", 9, nodes, 4, 4, quads, "quad4", 0, e) != 0;
    mcs_results_series *ts = NULL, *ds = NULL;
    bad |= mcs_results_field_series(r, 1, 9, &ts, &ds, e) != MCS_OK;
    for (int f = 0; !bad && f < RS_NOUT; f++) {
        double tf = f * 0.02, u[27] = {0};
        for (int k = 0; k < 9; k++) u[3 * k] = -0.3 * fmin(tf / 0.05, 1) * (k == 4 ? 1 : 0.5);
        bad |= mcs_results_series_append(ts, &tf, e) != MCS_OK;
        bad |= mcs_results_series_append(ds, u, e) != MCS_OK;
    }
    bad |= rs_ramp(r, "/stage1/retractor/thigh_l/force", 2000, 0.03, "N", e);
    bad |= rs_ramp(r, "/stage1/retractor/thigh_l/payout", -0.04, 0.02, "m", e);
    bad |= rs_ramp(r, "/stage1/airbag/front/pressure", 160e3, 0.04, "Pa", e);
    bad |= rs_ramp(r, "/stage1/airbag/front/volume", 0.045, 0.03, "m^3", e);
    bad |= rs_ramp(r, "/stage1/parts/foam_l/energy/internal", 80, 0.1, "J", e);
    bad |= rs_ramp(r, "/stage1/parts/bag_front/energy/internal", 120, 0.1, "J", e);
    bad |= rs_ramp(r, "/stage1/parts/bag_front/energy/kinetic", 30, 0.1, "J", e);
    bad |= rs_ramp(r, "/stage1/energy_groups/rider/contact/bag_rider", 900, 0.1, "J", e);
    bad |= mcs_results_set_attr_str(r, "/stage1/energy_groups/rider/contact/bag_rider",
                                    "category", "airbags", e) != MCS_OK;
    bad |= rs_ramp(r, "/stage1/energy_groups/rider/contact/car", 3000, 0.1, "J", e);
    bad |= mcs_results_set_attr_str(r, "/stage1/energy_groups/rider/contact/car", "category",
                                    "opponent", e) != MCS_OK;
    return bad;
}

/* stage 3: a rigid wall's force-crush and a one-hex tube crushed along x */
static int rs_stage3(mcs_results *r, mcs_error *e)
{
    enum { N3 = 151 };
    double t[N3], f[N3], d[N3];
    for (int i = 0; i < N3; i++) {
        t[i] = i * 1e-3;
        d[i] = 0.4 * fmin(t[i] / 0.1, 1);
        f[i] = 80e3 * (1 - exp(-d[i] / 0.02)) + 20e3 * sin(30 * d[i]) * (d[i] > 0);
    }
    int bad = mcs_results_put_time(r, 3, N3, t, e) != MCS_OK;
    bad |= mcs_results_put_rigidwall(r, "ram", N3, f, d, e) != MCS_OK;
    const double hex[24] = {0, 0, 0, 0.5, 0, 0, 0.5, 0.1, 0, 0, 0.1, 0,
                            0, 0, 0.1, 0.5, 0, 0.1, 0.5, 0.1, 0.1, 0, 0.1, 0.1};
    const int el[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    bad |= mcs_results_put_mesh(r, 3, "tube", 8, hex, 1, 8, el, "hex8", 0, e) != MCS_OK;
    mcs_results_series *ts = NULL, *ds = NULL;
    bad |= mcs_results_field_series(r, 3, 8, &ts, &ds, e) != MCS_OK;
    for (int k = 0; !bad && k < 8; k++) {
        double tf = k * 0.02, u[24] = {0};
        for (int n = 0; n < 8; n++)
            if (hex[3 * n] > 0.25) u[3 * n] = -0.4 * fmin(tf / 0.1, 1);
        bad |= mcs_results_series_append(ts, &tf, e) != MCS_OK;
        bad |= mcs_results_series_append(ds, u, e) != MCS_OK;
    }
    return bad;
}

/* the whole sample file at path; 0 when written */
static int rs_write(const char *path)
{
    mcs_results *r = NULL;
    mcs_error e = {0};
    if (mcs_results_create(&r, path, "mcrash: 1\nname: \"report sample\"\n", &e)) return 1;
    int bad = rs_stage_mb(r, 1, 0, &e) || rs_restraints(r, &e) || rs_stage_mb(r, 2, 0.004, &e) ||
              rs_stage3(r, &e);
    if (bad) {
        fprintf(stderr, "report sample: %s\n", e.msg);
        mcs_results_abort(&r);
        return 1;
    }
    return mcs_results_commit(&r, &e) != MCS_OK;
}

#endif

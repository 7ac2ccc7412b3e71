/* an_injury.c: criteria of a results file's stage against the limits table */
#include "analysis/an_injury.h"
#include "analysis/an_cfc.h"
#include "analysis/an_criteria.h"
#include "analysis/an_limits.h"
#include "analysis/an_signal.h"
#include "core/mcs_results.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *path;
    int stage;
    mcs_results *r;
    an_dummy dummy; /* Hybrid III size: its Nij intercepts and limits */
    an_injury_row *rows;
    int n, cap;
    mcs_error *err;
} inj_ctx;

static int chan_exists(inj_ctx *c, const char *name)
{
    char p[256];
    snprintf(p, sizeof p, "/stage%d/channels/%s", c->stage, name);
    return mcs_results_kind(c->r, p) == MCS_RES_DATASET;
}

/* read a dataset reference and filter it with `cfc` when it is unfiltered and the rate
 * allows (cfc 0: never) */
static mcs_status read_ref(inj_ctx *c, const char *dpath, int cfc, an_signal *s)
{
    char ref[4400];
    snprintf(ref, sizeof ref, "%s:%s", c->path, dpath);
    mcs_status st = an_signal_read_ref(ref, s, c->err);
    if (st || s->cfc > 0 || cfc <= 0) return st;
    mcs_error e2 = {0};
    if (an_cfc_signal(s, cfc, &e2) != MCS_OK) s->cfc = 0; /* too coarse or uneven: as is */
    return MCS_OK;
}

static mcs_status read_chan(inj_ctx *c, const char *name, int cfc, an_signal *s)
{
    char p[256];
    snprintf(p, sizeof p, "/stage%d/channels/%s", c->stage, name);
    return read_ref(c, p, cfc, s);
}

/* three channels prefix_<x y z suffix>, or a body's acceleration columns; *found = 0 if none */
static mcs_status read_triplet(inj_ctx *c, const char *prefix, const char *const sfx[3],
                               const char *const bodies[], int cfc, an_signal s[3], char *desc,
                               size_t ndesc, int *found)
{
    char names[3][64];
    *found = 0;
    int all = 1;
    for (int k = 0; k < 3; k++) {
        snprintf(names[k], sizeof names[k], "%s_%s", prefix, sfx[k]);
        all &= chan_exists(c, names[k]);
    }
    if (all) {
        for (int k = 0; k < 3; k++) {
            mcs_status st = read_chan(c, names[k], cfc, &s[k]);
            if (st) return st;
        }
        snprintf(desc, ndesc, "%s_%s/%s/%s", prefix, sfx[0], sfx[1], sfx[2]);
        *found = 1;
        return MCS_OK;
    }
    for (int b = 0; bodies && bodies[b]; b++) {
        char p[256];
        snprintf(p, sizeof p, "/stage%d/bodies/%s/acceleration", c->stage, bodies[b]);
        if (mcs_results_kind(c->r, p) != MCS_RES_DATASET) continue;
        for (int k = 0; k < 3; k++) {
            char q[300];
            snprintf(q, sizeof q, "%s[%d]", p, k);
            mcs_status st = read_ref(c, q, cfc, &s[k]);
            if (st) return st;
        }
        snprintf(desc, ndesc, "bodies/%s/acceleration", bodies[b]);
        *found = 1;
        return MCS_OK;
    }
    return MCS_OK;
}

static void free3(an_signal s[3])
{
    for (int k = 0; k < 3; k++) an_signal_free(&s[k]);
}

static mcs_status add_row(inj_ctx *c, const char *key, const char *label, double value,
                          const char *unit, double t1, double t2, const char *channel, int cfc)
{
    if (c->n == c->cap) {
        int nc = c->cap ? 2 * c->cap : 16;
        an_injury_row *p = realloc(c->rows, (size_t)nc * sizeof *p);
        if (!p) return MCS_ERR(c->err, MCS_ERR_NOMEM, "injury: out of memory");
        c->rows = p, c->cap = nc;
    }
    an_injury_row *r = &c->rows[c->n++];
    memset(r, 0, sizeof *r);
    const an_limit *l = an_limit_find_dummy(key, c->dummy);
    snprintf(r->key, sizeof r->key, "%s", key);
    snprintf(r->label, sizeof r->label, "%s", label ? label : l ? l->label : key);
    snprintf(r->unit, sizeof r->unit, "%s", unit);
    snprintf(r->channel, sizeof r->channel, "%s", channel);
    r->value = value, r->t1 = t1, r->t2 = t2, r->cfc = cfc;
    r->limit = l ? l->limit : NAN;
    r->fraction = l ? value / l->limit : NAN;
    return MCS_OK;
}

/* resultant acceleration criteria of a region: HIC15/36 (head only) and a3ms */
static mcs_status region_accel(inj_ctx *c, const char *prefix, const char *const bodies[],
                               int cfc, int head, const char *a3_key, const char *a3_label)
{
    static const char *const sfx[3] = {"ax", "ay", "az"};
    an_signal s[3] = {0};
    char desc[96];
    int found;
    mcs_status st = read_triplet(c, prefix, sfx, bodies, cfc, s, desc, sizeof desc, &found);
    if (st || !found) {
        free3(s);
        return st;
    }
    int n = s[0].n;
    double *res = malloc((size_t)n * sizeof(double));
    if (!res || s[1].n != n || s[2].n != n) {
        free(res), free3(s);
        return MCS_ERR(c->err, res ? MCS_ERR_FORMAT : MCS_ERR_NOMEM, "injury: %s: %s", c->path,
                       res ? "channels of different lengths" : "out of memory");
    }
    an_resultant(s[0].y, s[1].y, s[2].y, n, res);
    int used = s[0].cfc;
    if (head) {
        an_hic_result h;
        st = an_hic(s[0].t, res, n, 0.015, &h, c->err);
        if (!st) st = add_row(c, "hic15", NULL, h.hic, "-", h.t1, h.t2, desc, used);
        if (!st) st = an_hic(s[0].t, res, n, 0.036, &h, c->err);
        if (!st) st = add_row(c, "hic36", NULL, h.hic, "-", h.t1, h.t2, desc, used);
    }
    an_a3ms_result a;
    if (!st && s[0].t[n - 1] - s[0].t[0] >= 0.003) {
        st = an_a3ms(s[0].t, res, n, 0.003, &a, c->err);
        if (!st) st = add_row(c, a3_key, a3_label, a.level / AN_G0, "g", a.t1, a.t2, desc, used);
    }
    free(res), free3(s);
    return st;
}

static mcs_status head_rotation(inj_ctx *c)
{
    static const char *const sfx[3] = {"wx", "wy", "wz"};
    an_signal s[3] = {0};
    char desc[96];
    int found;
    mcs_status st = read_triplet(c, "head", sfx, NULL, 0, s, desc, sizeof desc, &found);
    if (!st && found) {
        an_bric_opts o = an_bric_opts_default();
        double b;
        st = an_bric(s[0].y, s[1].y, s[2].y, s[0].n, &o, &b, c->err);
        if (!st) st = add_row(c, "bric", NULL, b, "-", s[0].t[0], s[0].t[s[0].n - 1], desc, 0);
    }
    free3(s);
    return st;
}

static mcs_status neck(inj_ctx *c)
{
    static const char *const sfx[3] = {"fx", "fz", "my"};
    an_signal s[3] = {0};
    char desc[96];
    int found;
    mcs_status st = read_triplet(c, "neck", sfx, NULL, 600, s, desc, sizeof desc, &found);
    if (st || !found) {
        free3(s);
        return st;
    }
    an_nij_opts o = an_nij_opts_dummy(c->dummy);
    an_nij_result r;
    an_neck_peaks p;
    int n = s[0].n, cfc = s[0].cfc;
    const double *t = s[0].t, *fx = s[0].y, *fz = s[1].y, *my = s[2].y;
    st = an_nij(t, fx, fz, my, n, &o, &r, c->err);
    if (!st) {
        char lab[48];
        snprintf(lab, sizeof lab, "Nij (%s)", an_nij_mode_name(r.mode));
        st = add_row(c, "nij", lab, r.nij, "-", r.time, r.time, desc, cfc);
    }
    if (!st) st = an_neck_peaks_compute(fx, fz, my, n, o.condyle_offset, &p, c->err);
    /* times of the peaks */
    int it = 0, ic = 0, ie = 0, is = 0;
    for (int i = 0; i < n; i++) {
        double moc = my[i] - o.condyle_offset * fx[i];
        if (fz[i] > fz[it]) it = i;
        if (-fz[i] > -fz[ic]) ic = i;
        if (-moc > -(my[ie] - o.condyle_offset * fx[ie])) ie = i;
        if (fabs(fx[i]) > fabs(fx[is])) is = i;
    }
    if (!st) st = add_row(c, "neck_tension", NULL, p.fz_tension, "N", t[it], t[it], desc, cfc);
    if (!st)
        st = add_row(c, "neck_compression", NULL, p.fz_compression, "N", t[ic], t[ic], desc, cfc);
    if (!st)
        st = add_row(c, "neck_extension", "Neck extension M_oc", p.my_extension, "N*m", t[ie],
                     t[ie], desc, cfc);
    if (!st)
        st = add_row(c, "neck_shear", NULL, fmax(p.fx_max, -p.fx_min), "N", t[is], t[is], desc,
                     cfc);
    free3(s);
    return st;
}

static mcs_status chest_deflection(inj_ctx *c)
{
    if (!chan_exists(c, "chest_d")) return MCS_OK;
    an_signal d = {0};
    mcs_status st = read_chan(c, "chest_d", 180, &d);
    if (st) return st;
    int k;
    double peak = an_peak_abs(d.y, d.n, &k);
    st = add_row(c, "chest_deflection", NULL, peak, "m", d.t[k], d.t[k], "chest_d", d.cfc);
    double dt;
    if (!st && d.n >= 5 && an_signal_uniform(&d, 1e-6, &dt)) {
        an_vc_opts o = an_vc_opts_hybrid3_50m();
        double v, tv;
        st = an_vc(d.t, d.y, d.n, &o, &v, &tv, NULL, c->err);
        if (!st) st = add_row(c, "vc", NULL, v, "m/s", tv, tv, "chest_d", d.cfc);
    }
    an_signal_free(&d);
    return st;
}

static mcs_status femur(inj_ctx *c)
{
    static const char *const names[2] = {"femur_left_fz", "femur_right_fz"};
    double best = -1, tb = 0;
    int cfc = 0;
    const char *which = NULL;
    for (int k = 0; k < 2; k++) {
        if (!chan_exists(c, names[k])) continue;
        an_signal s = {0};
        mcs_status st = read_chan(c, names[k], 600, &s);
        if (st) return st;
        int i;
        double v = an_femur_compression(s.y, s.n, &i);
        if (v > best) best = v, tb = s.t[i], which = names[k], cfc = s.cfc;
        an_signal_free(&s);
    }
    if (!which) return MCS_OK;
    return add_row(c, "femur_compression", NULL, best, "N", tb, tb, which, cfc);
}

static mcs_status tibia(inj_ctx *c)
{
    static const char *const sides[2] = {"tibia_left", "tibia_right"};
    static const char *const sfx[3] = {"mx", "my", "fz"};
    double best = -1, tb = 0;
    int cfc = 0;
    char which[96] = "";
    for (int k = 0; k < 2; k++) {
        an_signal s[3] = {0};
        char desc[96];
        int found;
        mcs_status st = read_triplet(c, sides[k], sfx, NULL, 600, s, desc, sizeof desc, &found);
        if (!st && found) {
            an_ti_opts o = an_ti_opts_hybrid3_50m();
            double ti, t;
            st = an_tibia_index(s[0].t, s[0].y, s[1].y, s[2].y, s[0].n, &o, &ti, &t, c->err);
            if (!st && ti > best) {
                best = ti, tb = t, cfc = s[0].cfc;
                snprintf(which, sizeof which, "%s", desc);
            }
        }
        free3(s);
        if (st) return st;
    }
    if (best < 0) return MCS_OK;
    return add_row(c, "tibia_index", NULL, best, "-", tb, tb, which, cfc);
}

static int stage_present(mcs_results *r, int s)
{
    char p[64];
    snprintf(p, sizeof p, "/stage%d/channels", s);
    if (mcs_results_kind(r, p) == MCS_RES_GROUP) return 1;
    snprintf(p, sizeof p, "/stage%d/bodies", s);
    return mcs_results_kind(r, p) == MCS_RES_GROUP;
}

/* the dummy size: the `dummy` attribute of /stageN, else of /stage1, else the 50th male */
static mcs_status file_dummy(inj_ctx *c)
{
    char p[32];
    snprintf(p, sizeof p, "/stage%d", c->stage);
    if (!mcs_results_has_attr(c->r, p, "dummy")) snprintf(p, sizeof p, "/stage1");
    if (!mcs_results_has_attr(c->r, p, "dummy")) return MCS_OK;
    char *s = NULL;
    mcs_status st = mcs_results_attr_str(c->r, p, "dummy", &s, c->err);
    if (!st && an_dummy_parse(s, &c->dummy))
        st = MCS_ERR(c->err, MCS_ERR_FORMAT, "%s: %s attribute dummy '%s' is none of %s", c->path,
                     p, s, AN_DUMMY_CHOICES);
    free(s);
    return st;
}

mcs_status an_injury_evaluate(const char *h5_path, int stage, an_injury_row **rows, int *n,
                              int *stage_used, mcs_error *err)
{
    an_dummy d;
    return an_injury_evaluate_as(h5_path, stage, -1, rows, n, stage_used, &d, err);
}

mcs_status an_injury_evaluate_as(const char *h5_path, int stage, int dummy, an_injury_row **rows,
                                 int *n, int *stage_used, an_dummy *dummy_used, mcs_error *err)
{
    *rows = NULL, *n = 0, *stage_used = stage, *dummy_used = AN_DUMMY_H3_50M;
    inj_ctx c = {.path = h5_path, .stage = stage, .err = err};
    mcs_status st = mcs_results_open(&c.r, h5_path, err);
    if (st) return st;
    if (stage == AN_STAGE_AUTO)
        for (int s = 3; s >= 1 && c.stage < 1; s--)
            if (stage_present(c.r, s)) c.stage = s;
    if (c.stage < 0 || c.stage > 3 || !stage_present(c.r, c.stage)) {
        int s = stage >= 0 ? stage : 1;
        st = MCS_ERR(err, MCS_ERR_KEY, "%s: no /stage%d/channels or /stage%d/bodies", h5_path, s,
                     s);
        mcs_results_close(&c.r);
        return st;
    }
    if (dummy >= 0 && dummy < AN_NDUMMY) c.dummy = (an_dummy)dummy;
    else st = file_dummy(&c);
    if (st) {
        mcs_results_close(&c.r);
        return st;
    }
    static const char *const head_b[] = {"head", NULL};
    static const char *const chest_b[] = {"chest", "thorax", "torso", NULL};
    static const char *const pelvis_b[] = {"pelvis", NULL};
    st = region_accel(&c, "head", head_b, 1000, 1, "head_a3ms", NULL);
    if (!st) st = head_rotation(&c);
    if (!st) st = neck(&c);
    if (!st) st = region_accel(&c, "chest", chest_b, 180, 0, "chest_a3ms", NULL);
    if (!st) st = chest_deflection(&c);
    if (!st) st = region_accel(&c, "pelvis", pelvis_b, 1000, 0, "pelvis_a3ms", "Pelvis a3ms");
    if (!st) st = femur(&c);
    if (!st) st = tibia(&c);
    mcs_results_close(&c.r);
    if (st) {
        free(c.rows);
        return st;
    }
    *rows = c.rows, *n = c.n, *stage_used = c.stage, *dummy_used = c.dummy;
    return MCS_OK;
}

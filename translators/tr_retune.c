/* tr_retune.c: the retune fit (tr_retune.h, docs/retune.md). Each residual evaluation is a
 * whole stage-1 run of the scenario with the trial characteristics merged over it by name
 * (a scenario text that includes the scenario and gives `characteristics:` again). */
#include "translators/tr_retune.h"

#include "analysis/an_cfc.h"
#include "analysis/an_iso18571.h"
#include "core/mcs_results.h"
#include "core/mcs_scenario.h"
#include "stage1_mb/mb_model.h"
#include "translators/tr_lm.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

tr_rt_opts tr_rt_opts_default(void)
{
    return (tr_rt_opts){.wall_body = "barrier",
                        .joint = "moto_fork_deformation",
                        .tyre_char = "tyre_front",
                        .fork_char = "fork_deformation",
                        .cfc = 60,
                        .dt = 1e-4,
                        .free_mask = 0xf};
}

const char *tr_rt_par_name(int i)
{
    static const char *const n[TR_RT_NPAR] = {"tyre_force_scale", "fork_moment_scale",
                                              "fork_elastic_limit", "fork_stop_angle"};
    return i >= 0 && i < TR_RT_NPAR ? n[i] : "?";
}

/* bounds (docs/retune.md "Parameters"): scales 0.5..2; elastic limit 0.03..0.11 rad; stop
 * 0.12..0.35 rad, so the stop always lies beyond the elastic limit */
static const double par_lo[TR_RT_NPAR] = {0.5, 0.5, 0.03, 0.12};
static const double par_hi[TR_RT_NPAR] = {2.0, 2.0, 0.11, 0.35};

void tr_rt_target_free(tr_rt_target *t)
{
    free(t->t), free(t->force), free(t->angle);
    *t = (tr_rt_target){0};
}

static mcs_status read1(mcs_results *h, const char *h5, const char *path, mcs_array *a,
                        mcs_error *err)
{
    if (!mcs_results_exists(h, path))
        return MCS_ERR(err, MCS_ERR_KEY,
                       "%s: %s: not in the results file (retune needs the "
                       "stage-3 wall force and fork angle, docs/retune.md)",
                       h5, path);
    return mcs_results_read(h, path, a, err);
}

mcs_status tr_rt_read_target(const char *h5, const char *joint, tr_rt_target *t, mcs_error *err)
{
    *t = (tr_rt_target){0};
    mcs_results *h = NULL;
    mcs_status st = mcs_results_open(&h, h5, err);
    if (st) return st;
    mcs_array at = {0}, aa = {0}, af = {0};
    char path[512], **walls = NULL;
    int nw = 0;
    /* a generated motorcycle's fork angle is a channel named as stage 1's (stage3_fe/
     * s3_wallcase.h); a keyword deck's joint is a joint */
    snprintf(path, sizeof path, "/stage3/channels/%s_angle", joint);
    if (!mcs_results_exists(h, path)) snprintf(path, sizeof path, "/stage3/joints/%s/angle", joint);
    st = read1(h, h5, "/stage3/time", &at, err);
    if (!st) st = read1(h, h5, path, &aa, err);
    if (!st && !mcs_results_exists(h, "/stage3/rigidwall"))
        st = MCS_ERR(err, MCS_ERR_KEY,
                     "%s: /stage3/rigidwall: not in the results file "
                     "(retune needs the stage-3 wall force, docs/retune.md)",
                     h5);
    /* the impact wall alone when stage 3 named it (not the ground), else every wall */
    if (!st && mcs_results_has_attr(h, "/stage3/rigidwall", "impact_wall")) {
        walls = calloc(1, sizeof *walls);
        if (!walls) st = MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
        if (!st) st = mcs_results_attr_str(h, "/stage3/rigidwall", "impact_wall", &walls[0], err);
        nw = st ? 0 : 1;
    } else if (!st)
        st = mcs_results_list(h, "/stage3/rigidwall", &walls, &nw, err);
    if (!st && nw == 0) st = MCS_ERR(err, MCS_ERR_KEY, "%s: /stage3/rigidwall: no wall in it", h5);
    int nt = st ? 0 : (int)at.n;
    if (!st && (nt < 10 || aa.n != at.n))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s: %zu values for %d times (at least 10)", h5, path,
                     aa.n, nt);
    if (!st) {
        t->nt = nt;
        t->t = malloc((size_t)nt * sizeof(double));
        t->angle = malloc((size_t)nt * sizeof(double));
        t->force = calloc((size_t)nt, sizeof(double));
        if (!t->t || !t->angle || !t->force) st = MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    }
    if (!st) {
        memcpy(t->t, at.v, (size_t)nt * sizeof(double));
        memcpy(t->angle, aa.v, (size_t)nt * sizeof(double));
    }
    for (int w = 0; w < nw && !st; w++) {
        snprintf(path, sizeof path, "/stage3/rigidwall/%s/force_mean", walls[w]);
        if (!mcs_results_exists(h, path)) /* a penalty wall's interval mean, else the force */
            snprintf(path, sizeof path, "/stage3/rigidwall/%s/force", walls[w]);
        st = read1(h, h5, path, &af, err);
        if (!st && af.n != (size_t)nt)
            st =
                MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s: %zu values for %d times", h5, path, af.n, nt);
        for (int i = 0; i < nt && !st; i++)
            t->force[i] += af.v[i];
        mcs_array_free(&af);
    }
    mcs_results_list_free(&walls, nw);
    mcs_array_free(&at), mcs_array_free(&aa);
    mcs_results_close(&h);
    if (st) tr_rt_target_free(t);
    return st;
}

static mcs_status read_curve(const char *file, const mcs_node *ch, const char *name, double *x,
                             double *y, int *n, mcs_error *err)
{
    const mcs_node *c = ch ? mcs_node_get(ch, name) : NULL;
    const mcs_node *l = c ? mcs_node_get(c, "loading") : NULL;
    if (!l)
        return MCS_ERR(err, MCS_ERR_KEY,
                       "%s: characteristics.%s.loading: not in the scenario "
                       "(retune fits it, docs/retune.md)",
                       file, name);
    *n = mcs_node_curve_len(l);
    if (*n < 2 || *n > TR_RT_MAXPT)
        return mcs_node_error(l, err, MCS_ERR_RANGE,
                              "characteristics.%s.loading: %d points "
                              "(retune takes 2 to %d)",
                              name, *n, TR_RT_MAXPT);
    return mcs_node_curve(l, x, y, TR_RT_MAXPT, err);
}

mcs_status tr_rt_read_base(const tr_rt_opts *o, tr_rt_base *b, mcs_error *err)
{
    *b = (tr_rt_base){0};
    mcs_scenario *scn = NULL;
    mcs_status st = mcs_scenario_load(o->scenario, &scn, err);
    if (st) return st;
    const mcs_node *ch = mcs_node_get(mcs_scenario_root(scn), "characteristics");
    double fx[TR_RT_MAXPT], fy[TR_RT_MAXPT];
    int nf = 0;
    st = read_curve(o->scenario, ch, o->tyre_char, b->tyre_x, b->tyre_y, &b->ntyre, err);
    if (!st) st = read_curve(o->scenario, ch, o->fork_char, fx, fy, &nf, err);
    if (!st && (nf < 3 || fx[0] != 0 || fy[0] != 0 || !(fy[2] >= fy[1])))
        st = MCS_ERR(err, MCS_ERR_RANGE,
                     "%s: characteristics.%s.loading: retune takes an "
                     "elastic-plastic moment curve [[0, 0], [phi_e, M_e], [phi_stop, M_p], "
                     "[stop...]] (docs/retune.md)",
                     o->scenario, o->fork_char);
    if (!st) {
        b->phi_e = fx[1], b->m_e = fy[1], b->phi_s = fx[2], b->m_p = fy[2];
        b->k_stop = nf > 3 ? (fy[3] - fy[2]) / (fx[3] - fx[2]) : 3e6;
    }
    mcs_scenario_destroy(&scn);
    return st;
}

/* the fork curve at p: {0, phi_e, phi_s, phi_s + 0.02} */
static void fork_curve(const tr_rt_base *b, const double *p, double x[4], double y[4])
{
    x[0] = 0, y[0] = 0;
    x[1] = p[2], y[1] = p[1] * b->m_e;
    x[2] = p[3], y[2] = p[1] * b->m_p;
    x[3] = p[3] + 0.02, y[3] = y[2] + b->k_stop * 0.02;
}

void tr_rt_write_yaml(FILE *f, const tr_rt_opts *o, const tr_rt_base *b, const double *p)
{
    fprintf(f, "characteristics:\n  %s:\n    loading: [", o->tyre_char);
    for (int i = 0; i < b->ntyre; i++)
        fprintf(f, "%s[%.9g, %.9g]", i ? ", " : "", b->tyre_x[i], p[0] * b->tyre_y[i]);
    double x[4], y[4];
    fork_curve(b, p, x, y);
    fprintf(f, "]\n  %s:\n    loading: [", o->fork_char);
    for (int i = 0; i < 4; i++)
        fprintf(f, "%s[%.9g, %.9g]", i ? ", " : "", x[i], y[i]);
    fprintf(f, "]\n    unloading_slope: %.9g\n    elastic_limit: %.9g\n", y[1] / x[1], x[1]);
}

/* linear interpolation of (tx, ty)[n] at t (held beyond the ends) */
static double interp(const double *tx, const double *ty, long n, double t)
{
    if (t <= tx[0]) return ty[0];
    if (t >= tx[n - 1]) return ty[n - 1];
    long lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        long mid = (lo + hi) / 2;
        if (tx[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    double w = (t - tx[lo]) / (tx[hi] - tx[lo]);
    return ty[lo] + w * (ty[hi] - ty[lo]);
}

static mcs_status filter(double *v, int n, double dt, double cfc, mcs_error *err)
{
    if (cfc <= 0) return MCS_OK;
    double *y = malloc((size_t)n * sizeof(double));
    if (!y) return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    mcs_status st = an_cfc_filter(v, n, dt, cfc, y, err);
    if (!st) memcpy(v, y, (size_t)n * sizeof(double));
    free(y);
    return st;
}

static mcs_status sample(const tr_rt_opts *o, const mb_model *m, const mb_state *s, int nt,
                         double dt, double *force, double *angle, mcs_error *err)
{
    int wb = mb_model_body(m, o->wall_body), jr = -1, nch = mb_channels_count(m);
    for (int i = 0; i < m->nrestraint1; i++)
        if (!strcmp(m->joint[m->restraint1[i].joint].name, o->joint)) jr = i;
    if (wb < 0)
        return MCS_ERR(err, MCS_ERR_KEY, "%s: bodies: no body %s (the wall)", o->scenario,
                       o->wall_body);
    if (jr < 0)
        return MCS_ERR(err, MCS_ERR_KEY, "%s: joints: no restrained joint %s (the fork hinge)",
                       o->scenario, o->joint);
    long n = s->nrec;
    double *cf = calloc((size_t)n, sizeof(double)), *ca = malloc((size_t)n * sizeof(double));
    if (!cf || !ca) {
        free(cf), free(ca);
        return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    }
    for (long k = 0; k < n; k++) {
        const double *row = s->rec_chan + (size_t)k * (size_t)nch;
        for (int c = 0; c < m->ncontact; c++)
            if (m->contact[c].body_a == wb || m->contact[c].body_b == wb) cf[k] += row[3 * c];
        ca[k] = row[3 * m->ncontact + 2 * jr];
    }
    for (int i = 0; i < nt; i++) {
        force[i] = interp(s->rec_t, cf, n, i * dt);
        angle[i] = interp(s->rec_t, ca, n, i * dt);
    }
    free(cf), free(ca);
    mcs_status st = filter(force, nt, dt, o->cfc, err);
    return st ? st : filter(angle, nt, dt, o->cfc, err);
}

mcs_status tr_rt_stage1(const tr_rt_opts *o, const tr_rt_base *b, const double *p, int nt,
                        double dt, double *force, double *angle, mcs_error *err)
{
    char *real = realpath(o->scenario, NULL), *text = NULL;
    if (!real) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot resolve its path", o->scenario);
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f) {
        free(real);
        return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    }
    fprintf(f, "mcrash: 1\ninclude: [\"%s\"]\nsimulation: {end_time: %.9g}\n", real,
            (nt - 1) * dt + 1e-9);
    tr_rt_write_yaml(f, o, b, p);
    fclose(f);
    mcs_scenario *scn = NULL;
    mb_model *m = NULL;
    mb_state *s = NULL;
    /* named beside the scenario (its own name would be an include cycle) */
    char name[PATH_MAX + 32];
    snprintf(name, sizeof name, "%s.retune.yaml", real);
    mcs_status st = mcs_scenario_load_text(name, text, len, &scn, err);
    if (!st) st = mb_model_build(scn, NULL, &m, err);
    if (!st) st = mb_state_create(m, &s, err);
    while (!st && s->step < m->nsteps)
        st = mb_step(m, s, err);
    if (!st) st = sample(o, m, s, nt, dt, force, angle, err);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);
    free(text), free(real);
    return st;
}

/* the fit's context: the target on the grid and which parameters are free */
typedef struct {
    const tr_rt_opts *o;
    const tr_rt_base *b;
    int nt, nfree, idx[TR_RT_NPAR];
    double dt, fscale, ascale, p[TR_RT_NPAR];
    const double *tf, *ta;
    double *sf, *sa;
} fit_ctx;

static mcs_status residuals(void *vc, const double *q, double *r, mcs_error *err)
{
    fit_ctx *c = vc;
    for (int j = 0; j < c->nfree; j++)
        c->p[c->idx[j]] = q[j];
    mcs_status st = tr_rt_stage1(c->o, c->b, c->p, c->nt, c->dt, c->sf, c->sa, err);
    double w = 1 / sqrt((double)c->nt);
    for (int i = 0; i < c->nt && !st; i++) {
        r[i] = w * (c->sf[i] - c->tf[i]) / c->fscale;
        r[c->nt + i] = w * (c->sa[i] - c->ta[i]) / c->ascale;
    }
    return st;
}

static mcs_status rate(const fit_ctx *c, double *rf, double *ra, mcs_error *err)
{
    an_iso_opts io = an_iso_opts_default();
    an_iso_result res;
    mcs_status st = an_iso18571_arrays(c->tf, c->sf, c->nt, c->dt, &io, &res, err);
    *rf = res.rating;
    if (!st) st = an_iso18571_arrays(c->ta, c->sa, c->nt, c->dt, &io, &res, err);
    *ra = res.rating;
    return st;
}

/* the start: the best of the scenario's parameters and a full factorial over the free ones
 * (7 levels each for up to two, else 3: the centres of equal parts of each range), since the
 * objective has local minima (a stage-1 run is non-smooth in its parameters: contacts open and
 * close) */
static mcs_status scan_start(fit_ctx *c, double *q, const double *lo, const double *hi, double *rr,
                             int *nrun, mcs_error *err)
{
    double best = 0, trial[TR_RT_NPAR], qb[TR_RT_NPAR];
    int m = 2 * c->nt, ncomb = 1;
    for (int i = 0; i < m; i++)
        best += rr[i] * rr[i]; /* rr: the residuals at q */
    memcpy(qb, q, (size_t)c->nfree * sizeof(double));
    int lev = c->nfree <= 2 ? 7 : 3;
    for (int j = 0; j < c->nfree; j++)
        ncomb *= lev;
    mcs_status st = MCS_OK;
    for (int k = 0; k < ncomb && !st; k++) {
        for (int j = 0, kk = k; j < c->nfree; j++, kk /= lev)
            trial[j] = lo[j] + (1 + 2 * (kk % lev)) / (2.0 * lev) * (hi[j] - lo[j]);
        st = residuals(c, trial, rr, err);
        (*nrun)++;
        double s = 0;
        for (int i = 0; i < m; i++)
            s += rr[i] * rr[i];
        if (!st && s < best) best = s, memcpy(qb, trial, (size_t)c->nfree * sizeof(double));
    }
    memcpy(q, qb, (size_t)c->nfree * sizeof(double));
    return st;
}

mcs_status tr_rt_fit(const tr_rt_opts *o, const tr_rt_base *b, const tr_rt_target *t,
                     tr_rt_result *r, mcs_error *err)
{
    *r = (tr_rt_result){0};
    double p0[TR_RT_NPAR] = {1, 1, b->phi_e, b->phi_s};
    fit_ctx c = {.o = o, .b = b, .dt = o->dt};
    for (int i = 0; i < TR_RT_NPAR; i++) {
        r->p0[i] = r->p[i] = c.p[i] = p0[i];
        r->lo[i] = par_lo[i], r->hi[i] = par_hi[i];
        if (o->free_mask & (1 << i)) c.idx[c.nfree++] = i;
    }
    double T = t->t[t->nt - 1] - t->t[0];
    if (o->end_time > 0 && o->end_time < T) T = o->end_time;
    c.nt = (int)floor(T / c.dt + 1e-9) + 1;
    if (c.nt < 10) return MCS_ERR(err, MCS_ERR_RANGE, "retune: %.3g s of target: too short", T);
    size_t nt = (size_t)c.nt;
    double *buf = calloc(4 * nt + 2 * nt, sizeof(double));
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    double *tf = buf, *ta = tf + nt;
    c.tf = tf, c.ta = ta, c.sf = ta + nt, c.sa = c.sf + nt;
    double *res = c.sa + nt;
    for (int i = 0; i < c.nt; i++) {
        tf[i] = interp(t->t, t->force, t->nt, t->t[0] + i * c.dt);
        ta[i] = interp(t->t, t->angle, t->nt, t->t[0] + i * c.dt);
    }
    mcs_status st = filter(tf, c.nt, c.dt, o->cfc, err);
    if (!st) st = filter(ta, c.nt, c.dt, o->cfc, err);
    for (int i = 0; i < c.nt; i++)
        c.fscale = fmax(c.fscale, fabs(tf[i])), c.ascale = fmax(c.ascale, fabs(ta[i]));
    if (!st && (!(c.fscale > 0) || !(c.ascale > 0)))
        st = MCS_ERR(err, MCS_ERR_RANGE,
                     "retune: the target's wall force or fork angle is "
                     "zero throughout");
    double q[TR_RT_NPAR], lo[TR_RT_NPAR], hi[TR_RT_NPAR];
    for (int j = 0; j < c.nfree; j++)
        q[j] = p0[c.idx[j]], lo[j] = par_lo[c.idx[j]], hi[j] = par_hi[c.idx[j]];
    double *rr = malloc(2 * nt * sizeof(double));
    if (!rr) st = MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    if (!st) st = residuals(&c, q, rr, err);
    if (!st) st = rate(&c, &r->iso_force0, &r->iso_angle0, err);
    int nscan = 0;
    if (!st) st = scan_start(&c, q, lo, hi, rr, &nscan, err);
    tr_lm_result lr = {0};
    tr_lm_opts lo_ = tr_lm_opts_default();
    lo_.fd_rel = 1e-3, lo_.max_iter = 30, lo_.ftol = 1e-8;
    if (!st && c.nfree > 0)
        st = tr_lm_solve(residuals, &c, c.nfree, 2 * c.nt, q, lo, hi, &lo_, &lr, err);
    if (!st) {
        for (int j = 0; j < c.nfree; j++)
            r->p[c.idx[j]] = q[j];
        st = residuals(&c, q, rr, err);
    }
    if (!st) st = rate(&c, &r->iso_force, &r->iso_angle, err);
    r->cost0 = lr.cost0, r->cost = lr.cost, r->iter = lr.iter, r->nfev = lr.nfev + nscan + 2;
    r->why = lr.why ? lr.why : "nothing to fit";
    (void)res;
    free(rr);
    free(buf);
    return st;
}

mcs_status tr_rt_write_curves(const char *h5, const tr_rt_opts *o, const tr_rt_base *b,
                              const double *p, mcs_error *err)
{
    mcs_results *r = NULL;
    mcs_status st = mcs_results_append(&r, h5, err);
    if (st) return st;
    double xy[2 * TR_RT_MAXPT], x[4], y[4];
    char path[256];
    size_t dims[2] = {(size_t)b->ntyre, 2};
    for (int i = 0; i < b->ntyre; i++)
        xy[2 * i] = b->tyre_x[i], xy[2 * i + 1] = p[0] * b->tyre_y[i];
    snprintf(path, sizeof path, "/curves/%s/loading", o->tyre_char);
    st = mcs_results_write(r, path, 2, dims, xy, "m, N", err);
    /* the tyre unloads along its loading curve within its elastic range: unloading = loading
     * there; written as the loading curve (the scenario's unloading_slope is kept) */
    snprintf(path, sizeof path, "/curves/%s/unloading", o->tyre_char);
    if (!st) st = mcs_results_write(r, path, 2, dims, xy, "m, N", err);
    fork_curve(b, p, x, y);
    for (int i = 0; i < 4; i++)
        xy[2 * i] = x[i], xy[2 * i + 1] = y[i];
    dims[0] = 4;
    snprintf(path, sizeof path, "/curves/%s/loading", o->fork_char);
    if (!st) st = mcs_results_write(r, path, 2, dims, xy, "rad, N m", err);
    /* unloading from the elastic limit at the elastic slope down to zero moment */
    double ue[4] = {0, 0, x[1], y[1]};
    dims[0] = 2;
    snprintf(path, sizeof path, "/curves/%s/unloading", o->fork_char);
    if (!st) st = mcs_results_write(r, path, 2, dims, ue, "rad, N m", err);
    if (!st) st = mcs_results_commit(&r, err);
    mcs_results_abort(&r);
    return st;
}

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
#include "translators/tr_pool.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

tr_rt_opts tr_rt_opts_default(void)
{
    tr_rt_opts o = {.cfc = 60, .dt = 1e-4, .free_mask = 0xf, .scan = 1};
    snprintf(o.wall_body, sizeof o.wall_body, "barrier");
    snprintf(o.joint, sizeof o.joint, "moto_fork_deformation");
    snprintf(o.tyre_char, sizeof o.tyre_char, "tyre_front");
    snprintf(o.fork_char, sizeof o.fork_char, "fork_deformation");
    return o;
}

const char *tr_rt_par_name(int i)
{
    static const char *const n[TR_RT_NPAR] = {
        "tyre_force_scale", "fork_moment_scale", "fork_elastic_limit",
        "fork_stop_angle",  "rim_force_scale",   "fork_stop_stiffness"};
    return i >= 0 && i < TR_RT_NPAR ? n[i] : "?";
}

int tr_rt_par_index(const char *name)
{
    for (int i = 0; name && i < TR_RT_NPAR; i++)
        if (!strcmp(name, tr_rt_par_name(i))) return i;
    return -1;
}

/* a string key of the retune: block into dst */
static void get_str(const mcs_node *blk, const char *key, char *dst, size_t n)
{
    const char *v = mcs_node_str(mcs_node_get(blk, key));
    if (v) snprintf(dst, n, "%s", v);
}

mcs_status tr_rt_read_opts(tr_rt_opts *o, mcs_error *err)
{
    mcs_scenario *scn = NULL;
    mcs_status st = mcs_scenario_load(o->scenario, &scn, err);
    if (st) return st;
    const mcs_node *blk = mcs_node_get(mcs_scenario_root(scn), "retune");
    if (blk) {
        get_str(blk, "wall_body", o->wall_body, sizeof o->wall_body);
        get_str(blk, "joint", o->joint, sizeof o->joint);
        get_str(blk, "tyre", o->tyre_char, sizeof o->tyre_char);
        get_str(blk, "fork", o->fork_char, sizeof o->fork_char);
        get_str(blk, "target_force", o->target_force, sizeof o->target_force);
        get_str(blk, "target_angle", o->target_angle, sizeof o->target_angle);
        o->end_time = mcs_node_num_or(blk, "end_time", o->end_time);
        const mcs_node *fr = mcs_node_get(blk, "free");
        if (fr && mcs_node_kind(fr) != MCS_NODE_SEQ)
            st = mcs_node_error(fr, err, MCS_ERR_TYPE, "retune.free: a list of parameter names");
        if (fr && !st) o->free_mask = 0;
        for (int i = 0; fr && !st && i < mcs_node_len(fr); i++) {
            const mcs_node *it = mcs_node_at(fr, i);
            int k = tr_rt_par_index(mcs_node_str(it));
            if (k < 0)
                st = mcs_node_error(it, err, MCS_ERR_RANGE,
                                    "retune.free: unknown parameter (tyre_force_scale, "
                                    "fork_moment_scale, fork_elastic_limit, fork_stop_angle, "
                                    "rim_force_scale, fork_stop_stiffness)");
            else
                o->free_mask |= 1 << k;
        }
    }
    mcs_scenario_destroy(&scn);
    return st;
}

/* bounds (docs/retune.md "Parameters"): scales 0.5..2; elastic limit 0.03..0.11 rad; stop
 * 0.12..0.35 rad, so the stop always lies beyond the elastic limit; stop stiffness 3e4..3e6
 * N m/rad, fitted as its logarithm (par_log: two decades) */
static const double par_lo[TR_RT_NPAR] = {0.5, 0.5, 0.03, 0.12, 0.5, 3e4};
static const double par_hi[TR_RT_NPAR] = {2.0, 2.0, 0.11, 0.35, 2.0, 3e6};
static const int par_log[TR_RT_NPAR] = {0, 0, 0, 0, 0, 1};

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

/* the target's wall force: o->target_force, a dataset, or a group whose members' `force` are
 * summed. By default (""): the wall named by the attribute impact_wall of /stage3/rigidwall (a
 * generated motorcycle's run, stage3_fe/s3_wallcase.h), its force_mean (a penalty wall's
 * interval mean) or force, else every wall's force summed */
static mcs_status read_force(mcs_results *h, const char *h5, const char *fp, tr_rt_target *t,
                             mcs_error *err)
{
    const char *grp = fp[0] ? fp : "/stage3/rigidwall";
    char **walls = NULL, path[1024];
    int nw = 0;
    mcs_array af = {0};
    mcs_res_kind kind = mcs_results_kind(h, grp);
    mcs_status st = MCS_OK;
    if (kind == MCS_RES_NONE)
        return MCS_ERR(err, MCS_ERR_KEY,
                       "%s: %s: not in the results file (retune needs the "
                       "stage-3 wall force, docs/retune.md)",
                       h5, grp);
    if (kind == MCS_RES_GROUP && !fp[0] && mcs_results_has_attr(h, grp, "impact_wall")) {
        walls = calloc(1, sizeof *walls);
        if (!walls) return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
        nw = 1;
        st = mcs_results_attr_str(h, grp, "impact_wall", &walls[0], err);
    } else if (kind == MCS_RES_GROUP) {
        st = mcs_results_list(h, grp, &walls, &nw, err);
        if (!st && nw == 0) st = MCS_ERR(err, MCS_ERR_KEY, "%s: %s: no wall in it", h5, grp);
    } else {
        nw = 1;
    }
    for (int w = 0; w < nw && !st; w++) {
        if (kind != MCS_RES_GROUP) {
            snprintf(path, sizeof path, "%s", grp);
        } else {
            snprintf(path, sizeof path, "%s/%s/force_mean", grp, walls[w]);
            if (fp[0] || !mcs_results_exists(h, path))
                snprintf(path, sizeof path, "%s/%s/force", grp, walls[w]);
        }
        st = read1(h, h5, path, &af, err);
        if (!st && af.n != (size_t)t->nt)
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s: %zu values for %d times", h5, path, af.n,
                         t->nt);
        for (int i = 0; i < t->nt && !st; i++)
            t->force[i] += af.v[i];
        mcs_array_free(&af);
    }
    mcs_results_list_free(&walls, nw);
    return st;
}

mcs_status tr_rt_read_target(const char *h5, const tr_rt_opts *o, tr_rt_target *t,
                             mcs_error *err)
{
    *t = (tr_rt_target){0};
    mcs_results *h = NULL;
    mcs_status st = mcs_results_open(&h, h5, err);
    if (st) return st;
    mcs_array at = {0}, aa = {0};
    char path[1024];
    /* by default a generated motorcycle's fork angle channel, named as stage 1's
     * (stage3_fe/s3_wallcase.h), else a keyword deck's joint */
    if (o->target_angle[0]) {
        snprintf(path, sizeof path, "%s", o->target_angle);
    } else {
        snprintf(path, sizeof path, "/stage3/channels/%s_angle", o->joint);
        if (!mcs_results_exists(h, path))
            snprintf(path, sizeof path, "/stage3/joints/%s/angle", o->joint);
    }
    st = read1(h, h5, "/stage3/time", &at, err);
    if (!st) st = read1(h, h5, path, &aa, err);
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
        st = read_force(h, h5, o->target_force, t, err);
    }
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
    /* the rim's share of the tyre curve: beyond its elastic limit (none: no rim part) */
    if (!st)
        b->tyre_xe = mcs_node_num_or(mcs_node_get(ch, o->tyre_char), "elastic_limit", INFINITY);
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
    x[3] = p[3] + 0.02, y[3] = y[2] + p[5] * 0.02;
}

/* the tyre curve's i-th force at p: p[0] times the scenario's, its rise beyond the elastic
 * limit x_e (the rim, the hub) times p[4] more: p0 (y(x_e) + p4 (y(x) - y(x_e))), monotone
 * when the scenario's curve is */
static double tyre_force(const tr_rt_base *b, const double *p, int i)
{
    double x = b->tyre_x[i], y = b->tyre_y[i];
    if (!(x > b->tyre_xe)) return p[0] * y;
    int k = 1;
    while (k < b->ntyre - 1 && b->tyre_x[k] < b->tyre_xe)
        k++;
    double x0 = b->tyre_x[k - 1], x1 = b->tyre_x[k];
    double ye = b->tyre_y[k - 1] + (b->tyre_y[k] - b->tyre_y[k - 1]) * (b->tyre_xe - x0) /
                                       (x1 - x0);
    return p[0] * (ye + p[4] * (y - ye));
}

void tr_rt_write_yaml(FILE *f, const tr_rt_opts *o, const tr_rt_base *b, const double *p)
{
    fprintf(f, "characteristics:\n  %s:\n    loading: [", o->tyre_char);
    for (int i = 0; i < b->ntyre; i++)
        fprintf(f, "%s[%.9g, %.9g]", i ? ", " : "", b->tyre_x[i], tyre_force(b, p, i));
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

/* one stage-1 run of a batch (tr_pool_fn): out = force[nt] then angle[nt] */
typedef struct {
    const tr_rt_opts *o;
    const tr_rt_base *b;
    const double *p;
    int nt;
    double dt;
} many_ctx;

static mcs_status one_case(void *vc, int k, void *out, mcs_error *err)
{
    const many_ctx *c = vc;
    double *f = out;
    return tr_rt_stage1(c->o, c->b, c->p + (size_t)k * TR_RT_NPAR, c->nt, c->dt, f, f + c->nt,
                        err);
}

mcs_status tr_rt_stage1_many(const tr_rt_opts *o, const tr_rt_base *b, int np, const double *p,
                             int nt, double dt, double *force, double *angle, mcs_error *err)
{
    size_t n = (size_t)nt;
    double *buf = malloc((size_t)np * 2 * n * sizeof(double));
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    many_ctx c = {.o = o, .b = b, .p = p, .nt = nt, .dt = dt};
    mcs_status st = tr_pool_run(one_case, &c, np, 2 * n * sizeof(double), buf, o->jobs, err);
    for (int k = 0; k < np && !st; k++) {
        memcpy(force + (size_t)k * n, buf + (size_t)k * 2 * n, n * sizeof(double));
        memcpy(angle + (size_t)k * n, buf + (size_t)k * 2 * n + n, n * sizeof(double));
    }
    free(buf);
    return st;
}

/* the fit's context: the target on the grid and which parameters are free */
typedef struct {
    const tr_rt_opts *o;
    const tr_rt_base *b;
    int nt, nfree, idx[TR_RT_NPAR], nrun;
    double dt, fscale, ascale, p[TR_RT_NPAR];
    const double *tf, *ta;
    double *sf, *sa; /* the last point's stage-1 force and angle [nt] */
} fit_ctx;

/* a parameter as the fit moves it (its logarithm where par_log), and back */
static double to_q(int i, double p)
{
    return par_log[i] ? log(p) : p;
}

static double to_p(int i, double q)
{
    return par_log[i] ? exp(q) : q;
}

/* residuals R[k x 2nt] at the k free-parameter points Q[k x nfree] (tr_lm_many_fn): the
 * stage-1 runs in parallel */
static mcs_status residuals_many(void *vc, int k, const double *Q, double *R, mcs_error *err)
{
    fit_ctx *c = vc;
    size_t nt = (size_t)c->nt;
    double *P = malloc((size_t)k * TR_RT_NPAR * sizeof(double));
    double *F = malloc((size_t)k * 2 * nt * sizeof(double)), *A = F ? F + (size_t)k * nt : NULL;
    mcs_status st = P && F ? MCS_OK : MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    for (int q = 0; q < k && !st; q++) {
        double *pq = P + (size_t)q * TR_RT_NPAR;
        memcpy(pq, c->p, sizeof c->p);
        for (int j = 0; j < c->nfree; j++)
            pq[c->idx[j]] = to_p(c->idx[j], Q[(size_t)q * (size_t)c->nfree + (size_t)j]);
    }
    if (!st) st = tr_rt_stage1_many(c->o, c->b, k, P, c->nt, c->dt, F, A, err);
    c->nrun += k;
    double w = 1 / sqrt((double)c->nt);
    for (int q = 0; q < k && !st; q++) {
        const double *f = F + (size_t)q * nt, *a = A + (size_t)q * nt;
        double *r = R + (size_t)q * 2 * nt;
        for (size_t i = 0; i < nt; i++) {
            r[i] = w * (f[i] - c->tf[i]) / c->fscale;
            r[nt + i] = w * (a[i] - c->ta[i]) / c->ascale;
        }
        if (q == k - 1) {
            memcpy(c->sf, f, nt * sizeof(double));
            memcpy(c->sa, a, nt * sizeof(double));
        }
    }
    free(P), free(F);
    return st;
}

static mcs_status residuals(void *vc, const double *q, double *r, mcs_error *err)
{
    return residuals_many(vc, 1, q, r, err);
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

/* the start: the best of q and a full factorial over the free parameters (7 levels each for up
 * to two, 3 for up to four, else 2: the centres of equal parts of each range), all run at once,
 * since the objective has local minima (a stage-1 run is non-smooth in its parameters: contacts
 * open and close); ties go to the earlier point, so the choice does not depend on the jobs */
static mcs_status scan_start(fit_ctx *c, double *q, const double *lo, const double *hi,
                             const double *rr, mcs_error *err)
{
    size_t m = 2 * (size_t)c->nt, nf = (size_t)c->nfree;
    int lev = c->nfree <= 2 ? 7 : 3, ncomb = 1;
    for (int j = 0; j < c->nfree; j++)
        ncomb *= lev;
    double *Q = malloc((size_t)ncomb * nf * sizeof(double));
    double *R = malloc((size_t)ncomb * m * sizeof(double));
    mcs_status st = Q && R ? MCS_OK : MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    for (int k = 0; k < ncomb && !st; k++)
        for (int j = 0, kk = k; j < c->nfree; j++, kk /= lev)
            Q[(size_t)k * nf + (size_t)j] =
                lo[j] + (1 + 2 * (kk % lev)) / (2.0 * lev) * (hi[j] - lo[j]);
    if (!st) st = residuals_many(c, ncomb, Q, R, err);
    double best = 0;
    for (size_t i = 0; i < m; i++)
        best += rr[i] * rr[i]; /* rr: the residuals at q */
    for (int k = 0; k < ncomb && !st; k++) {
        double s = 0;
        for (size_t i = 0; i < m; i++)
            s += R[(size_t)k * m + i] * R[(size_t)k * m + i];
        if (s < best) best = s, memcpy(q, Q + (size_t)k * nf, nf * sizeof(double));
    }
    free(Q), free(R);
    return st;
}

mcs_status tr_rt_fit(const tr_rt_opts *o, const tr_rt_base *b, const tr_rt_target *t,
                     tr_rt_result *r, mcs_error *err)
{
    *r = (tr_rt_result){0};
    double p0[TR_RT_NPAR] = {1, 1, b->phi_e, b->phi_s, 1, b->k_stop};
    if (o->has_start) memcpy(p0, o->start, sizeof p0);
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
    double *buf = calloc(4 * nt, sizeof(double));
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    double *tf = buf, *ta = tf + nt;
    c.tf = tf, c.ta = ta, c.sf = ta + nt, c.sa = c.sf + nt;
    for (int i = 0; i < c.nt; i++) {
        tf[i] = interp(t->t, t->force, t->nt, t->t[0] + i * c.dt);
        ta[i] = interp(t->t, t->angle, t->nt, t->t[0] + i * c.dt);
    }
    mcs_status st = filter(tf, c.nt, c.dt, o->cfc, err);
    if (!st) st = filter(ta, c.nt, c.dt, o->cfc, err);
    for (int i = 0; i < c.nt; i++)
        c.fscale += tf[i] * tf[i] / c.nt, c.ascale += ta[i] * ta[i] / c.nt;
    c.fscale = sqrt(c.fscale), c.ascale = sqrt(c.ascale); /* the target's RMS */
    if (!st && (!(c.fscale > 0) || !(c.ascale > 0)))
        st = MCS_ERR(err, MCS_ERR_RANGE,
                     "retune: the target's wall force or fork angle is "
                     "zero throughout");
    double q[TR_RT_NPAR], lo[TR_RT_NPAR], hi[TR_RT_NPAR];
    for (int j = 0; j < c.nfree; j++)
        q[j] = to_q(c.idx[j], p0[c.idx[j]]), lo[j] = to_q(c.idx[j], par_lo[c.idx[j]]),
        hi[j] = to_q(c.idx[j], par_hi[c.idx[j]]);
    double *rr = malloc(2 * nt * sizeof(double));
    if (!rr) st = MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    if (!st) st = residuals(&c, q, rr, err);
    if (!st) st = rate(&c, &r->iso_force0, &r->iso_angle0, err);
    r->nt = c.nt;
    r->t = malloc(7 * nt * sizeof(double));
    if (!st && !r->t) st = MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    if (!st) {
        r->tf = r->t + nt, r->ta = r->tf + nt, r->f0 = r->ta + nt, r->a0 = r->f0 + nt;
        r->f1 = r->a0 + nt, r->a1 = r->f1 + nt;
        for (size_t i = 0; i < nt; i++)
            r->t[i] = (double)i * c.dt;
        memcpy(r->tf, tf, nt * sizeof(double)), memcpy(r->ta, ta, nt * sizeof(double));
        memcpy(r->f0, c.sf, nt * sizeof(double)), memcpy(r->a0, c.sa, nt * sizeof(double));
    }
    if (!st && o->scan && c.nfree > 0) st = scan_start(&c, q, lo, hi, rr, err);
    tr_lm_result lr = {0};
    tr_lm_opts lo_ = tr_lm_opts_default();
    lo_.fd_rel = 1e-3, lo_.max_iter = 30, lo_.ftol = 1e-8, lo_.many = residuals_many;
    double q0[TR_RT_NPAR];
    memcpy(q0, q, sizeof q0);
    if (!st && c.nfree > 0)
        st = tr_lm_solve(residuals, &c, c.nfree, 2 * c.nt, q, lo, hi, &lo_, &lr, err);
    /* a gain below the LM's ftol is no move: the start is kept to the last bit, so a retune
     * from its own fit (the loop's iteration k > 1) returns that fit and stage 1 repeats */
    if (!st && c.nfree > 0 && !(lr.cost < lr.cost0 * (1 - lo_.ftol))) {
        memcpy(q, q0, sizeof q0);
        lr.cost = lr.cost0;
    }
    if (!st && !c.nfree && o->has_after) { /* a case not in the fit: rated at o->after */
        memcpy(c.p, o->after, sizeof c.p);
        memcpy(r->p, o->after, sizeof r->p);
    }
    if (!st) {
        for (int j = 0; j < c.nfree; j++)
            r->p[c.idx[j]] = to_p(c.idx[j], q[j]);
        st = residuals(&c, q, rr, err);
    }
    if (!st) st = rate(&c, &r->iso_force, &r->iso_angle, err);
    if (!st) {
        memcpy(r->f1, c.sf, nt * sizeof(double));
        memcpy(r->a1, c.sa, nt * sizeof(double));
    }
    r->cost0 = lr.cost0, r->cost = lr.cost, r->iter = lr.iter, r->nfev = c.nrun;
    r->why = lr.why ? lr.why : o->has_after && !c.nfree ? "held out" : "nothing to fit";
    if (st) tr_rt_result_free(r);
    free(rr);
    free(buf);
    return st;
}

void tr_rt_result_free(tr_rt_result *r)
{
    free(r->t);
    r->t = r->tf = r->ta = r->f0 = r->a0 = r->f1 = r->a1 = NULL;
    r->nt = 0;
}

int tr_rt_write_csv(FILE *f, const tr_rt_result *r)
{
    fprintf(f, "time [s], force_stage3 [N], force_before [N], force_after [N], "
               "angle_stage3 [rad], angle_before [rad], angle_after [rad]\n");
    for (int i = 0; r->t && i < r->nt; i++)
        fprintf(f, "%.6g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g\n", r->t[i], r->tf[i], r->f0[i],
                r->f1[i], r->ta[i], r->a0[i], r->a1[i]);
    return ferror(f) ? -1 : 0;
}

mcs_status tr_rt_write_curves(const char *h5, const tr_rt_opts *o, const tr_rt_base *b,
                              const double *p, mcs_error *err)
{
    mcs_results *r = NULL;
    mcs_status st = mcs_results_append(&r, h5, err);
    if (st) return st;
    double xy[2 * TR_RT_MAXPT], x[4], y[4];
    char path[256];
    /* a retune again (the loop): the new curves replace the old */
    snprintf(path, sizeof path, "/curves/%s", o->tyre_char);
    st = mcs_results_remove(r, path, err);
    snprintf(path, sizeof path, "/curves/%s", o->fork_char);
    if (!st) st = mcs_results_remove(r, path, err);
    size_t dims[2] = {(size_t)b->ntyre, 2};
    for (int i = 0; i < b->ntyre; i++)
        xy[2 * i] = b->tyre_x[i], xy[2 * i + 1] = tyre_force(b, p, i);
    snprintf(path, sizeof path, "/curves/%s/loading", o->tyre_char);
    if (!st) st = mcs_results_write(r, path, 2, dims, xy, "m, N", err);
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

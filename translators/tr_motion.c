/* tr_motion.c: reading and checking a stage-1 file's body trajectories, and the look-up of the
 * sample interval (tr_motion.h). */
#include "translators/tr_motion_internal.h"

#include "core/mcs_results.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

mcs_status tr_motion_method_parse(const char *name, tr_motion_method *out, mcs_error *err)
{
    if (name && !strcmp(name, "pose")) return *out = TR_MOTION_POSE, MCS_OK;
    if (name && !strcmp(name, "pulse")) return *out = TR_MOTION_PULSE, MCS_OK;
    return MCS_ERR(err, MCS_ERR_KEY, "prescribed motion: method '%s' unknown (pose | pulse)",
                   name ? name : "(null)");
}

const char *tr_motion_method_name(tr_motion_method m)
{
    return m == TR_MOTION_PULSE ? "pulse" : "pose";
}

double tr_quat_angle(const double a[4], const double b[4])
{
    double cb[4] = {b[0], -b[1], -b[2], -b[3]}, r[4];
    tr_q_mul(a, cb, r);
    return 2 * atan2(mb_norm(r + 1), fabs(r[0]));
}

static void body_free(tr_motion_body_data *b)
{
    free(b->name), free(b->pos), free(b->quat), free(b->vel), free(b->angvel), free(b->acc);
    free(b->ipos), free(b->ivel), free(b->iquat), free(b->aedge), free(b->wedge);
}

void tr_motion_destroy(tr_motion **pm)
{
    tr_motion *m = pm ? *pm : NULL;
    if (!m) return;
    for (int i = 0; m->body && i < m->nbody; i++)
        body_free(&m->body[i]);
    free(m->body), free(m->t), free(m->path), free(m);
    *pm = NULL;
}

/* a [nt, w] dataset of finite values, malloc'ed into *v; qty names it in messages */
static mcs_status read_rows(mcs_results *r, const char *body, const char *qty, int nt, int w,
                            double **v, mcs_error *err)
{
    const char *f = mcs_results_path(r);
    char ds[512];
    snprintf(ds, sizeof ds, "/stage1/bodies/%s/%s", body, qty);
    if (mcs_results_kind(r, ds) != MCS_RES_DATASET)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: body '%s': no %s (a stage-1 file writes it)", f,
                       body, ds);
    mcs_array a = {0};
    mcs_status st = mcs_results_read(r, ds, &a, err);
    if (st) return st;
    if (a.rank != 2 || a.dims[0] != (size_t)nt || a.dims[1] != (size_t)w) {
        st = MCS_ERR(err, MCS_ERR_FORMAT,
                     "%s: body '%s': %s has shape [%zu%s%zu], expected [%d, %d] (/stage1/time "
                     "has %d rows)",
                     f, body, ds, a.dims[0], a.rank >= 2 ? ", " : "", a.rank >= 2 ? a.dims[1] : 0,
                     nt, w, nt);
    }
    for (size_t i = 0; !st && i < a.n; i++)
        if (!isfinite(a.v[i]))
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: body '%s': %s row %zu is not finite (%g)", f,
                         body, ds, i / (size_t)w, a.v[i]);
    if (!st) *v = a.v, a.v = NULL;
    mcs_array_free(&a);
    return st;
}

static mcs_status read_time(mcs_results *r, tr_motion *m, mcs_error *err)
{
    const char *f = mcs_results_path(r);
    if (mcs_results_kind(r, "/stage1") != MCS_RES_GROUP)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: no /stage1: not a stage-1 results file", f);
    if (mcs_results_kind(r, "/stage1/time") != MCS_RES_DATASET)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: no /stage1/time", f);
    mcs_array a = {0};
    mcs_status st = mcs_results_read(r, "/stage1/time", &a, err);
    if (!st && (a.rank != 1 || a.n < 2))
        st = MCS_ERR(err, MCS_ERR_FORMAT,
                     "%s: /stage1/time must be [nt] with nt >= 2 samples (rank %d, %zu values)", f,
                     a.rank, a.n);
    for (size_t i = 0; !st && i < a.n; i++)
        if (!isfinite(a.v[i]) || (i > 0 && !(a.v[i] > a.v[i - 1])))
            st = MCS_ERR(err, MCS_ERR_FORMAT,
                         "%s: /stage1/time[%zu] = %g: not finite or not after the one before", f, i,
                         a.v[i]);
    if (!st) m->t = a.v, m->nt = (int)a.n, a.v = NULL;
    mcs_array_free(&a);
    return st;
}

/* the error for a body not in the file, listing a few that are */
static mcs_status no_body(mcs_results *r, const char *name, mcs_error *err)
{
    char **nm = NULL, list[256] = "";
    int n = 0;
    mcs_error e2 = {0};
    if (mcs_results_list(r, "/stage1/bodies", &nm, &n, &e2) == MCS_OK)
        for (int i = 0; i < n && i < 8; i++) {
            size_t l = strlen(list);
            snprintf(list + l, sizeof list - l, "%s%s", i ? ", " : "", nm[i]);
        }
    mcs_status st = MCS_ERR(err, MCS_ERR_KEY,
                            "%s: body '%s' is not in /stage1/bodies (the file has %d bodies: "
                            "%s%s)",
                            mcs_results_path(r), name, n, list, n > 8 ? ", ..." : "");
    mcs_results_list_free(&nm, n);
    return st;
}

static mcs_status read_body(mcs_results *r, tr_motion *m, tr_motion_body_data *b, mcs_error *err)
{
    char g[512];
    snprintf(g, sizeof g, "/stage1/bodies/%s", b->name);
    if (mcs_results_kind(r, g) != MCS_RES_GROUP) return no_body(r, b->name, err);
    int nt = m->nt;
    mcs_status st = read_rows(r, b->name, "position", nt, 3, &b->pos, err);
    if (!st) st = read_rows(r, b->name, "orientation", nt, 4, &b->quat, err);
    if (!st) st = read_rows(r, b->name, "velocity", nt, 3, &b->vel, err);
    if (!st) st = read_rows(r, b->name, "angular_velocity", nt, 3, &b->angvel, err);
    if (!st && m->method == TR_MOTION_PULSE)
        st = read_rows(r, b->name, "acceleration", nt, 3, &b->acc, err);
    /* unit quaternions (stage 1 writes them normalised; allow 1e-6 and renormalise) */
    for (int i = 0; !st && i < nt; i++) {
        double *q = b->quat + 4 * i;
        double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (fabs(n - 1) > 1e-6)
            st = MCS_ERR(err, MCS_ERR_FORMAT,
                         "%s: body '%s': %s/orientation row %d has norm %.9g, not a unit "
                         "quaternion",
                         mcs_results_path(r), b->name, g, i, n);
        for (int j = 0; !st && j < 4; j++)
            q[j] /= n;
    }
    if (st || m->method != TR_MOTION_PULSE) return st;
    b->ipos = malloc(sizeof(double) * 3 * (size_t)nt);
    b->ivel = malloc(sizeof(double) * 3 * (size_t)nt);
    b->iquat = malloc(sizeof(double) * 4 * (size_t)nt);
    b->aedge = malloc(sizeof(double) * 3 * (size_t)nt);
    b->wedge = malloc(sizeof(double) * 3 * (size_t)nt);
    if (!b->ipos || !b->ivel || !b->iquat || !b->aedge || !b->wedge)
        return MCS_ERR(err, MCS_ERR_NOMEM, "%s: body '%s': out of memory", mcs_results_path(r),
                       b->name);
    tr_motion_pulse_integrate(m, b);
    return MCS_OK;
}

static mcs_status read_all(mcs_results *r, tr_motion *m, const char *const *names, int nbody,
                           mcs_error *err)
{
    mcs_status st = read_time(r, m, err);
    char **all = NULL;
    int nall = 0;
    if (!st && mcs_results_kind(r, "/stage1/bodies") != MCS_RES_GROUP)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: no /stage1/bodies", mcs_results_path(r));
    if (!st && !names) {
        st = mcs_results_list(r, "/stage1/bodies", &all, &nall, err);
        names = (const char *const *)all, nbody = nall;
    }
    if (!st && nbody < 1)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: no body in /stage1/bodies", mcs_results_path(r));
    if (!st && !(m->body = calloc((size_t)nbody, sizeof *m->body)))
        st = MCS_ERR(err, MCS_ERR_NOMEM, "prescribed motion: out of memory");
    for (int i = 0; !st && i < nbody; i++) {
        m->nbody = i + 1;
        if (!(m->body[i].name = strdup(names[i])))
            st = MCS_ERR(err, MCS_ERR_NOMEM, "prescribed motion: out of memory");
        if (!st) st = read_body(r, m, &m->body[i], err);
    }
    mcs_results_list_free(&all, nall);
    return st;
}

mcs_status tr_motion_open(tr_motion **out, const char *path, const char *const *names, int nbody,
                          tr_motion_method method, mcs_error *err)
{
    *out = NULL;
    tr_motion *m = calloc(1, sizeof *m);
    if (!m || !(m->path = strdup(path ? path : "")))
        return free(m), MCS_ERR(err, MCS_ERR_NOMEM, "prescribed motion: out of memory");
    m->method = method;
    mcs_results *r = NULL;
    mcs_status st = mcs_results_open(&r, path, err);
    if (!st) st = read_all(r, m, names, nbody, err);
    mcs_results_close(&r);
    if (st) {
        tr_motion_destroy(&m);
        return st;
    }
    *out = m;
    return MCS_OK;
}

int tr_motion_nbody(const tr_motion *m)
{
    return m->nbody;
}

const char *tr_motion_body_name(const tr_motion *m, int body)
{
    return body >= 0 && body < m->nbody ? m->body[body].name : NULL;
}

int tr_motion_body(const tr_motion *m, const char *name)
{
    for (int i = 0; i < m->nbody; i++)
        if (!strcmp(m->body[i].name, name)) return i;
    return -1;
}

tr_motion_method tr_motion_get_method(const tr_motion *m)
{
    return m->method;
}

void tr_motion_span(const tr_motion *m, double *t0, double *t_end, int *nt)
{
    if (t0) *t0 = m->t[0];
    if (t_end) *t_end = m->t[m->nt - 1];
    if (nt) *nt = m->nt;
}

double tr_motion_time(const tr_motion *m, int k)
{
    return m->t[k];
}

tr_motion_drift tr_motion_get_drift(const tr_motion *m, int body)
{
    tr_motion_drift d = {0};
    if (body >= 0 && body < m->nbody && m->method == TR_MOTION_PULSE) d = m->body[body].drift;
    return d;
}

mcs_status tr_motion_eval(const tr_motion *m, int body, double t, tr_motion_kin *k, mcs_error *err)
{
    if (body < 0 || body >= m->nbody)
        return MCS_ERR(err, MCS_ERR_KEY, "%s: body index %d of %d read", m->path, body, m->nbody);
    double t0 = m->t[0], t1 = m->t[m->nt - 1], tol = 1e-9 * (t1 - t0);
    if (!(t >= t0 - tol && t <= t1 + tol))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: body '%s': t = %.9g s is outside the file's span [%.9g, %.9g] s",
                       m->path, m->body[body].name, t, t0, t1);
    t = t < t0 ? t0 : t > t1 ? t1 : t;
    /* the interval [t_i, t_i+1] holding t: the last one for t = t_end */
    int lo = 0, hi = m->nt - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (m->t[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    if (m->method == TR_MOTION_PULSE)
        tr_motion_pulse_eval(m, &m->body[body], lo, t, k);
    else
        tr_motion_pose_eval(m, &m->body[body], lo, t, k);
    return MCS_OK;
}

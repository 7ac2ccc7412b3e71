#include "core/mcs_hysteresis.h"

#include <math.h>
#include <stdio.h>

/* the unloading path below x_max, fixed by the history: P = max(0, min(F_L, U)) for x > 0.
 * Its constituents (F_L, then one or two parts of U) are each linear between knots. */
enum { PATH_ELASTIC, PATH_SLOPE, PATH_CURVE, PATH_SLOPE_CURVE };
typedef struct {
    const mcs_hyst_model *m;
    int kind;  /* PATH_*                                        */
    double c;  /* line intercept (PATH_SLOPE, _SLOPE_CURVE) [N]  */
    double s;  /* uniform scale of G (PATH_CURVE) [-]            */
    double xm; /* x_max, where the scaled G ends (PATH_CURVE) [m] */
    double xa; /* anchor: at and above it the path is F_L (PATH_SLOPE, _SLOPE_CURVE) [m] */
} hpath;

typedef struct {
    double v, d; /* value [N] and right derivative [N/m] */
} vd;

static vd vd_min(vd a, vd b)
{
    return (a.v < b.v || (a.v == b.v && a.d <= b.d)) ? a : b;
}
static vd vd_max(vd a, vd b)
{
    return (a.v > b.v || (a.v == b.v && a.d >= b.d)) ? a : b;
}

static hpath path_of(const mcs_hyst_model *m, const mcs_hyst_state *s)
{
    hpath p = {
        .m = m, .kind = PATH_ELASTIC, .c = s->line_c, .s = 0, .xm = s->x_max, .xa = s->x_anchor};
    if (!(s->x_max > m->elastic_limit)) return p;
    switch (m->unload) {
    case MCS_UNLOAD_ELASTIC:
        break;
    case MCS_UNLOAD_SLOPE:
        p.kind = PATH_SLOPE;
        break;
    case MCS_UNLOAD_SLOPE_CURVE:
        p.kind = PATH_SLOPE_CURVE;
        break;
    case MCS_UNLOAD_CURVE:
        p.kind = PATH_CURVE;
        p.s = s->f_max / m->unloading->y[m->unloading->n - 1];
        break;
    }
    return p;
}

static hpath path_elastic(const mcs_hyst_model *m)
{
    return (hpath){.m = m, .kind = PATH_ELASTIC, .c = INFINITY, .s = 0, .xm = 0, .xa = 0};
}

/* value and right derivative with one segment lookup (as mcs_curve_eval / mcs_curve_slope) */
static vd curve_vd(const mcs_curve *c, double x)
{
    int n = c->n;
    if (n == 1 || (x < c->x[0] && c->lo == MCS_EXTRAP_CONSTANT)) return (vd){c->y[0], 0};
    if (x >= c->x[n - 1] && c->hi == MCS_EXTRAP_CONSTANT) return (vd){c->y[n - 1], 0};
    int i = mcs_curve_segment(c, x, -1);
    double sl = (c->y[i + 1] - c->y[i]) / (c->x[i + 1] - c->x[i]);
    return (vd){c->y[i] + sl * (x - c->x[i]), sl};
}

/* constituent values at x; returns how many (1..3) */
static int path_parts(const hpath *p, double x, vd out[3])
{
    const mcs_hyst_model *m = p->m;
    out[0] = curve_vd(m->loading, x);
    switch (p->kind) {
    case PATH_SLOPE:
        out[1] = (vd){m->unload_slope * x + p->c, m->unload_slope};
        return 2;
    case PATH_SLOPE_CURVE:
        out[1] = (vd){m->unload_slope * x + p->c, m->unload_slope};
        out[2] = curve_vd(m->unloading, x);
        return 3;
    case PATH_CURVE:
        if (!(p->s > 0)) {
            out[1] = (vd){0, 0};
        } else {
            const mcs_curve *g = m->unloading;
            double u = g->x[g->n - 1] + (x - p->xm) / p->s;
            out[1] = (vd){p->s * mcs_curve_eval(g, u), mcs_curve_slope(g, u)};
        }
        return 2;
    default:
        return 1;
    }
}

/* P at x from its constituents: max(0, min(F_L, U)), U = max(line, G) for PATH_SLOPE_CURVE;
 * F_L itself at and above the anchor of the slope rules */
static vd path_compose(const hpath *p, const vd v[3], double x)
{
    vd r = v[0];
    if ((p->kind == PATH_SLOPE || p->kind == PATH_SLOPE_CURVE) && x >= p->xa)
        ;
    else if (p->kind == PATH_SLOPE_CURVE)
        r = vd_min(r, vd_max(v[1], v[2]));
    else if (p->kind != PATH_ELASTIC)
        r = vd_min(r, v[1]);
    return vd_max((vd){0, 0}, r);
}

static vd path_eval(const hpath *p, double x)
{
    if (!(x > 0)) return (vd){0, 0};
    vd v[3];
    path_parts(p, x, v);
    return path_compose(p, v, x);
}

/* smallest a + b x_j > t (b > 0), or INFINITY; `up` = 0: largest < t, or -INFINITY */
static double curve_knot(const mcs_curve *c, double a, double b, double t, int up)
{
    int lo = 0, hi = c->n; /* first j with a + b x_j > t (up) or >= t (down) */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        double k = a + b * c->x[mid];
        if (up ? k > t : k >= t)
            hi = mid;
        else
            lo = mid + 1;
    }
    if (up) return lo < c->n ? a + b * c->x[lo] : INFINITY;
    return lo > 0 ? a + b * c->x[lo - 1] : -INFINITY;
}

/* next knot of P after t (up) or before t (down): x = 0, breakpoints of F_L and of G */
static double path_knot(const hpath *p, double t, int up)
{
    double k = up ? (t < 0 ? 0 : INFINITY) : (t > 0 ? 0 : -INFINITY);
    double kl = curve_knot(p->m->loading, 0, 1, t, up), kg = k;
    const mcs_curve *g = p->m->unloading;
    if (p->kind == PATH_SLOPE_CURVE) kg = curve_knot(g, 0, 1, t, up);
    if (p->kind == PATH_CURVE && p->s > 0)
        kg = curve_knot(g, p->xm - p->s * g->x[g->n - 1], p->s, t, up);
    if ((p->kind == PATH_SLOPE || p->kind == PATH_SLOPE_CURVE) && (up ? p->xa > t : p->xa < t))
        k = up ? fmin(k, p->xa) : fmax(k, p->xa);
    return up ? fmin(k, fmin(kl, kg)) : fmax(k, fmax(kl, kg));
}

/* points in (t0, t1) where two constituents (or one and zero) cross; P is linear between them */
static int piece_nodes(int nv, const vd *v0, const vd *v1, double t0, double t1, double *nodes)
{
    double a[4], b[4];
    for (int i = 0; i < nv; i++) {
        a[i] = v0[i].v;
        b[i] = v1[i].v;
    }
    a[nv] = b[nv] = 0.0;
    int n = 0;
    for (int i = 0; i <= nv; i++)
        for (int j = i + 1; j <= nv; j++) {
            double d0 = a[i] - a[j], d1 = b[i] - b[j];
            if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0)) {
                double t = t0 + (t1 - t0) * d0 / (d0 - d1);
                if (t > t0 && t < t1) nodes[n++] = t;
            }
        }
    for (int i = 1; i < n; i++) /* insertion sort, ascending */
        for (int j = i; j > 0 && nodes[j - 1] > nodes[j]; j--) {
            double tmp = nodes[j];
            nodes[j] = nodes[j - 1];
            nodes[j - 1] = tmp;
        }
    return n;
}

/* P at t in [t0, t1] by linear interpolation of the constituents (exact: they are linear) */
static double piece_value(const hpath *p, int nv, const vd *v0, const vd *v1, double t0, double t1,
                          double t)
{
    vd v[3];
    double w = (t1 > t0) ? (t - t0) / (t1 - t0) : 0.0;
    for (int i = 0; i < nv; i++)
        v[i] = (vd){v0[i].v + w * (v1[i].v - v0[i].v), 0};
    /* the side of the anchor is that of the piece (the anchor is a knot) */
    return path_compose(p, v, 0.5 * (t0 + t1)).v;
}

/* exact integral of P over [a, b], a <= b */
static double path_integral(const hpath *p, double a, double b)
{
    if (a < 0) a = 0;
    if (!(b > a)) return 0.0;
    double sum = 0.0, t0 = a;
    vd v0[3], v1[3];
    int nv = path_parts(p, t0, v0);
    while (t0 < b) {
        double t1 = fmin(path_knot(p, t0, 1), b);
        path_parts(p, t1, v1);
        double nodes[8];
        int nn = piece_nodes(nv, v0, v1, t0, t1, nodes);
        double tp = t0, fp = piece_value(p, nv, v0, v1, t0, t1, t0);
        for (int i = 0; i <= nn; i++) {
            double t = i < nn ? nodes[i] : t1;
            double f = piece_value(p, nv, v0, v1, t0, t1, t);
            sum += 0.5 * (fp + f) * (t - tp);
            tp = t;
            fp = f;
        }
        t0 = t1;
        for (int i = 0; i < nv; i++)
            v0[i] = v1[i];
    }
    return sum;
}

/* the slope rule's set without a walk over P: above the line's zero z the path is zero only
 * where F_L <= 0, so the set is the largest such x in [max(z, 0), x_max], or that bound */
static double slope_zero_below(const hpath *p, double xm)
{
    const mcs_curve *L = p->m->loading;
    double lo = fmax(-p->c / p->m->unload_slope, 0.0), hi = xm;
    double fh = mcs_curve_eval(L, hi);
    if (fh <= 0) return hi;
    /* breakpoints strictly inside (lo, hi), from the top: F_L is linear between them */
    int i = mcs_curve_segment(L, hi, -1); /* then the largest i with x_i < hi */
    if (i + 1 < L->n && L->x[i + 1] < hi) i++;
    if (L->x[i] >= hi) i--;
    for (; i >= 0 && L->x[i] > lo; i--) {
        if (L->y[i] <= 0) return L->x[i] + (hi - L->x[i]) * (-L->y[i]) / (fh - L->y[i]);
        hi = L->x[i];
        fh = L->y[i];
    }
    double fl = mcs_curve_eval(L, lo);
    if (fl <= 0) return lo + (hi - lo) * (-fl) / (fh - fl);
    return lo;
}

/* permanent set: the largest x in [0, x_max] with P(x) = 0, walking down from x_max */
static double path_zero_below(const hpath *p, double xm, double fscale)
{
    if (p->kind == PATH_SLOPE) return slope_zero_below(p, xm);
    double tol = 1e-12 * fscale, t1 = xm;
    vd v0[3], v1[3];
    int nv = path_parts(p, t1, v1);
    if (path_compose(p, v1, xm).v <= tol) return xm;
    while (t1 > 0) {
        double t0 = fmax(path_knot(p, t1, 0), 0.0);
        path_parts(p, t0, v0);
        double nodes[8];
        int nn = piece_nodes(nv, v0, v1, t0, t1, nodes);
        for (int i = nn - 1; i >= -1; i--) {
            double t = i >= 0 ? nodes[i] : t0;
            if (piece_value(p, nv, v0, v1, t0, t1, t) <= tol) return t;
        }
        t1 = t0;
        for (int i = 0; i < nv; i++)
            v1[i] = v0[i];
    }
    return 0.0;
}

mcs_status mcs_hyst_model_check(const mcs_hyst_model *m, const char *name, mcs_error *err)
{
    if (!name) name = "characteristic";
    if (!m->loading) return MCS_ERR(err, MCS_ERR_KEY, "%s: a loading curve is required", name);
    if (isnan(m->elastic_limit) || m->elastic_limit < 0)
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: elastic limit %g must be >= 0", name,
                       m->elastic_limit);
    int need_slope = m->unload == MCS_UNLOAD_SLOPE || m->unload == MCS_UNLOAD_SLOPE_CURVE;
    int need_curve = m->unload == MCS_UNLOAD_CURVE || m->unload == MCS_UNLOAD_SLOPE_CURVE;
    if (m->unload < MCS_UNLOAD_ELASTIC || m->unload > MCS_UNLOAD_SLOPE_CURVE)
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: unknown unloading rule %d", name, (int)m->unload);
    if (need_slope && !(m->unload_slope > 0 && isfinite(m->unload_slope)))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: unloading slope %g must be finite and > 0", name,
                       m->unload_slope);
    if (need_curve && !m->unloading)
        return MCS_ERR(err, MCS_ERR_KEY, "%s: an unloading curve is required", name);
    if (m->unload == MCS_UNLOAD_CURVE && !(m->unloading->y[m->unloading->n - 1] > 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: the unloading curve must end at a positive force (it is scaled to "
                       "start at the reached maximum); its last point has %g",
                       name, m->unloading->y[m->unloading->n - 1]);
    return MCS_OK;
}

void mcs_hyst_reset(const mcs_hyst_model *m, mcs_hyst_state *s)
{
    double f0 = mcs_curve_eval(m->loading, 0.0);
    *s = (mcs_hyst_state){.x = 0,
                          .force = 0,
                          .x_max = 0,
                          .f_max = f0 > 0 ? f0 : 0,
                          .x_set = 0,
                          .line_c = INFINITY,
                          .x_anchor = 0,
                          .work = 0};
}

double mcs_hyst_force(const mcs_hyst_model *m, const mcs_hyst_state *s, double x)
{
    if (x > s->x_max) {
        double f = mcs_curve_eval(m->loading, x);
        return f > 0 ? f : 0.0;
    }
    hpath p = path_of(m, s);
    return path_eval(&p, x).v;
}

double mcs_hyst_stiffness(const mcs_hyst_model *m, const mcs_hyst_state *s, double x)
{
    hpath p = x >= s->x_max ? path_elastic(m) : path_of(m, s);
    return path_eval(&p, x).d;
}

/* lower the line intercept over the plastic part of a new loading excursion [x0, x1]:
 * min of F_L(x') - k x' is at an end or a breakpoint of F_L; ties go to the larger x' */
static void anchor_try(const mcs_hyst_model *m, mcs_hyst_state *s, double x)
{
    double c = mcs_curve_eval(m->loading, x) - m->unload_slope * x;
    if (c <= s->line_c) {
        s->line_c = c;
        s->x_anchor = x;
    }
}

static void update_line(const mcs_hyst_model *m, mcs_hyst_state *s, double x0, double x1)
{
    if (m->unload != MCS_UNLOAD_SLOPE && m->unload != MCS_UNLOAD_SLOPE_CURVE) return;
    if (!(x1 > m->elastic_limit)) return;
    double a = fmax(x0, m->elastic_limit);
    anchor_try(m, s, a);
    for (double t = curve_knot(m->loading, 0, 1, a, 1); t < x1;
         t = curve_knot(m->loading, 0, 1, t, 1))
        anchor_try(m, s, t);
    anchor_try(m, s, x1);
}

double mcs_hyst_update(const mcs_hyst_model *m, mcs_hyst_state *s, double x)
{
    /* a NaN deflection is the caller's numerical failure: report it, keep the history */
    if (isnan(x)) return NAN;
    hpath p = path_of(m, s);
    double x0 = s->x;
    if (x <= s->x_max) {
        s->work += x >= x0 ? path_integral(&p, x0, x) : -path_integral(&p, x, x0);
    } else {
        hpath e = path_elastic(m);
        s->work += path_integral(&p, x0, s->x_max) + path_integral(&e, s->x_max, x);
        update_line(m, s, s->x_max, x);
        double f = mcs_curve_eval(m->loading, x);
        s->x_max = x;
        s->f_max = f > 0 ? f : 0;
        p = path_of(m, s);
        s->x_set = path_zero_below(&p, x, s->f_max);
    }
    s->x = x;
    s->force = path_eval(&p, x).v;
    return s->force;
}

double mcs_hyst_stored(const mcs_hyst_model *m, const mcs_hyst_state *s)
{
    hpath p = path_of(m, s);
    return path_integral(&p, 0.0, s->x);
}

double mcs_hyst_dissipated(const mcs_hyst_model *m, const mcs_hyst_state *s)
{
    hpath p = path_of(m, s), e = path_elastic(m);
    if (p.kind == PATH_ELASTIC) return 0.0; /* unloads along the loading curve */
    return path_integral(&e, 0.0, s->x_max) - path_integral(&p, 0.0, s->x_max);
}

/* ---- two-sided joints: independent branches ---- */

mcs_status mcs_hyst2_model_check(const mcs_hyst2_model *m, const char *name, mcs_error *err)
{
    char buf[160];
    snprintf(buf, sizeof buf, "%s (positive side)", name ? name : "joint");
    mcs_status st = mcs_hyst_model_check(&m->pos, buf, err);
    if (st != MCS_OK) return st;
    snprintf(buf, sizeof buf, "%s (negative side)", name ? name : "joint");
    return mcs_hyst_model_check(&m->neg, buf, err);
}

void mcs_hyst2_reset(const mcs_hyst2_model *m, mcs_hyst2_state *s)
{
    *s = (mcs_hyst2_state){0};
    mcs_hyst_reset(&m->pos, &s->pos);
    mcs_hyst_reset(&m->neg, &s->neg);
}

/* each branch carries no force outside its side, so the two simply add */
double mcs_hyst2_force(const mcs_hyst2_model *m, const mcs_hyst2_state *s, double x)
{
    return mcs_hyst_force(&m->pos, &s->pos, x - s->o_pos) -
           mcs_hyst_force(&m->neg, &s->neg, s->o_neg - x);
}

/* the inactive branch contributes zero (its deflection is on its open side or in its set) */
double mcs_hyst2_stiffness(const mcs_hyst2_model *m, const mcs_hyst2_state *s, double x)
{
    return mcs_hyst_stiffness(&m->pos, &s->pos, x - s->o_pos) +
           mcs_hyst_stiffness(&m->neg, &s->neg, s->o_neg - x);
}

/* move a branch's origin to o: bank its work (all dissipated: it carries no load on its open
 * side, where it is when the other side sets), clear its history, re-enter at deflection u */
static void branch_move(const mcs_hyst_model *m, mcs_hyst_state *b, double *banked, double u)
{
    *banked += b->work;
    mcs_hyst_reset(m, b);
    mcs_hyst_update(m, b, u);
}

/* free play of a loading curve: the end of its zero-force stretch from x = 0 (0 if none) */
static double free_play(const mcs_curve *c)
{
    double xp = 0, yp = mcs_curve_eval(c, 0.0);
    if (yp > 0) return 0.0;
    for (int i = 0; i < c->n; i++) {
        if (c->x[i] <= 0) continue;
        if (c->y[i] > 0) return xp + (c->x[i] - xp) * (-yp) / (c->y[i] - yp);
        xp = c->x[i], yp = c->y[i];
    }
    return xp;
}

/* plastic shift of a branch: its permanent set beyond the curve's own free play */
static double plastic_shift(const mcs_hyst_model *m, const mcs_hyst_state *b)
{
    if (!(b->x_max > m->elastic_limit)) return 0.0;
    double d = b->x_set - free_play(m->loading);
    return d > 0 ? d : 0.0;
}

double mcs_hyst2_update(const mcs_hyst2_model *m, mcs_hyst2_state *s, double x)
{
    double dp = s->pos.x_set, dn = s->neg.x_set;
    double f = mcs_hyst_update(&m->pos, &s->pos, x - s->o_pos) -
               mcs_hyst_update(&m->neg, &s->neg, s->o_neg - x);
    if (!m->follow_set || isnan(x)) return f;
    /* a side that set further this step moves the other side's origin by its plastic shift */
    if (s->pos.x_set != dp) {
        double o = s->o_pos + plastic_shift(&m->pos, &s->pos);
        if (o != s->o_neg) {
            s->o_neg = o;
            branch_move(&m->neg, &s->neg, &s->banked, o - x);
        }
    } else if (s->neg.x_set != dn) {
        double o = s->o_neg - plastic_shift(&m->neg, &s->neg);
        if (o != s->o_pos) {
            s->o_pos = o;
            branch_move(&m->pos, &s->pos, &s->banked, x - o);
        }
    }
    return f;
}

/* the negative branch's F_neg d(-x) is the work of -F_neg over dx: works add */
double mcs_hyst2_work(const mcs_hyst2_state *s)
{
    return s->pos.work + s->neg.work + s->banked;
}

double mcs_hyst2_stored(const mcs_hyst2_model *m, const mcs_hyst2_state *s)
{
    return mcs_hyst_stored(&m->pos, &s->pos) + mcs_hyst_stored(&m->neg, &s->neg);
}

double mcs_hyst2_dissipated(const mcs_hyst2_model *m, const mcs_hyst2_state *s)
{
    return mcs_hyst_dissipated(&m->pos, &s->pos) + mcs_hyst_dissipated(&m->neg, &s->neg) +
           s->banked;
}

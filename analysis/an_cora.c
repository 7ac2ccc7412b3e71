/* an_cora.c: CORA rating (Gehre, Gades, Wernicke, ESV 2009, paper 09-0407; CORAplus 4.0.x
 * defaults from REFERENCES.md). The paper and the CORA manual were not available to this
 * implementation; what is verified and what is a reading:
 *  - parameter names and default values: verified (a CORAplus 4.0.5 parameter file and a
 *    published wrapper list the same values, REFERENCES.md);
 *  - corridor rating: the same corridor scoring as ISO/TS 18571 (which took it from CORA):
 *    1 inside a0 Y, 0 outside b0 Y, ((b0 Y - |d|)/((b0 - a0) Y))^k between, Y = max|ref| over
 *    the interval, averaged over the interval -- matches the published method description;
 *  - cross-correlation rating = g_v E_V + g_g E_G + g_p E_P and CORA = g1 Z + g2 C: verified
 *    from the weight names and the published outputs (corridor, phase, size, progression);
 *  - reading: the normalised cross-correlation without mean removal,
 *    K(m) = sum r_i c_(i+m) / sqrt(sum r_i^2 sum c_(i+m)^2), over shifts keeping at least
 *    int_min of the interval, the comparison taken outside the interval when it is shifted;
 *  - reading: phase E_P = 1 for |shift| <= d_min T, 0 for >= d_max T, linear between (to the
 *    power k_p), T the length of the interval;
 *  - reading: size E_G = (min(Er, Ec)/max(Er, Ec))^k_g with Er, Ec the energies sum r^2, sum c^2
 *    of the shifted overlap (the ratio of the areas under the squared curves);
 *  - reading: progression E_V = ((1 + K(m*))/2)^k_v at the best shift m*;
 *  - reading: interval start t_a - a_eval (t_b - t_a), end t_b + b_delta_end (t_b - t_a), with
 *    t_a the first time |ref| >= a_thres Y and t_b the last time |ref| >= b_thres Y, both
 *    clipped to the common span.
 * The smallest |shift| wins ties (+m before -m), as in our ISO 18571 phase search. */
#include "analysis/an_cora.h"

#include <math.h>
#include <string.h>

#include "analysis/an_iso18571.h"
#include "analysis/an_resample.h"

an_cora_opts an_cora_opts_default(void)
{
    an_cora_opts o = {
        .sample_rate = 10000.0,
        .a_thres = 0.03,
        .b_thres = 0.075,
        .a_eval = 0.01,
        .b_delta_end = 0.2,
        .t_min = NAN,
        .t_max = NAN,
        .k = 2.0,
        .g1 = 0.5,
        .a0 = 0.05,
        .b0 = 0.5,
        .d_min = 0.01,
        .d_max = 0.12,
        .int_min = 0.8,
        .k_v = 10.0,
        .k_g = 1.0,
        .k_p = 1.0,
        .g_v = 0.5,
        .g_g = 0.25,
        .g_p = 0.25,
        .g2 = 0.5,
    };
    return o;
}

static mcs_status check_opts(const an_cora_opts *o, mcs_error *err)
{
    if (!(o->a0 >= 0 && o->b0 > o->a0))
        return MCS_ERR(err, MCS_ERR_RANGE, "CORA: need 0 <= a0 < b0 (a0 %g, b0 %g)", o->a0, o->b0);
    if (!(o->d_min >= 0 && o->d_max > o->d_min))
        return MCS_ERR(err, MCS_ERR_RANGE, "CORA: need 0 <= D_MIN < D_MAX (%g, %g)", o->d_min,
                       o->d_max);
    if (!(o->int_min > 0 && o->int_min <= 1))
        return MCS_ERR(err, MCS_ERR_RANGE, "CORA: INT_MIN must be in (0, 1], got %g", o->int_min);
    if (!(o->a_thres > 0 && o->a_thres < 1 && o->b_thres > 0 && o->b_thres < 1 &&
          o->a_eval >= 0 && o->b_delta_end >= 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "CORA: thresholds must be in (0, 1)");
    double w2 = o->g_v + o->g_g + o->g_p, w = o->g1 + o->g2;
    if (!(fabs(w2 - 1) < 1e-9) || !(fabs(w - 1) < 1e-9))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "CORA: weights G_V + G_G + G_P (%g) and G_1 + G_2 (%g) must be 1", w2, w);
    return MCS_OK;
}

mcs_status an_cora_interval(const double *ref, int n, double t0, double dt, const an_cora_opts *o,
                            int *i0, int *i1, mcs_error *err)
{
    double y = 0;
    for (int i = 0; i < n; i++) y = fmax(y, fabs(ref[i]));
    if (!(y > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "CORA: the reference is zero everywhere");
    int ia = 0, ib = n - 1;
    while (ia < n - 1 && fabs(ref[ia]) < o->a_thres * y) ia++;
    while (ib > 0 && fabs(ref[ib]) < o->b_thres * y) ib--;
    double ta = t0 + ia * dt, tb = t0 + ib * dt, tend = t0 + (n - 1) * dt;
    double len = tb > ta ? tb - ta : 0;
    double ts = isfinite(o->t_min) ? o->t_min : ta - o->a_eval * len;
    double te = isfinite(o->t_max) ? o->t_max : tb + o->b_delta_end * len;
    ts = fmax(ts, t0);
    te = fmin(te, tend);
    /* grid indices inside [ts, te], allowing rounding of 1e-9 of a step */
    long a = (long)ceil((ts - t0) / dt - 1e-9), b = (long)floor((te - t0) / dt + 1e-9);
    if (a < 0) a = 0;
    if (b > n - 1) b = n - 1;
    if (b - a + 1 < 10)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "CORA: the interval of evaluation %.6g..%.6g s holds %ld samples "
                       "(need 10)",
                       ts, te, b - a + 1 > 0 ? b - a + 1 : 0);
    *i0 = (int)a;
    *i1 = (int)b;
    return MCS_OK;
}

/* sums over the overlap of ref[i] (i0 <= i <= i1) with cmp[i + m] inside the arrays */
typedef struct {
    int len;
    double rr, cc, rc;
} overlap_sums;

static overlap_sums sums_at(const double *ref, const double *cmp, int n, int i0, int i1, int m)
{
    overlap_sums s = {0, 0, 0, 0};
    int lo = i0 > -m ? i0 : -m;
    int hi = i1 < n - 1 - m ? i1 : n - 1 - m;
    for (int i = lo; i <= hi; i++) {
        double r = ref[i], c = cmp[i + m];
        s.rr += r * r;
        s.cc += c * c;
        s.rc += r * c;
    }
    s.len = hi >= lo ? hi - lo + 1 : 0;
    return s;
}

static double xcorr_of(overlap_sums s)
{
    if (!(s.rr > 0) || !(s.cc > 0)) return 0.0;
    return fmax(-1.0, fmin(1.0, s.rc / sqrt(s.rr * s.cc)));
}

mcs_status an_cora_arrays(const double *ref, const double *cmp, int n, double t0, double dt,
                          const an_cora_opts *o, an_cora_result *r, mcs_error *err)
{
    memset(r, 0, sizeof *r);
    an_cora_opts def = an_cora_opts_default();
    if (!o) o = &def;
    mcs_status st = check_opts(o, err);
    if (st) return st;
    if (n < 10)
        return MCS_ERR(err, MCS_ERR_RANGE, "CORA: needs at least 10 samples, got %d", n);
    if (!(dt > 0) || !isfinite(dt) || !isfinite(t0))
        return MCS_ERR(err, MCS_ERR_RANGE, "CORA: sample interval must be > 0");
    for (int i = 0; i < n; i++)
        if (!isfinite(ref[i]) || !isfinite(cmp[i]))
            return MCS_ERR(err, MCS_ERR_RANGE, "CORA: sample %d is not a finite number", i + 1);
    int i0, i1;
    st = an_cora_interval(ref, n, t0, dt, o, &i0, &i1, err);
    if (st) return st;
    int mlen = i1 - i0 + 1;
    double ymax = 0;
    for (int i = i0; i <= i1; i++) ymax = fmax(ymax, fabs(ref[i]));
    if (!(ymax > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "CORA: the reference is zero in the interval of "
                                           "evaluation");
    r->n = n;
    r->t0 = t0;
    r->dt = dt;
    r->i_start = i0;
    r->i_end = i1;
    r->t_start = t0 + i0 * dt;
    r->t_end = t0 + i1 * dt;

    /* corridor rating over the interval */
    r->corridor = an_iso_corridor(ref + i0, cmp + i0, mlen, o->a0, o->b0, o->k);

    /* best shift: largest K(m) with an overlap of at least int_min of the interval */
    int need = (int)ceil(o->int_min * mlen - 1e-9), mmax = mlen - need;
    int best = 0;
    overlap_sums bs = sums_at(ref, cmp, n, i0, i1, 0);
    double bk = xcorr_of(bs);
    for (int m = 1; m <= mmax; m++) {
        for (int sgn = 1; sgn >= -1; sgn -= 2) {
            overlap_sums s = sums_at(ref, cmp, n, i0, i1, sgn * m);
            if (s.len < need) continue;
            double k = xcorr_of(s);
            if (k > bk + 1e-12) {
                bk = k;
                bs = s;
                best = sgn * m;
            }
        }
    }
    r->shift = best;
    r->shift_time = best * dt;
    r->xcorr = bk;

    /* phase: linear between d_min T and d_max T */
    double T = (i1 - i0) * dt, d = fabs(best * dt);
    if (d <= o->d_min * T)
        r->phase = 1.0;
    else if (d >= o->d_max * T)
        r->phase = 0.0;
    else
        r->phase = pow((o->d_max * T - d) / ((o->d_max - o->d_min) * T), o->k_p);

    /* size: ratio of the energies of the shifted overlap */
    double lo = fmin(bs.rr, bs.cc), hi = fmax(bs.rr, bs.cc);
    r->size = hi > 0 ? pow(lo / hi, o->k_g) : 0.0;

    /* progression: the cross-correlation at the best shift mapped to [0, 1] */
    r->progression = pow(0.5 * (1.0 + bk), o->k_v);

    r->cross = o->g_v * r->progression + o->g_g * r->size + o->g_p * r->phase;
    r->rating = o->g1 * r->corridor + o->g2 * r->cross;
    return MCS_OK;
}

mcs_status an_cora(const an_signal *ref, const an_signal *cmp, const an_cora_opts *o,
                   an_cora_result *r, mcs_error *err)
{
    an_cora_opts def = an_cora_opts_default();
    if (!o) o = &def;
    an_pair p;
    mcs_status st = an_resample_pair(ref->t, ref->y, ref->n, cmp->t, cmp->y, cmp->n,
                                     o->sample_rate, 10, &p, err);
    if (st) return st;
    st = an_cora_arrays(p.ref, p.cmp, p.n, p.t0, p.dt, o, r, err);
    an_pair_free(&p);
    return st;
}

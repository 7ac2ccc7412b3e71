/* an_anova.c: ANOVA of a factorial design by nested least-squares fits (an_stats.h): each term
 * adds its sum-to-zero coded columns; its sum of squares is the drop in the residual sum of
 * squares and its df the rise in rank (LAPACK dgelsy, rank-revealing QR) */
#include "analysis/an_stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

extern void dgelsy_(const int *m, const int *n, const int *nrhs, double *a, const int *lda,
                    double *b, const int *ldb, int *jpvt, const double *rcond, int *rank,
                    double *work, const int *lwork, int *info);

#define MAXLEV 64 /* distinct levels of one factor */

typedef struct {
    int m, ncol, cap; /* rows, columns so far, column capacity */
    double *X;        /* design matrix, column-major (m x cap) */
} design;

/* sorted distinct values of factor j over the usable rows; -1 when more than MAXLEV */
static int levels(int n, int k, const double *x, const char *use, int j, double *lev)
{
    int L = 0;
    for (int i = 0; i < n; i++) {
        if (!use[i]) continue;
        double v = x[(size_t)i * k + j];
        int q = 0;
        while (q < L && lev[q] < v) q++;
        if (q < L && lev[q] == v) continue;
        if (L == MAXLEV) return -1;
        memmove(lev + q + 1, lev + q, (size_t)(L - q) * sizeof *lev);
        lev[q] = v, L++;
    }
    return L;
}

/* coded column l (0..L-2) of factor j: 1 at level l, -1 at the last level, else 0 */
static void code(int n, int k, const double *x, const char *use, int j, const double *lev, int L,
                 int l, double *col)
{
    for (int i = 0, r = 0; i < n; i++) {
        if (!use[i]) continue;
        double v = x[(size_t)i * k + j];
        col[r++] = v == lev[l] ? 1 : v == lev[L - 1] ? -1 : 0;
    }
}

/* residuals R (m x nr, column-major) and rank of the least-squares fit of the nr columns of Y
 * on the ncol columns of d */
static int fit_resid(const design *d, const double *Y, int nr, double *R, int *rank)
{
    int m = d->m, nc = d->ncol, info = 0, lwork = -1;
    double rcond = 1e-10, wq;
    double *A = malloc((size_t)m * nc * sizeof *A), *b = malloc((size_t)m * nr * sizeof *b);
    int *jpvt = calloc((size_t)nc, sizeof *jpvt);
    if (!A || !b || !jpvt) {
        free(A), free(b), free(jpvt);
        return -1;
    }
    memcpy(A, d->X, (size_t)m * nc * sizeof *A);
    memcpy(b, Y, (size_t)m * nr * sizeof *b);
    dgelsy_(&m, &nc, &nr, A, &m, b, &m, jpvt, &rcond, rank, &wq, &lwork, &info);
    lwork = (int)wq;
    double *work = malloc((size_t)lwork * sizeof *work);
    if (work) dgelsy_(&m, &nc, &nr, A, &m, b, &m, jpvt, &rcond, rank, work, &lwork, &info);
    for (int q = 0; q < nr && work && !info; q++)
        for (int i = 0; i < m; i++) {
            double r = Y[i + (size_t)q * m];
            for (int c = 0; c < nc; c++)
                r -= d->X[i + (size_t)c * m] * b[c + (size_t)q * m];
            R[i + (size_t)q * m] = r;
        }
    int bad = !work || info;
    free(A), free(b), free(jpvt), free(work);
    return bad ? -1 : 0;
}

/* residual sum of squares and rank of the fit of y on the first ncol columns of d */
static int fit(const design *d, const double *y, double *rss, int *rank)
{
    double *r = malloc((size_t)d->m * sizeof *r);
    int bad = !r || fit_resid(d, y, 1, r, rank);
    *rss = 0;
    for (int i = 0; !bad && i < d->m; i++)
        *rss += r[i] * r[i];
    free(r);
    return bad ? -1 : 0;
}

typedef struct {
    int L[AN_ANOVA_MAXTERM];
    double lev[AN_ANOVA_MAXTERM][MAXLEV];
} factor_levels;

/* append the columns of term (fa, fb) to d */
static void add_term(design *d, int n, int k, const double *x, const char *use,
                     const factor_levels *fl, int fa, int fb)
{
    int m = d->m;
    double *ca = malloc((size_t)m * sizeof *ca), *cb = malloc((size_t)m * sizeof *cb);
    for (int la = 0; ca && cb && la < fl->L[fa] - 1; la++) {
        code(n, k, x, use, fa, fl->lev[fa], fl->L[fa], la, ca);
        int nb = fb < 0 ? 1 : fl->L[fb] - 1;
        for (int lb = 0; lb < nb && d->ncol < d->cap; lb++) {
            double *col = d->X + (size_t)d->ncol++ * m;
            if (fb >= 0) code(n, k, x, use, fb, fl->lev[fb], fl->L[fb], lb, cb);
            for (int i = 0; i < m; i++)
                col[i] = fb < 0 ? ca[i] : ca[i] * cb[i];
        }
    }
    free(ca), free(cb);
}

static int count_cols(int k, const factor_levels *fl, int inter)
{
    int c = 1;
    for (int a = 0; a < k; a++) {
        c += fl->L[a] - 1;
        for (int b = a + 1; inter && b < k; b++)
            c += (fl->L[a] - 1) * (fl->L[b] - 1);
    }
    return c;
}

/* the sequential fits of one model; 0 done */
static int run_model(int n, int k, const double *x, const char *use, const double *ym,
                     const factor_levels *fl, int inter, an_anova *a)
{
    design d = {.m = a->n, .cap = count_cols(k, fl, inter)};
    d.X = malloc((size_t)d.m * d.cap * sizeof *d.X);
    if (!d.X) return -1;
    for (int i = 0; i < d.m; i++)
        d.X[i] = 1; /* intercept */
    d.ncol = 1;
    double rss, prev;
    int rank, prank, bad = fit(&d, ym, &prev, &prank);
    a->nterm = 0;
    for (int t = 0; !bad && t < k + (inter ? k * (k - 1) / 2 : 0); t++) {
        int fa = t, fb = -1;
        if (t >= k) /* the pair number t - k in the order (0,1), (0,2), .., (1,2), .. */
            for (int q = t - k, i = 0; i < k; i++) {
                if (q < k - 1 - i) {
                    fa = i, fb = i + 1 + q;
                    break;
                }
                q -= k - 1 - i;
            }
        add_term(&d, n, k, x, use, fl, fa, fb);
        bad = fit(&d, ym, &rss, &rank);
        a->fa[a->nterm] = fa, a->fb[a->nterm] = fb;
        a->ss[a->nterm] = prev - rss;
        a->df[a->nterm++] = rank - prank;
        prev = rss, prank = rank;
    }
    a->ss_resid = prev;
    a->df_resid = a->n - prank;
    a->interactions = inter;
    free(d.X);
    return bad;
}

mcs_status an_anova_fit(int n, int k, const double *x, const double *y, int interactions,
                        an_anova *a, mcs_error *err)
{
    memset(a, 0, sizeof *a);
    if (k < 1 || k + k * (k - 1) / 2 > AN_ANOVA_MAXTERM)
        return MCS_ERR(err, MCS_ERR_USAGE, "error: ANOVA of %d factors", k);
    char *use = calloc((size_t)n + 1, 1);
    double *ym = malloc(((size_t)n + 1) * sizeof *ym);
    factor_levels *fl = malloc(sizeof *fl);
    mcs_status st = use && ym && fl ? MCS_OK : MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    double mean = 0;
    for (int i = 0; !st && i < n; i++) {
        int ok = !isnan(y[i]);
        for (int j = 0; j < k; j++)
            ok = ok && !isnan(x[(size_t)i * k + j]);
        if (ok) use[i] = 1, ym[a->n++] = y[i], mean += y[i];
    }
    for (int j = 0; !st && j < k; j++)
        if ((fl->L[j] = levels(n, k, x, use, j, fl->lev[j])) < 0)
            st = MCS_ERR(err, MCS_ERR_USAGE, "error: factor %d has more than %d levels", j + 1,
                         MAXLEV);
    if (!st) {
        mean /= a->n;
        for (int i = 0; i < a->n; i++)
            a->ss_total += (ym[i] - mean) * (ym[i] - mean);
        int inter = interactions && k > 1;
        int rc = run_model(n, k, x, use, ym, fl, inter, a);
        if (!rc && inter && a->df_resid < 1) rc = run_model(n, k, x, use, ym, fl, 0, a);
        if (rc) st = MCS_ERR(err, MCS_ERR_NOMEM, "error: the ANOVA fit failed");
    }
    for (int t = 0; !st && t < a->nterm; t++) {
        double ms = a->ss[t] / a->df[t], mse = a->ss_resid / a->df_resid;
        a->F[t] = a->df[t] > 0 && a->df_resid > 0 ? ms / mse : NAN;
        a->p[t] = an_f_sf(a->F[t], a->df[t], a->df_resid);
    }
    free(use), free(ym), free(fl);
    return st;
}

/* ---- MANOVA ---------------------------------------------------------------------------- */

extern void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info,
                    size_t luplo);

/* ln det of a symmetric positive definite nr x nr matrix (Cholesky); NaN when not SPD */
static double log_det(const double *S, int nr)
{
    double *c = malloc((size_t)nr * nr * sizeof *c), ld = 0;
    int info = 0;
    if (!c) return NAN;
    memcpy(c, S, (size_t)nr * nr * sizeof *c);
    dpotrf_("L", &nr, c, &nr, &info, 1);
    for (int i = 0; i < nr && !info; i++)
        ld += 2 * log(c[i + (size_t)i * nr]);
    free(c);
    return info ? NAN : ld;
}

/* S = R^T R (nr x nr) of residuals R (m x nr) */
static void sscp(const double *R, int m, int nr, double *S)
{
    for (int a = 0; a < nr; a++)
        for (int b = 0; b < nr; b++) {
            double s = 0;
            for (int i = 0; i < m; i++)
                s += R[i + (size_t)a * m] * R[i + (size_t)b * m];
            S[a + (size_t)b * nr] = s;
        }
}

/* Wilks' lambda of each term from the sequential SSCP drops, with Rao's F */
static int manova_model(int n, int k, const double *x, const char *use, const double *Y, int nr,
                        const factor_levels *fl, int inter, an_manova *a)
{
    int m = a->n, nt = k + (inter ? k * (k - 1) / 2 : 0), rank = 0, prank = 0, bad = 0;
    design d = {.m = m, .cap = count_cols(k, fl, inter)};
    d.X = malloc((size_t)m * d.cap * sizeof *d.X);
    double *R = malloc((size_t)m * nr * sizeof *R);
    double *S = malloc((size_t)(nt + 2) * nr * nr * sizeof *S); /* SSCP after each fit */
    if (!d.X || !R || !S) bad = -1;
    for (int i = 0; !bad && i < m; i++)
        d.X[i] = 1;
    d.ncol = 1;
    int dfs[AN_ANOVA_MAXTERM];
    bad = bad ? bad : fit_resid(&d, Y, nr, R, &prank);
    if (!bad) sscp(R, m, nr, S);
    for (int t = 0; !bad && t < nt; t++) {
        int fa = t, fb = -1;
        if (t >= k)
            for (int q = t - k, i = 0; i < k; i++) {
                if (q < k - 1 - i) {
                    fa = i, fb = i + 1 + q;
                    break;
                }
                q -= k - 1 - i;
            }
        add_term(&d, n, k, x, use, fl, fa, fb);
        bad = fit_resid(&d, Y, nr, R, &rank);
        if (!bad) sscp(R, m, nr, S + (size_t)(t + 1) * nr * nr);
        a->fa[t] = fa, a->fb[t] = fb, dfs[t] = rank - prank;
        prank = rank;
    }
    a->nterm = nt;
    a->df_resid = m - prank;
    a->interactions = inter;
    const double *E = S + (size_t)nt * nr * nr;
    double lde = log_det(E, nr);
    for (int t = 0; !bad && t < nt; t++) {
        /* E + H with H = S_(t) - S_(t+1): the residual SSCP before the term's drop */
        double *EH = malloc((size_t)nr * nr * sizeof *EH);
        for (int q = 0; EH && q < nr * nr; q++)
            EH[q] = E[q] + S[(size_t)t * nr * nr + q] - S[(size_t)(t + 1) * nr * nr + q];
        double w = EH ? exp(lde - log_det(EH, nr)) : NAN;
        free(EH);
        /* Rao's F (statsmodels' _multivariate_test): p responses, q hypothesis df, v = df_E */
        double p = nr, q = dfs[t], v = a->df_resid, r = v - (p - q + 1) / 2, u = (p * q - 2) / 4;
        double tt = p * p + q * q - 5 > 0 ? sqrt((p * p * q * q - 4) / (p * p + q * q - 5)) : 1;
        double w1 = pow(w, 1 / tt);
        a->df[t] = dfs[t];
        a->wilks[t] = w;
        a->df1[t] = p * q;
        a->df2[t] = r * tt - 2 * u;
        a->F[t] = q > 0 ? (1 - w1) / w1 * a->df2[t] / a->df1[t] : NAN;
        a->p[t] = an_f_sf(a->F[t], a->df1[t], a->df2[t]);
    }
    free(d.X), free(R), free(S);
    return bad;
}

mcs_status an_manova_fit(int n, int k, const double *x, int nr, const double *y,
                         int interactions, an_manova *a, mcs_error *err)
{
    memset(a, 0, sizeof *a);
    if (k < 1 || k + k * (k - 1) / 2 > AN_ANOVA_MAXTERM || nr < 1)
        return MCS_ERR(err, MCS_ERR_USAGE, "error: MANOVA of %d factors, %d responses", k, nr);
    char *use = calloc((size_t)n + 1, 1);
    double *Y = malloc(((size_t)n * nr + 1) * sizeof *Y);
    factor_levels *fl = malloc(sizeof *fl);
    mcs_status st = use && Y && fl ? MCS_OK : MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    for (int i = 0; !st && i < n; i++) {
        int ok = 1;
        for (int j = 0; j < k; j++)
            ok = ok && !isnan(x[(size_t)i * k + j]);
        for (int q = 0; q < nr; q++)
            ok = ok && !isnan(y[(size_t)i * nr + q]);
        use[i] = (char)ok;
        a->n += ok;
    }
    for (int i = 0, r = 0; !st && i < n; i++)
        for (int q = 0; use[i] && q < nr; q++)
            Y[r + (size_t)q * a->n] = y[(size_t)i * nr + q], r += q == nr - 1;
    a->nresp = nr;
    for (int j = 0; !st && j < k; j++)
        if ((fl->L[j] = levels(n, k, x, use, j, fl->lev[j])) < 0)
            st = MCS_ERR(err, MCS_ERR_USAGE, "error: factor %d has more than %d levels", j + 1,
                         MAXLEV);
    if (!st) {
        int inter = interactions && k > 1;
        int rc = manova_model(n, k, x, use, Y, nr, fl, inter, a);
        if (!rc && inter && a->df_resid < nr) rc = manova_model(n, k, x, use, Y, nr, fl, 0, a);
        if (rc) st = MCS_ERR(err, MCS_ERR_NOMEM, "error: the MANOVA fit failed");
        else if (a->df_resid < nr)
            st = MCS_ERR(err, MCS_ERR_NUMERIC, "%d residual degrees of freedom for %d responses",
                         a->df_resid, nr);
    }
    free(use), free(Y), free(fl);
    return st;
}

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

/* residual sum of squares and rank of the fit of y on the first ncol columns of d */
static int fit(const design *d, const double *y, double *rss, int *rank)
{
    int m = d->m, nc = d->ncol, one = 1, info = 0, lwork = -1;
    double rcond = 1e-10, wq;
    double *A = malloc((size_t)m * nc * sizeof *A), *b = malloc((size_t)m * sizeof *b);
    int *jpvt = calloc((size_t)nc, sizeof *jpvt);
    if (!A || !b || !jpvt) {
        free(A), free(b), free(jpvt);
        return -1;
    }
    memcpy(A, d->X, (size_t)m * nc * sizeof *A);
    memcpy(b, y, (size_t)m * sizeof *b);
    dgelsy_(&m, &nc, &one, A, &m, b, &m, jpvt, &rcond, rank, &wq, &lwork, &info);
    lwork = (int)wq;
    double *work = malloc((size_t)lwork * sizeof *work);
    if (work) dgelsy_(&m, &nc, &one, A, &m, b, &m, jpvt, &rcond, rank, work, &lwork, &info);
    *rss = 0;
    for (int i = 0; i < m && work && !info; i++) {
        double r = y[i];
        for (int c = 0; c < nc; c++)
            r -= d->X[i + (size_t)c * m] * b[c];
        *rss += r * r;
    }
    int bad = !work || info;
    free(A), free(b), free(jpvt), free(work);
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

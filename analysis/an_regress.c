/* an_regress.c: multiple linear regression by LAPACK least squares (an_stats.h). The factors
 * are centred and scaled to unit sample sd before the QR factorization (SI values of a study
 * span many decades: a stiffness of 1e5 N/m beside an angle of 1 rad), and the coefficients and
 * their covariance transformed back. */
#include "analysis/an_stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* LAPACK (Fortran: character lengths passed last, by value) */
extern void dgels_(const char *trans, const int *m, const int *n, const int *nrhs, double *a,
                   const int *lda, double *b, const int *ldb, double *work, const int *lwork,
                   int *info, size_t ltrans);
extern void dtrtri_(const char *uplo, const char *diag, const int *n, double *a, const int *lda,
                    int *info, size_t luplo, size_t ldiag);

void an_regression_free(an_regression *r)
{
    free(r->coef);
    free(r->se);
    free(r->t);
    free(r->p);
    free(r->std_coef);
    free(r->partial);
    memset(r, 0, sizeof *r);
}

static int row_ok(int k, const double *x, double y)
{
    if (isnan(y)) return 0;
    for (int j = 0; j < k; j++)
        if (isnan(x[j])) return 0;
    return 1;
}

/* mean and sample sd of column j (or y when j < 0) over the usable rows */
static void col_stats(int n, int k, const double *x, const double *y, const char *use, int j,
                      double *mean, double *sd)
{
    double s = 0, s2 = 0;
    int m = 0;
    for (int i = 0; i < n; i++)
        if (use[i]) s += j < 0 ? y[i] : x[i * k + j], m++;
    *mean = s / m;
    for (int i = 0; i < n; i++) {
        if (!use[i]) continue;
        double d = (j < 0 ? y[i] : x[i * k + j]) - *mean;
        s2 += d * d;
    }
    *sd = m > 1 ? sqrt(s2 / (m - 1)) : 0;
}

/* least squares of the scaled system A c = b (A m x p column-major, overwritten by its QR);
 * c in b[0..p-1], residual sum of squares returned, R^-1 left in A's upper triangle */
static int solve_qr(int m, int p, double *A, double *b, double *sse)
{
    int one = 1, info = 0, lwork = -1;
    double wq;
    dgels_("N", &m, &p, &one, A, &m, b, &m, &wq, &lwork, &info, 1);
    lwork = (int)wq;
    double *work = malloc((size_t)lwork * sizeof *work);
    if (!work) return -1;
    dgels_("N", &m, &p, &one, A, &m, b, &m, work, &lwork, &info, 1);
    free(work);
    if (info) return info;
    /* a diagonal of R far below the largest: the columns are (nearly) collinear */
    double rmax = 0;
    for (int j = 0; j < p; j++)
        rmax = fmax(rmax, fabs(A[j + (size_t)j * m]));
    for (int j = 0; j < p; j++)
        if (!(fabs(A[j + (size_t)j * m]) > 1e-10 * rmax)) return -2;
    *sse = 0;
    for (int i = p; i < m; i++)
        *sse += b[i] * b[i]; /* dgels leaves Q^T b's tail: the residual's coordinates */
    dtrtri_("U", "N", &p, A, &m, &info, 1, 1);
    return info;
}

static mcs_status alloc_result(an_regression *r, int k)
{
    r->coef = calloc((size_t)k + 1, sizeof(double));
    r->se = calloc((size_t)k + 1, sizeof(double));
    r->t = calloc((size_t)k + 1, sizeof(double));
    r->p = calloc((size_t)k + 1, sizeof(double));
    r->std_coef = calloc((size_t)k + 1, sizeof(double));
    r->partial = calloc((size_t)k + 1, sizeof(double));
    return r->coef && r->se && r->t && r->p && r->std_coef && r->partial ? MCS_OK
                                                                          : MCS_ERR_NOMEM;
}

/* coefficients and their covariance back from the scaled ones: b_j = c_j / sd_j,
 * b0 = c0 - sum_j b_j mean_j; cov(c) = s^2 Rinv Rinv^T */
static void back_transform(an_regression *r, int m, int k, const double *A, const double *c,
                           const double *mean, const double *sd, double s2)
{
    int p = k + 1;
    double *t0 = malloc((size_t)p * sizeof *t0);
    if (!t0) return;
    t0[0] = 1;
    r->coef[0] = c[0];
    for (int j = 1; j < p; j++) {
        r->coef[j] = c[j] / sd[j - 1];
        r->coef[0] -= r->coef[j] * mean[j - 1];
        t0[j] = -mean[j - 1] / sd[j - 1];
    }
    /* var(u^T c) = s^2 |Rinv^T u|^2 with Rinv upper triangular in A (leading dim m) */
    for (int q = 0; q < p; q++) {
        double v = 0;
        for (int col = 0; col < p; col++) {
            double w = 0; /* (Rinv^T u)_col = sum_row Rinv[row][col] u_row, row <= col */
            for (int row = 0; row <= col; row++) {
                double u = q == 0 ? t0[row] : (row == q ? 1 / sd[q - 1] : 0);
                w += A[row + (size_t)col * m] * u;
            }
            v += w * w;
        }
        r->se[q] = sqrt(s2 * v);
    }
    free(t0);
}

mcs_status an_regress(int n, int k, const double *x, const double *y, an_regression *r,
                      mcs_error *err)
{
    memset(r, 0, sizeof *r);
    char *use = calloc((size_t)n + 1, 1);
    int m = 0, p = k + 1;
    for (int i = 0; use && i < n; i++)
        m += use[i] = (char)row_ok(k, x + (size_t)i * k, y[i]);
    double *mean = calloc((size_t)p, sizeof *mean), *sd = calloc((size_t)p, sizeof *sd);
    double *A = calloc((size_t)(m + 1) * p, sizeof *A), *b = calloc((size_t)m + p, sizeof *b);
    mcs_status st = use && mean && sd && A && b ? alloc_result(r, k) : MCS_ERR_NOMEM;
    if (st) {
        st = MCS_ERR(err, st, "error: out of memory");
    } else if (m < k + 2) {
        st = MCS_ERR(err, MCS_ERR_NUMERIC, "%d usable observations for %d factors", m, k);
    }
    double ymean = 0, ysd = 0, sse = 0;
    for (int j = 0; j < k && !st; j++) {
        col_stats(n, k, x, y, use, j, &mean[j], &sd[j]);
        if (!(sd[j] > 0)) st = MCS_ERR(err, MCS_ERR_NUMERIC, "factor %d is constant", j + 1);
    }
    if (!st) {
        col_stats(n, k, x, y, use, -1, &ymean, &ysd);
        for (int i = 0, row = 0; i < n; i++) {
            if (!use[i]) continue;
            A[row] = 1;
            for (int j = 0; j < k; j++)
                A[row + (size_t)(j + 1) * m] = (x[(size_t)i * k + j] - mean[j]) / sd[j];
            b[row++] = y[i];
        }
        if (solve_qr(m, p, A, b, &sse))
            st = MCS_ERR(err, MCS_ERR_NUMERIC, "the factors are collinear");
    }
    if (!st) {
        r->n = m, r->k = k, r->df = m - k - 1;
        double sst = ysd * ysd * (m - 1), s2 = sse / r->df;
        back_transform(r, m, k, A, b, mean, sd, s2);
        for (int q = 0; q < p; q++) {
            r->t[q] = r->coef[q] / r->se[q];
            r->p[q] = an_t_p2(r->t[q], r->df);
        }
        for (int j = 0; j < k; j++) {
            r->std_coef[j] = r->coef[j + 1] * sd[j] / ysd;
            r->partial[j] = r->t[j + 1] / sqrt(r->t[j + 1] * r->t[j + 1] + r->df);
        }
        r->sigma = sqrt(s2);
        r->r2 = 1 - sse / sst;
        r->adj_r2 = 1 - (1 - r->r2) * (m - 1) / r->df;
        r->F = (sst - sse) / k / s2;
        r->F_p = an_f_sf(r->F, k, r->df);
    }
    free(use), free(mean), free(sd), free(A), free(b);
    if (st) an_regression_free(r);
    return st;
}

int an_rsm_nterm(int k)
{
    return 2 * k + k * (k - 1) / 2;
}

mcs_status an_rsm_fit(int n, int k, const double *x, const double *y, an_regression *r,
                      mcs_error *err)
{
    int q = an_rsm_nterm(k);
    double *z = malloc(((size_t)n * q + 1) * sizeof *z);
    if (!z) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    for (int i = 0; i < n; i++) {
        const double *xi = x + (size_t)i * k;
        double *zi = z + (size_t)i * q;
        int c = 0;
        for (int j = 0; j < k; j++)
            zi[c++] = xi[j];
        for (int j = 0; j < k; j++)
            zi[c++] = xi[j] * xi[j];
        for (int a = 0; a < k; a++)
            for (int b = a + 1; b < k; b++)
                zi[c++] = xi[a] * xi[b];
    }
    mcs_status st = an_regress(n, q, z, y, r, err);
    free(z);
    return st;
}

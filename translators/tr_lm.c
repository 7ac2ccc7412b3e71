/* tr_lm.c: bounded Levenberg-Marquardt (tr_lm.h). Marquardt (1963) damping on the diagonal
 * of J^T J; a trial step is clipped to the bounds and accepted when it lowers the cost
 * (lambda / 10), else rejected (lambda x 10). The Jacobian is a forward difference, stepped
 * inward at an upper bound. */
#include "translators/tr_lm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void dposv_(const char *uplo, const int *n, const int *nrhs, double *a, const int *lda, double *b,
            const int *ldb, int *info);

tr_lm_opts tr_lm_opts_default(void)
{
    return (tr_lm_opts){
        .max_iter = 50, .fd_rel = 1e-4, .ftol = 1e-10, .xtol = 1e-8, .lambda0 = 1e-3};
}

static double half_sq(const double *r, int m)
{
    double s = 0;
    for (int i = 0; i < m; i++)
        s += r[i] * r[i];
    return 0.5 * s;
}

static double clip(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

mcs_status tr_lm_solve(tr_lm_fn f, void *ctx, int n, int m, double *p, const double *lo,
                       const double *hi, const tr_lm_opts *o, tr_lm_result *res, mcs_error *err)
{
    tr_lm_opts d = o ? *o : tr_lm_opts_default();
    *res = (tr_lm_result){.why = "max_iter"};
    if (n < 1 || m < n)
        return MCS_ERR(err, MCS_ERR_RANGE, "least squares: %d residuals for %d parameters", m, n);
    for (int j = 0; j < n; j++) {
        if (!(hi[j] > lo[j]))
            return MCS_ERR(err, MCS_ERR_RANGE, "least squares: parameter %d bounds [%g, %g]", j + 1,
                           lo[j], hi[j]);
        p[j] = clip(p[j], lo[j], hi[j]);
    }
    size_t nn = (size_t)n, mm = (size_t)m;
    double *buf = calloc(3 * mm + mm * nn + 2 * nn * nn + 4 * nn, sizeof(double));
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "least squares: out of memory");
    double *r = buf, *rt = r + mm, *rj = rt + mm, *J = rj + mm, *A = J + mm * nn;
    double *A2 = A + nn * nn, *g = A2 + nn * nn, *dp = g + nn, *pt = dp + nn, *hs = pt + nn;
    double *P = A2; /* the Jacobian's points [n x n], before A2 is used */
    mcs_status st = f(ctx, p, r, err);
    res->nfev = 1;
    double cost = st ? 0 : half_sq(r, m), lambda = d.lambda0;
    res->cost0 = cost;
    for (int it = 0; !st && it < d.max_iter; it++) {
        res->iter = it + 1;
        /* forward-difference Jacobian, column j (all at once with `many`: P in A2's place) */
        for (int j = 0; j < n; j++) {
            double h = d.fd_rel * (hi[j] - lo[j]);
            hs[j] = p[j] + h > hi[j] ? -h : h;
            memcpy(P + (size_t)j * nn, p, nn * sizeof(double));
            P[(size_t)j * nn + (size_t)j] += hs[j];
        }
        if (d.many) st = d.many(ctx, n, P, J, err);
        for (int j = 0; j < n && !st; j++) {
            double *col = J + (size_t)j * mm;
            if (!d.many) st = f(ctx, P + (size_t)j * nn, rj, err);
            for (int i = 0; i < m && !st; i++)
                col[i] = ((d.many ? col[i] : rj[i]) - r[i]) / hs[j];
        }
        res->nfev += n;
        if (st) break;
        for (int a = 0; a < n; a++) {
            double s = 0;
            for (int i = 0; i < m; i++)
                s += J[(size_t)a * mm + (size_t)i] * r[i];
            g[a] = s;
            for (int b = 0; b < n; b++) {
                double t = 0;
                for (int i = 0; i < m; i++)
                    t += J[(size_t)a * mm + (size_t)i] * J[(size_t)b * mm + (size_t)i];
                A[(size_t)b * nn + (size_t)a] = t;
            }
        }
        int accepted = 0;
        double small = 0;
        while (!accepted && lambda < 1e12) {
            memcpy(A2, A, nn * nn * sizeof(double));
            for (int a = 0; a < n; a++) {
                double dg = A[(size_t)a * nn + (size_t)a];
                A2[(size_t)a * nn + (size_t)a] += lambda * (dg > 0 ? dg : 1e-12);
                dp[a] = -g[a];
            }
            int one = 1, info = 0;
            dposv_("L", &n, &one, A2, &n, dp, &n, &info);
            if (info != 0) {
                lambda *= 10;
                continue;
            }
            small = 1;
            for (int a = 0; a < n; a++) {
                pt[a] = clip(p[a] + dp[a], lo[a], hi[a]);
                if (fabs(pt[a] - p[a]) >= d.xtol * (hi[a] - lo[a])) small = 0;
            }
            if (small) break;
            st = f(ctx, pt, rt, err);
            res->nfev++;
            if (st) break;
            double ct = half_sq(rt, m);
            if (ct < cost) {
                accepted = 1;
                double drop = cost - ct;
                memcpy(p, pt, nn * sizeof(double));
                memcpy(r, rt, mm * sizeof(double));
                cost = ct;
                lambda = fmax(lambda / 10, 1e-12);
                if (drop <= d.ftol * ct) {
                    res->why = "ftol";
                    it = d.max_iter;
                }
            } else {
                lambda *= 10;
            }
        }
        if (st) break;
        if (!accepted) {
            res->why = small ? "xtol" : "lambda";
            break;
        }
    }
    res->cost = cost;
    free(buf);
    return st;
}

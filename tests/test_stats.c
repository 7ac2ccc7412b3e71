/* test_stats.c: the statistics of studies (analysis/an_stats.h) and their designs
 * (analysis/an_doe.h). Every reference value was computed outside mcrash with SciPy 1.10.1 and
 * statsmodels 0.13.5 by scripts/study_stats_reference.py (its output kept here as literals);
 * the data sets are cited where they are defined. */
#include "analysis/an_doe.h"
#include "analysis/an_stats.h"
#include "harness.h"

/* I_x(a,b) against scipy.special.betainc */
static void test_betainc(void)
{
    static const double ref[][4] = {
        {0.5, 0.5, 0.3, 0.36901011956554541},  {2, 3, 0.4, 0.52479999999999993},
        {10, 0.5, 0.9, 0.15164090963470997},   {0.5, 10, 0.01, 0.34207182484321552},
        {50, 60, 0.45, 0.46423529143060638},   {1, 1, 0.77, 0.77000000000000002},
        {200, 3, 0.99, 0.67123817103838634},   {3.5, 0.5, 0.999, 0.9356322688440224},
    };
    for (size_t i = 0; i < sizeof ref / sizeof ref[0]; i++)
        CHECK_NEAR(an_betainc(ref[i][0], ref[i][1], ref[i][2]), ref[i][3], 1e-13);
    /* integer a, b: I_x(a, n-a+1) = sum_{j=a..n} C(n,j) x^j (1-x)^(n-j) (A&S 6.6.4), by hand
     * for I_x(2, 3) */
    double x = 0.4, q = 1 - x;
    CHECK_NEAR(an_betainc(2, 3, x), 6 * x * x * q * q + 4 * x * x * x * q + x * x * x * x, 1e-15);
    CHECK(isnan(an_betainc(-1, 2, 0.5)) && isnan(an_betainc(1, 2, 1.5)));
    CHECK(an_betainc(2, 3, 0) == 0 && an_betainc(2, 3, 1) == 1);
}

/* two-sided t and upper-tail F against scipy.stats (2 t.sf(|t|, df), f.sf) */
static void test_t_f(void)
{
    static const double t[][3] = {
        {0.5, 1, 0.70483276469913358},   {2.0, 3, 0.13932596855884311},
        {-2.5, 10, 0.031446844236608776}, {4.0, 30, 0.00038184563608375637},
        {8.0, 100, 2.2728648077280803e-12}, {1.96, 1e6, 0.049996067585269782},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
        CHECK_REL(an_t_p2(t[i][0], t[i][1]), t[i][2], 1e-10);
    static const double f[][4] = {
        {1.0, 1, 1, 0.50000000000000011},     {3.5, 2, 27, 0.044508753946400192},
        {28.97, 2, 27, 1.9071961058423554e-07}, {0.2, 5, 7, 0.95241645022142751},
        {50, 3, 40, 1.3443392666414119e-13},
    };
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++)
        CHECK_REL(an_f_sf(f[i][0], f[i][1], f[i][2]), f[i][3], 1e-10);
}

/* Longley (1967), JASA 62:819-841, the NIST StRD "Longley" data: TOTEMP on GNPDEFL, GNP,
 * UNEMP, ARMED, POP, YEAR (an ill-conditioned least-squares benchmark) */
static const double longley[16][7] = {
    {60323, 83, 234289, 2356, 1590, 107608, 1947},
    {61122, 88.5, 259426, 2325, 1456, 108632, 1948},
    {60171, 88.2, 258054, 3682, 1616, 109773, 1949},
    {61187, 89.5, 284599, 3351, 1650, 110929, 1950},
    {63221, 96.2, 328975, 2099, 3099, 112075, 1951},
    {63639, 98.1, 346999, 1932, 3594, 113270, 1952},
    {64989, 99, 365385, 1870, 3547, 115094, 1953},
    {63761, 100, 363112, 3578, 3350, 116219, 1954},
    {66019, 101.2, 397469, 2904, 3048, 117388, 1955},
    {67857, 104.6, 419180, 2822, 2857, 118734, 1956},
    {68169, 108.4, 442769, 2936, 2798, 120445, 1957},
    {66513, 110.8, 444546, 4681, 2637, 121950, 1958},
    {68655, 112.6, 482704, 3813, 2552, 123366, 1959},
    {69564, 114.2, 502601, 3931, 2514, 125368, 1960},
    {69331, 115.7, 518173, 4806, 2572, 127852, 1961},
    {70551, 116.9, 554894, 4007, 2827, 130081, 1962},
};

/* statsmodels OLS of the Longley data: coefficient, standard error, t, p (intercept first);
 * the coefficients are NIST's certified values to the digits NIST gives (-3482258.63459582,
 * 15.0618722713733, ...) */
static const double longley_ref[7][4] = {
    {-3482258.6345978603, 890420.38360750501, -3.9108029181560502, 0.0035604036637169635},
    {15.061872271525772, 84.914925774657746, 0.17737602823202231, 0.86314083280767118},
    {-0.035819179292641001, 0.033491007772246388, -1.069516317222438, 0.31268106109211785},
    {-2.0202298038173119, 0.48839968165168235, -4.1364273559418541, 0.0025350917341069694},
    {-1.0332268671736102, 0.21427416316167455, -4.8219853104455614, 0.00094436676416166166},
    {-0.051104105653736909, 0.22607320006936232, -0.22605114466490267, 0.82621179576311976},
    {1829.1514646145988, 455.47849914228379, 4.0158898127114506, 0.0030368033416226701},
};
static const double longley_std[6] = {0.046282022671376655, -1.0137463487159388,
                                      -0.53754257763949587, -0.20474069234425518,
                                      -0.10122111394615993, 2.4796643829482452};

static void test_regress_longley(void)
{
    double x[16 * 6], y[16];
    for (int i = 0; i < 16; i++) {
        y[i] = longley[i][0];
        for (int j = 0; j < 6; j++)
            x[i * 6 + j] = longley[i][j + 1];
    }
    an_regression r;
    mcs_error err = {0};
    CHECK(an_regress(16, 6, x, y, &r, &err) == MCS_OK);
    if (!r.coef) return;
    CHECK(r.n == 16 && r.df == 9);
    for (int q = 0; q < 7; q++) {
        CHECK_REL(r.coef[q], longley_ref[q][0], 1e-8);
        CHECK_REL(r.se[q], longley_ref[q][1], 1e-8);
        CHECK_REL(r.t[q], longley_ref[q][2], 1e-8);
        CHECK_REL(r.p[q], longley_ref[q][3], 1e-8);
    }
    for (int j = 0; j < 6; j++)
        CHECK_REL(r.std_coef[j], longley_std[j], 1e-8);
    CHECK_NEAR(r.r2, 0.99547900457729399, 1e-12);
    CHECK_NEAR(r.adj_r2, 0.99246500762882328, 1e-12);
    CHECK_REL(r.F, 330.28533923446855, 1e-8);
    CHECK_REL(r.F_p, 4.9840305287328682e-10, 1e-7);
    /* partial correlations: numpy's correlation of the residuals of y and of x_j on the other
     * factors (scripts/study_stats_reference.py), not the t identity the code uses */
    static const double partial[6] = {0.059022267544302259, -0.33580385785308176,
                                      -0.80950904495884757, -0.84908396418754428,
                                      -0.075137380463210626, 0.80113971623743441};
    for (int j = 0; j < 6; j++)
        CHECK_NEAR(r.partial[j], partial[j], 1e-8);
    an_regression_free(&r);

    /* a NaN response (a failed case) leaves its row out; a constant factor is refused */
    y[3] = NAN;
    CHECK(an_regress(16, 6, x, y, &r, &err) == MCS_OK && r.n == 15 && r.df == 8);
    an_regression_free(&r);
    for (int i = 0; i < 16; i++)
        x[i * 6 + 2] = 1;
    mcs_error_clear(&err);
    CHECK(an_regress(16, 6, x, y, &r, &err) == MCS_ERR_NUMERIC);
    CHECK_STR_CONTAINS(err.msg, "constant");
}

/* Montgomery, Design and Analysis of Experiments, 8th ed., Example 5.1 (Table 5.1): battery
 * life [h] of material type 1..3 at 15, 70, 125 degF, 4 replicates. Montgomery's Table 5.5
 * gives SS 10683.72, 39118.72, 9613.78, error 18230.75; F 7.91, 28.97, 3.56 */
static const double life[3][3][4] = {
    {{130, 155, 74, 180}, {34, 40, 80, 75}, {20, 70, 82, 58}},
    {{150, 188, 159, 126}, {136, 122, 106, 115}, {25, 70, 58, 45}},
    {{138, 110, 168, 160}, {174, 120, 150, 139}, {96, 104, 82, 60}},
};

static int battery(double *x, double *y)
{
    static const double temp[3] = {15, 70, 125};
    int n = 0;
    for (int m = 0; m < 3; m++)
        for (int t = 0; t < 3; t++)
            for (int r = 0; r < 4; r++, n++)
                x[2 * n] = m + 1, x[2 * n + 1] = temp[t], y[n] = life[m][t][r];
    return n;
}

static void check_anova(const an_anova *a, const double ref[][4], int nterm, double ssr, int dfr)
{
    CHECK(a->nterm == nterm);
    for (int t = 0; t < nterm && t < a->nterm; t++) {
        CHECK(a->df[t] == (int)ref[t][0]);
        CHECK_REL(a->ss[t], ref[t][1], 1e-10);
        CHECK_REL(a->F[t], ref[t][2], 1e-10);
        CHECK_REL(a->p[t], ref[t][3], 1e-8);
    }
    CHECK_REL(a->ss_resid, ssr, 1e-10);
    CHECK(a->df_resid == dfr);
}

static void test_anova_battery(void)
{
    double x[72], y[36];
    int n = battery(x, y);
    an_anova a;
    mcs_error err = {0};
    /* statsmodels anova_lm(ols("life ~ C(mat) + C(temp) + C(mat):C(temp)"), typ=1) */
    static const double full[3][4] = {
        {2, 10683.722222222224, 7.9113722693800312, 0.0019760825909075253},
        {2, 39118.722222222204, 28.967691949042123, 1.908595897433208e-07},
        {4, 9613.7777777777792, 3.559535400353798, 0.018611168188941721},
    };
    CHECK(an_anova_fit(n, 2, x, y, 1, &a, &err) == MCS_OK && a.interactions == 1);
    check_anova(&a, full, 3, 18230.750000000004, 27);
    CHECK(a.fa[2] == 0 && a.fb[2] == 1 && a.fb[0] == -1);
    /* main effects only: "life ~ C(mat) + C(temp)" */
    static const double main[2][4] = {
        {2, 10683.722222222224, 5.9472258163632805, 0.0065146170623930607},
        {2, 39118.722222222204, 21.775919465524336, 1.2388013435131213e-06},
    };
    CHECK(an_anova_fit(n, 2, x, y, 0, &a, &err) == MCS_OK && a.interactions == 0);
    check_anova(&a, main, 2, 27844.527777777777, 31);
    /* unbalanced: cases 0, 5, 17 failed (NaN): sequential (type I) sums of squares */
    y[0] = y[5] = y[17] = NAN;
    static const double unb[3][4] = {
        {2, 9763.1196969696794, 6.582926291467901, 0.0052578198436125457},
        {2, 37342.164553307448, 25.178500771079065, 1.2784168289829334e-06},
        {4, 7562.0945376016261, 2.5494264382313525, 0.065355676047530634},
    };
    CHECK(an_anova_fit(n, 2, x, y, 1, &a, &err) == MCS_OK && a.n == 33);
    check_anova(&a, unb, 3, 17797.166666666668, 24);
}

/* a quadratic response surface of battery life on material (1, 2, 3) and temperature [degF]:
 * statsmodels ols("life ~ mat + temp + I(mat**2) + I(temp**2) + mat:temp"), the same column
 * order as an_rsm_fit's; coefficient, standard error, p */
static void test_rsm_battery(void)
{
    double x[72], y[36];
    int n = battery(x, y);
    static const double ref[6][3] = {
        {109.90955004583201, 44.587703710030709, 0.019645135065977339},
        {31.825757575757653, 44.315102576736955, 0.47820883601454267},
        {-0.76108815426974452, 0.57769191431234734, 0.19765694749001453},
        {-4.2083333333335311, 10.702991263695434, 0.69695784344418832},
        {-0.0010192837465509271, 0.0035381789301479113, 0.77526534378150713},
        {0.085227272727279438, 0.137602867300717, 0.54034743879752289},
    };
    an_regression r;
    mcs_error err = {0};
    CHECK(an_rsm_nterm(2) == 5);
    CHECK(an_rsm_fit(n, 2, x, y, &r, &err) == MCS_OK);
    for (int q = 0; q < 6 && r.coef; q++) {
        CHECK_REL(r.coef[q], ref[q][0], 1e-8);
        CHECK_REL(r.se[q], ref[q][1], 1e-8);
        CHECK_REL(r.p[q], ref[q][2], 1e-8);
    }
    CHECK_NEAR(r.r2, 0.64592353712010664, 1e-12);
    an_regression_free(&r);
    /* two levels only: x^2 is a line in x, refused */
    double x2[8] = {0, 0, 1, 0, 0, 1, 1, 1}, y2[4] = {1, 2, 3, 5};
    mcs_error_clear(&err);
    CHECK(an_rsm_fit(4, 2, x2, y2, &r, &err) != MCS_OK);
}

/* Hald's cement data (Hald 1952; Draper & Smith, Applied Regression Analysis, 3rd ed., Appendix
 * 15A): heat [cal/g] on 4 ingredients [%]. Stepwise with statsmodels p-values in the reference
 * script: p_enter 0.10, p_remove 0.15 gives x4, x1, x2 in, x4 out: {x1, x2}, Draper & Smith's
 * path; p_enter 0.05, p_remove 0.10 stops at {x1, x4} (x2's p in the 3-factor model is 0.052) */
static void test_stepwise_hald(void)
{
    static const double hald[13][5] = {
        {7, 26, 6, 60, 78.5},   {1, 29, 15, 52, 74.3},  {11, 56, 8, 20, 104.3},
        {11, 31, 8, 47, 87.6},  {7, 52, 6, 33, 95.9},   {11, 55, 9, 22, 109.2},
        {3, 71, 17, 6, 102.7},  {1, 31, 22, 44, 72.5},  {2, 54, 18, 22, 93.1},
        {21, 47, 4, 26, 115.9}, {1, 40, 23, 34, 83.8},  {11, 66, 9, 12, 113.3},
        {10, 68, 8, 12, 109.4},
    };
    double x[13 * 4], y[13];
    for (int i = 0; i < 13; i++) {
        y[i] = hald[i][4];
        for (int j = 0; j < 4; j++)
            x[i * 4 + j] = hald[i][j];
    }
    int sel[4], order[32], nstep;
    mcs_error err = {0};
    CHECK(an_stepwise(13, 4, x, y, 0.10, 0.15, sel, order, &nstep, &err) == MCS_OK);
    CHECK(nstep == 4 && order[0] == 4 && order[1] == 1 && order[2] == 2 && order[3] == -4);
    CHECK(sel[0] && sel[1] && !sel[2] && !sel[3]);
    CHECK(an_stepwise(13, 4, x, y, 0.05, 0.10, sel, order, &nstep, &err) == MCS_OK);
    CHECK(nstep == 2 && order[0] == 4 && order[1] == 1);
    CHECK(sel[0] && !sel[1] && !sel[2] && sel[3]);
}

/* MANOVA: Johnson & Wichern, Applied Multivariate Statistical Analysis, 6th ed., Example 6.13
 * (plastic film, rate x additive, 5 replicates; tear resistance, gloss, opacity). The book
 * gives Wilks' lambda 0.3819 (rate), 0.5230 (additive), 0.7771 (interaction), F 7.55, 4.26,
 * 1.34 on (3, 14) df; the literals are statsmodels' MANOVA.mv_test with sum coding */
static void test_manova_film(void)
{
    static const double film[20][5] = {
        {0, 0, 6.5, 9.5, 4.4}, {0, 0, 6.2, 9.9, 6.4}, {0, 0, 5.8, 9.6, 3.0},
        {0, 0, 6.5, 9.6, 4.1}, {0, 0, 6.5, 9.2, 0.8}, {0, 1, 6.9, 9.1, 5.7},
        {0, 1, 7.2, 10.0, 2.0}, {0, 1, 6.9, 9.9, 3.9}, {0, 1, 6.1, 9.5, 1.9},
        {0, 1, 6.3, 9.4, 5.7}, {1, 0, 6.7, 9.1, 2.8}, {1, 0, 6.6, 9.3, 4.1},
        {1, 0, 7.2, 8.3, 3.8}, {1, 0, 7.1, 8.4, 1.6}, {1, 0, 6.8, 8.5, 3.4},
        {1, 1, 7.1, 9.2, 8.4}, {1, 1, 7.0, 8.8, 5.2}, {1, 1, 7.2, 9.7, 6.9},
        {1, 1, 7.5, 10.1, 2.7}, {1, 1, 7.6, 9.2, 1.9},
    };
    double x[40], y[60];
    for (int i = 0; i < 20; i++) {
        x[2 * i] = film[i][0], x[2 * i + 1] = film[i][1];
        for (int q = 0; q < 3; q++)
            y[3 * i + q] = film[i][2 + q];
    }
    static const double ref[3][3] = {
        {0.38185838466113142, 7.5542687746434884, 0.0030340451602603163},
        {0.52303489541905168, 4.2556188395953347, 0.024745280999061772},
        {0.77710575787349478, 1.3385219699955189, 0.30178164509983046},
    };
    an_manova a;
    mcs_error err = {0};
    CHECK(an_manova_fit(20, 2, x, 3, y, 1, &a, &err) == MCS_OK);
    CHECK(a.nterm == 3 && a.interactions && a.df_resid == 16);
    for (int t = 0; t < 3 && a.nterm == 3; t++) {
        CHECK_REL(a.wilks[t], ref[t][0], 1e-10);
        CHECK_REL(a.F[t], ref[t][1], 1e-10);
        CHECK_REL(a.p[t], ref[t][2], 1e-8);
        CHECK(a.df1[t] == 3 && a.df2[t] == 14);
    }
}

/* an unreplicated 2x2: the interaction would leave no residual df, so it is pooled; the
 * main-effect SS of a 2-level factor is N (effect/2)^2 (Montgomery 6.2: SS_A = [A]^2 / 4n) */
static void test_anova_2x2(void)
{
    double x[8] = {0, 0, 1, 0, 0, 1, 1, 1}, y[4] = {10, 14, 20, 30};
    an_anova a;
    mcs_error err = {0};
    CHECK(an_anova_fit(4, 2, x, y, 1, &a, &err) == MCS_OK);
    CHECK(a.interactions == 0 && a.nterm == 2 && a.df_resid == 1);
    double effA = (14 + 30 - 10 - 20) / 2.0, effB = (20 + 30 - 10 - 14) / 2.0;
    CHECK_NEAR(a.ss[0], 4 * (effA / 2) * (effA / 2), 1e-9);
    CHECK_NEAR(a.ss[1], 4 * (effB / 2) * (effB / 2), 1e-9);
    double ab = (10 + 30 - 14 - 20) / 2.0; /* the pooled interaction */
    CHECK_NEAR(a.ss_resid, 4 * (ab / 2) * (ab / 2), 1e-9);
}

/* the standard fractional designs: each generator set has the resolution the table states
 * (the shortest word of its defining relation, counted independently of the table), and
 * every column is balanced and orthogonal to the others */
static void test_fractional(void)
{
    const char *gen[8];
    int ngen;
    for (int k = 3; k <= 8; k++) {
        for (int res = 3; res <= k; res++) {
            int got = an_doe_standard(k, res, gen, &ngen);
            if (!got) continue;
            CHECK(got >= res);
            CHECK(an_doe_resolution(k, ngen, gen) == got);
            int sign[256 * 8];
            char why[128];
            long n = an_doe_fractional(k, ngen, gen, sign, 256, why, sizeof why);
            CHECK(n == 1L << (k - ngen));
            for (int a = 0; a < k; a++)
                for (int b = a; b < k; b++) {
                    long s = 0;
                    for (long c = 0; c < n; c++)
                        s += b == a ? sign[c * k + a] : sign[c * k + a] * sign[c * k + b];
                    CHECK(s == (b == a ? 0 : 0));
                }
        }
    }
    /* resolution IV for 6 factors: 2^(6-2), E=ABC, F=BCD (Montgomery Table 8.14) */
    CHECK(an_doe_standard(6, 4, gen, &ngen) == 4 && ngen == 2 && !strcmp(gen[1], "F=BCD"));
    CHECK(an_doe_standard(3, 4, gen, &ngen) == 0); /* no 2^(3-p) of resolution IV */
    const char *bad[1] = {"D=AD"};
    char why[128];
    int sign[64];
    CHECK(an_doe_fractional(4, 1, bad, sign, 16, why, sizeof why) < 0);
    CHECK_STR_CONTAINS(why, "D=AD");
    const char *neg[1] = {"C=-AB"};
    CHECK(an_doe_fractional(3, 1, neg, sign, 16, why, sizeof why) == 4);
    for (int c = 0; c < 4; c++)
        CHECK(sign[c * 3 + 2] == -sign[c * 3] * sign[c * 3 + 1]);
    /* full factorial: first factor fastest */
    int nlev[2] = {2, 3}, idx[12];
    CHECK(an_doe_full(2, nlev, idx, 6) == 6 && idx[2] == 1 && idx[3] == 0 && idx[5] == 1);
}

/* SplitMix64 outputs of states 0 and 42 from an independent implementation of the published
 * algorithm (scripts/study_stats_reference.py); the Latin hypercube's strata */
static void test_lhs(void)
{
    uint64_t s = 0;
    CHECK(an_splitmix64(&s) == 0xe220a8397b1dcdafULL);
    CHECK(an_splitmix64(&s) == 0x6e789e6aa1b965f4ULL);
    CHECK(an_splitmix64(&s) == 0x06c45d188009454fULL);
    s = 42;
    CHECK(an_splitmix64(&s) == 0xbdd732262feb6e95ULL);
    enum { N = 17, K = 3 };
    double u[N * K], v[N * K];
    an_doe_lhs(N, K, 7, u);
    an_doe_lhs(N, K, 7, v);
    CHECK(memcmp(u, v, sizeof u) == 0);
    for (int j = 0; j < K; j++) {
        int seen[N] = {0};
        for (int i = 0; i < N; i++) {
            CHECK(u[i * K + j] >= 0 && u[i * K + j] < 1);
            seen[(int)(u[i * K + j] * N)]++;
        }
        for (int m = 0; m < N; m++)
            CHECK(seen[m] == 1);
    }
}

int main(void)
{
    RUN(test_betainc);
    RUN(test_t_f);
    RUN(test_regress_longley);
    RUN(test_anova_battery);
    RUN(test_anova_2x2);
    RUN(test_rsm_battery);
    RUN(test_stepwise_hald);
    RUN(test_manova_film);
    RUN(test_fractional);
    RUN(test_lhs);
    TEST_END();
}

#!/usr/bin/python3
"""Reference values for tests/test_stats.c, computed OUTSIDE mcrash with SciPy and statsmodels
(Debian: python3-scipy 1.10.1, python3-statsmodels 0.13.5). Run once by hand:
    /usr/bin/python3 scripts/study_stats_reference.py
and the printed numbers are kept as literals in tests/test_stats.c (the data sets are there too).
Data sets:
  - Longley (1967), "An appraisal of least squares programs for the electronic computer from the
    point of view of the user", JASA 62:819-841; as shipped in statsmodels.datasets.longley and
    certified by NIST StRD (Longley.dat): TOTEMP on GNPDEFL, GNP, UNEMP, ARMED, POP, YEAR.
  - Montgomery, Design and Analysis of Experiments, 8th ed., Example 5.1 (battery life, hours:
    material type 1..3 x temperature 15/70/125 degF, 4 replicates), Table 5.1.
  - the same battery data with cases 0, 5 and 17 left out (unbalanced: type I sums of squares).
"""
import numpy as np
import pandas as pd
import scipy.special as sp
import scipy.stats as st
import statsmodels.api as sm
import statsmodels.formula.api as smf
from statsmodels.stats.anova import anova_lm

def p(*a):
    print(*["%.17g" % v if isinstance(v, (float, np.floating)) else v for v in a])

print("# betainc(a, b, x)")
for a, b, x in [(0.5, 0.5, 0.3), (2, 3, 0.4), (10, 0.5, 0.9), (0.5, 10, 0.01), (50, 60, 0.45),
                (1, 1, 0.77), (200, 3, 0.99), (3.5, 0.5, 0.999)]:
    p(a, b, x, sp.betainc(a, b, x))
print("# two-sided t p: 2 sf(|t|, df)")
for t, df in [(0.5, 1), (2.0, 3), (-2.5, 10), (4.0, 30), (8.0, 100), (1.96, 1e6)]:
    p(t, df, 2 * st.t.sf(abs(t), df))
print("# F sf(f, d1, d2)")
for f, d1, d2 in [(1.0, 1, 1), (3.5, 2, 27), (28.97, 2, 27), (0.2, 5, 7), (50, 3, 40)]:
    p(f, d1, d2, st.f.sf(f, d1, d2))

print("# Longley regression")
d = sm.datasets.longley.load_pandas()
X, y = d.exog, d.endog
print("# data rows: TOTEMP GNPDEFL GNP UNEMP ARMED POP YEAR")
for i in range(len(y)):
    print(" ".join("%.17g" % v for v in [y.iloc[i]] + list(X.iloc[i])))
res = sm.OLS(y, sm.add_constant(X)).fit()
print("# coef se t p")
for k in res.params.index:
    p(k, res.params[k], res.bse[k], res.tvalues[k], res.pvalues[k])
sdx = X.std(ddof=1)
print("# standardized coefficients b sd(x)/sd(y)")
for k in X.columns:
    p(k, res.params[k] * sdx[k] / y.std(ddof=1))
p("r2", res.rsquared, "adj", res.rsquared_adj, "F", res.fvalue, "F_p", res.f_pvalue)

print("# battery life ANOVA")
life = [[[130, 155, 74, 180], [34, 40, 80, 75], [20, 70, 82, 58]],
        [[150, 188, 159, 126], [136, 122, 106, 115], [25, 70, 58, 45]],
        [[138, 110, 168, 160], [174, 120, 150, 139], [96, 104, 82, 60]]]
rows = []
for m in range(3):
    for ti, temp in enumerate([15, 70, 125]):
        for v in life[m][ti]:
            rows.append((m + 1, temp, v))
df = pd.DataFrame(rows, columns=["mat", "temp", "life"])
for typ in (1, 2):
    fit = smf.ols("life ~ C(mat) + C(temp) + C(mat):C(temp)", df).fit()
    print("# typ", typ)
    print(anova_lm(fit, typ=typ).to_string(float_format=lambda v: "%.17g" % v))
print("# unbalanced (rows 0, 5, 17 left out), type I")
du = df.drop(index=[0, 5, 17])
fit = smf.ols("life ~ C(mat) + C(temp) + C(mat):C(temp)", du).fit()
print(anova_lm(fit, typ=1).to_string(float_format=lambda v: "%.17g" % v))
print("# main effects only (no interaction), type I")
fit = smf.ols("life ~ C(mat) + C(temp)", df).fit()
print(anova_lm(fit, typ=1).to_string(float_format=lambda v: "%.17g" % v))

print("# SplitMix64 (Steele, Lea, Flood 2014; Vigna's splitmix64.c), state 0 and 42: 3 outputs")
M = (1 << 64) - 1
for seed in (0, 42):
    s = seed
    out = []
    for _ in range(3):
        s = (s + 0x9e3779b97f4a7c15) & M
        z = s
        z = ((z ^ (z >> 30)) * 0xbf58476d1ce4e5b9) & M
        z = ((z ^ (z >> 27)) * 0x94d049bb133111eb) & M
        out.append(z ^ (z >> 31))
    print(seed, " ".join("0x%016x" % v for v in out))

print("# partial correlations of TOTEMP with each Longley factor given the others (residuals)")
Xa = X.values
for j, name in enumerate(X.columns):
    others = sm.add_constant(np.delete(Xa, j, axis=1))
    ry = sm.OLS(y.values, others).fit().resid
    rx = sm.OLS(Xa[:, j], others).fit().resid
    p(name, np.corrcoef(ry, rx)[0, 1])

print("# quadratic response surface of battery life on material (1,2,3) and temperature [degF]")
fit = smf.ols("life ~ mat + temp + I(mat**2) + I(temp**2) + mat:temp", df).fit()
for k in fit.params.index:
    p(k, fit.params[k], fit.bse[k], fit.pvalues[k])
p("r2", fit.rsquared)

print("# stepwise (Efroymson, p_enter 0.05, p_remove 0.10) on Hald's cement data (Hald 1952;")
print("# Draper & Smith 3rd ed. Appendix 15A): statsmodels OLS p-values at each step")
hald = np.array([
    [7, 26, 6, 60, 78.5], [1, 29, 15, 52, 74.3], [11, 56, 8, 20, 104.3], [11, 31, 8, 47, 87.6],
    [7, 52, 6, 33, 95.9], [11, 55, 9, 22, 109.2], [3, 71, 17, 6, 102.7], [1, 31, 22, 44, 72.5],
    [2, 54, 18, 22, 93.1], [21, 47, 4, 26, 115.9], [1, 40, 23, 34, 83.8], [11, 66, 9, 12, 113.3],
    [10, 68, 8, 12, 109.4]])
hx, hy = hald[:, :4], hald[:, 4]
def pval(sel, j):
    cols = sorted(set(sel) | {j})
    r = sm.OLS(hy, sm.add_constant(hx[:, cols])).fit()
    return r.pvalues[1 + cols.index(j)]
for pe, pr in [(0.05, 0.10), (0.10, 0.15)]:
    sel, steps = [], []
    for _ in range(16):
        cand = [(pval(sel, j), j) for j in range(4) if j not in sel]
        best = min(cand) if cand else (1, -1)
        if best[0] < pe:
            sel.append(best[1]); steps.append(best[1] + 1)
        worst = max([(pval(sel, j), j) for j in sel]) if sel else (0, -1)
        if worst[0] > pr:
            sel.remove(worst[1]); steps.append(-(worst[1] + 1))
        if best[0] >= pe and worst[0] <= pr:
            break
    print("p_enter", pe, "p_remove", pr, "steps", steps, "final", sorted(j + 1 for j in sel))

print("# MANOVA: Johnson & Wichern, Applied Multivariate Statistical Analysis, 6th ed.,")
print("# Example 6.13 (plastic film: rate x additive, 5 replicates; tear, gloss, opacity)")
film = [  # rate, additive, tear, gloss, opacity
    (0, 0, 6.5, 9.5, 4.4), (0, 0, 6.2, 9.9, 6.4), (0, 0, 5.8, 9.6, 3.0), (0, 0, 6.5, 9.6, 4.1),
    (0, 0, 6.5, 9.2, 0.8), (0, 1, 6.9, 9.1, 5.7), (0, 1, 7.2, 10.0, 2.0), (0, 1, 6.9, 9.9, 3.9),
    (0, 1, 6.1, 9.5, 1.9), (0, 1, 6.3, 9.4, 5.7), (1, 0, 6.7, 9.1, 2.8), (1, 0, 6.6, 9.3, 4.1),
    (1, 0, 7.2, 8.3, 3.8), (1, 0, 7.1, 8.4, 1.6), (1, 0, 6.8, 8.5, 3.4), (1, 1, 7.1, 9.2, 8.4),
    (1, 1, 7.0, 8.8, 5.2), (1, 1, 7.2, 9.7, 6.9), (1, 1, 7.5, 10.1, 2.7), (1, 1, 7.6, 9.2, 1.9)]
fd = pd.DataFrame(film, columns=["rate", "add", "tear", "gloss", "opacity"])
from statsmodels.multivariate.manova import MANOVA
mv = MANOVA.from_formula("tear + gloss + opacity ~ C(rate, Sum) * C(add, Sum)", fd).mv_test()
for term in ["C(rate, Sum)", "C(add, Sum)", "C(rate, Sum):C(add, Sum)"]:
    w = mv.results[term]["stat"].loc["Wilks' lambda"]
    p(term, float(w["Value"]), float(w["F Value"]), float(w["Num DF"]), float(w["Den DF"]),
      float(w["Pr > F"]))

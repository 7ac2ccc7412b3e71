/* an_limits.h: biomechanical limits of the injury criteria, each with its source, and the
 * criteria as a fraction of their limit (the paper's Fig. 22).
 * The paper's Table 1 (motorcyclist limits from its ref. [38]) is not in the seed text we
 * have, so no entry comes from it; entries come from FMVSS 208 / Euro NCAP / the BrIC
 * definition, and `verified` says whether the value was checked against REFERENCES.md. */
#ifndef AN_LIMITS_H
#define AN_LIMITS_H

#include "analysis/an_dummy.h"

typedef struct {
    const char *key;    /* criterion key: "hic15", "nij", "neck_tension", ... */
    const char *label;  /* for tables: "HIC15", "Neck tension Fz", ... */
    double limit;       /* limit in `unit` */
    const char *unit;   /* unit of the criterion's value: "-", "g", "N", "N*m", "m", "m/s" */
    const char *source; /* where the limit comes from */
    int verified;       /* 1 if REFERENCES.md confirms it, 0 if unverified */
} an_limit;

/* the whole table (*n rows) */
const an_limit *an_limits_table(int *n);

/* the row of a criterion key, or NULL */
const an_limit *an_limit_find(const char *key);

/* the row of a criterion key for a Hybrid III size: its own where it differs (5th female:
 * FMVSS 208; 95th male: Mertz-scaled), else the 50th's; NULL when none */
const an_limit *an_limit_find_dummy(const char *key, an_dummy d);

/* value / limit; NaN when the key has no limit */
double an_limit_fraction(const char *key, double value);

#endif

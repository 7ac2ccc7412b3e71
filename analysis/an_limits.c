/* an_limits.c: the table of injury limits with sources */
#include "analysis/an_limits.h"

#include <math.h>
#include <string.h>

/* Values in the criterion's customary unit. "unverified": REFERENCES.md has no primary text
 * for the number; check it before relying on it. */
static const an_limit limits[] = {
    {"hic15", "HIC15", 700, "-", "FMVSS 208 S6.2 (Hybrid III 50th)", 1},
    {"hic36", "HIC36", 1000, "-", "FMVSS 208 (Hybrid III 50th, former HIC36 limit)", 1},
    {"head_a3ms", "Head a3ms", 80, "g", "ECE R94 / Euro NCAP head 3 ms exceedance (unverified)", 0},
    {"bric", "BrIC", 1.0, "-",
     "BrIC critical values 66.3/53.8/41.5 rad/s normalise to 1 (REFERENCES.md); as a limit "
     "unverified",
     0},
    {"nij", "Nij", 1.0, "-", "FMVSS 208 S6.6 (intercepts verified, REFERENCES.md)", 1},
    {"neck_tension", "Neck tension Fz", 4170, "N", "FMVSS 208 S6.6 peak tension (unverified)", 0},
    {"neck_compression", "Neck compression Fz", 4000, "N",
     "FMVSS 208 S6.6 peak compression (unverified)", 0},
    {"neck_extension", "Neck extension My", 57, "N*m", "Euro NCAP neck extension (unverified)", 0},
    {"neck_shear", "Neck shear Fx", 3100, "N", "Euro NCAP neck shear, 0 ms (unverified)", 0},
    {"chest_a3ms", "Chest a3ms", 60, "g", "FMVSS 208 S6.3 chest 3 ms clip (unverified)", 0},
    {"chest_deflection", "Chest deflection", 0.063, "m",
     "FMVSS 208 S6.4 sternal deflection, Hybrid III 50th (unverified)", 0},
    {"vc", "Viscous criterion VC", 1.0, "m/s", "ECE R94 / Euro NCAP (REFERENCES.md: unverified)",
     0},
    {"femur_compression", "Femur compression", 10000, "N",
     "FMVSS 208 S6.5 (REFERENCES.md: unverified)", 0},
    {"tibia_index", "Tibia index", 1.3, "-", "Euro NCAP lower-performance limit (unverified)", 0},
};

/* the limits that differ for the Hybrid III 5th female and 95th male (an_dummy.h); a key not
 * listed for a size takes the 50th's row above. The 5th female's are FMVSS 208's for that
 * dummy; the 95th male has no FMVSS 208 limits: Mertz's scaling of the 50th's (force x
 * lambda^2, lambda = 1.099 from the Nij intercepts, an_nij.c), as in Mertz, Irwin, Prasad 2003
 * (Stapp 47); both checked against the scaling law in tests/test_rider_sizes.c. */
static const an_limit limits_05f[] = {
    {"nij", "Nij", 1.0, "-",
     "FMVSS 208 S15.3 (5th female intercepts 4287/3880 N, 155/67 N*m: REFERENCES.md)", 1},
    {"neck_tension", "Neck tension Fz", 2620, "N", "FMVSS 208 S15.3 5th female (unverified)", 0},
    {"neck_compression", "Neck compression Fz", 2520, "N",
     "FMVSS 208 S15.3 5th female (unverified)", 0},
    {"chest_deflection", "Chest deflection", 0.052, "m",
     "FMVSS 208 S15.3 5th female sternal deflection (unverified)", 0},
    {"femur_compression", "Femur compression", 6805, "N", "FMVSS 208 S15.3 5th female (unverified)",
     0},
};
static const an_limit limits_95m[] = {
    {"nij", "Nij", 1.0, "-", "intercepts 8216/7440 N, 415/179 N*m (unverified, an_nij.c)", 0},
    {"neck_tension", "Neck tension Fz", 5030, "N",
     "50th's 4170 N x lambda^2 (Mertz scaling, lambda 1.099; unverified)", 0},
    {"neck_compression", "Neck compression Fz", 4830, "N",
     "50th's 4000 N x lambda^2 (Mertz scaling, lambda 1.099; unverified)", 0},
};

const an_limit *an_limit_find_dummy(const char *key, an_dummy d)
{
    const an_limit *t = d == AN_DUMMY_H3_05F   ? limits_05f
                        : d == AN_DUMMY_H3_95M ? limits_95m
                                               : NULL;
    size_t n = d == AN_DUMMY_H3_05F   ? sizeof limits_05f / sizeof limits_05f[0]
               : d == AN_DUMMY_H3_95M ? sizeof limits_95m / sizeof limits_95m[0]
                                      : 0;
    for (size_t i = 0; i < n; i++)
        if (strcmp(t[i].key, key) == 0) return &t[i];
    return an_limit_find(key);
}

const an_limit *an_limits_table(int *n)
{
    *n = (int)(sizeof limits / sizeof limits[0]);
    return limits;
}

const an_limit *an_limit_find(const char *key)
{
    for (size_t i = 0; i < sizeof limits / sizeof limits[0]; i++)
        if (strcmp(limits[i].key, key) == 0) return &limits[i];
    return NULL;
}

double an_limit_fraction(const char *key, double value)
{
    const an_limit *l = an_limit_find(key);
    return l ? value / l->limit : NAN;
}

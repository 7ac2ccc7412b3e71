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

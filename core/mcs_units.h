/* mcs_units: the unit parser of the scenario reader. Only this module knows km/h, ms, mm, deg.
 *
 * A unit expression is a product/quotient of base units with SI prefixes and integer powers:
 *   expr    := product ('/' product)*           "a/b c" = a/(b c), "a/b/c" = a/(b c)
 *   product := factor ((' ' | '*' | '·') factor)*
 *   factor  := ('(' expr ')' | '1' | [prefix] unit) [('^' | '**') [+-]int | '²' | '³']
 * e.g. "m/s^2", "kg*m^2", "N s/m", "N·m", "N m/rad", "kg/(m s^2)", "1/s".
 * Units: m g s K rad N Pa J W Hz bar (SI prefixes Y..a, u or µ for micro), and without prefixes
 * min h deg ° rev rpm mph in ft lb lbf psi t gn %. "g" alone is the gram, or standard gravity
 * 9.80665 m/s^2 where an acceleration is expected (mcs_quantity_parse decides).
 * Dimensions are exponents of (m, kg, s, K, rad). rad is dimensionless in SI: a check ignores
 * it, except that an angle is refused where a plain number is expected. */
#ifndef MCS_UNITS_H
#define MCS_UNITS_H

#include "core/mcs_error.h"

#include <stddef.h>

enum { MCS_DIM_M, MCS_DIM_KG, MCS_DIM_S, MCS_DIM_K, MCS_DIM_RAD, MCS_NDIM };

/* exponents of m, kg, s, K, rad */
typedef struct {
    signed char e[MCS_NDIM];
} mcs_dim;

/* value_SI = value * factor = value * num / den. num and den are kept apart so that decimal
 * prefixes below one divide by an exact power of ten ("10 us" gives 1e-05, not 9.99...e-06) */
typedef struct {
    double factor; /* to SI, num/den [-] */
    double num;    /* numerator of the factor [-] */
    double den;    /* denominator of the factor [-] */
    mcs_dim dim;   /* dimension of the unit */
} mcs_unit;

/* initialisers for tables: MCS_D(m, kg, s, K, rad); in expressions use (mcs_dim)MCS_D(...) */
#define MCS_D(m, kg, s, K, rad)                                                                    \
    {                                                                                              \
        {                                                                                          \
            (m), (kg), (s), (K), (rad)                                                             \
        }                                                                                          \
    }
#define MCS_DIM_NONE MCS_D(0, 0, 0, 0, 0)
#define MCS_DIM_LENGTH MCS_D(1, 0, 0, 0, 0)
#define MCS_DIM_MASS MCS_D(0, 1, 0, 0, 0)
#define MCS_DIM_TIME MCS_D(0, 0, 1, 0, 0)
#define MCS_DIM_TEMP MCS_D(0, 0, 0, 1, 0)
#define MCS_DIM_ANGLE MCS_D(0, 0, 0, 0, 1)
#define MCS_DIM_AREA MCS_D(2, 0, 0, 0, 0)
#define MCS_DIM_VELOCITY MCS_D(1, 0, -1, 0, 0)
#define MCS_DIM_ACCEL MCS_D(1, 0, -2, 0, 0)
#define MCS_DIM_ANGVEL MCS_D(0, 0, -1, 0, 1)
#define MCS_DIM_FREQ MCS_D(0, 0, -1, 0, 0)
#define MCS_DIM_FORCE MCS_D(1, 1, -2, 0, 0)
#define MCS_DIM_PRESSURE MCS_D(-1, 1, -2, 0, 0)
#define MCS_DIM_DENSITY MCS_D(-3, 1, 0, 0, 0)
#define MCS_DIM_ENERGY MCS_D(2, 1, -2, 0, 0)
#define MCS_DIM_MOMENT MCS_D(2, 1, -2, 0, 0)
#define MCS_DIM_INERTIA MCS_D(2, 1, 0, 0, 0)
#define MCS_DIM_STIFFNESS MCS_D(0, 1, -2, 0, 0) /* N/m */
#define MCS_DIM_DAMPING MCS_D(0, 1, -1, 0, 0)   /* N s/m */
#define MCS_DIM_ROTSTIFF MCS_D(2, 1, -2, 0, -1) /* N m/rad */
#define MCS_DIM_ROTDAMP MCS_D(2, 1, -1, 0, -1)  /* N m s/rad */

int mcs_dim_eq(mcs_dim a, mcs_dim b);

/* may a value of dimension got stand where want is expected? (rad ignored, see above) */
int mcs_dim_compatible(mcs_dim want, mcs_dim got);

/* "kg m s^-2" ("1" when dimensionless) */
void mcs_dim_format(mcs_dim d, char *buf, size_t n);

/* a name for the dimension ("force", "velocity"), or NULL if it has none */
const char *mcs_dim_name(mcs_dim d);

/* the usual SI unit of the dimension ("N", "N s/m", "" when dimensionless), else the base form */
void mcs_dim_si(mcs_dim d, char *buf, size_t n);

/* "a force (N)", or the base form ("m^5") for dimensions without a name: for messages */
void mcs_dim_describe(mcs_dim d, char *buf, size_t n);

/* parse a unit expression; g_is_accel: "g" alone is standard gravity instead of the gram.
 * On error returns MCS_ERR_UNIT and writes why (no location) */
mcs_status mcs_unit_parse(const char *text, int g_is_accel, mcs_unit *u, char *why, size_t nwhy);

/* a strict decimal number ([+-]digits[.digits][e[+-]digits]) at the start of s; returns the
 * number of characters used (0: not a number) and sets *v. Non-finite (overflow) sets *v to
 * +-inf: the caller rejects it. */
size_t mcs_number_scan(const char *s, double *v);

/* true if s (len chars) is NaN or infinity in any YAML or C spelling (.nan, -.inf, inf, ...) */
int mcs_is_nonfinite_word(const char *s, size_t len);

/* "48.5 km/h" -> 13.47 (SI). want: the dimension expected. A number with no unit is SI.
 * Errors (why filled, no location): MCS_ERR_TYPE not a number, MCS_ERR_UNIT bad unit or wrong
 * dimension, MCS_ERR_RANGE NaN or infinite. */
mcs_status mcs_quantity_parse(const char *text, mcs_dim want, double *si, char *why, size_t nwhy);

#endif

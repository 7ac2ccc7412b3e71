/* tests for core/mcs_units: unit expressions, quantities, dimensions.
 * Reference factors: SI brochure (9th ed.) prefixes; 1 km/h = 1/3.6 m/s; g_n = 9.80665 m/s^2
 * (CGPM 1901); 1 mph = 0.44704 m/s, 1 in = 0.0254 m, 1 lb = 0.45359237 kg (exact, 1959). */
#include "tests/harness.h"
#include "core/mcs_units.h"

#include <math.h>

#define PI 3.14159265358979323846

static double q(const char *text, mcs_dim want, mcs_status *st)
{
    char why[256];
    double v = NAN;
    *st = mcs_quantity_parse(text, want, &v, why, sizeof why);
    return v;
}

/* the quantity parses with the dimension wanted and gives si */
#define CHECK_Q(text, dim, si)                                                                     \
    do {                                                                                           \
        mcs_status st_;                                                                            \
        double v_ = q(text, (mcs_dim)dim, &st_);                                                   \
        CHECK(st_ == MCS_OK);                                                                      \
        CHECK_REL(v_, si, 1e-12);                                                                  \
    } while (0)

#define CHECK_QFAIL(text, dim, status)                                                             \
    do {                                                                                           \
        mcs_status st_;                                                                            \
        q(text, (mcs_dim)dim, &st_);                                                               \
        CHECK(st_ == status);                                                                      \
    } while (0)

static void test_design_examples(void)
{
    CHECK_Q("48.5 km/h", MCS_DIM_VELOCITY, 48.5 / 3.6);
    CHECK_Q("12 ms", MCS_DIM_TIME, 0.012);
    CHECK_Q("2 kN", MCS_DIM_FORCE, 2000.0);
    CHECK_Q("90 deg", MCS_DIM_ANGLE, PI / 2);
    CHECK_Q("250 MPa", MCS_DIM_PRESSURE, 250e6);
    CHECK_Q("7850 kg/m^3", MCS_DIM_DENSITY, 7850.0);
    CHECK_Q("10 kHz", MCS_DIM_FREQ, 1e4);
    CHECK_Q("9.81 m/s^2", MCS_DIM_ACCEL, 9.81);
    CHECK_Q("10 us", MCS_DIM_TIME, 1e-5);
    CHECK_Q("50 mm", MCS_DIM_LENGTH, 0.05);
    CHECK_Q("1.5 mm", MCS_DIM_LENGTH, 0.0015);
    CHECK_Q("210 GPa", MCS_DIM_PRESSURE, 210e9);
    CHECK_Q("2 kN/m", MCS_DIM_STIFFNESS, 2000.0);
    CHECK_Q("0 N s/m", MCS_DIM_DAMPING, 0.0);
    CHECK_Q("3 N s/m", MCS_DIM_DAMPING, 3.0);
    CHECK_Q("5 N*m", MCS_DIM_MOMENT, 5.0);
    CHECK_Q("5 N m/rad", MCS_DIM_ROTSTIFF, 5.0);
    CHECK_Q("0.2 s", MCS_DIM_TIME, 0.2);
    CHECK_Q("0.5 m", MCS_DIM_LENGTH, 0.5);
    CHECK_Q("1 kg", MCS_DIM_MASS, 1.0);
}

static void test_units_alone(void)
{
    char why[128];
    mcs_unit u;
    /* N s/m = kg s^-1 */
    CHECK(mcs_unit_parse("N s/m", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_DAMPING));
    CHECK_NEAR(u.factor, 1.0, 1e-15);
    CHECK(mcs_unit_parse("N*m", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_MOMENT));
    CHECK(mcs_unit_parse("N\xc2\xb7m", 0, &u, why, sizeof why) == MCS_OK); /* N·m */
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_MOMENT));
    CHECK(mcs_unit_parse("N m/rad", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_ROTSTIFF));
    CHECK(mcs_unit_parse("kg*m^2", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_INERTIA));
    /* everything after '/' is the denominator: W/m K = W/(m K) */
    CHECK(mcs_unit_parse("W/m K", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_D(1, 1, -3, -1, 0)));
    CHECK(mcs_unit_parse("kg/(m s^2)", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_PRESSURE));
    CHECK(mcs_unit_parse("1/s", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_FREQ));
    CHECK(mcs_unit_parse("m/s/s", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_ACCEL));
    CHECK(mcs_unit_parse("m s^-2", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_ACCEL));
    CHECK(mcs_unit_parse("m**2", 0, &u, why, sizeof why) == MCS_OK);
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_AREA));
    CHECK(mcs_unit_parse("mm\xc2\xb2", 0, &u, why, sizeof why) == MCS_OK); /* mm² */
    CHECK(mcs_dim_eq(u.dim, (mcs_dim)MCS_DIM_AREA));
    CHECK_REL(u.factor, 1e-6, 1e-12);
}

static void test_prefixes_and_powers(void)
{
    CHECK_Q("1 km", MCS_DIM_LENGTH, 1e3);
    CHECK_Q("1 cm", MCS_DIM_LENGTH, 1e-2);
    CHECK_Q("1 um", MCS_DIM_LENGTH, 1e-6);
    CHECK_Q("1 \xc2\xb5m", MCS_DIM_LENGTH, 1e-6); /* µm, micro sign */
    CHECK_Q("1 \xce\xbcs", MCS_DIM_TIME, 1e-6);   /* μs, Greek mu */
    CHECK_Q("1 ns", MCS_DIM_TIME, 1e-9);
    CHECK_Q("3 mg", MCS_DIM_MASS, 3e-6);
    CHECK_Q("2 t", MCS_DIM_MASS, 2000.0);
    CHECK_Q("1 hPa", MCS_DIM_PRESSURE, 100.0);
    CHECK_Q("2 bar", MCS_DIM_PRESSURE, 2e5);
    CHECK_Q("1 MJ", MCS_DIM_ENERGY, 1e6);
    CHECK_Q("1 mrad", MCS_DIM_ANGLE, 1e-3);
    CHECK_Q("1 cm^2", MCS_DIM_AREA, 1e-4);
    CHECK_Q("1 cm^3", MCS_D(3, 0, 0, 0, 0), 1e-6);
    CHECK_Q("1 g/cm^3", MCS_DIM_DENSITY, 1000.0);
    CHECK_Q("2 min", MCS_DIM_TIME, 120.0);
    CHECK_Q("1 h", MCS_DIM_TIME, 3600.0);
    CHECK_Q("30 mph", MCS_DIM_VELOCITY, 30 * 0.44704);
    CHECK_Q("2 in", MCS_DIM_LENGTH, 0.0508);
    CHECK_Q("60 rpm", MCS_DIM_ANGVEL, 2 * PI);
    CHECK_Q("180 \xc2\xb0", MCS_DIM_ANGLE, PI); /* ° */
    CHECK_Q("50mm", MCS_DIM_LENGTH, 0.05);      /* no space */
    CHECK_Q("1.5e3 N", MCS_DIM_FORCE, 1500.0);
    CHECK_Q("-10 m/s", MCS_DIM_VELOCITY, -10.0);
    CHECK_Q("  7  ", MCS_DIM_MASS, 7.0); /* a bare number is SI */
    CHECK_Q("20 %", MCS_DIM_NONE, 0.2);
}

/* "g": gram where a mass is expected, standard gravity where an acceleration is */
static void test_g_means_gravity_for_accelerations(void)
{
    CHECK_Q("50 g", MCS_DIM_ACCEL, 50 * 9.80665);
    CHECK_Q("1 g", MCS_DIM_ACCEL, 9.80665);
    CHECK_Q("500 g", MCS_DIM_MASS, 0.5);
    CHECK_Q("2 kg", MCS_DIM_MASS, 2.0);
    CHECK_Q("3 gn", MCS_DIM_ACCEL, 3 * 9.80665);
    CHECK_QFAIL("2 kg", MCS_DIM_ACCEL, MCS_ERR_UNIT); /* kg is never an acceleration */
}

/* rad counts as dimensionless, but an angle is refused where a plain number is expected */
static void test_angles(void)
{
    CHECK_Q("10 rad/s", MCS_DIM_ANGVEL, 10.0);
    CHECK_Q("10 1/s", MCS_DIM_ANGVEL, 10.0);
    CHECK_Q("100 N m", MCS_DIM_ROTSTIFF, 100.0); /* N m where N m/rad is expected */
    CHECK_Q("0.5", MCS_DIM_NONE, 0.5);
    CHECK_QFAIL("30 deg", MCS_DIM_NONE, MCS_ERR_UNIT);
}

static void test_wrong_dimension_names_both(void)
{
    char why[256];
    double v;
    CHECK(mcs_quantity_parse("2 kN", (mcs_dim)MCS_DIM_LENGTH, &v, why, sizeof why) == MCS_ERR_UNIT);
    CHECK_STR_CONTAINS(why, "'2 kN' is a force (N), expected a length (m)");
    CHECK(mcs_quantity_parse("10 kHz", (mcs_dim)MCS_DIM_TIME, &v, why, sizeof why) == MCS_ERR_UNIT);
    CHECK_STR_CONTAINS(why, "frequency");
    CHECK_QFAIL("7850 kg/m^2", MCS_DIM_DENSITY, MCS_ERR_UNIT);
    CHECK_QFAIL("9.81 m/s", MCS_DIM_ACCEL, MCS_ERR_UNIT);
}

static void test_bad_units(void)
{
    char why[256];
    double v;
    CHECK(mcs_quantity_parse("3 parsec", (mcs_dim)MCS_DIM_LENGTH, &v, why, sizeof why) ==
          MCS_ERR_UNIT);
    CHECK_STR_CONTAINS(why, "unknown unit 'parsec'");
    CHECK_QFAIL("3 m/", MCS_DIM_LENGTH, MCS_ERR_UNIT);
    CHECK_QFAIL("3 m^", MCS_DIM_AREA, MCS_ERR_UNIT);
    CHECK_QFAIL("3 (m", MCS_DIM_LENGTH, MCS_ERR_UNIT);
    CHECK_QFAIL("3 m)", MCS_DIM_LENGTH, MCS_ERR_UNIT);
    CHECK_QFAIL("3 m^99", MCS_DIM_LENGTH, MCS_ERR_UNIT);
    CHECK_QFAIL("3 kdeg", MCS_DIM_ANGLE, MCS_ERR_UNIT); /* deg takes no prefix */
    CHECK_QFAIL("3 m 2", MCS_DIM_LENGTH, MCS_ERR_UNIT);
    CHECK_QFAIL("3 \xff", MCS_DIM_LENGTH, MCS_ERR_UNIT);
    CHECK_QFAIL("m", MCS_DIM_LENGTH, MCS_ERR_TYPE); /* no number */
    CHECK_QFAIL("", MCS_DIM_LENGTH, MCS_ERR_TYPE);
    CHECK_QFAIL("abc", MCS_DIM_LENGTH, MCS_ERR_TYPE);
}

static void test_nonfinite(void)
{
    CHECK_QFAIL("nan", MCS_DIM_LENGTH, MCS_ERR_RANGE);
    CHECK_QFAIL("-inf m", MCS_DIM_LENGTH, MCS_ERR_RANGE);
    CHECK_QFAIL(".inf", MCS_DIM_LENGTH, MCS_ERR_RANGE);
    CHECK_QFAIL("1e999 m", MCS_DIM_LENGTH, MCS_ERR_RANGE);
    CHECK_QFAIL("1e300 Ym^3", MCS_D(3, 0, 0, 0, 0), MCS_ERR_RANGE); /* overflows in SI */
    CHECK(mcs_is_nonfinite_word(".NaN", 4));
    CHECK(mcs_is_nonfinite_word("-.Inf", 5));
    CHECK(!mcs_is_nonfinite_word("info", 4));
}

static void test_number_scan(void)
{
    double v;
    CHECK(mcs_number_scan("12.5e-3 m", &v) == 7);
    CHECK_NEAR(v, 0.0125, 1e-15);
    CHECK(mcs_number_scan(".5", &v) == 2);
    CHECK_NEAR(v, 0.5, 0);
    CHECK(mcs_number_scan("5.", &v) == 2);
    CHECK(mcs_number_scan("0x10", &v) == 1); /* hex is not read as a number */
    CHECK(mcs_number_scan("e5", &v) == 0);
    CHECK(mcs_number_scan("-", &v) == 0);
    CHECK(mcs_number_scan("1e", &v) == 1);
}

static void test_dim_text(void)
{
    char b[96];
    mcs_dim_format((mcs_dim)MCS_DIM_FORCE, b, sizeof b);
    CHECK(strcmp(b, "kg m s^-2") == 0);
    mcs_dim_format((mcs_dim)MCS_DIM_NONE, b, sizeof b);
    CHECK(strcmp(b, "1") == 0);
    mcs_dim_describe((mcs_dim)MCS_DIM_ACCEL, b, sizeof b);
    CHECK(strcmp(b, "an acceleration (m/s^2)") == 0);
    mcs_dim_describe((mcs_dim)MCS_D(5, 0, 0, 0, 0), b, sizeof b);
    CHECK(strcmp(b, "m^5") == 0);
    mcs_dim_si((mcs_dim)MCS_DIM_DAMPING, b, sizeof b);
    CHECK(strcmp(b, "N s/m") == 0);
    CHECK(strcmp(mcs_dim_name((mcs_dim)MCS_DIM_DAMPING), "damping coefficient") == 0);
    CHECK(mcs_dim_name((mcs_dim)MCS_D(5, 0, 0, 0, 0)) == NULL);
}

int main(void)
{
    RUN(test_design_examples);
    RUN(test_units_alone);
    RUN(test_prefixes_and_powers);
    RUN(test_g_means_gravity_for_accelerations);
    RUN(test_angles);
    RUN(test_wrong_dimension_names_both);
    RUN(test_bad_units);
    RUN(test_nonfinite);
    RUN(test_number_scan);
    RUN(test_dim_text);
    TEST_END();
}

/* an_units.h: units written in channel files (CSV `name [unit]`, ISO-MME `Unit :...`) to SI.
 * Known: g (9.80665 m/s^2), m/s^2, km/h, m/s, N, kN, daN, N*m (Nm, N.m), kN*m, N*mm, m, mm,
 * cm, rad/s, deg/s, rad, deg, s, ms, us, Pa, kPa, bar, J, kJ, kg, and "-" / empty (no unit). */
#ifndef AN_UNITS_H
#define AN_UNITS_H

/* 1 and SI factor/unit name if `unit` is known (value_SI = value * factor), else 0 */
int an_unit_to_si(const char *unit, double *factor, const char **si);

#endif

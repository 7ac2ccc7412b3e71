/* an_units.c: channel units (CSV headers, ISO-MME `Unit` lines) to SI */
#include "analysis/an_units.h"

#include <ctype.h>
#include <string.h>
#include <strings.h>

typedef struct {
    const char *name; /* as written in a file */
    double factor;    /* SI value of one unit */
    const char *si;   /* SI unit */
} unit_row;

/* standard gravity 9.80665 m/s^2 (CGPM 1901, ISO 80000-3) */
#define AN_G0 9.80665
#define AN_DEG (3.14159265358979323846 / 180.0)

static const unit_row units[] = {
    {"g", AN_G0, "m/s^2"},       {"G", AN_G0, "m/s^2"},       {"m/s^2", 1.0, "m/s^2"},
    {"m/s2", 1.0, "m/s^2"},      {"m/s**2", 1.0, "m/s^2"},    {"mm/s^2", 1e-3, "m/s^2"},
    {"m/s", 1.0, "m/s"},         {"mm/s", 1e-3, "m/s"},       {"mm/ms", 1.0, "m/s"},
    {"km/h", 1.0 / 3.6, "m/s"},  {"N", 1.0, "N"},             {"kN", 1e3, "N"},
    {"daN", 10.0, "N"},          {"N*m", 1.0, "N*m"},         {"Nm", 1.0, "N*m"},
    {"N.m", 1.0, "N*m"},         {"N m", 1.0, "N*m"},         {"kN*m", 1e3, "N*m"},
    {"kNm", 1e3, "N*m"},         {"N*mm", 1e-3, "N*m"},       {"Nmm", 1e-3, "N*m"},
    {"m", 1.0, "m"},             {"mm", 1e-3, "m"},           {"cm", 1e-2, "m"},
    {"rad/s", 1.0, "rad/s"},     {"deg/s", AN_DEG, "rad/s"},  {"rad/s^2", 1.0, "rad/s^2"},
    {"rad/s2", 1.0, "rad/s^2"},  {"deg/s^2", AN_DEG, "rad/s^2"}, {"rad", 1.0, "rad"},
    {"deg", AN_DEG, "rad"},      {"s", 1.0, "s"},             {"ms", 1e-3, "s"},
    {"us", 1e-6, "s"},           {"Pa", 1.0, "Pa"},           {"kPa", 1e3, "Pa"},
    {"bar", 1e5, "Pa"},          {"J", 1.0, "J"},             {"kJ", 1e3, "J"},
    {"kg", 1.0, "kg"},           {"-", 1.0, "-"},             {"1", 1.0, "-"},
    {"", 1.0, "-"},              {"NOVALUE", 1.0, "-"},
};

int an_unit_to_si(const char *unit, double *factor, const char **si)
{
    /* trim surrounding blanks without modifying the caller's text */
    while (*unit && isspace((unsigned char)*unit)) unit++;
    size_t len = strlen(unit);
    while (len && isspace((unsigned char)unit[len - 1])) len--;
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++) {
        if (strlen(units[i].name) == len && strncmp(units[i].name, unit, len) == 0) {
            *factor = units[i].factor;
            *si = units[i].si;
            return 1;
        }
    }
    return 0;
}

/* mcs_units.c: unit expressions -> factor to SI and dimension (see mcs_units.h) */
#include "core/mcs_units.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define G_N 9.80665 /* standard gravity [m/s^2], CGPM 1901 */

typedef struct {
    const char *sym;
    double num, den; /* factor to SI = num / den */
    mcs_dim dim;
    int prefixable;
} unit_def;

/* exact symbols are matched first, so "min", "Pa", "h", "mph" are never read as prefix+unit */
static const unit_def units[] = {
    {"m", 1, 1, MCS_DIM_LENGTH, 1},
    {"g", 1, 1000, MCS_DIM_MASS, 1},
    {"s", 1, 1, MCS_DIM_TIME, 1},
    {"K", 1, 1, MCS_DIM_TEMP, 1},
    {"rad", 1, 1, MCS_DIM_ANGLE, 1},
    {"N", 1, 1, MCS_DIM_FORCE, 1},
    {"Pa", 1, 1, MCS_DIM_PRESSURE, 1},
    {"J", 1, 1, MCS_DIM_ENERGY, 1},
    {"W", 1, 1, MCS_D(2, 1, -3, 0, 0), 1},
    {"Hz", 1, 1, MCS_DIM_FREQ, 1},
    {"bar", 1e5, 1, MCS_DIM_PRESSURE, 1},
    {"min", 60, 1, MCS_DIM_TIME, 0},
    {"h", 3600, 1, MCS_DIM_TIME, 0},
    {"deg", PI, 180, MCS_DIM_ANGLE, 0},
    {"\xc2\xb0", PI, 180, MCS_DIM_ANGLE, 0}, /* ° */
    {"rev", 2.0 * PI, 1, MCS_DIM_ANGLE, 0},
    {"rpm", 2.0 * PI, 60, MCS_DIM_ANGVEL, 0},
    {"mph", 44704, 1e5, MCS_DIM_VELOCITY, 0},
    {"in", 254, 1e4, MCS_DIM_LENGTH, 0},
    {"ft", 3048, 1e4, MCS_DIM_LENGTH, 0},
    {"lb", 45359237, 1e8, MCS_DIM_MASS, 0},
    {"lbf", 45359237 * G_N, 1e8, MCS_DIM_FORCE, 0},
    {"psi", 45359237 * G_N, 1e8 * 0.0254 * 0.0254, MCS_DIM_PRESSURE, 0},
    {"t", 1000, 1, MCS_DIM_MASS, 0},
    {"gn", G_N, 1, MCS_DIM_ACCEL, 0},
    {"%", 1, 100, MCS_DIM_NONE, 0},
};
static const int nunits = (int)(sizeof units / sizeof units[0]);

/* prefix factor = num / den, both exact in binary64 */
static const struct {
    const char *sym;
    double num, den;
} prefixes[] = {
    {"Y", 1e24, 1}, {"Z", 1e21, 1}, {"E", 1e18, 1}, {"P", 1e15, 1},       {"T", 1e12, 1},
    {"G", 1e9, 1},  {"M", 1e6, 1},  {"k", 1e3, 1},  {"h", 1e2, 1},        {"d", 1, 1e1},
    {"c", 1, 1e2},  {"m", 1, 1e3},  {"u", 1, 1e6},  {"\xc2\xb5", 1, 1e6}, {"\xce\xbc", 1, 1e6},
    {"n", 1, 1e9},  {"p", 1, 1e12}, {"f", 1, 1e15}, {"a", 1, 1e18}, /* µ micro sign, μ mu */
};
static const int nprefixes = (int)(sizeof prefixes / sizeof prefixes[0]);

int mcs_dim_eq(mcs_dim a, mcs_dim b)
{
    return memcmp(a.e, b.e, sizeof a.e) == 0;
}

static int dim_is_none(mcs_dim d)
{
    return mcs_dim_eq(d, (mcs_dim)MCS_DIM_NONE);
}

int mcs_dim_compatible(mcs_dim want, mcs_dim got)
{
    for (int i = 0; i < MCS_DIM_RAD; i++)
        if (want.e[i] != got.e[i]) return 0;
    /* an angle where a pure number is wanted is almost always a mistake ("friction: 30 deg") */
    if (dim_is_none(want) && got.e[MCS_DIM_RAD] != 0) return 0;
    return 1;
}

void mcs_dim_format(mcs_dim d, char *buf, size_t n)
{
    static const char *const base[MCS_NDIM] = {"m", "kg", "s", "K", "rad"};
    static const int order[MCS_NDIM] = {MCS_DIM_KG, MCS_DIM_M, MCS_DIM_S, MCS_DIM_K, MCS_DIM_RAD};
    size_t k = 0;
    buf[0] = 0;
    for (int o = 0; o < MCS_NDIM && k < n; o++) {
        int i = order[o];
        if (d.e[i] == 0) continue;
        const char *sep = k ? " " : "";
        if (d.e[i] == 1)
            k += (size_t)snprintf(buf + k, n - k, "%s%s", sep, base[i]);
        else
            k += (size_t)snprintf(buf + k, n - k, "%s%s^%d", sep, base[i], d.e[i]);
    }
    if (k == 0) snprintf(buf, n, "1");
}

/* names and the usual SI symbol of the dimensions engineers meet */
static const struct {
    mcs_dim dim;
    const char *name, *si;
} dim_names[] = {
    {MCS_DIM_NONE, "dimensionless number", ""},
    {MCS_DIM_LENGTH, "length", "m"},
    {MCS_DIM_MASS, "mass", "kg"},
    {MCS_DIM_TIME, "time", "s"},
    {MCS_DIM_TEMP, "temperature", "K"},
    {MCS_DIM_ANGLE, "angle", "rad"},
    {MCS_DIM_AREA, "area", "m^2"},
    {MCS_D(3, 0, 0, 0, 0), "volume", "m^3"},
    {MCS_DIM_VELOCITY, "velocity", "m/s"},
    {MCS_DIM_ACCEL, "acceleration", "m/s^2"},
    {MCS_DIM_ANGVEL, "angular velocity", "rad/s"},
    {MCS_D(0, 0, -2, 0, 1), "angular acceleration", "rad/s^2"},
    {MCS_DIM_FREQ, "frequency", "Hz"},
    {MCS_DIM_FORCE, "force", "N"},
    {MCS_DIM_PRESSURE, "pressure", "Pa"},
    {MCS_DIM_DENSITY, "density", "kg/m^3"},
    {MCS_DIM_ENERGY, "energy or moment", "N m"},
    {MCS_D(2, 1, -3, 0, 0), "power", "W"},
    {MCS_DIM_INERTIA, "moment of inertia", "kg m^2"},
    {MCS_DIM_STIFFNESS, "stiffness", "N/m"},
    {MCS_DIM_DAMPING, "damping coefficient", "N s/m"},
    {MCS_DIM_ROTSTIFF, "rotational stiffness", "N m/rad"},
    {MCS_DIM_ROTDAMP, "rotational damping coefficient", "N m s/rad"},
    {MCS_D(1, 1, -1, 0, 0), "momentum", "N s"},
};

static int dim_index(mcs_dim d)
{
    for (size_t i = 0; i < sizeof dim_names / sizeof dim_names[0]; i++)
        if (mcs_dim_eq(d, dim_names[i].dim)) return (int)i;
    return -1;
}

const char *mcs_dim_name(mcs_dim d)
{
    int i = dim_index(d);
    return i < 0 ? NULL : dim_names[i].name;
}

void mcs_dim_si(mcs_dim d, char *buf, size_t n)
{
    int i = dim_index(d);
    if (i >= 0)
        snprintf(buf, n, "%s", dim_names[i].si);
    else
        mcs_dim_format(d, buf, n);
}

void mcs_dim_describe(mcs_dim d, char *buf, size_t n)
{
    char f[64];
    mcs_dim_si(d, f, sizeof f);
    const char *name = mcs_dim_name(d);
    if (!name)
        snprintf(buf, n, "%s", f);
    else if (dim_is_none(d))
        snprintf(buf, n, "a %s", name);
    else
        snprintf(buf, n, "%s %s (%s)", strchr("aeiou", name[0]) ? "an" : "a", name, f);
}

/* ---- the expression parser ---- */

typedef struct {
    const char *s;  /* whole text */
    const char *p;  /* cursor */
    int g_is_accel; /* "g" alone means standard gravity */
    int depth;      /* parenthesis depth */
    char *why;
    size_t nwhy;
} uparser;

static mcs_status ufail(uparser *u, const char *fmt, const char *arg)
{
    snprintf(u->why, u->nwhy, fmt, arg);
    return MCS_ERR_UNIT;
}

static void umul(mcs_unit *a, mcs_unit b, int power)
{
    double n = power > 0 ? b.num : b.den, d = power > 0 ? b.den : b.num;
    a->num *= pow(n, abs(power));
    a->den *= pow(d, abs(power));
    a->factor = a->num / a->den;
    for (int i = 0; i < MCS_NDIM; i++)
        a->dim.e[i] = (signed char)(a->dim.e[i] + power * b.dim.e[i]);
}

static int is_symbol_byte(unsigned char c)
{
    return isalpha(c) || c == '%' || c >= 0x80;
}

/* UTF-8 symbols allowed in unit names: µ μ ° (² ³ · are handled as operators) */
static int utf8_symbol_len(const char *p)
{
    if (!strncmp(p, "\xc2\xb5", 2) || !strncmp(p, "\xce\xbc", 2) || !strncmp(p, "\xc2\xb0", 2))
        return 2;
    return 0;
}

static size_t symbol_len(const char *p)
{
    size_t k = 0;
    for (;;) {
        unsigned char c = (unsigned char)p[k];
        if (c >= 0x80) {
            int m = utf8_symbol_len(p + k);
            if (!m) break;
            k += (size_t)m;
        } else if (is_symbol_byte(c)) {
            k++;
        } else {
            break;
        }
    }
    return k;
}

static const unit_def *find_exact(const char *sym, size_t len)
{
    for (int i = 0; i < nunits; i++)
        if (strlen(units[i].sym) == len && !strncmp(units[i].sym, sym, len)) return &units[i];
    return NULL;
}

/* resolve one symbol: exact unit, else prefix + prefixable unit */
static int lookup_symbol(uparser *u, const char *sym, size_t len, mcs_unit *out)
{
    if (u->g_is_accel && len == 1 && sym[0] == 'g') {
        *out = (mcs_unit){G_N, G_N, 1.0, MCS_DIM_ACCEL};
        return 1;
    }
    const unit_def *d = find_exact(sym, len);
    if (d) {
        *out = (mcs_unit){d->num / d->den, d->num, d->den, d->dim};
        return 1;
    }
    for (int i = 0; i < nprefixes; i++) {
        size_t pl = strlen(prefixes[i].sym);
        if (pl >= len || strncmp(prefixes[i].sym, sym, pl)) continue;
        d = find_exact(sym + pl, len - pl);
        if (d && d->prefixable) {
            double num = prefixes[i].num * d->num, den = prefixes[i].den * d->den;
            *out = (mcs_unit){num / den, num, den, d->dim};
            return 1;
        }
    }
    return 0;
}

static void skip_spaces(uparser *u)
{
    while (*u->p == ' ' || *u->p == '\t')
        u->p++;
}

/* optional power after a factor: ^n, **n, ², ³ */
static mcs_status parse_power(uparser *u, int *power)
{
    *power = 1;
    if (!strncmp(u->p, "\xc2\xb2", 2) || !strncmp(u->p, "\xc2\xb3", 2)) {
        *power = u->p[1] == '\xb2' ? 2 : 3;
        u->p += 2;
        return MCS_OK;
    }
    if (*u->p == '^')
        u->p++;
    else if (u->p[0] == '*' && u->p[1] == '*')
        u->p += 2;
    else
        return MCS_OK;
    const char *start = u->p;
    if (*u->p == '-' || *u->p == '+') u->p++;
    if (!isdigit((unsigned char)*u->p))
        return ufail(u, "expected an integer power after '%s'", "^");
    long v = strtol(start, (char **)&u->p, 10);
    if (v < -12 || v > 12) return ufail(u, "power out of range in '%s'", u->s);
    *power = (int)v;
    return MCS_OK;
}

static mcs_status parse_expr(uparser *u, mcs_unit *out);

static mcs_status parse_factor(uparser *u, mcs_unit *out)
{
    mcs_unit base = {1.0, 1.0, 1.0, MCS_DIM_NONE};
    mcs_status st = MCS_OK;
    if (*u->p == '(') {
        if (++u->depth > 8) return ufail(u, "too many parentheses in '%s'", u->s);
        u->p++;
        skip_spaces(u);
        if ((st = parse_expr(u, &base))) return st;
        skip_spaces(u);
        if (*u->p != ')') return ufail(u, "missing ')' in '%s'", u->s);
        u->p++;
        u->depth--;
    } else if (*u->p == '1' && !isdigit((unsigned char)u->p[1]) && u->p[1] != '.') {
        u->p++;
    } else {
        size_t len = symbol_len(u->p);
        if (len == 0) {
            char c[8];
            snprintf(c, sizeof c, "%.*s", (unsigned char)*u->p >= 0x80 ? 2 : 1, u->p);
            return ufail(u, *u->p ? "unexpected '%s' in unit" : "unit ends too early%s", c);
        }
        if (!lookup_symbol(u, u->p, len, &base)) {
            char sym[64];
            snprintf(sym, sizeof sym, "%.*s", (int)(len < 60 ? len : 60), u->p);
            return ufail(u, "unknown unit '%s'", sym);
        }
        u->p += len;
    }
    int power = 1;
    if ((st = parse_power(u, &power))) return st;
    *out = (mcs_unit){1.0, 1.0, 1.0, MCS_DIM_NONE};
    umul(out, base, power);
    return MCS_OK;
}

static int starts_factor(const char *p)
{
    return *p == '(' || *p == '1' || symbol_len(p) > 0;
}

static mcs_status parse_product(uparser *u, mcs_unit *out)
{
    mcs_status st = parse_factor(u, out);
    while (st == MCS_OK) {
        const char *before = u->p;
        skip_spaces(u);
        int op = 0;
        if (*u->p == '*' && u->p[1] != '*') {
            op = 1, u->p++;
        } else if (!strncmp(u->p, "\xc2\xb7", 2)) {
            op = 1, u->p += 2;
        }
        if (op) skip_spaces(u);
        if (!op && (u->p == before || !starts_factor(u->p))) break;
        mcs_unit f;
        if ((st = parse_factor(u, &f))) break;
        umul(out, f, 1);
    }
    return st;
}

static mcs_status parse_expr(uparser *u, mcs_unit *out)
{
    mcs_status st = parse_product(u, out);
    while (st == MCS_OK) {
        skip_spaces(u);
        if (*u->p != '/') break;
        u->p++;
        skip_spaces(u);
        mcs_unit d;
        if ((st = parse_product(u, &d))) break;
        umul(out, d, -1);
    }
    return st;
}

mcs_status mcs_unit_parse(const char *text, int g_is_accel, mcs_unit *out, char *why, size_t nwhy)
{
    uparser u = {text, text, g_is_accel, 0, why, nwhy};
    skip_spaces(&u);
    if (!*u.p) return ufail(&u, "empty unit%s", "");
    mcs_status st = parse_expr(&u, out);
    if (st) return st;
    skip_spaces(&u);
    if (*u.p) {
        char c[8];
        snprintf(c, sizeof c, "%.*s", (unsigned char)*u.p >= 0x80 ? 2 : 1, u.p);
        return ufail(&u, "unexpected '%s' in unit", c);
    }
    return MCS_OK;
}

/* ---- numbers and quantities ---- */

size_t mcs_number_scan(const char *s, double *v)
{
    const char *p = s;
    if (*p == '+' || *p == '-') p++;
    size_t nd = 0;
    while (isdigit((unsigned char)*p))
        p++, nd++;
    if (*p == '.') {
        p++;
        while (isdigit((unsigned char)*p))
            p++, nd++;
    }
    if (nd == 0) return 0;
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        if (*q == '+' || *q == '-') q++;
        if (isdigit((unsigned char)*q)) {
            while (isdigit((unsigned char)*q))
                q++;
            p = q;
        }
    }
    /* strtod on a bounded copy: the text may not be NUL-terminated right after the number */
    char buf[128];
    size_t n = (size_t)(p - s);
    if (n >= sizeof buf) {
        *v = HUGE_VAL; /* absurdly long number: treat as overflow */
        return n;
    }
    memcpy(buf, s, n);
    buf[n] = 0;
    *v = strtod(buf, NULL);
    return n;
}

int mcs_is_nonfinite_word(const char *s, size_t len)
{
    if (len && (s[0] == '+' || s[0] == '-')) s++, len--;
    if (len && s[0] == '.') s++, len--;
    static const char *const words[] = {"nan", "inf", "infinity"};
    for (int i = 0; i < 3; i++)
        if (strlen(words[i]) == len && !strncasecmp(s, words[i], len)) return 1;
    return 0;
}

static mcs_status qfail(char *why, size_t n, mcs_status st, const char *fmt, const char *a,
                        const char *b)
{
    snprintf(why, n, fmt, a, b);
    return st;
}

/* parse the unit of a quantity; "g" is tried as gram first, then as standard gravity */
static mcs_status quantity_unit(const char *text, const char *ustr, mcs_dim want, mcs_unit *u,
                                char *why, size_t nwhy)
{
    mcs_status st = mcs_unit_parse(ustr, 0, u, why, nwhy);
    if (st) return st;
    if (mcs_dim_compatible(want, u->dim)) return MCS_OK;
    mcs_unit ug;
    char tmp[16];
    if (mcs_unit_parse(ustr, 1, &ug, tmp, sizeof tmp) == MCS_OK &&
        mcs_dim_compatible(want, ug.dim)) {
        *u = ug;
        return MCS_OK;
    }
    char got[96], exp[96];
    mcs_dim_describe(u->dim, got, sizeof got);
    mcs_dim_describe(want, exp, sizeof exp);
    snprintf(why, nwhy, "'%.80s' is %s, expected %s", text, got, exp);
    return MCS_ERR_UNIT;
}

mcs_status mcs_quantity_parse(const char *text, mcs_dim want, double *si, char *why, size_t nwhy)
{
    const char *p = text;
    while (*p == ' ' || *p == '\t')
        p++;
    double v = 0.0;
    size_t n = mcs_number_scan(p, &v);
    if (n == 0) {
        size_t w = strcspn(p, " \t");
        if (mcs_is_nonfinite_word(p, w))
            return qfail(why, nwhy, MCS_ERR_RANGE, "'%s' is not a finite number%s", text, "");
        return qfail(why, nwhy, MCS_ERR_TYPE, "'%s' does not start with a number%s", text, "");
    }
    if (!isfinite(v))
        return qfail(why, nwhy, MCS_ERR_RANGE, "'%s' is not a finite number%s", text, "");
    p += n;
    while (*p == ' ' || *p == '\t')
        p++;
    if (!*p) { /* a bare number is SI */
        *si = v;
        return MCS_OK;
    }
    mcs_unit u;
    char uwhy[512];
    mcs_status st = quantity_unit(text, p, want, &u, uwhy, sizeof uwhy);
    if (st) return qfail(why, nwhy, st, "%s%s", uwhy, "");
    *si = v * u.num / u.den;
    if (!isfinite(*si))
        return qfail(why, nwhy, MCS_ERR_RANGE, "'%s' overflows in SI units%s", text, "");
    return MCS_OK;
}

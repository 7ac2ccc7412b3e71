/* fe_kw_expr: the arithmetic of *PARAMETER_EXPRESSION, a recursive-descent evaluator over
 * doubles (fe_kw_impl.h, kw_expr_eval):
 *     expr    = term { ('+' | '-') term }
 *     term    = unary { ('*' | '/') unary }
 *     unary   = ('+' | '-') unary | power
 *     power   = primary [ ('**' | '^') unary ]          right-associative: 2**3**2 = 2**9
 *     primary = number | '(' expr ')' | name '(' expr { ',' expr } ')' | ['&'] name
 * As in Fortran, -2**2 = -(2**2) = -4. Numbers take the Fortran forms of the card reader
 * (1.5, .5, 1.5e3, 1.5d3). Functions: sin cos tan asin acos atan atan2 sinh cosh tanh exp log
 * log10 sqrt abs min max (min and max of any number of arguments), sign(a, b), mod(a, b),
 * int (toward zero), nint (nearest); angles in radians. Names are looked up by the caller. */
#include "fe/fe_kw_impl.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct {
    const char *s;
    int at;
    int (*look)(void *user, const char *name, double *v);
    void *user;
    int err;     /* error offset + 1 (0: none) */
    char *msg;
    size_t nmsg;
    int depth;
} ex;

static double expr(ex *e);

static int fail(ex *e, int at, const char *what, const char *name)
{
    if (!e->err) {
        e->err = at + 1;
        snprintf(e->msg, e->nmsg, what, name);
    }
    return 0;
}

static void blanks(ex *e)
{
    while (e->s[e->at] == ' ' || e->s[e->at] == '\t') e->at++;
}

/* the next non-blank character is c: consume it */
static int eat(ex *e, char c)
{
    blanks(e);
    if (e->s[e->at] != c) return 0;
    e->at++;
    return 1;
}

static double number(ex *e)
{
    const char *s = e->s + e->at;
    int n = 0;
    while (isdigit((unsigned char)s[n]) || s[n] == '.') n++;
    if (n && strchr("eEdD", s[n]) && s[n]) {
        int k = n + 1;
        if (s[k] == '+' || s[k] == '-') k++;
        if (isdigit((unsigned char)s[k])) {
            n = k;
            while (isdigit((unsigned char)s[n])) n++;
        }
    }
    double v = 0;
    if (kw_parse_real(s, n, &v)) fail(e, e->at, "a malformed number%s", "");
    e->at += n;
    return v;
}

typedef struct {
    const char *name;
    int nargs; /* -1: one or more */
} fn_desc;

static const fn_desc fns[] = {
    {"SIN", 1},   {"COS", 1},  {"TAN", 1},   {"ASIN", 1}, {"ACOS", 1},  {"ATAN", 1},
    {"ATAN2", 2}, {"SINH", 1}, {"COSH", 1},  {"TANH", 1}, {"EXP", 1},   {"LOG", 1},
    {"LOG10", 1}, {"SQRT", 1}, {"ABS", 1},   {"MIN", -1}, {"MAX", -1},  {"SIGN", 2},
    {"MOD", 2},   {"INT", 1},  {"NINT", 1},
};

static double apply(ex *e, int at, const char *f, const double *a, int n)
{
    double x = a[0];
    if (!strcmp(f, "SIN")) return sin(x);
    if (!strcmp(f, "COS")) return cos(x);
    if (!strcmp(f, "TAN")) return tan(x);
    if (!strcmp(f, "ASIN")) return asin(x);
    if (!strcmp(f, "ACOS")) return acos(x);
    if (!strcmp(f, "ATAN")) return atan(x);
    if (!strcmp(f, "ATAN2")) return atan2(x, a[1]);
    if (!strcmp(f, "SINH")) return sinh(x);
    if (!strcmp(f, "COSH")) return cosh(x);
    if (!strcmp(f, "TANH")) return tanh(x);
    if (!strcmp(f, "EXP")) return exp(x);
    if (!strcmp(f, "LOG")) return log(x);
    if (!strcmp(f, "LOG10")) return log10(x);
    if (!strcmp(f, "SQRT")) return sqrt(x);
    if (!strcmp(f, "ABS")) return fabs(x);
    if (!strcmp(f, "SIGN")) return copysign(fabs(x), a[1]);
    if (!strcmp(f, "MOD")) return fmod(x, a[1]);
    if (!strcmp(f, "INT")) return trunc(x);
    if (!strcmp(f, "NINT")) return round(x);
    double m = x;
    for (int i = 1; i < n; i++) m = !strcmp(f, "MIN") ? fmin(m, a[i]) : fmax(m, a[i]);
    if (strcmp(f, "MIN") && strcmp(f, "MAX")) fail(e, at, "unknown function '%s'", f);
    return m;
}

/* a function call; e->at is at '(' */
static double call(ex *e, int at, const char *name)
{
    const fn_desc *fd = NULL;
    for (size_t i = 0; i < sizeof fns / sizeof fns[0]; i++)
        if (!strcmp(fns[i].name, name)) fd = &fns[i];
    if (!fd) return fail(e, at, "unknown function '%s'", name);
    double a[16];
    int n = 0;
    e->at++;
    do {
        double v = expr(e);
        if (n < 16) a[n] = v;
        n++;
    } while (!e->err && eat(e, ','));
    if (!e->err && !eat(e, ')')) return fail(e, e->at, "')' expected%s", "");
    if (e->err) return 0;
    if (n > 16 || (fd->nargs > 0 && n != fd->nargs))
        return fail(e, at, "wrong number of arguments to '%s'", name);
    return apply(e, at, name, a, n);
}

static double primary(ex *e)
{
    blanks(e);
    int at = e->at;
    char c = e->s[at];
    if (c == '(') {
        e->at++;
        double v = expr(e);
        if (!e->err && !eat(e, ')')) return fail(e, e->at, "')' expected%s", "");
        return v;
    }
    if (isdigit((unsigned char)c) || c == '.') return number(e);
    int amp = c == '&';
    if (amp) e->at++;
    char name[64];
    int n = 0;
    while (isalnum((unsigned char)e->s[e->at]) || e->s[e->at] == '_') {
        if (n < 63) name[n++] = (char)toupper((unsigned char)e->s[e->at]);
        e->at++;
    }
    name[n] = 0;
    if (!n) return fail(e, at, c ? "unexpected '%.1s'" : "unexpected end%s", e->s + at);
    blanks(e);
    if (!amp && e->s[e->at] == '(') return call(e, at, name);
    double v = 0;
    if (e->look(e->user, name, &v)) return fail(e, at, "parameter '%s' is not defined", name);
    return v;
}

static double unary(ex *e);

static double power(ex *e)
{
    double b = primary(e);
    blanks(e);
    if (e->s[e->at] == '*' && e->s[e->at + 1] == '*') e->at += 2;
    else if (e->s[e->at] == '^') e->at++;
    else return b;
    return pow(b, unary(e));
}

static double unary(ex *e)
{
    if (++e->depth > 200) return fail(e, e->at, "nested too deeply%s", "");
    double v;
    if (eat(e, '-')) v = -unary(e);
    else if (eat(e, '+')) v = unary(e);
    else v = power(e);
    e->depth--;
    return v;
}

static double term(ex *e)
{
    double v = unary(e);
    for (;;) {
        blanks(e);
        char c = e->s[e->at];
        if (e->err || (c != '*' && c != '/') || e->s[e->at + 1] == '*') return v;
        e->at++;
        double r = unary(e);
        v = c == '*' ? v * r : v / r;
    }
}

static double expr(ex *e)
{
    double v = term(e);
    for (;;) {
        blanks(e);
        char c = e->s[e->at];
        if (e->err || (c != '+' && c != '-')) return v;
        e->at++;
        double r = term(e);
        v = c == '+' ? v + r : v - r;
    }
}

int kw_expr_eval(const char *s, int (*look)(void *user, const char *name, double *v), void *user,
                 double *out, int *errpos, char *msg, size_t nmsg)
{
    ex e = {.s = s, .look = look, .user = user, .msg = msg, .nmsg = nmsg};
    double v = expr(&e);
    blanks(&e);
    if (!e.err && e.s[e.at]) fail(&e, e.at, "unexpected '%.1s'", e.s + e.at);
    if (!e.err && !isfinite(v)) fail(&e, 0, "the value is not finite%s", "");
    *errpos = e.err ? e.err - 1 : 0;
    if (e.err) return -1;
    *out = v;
    return 0;
}

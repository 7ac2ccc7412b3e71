/* an_mme.c: ISO/TS 13499 (ISO-MME) channel files, read and write */
#include "analysis/an_mme.h"
#include "analysis/an_units.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* trim blanks in place; returns the start */
static char *trim(char *s)
{
    while (isspace((unsigned char)*s)) s++;
    size_t n = strlen(s);
    while (n && isspace((unsigned char)s[n - 1])) s[--n] = 0;
    return s;
}

/* whole line is one finite number */
static int parse_number(const char *s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    if (end == s || errno == ERANGE || !isfinite(*v)) return 0;
    while (isspace((unsigned char)*end)) end++;
    return *end == 0;
}

/* channel header fields gathered while reading */
typedef struct {
    char name[128], code[64], unit[32];
    double t0, dt;
    long nsamp;
    int cfc, have_t0, have_dt, have_n;
} mme_head;

static mcs_status head_line(const char *path, int line, char *key, char *val, mme_head *h,
                            mcs_error *err)
{
    double v;
    if (strcasecmp(key, "Name of the channel") == 0) {
        snprintf(h->name, sizeof h->name, "%s", val);
    } else if (strcasecmp(key, "Channel code") == 0) {
        snprintf(h->code, sizeof h->code, "%s", val);
    } else if (strcasecmp(key, "Unit") == 0) {
        snprintf(h->unit, sizeof h->unit, "%s", val);
    } else if (strcasecmp(key, "Channel frequency class") == 0) {
        /* NOVALUE (or a number no filter class has): unfiltered */
        h->cfc = parse_number(val, &v) && v >= 0 && v <= 1e6 ? (int)v : 0;
    } else if (strcasecmp(key, "Time of first sample") == 0) {
        if (!parse_number(val, &v))
            return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d: error: Time of first sample: \"%s\"",
                           path, line, val);
        h->t0 = v, h->have_t0 = 1;
    } else if (strcasecmp(key, "Sampling interval") == 0) {
        if (!parse_number(val, &v) || !(v > 0))
            return MCS_ERR(err, MCS_ERR_FORMAT,
                           "%s:%d: error: Sampling interval: \"%s\" is not a positive number",
                           path, line, val);
        h->dt = v, h->have_dt = 1;
    } else if (strcasecmp(key, "Number of samples") == 0) {
        if (!parse_number(val, &v) || v < 2 || v > 1e9 || v != floor(v))
            return MCS_ERR(err, MCS_ERR_FORMAT,
                           "%s:%d: error: Number of samples: \"%s\" is not an integer >= 2", path,
                           line, val);
        h->nsamp = (long)v, h->have_n = 1;
    }
    return MCS_OK;
}

static mcs_status check_head(const char *path, const mme_head *h, double *factor,
                             const char **si, mcs_error *err)
{
    if (!h->have_t0 || !h->have_dt || !h->have_n)
        return MCS_ERR(err, MCS_ERR_FORMAT,
                       "%s: error: missing header line \"%s\"", path,
                       !h->have_t0 ? "Time of first sample" :
                       !h->have_dt ? "Sampling interval" : "Number of samples");
    char u[32];
    snprintf(u, sizeof u, "%s", h->unit);
    /* ISO-MME writes powers as ** (m/s**2) */
    if (!an_unit_to_si(u, factor, si))
        return MCS_ERR(err, MCS_ERR_UNIT, "%s: error: Unit: unknown unit \"%s\"", path, h->unit);
    return MCS_OK;
}

mcs_status an_mme_read_file(const char *path, an_signal *out, mcs_error *err)
{
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "r");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    mme_head h = {0};
    double factor = 1;
    const char *si = "-";
    char *buf = NULL;
    size_t cap = 0;
    int line = 0, indata = 0;
    long k = 0, cap_s = 0;
    mcs_status st = MCS_OK;
    while (!st && getline(&buf, &cap, f) >= 0) {
        line++;
        char *s = trim(buf);
        double v;
        if (!*s) continue;
        if (!indata && !parse_number(s, &v)) {
            char *colon = strchr(s, ':');
            if (!colon) {
                st = MCS_ERR(err, MCS_ERR_FORMAT,
                             "%s:%d:1: error: expected \"key :value\" or a sample value", path,
                             line);
                break;
            }
            *colon = 0;
            st = head_line(path, line, trim(s), trim(colon + 1), &h, err);
            continue;
        }
        if (!indata) {
            indata = 1;
            st = check_head(path, &h, &factor, &si, err);
            if (st) break;
        }
        if (k == cap_s && k < h.nsamp) {
            /* grown with the samples the file holds, not to the size its header declares
             * (up to 10^9: a 16 GB allocation for a file of a few lines) */
            long c = cap_s ? 2 * cap_s : 1024;
            if (c > h.nsamp) c = h.nsamp;
            double *t = realloc(out->t, (size_t)c * sizeof(double));
            if (t) out->t = t;
            double *y = t ? realloc(out->y, (size_t)c * sizeof(double)) : NULL;
            if (y) out->y = y;
            if (!t || !y) {
                st = MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
                break;
            }
            cap_s = c;
        }
        if (!parse_number(s, &v)) {
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d:1: error: \"%s\" is not a sample value",
                         path, line, s);
        } else if (k >= h.nsamp) {
            st = MCS_ERR(err, MCS_ERR_FORMAT,
                         "%s:%d:1: error: more samples than Number of samples (%ld)", path, line,
                         h.nsamp);
        } else {
            out->t[k] = h.t0 + (double)k * h.dt;
            out->y[k] = v * factor;
            k++;
        }
    }
    free(buf);
    fclose(f);
    if (!st && !indata) st = check_head(path, &h, &factor, &si, err);
    if (!st && k != h.nsamp)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%d: error: %ld samples, Number of samples says %ld",
                     path, line, k, h.nsamp);
    if (st) {
        an_signal_free(out);
        return st;
    }
    out->n = (int)k;
    out->cfc = h.cfc;
    const char *nm = h.code[0] && strcasecmp(h.code, "NOVALUE") != 0 ? h.code : h.name;
    snprintf(out->name, sizeof out->name, "%.*s", (int)strcspn(nm, "/"), nm);
    char *e = out->name + strlen(out->name);
    while (e > out->name && isspace((unsigned char)e[-1])) *--e = 0;
    snprintf(out->unit, sizeof out->unit, "%s", si);
    return MCS_OK;
}

/* DIR and TEST of DIR/TEST.mme, and the channel folder that exists */
static mcs_status mme_paths(const char *mme, char *chdir_, size_t nd, char *test, size_t nt,
                            mcs_error *err)
{
    const char *slash = strrchr(mme, '/');
    const char *base = slash ? slash + 1 : mme;
    size_t dl = slash ? (size_t)(slash - mme) : 0;
    size_t bl = strlen(base);
    if (bl < 5 || bl - 4 >= nt) return MCS_ERR(err, MCS_ERR_USAGE, "%s: bad .mme name", mme);
    snprintf(test, nt, "%.*s", (int)(bl - 4), base);
    struct stat sb;
    if (stat(mme, &sb) != 0)
        return MCS_ERR(err, MCS_ERR_IO, "%s: cannot open: %s", mme, strerror(errno));
    static const char *const names[] = {"Channel", "CHANNEL", "channel"};
    for (int i = 0; i < 3; i++) {
        snprintf(chdir_, nd, "%.*s%s%s", (int)dl, mme, dl ? "/" : "", names[i]);
        if (stat(chdir_, &sb) == 0 && S_ISDIR(sb.st_mode)) return MCS_OK;
    }
    return MCS_ERR(err, MCS_ERR_IO, "%s: no Channel folder beside it", mme);
}

/* does channel file number i match the selector (code, name, or description)? */
static int name_matches(const char *chname, const char *sel)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", chname);
    char *slash = strchr(buf, '/');
    if (strcasecmp(trim(buf), sel) == 0) return 1;
    if (slash) {
        *slash = 0;
        if (strcasecmp(trim(buf), sel) == 0) return 1;
        snprintf(buf, sizeof buf, "%s", strchr(chname, '/') + 1);
        if (strcasecmp(trim(buf), sel) == 0) return 1;
    }
    return 0;
}

mcs_status an_mme_read_channel(const char *mme_path, const char *channel, an_signal *out,
                               mcs_error *err)
{
    memset(out, 0, sizeof *out);
    char dir[4096], test[256], path[4600];
    mcs_status st = mme_paths(mme_path, dir, sizeof dir, test, sizeof test, err);
    if (st) return st;
    char *end;
    long num = strtol(channel, &end, 10);
    if (*end == 0 && num >= 1 && num <= 999) {
        snprintf(path, sizeof path, "%s/%s.%03ld", dir, test, num);
        return an_mme_read_file(path, out, err);
    }
    /* search the channel files for the name or code */
    for (int i = 1; i <= 999; i++) {
        snprintf(path, sizeof path, "%s/%s.%03d", dir, test, i);
        FILE *f = fopen(path, "r");
        if (!f) break;
        fclose(f);
        an_signal s;
        mcs_error e2 = {0};
        if (an_mme_read_file(path, &s, &e2)) {
            return MCS_ERR(err, e2.status, "%s", e2.msg);
        }
        /* re-read the raw name line for a match on the description too */
        int hit = name_matches(s.name, channel);
        if (!hit) {
            FILE *g = fopen(path, "r");
            char *buf = NULL;
            size_t cap = 0;
            while (g && !hit && getline(&buf, &cap, g) >= 0) {
                char *c = strchr(buf, ':');
                if (!c) break;
                *c = 0;
                char *k = trim(buf);
                if (strcasecmp(k, "Name of the channel") == 0 || strcasecmp(k, "Channel code") == 0)
                    hit = name_matches(trim(c + 1), channel);
            }
            free(buf);
            if (g) fclose(g);
        }
        if (hit) {
            *out = s;
            return MCS_OK;
        }
        an_signal_free(&s);
    }
    return MCS_ERR(err, MCS_ERR_KEY, "%s: no channel \"%s\" in %s/%s.NNN", mme_path, channel, dir,
                   test);
}

/* ISO-MME spelling of an SI unit */
static const char *mme_unit(const char *si)
{
    if (strcmp(si, "m/s^2") == 0) return "m/s**2";
    if (strcmp(si, "rad/s^2") == 0) return "rad/s**2";
    if (strcmp(si, "-") == 0) return "NOVALUE";
    return si;
}

static mcs_status write_channel(const char *path, const char *test, const an_signal *s,
                                const an_mme_axes *ax, mcs_error *err)
{
    FILE *f = fopen(path, "w");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
    double dt = (s->t[s->n - 1] - s->t[0]) / (s->n - 1);
    fprintf(f, "%-28s:%s\n", "Test object number", test);
    fprintf(f, "%-28s:%s\n", "Name of the channel", s->name);
    fprintf(f, "%-28s:%s\n", "Channel code", s->name);
    fprintf(f, "%-28s:%s\n", "Unit", mme_unit(s->unit));
    if (ax) {
        fprintf(f, "%-28s:%s\n", "Reference system", ax->frame[0] ? ax->frame : "NOVALUE");
        fprintf(f, "%-28s:%c\n", "Direction", ax->direction ? ax->direction : '0');
    }
    if (s->cfc > 0)
        fprintf(f, "%-28s:%d\n", "Channel frequency class", s->cfc);
    else
        fprintf(f, "%-28s:NOVALUE\n", "Channel frequency class");
    fprintf(f, "%-28s:%.17g\n", "Time of first sample", s->t[0]);
    fprintf(f, "%-28s:%.17g\n", "Sampling interval", dt);
    fprintf(f, "%-28s:%d\n", "Number of samples", s->n);
    /* 17 significant digits: every double reads back bit for bit */
    for (int i = 0; i < s->n; i++) fprintf(f, "%.17g\n", s->y[i]);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad)
        return MCS_ERR(err, MCS_ERR_IO, "%s: write error", path);
    return MCS_OK;
}

mcs_status an_mme_check(const an_signal *ch, int n, mcs_error *err)
{
    if (n < 1 || n > 999) return MCS_ERR(err, MCS_ERR_RANGE, "ISO-MME: %d channels (1..999)", n);
    for (int c = 0; c < n; c++) {
        const an_signal *s = &ch[c];
        if (s->n < 2)
            return MCS_ERR(err, MCS_ERR_RANGE, "ISO-MME: channel %s has %d samples", s->name, s->n);
        double dt = (s->t[s->n - 1] - s->t[0]) / (s->n - 1);
        for (int i = 0; i < s->n; i++)
            /* 1e-6 of a step: times that came through %.12g text stay uniform */
            if (!(fabs(s->t[i] - (s->t[0] + i * dt)) <= 1e-6 * dt))
                return MCS_ERR(err, MCS_ERR_RANGE,
                               "ISO-MME: channel %s is not uniformly sampled (sample %d at %g s); "
                               "ISO-MME needs a constant sampling interval",
                               s->name, i, s->t[i]);
        /* the unit as written must read back as the same SI unit, unscaled */
        double factor = 0;
        const char *si = NULL;
        if (!an_unit_to_si(mme_unit(s->unit), &factor, &si) || factor != 1 ||
            strcmp(si, s->unit) != 0)
            return MCS_ERR(err, MCS_ERR_UNIT,
                           "ISO-MME: channel %s: unit \"%s\" is not an SI unit the reader knows",
                           s->name, s->unit);
    }
    return MCS_OK;
}

mcs_status an_mme_write(const char *dir, const char *test, const an_signal *ch, int n,
                        mcs_error *err)
{
    return an_mme_write_axes(dir, test, ch, NULL, n, err);
}

mcs_status an_mme_write_axes(const char *dir, const char *test, const an_signal *ch,
                             const an_mme_axes *axes, int n, mcs_error *err)
{
    /* validate everything first, so nothing is written for bad input */
    mcs_status st0 = an_mme_check(ch, n, err);
    if (st0) return st0;
    char path[4600];
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return MCS_ERR(err, MCS_ERR_IO, "%s: cannot create: %s", dir, strerror(errno));
    snprintf(path, sizeof path, "%s/Channel", dir);
    if (mkdir(path, 0777) != 0 && errno != EEXIST)
        return MCS_ERR(err, MCS_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
    snprintf(path, sizeof path, "%s/%s.mme", dir, test);
    FILE *f = fopen(path, "w");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
    fprintf(f, "%-28s:%s\n", "Data format edition number", "1.6");
    fprintf(f, "%-28s:%s\n", "Laboratory name", "NOVALUE");
    fprintf(f, "%-28s:%s\n", "Laboratory test ref. number", test);
    fprintf(f, "%-28s:%s\n", "Title", "written by mcrash");
    fprintf(f, "%-28s:%d\n", "Number of channels", n);
    if (fclose(f) != 0) return MCS_ERR(err, MCS_ERR_IO, "%s: write error", path);
    snprintf(path, sizeof path, "%s/Channel/%s.chn", dir, test);
    f = fopen(path, "w");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
    fprintf(f, "%-28s:%s\n", "Instrumentation standard", "ISO/TS 13499");
    fprintf(f, "%-28s:%d\n", "Number of channels", n);
    for (int c = 0; c < n; c++) {
        char key[40];
        snprintf(key, sizeof key, "Name of channel %03d", c + 1);
        fprintf(f, "%-28s:%s\n", key, ch[c].name);
    }
    if (fclose(f) != 0) return MCS_ERR(err, MCS_ERR_IO, "%s: write error", path);
    for (int c = 0; c < n; c++) {
        snprintf(path, sizeof path, "%s/Channel/%s.%03d", dir, test, c + 1);
        mcs_status st = write_channel(path, test, &ch[c], axes ? &axes[c] : NULL, err);
        if (st) return st;
    }
    return MCS_OK;
}

/* tr_mme.c: results-file channels -> ISO-MME tests, one per stage (tr_mme.h) */
#include "translators/tr_mme.h"
#include "analysis/an_mme.h"
#include "analysis/an_units.h"
#include "core/mcs_results_export.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

typedef struct {
    int stage, n;
    an_signal *ch;
    an_mme_axes *ax;
} mme_stage;

static void stage_free(mme_stage *s)
{
    for (int c = 0; c < s->n; c++)
        an_signal_free(&s->ch[c]);
    free(s->ch);
    free(s->ax);
    memset(s, 0, sizeof *s);
}

static int ends_with(const char *s, const char *suf)
{
    size_t a = strlen(s), b = strlen(suf);
    return a >= b && strcmp(s + a - b, suf) == 0;
}

/* J211 direction from the channel name: head_ax -> X, ..._z -> Z, _r/_res/_resultant -> R */
static char direction(const char *name)
{
    if (ends_with(name, "_r") || ends_with(name, "_res") || ends_with(name, "_resultant"))
        return 'R';
    /* ..._x, or one letter after the last '_' and an axis: head_ax, neck_fz, chest_dx */
    size_t n = strlen(name);
    char last = n >= 2 ? (char)tolower((unsigned char)name[n - 1]) : 0;
    if ((last == 'x' || last == 'y' || last == 'z') &&
        (name[n - 2] == '_' ||
         (n >= 3 && isalpha((unsigned char)name[n - 2]) && name[n - 3] == '_')))
        return (char)toupper((unsigned char)last);
    return '0';
}

/* one channel of stage s into ch/ax (SI, time from /stageS/time) */
static mcs_status read_channel(mcs_results *r, int s, const char *name, const mcs_array *t,
                               an_signal *ch, an_mme_axes *ax, mcs_error *err)
{
    char path[512];
    snprintf(path, sizeof path, "/stage%d/channels/%s", s, name);
    mcs_array a = {0};
    mcs_status st = mcs_results_read(r, path, &a, err);
    double factor = 1;
    const char *si = "-";
    if (!st && (a.rank != 1 || a.n != t->n))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %zu values, /stage%d/time has %zu", path, a.n, s,
                     t->n);
    if (!st && !an_unit_to_si(a.unit, &factor, &si))
        st = MCS_ERR(err, MCS_ERR_UNIT, "%s: unknown unit \"%s\"", path, a.unit);
    if (!st && strlen(name) >= sizeof ch->name)
        st = MCS_ERR(err, MCS_ERR_RANGE, "%s: name longer than %zu characters", path,
                     sizeof ch->name - 1);
    if (!st) {
        ch->t = malloc(t->n * sizeof(double));
        ch->y = malloc(t->n * sizeof(double));
        if (!ch->t || !ch->y) st = MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    }
    if (!st) {
        ch->n = (int)t->n;
        for (size_t i = 0; i < t->n; i++)
            ch->t[i] = t->v[i], ch->y[i] = a.v[i] * factor;
        snprintf(ch->name, sizeof ch->name, "%s", name);
        snprintf(ch->unit, sizeof ch->unit, "%s", si);
        double cfc = 0;
        mcs_error e2 = {0};
        if (mcs_results_has_attr(r, path, "cfc") &&
            mcs_results_attr_double(r, path, "cfc", &cfc, &e2) == MCS_OK)
            ch->cfc = (int)cfc;
        char *frame = NULL;
        if (mcs_results_has_attr(r, path, "frame") &&
            mcs_results_attr_str(r, path, "frame", &frame, &e2) == MCS_OK)
            snprintf(ax->frame, sizeof ax->frame, "%s", frame);
        free(frame);
        ax->direction = direction(name);
    }
    mcs_array_free(&a);
    return st;
}

/* every channel of stage s; MCS_OK with out->n = 0 when it has none */
static mcs_status read_stage(mcs_results *r, int s, mme_stage *out, mcs_error *err)
{
    memset(out, 0, sizeof *out);
    out->stage = s;
    char grp[64], tpath[64];
    snprintf(grp, sizeof grp, "/stage%d/channels", s);
    snprintf(tpath, sizeof tpath, "/stage%d/time", s);
    if (mcs_results_kind(r, grp) != MCS_RES_GROUP) return MCS_OK;
    char **names = NULL;
    int nn = 0;
    mcs_status st = mcs_results_list(r, grp, &names, &nn, err);
    if (st || nn == 0) return st;
    mcs_array t = {0};
    st = mcs_results_read(r, tpath, &t, err);
    if (!st) {
        out->ch = calloc((size_t)nn, sizeof *out->ch);
        out->ax = calloc((size_t)nn, sizeof *out->ax);
        if (!out->ch || !out->ax) st = MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    }
    for (int c = 0; !st && c < nn; c++) {
        st = read_channel(r, s, names[c], &t, &out->ch[c], &out->ax[c], err);
        if (!st) out->n = c + 1;
    }
    if (!st) {
        mcs_error e2 = {0};
        st = an_mme_check(out->ch, out->n, &e2);
        if (st) st = MCS_ERR(err, e2.status, "stage %d: %s", s, e2.msg);
    }
    mcs_array_free(&t);
    mcs_results_list_free(&names, nn);
    if (st) stage_free(out);
    return st;
}

/* remove what writing stage s (n channels) under dir made; directories only when empty */
static void unwrite_stage(const char *dir, int s, int n)
{
    char p[4600];
    for (int c = 1; c <= n; c++) {
        snprintf(p, sizeof p, "%s/stage%d/Channel/stage%d.%03d", dir, s, s, c);
        unlink(p);
    }
    snprintf(p, sizeof p, "%s/stage%d/Channel/stage%d.chn", dir, s, s);
    unlink(p);
    snprintf(p, sizeof p, "%s/stage%d/Channel", dir, s);
    rmdir(p);
    snprintf(p, sizeof p, "%s/stage%d/stage%d.mme", dir, s, s);
    unlink(p);
    snprintf(p, sizeof p, "%s/stage%d", dir, s);
    rmdir(p);
}

mcs_status tr_mme_export(mcs_results *r, const char *dir, int stage, int *nstages, int *nchannels,
                         mcs_error *err)
{
    if (nstages) *nstages = 0;
    if (nchannels) *nchannels = 0;
    int list[64];
    int ns = mcs_results_stages(r, list, 64);
    if (ns > 64) ns = 64;
    mme_stage st_[64];
    int nst = 0;
    mcs_status st = MCS_OK;
    for (int i = 0; !st && i < ns; i++) {
        if (stage && list[i] != stage) continue;
        st = read_stage(r, list[i], &st_[nst], err);
        if (!st && st_[nst].n > 0) nst++;
    }
    if (!st && nst == 0) {
        if (stage)
            st = MCS_ERR(err, MCS_ERR_KEY,
                         "%s: no channels in /stage%d (no such stage, or it "
                         "wrote none)",
                         mcs_results_path(r), stage);
        else
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: no channels in any stage", mcs_results_path(r));
    }
    /* write */
    int made_dir = 0;
    if (!st) {
        if (mkdir(dir, 0777) == 0)
            made_dir = 1;
        else if (errno != EEXIST)
            st = MCS_ERR(err, MCS_ERR_IO, "%s: cannot create: %s", dir, strerror(errno));
        struct stat sb;
        if (!st && (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)))
            st = MCS_ERR(err, MCS_ERR_IO, "%s: not a directory", dir);
    }
    int done = 0;
    for (; !st && done < nst; done++) {
        char sub[4200], test[32];
        snprintf(sub, sizeof sub, "%s/stage%d", dir, st_[done].stage);
        snprintf(test, sizeof test, "stage%d", st_[done].stage);
        st = an_mme_write_axes(sub, test, st_[done].ch, st_[done].ax, st_[done].n, err);
        if (st) break;
        if (nchannels) *nchannels += st_[done].n;
    }
    if (st) {
        /* the failed stage too: an_mme_write_axes may have left part of it */
        for (int i = 0; i <= done && i < nst; i++)
            unwrite_stage(dir, st_[i].stage, st_[i].n);
        if (made_dir) rmdir(dir);
        if (nchannels) *nchannels = 0;
    } else if (nstages) {
        *nstages = nst;
    }
    for (int i = 0; i < nst; i++)
        stage_free(&st_[i]);
    return st;
}

/* tr_stages.c: stage against stage in one results file (see tr_stages.h). */
#include "translators/tr_stages.h"

#include "analysis/an_signal.h"
#include "core/mcs_results.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void tr_stage_compare_free(tr_stage_compare *c)
{
    if (!c) return;
    free(c->rating);
    free(c->crit);
    memset(c, 0, sizeof *c);
}

static int has(char **names, int n, const char *s)
{
    for (int i = 0; i < n; i++)
        if (strcmp(names[i], s) == 0) return 1;
    return 0;
}

/* rate "h5:/stage<b>/sel" against "h5:/stage<a>/sel" with both methods into r */
static void rate(const char *h5, const int st[2], const char *sel, tr_stage_rating *r)
{
    char ref[2][4400];
    an_signal s[2];
    memset(s, 0, sizeof s);
    mcs_error e = {0};
    mcs_status rc = MCS_OK;
    for (int k = 0; k < 2 && !rc; k++) {
        snprintf(ref[k], sizeof ref[k], "%s:/stage%d/%s", h5, st[k], sel);
        rc = an_signal_read_ref(ref[k], &s[k], &e);
    }
    if (!rc && s[0].unit[0] && s[1].unit[0] && strcmp(s[0].unit, s[1].unit) != 0)
        rc = MCS_ERR(&e, MCS_ERR_UNIT, "units differ: %s against %s", s[1].unit, s[0].unit);
    if (!rc) snprintf(r->unit, sizeof r->unit, "%s", s[0].unit);
    if (rc) {
        snprintf(r->iso_error, sizeof r->iso_error, "%.255s", e.msg);
        snprintf(r->cora_error, sizeof r->cora_error, "%.255s", e.msg);
    } else {
        an_iso_opts io = an_iso_opts_default();
        an_cora_opts co = an_cora_opts_default();
        mcs_error ei = {0}, ec = {0};
        r->iso_ok = an_iso18571(&s[0], &s[1], &io, &r->iso, &ei) == MCS_OK;
        r->cora_ok = an_cora(&s[0], &s[1], &co, &r->cora, &ec) == MCS_OK;
        if (!r->iso_ok) snprintf(r->iso_error, sizeof r->iso_error, "%.255s", ei.msg);
        if (!r->cora_ok) snprintf(r->cora_error, sizeof r->cora_error, "%.255s", ec.msg);
    }
    an_signal_free(&s[0]);
    an_signal_free(&s[1]);
}

/* room for one more rating */
static tr_stage_rating *next(tr_stage_compare *c, int *cap, mcs_error *err)
{
    if (c->nrating == *cap) {
        int nc = *cap ? 2 * *cap : 32;
        tr_stage_rating *p = realloc(c->rating, sizeof *p * (size_t)nc);
        if (!p) return MCS_ERR(err, MCS_ERR_NOMEM, "compare: out of memory"), NULL;
        c->rating = p, *cap = nc;
    }
    tr_stage_rating *r = &c->rating[c->nrating++];
    memset(r, 0, sizeof *r);
    return r;
}

/* the members of group /stage<s>/<sub> (none when absent) */
static mcs_status members(mcs_results *f, int s, const char *sub, char ***names, int *n,
                          mcs_error *err)
{
    char g[600];
    snprintf(g, sizeof g, "/stage%d/%s", s, sub);
    *names = NULL, *n = 0;
    if (mcs_results_kind(f, g) != MCS_RES_GROUP) return MCS_OK;
    return mcs_results_list(f, g, names, n, err);
}

static mcs_status channels(mcs_results *f, const char *h5, tr_stage_compare *c, int *cap,
                           mcs_error *err)
{
    char **na = NULL, **nb = NULL;
    int ka = 0, kb = 0;
    mcs_status st = members(f, c->stage[0], "channels", &na, &ka, err);
    if (!st) st = members(f, c->stage[1], "channels", &nb, &kb, err);
    for (int i = 0; !st && i < ka; i++) {
        if (!has(nb, kb, na[i])) continue;
        tr_stage_rating *r = next(c, cap, err);
        if (!r) st = MCS_ERR_NOMEM;
        if (st) break;
        snprintf(r->name, sizeof r->name, "%s", na[i]);
        char sel[300];
        snprintf(sel, sizeof sel, "channels/%s", na[i]);
        rate(h5, c->stage, sel, r);
    }
    mcs_results_list_free(&na, ka);
    mcs_results_list_free(&nb, kb);
    return st;
}

/* the x y z components of the shared bodies' translational and angular motion */
static mcs_status bodies(mcs_results *f, const char *h5, tr_stage_compare *c, int *cap,
                         mcs_error *err)
{
    static const char *const q[] = {"position", "velocity", "acceleration", "angular_velocity"};
    char **na = NULL, **nb = NULL;
    int ka = 0, kb = 0;
    mcs_status st = members(f, c->stage[0], "bodies", &na, &ka, err);
    if (!st) st = members(f, c->stage[1], "bodies", &nb, &kb, err);
    for (int i = 0; !st && i < ka; i++) {
        if (!has(nb, kb, na[i])) continue;
        for (int j = 0; !st && j < 4; j++) {
            char p[2][600];
            for (int k = 0; k < 2; k++)
                snprintf(p[k], sizeof p[k], "/stage%d/bodies/%s/%s", c->stage[k], na[i], q[j]);
            if (mcs_results_kind(f, p[0]) != MCS_RES_DATASET ||
                mcs_results_kind(f, p[1]) != MCS_RES_DATASET)
                continue;
            for (int k = 0; !st && k < 3; k++) {
                tr_stage_rating *r = next(c, cap, err);
                if (!r) st = MCS_ERR_NOMEM;
                if (st) break;
                r->body = 1;
                snprintf(r->name, sizeof r->name, "%s/%s_%c", na[i], q[j], "xyz"[k]);
                char sel[700];
                snprintf(sel, sizeof sel, "bodies/%s/%s[%d]", na[i], q[j], k);
                rate(h5, c->stage, sel, r);
            }
        }
    }
    mcs_results_list_free(&na, ka);
    mcs_results_list_free(&nb, kb);
    return st;
}

/* the criteria of both stages, matched by key */
static mcs_status criteria(const char *h5, tr_stage_compare *c, mcs_error *err)
{
    an_injury_row *row[2] = {NULL, NULL};
    int n[2] = {0, 0}, used;
    an_dummy d;
    mcs_status st = MCS_OK;
    for (int k = 0; k < 2 && !st; k++)
        st = an_injury_evaluate_as(h5, c->stage[k], -1, &row[k], &n[k], &used, &d, err);
    if (!st && n[0] + n[1] > 0 && !(c->crit = calloc((size_t)(n[0] + n[1]), sizeof *c->crit)))
        st = MCS_ERR(err, MCS_ERR_NOMEM, "compare: out of memory");
    for (int k = 0; k < 2 && !st; k++)
        for (int i = 0; i < n[k]; i++) {
            const an_injury_row *w = &row[k][i];
            int j = 0;
            while (j < c->ncrit && strcmp(c->crit[j].key, w->key) != 0) j++;
            tr_stage_criterion *x = &c->crit[j];
            if (j == c->ncrit) {
                c->ncrit++;
                snprintf(x->key, sizeof x->key, "%s", w->key);
                snprintf(x->label, sizeof x->label, "%s", w->label);
                snprintf(x->unit, sizeof x->unit, "%s", w->unit);
                x->limit = w->limit;
                x->value[0] = x->value[1] = x->fraction[0] = x->fraction[1] = NAN;
            }
            x->value[k] = w->value;
            x->fraction[k] = w->fraction;
        }
    free(row[0]);
    free(row[1]);
    return st;
}

mcs_status tr_compare_stages(const char *h5, int a, int b, tr_stage_compare *out,
                             mcs_error *err)
{
    memset(out, 0, sizeof *out);
    out->stage[0] = a, out->stage[1] = b;
    mcs_results *f = NULL;
    mcs_status st = mcs_results_open(&f, h5, err);
    for (int k = 0; k < 2 && !st; k++) {
        char g[32];
        snprintf(g, sizeof g, "/stage%d", out->stage[k]);
        if (mcs_results_kind(f, g) != MCS_RES_GROUP)
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: no %s", h5, g);
    }
    int cap = 0;
    if (!st) st = channels(f, h5, out, &cap, err);
    if (!st) st = bodies(f, h5, out, &cap, err);
    mcs_results_close(&f);
    if (!st && out->nrating == 0)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: /stage%d and /stage%d share no channel and no body",
                     h5, a, b);
    if (!st) st = criteria(h5, out, err);
    if (st) tr_stage_compare_free(out);
    return st;
}

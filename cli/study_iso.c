/* study_iso.c: the iso13232 design of `mcrash study`: impact configurations in ISO 13232's code
 * format "OMH-VO/VM" (O the opponent's contact point code, M the motorcycle's, H the relative
 * heading code, VO/VM the opponent's and the motorcycle's speeds in m/s; "413-0/13.4") from the
 * code tables the study file gives: each code's point or angle is the study file's, not the
 * standard's (docs/contracts.md "Studies"). Each configuration sets the impact: block's keys
 * (docs/models.md "Placing and speeding the vehicles") and impact.code. */
#include "cli/study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ISO_MAXCODE 10

/* the keys a configuration sets, the design's factors in this order */
static const char *const iso_path[9] = {
    "impact.opponent_contact[0]",   "impact.opponent_contact[1]",
    "impact.opponent_contact[2]",   "impact.motorcycle_contact[0]",
    "impact.motorcycle_contact[1]", "impact.motorcycle_contact[2]",
    "impact.heading_angle",         "impact.opponent_speed",
    "impact.motorcycle_speed"};

typedef struct {
    int n, code[ISO_MAXCODE];
    double v[ISO_MAXCODE][3]; /* point [m] (3) or angle [rad] (1) */
} iso_table;

static int fail(const mcs_node *at, const char *fmt, const char *a)
{
    mcs_error err = {0};
    char what[512];
    snprintf(what, sizeof what, fmt, a ? a : "");
    mcs_node_error(at, &err, MCS_ERR_KEY, "%s", what);
    fprintf(stderr, "%s\n", err.msg);
    return 2;
}

/* a code table: a list of {code: D, point: [x, y, z]} (factor first: its three keys) or of
 * {code: D, angle: A} (factor first: the heading) */
static int read_table(study *s, const mcs_node *d, const char *key, int first, int npt,
                      iso_table *t)
{
    const mcs_node *l = mcs_node_get(d, key);
    const char *vk = npt == 3 ? "point" : "angle";
    t->n = mcs_node_len(l);
    if (mcs_node_kind(l) != MCS_NODE_SEQ || t->n < 1 || t->n > ISO_MAXCODE)
        return fail(l ? l : d, "study.design.%s: a list of 1..10 {code: D, ...}", key);
    for (int i = 0; i < t->n; i++) {
        const mcs_node *e = mcs_node_at(l, i), *c = mcs_node_get(e, "code");
        const mcs_node *v = mcs_node_get(e, vk);
        double cd = mcs_node_num(c);
        if (mcs_node_kind(e) != MCS_NODE_MAP || mcs_node_len(e) != 2 || !v ||
            mcs_node_kind(c) != MCS_NODE_NUM || !(cd >= 0 && cd <= 9 && cd == floor(cd)))
            return fail(e, npt == 3 ? "study.design.%s: each entry {code: 0..9, point: [x, y, z]}"
                                    : "study.design.%s: each entry {code: 0..9, angle: A}",
                        key);
        t->code[i] = (int)cd;
        for (int q = 0; q < i; q++)
            if (t->code[q] == t->code[i]) return fail(c, "study.design.%s: code given twice", key);
        if (npt == 3 && (mcs_node_kind(v) != MCS_NODE_SEQ || mcs_node_len(v) != 3))
            return fail(v, "study.design.%s: point: expected [x, y, z]", key);
        for (int k = 0; k < npt; k++)
            if (study_level_si(s, &s->f[first + k], npt == 3 ? mcs_node_at(v, k) : v, 0,
                               &t->v[i][k]))
                return 2;
    }
    return 0;
}

static int find_code(const iso_table *t, int code)
{
    for (int i = 0; i < t->n; i++)
        if (t->code[i] == code) return i;
    return -1;
}

/* one row: the tables' entries o, m, h and the speeds (vo, vm) [m/s] */
static void set_row(study *s, long r, const iso_table *t, const int *ix, double vo, double vm)
{
    double *x = s->x + r * s->nfactor;
    for (int k = 0; k < 3; k++)
        x[k] = t[0].v[ix[0]][k], x[3 + k] = t[1].v[ix[1]][k];
    x[6] = t[2].v[ix[2]][0], x[7] = vo, x[8] = vm;
    int n = snprintf(s->code[r], STUDY_CODE, "%d%d%d-%.6g/%.6g", t[0].code[ix[0]],
                     t[1].code[ix[1]], t[2].code[ix[2]], vo, vm);
    (void)n; /* at most 3 + 2 + 2 x 13 characters */
}

/* configurations: ["413-0/13.4", ...]: each code's digits from the tables, its speeds in m/s */
static int listed_rows(study *s, const mcs_node *l, const iso_table *t)
{
    s->nrow = mcs_node_len(l);
    if (mcs_node_kind(l) != MCS_NODE_SEQ || s->nrow < 1)
        return fail(l, "study.design.configurations: a list of codes \"413-0/13.4\"", NULL);
    s->x = calloc((size_t)s->nrow * s->nfactor, sizeof *s->x);
    s->code = calloc((size_t)s->nrow, sizeof *s->code);
    if (!s->x || !s->code) return 2;
    for (long r = 0; r < s->nrow; r++) {
        const mcs_node *c = mcs_node_at(l, (int)r);
        const char *txt = mcs_node_text(c);
        char tail;
        double v[2];
        int d[3], ix[3];
        int n = txt ? sscanf(txt, "%1d%1d%1d-%lf/%lf%c", d, d + 1, d + 2, v, v + 1, &tail) : 0;
        if (n != 5) return fail(c, "study.design.configurations: '%s': expected a code "
                                   "OMH-VO/VM such as \"413-0/13.4\"", txt);
        static const char *const what[3] = {"opponent contact", "motorcycle contact", "heading"};
        for (int k = 0; k < 3; k++)
            if (d[k] < 0 || (ix[k] = find_code(&t[k], d[k])) < 0)
                return fail(c, "study.design.configurations: a code the %s table lacks", what[k]);
        for (int k = 0; k < 2; k++) {
            study_factor f = s->f[7 + k];
            f.at = c; /* a speed its key refuses: at the code */
            if (study_level_si(s, &f, NULL, v[k], &v[k])) return 2;
        }
        set_row(s, r, t, ix, v[0], v[1]);
    }
    return 0;
}

/* every combination: opponent contact, motorcycle contact, heading, speeds, the last fastest */
static int all_rows(study *s, const mcs_node *d, const iso_table *t)
{
    const mcs_node *sp = mcs_node_get(d, "speeds");
    int ns = mcs_node_len(sp);
    if (mcs_node_kind(sp) != MCS_NODE_SEQ || ns < 1)
        return fail(sp ? sp : d, "study.design.speeds: a list of [opponent, motorcycle] speeds",
                    NULL);
    double (*v)[2] = calloc((size_t)ns, sizeof *v);
    for (int i = 0; v && i < ns; i++) {
        const mcs_node *p = mcs_node_at(sp, i);
        if (mcs_node_kind(p) != MCS_NODE_SEQ || mcs_node_len(p) != 2) {
            free(v);
            return fail(p, "study.design.speeds: each entry [opponent, motorcycle]", NULL);
        }
        for (int k = 0; k < 2; k++)
            if (study_level_si(s, &s->f[7 + k], mcs_node_at(p, k), 0, &v[i][k])) {
                free(v);
                return 2;
            }
    }
    s->nrow = (long)t[0].n * t[1].n * t[2].n * ns;
    s->x = calloc((size_t)s->nrow * s->nfactor, sizeof *s->x);
    s->code = calloc((size_t)s->nrow, sizeof *s->code);
    long r = 0;
    for (int o = 0; v && s->x && s->code && o < t[0].n; o++)
        for (int m = 0; m < t[1].n; m++)
            for (int h = 0; h < t[2].n; h++)
                for (int i = 0; i < ns; i++)
                    set_row(s, r++, t, (int[3]){o, m, h}, v[i][0], v[i][1]);
    free(v);
    return s->x && s->code ? 0 : 2;
}

int study_iso_rows(study *s, const mcs_node *d)
{
    s->nfactor = 9;
    s->f = calloc(9, sizeof *s->f);
    if (!s->f) return 2;
    for (int j = 0; j < 9; j++) {
        snprintf(s->f[j].path, sizeof s->f[j].path, "%s", iso_path[j]);
        s->f[j].at = d;
        s->f[j].lo = s->f[j].hi = s->f[j].base = NAN;
    }
    iso_table t[3];
    if (read_table(s, d, "opponent_contacts", 0, 3, &t[0]) ||
        read_table(s, d, "motorcycle_contacts", 3, 3, &t[1]) ||
        read_table(s, d, "headings", 6, 1, &t[2]))
        return 2;
    const mcs_node *l = mcs_node_get(d, "configurations");
    return l ? listed_rows(s, l, t) : all_rows(s, d, t);
}

/* study_load.c: a study file read into its base scenario, factors (levels in SI, converted by
 * the scenario's own schema at each factor's key), cases and responses; every case's scenario
 * is built and validated before any run, so a bad factor, level or response exits 2 with its
 * FILE:LINE:COL (docs/contracts.md "Studies") */
#include "analysis/an_doe.h"
#include "analysis/an_limits.h"
#include "cli/study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define STUDY_MAXCASE 100000

static int fail(const mcs_node *at, const char *fmt, const char *a, const char *b)
{
    mcs_error err = {0};
    char what[512];
    snprintf(what, sizeof what, fmt, a ? a : "", b ? b : "");
    mcs_node_error(at, &err, MCS_ERR_KEY, "%s", what);
    fprintf(stderr, "%s\n", err.msg);
    return 2;
}

static int print_err(const mcs_error *err)
{
    fprintf(stderr, "%s\n", err->msg);
    return mcs_status_exit_code(err->status);
}

/* a key of a map from an allowed list (one of "a|b|c"): an unknown key fails */
static int check_keys(const mcs_node *map, const char *what, const char *allowed)
{
    for (int i = 0; i < mcs_node_len(map); i++) {
        const char *k = mcs_node_key(map, i);
        char pat[256];
        snprintf(pat, sizeof pat, "|%s|", allowed);
        char key[128];
        snprintf(key, sizeof key, "|%s|", k);
        if (!strstr(pat, key))
            return fail(mcs_node_at(map, i), "%s: unknown key '%s'", what, k);
    }
    return 0;
}

/* SI value of a level node (or num when v is NULL) at the factor's key: the base scenario with
 * that value set and validated again */
int study_level_si(study *s, const study_factor *f, const mcs_node *v, double num, double *out)
{
    mcs_scn_setting set = {.path = f->path, .value = v, .num = num, .at = f->at};
    mcs_scenario *c = NULL;
    mcs_error err = {0};
    if (mcs_scenario_set(s->base, &set, 1, &c, &err)) return print_err(&err);
    const mcs_node *n = mcs_scenario_find(mcs_scenario_root(c), f->path);
    int ok = mcs_node_kind(n) == MCS_NODE_NUM;
    *out = mcs_node_num(n);
    mcs_scenario_destroy(&c);
    if (!ok)
        return fail(v ? v : f->at, "%s: a factor level must be a number or a quantity", f->path,
                    NULL);
    return 0;
}

static int read_factor(study *s, const mcs_node *fn, study_factor *f)
{
    if (mcs_node_kind(fn) != MCS_NODE_MAP)
        return fail(fn, "study.factors: each factor is a map {path, levels | range}", NULL, NULL);
    if (check_keys(fn, "study.factors", "path|levels|range")) return 2;
    const mcs_node *p = mcs_node_get(fn, "path"), *lv = mcs_node_get(fn, "levels"),
                   *rg = mcs_node_get(fn, "range");
    if (!mcs_node_str(p)) return fail(fn, "study.factors: path: a key path is missing", NULL, NULL);
    if (strlen(mcs_node_str(p)) >= sizeof f->path)
        return fail(p, "study.factors: path too long", NULL, NULL);
    snprintf(f->path, sizeof f->path, "%s", mcs_node_str(p));
    f->at = p;
    f->lo = f->hi = f->base = NAN;
    if (rg) {
        if (mcs_node_kind(rg) != MCS_NODE_SEQ || mcs_node_len(rg) != 2)
            return fail(rg, "%s: range: expected [low, high]", f->path, NULL);
        if (study_level_si(s, f, mcs_node_at(rg, 0), 0, &f->lo) ||
            study_level_si(s, f, mcs_node_at(rg, 1), 0, &f->hi))
            return 2;
        if (!(f->hi > f->lo)) return fail(rg, "%s: range: high must exceed low", f->path, NULL);
        int n = lv ? (int)mcs_node_num(lv) : 2;
        if (lv && (mcs_node_kind(lv) != MCS_NODE_NUM || n < 2 || n != mcs_node_num(lv) || n > 1000))
            return fail(lv, "%s: levels: with a range, the number of levels (2..1000)", f->path, 0);
        f->nlev = n;
        f->lev = calloc((size_t)n, sizeof *f->lev);
        for (int i = 0; f->lev && i < n; i++)
            f->lev[i] = f->lo + (f->hi - f->lo) * i / (n - 1);
        if (f->lev) f->lev[n - 1] = f->hi;
        return f->lev ? 0 : 2;
    }
    if (mcs_node_kind(lv) != MCS_NODE_SEQ || mcs_node_len(lv) < 1)
        return fail(lv ? lv : fn, "%s: levels: expected a list of values, or range: [low, high]",
                    f->path, NULL);
    f->nlev = mcs_node_len(lv);
    f->lev = calloc((size_t)f->nlev, sizeof *f->lev);
    for (int i = 0; f->lev && i < f->nlev; i++)
        if (study_level_si(s, f, mcs_node_at(lv, i), 0, &f->lev[i])) return 2;
    f->lo = f->hi = f->lev ? f->lev[0] : NAN;
    for (int i = 0; f->lev && i < f->nlev; i++)
        f->lo = fmin(f->lo, f->lev[i]), f->hi = fmax(f->hi, f->lev[i]);
    return f->lev ? 0 : 2;
}

static int known_criterion(const char *name)
{
    int n;
    const an_limit *t = an_limits_table(&n);
    for (int i = 0; i < n; i++)
        if (!strcasecmp(name, t[i].key) || !strcasecmp(name, t[i].label)) return 1;
    return !strcasecmp(name, "pelvis_a3ms") || !strcasecmp(name, "Pelvis a3ms");
}

static int read_response(const mcs_node *rn, study_response *r)
{
    const mcs_node *v = rn, *nm = NULL;
    if (mcs_node_kind(rn) == MCS_NODE_MAP) {
        if (check_keys(rn, "study.responses", "name|value")) return 2;
        v = mcs_node_get(rn, "value"), nm = mcs_node_get(rn, "name");
    }
    const char *spec = mcs_node_str(v);
    if (!spec || strlen(spec) >= sizeof r->spec || (nm && !mcs_node_str(nm)))
        return fail(v ? v : rn, "study.responses: expected a criterion, \"peak:/stageN/channels/"
                    "NAME\", a dataset path, or {name: N, value: ...}", NULL, NULL);
    snprintf(r->spec, sizeof r->spec, "%s", spec);
    r->at = v;
    static const struct { const char *pre; study_rkind k; } pre[] = {
        {"peak:", STUDY_R_PEAK}, {"max:", STUDY_R_MAX}, {"min:", STUDY_R_MIN}};
    r->kind = STUDY_R_INJURY;
    r->target = r->spec;
    for (int i = 0; i < 3; i++)
        if (!strncmp(r->spec, pre[i].pre, strlen(pre[i].pre)))
            r->kind = pre[i].k, r->target = r->spec + strlen(pre[i].pre);
    if (r->kind == STUDY_R_INJURY && r->spec[0] == '/') r->kind = STUDY_R_SCALAR;
    if (r->kind != STUDY_R_INJURY && (r->target[0] != '/' || strstr(r->target, "//")))
        return fail(v, "study.responses: '%s': expected an absolute dataset path /stageN/...",
                    r->spec, NULL);
    if (r->kind == STUDY_R_INJURY && !known_criterion(r->spec))
        return fail(v, "study.responses: '%s' is no injury criterion (`mcrash injury` lists them)",
                    r->spec, NULL);
    /* the default name: the spec with the dataset path's slashes as dots */
    const char *name = nm ? mcs_node_str(nm) : r->spec;
    if (strlen(name) >= sizeof r->name || strchr(nm ? name : "", '/') || !*name)
        return fail(nm ? nm : v, "study.responses: name '%s': 1..127 characters, no '/'", name, 0);
    char *o = r->name;
    for (const char *c = name; *c; c++) {
        if (*c == '/' && (c == r->target || c[-1] == ':')) continue;
        *o++ = *c == '/' ? '.' : *c;
    }
    *o = 0;
    return 0;
}

static int read_design(study *s, const mcs_node *d, const char ***gen, int *ngen, int *res)
{
    const char *t = mcs_node_str(mcs_node_get(d, "type"));
    if (mcs_node_kind(d) != MCS_NODE_MAP || !t)
        return fail(d, "study.design: expected {type: full_factorial | fractional_factorial | "
                    "latin_hypercube | one_at_a_time | iso13232, ...}", NULL, NULL);
    static const char *names[] = {"full_factorial", "fractional_factorial", "latin_hypercube",
                                  "one_at_a_time", "iso13232"};
    int k = 0;
    while (k < 5 && strcmp(t, names[k])) k++;
    if (k == 5)
        return fail(mcs_node_get(d, "type"), "study.design.type: unknown design '%s'", t, NULL);
    s->design = (study_design)k;
    s->design_name = names[k];
    if (check_keys(d, "study.design",
                   k == 1   ? "type|resolution|generators"
                   : k == 2 ? "type|samples|seed"
                   : k == 4 ? "type|opponent_contacts|motorcycle_contacts|headings|speeds|"
                              "configurations"
                            : "type"))
        return 2;
    const mcs_node *sm = mcs_node_get(d, "samples"), *sd = mcs_node_get(d, "seed");
    const mcs_node *rs = mcs_node_get(d, "resolution"), *gn = mcs_node_get(d, "generators");
    if (k == 2) {
        double n = mcs_node_num(sm), seed = sd ? mcs_node_num(sd) : 1;
        if (!(n >= 2 && n <= STUDY_MAXCASE && n == floor(n)))
            return fail(sm ? sm : d, "study.design.samples: the number of cases, 2..100000", 0, 0);
        if (!(seed >= 0 && seed < 9007199254740992.0 && seed == floor(seed)))
            return fail(sd, "study.design.seed: an integer 0..2^53", NULL, NULL);
        s->ncase = (long)n;
        s->seed = (uint64_t)seed;
    }
    if (k == 1) {
        if (!rs == !gn)
            return fail(d, "study.design: fractional_factorial takes resolution: R or "
                        "generators: [\"D=ABC\", ...]", NULL, NULL);
        *res = rs ? (int)mcs_node_num(rs) : 0;
        if (rs && (*res < 3 || *res != mcs_node_num(rs)))
            return fail(rs, "study.design.resolution: an integer >= 3", NULL, NULL);
        *ngen = mcs_node_len(gn);
        *gen = calloc((size_t)*ngen + 1, sizeof **gen);
        for (int i = 0; *gen && i < *ngen; i++)
            if (!((*gen)[i] = mcs_node_str(mcs_node_at(gn, i))))
                return fail(mcs_node_at(gn, i), "study.design.generators: strings \"D=ABC\"", 0, 0);
        if (gn && (mcs_node_kind(gn) != MCS_NODE_SEQ || !*ngen))
            return fail(gn, "study.design.generators: a list of \"D=ABC\"", NULL, NULL);
    }
    return 0;
}

/* full factorial: every combination of levels, the first factor fastest */
static int cases_full(study *s, const mcs_node *d)
{
    int k = s->nfactor, *nlev = calloc((size_t)k, sizeof *nlev), *idx;
    long cap = 1;
    for (int j = 0; nlev && j < k; j++)
        nlev[j] = s->f[j].nlev;
    for (int j = 0; nlev && j < k && cap <= STUDY_MAXCASE; j++)
        cap *= nlev[j];
    if (!nlev || cap > STUDY_MAXCASE) {
        free(nlev);
        return fail(d, "study.design: more than %s cases", "100000", NULL);
    }
    idx = calloc((size_t)cap * k, sizeof *idx);
    s->x = calloc((size_t)cap * k, sizeof *s->x);
    s->ncase = idx && s->x ? an_doe_full(k, nlev, idx, cap) : 0;
    for (long c = 0; c < s->ncase; c++)
        for (int j = 0; j < k; j++)
            s->x[c * k + j] = s->f[j].lev[idx[c * k + j]];
    free(nlev), free(idx);
    return 0;
}

/* 2-level fractional factorial from generators, or the standard ones of a resolution */
static int cases_fractional(study *s, const mcs_node *d, const char **gen, int ngen, int res)
{
    int k = s->nfactor;
    char why[256];
    for (int j = 0; j < k; j++)
        if (s->f[j].nlev != 2)
            return fail(s->f[j].at, "%s: a fractional factorial takes 2 levels per factor",
                        s->f[j].path, NULL);
    const char *std[4];
    if (res) {
        if (!an_doe_standard(k, res, std, &ngen)) {
            snprintf(why, sizeof why, "%d", k);
            return fail(d, "study.design.resolution: the standard table (3..8 factors, "
                        "Montgomery Table 8.14) has no design of this resolution for %s "
                        "factors: give generators:", why, NULL);
        }
        gen = std;
    }
    long cap = 1L << 20;
    int *sign = calloc((size_t)cap, sizeof *sign);
    s->ncase = sign ? an_doe_fractional(k, ngen, gen, sign, cap / k, why, sizeof why) : -1;
    if (s->ncase < 0) {
        free(sign);
        const mcs_node *g = mcs_node_get(d, "generators");
        return fail(g ? g : d, "study.design.generators: %s", why, NULL);
    }
    s->x = calloc((size_t)s->ncase * k, sizeof *s->x);
    for (long c = 0; s->x && c < s->ncase; c++)
        for (int j = 0; j < k; j++)
            s->x[c * k + j] = s->f[j].lev[sign[c * k + j] > 0];
    free(sign);
    return 0;
}

/* Latin hypercube over each factor's range */
static int cases_lhs(study *s)
{
    int k = s->nfactor;
    for (int j = 0; j < k; j++)
        if (!(s->f[j].hi > s->f[j].lo))
            return fail(s->f[j].at, "%s: a Latin hypercube takes range: [low, high]",
                        s->f[j].path, NULL);
    s->x = calloc((size_t)s->ncase * k, sizeof *s->x);
    if (s->x) an_doe_lhs((int)s->ncase, k, s->seed, s->x);
    for (long c = 0; s->x && c < s->ncase; c++)
        for (int j = 0; j < k; j++)
            s->x[c * k + j] = s->f[j].lo + (s->f[j].hi - s->f[j].lo) * s->x[c * k + j];
    return 0;
}

/* one at a time: the base case, then each factor's other levels, the rest at base */
static int cases_oat(study *s)
{
    int k = s->nfactor;
    long n = 1;
    for (int j = 0; j < k; j++) {
        const mcs_node *b = mcs_scenario_find(mcs_scenario_root(s->base), s->f[j].path);
        s->f[j].base = mcs_node_kind(b) == MCS_NODE_NUM ? mcs_node_num(b) : s->f[j].lev[0];
        for (int l = 0; l < s->f[j].nlev; l++)
            n += s->f[j].lev[l] != s->f[j].base;
    }
    s->x = calloc((size_t)n * k, sizeof *s->x);
    s->ncase = 0;
    for (int j = -1; s->x && j < k; j++)
        for (int l = 0; l < (j < 0 ? 1 : s->f[j].nlev); l++) {
            if (j >= 0 && s->f[j].lev[l] == s->f[j].base) continue;
            for (int q = 0; q < k; q++)
                s->x[s->ncase * k + q] = q == j ? s->f[j].lev[l] : s->f[q].base;
            s->ncase++;
        }
    return 0;
}

/* the cases of the design: s->x (ncase x nfactor) in SI */
static int make_cases(study *s, const mcs_node *d, const char **gen, int ngen, int res)
{
    int rc = s->design == STUDY_FULL         ? cases_full(s, d)
             : s->design == STUDY_FRACTIONAL ? cases_fractional(s, d, gen, ngen, res)
             : s->design == STUDY_LHS        ? cases_lhs(s)
             : s->design == STUDY_OAT        ? cases_oat(s)
                                             : 0;
    if (rc) return rc;
    if (s->design != STUDY_ISO13232) s->nrow = s->ncase;
    if (!s->x || s->nrow < 1) return fail(d, "study.design: no cases (out of memory?)", 0, 0);
    /* compare: each row twice, the scenario's case then the compared one's */
    s->ncase = s->nrow * s->nvar;
    if (s->nvar == 1) return 0;
    int k = s->nfactor;
    double *x = calloc((size_t)s->ncase * k, sizeof *x);
    if (!x) return 2;
    for (long c = 0; c < s->ncase; c++)
        memcpy(x + c * k, s->x + c / s->nvar * k, (size_t)k * sizeof *x);
    free(s->x);
    s->x = x;
    return 0;
}

mcs_status study_case_scenario(const study *s, long c, mcs_scenario **out, mcs_error *err)
{
    int n = s->nset;
    mcs_scn_setting *set = calloc((size_t)n + s->nfactor + 1, sizeof *set);
    if (!set) return MCS_ERR(err, MCS_ERR_NOMEM, "error: out of memory");
    if (n) memcpy(set, s->set, (size_t)n * sizeof *set);
    for (int j = 0; j < s->nfactor; j++)
        set[n++] = (mcs_scn_setting){.path = s->f[j].path, .num = s->x[c * s->nfactor + j],
                                     .at = s->f[j].at};
    if (s->code)
        set[n++] = (mcs_scn_setting){.path = "impact.code", .str = s->code[c / s->nvar],
                                     .at = s->f[0].at};
    mcs_status st = mcs_scenario_set(s->nvar == 2 && c % 2 ? s->alt : s->base, set, n, out, err);
    free(set);
    return st;
}

/* a scenario named in the study file, relative to it */
static int load_scenario(const char *path, const mcs_node *sc, const char *key, char *file,
                         size_t nfile, mcs_scenario **out)
{
    const char *p = mcs_node_str(sc);
    if (!p) return fail(sc, "study.%s: a scenario file is missing", key, NULL);
    const char *slash = strrchr(path, '/');
    if (p[0] == '/' || !slash)
        snprintf(file, nfile, "%s", p);
    else
        snprintf(file, nfile, "%.*s/%s", (int)(slash - path), path, p);
    mcs_error err = {0};
    if (mcs_scenario_load(file, out, &err)) return print_err(&err);
    return 0;
}

/* the base scenario, the compared one (compare:) and the settings of every case (set:) */
static int load_base(study *s, const char *path, const mcs_node *st)
{
    const mcs_node *sc = mcs_node_get(st, "scenario"), *cmp = mcs_node_get(st, "compare");
    const mcs_node *set = mcs_node_get(st, "set");
    if (load_scenario(path, sc, "scenario", s->scenario, sizeof s->scenario, &s->base)) return 2;
    s->nvar = cmp ? 2 : 1;
    if (cmp && load_scenario(path, cmp, "compare", s->alt_path, sizeof s->alt_path, &s->alt))
        return 2;
    if (!set) return 0;
    if (mcs_node_kind(set) != MCS_NODE_MAP || mcs_node_len(set) < 1)
        return fail(set, "study.set: a map {key.path: value, ...}", NULL, NULL);
    s->nset = mcs_node_len(set);
    s->set = calloc((size_t)s->nset, sizeof *s->set);
    for (int i = 0; s->set && i < s->nset; i++)
        s->set[i] = (mcs_scn_setting){.path = mcs_node_key(set, i),
                                      .value = mcs_node_at(set, i), .at = mcs_node_at(set, i)};
    return s->set ? 0 : 2;
}

static int read_study(study *s, const char *path, const mcs_node *st, const char ***gen,
                      int *ngen, int *res)
{
    if (mcs_node_kind(st) != MCS_NODE_MAP)
        return fail(mcs_scenario_root(s->file), "study: the file's top-level study: map is "
                    "missing", NULL, NULL);
    if (check_keys(st, "study", "scenario|compare|set|stage|design|factors|responses")) return 2;
    if (load_base(s, path, st)) return 2;
    const mcs_node *sg = mcs_node_get(st, "stage");
    snprintf(s->stage, sizeof s->stage, "1");
    if (sg) {
        const char *t = mcs_node_text(sg);
        if (!t || (strcmp(t, "1") && strcmp(t, "2") && strcmp(t, "3") && strcmp(t, "all") &&
                   strcmp(t, "rom")))
            return fail(sg, "study.stage: 1, 2, 3, all or rom", NULL, NULL);
        snprintf(s->stage, sizeof s->stage, "%s", t);
    }
    const mcs_node *dn = mcs_node_get(st, "design");
    if (!dn) /* the error at the study: block, not at a node that is not there */
        return fail(st, "study.design: missing (expected {type: full_factorial | ...})", 0, 0);
    if (read_design(s, dn, gen, ngen, res)) return 2;
    const mcs_node *fs = mcs_node_get(st, "factors"), *rs = mcs_node_get(st, "responses");
    if (s->design == STUDY_ISO13232 && fs)
        return fail(fs, "study.factors: the iso13232 design sets the impact: keys itself", 0, 0);
    if (s->design == STUDY_ISO13232 && study_iso_rows(s, mcs_node_get(st, "design"))) return 2;
    s->nfactor = s->design == STUDY_ISO13232 ? s->nfactor : mcs_node_len(fs);
    if (s->design != STUDY_ISO13232 &&
        (mcs_node_kind(fs) != MCS_NODE_SEQ || s->nfactor < 1 || s->nfactor > AN_DOE_MAXFACTOR))
        return fail(fs ? fs : st, "study.factors: a list of 1..26 factors", NULL, NULL);
    s->nresp = mcs_node_len(rs);
    if (mcs_node_kind(rs) != MCS_NODE_SEQ || s->nresp < 1 || s->nresp > STUDY_MAXRESP)
        return fail(rs ? rs : st, "study.responses: a list of 1..64 responses", NULL, NULL);
    if (!s->f) s->f = calloc((size_t)s->nfactor, sizeof *s->f);
    s->r = calloc((size_t)s->nresp, sizeof *s->r);
    if (!s->f || !s->r) return 2;
    for (int j = 0; s->design != STUDY_ISO13232 && j < s->nfactor; j++) {
        if (read_factor(s, mcs_node_at(fs, j), &s->f[j])) return 2;
        for (int q = 0; q < j; q++)
            if (!strcmp(s->f[q].path, s->f[j].path))
                return fail(s->f[j].at, "study.factors: '%s' given twice", s->f[j].path, 0);
    }
    for (int i = 0; i < s->nresp; i++) {
        if (read_response(mcs_node_at(rs, i), &s->r[i])) return 2;
        for (int q = 0; q < i; q++)
            if (!strcmp(s->r[q].name, s->r[i].name))
                return fail(s->r[i].at, "study.responses: the name '%s' is given twice",
                            s->r[i].name, NULL);
    }
    return 0;
}

int study_load(const char *path, study *s)
{
    memset(s, 0, sizeof *s);
    mcs_error err = {0};
    if (mcs_yaml_load(path, &s->file, &err)) return print_err(&err);
    const char **gen = NULL;
    int ngen = 0, res = 0;
    const mcs_node *st = mcs_node_get(mcs_scenario_root(s->file), "study");
    int rc = read_study(s, path, st, &gen, &ngen, &res);
    if (!rc) rc = make_cases(s, mcs_node_get(st, "design"), gen, ngen, res);
    free(gen);
    /* every case's scenario, validated before any run */
    for (long c = 0; !rc && c < s->ncase; c++) {
        mcs_scenario *cs = NULL;
        if (study_case_scenario(s, c, &cs, &err)) rc = print_err(&err);
        mcs_scenario_destroy(&cs);
    }
    return rc ? 2 : 0;
}

void study_free(study *s)
{
    for (int j = 0; s->f && j < s->nfactor; j++)
        free(s->f[j].lev);
    free(s->f), free(s->r), free(s->x), free(s->code), free(s->set);
    mcs_scenario_destroy(&s->base);
    mcs_scenario_destroy(&s->alt);
    mcs_scenario_destroy(&s->file);
    memset(s, 0, sizeof *s);
}

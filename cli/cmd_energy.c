/* cmd_energy.c: `mcrash energy OUT.h5 [--stage N] [--group G] [--json]`: the energy balance of a
 * group of bodies (the rider) and the energy it transferred to each contact partner, ranked by
 * category (the 2023 paper's Eq. 9 and Fig. 24b), at the last output time; then the restraints'
 * own energies (/stageN/parts, retractor, slipring, airbag). Layout: docs/contracts.md
 * (/stageN/energy_groups). */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "core/mcs_results.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EN_NSERIES 5
static const char *const series[EN_NSERIES] = {"kinetic", "potential", "internal", "contact_total",
                                               "total"};

typedef struct {
    char name[128];
    char cat[32];
    double e; /* at the last row [J] */
} en_item;

typedef struct {
    char kind[16]; /* part | retractor | slipring | airbag */
    char name[128];
    double v[5]; /* part: kinetic, internal (+ hourglass), contact, dissipated, -;
                    retractor: limiter, pretensioner; slipring: friction; airbag: gas work
                    on the fabric, int (p - p0) dV [J]                                     */
} en_restraint;

typedef struct {
    const char *file;
    int stage;
    char group[128];
    double t_end;
    double first[EN_NSERIES], last[EN_NSERIES], worst; /* worst |total - total0| [J] */
    en_item *partner, cat[16];
    int npartner, ncat;
    en_restraint *rx;
    int nrx;
} en_report;

/* the value at the last row of a dataset (and the first into *first when not NULL) */
static int last_of(mcs_results *r, const char *path, double *first, double *last)
{
    mcs_array a = {0};
    mcs_error e = {0};
    if (mcs_results_read(r, path, &a, &e) || a.n == 0) {
        mcs_array_free(&a);
        return -1;
    }
    size_t w = a.n / (a.dims[0] ? a.dims[0] : 1);
    if (first) *first = a.v[0];
    *last = a.v[a.n - w];
    mcs_array_free(&a);
    return 0;
}

static int find_stage(mcs_results *r, int stage)
{
    char p[64];
    for (int s = stage ? stage : 3; s >= (stage ? stage : 1); s--) {
        snprintf(p, sizeof p, "/stage%d/energy_groups", s);
        if (mcs_results_kind(r, p) == MCS_RES_GROUP) return s;
    }
    return 0;
}

static int read_balance(mcs_results *r, en_report *o)
{
    char p[256];
    for (int k = 0; k < EN_NSERIES; k++) {
        snprintf(p, sizeof p, "/stage%d/energy_groups/%s/%s", o->stage, o->group, series[k]);
        if (last_of(r, p, &o->first[k], &o->last[k])) return -1;
    }
    snprintf(p, sizeof p, "/stage%d/energy_groups/%s/total", o->stage, o->group);
    mcs_array a = {0};
    mcs_error e = {0};
    if (mcs_results_read(r, p, &a, &e)) return -1;
    o->worst = 0;
    for (size_t i = 0; i < a.n; i++)
        o->worst = fmax(o->worst, fabs(a.v[i] - a.v[0]));
    mcs_array_free(&a);
    snprintf(p, sizeof p, "/stage%d/time", o->stage);
    double t0;
    return last_of(r, p, &t0, &o->t_end);
}

static int by_energy(const void *a, const void *b)
{
    double x = ((const en_item *)a)->e, y = ((const en_item *)b)->e;
    return x < y ? 1 : x > y ? -1 : strcmp(((const en_item *)a)->name, ((const en_item *)b)->name);
}

static void add_category(en_report *o, const en_item *it)
{
    for (int c = 0; c < o->ncat; c++)
        if (strcmp(o->cat[c].name, it->cat) == 0) {
            o->cat[c].e += it->e;
            return;
        }
    if (o->ncat == (int)(sizeof o->cat / sizeof o->cat[0])) return;
    en_item *c = &o->cat[o->ncat++];
    snprintf(c->name, sizeof c->name, "%s", it->cat);
    c->e = it->e;
}

static int read_partners(mcs_results *r, en_report *o)
{
    char g[256], p[512];
    snprintf(g, sizeof g, "/stage%d/energy_groups/%s/contact", o->stage, o->group);
    char **names = NULL;
    int n = 0;
    mcs_error e = {0};
    if (mcs_results_kind(r, g) == MCS_RES_GROUP && mcs_results_list(r, g, &names, &n, &e))
        return -1;
    o->partner = calloc((size_t)(n ? n : 1), sizeof *o->partner);
    if (!o->partner) return -1;
    for (int i = 0; i < n; i++) {
        en_item *it = &o->partner[o->npartner];
        snprintf(p, sizeof p, "%s/%s", g, names[i]);
        if (last_of(r, p, NULL, &it->e)) continue;
        snprintf(it->name, sizeof it->name, "%s", names[i]);
        char *c = NULL;
        if (!mcs_results_attr_str(r, p, "category", &c, &e)) snprintf(it->cat, 32, "%s", c);
        free(c);
        add_category(o, it);
        o->npartner++;
    }
    mcs_results_list_free(&names, n);
    qsort(o->partner, (size_t)o->npartner, sizeof *o->partner, by_energy);
    qsort(o->cat, (size_t)o->ncat, sizeof *o->cat, by_energy);
    return 0;
}

static en_restraint *push_rx(en_report *o, const char *kind, const char *name)
{
    en_restraint *nr = realloc(o->rx, sizeof *nr * (size_t)(o->nrx + 1));
    if (!nr) return NULL;
    o->rx = nr;
    en_restraint *x = &o->rx[o->nrx++];
    memset(x, 0, sizeof *x);
    snprintf(x->kind, sizeof x->kind, "%s", kind);
    snprintf(x->name, sizeof x->name, "%s", name);
    return x;
}

/* the work of a force f over a length change dl: the trapezoid sum of -f dl (pay-in < 0) */
static double trapz_work(const mcs_array *f, const mcs_array *l, double sign)
{
    double w = 0;
    for (size_t i = 1; i < f->n && i < l->n; i++)
        w += sign * 0.5 * (f->v[i] + f->v[i - 1]) * (l->v[i] - l->v[i - 1]);
    return w;
}

static void read_device(mcs_results *r, en_report *o, const char *kind, const char *name)
{
    char p[512], q[512];
    mcs_array a = {0}, b = {0};
    mcs_error e = {0};
    en_restraint *x = push_rx(o, kind, name);
    if (!x) return;
    if (strcmp(kind, "retractor") == 0) {
        snprintf(p, sizeof p, "/stage%d/retractor/%s/energy_limiter", o->stage, name);
        last_of(r, p, NULL, &x->v[0]);
        snprintf(p, sizeof p, "/stage%d/retractor/%s/energy_pretensioner", o->stage, name);
        snprintf(q, sizeof q, "/stage%d/retractor/%s/payout_pretensioner", o->stage, name);
        if (last_of(r, p, NULL, &x->v[1])) { /* older files: from the channels */
            snprintf(p, sizeof p, "/stage%d/retractor/%s/force", o->stage, name);
            if (!mcs_results_read(r, p, &a, &e) && !mcs_results_read(r, q, &b, &e))
                x->v[1] = trapz_work(&a, &b, -1); /* pulled in (< 0) against the belt force */
        }
    } else if (strcmp(kind, "slipring") == 0) {
        snprintf(p, sizeof p, "/stage%d/slipring/%s/energy_friction", o->stage, name);
        last_of(r, p, NULL, &x->v[0]);
    } else { /* airbag: the structure's work on the gas -int (p - p0) dV, p0 the pressure at
                t = 0 (ambient: the fabric carries p - p_amb); the gas's enthalpy in and out,
                its internal energy change (fe/fe_gasbag.h) */
        snprintf(p, sizeof p, "/stage%d/airbag/%s/pressure", o->stage, name);
        snprintf(q, sizeof q, "/stage%d/airbag/%s/volume", o->stage, name);
        double w = 0;
        char pw[512];
        snprintf(pw, sizeof pw, "/stage%d/airbag/%s/work", o->stage, name);
        if (!mcs_results_read(r, p, &a, &e) && !mcs_results_read(r, q, &b, &e) && a.n && b.n) {
            const double p0 = a.v[0];
            if (!last_of(r, pw, NULL, &w)) { /* the gas's int p dV less p0 dV */
                x->v[0] = -(w - p0 * (b.v[b.n - 1] - b.v[0]));
            } else { /* older files: the trapezoid sum over the output rows */
                for (size_t i = 0; i < a.n; i++)
                    a.v[i] -= p0;
                x->v[0] = trapz_work(&a, &b, -1);
            }
        }
        static const char *const ch[3] = {"energy_in", "energy_vent", "energy_leak"};
        double v[3] = {0, 0, 0}, u0 = 0, u1 = 0;
        for (int k = 0; k < 3; k++) {
            snprintf(p, sizeof p, "/stage%d/airbag/%s/%s", o->stage, name, ch[k]);
            last_of(r, p, NULL, &v[k]);
        }
        snprintf(p, sizeof p, "/stage%d/airbag/%s/energy", o->stage, name);
        last_of(r, p, &u0, &u1);
        x->v[1] = v[0], x->v[2] = v[1] + v[2], x->v[3] = u1 - u0;
    }
    mcs_array_free(&a), mcs_array_free(&b);
}

static void read_restraints(mcs_results *r, en_report *o)
{
    static const char *const kinds[] = {"parts", "retractor", "slipring", "airbag"};
    static const char *const pk[4] = {"kinetic", "internal", "contact", "dissipated"};
    for (int k = 0; k < 4; k++) {
        char g[64], p[512];
        snprintf(g, sizeof g, "/stage%d/%s", o->stage, kinds[k]);
        char **names = NULL;
        int n = 0;
        mcs_error e = {0};
        if (mcs_results_kind(r, g) != MCS_RES_GROUP || mcs_results_list(r, g, &names, &n, &e))
            continue;
        for (int i = 0; i < n; i++) {
            if (k > 0) {
                read_device(r, o, kinds[k], names[i]);
                continue;
            }
            en_restraint *x = push_rx(o, "part", names[i]);
            for (int j = 0; x && j < 4; j++) {
                snprintf(p, sizeof p, "%s/%s/energy/%s", g, names[i], pk[j]);
                last_of(r, p, NULL, &x->v[j]);
            }
            double hg = 0;
            snprintf(p, sizeof p, "%s/%s/energy/hourglass", g, names[i]);
            if (x && !last_of(r, p, NULL, &hg)) x->v[1] += hg;
        }
        mcs_results_list_free(&names, n);
    }
}

static void print_table(const en_report *o)
{
    printf("%s, stage %d, group %s, t = %.4f s\n", o->file, o->stage, o->group, o->t_end);
    printf("%-16s %12s %12s   [J] (2023 paper Eq. 9)\n", "balance", "t = 0", "t end");
    for (int k = 0; k < EN_NSERIES; k++)
        printf("%-16s %12.4f %12.4f\n", series[k], o->first[k], o->last[k]);
    printf("closure: total - total(0) = %+.3g J at the end, %.3g J at most (%.2e of total(0))\n",
           o->last[4] - o->first[4], o->worst, o->worst / fmax(fabs(o->first[4]), 1e-300));
    printf("\ncontact energy by category (transferred to the partners, Fig. 24b)\n");
    printf("%-4s %-16s %12s %8s\n", "rank", "category", "energy [J]", "share");
    for (int c = 0; c < o->ncat; c++)
        printf("%-4d %-16s %12.3f %7.1f%%\n", c + 1, o->cat[c].name, o->cat[c].e,
               100 * o->cat[c].e / fmax(fabs(o->last[3]), 1e-300));
    printf("\npartners (non-zero)\n%-40s %-12s %12s\n", "partner", "category", "energy [J]");
    for (int i = 0; i < o->npartner; i++)
        if (o->partner[i].e != 0)
            printf("%-40s %-12s %12.3f\n", o->partner[i].name, o->partner[i].cat, o->partner[i].e);
    if (o->nrx == 0) return;
    printf("\nrestraints [J]\n  part: kinetic, internal + hourglass, contact, dissipated\n"
           "  retractor: limiter, pretensioner work\n  slipring: friction\n"
           "  airbag: work on the gas -int (p - p0) dV, inflator enthalpy in, enthalpy vented and"
           " leaked, gas internal energy change\n");
    for (int i = 0; i < o->nrx; i++) {
        const en_restraint *x = &o->rx[i];
        printf("%-10s %-24s", x->kind, x->name);
        int nv = strcmp(x->kind, "retractor") == 0 ? 2 : strcmp(x->kind, "slipring") == 0 ? 1 : 4;
        for (int j = 0; j < nv; j++)
            printf(" %12.3f", x->v[j]);
        printf("\n");
    }
}

static void json_items(const char *key, const en_item *it, int n, int with_cat)
{
    printf(", \"%s\": [", key);
    for (int i = 0; i < n; i++) {
        printf("%s{\"name\": ", i ? ", " : "");
        cli_json_string(it[i].name);
        if (with_cat) {
            printf(", \"category\": ");
            cli_json_string(it[i].cat);
        }
        printf(", \"energy\": %.10g}", it[i].e);
    }
    printf("]");
}

static void print_json(const en_report *o)
{
    printf("{\"file\": ");
    cli_json_string(o->file);
    printf(", \"stage\": %d, \"group\": ", o->stage);
    cli_json_string(o->group);
    printf(", \"time\": %.10g, \"balance\": {", o->t_end);
    for (int k = 0; k < EN_NSERIES; k++)
        printf("%s\"%s\": [%.10g, %.10g]", k ? ", " : "", series[k], o->first[k], o->last[k]);
    printf("}, \"closure_max\": %.10g", o->worst);
    json_items("categories", o->cat, o->ncat, 0);
    json_items("partners", o->partner, o->npartner, 1);
    printf(", \"restraints\": [");
    for (int i = 0; i < o->nrx; i++) {
        printf("%s{\"kind\": ", i ? ", " : "");
        cli_json_string(o->rx[i].kind);
        printf(", \"name\": ");
        cli_json_string(o->rx[i].name);
        printf(", \"values\": [%.10g, %.10g, %.10g, %.10g]}", o->rx[i].v[0], o->rx[i].v[1],
               o->rx[i].v[2], o->rx[i].v[3]);
    }
    printf("]}\n");
}

/* the report of file at stage (0: the highest with groups) for group (NULL: the first) */
static int report(const char *file, int stage, const char *group, en_report *o)
{
    mcs_results *r = NULL;
    mcs_error e = {0};
    if (mcs_results_open(&r, file, &e)) {
        fprintf(stderr, "mcrash energy: %s\n", e.msg);
        return 2;
    }
    int rc = 0;
    o->file = file;
    o->stage = find_stage(r, stage);
    char g[64], **names = NULL;
    int n = 0;
    snprintf(g, sizeof g, "/stage%d/energy_groups", o->stage);
    if (!o->stage || mcs_results_list(r, g, &names, &n, &e) || n == 0) {
        fprintf(stderr,
                "mcrash energy: %s: no /stage%s/energy_groups (a run with rider_* bodies "
                "writes /stageN/energy_groups/rider)\n",
                file, stage ? (char[]){(char)('0' + stage), 0} : "N");
        rc = 2;
    }
    for (int i = 0; !rc && i < n && !o->group[0]; i++)
        if (!group || strcmp(names[i], group) == 0) snprintf(o->group, 128, "%s", names[i]);
    if (!rc && !o->group[0]) {
        fprintf(stderr, "mcrash energy: %s: no group %s in %s\n", file, group, g);
        rc = 2;
    }
    mcs_results_list_free(&names, n);
    if (!rc && (read_balance(r, o) || read_partners(r, o))) {
        fprintf(stderr, "mcrash energy: %s: %s/%s is incomplete\n", file, g, o->group);
        rc = 2;
    }
    if (!rc) read_restraints(r, o);
    mcs_results_close(&r);
    return rc;
}

int cli_energy(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *file = NULL, *group = NULL;
    int stage = 0, json = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0) {
            json = 1;
        } else if (strcmp(argv[i], "--stage") == 0 && i + 1 < argc) {
            char *end = NULL;
            long s = strtol(argv[++i], &end, 10);
            if (*end || s < 1 || s > 3) {
                fprintf(stderr, "mcrash energy: --stage %s: 1, 2 or 3\n", argv[i]);
                return 2;
            }
            stage = (int)s;
        } else if (strcmp(argv[i], "--group") == 0 && i + 1 < argc) {
            group = argv[++i];
        } else if (argv[i][0] == '-' || file) {
            fprintf(stderr, "mcrash energy: unexpected argument %s\n", argv[i]);
            return cli_usage(argv[0]);
        } else {
            file = argv[i];
        }
    }
    if (!file) return cli_usage(argv[0]);
    en_report o;
    memset(&o, 0, sizeof o);
    int rc = report(file, stage, group, &o);
    if (!rc && json)
        print_json(&o);
    else if (!rc)
        print_table(&o);
    free(o.partner), free(o.rx);
    return rc;
}

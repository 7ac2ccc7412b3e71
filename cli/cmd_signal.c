/* cmd_signal.c: `mcrash signal hic|a3ms|cfc|nij|bric|vc|ti FILE.csv [--class CFC] [--window S]
 * [--json]`: filter the channels of a CSV file, or compute one criterion from it. FILE may
 * also name one channel (file.mme:channel, file.h5:/stageN/channels/NAME, file.csv:column),
 * enough for hic, a3ms, vc and cfc.
 * With --class the input channels are CFC-filtered before the criterion; without it they are
 * used as they are. `cfc` without --class picks J211's class from each column's name. */
#include "analysis/an_cfc.h"
#include "analysis/an_criteria.h"
#include "analysis/an_limits.h"
#include "analysis/an_signal.h"
#include "cli/cli.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

typedef struct {
    const char *sub, *file;
    double cfc;    /* 0: none given */
    double window; /* 0: default of the criterion [s] */
    int json;
} sig_args;

/* "15ms", "0.015", "0.015s" -> seconds */
static int parse_seconds(const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    if (end == s) return 0;
    while (isspace((unsigned char)*end)) end++;
    if (strcmp(end, "ms") == 0) *v *= 1e-3;
    else if (*end && strcmp(end, "s") != 0) return 0;
    return *v > 0;
}

static int parse_args(int argc, char **argv, sig_args *a)
{
    *a = (sig_args){0};
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (strcmp(s, "--json") == 0) {
            a->json = 1;
        } else if (strcmp(s, "--class") == 0 && i + 1 < argc) {
            char *end;
            a->cfc = strtod(argv[++i], &end);
            if (*end || !(a->cfc > 0)) {
                fprintf(stderr, "mcrash signal: --class %s: a positive number (60, 180, 600, "
                                "1000, ...)\n", argv[i]);
                return 0;
            }
        } else if (strcmp(s, "--window") == 0 && i + 1 < argc) {
            if (!parse_seconds(argv[++i], &a->window)) {
                fprintf(stderr, "mcrash signal: --window %s: a positive time in s (or 15ms)\n",
                        argv[i]);
                return 0;
            }
        } else if (s[0] == '-' && s[1]) {
            fprintf(stderr, "mcrash signal: unknown or incomplete option %s\n", s);
            return 0;
        } else if (!a->sub) {
            a->sub = s;
        } else if (!a->file) {
            a->file = s;
        } else {
            fprintf(stderr, "mcrash signal: unexpected argument %s\n", s);
            return 0;
        }
    }
    static const char *const subs[] = {"hic", "a3ms", "cfc", "nij", "bric", "vc", "ti"};
    int ok = 0;
    for (int k = 0; a->sub && k < 7; k++) ok |= strcmp(a->sub, subs[k]) == 0;
    if (!ok) {
        if (a->sub) fprintf(stderr, "mcrash signal: unknown criterion %s\n", a->sub);
        return 0;
    }
    if (!a->file) return 0;
    return 1;
}

/* J211 class from a column name (head 1000, neck 600, chest 180, femur/tibia 600, ...) */
static int class_from_name(const char *name)
{
    static const struct {
        const char *word, *kind;
    } map[] = {{"head", "head_acceleration"}, {"neck", "neck_force"},
               {"chest", "chest_acceleration"}, {"thorax", "chest_acceleration"},
               {"femur", "femur"},            {"tibia", "tibia"},
               {"pelvis", "pelvis_acceleration"}, {"vehicle", "vehicle"},
               {"moto", "vehicle"},           {"car", "vehicle"}};
    char low[64];
    size_t i = 0;
    for (; name[i] && i + 1 < sizeof low; i++) low[i] = (char)tolower((unsigned char)name[i]);
    low[i] = 0;
    for (size_t k = 0; k < sizeof map / sizeof map[0]; k++)
        if (strstr(low, map[k].word)) return an_cfc_default(map[k].kind);
    return 0;
}

static int fail(const mcs_error *e)
{
    fprintf(stderr, "mcrash signal: %s\n", e->msg);
    return mcs_status_exit_code(e->status);
}

/* `cfc`: every column filtered, CSV on stdout */
static int do_cfc(const sig_args *a, an_signal *c, int n)
{
    mcs_error e = {0};
    for (int k = 0; k < n; k++) {
        int cls = a->cfc > 0 ? (int)a->cfc : class_from_name(c[k].name);
        if (cls <= 0) {
            fprintf(stderr,
                    "mcrash signal: %s: column \"%s\": no --class given and no J211 default for "
                    "this name (head, neck, chest, femur, tibia, pelvis, vehicle)\n",
                    a->file, c[k].name);
            return 2;
        }
        double dt;
        if (!an_signal_uniform(&c[k], 1e-6, &dt)) {
            fprintf(stderr, "mcrash signal: %s: CFC filtering needs a constant time step\n",
                    a->file);
            return 2;
        }
        if (an_cfc_filter(c[k].y, c[k].n, dt, a->cfc > 0 ? a->cfc : cls, c[k].y, &e))
            return fail(&e);
        c[k].cfc = cls;
    }
    printf("time [s]");
    for (int k = 0; k < n; k++) printf(", %s [%s]", c[k].name, c[k].unit);
    printf("\n");
    for (int i = 0; i < c[0].n; i++) {
        printf("%.12g", c[0].t[i]);
        for (int k = 0; k < n; k++) printf(", %.10g", c[k].y[i]);
        printf("\n");
    }
    return 0;
}

/* the columns a criterion needs, by name, with their SI unit checked */
static int need(const sig_args *a, const an_signal *c, int n, const char *name, const char *unit,
                int *idx)
{
    *idx = an_signal_find(c, n, name);
    if (*idx < 0) return 0;
    if (strcmp(c[*idx].unit, unit) != 0) {
        fprintf(stderr,
                "mcrash signal: %s: column \"%s\" is in [%s] after conversion; %s needs a unit "
                "convertible to %s (write it in the header, e.g. \"%s [%s]\")\n",
                a->file, c[*idx].name, c[*idx].unit, a->sub, unit, name, unit);
        *idx = -2;
        return 0;
    }
    return 1;
}

static void list_columns(const sig_args *a, const an_signal *c, int n, const char *want)
{
    fprintf(stderr, "mcrash signal: %s: %s needs the columns %s; the file has:", a->file, a->sub,
            want);
    for (int k = 0; k < n; k++) fprintf(stderr, " %s [%s]", c[k].name, c[k].unit);
    fprintf(stderr, "\n");
}

/* the one prefix P for which columns P<names[0..2]> all exist (e.g. head_ax head_ay head_az,
 * as stage-1 exports name them); 1 and the prefix if exactly one triple exists */
static int prefixed_triple(const an_signal *c, int n, const char *const names[3], char *prefix,
                           size_t size)
{
    int found = 0;
    for (int k = 0; k < n; k++) {
        size_t ln = strlen(c[k].name), ls = strlen(names[0]);
        if (ln <= ls || strcmp(c[k].name + ln - ls, names[0]) != 0 || ln - ls >= size) continue;
        char p[64], full[128];
        snprintf(p, sizeof p, "%.*s", (int)(ln - ls), c[k].name);
        int all = 1;
        for (int j = 1; j < 3 && all; j++) {
            snprintf(full, sizeof full, "%s%s", p, names[j]);
            all = an_signal_find(c, n, full) >= 0;
        }
        if (all && found++ == 0) snprintf(prefix, size, "%s", p);
    }
    return found == 1;
}

/* three named columns (ax ay az, Fx Fz My, ...), bare or with one common prefix */
static int need3(const sig_args *a, const an_signal *c, int n, const char *const names[3],
                 const char *const units[3], int idx[3])
{
    char prefix[64] = "", full[3][128];
    const char *use[3] = {names[0], names[1], names[2]};
    if (an_signal_find(c, n, names[0]) < 0 && prefixed_triple(c, n, names, prefix, sizeof prefix))
        for (int k = 0; k < 3; k++) {
            snprintf(full[k], sizeof full[k], "%s%s", prefix, names[k]);
            use[k] = full[k];
        }
    int found = 0;
    for (int k = 0; k < 3; k++) {
        found += need(a, c, n, use[k], units[k], &idx[k]);
        if (idx[k] == -2) return -1;
    }
    if (found == 3) return 1;
    return 0;
}

/* the acceleration of hic/a3ms: ax ay az (resultant) or the only column; y owned by caller */
static int accel_channel(const sig_args *a, an_signal *c, int n, double **acc, const char **what)
{
    static const char *const names[3] = {"ax", "ay", "az"};
    static const char *const units[3] = {"m/s^2", "m/s^2", "m/s^2"};
    int idx[3];
    int r = need3(a, c, n, names, units, idx);
    if (r < 0) return 0;
    *acc = malloc((size_t)c[0].n * sizeof(double));
    if (!*acc) return 0;
    if (r == 1) {
        an_resultant(c[idx[0]].y, c[idx[1]].y, c[idx[2]].y, c[0].n, *acc);
        *what = "resultant of ax, ay, az";
        return 1;
    }
    if (n == 1 && strcmp(c[0].unit, "m/s^2") == 0) {
        /* one axis: its resultant is its magnitude (a J211 z channel is negative in a drop) */
        for (int i = 0; i < c[0].n; i++) (*acc)[i] = fabs(c[0].y[i]);
        *what = c[0].name;
        return 1;
    }
    free(*acc);
    *acc = NULL;
    list_columns(a, c, n, "ax, ay, az [g or m/s^2], or one acceleration column");
    return 0;
}

static void print_limit(const sig_args *a, const char *key, double value)
{
    const an_limit *l = an_limit_find(key);
    if (!l) return;
    if (a->json)
        printf(", \"limit\": %.10g, \"fraction\": %.10g", l->limit, value / l->limit);
    else
        printf("  (%.0f%% of the limit %g%s%s; %s)", 100 * value / l->limit, l->limit,
               strcmp(l->unit, "-") ? " " : "", strcmp(l->unit, "-") ? l->unit : "", l->source);
}

static int do_hic(const sig_args *a, an_signal *c, int n)
{
    double *acc = NULL;
    const char *what = "";
    if (!accel_channel(a, c, n, &acc, &what)) return 2;
    double w = a->window > 0 ? a->window : 0.015;
    an_hic_result r;
    mcs_error e = {0};
    mcs_status st = an_hic(c[0].t, acc, c[0].n, w, &r, &e);
    free(acc);
    if (st) return fail(&e);
    char key[16] = "";
    if (fabs(w - 0.015) < 1e-12) snprintf(key, sizeof key, "hic15");
    if (fabs(w - 0.036) < 1e-12) snprintf(key, sizeof key, "hic36");
    if (a->json) {
        printf("{\"hic\": %.10g, \"t1\": %.10g, \"t2\": %.10g, \"window\": %.10g", r.hic, r.t1,
               r.t2, w);
        print_limit(a, key, r.hic);
        printf("}\n");
    } else {
        printf("HIC (window %g ms, %s) = %.4g  t1 = %.6g s  t2 = %.6g s", w * 1e3, what, r.hic,
               r.t1, r.t2);
        print_limit(a, key, r.hic);
        printf("\n");
    }
    return 0;
}

static int do_a3ms(const sig_args *a, an_signal *c, int n)
{
    double *acc = NULL;
    const char *what = "";
    if (!accel_channel(a, c, n, &acc, &what)) return 2;
    double d = a->window > 0 ? a->window : 0.003;
    an_a3ms_result r, rc;
    mcs_error e = {0};
    mcs_status st = an_a3ms(c[0].t, acc, c[0].n, d, &r, &e);
    if (!st) st = an_a3ms_cumulative(c[0].t, acc, c[0].n, d, &rc, &e);
    free(acc);
    if (st) return fail(&e);
    if (a->json)
        printf("{\"a3ms\": %.10g, \"t1\": %.10g, \"t2\": %.10g, \"a3ms_cumulative\": %.10g, "
               "\"duration\": %.10g, \"unit\": \"g\"}\n",
               r.level / AN_G0, r.t1, r.t2, rc.level / AN_G0, d);
    else
        printf("a%gms (%s) = %.4g g, held from %.6g s to %.6g s; cumulative variant %.4g g\n",
               d * 1e3, what, r.level / AN_G0, r.t1, r.t2, rc.level / AN_G0);
    return 0;
}

static int do_nij(const sig_args *a, an_signal *c, int n)
{
    static const char *const names[3] = {"Fx", "Fz", "My"};
    static const char *const units[3] = {"N", "N", "N*m"};
    int idx[3];
    int r3 = need3(a, c, n, names, units, idx);
    if (r3 <= 0) {
        if (r3 == 0) list_columns(a, c, n, "Fx [N or kN], Fz [N or kN], My [N*m]");
        return 2;
    }
    an_nij_opts o = an_nij_opts_hybrid3_50m();
    an_nij_result r;
    mcs_error e = {0};
    if (an_nij(c[0].t, c[idx[0]].y, c[idx[1]].y, c[idx[2]].y, c[0].n, &o, &r, &e)) return fail(&e);
    if (a->json) {
        printf("{\"nij\": %.10g, \"mode\": \"%s\", \"time\": %.10g", r.nij, an_nij_mode_name(r.mode),
               r.time);
        for (int m = 0; m < AN_NIJ_NMODES; m++)
            printf(", \"%s\": %.10g", an_nij_mode_name((an_nij_mode)m), r.mode_max[m]);
        print_limit(a, "nij", r.nij);
        printf("}\n");
    } else {
        printf("Nij (Hybrid III 50th) = %.4g, mode %s at %.6g s", r.nij, an_nij_mode_name(r.mode),
               r.time);
        print_limit(a, "nij", r.nij);
        printf("\n  TF %.4g  TE %.4g  CF %.4g  CE %.4g\n", r.mode_max[0], r.mode_max[1],
               r.mode_max[2], r.mode_max[3]);
    }
    return 0;
}

static int do_bric(const sig_args *a, an_signal *c, int n)
{
    static const char *const names[3] = {"wx", "wy", "wz"};
    static const char *const units[3] = {"rad/s", "rad/s", "rad/s"};
    int idx[3];
    int r3 = need3(a, c, n, names, units, idx);
    if (r3 <= 0) {
        if (r3 == 0) list_columns(a, c, n, "wx, wy, wz [rad/s or deg/s]");
        return 2;
    }
    an_bric_opts o = an_bric_opts_default();
    double b;
    mcs_error e = {0};
    if (an_bric(c[idx[0]].y, c[idx[1]].y, c[idx[2]].y, c[0].n, &o, &b, &e)) return fail(&e);
    if (a->json) {
        printf("{\"bric\": %.10g", b);
        print_limit(a, "bric", b);
        printf("}\n");
    } else {
        printf("BrIC = %.4g", b);
        print_limit(a, "bric", b);
        printf("\n");
    }
    return 0;
}

static int do_vc(const sig_args *a, an_signal *c, int n)
{
    int k;
    if (!need(a, c, n, "D", "m", &k)) {
        if (k != -2) list_columns(a, c, n, "D [mm or m] (chest deflection)");
        return 2;
    }
    an_vc_opts o = an_vc_opts_hybrid3_50m();
    double v, t;
    mcs_error e = {0};
    if (an_vc(c[k].t, c[k].y, c[k].n, &o, &v, &t, NULL, &e)) return fail(&e);
    if (a->json) {
        printf("{\"vc\": %.10g, \"time\": %.10g, \"unit\": \"m/s\"", v, t);
        print_limit(a, "vc", v);
        printf("}\n");
    } else {
        printf("VC (Hybrid III 50th) = %.4g m/s at %.6g s", v, t);
        print_limit(a, "vc", v);
        printf("\n");
    }
    return 0;
}

static int do_ti(const sig_args *a, an_signal *c, int n)
{
    static const char *const names[3] = {"Mx", "My", "Fz"};
    static const char *const units[3] = {"N*m", "N*m", "N"};
    int idx[3];
    int r3 = need3(a, c, n, names, units, idx);
    if (r3 <= 0) {
        if (r3 == 0) list_columns(a, c, n, "Mx [N*m], My [N*m], Fz [N or kN]");
        return 2;
    }
    an_ti_opts o = an_ti_opts_hybrid3_50m();
    double ti, t;
    mcs_error e = {0};
    if (an_tibia_index(c[0].t, c[idx[0]].y, c[idx[1]].y, c[idx[2]].y, c[0].n, &o, &ti, &t, &e))
        return fail(&e);
    if (a->json) {
        printf("{\"ti\": %.10g, \"time\": %.10g", ti, t);
        print_limit(a, "tibia_index", ti);
        printf("}\n");
    } else {
        printf("tibia index (Hybrid III 50th) = %.4g at %.6g s", ti, t);
        print_limit(a, "tibia_index", ti);
        printf("\n");
    }
    return 0;
}

int cli_signal(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    sig_args a;
    if (!parse_args(argc, argv, &a)) return cli_usage(argv[0]);
    an_signal *c = NULL;
    int n = 0;
    mcs_error e = {0};
    /* a CSV file, or one channel by reference (file.mme:channel, file.h5:/path, file.csv:col) */
    if (strstr(a.file, ".mme:") || strstr(a.file, ".h5:") || strstr(a.file, ".csv:")) {
        c = calloc(1, sizeof *c);
        if (!c) return 2;
        if (an_signal_read_ref(a.file, c, &e)) {
            free(c);
            return fail(&e);
        }
        n = 1;
    } else if (an_csv_read(a.file, &c, &n, &e)) {
        return fail(&e);
    }
    int rc = 0;
    /* optional CFC filtering of the inputs of a criterion */
    for (int k = 0; strcmp(a.sub, "cfc") != 0 && a.cfc > 0 && k < n && !rc; k++)
        if (an_cfc_signal(&c[k], (int)a.cfc, &e)) rc = fail(&e);
    if (!rc) {
        if (strcmp(a.sub, "cfc") == 0) rc = do_cfc(&a, c, n);
        else if (strcmp(a.sub, "hic") == 0) rc = do_hic(&a, c, n);
        else if (strcmp(a.sub, "a3ms") == 0) rc = do_a3ms(&a, c, n);
        else if (strcmp(a.sub, "nij") == 0) rc = do_nij(&a, c, n);
        else if (strcmp(a.sub, "bric") == 0) rc = do_bric(&a, c, n);
        else if (strcmp(a.sub, "vc") == 0) rc = do_vc(&a, c, n);
        else rc = do_ti(&a, c, n);
    }
    an_signals_free(&c, n);
    return rc;
}

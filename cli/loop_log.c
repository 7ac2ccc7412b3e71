/* loop_log.c: `mcrash loop`'s log (loop_log.h): loop.json with fixed keys (DESIGN.md "Retune
 * and loop") and loop.csv, one row per value (k, group, name, value) */
#include "cli/loop_log.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void loop_iter_free(loop_iter *it)
{
    tr_stage_compare_free(&it->cmp);
}

/* a shared curve's ISO/TS 18571 rating, NaN when it could not be rated */
static double iso(const tr_stage_rating *r)
{
    return r->iso_ok ? r->iso.rating : NAN;
}

static double change(double a, double b)
{
    if (isnan(a) && isnan(b)) return 0;
    if (isnan(a) || isnan(b)) return 1;
    return fabs(a - b);
}

double loop_rating_change(const loop_iter *a, const loop_iter *b)
{
    double d = fmax(change(a->iso_force, b->iso_force), change(a->iso_angle, b->iso_angle));
    const tr_stage_compare *ca = &a->cmp, *cb = &b->cmp;
    for (int i = 0; i < cb->nrating; i++) {
        double ra = NAN;
        int found = 0;
        for (int j = 0; j < ca->nrating && !found; j++)
            if (!strcmp(ca->rating[j].name, cb->rating[i].name))
                ra = iso(&ca->rating[j]), found = 1;
        d = fmax(d, found ? change(ra, iso(&cb->rating[i])) : 1);
    }
    return d;
}

/* a JSON string (quotes, backslashes and control characters escaped) */
static void jstr(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            fprintf(f, "\\%c", *s);
        else if ((unsigned char)*s < 0x20)
            fprintf(f, "\\u%04x", *s);
        else
            fputc(*s, f);
    }
    fputc('"', f);
}

/* a number, null when not finite */
static void jnum(FILE *f, double v)
{
    if (isfinite(v))
        fprintf(f, "%.10g", v);
    else
        fprintf(f, "null");
}

static void json_iter(FILE *f, const loop_iter *it)
{
    fprintf(f, "    {\"k\": %d, \"results\": ", it->k);
    jstr(f, it->results);
    fprintf(f, ", \"curves\": ");
    jstr(f, it->curves);
    fprintf(f, ",\n     \"ratings\": {\"stage1_vs_stage3\": {\"wall_force\": ");
    jnum(f, it->iso_force);
    fprintf(f, ", \"fork_angle\": ");
    jnum(f, it->iso_angle);
    fprintf(f, "},\n       \"stage2_vs_stage1\": {");
    const tr_stage_compare *c = &it->cmp;
    for (int i = 0; i < c->nrating; i++) {
        fprintf(f, "%s", i ? ", " : "");
        jstr(f, c->rating[i].name);
        fprintf(f, ": ");
        jnum(f, iso(&c->rating[i]));
    }
    fprintf(f, "}},\n     \"criteria\": {");
    for (int s = 0; s < 2; s++) {
        fprintf(f, "%s\"stage%d\": {", s ? ", " : "", s + 1);
        for (int i = 0, n = 0; i < c->ncrit; i++) {
            if (isnan(c->crit[i].value[s])) continue;
            fprintf(f, "%s", n++ ? ", " : "");
            jstr(f, c->crit[i].key);
            fprintf(f, ": ");
            jnum(f, c->crit[i].value[s]);
        }
        fprintf(f, "}");
    }
    fprintf(f, "},\n     \"parameters\": {");
    for (int i = 0; i < TR_RT_NPAR; i++) {
        fprintf(f, "%s\"%s\": ", i ? ", " : "", tr_rt_par_name(i));
        jnum(f, it->p[i]);
    }
    fprintf(f, "}, \"retune_runs\": %d}", it->nrun);
}

static void csv_iter(FILE *f, const loop_iter *it)
{
    fprintf(f, "%d,stage1_vs_stage3,wall_force,%.10g\n", it->k, it->iso_force);
    fprintf(f, "%d,stage1_vs_stage3,fork_angle,%.10g\n", it->k, it->iso_angle);
    const tr_stage_compare *c = &it->cmp;
    for (int i = 0; i < c->nrating; i++)
        fprintf(f, "%d,stage2_vs_stage1,%s,%.10g\n", it->k, c->rating[i].name,
                iso(&c->rating[i]));
    for (int s = 0; s < 2; s++)
        for (int i = 0; i < c->ncrit; i++)
            if (!isnan(c->crit[i].value[s]))
                fprintf(f, "%d,criteria_stage%d,%s,%.10g\n", it->k, s + 1, c->crit[i].key,
                        c->crit[i].value[s]);
    for (int i = 0; i < TR_RT_NPAR; i++)
        fprintf(f, "%d,parameters,%s,%.10g\n", it->k, tr_rt_par_name(i), it->p[i]);
}

int loop_log_write(const char *dir, const char *scenario, const loop_iter *it, int n,
                   int converged, const char *reason)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/loop.json", dir);
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    fprintf(f, "{\"scenario\": ");
    jstr(f, scenario);
    fprintf(f, ",\n  \"iterations\": [\n");
    for (int i = 0; i < n; i++) {
        json_iter(f, &it[i]);
        fprintf(f, "%s\n", i + 1 < n ? "," : "");
    }
    fprintf(f, "  ],\n  \"converged\": %s, \"reason\": ", converged ? "true" : "false");
    jstr(f, reason);
    fprintf(f, "}\n");
    int bad = fclose(f) != 0;
    snprintf(path, sizeof path, "%s/loop.csv", dir);
    f = fopen(path, "w");
    if (!f) return -1;
    fprintf(f, "k,group,name,value\n");
    for (int i = 0; i < n; i++)
        csv_iter(f, &it[i]);
    bad |= fclose(f) != 0;
    return bad ? -1 : 0;
}

/* cmd_compare_stages.c: `mcrash compare OUT.h5 --stages A,B [--json]` (DESIGN.md "The command";
 * translators/tr_stages.h): every channel and body component stages A and B of one results file
 * share, stage B rated against stage A by ISO/TS 18571 and by CORA (both, whatever --method
 * says), and the injury criteria of both stages side by side. A table, or with --json one
 * object of fixed keys (docs/contracts.md "compare --stages"). A curve that cannot be rated (a
 * constant reference, units that differ) gets its reason instead; nothing shared is an error
 * (exit 2). */
#include "cli/cli_common.h"
#include "translators/tr_stages.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* "A,B" with A, B stage numbers 0..9 (0: the reduced-order model) */
int cli_parse_stages(const char *s, int *a, int *b)
{
    char c;
    return s && sscanf(s, "%d,%d%c", a, b, &c) == 2 && *a >= 0 && *a <= 9 && *b >= 0 && *b <= 9;
}

static void num(double v)
{
    if (isfinite(v))
        printf("%.10g", v);
    else
        printf("null");
}

static void json_iso(const tr_stage_rating *r)
{
    const an_iso_result *i = &r->iso;
    if (!r->iso_ok) {
        printf("{\"error\": ");
        cli_json_string(r->iso_error);
        printf("}");
        return;
    }
    printf("{\"rating\": %.10g, \"grade\": \"%s\", \"corridor\": %.10g, \"phase\": %.10g, "
           "\"magnitude\": %.10g, \"slope\": %.10g, \"shift_time\": %.10g}",
           i->rating, an_iso_grade(i->rating), i->corridor, i->phase, i->magnitude, i->slope,
           i->shift_time);
}

static void json_cora(const tr_stage_rating *r)
{
    const an_cora_result *c = &r->cora;
    if (!r->cora_ok) {
        printf("{\"error\": ");
        cli_json_string(r->cora_error);
        printf("}");
        return;
    }
    printf("{\"rating\": %.10g, \"corridor\": %.10g, \"cross\": %.10g, \"phase\": %.10g, "
           "\"size\": %.10g, \"progression\": %.10g, \"shift_time\": %.10g}",
           c->rating, c->corridor, c->cross, c->phase, c->size, c->progression, c->shift_time);
}

static void print_json(const char *h5, const tr_stage_compare *c)
{
    printf("{\"file\": ");
    cli_json_string(h5);
    printf(", \"stages\": [%d, %d], \"reference\": %d, \"ratings\": [", c->stage[0], c->stage[1],
           c->stage[0]);
    for (int i = 0; i < c->nrating; i++) {
        const tr_stage_rating *r = &c->rating[i];
        printf("%s{\"name\": ", i ? ", " : "");
        cli_json_string(r->name);
        printf(", \"kind\": \"%s\", \"unit\": ", r->body ? "body" : "channel");
        cli_json_string(r->unit);
        printf(", \"iso18571\": ");
        json_iso(r);
        printf(", \"cora\": ");
        json_cora(r);
        printf("}");
    }
    printf("], \"injury\": [");
    for (int i = 0; i < c->ncrit; i++) {
        const tr_stage_criterion *x = &c->crit[i];
        printf("%s{\"key\": ", i ? ", " : "");
        cli_json_string(x->key);
        printf(", \"label\": ");
        cli_json_string(x->label);
        printf(", \"unit\": ");
        cli_json_string(x->unit);
        printf(", \"limit\": ");
        num(x->limit);
        printf(", \"value\": [");
        num(x->value[0]);
        printf(", ");
        num(x->value[1]);
        printf("], \"fraction\": [");
        num(x->fraction[0]);
        printf(", ");
        num(x->fraction[1]);
        printf("]}");
    }
    printf("]}\n");
}

static void print_text(const char *h5, const tr_stage_compare *c)
{
    printf("%s: stage %d against stage %d (ISO/TS 18571, CORA)\n", h5, c->stage[1], c->stage[0]);
    printf("  %-40s  %-8s  %-8s\n", "channel or body component", "ISO", "CORA");
    for (int i = 0; i < c->nrating; i++) {
        const tr_stage_rating *r = &c->rating[i];
        char a[16] = "-", b[16] = "-";
        if (r->iso_ok) snprintf(a, sizeof a, "%.4f", r->iso.rating);
        if (r->cora_ok) snprintf(b, sizeof b, "%.4f", r->cora.rating);
        printf("  %-40s  %-8s  %-8s", r->name, a, b);
        if (!r->iso_ok || !r->cora_ok) printf("  %s", !r->iso_ok ? r->iso_error : r->cora_error);
        printf("\n");
    }
    if (c->ncrit == 0) return;
    char ha[16], hb[16];
    snprintf(ha, sizeof ha, "stage %d", c->stage[0]);
    snprintf(hb, sizeof hb, "stage %d", c->stage[1]);
    printf("\n  %-28s  %-6s  %12s  %12s  %12s\n", "criterion", "unit", "limit", ha, hb);
    for (int i = 0; i < c->ncrit; i++) {
        const tr_stage_criterion *x = &c->crit[i];
        char v[3][24];
        const double d[3] = {x->limit, x->value[0], x->value[1]};
        for (int k = 0; k < 3; k++)
            snprintf(v[k], sizeof v[k], isfinite(d[k]) ? "%.4g" : "-", d[k]);
        printf("  %-28s  %-6s  %12s  %12s  %12s\n", x->label, x->unit, v[0], v[1], v[2]);
    }
}

int cli_compare_stages(const char *h5, int sa, int sb, int cora, int json)
{
    (void)cora; /* both methods, always */
    tr_stage_compare c;
    mcs_error err = {0};
    mcs_status st = tr_compare_stages(h5, sa, sb, &c, &err);
    if (st) {
        fprintf(stderr, "mcrash compare: %s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    if (json)
        print_json(h5, &c);
    else
        print_text(h5, &c);
    tr_stage_compare_free(&c);
    return fflush(stdout) ? 2 : 0;
}

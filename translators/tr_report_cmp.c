/* tr_report_cmp.c: the report's stage-against-stage section: each pair of stages of the file
 * rated by translators/tr_stages.c as `mcrash compare OUT.h5 --stages A,B` rates them (every
 * shared channel and body component, ISO/TS 18571 and CORA, the later stage against the
 * earlier), the dummy channels overlaid with their ratings, and the table of all of them */
#include "translators/tr_report_int.h"
#include "translators/tr_stages.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RP_MAXROWS 400 /* rows of the ratings table per pair */

/* the overlays drawn when both stages have them */
static const char *key_channel[] = {"head_ax",  "head_az", "chest_ax", "pelvis_ax",
                                    "neck_fx",  "neck_fz", "neck_my",  "femur_left_fz"};
enum { NKEY = sizeof key_channel / sizeof key_channel[0] };

/* stage s's channel name and its time, or -1 */
static int read_channel(tr_rp *c, int s, const char *name, mcs_array *a)
{
    char p[200];
    snprintf(p, sizeof p, "/stage%d/channels/%s", s, name);
    if (rp_read(c, p, a) || a->rank != 1 || a->n != c->time[s].n || a->n < 2) {
        mcs_array_free(a);
        return -1;
    }
    return 0;
}

/* one channel of both stages overlaid, its ratings in the title */
static void overlay(tr_rp *c, const int st[2], const tr_stage_rating *r)
{
    mcs_array a[2];
    if (read_channel(c, st[0], r->name, &a[0])) return;
    if (read_channel(c, st[1], r->name, &a[1])) {
        mcs_array_free(&a[0]);
        return;
    }
    char title[200], la[16], lb[16], ylab[200];
    int k = snprintf(title, sizeof title, "%s: ", r->name);
    if (r->iso_ok)
        k += snprintf(title + k, sizeof title - (size_t)k, "R = %.2f (%s)", r->iso.rating,
                      an_iso_grade(r->iso.rating));
    else k += snprintf(title + k, sizeof title - (size_t)k, "not rated");
    if (r->cora_ok && k < (int)sizeof title)
        snprintf(title + k, sizeof title - (size_t)k, ", CORA %.2f", r->cora.rating);
    snprintf(la, sizeof la, "stage %d", st[0]);
    snprintf(lb, sizeof lb, "stage %d", st[1]);
    rp_series s[2] = {{.x = c->time[st[0]].v, .y = a[0].v, .n = a[0].n, .label = la},
                      {.x = c->time[st[1]].v, .y = a[1].v, .n = a[1].n, .label = lb,
                       .dash = "6 3"}};
    const char *shown = a[0].unit;
    double scale = 1;
    if (strcmp(a[0].unit, "m/s^2") == 0) shown = "g", scale = 1 / 9.80665;
    else if (strcmp(a[0].unit, "N") == 0) shown = "kN", scale = 1e-3;
    snprintf(ylab, sizeof ylab, "%s [%s]", r->name, shown[0] ? shown : "-");
    rp_plot p = {.title = title, .xlabel = "time [ms]", .ylabel = ylab, .xscale = 1e3,
                 .yscale = scale, .ymin0 = NAN, .ymax0 = NAN};
    rp_lines(c, &p, s, 2);
    mcs_array_free(&a[0]);
    mcs_array_free(&a[1]);
}

static void cell_rating(tr_rp *c, int ok, double v, const char *why, int grade)
{
    if (ok && grade)
        fprintf(c->f, "<td class=\"n\">%.3f</td><td>%s</td>", v, an_iso_grade(v));
    else if (ok) fprintf(c->f, "<td class=\"n\">%.3f</td>", v);
    else {
        fprintf(c->f, "<td%s>-</td>", grade ? " colspan=\"2\"" : "");
        (void)why;
    }
}

/* one pair of stages: overlays, then the table of every rating */
static void pair(tr_rp *c, const tr_stage_compare *cmp)
{
    char h[80];
    snprintf(h, sizeof h, "Stage %d against stage %d", cmp->stage[1], cmp->stage[0]);
    rp_h3(c, h);
    fputs("<div class=\"plots\">\n", c->f);
    int drawn = 0;
    for (int k = 0; k < NKEY; k++)
        for (int i = 0; i < cmp->nrating; i++)
            if (!cmp->rating[i].body && strcmp(cmp->rating[i].name, key_channel[k]) == 0) {
                overlay(c, cmp->stage, &cmp->rating[i]);
                drawn++;
            }
    for (int i = 0; i < cmp->nrating && !drawn && i < 4; i++) /* no dummy: the first four */
        if (!cmp->rating[i].body) overlay(c, cmp->stage, &cmp->rating[i]);
    fputs("</div>\n<table><tr><th>curve</th><th>unit</th><th>ISO/TS 18571 R</th><th>grade</th>"
          "<th>CORA</th><th>not rated because</th></tr>\n",
          c->f);
    int rows = cmp->nrating < RP_MAXROWS ? cmp->nrating : RP_MAXROWS;
    for (int i = 0; i < rows; i++) {
        const tr_stage_rating *r = &cmp->rating[i];
        fputs("<tr><td>", c->f);
        rp_esc(c, r->name);
        fputs("</td><td>", c->f);
        rp_esc(c, r->unit);
        fputs("</td>", c->f);
        cell_rating(c, r->iso_ok, r->iso.rating, r->iso_error, 1);
        cell_rating(c, r->cora_ok, r->cora.rating, r->cora_error, 0);
        fputs("<td>", c->f);
        rp_esc(c, !r->iso_ok ? r->iso_error : !r->cora_ok ? r->cora_error : "");
        fputs("</td></tr>\n", c->f);
    }
    fputs("</table>\n", c->f);
    if (cmp->nrating > rows)
        fprintf(c->f, "<p class=\"note\">the first %d of %d rated curves; <code>mcrash compare "
                      "FILE --stages %d,%d</code> lists them all.</p>\n",
                rows, cmp->nrating, cmp->stage[0], cmp->stage[1]);
}

void rp_compare(tr_rp *c)
{
    int any = 0;
    for (int sa = 1; sa <= RP_NSTAGE; sa++)
        for (int sb = sa + 1; sb <= RP_NSTAGE; sb++) {
            if (!c->has_stage[sa] || !c->has_stage[sb]) continue;
            tr_stage_compare cmp;
            mcs_error e = {0};
            memset(&cmp, 0, sizeof cmp);
            if (tr_compare_stages(c->h5, sa, sb, &cmp, &e) == MCS_OK && cmp.nrating > 0) {
                if (!any) rp_section(c, "stages", "Stage against stage");
                any = 1;
                pair(c, &cmp);
            }
            tr_stage_compare_free(&cmp);
        }
    if (any)
        fputs("<p class=\"note\">the later stage's curve rated against the earlier one's as "
              "<code>mcrash compare FILE --stages A,B</code> rates it (ISO/TS 18571 grades: "
              "excellent &gt; 0.94, good &gt; 0.80, fair &gt; 0.58, else poor; CORA 0 to 1)."
              "</p>\n</section>\n",
              c->f);
    else rp_skip(c, "stages", "no two stages with shared channels or bodies");
}

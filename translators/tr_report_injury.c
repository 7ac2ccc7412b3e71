/* tr_report_injury.c: the report's injury section: each criterion as a bar of its value over
 * its limit, one bar per stage (the 2023 paper's Fig. 22), and the table with the values,
 * limits and their sources (analysis/an_limits.c) */
#include "analysis/an_injury.h"
#include "analysis/an_limits.h"
#include "analysis/an_svg.h"
#include "translators/tr_report_int.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    an_injury_row *row;
    int n;
    an_dummy dummy;
} rp_inj;

static void bars(tr_rp *c, const rp_inj *inj, const int *stage, int ns)
{
    /* the criteria with a limit, in the order first seen */
    const an_injury_row *crit[32];
    int nc = 0;
    double fmax = 1;
    for (int k = 0; k < ns; k++)
        for (int i = 0; i < inj[k].n; i++) {
            const an_injury_row *r = &inj[k].row[i];
            if (!isfinite(r->fraction)) continue;
            if (r->fraction > fmax) fmax = r->fraction;
            int seen = 0;
            for (int j = 0; j < nc && !seen; j++) seen = strcmp(crit[j]->key, r->key) == 0;
            if (!seen && nc < 32) crit[nc++] = r;
        }
    if (!nc) return;
    double rowh = 8 + 14 * ns, W = 720, H = 60 + nc * rowh + 40;
    an_svg_axes a;
    an_svg_axes_fit(&a, 170, 34, 400, nc * rowh, 0, 100 * fmax, 0, 1);
    FILE *f = c->f;
    an_svg_begin(f, W, H, "injury criteria as a percentage of their limits");
    fputs("<g font-weight=\"bold\">", f);
    an_svg_text(f, 8, 16, "start", 13, NULL, "Injury criteria against their limits");
    fputs("</g>\n", f);
    for (int i = 0; i < a.nxt; i++) { /* x grid and ticks */
        char lb[32];
        double x = an_svg_px(&a, a.xt[i]);
        an_svg_line(f, x, a.y0, x, a.y0 + a.h, "#e4e4e4", 1, NULL);
        an_svg_tick_label(a.xt[i], a.xstep, lb, sizeof lb);
        an_svg_text(f, x, a.y0 + a.h + 15, "middle", 0, NULL, lb);
    }
    an_svg_text(f, a.x0 + a.w / 2, a.y0 + a.h + 32, "middle", 12, NULL, "value / limit [%]");
    for (int j = 0; j < nc; j++) {
        double y = a.y0 + j * rowh + 4;
        an_svg_text(f, a.x0 - 8, y + rowh / 2 + 2, "end", 12, NULL, crit[j]->label);
        for (int k = 0; k < ns; k++) {
            const an_injury_row *r = NULL;
            for (int i = 0; i < inj[k].n && !r; i++)
                if (strcmp(inj[k].row[i].key, crit[j]->key) == 0) r = &inj[k].row[i];
            if (!r || !isfinite(r->fraction)) continue;
            double x1 = an_svg_px(&a, 100 * r->fraction), yy = y + k * 14;
            char tip[200], val[64];
            snprintf(tip, sizeof tip, "stage %d %s = %.4g %s (limit %.4g)", stage[k], r->label,
                     r->value, r->unit, r->limit);
            const char *fill = r->fraction >= 1 ? "#d62728" : an_svg_color(k == 0 ? 0 : k + 1);
            an_svg_rect(f, a.x0, yy, x1 - a.x0, 12, fill, tip);
            snprintf(val, sizeof val, "%.4g %s (%.0f%%)", r->value,
                     strcmp(r->unit, "-") ? r->unit : "", 100 * r->fraction);
            if (ns > 1) {
                size_t l = strlen(val);
                snprintf(val + l, sizeof val - l, "  stage %d", stage[k]);
            }
            an_svg_text(f, x1 + 4, yy + 10, "start", 10, NULL, val);
        }
    }
    an_svg_line(f, a.x0, a.y0, a.x0, a.y0 + a.h, "#444", 1, NULL);
    double xl = an_svg_px(&a, 100);
    an_svg_line(f, xl, a.y0 - 6, xl, a.y0 + a.h, "#d62728", 2, "5 3");
    an_svg_text(f, xl, a.y0 - 9, "middle", 11, "#d62728", "limit");
    an_svg_end(f);
    c->sum->nsvg++;
}

static void table(tr_rp *c, int stage, const rp_inj *inj)
{
    FILE *f = c->f;
    fprintf(f, "<h3>Stage %d, Hybrid III %s</h3>\n<table><tr><th>criterion</th><th>value</th>"
               "<th>unit</th><th>limit</th><th>of limit</th><th>time [ms]</th>"
               "<th>channels (CFC)</th><th>source of the limit</th></tr>\n",
            stage, an_dummy_name(inj->dummy));
    for (int i = 0; i < inj->n; i++) {
        const an_injury_row *r = &inj->row[i];
        const an_limit *l = an_limit_find_dummy(r->key, inj->dummy);
        int over = isfinite(r->fraction) && r->fraction >= 1;
        fprintf(f, "<tr%s><td>", over ? " class=\"over\"" : "");
        rp_esc(c, r->label);
        fprintf(f, "</td><td class=\"n\">%.4g</td><td>", r->value);
        rp_esc(c, r->unit);
        if (isfinite(r->limit))
            fprintf(f, "</td><td class=\"n\">%.6g</td><td class=\"n\">%.0f%%</td>", r->limit,
                    100 * r->fraction);
        else fputs("</td><td>-</td><td>-</td>", f);
        if (r->t1 == r->t2) fprintf(f, "<td class=\"n\">%.2f</td><td>", 1e3 * r->t1);
        else fprintf(f, "<td class=\"n\">%.2f-%.2f</td><td>", 1e3 * r->t1, 1e3 * r->t2);
        rp_esc(c, r->channel);
        fprintf(f, " (%d)</td><td>", r->cfc);
        rp_esc(c, l ? l->source : "no limit");
        fputs("</td></tr>\n", f);
    }
    fputs("</table>\n", f);
}

void rp_injury(tr_rp *c)
{
    rp_inj inj[RP_NSTAGE];
    int stage[RP_NSTAGE], ns = 0;
    for (int s = 1; s <= RP_NSTAGE; s++) {
        if (!c->has_stage[s] || c->time[s].n < 2) continue;
        mcs_error e = {0};
        int used = 0;
        rp_inj *q = &inj[ns];
        memset(q, 0, sizeof *q);
        if (an_injury_evaluate_as(c->h5, s, -1, &q->row, &q->n, &used, &q->dummy, &e) ||
            used != s || q->n == 0) {
            free(q->row);
            continue;
        }
        stage[ns++] = s;
    }
    if (!ns) {
        rp_skip(c, "injury", "no dummy channels for the injury criteria");
        return;
    }
    rp_section(c, "injury", "Injury criteria");
    bars(c, inj, stage, ns);
    for (int k = 0; k < ns; k++) table(c, stage[k], &inj[k]);
    fputs("<p class=\"note\">as <code>mcrash injury</code> computes them (analysis/an_injury.h);"
          " limits from analysis/an_limits.c, those marked unverified there are not checked "
          "against a primary text.</p>\n</section>\n",
          c->f);
    for (int k = 0; k < ns; k++) free(inj[k].row);
}

/* tr_report_cmp.c: the report's stage-against-stage section: the channels two stages of the
 * file share, the later stage's curve rated against the earlier one's by ISO/TS 18571 (as
 * `mcrash compare OUT.h5 --stages A,B`), the dummy channels overlaid */
#include "analysis/an_iso18571.h"
#include "analysis/an_svg.h"
#include "translators/tr_report_int.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RP_MAXRATE 120 /* channels rated per pair of stages */

/* the overlays drawn first when both stages have them */
static const char *key_channel[] = {"head_ax",  "head_az", "chest_ax", "pelvis_ax",
                                    "neck_fx",  "neck_fz", "neck_my",  "femur_left_fz"};
enum { NKEY = sizeof key_channel / sizeof key_channel[0] };

/* /stageS/channels/name as a signal borrowing the arrays of a (free a) */
static int read_signal(tr_rp *c, int s, const char *name, mcs_array *a, an_signal *sig)
{
    char p[200];
    snprintf(p, sizeof p, "/stage%d/channels/%s", s, name);
    if (rp_read(c, p, a) || a->rank != 1 || a->n != c->time[s].n || a->n < 2) {
        mcs_array_free(a);
        return -1;
    }
    memset(sig, 0, sizeof *sig);
    rp_copy(sig->name, sizeof sig->name, name);
    rp_copy(sig->unit, sizeof sig->unit, a->unit);
    sig->n = (int)a->n;
    sig->t = c->time[s].v;
    sig->y = a->v;
    return 0;
}

/* rating of stage b's channel against stage a's; NaN and the reason in why when none */
static double rate(tr_rp *c, int sa, int sb, const char *name, int overlay, char *why,
                   size_t nwhy)
{
    mcs_array aa, ab;
    an_signal ra, rb;
    why[0] = 0;
    if (read_signal(c, sa, name, &aa, &ra)) {
        snprintf(why, nwhy, "not a channel of stage %d's time axis", sa);
        return NAN;
    }
    if (read_signal(c, sb, name, &ab, &rb)) {
        mcs_array_free(&aa);
        snprintf(why, nwhy, "not a channel of stage %d's time axis", sb);
        return NAN;
    }
    double v = NAN;
    mcs_error e = {0};
    an_iso_opts o = an_iso_opts_default();
    an_iso_result r;
    if (strcmp(ra.unit, rb.unit) != 0)
        snprintf(why, nwhy, "units differ: %s, %s", ra.unit, rb.unit);
    else if (an_iso18571(&ra, &rb, &o, &r, &e)) rp_copy(why, nwhy, e.msg);
    else v = r.rating;
    if (overlay) {
        char title[160], la[16], lb[16];
        if (isfinite(v))
            snprintf(title, sizeof title, "%s: R = %.2f (%s)", name, v, an_iso_grade(v));
        else snprintf(title, sizeof title, "%s: not rated", name);
        snprintf(la, sizeof la, "stage %d", sa);
        snprintf(lb, sizeof lb, "stage %d", sb);
        rp_series s[2] = {{.x = ra.t, .y = ra.y, .n = (size_t)ra.n, .label = la},
                          {.x = rb.t, .y = rb.y, .n = (size_t)rb.n, .label = lb, .dash = "6 3"}};
        const char *shown = ra.unit;
        double scale = 1;
        if (strcmp(ra.unit, "m/s^2") == 0) shown = "g", scale = 1 / 9.80665;
        else if (strcmp(ra.unit, "N") == 0) shown = "kN", scale = 1e-3;
        char ylab[48];
        snprintf(ylab, sizeof ylab, "%s [%s]", name, shown[0] ? shown : "-");
        rp_plot p = {.title = title, .xlabel = "time [ms]", .ylabel = ylab, .xscale = 1e3,
                     .yscale = scale, .ymin0 = NAN, .ymax0 = NAN};
        rp_lines(c, &p, s, 2);
    }
    mcs_array_free(&aa);
    mcs_array_free(&ab);
    return v;
}

static int is_key(const char *name)
{
    for (int k = 0; k < NKEY; k++)
        if (strcmp(name, key_channel[k]) == 0) return 1;
    return 0;
}

/* one pair of stages: overlays, then the table of every shared channel's rating */
static void pair(tr_rp *c, int sa, int sb, char **na, int ka, char **nb, int kb)
{
    char h[64];
    snprintf(h, sizeof h, "Stage %d against stage %d (ISO/TS 18571)", sb, sa);
    rp_h3(c, h);
    fputs("<div class=\"plots\">\n", c->f);
    int nover = 0;
    for (int k = 0; k < NKEY; k++) {
        int ina = 0, inb = 0;
        for (int i = 0; i < ka; i++) ina |= strcmp(na[i], key_channel[k]) == 0;
        for (int j = 0; j < kb; j++) inb |= strcmp(nb[j], key_channel[k]) == 0;
        if (!ina || !inb) continue;
        char why[256];
        rate(c, sa, sb, key_channel[k], 1, why, sizeof why);
        nover++;
    }
    fputs("</div>\n<table><tr><th>channel</th><th>R</th><th>grade</th></tr>\n", c->f);
    int nrated = 0, nshared = 0;
    for (int i = 0; i < ka; i++) {
        int inb = 0;
        for (int j = 0; j < kb && !inb; j++) inb = strcmp(na[i], nb[j]) == 0;
        if (!inb) continue;
        nshared++;
        if (nrated >= RP_MAXRATE) continue;
        char why[256];
        double v = rate(c, sa, sb, na[i], nover == 0 && nrated < 4 && !is_key(na[i]), why,
                        sizeof why);
        fputs("<tr><td>", c->f);
        rp_esc(c, na[i]);
        if (isfinite(v)) fprintf(c->f, "</td><td class=\"n\">%.3f</td><td>%s</td></tr>\n", v,
                                 an_iso_grade(v));
        else {
            fputs("</td><td>-</td><td>", c->f);
            rp_esc(c, why);
            fputs("</td></tr>\n", c->f);
        }
        nrated++;
    }
    fputs("</table>\n", c->f);
    if (nshared > nrated)
        fprintf(c->f, "<p class=\"note\">%d of %d shared channels rated (the first in the "
                      "file's order); <code>mcrash compare FILE --stages %d,%d</code> rates "
                      "them all.</p>\n",
                nrated, nshared, sa, sb);
}

void rp_compare(tr_rp *c)
{
    int any = 0;
    for (int sa = 1; sa <= RP_NSTAGE; sa++)
        for (int sb = sa + 1; sb <= RP_NSTAGE; sb++) {
            char ga[32], gb[32];
            snprintf(ga, sizeof ga, "/stage%d/channels", sa);
            snprintf(gb, sizeof gb, "/stage%d/channels", sb);
            int ka, kb, shared = 0;
            char **na = rp_list(c, ga, &ka), **nb = rp_list(c, gb, &kb);
            for (int i = 0; i < ka && !shared; i++)
                for (int j = 0; j < kb && !shared; j++) shared = strcmp(na[i], nb[j]) == 0;
            if (shared) {
                if (!any)
                    rp_section(c, "stages", "Stage against stage");
                any = 1;
                pair(c, sa, sb, na, ka, nb, kb);
            }
            mcs_results_list_free(&na, ka);
            mcs_results_list_free(&nb, kb);
        }
    if (any)
        fputs("<p class=\"note\">R: ISO/TS 18571 rating of the later stage's curve against the "
              "earlier one's (excellent &gt; 0.94, good &gt; 0.80, fair &gt; 0.58, else "
              "poor).</p>\n</section>\n",
              c->f);
    else rp_skip(c, "stages", "no two stages with shared channels");
}

/* tr_retune_svg.c: retune's compared curves as SVG plots (tr_retune.h, docs/loop.md): the
 * target's wall force or fork angle against stage 1 before and after the retune, on the common
 * CFC-filtered grid, drawn with analysis/an_svg.h; the ISO/TS 18571 ratings in the legend. */
#include "translators/tr_retune.h"

#include "analysis/an_svg.h"

#include <math.h>
#include <stdlib.h>

void tr_rt_write_svg(FILE *f, const tr_rt_result *r, int angle, const char *title)
{
    const double W = 640, H = 400, s = angle ? 1 : 1e-3;
    const double *y[3] = {angle ? r->ta : r->tf, angle ? r->a0 : r->f0, angle ? r->a1 : r->f1};
    double lo = 0, hi = 0, *tms = malloc((size_t)(r->nt > 0 ? r->nt : 1) * sizeof(double));
    if (!tms) return;
    for (int i = 0; i < r->nt; i++) {
        tms[i] = 1e3 * r->t[i];
        for (int k = 0; k < 3; k++)
            if (isfinite(y[k][i])) lo = fmin(lo, s * y[k][i]), hi = fmax(hi, s * y[k][i]);
    }
    if (lo > -0.02 * hi) lo = 0; /* the filters' undershoot: no axis below zero for it */
    an_svg_axes a;
    an_svg_axes_fit(&a, 70, 34, W - 90, H - 84, 0, r->nt > 0 ? tms[r->nt - 1] : 1, lo, hi);
    an_svg_begin(f, W, H, title);
    fputs("<g font-weight=\"bold\">", f);
    an_svg_text(f, 8, 18, "start", 13, NULL, title);
    fputs("</g>\n", f);
    an_svg_draw_axes(f, &a, "time from the first row [ms]",
                     angle ? "fork angle [rad]" : "wall force [kN]");
    const char *col[3] = {"#000000", "#c03030", "#3050c0"}, *dash[3] = {NULL, "6 4", NULL};
    const double wd[3] = {2, 1.5, 1.5};
    for (int k = 0; k < 3; k++)
        an_svg_path(f, &a, tms, y[k], (size_t)r->nt, s, col[k], wd[k], dash[k]);
    char l0[64], l1[64], l2[64];
    snprintf(l0, sizeof l0, "stage 3");
    snprintf(l1, sizeof l1, "stage 1 before (ISO %.2f)", angle ? r->iso_angle0 : r->iso_force0);
    snprintf(l2, sizeof l2, "stage 1 after (ISO %.2f)", angle ? r->iso_angle : r->iso_force);
    const char *lab[3] = {l0, l1, l2};
    an_svg_legend(f, a.x0 + a.w - 205, a.y0 + 8, lab, col, dash, 3);
    an_svg_end(f);
    free(tms);
}

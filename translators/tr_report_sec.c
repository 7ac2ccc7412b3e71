/* tr_report_sec.c: the report's curve sections: energy balance, dummy channels, belt / airbag /
 * foam channels, force-crush of rigid walls, energy per part and per contact partner */
#include "analysis/an_svg.h"
#include "translators/tr_report_int.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define G0 9.80665 /* standard gravity [m/s^2], for accelerations shown in g */

/* how a SI unit is shown: scale and label ("m/s^2" -> g) */
static double display_unit(const char *si, const char **shown)
{
    static const struct {
        const char *si, *shown;
        double scale;
    } u[] = {{"m/s^2", "g", 1 / G0}, {"N", "kN", 1e-3}, {"N*m", "N m", 1},  {"m", "mm", 1e3},
             {"rad", "deg", 57.29577951308232}, {"Pa", "kPa", 1e-3}, {"m^3", "L", 1e3},
             {"m/s", "m/s", 1}, {"J", "J", 1}, {"K", "K", 1}, {"kg", "g", 1e3}};
    for (size_t i = 0; i < sizeof u / sizeof u[0]; i++)
        if (strcmp(si, u[i].si) == 0) {
            *shown = u[i].shown;
            return u[i].scale;
        }
    *shown = si[0] ? si : "-";
    return 1;
}

/* what a SI unit measures, for an axis title */
static const char *quantity(const char *si)
{
    static const char *q[][2] = {{"m/s^2", "acceleration"}, {"N", "force"}, {"N*m", "moment"},
                                 {"m", "displacement"},     {"Pa", "pressure"}, {"m^3", "volume"},
                                 {"K", "temperature"},      {"J", "energy"},  {"rad", "angle"},
                                 {"m/s", "velocity"},       {"kg", "mass"}};
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++)
        if (strcmp(si, q[i][0]) == 0) return q[i][1];
    return "value";
}

/* datasets path_fmt % name[i] of one stage (each [nt] at /stageN/time) in one plot; a name not
 * in the file is left out; resultant adds |(first three)|. Returns 1 when drawn */
static int plot_group(tr_rp *c, int s, const char *title, const char *const *label,
                      const char *const *path, int n, int resultant, int cfc_in_title)
{
    const mcs_array *t = &c->time[s];
    mcs_array a[8];
    rp_series ser[9];
    int ns = 0, cfc[8];
    char unit[32] = "";
    for (int i = 0; i < n && i < 8; i++) {
        if (rp_read(c, path[i], &a[ns]) || a[ns].rank != 1 || a[ns].n != t->n || t->n < 2) {
            mcs_array_free(&a[ns]);
            continue;
        }
        if (!unit[0]) snprintf(unit, sizeof unit, "%s", a[ns].unit);
        double v = 0;
        mcs_error e = {0};
        cfc[ns] = mcs_results_has_attr(c->r, path[i], "cfc") &&
                          !mcs_results_attr_double(c->r, path[i], "cfc", &v, &e)
                      ? (int)v
                      : -1;
        ser[ns] = (rp_series){.x = t->v, .y = a[ns].v, .n = t->n, .label = label[i]};
        ns++;
    }
    if (!ns) return 0;
    double *res = NULL;
    if (resultant && ns >= 3) {
        res = malloc(sizeof *res * t->n);
        for (size_t k = 0; res && k < t->n; k++)
            res[k] = sqrt(a[0].v[k] * a[0].v[k] + a[1].v[k] * a[1].v[k] + a[2].v[k] * a[2].v[k]);
        if (res) ser[ns] = (rp_series){.x = t->v, .y = res, .n = t->n, .label = "resultant",
                                       .color = "#222"};
    }
    const char *shown;
    double scale = display_unit(unit, &shown);
    char full[160], ylab[64];
    snprintf(full, sizeof full, "%s", title);
    if (cfc_in_title) { /* the filter classes of the channels, each once */
        int seen[8], nseen = 0;
        for (int i = 0; i < ns; i++) {
            int dup = 0;
            for (int j = 0; j < nseen; j++) dup |= seen[j] == cfc[i];
            if (!dup) seen[nseen++] = cfc[i];
        }
        size_t k = strlen(full);
        for (int j = 0; j < nseen && k < sizeof full - 24; j++, k = strlen(full)) {
            const char *sep = j ? "/" : ", ";
            if (seen[j] < 0) snprintf(full + k, sizeof full - k, "%sCFC not recorded", sep);
            else if (seen[j] == 0) snprintf(full + k, sizeof full - k, "%sunfiltered", sep);
            else snprintf(full + k, sizeof full - k, "%sCFC %d", sep, seen[j]);
        }
    }
    snprintf(ylab, sizeof ylab, "%s [%s]", quantity(unit), shown);
    rp_plot p = {.title = full, .xlabel = "time [ms]", .ylabel = ylab, .xscale = 1e3,
                 .yscale = scale, .ymin0 = NAN, .ymax0 = NAN};
    rp_lines(c, &p, ser, ns + (res ? 1 : 0));
    free(res);
    for (int i = 0; i < ns; i++) mcs_array_free(&a[i]);
    return 1;
}

/* ---- energy balance ---------------------------------------------------------------------- */

void rp_energy(tr_rp *c)
{
    int any = 0;
    for (int s = 1; s <= RP_NSTAGE; s++) {
        char g[64];
        snprintf(g, sizeof g, "/stage%d/energy", s);
        int n;
        char **names = rp_list(c, g, &n);
        if (!n || c->time[s].n < 2) {
            mcs_results_list_free(&names, n);
            continue;
        }
        if (!any) rp_section(c, "energy", "Energy balance");
        any = 1;
        fputs("<div class=\"plots\">\n", c->f);
        const mcs_array *t = &c->time[s];
        mcs_array a[16];
        rp_series ser[16];
        int ns = 0;
        double emax = 0;
        for (int i = 0; i < n && ns < 16; i++) {
            char path[160];
            snprintf(path, sizeof path, "%s/%s", g, names[i]);
            if (rp_read(c, path, &a[ns]) || a[ns].n != t->n) {
                mcs_array_free(&a[ns]);
                continue;
            }
            for (size_t k = 0; k < a[ns].n; k++)
                if (fabs(a[ns].v[k]) > emax) emax = fabs(a[ns].v[k]);
            int total = strcmp(names[i], "total") == 0;
            ser[ns] = (rp_series){.x = t->v, .y = a[ns].v, .n = t->n, .label = names[i],
                                  .color = total ? "#222" : NULL, .dash = total ? "6 3" : NULL};
            ns++;
        }
        char title[64];
        snprintf(title, sizeof title, "Stage %d energies", s);
        int kj = emax >= 1e4;
        rp_plot p = {.title = title, .xlabel = "time [ms]",
                     .ylabel = kj ? "energy [kJ]" : "energy [J]", .xscale = 1e3,
                     .yscale = kj ? 1e-3 : 1, .ymin0 = 0, .ymax0 = NAN};
        rp_lines(c, &p, ser, ns);
        fputs("</div>\n<p class=\"note\">total = kinetic + potential + internal + contact + "
              "hourglass + dissipated (+ eroded) - external work: flat in a sound run.</p>\n",
              c->f);
        for (int i = 0; i < ns; i++) mcs_array_free(&a[i]);
        mcs_results_list_free(&names, n);
    }
    if (any) fputs("</section>\n", c->f);
    else rp_skip(c, "energy", "no /stageN/energy");
}

/* ---- dummy channels ---------------------------------------------------------------------- */

void rp_dummy(tr_rp *c)
{
    static const struct {
        const char *title, *prefix, *q[3];
        int resultant;
    } grp[] = {
        {"Head acceleration", "head_", {"ax", "ay", "az"}, 1},
        {"Chest acceleration", "chest_", {"ax", "ay", "az"}, 1},
        {"Pelvis acceleration", "pelvis_", {"ax", "ay", "az"}, 1},
        {"Upper neck forces", "neck_", {"fx", "fy", "fz"}, 0},
        {"Upper neck moments", "neck_", {"mx", "my", "mz"}, 0},
        {"Chest deflection", "chest_", {"d", NULL, NULL}, 0},
    };
    int any = 0;
    for (int s = 1; s <= RP_NSTAGE; s++) {
        int drawn = 0;
        for (size_t gi = 0; gi < sizeof grp / sizeof grp[0]; gi++) {
            char pbuf[3][96], lbuf[3][32];
            const char *path[3], *label[3];
            int n = 0;
            for (int k = 0; k < 3 && grp[gi].q[k]; k++, n++) {
                snprintf(pbuf[k], sizeof pbuf[k], "/stage%d/channels/%s%s", s, grp[gi].prefix,
                         grp[gi].q[k]);
                snprintf(lbuf[k], sizeof lbuf[k], "%s%s", grp[gi].prefix, grp[gi].q[k]);
                path[k] = pbuf[k];
                label[k] = lbuf[k];
            }
            int has = 0;
            for (int k = 0; k < n; k++) has |= mcs_results_kind(c->r, path[k]) == MCS_RES_DATASET;
            if (!has) continue;
            if (!any) {
                rp_section(c, "dummy", "Dummy channels");
                fputs("<p class=\"note\">SAE J211 sensor frames (x forward, y right, z down); "
                      "the filter class is the channel's <code>cfc</code> attribute.</p>\n",
                      c->f);
                any = 1;
            }
            if (!drawn) {
                char h[32];
                snprintf(h, sizeof h, "Stage %d", s);
                rp_h3(c, h);
                fputs("<div class=\"plots\">\n", c->f);
            }
            drawn += plot_group(c, s, grp[gi].title, label, path, n, grp[gi].resultant, 1);
        }
        if (drawn) fputs("</div>\n", c->f);
    }
    if (any) fputs("</section>\n", c->f);
    else rp_skip(c, "dummy", "no head, chest, pelvis or neck channels");
}

/* ---- belt, airbag, foam ------------------------------------------------------------------ */

/* the datasets quantity q of every member of /stageN/<kind> (q NULL: the internal energy of
 * parts named *foam*), at most 8; returns their count */
typedef struct {
    char path[8][160];
    char label[8][64];
} rp_members;

static int collect_members(tr_rp *c, int s, const char *kind, const char *q, rp_members *m)
{
    char g[64];
    snprintf(g, sizeof g, "/stage%d/%s", s, kind);
    int n, k = 0;
    char **names = rp_list(c, g, &n);
    for (int i = 0; i < n && k < 8; i++) {
        if (!q && !strstr(names[i], "foam")) continue;
        snprintf(m->path[k], sizeof m->path[k], "%s/%s/%s", g, names[i],
                 q ? q : "energy/internal");
        if (mcs_results_kind(c->r, m->path[k]) != MCS_RES_DATASET) continue;
        snprintf(m->label[k], sizeof m->label[k], "%s", names[i]);
        k++;
    }
    mcs_results_list_free(&names, n);
    return k;
}

void rp_restraints(tr_rp *c)
{
    static const struct {
        const char *kind, *q, *title;
    } item[] = {
        {"retractor", "force", "Belt force at the retractor"},
        {"retractor", "payout", "Belt payout (< 0 pulled in)"},
        {"slipring", "force1", "Belt force after the slip ring"},
        {"airbag", "pressure", "Airbag pressure (absolute)"},
        {"airbag", "volume", "Airbag volume"},
        {"airbag", "temperature", "Airbag gas temperature"},
        {"parts", NULL, "Foam internal energy"},
    };
    enum { NITEM = sizeof item / sizeof item[0] };
    int any = 0;
    static rp_members m[NITEM];
    for (int s = 1; s <= RP_NSTAGE; s++) {
        if (c->time[s].n < 2) continue;
        int k[NITEM], total = 0;
        for (int i = 0; i < NITEM; i++) total += k[i] = collect_members(c, s, item[i].kind,
                                                                          item[i].q, &m[i]);
        if (!total) continue;
        if (!any) rp_section(c, "restraints", "Belts, airbags and foam");
        any = 1;
        char h[32];
        snprintf(h, sizeof h, "Stage %d", s);
        rp_h3(c, h);
        fputs("<div class=\"plots\">\n", c->f);
        for (int i = 0; i < NITEM; i++) {
            const char *path[8], *label[8];
            for (int j = 0; j < k[i]; j++) {
                path[j] = m[i].path[j];
                label[j] = m[i].label[j];
            }
            if (k[i]) plot_group(c, s, item[i].title, label, path, k[i], 0, 0);
        }
        fputs("</div>\n", c->f);
    }
    if (any) fputs("</section>\n", c->f);
    else rp_skip(c, "restraints", "no retractor, slipring, airbag or foam part");
}

/* ---- force-crush (stage 3 rigid walls) --------------------------------------------------- */

void rp_crush(tr_rp *c)
{
    int n;
    char **walls = rp_list(c, "/stage3/rigidwall", &n);
    mcs_array fa[8], da[8];
    rp_series fd[8], ft[8];
    int k = 0;
    for (int i = 0; i < n && k < 8; i++) {
        char pf[160], pd[160];
        snprintf(pf, sizeof pf, "/stage3/rigidwall/%s/force", walls[i]);
        snprintf(pd, sizeof pd, "/stage3/rigidwall/%s/displacement", walls[i]);
        if (rp_read(c, pf, &fa[k])) continue;
        if (rp_read(c, pd, &da[k]) || da[k].n != fa[k].n) {
            mcs_array_free(&fa[k]);
            mcs_array_free(&da[k]);
            continue;
        }
        fd[k] = (rp_series){.x = da[k].v, .y = fa[k].v, .n = fa[k].n, .label = walls[i]};
        ft[k] = fd[k];
        ft[k].x = c->time[3].v;
        if (c->time[3].n != fa[k].n) ft[k].n = 0;
        k++;
    }
    if (k) {
        rp_section(c, "crush", "Force-crush (stage 3 rigid walls)");
        fputs("<div class=\"plots\">\n", c->f);
        rp_plot p = {.title = "Wall force against crush", .xlabel = "crush [mm]",
                     .ylabel = "force [kN]", .xscale = 1e3, .yscale = 1e-3, .ymin0 = 0,
                     .ymax0 = NAN};
        rp_lines(c, &p, fd, k);
        rp_plot q = {.title = "Wall force", .xlabel = "time [ms]", .ylabel = "force [kN]",
                     .xscale = 1e3, .yscale = 1e-3, .ymin0 = 0, .ymax0 = NAN};
        rp_lines(c, &q, ft, k);
        fputs("</div></section>\n", c->f);
    } else {
        rp_skip(c, "crush", "no /stage3/rigidwall");
    }
    for (int i = 0; i < k; i++) {
        mcs_array_free(&fa[i]);
        mcs_array_free(&da[i]);
    }
    mcs_results_list_free(&walls, n);
}

/* ---- energy per part and per contact partner (stacked bars) ------------------------------ */

#define RP_MAXBAR 64
#define RP_MAXSTACK 12

/* vertical stacked bars: v[bar * RP_MAXSTACK + k] in the displayed unit; positive parts stack
 * up from 0, negative ones down */
static void stacked_bars(tr_rp *c, const char *title, const char *ylabel, char (*bar)[64],
                         int nbar, const char *const *stack, int nstack, const double *v)
{
    double lo = 0, hi = 0;
    for (int b = 0; b < nbar; b++) {
        double up = 0, dn = 0;
        for (int k = 0; k < nstack; k++) {
            double x = v[b * RP_MAXSTACK + k];
            if (x > 0) up += x;
            else dn += x;
        }
        if (up > hi) hi = up;
        if (dn < lo) lo = dn;
    }
    double bw = nbar > 12 ? 22 : 40, W = 64 + nbar * (bw + 10) + 180, H = 330;
    if (W < 420) W = 420;
    an_svg_axes a;
    an_svg_axes_fit(&a, 64, 28, nbar * (bw + 10) + 10, 190, 0, 1, lo, hi);
    FILE *f = c->f;
    an_svg_begin(f, W, H, title);
    fputs("<g font-weight=\"bold\">", f);
    an_svg_text(f, 8, 16, "start", 13, NULL, title);
    fputs("</g>\n", f);
    /* y axis only: the x axis holds names */
    for (int i = 0; i < a.nyt; i++) {
        char lb[32];
        double y = an_svg_py(&a, a.yt[i]);
        an_svg_line(f, a.x0, y, a.x0 + a.w, y, i ? "#e4e4e4" : "#444", 1, NULL);
        an_svg_tick_label(a.yt[i], a.ystep, lb, sizeof lb);
        an_svg_text(f, a.x0 - 6, y + 4, "end", 0, NULL, lb);
    }
    an_svg_line(f, a.x0, an_svg_py(&a, 0), a.x0 + a.w, an_svg_py(&a, 0), "#444", 1, NULL);
    fprintf(f, "<text transform=\"translate(20 %.1f) rotate(-90)\" text-anchor=\"middle\" "
               "font-size=\"12\">",
            a.y0 + a.h / 2);
    an_svg_escape(f, ylabel);
    fputs("</text>\n", f);
    for (int b = 0; b < nbar; b++) {
        double x = a.x0 + 10 + b * (bw + 10), up = 0, dn = 0;
        for (int k = 0; k < nstack; k++) {
            double val = v[b * RP_MAXSTACK + k];
            if (val == 0 || !isfinite(val)) continue;
            double from = val > 0 ? up : dn, to = from + val;
            char tip[160];
            snprintf(tip, sizeof tip, "%s %s: %.4g", bar[b], stack[k], val);
            double y1 = an_svg_py(&a, val > 0 ? to : from);
            double y2 = an_svg_py(&a, val > 0 ? from : to);
            an_svg_rect(f, x, y1, bw, y2 - y1, an_svg_color(k), tip);
            if (val > 0) up = to;
            else dn = to;
        }
        fprintf(f, "<text transform=\"translate(%.1f %.1f) rotate(-35)\" text-anchor=\"end\">",
                x + bw / 2, a.y0 + a.h + 14);
        an_svg_escape(f, bar[b]);
        fputs("</text>\n", f);
    }
    const char *col[RP_MAXSTACK];
    for (int k = 0; k < nstack; k++) col[k] = an_svg_color(k);
    an_svg_legend(f, a.x0 + a.w + 12, a.y0, stack, col, NULL, nstack);
    an_svg_end(f);
    c->sum->nsvg++;
}

/* last finite value of a dataset, NaN when none */
static double last_value(tr_rp *c, const char *path)
{
    mcs_array a;
    double v = NAN;
    if (rp_read(c, path, &a)) return v;
    for (size_t i = a.n; i-- > 0;)
        if (isfinite(a.v[i])) {
            v = a.v[i];
            break;
        }
    mcs_array_free(&a);
    return v;
}

/* /stageN/parts/<part>/energy/<kind> at the end of the run, one bar per part; 1 when drawn */
static int parts_bars(tr_rp *c, int s)
{
    static const char *kind[] = {"kinetic", "internal", "dissipated", "contact", "hourglass"};
    const int nk = 5;
    char g[64];
    snprintf(g, sizeof g, "/stage%d/parts", s);
    int n;
    char **names = rp_list(c, g, &n);
    static char bar[RP_MAXBAR][64];
    static double v[RP_MAXBAR * RP_MAXSTACK];
    int nb = 0;
    double vmax = 0;
    for (int i = 0; i < n && nb < RP_MAXBAR; i++) {
        int have = 0;
        for (int k = 0; k < nk; k++) {
            char p[200];
            snprintf(p, sizeof p, "%s/%s/energy/%s", g, names[i], kind[k]);
            double x = last_value(c, p);
            v[nb * RP_MAXSTACK + k] = isfinite(x) ? x : 0;
            have |= isfinite(x);
            if (fabs(x) > vmax) vmax = fabs(x);
        }
        if (!have) continue;
        snprintf(bar[nb++], 64, "%s", names[i]);
    }
    mcs_results_list_free(&names, n);
    if (!nb) return 0;
    int kj = vmax >= 1e4;
    for (int i = 0; i < nb * RP_MAXSTACK; i++) v[i] *= kj ? 1e-3 : 1;
    char title[96];
    snprintf(title, sizeof title, "Stage %d energy per FE part at the end of the run", s);
    stacked_bars(c, title, kj ? "energy [kJ]" : "energy [J]", bar, nb, kind, nk, v);
    return 1;
}

/* /stageN/energy_groups/<group>/contact/<partner> at the end, summed by category: one bar
 * per group (the paper's Fig. 24); 1 when drawn */
static int group_bars(tr_rp *c, int s)
{
    char g[64];
    snprintf(g, sizeof g, "/stage%d/energy_groups", s);
    int n;
    char **groups = rp_list(c, g, &n);
    static char bar[RP_MAXBAR][64], cat[RP_MAXSTACK][32];
    static double v[RP_MAXBAR * RP_MAXSTACK];
    const char *stack[RP_MAXSTACK];
    int nb = 0, nc = 0;
    memset(v, 0, sizeof v);
    for (int i = 0; i < n && nb < RP_MAXBAR; i++) {
        char cg[200];
        snprintf(cg, sizeof cg, "%s/%s/contact", g, groups[i]);
        int np;
        char **partners = rp_list(c, cg, &np);
        for (int j = 0; j < np; j++) {
            char p[300], category[32];
            snprintf(p, sizeof p, "%s/%s", cg, partners[j]);
            rp_attr(c, p, "category", category, sizeof category);
            if (!category[0]) snprintf(category, sizeof category, "other");
            int k = 0;
            while (k < nc && strcmp(cat[k], category) != 0) k++;
            if (k == nc && nc < RP_MAXSTACK) snprintf(cat[nc++], 32, "%s", category);
            if (k >= nc) continue;
            double x = last_value(c, p);
            if (isfinite(x)) v[nb * RP_MAXSTACK + k] += x;
        }
        mcs_results_list_free(&partners, np);
        if (np) snprintf(bar[nb++], 64, "%s", groups[i]);
    }
    mcs_results_list_free(&groups, n);
    if (!nb) return 0;
    for (int k = 0; k < nc; k++) stack[k] = cat[k];
    char title[96];
    snprintf(title, sizeof title, "Stage %d energy given to each partner category", s);
    stacked_bars(c, title, "energy [J]", bar, nb, stack, nc, v);
    return 1;
}

void rp_parts(tr_rp *c)
{
    int any = 0;
    for (int s = 1; s <= RP_NSTAGE; s++) {
        char g1[64], g2[64];
        snprintf(g1, sizeof g1, "/stage%d/parts", s);
        snprintf(g2, sizeof g2, "/stage%d/energy_groups", s);
        if (mcs_results_kind(c->r, g1) != MCS_RES_GROUP &&
            mcs_results_kind(c->r, g2) != MCS_RES_GROUP)
            continue;
        if (!any) rp_section(c, "parts", "Energy per part and per contact partner");
        any = 1;
        fputs("<div class=\"plots\">\n", c->f);
        parts_bars(c, s);
        group_bars(c, s);
        fputs("</div>\n", c->f);
    }
    if (any) fputs("</section>\n", c->f);
    else rp_skip(c, "parts", "no /stageN/parts or energy_groups");
}

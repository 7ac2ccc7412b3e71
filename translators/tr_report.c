/* tr_report.c: `mcrash report`'s page (tr_report.h): the checks of the input, the page head
 * and summary, the sections in order, and the temporary renamed when complete */
#include "translators/tr_report.h"
#include "translators/tr_report_int.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

tr_report_opts tr_report_opts_default(void)
{
    return (tr_report_opts){.snapshot_dt = 0.020, .max_frames = 24};
}

static const char *page_css =
    "body{font-family:sans-serif;margin:16px 24px;color:#222;max-width:1280px}"
    "h1{font-size:22px;margin:4px 0}h2{font-size:18px;border-bottom:2px solid #1f77b4;"
    "padding-bottom:3px;margin-top:28px}h3{font-size:14px;margin:14px 0 4px}"
    ".plots{display:flex;flex-wrap:wrap;gap:6px 10px}"
    "table{border-collapse:collapse;font-size:12px;margin:6px 0}"
    "td,th{border:1px solid #ccc;padding:2px 6px;text-align:left}"
    "th{background:#f0f4f8}td.n{text-align:right;font-variant-numeric:tabular-nums}"
    "tr.over td{background:#fde2e2}.note{color:#666;font-size:12px}"
    "nav a{margin-right:12px}";

/* "name: ..." of the scenario text kept in /meta, into buf */
static void scenario_name(tr_rp *c, char *buf, size_t n)
{
    char *text = NULL;
    mcs_error e = {0};
    buf[0] = 0;
    if (!mcs_results_has_attr(c->r, "/meta", "scenario") ||
        mcs_results_attr_str(c->r, "/meta", "scenario", &text, &e))
        return;
    for (const char *p = text; p && *p;) {
        if (strncmp(p, "name:", 5) == 0) {
            p += 5;
            while (*p == ' ' || *p == '"' || *p == '\'') p++;
            size_t k = strcspn(p, "\"'\n#");
            while (k > 0 && p[k - 1] == ' ') k--;
            snprintf(buf, n, "%.*s", (int)k, p);
            break;
        }
        p = strchr(p, '\n');
        if (p) p++;
    }
    free(text);
}

static void write_head(tr_rp *c, FILE *f)
{
    char name[256], ver[64], created[64], dummy[32];
    scenario_name(c, name, sizeof name);
    rp_attr(c, "/meta", "mcrash_version", ver, sizeof ver);
    rp_attr(c, "/meta", "created", created, sizeof created);
    fputs("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>mcrash "
          "report: ",
          f);
    FILE *keep = c->f;
    c->f = f;
    rp_esc(c, name[0] ? name : c->h5);
    fprintf(f, "</title>\n<style>%s</style></head><body>\n<h1>mcrash report: ", page_css);
    rp_esc(c, name[0] ? name : c->h5);
    fputs("</h1>\n<table><tr><th>results file</th><td>", f);
    rp_esc(c, c->h5);
    fputs("</td></tr>\n<tr><th>written by</th><td>mcrash ", f);
    rp_esc(c, ver);
    fputs(" (", f);
    rp_esc(c, created);
    fputs(")</td></tr>\n", f);
    for (int s = 1; s <= RP_NSTAGE; s++) {
        if (!c->has_stage[s]) continue;
        char g[32];
        snprintf(g, sizeof g, "/stage%d", s);
        rp_attr(c, g, "dummy", dummy, sizeof dummy);
        const mcs_array *t = &c->time[s];
        fprintf(f, "<tr><th>stage %d</th><td>", s);
        if (t->n > 1)
            fprintf(f, "%.1f to %.1f ms, %zu samples", 1e3 * t->v[0], 1e3 * t->v[t->n - 1],
                    t->n);
        else fputs("no time axis", f);
        if (dummy[0]) {
            fputs(", dummy Hybrid III ", f);
            rp_esc(c, dummy);
        }
        fputs("</td></tr>\n", f);
    }
    fputs("</table>\n<nav>", f);
    char *list = strdup(c->sum->sections);
    for (char *tok = list ? strtok(list, ",") : NULL; tok; tok = strtok(NULL, ","))
        fprintf(f, "<a href=\"#%s\">%s</a>", tok, tok);
    free(list);
    fputs("</nav>\n", f);
    if (c->sum->skipped[0]) {
        fputs("<p class=\"note\">not in this file: ", f);
        rp_esc(c, c->sum->skipped);
        fputs("</p>\n", f);
    }
    c->f = keep;
}

/* the input checks: a readable HDF5 file with a /stageN group, or a study file (/study) */
static mcs_status open_input(tr_rp *c, const char *h5, mcs_error *err)
{
    struct stat st;
    if (stat(h5, &st) != 0)
        return MCS_ERR(err, MCS_ERR_IO, "%s: %s", h5, strerror(errno));
    if (!S_ISREG(st.st_mode) || !mcs_results_is_hdf5(h5))
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: not an HDF5 results file", h5);
    mcs_status s = mcs_results_open(&c->r, h5, err);
    if (s) return s;
    int any = 0;
    for (int k = 1; k <= RP_NSTAGE; k++) {
        char g[32];
        snprintf(g, sizeof g, "/stage%d", k);
        c->has_stage[k] = mcs_results_kind(c->r, g) == MCS_RES_GROUP;
        any |= c->has_stage[k];
        snprintf(g, sizeof g, "/stage%d/time", k);
        if (c->has_stage[k] && rp_read(c, g, &c->time[k]) == 0 && c->time[k].rank != 1)
            mcs_array_free(&c->time[k]);
    }
    c->study = mcs_results_kind(c->r, "/study") == MCS_RES_GROUP;
    if (!any && !c->study)
        return MCS_ERR(err, MCS_ERR_FORMAT,
                       "%s: not an mcrash results file (no /stage1, /stage2, /stage3 or /study "
                       "group)",
                       h5);
    return MCS_OK;
}

static void close_input(tr_rp *c)
{
    for (int k = 0; k <= RP_NSTAGE; k++) mcs_array_free(&c->time[k]);
    mcs_results_close(&c->r);
}

mcs_status tr_report_check(const char *h5, mcs_error *err)
{
    tr_rp c = {.h5 = h5};
    mcs_status s = open_input(&c, h5, err);
    close_input(&c);
    return s;
}

/* the body of the page (sections) into a string */
static char *write_body(tr_rp *c, size_t *len)
{
    char *buf = NULL;
    c->f = open_memstream(&buf, len);
    if (!c->f) return NULL;
    if (c->study) {
        rp_study(c);
        fclose(c->f);
        c->f = NULL;
        return buf;
    }
    rp_energy(c);
    rp_injury(c);
    rp_dummy(c);
    rp_restraints(c);
    rp_crush(c);
    rp_parts(c);
    rp_compare(c);
    rp_kinematics(c);
    fclose(c->f);
    c->f = NULL;
    return buf;
}

mcs_status tr_report_write(const char *h5, const char *html, const tr_report_opts *o,
                           tr_report_summary *sum, mcs_error *err)
{
    tr_report_summary local;
    tr_rp c = {.h5 = h5, .o = o ? *o : tr_report_opts_default(), .sum = sum ? sum : &local,
               .svg_w = 600};
    memset(c.sum, 0, sizeof *c.sum);
    mcs_status s = open_input(&c, h5, err);
    if (s) {
        close_input(&c);
        return s;
    }
    size_t blen = 0;
    char *body = write_body(&c, &blen);
    if (!body) {
        close_input(&c);
        return MCS_ERR(err, MCS_ERR_NOMEM, "%s: no memory for the page", html);
    }
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", html, (long)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        free(body);
        close_input(&c);
        return MCS_ERR(err, MCS_ERR_IO, "%s: %s", html, strerror(errno));
    }
    write_head(&c, f);
    fwrite(body, 1, blen, f);
    fputs("<p class=\"note\">drawn by mcrash report; SI units inside, shown as the axes say."
          "</p>\n</body></html>\n",
          f);
    free(body);
    close_input(&c);
    long size = ftell(f);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad || rename(tmp, html) != 0) {
        int e = errno;
        remove(tmp);
        return MCS_ERR(err, MCS_ERR_IO, "%s: %s", html, strerror(e));
    }
    c.sum->bytes = size > 0 ? (size_t)size : 0;
    return MCS_OK;
}

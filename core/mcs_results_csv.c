/* mcs_results_csv.c: `mcrash export --csv` — the channels and energies of each stage as CSV. */
#include "core/mcs_results_export.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int mcs_results_stages(mcs_results *r, int *stages, int max)
{
    char **v = NULL;
    int n = 0, k = 0;
    mcs_error e = {0};
    if (mcs_results_list(r, "/", &v, &n, &e) != MCS_OK) return 0;
    for (int i = 0; i < n; i++) {
        int s, len = 0;
        char p[300];
        if (sscanf(v[i], "stage%d%n", &s, &len) != 1 || v[i][len] != 0 || s < 1) continue;
        snprintf(p, sizeof p, "/%s", v[i]);
        if (mcs_results_kind(r, p) != MCS_RES_GROUP || k >= max) continue;
        /* insertion sort: files list in creation order, stages go out ascending */
        int j = k++;
        for (; j > 0 && stages[j - 1] > s; j--) stages[j] = stages[j - 1];
        stages[j] = s;
    }
    mcs_results_list_free(&v, n);
    return k;
}

/* mkdir -p */
static mcs_status make_dir(const char *dir, mcs_error *err)
{
    char buf[4096];
    if (snprintf(buf, sizeof buf, "%s", dir) >= (int)sizeof buf)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s: directory name too long", dir);
    for (char *p = buf + 1;; p++) {
        if (*p != '/' && *p != 0) continue;
        char c = *p;
        *p = 0;
        struct stat sb;
        if (stat(buf, &sb) != 0) {
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return MCS_ERR(err, MCS_ERR_IO, "%s: cannot create directory: %s", buf,
                               strerror(errno));
        } else if (!S_ISDIR(sb.st_mode)) {
            return MCS_ERR(err, MCS_ERR_IO, "%s: not a directory", buf);
        }
        *p = c;
        if (c == 0) break;
    }
    return MCS_OK;
}

/* a CSV header cell: quoted when it holds a comma or a quote */
static void put_cell(FILE *f, const char *name, const char *unit)
{
    char cell[512];
    snprintf(cell, sizeof cell, "%s [%s]", name, unit && *unit ? unit : "-");
    if (!strpbrk(cell, ",\"")) {
        fputs(cell, f);
        return;
    }
    fputc('"', f);
    for (const char *c = cell; *c; c++) {
        if (*c == '"') fputc('"', f);
        fputc(*c, f);
    }
    fputc('"', f);
}

typedef struct {
    int n;          /* columns after time */
    char **names;   /* dataset names       */
    mcs_array *col; /* their values        */
} csv_table;

static void table_free(csv_table *t)
{
    for (int i = 0; i < t->n; i++) mcs_array_free(&t->col[i]);
    free(t->col);
    mcs_results_list_free(&t->names, t->n);
    t->n = 0;
}

/* read every dataset of group: each must be [nt] */
static mcs_status read_table(mcs_results *r, const char *group, size_t nt, csv_table *t,
                             mcs_error *err)
{
    mcs_status st = mcs_results_list(r, group, &t->names, &t->n, err);
    if (st) return st;
    t->col = calloc((size_t)t->n + 1, sizeof *t->col);
    if (!t->col) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", group);
    for (int i = 0; i < t->n && !st; i++) {
        char p[1024];
        snprintf(p, sizeof p, "%s/%s", group, t->names[i]);
        if (mcs_results_kind(r, p) != MCS_RES_DATASET)
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: a group where a channel was expected",
                         mcs_results_path(r), p);
        if (!st) st = mcs_results_read(r, p, &t->col[i], err);
        if (!st && (t->col[i].rank != 1 || t->col[i].n != nt))
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: %zu values, but the stage has %zu times",
                         mcs_results_path(r), p, t->col[i].n, nt);
    }
    return st;
}

static mcs_status write_table(const char *path, const mcs_array *time, const csv_table *t,
                              mcs_error *err)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
    fputs("time [s]", f);
    for (int i = 0; i < t->n; i++) {
        fputs(", ", f);
        put_cell(f, t->names[i], t->col[i].unit);
    }
    fputc('\n', f);
    /* 15 significant digits: a double read back within 1e-15 relative; + 0.0 turns -0 into 0 */
    for (size_t k = 0; k < time->n; k++) {
        fprintf(f, "%.15g", time->v[k] + 0.0);
        for (int i = 0; i < t->n; i++) fprintf(f, ", %.15g", t->col[i].v[k] + 0.0);
        fputc('\n', f);
    }
    int bad = ferror(f);
    if (fclose(f) != 0 || bad || rename(tmp, path) != 0) {
        remove(tmp);
        return MCS_ERR(err, MCS_ERR_IO, "%s: write failed: %s", path, strerror(errno));
    }
    return MCS_OK;
}

/* /stageN/<group> → DIR/stageN_<group>.csv when the group has datasets */
static mcs_status export_group(mcs_results *r, int stage, const char *group, const char *dir,
                               int *nfiles, mcs_error *err)
{
    char g[64], tp[64], out[4096];
    snprintf(g, sizeof g, "/stage%d/%s", stage, group);
    if (mcs_results_kind(r, g) != MCS_RES_GROUP) return MCS_OK;
    char **names = NULL;
    int n = 0;
    mcs_status st = mcs_results_list(r, g, &names, &n, err);
    mcs_results_list_free(&names, n);
    if (st || n == 0) return st;
    snprintf(tp, sizeof tp, "/stage%d/time", stage);
    if (mcs_results_kind(r, tp) != MCS_RES_DATASET)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: %s has no %s to go with it",
                       mcs_results_path(r), g, tp);
    mcs_array time = {0};
    csv_table t = {0};
    st = mcs_results_read(r, tp, &time, err);
    if (!st && time.rank != 1)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: not a 1-D array", mcs_results_path(r), tp);
    if (!st) st = read_table(r, g, time.n, &t, err);
    if (!st && snprintf(out, sizeof out, "%s/stage%d_%s.csv", dir, stage, group) >= (int)sizeof out)
        st = MCS_ERR(err, MCS_ERR_USAGE, "%s: directory name too long", dir);
    if (!st) st = write_table(out, &time, &t, err);
    if (!st) (*nfiles)++;
    table_free(&t);
    mcs_array_free(&time);
    return st;
}

mcs_status mcs_results_export_csv(mcs_results *r, const char *dir, int *nfiles, mcs_error *err)
{
    *nfiles = 0;
    int stages[64];
    int ns = mcs_results_stages(r, stages, 64);
    if (ns == 0)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: no /stageN group: nothing to export (not an "
                                            "mcrash results file?)",
                       mcs_results_path(r));
    if (!dir || !*dir) return MCS_ERR(err, MCS_ERR_USAGE, "export --csv: no directory");
    mcs_status st = make_dir(dir, err);
    for (int i = 0; i < ns && !st; i++) {
        st = export_group(r, stages[i], "channels", dir, nfiles, err);
        if (!st) st = export_group(r, stages[i], "energy", dir, nfiles, err);
    }
    return st;
}

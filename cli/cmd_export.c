/* cmd_export.c: `mcrash export OUT.h5 --csv DIR | --xdmf [FILE.xmf] [--stride N]`
 * (--xdmf2 [FILE.xmf] writes XDMF 2 for ParaView's legacy "XDMF Reader")
 * | --k FILE [--stage N] [--deformed] [--units mm-s-t] [--long | --i10] (LS-DYNA keyword mesh,
 * translators/tr_keyword.h) | --mme DIR [--stage N] (ISO-MME, one test per stage,
 * translators/tr_mme.h) */
#include "cli/cli.h"
#include "core/mcs_results_export.h"
#include "fe/fe_out_mesh.h"
#include "translators/tr_keyword.h"
#include "translators/tr_mme.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *h5;      /* the results file            */
    const char *csv_dir; /* --csv DIR                   */
    int xdmf;            /* --xdmf given                */
    const char *xmf;     /* its FILE.xmf, NULL: default */
    mcs_xdmf_opts xo;
    const char *k;       /* --k FILE                    */
    const char *mme_dir; /* --mme DIR                   */
    tr_kw_export_opts ko;
} export_args;

static int ends_with(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && strcmp(s + a - b, suffix) == 0;
}

/* 0 ok, 2 usage error (message printed), 3 a part that is not built yet (printed) */
static int parse(int argc, char **argv, export_args *a)
{
    memset(a, 0, sizeof *a);
    a->xo = mcs_xdmf_opts_default();
    a->xo.cells = fe_out_cell_types(&a->xo.ncells);
    a->ko = tr_kw_export_opts_default();
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (strcmp(s, "--csv") == 0) {
            if (i + 1 >= argc) return cli_usage(argv[0]);
            a->csv_dir = argv[++i];
        } else if (strcmp(s, "--xdmf") == 0 || strcmp(s, "--xdmf2") == 0) {
            a->xdmf = 1;
            a->xo.legacy = strcmp(s, "--xdmf2") == 0;
            /* an optional FILE.xmf right after it */
            if (i + 1 < argc && argv[i + 1][0] != '-' &&
                (ends_with(argv[i + 1], ".xmf") || ends_with(argv[i + 1], ".xdmf")))
                a->xmf = argv[++i];
        } else if (strcmp(s, "--stride") == 0) {
            char *end;
            long v = i + 1 < argc ? strtol(argv[i + 1], &end, 10) : 0;
            if (i + 1 >= argc || *end || v < 1 || v > 1000000000) {
                fprintf(stderr, "mcrash export: --stride needs a whole number >= 1\n");
                return 2;
            }
            a->xo.stride = (int)v;
            i++;
        } else if (strcmp(s, "--k") == 0 || strcmp(s, "--units") == 0) {
            if (i + 1 >= argc) return cli_usage(argv[0]);
            if (s[2] == 'k') a->k = argv[++i];
            else a->ko.units = argv[++i];
        } else if (strcmp(s, "--stage") == 0) {
            char *end;
            long v = i + 1 < argc ? strtol(argv[i + 1], &end, 10) : 0;
            if (i + 1 >= argc || *end || v < 1 || v > 9) {
                fprintf(stderr, "mcrash export: --stage needs 1, 2 or 3\n");
                return 2;
            }
            a->ko.stage = (int)v;
            i++;
        } else if (strcmp(s, "--deformed") == 0) {
            a->ko.deformed = 1;
        } else if (strcmp(s, "--long") == 0 || strcmp(s, "--i10") == 0) {
            a->ko.fmt = s[2] == 'l' ? FE_KW_FIXED_LONG : FE_KW_FIXED_I10;
        } else if (strcmp(s, "--mme") == 0) {
            if (i + 1 >= argc) return cli_usage(argv[0]);
            a->mme_dir = argv[++i];
        } else if (s[0] == '-') {
            fprintf(stderr, "mcrash export: unknown option %s\n", s);
            return cli_usage(argv[0]);
        } else if (!a->h5) {
            a->h5 = s;
        } else {
            fprintf(stderr, "mcrash export: unexpected argument %s\n", s);
            return cli_usage(argv[0]);
        }
    }
    if (!a->h5 || (!a->csv_dir && !a->xdmf && !a->k && !a->mme_dir)) return cli_usage(argv[0]);
    return 0;
}

/* OUT.h5 -> OUT.xmf beside it */
static char *default_xmf(const char *h5)
{
    size_t n = strlen(h5);
    char *x = malloc(n + 8);
    if (!x) return NULL;
    memcpy(x, h5, n + 1);
    const char *slash = strrchr(x, '/');
    char *dot = strrchr(x, '.');
    if (dot && (!slash || dot > slash) && dot != x) *dot = 0;
    strcat(x, ".xmf");
    return x;
}

int cli_export(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    export_args a;
    int rc = parse(argc, argv, &a);
    if (rc) return 2;
    mcs_error err = {0};
    mcs_results *r = NULL;
    mcs_status st = mcs_results_open(&r, a.h5, &err);
    int nstage[64];
    if (!st && mcs_results_stages(r, nstage, 64) == 0)
        st = MCS_ERR(&err, MCS_ERR_FORMAT, "%s: no /stageN group: not an mcrash results file, "
                                           "or a run that wrote nothing",
                     a.h5);
    if (!st && a.csv_dir) {
        int nfiles = 0;
        st = mcs_results_export_csv(r, a.csv_dir, &nfiles, &err);
        if (!st && nfiles == 0)
            st = MCS_ERR(&err, MCS_ERR_FORMAT, "%s: no channels or energies to write as CSV",
                         a.h5);
        if (!st) printf("wrote %d CSV file%s in %s\n", nfiles, nfiles == 1 ? "" : "s", a.csv_dir);
    }
    if (!st && a.xdmf) {
        char *xmf = a.xmf ? NULL : default_xmf(a.h5);
        const char *out = a.xmf ? a.xmf : xmf;
        if (!out)
            st = MCS_ERR(&err, MCS_ERR_NOMEM, "out of memory");
        else
            st = mcs_results_export_xdmf(r, out, &a.xo, &err);
        if (!st) printf("wrote %s\n", out);
        free(xmf);
    }
    if (!st && a.k) {
        int nn = 0, ne = 0;
        st = tr_kw_export(r, a.k, &a.ko, &nn, &ne, &err);
        if (!st) printf("wrote %s (%d nodes, %d elements)\n", a.k, nn, ne);
    }
    if (!st && a.mme_dir) {
        int ns = 0, nc = 0;
        st = tr_mme_export(r, a.mme_dir, a.ko.stage, &ns, &nc, &err);
        if (!st)
            printf("wrote %d ISO-MME test%s (%d channels) in %s\n", ns, ns == 1 ? "" : "s", nc,
                   a.mme_dir);
    }
    mcs_results_close(&r);
    if (st) {
        fprintf(stderr, "mcrash export: %s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    return 0;
}

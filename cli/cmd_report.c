/* cmd_report.c: `mcrash report OUT.h5 [-o DIR]`: one self-contained HTML page of a results
 * file (translators/tr_report.h), DIR/<OUT>.html; DIR defaults to the results file's folder
 * and is created when missing. A missing or non-results file exits 2 and writes nothing */
#include "cli/cli.h"
#include "translators/tr_report.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* mkdir -p */
static int make_dirs(const char *dir)
{
    char p[4096];
    snprintf(p, sizeof p, "%s", dir);
    for (char *s = p + 1; *s; s++) {
        if (*s != '/') continue;
        *s = 0;
        if (mkdir(p, 0777) != 0 && errno != EEXIST) return -1;
        *s = '/';
    }
    return mkdir(p, 0777) != 0 && errno != EEXIST ? -1 : 0;
}

int cli_report(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    const char *h5 = NULL, *dir = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) dir = argv[++i];
        else if (argv[i][0] == '-' || h5) {
            fprintf(stderr, "mcrash report: unexpected argument %s\n", argv[i]);
            return cli_usage(argv[0]);
        } else h5 = argv[i];
    }
    if (!h5) return cli_usage(argv[0]);
    mcs_error err = {0};
    mcs_status st = tr_report_check(h5, &err);
    if (st) {
        fprintf(stderr, "mcrash report: %s\n", err.msg);
        return 2;
    }
    /* DIR/<basename without .h5>.html */
    const char *base = strrchr(h5, '/');
    base = base ? base + 1 : h5;
    size_t nb = strlen(base);
    if (nb > 3 && strcmp(base + nb - 3, ".h5") == 0) nb -= 3;
    char defdir[4096], html[8300];
    if (!dir) {
        snprintf(defdir, sizeof defdir, "%.*s", base > h5 ? (int)(base - h5 - 1) : 1,
                 base > h5 ? h5 : ".");
        if (!defdir[0]) snprintf(defdir, sizeof defdir, "/");
        dir = defdir;
    }
    if (make_dirs(dir) != 0) {
        fprintf(stderr, "mcrash report: %s: %s\n", dir, strerror(errno));
        return 2;
    }
    snprintf(html, sizeof html, "%s/%.*s.html", dir, (int)nb, base);
    tr_report_summary sum;
    st = tr_report_write(h5, html, NULL, &sum, &err);
    if (st) {
        fprintf(stderr, "mcrash report: %s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    printf("%s: %zu bytes, %d plots; sections: %s", html, sum.bytes, sum.nsvg, sum.sections);
    if (sum.skipped[0]) printf("; not in the file: %s", sum.skipped);
    printf("\n");
    return 0;
}

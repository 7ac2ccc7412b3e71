/* bench_keyword: time and memory to read a generated keyword deck of one million hexahedra
 * (100 x 100 x 100 cubes of 1 mm, 1 030 301 nodes; *PART, *SECTION_SOLID, *MAT_ELASTIC, *NODE,
 * *ELEMENT_SOLID in the standard fixed format, mm-ms-kg) written to a temporary folder and read
 * by fe_kw_read. Prints the file size, the seconds to read (wall and CPU) and the peak resident
 * memory (getrusage ru_maxrss) before and after; never fails on time. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "fe/fe_keyword.h"

static double clock_s(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double maxrss_mb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (double)ru.ru_maxrss / 1024.0; /* kB on Linux */
}

/* the deck of g x g x g cubes of 1 mm; node (i, j, k) has ID 1 + i + (g+1) (j + (g+1) k) */
static int write_deck(const char *path, int g)
{
    FILE *f = fopen(path, "w");
    if (!f) return perror(path), 1;
    fprintf(f, "*KEYWORD\n*TITLE\nbench: %d hexahedra\n*PART\nblock\n", g * g * g);
    fprintf(f, "%10d%10d%10d\n", 1, 1, 1);
    fprintf(f, "*SECTION_SOLID\n%10d%10d\n", 1, 1);
    fprintf(f, "*MAT_ELASTIC\n%10d%10.4g%10.4g%10.4g\n", 1, 7.85e-6, 210.0, 0.3);
    fprintf(f, "*NODE\n");
    const int n1 = g + 1;
    for (int k = 0; k <= g; k++)
        for (int j = 0; j <= g; j++)
            for (int i = 0; i <= g; i++)
                fprintf(f, "%8d%16.6f%16.6f%16.6f%8d%8d\n", 1 + i + n1 * (j + n1 * k), (double)i,
                        (double)j, (double)k, 0, 0);
    fprintf(f, "*ELEMENT_SOLID\n");
    int e = 0;
    for (int k = 0; k < g; k++)
        for (int j = 0; j < g; j++)
            for (int i = 0; i < g; i++) {
                const int a = 1 + i + n1 * (j + n1 * k), b = a + n1 * n1;
                fprintf(f, "%8d%8d%8d%8d%8d%8d%8d%8d%8d%8d\n", ++e, 1, a, a + 1, a + 1 + n1,
                        a + n1, b, b + 1, b + 1 + n1, b + n1);
            }
    fprintf(f, "*END\n");
    return fclose(f) != 0;
}

int main(void)
{
    const int g = 100;
    const char *tmp = getenv("TMPDIR");
    char dir[256], path[300];
    snprintf(dir, sizeof dir, "%s/mcs_bench_kw_XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(dir)) return perror("mkdtemp"), 1;
    snprintf(path, sizeof path, "%s/block.k", dir);
    double w0 = clock_s(CLOCK_MONOTONIC);
    if (write_deck(path, g)) return 1;
    double w1 = clock_s(CLOCK_MONOTONIC);
    struct stat sb;
    if (stat(path, &sb)) return perror(path), 1;
    const double rss0 = maxrss_mb();
    fe_kw_opts o = fe_kw_opts_default();
    o.units = "mm-ms-kg";
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    double t0 = clock_s(CLOCK_MONOTONIC), c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID);
    mcs_status st = fe_kw_read(path, &o, &d, &err);
    double t1 = clock_s(CLOCK_MONOTONIC), c1 = clock_s(CLOCK_PROCESS_CPUTIME_ID);
    const double rss1 = maxrss_mb();
    if (st) fprintf(stderr, "bench_keyword: %s\n", err.msg);
    else
        printf("keyword deck %d hexahedra, %d nodes, %.0f MB (written in %.2f s): read in %.2f s "
               "(CPU %.2f s), %.0f ns per element; peak memory %.0f MB (%.0f MB before the read, "
               "%.0f bytes per element)\n",
               d->elem[FE_KW_SOLID].n, d->nnode, (double)sb.st_size / 1048576.0, w1 - w0, t1 - t0,
               c1 - c0, 1e9 * (t1 - t0) / (double)d->elem[FE_KW_SOLID].n, rss1, rss0,
               (rss1 - rss0) * 1048576.0 / (double)d->elem[FE_KW_SOLID].n);
    fe_kw_deck_destroy(&d);
    unlink(path);
    rmdir(dir);
    return st ? 1 : 0;
}

/* bench_kw_read: the time and memory to read a generated keyword deck of 1 000 000 hexahedra
 * (a 100 x 100 x 100 block of 1 mm cubes, 1 030 301 nodes, standard fixed format, mm-s-t) with
 * fe_kw_read, then to build it into a model (fe_kw_add_deck, fe_model_create). Prints wall and
 * CPU seconds and the process's peak resident memory after each phase; never fails on time.
 * The deck is written to a temporary file and removed. */
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "fe/fe_keyword.h"
#include "fe/fe_model.h"

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* peak resident memory of the process so far [MB] */
static double peak_mb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (double)ru.ru_maxrss / 1024.0;
}

static int write_deck(FILE *f, int g)
{
    const int n1 = g + 1;
    fprintf(f, "*KEYWORD\n*TITLE\ngenerated block of %d hexahedra\n", g * g * g);
    fprintf(f, "*PART\nblock\n         1         1         1\n");
    fprintf(f, "*SECTION_SOLID\n         1         1\n");
    fprintf(f, "*MAT_ELASTIC\n         1   7.85e-9  210000.0       0.3\n*NODE\n");
    for (int k = 0; k < n1; k++)
        for (int j = 0; j < n1; j++)
            for (int i = 0; i < n1; i++)
                fprintf(f, "%8d%16.1f%16.1f%16.1f\n", 1 + i + n1 * (j + n1 * k), (double)i,
                        (double)j, (double)k);
    fprintf(f, "*ELEMENT_SOLID\n");
    int e = 0;
    for (int k = 0; k < g; k++)
        for (int j = 0; j < g; j++)
            for (int i = 0; i < g; i++) {
                int a = 1 + i + n1 * (j + n1 * k), up = n1 * n1;
                fprintf(f, "%8d%8d%8d%8d%8d%8d%8d%8d%8d%8d\n", ++e, 1, a, a + 1, a + 1 + n1,
                        a + n1, a + up, a + 1 + up, a + 1 + n1 + up, a + n1 + up);
            }
    fprintf(f, "*END\n");
    return ferror(f);
}

int main(void)
{
    const int g = 100;
    char path[] = "/tmp/mcrash_bench_kw_XXXXXX";
    int fd = mkstemp(path);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f || write_deck(f, g) || fclose(f)) {
        fprintf(stderr, "bench_kw_read: cannot write %s\n", path);
        return 1;
    }
    long bytes = 0;
    FILE *r = fopen(path, "rb");
    if (r && fseek(r, 0, SEEK_END) == 0) bytes = ftell(r);
    if (r) fclose(r);
    double m0 = peak_mb();
    fe_kw_opts o = fe_kw_opts_default();
    o.units = "mm-s-t";
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    double w0 = wall_now(), c0 = cpu_now();
    mcs_status st = fe_kw_read(path, &o, &d, &err);
    double w1 = wall_now(), c1 = cpu_now(), m1 = peak_mb();
    remove(path);
    if (st) {
        fprintf(stderr, "bench_kw_read: %s\n", err.msg);
        return 1;
    }
    printf("kw read: %d nodes, %d hexahedra, %.0f MB deck: %.2f s wall, %.2f s CPU, peak "
           "memory %.0f MB (%.0f MB before)\n",
           d->nnode, d->elem[FE_KW_SOLID].n, (double)bytes / 1048576.0, w1 - w0, c1 - c0, m1, m0);
    fe_builder *b = NULL;
    fe_model *m = NULL;
    st = fe_builder_create(&b, &err);
    if (!st) st = fe_kw_add_deck(b, d, &err);
    fe_kw_deck_destroy(&d);
    if (!st) st = fe_model_create(b, NULL, &m, &err);
    double w2 = wall_now(), c2 = cpu_now(), m2 = peak_mb();
    if (st) fprintf(stderr, "bench_kw_read: build: %s\n", err.msg);
    else
        printf("kw build: deck into a model: %.2f s wall, %.2f s CPU, peak memory %.0f MB\n",
               w2 - w1, c2 - c1, m2);
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    return st ? 1 : 0;
}

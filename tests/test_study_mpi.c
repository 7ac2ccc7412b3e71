/* test_study_mpi.c: `mpirun -n 2 --oversubscribe mcrash study` (cli/study_mpi.c) spreads the
 * 2x2 headform study over two ranks and writes the same study file, byte for byte, as `-j 2`.
 * Skipped (passing, with a note) where mpirun or bin/mcrash-mpi is absent; `make deps`
 * installs OpenMPI, so CI runs it. */
#include "cli_util.h"
#include "harness.h"

#include <sys/stat.h>

static char tmp[64];

static int have_mpi(void)
{
    char mpi[4200];
    struct stat st;
    snprintf(mpi, sizeof mpi, "%s-mpi", cli_bin());
    if (stat(mpi, &st) != 0) {
        printf("test_study_mpi: %s not built (no mpicc): skipped\n", mpi);
        return 0;
    }
    if (system("command -v mpirun >/dev/null 2>&1") != 0) {
        printf("test_study_mpi: mpirun not found: skipped\n");
        return 0;
    }
    return 1;
}

static void test_mpi_same_file(void)
{
    if (!have_mpi()) return;
    char cmd[1024], a[128], b[128];
    snprintf(a, sizeof a, "%s/j2.h5", tmp);
    snprintf(b, sizeof b, "%s/mpi.h5", tmp);
    snprintf(cmd, sizeof cmd, "study tests/data/study/head_drop_2x2.yaml -o %s -j 2 --quiet", a);
    CHECK(cli_run(cmd)->status == 0);
    snprintf(cmd, sizeof cmd,
             "timeout 120 mpirun -n 2 --oversubscribe %s study tests/data/study/head_drop_2x2.yaml "
             "-o %s --quiet > %s/mpi.log 2>&1",
             cli_bin(), b, tmp);
    int st = system(cmd);
    CHECK(st == 0);
    if (st) {
        char log[128];
        size_t n;
        snprintf(log, sizeof log, "%s/mpi.log", tmp);
        char *t = th_slurp(log, &n);
        if (t) fprintf(stderr, "%.*s\n", (int)(n < 4000 ? n : 4000), t);
        free(t);
    }
    size_t na = 0, nb = 0;
    char *fa = th_slurp(a, &na), *fb = th_slurp(b, &nb);
    CHECK(fa && fb && na == nb && na > 0 && memcmp(fa, fb, na) == 0);
    free(fa), free(fb);
}

int main(void)
{
    setenv("SOURCE_DATE_EPOCH", "0", 1);
    /* OpenMPI refuses root without these (containers, CI); LeakSanitizer would report
     * OpenMPI's own allocations at exit in the ASan build */
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    setenv("ASAN_OPTIONS", "detect_leaks=0", 1);
    snprintf(tmp, sizeof tmp, "/tmp/mcrash_mpi_XXXXXX");
    if (!mkdtemp(tmp)) return 1;
    RUN(test_mpi_same_file);
    char rm[128];
    snprintf(rm, sizeof rm, "rm -rf %s", tmp);
    if (system(rm)) fprintf(stderr, "could not remove %s\n", tmp);
    TEST_END();
}

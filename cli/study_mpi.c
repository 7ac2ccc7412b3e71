/* study_mpi.c: `mcrash study` under mpirun. Built twice: into bin/mcrash without MCS_MPI, where
 * a study started by mpirun (OMPI_COMM_WORLD_SIZE or PMI_SIZE > 1 in the environment) runs
 * bin/mcrash-mpi beside it with the same arguments; and with MCS_MPI by mpicc into
 * bin/mcrash-mpi (where mpicc exists), where rank r runs cases r, r + size, ... (each with up
 * to -j processes, as without MPI) and rank 0 gathers every case's result and writes the one
 * study file: the same bytes as `-j N` gives. */
#include "cli/study.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#ifdef MCS_MPI
#include <fcntl.h>
#include <mpi.h>
#endif

/* the world size mpirun gives in the environment (1 when not under mpirun) */
static int env_size(void)
{
    const char *v = getenv("OMPI_COMM_WORLD_SIZE");
    if (!v) v = getenv("PMI_SIZE");
    return v ? atoi(v) : 1;
}

#ifndef MCS_MPI
int study_mpi(int argc, char **argv, const char *path, const char *out, int jobs, int quiet)
{
    (void)argc, (void)path, (void)out, (void)jobs, (void)quiet;
    if (env_size() <= 1) return -1;
    char self[PATH_MAX], mpi[PATH_MAX + 16];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return -1;
    self[n] = 0;
    char *slash = strrchr(self, '/');
    snprintf(mpi, sizeof mpi, "%.*s/mcrash-mpi", slash ? (int)(slash - self) : 0, self);
    /* mcrash SUBCOMMAND ARGS: argv[0] is the subcommand, argv[-1] the program */
    char **args = calloc((size_t)argc + 2, sizeof *args);
    if (!args) return 2;
    args[0] = mpi;
    for (int i = 0; i < argc; i++)
        args[i + 1] = argv[i];
    execv(mpi, args);
    fprintf(stderr, "study: under mpirun but %s cannot run (%s): build it where mpicc exists "
            "(make deps installs OpenMPI)\n", mpi, strerror(errno));
    free(args);
    return 2;
}
#else
/* this rank's results for its cases sent to rank 0, which places them */
static void gather(const study *s, study_result *res, int rank, int size)
{
    int bytes = (int)(s->ncase * (long)sizeof *res);
    if (rank != 0) {
        MPI_Send(res, bytes, MPI_BYTE, 0, 17, MPI_COMM_WORLD);
        return;
    }
    study_result *buf = malloc((size_t)bytes);
    for (int r = 1; r < size; r++) {
        MPI_Recv(buf, bytes, MPI_BYTE, r, 17, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        for (long c = r; buf && c < s->ncase; c += size)
            res[c] = buf[c];
    }
    free(buf);
}

int study_mpi(int argc, char **argv, const char *path, const char *out, int jobs, int quiet)
{
    (void)argc, (void)argv;
    if (env_size() <= 1) return -1;
    int rank = 0, size = 1;
    MPI_Init(NULL, NULL);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (rank != 0) { /* one voice: rank 0's */
        int fd = open("/dev/null", O_WRONLY);
        if (fd >= 0) dup2(fd, 2), close(fd);
    }
    study s;
    int rc = study_load(path, &s); /* every rank: the same cases, the same checks */
    study_result *res = rc ? NULL : calloc((size_t)s.ncase, sizeof *res);
    char dir[4200];
    if (!rc && !res) rc = 2;
    if (!rc) rc = study_cases_dir(out, dir, sizeof dir);
    if (!rc) rc = study_probe(&s, dir);
    if (!rc) {
        if (!quiet && rank == 0)
            fprintf(stderr, "study: %ld cases of %s over %d ranks, %d at once each, in %s\n",
                    s.ncase, path, size, jobs, dir);
        study_run_cases(&s, dir, jobs, rank, size, res);
        gather(&s, res, rank, size);
        if (rank == 0) rc = study_write(&s, res, out);
        if (rank == 0 && !rc && !quiet) {
            long nfail = 0;
            for (long c = 0; c < s.ncase; c++)
                nfail += res[c].status != 0;
            fprintf(stderr, "study: %ld cases, %ld failed -> %s\n", s.ncase, nfail, out);
        }
    }
    MPI_Bcast(&rc, 1, MPI_INT, 0, MPI_COMM_WORLD);
    free(res);
    study_free(&s);
    MPI_Finalize();
    return rc;
}
#endif

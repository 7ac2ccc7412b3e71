/* study.h: `mcrash study` inside cli/ (cmd_study.c): the study file read into factors, cases
 * and responses (study_load.c), the cases run (study_run.c), the study file written and read
 * (study_file.c) and analysed (study_analyze.c). DESIGN.md "Studies", docs/contracts.md. */
#ifndef MCS_CLI_STUDY_H
#define MCS_CLI_STUDY_H

#include "core/mcs_scenario.h"

#include <stddef.h>
#include <stdio.h>
#include <stdint.h>

#define STUDY_NAME 128
#define STUDY_UNIT 32

typedef enum { STUDY_FULL, STUDY_FRACTIONAL, STUDY_LHS, STUDY_OAT, STUDY_ISO13232 } study_design;

#define STUDY_CODE 32 /* an ISO 13232 configuration code, "413-0/13.4" */

typedef struct {
    char path[STUDY_NAME]; /* key path in the scenario                                    */
    const mcs_node *at;    /* its path: node in the study file                             */
    int nlev;              /* levels (factorial, one at a time)                            */
    double *lev;           /* levels [SI] (nlev)                                           */
    double lo, hi;         /* range [SI] (Latin hypercube)                                 */
    double base;           /* one at a time: the base scenario's value [SI]                */
} study_factor;

typedef enum { STUDY_R_INJURY, STUDY_R_PEAK, STUDY_R_MAX, STUDY_R_MIN, STUDY_R_SCALAR } study_rkind;

typedef struct {
    char name[STUDY_NAME]; /* dataset name under /study/responses                          */
    char spec[256];        /* as written: "HIC15", "peak:/stage1/channels/head_az", ...     */
    const char *target;    /* criterion or dataset path inside spec                         */
    study_rkind kind;
    const mcs_node *at;
} study_response;

typedef struct {
    mcs_scenario *file;          /* the study file as read (mcs_yaml_load)                 */
    mcs_scenario *base;          /* the base scenario                                      */
    char scenario[4096];         /* its path as opened                                     */
    char stage[8];               /* "1" (default), "2", "3", "all"                          */
    study_design design;
    const char *design_name;
    uint64_t seed;               /* Latin hypercube                                         */
    int nfactor, nresp;
    study_factor *f;
    study_response *r;
    long ncase;
    double *x;                   /* factor values of each case [SI] (ncase x nfactor)       */
    /* compare: a second scenario run on every row of the design (docs/contracts.md): case c
     * is row c / nvar on the scenario (c % nvar == 0) or on the compared one (1) */
    mcs_scenario *alt;
    char alt_path[4096];
    int nvar;                    /* 1, or 2 with compare:                                    */
    long nrow;                   /* rows of the design (ncase / nvar)                        */
    char (*code)[STUDY_CODE];    /* iso13232: each row's configuration code (nrow)           */
    int nset;                    /* set: settings applied to every case                     */
    mcs_scn_setting *set;
} study;

/* one case's outcome (fixed size: gathered across processes as bytes) */
#define STUDY_MAXRESP 64
typedef struct {
    int status;                           /* 0 done, else the run's exit status (128+signal) */
    double v[STUDY_MAXRESP];              /* responses, NaN when missing or failed           */
    char unit[STUDY_MAXRESP][STUDY_UNIT]; /* their units                                     */
} study_result;

/* read and check the study file, every case's scenario built and validated; on error print
 * it (FILE:LINE:COL) and return 2, else 0 */
int study_load(const char *path, study *s);
void study_free(study *s);

/* the SI value of a level node v (or num when v is NULL) at factor f's key: the base scenario
 * with it set and validated; 2 with the message printed (FILE:LINE:COL) */
int study_level_si(study *s, const study_factor *f, const mcs_node *v, double num, double *out);

/* the iso13232 design (study_iso.c) from the study file's design: map: s->f (the impact keys
 * set per row), s->nrow rows in s->x and their codes; 0, or 2 with the message printed */
int study_iso_rows(study *s, const mcs_node *d);

/* with compare: the pairs: STUDY_pairs.csv (per row and response: base, compare, compare -
 * base) and /study/difference/<response> written by study_write; the summary printed */
int study_write_pairs(const study *s, const study_result *res, const char *csv);
void study_pairs_summary(const study *s, const study_result *res, FILE *out);

/* the case's scenario (the base, or the compared one, with set: and the case's factor values,
 * and its configuration code, set) */
mcs_status study_case_scenario(const study *s, long c, mcs_scenario **out, mcs_error *err);

/* run case c in a child process into dir/case_NNNN.h5 (its messages in case_NNNN.log) and
 * evaluate its responses into res; start only (study_case_start) and finish (study_case_wait)
 * let several run at once */
int study_case_start(const study *s, long c, const char *dir); /* pid, -1 when fork failed */
void study_case_finish(const study *s, long c, const char *dir, int wstatus, study_result *res);

/* the response datasets checked on a two-step run of the base scenario (stage 1): 2 with the
 * response's FILE:LINE:COL printed when one is missing, else 0 */
int study_probe(const study *s, const char *dir);

/* every case with up to jobs at once (cases first..ncase-1 by step stride: a rank's share) */
void study_run_cases(const study *s, const char *dir, int jobs, long first, long stride,
                     study_result *res);

/* STUDY.h5 and STUDY.csv beside it; 0 done, else the exit status (message printed) */
int study_write(const study *s, const study_result *res, const char *out);

/* DIR for the cases: the output's name without .h5, and _cases (created); 0 or 2 */
int study_cases_dir(const char *out, char *dir, size_t n);

/* under mpirun: the study over the ranks (study_mpi.c), its exit status; -1 when not under
 * mpirun (then the caller runs it here) */
int study_mpi(int argc, char **argv, const char *path, const char *out, int jobs, int quiet);

/* `mcrash study --analyze STUDY.h5 [--json]` */
int study_analyze(const char *h5, int json);

/* the rest of --analyze (study_analyze_more.c): per response the stepwise selection and the
 * quadratic response surface, and the MANOVA of all responses (factorial designs); as text
 * sections, or (json) as the members ", \"stepwise\": ..., \"quadratic\": ..., \"manova\": ..." */
void study_analyze_more(long ncase, int k, const double *x, int nresp, double *const *y,
                        const char *const *fn, const char *const *rn, int factorial, int json);

#endif

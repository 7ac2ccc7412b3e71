/* tr_report_int.h: the insides of the report (tr_report*.c): the page being written and the
 * plot helpers the sections share */
#ifndef TR_REPORT_INT_H
#define TR_REPORT_INT_H

#include <stdio.h>

#include "core/mcs_results.h"
#include "translators/tr_report.h"

#define RP_NSTAGE 3

typedef struct {
    const char *h5;          /* the results file */
    mcs_results *r;          /* open for reading */
    FILE *f;                 /* the page */
    tr_report_opts o;
    int has_stage[RP_NSTAGE + 1];  /* 1 when /stageN is a group */
    mcs_array time[RP_NSTAGE + 1]; /* /stageN/time [s] (n = 0 when absent) */
    tr_report_summary *sum;
    int svg_w;               /* width of a line plot [px] */
    int study;               /* 1: a study file (/study): the study page */
} tr_rp;

/* one curve of a line plot: x [SI] and y [SI] with n samples, its legend label */
typedef struct {
    const double *x, *y;
    size_t n;
    const char *label;
    const char *color; /* NULL: the palette's */
    const char *dash;  /* NULL: solid */
} rp_series;

/* a line plot: displayed values are SI * scale ("time [ms]": xscale 1000) */
typedef struct {
    const char *title, *xlabel, *ylabel;
    double xscale, yscale;
    double ymin0, ymax0; /* the y range always includes these (NaN: nothing) */
} rp_plot;

/* draw one line plot as an <svg> with a legend on its right */
void rp_lines(tr_rp *c, const rp_plot *p, const rp_series *s, int ns);

/* read a dataset when it exists: 0 and *a filled, else -1 (a missing path is no error) */
int rp_read(tr_rp *c, const char *path, mcs_array *a);

/* a string attribute into buf ("" when absent) */
void rp_attr(tr_rp *c, const char *path, const char *name, char *buf, size_t n);

/* the members of a group (n = 0 when it does not exist); free with mcs_results_list_free */
char **rp_list(tr_rp *c, const char *group, int *n);

/* the section heading (and its anchor); the summary records it */
void rp_section(tr_rp *c, const char *id, const char *title);
/* a section left out: noted for the "not in this file" line */
void rp_skip(tr_rp *c, const char *id, const char *why);
/* "<h3>text</h3>" escaped */
void rp_h3(tr_rp *c, const char *text);
/* an HTML-escaped string */
void rp_esc(tr_rp *c, const char *s);

/* src into dst (n bytes), cut to fit */
void rp_copy(char *dst, size_t n, const char *src);

/* column k of an [n, w] array into a new array (free()) */
double *rp_column(const mcs_array *a, int k);
/* |row| of an [n, 3] array into a new array */
double *rp_norm3(const mcs_array *a);

/* the sections (tr_report_sec.c, tr_report_injury.c, tr_report_cmp.c, tr_report_kin.c) */
void rp_energy(tr_rp *c);
void rp_injury(tr_rp *c);
void rp_dummy(tr_rp *c);
void rp_restraints(tr_rp *c);
void rp_crush(tr_rp *c);
void rp_parts(tr_rp *c);
void rp_compare(tr_rp *c);
void rp_kinematics(tr_rp *c);
/* the study page of a STUDY.h5 (tr_report_study.c) */
void rp_study(tr_rp *c);

#endif

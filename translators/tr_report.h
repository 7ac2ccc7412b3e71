/* tr_report.h: `mcrash report`: one self-contained HTML page of a results file (no network,
 * no scripts, no external fonts): inline SVG plots drawn by analysis/an_svg.c. Sections, each
 * left out when the file lacks its data (listed at the top as "not in this file"):
 *   summary, energy balance per stage, injury criteria against their limits (bars, the 2023
 *   paper's Fig. 22), dummy channels (head, chest, pelvis accelerations, neck loads, with their
 *   CFC), belt / airbag / foam channels, force-crush of stage-3 rigid walls, energy per part
 *   and per contact partner (stacked bars), stage against stage overlays with their ISO/TS 18571
 *   ratings, kinematic snapshots (side and top views of the bodies and FE meshes, strips).
 * A study file (`mcrash study`'s STUDY.h5, a /study group) gets the study page instead: per
 * response the main-effect and two-factor interaction plots (tr_report_study.c).
 * The page is written to a temporary beside the output and renamed when complete: an error
 * leaves no page (and an earlier page as it was). */
#ifndef TR_REPORT_H
#define TR_REPORT_H

#include <stddef.h>

#include "core/mcs_error.h"

typedef struct {
    double snapshot_dt; /* interval of the kinematic snapshots [s] (20 ms) */
    int max_frames;     /* most snapshots per strip (24); the interval grows to fit */
} tr_report_opts;

tr_report_opts tr_report_opts_default(void);

typedef struct {
    size_t bytes;       /* size of the page [bytes] */
    int nsvg;           /* SVG plots drawn */
    int nsections;      /* sections written */
    char sections[512]; /* their ids, comma separated */
    char skipped[512];  /* sections left out, comma separated */
} tr_report_summary;

/* the input checks alone (as tr_report_write makes them): a readable HDF5 file with a
 * /stage1, /stage2, /stage3 or /study group */
mcs_status tr_report_check(const char *h5, mcs_error *err);

/* the page of results file h5 at html (e.g. "out/iso413.html"); sum may be NULL. A missing
 * file: MCS_ERR_IO; a file that is not HDF5 or has no /stage1../stage3 or /study group: MCS_ERR_FORMAT,
 * both naming the file */
mcs_status tr_report_write(const char *h5, const char *html, const tr_report_opts *o,
                           tr_report_summary *sum, mcs_error *err);

#endif

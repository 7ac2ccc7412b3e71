/* tr_keyword: a results file's FE mesh as an LS-DYNA keyword deck (`mcrash export --k`).
 * Parts of /stageN/mesh become *PART (PID = order in the file, heading = part name; SECID and
 * MID 0: the results file holds no section or material), their nodes *NODE with ID
 * node_offset + row + 1 (one node shared by parts is written once), their elements
 * *ELEMENT_SOLID (hex8; tet4 as N1 N2 N3 N4 N4 N4 N4 N4), *ELEMENT_SHELL (quad4; tri3 with
 * N4 = N3) or *ELEMENT_BEAM (line2). With `deformed` the coordinates are those of the last
 * row of /stageN/fields/displacement (the final output). docs/keyword.md. */
#ifndef TR_KEYWORD_H
#define TR_KEYWORD_H

#include "core/mcs_results.h"
#include "fe/fe_keyword.h"

typedef struct {
    int stage;          /* 0: the highest stage that has a mesh                          */
    int deformed;       /* coordinates at the final output                               */
    const char *units;  /* unit system of the written deck (NULL: m-s-kg)                */
    fe_kw_format fmt;   /* FE_KW_FIXED (default), FE_KW_FIXED_I10, FE_KW_FIXED_LONG       */
} tr_kw_export_opts;

tr_kw_export_opts tr_kw_export_opts_default(void);

/* the mesh of a results file as a deck (SI, dk->unit set from opts->units) */
mcs_status tr_kw_deck_from_results(mcs_results *r, const tr_kw_export_opts *o, fe_kw_deck **out,
                                   int *stage, mcs_error *err);

/* ... and written to path */
mcs_status tr_kw_export(mcs_results *r, const char *path, const tr_kw_export_opts *o,
                        int *nnode, int *nelem, mcs_error *err);

#endif

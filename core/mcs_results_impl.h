/* mcs_results_impl.h: private to core/mcs_results_*.c — the HDF5 handles behind the opaque
 * mcs_results. Nothing outside these files includes it. */
#ifndef MCS_RESULTS_IMPL_H
#define MCS_RESULTS_IMPL_H

#include <hdf5.h>

#include "core/mcs_results.h"

struct mcs_results_series {
    mcs_results *r;                     /* owner                                  */
    mcs_results_series *next;           /* owner's list                           */
    hid_t dset;                         /* the extendible dataset                 */
    int rank;                           /* 1..3                                   */
    hsize_t dims[MCS_RESULTS_MAXRANK];  /* current extent on file (dims[0] rows)  */
    size_t row_len;                     /* values per row                         */
    size_t chunk_rows;                  /* rows per chunk = rows in buf           */
    size_t nbuf;                        /* rows waiting in buf                    */
    double *buf;                        /* chunk_rows * row_len values            */
    char path[256];                     /* for messages                           */
};

struct mcs_results {
    hid_t file;                /* open file                                   */
    int writable;              /* 1 for a writer                              */
    int committed;             /* 1 once renamed                              */
    char *path;                /* final name                                  */
    char *tmp;                 /* temporary name of a writer                  */
    int tmp_slot;              /* its slot in core/mcs_interrupt.c, or -1     */
    mcs_results_series *series;
};

/* HDF5 failure → MCS_ERR_HDF5 "FILE:PATH: what (hdf5: innermost message)" */
mcs_status mcs_res_h5err(mcs_error *err, const mcs_results *r, const char *path,
                         const char *what);

/* the HDF5 error printer off, once per process */
void mcs_res_quiet(void);

/* create the groups leading to path (not the last component) with creation order tracked */
mcs_status mcs_res_make_parents(mcs_results *r, const char *path, mcs_error *err);

/* a group creation list tracking and indexing creation order (caller closes) */
hid_t mcs_res_gcpl(void);

/* write the `unit` attribute and the string/number attributes on an open object */
mcs_status mcs_res_attr_str_id(hid_t obj, const char *name, const char *value);
mcs_status mcs_res_attr_num_id(hid_t obj, const char *name, hid_t type, const void *value);

/* reject NULL, relative or overlong paths; rejects writes on a reader */
mcs_status mcs_res_check_path(const mcs_results *r, const char *path, int want_write,
                              mcs_error *err);

/* flush and release every series (on commit/abort) */
mcs_status mcs_res_series_flush_all(mcs_results *r, mcs_error *err);
void mcs_res_series_release_all(mcs_results *r);

#endif

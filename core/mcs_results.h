/* mcs_results: the results file of a run (HDF5), DESIGN.md "The results file (HDF5)".
 *
 * Writing: mcs_results_create() opens "OUT.h5.tmp.<pid>" beside OUT.h5; mcs_results_commit()
 * flushes, closes and renames it to OUT.h5; mcs_results_abort() (or destroying an uncommitted
 * writer) removes the temporary. A failed run therefore never leaves a partial file, and an
 * OUT.h5 from an earlier run stays as it was until a new one is complete.
 *
 * Every dataset carries a `unit` attribute ("-" for dimensionless); the write calls take it.
 * Paths are absolute ("/stage1/channels/head_ax"); missing groups are created on the way.
 * Groups keep the order their members were written in (creation order is tracked).
 *
 * Conventions beyond DESIGN.md (extensions, nothing renamed):
 *   /stageN/mesh/<part>/elements  int [ne,k], 0-based rows of that part's `nodes`;
 *                                 attr `type`: a cell type's name, ending in its node count k;
 *                                 the writer of the meshes owns the types and their node
 *                                 orders (fe/fe_out_mesh.h: line2, tri3, quad4, tet4, wedge6,
 *                                 hex8, tet10, as VTK / XDMF; without `type` the width decides)
 *   /stageN/mesh/<part>/elements_<type>  the same for the elements of another type when a part
 *                                 holds several (e.g. hexahedra in `elements`, the tetrahedra
 *                                 and wedges of the same part in elements_tet4, elements_wedge6)
 *   /stageN/mesh/<part>/nodes     attr `node_offset` (int): first row of this part in the
 *                                 stage's node numbering used by the arrays in /stageN/fields
 *   /stageN/fields/time           [nout] s: the output times of /stageN/fields/displacement
 *                                 (when absent, /stageN/time is used if it has nout rows)
 *
 * HDF5's own error printing is switched off; HDF5 failures become MCS_ERR_HDF5 (MCS_ERR_IO
 * when a file cannot be created or opened) with the file and the object path in the message.
 * The handle is opaque: no HDF5 type appears here. */
#ifndef MCS_RESULTS_H
#define MCS_RESULTS_H

#include <stddef.h>

#include "core/mcs_error.h"

typedef struct mcs_results mcs_results;               /* an open results file */
typedef struct mcs_results_series mcs_results_series; /* a dataset growing row by row */

#define MCS_RESULTS_MAXRANK 3

/* ---- lifecycle ------------------------------------------------------------------------- */

/* start a new results file `path` (written to a temporary until commit) with /meta:
 * mcrash_version, created (ISO 8601 UTC; SOURCE_DATE_EPOCH is honoured), scenario, units="SI".
 * scenario_text may be NULL (stored as ""). */
mcs_status mcs_results_create(mcs_results **out, const char *path, const char *scenario_text,
                              mcs_error *err);

/* continue an existing results file (a later stage adds its group): the file is copied to a
 * temporary, written there, and replaces `path` only on commit. /meta is kept. */
mcs_status mcs_results_append(mcs_results **out, const char *path, mcs_error *err);

/* flush every series, close, and rename the temporary to the final name. *r is freed and
 * nulled, also on failure (then the temporary is removed). */
mcs_status mcs_results_commit(mcs_results **r, mcs_error *err);

/* give up a run being written: close and remove the temporary. Safe on NULL. */
void mcs_results_abort(mcs_results **r);

/* remove a dataset or group (and what it holds) from a file being written; absent: nothing */
mcs_status mcs_results_remove(mcs_results *r, const char *path, mcs_error *err);

/* open a results file read-only */
mcs_status mcs_results_open(mcs_results **out, const char *path, mcs_error *err);

/* close a reader; on an uncommitted writer this is mcs_results_abort. Safe on NULL. */
void mcs_results_close(mcs_results **r);

/* name of the file (final name for a writer) */
const char *mcs_results_path(const mcs_results *r);

/* ---- writing whole arrays --------------------------------------------------------------- */

/* double array of rank 1..3 with dims[0..rank-1], row-major, at `path` */
mcs_status mcs_results_write(mcs_results *r, const char *path, int rank, const size_t *dims,
                             const double *data, const char *unit, mcs_error *err);

/* int array (element connectivity, ids) of rank 1..3 */
mcs_status mcs_results_write_int(mcs_results *r, const char *path, int rank, const size_t *dims,
                                 const int *data, const char *unit, mcs_error *err);

/* a scalar (an injury criterion) */
mcs_status mcs_results_write_scalar(mcs_results *r, const char *path, double value,
                                    const char *unit, mcs_error *err);

/* attributes on an existing group or dataset (replaced if present) */
mcs_status mcs_results_set_attr_str(mcs_results *r, const char *path, const char *name,
                                    const char *value, mcs_error *err);
mcs_status mcs_results_set_attr_double(mcs_results *r, const char *path, const char *name,
                                       double value, mcs_error *err);
mcs_status mcs_results_set_attr_int(mcs_results *r, const char *path, const char *name,
                                    int value, mcs_error *err);

/* ---- time series written during a run --------------------------------------------------- */

/* an extendible dataset of rank 1..3 whose first axis grows: each row has the shape
 * row_dims[0..rank-2] (nothing for rank 1). Rows are buffered a chunk at a time and written
 * as whole chunks; appending never allocates. The series belongs to r and is flushed and
 * released by commit/abort/close. chunk_rows 0 chooses (about 64 KiB per chunk). */
mcs_status mcs_results_series_create(mcs_results *r, const char *path, int rank,
                                     const size_t *row_dims, const char *unit, size_t chunk_rows,
                                     mcs_results_series **out, mcs_error *err);

/* append one row (row_len values, row_len = product of row_dims) */
mcs_status mcs_results_series_append(mcs_results_series *s, const double *row, mcs_error *err);

size_t mcs_results_series_rows(const mcs_results_series *s);   /* rows appended so far */
size_t mcs_results_series_row_len(const mcs_results_series *s); /* values per row */

/* write buffered rows of every series to the file (commit does this) */
mcs_status mcs_results_flush(mcs_results *r, mcs_error *err);

/* ---- reading ---------------------------------------------------------------------------- */

/* a dataset read into memory; free with mcs_array_free */
typedef struct {
    int rank;                          /* 0 for a scalar, else 1..3                 */
    size_t dims[MCS_RESULTS_MAXRANK];  /* extent of each axis (1 beyond rank)       */
    size_t n;                          /* number of values                         */
    char unit[32];                     /* `unit` attribute, "" when absent          */
    double *v;                         /* values [unit] (n), row-major, owned       */
    int *iv;                           /* or integer values (n) from read_int       */
} mcs_array;

void mcs_array_free(mcs_array *a);

typedef enum { MCS_RES_NONE, MCS_RES_GROUP, MCS_RES_DATASET } mcs_res_kind;

/* what is at path (NONE when missing, also when an intermediate group is missing) */
mcs_res_kind mcs_results_kind(mcs_results *r, const char *path);
int mcs_results_exists(mcs_results *r, const char *path);

/* shape of a dataset without reading it */
mcs_status mcs_results_shape(mcs_results *r, const char *path, int *rank, size_t *dims,
                             mcs_error *err);

/* read any numeric dataset as doubles / as ints (rank 0..3) */
mcs_status mcs_results_read(mcs_results *r, const char *path, mcs_array *out, mcs_error *err);
mcs_status mcs_results_read_int(mcs_results *r, const char *path, mcs_array *out,
                                mcs_error *err);

/* row `row` (first axis) of a double dataset of rank 1..3 into v (n values: the row's length) */
mcs_status mcs_results_read_row(mcs_results *r, const char *path, size_t row, double *v,
                                size_t n, mcs_error *err);

/* attributes: has, string (newly allocated, free()), number (any numeric type) */
int mcs_results_has_attr(mcs_results *r, const char *path, const char *name);
mcs_status mcs_results_attr_str(mcs_results *r, const char *path, const char *name, char **out,
                                mcs_error *err);
mcs_status mcs_results_attr_double(mcs_results *r, const char *path, const char *name,
                                   double *out, mcs_error *err);

/* members of a group in the order they were written (by name for foreign files);
 * *names is an array of *n strings, freed with mcs_results_list_free */
mcs_status mcs_results_list(mcs_results *r, const char *group, char ***names, int *n,
                            mcs_error *err);
void mcs_results_list_free(char ***names, int n);

/* read "file.h5:/path/to/dataset" in one call (for injury/compare) */
mcs_status mcs_results_read_ref(const char *ref, mcs_array *out, mcs_error *err);

/* true if the file exists and has the HDF5 signature */
int mcs_results_is_hdf5(const char *path);

/* ---- the DESIGN.md layout --------------------------------------------------------------- */

/* /stageN/time [nt] s */
mcs_status mcs_results_put_time(mcs_results *r, int stage, size_t nt, const double *t,
                                mcs_error *err);

/* /stageN/channels/<name> [nt] with unit, frame ("SAE J211 local" ...), cfc (0 = unfiltered),
 * body; frame and body may be NULL (not written) */
mcs_status mcs_results_put_channel(mcs_results *r, int stage, const char *name, size_t nt,
                                   const double *y, const char *unit, const char *frame, int cfc,
                                   const char *body, mcs_error *err);

/* /stageN/energy/<kind> [nt] J; kind is one of kinetic, potential, internal, contact,
 * hourglass, dissipated, external_work, total */
mcs_status mcs_results_put_energy(mcs_results *r, int stage, const char *kind, size_t nt,
                                  const double *e, mcs_error *err);

/* /stageN/bodies/<body>/<quantity> [nt, w]: position (3, m), orientation (4, -, quaternion
 * w,x,y,z body->world), velocity (3, m/s), angular_velocity (3, rad/s),
 * acceleration (3, m/s^2) */
mcs_status mcs_results_put_body(mcs_results *r, int stage, const char *body,
                                const char *quantity, size_t nt, const double *v,
                                mcs_error *err);

/* the same as a series during a run */
mcs_status mcs_results_body_series(mcs_results *r, int stage, const char *body,
                                   const char *quantity, mcs_results_series **out,
                                   mcs_error *err);

/* unit and width of a body quantity; NULL for an unknown quantity */
const char *mcs_results_body_unit(const char *quantity, int *width);

/* /stageN/injury/<criterion> scalar with unit, limit, t1, t2 [s], channel (may be NULL) */
mcs_status mcs_results_put_injury(mcs_results *r, int stage, const char *criterion,
                                  double value, const char *unit, double limit, double t1,
                                  double t2, const char *channel, mcs_error *err);

/* /stageN/mesh/<part>/{nodes [nn,3] m, elements [ne,k] -} (see the conventions above);
 * type may be NULL */
mcs_status mcs_results_put_mesh(mcs_results *r, int stage, const char *part, size_t nn,
                                const double *nodes, size_t ne, int k, const int *elements,
                                const char *type, int node_offset, mcs_error *err);

/* /stageN/mesh/<part>/elements_<type> [ne,k]: another element block of a part written by
 * mcs_results_put_mesh (nn: its node count, for the range check) */
mcs_status mcs_results_put_mesh_block(mcs_results *r, int stage, const char *part, size_t nn,
                                      size_t ne, int k, const int *elements, const char *type,
                                      mcs_error *err);

/* /stageN/fields/displacement [nout, nn, 3] m as a series (one row per output time) and
 * /stageN/fields/time [nout] s beside it; append the time, then the field */
mcs_status mcs_results_field_series(mcs_results *r, int stage, size_t nn,
                                    mcs_results_series **time, mcs_results_series **disp,
                                    mcs_error *err);

/* /stage3/rigidwall/<wall>/{force [nt] N, displacement [nt] m} */
mcs_status mcs_results_put_rigidwall(mcs_results *r, const char *wall, size_t nt,
                                     const double *force, const double *displacement,
                                     mcs_error *err);

/* /curves/<name>/{loading [n,2], unloading [n,2]} (x, y); x_unit/y_unit say what the columns
 * are (e.g. "m", "N"); the dataset's unit attribute is "x_unit,y_unit". unloading may be NULL */
mcs_status mcs_results_put_curve(mcs_results *r, const char *name, size_t nload,
                                 const double *loading, size_t nunload, const double *unloading,
                                 const char *x_unit, const char *y_unit, mcs_error *err);

#endif

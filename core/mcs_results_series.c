/* mcs_results_series.c: datasets that grow by one row per output step during a run.
 * Rows collect in a buffer of one chunk and go to the file a chunk at a time, so the run
 * keeps at most one chunk per series in memory and an append never allocates. */
#include "core/mcs_results_impl.h"

#include <stdlib.h>
#include <string.h>

enum { CHUNK_BYTES = 64 * 1024 };

static mcs_status series_flush(mcs_results_series *s, mcs_error *err)
{
    if (s->nbuf == 0) return MCS_OK;
    hsize_t start[MCS_RESULTS_MAXRANK] = {s->dims[0], 0, 0};
    hsize_t count[MCS_RESULTS_MAXRANK] = {s->nbuf, s->dims[1], s->dims[2]};
    hsize_t ext[MCS_RESULTS_MAXRANK] = {s->dims[0] + s->nbuf, s->dims[1], s->dims[2]};
    if (H5Dset_extent(s->dset, ext) < 0)
        return mcs_res_h5err(err, s->r, s->path, "cannot extend series");
    hid_t fs = H5Dget_space(s->dset);
    hid_t ms = H5Screate_simple(s->rank, count, NULL);
    herr_t h = fs < 0 || ms < 0 ? -1 : H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL);
    if (h >= 0) h = H5Dwrite(s->dset, H5T_NATIVE_DOUBLE, ms, fs, H5P_DEFAULT, s->buf);
    if (fs >= 0) H5Sclose(fs);
    if (ms >= 0) H5Sclose(ms);
    if (h < 0) return mcs_res_h5err(err, s->r, s->path, "cannot write series rows");
    s->dims[0] += s->nbuf;
    s->nbuf = 0;
    return MCS_OK;
}

static void series_free(mcs_results_series *s)
{
    if (s->dset >= 0) H5Dclose(s->dset);
    free(s->buf);
    free(s);
}

mcs_status mcs_results_series_create(mcs_results *r, const char *path, int rank,
                                     const size_t *row_dims, const char *unit, size_t chunk_rows,
                                     mcs_results_series **out, mcs_error *err)
{
    *out = NULL;
    mcs_status st = mcs_res_check_path(r, path, 1, err);
    if (st) return st;
    if (!unit || !*unit)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: a dataset needs a unit (\"-\" if none)",
                       r->path, path);
    if (rank < 1 || rank > MCS_RESULTS_MAXRANK || (rank > 1 && !row_dims))
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: series rank %d not in 1..3", r->path, path,
                       rank);
    if (strlen(path) >= sizeof((mcs_results_series *)0)->path)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: path too long for a series", r->path, path);
    if (mcs_results_kind(r, path) != MCS_RES_NONE)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: already exists", r->path, path);
    mcs_results_series *s = calloc(1, sizeof *s);
    if (!s) return MCS_ERR(err, MCS_ERR_NOMEM, "%s:%s: out of memory", r->path, path);
    s->r = r;
    s->dset = H5I_INVALID_HID;
    s->rank = rank;
    s->row_len = 1;
    s->dims[0] = 0;
    for (int i = 1; i < MCS_RESULTS_MAXRANK; i++) {
        s->dims[i] = i < rank ? (hsize_t)row_dims[i - 1] : 1;
        s->row_len *= (size_t)s->dims[i];
    }
    snprintf(s->path, sizeof s->path, "%s", path);
    if (s->row_len == 0) {
        free(s);
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: empty row", r->path, path);
    }
    s->chunk_rows = chunk_rows ? chunk_rows : CHUNK_BYTES / (s->row_len * sizeof(double));
    if (s->chunk_rows < 1) s->chunk_rows = 1;
    s->buf = malloc(s->chunk_rows * s->row_len * sizeof(double));
    if (!s->buf) {
        free(s);
        return MCS_ERR(err, MCS_ERR_NOMEM, "%s:%s: out of memory", r->path, path);
    }
    if ((st = mcs_res_make_parents(r, path, err))) {
        series_free(s);
        return st;
    }
    hsize_t maxd[MCS_RESULTS_MAXRANK] = {H5S_UNLIMITED, s->dims[1], s->dims[2]};
    hsize_t chunk[MCS_RESULTS_MAXRANK] = {s->chunk_rows, s->dims[1], s->dims[2]};
    hid_t sp = H5Screate_simple(rank, s->dims, maxd);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(dcpl, rank, chunk);
    H5Pset_obj_track_times(dcpl, 0);
    s->dset = H5Dcreate2(r->file, path, H5T_IEEE_F64LE, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Pclose(dcpl);
    H5Sclose(sp);
    if (s->dset < 0 || mcs_res_attr_str_id(s->dset, "unit", unit)) {
        st = mcs_res_h5err(err, r, path, "cannot create series");
        series_free(s);
        return st;
    }
    s->next = r->series;
    r->series = s;
    *out = s;
    return MCS_OK;
}

mcs_status mcs_results_series_append(mcs_results_series *s, const double *row, mcs_error *err)
{
    if (!s || !row) return MCS_ERR(err, MCS_ERR_USAGE, "series append: NULL series or row");
    memcpy(s->buf + s->nbuf * s->row_len, row, s->row_len * sizeof(double));
    if (++s->nbuf == s->chunk_rows) return series_flush(s, err);
    return MCS_OK;
}

size_t mcs_results_series_rows(const mcs_results_series *s)
{
    return s ? (size_t)s->dims[0] + s->nbuf : 0;
}

size_t mcs_results_series_row_len(const mcs_results_series *s)
{
    return s ? s->row_len : 0;
}

mcs_status mcs_res_series_flush_all(mcs_results *r, mcs_error *err)
{
    for (mcs_results_series *s = r->series; s; s = s->next) {
        mcs_status st = series_flush(s, err);
        if (st) return st;
    }
    return MCS_OK;
}

mcs_status mcs_results_flush(mcs_results *r, mcs_error *err)
{
    if (!r || !r->writable) return MCS_ERR(err, MCS_ERR_USAGE, "results: flush of no writer");
    mcs_status st = mcs_res_series_flush_all(r, err);
    if (st) return st;
    if (H5Fflush(r->file, H5F_SCOPE_LOCAL) < 0)
        return mcs_res_h5err(err, r, "", "cannot flush");
    return MCS_OK;
}

void mcs_res_series_release_all(mcs_results *r)
{
    while (r->series) {
        mcs_results_series *s = r->series;
        r->series = s->next;
        series_free(s);
    }
}

/* mcs_results_io.c: whole datasets and attributes — write, read, look up, list. */
#include "core/mcs_results_impl.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- attributes on an open object ---- */

static herr_t replace_attr(hid_t obj, const char *name)
{
    htri_t ex = H5Aexists(obj, name);
    if (ex < 0) return -1;
    return ex ? H5Adelete(obj, name) : 0;
}

mcs_status mcs_res_attr_str_id(hid_t obj, const char *name, const char *value)
{
    if (replace_attr(obj, name) < 0) return MCS_ERR_HDF5;
    size_t len = strlen(value);
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, len + 1);
    H5Tset_strpad(t, H5T_STR_NULLTERM);
    H5Tset_cset(t, H5T_CSET_UTF8);
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
    herr_t h = a < 0 ? -1 : H5Awrite(a, t, value);
    if (a >= 0) H5Aclose(a);
    H5Sclose(sp);
    H5Tclose(t);
    return h < 0 ? MCS_ERR_HDF5 : MCS_OK;
}

mcs_status mcs_res_attr_num_id(hid_t obj, const char *name, hid_t type, const void *value)
{
    if (replace_attr(obj, name) < 0) return MCS_ERR_HDF5;
    /* little-endian on file whatever the machine, so files compare byte for byte */
    hid_t ft = H5Tequal(type, H5T_NATIVE_INT) > 0 ? H5T_STD_I32LE : H5T_IEEE_F64LE;
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(obj, name, ft, sp, H5P_DEFAULT, H5P_DEFAULT);
    herr_t h = a < 0 ? -1 : H5Awrite(a, type, value);
    if (a >= 0) H5Aclose(a);
    H5Sclose(sp);
    return h < 0 ? MCS_ERR_HDF5 : MCS_OK;
}

static mcs_status set_attr(mcs_results *r, const char *path, const char *name, hid_t type,
                           const void *value, mcs_error *err)
{
    mcs_status st = mcs_res_check_path(r, path, 1, err);
    if (st) return st;
    if (!name || !*name) return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: empty attribute name",
                                        r->path, path);
    if (mcs_results_kind(r, path) == MCS_RES_NONE)
        return MCS_ERR(err, MCS_ERR_KEY, "%s:%s: no such object for attribute %s", r->path,
                       path, name);
    hid_t o = H5Oopen(r->file, path, H5P_DEFAULT);
    if (o < 0) return mcs_res_h5err(err, r, path, "cannot open object");
    st = type < 0 ? mcs_res_attr_str_id(o, name, value) : mcs_res_attr_num_id(o, name, type, value);
    H5Oclose(o);
    if (st) {
        char what[160];
        snprintf(what, sizeof what, "cannot write attribute %s", name);
        return mcs_res_h5err(err, r, path, what);
    }
    return MCS_OK;
}

mcs_status mcs_results_set_attr_str(mcs_results *r, const char *path, const char *name,
                                    const char *value, mcs_error *err)
{
    return set_attr(r, path, name, -1, value ? value : "", err);
}

mcs_status mcs_results_set_attr_double(mcs_results *r, const char *path, const char *name,
                                       double value, mcs_error *err)
{
    return set_attr(r, path, name, H5T_NATIVE_DOUBLE, &value, err);
}

mcs_status mcs_results_set_attr_int(mcs_results *r, const char *path, const char *name,
                                    int value, mcs_error *err)
{
    return set_attr(r, path, name, H5T_NATIVE_INT, &value, err);
}

/* ---- whole datasets ---- */

static mcs_status write_array(mcs_results *r, const char *path, int rank, const size_t *dims,
                              hid_t memtype, hid_t filetype, const void *data, const char *unit,
                              mcs_error *err)
{
    mcs_status st = mcs_res_check_path(r, path, 1, err);
    if (st) return st;
    if (!unit || !*unit)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: a dataset needs a unit (\"-\" if none)",
                       r->path, path);
    if (rank < 0 || rank > MCS_RESULTS_MAXRANK || (rank > 0 && !dims))
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: rank %d not in 0..3", r->path, path, rank);
    hsize_t hd[MCS_RESULTS_MAXRANK];
    size_t n = 1;
    for (int i = 0; i < rank; i++) n *= (size_t)(hd[i] = dims[i]);
    if (n > 0 && !data) return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: no data", r->path, path);
    if (mcs_results_kind(r, path) != MCS_RES_NONE)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: already exists", r->path, path);
    if ((st = mcs_res_make_parents(r, path, err))) return st;

    hid_t sp = rank == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(rank, hd, NULL);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_obj_track_times(dcpl, 0);
    hid_t d = H5Dcreate2(r->file, path, filetype, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Pclose(dcpl);
    H5Sclose(sp);
    if (d < 0) return mcs_res_h5err(err, r, path, "cannot create dataset");
    herr_t h = n > 0 ? H5Dwrite(d, memtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
    if (h >= 0 && mcs_res_attr_str_id(d, "unit", unit)) h = -1;
    H5Dclose(d);
    if (h < 0) return mcs_res_h5err(err, r, path, "cannot write dataset");
    return MCS_OK;
}

mcs_status mcs_results_write(mcs_results *r, const char *path, int rank, const size_t *dims,
                             const double *data, const char *unit, mcs_error *err)
{
    if (rank < 1) return MCS_ERR(err, MCS_ERR_USAGE, "%s: rank must be 1..3", path ? path : "");
    return write_array(r, path, rank, dims, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, data, unit, err);
}

mcs_status mcs_results_write_int(mcs_results *r, const char *path, int rank, const size_t *dims,
                                 const int *data, const char *unit, mcs_error *err)
{
    if (rank < 1) return MCS_ERR(err, MCS_ERR_USAGE, "%s: rank must be 1..3", path ? path : "");
    return write_array(r, path, rank, dims, H5T_NATIVE_INT, H5T_STD_I32LE, data, unit, err);
}

mcs_status mcs_results_write_scalar(mcs_results *r, const char *path, double value,
                                    const char *unit, mcs_error *err)
{
    return write_array(r, path, 0, NULL, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, &value, unit, err);
}

/* ---- looking up ---- */

mcs_res_kind mcs_results_kind(mcs_results *r, const char *path)
{
    if (!r || !path || path[0] != '/' || strlen(path) >= 1024) return MCS_RES_NONE;
    if (strcmp(path, "/") == 0) return MCS_RES_GROUP;
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", path);
    /* each link in turn: H5Lexists fails on a missing intermediate group */
    for (char *p = buf + 1;; p++) {
        if (*p != '/' && *p != 0) continue;
        char c = *p;
        *p = 0;
        htri_t ex = H5Lexists(r->file, buf, H5P_DEFAULT);
        *p = c;
        if (ex <= 0) {
            H5Eclear2(H5E_DEFAULT);
            return MCS_RES_NONE;
        }
        if (c == 0) break;
    }
    hid_t o = H5Oopen(r->file, path, H5P_DEFAULT);
    if (o < 0) {
        H5Eclear2(H5E_DEFAULT);
        return MCS_RES_NONE;
    }
    H5I_type_t t = H5Iget_type(o);
    H5Oclose(o);
    return t == H5I_GROUP ? MCS_RES_GROUP : t == H5I_DATASET ? MCS_RES_DATASET : MCS_RES_NONE;
}

int mcs_results_exists(mcs_results *r, const char *path)
{
    return mcs_results_kind(r, path) != MCS_RES_NONE;
}

static mcs_status open_dataset(mcs_results *r, const char *path, hid_t *d, mcs_error *err)
{
    mcs_status st = mcs_res_check_path(r, path, 0, err);
    if (st) return st;
    if (r->writable && (st = mcs_res_series_flush_all(r, err))) return st;
    mcs_res_kind k = mcs_results_kind(r, path);
    if (k != MCS_RES_DATASET)
        return MCS_ERR(err, MCS_ERR_KEY, "%s:%s: %s", r->path, path,
                       k == MCS_RES_GROUP ? "is a group, not a dataset" : "no such dataset");
    *d = H5Dopen2(r->file, path, H5P_DEFAULT);
    if (*d < 0) return mcs_res_h5err(err, r, path, "cannot open dataset");
    return MCS_OK;
}

static mcs_status dataset_shape(mcs_results *r, const char *path, hid_t d, int *rank,
                                size_t *dims, mcs_error *err)
{
    hid_t sp = H5Dget_space(d);
    int nd = sp < 0 ? -1 : H5Sget_simple_extent_ndims(sp);
    hsize_t hd[MCS_RESULTS_MAXRANK];
    if (nd >= 0 && nd <= MCS_RESULTS_MAXRANK) H5Sget_simple_extent_dims(sp, hd, NULL);
    if (sp >= 0) H5Sclose(sp);
    if (nd < 0) return mcs_res_h5err(err, r, path, "cannot read the shape");
    if (nd > MCS_RESULTS_MAXRANK)
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED, "%s:%s: rank %d above 3", r->path, path, nd);
    *rank = nd;
    for (int i = 0; i < MCS_RESULTS_MAXRANK; i++) dims[i] = i < nd ? (size_t)hd[i] : 1;
    return MCS_OK;
}

mcs_status mcs_results_shape(mcs_results *r, const char *path, int *rank, size_t *dims,
                             mcs_error *err)
{
    hid_t d;
    mcs_status st = open_dataset(r, path, &d, err);
    if (st) return st;
    st = dataset_shape(r, path, d, rank, dims, err);
    H5Dclose(d);
    return st;
}

void mcs_array_free(mcs_array *a)
{
    if (!a) return;
    free(a->v);
    free(a->iv);
    memset(a, 0, sizeof *a);
}

/* read the attribute `name` as a string into buf (truncated); "" when absent */
static void attr_to_buf(mcs_results *r, const char *path, const char *name, char *buf, size_t n)
{
    buf[0] = 0;
    if (!mcs_results_has_attr(r, path, name)) return;
    char *s = NULL;
    mcs_error e = {0};
    if (mcs_results_attr_str(r, path, name, &s, &e) == MCS_OK) snprintf(buf, n, "%s", s);
    free(s);
}

/* a dataset's declared size must be one the file holds: the count must not overflow, and more
 * than 1 MiB declared must be held in at least 1/1024 of its bytes (the ratio bounds deflate's,
 * ~1000; mcrash writes no filter). Refused otherwise, before anything is allocated for it. */
static mcs_status check_held(mcs_results *r, const char *path, hid_t d, const size_t *dims,
                             size_t fsz, size_t esz, mcs_error *err)
{
    size_t n = 1;
    for (int i = 0; i < MCS_RESULTS_MAXRANK; i++) {
        if (dims[i] && n > SIZE_MAX / dims[i])
            return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: declares [%zu, %zu, %zu] values: too many",
                           r->path, path, dims[0], dims[1], dims[2]);
        n *= dims[i];
    }
    size_t big = fsz > esz ? fsz : esz;
    if (big && n > SIZE_MAX / big)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: declares %zu values: too many", r->path, path,
                       n);
    unsigned long long held = (unsigned long long)H5Dget_storage_size(d);
    if ((double)n * (double)fsz > 1048576.0 && (double)held * 1024.0 < (double)n * (double)fsz)
        return MCS_ERR(err, MCS_ERR_FORMAT,
                       "%s:%s: declares %zu values (%zu bytes) but the file holds %llu bytes of "
                       "them",
                       r->path, path, n, n * fsz, held);
    return MCS_OK;
}

static mcs_status read_any(mcs_results *r, const char *path, mcs_array *out, int as_int,
                           mcs_error *err)
{
    memset(out, 0, sizeof *out);
    hid_t d;
    mcs_status st = open_dataset(r, path, &d, err);
    if (st) return st;
    st = dataset_shape(r, path, d, &out->rank, out->dims, err);
    hid_t t = H5Dget_type(d);
    H5T_class_t c = t < 0 ? H5T_NO_CLASS : H5Tget_class(t);
    size_t fsz = t < 0 ? 0 : H5Tget_size(t);
    if (t >= 0) H5Tclose(t);
    if (!st && c != H5T_INTEGER && c != H5T_FLOAT)
        st = MCS_ERR(err, MCS_ERR_TYPE, "%s:%s: not a numeric dataset", r->path, path);
    size_t esz = as_int ? sizeof(int) : sizeof(double);
    if (!st) st = check_held(r, path, d, out->dims, fsz, esz, err);
    if (st) {
        H5Dclose(d);
        return st;
    }
    out->n = out->dims[0] * out->dims[1] * out->dims[2];
    if (out->rank == 0) out->n = 1;
    void *buf = malloc(esz * (out->n ? out->n : 1));
    if (!buf) {
        H5Dclose(d);
        return MCS_ERR(err, MCS_ERR_NOMEM, "%s:%s: out of memory (%zu values)", r->path, path,
                       out->n);
    }
    herr_t h = out->n ? H5Dread(d, as_int ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, H5S_ALL,
                                H5S_ALL, H5P_DEFAULT, buf)
                      : 0;
    H5Dclose(d);
    if (as_int)
        out->iv = buf;
    else
        out->v = buf;
    if (h < 0) {
        mcs_array_free(out);
        return mcs_res_h5err(err, r, path, "cannot read dataset");
    }
    attr_to_buf(r, path, "unit", out->unit, sizeof out->unit);
    return MCS_OK;
}

mcs_status mcs_results_read(mcs_results *r, const char *path, mcs_array *out, mcs_error *err)
{
    return read_any(r, path, out, 0, err);
}

mcs_status mcs_results_read_int(mcs_results *r, const char *path, mcs_array *out,
                                mcs_error *err)
{
    return read_any(r, path, out, 1, err);
}

mcs_status mcs_results_read_row(mcs_results *r, const char *path, size_t row, double *v,
                                size_t n, mcs_error *err)
{
    hid_t d;
    mcs_status st = open_dataset(r, path, &d, err);
    if (st) return st;
    int rank = 0;
    size_t dims[MCS_RESULTS_MAXRANK] = {1, 1, 1};
    st = dataset_shape(r, path, d, &rank, dims, err);
    if (!st && (rank < 1 || row >= dims[0] || n != dims[1] * dims[2]))
        st = MCS_ERR(err, MCS_ERR_RANGE, "%s:%s: no row %zu of %zu values", r->path, path, row,
                     n);
    hid_t fs = -1, ms = -1;
    herr_t h = 0;
    if (!st) {
        hsize_t start[3] = {row, 0, 0}, count[3] = {1, dims[1], dims[2]}, mn = n;
        fs = H5Dget_space(d);
        ms = H5Screate_simple(1, &mn, NULL);
        h = fs < 0 || ms < 0 ? -1
                             : H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL);
        if (h >= 0) h = H5Dread(d, H5T_NATIVE_DOUBLE, ms, fs, H5P_DEFAULT, v);
        if (h < 0) st = mcs_res_h5err(err, r, path, "cannot read a row");
    }
    if (fs >= 0) H5Sclose(fs);
    if (ms >= 0) H5Sclose(ms);
    H5Dclose(d);
    return st;
}

/* ---- reading attributes ---- */

int mcs_results_has_attr(mcs_results *r, const char *path, const char *name)
{
    if (!name || mcs_results_kind(r, path) == MCS_RES_NONE) return 0;
    htri_t ex = H5Aexists_by_name(r->file, path, name, H5P_DEFAULT);
    H5Eclear2(H5E_DEFAULT);
    return ex > 0;
}

/* open attribute `name` of `path`, checking it holds one value of class want */
static mcs_status open_attr(mcs_results *r, const char *path, const char *name,
                            H5T_class_t want, hid_t *a, hid_t *t, mcs_error *err)
{
    mcs_status st = mcs_res_check_path(r, path, 0, err);
    if (st) return st;
    if (!mcs_results_has_attr(r, path, name))
        return MCS_ERR(err, MCS_ERR_KEY, "%s:%s: no attribute %s", r->path, path,
                       name ? name : "(null)");
    *a = H5Aopen_by_name(r->file, path, name, H5P_DEFAULT, H5P_DEFAULT);
    if (*a < 0) return mcs_res_h5err(err, r, path, "cannot open attribute");
    *t = H5Aget_type(*a);
    hid_t sp = H5Aget_space(*a);
    hssize_t np = H5Sget_simple_extent_npoints(sp);
    H5Sclose(sp);
    H5T_class_t c = H5Tget_class(*t);
    int ok = np == 1 && (c == want || (want == H5T_FLOAT && c == H5T_INTEGER));
    if (!ok) {
        H5Tclose(*t);
        H5Aclose(*a);
        return MCS_ERR(err, MCS_ERR_TYPE, "%s:%s: attribute %s is not one %s", r->path, path,
                       name, want == H5T_STRING ? "string" : "number");
    }
    return MCS_OK;
}

mcs_status mcs_results_attr_str(mcs_results *r, const char *path, const char *name, char **out,
                                mcs_error *err)
{
    *out = NULL;
    hid_t a, t;
    mcs_status st = open_attr(r, path, name, H5T_STRING, &a, &t, err);
    if (st) return st;
    herr_t h;
    if (H5Tis_variable_str(t) > 0) {
        /* as h5py writes them */
        char *s = NULL;
        hid_t mt = H5Tcopy(H5T_C_S1);
        H5Tset_size(mt, H5T_VARIABLE);
        h = H5Aread(a, mt, &s);
        H5Tclose(mt);
        if (h >= 0) *out = strdup(s ? s : "");
        if (s) H5free_memory(s);
    } else {
        size_t n = H5Tget_size(t);
        *out = calloc(n + 1, 1);
        h = *out ? H5Aread(a, t, *out) : 0;
    }
    H5Tclose(t);
    H5Aclose(a);
    if (h < 0) {
        free(*out);
        *out = NULL;
        return mcs_res_h5err(err, r, path, "cannot read attribute");
    }
    if (!*out) return MCS_ERR(err, MCS_ERR_NOMEM, "%s:%s: out of memory", r->path, path);
    return MCS_OK;
}

mcs_status mcs_results_attr_double(mcs_results *r, const char *path, const char *name,
                                   double *out, mcs_error *err)
{
    hid_t a, t;
    mcs_status st = open_attr(r, path, name, H5T_FLOAT, &a, &t, err);
    if (st) return st;
    herr_t h = H5Aread(a, H5T_NATIVE_DOUBLE, out);
    H5Tclose(t);
    H5Aclose(a);
    if (h < 0) return mcs_res_h5err(err, r, path, "cannot read attribute");
    return MCS_OK;
}

/* ---- listing ---- */

void mcs_results_list_free(char ***names, int n)
{
    if (!names || !*names) return;
    for (int i = 0; i < n; i++) free((*names)[i]);
    free(*names);
    *names = NULL;
}

mcs_status mcs_results_list(mcs_results *r, const char *group, char ***names, int *n,
                            mcs_error *err)
{
    *names = NULL;
    *n = 0;
    mcs_status st = mcs_res_check_path(r, group, 0, err);
    if (st) return st;
    if (mcs_results_kind(r, group) != MCS_RES_GROUP)
        return MCS_ERR(err, MCS_ERR_KEY, "%s:%s: no such group", r->path, group);
    hid_t g = H5Gopen2(r->file, group, H5P_DEFAULT);
    if (g < 0) return mcs_res_h5err(err, r, group, "cannot open group");
    H5G_info_t info;
    unsigned flags = 0;
    hid_t gcpl = H5Gget_create_plist(g);
    if (gcpl >= 0) {
        H5Pget_link_creation_order(gcpl, &flags);
        H5Pclose(gcpl);
    }
    H5_index_t idx = (flags & H5P_CRT_ORDER_INDEXED) ? H5_INDEX_CRT_ORDER : H5_INDEX_NAME;
    if (H5Gget_info(g, &info) < 0) {
        H5Gclose(g);
        return mcs_res_h5err(err, r, group, "cannot read group");
    }
    char **v = calloc(info.nlinks ? info.nlinks : 1, sizeof *v);
    if (!v) st = MCS_ERR(err, MCS_ERR_NOMEM, "%s:%s: out of memory", r->path, group);
    for (hsize_t i = 0; !st && i < info.nlinks; i++) {
        ssize_t len = H5Lget_name_by_idx(g, ".", idx, H5_ITER_INC, i, NULL, 0, H5P_DEFAULT);
        if (len < 0) {
            st = mcs_res_h5err(err, r, group, "cannot read member name");
            break;
        }
        v[i] = malloc((size_t)len + 1);
        if (!v[i]) {
            st = MCS_ERR(err, MCS_ERR_NOMEM, "%s:%s: out of memory", r->path, group);
            break;
        }
        H5Lget_name_by_idx(g, ".", idx, H5_ITER_INC, i, v[i], (size_t)len + 1, H5P_DEFAULT);
    }
    H5Gclose(g);
    if (st) {
        mcs_results_list_free(&v, (int)info.nlinks);
        return st;
    }
    *names = v;
    *n = (int)info.nlinks;
    return MCS_OK;
}

mcs_status mcs_results_read_ref(const char *ref, mcs_array *out, mcs_error *err)
{
    memset(out, 0, sizeof *out);
    /* the last ":/" separates the file from the object path */
    const char *sep = NULL;
    for (const char *p = ref ? strstr(ref, ":/") : NULL; p; p = strstr(p + 1, ":/")) sep = p;
    if (!sep || sep == ref)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s: expected file.h5:/path/to/dataset",
                       ref ? ref : "(null)");
    char file[4096];
    size_t fl = (size_t)(sep - ref);
    if (fl >= sizeof file) return MCS_ERR(err, MCS_ERR_USAGE, "%s: file name too long", ref);
    memcpy(file, ref, fl);
    file[fl] = 0;
    mcs_results *r;
    mcs_status st = mcs_results_open(&r, file, err);
    if (st) return st;
    st = mcs_results_read(r, sep + 1, out, err);
    mcs_results_close(&r);
    return st;
}

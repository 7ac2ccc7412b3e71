/* mcs_results.c: the results file's lifecycle — create to a temporary, commit by rename,
 * abort by removal, open for reading — and the HDF5 error translation. */
#include "core/mcs_interrupt.h"
#include "core/mcs_results_impl.h"
#include "core/mcs_version.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

void mcs_res_quiet(void)
{
    /* once per process; the default printer would write HDF5's stack to stderr */
    static int done;
    if (done) return;
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    done = 1;
}

typedef struct {
    char inner[256]; /* the most specific message on HDF5's stack */
    int have;
} h5_walk;

static herr_t walk_cb(unsigned n, const H5E_error2_t *e, void *data)
{
    (void)n;
    h5_walk *w = data;
    if (!w->have && e->desc && e->desc[0]) {
        snprintf(w->inner, sizeof w->inner, "%s", e->desc);
        w->have = 1;
    }
    return 0;
}

mcs_status mcs_res_h5err(mcs_error *err, const mcs_results *r, const char *path,
                         const char *what)
{
    h5_walk w = {{0}, 0};
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, walk_cb, &w);
    H5Eclear2(H5E_DEFAULT);
    int at = path && *path; /* the file alone: no "file::" */
    return MCS_ERR(err, MCS_ERR_HDF5, "%s%s%s: %s%s%s%s", r && r->path ? r->path : "(results)",
                   at ? ":" : "", at ? path : "", what, w.have ? " (hdf5: " : "",
                   w.have ? w.inner : "", w.have ? ")" : "");
}

mcs_status mcs_res_check_path(const mcs_results *r, const char *path, int want_write,
                              mcs_error *err)
{
    if (!r) return MCS_ERR(err, MCS_ERR_USAGE, "results: no file (NULL handle)");
    if (want_write && !r->writable)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: file is open read-only", r->path,
                       path ? path : "");
    if (!path || path[0] != '/' || strlen(path) >= 1024)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s: bad object path \"%s\" (must start with /)",
                       r->path, path ? path : "(null)");
    if (strstr(path, "//") || (path[1] && path[strlen(path) - 1] == '/'))
        return MCS_ERR(err, MCS_ERR_USAGE, "%s: bad object path \"%s\" (empty name)", r->path,
                       path);
    return MCS_OK;
}

hid_t mcs_res_gcpl(void)
{
    hid_t gcpl = H5Pcreate(H5P_GROUP_CREATE);
    if (gcpl < 0) return gcpl;
    /* members listed in the order written; no time stamps, so equal runs give equal bytes */
    H5Pset_link_creation_order(gcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
    H5Pset_obj_track_times(gcpl, 0);
    return gcpl;
}

mcs_status mcs_res_make_parents(mcs_results *r, const char *path, mcs_error *err)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", path);
    hid_t gcpl = mcs_res_gcpl();
    if (gcpl < 0) return mcs_res_h5err(err, r, path, "cannot make a group property list");
    mcs_status st = MCS_OK;
    for (char *p = strchr(buf + 1, '/'); p && st == MCS_OK; p = strchr(p + 1, '/')) {
        *p = 0;
        htri_t ex = H5Lexists(r->file, buf, H5P_DEFAULT);
        if (ex < 0) {
            st = mcs_res_h5err(err, r, buf, "cannot look up group");
        } else if (!ex) {
            hid_t g = H5Gcreate2(r->file, buf, H5P_DEFAULT, gcpl, H5P_DEFAULT);
            if (g < 0)
                st = mcs_res_h5err(err, r, buf, "cannot create group");
            else
                H5Gclose(g);
        } else if (mcs_results_kind(r, buf) != MCS_RES_GROUP) {
            st = MCS_ERR(err, MCS_ERR_USAGE, "%s:%s: is a dataset, not a group", r->path, buf);
        }
        *p = '/';
    }
    H5Pclose(gcpl);
    return st;
}

/* file access: 1.8 object format (readable by every current reader, and the first that
 * stores attributes above 64 KiB), strong close so a close releases every object */
static hid_t make_fapl(void)
{
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl < 0) return fapl;
    H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_V18);
    H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG);
    return fapl;
}

static void iso8601_now(char *buf, size_t n)
{
    time_t t = time(NULL);
    const char *sde = getenv("SOURCE_DATE_EPOCH"); /* reproducible builds convention */
    if (sde && *sde) {
        char *end;
        long long v = strtoll(sde, &end, 10);
        if (*end == 0 && v >= 0) t = (time_t)v;
    }
    struct tm tm;
    gmtime_r(&t, &tm);
    strftime(buf, n, "%Y-%m-%dT%H:%M:%SZ", &tm);
}

static mcs_status write_meta(mcs_results *r, const char *scenario, mcs_error *err)
{
    hid_t gcpl = mcs_res_gcpl();
    if (gcpl < 0) return mcs_res_h5err(err, r, "/meta", "cannot make a group property list");
    /* dense attribute storage: the scenario text may exceed the 64 KiB header limit */
    H5Pset_attr_phase_change(gcpl, 0, 0);
    hid_t g = H5Gcreate2(r->file, "/meta", H5P_DEFAULT, gcpl, H5P_DEFAULT);
    H5Pclose(gcpl);
    if (g < 0) return mcs_res_h5err(err, r, "/meta", "cannot create group");
    char created[32];
    iso8601_now(created, sizeof created);
    mcs_status st = MCS_OK;
    if (mcs_res_attr_str_id(g, "mcrash_version", MCS_VERSION) ||
        mcs_res_attr_str_id(g, "created", created) ||
        mcs_res_attr_str_id(g, "scenario", scenario ? scenario : "") ||
        mcs_res_attr_str_id(g, "units", "SI"))
        st = mcs_res_h5err(err, r, "/meta", "cannot write attributes");
    H5Gclose(g);
    return st;
}

static mcs_results *new_handle(const char *path, int writable)
{
    mcs_results *r = calloc(1, sizeof *r);
    if (!r) return NULL;
    r->file = H5I_INVALID_HID;
    r->writable = writable;
    r->tmp_slot = -1;
    r->path = strdup(path);
    if (writable) {
        size_t n = strlen(path) + 40;
        r->tmp = malloc(n);
        if (r->tmp) snprintf(r->tmp, n, "%s.tmp.%ld", path, (long)getpid());
        /* a second SIGINT / SIGTERM removes it (core/mcs_interrupt.h) */
        r->tmp_slot = r->tmp ? mcs_interrupt_track(r->tmp) : -1;
    }
    if (!r->path || (writable && !r->tmp)) {
        mcs_interrupt_untrack(r->tmp_slot);
        free(r->path);
        free(r->tmp);
        free(r);
        return NULL;
    }
    return r;
}

static void free_handle(mcs_results *r)
{
    mcs_interrupt_untrack(r->tmp_slot);
    free(r->path);
    free(r->tmp);
    free(r);
}

/* probe that the temporary can be created, for a plain "No such file or directory" message */
static mcs_status probe_writable(const char *tmp, const char *path, mcs_error *err)
{
    FILE *f = fopen(tmp, "wb");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
    fclose(f);
    remove(tmp);
    return MCS_OK;
}

mcs_status mcs_results_create(mcs_results **out, const char *path, const char *scenario_text,
                              mcs_error *err)
{
    *out = NULL;
    if (!path || !*path) return MCS_ERR(err, MCS_ERR_USAGE, "results: no output file name");
    mcs_res_quiet();
    mcs_results *r = new_handle(path, 1);
    if (!r) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
    mcs_status st = probe_writable(r->tmp, path, err);
    if (st) {
        free_handle(r);
        return st;
    }
    hid_t fapl = make_fapl(), fcpl = H5Pcreate(H5P_FILE_CREATE);
    H5Pset_link_creation_order(fcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
    H5Pset_obj_track_times(fcpl, 0); /* the root group too: no time stamps */
    r->file = H5Fcreate(r->tmp, H5F_ACC_TRUNC, fcpl, fapl);
    H5Pclose(fcpl);
    H5Pclose(fapl);
    if (r->file < 0) {
        st = mcs_res_h5err(err, r, "", "cannot create the temporary results file");
        remove(r->tmp);
        free_handle(r);
        return st;
    }
    st = write_meta(r, scenario_text, err);
    if (st) {
        mcs_results_abort(&r);
        return st;
    }
    *out = r;
    return MCS_OK;
}

static mcs_status copy_file(const char *from, const char *to, mcs_error *err)
{
    FILE *in = fopen(from, "rb");
    if (!in) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot read: %s", from, strerror(errno));
    FILE *o = fopen(to, "wb");
    if (!o) {
        fclose(in);
        return MCS_ERR(err, MCS_ERR_IO, "%s: cannot write: %s", to, strerror(errno));
    }
    char buf[65536];
    size_t k;
    int bad = 0;
    while ((k = fread(buf, 1, sizeof buf, in)) > 0)
        if (fwrite(buf, 1, k, o) != k) bad = 1;
    if (ferror(in)) bad = 1;
    fclose(in);
    if (fclose(o) != 0) bad = 1;
    if (bad) {
        remove(to);
        return MCS_ERR(err, MCS_ERR_IO, "%s: copy to %s failed", from, to);
    }
    return MCS_OK;
}

mcs_status mcs_results_append(mcs_results **out, const char *path, mcs_error *err)
{
    *out = NULL;
    if (!path || !*path) return MCS_ERR(err, MCS_ERR_USAGE, "results: no file name");
    mcs_res_quiet();
    if (!mcs_results_is_hdf5(path))
        return MCS_ERR(err, access(path, F_OK) ? MCS_ERR_IO : MCS_ERR_FORMAT, "%s: %s", path,
                       access(path, F_OK) ? strerror(errno) : "not an HDF5 file");
    mcs_results *r = new_handle(path, 1);
    if (!r) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
    mcs_status st = copy_file(path, r->tmp, err);
    if (st) {
        free_handle(r);
        return st;
    }
    hid_t fapl = make_fapl();
    r->file = H5Fopen(r->tmp, H5F_ACC_RDWR, fapl);
    H5Pclose(fapl);
    if (r->file < 0) {
        st = mcs_res_h5err(err, r, "", "cannot open a copy for writing");
        remove(r->tmp);
        free_handle(r);
        return st;
    }
    if (mcs_results_kind(r, "/meta") != MCS_RES_GROUP) {
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: no /meta group: not an mcrash results file",
                     path);
        mcs_results_abort(&r);
        return st;
    }
    *out = r;
    return MCS_OK;
}

mcs_status mcs_results_remove(mcs_results *r, const char *path, mcs_error *err)
{
    if (!r || !r->writable)
        return MCS_ERR(err, MCS_ERR_USAGE, "results: remove in a file opened read-only");
    if (mcs_results_kind(r, path) == MCS_RES_NONE) return MCS_OK;
    if (H5Ldelete(r->file, path, H5P_DEFAULT) < 0)
        return mcs_res_h5err(err, r, path, "cannot remove");
    return MCS_OK;
}

mcs_status mcs_results_commit(mcs_results **rp, mcs_error *err)
{
    mcs_results *r = rp ? *rp : NULL;
    if (!r) return MCS_ERR(err, MCS_ERR_USAGE, "results: commit of no file");
    if (!r->writable) {
        mcs_results_close(rp);
        return MCS_ERR(err, MCS_ERR_USAGE, "results: commit of a file opened read-only");
    }
    mcs_status st = mcs_res_series_flush_all(r, err);
    mcs_res_series_release_all(r);
    if (st) {
        mcs_results_abort(rp);
        return st;
    }
    herr_t h = H5Fclose(r->file);
    r->file = H5I_INVALID_HID;
    if (h < 0) {
        st = mcs_res_h5err(err, r, "", "cannot close the results file");
        mcs_results_abort(rp);
        return st;
    }
    /* on disk before the rename makes it visible */
    int fd = open(r->tmp, O_RDONLY);
    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
    if (rename(r->tmp, r->path) != 0) {
        st = MCS_ERR(err, MCS_ERR_IO, "%s: cannot rename %s: %s", r->path, r->tmp,
                     strerror(errno));
        mcs_results_abort(rp);
        return st;
    }
    r->committed = 1;
    free_handle(r);
    *rp = NULL;
    return MCS_OK;
}

void mcs_results_abort(mcs_results **rp)
{
    mcs_results *r = rp ? *rp : NULL;
    if (!r) return;
    mcs_res_series_release_all(r);
    if (r->file >= 0) H5Fclose(r->file);
    H5Eclear2(H5E_DEFAULT);
    if (r->writable && !r->committed && r->tmp) remove(r->tmp);
    free_handle(r);
    *rp = NULL;
}

int mcs_results_is_hdf5(const char *path)
{
    struct stat sb;
    if (!path || stat(path, &sb) != 0 || !S_ISREG(sb.st_mode)) return 0;
    mcs_res_quiet();
    htri_t t = H5Fis_hdf5(path);
    H5Eclear2(H5E_DEFAULT);
    return t > 0;
}

mcs_status mcs_results_open(mcs_results **out, const char *path, mcs_error *err)
{
    *out = NULL;
    if (!path || !*path) return MCS_ERR(err, MCS_ERR_USAGE, "results: no file name");
    mcs_res_quiet();
    struct stat sb;
    if (stat(path, &sb) != 0)
        return MCS_ERR(err, MCS_ERR_IO, "%s: %s", path, strerror(errno));
    if (!S_ISREG(sb.st_mode)) return MCS_ERR(err, MCS_ERR_IO, "%s: not a regular file", path);
    if (!mcs_results_is_hdf5(path))
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: not an HDF5 file", path);
    mcs_results *r = new_handle(path, 0);
    if (!r) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: out of memory", path);
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG);
    r->file = H5Fopen(path, H5F_ACC_RDONLY, fapl);
    H5Pclose(fapl);
    if (r->file < 0) {
        mcs_status st = mcs_res_h5err(err, r, "", "cannot open: a truncated or damaged file");
        free_handle(r);
        return st;
    }
    *out = r;
    return MCS_OK;
}

void mcs_results_close(mcs_results **rp)
{
    mcs_results *r = rp ? *rp : NULL;
    if (!r) return;
    if (r->writable) {
        mcs_results_abort(rp);
        return;
    }
    if (r->file >= 0) H5Fclose(r->file);
    H5Eclear2(H5E_DEFAULT);
    free_handle(r);
    *rp = NULL;
}

const char *mcs_results_path(const mcs_results *r)
{
    return r ? r->path : "";
}

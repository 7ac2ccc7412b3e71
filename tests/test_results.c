/* test_results.c: the results file — every writer call read back, a unit on every dataset,
 * temporary + rename, abort leaving an earlier file untouched, series of 10 000 rows. */
#include "core/mcs_results.h"
#include "core/mcs_version.h"
#include "tests/harness.h"

#include <dirent.h>
#include <hdf5.h>
#include <malloc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char tdir[64];

static void make_tdir(void)
{
    snprintf(tdir, sizeof tdir, "/tmp/mcs_results_XXXXXX");
    if (!mkdtemp(tdir)) {
        perror("mkdtemp");
        exit(1);
    }
}

static void rm_tdir(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tdir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tdir);
}

#define tpath(name) th_path(tdir, (name))

static int file_exists(const char *p)
{
    struct stat sb;
    return stat(p, &sb) == 0;
}

/* number of directory entries whose name contains s */
static int count_entries(const char *s)
{
    DIR *d = opendir(tdir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        if (strstr(e->d_name, s)) n++;
    if (d) closedir(d);
    return n;
}

static void test_create_commit_meta(void)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    const char *out = tpath("meta.h5");
    const char *yaml = "mcrash: 1\nname: \"drop\"\n";
    CHECK(mcs_results_create(&r, out, yaml, &e) == MCS_OK);
    /* while a run writes, only the temporary exists */
    CHECK(!file_exists(out));
    CHECK(count_entries("meta.h5.tmp.") == 1);
    double t[3] = {0, 1e-3, 2e-3};
    CHECK(mcs_results_put_time(r, 1, 3, t, &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    CHECK(r == NULL);
    CHECK(file_exists(out));
    CHECK(count_entries(".tmp.") == 0);

    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    char *s = NULL;
    CHECK(mcs_results_attr_str(r, "/meta", "mcrash_version", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, MCS_VERSION) == 0);
    free(s);
    CHECK(mcs_results_attr_str(r, "/meta", "scenario", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, yaml) == 0);
    free(s);
    CHECK(mcs_results_attr_str(r, "/meta", "units", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, "SI") == 0);
    free(s);
    /* ISO 8601 UTC: YYYY-MM-DDTHH:MM:SSZ */
    CHECK(mcs_results_attr_str(r, "/meta", "created", &s, &e) == MCS_OK);
    CHECK(s && strlen(s) == 20 && s[4] == '-' && s[7] == '-' && s[10] == 'T' && s[13] == ':' &&
          s[19] == 'Z');
    free(s);
    mcs_results_close(&r);
    CHECK(e.status == MCS_OK);
}

static void test_arrays_roundtrip(void)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    const char *out = tpath("arrays.h5");
    CHECK(mcs_results_create(&r, out, NULL, &e) == MCS_OK);
    double a1[5], a2[4 * 3], a3[2 * 3 * 4];
    int iv[6] = {0, 1, 2, 2, 3, -7};
    for (int i = 0; i < 5; i++) a1[i] = 0.1 * i - 1e-300;
    for (int i = 0; i < 12; i++) a2[i] = i * 1.5e7;
    for (int i = 0; i < 24; i++) a3[i] = 1.0 / (i + 1);
    size_t d1[1] = {5}, d2[2] = {4, 3}, d3[3] = {2, 3, 4}, di[2] = {3, 2};
    CHECK(mcs_results_write(r, "/a/b/c/one", 1, d1, a1, "m", &e) == MCS_OK);
    CHECK(mcs_results_write(r, "/a/two", 2, d2, a2, "Pa", &e) == MCS_OK);
    CHECK(mcs_results_write(r, "/three", 3, d3, a3, "-", &e) == MCS_OK);
    CHECK(mcs_results_write_int(r, "/a/ints", 2, di, iv, "-", &e) == MCS_OK);
    CHECK(mcs_results_write_scalar(r, "/s/hic", 612.5, "-", &e) == MCS_OK);
    CHECK(mcs_results_set_attr_str(r, "/a/two", "frame", "world", &e) == MCS_OK);
    CHECK(mcs_results_set_attr_double(r, "/a/two", "t1", 0.0123, &e) == MCS_OK);
    CHECK(mcs_results_set_attr_int(r, "/a/two", "cfc", 1000, &e) == MCS_OK);
    CHECK(mcs_results_set_attr_str(r, "/a", "note", "group attribute", &e) == MCS_OK);
    /* replacing an attribute keeps the last value */
    CHECK(mcs_results_set_attr_str(r, "/a/two", "frame", "SAE J211", &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);

    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    mcs_array a = {0};
    CHECK(mcs_results_read(r, "/a/b/c/one", &a, &e) == MCS_OK);
    CHECK(a.rank == 1 && a.dims[0] == 5 && a.n == 5 && strcmp(a.unit, "m") == 0);
    for (int i = 0; i < 5 && a.v; i++) CHECK(a.v[i] == a1[i]);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/a/two", &a, &e) == MCS_OK);
    CHECK(a.rank == 2 && a.dims[0] == 4 && a.dims[1] == 3 && strcmp(a.unit, "Pa") == 0);
    for (int i = 0; i < 12 && a.v; i++) CHECK(a.v[i] == a2[i]);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/three", &a, &e) == MCS_OK);
    CHECK(a.rank == 3 && a.dims[0] == 2 && a.dims[1] == 3 && a.dims[2] == 4 && a.n == 24);
    for (int i = 0; i < 24 && a.v; i++) CHECK(a.v[i] == a3[i]);
    mcs_array_free(&a);
    CHECK(mcs_results_read_int(r, "/a/ints", &a, &e) == MCS_OK);
    CHECK(a.rank == 2 && a.dims[0] == 3 && a.dims[1] == 2 && a.iv && !a.v);
    for (int i = 0; i < 6 && a.iv; i++) CHECK(a.iv[i] == iv[i]);
    mcs_array_free(&a);
    /* ints read as doubles too */
    CHECK(mcs_results_read(r, "/a/ints", &a, &e) == MCS_OK);
    CHECK(a.v && a.v[5] == -7.0);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/s/hic", &a, &e) == MCS_OK);
    CHECK(a.rank == 0 && a.n == 1 && a.v && a.v[0] == 612.5 && strcmp(a.unit, "-") == 0);
    mcs_array_free(&a);

    int rank;
    size_t dims[3];
    CHECK(mcs_results_shape(r, "/three", &rank, dims, &e) == MCS_OK);
    CHECK(rank == 3 && dims[0] == 2 && dims[1] == 3 && dims[2] == 4);

    char *s = NULL;
    double v = 0;
    CHECK(mcs_results_attr_str(r, "/a/two", "frame", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, "SAE J211") == 0);
    free(s);
    CHECK(mcs_results_attr_double(r, "/a/two", "t1", &v, &e) == MCS_OK && v == 0.0123);
    CHECK(mcs_results_attr_double(r, "/a/two", "cfc", &v, &e) == MCS_OK && v == 1000.0);
    CHECK(mcs_results_attr_str(r, "/a", "note", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, "group attribute") == 0);
    free(s);
    CHECK(mcs_results_has_attr(r, "/a/two", "cfc"));
    CHECK(!mcs_results_has_attr(r, "/a/two", "nope"));
    CHECK(!mcs_results_has_attr(r, "/missing/x", "unit"));

    CHECK(mcs_results_kind(r, "/a") == MCS_RES_GROUP);
    CHECK(mcs_results_kind(r, "/a/b/c/one") == MCS_RES_DATASET);
    CHECK(mcs_results_kind(r, "/a/b/x/one") == MCS_RES_NONE);
    CHECK(mcs_results_kind(r, "/") == MCS_RES_GROUP);
    CHECK(mcs_results_exists(r, "/meta"));
    CHECK(!mcs_results_exists(r, "/stage9"));
    mcs_results_close(&r);
    CHECK(e.status == MCS_OK);
}

static void test_list_order(void)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    const char *out = tpath("list.h5");
    CHECK(mcs_results_create(&r, out, "", &e) == MCS_OK);
    const char *names[] = {"zeta", "alpha", "mid", "Beta"};
    double x = 1;
    size_t one = 1;
    char p[64];
    for (int i = 0; i < 4; i++) {
        snprintf(p, sizeof p, "/g/%s", names[i]);
        CHECK(mcs_results_write(r, p, 1, &one, &x, "-", &e) == MCS_OK);
    }
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    char **v = NULL;
    int n = 0;
    /* the order written, not alphabetical: channels export in the model's order */
    CHECK(mcs_results_list(r, "/g", &v, &n, &e) == MCS_OK);
    CHECK(n == 4);
    for (int i = 0; i < n && i < 4; i++) CHECK(strcmp(v[i], names[i]) == 0);
    mcs_results_list_free(&v, n);
    CHECK(v == NULL);
    CHECK(mcs_results_list(r, "/", &v, &n, &e) == MCS_OK);
    CHECK(n == 2 && strcmp(v[0], "meta") == 0 && strcmp(v[1], "g") == 0);
    mcs_results_list_free(&v, n);
    mcs_error e2 = {0};
    CHECK(mcs_results_list(r, "/g/zeta", &v, &n, &e2) == MCS_ERR_KEY);
    mcs_results_close(&r);
}

/* every layout helper, read back */
static void write_layout(mcs_results *r, mcs_error *e)
{
    double t[4] = {0, 0.001, 0.002, 0.003}, y[4] = {0, -9.81, -19.62, 3};
    CHECK(mcs_results_put_time(r, 1, 4, t, e) == MCS_OK);
    CHECK(mcs_results_put_channel(r, 1, "head_ax", 4, y, "m/s^2", "SAE J211 local", 1000,
                                  "head", e) == MCS_OK);
    CHECK(mcs_results_put_energy(r, 1, "kinetic", 4, y, e) == MCS_OK);
    double pos[12], q[16];
    for (int i = 0; i < 12; i++) pos[i] = i * 0.25;
    for (int i = 0; i < 16; i++) q[i] = (i % 4 == 0) ? 1.0 : 0.0;
    CHECK(mcs_results_put_body(r, 1, "head", "position", 4, pos, e) == MCS_OK);
    CHECK(mcs_results_put_body(r, 1, "head", "orientation", 4, q, e) == MCS_OK);
    CHECK(mcs_results_put_injury(r, 1, "HIC15", 512.0, "-", 700.0, 0.010, 0.025, "head_ax", e) ==
          MCS_OK);
    double nodes[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    int quad[4] = {0, 1, 2, 3};
    CHECK(mcs_results_put_mesh(r, 3, "plate", 4, nodes, 1, 4, quad, "quad4", 0, e) == MCS_OK);
    double f[4] = {0, 1e3, 2e3, 1.5e3}, d[4] = {0, 1e-3, 2e-3, 2.5e-3};
    CHECK(mcs_results_put_rigidwall(r, "ram", 4, f, d, e) == MCS_OK);
    double lo[6] = {0, 0, 0.01, 1000, 0.02, 3000}, un[4] = {0.005, 0, 0.02, 3000};
    CHECK(mcs_results_put_curve(r, "fork", 3, lo, 2, un, "m", "N", e) == MCS_OK);
}

static void test_layout_roundtrip(void)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    const char *out = tpath("layout.h5");
    CHECK(mcs_results_create(&r, out, "", &e) == MCS_OK);
    write_layout(r, &e);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    mcs_array a = {0};
    char *s = NULL;
    double v;
    CHECK(mcs_results_read(r, "/stage1/channels/head_ax", &a, &e) == MCS_OK);
    CHECK(a.n == 4 && a.v && a.v[1] == -9.81 && strcmp(a.unit, "m/s^2") == 0);
    mcs_array_free(&a);
    CHECK(mcs_results_attr_str(r, "/stage1/channels/head_ax", "frame", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, "SAE J211 local") == 0);
    free(s);
    CHECK(mcs_results_attr_str(r, "/stage1/channels/head_ax", "body", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, "head") == 0);
    free(s);
    CHECK(mcs_results_attr_double(r, "/stage1/channels/head_ax", "cfc", &v, &e) == MCS_OK);
    CHECK(v == 1000);
    CHECK(mcs_results_read(r, "/stage1/energy/kinetic", &a, &e) == MCS_OK);
    CHECK(strcmp(a.unit, "J") == 0 && a.v && a.v[3] == 3);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/stage1/bodies/head/orientation", &a, &e) == MCS_OK);
    CHECK(a.rank == 2 && a.dims[0] == 4 && a.dims[1] == 4 && strcmp(a.unit, "-") == 0);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/stage1/bodies/head/position", &a, &e) == MCS_OK);
    CHECK(a.dims[1] == 3 && strcmp(a.unit, "m") == 0 && a.v && a.v[11] == 2.75);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/stage1/injury/HIC15", &a, &e) == MCS_OK);
    CHECK(a.rank == 0 && a.v && a.v[0] == 512.0);
    mcs_array_free(&a);
    CHECK(mcs_results_attr_double(r, "/stage1/injury/HIC15", "limit", &v, &e) == MCS_OK);
    CHECK(v == 700.0);
    CHECK(mcs_results_attr_double(r, "/stage1/injury/HIC15", "t2", &v, &e) == MCS_OK);
    CHECK(v == 0.025);
    CHECK(mcs_results_attr_str(r, "/stage1/injury/HIC15", "channel", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, "head_ax") == 0);
    free(s);
    CHECK(mcs_results_read_int(r, "/stage3/mesh/plate/elements", &a, &e) == MCS_OK);
    CHECK(a.dims[0] == 1 && a.dims[1] == 4 && a.iv && a.iv[2] == 2);
    mcs_array_free(&a);
    CHECK(mcs_results_attr_str(r, "/stage3/mesh/plate/elements", "type", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, "quad4") == 0);
    free(s);
    CHECK(mcs_results_attr_double(r, "/stage3/mesh/plate/nodes", "node_offset", &v, &e) ==
          MCS_OK);
    CHECK(v == 0);
    CHECK(mcs_results_read(r, "/stage3/rigidwall/ram/force", &a, &e) == MCS_OK);
    CHECK(strcmp(a.unit, "N") == 0 && a.v && a.v[2] == 2e3);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/stage3/rigidwall/ram/displacement", &a, &e) == MCS_OK);
    CHECK(strcmp(a.unit, "m") == 0 && a.v && a.v[3] == 2.5e-3);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/curves/fork/loading", &a, &e) == MCS_OK);
    CHECK(a.dims[0] == 3 && a.dims[1] == 2 && strcmp(a.unit, "m,N") == 0 && a.v &&
          a.v[5] == 3000);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/curves/fork/unloading", &a, &e) == MCS_OK);
    CHECK(a.dims[0] == 2 && a.v && a.v[0] == 0.005);
    mcs_array_free(&a);
    mcs_results_close(&r);
    CHECK(e.status == MCS_OK);

    /* one call with a reference, as injury/compare use it */
    char ref[300];
    snprintf(ref, sizeof ref, "%s:/stage1/channels/head_ax", out);
    CHECK(mcs_results_read_ref(ref, &a, &e) == MCS_OK);
    CHECK(a.n == 4 && a.v && a.v[2] == -19.62);
    mcs_array_free(&a);
    mcs_error e2 = {0};
    snprintf(ref, sizeof ref, "%s:/stage1/channels/nope", out);
    CHECK(mcs_results_read_ref(ref, &a, &e2) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(e2.msg, "/stage1/channels/nope");
}

/* the layout file read with the HDF5 library itself, not our reader: the shapes, the
 * row-major values and the unit attributes are what write_layout passed (a round trip through
 * our writer and reader alone would pass with both transposing or dropping the unit) */
static void h5_expect(hid_t f, const char *path, int rank, const hsize_t *dims, const double *v,
                      const char *unit)
{
    hid_t d = H5Dopen2(f, path, H5P_DEFAULT);
    CHECK(d >= 0);
    if (d < 0) return;
    hid_t sp = H5Dget_space(d);
    hsize_t got[4] = {0};
    CHECK(H5Sget_simple_extent_ndims(sp) == rank);
    H5Sget_simple_extent_dims(sp, got, NULL);
    hsize_t n = 1;
    for (int i = 0; i < rank; i++) {
        CHECK(got[i] == dims[i]);
        n *= dims[i];
    }
    double buf[64] = {0};
    if (n <= 64 && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) >= 0)
        for (hsize_t i = 0; i < n; i++)
            CHECK(buf[i] == v[i]);
    else
        CHECK(!"H5Dread");
    char text[32] = "";
    hid_t a = H5Aopen(d, "unit", H5P_DEFAULT);
    hid_t t = a >= 0 ? H5Aget_type(a) : -1;
    CHECK(a >= 0 && t >= 0 && H5Tget_class(t) == H5T_STRING && H5Tget_size(t) < sizeof text);
    if (t >= 0 && H5Tget_size(t) < sizeof text) H5Aread(a, t, text);
    CHECK(strcmp(text, unit) == 0);
    if (t >= 0) H5Tclose(t);
    if (a >= 0) H5Aclose(a);
    H5Sclose(sp);
    H5Dclose(d);
}

static void test_layout_read_by_hdf5(void)
{
    hid_t f = H5Fopen(tpath("layout.h5"), H5F_ACC_RDONLY, H5P_DEFAULT);
    CHECK(f >= 0);
    if (f < 0) return;
    double pos[12], q[16];
    for (int i = 0; i < 12; i++) pos[i] = i * 0.25; /* row i: body position at output i */
    for (int i = 0; i < 16; i++) q[i] = (i % 4 == 0) ? 1.0 : 0.0;
    const double y[4] = {0, -9.81, -19.62, 3}, t[4] = {0, 0.001, 0.002, 0.003};
    const double lo[6] = {0, 0, 0.01, 1000, 0.02, 3000}, hic = 512.0;
    h5_expect(f, "/stage1/time", 1, (hsize_t[]){4}, t, "s");
    h5_expect(f, "/stage1/channels/head_ax", 1, (hsize_t[]){4}, y, "m/s^2");
    h5_expect(f, "/stage1/energy/kinetic", 1, (hsize_t[]){4}, y, "J");
    h5_expect(f, "/stage1/bodies/head/position", 2, (hsize_t[]){4, 3}, pos, "m");
    h5_expect(f, "/stage1/bodies/head/orientation", 2, (hsize_t[]){4, 4}, q, "-");
    h5_expect(f, "/stage1/injury/HIC15", 0, NULL, &hic, "-");
    h5_expect(f, "/curves/fork/loading", 2, (hsize_t[]){3, 2}, lo, "m,N");
    /* connectivity is stored as integers */
    hid_t d = H5Dopen2(f, "/stage3/mesh/plate/elements", H5P_DEFAULT);
    hid_t t_el = d >= 0 ? H5Dget_type(d) : -1;
    CHECK(t_el >= 0 && H5Tget_class(t_el) == H5T_INTEGER);
    int el[4] = {-1, -1, -1, -1};
    CHECK(d >= 0 && H5Dread(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, el) >= 0);
    CHECK(el[0] == 0 && el[1] == 1 && el[2] == 2 && el[3] == 3);
    if (t_el >= 0) H5Tclose(t_el);
    if (d >= 0) H5Dclose(d);
    H5Fclose(f);
}

/* walk every object below group; count datasets and those lacking a unit */
static void walk_units(mcs_results *r, const char *group, int *ndset, int *nbad)
{
    char **v = NULL;
    int n = 0;
    mcs_error e = {0};
    if (mcs_results_list(r, group, &v, &n, &e) != MCS_OK) {
        (*nbad)++;
        return;
    }
    for (int i = 0; i < n; i++) {
        char p[1024];
        snprintf(p, sizeof p, "%s/%s", strcmp(group, "/") ? group : "", v[i]);
        mcs_res_kind k = mcs_results_kind(r, p);
        if (k == MCS_RES_GROUP) walk_units(r, p, ndset, nbad);
        if (k != MCS_RES_DATASET) continue;
        (*ndset)++;
        char *u = NULL;
        if (mcs_results_attr_str(r, p, "unit", &u, &e) != MCS_OK || !u || !*u) {
            fprintf(stderr, "no unit on %s\n", p);
            (*nbad)++;
        }
        free(u);
    }
    mcs_results_list_free(&v, n);
}

static void test_unit_on_every_dataset(void)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    const char *out = tpath("units.h5");
    CHECK(mcs_results_create(&r, out, "", &e) == MCS_OK);
    write_layout(r, &e);
    mcs_results_series *ft, *fd, *bs;
    CHECK(mcs_results_field_series(r, 3, 4, &ft, &fd, &e) == MCS_OK);
    CHECK(mcs_results_body_series(r, 1, "torso", "velocity", &bs, &e) == MCS_OK);
    double row[12] = {0}, t0 = 0;
    CHECK(mcs_results_series_append(ft, &t0, &e) == MCS_OK);
    CHECK(mcs_results_series_append(fd, row, &e) == MCS_OK);
    CHECK(mcs_results_series_append(bs, row, &e) == MCS_OK);
    /* the API refuses a dataset without a unit */
    mcs_error e2 = {0};
    size_t one = 1;
    CHECK(mcs_results_write(r, "/x/nounit", 1, &one, row, NULL, &e2) == MCS_ERR_USAGE);
    CHECK_STR_CONTAINS(e2.msg, "unit");
    mcs_error_clear(&e2);
    CHECK(mcs_results_write(r, "/x/nounit", 1, &one, row, "", &e2) == MCS_ERR_USAGE);
    mcs_error_clear(&e2);
    mcs_results_series *s;
    CHECK(mcs_results_series_create(r, "/x/s", 1, NULL, NULL, 0, &s, &e2) == MCS_ERR_USAGE);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);

    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    int ndset = 0, nbad = 0;
    walk_units(r, "/", &ndset, &nbad);
    /* time, channel, energy, 2 body, injury, 2 mesh, 2 wall, 2 curve, 2 field, body series */
    CHECK(ndset == 15);
    CHECK(nbad == 0);
    mcs_results_close(&r);
}

static void test_abort_keeps_earlier_file(void)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    const char *out = tpath("run.h5");
    double t[2] = {0, 1};
    CHECK(mcs_results_create(&r, out, "first run", &e) == MCS_OK);
    CHECK(mcs_results_put_time(r, 1, 2, t, &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    size_t n0, n1;
    char *before = th_slurp(out, &n0);

    /* a second run that fails half-way: the earlier file stays byte for byte */
    CHECK(mcs_results_create(&r, out, "second run", &e) == MCS_OK);
    CHECK(mcs_results_put_time(r, 2, 2, t, &e) == MCS_OK);
    mcs_results_series *s;
    CHECK(mcs_results_series_create(r, "/stage2/channels/x", 1, NULL, "m", 0, &s, &e) == MCS_OK);
    for (int i = 0; i < 100; i++) CHECK(mcs_results_series_append(s, t, &e) == MCS_OK);
    CHECK(count_entries("run.h5.tmp.") == 1);
    mcs_results_abort(&r);
    CHECK(r == NULL);
    CHECK(count_entries("run.h5.tmp.") == 0);
    char *after = th_slurp(out, &n1);
    CHECK(before && after && n0 == n1 && memcmp(before, after, n0) == 0);
    free(after);

    /* closing an uncommitted writer is an abort too */
    CHECK(mcs_results_create(&r, out, "third run", &e) == MCS_OK);
    mcs_results_close(&r);
    CHECK(count_entries("run.h5.tmp.") == 0);
    after = th_slurp(out, &n1);
    CHECK(after && n0 == n1 && memcmp(before, after, n0) == 0);
    free(after);
    free(before);

    /* a run with no earlier file that aborts leaves nothing at all */
    const char *fresh = tpath("never.h5");
    CHECK(mcs_results_create(&r, fresh, "", &e) == MCS_OK);
    mcs_results_abort(&r);
    CHECK(!file_exists(fresh));
    CHECK(count_entries("never.h5") == 0);
    mcs_results_abort(&r); /* NULL is fine */
    CHECK(e.status == MCS_OK);
}

static void test_series_10000(void)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    const char *out = tpath("series.h5");
    CHECK(mcs_results_create(&r, out, "", &e) == MCS_OK);
    mcs_results_series *st, *sq, *sf;
    size_t k = 4, frow[2] = {5, 3};
    CHECK(mcs_results_series_create(r, "/stage1/time", 1, NULL, "s", 0, &st, &e) == MCS_OK);
    /* 333 rows per chunk: 10 000 is not a multiple, so the last chunk is partial */
    CHECK(mcs_results_series_create(r, "/stage1/bodies/b/orientation", 2, &k, "-", 333, &sq,
                                    &e) == MCS_OK);
    CHECK(mcs_results_series_create(r, "/stage1/fields/displacement", 3, frow, "m", 7, &sf,
                                    &e) == MCS_OK);
    CHECK(mcs_results_series_row_len(sq) == 4 && mcs_results_series_row_len(sf) == 15);
    const int nt = 10000;
    for (int i = 0; i < nt; i++) {
        double t = i * 1e-4, q[4] = {i, -i, 0.5 * i, 1.0 / (i + 1)}, f[15];
        for (int j = 0; j < 15; j++) f[j] = i * 100.0 + j;
        CHECK(mcs_results_series_append(st, &t, &e) == MCS_OK);
        CHECK(mcs_results_series_append(sq, q, &e) == MCS_OK);
        if (i < 50) CHECK(mcs_results_series_append(sf, f, &e) == MCS_OK);
    }
    CHECK(mcs_results_series_rows(st) == (size_t)nt && mcs_results_series_rows(sf) == 50);
    /* read back before commit: buffered rows are flushed first */
    mcs_array a = {0};
    CHECK(mcs_results_read(r, "/stage1/time", &a, &e) == MCS_OK);
    CHECK(a.n == (size_t)nt);
    mcs_array_free(&a);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);

    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    CHECK(mcs_results_read(r, "/stage1/time", &a, &e) == MCS_OK);
    CHECK(a.rank == 1 && a.n == (size_t)nt && strcmp(a.unit, "s") == 0);
    int bad = 0;
    for (int i = 0; i < nt && a.v; i++) bad += a.v[i] != i * 1e-4;
    CHECK(bad == 0);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/stage1/bodies/b/orientation", &a, &e) == MCS_OK);
    CHECK(a.rank == 2 && a.dims[0] == (size_t)nt && a.dims[1] == 4);
    bad = 0;
    for (int i = 0; i < nt && a.v; i++)
        bad += a.v[4 * i] != i || a.v[4 * i + 1] != -i || a.v[4 * i + 2] != 0.5 * i ||
               a.v[4 * i + 3] != 1.0 / (i + 1);
    CHECK(bad == 0);
    mcs_array_free(&a);
    CHECK(mcs_results_read(r, "/stage1/fields/displacement", &a, &e) == MCS_OK);
    CHECK(a.rank == 3 && a.dims[0] == 50 && a.dims[1] == 5 && a.dims[2] == 3);
    bad = 0;
    for (int i = 0; i < 50 && a.v; i++)
        for (int j = 0; j < 15; j++) bad += a.v[15 * i + j] != i * 100.0 + j;
    CHECK(bad == 0);
    mcs_array_free(&a);
    mcs_results_close(&r);
    CHECK(e.status == MCS_OK);
}

static void test_append_does_not_allocate(void)
{
    /* heap in use stays the same while rows go into the chunk buffer (glibc's count; under
     * ASan's allocator mallinfo2 reports nothing and this holds trivially) */
    mcs_error e = {0};
    mcs_results *r = NULL;
    CHECK(mcs_results_create(&r, tpath("noalloc.h5"), "", &e) == MCS_OK);
    mcs_results_series *s;
    size_t k = 6;
    CHECK(mcs_results_series_create(r, "/stage1/bodies/b/x", 2, &k, "m", 1000, &s, &e) == MCS_OK);
    double row[6] = {1, 2, 3, 4, 5, 6};
    CHECK(mcs_results_series_append(s, row, &e) == MCS_OK);
    size_t before = mallinfo2().uordblks;
    for (int i = 0; i < 998; i++) mcs_results_series_append(s, row, &e);
    size_t after = mallinfo2().uordblks;
    CHECK(after == before);
    CHECK(mcs_results_series_rows(s) == 999);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    CHECK(e.status == MCS_OK);
}

static void test_errors(void)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    /* missing file, a directory, not HDF5, an unwritable place */
    CHECK(mcs_results_open(&r, tpath("missing.h5"), &e) == MCS_ERR_IO && r == NULL);
    CHECK_STR_CONTAINS(e.msg, "missing.h5");
    mcs_error_clear(&e);
    CHECK(mcs_results_open(&r, tdir, &e) == MCS_ERR_IO);
    mcs_error_clear(&e);
    FILE *f = fopen(tpath("text.h5"), "w");
    fputs("this is not HDF5\n", f);
    fclose(f);
    CHECK(mcs_results_open(&r, tpath("text.h5"), &e) == MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(e.msg, "not an HDF5 file");
    mcs_error_clear(&e);
    CHECK(mcs_results_create(&r, tpath("no/such/dir/out.h5"), "", &e) == MCS_ERR_IO);
    CHECK_STR_CONTAINS(e.msg, "out.h5");
    mcs_error_clear(&e);
    CHECK(mcs_results_read_ref("nocolon.h5", &(mcs_array){0}, &e) == MCS_ERR_USAGE);
    mcs_error_clear(&e);

    const char *out = tpath("err.h5");
    CHECK(mcs_results_create(&r, out, "", &e) == MCS_OK);
    double x[2] = {1, 2};
    size_t two = 2;
    CHECK(mcs_results_write(r, "/a/x", 1, &two, x, "m", &e) == MCS_OK);
    CHECK(mcs_results_write(r, "/a/x", 1, &two, x, "m", &e) == MCS_ERR_USAGE);
    CHECK_STR_CONTAINS(e.msg, "already exists");
    mcs_error_clear(&e);
    CHECK(mcs_results_write(r, "/a/x/y", 1, &two, x, "m", &e) == MCS_ERR_USAGE);
    CHECK_STR_CONTAINS(e.msg, "not a group");
    mcs_error_clear(&e);
    CHECK(mcs_results_write(r, "relative", 1, &two, x, "m", &e) == MCS_ERR_USAGE);
    mcs_error_clear(&e);
    CHECK(mcs_results_write(r, "/a//b", 1, &two, x, "m", &e) == MCS_ERR_USAGE);
    mcs_error_clear(&e);
    CHECK(mcs_results_write(r, "/a/r4", 4, (size_t[4]){1, 1, 1, 2}, x, "m", &e) == MCS_ERR_USAGE);
    mcs_error_clear(&e);
    CHECK(mcs_results_set_attr_str(r, "/nothing", "a", "b", &e) == MCS_ERR_KEY);
    mcs_error_clear(&e);
    CHECK(mcs_results_put_energy(r, 1, "kinetik", 2, x, &e) == MCS_ERR_USAGE);
    CHECK_STR_CONTAINS(e.msg, "kinetik");
    mcs_error_clear(&e);
    CHECK(mcs_results_put_body(r, 1, "b", "speed", 1, x, &e) == MCS_ERR_USAGE);
    mcs_error_clear(&e);
    CHECK(mcs_results_put_channel(r, 4, "c", 2, x, "m", NULL, 0, NULL, &e) == MCS_ERR_USAGE);
    mcs_error_clear(&e);
    CHECK(mcs_results_put_channel(r, 1, "a/b", 2, x, "m", NULL, 0, NULL, &e) == MCS_ERR_USAGE);
    mcs_error_clear(&e);
    int bad_el[4] = {0, 1, 2, 9};
    double nodes[9] = {0};
    CHECK(mcs_results_put_mesh(r, 3, "p", 3, nodes, 1, 4, bad_el, NULL, 0, &e) == MCS_ERR_RANGE);
    mcs_error_clear(&e);
    CHECK(mcs_results_put_mesh(r, 3, "p", 3, nodes, 1, 4, bad_el, "tri3", 0, &e) ==
          MCS_ERR_USAGE);
    mcs_error_clear(&e);
    mcs_array a = {0};
    CHECK(mcs_results_read(r, "/a", &a, &e) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(e.msg, "is a group");
    mcs_error_clear(&e);
    char *s = NULL;
    CHECK(mcs_results_attr_str(r, "/a/x", "nope", &s, &e) == MCS_ERR_KEY && !s);
    mcs_error_clear(&e);
    CHECK(mcs_results_attr_double(r, "/a/x", "unit", &(double){0}, &e) == MCS_ERR_TYPE);
    mcs_error_clear(&e);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);

    /* writes on a reader are refused */
    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    CHECK(mcs_results_write(r, "/b", 1, &two, x, "m", &e) == MCS_ERR_USAGE);
    CHECK_STR_CONTAINS(e.msg, "read-only");
    mcs_error_clear(&e);
    CHECK(mcs_results_commit(&r, &e) == MCS_ERR_USAGE && r == NULL);
}

static void test_big_scenario(void)
{
    /* 300 kB of YAML: above HDF5's 64 KiB limit for compact attributes */
    size_t n = 300000;
    char *yaml = malloc(n + 1);
    for (size_t i = 0; i < n; i++) yaml[i] = (i % 61 == 60) ? '\n' : (char)('a' + i % 26);
    yaml[n] = 0;
    mcs_error e = {0};
    mcs_results *r = NULL;
    const char *out = tpath("big.h5");
    CHECK(mcs_results_create(&r, out, yaml, &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    char *s = NULL;
    CHECK(mcs_results_attr_str(r, "/meta", "scenario", &s, &e) == MCS_OK);
    CHECK(s && strlen(s) == n && strcmp(s, yaml) == 0);
    free(s);
    free(yaml);
    mcs_results_close(&r);
    CHECK(e.status == MCS_OK);
}

static void test_append_stage(void)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    const char *out = tpath("append.h5");
    double t[3] = {0, 1, 2};
    CHECK(mcs_results_create(&r, out, "scenario text", &e) == MCS_OK);
    CHECK(mcs_results_put_time(r, 1, 3, t, &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    size_t n0, n1;
    char *before = th_slurp(out, &n0);
    /* a later stage that fails leaves the file as it was */
    CHECK(mcs_results_append(&r, out, &e) == MCS_OK);
    CHECK(mcs_results_put_time(r, 2, 3, t, &e) == MCS_OK);
    mcs_results_abort(&r);
    char *after = th_slurp(out, &n1);
    CHECK(before && after && n0 == n1 && memcmp(before, after, n0) == 0);
    free(before);
    free(after);
    CHECK(count_entries("append.h5.tmp") == 0);
    /* one that succeeds adds its group and keeps /meta and stage 1 */
    CHECK(mcs_results_append(&r, out, &e) == MCS_OK);
    CHECK(mcs_results_put_time(r, 2, 3, t, &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    CHECK(mcs_results_open(&r, out, &e) == MCS_OK);
    CHECK(mcs_results_kind(r, "/stage1/time") == MCS_RES_DATASET);
    CHECK(mcs_results_kind(r, "/stage2/time") == MCS_RES_DATASET);
    char *s = NULL;
    CHECK(mcs_results_attr_str(r, "/meta", "scenario", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, "scenario text") == 0);
    free(s);
    mcs_results_close(&r);
    CHECK(e.status == MCS_OK);
    /* appending to a file that is not a results file */
    mcs_error e2 = {0};
    CHECK(mcs_results_append(&r, tpath("nothere.h5"), &e2) == MCS_ERR_IO);
}

static void test_deterministic_bytes(void)
{
    /* same input, same bytes: no object time stamps, creation time from SOURCE_DATE_EPOCH */
    setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
    const char *p[2] = {tpath("det_a.h5"), tpath("det_b.h5")};
    mcs_error e = {0};
    for (int k = 0; k < 2; k++) {
        mcs_results *r = NULL;
        CHECK(mcs_results_create(&r, p[k], "same", &e) == MCS_OK);
        write_layout(r, &e);
        CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    }
    unsetenv("SOURCE_DATE_EPOCH");
    size_t na, nb;
    char *a = th_slurp(p[0], &na), *b = th_slurp(p[1], &nb);
    CHECK(a && b && na == nb && memcmp(a, b, na) == 0);
    free(a);
    free(b);
    mcs_results *r = NULL;
    char *s = NULL;
    CHECK(mcs_results_open(&r, p[0], &e) == MCS_OK);
    CHECK(mcs_results_attr_str(r, "/meta", "created", &s, &e) == MCS_OK);
    CHECK(s && strcmp(s, "2023-11-14T22:13:20Z") == 0);
    free(s);
    mcs_results_close(&r);
}

int main(void)
{
    make_tdir();
    RUN(test_create_commit_meta);
    RUN(test_arrays_roundtrip);
    RUN(test_list_order);
    RUN(test_layout_roundtrip);
    RUN(test_layout_read_by_hdf5);
    RUN(test_unit_on_every_dataset);
    RUN(test_abort_keeps_earlier_file);
    RUN(test_series_10000);
    RUN(test_append_does_not_allocate);
    RUN(test_errors);
    RUN(test_big_scenario);
    RUN(test_append_stage);
    RUN(test_deterministic_bytes);
    rm_tdir();
    TEST_END();
}

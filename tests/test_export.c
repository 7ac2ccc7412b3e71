/* test_export.c: `mcrash export` — CSV content checked against the values written, every
 * HDF5 reference of the XDMF file resolved with the stated shape, the time values, bad input.
 * With `pvpython` installed (Debian paraview) the XDMF file is also opened in ParaView.
 * `test_export --write-sample DIR` only writes DIR/sample.h5 (for `make check-paraview`). */
#include "core/mcs_results.h"
#include "core/mcs_results_export.h"
#include "tests/cli_util.h"
#include "tests/harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char tdir[64];

#define tpath(name) th_path(tdir, (name))

/* ---- the sample run: analytic motions, so every exported number can be checked ---- */

enum { NT = 201, NOUT = 11, NN = 27 };
static const double DT = 1e-3;      /* stage-1 output interval [s]  */
static const double V0 = 13.9;      /* forward speed [m/s]          */
static const double W = 4.0;        /* pitch rate [rad/s]           */
static const double CRUSH = 0.05;   /* stage-3 crush rate [m/s]     */
static const double G = 9.80665;    /* gravity [m/s^2]              */

static double head_ax(double t) { return -200.0 * G * sin(M_PI * t / 0.2); }
static double head_z(double t) { return 1.2 - 0.5 * G * t * t; }
static double t3(int i) { return i * 2e-3; } /* stage-3 output times [s] */

/* stage 3: a quad plate (4 x 3 nodes), one hex, two triangles, a 2-segment beam */
static void sample_mesh(mcs_results *r, mcs_error *e)
{
    double plate[12 * 3], hex[8 * 3], tri[4 * 3], beam[3 * 3];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) {
            double *p = &plate[3 * (4 * j + i)];
            p[0] = 0.1 * i, p[1] = 0.1 * j, p[2] = 0;
        }
    int quads[6 * 4], n = 0;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 3; i++) {
            int a = 4 * j + i;
            quads[n++] = a, quads[n++] = a + 1, quads[n++] = a + 5, quads[n++] = a + 4;
        }
    static const double cube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (int i = 0; i < 8; i++)
        for (int c = 0; c < 3; c++) hex[3 * i + c] = 0.05 * cube[i][c] + (c == 2 ? 0.2 : 0);
    int hexel[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    for (int i = 0; i < 4; i++) tri[3 * i] = 0.5 + 0.1 * (i % 2), tri[3 * i + 1] = 0.1 * (i / 2), tri[3 * i + 2] = 0;
    int tris[6] = {0, 1, 3, 0, 3, 2};
    for (int i = 0; i < 3; i++) beam[3 * i] = 0, beam[3 * i + 1] = -0.1, beam[3 * i + 2] = 0.1 * i;
    int lines[4] = {0, 1, 1, 2};
    CHECK(mcs_results_put_mesh(r, 3, "plate", 12, plate, 6, 4, quads, "quad4", 0, e) == MCS_OK);
    CHECK(mcs_results_put_mesh(r, 3, "block", 8, hex, 1, 8, hexel, NULL, 12, e) == MCS_OK);
    CHECK(mcs_results_put_mesh(r, 3, "skin", 4, tri, 2, 3, tris, "tri3", 20, e) == MCS_OK);
    CHECK(mcs_results_put_mesh(r, 3, "beam", 3, beam, 2, 2, lines, "line2", 24, e) == MCS_OK);
    /* every node moves down by CRUSH * t: u = (0, 0, -CRUSH t) */
    mcs_results_series *st, *sd;
    CHECK(mcs_results_field_series(r, 3, NN, &st, &sd, e) == MCS_OK);
    for (int i = 0; i < NOUT; i++) {
        double t = t3(i), u[NN * 3];
        for (int k = 0; k < NN; k++) u[3 * k] = 0, u[3 * k + 1] = 0, u[3 * k + 2] = -CRUSH * t;
        CHECK(mcs_results_series_append(st, &t, e) == MCS_OK);
        CHECK(mcs_results_series_append(sd, u, e) == MCS_OK);
    }
}

static int write_sample(const char *path)
{
    mcs_error e = {0};
    mcs_results *r = NULL;
    if (mcs_results_create(&r, path, "mcrash: 1\nname: sample\n", &e)) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    /* stage 1: two rigid bodies over 0.2 s, head channels and energies */
    static double t[NT], ax[NT], dx[NT], ek[NT], ep[NT], pos[2][NT * 3], q[2][NT * 4];
    for (int i = 0; i < NT; i++) {
        t[i] = i * DT;
        ax[i] = head_ax(t[i]);
        dx[i] = -0.01 * t[i];
        ek[i] = 0.5 * 250 * V0 * V0;
        ep[i] = 250 * G * head_z(t[i]);
        for (int b = 0; b < 2; b++) {
            pos[b][3 * i] = V0 * t[i] + b * 0.5;
            pos[b][3 * i + 1] = 0;
            pos[b][3 * i + 2] = b ? head_z(t[i]) : 0.6;
            /* rotation by W t about y: q = (cos(W t / 2), 0, sin(W t / 2), 0) */
            double h = b ? 0.5 * W * t[i] : 0;
            q[b][4 * i] = cos(h), q[b][4 * i + 1] = 0, q[b][4 * i + 2] = sin(h), q[b][4 * i + 3] = 0;
        }
    }
    CHECK(mcs_results_put_time(r, 1, NT, t, &e) == MCS_OK);
    CHECK(mcs_results_put_channel(r, 1, "head_ax", NT, ax, "m/s^2", "SAE J211 local", 1000,
                                  "rider_head", &e) == MCS_OK);
    CHECK(mcs_results_put_channel(r, 1, "chest_dx", NT, dx, "m", "SAE J211 local", 180,
                                  "rider_chest", &e) == MCS_OK);
    CHECK(mcs_results_put_energy(r, 1, "kinetic", NT, ek, &e) == MCS_OK);
    CHECK(mcs_results_put_energy(r, 1, "potential", NT, ep, &e) == MCS_OK);
    CHECK(mcs_results_put_body(r, 1, "frame", "position", NT, pos[0], &e) == MCS_OK);
    CHECK(mcs_results_put_body(r, 1, "frame", "orientation", NT, q[0], &e) == MCS_OK);
    CHECK(mcs_results_put_body(r, 1, "rider_head", "position", NT, pos[1], &e) == MCS_OK);
    CHECK(mcs_results_put_body(r, 1, "rider_head", "orientation", NT, q[1], &e) == MCS_OK);
    sample_mesh(r, &e);
    /* stage 3: a wall force channel F = 1e4 N/s * t on its own time base */
    double tw[NOUT], fw[NOUT];
    for (int i = 0; i < NOUT; i++) tw[i] = t3(i), fw[i] = 1e4 * t3(i);
    CHECK(mcs_results_put_time(r, 3, NOUT, tw, &e) == MCS_OK);
    CHECK(mcs_results_put_channel(r, 3, "wall_force", NOUT, fw, "N", "world", 0, NULL, &e) ==
          MCS_OK);
    mcs_status st = mcs_results_commit(&r, &e);
    if (st) fprintf(stderr, "%s\n", e.msg);
    return st != MCS_OK;
}

/* ---- CSV ---- */

/* read a CSV: header line into hdr, then rows of numbers; returns the row count */
static int read_csv(const char *path, char *hdr, size_t nh, double *v, int maxcols, int maxrows,
                    int *ncols)
{
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    char line[8192];
    int rows = 0;
    *ncols = 0;
    if (!fgets(line, sizeof line, f)) {
        fclose(f);
        return -1;
    }
    memcpy(hdr, line, nh - 1);
    hdr[nh - 1] = 0;
    while (fgets(line, sizeof line, f) && rows < maxrows) {
        int c = 0;
        for (char *p = line, *end; c < maxcols; p = end + 1, c++) {
            v[rows * maxcols + c] = strtod(p, &end);
            if (end == p) break;
            if (*end != ',') {
                c++;
                break;
            }
        }
        *ncols = c;
        rows++;
    }
    fclose(f);
    return rows;
}

static void test_csv_content(void)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "export %s --csv %s", tpath("sample.h5"), tpath("csv/out"));
    cli_result *res = cli_run(cmd);
    CHECK(res->status == 0);
    CHECK_STR_CONTAINS(res->out, "wrote 3 CSV files");
    static double v[NT * 8];
    char hdr[1024];
    int nc = 0;
    int rows = read_csv(tpath("csv/out/stage1_channels.csv"), hdr, sizeof hdr, v, 8, NT + 5, &nc);
    CHECK(rows == NT && nc == 3);
    CHECK(strcmp(hdr, "time [s], head_ax [m/s^2], chest_dx [m]\n") == 0);
    double worst = 0;
    for (int i = 0; i < rows; i++) {
        double t = i * DT;
        worst = fmax(worst, fabs(v[i * 8] - t));
        worst = fmax(worst, fabs(v[i * 8 + 1] - head_ax(t)) / (200 * G));
        worst = fmax(worst, fabs(v[i * 8 + 2] + 0.01 * t));
    }
    /* 15 significant digits written */
    CHECK(worst < 1e-14);
    rows = read_csv(tpath("csv/out/stage1_energy.csv"), hdr, sizeof hdr, v, 8, NT + 5, &nc);
    CHECK(rows == NT && nc == 3);
    CHECK(strcmp(hdr, "time [s], kinetic [J], potential [J]\n") == 0);
    CHECK_REL(v[50 * 8 + 1], 0.5 * 250 * V0 * V0, 1e-14);
    CHECK_REL(v[50 * 8 + 2], 250 * G * head_z(50 * DT), 1e-14);
    rows = read_csv(tpath("csv/out/stage3_channels.csv"), hdr, sizeof hdr, v, 8, NT + 5, &nc);
    CHECK(rows == NOUT && nc == 2);
    CHECK(strcmp(hdr, "time [s], wall_force [N]\n") == 0);
    for (int i = 0; i < rows && i < NOUT; i++) {
        CHECK_NEAR(v[i * 8], t3(i), 1e-17);
        CHECK_NEAR(v[i * 8 + 1], 1e4 * t3(i), 1e-12);
    }
    /* stage 3 has no energies: no file for them */
    CHECK(access(tpath("csv/out/stage3_energy.csv"), F_OK) != 0);
}

/* ---- XDMF ---- */

/* the value of attribute `name` in the tag starting at tag, into out */
static int tag_attr(const char *tag, const char *name, char *out, size_t n)
{
    const char *end = strchr(tag, '>');
    char key[64];
    snprintf(key, sizeof key, " %s=\"", name);
    const char *p = strstr(tag, key);
    if (!p || (end && p > end)) return 0;
    p += strlen(key);
    const char *q = strchr(p, '"');
    snprintf(out, n, "%.*s", (int)(q - p), p);
    return 1;
}

static int parse_dims(const char *s, size_t *d)
{
    int n = 0;
    for (char *end; n < 4; s = end) {
        unsigned long v = strtoul(s, &end, 10);
        if (end == s) break;
        d[n++] = v;
    }
    return n;
}

typedef struct {
    int nref, nbad, nslab;
} xdmf_check;

static size_t prod(const size_t *d, int n)
{
    size_t p = 1;
    for (int i = 0; i < n; i++) p *= d[i];
    return p;
}

/* a block "start stride count" of a dataset of shape got (rank n) lies inside it */
static int slab_inside(const size_t *start, const size_t *stride, const size_t *count,
                       const size_t *got, int n)
{
    for (int i = 0; i < n; i++)
        if (count[i] == 0 || start[i] + (count[i] - 1) * stride[i] >= got[i]) return 0;
    return 1;
}

/* the selection of a legacy HyperSlab item: the XML DataItem just before p, inside an item
 * with ItemType="HyperSlab"; fills sel (3 n values) and returns 1 when there is one */
static int legacy_selection(const char *xml, const char *p, size_t *sel, int n)
{
    const char *xsel = NULL, *outer = NULL;
    for (const char *q = p - 1; q > xml && !outer; q--) {
        if (strncmp(q, "<DataItem", 9) != 0) continue;
        if (!xsel)
            xsel = q;
        else
            outer = q;
    }
    char fmt[16] = "", it[32] = "";
    if (!outer || !tag_attr(xsel, "Format", fmt, sizeof fmt) || strcmp(fmt, "XML") != 0 ||
        !tag_attr(outer, "ItemType", it, sizeof it) || strcmp(it, "HyperSlab") != 0)
        return 0;
    const char *q = strchr(xsel, '>') + 1;
    int k = 0;
    for (char *end; k < 3 * n; q = end) {
        unsigned long v = strtoul(q, &end, 10);
        if (end == q) break;
        sel[k++] = v;
    }
    return k == 3 * n ? 1 : -1;
}

/* every HDF DataItem: the file is the sample beside the .xmf, the dataset exists with the
 * stated shape, and a block of it (XDMF 3 "|start:stride:count:shape", or a legacy
 * HyperSlab around it) lies inside it with as many values as the item states */
static void check_refs(const char *xml, const char *xmf_dir, const char *want_file, xdmf_check *c)
{
    for (const char *p = strstr(xml, "<DataItem"); p; p = strstr(p + 1, "<DataItem")) {
        char fmt[32] = "", dims[128] = "";
        tag_attr(p, "Format", fmt, sizeof fmt);
        if (strcmp(fmt, "HDF") != 0) continue;
        c->nref++;
        tag_attr(p, "Dimensions", dims, sizeof dims);
        const char *text = strchr(p, '>') + 1;
        const char *close = strstr(text, "</DataItem>");
        char ref[1024], file[2200], path[1024];
        snprintf(ref, sizeof ref, "%.*s", (int)(close - text), text);
        char *bar = strchr(ref, '|'), *colon = strstr(ref, ":/");
        if (bar) *bar++ = 0;
        if (!colon) {
            c->nbad++;
            continue;
        }
        *colon = 0;
        snprintf(file, sizeof file, "%s/%s", xmf_dir, ref);
        snprintf(path, sizeof path, "%s", colon + 1);
        if (strcmp(ref, want_file) != 0) {
            fprintf(stderr, "reference names %s, not %s\n", ref, want_file);
            c->nbad++;
        }
        mcs_results *r = NULL;
        mcs_error e = {0};
        size_t want[4], got[3] = {0, 0, 0};
        int nw = parse_dims(dims, want), rank = -1;
        if (mcs_results_open(&r, file, &e) || mcs_results_shape(r, path, &rank, got, &e)) {
            fprintf(stderr, "%s:%s: %s\n", file, path, e.msg);
            c->nbad++;
            mcs_results_close(&r);
            continue;
        }
        mcs_results_close(&r);
        if (bar) {
            /* start:stride:count:shape, each with one number per axis of the dataset */
            size_t part[4][4];
            int np = 0, ok = 1;
            for (char *tok = bar; tok && np < 4; np++) {
                char *next = strchr(tok, ':');
                if (next) *next++ = 0;
                ok &= parse_dims(tok, part[np]) == rank;
                tok = next;
            }
            ok &= np == 4 && prod(part[2], rank) == prod(want, nw);
            for (int i = 0; ok && i < rank; i++) ok &= part[3][i] == got[i];
            ok = ok && slab_inside(part[0], part[1], part[2], got, rank);
            if (!ok) {
                fprintf(stderr, "%s: bad block |%s for shape %zu %zu %zu\n", path, bar, got[0],
                        got[1], got[2]);
                c->nbad++;
            }
            c->nslab++;
            continue;
        }
        if (rank != nw) {
            fprintf(stderr, "%s: rank %d, xdmf says %d\n", path, rank, nw);
            c->nbad++;
            continue;
        }
        for (int i = 0; i < nw; i++)
            if (want[i] != got[i]) {
                fprintf(stderr, "%s: axis %d: xdmf says %zu, file has %zu\n", path, i, want[i],
                        got[i]);
                c->nbad++;
            }
        size_t sel[9];
        int ls = legacy_selection(xml, p, sel, rank);
        if (ls < 0 || (ls > 0 && !slab_inside(sel, sel + rank, sel + 2 * rank, got, rank))) {
            fprintf(stderr, "%s: bad HyperSlab selection\n", path);
            c->nbad++;
        }
        if (ls > 0) c->nslab++;
    }
}

/* the <Time Value> of each step of the temporal collection named name */
static int collection_times(const char *xml, const char *name, double *t, int max)
{
    char key[128];
    snprintf(key, sizeof key, "<Grid Name=\"%s\"", name);
    const char *p = strstr(xml, key);
    if (!p) return -1;
    const char *end = strstr(p, "CollectionType=\"Temporal\"");
    if (!end) return -1;
    /* the collection ends where the next top-level temporal one starts */
    const char *stop = strstr(end + 1, "CollectionType=\"Temporal\"");
    int n = 0;
    for (const char *q = strstr(p, "<Time Value=\""); q && (!stop || q < stop) && n < max;
         q = strstr(q + 1, "<Time Value=\""))
        t[n++] = strtod(q + 13, NULL);
    return n;
}

static int count_str(const char *s, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(s, needle); p; p = strstr(p + 1, needle)) n++;
    return n;
}

static void test_xdmf_references(void)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "export %s --xdmf", tpath("sample.h5"));
    cli_result *res = cli_run(cmd);
    CHECK(res->status == 0);
    CHECK_STR_CONTAINS(res->out, "sample.xmf");
    char *xml = th_slurp(tpath("sample.xmf"), NULL);
    CHECK(xml != NULL);
    if (!xml) return;
    CHECK_STR_CONTAINS(xml, "<Xdmf Version=\"3.0\">");
    CHECK(strstr(xml, tdir) == NULL); /* relative file names only */
    xdmf_check c = {0};
    check_refs(xml, tdir, "sample.h5", &c);
    CHECK(c.nbad == 0);
    /* per stage-3 step: 4 parts x (elements, nodes, displacement block), and per stage-1
     * step 2 bodies x (position, orientation blocks) */
    CHECK(c.nref == NOUT * 4 * 3 + NT * 2 * 2);
    CHECK(c.nslab == NOUT * 4 + NT * 2 * 2);
    double t[NT + 1];
    int n = collection_times(xml, "stage3_fe", t, NT + 1);
    CHECK(n == NOUT);
    for (int i = 0; i < n && i < NOUT; i++) CHECK(t[i] == t3(i));
    n = collection_times(xml, "stage1_bodies", t, NT + 1);
    CHECK(n == NT);
    for (int i = 0; i < n && i < NT; i++) CHECK(t[i] == i * DT);
    CHECK(count_str(xml, "TopologyType=\"Quadrilateral\" NumberOfElements=\"6\"") == NOUT);
    CHECK(count_str(xml, "TopologyType=\"Hexahedron\" NumberOfElements=\"1\"") == NOUT);
    CHECK(count_str(xml, "TopologyType=\"Triangle\" NumberOfElements=\"2\"") == NOUT);
    CHECK(count_str(xml, "TopologyType=\"Polyline\" NumberOfElements=\"2\" NodesPerElement=\"2\"") ==
          NOUT);
    CHECK(count_str(xml, "TopologyType=\"Polyvertex\"") == NT * 2);
    /* the block's nodes are rows 12..19 of the displacement field */
    CHECK_STR_CONTAINS(xml, "sample.h5:/stage3/fields/displacement|10 12 0:1 1 1:1 8 3:11 27 3<");
    free(xml);
}

static void test_xdmf2_legacy(void)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "export %s --xdmf2 %s", tpath("sample.h5"), tpath("legacy.xmf"));
    cli_result *res = cli_run(cmd);
    CHECK(res->status == 0);
    char *xml = th_slurp(tpath("legacy.xmf"), NULL);
    CHECK(xml != NULL);
    if (!xml) return;
    CHECK_STR_CONTAINS(xml, "<Xdmf Version=\"2.0\">");
    xdmf_check c = {0};
    check_refs(xml, tdir, "sample.h5", &c);
    CHECK(c.nbad == 0);
    /* per part and step: elements, nodes and a displacement block for the deformed geometry,
     * and the block again for the attribute; per body and step: position, orientation */
    CHECK(c.nref == NOUT * 4 * 4 + NT * 2 * 2);
    CHECK(c.nslab == NOUT * 4 * 2 + NT * 2 * 2);
    CHECK(count_str(xml, "Function=\"$0 + $1\"") == NOUT * 4);
    CHECK_STR_CONTAINS(xml, ">10 12 0 1 1 1 1 8 3</DataItem>");
    double t[NT + 1];
    CHECK(collection_times(xml, "stage3_fe", t, NT + 1) == NOUT);
    free(xml);
}

static void test_xdmf_elsewhere_and_stride(void)
{
    /* an .xmf in another directory names the h5 relative to itself */
    mkdir(tpath("views"), 0777);
    mkdir(tpath("views/deep"), 0777);
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "export %s --xdmf %s --stride 50", tpath("sample.h5"),
             tpath("views/deep/s.xmf"));
    cli_result *res = cli_run(cmd);
    CHECK(res->status == 0);
    char *xml = th_slurp(tpath("views/deep/s.xmf"), NULL);
    CHECK(xml != NULL);
    if (!xml) return;
    xdmf_check c = {0};
    check_refs(xml, tpath("views/deep"), "../../sample.h5", &c);
    CHECK(c.nbad == 0 && c.nref > 0);
    /* every 50th step and the last: 0, 50, 100, 150, 200 and 0, 10 */
    double t[64];
    int n = collection_times(xml, "stage1_bodies", t, 64);
    CHECK(n == 5);
    for (int i = 0; i < n && i < 5; i++) CHECK(t[i] == 50 * i * DT);
    n = collection_times(xml, "stage3_fe", t, 64);
    CHECK(n == 2 && t[0] == 0 && t[1] == t3(NOUT - 1));
    free(xml);
    snprintf(cmd, sizeof cmd, "export %s --xdmf --stride 0", tpath("sample.h5"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "--stride");
}

static void test_bad_input(void)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "export %s --csv %s", tpath("missing.h5"), tpath("x"));
    cli_result *res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "missing.h5: No such file");

    FILE *f = fopen(tpath("notes.h5"), "w");
    fputs("time, a\n0, 1\n", f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "export %s --xdmf", tpath("notes.h5"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "not an HDF5 file");

    /* an HDF5 results file in which no stage wrote anything */
    mcs_results *r = NULL;
    mcs_error e = {0};
    CHECK(mcs_results_create(&r, tpath("empty.h5"), "", &e) == MCS_OK);
    CHECK(mcs_results_commit(&r, &e) == MCS_OK);
    snprintf(cmd, sizeof cmd, "export %s --csv %s", tpath("empty.h5"), tpath("e"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "no /stageN group");
    snprintf(cmd, sizeof cmd, "export %s --xdmf", tpath("empty.h5"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "no /stageN group");
    CHECK(access(tpath("empty.xmf"), F_OK) != 0);
    /* the library says the same */
    CHECK(mcs_results_open(&r, tpath("empty.h5"), &e) == MCS_OK);
    int nf = 0;
    CHECK(mcs_results_export_csv(r, tpath("e"), &nf, &e) == MCS_ERR_FORMAT);
    mcs_results_close(&r);

    /* --mme is built (tests/test_mme_export.c): one test per stage */
    snprintf(cmd, sizeof cmd, "export %s --mme %s", tpath("sample.h5"), tpath("m"));
    res = cli_run(cmd);
    CHECK(res->status == 0);
    CHECK_STR_CONTAINS(res->out, "wrote 2 ISO-MME tests (3 channels)");
    /* --k is built (tests/test_fe_keyword.c): every part of every element type is written */
    snprintf(cmd, sizeof cmd, "export %s --k %s", tpath("sample.h5"), tpath("a.k"));
    res = cli_run(cmd);
    CHECK(res->status == 0);
    CHECK_STR_CONTAINS(res->out, "(27 nodes, 11 elements)");
    snprintf(cmd, sizeof cmd, "export %s", tpath("sample.h5"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "usage");
    snprintf(cmd, sizeof cmd, "export %s --csv", tpath("sample.h5"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    /* a CSV directory that cannot be made */
    snprintf(cmd, sizeof cmd, "export %s --csv %s/sub", tpath("sample.h5"), tpath("notes.h5"));
    res = cli_run(cmd);
    CHECK(res->status == 2);
    CHECK_STR_CONTAINS(res->err, "not a directory");
}

/* run the ParaView check script on xmf at time at; parse its line; 0 when it ran */
static int paraview_read(const char *xmf, int legacy, double at, long *pts, long *cells,
                         long *steps, double *t, double *zmin, double *qw, double *qy)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd,
             "timeout 300 pvpython --force-offscreen-rendering scripts/check_xdmf_paraview.py "
             "%s --time %.17g %s > %s 2>&1",
             legacy ? "--xdmf2" : "", at, xmf, tpath("pv.txt"));
    int rc = system(cmd);
    char *out = th_slurp(tpath("pv.txt"), NULL);
    const char *p = out ? strstr(out, "xdmf:") : NULL;
    int n = p ? sscanf(p, "xdmf: points %ld cells %ld timesteps %ld last %lf zmin %lf q %lf %lf",
                       pts, cells, steps, t, zmin, qw, qy)
              : 0;
    if (rc != 0 || n != 7) fprintf(stderr, "pvpython said:\n%s\n", out ? out : "(nothing)");
    free(out);
    return rc == 0 && n == 7 ? 0 : -1;
}

/* ParaView itself, when it is installed: what its XDMF readers make of both files at the
 * last stage-3 output time, t = 0.02 s, where stage 1 and stage 3 are both shown */
static void test_paraview(void)
{
    if (system("command -v pvpython >/dev/null 2>&1") != 0) {
        printf("test_export: pvpython not found (Debian package python3-paraview): ParaView "
               "check skipped\n");
        return;
    }
    const char *files[2] = {tpath("sample.xmf"), tpath("legacy.xmf")};
    double at = t3(NOUT - 1);
    for (int legacy = 0; legacy < 2; legacy++) {
        long pts = -1, cells = -1, steps = -1;
        double t = NAN, zmin = NAN, qw = NAN, qy = NAN;
        CHECK(paraview_read(files[legacy], legacy, at, &pts, &cells, &steps, &t, &zmin, &qw,
                            &qy) == 0);
        /* 27 FE nodes + 2 bodies; 6 quads + 1 hex + 2 triangles + 2 lines + 2 vertices */
        CHECK(pts == NN + 2);
        CHECK(cells == 11 + 2);
        /* the union of both time lists: the stage-3 times are stage-1 times too */
        CHECK(steps == NT);
        CHECK_NEAR(t, at, 1e-15);
        /* deformed: every node moved down by CRUSH t; the lowest reference z is 0 */
        CHECK_NEAR(zmin, -CRUSH * at, 1e-12);
        /* head quaternion (cos(W t / 2), 0, sin(W t / 2), 0) */
        CHECK_NEAR(qw, cos(0.5 * W * at), 1e-12);
        CHECK_NEAR(qy, sin(0.5 * W * at), 1e-12);
    }
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "--write-sample") == 0) {
        char p[4096];
        mkdir(argv[2], 0777);
        snprintf(p, sizeof p, "%s/sample.h5", argv[2]);
        int rc = write_sample(p);
        if (!rc) printf("%s\n", p);
        return rc;
    }
    snprintf(tdir, sizeof tdir, "/tmp/mcs_export_XXXXXX");
    if (!mkdtemp(tdir)) return 1;
    CHECK(write_sample(tpath("sample.h5")) == 0);
    RUN(test_csv_content);
    RUN(test_xdmf_references);
    RUN(test_xdmf2_legacy);
    RUN(test_xdmf_elsewhere_and_stride);
    RUN(test_bad_input);
    RUN(test_paraview);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tdir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tdir);
    TEST_END();
}

/* mcs_results_xdmf.c: `mcrash export --xdmf` — an XDMF 3 file that points into the results
 * file, so ParaView shows the FE meshes deforming and the rigid bodies moving over time. What
 * XDMF cannot compute from the results (the bodies' outlines posed in the world; the deformed
 * positions of the parts of a stage that also has bodies) is written at export into
 * FILE.xmf.h5 beside the .xmf (docs/contracts.md). */
#include "core/mcs_results_export.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct {
    FILE *f;
    mcs_results *r;
    char h5[PATH_MAX];   /* the results file, relative to the .xmf          */
    const char *cur;     /* the file the DataItems name: h5, or side_name    */
    char side[PATH_MAX + 16];      /* the outlines file <xmf>.h5 beside the .xmf */
    char side_name[PATH_MAX + 16]; /* its name relative to the .xmf            */
    mcs_results *sw;     /* its writer, created at the first outline       */
    size_t npos_frames;  /* frames of the parts' positions written there     */
    mcs_xdmf_opts opts;
} xw;

mcs_xdmf_opts mcs_xdmf_opts_default(void)
{
    return (mcs_xdmf_opts){.stride = 0, .max_frames = 2000, .legacy = 0, .cells = NULL};
}

/* ---- file names ---- */

/* directory part of path, resolved; "." when there is none */
static int real_dir(const char *path, char *out)
{
    char d[PATH_MAX];
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(d, sizeof d, ".");
    else if (slash == path)
        snprintf(d, sizeof d, "/");
    else
        snprintf(d, sizeof d, "%.*s", (int)(slash - path), path);
    return realpath(d, out) ? 0 : -1;
}

/* split an absolute path into its components (in place); returns their number */
static int split_path(char *p, char **comp, int max)
{
    int n = 0;
    char *save = NULL;
    for (char *tok = strtok_r(p, "/", &save); tok && n < max; tok = strtok_r(NULL, "/", &save))
        comp[n++] = tok;
    return n;
}

/* h5 as seen from the directory of xmf: "out.h5", "../runs/out.h5" */
static int relative_name(const char *h5, const char *xmf, char *out, size_t n)
{
    char a[PATH_MAX], b[PATH_MAX], *ca[256], *cb[256];
    if (real_dir(h5, a) || real_dir(xmf, b)) return -1;
    const char *base = strrchr(h5, '/') ? strrchr(h5, '/') + 1 : h5;
    int na = split_path(a, ca, 256), nb = split_path(b, cb, 256), c = 0;
    while (c < na && c < nb && strcmp(ca[c], cb[c]) == 0) c++;
    size_t used = 0;
    out[0] = 0;
    for (int i = c; i < nb && used < n; i++) used += (size_t)snprintf(out + used, n - used, "../");
    for (int i = c; i < na && used < n; i++)
        used += (size_t)snprintf(out + used, n - used, "%s/", ca[i]);
    if (used < n) used += (size_t)snprintf(out + used, n - used, "%s", base);
    return used >= n ? -1 : 0;
}

/* ---- XML pieces ---- */

static void put_esc(FILE *f, const char *s)
{
    for (; *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
    }
}

static void put_dims(FILE *f, int rank, const size_t *dims)
{
    for (int i = 0; i < rank; i++) fprintf(f, "%s%zu", i ? " " : "", dims[i]);
}

static void put_indent(FILE *f, int ind)
{
    fprintf(f, "%*s", 2 * ind, "");
}

/* <DataItem ... Format="HDF">file.h5:/path</DataItem> */
static void item_hdf(xw *w, int ind, const char *path, int rank, const size_t *dims, int is_int)
{
    put_indent(w->f, ind);
    fputs("<DataItem Dimensions=\"", w->f);
    put_dims(w->f, rank, dims);
    fprintf(w->f, "\" NumberType=\"%s\" Precision=\"%d\" Format=\"HDF\">", is_int ? "Int" : "Float",
            is_int ? 4 : 8);
    put_esc(w->f, w->cur);
    fputc(':', w->f);
    put_esc(w->f, path);
    fputs("</DataItem>\n", w->f);
}

/* a block of an HDF dataset: start/count per axis of its full shape (stride 1); the result
 * has the shape out_dims. XDMF 3 states the block in the heavy-data reference itself
 * ("file.h5:/path|start:stride:count:shape"), which ParaView's Xdmf3 readers take; XDMF 2
 * nests it in a HyperSlab item, which the legacy XDMF reader takes. */
static void item_slab(xw *w, int ind, const char *path, int rank, const size_t *dims,
                      const size_t *start, const size_t *count, int out_rank,
                      const size_t *out_dims)
{
    size_t ones[MCS_RESULTS_MAXRANK] = {1, 1, 1};
    FILE *f = w->f;
    put_indent(f, ind);
    fputs("<DataItem ", f);
    if (w->opts.legacy) fputs("ItemType=\"HyperSlab\" Type=\"HyperSlab\" ", f);
    fputs("Dimensions=\"", f);
    put_dims(f, out_rank, out_dims);
    fputs("\" NumberType=\"Float\" Precision=\"8\"", f);
    if (!w->opts.legacy) {
        fputs(" Format=\"HDF\">", f);
        put_esc(f, w->cur);
        fputc(':', f);
        put_esc(f, path);
        fputc('|', f);
        put_dims(f, rank, start);
        fputc(':', f);
        put_dims(f, rank, ones);
        fputc(':', f);
        put_dims(f, rank, count);
        fputc(':', f);
        put_dims(f, rank, dims);
        fputs("</DataItem>\n", f);
        return;
    }
    fputs(">\n", f);
    put_indent(f, ind + 1);
    fprintf(f, "<DataItem Dimensions=\"3 %d\" NumberType=\"Int\" Format=\"XML\">", rank);
    put_dims(f, rank, start);
    fputc(' ', f);
    put_dims(f, rank, ones);
    fputc(' ', f);
    put_dims(f, rank, count);
    fputs("</DataItem>\n", f);
    item_hdf(w, ind + 1, path, rank, dims, 0);
    put_indent(f, ind);
    fputs("</DataItem>\n", f);
}

/* ---- times ---- */

/* the times of n rows: from the first candidate dataset that has n values, else 0, 1, 2 ... */
static mcs_status read_times(mcs_results *r, const char *const *cands, size_t n, double **t,
                             mcs_error *err)
{
    *t = malloc((n ? n : 1) * sizeof **t);
    if (!*t) return MCS_ERR(err, MCS_ERR_NOMEM, "export: out of memory");
    for (size_t i = 0; i < n; i++) (*t)[i] = (double)i;
    for (int c = 0; cands[c]; c++) {
        if (mcs_results_kind(r, cands[c]) != MCS_RES_DATASET) continue;
        mcs_array a = {0};
        mcs_status st = mcs_results_read(r, cands[c], &a, err);
        if (st) return st;
        int ok = a.rank == 1 && a.n == n;
        if (ok) memcpy(*t, a.v, n * sizeof **t);
        mcs_array_free(&a);
        if (ok) return MCS_OK;
    }
    mcs_log(MCS_LOG_WARN, "%s: no time values for %zu output steps; using their index",
            mcs_results_path(r), n);
    return MCS_OK;
}

/* output steps to write: every stride-th, and always the last */
static size_t frame_stride(const xw *w, size_t n)
{
    size_t s = (size_t)(w->opts.stride > 0 ? w->opts.stride : 1);
    if (w->opts.stride <= 0 && w->opts.max_frames > 0 && n > (size_t)w->opts.max_frames)
        s = (n + (size_t)w->opts.max_frames - 1) / (size_t)w->opts.max_frames;
    return s;
}

static int next_frame(size_t i, size_t s, size_t n)
{
    return i + s < n ? (int)(i + s) : (i + 1 < n ? (int)(n - 1) : -1);
}

/* ---- FE meshes ---- */

typedef struct {
    char name[256];
    char nodes[512], elems[512];
    size_t nn, ne, k;
    int offset;
    const char *topo; /* XDMF topology type */
} fe_part;

/* the XDMF topology of a block of k-node cells of the given type (NULL: its width decides) */
static const char *topology(const mcs_xdmf_opts *o, const char *type, size_t k)
{
    for (int i = 0; i < o->ncells; i++) {
        const mcs_cell_type *c = &o->cells[i];
        if ((size_t)c->nodes == k && (type ? strcmp(type, c->name) == 0 : c->by_width))
            return c->xdmf;
    }
    return NULL;
}

/* the cell types' names, comma-separated, into buf */
static const char *type_names(const mcs_xdmf_opts *o, char *buf, size_t n)
{
    size_t l = 0;
    buf[0] = '\0';
    for (int i = 0; i < o->ncells && l < n; i++)
        l += (size_t)snprintf(buf + l, n - l, "%s%s", i ? ", " : "", o->cells[i].name);
    return o->ncells ? buf : "none (no cell types given)";
}

/* one element block of a part: `elements`, or block "elements_<type>" (grid "<part>.<type>") */
static mcs_status read_part(mcs_results *r, const mcs_xdmf_opts *o, int stage, const char *name,
                            const char *block, fe_part *p, mcs_error *err)
{
    memset(p, 0, sizeof *p);
    snprintf(p->name, sizeof p->name, "%s%s%s", name, block ? "." : "", block ? block : "");
    snprintf(p->nodes, sizeof p->nodes, "/stage%d/mesh/%s/nodes", stage, name);
    snprintf(p->elems, sizeof p->elems, "/stage%d/mesh/%s/elements%s%s", stage, name,
             block ? "_" : "", block ? block : "");
    int rn, re;
    size_t dn[3], de[3];
    mcs_status st = mcs_results_shape(r, p->nodes, &rn, dn, err);
    if (!st) st = mcs_results_shape(r, p->elems, &re, de, err);
    if (st) return st;
    if (rn != 2 || dn[1] != 3 || re != 2)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: part %s: nodes must be [nn,3] and elements "
                                            "[ne,k]",
                       mcs_results_path(r), name);
    p->nn = dn[0];
    p->ne = de[0];
    p->k = de[1];
    char *type = NULL;
    if (mcs_results_has_attr(r, p->elems, "type") &&
        (st = mcs_results_attr_str(r, p->elems, "type", &type, err)))
        return st;
    p->topo = topology(o, type, p->k);
    char known[256];
    if (!p->topo)
        st = MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                     "%s: part %s: %zu-node elements%s%s%s: XDMF export knows %s",
                     mcs_results_path(r), p->name, p->k, type ? " of type \"" : "",
                     type ? type : "", type ? "\"" : "", type_names(o, known, sizeof known));
    free(type);
    double off = 0;
    if (!st && mcs_results_has_attr(r, p->nodes, "node_offset"))
        st = mcs_results_attr_double(r, p->nodes, "node_offset", &off, err);
    p->offset = (int)off;
    return st;
}

/* <Grid Name="name" GridType="Uniform"> at indent ind */
static void put_grid_open(FILE *f, int ind, const char *name)
{
    put_indent(f, ind);
    fputs("<Grid Name=\"", f);
    put_esc(f, name);
    fputs("\" GridType=\"Uniform\">\n", f);
}

/* a body's grid ends: its index as the attribute body_id (center Node or Grid), </Grid> */
static void put_body_id_close(FILE *f, int ind, const char *center, int id)
{
    put_indent(f, ind + 1);
    fprintf(f, "<Attribute Name=\"body_id\" AttributeType=\"Scalar\" Center=\"%s\">\n", center);
    put_indent(f, ind + 2);
    fprintf(f, "<DataItem Dimensions=\"1\" NumberType=\"Int\" Format=\"XML\">%d</DataItem>\n", id);
    put_indent(f, ind + 1);
    fputs("</Attribute>\n", f);
    put_indent(f, ind);
    fputs("</Grid>\n", f);
}

/* one part at output row step; pos (NULL: none) names the deformed positions [nf, nn, 3] of
 * the outlines file (frame k of them) */
static void put_part(xw *w, int ind, const fe_part *p, const char *disp, const size_t *ddims,
                     size_t step, const char *pos, size_t k)
{
    FILE *f = w->f;
    size_t de[2] = {p->ne, p->k}, dn[2] = {p->nn, 3};
    put_grid_open(f, ind, p->name);
    put_indent(f, ind + 1);
    fprintf(f, "<Topology TopologyType=\"%s\" NumberOfElements=\"%zu\"", p->topo, p->ne);
    if (strcmp(p->topo, "Polyline") == 0) fprintf(f, " NodesPerElement=\"%zu\"", p->k);
    fputs(">\n", f);
    item_hdf(w, ind + 2, p->elems, 2, de, 1);
    put_indent(f, ind + 1);
    fputs("</Topology>\n", f);
    put_indent(f, ind + 1);
    fputs("<Geometry GeometryType=\"XYZ\">\n", f);
    size_t start[3] = {step, (size_t)p->offset, 0}, count[3] = {1, p->nn, 3};
    if (pos) { /* deformed geometry from the outlines file (a stage with bodies) */
        size_t pd[3] = {ddims[0], ddims[1], 3}, ps[3] = {k, (size_t)p->offset, 0};
        pd[0] = w->npos_frames;
        w->cur = w->side_name;
        item_slab(w, ind + 2, pos, 3, pd, ps, count, 2, dn);
        w->cur = w->h5;
    } else if (disp && w->opts.legacy) {
        /* deformed geometry: reference nodes + displacement at this output time (the legacy
         * reader evaluates functions; ParaView 5.11's Xdmf3 readers do not, so XDMF 3 gets the
         * reference geometry and the displacement for Warp By Vector) */
        put_indent(f, ind + 2);
        fprintf(f, "<DataItem ItemType=\"Function\" Function=\"$0 + $1\" Dimensions=\"%zu 3\">\n",
                p->nn);
        item_hdf(w, ind + 3, p->nodes, 2, dn, 0);
        item_slab(w, ind + 3, disp, 3, ddims, start, count, 2, dn);
        put_indent(f, ind + 2);
        fputs("</DataItem>\n", f);
    } else {
        item_hdf(w, ind + 2, p->nodes, 2, dn, 0);
    }
    put_indent(f, ind + 1);
    fputs("</Geometry>\n", f);
    if (disp) {
        put_indent(f, ind + 1);
        fputs("<Attribute Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\">\n", f);
        item_slab(w, ind + 2, disp, 3, ddims, start, count, 2, dn);
        put_indent(f, ind + 1);
        fputs("</Attribute>\n", f);
    }
    put_indent(f, ind);
    fputs("</Grid>\n", f);
}

/* x0 + u of every node at the frames shown into the outlines file at pos [nf, nnode, 3],
 * a frame at a time */
static mcs_status write_positions(xw *w, const fe_part *parts, int np, const char *disp,
                                  const size_t *dd, const char *pos, mcs_error *err)
{
    const size_t nn = dd[1], s = frame_stride(w, dd[0]);
    double *x0 = calloc(3 * nn + 1, sizeof *x0), *x = malloc(sizeof *x * (3 * nn + 1));
    mcs_status st = x0 && x ? MCS_OK : MCS_ERR(err, MCS_ERR_NOMEM, "export: out of memory");
    for (int p = 0; p < np && !st; p++) { /* reference nodes at their offsets */
        mcs_array a = {0};
        st = mcs_results_read(w->r, parts[p].nodes, &a, err);
        for (size_t j = 0; !st && j < 3 * parts[p].nn; j++)
            x0[3 * (size_t)parts[p].offset + j] = a.v[j];
        mcs_array_free(&a);
    }
    if (!st && !w->sw) st = mcs_results_create(&w->sw, w->side, NULL, err);
    mcs_results_series *ser = NULL;
    const size_t row[2] = {nn, 3};
    if (!st) st = mcs_results_series_create(w->sw, pos, 3, row, "m", 0, &ser, err);
    size_t nf = 0;
    for (int i = 0; !st && i >= 0; i = next_frame((size_t)i, s, dd[0]), nf++) {
        st = mcs_results_read_row(w->r, disp, (size_t)i, x, 3 * nn, err);
        for (size_t j = 0; !st && j < 3 * nn; j++) x[j] += x0[j];
        if (!st) st = mcs_results_series_append(ser, x, err);
    }
    w->npos_frames = nf;
    free(x0);
    free(x);
    return st;
}

static mcs_status fe_stage(xw *w, int stage, int *ngrids, mcs_error *err)
{
    char mesh[64], disp[64], ft[64], st_t[64];
    snprintf(mesh, sizeof mesh, "/stage%d/mesh", stage);
    snprintf(disp, sizeof disp, "/stage%d/fields/displacement", stage);
    snprintf(ft, sizeof ft, "/stage%d/fields/time", stage);
    snprintf(st_t, sizeof st_t, "/stage%d/time", stage);
    if (mcs_results_kind(w->r, mesh) != MCS_RES_GROUP) return MCS_OK;
    char **names = NULL;
    int np = 0;
    mcs_status st = mcs_results_list(w->r, mesh, &names, &np, err);
    if (st || np == 0) {
        mcs_results_list_free(&names, np);
        return st;
    }
    /* each part's `elements` and its further blocks elements_<type> (mcs_results.h), in the
     * order of the cell types given */
    const mcs_xdmf_opts *o = &w->opts;
    const int nb = o->ncells > 0 ? o->ncells : 0;
    fe_part *parts = calloc((size_t)np * (size_t)(1 + nb), sizeof *parts);
    if (!parts) st = MCS_ERR(err, MCS_ERR_NOMEM, "export: out of memory");
    int ng = 0;
    for (int i = 0; i < np && !st; i++) {
        st = read_part(w->r, o, stage, names[i], NULL, &parts[ng++], err);
        for (int b = 0; b < nb && !st; b++) {
            char pb[512];
            snprintf(pb, sizeof pb, "/stage%d/mesh/%s/elements_%s", stage, names[i],
                     o->cells[b].name);
            if (mcs_results_kind(w->r, pb) == MCS_RES_DATASET)
                st = read_part(w->r, o, stage, names[i], o->cells[b].name, &parts[ng++], err);
        }
    }
    mcs_results_list_free(&names, np);
    np = ng;

    int has_disp = !st && mcs_results_kind(w->r, disp) == MCS_RES_DATASET;
    int dr = 0;
    size_t dd[3] = {0, 0, 0};
    if (has_disp) st = mcs_results_shape(w->r, disp, &dr, dd, err);
    if (has_disp && !st && (dr != 3 || dd[2] != 3))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: must be [nout, nn, 3]", mcs_results_path(w->r),
                     disp);
    for (int i = 0; has_disp && i < np && !st; i++)
        if ((size_t)parts[i].offset + parts[i].nn > dd[1])
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: part %s: nodes %d..%zu beyond the %zu of %s",
                         mcs_results_path(w->r), parts[i].name, parts[i].offset,
                         (size_t)parts[i].offset + parts[i].nn - 1, dd[1], disp);
    double *t = NULL;
    const char *cands[] = {ft, st_t, NULL};
    if (!st && has_disp) st = read_times(w->r, cands, dd[0], &t, err);
    /* a stage with bodies (a coupled stage 1): the parts' deformed positions go to the outlines
     * file, so that parts and bodies move together without a filter (XDMF 3 readers do not
     * evaluate x0 + u); the displacement stays an attribute */
    char bodies[64], pos[64];
    snprintf(bodies, sizeof bodies, "/stage%d/bodies", stage);
    snprintf(pos, sizeof pos, "/stage%d/positions", stage);
    int deformed = !st && has_disp && dd[0] > 0 && !w->opts.legacy &&
                   mcs_results_kind(w->r, bodies) == MCS_RES_GROUP;
    if (deformed) st = write_positions(w, parts, np, disp, dd, pos, err);
    if (!st) {
        FILE *f = w->f;
        if (has_disp && dd[0] > 0) {
            fprintf(f, "    <Grid Name=\"stage%d_fe\" GridType=\"Collection\" "
                       "CollectionType=\"Temporal\">\n", stage);
            size_t s = frame_stride(w, dd[0]), k = 0;
            for (int i = 0; i >= 0; i = next_frame((size_t)i, s, dd[0]), k++) {
                fprintf(f, "      <Grid Name=\"stage%d_fe_%d\" GridType=\"Collection\" "
                           "CollectionType=\"Spatial\">\n", stage, i);
                fprintf(f, "        <Time Value=\"%.17g\"/>\n", t[i]);
                for (int p = 0; p < np; p++)
                    put_part(w, 4, &parts[p], disp, dd, (size_t)i, deformed ? pos : NULL, k);
                fputs("      </Grid>\n", f);
            }
            fputs("    </Grid>\n", f);
        } else {
            fprintf(f, "    <Grid Name=\"stage%d_fe\" GridType=\"Collection\" "
                       "CollectionType=\"Spatial\">\n", stage);
            for (int p = 0; p < np; p++) put_part(w, 3, &parts[p], NULL, NULL, 0, NULL, 0);
            fputs("    </Grid>\n", f);
        }
        (*ngrids)++;
    }
    free(t);
    free(parts);
    return st;
}

/* ---- rigid bodies ---- */

typedef struct {
    char name[256], pos[512], ori[512];
    int has_ori;
    size_t nout, neout; /* outline nodes and triangles (/stageN/outlines/<body>), 0: none */
} rb_body;

static void put_body(xw *w, int ind, const rb_body *b, int id, size_t nt, size_t step)
{
    FILE *f = w->f;
    size_t dp[2] = {nt, 3}, dq[2] = {nt, 4}, start[2] = {step, 0};
    size_t cp[2] = {1, 3}, cq[2] = {1, 4};
    put_grid_open(f, ind, b->name);
    put_indent(f, ind + 1);
    /* the connectivity spelled out: without it the Xdmf3 readers make no vertex cell */
    fputs("<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"1\" "
          "NodesPerElement=\"1\">\n", f);
    put_indent(f, ind + 2);
    fputs("<DataItem Dimensions=\"1\" NumberType=\"Int\" Format=\"XML\">0</DataItem>\n", f);
    put_indent(f, ind + 1);
    fputs("</Topology>\n", f);
    put_indent(f, ind + 1);
    fputs("<Geometry GeometryType=\"XYZ\">\n", f);
    item_slab(w, ind + 2, b->pos, 2, dp, start, cp, 2, cp);
    put_indent(f, ind + 1);
    fputs("</Geometry>\n", f);
    if (b->has_ori) {
        /* quaternion w, x, y, z (body -> world), as one 4-component nodal array */
        put_indent(f, ind + 1);
        fputs("<Attribute Name=\"orientation\" AttributeType=\"Matrix\" Center=\"Node\">\n", f);
        item_slab(w, ind + 2, b->ori, 2, dq, start, cq, 2, cq);
        put_indent(f, ind + 1);
        fputs("</Attribute>\n", f);
    }
    put_body_id_close(f, ind, "Node", id);
}

/* a body's outline at frame k of the outlines file: triangles on its world nodes */
static void put_outline(xw *w, int ind, int stage, const rb_body *b, int id, size_t nf,
                        size_t k)
{
    FILE *f = w->f;
    char pe[600], pn[600];
    snprintf(pe, sizeof pe, "/stage%d/outlines/%s/elements", stage, b->name);
    snprintf(pn, sizeof pn, "/stage%d/outlines/%s/nodes", stage, b->name);
    size_t de[2] = {b->neout, 3}, dn[3] = {nf, b->nout, 3}, start[3] = {k, 0, 0};
    size_t count[3] = {1, b->nout, 3}, out[2] = {b->nout, 3};
    w->cur = w->side_name;
    put_grid_open(f, ind, b->name);
    put_indent(f, ind + 1);
    fprintf(f, "<Topology TopologyType=\"Triangle\" NumberOfElements=\"%zu\">\n", b->neout);
    item_hdf(w, ind + 2, pe, 2, de, 1);
    put_indent(f, ind + 1);
    fputs("</Topology>\n", f);
    put_indent(f, ind + 1);
    fputs("<Geometry GeometryType=\"XYZ\">\n", f);
    item_slab(w, ind + 2, pn, 3, dn, start, count, 2, out);
    put_indent(f, ind + 1);
    fputs("</Geometry>\n", f);
    put_body_id_close(f, ind, "Grid", id);
    w->cur = w->h5;
}

/* bodies with a position [nt,3]; an orientation, when there is one, must be [nt,4] */
static mcs_status read_bodies(mcs_results *r, int stage, rb_body **out, int *nb, size_t *nt,
                              mcs_error *err)
{
    char g[64];
    snprintf(g, sizeof g, "/stage%d/bodies", stage);
    *out = NULL;
    *nb = 0;
    *nt = 0;
    if (mcs_results_kind(r, g) != MCS_RES_GROUP) return MCS_OK;
    char **names = NULL;
    int n = 0;
    mcs_status st = mcs_results_list(r, g, &names, &n, err);
    rb_body *b = st ? NULL : calloc((size_t)n + 1, sizeof *b);
    if (!st && !b) st = MCS_ERR(err, MCS_ERR_NOMEM, "export: out of memory");
    int k = 0;
    for (int i = 0; i < n && !st; i++) {
        rb_body *x = &b[k];
        snprintf(x->name, sizeof x->name, "%s", names[i]);
        snprintf(x->pos, sizeof x->pos, "%s/%s/position", g, names[i]);
        snprintf(x->ori, sizeof x->ori, "%s/%s/orientation", g, names[i]);
        if (mcs_results_kind(r, x->pos) != MCS_RES_DATASET) continue;
        int rk;
        size_t d[3];
        st = mcs_results_shape(r, x->pos, &rk, d, err);
        if (!st && (rk != 2 || d[1] != 3 || (k > 0 && d[0] != *nt)))
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: must be [nt,3] with the nt of the other "
                                              "bodies",
                         mcs_results_path(r), x->pos);
        *nt = d[0];
        x->has_ori = !st && mcs_results_kind(r, x->ori) == MCS_RES_DATASET;
        if (x->has_ori) st = mcs_results_shape(r, x->ori, &rk, d, err);
        if (x->has_ori && !st && (rk != 2 || d[0] != *nt || d[1] != 4))
            st = MCS_ERR(err, MCS_ERR_FORMAT, "%s:%s: must be [nt,4]", mcs_results_path(r),
                         x->ori);
        /* an outline (stage-1 surfaces in the body frame) needs the orientation */
        char pn[600], pe[600];
        snprintf(pn, sizeof pn, "/stage%d/outlines/%s/nodes", stage, names[i]);
        snprintf(pe, sizeof pe, "/stage%d/outlines/%s/elements", stage, names[i]);
        size_t dn[3], de[3];
        int rn = 0, re = 0;
        if (!st && x->has_ori && mcs_results_kind(r, pn) == MCS_RES_DATASET &&
            mcs_results_kind(r, pe) == MCS_RES_DATASET &&
            !(st = mcs_results_shape(r, pn, &rn, dn, err)) &&
            !(st = mcs_results_shape(r, pe, &re, de, err)) && rn == 2 && dn[1] == 3 && re == 2 &&
            de[1] == 3 && dn[0] > 0 && de[0] > 0)
            x->nout = dn[0], x->neout = de[0];
        k++;
    }
    mcs_results_list_free(&names, n);
    if (st) {
        free(b);
        return st;
    }
    *out = b;
    *nb = k;
    return MCS_OK;
}

/* the outline of body b in the world at frames fr[0..nf-1] into the outlines file:
 * x = p + R(q) x_body; elements copied */
static mcs_status write_outline(xw *w, int stage, const rb_body *b, const size_t *fr, size_t nf,
                                mcs_error *err)
{
    char pn[600], pe[600];
    snprintf(pn, sizeof pn, "/stage%d/outlines/%s/nodes", stage, b->name);
    snprintf(pe, sizeof pe, "/stage%d/outlines/%s/elements", stage, b->name);
    mcs_array xl = {0}, el = {0}, p = {0}, q = {0};
    double *x = NULL;
    mcs_status st = mcs_results_read(w->r, pn, &xl, err);
    if (!st) st = mcs_results_read_int(w->r, pe, &el, err);
    if (!st) st = mcs_results_read(w->r, b->pos, &p, err);
    if (!st) st = mcs_results_read(w->r, b->ori, &q, err);
    const size_t n = b->nout;
    if (!st && !(x = malloc(sizeof *x * 3 * n * (nf ? nf : 1))))
        st = MCS_ERR(err, MCS_ERR_NOMEM, "export: out of memory");
    for (size_t k = 0; k < nf && !st; k++) {
        const double *pp = p.v + 3 * fr[k], *qq = q.v + 4 * fr[k];
        double qw = qq[0], qx = qq[1], qy = qq[2], qz = qq[3];
        double nq = qw * qw + qx * qx + qy * qy + qz * qz;
        double s = nq > 0 ? 2 / nq : 0;
        double R[9] = {1 - s * (qy * qy + qz * qz), s * (qx * qy - qw * qz),
                       s * (qx * qz + qw * qy),     s * (qx * qy + qw * qz),
                       1 - s * (qx * qx + qz * qz), s * (qy * qz - qw * qx),
                       s * (qx * qz - qw * qy),     s * (qy * qz + qw * qx),
                       1 - s * (qx * qx + qy * qy)};
        for (size_t j = 0; j < n; j++) {
            const double *l = xl.v + 3 * j;
            double *o = x + 3 * (k * n + j);
            for (int i = 0; i < 3; i++)
                o[i] = pp[i] + R[3 * i] * l[0] + R[3 * i + 1] * l[1] + R[3 * i + 2] * l[2];
        }
    }
    if (!st && !w->sw) st = mcs_results_create(&w->sw, w->side, NULL, err);
    size_t dn[3] = {nf, n, 3}, de[2] = {b->neout, 3};
    if (!st) st = mcs_results_write(w->sw, pn, 3, dn, x, "m", err);
    if (!st) st = mcs_results_write_int(w->sw, pe, 2, de, el.iv, "-", err);
    free(x);
    mcs_array_free(&xl), mcs_array_free(&el), mcs_array_free(&p), mcs_array_free(&q);
    return st;
}

static mcs_status body_stage(xw *w, int stage, int *ngrids, mcs_error *err)
{
    rb_body *b;
    int nb;
    size_t nt;
    mcs_status st = read_bodies(w->r, stage, &b, &nb, &nt, err);
    if (st || nb == 0 || nt == 0) {
        free(b);
        return st;
    }
    char tp[64];
    snprintf(tp, sizeof tp, "/stage%d/time", stage);
    const char *cands[] = {tp, NULL};
    double *t = NULL;
    size_t *fr = malloc(sizeof *fr * nt), nf = 0;
    st = fr ? read_times(w->r, cands, nt, &t, err)
            : MCS_ERR(err, MCS_ERR_NOMEM, "export: out of memory");
    const size_t s = frame_stride(w, nt);
    for (int i = 0; !st && i >= 0; i = next_frame((size_t)i, s, nt)) fr[nf++] = (size_t)i;
    /* the outlines in the world at the frames shown, in the outlines file beside the .xmf */
    for (int j = 0; j < nb && !st; j++)
        if (b[j].nout) st = write_outline(w, stage, &b[j], fr, nf, err);
    if (!st) {
        FILE *f = w->f;
        fprintf(f, "    <Grid Name=\"stage%d_bodies\" GridType=\"Collection\" "
                   "CollectionType=\"Temporal\">\n", stage);
        for (size_t k = 0; k < nf; k++) {
            fprintf(f, "      <Grid Name=\"stage%d_bodies_%zu\" GridType=\"Collection\" "
                       "CollectionType=\"Spatial\">\n", stage, fr[k]);
            fprintf(f, "        <Time Value=\"%.17g\"/>\n", t[fr[k]]);
            for (int j = 0; j < nb; j++) {
                if (b[j].nout) put_outline(w, 4, stage, &b[j], j, nf, k);
                else put_body(w, 4, &b[j], j, nt, fr[k]);
            }
            fputs("      </Grid>\n", f);
        }
        fputs("    </Grid>\n", f);
        (*ngrids)++;
    }
    free(fr);
    free(t);
    free(b);
    return st;
}

/* ---- the file ---- */

mcs_status mcs_results_export_xdmf(mcs_results *r, const char *xmf_path,
                                   const mcs_xdmf_opts *opts, mcs_error *err)
{
    int stages[64];
    int ns = mcs_results_stages(r, stages, 64);
    if (ns == 0)
        return MCS_ERR(err, MCS_ERR_FORMAT, "%s: no /stageN group: nothing to export (not an "
                                            "mcrash results file?)",
                       mcs_results_path(r));
    xw w = {.r = r, .opts = opts ? *opts : mcs_xdmf_opts_default()};
    w.cur = w.h5;
    if (!xmf_path || !*xmf_path) return MCS_ERR(err, MCS_ERR_USAGE, "export --xdmf: no file");
    /* the bodies' outlines and the positions of a coupled stage's parts go to <xmf>.h5 beside
     * it (named by its base name) */
    const char *xb = strrchr(xmf_path, '/') ? strrchr(xmf_path, '/') + 1 : xmf_path;
    snprintf(w.side, sizeof w.side, "%s.h5", xmf_path);
    snprintf(w.side_name, sizeof w.side_name, "%s.h5", xb);
    if (relative_name(mcs_results_path(r), xmf_path, w.h5, sizeof w.h5))
        return MCS_ERR(err, MCS_ERR_IO, "%s: cannot resolve the directory: %s", xmf_path,
                       strerror(errno));
    char tmp[PATH_MAX + 32];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", xmf_path, (long)getpid());
    w.f = fopen(tmp, "w");
    if (!w.f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot write: %s", xmf_path, strerror(errno));
    fprintf(w.f, "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                 "<Xdmf Version=\"%s\">\n  <Domain Name=\"mcrash\">\n",
            w.opts.legacy ? "2.0" : "3.0");
    mcs_status st = MCS_OK;
    int ngrids = 0;
    for (int i = 0; i < ns && !st; i++) {
        st = fe_stage(&w, stages[i], &ngrids, err);
        if (!st) st = body_stage(&w, stages[i], &ngrids, err);
    }
    fputs("  </Domain>\n</Xdmf>\n", w.f);
    int bad = ferror(w.f);
    if (fclose(w.f) != 0) bad = 1;
    if (!st && bad) st = MCS_ERR(err, MCS_ERR_IO, "%s: write failed", xmf_path);
    if (!st && ngrids == 0)
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: no meshes (/stageN/mesh) and no bodies "
                                          "(/stageN/bodies) to show",
                     mcs_results_path(r));
    if (!st && w.sw) st = mcs_results_commit(&w.sw, err);
    mcs_results_abort(&w.sw);
    if (!st && rename(tmp, xmf_path) != 0)
        st = MCS_ERR(err, MCS_ERR_IO, "%s: cannot rename: %s", xmf_path, strerror(errno));
    if (st) remove(tmp);
    return st;
}

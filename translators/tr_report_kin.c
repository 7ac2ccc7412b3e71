/* tr_report_kin.c: the report's kinematic snapshots: each stage's bodies and FE meshes every
 * snapshot_dt, as strips of a side view (x forward, z up) and a top view (x forward, y left).
 * A body with /stageN/outlines is drawn as the convex hull of each of its surfaces (ellipsoids
 * and wheels project to their outlines), posed by its position and orientation at the frame;
 * a body without one as its centre and its x axis. An FE part is drawn as its element edges
 * at the frame's displacement, or as the hull of its nodes when it has more than
 * RP_MAXEDGE edges (a page stays small) */
#include "analysis/an_svg.h"
#include "translators/tr_report_int.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RP_MAXEDGE 600
#define RP_MAXBODY 96
#define RP_MAXPART 64
#define RP_COLS 6
#define RP_CELLW 182.0

typedef struct {
    char name[64];
    int cls;                /* 0 rider, 1 motorcycle, 2 other */
    mcs_array pos, ori;     /* [nt, 3] m, [nt, 4] quaternion w x y z */
    mcs_array on;           /* outline nodes [n, 3] in the body frame (n = 0: none) */
    int ncomp, *cstart, *cnode; /* surfaces: nodes cnode[cstart[k] .. cstart[k+1]) */
} kin_body;

typedef struct {
    char name[64];
    mcs_array nodes;        /* [nn, 3] m, undeformed */
    int offset;             /* first row in the displacement field */
    int *edge, nedge;       /* unique edges (pairs of local nodes) */
    int hull;               /* drawn as the hull of its nodes */
} kin_part;

typedef struct {
    int s, nb, np;
    kin_body b[RP_MAXBODY];
    kin_part p[RP_MAXPART];
    double *disp;           /* one frame's displacement field (nn_total x 3) */
    size_t nfield;          /* values in a field row */
    mcs_array ftime;        /* field times */
    double lo[3], hi[3];    /* world bounds over the frames [m] */
    double *xy, *hull;      /* hull scratch */
    int nscratch;
} kin;

/* v' = R(q) v for a unit quaternion q = (w, x, y, z) */
static void qrot(const double *q, const double *v, double *o)
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double t0 = 2 * (y * v[2] - z * v[1]), t1 = 2 * (z * v[0] - x * v[2]),
           t2 = 2 * (x * v[1] - y * v[0]);
    o[0] = v[0] + w * t0 + (y * t2 - z * t1);
    o[1] = v[1] + w * t1 + (z * t0 - x * t2);
    o[2] = v[2] + w * t2 + (x * t1 - y * t0);
}

static int find_root(int *par, int i)
{
    while (par[i] != i) i = par[i] = par[par[i]];
    return i;
}

/* the surfaces of a body's outline: connected sets of its triangles' nodes */
static void outline_components(kin_body *b, const mcs_array *el)
{
    int n = (int)b->on.dims[0], w = el->rank == 2 ? (int)el->dims[1] : 0;
    int *par = malloc(sizeof *par * (size_t)n), *cnt = calloc((size_t)n + 1, sizeof *cnt);
    b->cnode = malloc(sizeof *b->cnode * (size_t)n);
    b->cstart = malloc(sizeof *b->cstart * ((size_t)n + 1));
    if (!par || !cnt || !b->cnode || !b->cstart) goto done;
    for (int i = 0; i < n; i++) par[i] = i;
    for (size_t e = 0; w > 0 && e < el->dims[0]; e++)
        for (int k = 1; k < w; k++) {
            int a = el->iv[e * (size_t)w], c = el->iv[e * (size_t)w + (size_t)k];
            if (a < 0 || c < 0 || a >= n || c >= n) continue;
            par[find_root(par, a)] = find_root(par, c);
        }
    /* number the roots, then bucket the nodes */
    int *id = malloc(sizeof *id * (size_t)n);
    if (!id) goto done;
    for (int i = 0; i < n; i++) id[i] = -1;
    for (int i = 0; i < n; i++) {
        int r = find_root(par, i);
        if (id[r] < 0) id[r] = b->ncomp++;
        cnt[id[r] + 1]++;
    }
    for (int k = 0; k < b->ncomp; k++) cnt[k + 1] += cnt[k];
    memcpy(b->cstart, cnt, sizeof *cnt * ((size_t)b->ncomp + 1));
    for (int i = 0; i < n; i++) b->cnode[cnt[id[find_root(par, i)]]++] = i;
    free(id);
done:
    free(par);
    free(cnt);
}

static int cmp_edge(const void *a, const void *b)
{
    const int *x = a, *y = b;
    return x[0] != y[0] ? (x[0] > y[0]) - (x[0] < y[0]) : (x[1] > y[1]) - (x[1] < y[1]);
}

/* the edges of one element block of width w and type t (attribute or by width) */
static void add_edges(kin_part *p, const mcs_array *el, const char *type)
{
    static const int line2[] = {0, 1}, tri3[] = {0, 1, 1, 2, 2, 0},
                     quad4[] = {0, 1, 1, 2, 2, 3, 3, 0},
                     tet4[] = {0, 1, 1, 2, 2, 0, 0, 3, 1, 3, 2, 3},
                     wedge6[] = {0, 1, 1, 2, 2, 0, 3, 4, 4, 5, 5, 3, 0, 3, 1, 4, 2, 5},
                     hex8[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 0, 4, 1, 5, 2, 6,
                               3, 7};
    int w = el->rank == 2 ? (int)el->dims[1] : 0;
    const int *e = NULL;
    int ne = 0;
    if (!strcmp(type, "line2") || (!type[0] && w == 2)) e = line2, ne = 1;
    else if (!strcmp(type, "tri3") || (!type[0] && w == 3)) e = tri3, ne = 3;
    else if (!strcmp(type, "quad4") || (!type[0] && w == 4)) e = quad4, ne = 4;
    else if (!strcmp(type, "tet4") || !strcmp(type, "tet10") || (!type[0] && w == 10))
        e = tet4, ne = 6;
    else if (!strcmp(type, "wedge6") || (!type[0] && w == 6)) e = wedge6, ne = 9;
    else if (!strcmp(type, "hex8") || (!type[0] && w == 8)) e = hex8, ne = 12;
    if (!e) return;
    size_t nel = el->dims[0];
    int *ed = realloc(p->edge, sizeof *ed * 2 * ((size_t)p->nedge + nel * (size_t)ne));
    if (!ed) return;
    p->edge = ed;
    int nn = (int)p->nodes.dims[0];
    for (size_t i = 0; i < nel; i++)
        for (int k = 0; k < ne; k++) {
            int a = el->iv[i * (size_t)w + (size_t)e[2 * k]],
                b = el->iv[i * (size_t)w + (size_t)e[2 * k + 1]];
            if (a == b || a < 0 || b < 0 || a >= nn || b >= nn) continue;
            ed[2 * p->nedge] = a < b ? a : b;
            ed[2 * p->nedge + 1] = a < b ? b : a;
            p->nedge++;
        }
}

static void load_part(tr_rp *c, kin *k, const char *name)
{
    kin_part *p = &k->p[k->np];
    memset(p, 0, sizeof *p);
    snprintf(p->name, sizeof p->name, "%s", name);
    char g[160], path[200];
    snprintf(g, sizeof g, "/stage%d/mesh/%s", k->s, name);
    snprintf(path, sizeof path, "%s/nodes", g);
    if (rp_read(c, path, &p->nodes) || p->nodes.rank != 2 || p->nodes.dims[1] != 3) {
        mcs_array_free(&p->nodes);
        return;
    }
    double off = 0;
    mcs_error e = {0};
    if (mcs_results_has_attr(c->r, path, "node_offset"))
        mcs_results_attr_double(c->r, path, "node_offset", &off, &e);
    p->offset = (int)off;
    int nm;
    char **mem = rp_list(c, g, &nm);
    for (int i = 0; i < nm; i++) {
        if (strncmp(mem[i], "elements", 8) != 0) continue;
        mcs_array el = {0};
        char type[16];
        snprintf(path, sizeof path, "%s/%s", g, mem[i]);
        rp_attr(c, path, "type", type, sizeof type);
        if (mcs_results_kind(c->r, path) != MCS_RES_DATASET ||
            mcs_results_read_int(c->r, path, &el, &e)) {
            mcs_array_free(&el);
            continue;
        }
        add_edges(p, &el, type);
        mcs_array_free(&el);
    }
    mcs_results_list_free(&mem, nm);
    qsort(p->edge, (size_t)p->nedge, 2 * sizeof(int), cmp_edge);
    int u = 0;
    for (int i = 0; i < p->nedge; i++)
        if (!u || cmp_edge(p->edge + 2 * i, p->edge + 2 * (u - 1)) != 0) {
            p->edge[2 * u] = p->edge[2 * i];
            p->edge[2 * u + 1] = p->edge[2 * i + 1];
            u++;
        }
    p->nedge = u;
    p->hull = u > RP_MAXEDGE || u == 0;
    k->np++;
}

static void load_body(tr_rp *c, kin *k, const char *name)
{
    kin_body *b = &k->b[k->nb];
    memset(b, 0, sizeof *b);
    snprintf(b->name, sizeof b->name, "%s", name);
    b->cls = !strncmp(name, "rider_", 6) ? 0 : !strncmp(name, "moto_", 5) ? 1 : 2;
    char path[200];
    size_t nt = c->time[k->s].n;
    snprintf(path, sizeof path, "/stage%d/bodies/%s/position", k->s, name);
    int bad = rp_read(c, path, &b->pos) || b->pos.rank != 2 || b->pos.dims[0] != nt ||
              b->pos.dims[1] != 3;
    snprintf(path, sizeof path, "/stage%d/bodies/%s/orientation", k->s, name);
    bad = bad || rp_read(c, path, &b->ori) || b->ori.rank != 2 || b->ori.dims[0] != nt ||
          b->ori.dims[1] != 4;
    if (bad) {
        mcs_array_free(&b->pos);
        mcs_array_free(&b->ori);
        return;
    }
    snprintf(path, sizeof path, "/stage%d/outlines/%s/nodes", k->s, name);
    mcs_array el = {0};
    mcs_error e = {0};
    if (!rp_read(c, path, &b->on) && b->on.rank == 2 && b->on.dims[1] == 3) {
        snprintf(path, sizeof path, "/stage%d/outlines/%s/elements", k->s, name);
        if (mcs_results_kind(c->r, path) == MCS_RES_DATASET &&
            !mcs_results_read_int(c->r, path, &el, &e))
            outline_components(b, &el);
        mcs_array_free(&el);
    }
    if (!b->ncomp) mcs_array_free(&b->on);
    k->nb++;
}

static void kin_free(kin *k)
{
    for (int i = 0; i < k->nb; i++) {
        mcs_array_free(&k->b[i].pos);
        mcs_array_free(&k->b[i].ori);
        mcs_array_free(&k->b[i].on);
        free(k->b[i].cstart);
        free(k->b[i].cnode);
    }
    for (int i = 0; i < k->np; i++) {
        mcs_array_free(&k->p[i].nodes);
        free(k->p[i].edge);
    }
    mcs_array_free(&k->ftime);
    free(k->disp);
    free(k->xy);
    free(k->hull);
}

/* the index of the sample of t (n) nearest to time */
static size_t nearest(const double *t, size_t n, double time)
{
    size_t best = 0;
    for (size_t i = 1; i < n; i++)
        if (fabs(t[i] - time) < fabs(t[best] - time)) best = i;
    return best;
}

/* a world point of body b at row r: the outline node j (or the centre when j < 0) */
static void body_point(const kin_body *b, size_t r, int j, double *w)
{
    const double *p = b->pos.v + 3 * r, *q = b->ori.v + 4 * r;
    if (j < 0) {
        memcpy(w, p, 3 * sizeof *w);
        return;
    }
    qrot(q, b->on.v + 3 * (size_t)j, w);
    for (int i = 0; i < 3; i++) w[i] += p[i];
}

/* the world position of part node j in the current field */
static void part_point(const kin *k, const kin_part *p, int j, double *w)
{
    const double *x = p->nodes.v + 3 * (size_t)j;
    size_t g = 3 * ((size_t)p->offset + (size_t)j);
    for (int i = 0; i < 3; i++) w[i] = x[i] + (k->disp && g + 2 < k->nfield ? k->disp[g + i] : 0);
}

/* the margin around a span [m]: 10 % and at least 0.1 m */
static double pass_margin(double span)
{
    return fmax(0.1 * span, 0.1);
}

static void grow(double *lo, double *hi, const double *w)
{
    for (int i = 0; i < 3; i++) {
        if (w[i] < lo[i]) lo[i] = w[i];
        if (w[i] > hi[i]) hi[i] = w[i];
    }
}

/* load the field frame nearest to time (no field: zero displacement) */
static void load_field(tr_rp *c, kin *k, double time)
{
    if (!k->disp || !k->ftime.n) return;
    char path[64];
    mcs_error e = {0};
    snprintf(path, sizeof path, "/stage%d/fields/displacement", k->s);
    size_t row = nearest(k->ftime.v, k->ftime.n, time);
    if (mcs_results_read_row(c->r, path, row, k->disp, k->nfield, &e))
        memset(k->disp, 0, sizeof *k->disp * k->nfield);
}

/* one cell of a strip: view 0 side (x, z), 1 top (x, y) */
typedef struct {
    double ox, oy, sc; /* pixel origin of (lo.x, lo.v) and pixels per metre */
    int v;             /* the vertical world axis: 2 (z) or 1 (y) */
    double lo0, lov;
} kin_cell;

static void cell_px(const kin_cell *cl, const double *w, double *px, double *py)
{
    *px = cl->ox + (w[0] - cl->lo0) * cl->sc;
    *py = cl->oy - (w[cl->v] - cl->lov) * cl->sc;
}

static const char *cls_fill[] = {"#d62728", "#1f77b4", "#8c8c8c"};

static void draw_bodies(FILE *f, kin *k, const kin_cell *cl, size_t r)
{
    for (int i = 0; i < k->nb; i++) {
        const kin_body *b = &k->b[i];
        if (!b->ncomp) { /* centre and x axis */
            double w[3], a[3], ex[3] = {0.1, 0, 0}, px, py, qx, qy;
            body_point(b, r, -1, w);
            qrot(b->ori.v + 4 * r, ex, a);
            for (int d = 0; d < 3; d++) a[d] += w[d];
            cell_px(cl, w, &px, &py);
            cell_px(cl, a, &qx, &qy);
            fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"2.5\" fill=\"%s\"/>", px, py,
                    cls_fill[b->cls]);
            an_svg_line(f, px, py, qx, qy, cls_fill[b->cls], 1, NULL);
            continue;
        }
        for (int s = 0; s < b->ncomp; s++) {
            int n = 0;
            for (int j = b->cstart[s]; j < b->cstart[s + 1]; j++, n++) {
                double w[3];
                body_point(b, r, b->cnode[j], w);
                cell_px(cl, w, &k->xy[2 * n], &k->xy[2 * n + 1]);
            }
            int h = an_svg_hull(k->xy, n, k->hull);
            double hx[512], hy[512];
            for (int j = 0; j < h && j < 512; j++) {
                hx[j] = k->hull[2 * j];
                hy[j] = k->hull[2 * j + 1];
            }
            an_svg_polygon(f, hx, hy, h < 512 ? h : 512, cls_fill[b->cls], cls_fill[b->cls],
                           0.35);
        }
    }
}

static void draw_parts(FILE *f, kin *k, const kin_cell *cl)
{
    for (int i = 0; i < k->np; i++) {
        const kin_part *p = &k->p[i];
        const char *col = strstr(p->name, "foam") ? "#ff7f0e" : "#2ca02c";
        if (p->hull) {
            int n = (int)p->nodes.dims[0];
            if (n > k->nscratch) n = k->nscratch;
            for (int j = 0; j < n; j++) {
                double w[3];
                part_point(k, p, j, w);
                cell_px(cl, w, &k->xy[2 * j], &k->xy[2 * j + 1]);
            }
            int h = an_svg_hull(k->xy, n, k->hull);
            double *hx = malloc(sizeof *hx * 2 * (size_t)(h + 1));
            if (!hx) continue;
            for (int j = 0; j < h; j++) {
                hx[j] = k->hull[2 * j];
                hx[h + 1 + j] = k->hull[2 * j + 1];
            }
            an_svg_polygon(f, hx, hx + h + 1, h, col, col, 0.3);
            free(hx);
            continue;
        }
        fputs("<path d=\"", f);
        for (int e = 0; e < p->nedge; e++) {
            double a[3], b[3], ax, ay, bx, by;
            part_point(k, p, p->edge[2 * e], a);
            part_point(k, p, p->edge[2 * e + 1], b);
            cell_px(cl, a, &ax, &ay);
            cell_px(cl, b, &bx, &by);
            fprintf(f, "M%.1f %.1fL%.1f %.1f", ax, ay, bx, by);
        }
        fprintf(f, "\" stroke=\"%s\" stroke-width=\"%s\" fill=\"none\"/>\n", col,
                strstr(p->name, "belt") ? "2" : "0.8");
    }
}

/* frame times: every dt from the first sample, at most max_frames (dt grows to fit) */
static int frame_times(const tr_rp *c, int s, double *ft, int cap)
{
    const mcs_array *t = &c->time[s];
    double t0 = t->v[0], t1 = t->v[t->n - 1], dt = c->o.snapshot_dt;
    if (!(dt > 0)) dt = 0.02;
    int n = (int)floor((t1 - t0) / dt + 1e-9) + 1;
    int maxf = c->o.max_frames > 0 && c->o.max_frames < cap ? c->o.max_frames : cap;
    if (n > maxf) {
        dt *= ceil((double)n / maxf);
        n = (int)floor((t1 - t0) / dt + 1e-9) + 1;
    }
    for (int i = 0; i < n; i++) ft[i] = t0 + i * dt;
    return n;
}

/* one strip (view 0 side, 1 top) of the frames */
static void strip(tr_rp *c, kin *k, int view, const double *ft, int nf)
{
    int v = view ? 1 : 2;
    double ww = k->hi[0] - k->lo[0], wh = k->hi[v] - k->lo[v];
    double sc = RP_CELLW / ww, ch = wh * sc;
    if (ch > 240) ch = 240, sc = fmin(sc, 240 / wh);
    if (ch < 70) ch = 70;
    int cols = nf < RP_COLS ? nf : RP_COLS, rows = (nf + RP_COLS - 1) / RP_COLS;
    double padl = 40, padb = 30, gap = 8, cw = RP_CELLW;
    double W = padl + cols * (cw + gap), H = 34 + rows * (ch + padb + gap);
    char title[128];
    snprintf(title, sizeof title, "Stage %d, %s view (%s), every %.0f ms", k->s,
             view ? "top" : "side", view ? "x forward, y left" : "x forward, z up",
             nf > 1 ? 1e3 * (ft[1] - ft[0]) : 0);
    FILE *f = c->f;
    an_svg_begin(f, W, H, title);
    fputs("<g font-weight=\"bold\">", f);
    an_svg_text(f, 8, 16, "start", 13, NULL, title);
    fputs("</g>\n", f);
    double xt[AN_SVG_MAXTICKS], yt[AN_SVG_MAXTICKS], xs, ys;
    int nxt = an_svg_ticks(k->lo[0], k->hi[0], 5, xt, &xs);
    int nyt = an_svg_ticks(k->lo[v], k->hi[v], 5, yt, &ys);
    for (int i = 0; i < nf; i++) {
        int col = i % RP_COLS, row = i / RP_COLS;
        double x0 = padl + col * (cw + gap), y0 = 28 + row * (ch + padb + gap);
        kin_cell cl = {.ox = x0 + (cw - ww * sc) / 2, .oy = y0 + ch - (ch - wh * sc) / 2,
                       .sc = sc, .v = v, .lo0 = k->lo[0], .lov = k->lo[v]};
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#fafafa\" "
                   "stroke=\"#bbb\"/>\n",
                x0, y0, cw, ch);
        char lb[48];
        for (int j = 0; j < nxt; j++) { /* x ticks on every cell */
            double w[3] = {xt[j], 0, 0}, px, py;
            w[v] = k->lo[v];
            cell_px(&cl, w, &px, &py);
            if (px < x0 - 0.5 || px > x0 + cw + 0.5) continue;
            an_svg_line(f, px, y0 + ch, px, y0 + ch + 3, "#444", 1, NULL);
            an_svg_tick_label(xt[j], xs, lb, sizeof lb);
            an_svg_text(f, px, y0 + ch + 13, "middle", 9, NULL, lb);
        }
        if (col == 0)
            for (int j = 0; j < nyt; j++) {
                double w[3] = {k->lo[0], 0, 0}, px, py;
                w[v] = yt[j];
                cell_px(&cl, w, &px, &py);
                if (py < y0 - 0.5 || py > y0 + ch + 0.5) continue;
                an_svg_line(f, x0 - 3, py, x0, py, "#444", 1, NULL);
                an_svg_tick_label(yt[j], ys, lb, sizeof lb);
                an_svg_text(f, x0 - 5, py + 3, "end", 9, NULL, lb);
            }
        if (view == 0 && k->lo[2] <= 0 && k->hi[2] >= 0) { /* the ground */
            double a[3] = {k->lo[0], 0, 0}, b[3] = {k->hi[0], 0, 0}, ax, ay, bx, by;
            cell_px(&cl, a, &ax, &ay);
            cell_px(&cl, b, &bx, &by);
            an_svg_line(f, ax, ay, bx, by, "#6b4f2a", 1.5, NULL);
        }
        size_t r = nearest(c->time[k->s].v, c->time[k->s].n, ft[i]);
        load_field(c, k, ft[i]);
        fprintf(f, "<clipPath id=\"k%d%d_%d\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" "
                   "height=\"%.1f\"/></clipPath><g clip-path=\"url(#k%d%d_%d)\">\n",
                k->s, view, i, x0, y0, cw, ch, k->s, view, i);
        draw_bodies(f, k, &cl, r);
        draw_parts(f, k, &cl);
        fputs("</g>\n", f);
        snprintf(lb, sizeof lb, "%.0f ms", 1e3 * c->time[k->s].v[r]);
        an_svg_text(f, x0 + 4, y0 + 12, "start", 10, "#333", lb);
        an_svg_text(f, x0 + cw, y0 + ch + 24, "end", 9, "#666", "x [m]");
    }
    fprintf(f, "<text transform=\"translate(10 %.1f) rotate(-90)\" text-anchor=\"middle\" "
               "font-size=\"10\">%s [m]</text>\n",
            28 + ch / 2, view ? "y" : "z");
    an_svg_end(f);
    c->sum->nsvg++;
}

/* the world bounds over all frames of the rider, the motorcycle and the FE parts (of every
 * body when there are none of those), with a margin; other bodies are clipped */
static void bounds(tr_rp *c, kin *k, const double *ft, int nf)
{
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < 3; i++) k->lo[i] = INFINITY, k->hi[i] = -INFINITY;
        for (int f = 0; f < nf; f++) {
            size_t r = nearest(c->time[k->s].v, c->time[k->s].n, ft[f]);
            load_field(c, k, ft[f]);
            for (int i = 0; i < k->nb; i++) {
                const kin_body *b = &k->b[i];
                double w[3];
                if (pass == 0 && b->cls == 2) continue;
                if (!b->ncomp) {
                    body_point(b, r, -1, w);
                    grow(k->lo, k->hi, w);
                }
                for (size_t j = 0; b->ncomp && j < b->on.dims[0]; j++) {
                    body_point(b, r, (int)j, w);
                    grow(k->lo, k->hi, w);
                }
            }
            for (int i = 0; i < k->np; i++)
                for (size_t j = 0; j < k->p[i].nodes.dims[0]; j++) {
                    double w[3];
                    part_point(k, &k->p[i], (int)j, w);
                    grow(k->lo, k->hi, w);
                }
        }
        if (k->lo[0] <= k->hi[0]) break;
    }
    for (int i = 0; i < 3; i++) {
        double m = pass_margin(k->hi[i] - k->lo[i]);
        k->lo[i] -= m;
        k->hi[i] += m;
    }
}

static int stage_kin(tr_rp *c, int s, int *any)
{
    if (c->time[s].n < 2) return 0;
    kin *k = calloc(1, sizeof *k);
    if (!k) return 0;
    k->s = s;
    char g[64];
    int n;
    snprintf(g, sizeof g, "/stage%d/bodies", s);
    char **names = rp_list(c, g, &n);
    for (int i = 0; i < n && k->nb < RP_MAXBODY; i++) load_body(c, k, names[i]);
    mcs_results_list_free(&names, n);
    snprintf(g, sizeof g, "/stage%d/mesh", s);
    names = rp_list(c, g, &n);
    for (int i = 0; i < n && k->np < RP_MAXPART; i++) load_part(c, k, names[i]);
    mcs_results_list_free(&names, n);
    /* the field: its times (else /stageN/time when the rows match) and one row's storage */
    char path[64];
    int rank;
    size_t dims[MCS_RESULTS_MAXRANK];
    mcs_error e = {0};
    snprintf(path, sizeof path, "/stage%d/fields/displacement", s);
    if (k->np && mcs_results_kind(c->r, path) == MCS_RES_DATASET &&
        !mcs_results_shape(c->r, path, &rank, dims, &e) && rank == 3) {
        snprintf(g, sizeof g, "/stage%d/fields/time", s);
        if (rp_read(c, g, &k->ftime) || k->ftime.n != dims[0]) {
            mcs_array_free(&k->ftime);
            if (c->time[s].n == dims[0]) {
                k->ftime = c->time[s];
                k->ftime.v = malloc(sizeof(double) * dims[0]);
                if (k->ftime.v) memcpy(k->ftime.v, c->time[s].v, sizeof(double) * dims[0]);
                else k->ftime.n = 0;
            }
        }
        k->nfield = dims[1] * dims[2];
        k->disp = calloc(k->nfield, sizeof *k->disp);
    }
    int drawn = 0;
    if (k->nb || k->np) {
        int cap = 1;
        for (int i = 0; i < k->nb; i++)
            if (k->b[i].ncomp && (int)k->b[i].on.dims[0] > cap) cap = (int)k->b[i].on.dims[0];
        for (int i = 0; i < k->np; i++)
            if ((int)k->p[i].nodes.dims[0] > cap) cap = (int)k->p[i].nodes.dims[0];
        k->nscratch = cap;
        k->xy = malloc(sizeof *k->xy * 2 * (size_t)cap);
        k->hull = malloc(sizeof *k->hull * (4 * (size_t)cap + 2));
        double ft[64];
        int nf = frame_times(c, s, ft, 64);
        if (k->xy && k->hull && nf > 0) {
            bounds(c, k, ft, nf);
            if (!*any) {
                rp_section(c, "kinematics", "Kinematic snapshots");
                fputs("<p class=\"note\">rider bodies red, motorcycle blue, other bodies grey "
                      "(each surface's outline); FE parts green (edges, or the outline of a "
                      "large mesh), foam orange. Bodies without outlines: centre and x axis."
                      "</p>\n",
                      c->f);
                *any = 1;
            }
            strip(c, k, 0, ft, nf);
            strip(c, k, 1, ft, nf);
            drawn = 1;
        }
    }
    kin_free(k);
    free(k);
    return drawn;
}

void rp_kinematics(tr_rp *c)
{
    int any = 0;
    for (int s = 1; s <= RP_NSTAGE; s++) stage_kin(c, s, &any);
    if (any) fputs("</section>\n", c->f);
    else rp_skip(c, "kinematics", "no bodies or meshes");
}

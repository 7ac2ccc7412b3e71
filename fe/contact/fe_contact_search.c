/* fe_contact_search: bucket sort of the contact segments (spatial hashing).
 *
 * Each segment's box, grown by the surface offsets and the search margin, has its centre in
 * one cell of a grid whose edge is the largest grown box; the segment goes into that cell's
 * bucket only (one item per segment). A point inside a grown box is then within half a cell
 * of the box centre on each axis, so the cells overlapping [x - cell/2, x + cell/2] (at most
 * 2 per axis, 8 in all) hold every segment whose box holds the point. Cells are hashed into a
 * table of at least nseg buckets, so the grid costs nothing where there is no segment. While
 * no segment node has moved more than the margin since the search, every segment within
 * contact distance of a node is among them (fe_contact.c checks the motion each step and asks
 * for a new search). Boxes and reference positions are kept in single precision, the boxes
 * rounded outwards and the motion threshold lowered by the rounding of the positions, so that
 * both stay conservative. */
#include "fe/fe_contact_impl.h"

#include <math.h>
#include <string.h>

int fe_contact_hash_size(const fe_contact_model *c, int p)
{
    int n = c->pass[p].seg_end - c->pass[p].seg_begin, h = 16;
    while (2 * h < n) h *= 2; /* at least n/2: far more than the cells segments occupy */
    return h;
}

static inline unsigned cell_hash(long ix, long iy, long iz, int h)
{
    unsigned long k = (unsigned long)ix * 73856093ul ^ (unsigned long)iy * 19349663ul ^
                      (unsigned long)iz * 83492791ul;
    return (unsigned)(k & (unsigned long)(h - 1));
}

static inline int cell_of(const double *g, double x, int i, long *ix)
{
    double u = (x - g[i]) / g[3];
    if (!(fabs(u) < 1e9)) return 0;
    *ix = (long)floor(u);
    return 1;
}

int fe_contact_buckets(const fe_contact_state *cs, int p, const double x[3], int bk[27])
{
    const double *g = cs->pass_cell + 4 * p;
    if (!(g[3] > 0)) return 0;
    const double h = 0.5 * g[3];
    long lo[3], hi[3];
    for (int i = 0; i < 3; i++)
        if (!cell_of(g, x[i] - h, i, &lo[i]) || !cell_of(g, x[i] + h, i, &hi[i])) return 0;
    const int hs = cs->pass_hash[p];
    int n = 0;
    for (long a = lo[0]; a <= hi[0]; a++)
        for (long b = lo[1]; b <= hi[1]; b++)
            for (long c = lo[2]; c <= hi[2]; c++) {
                int k = (int)cell_hash(a, b, c, hs), dup = 0;
                for (int j = 0; j < n && !dup; j++) dup = bk[j] == k;
                if (!dup && n < 27) bk[n++] = k;
            }
    return n;
}

/* float bounds that contain [lo, hi] */
static inline void round_out(double lo, double hi, float *flo, float *fhi)
{
    float a = (float)lo, b = (float)hi;
    if ((double)a > lo) a = nextafterf(a, -INFINITY);
    if ((double)b < hi) b = nextafterf(b, INFINITY);
    *flo = a, *fhi = b;
}

/* the grown box of each segment of pass P (doubles in box, floats kept); the grid origin and
 * cell; returns the cell edge (0: no usable segment) */
static double pass_boxes(const fe_contact_model *c, const fe_state *s, const fe_contact_pass *P,
                         double *g)
{
    fe_contact_state *cs = s->contact;
    double htmax = 0;
    for (int e = P->ent_begin; e < P->ent_end; e++) htmax = fmax(htmax, c->ent_ht[e]);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, cell = 0;
    for (int sg = P->seg_begin; sg < P->seg_end; sg++) {
        double box[6];
        const int *q = c->seg_node + 4 * sg;
        for (int i = 0; i < 3; i++) box[i] = INFINITY, box[3 + i] = -INFINITY;
        for (int k = 0; k < 4; k++)
            for (int i = 0; i < 3; i++) {
                double x = s->node_x[3 * q[k] + i];
                box[i] = fmin(box[i], x);
                box[3 + i] = fmax(box[3 + i], x);
            }
        double grow = c->seg_ht[sg] + htmax + c->margin;
        float *fb = cs->seg_box + 6 * sg;
        for (int i = 0; i < 3; i++) {
            box[i] -= grow;
            box[3 + i] += grow;
            round_out(box[i], box[3 + i], &fb[i], &fb[3 + i]);
            lo[i] = fmin(lo[i], fb[i]);
            cell = fmax(cell, (double)fb[3 + i] - (double)fb[i]);
        }
    }
    g[0] = lo[0], g[1] = lo[1], g[2] = lo[2], g[3] = cell * (1 + 1e-9);
    if (!(cell > 0) || !isfinite(cell)) g[3] = 0;
    return g[3];
}

/* the bucket of a segment: the cell of its (float) box centre, -1 if off the grid */
static inline int seg_bucket(const float *b, const double *g, int hs)
{
    long ix[3];
    for (int i = 0; i < 3; i++)
        if (!cell_of(g, 0.5 * ((double)b[i] + (double)b[3 + i]), i, &ix[i])) return -1;
    return (int)cell_hash(ix[0], ix[1], ix[2], hs);
}

void fe_contact_search(const fe_model *m, fe_state *s)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    /* reference positions; the motion threshold less what their rounding can hide */
    double err = 0;
    for (int t = 0; t < c->nnode_touch; t++)
        for (int i = 0; i < 3; i++) {
            const double x = s->node_x[3 * c->touch[t] + i];
            float *r = cs->x_ref + 3 * t + i;
            *r = (float)x;
            err = fmax(err, fabs(x - (double)*r));
        }
    const double h = fmax(0, 0.5 * c->margin - 2 * err);
    cs->margin2 = h * h;
    for (int p = 0; p < c->npass; p++) {
        const fe_contact_pass *P = &c->pass[p];
        double *g = cs->pass_cell + 4 * p;
        int hs = cs->pass_hash[p];
        int *off = cs->cell_off + cs->pass_cell_base[p];
        memset(off, 0, sizeof(int) * ((size_t)hs + 1));
        if (!(pass_boxes(c, s, P, g) > 0)) continue;
        /* counting sort of the segments by bucket; items of pass p start at seg_begin */
        for (int sg = P->seg_begin; sg < P->seg_end; sg++) {
            int k = seg_bucket(cs->seg_box + 6 * sg, g, hs);
            if (k >= 0) off[k + 1]++;
        }
        for (int k = 0; k < hs; k++) off[k + 1] += off[k];
        for (int k = hs; k > 0; k--) off[k] = off[k - 1];
        off[0] = 0;
        int *item = cs->cell_item + P->seg_begin;
        for (int sg = P->seg_begin; sg < P->seg_end; sg++) {
            int k = seg_bucket(cs->seg_box + 6 * sg, g, hs);
            if (k >= 0) item[off[k + 1]++] = sg;
        }
    }
    cs->nrebuild++;
    cs->need_rebuild = 0;
}

/* the candidates of entry e (pass P) at x, written to out when out is not NULL (at most cap;
 * one more means too many); returns their number */
static int entry_candidates(const fe_contact_model *c, const fe_contact_state *cs, int e, int p,
                            const double *x, int *out, int cap)
{
    const fe_contact_pass *P = &c->pass[p];
    const int node = c->ent_node[e], *off = cs->cell_off + cs->pass_cell_base[p];
    const int *item = cs->cell_item + P->seg_begin;
    int bk[27], nb = fe_contact_buckets(cs, p, x, bk), n = 0;
    for (int ib = 0; ib < nb; ib++)
        for (int k = off[bk[ib]]; k < off[bk[ib] + 1]; k++) {
            const int sg = item[k], *q = c->seg_node + 4 * sg;
            if (!fe_contact_in_box(cs->seg_box + 6 * sg, x)) continue;
            if (q[0] == node || q[1] == node || q[2] == node || q[3] == node) continue;
            if (P->self && fe_contact_seg_has_nbr(c, q, node)) continue;
            if (out) {
                if (n == cap) return n + 1;
                /* in segment order (the order of a bucket), insertion sort of a short list */
                int j = n;
                for (; j > 0 && out[j - 1] > sg; j--) out[j] = out[j - 1];
                out[j] = sg;
            }
            n++;
        }
    return n;
}

void fe_contact_candidates(const fe_model *m, fe_state *s)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    int *off = cs->ent_cand_off;
    /* counts, then offsets; an entry whose list would not fit in the pool scans its buckets */
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 256) if (c->nent > 4096)
#endif
    for (int e = 0; e < c->nent; e++)
        off[e + 1] = entry_candidates(c, cs, e, fe_contact_ent_pass(c, e),
                                      s->node_x + 3 * c->ent_node[e], NULL, 0);
    off[0] = 0;
    int nlive = 0;
    for (int e = 0; e < c->nent; e++) {
        const int n = off[e + 1];
        unsigned char f = cs->ent_flag[e] & (FE_CFLAG_SLOT0 | FE_CFLAG_SLOT1);
        off[e + 1] = off[e];
        if (n > cs->cand_cap - off[e]) f |= FE_CFLAG_SCAN;
        else off[e + 1] += n;
        if (n > 0 || f) cs->live[nlive++] = e, f |= FE_CFLAG_LIVE;
        cs->ent_flag[e] = f;
    }
    cs->nlive = nlive;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 256) if (c->nent > 4096)
#endif
    for (int e = 0; e < c->nent; e++)
        if (off[e + 1] > off[e])
            entry_candidates(c, cs, e, fe_contact_ent_pass(c, e), s->node_x + 3 * c->ent_node[e],
                             cs->ent_cand + off[e], off[e + 1] - off[e]);
}

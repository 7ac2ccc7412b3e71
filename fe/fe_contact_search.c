/* fe_contact_search: bucket sort of the contact segments (spatial hashing).
 *
 * Each segment's box, grown by the surface offsets and the search margin, is put into every
 * bucket it overlaps. The cell edge is the largest grown box, so a box spans at most 2 cells
 * per axis (8 buckets): the bucket arrays have a fixed size and never overflow. Cells are
 * hashed into a table of at least 2 nseg buckets, so the grid costs nothing where there is no
 * segment. A node's candidates are the segments of its own bucket: while no segment node has
 * moved more than the margin since the search, every segment within contact distance of the
 * node is there (fe_contact.c checks the motion each step and asks for a new search). */
#include "fe/fe_contact_impl.h"

#include <math.h>
#include <string.h>

int fe_contact_hash_size(const fe_contact_model *c, int p)
{
    int n = c->pass[p].seg_end - c->pass[p].seg_begin, h = 16;
    while (h < 2 * n) h *= 2;
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

void fe_contact_bucket(const fe_contact_state *cs, int p, const double x[3], int *begin, int *end)
{
    const double *g = cs->pass_cell + 4 * p;
    long ix, iy, iz;
    *begin = *end = 0;
    if (!(g[3] > 0) || !cell_of(g, x[0], 0, &ix) || !cell_of(g, x[1], 1, &iy) ||
        !cell_of(g, x[2], 2, &iz))
        return;
    const int *off = cs->cell_off + cs->pass_cell_base[p];
    unsigned h = cell_hash(ix, iy, iz, cs->pass_hash[p]);
    *begin = off[h];
    *end = off[h + 1];
}

/* the distinct buckets of segment sg's grown box (at most 8), -1 padded */
static void seg_buckets(const double *box, const double *g, int hsize, int *out)
{
    long lo[3], hi[3];
    int n = 0;
    for (int i = 0; i < 3; i++) {
        if (!cell_of(g, box[i], i, &lo[i]) || !cell_of(g, box[3 + i], i, &hi[i])) {
            for (int k = 0; k < 8; k++) out[k] = -1;
            return;
        }
        if (hi[i] > lo[i] + 1) hi[i] = lo[i] + 1; /* cannot happen: the cell is the largest box */
    }
    for (long a = lo[0]; a <= hi[0]; a++)
        for (long b = lo[1]; b <= hi[1]; b++)
            for (long c = lo[2]; c <= hi[2]; c++) {
                int h = (int)cell_hash(a, b, c, hsize), dup = 0;
                for (int k = 0; k < n && !dup; k++) dup = out[k] == h;
                if (!dup) out[n++] = h;
            }
    for (int k = n; k < 8; k++) out[k] = -1;
}

void fe_contact_search(const fe_model *m, fe_state *s)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    for (int t = 0; t < c->nnode_touch; t++)
        memcpy(cs->x_ref + 3 * t, s->node_x + 3 * c->touch[t], 3 * sizeof(double));
    for (int p = 0; p < c->npass; p++) {
        const fe_contact_pass *P = &c->pass[p];
        double htmax = 0;
        for (int e = P->ent_begin; e < P->ent_end; e++) htmax = fmax(htmax, c->ent_ht[e]);
        double *g = cs->pass_cell + 4 * p, lo[3] = {INFINITY, INFINITY, INFINITY}, cell = 0;
        for (int sg = P->seg_begin; sg < P->seg_end; sg++) {
            double *box = cs->seg_box + 6 * sg;
            const int *q = c->seg_node + 4 * sg;
            for (int i = 0; i < 3; i++) box[i] = INFINITY, box[3 + i] = -INFINITY;
            for (int k = 0; k < 4; k++)
                for (int i = 0; i < 3; i++) {
                    double x = s->node_x[3 * q[k] + i];
                    box[i] = fmin(box[i], x);
                    box[3 + i] = fmax(box[3 + i], x);
                }
            double grow = c->seg_ht[sg] + htmax + c->margin;
            for (int i = 0; i < 3; i++) {
                box[i] -= grow;
                box[3 + i] += grow;
                lo[i] = fmin(lo[i], box[i]);
                cell = fmax(cell, box[3 + i] - box[i]);
            }
        }
        int hs = cs->pass_hash[p];
        int *off = cs->cell_off + cs->pass_cell_base[p];
        memset(off, 0, sizeof(int) * ((size_t)hs + 1));
        g[0] = lo[0], g[1] = lo[1], g[2] = lo[2], g[3] = cell * (1 + 1e-9);
        if (!(cell > 0) || !isfinite(cell)) {
            g[3] = 0;
            continue;
        }
        int *sc = cs->seg_cells;
        for (int sg = P->seg_begin; sg < P->seg_end; sg++) {
            seg_buckets(cs->seg_box + 6 * sg, g, hs, sc + 8 * sg);
            for (int k = 0; k < 8 && sc[8 * sg + k] >= 0; k++) off[sc[8 * sg + k] + 1]++;
        }
        for (int h = 0; h < hs; h++) off[h + 1] += off[h];
        /* fill: items of pass p start at 8 seg_begin in cell_item; offsets are relative */
        int *item = cs->cell_item + 8 * (size_t)P->seg_begin;
        for (int h = hs; h > 0; h--) off[h] = off[h - 1];
        off[0] = 0;
        for (int sg = P->seg_begin; sg < P->seg_end; sg++)
            for (int k = 0; k < 8 && sc[8 * sg + k] >= 0; k++) item[off[sc[8 * sg + k] + 1]++] = sg;
    }
    cs->nrebuild++;
    cs->need_rebuild = 0;
}

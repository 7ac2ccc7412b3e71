/* fe_kw_tet10: *ELEMENT_SOLID_TET4TOTET10, 4-node tetrahedra read as 10-node ones: each edge
 * gets a node at its middle, shared by the elements around it, numbered after the deck's
 * largest node ID in the order of the sorted corner pairs (the edges 1-2, 2-3, 3-1, 1-4, 2-4,
 * 3-4 become N5..N10, LS-DYNA's 10-node order). */
#include "fe/fe_kw_impl.h"

#include <stdlib.h>
#include <string.h>

typedef struct {
    int a, b;  /* corner node IDs, a < b */
    int slot;  /* element index * 6 + edge */
} edge_rec;

static int cmp_edge(const void *p, const void *q)
{
    const edge_rec *x = p, *y = q;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    return (x->slot > y->slot) - (x->slot < y->slot);
}

static const kw_node *find(const kw_ctx *c, int id)
{
    int lo = 0, hi = c->nnode - 1;
    while (lo <= hi) {
        const int mid = (lo + hi) / 2;
        if (c->node[mid].id == id) return &c->node[mid];
        if (c->node[mid].id < id) lo = mid + 1;
        else hi = mid - 1;
    }
    return NULL;
}

mcs_status kw_tet4_to_tet10(kw_ctx *c)
{
    static const int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    fe_kw_elems *e = &c->d->elem[FE_KW_TET10];
    int npend = 0;
    for (int i = 0; i < e->n; i++) npend += e->node[10 * (size_t)i + 4] == 0;
    if (npend == 0) return MCS_OK;
    edge_rec *r = malloc(sizeof *r * 6 * (size_t)npend);
    if (!r) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory (TET4TOTET10)");
    int nr = 0;
    for (int i = 0; i < e->n; i++) {
        const int *nd = e->node + 10 * (size_t)i;
        if (nd[4] != 0) continue;
        for (int j = 0; j < 4; j++)
            if (!find(c, nd[j])) {
                free(r);
                snprintf(c->kw, sizeof c->kw, "ELEMENT_SOLID_TET4TOTET10");
                return kw_fail(c, e->loc[i].file, e->loc[i].line, 0, MCS_ERR_FORMAT,
                               "element %d: node N%d = %d is not defined by any *NODE", e->id[i],
                               j + 1, nd[j]);
            }
        for (int k = 0; k < 6; k++) {
            const int p = nd[edge[k][0]], q = nd[edge[k][1]];
            r[nr++] = (edge_rec){p < q ? p : q, p < q ? q : p, 6 * i + k};
        }
    }
    qsort(r, (size_t)nr, sizeof *r, cmp_edge);
    int next = c->node[c->nnode - 1].id + 1; /* c->node is sorted by ID */
    mcs_status st = MCS_OK;
    for (int j = 0; j < nr && !st; j++) {
        if (j == 0 || r[j].a != r[j - 1].a || r[j].b != r[j - 1].b) {
            const kw_node *pa = find(c, r[j].a), *pb = find(c, r[j].b);
            double x[3];
            for (int i = 0; i < 3; i++) x[i] = 0.5 * (pa->x[i] + pb->x[i]);
            st = kw_add_node(c, next++, x, e->loc[r[j].slot / 6]); /* IDs above all: sorted */
        }
        e->node[10 * (size_t)(r[j].slot / 6) + 4 + r[j].slot % 6] = next - 1;
    }
    free(r);
    return st;
}

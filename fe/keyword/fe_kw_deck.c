/* fe_kw_deck: the neutral deck's memory, lookups by ID, and the checks made once a deck is
 * read (unique node IDs, every element's nodes defined). */
#include "fe/fe_kw_impl.h"

#include <stdlib.h>
#include <string.h>

static const int etype_nnode[FE_KW_NETYPE] = {4, 8, 2, 2, 10, 8};
static const char *const etype_name[FE_KW_NETYPE] = {"SHELL", "SOLID", "BEAM", "DISCRETE",
                                                     "SOLID", "TSHELL"};

int fe_kw_etype_nnode(fe_kw_etype t) { return etype_nnode[t]; }
const char *fe_kw_etype_name(fe_kw_etype t) { return etype_name[t]; }

int kw_grow(void **p, int *cap, int need, size_t sz)
{
    if (need <= *cap) return 0;
    if (need > 1 << 29) return -1;
    int nc = *cap ? *cap : 16;
    while (nc < need) nc *= 2;
    void *q = realloc(*p, (size_t)nc * sz);
    if (!q) return -1;
    *p = q;
    *cap = nc;
    return 0;
}

void *kw_push(void **arr, int *n, int *cap, size_t sz)
{
    if (kw_grow(arr, cap, *n + 1, sz)) return NULL;
    char *e = (char *)*arr + sz * (size_t)(*n)++;
    memset(e, 0, sz);
    return e;
}

const char *fe_kw_skipped(const fe_kw_deck *d, const char *prefixes, char *buf, size_t n)
{
    size_t at = 0;
    buf[0] = 0;
    for (int i = 0; i < d->nunknown; i++) {
        const fe_kw_unknown *u = &d->unknown[i];
        int hit = 0;
        for (const char *p = prefixes; *p && !hit;) {
            size_t k = strcspn(p, "|");
            hit = k && strncmp(u->name, p, k) == 0;
            p += k + (p[k] == '|');
        }
        if (!hit || at + 1 >= n) continue;
        at += (size_t)snprintf(buf + at, n - at, "%s*%s at %s:%d",
                               at ? ", " : " (skipped as not supported: ", u->name,
                               d->file[u->loc.file], u->loc.line);
    }
    if (at && at + 2 < n) snprintf(buf + at, n - at, ")");
    return buf;
}

fe_kw_opts fe_kw_opts_default(void)
{
    fe_kw_opts o = {.units = NULL, .strict = 0, .quiet = 0};
    return o;
}

mcs_status fe_kw_deck_create(fe_kw_deck **out, mcs_error *err)
{
    *out = calloc(1, sizeof **out);
    if (!*out) return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
    (*out)->unit[0] = (*out)->unit[1] = (*out)->unit[2] = 1;
    return MCS_OK;
}

void fe_kw_deck_destroy(fe_kw_deck **p)
{
    if (!p || !*p) return;
    fe_kw_deck *d = *p;
    for (int i = 0; i < d->nfile; i++) free(d->file[i]);
    free(d->file);
    free(d->node_id);
    free(d->node_x);
    for (int t = 0; t < FE_KW_NETYPE; t++) {
        free(d->elem[t].id);
        free(d->elem[t].pid);
        free(d->elem[t].node);
        free(d->elem[t].dval);
        free(d->elem[t].loc);
        free(d->elem[t].thick);
    }
    for (int i = 0; i < d->ncurve; i++) free(d->curve[i].xy);
    for (int i = 0; i < d->nset; i++) free(d->set[i].ids);
    free(d->part);
    free(d->section);
    free(d->mat);
    free(d->curve);
    free(d->set);
    free(d->wall);
    free(d->wmotion);
    free(d->iv);
    free(d->spc);
    free(d->unknown);
    free(d->hg);
    kw_contact_free(d); /* fe_kw_cards_contact.c */
    kw_joint_free(d);   /* fe_kw_cards_joint.c */
    free(d);
    *p = NULL;
}

int kw_add_file(fe_kw_deck *d, const char *path)
{
    int cap = d->nfile;
    if (kw_grow((void **)&d->file, &cap, d->nfile + 1, sizeof(char *))) return -1;
    char *s = strdup(path);
    if (!s) return -1;
    d->file[d->nfile] = s;
    return d->nfile++;
}

mcs_status kw_add_node(kw_ctx *c, int id, const double x[3], fe_kw_loc loc)
{
    kw_node *n = kw_push((void **)&c->node, &c->nnode, &c->cap_node, sizeof *c->node);
    if (!n) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory (nodes)");
    n->id = id;
    memcpy(n->x, x, sizeof n->x);
    n->loc = loc;
    return MCS_OK;
}

static mcs_status elem_push(fe_kw_elems *e, fe_kw_etype t, int id, int pid, const int *nodes,
                            const double *dval, fe_kw_loc loc, mcs_error *err)
{
    int k = etype_nnode[t], c1 = e->cap, c2 = e->cap, c3 = e->cap, c4 = e->cap, c5 = e->cap;
    if (kw_grow((void **)&e->id, &c1, e->n + 1, sizeof(int)) ||
        kw_grow((void **)&e->pid, &c2, e->n + 1, sizeof(int)) ||
        kw_grow((void **)&e->node, &c3, e->n + 1, (size_t)k * sizeof(int)) ||
        kw_grow((void **)&e->dval, &c4, e->n + 1, 2 * sizeof(double)) ||
        kw_grow((void **)&e->loc, &c5, e->n + 1, sizeof(fe_kw_loc)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory (elements)");
    e->cap = c1;
    e->id[e->n] = id;
    e->pid[e->n] = pid;
    memcpy(e->node + (size_t)k * e->n, nodes, (size_t)k * sizeof(int));
    e->dval[2 * e->n] = dval ? dval[0] : 0;
    e->dval[2 * e->n + 1] = dval ? dval[1] : 0;
    e->loc[e->n] = loc;
    e->n++;
    return MCS_OK;
}

mcs_status kw_add_elem(kw_ctx *c, fe_kw_etype t, int id, int pid, const int *nodes,
                       const double *dval, fe_kw_loc loc)
{
    return elem_push(&c->d->elem[t], t, id, pid, nodes, dval, loc, c->err);
}

static int cmp_node(const void *a, const void *b)
{
    const kw_node *x = a, *y = b;
    if (x->id != y->id) return x->id < y->id ? -1 : 1;
    if (x->loc.file != y->loc.file) return x->loc.file < y->loc.file ? -1 : 1;
    return x->loc.line < y->loc.line ? -1 : x->loc.line > y->loc.line;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return x < y ? -1 : x > y;
}

int fe_kw_node_index(const fe_kw_deck *d, int nid)
{
    int lo = 0, hi = d->nnode - 1;
    while (lo <= hi) {
        int mid = lo + (hi - lo) / 2;
        if (d->node_id[mid] == nid) return mid;
        if (d->node_id[mid] < nid) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

/* duplicate IDs in one kind of element */
static mcs_status check_elem_ids(kw_ctx *c, fe_kw_etype t)
{
    const fe_kw_elems *e = &c->d->elem[t];
    if (e->n < 2) return MCS_OK;
    int *ids = malloc(sizeof(int) * (size_t)e->n);
    if (!ids) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    memcpy(ids, e->id, sizeof(int) * (size_t)e->n);
    qsort(ids, (size_t)e->n, sizeof(int), cmp_int);
    int dup = 0, found = 0;
    for (int i = 1; i < e->n && !found; i++)
        if (ids[i] == ids[i - 1]) dup = ids[i], found = 1;
    free(ids);
    if (!found) return MCS_OK;
    for (int i = e->n - 1; i >= 0; i--)
        if (e->id[i] == dup) {
            snprintf(c->kw, sizeof c->kw, "ELEMENT_%s", etype_name[t]);
            return kw_fail(c, e->loc[i].file, e->loc[i].line, 0, MCS_ERR_FORMAT,
                           "element %d is defined twice", dup);
        }
    return MCS_OK;
}

mcs_status kw_finish(kw_ctx *c)
{
    fe_kw_deck *d = c->d;
    if (c->nnode > 1) qsort(c->node, (size_t)c->nnode, sizeof *c->node, cmp_node);
    for (int i = 1; i < c->nnode; i++)
        if (c->node[i].id == c->node[i - 1].id) {
            snprintf(c->kw, sizeof c->kw, "NODE");
            return kw_fail(c, c->node[i].loc.file, c->node[i].loc.line, 0, MCS_ERR_FORMAT,
                           "node %d is defined twice (also at %s:%d)", c->node[i].id,
                           d->file[c->node[i - 1].loc.file], c->node[i - 1].loc.line);
        }
    mcs_status st0 = kw_tet4_to_tet10(c); /* mid-edge nodes of TET4TOTET10 (sorted IDs kept) */
    if (st0) return st0;
    d->node_id = malloc(sizeof(int) * (size_t)(c->nnode ? c->nnode : 1));
    d->node_x = malloc(3 * sizeof(double) * (size_t)(c->nnode ? c->nnode : 1));
    if (!d->node_id || !d->node_x) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    d->nnode = d->cap_node = c->nnode;
    for (int i = 0; i < c->nnode; i++) {
        d->node_id[i] = c->node[i].id;
        memcpy(d->node_x + 3 * i, c->node[i].x, 3 * sizeof(double));
    }
    for (int t = 0; t < FE_KW_NETYPE; t++) {
        const fe_kw_elems *e = &d->elem[t];
        int k = etype_nnode[t];
        for (int i = 0; i < e->n; i++)
            for (int j = 0; j < k; j++) {
                int nid = e->node[(size_t)k * i + j];
                /* a discrete element may tie its N2 to ground (0) */
                if (nid == 0 && t == FE_KW_DISCRETE && j == 1) continue;
                if (fe_kw_node_index(d, nid) < 0) {
                    snprintf(c->kw, sizeof c->kw, "ELEMENT_%s", etype_name[t]);
                    return kw_fail(c, e->loc[i].file, e->loc[i].line, 0, MCS_ERR_FORMAT,
                                   "element %d: node N%d = %d is not defined by any *NODE",
                                   e->id[i], j + 1, nid);
                }
            }
        mcs_status st = check_elem_ids(c, (fe_kw_etype)t);
        if (st) return st;
    }
    return MCS_OK;
}

const fe_kw_part *fe_kw_find_part(const fe_kw_deck *d, int pid)
{
    for (int i = 0; i < d->npart; i++)
        if (d->part[i].id == pid) return &d->part[i];
    return NULL;
}

const fe_kw_section *fe_kw_find_section(const fe_kw_deck *d, int secid)
{
    for (int i = 0; i < d->nsection; i++)
        if (d->section[i].id == secid) return &d->section[i];
    return NULL;
}

const fe_kw_mat *fe_kw_find_mat(const fe_kw_deck *d, int mid)
{
    for (int i = 0; i < d->nmat; i++)
        if (d->mat[i].id == mid) return &d->mat[i];
    return NULL;
}

const fe_kw_curve *fe_kw_find_curve(const fe_kw_deck *d, int lcid)
{
    for (int i = 0; i < d->ncurve; i++)
        if (d->curve[i].id == lcid) return &d->curve[i];
    return NULL;
}

const fe_kw_set *fe_kw_find_set(const fe_kw_deck *d, int sid, int is_part)
{
    for (int i = 0; i < d->nset; i++)
        if (d->set[i].id == sid && d->set[i].is_part == is_part) return &d->set[i];
    return NULL;
}

/* ---- decks made by hand (writers) ---- */

mcs_status fe_kw_deck_add_node(fe_kw_deck *d, int id, const double x[3], mcs_error *err)
{
    int c1 = d->cap_node, c2 = d->cap_node;
    if (d->nnode > 0 && id <= d->node_id[d->nnode - 1])
        return MCS_ERR(err, MCS_ERR_RANGE, "keyword: node %d: IDs must ascend", id);
    if (kw_grow((void **)&d->node_id, &c1, d->nnode + 1, sizeof(int)) ||
        kw_grow((void **)&d->node_x, &c2, d->nnode + 1, 3 * sizeof(double)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory (nodes)");
    d->cap_node = c1;
    d->node_id[d->nnode] = id;
    memcpy(d->node_x + 3 * d->nnode, x, 3 * sizeof(double));
    d->nnode++;
    return MCS_OK;
}

mcs_status fe_kw_deck_add_elem(fe_kw_deck *d, fe_kw_etype t, int id, int pid, const int *nodes,
                               mcs_error *err)
{
    fe_kw_loc loc = {0, 0};
    return elem_push(&d->elem[t], t, id, pid, nodes, NULL, loc, err);
}

mcs_status fe_kw_deck_add_part(fe_kw_deck *d, const fe_kw_part *p, mcs_error *err)
{
    fe_kw_part *q = kw_push((void **)&d->part, &d->npart, &d->cap_part, sizeof *q);
    if (!q) return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory (parts)");
    *q = *p;
    return MCS_OK;
}

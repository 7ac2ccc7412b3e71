/* fe_contact_build: contact descriptors -> the frozen contact model: segments (shell elements,
 * exterior hex faces), slave entries, LS-DYNA penalty stiffnesses, neighbour lists for self
 * contact, rigid ellipsoids. Runs once inside fe_model_create. */
#include "fe/fe_builder_impl.h"
#include "fe/fe_contact.h"
#include "fe/fe_contact_impl.h"
#include "fe/fe_elem.h"
#include "fe/fe_state.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the stiffness cap: k (1/m_s + 1/m_m) dt0^2 <= FE_CONTACT_KCAP, i.e. the contact spring's
 * frequency omega dt0 <= 0.45, well inside the central-difference limit 2, so the contact
 * never needs a smaller step than the elements (docs/fe.md "Contact") */
#define FE_CONTACT_KCAP 0.1

fe_contact_desc fe_contact_desc_default(void)
{
    fe_contact_desc d;
    memset(&d, 0, sizeof d);
    d.type = FE_CONTACT_SINGLE_SURFACE;
    d.friction_dynamic = -1;
    return d;
}

static mcs_status check_parts(const fe_builder *b, const char *what, const char *name, int n,
                              const char (*parts)[FE_NAME_MAX], int need, mcs_error *err)
{
    if (n < need || n > FE_CONTACT_PARTS)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: %s '%s': needs %d..%d parts, got %d", what, name,
                       need, FE_CONTACT_PARTS, n);
    for (int i = 0; i < n; i++)
        if (fe_builder_find_part(b, parts[i]) < 0)
            return MCS_ERR(err, MCS_ERR_KEY, "fe: %s '%s': unknown part '%s'", what, name,
                           parts[i]);
    return MCS_OK;
}

void fe_contact_desc_free(fe_contact_desc *d)
{
    free((void *)d->slave_node), free((void *)d->slave_face);
    free((void *)d->master_node), free((void *)d->master_face);
    d->slave_node = d->slave_face = d->master_node = d->master_face = NULL;
}

mcs_status fe_builder_add_contact(fe_builder *b, const fe_contact_desc *d, mcs_error *err)
{
    if (b->ncontact >= FE_CONTACT_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: at most %d contacts", FE_CONTACT_MAX);
    if (d->type < FE_CONTACT_TWO_SURFACE || d->type > FE_CONTACT_SINGLE_SURFACE)
        return MCS_ERR(err, MCS_ERR_KEY, "fe: contact '%s': unknown type", d->name);
    mcs_status st = check_parts(b, "contact", d->name, d->nslave, d->slave, 1, err);
    if (!st && d->type != FE_CONTACT_SINGLE_SURFACE)
        st = check_parts(b, "contact", d->name, d->nmaster, d->master, 1, err);
    if (st) return st;
    if (!(d->friction >= 0) || !(d->friction_decay >= 0) || !(d->penalty_scale >= 0) ||
        !(d->thickness_scale >= 0) || !isfinite(d->friction_dynamic) ||
        !(d->damping >= 0 && d->damping <= 1) || !(d->birth >= 0) || !(d->death >= 0) ||
        (d->death > 0 && d->death <= d->birth) ||
        d->friction_dynamic > d->friction)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: contact '%s': friction, decay, penalty_scale and thickness_scale "
                       "must be >= 0, friction_dynamic <= friction, damping in [0, 1], "
                       "birth >= 0, death 0 or > birth",
                       d->name);
    if (!(d->fabric_thickness >= 0) || !isfinite(d->fabric_thickness))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: contact '%s': fabric_thickness must be >= 0",
                       d->name);
    fe_contact_desc *o = &b->contact[b->ncontact];
    *o = *d;
    o->slave_node = o->slave_face = o->master_node = o->master_face = NULL;
    const int *src[4] = {d->slave_node, d->slave_face, d->master_node, d->master_face};
    const int num[4] = {d->nslave_node, 4 * d->nslave_face, d->nmaster_node, 4 * d->nmaster_face};
    const int **dst[4] = {&o->slave_node, &o->slave_face, &o->master_node, &o->master_face};
    for (int k = 0; k < 4; k++) { /* the side filters, copied (freed with the builder) */
        if (num[k] <= 0) continue;
        for (int i = 0; i < num[k]; i++)
            if (!src[k] || src[k][i] < 0 || src[k][i] >= fe_builder_nnode(b)) {
                fe_contact_desc_free(o);
                return MCS_ERR(err, MCS_ERR_RANGE, "fe: contact '%s': a node of its node or "
                                                   "face lists is not a node of the model",
                               d->name);
            }
        int *q = malloc(sizeof(int) * (size_t)num[k]);
        if (!q) {
            fe_contact_desc_free(o);
            return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
        }
        memcpy(q, src[k], sizeof(int) * (size_t)num[k]);
        *dst[k] = q;
    }
    if (!b->contact[b->ncontact].name[0])
        snprintf(b->contact[b->ncontact].name, FE_NAME_MAX, "contact%d", b->ncontact);
    b->ncontact++;
    return MCS_OK;
}

mcs_status fe_builder_add_ellipsoid(fe_builder *b, const fe_ellipsoid_desc *d, mcs_error *err)
{
    if (b->nellipsoid >= FE_ELLIPSOID_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: at most %d rigid ellipsoids", FE_ELLIPSOID_MAX);
    for (int i = 0; i < 3; i++)
        if (!(d->semi_axes[i] > 0) || !isfinite(d->semi_axes[i]) || !isfinite(d->center[i]) ||
            !isfinite(d->velocity[i]))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: ellipsoid '%s': semi_axes must be > 0, centre and velocity finite",
                           d->name);
    if (!(d->penalty_scale >= 0) || !(d->friction >= 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: ellipsoid '%s': penalty_scale and friction must be >= 0", d->name);
    mcs_status st = check_parts(b, "ellipsoid", d->name, d->nparts, d->parts, 0, err);
    if (st) return st;
    b->ellipsoid[b->nellipsoid++] = *d;
    return MCS_OK;
}

int fe_builder_nellipsoid(const fe_builder *b)
{
    return b->nellipsoid;
}

int fe_builder_nfacets(const fe_builder *b)
{
    return b->nfacets;
}

mcs_status fe_builder_add_facets(fe_builder *b, const fe_facet_desc *d, mcs_error *err)
{
    if (b->nfacets >= FE_FACETS_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: at most %d rigid facet surfaces", FE_FACETS_MAX);
    if (d->nvert < 3 || d->ntri < 1 || !d->vert || !d->tri)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: facet surface '%s': no triangles", d->name);
    for (int i = 0; i < 3 * d->nvert; i++)
        if (!isfinite(d->vert[i]))
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: facet surface '%s': vertex not finite",
                           d->name);
    for (int i = 0; i < 3 * d->ntri; i++)
        if (d->tri[i] < 0 || d->tri[i] >= d->nvert)
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: facet surface '%s': bad vertex index %d",
                           d->name, d->tri[i]);
    if (!(d->penalty_scale >= 0) || !(d->friction >= 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: facet surface '%s': penalty_scale and friction must be >= 0", d->name);
    mcs_status st = check_parts(b, "facet surface", d->name, d->nparts, d->parts, 0, err);
    if (st) return st;
    double *v = malloc(sizeof(double) * 3 * (size_t)d->nvert);
    int *t = malloc(sizeof(int) * 3 * (size_t)d->ntri);
    if (!v || !t) {
        free(v), free(t);
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (facets)");
    }
    memcpy(v, d->vert, sizeof(double) * 3 * (size_t)d->nvert);
    memcpy(t, d->tri, sizeof(int) * 3 * (size_t)d->ntri);
    fe_facet_desc *o = &b->facets[b->nfacets++];
    *o = *d;
    o->vert = v, o->tri = t;
    return MCS_OK;
}

/* ---- building -------------------------------------------------------------------------- */

/* the 6 faces of a hex8, nodes ordered so the diagonal cross product points outwards */
static const int hex_face[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

typedef struct {
    int key[4]; /* sorted nodes */
    int hex, face;
} face_rec;

static int cmp_face(const void *a, const void *b)
{
    const face_rec *x = a, *y = b;
    for (int i = 0; i < 4; i++)
        if (x->key[i] != y->key[i]) return x->key[i] < y->key[i] ? -1 : 1;
    return 0;
}

static void sort4(int k[4])
{
    for (int i = 1; i < 4; i++)
        for (int j = i; j > 0 && k[j - 1] > k[j]; j--) {
            int t = k[j];
            k[j] = k[j - 1];
            k[j - 1] = t;
        }
}

/* exterior[6 e + f] = 1 when face f of hex e belongs to no other hex of the model */
static unsigned char *exterior_faces(const fe_model *m)
{
    size_t nf = 6 * (size_t)m->nhex;
    unsigned char *ext = calloc(nf ? nf : 1, 1);
    face_rec *r = malloc(sizeof *r * (nf ? nf : 1));
    if (!ext || !r) {
        free(ext);
        free(r);
        return NULL;
    }
    for (int e = 0; e < m->nhex; e++)
        for (int f = 0; f < 6; f++) {
            face_rec *q = &r[6 * e + f];
            for (int i = 0; i < 4; i++) q->key[i] = m->hex_node[8 * e + hex_face[f][i]];
            sort4(q->key);
            /* tetrahedra, pentahedra (fe_tet.c): distinct nodes, padded; a triangle face then
               matches its neighbour's whichever node is repeated */
            for (int i = 3; i > 0; i--)
                if (q->key[i] == q->key[i - 1]) {
                    for (int j = i; j < 3; j++) q->key[j] = q->key[j + 1];
                    q->key[3] = INT_MAX;
                }
            q->hex = e;
            q->face = f;
        }
    qsort(r, nf, sizeof *r, cmp_face);
    for (size_t i = 0; i < nf;) {
        size_t j = i + 1;
        while (j < nf && cmp_face(&r[i], &r[j]) == 0) j++;
        if (j == i + 1 && r[i].key[2] != INT_MAX) /* collapsed faces (edge, point): none */
            ext[6 * (size_t)r[i].hex + (size_t)r[i].face] = 1;
        i = j;
    }
    free(r);
    return ext;
}

typedef struct {
    fe_contact_model *c;
    int cap_seg, cap_ent;
    unsigned char *ext;    /* exterior hex faces                  */
    unsigned char *mark;   /* scratch per node                    */
    double *shell_ht;      /* half thickness of shells and membranes at a node (ellipsoids) */
    double *plain_ht;      /* half thickness of the (non-membrane) shells at a node */
    double *fabric_t;      /* section thickness of the membranes at a node (0 none) */
} cbuild;

/* contact thickness of a membrane (fabric) of section thickness t in contact d: the key, or
 * the fabric thickness but at least FE_CONTACT_FABRIC_TMIN (docs/fe.md "Contact") [m] */
static double fabric_contact_thickness(const fe_contact_desc *d, double t)
{
    return d->fabric_thickness > 0 ? d->fabric_thickness : fmax(t, FE_CONTACT_FABRIC_TMIN);
}

static int grow_arrays(cbuild *cb, int nseg, int nent)
{
    fe_contact_model *c = cb->c;
    if (nseg > cb->cap_seg) {
        int n = nseg * 2;
        void *p[6] = {realloc(c->seg_node, sizeof(int) * 4 * (size_t)n),
                      realloc(c->seg_part, sizeof(int) * (size_t)n),
                      realloc(c->seg_solid, (size_t)n),
                      realloc(c->seg_ht, sizeof(double) * (size_t)n),
                      realloc(c->seg_k, sizeof(double) * (size_t)n),
                      realloc(c->seg_elem, sizeof(int) * (size_t)n)};
        if (p[0]) c->seg_node = p[0];
        if (p[1]) c->seg_part = p[1];
        if (p[2]) c->seg_solid = p[2];
        if (p[3]) c->seg_ht = p[3];
        if (p[4]) c->seg_k = p[4];
        if (p[5]) c->seg_elem = p[5];
        for (int i = 0; i < 6; i++)
            if (!p[i]) return -1;
        cb->cap_seg = n;
    }
    if (nent > cb->cap_ent) {
        int n = nent * 2;
        void *p[2] = {realloc(c->ent_node, sizeof(int) * (size_t)n),
                      realloc(c->ent_ht, sizeof(double) * (size_t)n)};
        if (p[0]) c->ent_node = p[0];
        if (p[1]) c->ent_ht = p[1];
        for (int i = 0; i < 2; i++)
            if (!p[i]) return -1;
        cb->cap_ent = n;
    }
    return 0;
}

static int in_list(int part, const int *list, int n)
{
    for (int i = 0; i < n; i++)
        if (list[i] == part) return 1;
    return 0;
}

static void set_seg(fe_contact_model *c, int sg, const int nodes[4], int part, int solid,
                    double ht, double k, int elem)
{
    c->seg_elem[sg] = elem;
    memcpy(c->seg_node + 4 * sg, nodes, 4 * sizeof(int));
    c->seg_part[sg] = part;
    c->seg_solid[sg] = (unsigned char)solid;
    c->seg_ht[sg] = ht;
    c->seg_k[sg] = k;
}

/* the key of a face: its nodes sorted, a repeated node dropped (INT_MAX fills) */
static void face_key(const int q[4], int key[4])
{
    memcpy(key, q, 4 * sizeof(int));
    sort4(key);
    for (int i = 3; i > 0; i--)
        if (key[i] == key[i - 1]) {
            for (int j = i; j < 3; j++) key[j] = key[j + 1];
            key[3] = INT_MAX;
        }
}

static int cmp_key(const void *a, const void *b)
{
    const int *x = a, *y = b;
    for (int i = 0; i < 4; i++)
        if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
    return 0;
}

/* a side's face filter: sorted keys of nf faces (NULL when nf is 0: every face) */
typedef struct {
    int n;
    int *key; /* (n x 4) */
} face_filter;

static int face_filter_make(face_filter *f, const int *faces, int nf)
{
    f->n = nf > 0 ? nf : 0;
    f->key = NULL;
    if (f->n == 0) return 0;
    f->key = malloc(sizeof(int) * 4 * (size_t)f->n);
    if (!f->key) return -1;
    for (int i = 0; i < f->n; i++) face_key(faces + 4 * i, f->key + 4 * i);
    qsort(f->key, (size_t)f->n, 4 * sizeof(int), cmp_key);
    return 0;
}

static int face_passes(const face_filter *f, const int q[4])
{
    if (!f || f->n == 0) return 1;
    int key[4];
    face_key(q, key);
    return bsearch(key, f->key, (size_t)f->n, 4 * sizeof(int), cmp_key) != NULL;
}

/* segments of the parts in list: shell elements; exterior faces of hexes; only those in the
 * face filter ff when it has faces */
static mcs_status add_segments(cbuild *cb, const fe_model *m, const int *list, int n,
                               double scale, double tscale, const fe_contact_desc *d,
                               const face_filter *ff, mcs_error *err)
{
    fe_contact_model *c = cb->c;
    for (int ip = 0; ip < m->npart; ip++) {
        if (!in_list(ip, list, n)) continue;
        const fe_part *p = &m->part[ip];
        double K = p->bulk;
        if (!(K > 0))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: contact '%s': part '%s' has no stiffness for the penalty (a null "
                           "material needs a Young's modulus, *MAT_NULL YM)",
                           d->name, p->name);
        for (int e = p->elem_begin; e < p->elem_end; e++) {
            if (p->elem_kind == FE_KIND_SHELL) {
                const int *q = m->shell_node + 4 * e;
                if (!face_passes(ff, q)) continue;
                double xe[4][3], fr[3][3], xl[4], yl[4];
                for (int i = 0; i < 4; i++) memcpy(xe[i], m->node_x0 + 3 * q[i], sizeof xe[i]);
                double A = fe_shell_frame(xe, fr, xl, yl), dmax = 0;
                /* a quad's diagonals; a triangle's (a b c c) sides, so that the two halves
                 * of a split quad get the same stiffness whichever way they are numbered */
                const int tri = q[2] == q[3];
                for (int i = 0; i < (tri ? 3 : 2); i++) {
                    const int j = tri ? (i + 1) % 3 : i + 2;
                    double d[3] = {xe[j][0] - xe[i][0], xe[j][1] - xe[i][1], xe[j][2] - xe[i][2]};
                    dmax = fmax(dmax, sqrt(fe_dot(d, d)));
                }
                if (grow_arrays(cb, c->nseg + 1, 0))
                    return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact segments)");
                /* LS-DYNA shells: k = s K A / max diagonal; fabric at its contact thickness */
                double ht = p->section.type == FE_SECTION_MEMBRANE
                                ? 0.5 * fabric_contact_thickness(d, m->shell_t[e])
                                : 0.5 * tscale * m->shell_t[e];
                set_seg(c, c->nseg++, q, ip, 0, ht, scale * K * A / dmax, m->nhex + e);
            } else if (p->elem_kind == FE_KIND_HEX) {
                double xe[8][3], bb[8][3], aa[8][3];
                const int *h = m->hex_node + 8 * e;
                for (int i = 0; i < 8; i++) memcpy(xe[i], m->node_x0 + 3 * h[i], sizeof xe[i]);
                double V = fe_hex_gradients(xe, bb, aa);
                for (int f = 0; f < 6; f++) {
                    if (!cb->ext[6 * e + f]) continue;
                    int q[4];
                    for (int i = 0; i < 4; i++) q[i] = h[hex_face[f][i]];
                    /* a triangle face (tetrahedra, pentahedra) as a b c c, like shells */
                    for (int r = 0; r < 3 && q[2] != q[3] &&
                                    (q[0] == q[1] || q[1] == q[2] || q[3] == q[0]);
                         r++) {
                        int t = q[0];
                        q[0] = q[1], q[1] = q[2], q[2] = q[3], q[3] = t;
                    }
                    if (!face_passes(ff, q)) continue;
                    double d1[3], d2[3], nn[3];
                    for (int i = 0; i < 3; i++) {
                        d1[i] = m->node_x0[3 * q[2] + i] - m->node_x0[3 * q[0] + i];
                        d2[i] = m->node_x0[3 * q[3] + i] - m->node_x0[3 * q[1] + i];
                    }
                    fe_cross(d1, d2, nn);
                    double A = 0.5 * sqrt(fe_dot(nn, nn));
                    if (grow_arrays(cb, c->nseg + 1, 0))
                        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact segments)");
                    /* LS-DYNA solids: k = s K A^2 / V */
                    set_seg(c, c->nseg++, q, ip, 1, 0, scale * K * A * A / V, e);
                }
            }
        }
    }
    return MCS_OK;
}

/* slave entries: every node with mass of the parts in list (hex parts: surface nodes only);
 * only the nonly nodes of `only` when nonly > 0 */
static mcs_status add_entries(cbuild *cb, const fe_model *m, const int *list, int n,
                              double tscale, const fe_contact_desc *d, const int *only,
                              int nonly, mcs_error *err)
{
    fe_contact_model *c = cb->c;
    memset(cb->mark, 0, (size_t)m->nnode);
    for (int ip = 0; ip < m->npart; ip++) {
        if (!in_list(ip, list, n)) continue;
        const fe_part *p = &m->part[ip];
        for (int e = p->elem_begin; e < p->elem_end; e++) {
            if (p->elem_kind == FE_KIND_SHELL)
                for (int i = 0; i < 4; i++) cb->mark[m->shell_node[4 * e + i]] = 1;
            else if (p->elem_kind == FE_KIND_TRUSS)
                for (int i = 0; i < 2; i++) cb->mark[m->truss_node[2 * e + i]] = 1;
            else
                for (int f = 0; f < 6; f++)
                    if (cb->ext[6 * e + f])
                        for (int i = 0; i < 4; i++)
                            cb->mark[m->hex_node[8 * e + hex_face[f][i]]] = 1;
        }
    }
    for (int i = 0; i < nonly; i++) /* the node filter: 3 marks a node of both */
        if (cb->mark[only[i]]) cb->mark[only[i]] = 3;
    for (int nd = 0; nd < m->nnode; nd++) {
        if (!cb->mark[nd] || (nonly > 0 && cb->mark[nd] != 3) || !(m->node_mass[nd] > 0))
            continue;
        if (grow_arrays(cb, 0, c->nent + 1))
            return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact nodes)");
        c->ent_node[c->nent] = nd;
        /* shells at t/2 (scaled), fabric at half its contact thickness; the larger */
        const double tf = cb->fabric_t[nd];
        c->ent_ht[c->nent] = fmax(tscale * cb->plain_ht[nd],
                                  tf > 0 ? 0.5 * fabric_contact_thickness(d, tf) : 0);
        c->nent++;
    }
    return MCS_OK;
}

static int part_list(const fe_builder *b, const char (*names)[FE_NAME_MAX], int n, int *out)
{
    for (int i = 0; i < n; i++) out[i] = fe_builder_find_part(b, names[i]);
    return n;
}

static mcs_status add_pass(cbuild *cb, const fe_model *m, int iface, int self, int rev, const int *sl,
                           int nsl, const int *ma, int nma, const fe_contact_desc *d,
                           mcs_error *err)
{
    /* the side filters: entries from the slave side (the master side when reversed), segments
     * from the other */
    const int *only = rev ? d->master_node : d->slave_node;
    int nonly = rev ? d->nmaster_node : d->nslave_node;
    const int self_faces = self || rev;
    fe_contact_model *c = cb->c;
    fe_contact_pass *p = &c->pass[c->npass];
    double scale = d->penalty_scale > 0 ? d->penalty_scale : 0.1;
    double tscale = d->thickness_scale > 0 ? d->thickness_scale : 1;
    p->iface = iface;
    p->self = self;
    p->reverse = rev;
    p->ent_begin = c->nent;
    p->seg_begin = c->nseg;
    for (int i = 0; i < nsl + nma; i++) { /* tet10 surfaces are not built (fe_tet10.c) */
        const int ip = i < nsl ? sl[i] : ma[i - nsl];
        if (ip >= 0 && m->part[ip].elem_kind == FE_KIND_TET10)
            return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                           "fe: contact '%s': part '%s' is of tet10 elements, whose contact "
                           "surfaces are not built yet",
                           d->name, m->part[ip].name);
    }
    face_filter ff;
    if (face_filter_make(&ff, self_faces ? d->slave_face : d->master_face,
                         self_faces ? d->nslave_face : d->nmaster_face))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
    mcs_status st = add_entries(cb, m, sl, nsl, tscale, d, only, nonly, err);
    if (!st) st = add_segments(cb, m, ma, nma, scale, tscale, d, &ff, err);
    free(ff.key);
    p->ent_end = c->nent;
    p->seg_end = c->nseg;
    c->npass++;
    return st;
}

/* nodes sharing an element with each node (itself included), CSR */
static mcs_status build_neighbours(fe_contact_model *c, const fe_model *m, mcs_error *err)
{
    const int *conn[FE_NKIND] = {m->hex_node, m->shell_node, m->truss_node, m->tet10_node};
    const int nel[FE_NKIND] = {m->nhex, m->nshell, m->ntruss, m->ntet10};
    const int nn[FE_NKIND] = {8, 4, 2, 10};
    c->nbr_off = calloc((size_t)m->nnode + 1, sizeof(int));
    if (!c->nbr_off) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
    for (int k = 0; k < FE_NKIND; k++)
        for (int e = 0; e < nel[k]; e++)
            for (int i = 0; i < nn[k]; i++) c->nbr_off[conn[k][nn[k] * e + i] + 1] += nn[k];
    for (int n = 0; n < m->nnode; n++) c->nbr_off[n + 1] += c->nbr_off[n];
    int tot = c->nbr_off[m->nnode];
    c->nbr = malloc(sizeof(int) * (size_t)(tot ? tot : 1));
    int *fill = calloc((size_t)m->nnode + 1, sizeof(int));
    if (!c->nbr || !fill) {
        free(fill);
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
    }
    for (int k = 0; k < FE_NKIND; k++)
        for (int e = 0; e < nel[k]; e++)
            for (int i = 0; i < nn[k]; i++) {
                int a = conn[k][nn[k] * e + i];
                for (int j = 0; j < nn[k]; j++)
                    c->nbr[c->nbr_off[a] + fill[a]++] = conn[k][nn[k] * e + j];
            }
    /* compact: drop repeats in place, keeping the offsets valid */
    int w = 0;
    for (int n = 0; n < m->nnode; n++) {
        int b0 = c->nbr_off[n], b1 = c->nbr_off[n + 1], start = w;
        for (int j = b0; j < b1; j++) {
            int v = c->nbr[j], dup = 0;
            for (int q = start; q < w && !dup; q++) dup = c->nbr[q] == v;
            if (!dup) c->nbr[w++] = v;
        }
        c->nbr_off[n] = start;
    }
    c->nbr_off[m->nnode] = w;
    free(fill);
    /* give back what the repeats took */
    int *nb = realloc(c->nbr, sizeof(int) * (size_t)(w ? w : 1));
    if (nb) c->nbr = nb;
    c->bytes += sizeof(int) * ((size_t)m->nnode + 1 + (size_t)w);
    return MCS_OK;
}

void fe_contact_quat_to_R(const double q0[4], double R[9])
{
    double q[4] = {q0[0], q0[1], q0[2], q0[3]};
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(n > 0)) q[0] = 1, q[1] = q[2] = q[3] = 0, n = 1;
    for (int i = 0; i < 4; i++) q[i] /= n;
    double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}

/* the body law of ellipsoid E from its descriptor (docs/contracts.md "Soft body surfaces in
 * bodies contacts") */
static mcs_status build_law(const fe_body_law_desc *d, fe_contact_ellipsoid *E, mcs_error *err)
{
    if (d->n == 0) return MCS_OK;
    mcs_error e2 = {0};
    mcs_status st = mcs_curve_create(E->name, d->n, d->x, d->y, MCS_EXTRAP_LINEAR,
                                     MCS_EXTRAP_LINEAR, &E->law_curve, &e2);
    if (st) return MCS_ERR(err, st, "fe: ellipsoid '%s': body law: %s", E->name, e2.msg);
    E->law = (mcs_hyst_model){.loading = E->law_curve, .unload = MCS_UNLOAD_ELASTIC,
                              .elastic_limit = INFINITY};
    if (d->unload_slope > 0) {
        E->law.unload = MCS_UNLOAD_SLOPE;
        E->law.unload_slope = d->unload_slope;
        E->law.elastic_limit = d->elastic_limit;
    }
    st = mcs_hyst_model_check(&E->law, E->name, &e2);
    if (st) return MCS_ERR(err, st, "fe: ellipsoid '%s': body law: %s", E->name, e2.msg);
    return MCS_OK;
}

/* the body laws' surface faces of each node: the exterior hex faces (tetrahedra, pentahedra:
 * their padded faces) and the shell elements (two-sided), CSR (fe_contact_node_area) */
static mcs_status build_node_faces(fe_contact_model *c, const fe_model *m,
                                   const unsigned char *ext, mcs_error *err)
{
    c->area_off = calloc((size_t)m->nnode + 1, sizeof(int));
    if (!c->area_off) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
    for (int pass = 0; pass < 2; pass++) {
        int *fill = NULL;
        if (pass == 1) {
            for (int n = 0; n < m->nnode; n++) c->area_off[n + 1] += c->area_off[n];
            c->area_face = malloc(sizeof *c->area_face * (size_t)(c->area_off[m->nnode] + 1));
            fill = calloc((size_t)m->nnode + 1, sizeof(int));
            if (!c->area_face || !fill) {
                free(fill);
                return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
            }
        }
        for (int e = 0; e < m->nhex + m->nshell; e++) {
            const int hex = e < m->nhex, el = hex ? e : e - m->nhex;
            for (int f = 0; f < (hex ? 6 : 1); f++) {
                if (hex && !ext[6 * el + f]) continue;
                int q[5];
                for (int i = 0; i < 4; i++)
                    q[i] = hex ? m->hex_node[8 * el + hex_face[f][i]] : m->shell_node[4 * el + i];
                q[4] = !hex;
                for (int i = 0; i < 4; i++) {
                    int dup = 0;
                    for (int j = 0; j < i; j++) dup |= q[j] == q[i];
                    if (dup) continue;
                    if (pass == 0) c->area_off[q[i] + 1]++;
                    else memcpy(c->area_face[c->area_off[q[i]] + fill[q[i]]++], q, sizeof q);
                }
            }
        }
        free(fill);
    }
    c->bytes += sizeof(int) * ((size_t)m->nnode + 1 + 5 * (size_t)c->area_off[m->nnode]);
    return MCS_OK;
}

double fe_contact_node_area(const fe_model *m, const fe_state *s, int n, const double dir[3])
{
    const fe_contact_model *c = m->contact;
    const double *X = s->node_x;
    double A = 0;
    for (int k = c->area_off[n]; k < c->area_off[n + 1]; k++) {
        const int *q = c->area_face[k];
        int nu = 0;
        for (int i = 0; i < 4; i++) {
            int dup = 0;
            for (int j = 0; j < i; j++) dup |= q[j] == q[i];
            nu += !dup;
        }
        if (nu < 3) continue;
        double d1[3], d2[3], a[3];
        for (int k2 = 0; k2 < 3; k2++) {
            d1[k2] = X[3 * q[2] + k2] - X[3 * q[0] + k2];
            d2[k2] = X[3 * q[3] + k2] - X[3 * q[1] + k2];
        }
        fe_cross(d1, d2, a); /* twice the vector area (outward for a hex face) */
        const double an = -0.5 * fe_dot(a, dir) / nu;
        A += q[4] ? fabs(an) : fmax(an, 0);
    }
    return A;
}

static mcs_status build_ellipsoids(const fe_builder *b, fe_contact_model *c, const fe_model *m,
                                   unsigned char *mark, const double *shell_ht, mcs_error *err)
{
    c->nell = b->nellipsoid;
    c->ell = calloc((size_t)(c->nell ? c->nell : 1), sizeof *c->ell);
    c->ell_node = malloc(sizeof(int) * (size_t)(c->nell ? c->nell : 1) * (size_t)m->nnode);
    c->ell_ht = malloc(sizeof(double) * (size_t)(c->nell ? c->nell : 1) * (size_t)m->nnode);
    if (!c->ell || !c->ell_node || !c->ell_ht)
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
    unsigned char *mk = malloc((size_t)m->nnode);
    if (!mk) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
    for (int i = 0; i < c->nell; i++) {
        const fe_ellipsoid_desc *d = &b->ellipsoid[i];
        fe_contact_ellipsoid *E = &c->ell[i];
        memcpy(E->name, d->name, FE_NAME_MAX);
        memcpy(E->center, d->center, sizeof E->center);
        memcpy(E->semi, d->semi_axes, sizeof E->semi);
        memcpy(E->velocity, d->velocity, sizeof E->velocity);
        fe_contact_quat_to_R(d->orientation, E->R);
        E->scale = d->penalty_scale > 0 ? d->penalty_scale : 0.1;
        E->mu = d->friction;
        mcs_status st = build_law(&d->law, E, err);
        if (st) {
            free(mk);
            return st;
        }
        memset(mark, d->nparts ? 0 : 1, (size_t)m->nnode);
        for (int j = 0; j < d->nparts; j++) {
            fe_builder_part_nodes(b, fe_builder_find_part(b, d->parts[j]), mk);
            for (int n = 0; n < m->nnode; n++) mark[n] |= mk[n];
        }
        E->node_begin = c->nell_node;
        for (int n = 0; n < m->nnode; n++)
            if (mark[n] && m->node_mass[n] > 0) {
                c->ell_ht[c->nell_node] = shell_ht[n]; /* shells meet it at t/2 */
                c->ell_node[c->nell_node++] = n;
            }
        E->node_end = c->nell_node;
    }
    free(mk);
    int *en = realloc(c->ell_node, sizeof(int) * (size_t)(c->nell_node ? c->nell_node : 1));
    if (en) c->ell_node = en;
    return MCS_OK;
}

/* nodes any contact touches (slaves, segment nodes, ellipsoid nodes) */
static mcs_status build_touch(fe_contact_model *c, const fe_model *m, unsigned char *mark,
                              mcs_error *err)
{
    memset(mark, 0, (size_t)m->nnode);
    for (int e = 0; e < c->nent; e++) mark[c->ent_node[e]] = 1;
    for (int s = 0; s < 4 * c->nseg; s++) mark[c->seg_node[s]] = 1;
    for (int i = 0; i < c->nell_node; i++) mark[c->ell_node[i]] = 1;
    for (int i = 0; i < c->nfac_node; i++) mark[c->fac_node[i]] = 1;
    c->touch = malloc(sizeof(int) * (size_t)(m->nnode ? m->nnode : 1));
    if (!c->touch) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
    for (int n = 0; n < m->nnode; n++)
        if (mark[n] && m->node_mass[n] > 0) c->touch[c->nnode_touch++] = n;
    int *t = realloc(c->touch, sizeof(int) * (size_t)(c->nnode_touch ? c->nnode_touch : 1));
    if (t) c->touch = t;
    return MCS_OK;
}

static void search_margin(fe_contact_model *c, const fe_model *m)
{
    double sum = 0;
    long cnt = 0;
    for (int s = 0; s < c->nseg; s++)
        for (int i = 0; i < 4; i++) {
            int a = c->seg_node[4 * s + i], b = c->seg_node[4 * s + (i + 1) % 4];
            if (a == b) continue;
            double d[3];
            for (int k = 0; k < 3; k++) d[k] = m->node_x0[3 * b + k] - m->node_x0[3 * a + k];
            sum += sqrt(fe_dot(d, d));
            cnt++;
        }
    /* half the mean edge: a few hundred steps between searches at crash speeds */
    c->margin = cnt ? 0.5 * sum / (double)cnt : 0;
}

void fe_contact_model_free(fe_model *m)
{
    fe_contact_model *c = m->contact;
    if (!c) return;
    free(c->iface), free(c->pass), free(c->seg_node), free(c->seg_part), free(c->seg_solid);
    free(c->seg_ht), free(c->seg_k), free(c->seg_elem);
    free(c->ent_node), free(c->ent_ht), free(c->nbr_off), free(c->nbr);
    for (int i = 0; c->ell && i < c->nell; i++) mcs_curve_destroy(&c->ell[i].law_curve);
    free(c->touch), free(c->ell), free(c->ell_node), free(c->ell_ht), free(c->area_off);
    free(c->area_face);
    fe_contact_facets_free(c);
    free(c);
    m->contact = NULL;
}

mcs_status fe_contact_model_build(const fe_builder *b, fe_model *m, mcs_error *err)
{
    if (b->ncontact == 0 && b->nellipsoid == 0 && b->nfacets == 0) return MCS_OK;
    fe_contact_model *c = calloc(1, sizeof *c);
    if (!c) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
    m->contact = c;
    cbuild cb = {.c = c};
    c->iface = calloc((size_t)(b->ncontact ? b->ncontact : 1), sizeof *c->iface);
    c->pass = calloc(2 * (size_t)(b->ncontact ? b->ncontact : 1), sizeof *c->pass);
    cb.ext = exterior_faces(m);
    cb.mark = malloc((size_t)m->nnode);
    cb.shell_ht = calloc((size_t)m->nnode, sizeof(double));
    cb.plain_ht = calloc((size_t)m->nnode, sizeof(double));
    cb.fabric_t = calloc((size_t)m->nnode, sizeof(double));
    mcs_status st = MCS_OK;
    if (!c->iface || !c->pass || !cb.ext || !cb.mark || !cb.shell_ht || !cb.plain_ht ||
        !cb.fabric_t || grow_arrays(&cb, 1, 1))
        st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact)");
    for (int e = 0; e < m->nshell && !st; e++) {
        const fe_section_desc *sec = &m->part[m->shell_part[e]].section;
        const int fabric = sec->type == FE_SECTION_MEMBRANE;
        double ht = 0.5 * m->shell_t[e];
        for (int i = 0; i < 4; i++) {
            const int nd = m->shell_node[4 * e + i];
            cb.shell_ht[nd] = fmax(cb.shell_ht[nd], ht);
            if (fabric) cb.fabric_t[nd] = fmax(cb.fabric_t[nd], m->shell_t[e]);
            else cb.plain_ht[nd] = fmax(cb.plain_ht[nd], ht);
        }
    }
    int any_self = 0;
    for (int i = 0; i < b->ncontact && !st; i++) {
        const fe_contact_desc *d = &b->contact[i];
        fe_contact_if *I = &c->iface[c->nif++];
        memcpy(I->name, d->name, FE_NAME_MAX);
        I->mu_s = d->friction;
        I->mu_d = d->friction_dynamic >= 0 ? d->friction_dynamic : d->friction;
        I->decay = d->friction_decay;
        I->damping = d->damping;
        I->birth = d->birth, I->death = d->death;
        int sl[FE_CONTACT_PARTS], ma[FE_CONTACT_PARTS];
        int nsl = part_list(b, d->slave, d->nslave, sl), nma = part_list(b, d->master, d->nmaster, ma);
        if (d->type == FE_CONTACT_SINGLE_SURFACE) {
            st = add_pass(&cb, m, i, 1, 0, sl, nsl, sl, nsl, d, err);
            any_self = 1;
        } else {
            st = add_pass(&cb, m, i, 0, 0, sl, nsl, ma, nma, d, err);
            if (!st && d->type == FE_CONTACT_TWO_SURFACE)
                st = add_pass(&cb, m, i, 0, 1, ma, nma, sl, nsl, d, err);
        }
    }
    if (!st && any_self) st = build_neighbours(c, m, err);
    if (!st) st = build_ellipsoids(b, c, m, cb.mark, cb.shell_ht, err);
    for (int i = 0; i < c->nell && !st; i++)
        if (c->ell[i].law_curve && !c->area_off) st = build_node_faces(c, m, cb.ext, err);
    if (!st) st = fe_contact_facets_build(b, c, m, cb.mark, cb.shell_ht, err);
    if (!st) st = build_touch(c, m, cb.mark, err);
    if (!st) {
        search_margin(c, m);
        c->k_cap = FE_CONTACT_KCAP;
        c->dt0 = m->dt_initial;
        c->bytes += sizeof *c + sizeof *c->iface * (size_t)c->nif +
                    sizeof *c->pass * (size_t)c->npass +
                    (size_t)c->nseg * (4 * sizeof(int) + 2 * sizeof(int) + 1 + 2 * sizeof(double)) +
                    (size_t)c->nent * (sizeof(int) + sizeof(double)) +
                    sizeof(int) * ((size_t)c->nnode_touch + (size_t)c->nell_node) +
                    sizeof(double) * (size_t)c->nell_node +
                    sizeof *c->ell * (size_t)c->nell;
        m->bytes += c->bytes;
    }
    free(cb.ext);
    free(cb.mark);
    free(cb.shell_ht);
    free(cb.plain_ht);
    free(cb.fabric_t);
    if (st) fe_contact_model_free(m);
    return st;
}

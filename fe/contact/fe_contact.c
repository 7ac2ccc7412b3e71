/* fe_contact: the contact sub-stage (penalty node-to-segment and rigid ellipsoids), its
 * state and its energy bookkeeping. See fe_contact.h and docs/fe.md "Contact".
 *
 * Phase 1 (each slave entry on its own, writing only its own slots): find the segments within
 * contact distance in the node's bucket, keep the deepest and the deepest on the other side
 * (a node pinched between two layers), penalty normal force and friction. Phase 2 (serial):
 * scatter each slot's force to the slave node and, with the nearest point's weights, to the
 * segment nodes; energies per part and per interface. Phase 3: the ellipsoids (a node's force
 * depends on the node only). Then node_fc goes into node_fext and the contact-force work is
 * summed with the integrator's trapezoidal weights, so fe_stable_step can take it out of the
 * external work: total energy then checks contact energy = -(work of the contact forces). */
#include "fe/fe_contact_impl.h"
#include "fe/fe_elem.h"
#include "fe/fe_parallel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define FE_CONTACT_HITS 16 /* segments within contact distance kept per node per step */
#define FE_CONTACT_OMP_MIN 1024 /* fewer slave entries: one thread (a parallel region costs more) */

void fe_contact_state_destroy(fe_contact_state **p)
{
    if (!p || !*p) return;
    fe_contact_state *c = *p;
    free(c->x_ref), free(c->seg_box), free(c->cell_off), free(c->cell_item);
    free(c->pass_hash), free(c->pass_cell_base), free(c->pass_cell), free(c->ent_cand);
    free(c->ent_cand_off), free(c->ent_flag), free(c->live), free(c->slot);
    free(c->ent_ft), free(c->ent_et), free(c->ell_ft), free(c->ell_et), free(c->ell_law);
    free(c->node_fc), free(c->part_fric), free(c->part_elastic), free(c->if_force);
    free(c->if_energy), free(c->if_fric), free(c->ell_c), free(c->ell_R), free(c->ell_v);
    free(c->ell_force), free(c->ell_w), free(c->ell_vl), free(c->ell_moment), free(c->ell_work);
    free(c->fac_c), free(c->fac_R), free(c->fac_v), free(c->fac_w), free(c->fac_vl);
    free(c->fac_force), free(c->fac_moment), free(c->fac_work), free(c->fac_ft), free(c->fac_et);
    free(c->fac_side), free(c->ell_cand), free(c->ell_ncand), free(c->ell_cref);
    free(c->fac_cand), free(c->fac_ncand), free(c->fac_cref);
    free(c->rec_live), free(c->q_rec0), free(c->q_nrec), free(c->q_done), free(c->pow_chunk);
    free(c);
    *p = NULL;
}

static void *zalloc(size_t n, size_t sz, size_t *bytes)
{
    *bytes += n * sz;
    return calloc(n ? n : 1, sz);
}

mcs_status fe_contact_state_create(const fe_model *m, fe_contact_state **out, mcs_error *err)
{
    const fe_contact_model *c = m->contact;
    *out = NULL;
    fe_contact_state *s = calloc(1, sizeof *s);
    if (!s) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact state)");
    size_t b = sizeof *s, ncell = 0;
    s->pass_hash = zalloc((size_t)c->npass, sizeof(int), &b);
    s->pass_cell_base = zalloc((size_t)c->npass, sizeof(int), &b);
    if (s->pass_hash && s->pass_cell_base)
        for (int p = 0; p < c->npass; p++) {
            s->pass_hash[p] = fe_contact_hash_size(c, p);
            s->pass_cell_base[p] = (int)ncell;
            ncell += (size_t)s->pass_hash[p] + 1;
        }
    size_t ne = (size_t)c->nent, ne2 = 2 * ne, nseg = (size_t)c->nseg;
    s->cand_cap = FE_CONTACT_CAND * c->nent;
    s->slot_cap = c->nent / FE_CONTACT_LIVE + 1;
    s->pass_cell = zalloc(4 * (size_t)c->npass, sizeof(double), &b);
    s->x_ref = zalloc(3 * (size_t)c->nnode_touch, sizeof(float), &b);
    s->seg_box = zalloc(6 * nseg, sizeof(float), &b);
    s->cell_off = zalloc(ncell, sizeof(int), &b);
    s->cell_item = zalloc(nseg, sizeof(int), &b);
    s->ent_cand_off = zalloc(ne + 1, sizeof(int), &b);
    s->ent_cand = zalloc((size_t)s->cand_cap, sizeof(int), &b);
    s->ent_flag = zalloc(ne, 1, &b);
    s->live = zalloc(ne, sizeof(int), &b);
    s->slot = zalloc(2 * (size_t)s->slot_cap, sizeof(fe_contact_slot), &b);
    s->ent_ft = zalloc(3 * ne2, sizeof(double), &b);
    s->ent_et = zalloc(ne2, sizeof(double), &b);
    s->ell_ft = zalloc(3 * (size_t)c->nell_node, sizeof(double), &b);
    s->ell_et = zalloc((size_t)c->nell_node, sizeof(double), &b);
    s->ell_law = zalloc((size_t)c->nell_node, sizeof(fe_body_law_node), &b);
    s->node_fc = zalloc(3 * (size_t)m->nnode, sizeof(double), &b);
    s->part_fric = zalloc((size_t)m->npart, sizeof(double), &b);
    s->part_elastic = zalloc((size_t)m->npart, sizeof(double), &b);
    s->if_force = zalloc(3 * (size_t)c->nif, sizeof(double), &b);
    s->if_energy = zalloc((size_t)c->nif, sizeof(double), &b);
    s->if_fric = zalloc((size_t)c->nif, sizeof(double), &b);
    s->ell_c = zalloc(3 * (size_t)c->nell, sizeof(double), &b);
    s->ell_R = zalloc(9 * (size_t)c->nell, sizeof(double), &b);
    s->ell_v = zalloc(3 * (size_t)c->nell, sizeof(double), &b);
    s->ell_force = zalloc(3 * (size_t)c->nell, sizeof(double), &b);
    const size_t nl = (size_t)c->nell, nf = (size_t)c->nfac, nfn = (size_t)c->nfac_node;
    s->ell_w = zalloc(3 * nl, sizeof(double), &b);
    s->ell_vl = zalloc(6 * nl, sizeof(double), &b);
    s->ell_moment = zalloc(3 * nl, sizeof(double), &b);
    s->ell_work = zalloc(nl, sizeof(double), &b);
    s->fac_c = zalloc(3 * nf, sizeof(double), &b);
    s->fac_R = zalloc(9 * nf, sizeof(double), &b);
    s->fac_v = zalloc(3 * nf, sizeof(double), &b);
    s->fac_w = zalloc(3 * nf, sizeof(double), &b);
    s->fac_vl = zalloc(6 * nf, sizeof(double), &b);
    s->fac_force = zalloc(3 * nf, sizeof(double), &b);
    s->fac_moment = zalloc(3 * nf, sizeof(double), &b);
    s->fac_work = zalloc(nf, sizeof(double), &b);
    s->fac_ft = zalloc(3 * nfn, sizeof(double), &b);
    s->fac_et = zalloc(nfn, sizeof(double), &b);
    s->fac_side = zalloc(nfn, 1, &b);
    s->ell_cand = zalloc((size_t)c->nell_node, sizeof(int), &b);
    s->ell_ncand = zalloc(nl, sizeof(int), &b);
    s->ell_cref = zalloc(4 * nl, sizeof(double), &b);
    s->fac_cand = zalloc(nfn, sizeof(int), &b);
    s->fac_ncand = zalloc(nf, sizeof(int), &b);
    s->fac_cref = zalloc(4 * nf, sizeof(double), &b);
    const size_t nq = (ne + FE_CONTACT_LIVE_CHUNK - 1) / FE_CONTACT_LIVE_CHUNK;
    s->rec_live = zalloc((size_t)s->slot_cap, sizeof(int), &b);
    s->q_rec0 = zalloc(nq, sizeof(int), &b);
    s->q_nrec = zalloc(nq, sizeof(int), &b);
    s->q_done = zalloc(nq, sizeof(int), &b);
    s->pow_chunk = zalloc((size_t)m->nnode_chunk, sizeof(double), &b);
    s->bytes = b;
    if (!s->pass_hash || !s->pass_cell_base || !s->pass_cell || !s->x_ref || !s->seg_box ||
        !s->cell_off || !s->cell_item || !s->ent_cand_off || !s->ent_cand || !s->ent_flag ||
        !s->live || !s->slot || !s->ent_ft || !s->ent_et || !s->ell_ft || !s->ell_et ||
        !s->ell_law ||
        !s->node_fc || !s->part_fric || !s->part_elastic || !s->if_force || !s->if_energy ||
        !s->if_fric || !s->ell_c || !s->ell_R || !s->ell_v || !s->ell_force || !s->ell_w ||
        !s->ell_vl || !s->ell_moment || !s->ell_work || !s->fac_c || !s->fac_R || !s->fac_v ||
        !s->fac_w || !s->fac_vl || !s->fac_force || !s->fac_moment || !s->fac_work ||
        !s->fac_ft || !s->fac_et || !s->fac_side || !s->ell_cand || !s->ell_ncand ||
        !s->ell_cref || !s->fac_cand || !s->fac_ncand || !s->fac_cref || !s->rec_live ||
        !s->q_rec0 || !s->q_nrec || !s->q_done || !s->pow_chunk) {
        fe_contact_state_destroy(&s);
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (contact state)");
    }
    fe_contact_state_reset(m, s);
    *out = s;
    return MCS_OK;
}

void fe_contact_state_reset(const fe_model *m, fe_contact_state *s)
{
    const fe_contact_model *c = m->contact;
    size_t ne2 = 2 * (size_t)c->nent;
    memset(s->ent_flag, 0, (size_t)c->nent);
    memset(s->ent_cand_off, 0, ((size_t)c->nent + 1) * sizeof(int));
    s->nlive = 0;
    memset(s->ent_ft, 0, 3 * ne2 * sizeof(double));
    memset(s->ent_et, 0, ne2 * sizeof(double));
    memset(s->ell_ft, 0, 3 * (size_t)c->nell_node * sizeof(double));
    memset(s->ell_et, 0, (size_t)c->nell_node * sizeof(double));
    memset(s->ell_law, 0, (size_t)c->nell_node * sizeof(fe_body_law_node));
    for (int i = 0; i < c->nell; i++)
        for (int j = c->ell[i].node_begin; c->ell[i].law_curve && j < c->ell[i].node_end; j++)
            mcs_hyst_reset(&c->ell[i].law, &s->ell_law[j].h);
    memset(s->node_fc, 0, 3 * (size_t)m->nnode * sizeof(double));
    memset(s->part_fric, 0, (size_t)m->npart * sizeof(double));
    memset(s->part_elastic, 0, (size_t)m->npart * sizeof(double));
    memset(s->if_force, 0, 3 * (size_t)c->nif * sizeof(double));
    memset(s->if_energy, 0, (size_t)c->nif * sizeof(double));
    memset(s->if_fric, 0, (size_t)c->nif * sizeof(double));
    memset(s->ell_force, 0, 3 * (size_t)c->nell * sizeof(double));
    memset(s->ell_moment, 0, 3 * (size_t)c->nell * sizeof(double));
    memset(s->ell_w, 0, 3 * (size_t)c->nell * sizeof(double));
    memset(s->ell_vl, 0, 6 * (size_t)c->nell * sizeof(double));
    memset(s->ell_work, 0, (size_t)c->nell * sizeof(double));
    for (int i = 0; i < c->nell; i++) {
        memcpy(s->ell_c + 3 * i, c->ell[i].center, 3 * sizeof(double));
        memcpy(s->ell_R + 9 * i, c->ell[i].R, 9 * sizeof(double));
        memcpy(s->ell_v + 3 * i, c->ell[i].velocity, 3 * sizeof(double));
        memcpy(s->ell_vl + 6 * i, c->ell[i].velocity, 3 * sizeof(double));
    }
    const size_t nf = (size_t)c->nfac, nfn = (size_t)c->nfac_node;
    memset(s->fac_v, 0, 3 * nf * sizeof(double));
    memset(s->fac_w, 0, 3 * nf * sizeof(double));
    memset(s->fac_vl, 0, 6 * nf * sizeof(double));
    memset(s->fac_force, 0, 3 * nf * sizeof(double));
    memset(s->fac_moment, 0, 3 * nf * sizeof(double));
    memset(s->fac_work, 0, nf * sizeof(double));
    memset(s->fac_ft, 0, 3 * nfn * sizeof(double));
    memset(s->fac_et, 0, nfn * sizeof(double));
    memset(s->fac_side, 0, nfn);
    /* no candidates yet: the first step makes the lists */
    s->travel = 0;
    for (int i = 0; i < c->nell; i++) s->ell_cref[4 * i + 3] = -INFINITY;
    for (int i = 0; i < c->nfac; i++) s->fac_cref[4 * i + 3] = -INFINITY;
    for (int i = 0; i < c->nfac; i++) {
        memcpy(s->fac_c + 3 * i, c->fac[i].center, 3 * sizeof(double));
        memcpy(s->fac_R + 9 * i, c->fac[i].R, 9 * sizeof(double));
    }
    s->work_nodes = s->work_bodies = s->dth_prev = s->pen_max = s->energy = 0;
    s->nrebuild = 0;
    s->need_rebuild = 1;
}

static void set_pose(double *C, double *Rs, double *V, double *W, const double c[3],
                     const double R[9], const double v[3], const double w[3])
{
    memcpy(C, c, 3 * sizeof(double));
    if (R) memcpy(Rs, R, 9 * sizeof(double));
    memcpy(V, v, 3 * sizeof(double));
    for (int k = 0; k < 3; k++) W[k] = w ? w[k] : 0;
}

void fe_contact_set_ellipsoid(const fe_model *m, fe_state *s, int i, const double c[3],
                              const double R[9], const double v[3], const double w[3])
{
    if (!m->contact || !s->contact || i < 0 || i >= m->contact->nell) return;
    fe_contact_state *cs = s->contact;
    set_pose(cs->ell_c + 3 * i, cs->ell_R + 9 * i, cs->ell_v + 3 * i, cs->ell_w + 3 * i, c, R,
             v, w);
}

void fe_contact_set_facets(const fe_model *m, fe_state *s, int i, const double c[3],
                           const double R[9], const double v[3], const double w[3])
{
    if (!m->contact || !s->contact || i < 0 || i >= m->contact->nfac) return;
    fe_contact_state *cs = s->contact;
    set_pose(cs->fac_c + 3 * i, cs->fac_R + 9 * i, cs->fac_v + 3 * i, cs->fac_w + 3 * i, c, R,
             v, w);
}

/* ---- phase 1: one slave entry ------------------------------------------------------------ */

typedef struct {
    double gap, dir[3], w[4];
    int seg;
} hit;

/* gap of node x to segment sg (< 0 in contact), direction pushing the node out, weights */
static int seg_gap(const fe_model *m, const double *X, int sg, const double x[3], double ht,
                   hit *h)
{
    const fe_contact_model *c = m->contact;
    const int *q = c->seg_node + 4 * sg;
    const double *a = X + 3 * q[0], *b = X + 3 * q[1], *cc = X + 3 * q[2], *d = X + 3 * q[3];
    /* a shell touches only within the offset: a node farther than that from the segment's
     * box is out (the usual case for a candidate; saves the two triangle projections) */
    if (!c->seg_solid[sg]) {
        const double off = ht + c->seg_ht[sg];
        for (int i = 0; i < 3; i++) {
            const double l1 = a[i] < b[i] ? a[i] : b[i], l2 = cc[i] < d[i] ? cc[i] : d[i];
            const double h1 = a[i] > b[i] ? a[i] : b[i], h2 = cc[i] > d[i] ? cc[i] : d[i];
            if (x[i] < (l1 < l2 ? l1 : l2) - off || x[i] > (h1 > h2 ? h1 : h2) + off) return 0;
        }
    }
    double w1[3], w2[3] = {0, 0, 0};
    double d1 = fe_tri_nearest(x, a, b, cc, w1), d2 = INFINITY;
    if (q[3] != q[2]) d2 = fe_tri_nearest(x, a, cc, d, w2);
    if (d2 < d1) {
        h->w[0] = w2[0], h->w[1] = 0, h->w[2] = w2[1], h->w[3] = w2[2];
        d1 = d2;
    } else {
        h->w[0] = w1[0], h->w[1] = w1[1], h->w[2] = w1[2], h->w[3] = 0;
    }
    double off = ht + c->seg_ht[sg], dist = sqrt(d1), p[3], r[3];
    if (dist - off >= 0 && !c->seg_solid[sg]) return 0;
    for (int i = 0; i < 3; i++) {
        p[i] = h->w[0] * a[i] + h->w[1] * b[i] + h->w[2] * cc[i] + h->w[3] * d[i];
        r[i] = x[i] - p[i];
    }
    double e1[3], e2[3], n[3];
    for (int i = 0; i < 3; i++) e1[i] = cc[i] - a[i], e2[i] = d[i] - b[i];
    if (q[3] == q[2])
        for (int i = 0; i < 3; i++) e2[i] = cc[i] - b[i], e1[i] = b[i] - a[i];
    fe_cross(e1, e2, n);
    double nn = sqrt(fe_dot(n, n));
    if (!(nn > 0)) return 0;
    for (int i = 0; i < 3; i++) n[i] /= nn;
    double sn = fe_dot(r, n);
    if (c->seg_solid[sg]) {
        /* one-sided: outside along the outward normal, inside down to the depth limit */
        if (sn >= 0) {
            h->gap = dist - off;
            for (int i = 0; i < 3; i++) h->dir[i] = dist > 0 ? r[i] / dist : n[i];
        } else {
            /* inside only where the node projects onto the face: beyond an edge the node
             * belongs to the neighbouring face (coplanar sides of two blocks touch there) */
            if (-sn < 0.7 * dist) return 0;
            h->gap = -dist - off;
            if (h->gap < -fe_contact_seg_depth(c, m, sg)) return 0;
            for (int i = 0; i < 3; i++) h->dir[i] = n[i];
        }
    } else {
        /* two-sided shell: pushed away from the mid-surface on the side it is */
        h->gap = dist - off;
        double sg_ = sn >= 0 ? 1 : -1;
        for (int i = 0; i < 3; i++) h->dir[i] = dist > 1e-12 * off ? r[i] / dist : sg_ * n[i];
    }
    h->seg = sg;
    return h->gap < 0;
}

/* the contact of entry e this step: its two slots' results in r[2], friction history kept */
static void entry_forces(const fe_model *m, fe_state *s, int e, fe_contact_slot r[2])
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    const int node = c->ent_node[e], p = fe_contact_ent_pass(c, e);
    const fe_contact_pass *P = &c->pass[p];
    const fe_contact_if *I = &c->iface[P->iface];
    const double *x = s->node_x + 3 * node;
    hit hits[FE_CONTACT_HITS];
    int nh = 0, bk[27], nb = 1;
    const int scan = cs->ent_flag[e] & FE_CFLAG_SCAN;
    const int *off = cs->cell_off + cs->pass_cell_base[p];
    if (scan) nb = fe_contact_buckets(cs, p, x, bk); /* too many candidates to keep */
    /* before its birth or after its death the interface finds nothing (its nodes released) */
    if (s->time < I->birth || (I->death > 0 && s->time > I->death)) nb = 0;
    for (int ib = 0; ib < nb; ib++) {
        const int *item = scan ? cs->cell_item : cs->ent_cand;
        const int b0 = scan ? off[bk[ib]] + P->seg_begin : cs->ent_cand_off[e];
        const int b1 = scan ? off[bk[ib] + 1] + P->seg_begin : cs->ent_cand_off[e + 1];
        for (int k = b0; k < b1; k++) {
            int sg = item[k];
            if (!fe_contact_in_box(cs->seg_box + 6 * sg, x)) continue;
            if (fe_contact_seg_gone(m, s, sg)) continue; /* eroded */
            const int *q = c->seg_node + 4 * sg;
            /* a bucket also holds the node's own segments and (self contact) its
             * neighbours', which its candidate list already left out */
            if (scan && (q[0] == node || q[1] == node || q[2] == node || q[3] == node ||
                         (P->self && fe_contact_seg_has_nbr(c, q, node))))
                continue;
            hit h;
            if (!seg_gap(m, s->node_x, sg, x, c->ent_ht[e], &h)) continue;
            if (nh < FE_CONTACT_HITS) hits[nh++] = h;
            else { /* keep the deepest */
                int wmax = 0;
                for (int i = 1; i < nh; i++)
                    if (hits[i].gap > hits[wmax].gap) wmax = i;
                if (h.gap < hits[wmax].gap) hits[wmax] = h;
            }
        }
    }
    /* slot 0: deepest; slot 1: deepest of those pushing the other way */
    int best[2] = {-1, -1};
    for (int i = 0; i < nh; i++)
        if (best[0] < 0 || hits[i].gap < hits[best[0]].gap) best[0] = i;
    for (int i = 0; i < nh && best[0] >= 0; i++)
        if (fe_dot(hits[i].dir, hits[best[0]].dir) < 0 &&
            (best[1] < 0 || hits[i].gap < hits[best[1]].gap))
            best[1] = i;
    const double minv = 1 / m->node_mass[node], dt0 = c->dt0, dtp = s->dt_prev;
    unsigned char flag = cs->ent_flag[e] & (unsigned char)~(FE_CFLAG_SLOT0 | FE_CFLAG_SLOT1);
    for (int k = 0; k < 2; k++) {
        const int slot = 2 * e + k;
        double *f = r[k].f, *ft = cs->ent_ft + 3 * slot;
        r[k].d = 0;
        if (best[k] < 0) {
            /* released: the stick spring's energy is dissipated */
            r[k].d = cs->ent_et[slot];
            cs->ent_et[slot] = r[k].el = r[k].g = 0;
            r[k].seg = -1;
            f[0] = f[1] = f[2] = ft[0] = ft[1] = ft[2] = 0;
            continue;
        }
        const hit *h = &hits[best[k]];
        const int sg = h->seg, *q = c->seg_node + 4 * sg;
        double kp = fmin(c->seg_k[sg], c->k_cap / (dt0 * dt0 * (minv + fe_contact_seg_minv(c, m, sg))));
        double fn = -kp * h->gap, el = 0.5 * kp * h->gap * h->gap;
        for (int i = 0; i < 3; i++) f[i] = fn * h->dir[i];
        double vr[3];
        for (int i = 0; i < 3; i++) {
            vr[i] = s->node_v[3 * node + i];
            for (int j = 0; j < 4; j++) vr[i] -= h->w[j] * s->node_v[3 * q[j] + i];
        }
        if (I->damping > 0) {
            /* LS-DYNA's VDC: c = VDC/100 x 2 m omega, m = min(m_node, m_seg), omega =
             * sqrt(k (m_node + m_seg) / (m_node m_seg)); the force -c v_n along the normal
             * (not clipped: a linear Kelvin-Voigt contact), its work dissipated */
            const double sminv = fe_contact_seg_minv(c, m, sg);
            const double mm = fmin(1 / minv, sminv > 0 ? 1 / sminv : INFINITY);
            const double omega = sqrt(kp * (minv + sminv));
            const double cd = 2 * I->damping * mm * omega, vn = fe_dot(vr, h->dir);
            for (int i = 0; i < 3; i++) f[i] -= cd * vn * h->dir[i];
            r[k].d += cd * vn * vn * dtp;
        }
        if (I->mu_s > 0) {
            double du[3];
            double vn = fe_dot(vr, h->dir), vt = 0;
            for (int i = 0; i < 3; i++) {
                du[i] = (vr[i] - vn * h->dir[i]) * dtp;
                vt += (vr[i] - vn * h->dir[i]) * (vr[i] - vn * h->dir[i]);
            }
            double mu = I->mu_d + (I->mu_s - I->mu_d) * exp(-I->decay * sqrt(vt)), taken;
            double et = fe_friction_update(ft, h->dir, du, kp, mu * fn, &taken);
            r[k].d += taken - (et - cs->ent_et[slot]);
            cs->ent_et[slot] = et;
            el += et;
            for (int i = 0; i < 3; i++) f[i] += ft[i];
        }
        r[k].el = el;
        r[k].g = h->gap;
        r[k].seg = sg;
        memcpy(r[k].w, h->w, sizeof h->w);
        flag |= (unsigned char)(k ? FE_CFLAG_SLOT1 : FE_CFLAG_SLOT0);
    }
    cs->ent_flag[e] = flag;
}

/* ---- phase 3: rigid ellipsoids ---------------------------------------------------------- */

/* the body law's deflection delta_b in [0, d] with delta_b + A sigma(delta_b) / kp = d: the
 * penalty spring (kp) and the body's surface (A sigma) in series carry one force and their
 * deflections add to the penetration d. The left side increases with delta_b (sigma does not
 * decrease along a path), so Newton's iterates kept inside the bracket converge (bisection
 * where a step leaves it) [m] */
static double law_deflection(const mcs_hyst_model *L, const mcs_hyst_state *h, double A,
                             double kp, double d)
{
    if (!(d > 0)) return 0;
    double lo = 0, hi = d, x = fmin(fmax(h->x, 0), d);
    for (int it = 0; it < 100; it++) {
        const double r = x + A * mcs_hyst_force(L, h, x) / kp - d;
        if (fabs(r) <= 1e-13 * d || hi - lo <= 1e-15 * d) break;
        if (r > 0) hi = x;
        else lo = x;
        const double xn = x - r / (1 + A * mcs_hyst_stiffness(L, h, x) / kp);
        x = (xn > lo && xn < hi) ? xn : 0.5 * (lo + hi);
    }
    return x;
}

void fe_contact_rigid_node(const fe_model *m, fe_state *s, int n, double g, const double R[9],
                           const double db[3], const double qb[3], double scale, double mu,
                           const double V[3], const double W[3], double ft[3], double *et,
                           const fe_contact_law *law, double F[3], double M[3])
{
    double dir[3], qw[3]; /* the normal and the surface point q - c, world */
    for (int k = 0; k < 3; k++) {
        dir[k] = R[3 * k] * db[0] + R[3 * k + 1] * db[1] + R[3 * k + 2] * db[2];
        qw[k] = R[3 * k] * qb[0] + R[3 * k + 1] * qb[1] + R[3 * k + 2] * qb[2];
    }
    fe_contact_state *cs = s->contact;
    const double dt0 = m->contact->dt0, dtp = s->dt_prev;
    double kp = scale * m->node_mass[n] / (dt0 * dt0), fn = -kp * g;
    double f[3], el = 0.5 * kp * g * g, d = 0;
    if (law && law->model) {
        /* the body's surface in series: the penalty spring carries the law's force A sigma */
        fe_body_law_node *b = law->node;
        const double A = fe_contact_node_area(m, s, n, dir), x0 = b->h.x;
        const double xb = law_deflection(law->model, &b->h, A, kp, -g);
        fn = A * mcs_hyst_update(law->model, &b->h, xb);
        b->work += 0.5 * (b->force + fn) * (xb - x0);
        b->force = fn;
        el = 0.5 * fn * fn / kp + b->work;
    }
    for (int k = 0; k < 3; k++) f[k] = fn * dir[k];
    if (mu > 0) {
        /* slip against the surface point q, moving at V + W x (q - c) */
        const double *v = s->node_v + 3 * n;
        double wr[3], du[3], taken;
        fe_cross(W, qw, wr);
        double vr[3];
        for (int k = 0; k < 3; k++) vr[k] = v[k] - V[k] - wr[k];
        double vn = fe_dot(vr, dir);
        for (int k = 0; k < 3; k++) du[k] = (vr[k] - vn * dir[k]) * dtp;
        double e1 = fe_friction_update(ft, dir, du, kp, mu * fn, &taken);
        d = taken - (e1 - *et);
        *et = e1;
        el += e1;
        for (int k = 0; k < 3; k++) f[k] += ft[k];
    }
    /* on the surface at its point q: the moment about the reference point */
    double mq[3];
    for (int k = 0; k < 3; k++) {
        cs->node_fc[3 * n + k] += f[k];
        F[k] -= f[k];
    }
    fe_cross(qw, f, mq);
    for (int k = 0; k < 3; k++) M[k] -= mq[k];
    int ip = m->node_part[n];
    if (ip >= 0) {
        cs->part_elastic[ip] += el;
        cs->part_fric[ip] += d;
    }
    cs->pen_max = fmax(cs->pen_max, -g);
}

void fe_contact_rigid_release(const fe_model *m, fe_state *s, int n, double ft[3], double *et,
                              const fe_contact_law *law)
{
    fe_contact_state *cs = s->contact;
    fe_body_law_node *b = law && law->model ? law->node : NULL;
    if (b && (b->h.x != 0 || b->work != 0)) {
        /* the body's surface unloads to 0: its work so far is what its hysteresis dissipated */
        b->work -= 0.5 * b->force * b->h.x;
        if (m->node_part[n] >= 0) cs->part_fric[m->node_part[n]] += b->work;
        mcs_hyst_reset(law->model, &b->h);
        b->work = b->force = 0;
    }
    if (*et > 0 && m->node_part[n] >= 0) cs->part_fric[m->node_part[n]] += *et;
    *et = 0;
    ft[0] = ft[1] = ft[2] = 0;
}


static void ellipsoid_forces(const fe_model *m, fe_state *s)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    for (int i = 0; i < c->nell; i++) {
        const fe_contact_ellipsoid *E = &c->ell[i];
        const double *C = cs->ell_c + 3 * i, *R = cs->ell_R + 9 * i, *V = cs->ell_v + 3 * i;
        const double *W = cs->ell_w + 3 * i;
        const double amax = fmax(E->semi[0], fmax(E->semi[1], E->semi[2]));
        const double amin = fmin(E->semi[0], fmin(E->semi[1], E->semi[2]));
        double *F = cs->ell_force + 3 * i, *M = cs->ell_moment + 3 * i;
        F[0] = F[1] = F[2] = M[0] = M[1] = M[2] = 0;
        for (int jc = 0; jc < cs->ell_ncand[i]; jc++) {
            const int j = cs->ell_cand[E->node_begin + jc], n = c->ell_node[j];
            const double *x = s->node_x + 3 * n;
            double *ft = cs->ell_ft + 3 * j;
            const fe_contact_law law = {E->law_curve ? &E->law : NULL, cs->ell_law + j};
            double r[3] = {x[0] - C[0], x[1] - C[1], x[2] - C[2]}, pb[3], qb[3];
            const double ht = c->ell_ht[j]; /* shell nodes meet it at t/2, solids at 0 */
            if (fe_dot(r, r) > (amax + ht) * (amax + ht)) goto release;
            for (int k = 0; k < 3; k++) pb[k] = R[k] * r[0] + R[3 + k] * r[1] + R[6 + k] * r[2];
            /* outside at level s = |p|_a > 1 the distance is at least (s - 1) a_min: most nodes
             * near but off the surface need no nearest-point solve */
            double s2 = 0;
            for (int k = 0; k < 3; k++) s2 += pb[k] * pb[k] / (E->semi[k] * E->semi[k]);
            if (s2 > 1 && (sqrt(s2) - 1) * amin > ht) goto release;
            double g = fe_ellipsoid_nearest(E->semi, pb, qb) - ht;
            if (g >= 0) goto release;
            {
                /* outward direction: from the nearest point to the node, or the surface
                 * normal (gradient) when the node sits on the surface */
                double db[3], nb[3], len = 0;
                for (int k = 0; k < 3; k++) {
                    nb[k] = qb[k] / (E->semi[k] * E->semi[k]);
                    len += nb[k] * nb[k];
                }
                len = sqrt(len);
                for (int k = 0; k < 3; k++) db[k] = nb[k] / len;
                fe_contact_rigid_node(m, s, n, g, R, db, qb, E->scale, E->mu, V, W, ft,
                                      &cs->ell_et[j], &law, F, M);
                continue;
            }
        release:
            fe_contact_rigid_release(m, s, n, ft, &cs->ell_et[j], &law);
        }
    }
}

/* ---- the sub-stage ----------------------------------------------------------------------- */

/* the power of the moving rigid surfaces on the structure, -(F.V + M.W), with the velocities
 * of the last step (vl); each surface's work is summed in ell_work / fac_work with weight hw,
 * the total returned [W] */
static double body_power(const fe_contact_model *c, fe_contact_state *cs, double hw)
{
    double p = 0;
    for (int i = 0; i < c->nell; i++) {
        const double *vl = cs->ell_vl + 6 * i;
        double pi = -fe_dot(cs->ell_force + 3 * i, vl) - fe_dot(cs->ell_moment + 3 * i, vl + 3);
        cs->ell_work[i] += hw * pi;
        p += pi;
    }
    for (int i = 0; i < c->nfac; i++) {
        const double *vl = cs->fac_vl + 6 * i;
        double pi = -fe_dot(cs->fac_force + 3 * i, vl) - fe_dot(cs->fac_moment + 3 * i, vl + 3);
        cs->fac_work[i] += hw * pi;
        p += pi;
    }
    return p;
}

/* the velocities of this step become the last step's */
static void keep_velocities(const fe_contact_model *c, fe_contact_state *cs)
{
    for (int i = 0; i < c->nell; i++) {
        memcpy(cs->ell_vl + 6 * i, cs->ell_v + 3 * i, 3 * sizeof(double));
        memcpy(cs->ell_vl + 6 * i + 3, cs->ell_w + 3 * i, 3 * sizeof(double));
    }
    for (int i = 0; i < c->nfac; i++) {
        memcpy(cs->fac_vl + 6 * i, cs->fac_v + 3 * i, 3 * sizeof(double));
        memcpy(cs->fac_vl + 6 * i + 3, cs->fac_w + 3 * i, 3 * sizeof(double));
    }
}

/* ---- thread shares ----------------------------------------------------------------------
 * With more than FE_CONTACT_OMP_MIN slave entries the contact runs on the FE loops' team
 * (fe_parallel.h): a chunk of the live list on the thread owning its first slave node, the
 * touched nodes of a node chunk on the thread owning the chunk, so positions, velocities and
 * contact forces stay in that core's cache (a chunk run by the other thread puts the lines of
 * its nodes in both cores' caches, and the owner's next write of x and v then waits for the
 * other copy to be invalidated: in the tube crush that doubled the integration's time on 2
 * threads). The time of each live chunk is added to its node chunk's (fe_state.node_cost), so the
 * thread shares balance the elements and the contact together (fe_parallel.c). Powers are
 * summed per node chunk and added in chunk order; the scatter to the nodes is serial in live
 * order: results do not depend on the number of threads (tests/test_fe_parallel.c). */

long fe_contact_omp_work(const fe_model *m)
{
    return m->contact && m->contact->nent > FE_CONTACT_OMP_MIN ? m->contact->nent : 0;
}

static int contact_team(const fe_model *m, const fe_state *s)
{
    const int nt = s->par_nt > 1 ? s->par_nt : 1;
    return m->contact->nent > FE_CONTACT_OMP_MIN ? nt : 1;
}

/* node chunks and nodes of share t of a team of nt (one thread: all of them) */
static fe_par_range contact_share(const fe_model *m, const fe_state *s, int nt, int t)
{
    fe_par_range r = {0, m->nchunk, 0, m->nnode_chunk, 0, m->nnode};
    if (nt > 1) fe_par_share(m, s, t, &r);
    return r;
}

/* first index of the (sorted) touch list whose node is >= node */
static int touch_lo(const fe_contact_model *c, int node)
{
    int lo = 0, hi = c->nnode_touch;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (c->touch[mid] < node) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

/* touched nodes of node chunk k: touch[*t0 .. *t1) */
static void chunk_touch(const fe_model *m, int k, int *t0, int *t1)
{
    const int n1 = (k + 1) * FE_CHUNK_NODES < m->nnode ? (k + 1) * FE_CHUNK_NODES : m->nnode;
    *t0 = touch_lo(m->contact, k * FE_CHUNK_NODES);
    *t1 = touch_lo(m->contact, n1);
}

/* before the entries, on a share: the power of the last step's contact forces at the current
 * velocities per node chunk (pow_chunk); whether a node moved far enough since the search to
 * ask for a new one (*moved set to 1); node_fc zeroed */
static void pre_share(const fe_model *m, fe_state *s, const fe_par_range *r, int *moved)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    const double m2 = cs->margin2;
    int mv = 0;
    for (int k = r->nc0; k < r->nc1; k++) {
        int t0, t1;
        chunk_touch(m, k, &t0, &t1);
        double p = 0;
        for (int t = t0; t < t1; t++) {
            const int n = c->touch[t];
            double *f = cs->node_fc + 3 * n;
            const double *x = s->node_x + 3 * n;
            const float *xr = cs->x_ref + 3 * t;
            p += fe_dot(f, s->node_v + 3 * n);
            f[0] = f[1] = f[2] = 0;
            double d0 = x[0] - xr[0], d1 = x[1] - xr[1], d2 = x[2] - xr[2];
            mv |= d0 * d0 + d1 * d1 + d2 * d2 > m2;
        }
        cs->pow_chunk[k] = p;
    }
    if (mv) {
#pragma omp atomic write
        *moved = 1;
    }
}

/* after the scatter, on a share: node_fc into node_fext, the power of the new forces per
 * node chunk */
static void post_share(const fe_model *m, fe_state *s, const fe_par_range *r)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    for (int k = r->nc0; k < r->nc1; k++) {
        int t0, t1;
        chunk_touch(m, k, &t0, &t1);
        double p = 0;
        for (int t = t0; t < t1; t++) {
            const int n = c->touch[t];
            const double *f = cs->node_fc + 3 * n;
            for (int i = 0; i < 3; i++) s->node_fext[3 * n + i] += f[i];
            p += fe_dot(f, s->node_v + 3 * n);
        }
        cs->pow_chunk[k] = p;
    }
}

/* the node chunks' powers in chunk order [W] */
static double chunk_power(const fe_model *m, const fe_contact_state *cs)
{
    double p = 0;
    for (int k = 0; k < m->nnode_chunk; k++) p += cs->pow_chunk[k];
    return p;
}

static int nlive_chunk(const fe_contact_state *cs)
{
    return (cs->nlive + FE_CONTACT_LIVE_CHUNK - 1) / FE_CONTACT_LIVE_CHUNK;
}

/* the thread of a team of nt owning live chunk q (that of its first slave node) */
static int chunk_owner(const fe_model *m, const fe_state *s, int nt, int q)
{
    const int nc = m->contact->ent_node[s->contact->live[q * FE_CONTACT_LIVE_CHUNK]] /
                   FE_CHUNK_NODES;
    int t = 0;
    while (t + 1 < nt && s->par_ncut[t + 1] <= nc) t++;
    return t;
}

/* each thread's first record: the records split in proportion to the live chunks each thread
 * owns (rec0[0 .. nt]) */
static void record_shares(const fe_model *m, const fe_state *s, int nt, int *rec0)
{
    const fe_contact_state *cs = s->contact;
    const int nq = nlive_chunk(cs);
    int cnt[FE_PAR_MAX] = {0}, cum = 0;
    for (int q = 0; q < nq; q++) cnt[chunk_owner(m, s, nt, q)]++;
    for (int t = 0; t < nt; t++) {
        rec0[t] = nq > 0 ? (int)((long)cs->slot_cap * cum / nq) : 0;
        cum += cnt[t];
    }
    rec0[nt] = cs->slot_cap;
}

/* phase 1 on share t of nt: the live chunks whose first slave node is the share's; each
 * entry with a force or a dissipation keeps its two slots as a record in the thread's part of
 * `slot` (rec0[t] .. rec0[t + 1]); once that part is full the rest of the share's entries are
 * left to the scatter. Threaded, each chunk's time goes to its first node chunk. */
static void live_share(const fe_model *m, fe_state *s, int nt, int t, const int *rec0)
{
    fe_contact_state *cs = s->contact;
    const int rec1 = rec0[t + 1], nq = nlive_chunk(cs);
    int nr = rec0[t];
    for (int q = 0; q < nq; q++) {
        const int i0 = q * FE_CONTACT_LIVE_CHUNK;
        const int i1 = i0 + FE_CONTACT_LIVE_CHUNK < cs->nlive ? i0 + FE_CONTACT_LIVE_CHUNK
                                                               : cs->nlive;
        if (nt > 1 && chunk_owner(m, s, nt, q) != t) continue;
        const double c0 = nt > 1 ? fe_par_clock() : 0;
        cs->q_rec0[q] = nr;
        cs->q_done[q] = i1;
        for (int i = i0; i < i1; i++) {
            if (nr == rec1) {
                cs->q_done[q] = i;
                break;
            }
            fe_contact_slot *sl = cs->slot + 2 * (size_t)nr;
            entry_forces(m, s, cs->live[i], sl);
            if (sl[0].seg >= 0 || sl[1].seg >= 0 || sl[0].d != 0 || sl[1].d != 0)
                cs->rec_live[nr++] = i;
        }
        cs->q_nrec[q] = nr - cs->q_rec0[q];
        if (nt > 1) s->node_cost[m->contact->ent_node[cs->live[i0]] / FE_CHUNK_NODES] +=
            fe_par_clock() - c0;
    }
}

/* phase 2 for entry e: its two slots' forces to the slave node and, with the nearest point's
 * weights, to the segment nodes; energies per part and per interface */
static void scatter_entry(const fe_model *m, fe_state *s, int e, const fe_contact_slot *r)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    const fe_contact_pass *P = &c->pass[fe_contact_ent_pass(c, e)];
    const int node = c->ent_node[e], ifc = P->iface, rev = P->reverse;
    const int ps = m->node_part[node];
    for (int k = 0; k < 2; k++) {
        const int sg = r[k].seg;
        const double d = r[k].d;
        if (d != 0) {
            cs->if_fric[ifc] += d;
            if (sg >= 0) {
                cs->part_fric[ps] += 0.5 * d;
                cs->part_fric[c->seg_part[sg]] += 0.5 * d;
            } else {
                cs->part_fric[ps] += d;
            }
        }
        if (sg < 0) continue;
        const double *f = r[k].f, *w = r[k].w;
        const int *q = c->seg_node + 4 * sg;
        for (int j = 0; j < 3; j++) {
            cs->node_fc[3 * node + j] += f[j];
            cs->if_force[3 * ifc + j] += rev ? -f[j] : f[j];
        }
        for (int j = 0; j < 4; j++)
            if (w[j] != 0)
                for (int l = 0; l < 3; l++) cs->node_fc[3 * q[j] + l] -= w[j] * f[l];
        const double el = r[k].el;
        cs->part_elastic[ps] += 0.5 * el;
        cs->part_elastic[c->seg_part[sg]] += 0.5 * el;
        cs->if_energy[ifc] += el;
        cs->pen_max = fmax(cs->pen_max, -r[k].g);
    }
}

/* phase 2 (serial, live order) and phase 3: each chunk's records, then the entries its
 * thread left over (run here); an entry without a record had no force and no dissipation */
static void scatter(const fe_model *m, fe_state *s)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    memset(cs->part_elastic, 0, sizeof(double) * (size_t)m->npart);
    memset(cs->if_force, 0, sizeof(double) * 3 * (size_t)c->nif);
    memset(cs->if_energy, 0, sizeof(double) * (size_t)c->nif);
    const int nq = nlive_chunk(cs);
    for (int q = 0; q < nq; q++) {
        for (int j = cs->q_rec0[q]; j < cs->q_rec0[q] + cs->q_nrec[q]; j++)
            scatter_entry(m, s, cs->live[cs->rec_live[j]], cs->slot + 2 * (size_t)j);
        const int i1 = (q + 1) * FE_CONTACT_LIVE_CHUNK < cs->nlive
                           ? (q + 1) * FE_CONTACT_LIVE_CHUNK
                           : cs->nlive;
        for (int i = cs->q_done[q]; i < i1; i++) {
            fe_contact_slot tmp[2];
            entry_forces(m, s, cs->live[i], tmp);
            scatter_entry(m, s, cs->live[i], tmp);
        }
    }
    for (int i = 0; i < c->nif; i++) cs->if_energy[i] += cs->if_fric[i];
    /* phase 3: ellipsoids and rigid facet surfaces add to node_fc */
    if (c->nell + c->nfac > 0) fe_contact_rigid_candidates(m, s);
    ellipsoid_forces(m, s);
    fe_contact_facets_forces(m, s);
}

void fe_contact_begin(const fe_model *m, fe_state *s)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    const int nt = contact_team(m, s);
    /* forward half of the previous step's contact work (velocities now at t - dt/2), the
     * search margin, node_fc zeroed */
    int moved = 0;
    if (nt > 1) {
#pragma omp parallel num_threads(nt)
        for (int t = fe_par_tid(); t < nt; t += fe_par_nth()) {
            const fe_par_range r = contact_share(m, s, nt, t);
            pre_share(m, s, &r, &moved);
        }
    } else {
        const fe_par_range r = contact_share(m, s, 1, 0);
        pre_share(m, s, &r, &moved);
    }
    cs->work_nodes += 0.5 * cs->dth_prev * chunk_power(m, cs);
    cs->work_bodies += 0.5 * cs->dth_prev * body_power(c, cs, 0.5 * cs->dth_prev);
    if (c->npass > 0 && (cs->need_rebuild || moved)) {
        fe_contact_search(m, s);
        fe_contact_candidates(m, s);
    }
    /* phase 1 is left to fe_contact_live (threaded, in the element loops' region) */
    cs->live_nt = nt;
    cs->live_done = 0;
    if (nt > 1) record_shares(m, s, nt, cs->rec0);
    else cs->rec0[0] = 0, cs->rec0[1] = cs->slot_cap;
}

int fe_contact_threaded(const fe_model *m, const fe_state *s)
{
    return m->contact && s->contact->live_nt > 1;
}

void fe_contact_live(const fe_model *m, fe_state *s, int t)
{
    fe_contact_state *cs = s->contact;
    live_share(m, s, cs->live_nt, t, cs->rec0);
}

void fe_contact_finish(const fe_model *m, fe_state *s)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    const double dth = 0.5 * (s->dt + s->dt_prev), hb = s->dt_prev > 0 ? dth : 0;
    const int nt = cs->live_nt;
    /* phase 1 here unless fe_contact_live ran it (one thread), phase 2 and 3 serial; then
     * node_fc into node_fext by each node's thread */
    if (!cs->live_done)
        for (int t = 0; t < nt; t++) live_share(m, s, nt, t, cs->rec0);
    if (nt > 1) {
#pragma omp parallel num_threads(nt)
        {
#pragma omp single
            scatter(m, s);
            for (int t = fe_par_tid(); t < nt; t += fe_par_nth()) {
                const fe_par_range r = contact_share(m, s, nt, t);
                post_share(m, s, &r);
            }
        }
    } else {
        scatter(m, s);
        const fe_par_range r = contact_share(m, s, 1, 0);
        post_share(m, s, &r);
    }
    /* back half of this step's contact work */
    cs->work_nodes += 0.5 * hb * chunk_power(m, cs);
    cs->work_bodies += 0.5 * hb * body_power(c, cs, 0.5 * hb);
    keep_velocities(c, cs);
    cs->dth_prev = dth;
    /* energies at t */
    double e = 0;
    for (int ip = 0; ip < m->npart; ip++) {
        double pe = cs->part_elastic[ip] + cs->part_fric[ip];
        s->part_energy[FE_NENERGY * ip + FE_E_contact] = pe;
        e += pe;
    }
    cs->energy = e;
    /* the ellipsoids move on with their velocity */
    for (int i = 0; i < 3 * c->nell; i++) cs->ell_c[i] += s->dt * cs->ell_v[i];
    for (int i = 0; i < 3 * c->nfac; i++) cs->fac_c[i] += s->dt * cs->fac_v[i];
}

double fe_contact_energy(const fe_model *m, const fe_state *s)
{
    (void)m;
    return s->contact ? s->contact->energy : 0;
}

double fe_contact_work(const fe_model *m, const fe_state *s)
{
    (void)m;
    return s->contact ? s->contact->work_nodes - s->contact->work_bodies : 0;
}

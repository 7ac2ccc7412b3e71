/* fe_contact_facet: FE nodes against rigid triangle meshes moving with a pose (the facet
 * surfaces of stage-1 bodies, stage1_mb/mb_couple_contact.c). See fe_contact.h and docs/fe.md
 * "Contact".
 *
 * Each mesh is fixed in its own frame (vertices about a reference point c, rotation R to the
 * world); a grid over the mesh, built once in that frame, holds the triangles within
 * FE_FACET_DEPTH of each cell, so a node's candidates are those of the cell it falls in once
 * taken into the mesh frame. A node meets the nearest triangle: on its outer side the gap is
 * the distance less the shell half thickness, pushed along the line from the nearest point;
 * behind it (signed distance < 0) and under a face (the line to the nearest point within
 * about 45 degrees of the normal, the kernel's rule for hex faces), the gap is minus the
 * distance less the half thickness, pushed out the same way, but only for a node seen on the
 * outer side before (fac_side): a node found behind otherwise (it came round an open edge, or
 * began there) is left alone until it is out in front again, and one deeper than
 * FE_FACET_DEPTH is let go. Penalty k = s m_node / dt0^2 and elastic-stick Coulomb friction
 * as for the ellipsoids; the force on the node and minus it on the mesh at the nearest point,
 * summed as the mesh's force and moment about c. */
#include "fe/fe_builder_impl.h"
#include "fe/fe_contact_impl.h"
#include "fe/fe_elem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define FE_FACET_CELLS 262144 /* most grid cells of one mesh [-] */

/* the grid of mesh F: triangle boxes grown by the reach (FE_FACET_DEPTH + largest half
 * thickness), counted then filled cell by cell */
static mcs_status facet_grid(fe_contact_facets *F, double reach, mcs_error *err)
{
    double hi[3], edge = 0;
    for (int k = 0; k < 3; k++)
        F->lo[k] = INFINITY, hi[k] = -INFINITY;
    for (int v = 0; v < F->nvert; v++)
        for (int k = 0; k < 3; k++) {
            F->lo[k] = fmin(F->lo[k], F->vert[3 * v + k]);
            hi[k] = fmax(hi[k], F->vert[3 * v + k]);
        }
    for (int t = 0; t < F->ntri; t++) {
        const int *q = F->tri + 3 * t;
        for (int j = 0; j < 3; j++) {
            double d[3];
            for (int k = 0; k < 3; k++)
                d[k] = F->vert[3 * q[(j + 1) % 3] + k] - F->vert[3 * q[j] + k];
            edge += sqrt(fe_dot(d, d));
        }
    }
    for (int k = 0; k < 3; k++)
        F->lo[k] -= reach, hi[k] += reach;
    /* cells about the mean edge (at least the reach), fewer than FE_FACET_CELLS */
    F->cell = fmax(edge / (3.0 * F->ntri), reach);
    for (;;) {
        double n = 1;
        for (int k = 0; k < 3; k++) {
            F->dim[k] = (int)ceil((hi[k] - F->lo[k]) / F->cell);
            if (F->dim[k] < 1) F->dim[k] = 1;
            n *= F->dim[k];
        }
        if (n <= FE_FACET_CELLS) break;
        F->cell *= 1.5;
    }
    const int ncell = F->dim[0] * F->dim[1] * F->dim[2];
    F->cell_off = calloc((size_t)ncell + 1, sizeof(int));
    if (!F->cell_off) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (facets)");
    for (int pass = 0; pass < 2; pass++) {
        for (int t = 0; t < F->ntri; t++) {
            const int *q = F->tri + 3 * t;
            int c0[3], c1[3];
            for (int k = 0; k < 3; k++) {
                double a = F->vert[3 * q[0] + k], b = F->vert[3 * q[1] + k],
                       c = F->vert[3 * q[2] + k];
                double l = fmin(a, fmin(b, c)) - reach, h = fmax(a, fmax(b, c)) + reach;
                c0[k] = (int)floor((l - F->lo[k]) / F->cell);
                c1[k] = (int)floor((h - F->lo[k]) / F->cell);
                c0[k] = c0[k] < 0 ? 0 : c0[k] >= F->dim[k] ? F->dim[k] - 1 : c0[k];
                c1[k] = c1[k] < 0 ? 0 : c1[k] >= F->dim[k] ? F->dim[k] - 1 : c1[k];
            }
            for (int z = c0[2]; z <= c1[2]; z++)
                for (int y = c0[1]; y <= c1[1]; y++)
                    for (int x = c0[0]; x <= c1[0]; x++) {
                        int cell = (z * F->dim[1] + y) * F->dim[0] + x;
                        if (pass == 0)
                            F->cell_off[cell + 1]++;
                        else
                            F->cell_tri[F->cell_off[cell]++] = t;
                    }
        }
        if (pass == 0) {
            for (int c = 0; c < ncell; c++)
                F->cell_off[c + 1] += F->cell_off[c];
            F->cell_tri =
                malloc(sizeof(int) * (size_t)(F->cell_off[ncell] ? F->cell_off[ncell] : 1));
            if (!F->cell_tri) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (facets)");
        }
    }
    /* the fill advanced each offset to the next cell's start: shift back */
    for (int c = ncell; c > 0; c--)
        F->cell_off[c] = F->cell_off[c - 1];
    F->cell_off[0] = 0;
    return MCS_OK;
}

mcs_status fe_contact_facets_build(const fe_builder *b, fe_contact_model *c, const fe_model *m,
                                   unsigned char *mark, const double *shell_ht, mcs_error *err)
{
    c->nfac = b->nfacets;
    if (c->nfac == 0) return MCS_OK;
    c->fac = calloc((size_t)c->nfac, sizeof *c->fac);
    c->fac_node = malloc(sizeof(int) * (size_t)c->nfac * (size_t)(m->nnode ? m->nnode : 1));
    c->fac_ht = malloc(sizeof(double) * (size_t)c->nfac * (size_t)(m->nnode ? m->nnode : 1));
    unsigned char *mk = malloc((size_t)(m->nnode ? m->nnode : 1));
    mcs_status st = MCS_OK;
    if (!c->fac || !c->fac_node || !c->fac_ht || !mk)
        st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (facets)");
    double htmax = 0;
    for (int n = 0; n < m->nnode; n++)
        htmax = fmax(htmax, shell_ht[n]);
    for (int i = 0; i < c->nfac && !st; i++) {
        const fe_facet_desc *d = &b->facets[i];
        fe_contact_facets *F = &c->fac[i];
        memcpy(F->name, d->name, FE_NAME_MAX);
        memcpy(F->center, d->center, sizeof F->center);
        fe_contact_quat_to_R(d->orientation, F->R);
        F->scale = d->penalty_scale > 0 ? d->penalty_scale : 0.1;
        F->mu = d->friction;
        F->nvert = d->nvert, F->ntri = d->ntri;
        F->vert = malloc(sizeof(double) * 3 * (size_t)d->nvert);
        F->tri = malloc(sizeof(int) * 3 * (size_t)d->ntri);
        F->tri_n = malloc(sizeof(double) * 3 * (size_t)d->ntri);
        if (!F->vert || !F->tri || !F->tri_n) {
            st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (facets)");
            break;
        }
        memcpy(F->vert, d->vert, sizeof(double) * 3 * (size_t)d->nvert);
        memcpy(F->tri, d->tri, sizeof(int) * 3 * (size_t)d->ntri);
        for (int t = 0; t < F->ntri; t++) {
            const double *a = F->vert + 3 * F->tri[3 * t], *bb = F->vert + 3 * F->tri[3 * t + 1];
            const double *cc = F->vert + 3 * F->tri[3 * t + 2];
            double e1[3], e2[3], *n = F->tri_n + 3 * t;
            for (int k = 0; k < 3; k++)
                e1[k] = bb[k] - a[k], e2[k] = cc[k] - a[k];
            fe_cross(e1, e2, n);
            double len = sqrt(fe_dot(n, n));
            if (!(len > 0)) {
                st = MCS_ERR(err, MCS_ERR_RANGE, "fe: facet surface '%s': triangle %d has no area",
                             d->name, t);
                break;
            }
            for (int k = 0; k < 3; k++)
                n[k] /= len;
        }
        for (int v = 0; v < F->nvert; v++) {
            const double *p = F->vert + 3 * v;
            F->rmax = fmax(F->rmax, sqrt(fe_dot(p, p)));
        }
        if (!st) st = facet_grid(F, FE_FACET_DEPTH + htmax, err);
        memset(mark, d->nparts ? 0 : 1, (size_t)m->nnode);
        for (int j = 0; j < d->nparts && !st; j++) {
            fe_builder_part_nodes(b, fe_builder_find_part(b, d->parts[j]), mk);
            for (int n = 0; n < m->nnode; n++)
                mark[n] |= mk[n];
        }
        F->node_begin = c->nfac_node;
        for (int n = 0; n < m->nnode && !st; n++)
            if (mark[n] && m->node_mass[n] > 0) {
                c->fac_ht[c->nfac_node] = shell_ht[n];
                c->fac_node[c->nfac_node++] = n;
            }
        F->node_end = c->nfac_node;
        c->bytes += sizeof(double) * 3 * ((size_t)F->nvert + (size_t)F->ntri) +
                    sizeof(int) * 3 * (size_t)F->ntri +
                    sizeof(int) * ((size_t)F->dim[0] * F->dim[1] * F->dim[2] + 1);
    }
    free(mk);
    c->bytes +=
        (sizeof(int) + sizeof(double)) * (size_t)c->nfac_node + sizeof *c->fac * (size_t)c->nfac;
    return st;
}

void fe_contact_facets_free(fe_contact_model *c)
{
    for (int i = 0; c->fac && i < c->nfac; i++) {
        fe_contact_facets *F = &c->fac[i];
        free(F->vert), free(F->tri), free(F->tri_n), free(F->cell_off), free(F->cell_tri);
    }
    free(c->fac), free(c->fac_node), free(c->fac_ht);
    c->fac = NULL, c->fac_node = NULL, c->fac_ht = NULL;
}

/* nearest triangle of mesh F to p (mesh frame) within reach: its index, the nearest point q,
 * the distance; -1 when none is within reach */
static int facet_nearest(const fe_contact_facets *F, const double p[3], double reach, double q[3],
                         double *dist)
{
    int ci[3];
    for (int k = 0; k < 3; k++) {
        double u = (p[k] - F->lo[k]) / F->cell;
        if (!(u >= 0) || u >= F->dim[k]) return -1;
        ci[k] = (int)u;
    }
    const int cell = (ci[2] * F->dim[1] + ci[1]) * F->dim[0] + ci[0];
    int best = -1;
    double d2best = reach * reach;
    for (int j = F->cell_off[cell]; j < F->cell_off[cell + 1]; j++) {
        const int t = F->cell_tri[j], *v = F->tri + 3 * t;
        const double *a = F->vert + 3 * v[0], *b = F->vert + 3 * v[1], *c = F->vert + 3 * v[2];
        double w[3], d2 = fe_tri_nearest(p, a, b, c, w);
        if (d2 < d2best) {
            d2best = d2, best = t;
            for (int k = 0; k < 3; k++)
                q[k] = w[0] * a[k] + w[1] * b[k] + w[2] * c[k];
        }
    }
    *dist = sqrt(d2best);
    return best;
}

void fe_contact_facets_forces(const fe_model *m, fe_state *s)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    for (int i = 0; i < c->nfac; i++) {
        const fe_contact_facets *F = &c->fac[i];
        const double *C = cs->fac_c + 3 * i, *R = cs->fac_R + 9 * i, *V = cs->fac_v + 3 * i;
        const double *W = cs->fac_w + 3 * i;
        double *Ft = cs->fac_force + 3 * i, *M = cs->fac_moment + 3 * i;
        Ft[0] = Ft[1] = Ft[2] = M[0] = M[1] = M[2] = 0;
        for (int jc = 0; jc < cs->fac_ncand[i]; jc++) {
            const int j = cs->fac_cand[F->node_begin + jc], n = c->fac_node[j];
            const double *x = s->node_x + 3 * n, ht = c->fac_ht[j];
            double *ft = cs->fac_ft + 3 * j;
            double r[3] = {x[0] - C[0], x[1] - C[1], x[2] - C[2]}, pb[3], qb[3], dist;
            for (int k = 0; k < 3; k++)
                pb[k] = R[k] * r[0] + R[3 + k] * r[1] + R[6 + k] * r[2];
            const int t = facet_nearest(F, pb, FE_FACET_DEPTH + ht, qb, &dist);
            double db[3], g = 0;
            if (t < 0) { /* out of reach: the side is unknown again */
                cs->fac_side[j] = 0;
                goto release;
            }
            {
                const double *nb = F->tri_n + 3 * t;
                double sn = 0;
                for (int k = 0; k < 3; k++)
                    sn += (pb[k] - qb[k]) * nb[k];
                const double sg = sn >= 0 ? 1 : -1;
                if (sn >= 0) {
                    cs->fac_side[j] = 1;
                } else if (!cs->fac_side[j] || -sn < 0.7 * dist) {
                    /* found behind, or behind beside the mesh's edge (not under a face; the
                     * kernel's rule for hex faces): left alone until it is in front again */
                    cs->fac_side[j] = 0;
                    goto release;
                }
                /* out along the line to the nearest point (through the plane when behind) */
                for (int k = 0; k < 3; k++)
                    db[k] = dist > 1e-12 ? sg * (pb[k] - qb[k]) / dist : nb[k];
                g = sg * dist - ht;
                if (g >= 0) goto release;
                if (-g > FE_FACET_DEPTH) { /* through it: let go */
                    cs->fac_side[j] = 0;
                    goto release;
                }
            }
            fe_contact_rigid_node(m, s, n, g, R, db, qb, F->scale, F->mu, V, W, ft, &cs->fac_et[j],
                                  NULL, Ft, M);
            continue;
        release:
            fe_contact_rigid_release(m, s, n, ft, &cs->fac_et[j], NULL);
        }
    }
}

/* ---- candidate nodes of the moving rigid surfaces ----------------------------------------
 * A node farther from a surface's reference point than its bounding radius (an ellipsoid's
 * largest semi-axis, a mesh's farthest vertex, plus the node's reach) cannot touch it, whatever
 * the rotation. Each surface keeps the nodes within that radius + FE_RIGID_MARGIN; the list
 * holds while the fastest node's travel plus the centre's displacement since it was made stay
 * below half the margin, so every step looks at the few nodes near the surface, not at every
 * node of the parts. */

/* the nodes of range [b, e) within radius + reach_j + margin of centre C into cand */
static int make_list(const fe_state *s, const int *node, const double *reach, int b, int e,
                     const double C[3], double radius, int *cand)
{
    int n = 0;
    for (int j = b; j < e; j++) {
        const double *x = s->node_x + 3 * node[j];
        const double r[3] = {x[0] - C[0], x[1] - C[1], x[2] - C[2]};
        const double lim = radius + reach[j] + FE_RIGID_MARGIN;
        if (fe_dot(r, r) <= lim * lim) cand[n++] = j;
    }
    return n;
}

/* whether a list made at ref (centre, travel) still holds at centre C */
static int list_holds(const double *ref, const double C[3], double travel)
{
    const double d[3] = {C[0] - ref[0], C[1] - ref[1], C[2] - ref[2]};
    return travel - ref[3] + sqrt(fe_dot(d, d)) < 0.5 * FE_RIGID_MARGIN;
}

void fe_contact_rigid_candidates(const fe_model *m, fe_state *s)
{
    const fe_contact_model *c = m->contact;
    fe_contact_state *cs = s->contact;
    /* x(t) = x(t - dt_prev) + dt_prev v: the fastest node's step */
    double v2 = 0;
    for (int t = 0; t < c->nnode_touch; t++) {
        const double *v = s->node_v + 3 * c->touch[t];
        v2 = fmax(v2, fe_dot(v, v));
    }
    cs->travel += s->dt_prev * sqrt(v2);
    for (int i = 0; i < c->nell; i++) {
        const fe_contact_ellipsoid *E = &c->ell[i];
        const double *C = cs->ell_c + 3 * i;
        double *ref = cs->ell_cref + 4 * i;
        if (list_holds(ref, C, cs->travel)) continue;
        const double amax = fmax(E->semi[0], fmax(E->semi[1], E->semi[2]));
        cs->ell_ncand[i] = make_list(s, c->ell_node, c->ell_ht, E->node_begin, E->node_end, C, amax,
                                     cs->ell_cand + E->node_begin);
        ref[0] = C[0], ref[1] = C[1], ref[2] = C[2], ref[3] = cs->travel;
    }
    for (int i = 0; i < c->nfac; i++) {
        const fe_contact_facets *F = &c->fac[i];
        const double *C = cs->fac_c + 3 * i;
        double *ref = cs->fac_cref + 4 * i;
        if (list_holds(ref, C, cs->travel)) continue;
        const int *cand = cs->fac_cand + F->node_begin;
        const int n = make_list(s, c->fac_node, c->fac_ht, F->node_begin, F->node_end, C,
                                F->rmax + FE_FACET_DEPTH, cs->fac_cand + F->node_begin);
        /* a node left out is out of reach: its side is unknown again (the list is in order) */
        for (int j = F->node_begin, k = 0; j < F->node_end; j++) {
            if (k < n && cand[k] == j)
                k++;
            else
                cs->fac_side[j] = 0;
        }
        cs->fac_ncand[i] = n;
        ref[0] = C[0], ref[1] = C[1], ref[2] = C[2], ref[3] = cs->travel;
    }
}

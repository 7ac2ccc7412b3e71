/* fe_imm: the initial metric method (IMM) of a membrane part -- the nodes start on a scaled-down
 * copy of the part's mesh while the elements keep the unscaled mesh as their reference
 * (stress-free, design) geometry.
 *
 * The 2023 paper (Sec. 2.3.2, Fig. 15, after its ref. [53]) starts its front airbag this way:
 * "two meshes, an initial mesh and an undeformed reference or design mesh ... internal forces
 * based on the geometric differences between the initial and the reference mesh ... allow the
 * elements to relax to their reference surface area". Here the membrane element (fe_membrane.c)
 * is total Lagrangian on its reference, so the method needs only two things from the builder:
 * the reference positions (b->xref, the mesh as generated or read) from which the model takes
 * the membranes' reference metric and their lumped masses, and the initial positions (b->x,
 * the scaled copy) where the nodes start (node_x0: the gas bag's initial volume, contacts,
 * attachments, output). The scaled copy is shorter in every direction of the reference
 * (0 < scale <= 1), so its Green strain has no positive principal value and the fabric carries
 * no stress (fe_fabric.c: slack, tension-field theory) until the gas has opened it to its
 * reference size. */
#include "fe/fe_builder_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

mcs_status fe_builder_imm(fe_builder *b, int part, const double scale[3], const double *about,
                          mcs_error *err)
{
    if (part < 0 || part >= b->npart)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: initial mesh of unknown part index %d", part);
    const fe_part_desc *d = &b->part[part];
    if (d->section.type != FE_SECTION_MEMBRANE)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': a scaled initial mesh needs a membrane section (the "
                       "other elements take their t = 0 positions as the reference)",
                       d->name);
    for (int i = 0; i < 3; i++)
        if (!(scale[i] > 0 && scale[i] <= 1))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: part '%s': initial scale %g: each factor must be in (0, 1]",
                           d->name, scale[i]);
    if (about && !isfinite(about[0] + about[1] + about[2]))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': initial.about is not finite", d->name);
    const int nn = b->nnode;
    unsigned char *mine = malloc((size_t)nn + 1), *other = malloc((size_t)nn + 1);
    if (!mine || !other) {
        free(mine), free(other);
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    }
    fe_builder_part_nodes(b, part, mine);
    mcs_status st = MCS_OK;
    /* a node of another part would move with this one: that part's reference would change */
    for (int q = 0; q < b->npart && st == MCS_OK; q++) {
        if (q == part) continue;
        fe_builder_part_nodes(b, q, other);
        for (int n = 0; n < nn; n++)
            if (mine[n] && other[n]) {
                st = MCS_ERR(err, MCS_ERR_RANGE,
                             "fe: part '%s': node %d is shared with part '%s': a scaled initial "
                             "mesh needs nodes of its own",
                             d->name, n, b->part[q].name);
                break;
            }
    }
    int cnt = 0;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int n = 0; n < nn; n++)
        if (mine[n]) {
            cnt++;
            for (int i = 0; i < 3; i++) {
                lo[i] = fmin(lo[i], b->x[3 * n + i]);
                hi[i] = fmax(hi[i], b->x[3 * n + i]);
            }
        }
    if (st == MCS_OK && cnt == 0)
        st = MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': no nodes to scale", d->name);
    if (st == MCS_OK && b->cap_xref < b->cap_node) { /* the reference: x until now */
        double *r = realloc(b->xref, 3 * sizeof(double) * (size_t)b->cap_node);
        if (!r) st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
        if (r && !b->xref) memcpy(r, b->x, 3 * sizeof(double) * (size_t)nn);
        if (r) b->xref = r, b->cap_xref = b->cap_node;
    }
    if (st == MCS_OK) {
        double c[3]; /* default centre: the middle of the part's bounding box */
        for (int i = 0; i < 3; i++)
            c[i] = about ? about[i] : 0.5 * (lo[i] + hi[i]);
        for (int n = 0; n < nn; n++)
            if (mine[n])
                for (int i = 0; i < 3; i++) {
                    double *x = b->x + 3 * n + i;
                    b->xref[3 * n + i] = *x;
                    *x = c[i] + scale[i] * (*x - c[i]);
                }
    }
    free(mine), free(other);
    return st;
}

mcs_status fe_builder_imm_grow(fe_builder *b, mcs_error *err)
{
    if (!b->xref || b->cap_xref >= b->cap_node) return MCS_OK;
    double *r = realloc(b->xref, 3 * sizeof(double) * (size_t)b->cap_node);
    if (!r) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    b->xref = r, b->cap_xref = b->cap_node;
    return MCS_OK;
}

/* fe_mesh_shell: surface generators for shells and membranes (DESIGN.md `fe:` mesh keys
 * sphere_shell and cylinder_shell). Every face is oriented with its normal outwards, so a
 * closed one can bound a gas bag directly (fe_restraint.c).
 *
 * sphere_shell: a cube-sphere — the six faces of a cube, n x n quads each, projected on the
 * sphere by the equal-angle map x = r u/|u|, u = tan(pi/4 c), c in [-1, 1]^3 (quads of nearly
 * equal size, no poles), n = round((pi r / 2) / element_size). Closed, all quads.
 * cylinder_shell: rings of quads along `axis` from w = 0 to length (as circular_tube), centred
 * on the axis through `origin`; with `closed`, two flat end caps of concentric rings whose
 * point counts grow with the radius, joined by triangle strips (degenerate shells; membrane
 * parts take triangles anyway), a fan around the centre.
 * flat_bag: a flat (2D-design) gas bag, two rectangular panels of size[0] x size[1] in the
 * plane normal to `axis`, centred on `origin`, sewn along their edges: the edge nodes are
 * shared (w = 0), the inner nodes of the panels lie at w = +-gap/2. Closed, all quads, each
 * starting at a node whose diagonal (the membrane split, fe_builder.c) never joins two seam
 * nodes, which both panels would share. Enclosed volume (grid spacings du, dv; nu x nv cells):
 * shells gap du dv (nu - 1)(nv - 1) (a quad's split about its centroid encloses its bilinear
 * mean height), membranes gap du dv ((nu - 1)(nv - 1) + 1/3) (a corner cell's two triangles
 * both hold its inner node: mean height gap/6 instead of gap/8 per panel). */
#include "fe/fe_builder_impl.h"

#include <math.h>
#include <stdlib.h>

static int rounded(double x) { return (int)fmax(1.0, floor(x + 0.5)); }

static void to_world(int axis, double u, double v, double w, const double o[3], double x[3])
{
    x[(axis + 1) % 3] = o[(axis + 1) % 3] + u;
    x[(axis + 2) % 3] = o[(axis + 2) % 3] + v;
    x[axis] = o[axis] + w;
}

static mcs_status add_quad(fe_builder *b, int ip, int a, int c, int d, int e, int flip,
                           mcs_error *err)
{
    int q[4] = {a, c, d, e};
    if (flip) {
        q[1] = e;
        q[3] = c;
    }
    return fe_builder_add_elem(b, ip, q, err);
}

static mcs_status add_tri(fe_builder *b, int ip, int a, int c, int d, int flip, mcs_error *err)
{
    int q[4] = {a, flip ? d : c, flip ? c : d, flip ? c : d};
    return fe_builder_add_elem(b, ip, q, err);
}

mcs_status fe_mesh_sphere(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err)
{
    const char *name = b->part[ip].name;
    if (!(m->radius > 0) || !(m->element_size > 0) || !isfinite(m->radius + m->element_size))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': mesh: radius and element_size must be > 0", name);
    double nd = floor(0.5 * M_PI * m->radius / m->element_size + 0.5);
    if (6 * nd * nd > 5e7)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': mesh: too many elements", name);
    const int n = nd < 1 ? 1 : (int)nd, np = (n + 1) * (n + 1);
    int *grid = malloc(sizeof(int) * 6 * (size_t)np);
    if (!grid) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory meshing '%s'", name);
    mcs_status st = MCS_OK;
    /* face f = 2 d + s: lattice coordinate d is s n; a lattice point shared by several faces
     * belongs to the first of them and is numbered there */
    for (int f = 0; f < 6 && st == MCS_OK; f++) {
        const int d = f / 2, s = f % 2;
        for (int bb = 0; bb <= n && st == MCS_OK; bb++)
            for (int a = 0; a <= n && st == MCS_OK; a++) {
                int l[3];
                l[d] = s * n, l[(d + 1) % 3] = a, l[(d + 2) % 3] = bb;
                int cf = f;
                for (int g = 0; g < f; g++)
                    if (l[g / 2] == (g % 2) * n) {
                        cf = g;
                        break;
                    }
                if (cf < f) {
                    int dc = cf / 2;
                    grid[np * f + a + (n + 1) * bb] =
                        grid[np * cf + l[(dc + 1) % 3] + (n + 1) * l[(dc + 2) % 3]];
                    continue;
                }
                double u[3], x[3];
                for (int i = 0; i < 3; i++) u[i] = tan(0.25 * M_PI * (2.0 * l[i] / n - 1));
                double r = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
                for (int i = 0; i < 3; i++) x[i] = m->origin[i] + m->radius * u[i] / r;
                st = fe_builder_add_node(b, x, &grid[np * f + a + (n + 1) * bb], err);
            }
    }
    /* quads counter-clockwise about +d (e_(d+1) x e_(d+2) = e_d); reversed on the s = 0 side */
    for (int f = 0; f < 6 && st == MCS_OK; f++)
        for (int bb = 0; bb < n && st == MCS_OK; bb++)
            for (int a = 0; a < n && st == MCS_OK; a++) {
                const int *g = grid + np * f;
                int i0 = a + (n + 1) * bb;
                st = add_quad(b, ip, g[i0], g[i0 + 1], g[i0 + n + 2], g[i0 + n + 1], f % 2 == 0,
                              err);
            }
    free(grid);
    return st;
}

/* a flat end cap at w whose outer ring is the nodes ring[0..nc) (radius R); normal +axis
 * unless flip. Inner rings k = 1..nr-1 with max(3, round(nc k / nr)) points, a centre node. */
static mcs_status gen_cap(fe_builder *b, int ip, const fe_mesh_desc *m, double w, const int *ring,
                          int nc, int flip, mcs_error *err)
{
    const double R = 0.5 * m->diameter;
    const int nr = rounded(R / m->element_size);
    mcs_status st = MCS_OK;
    int in0 = -1, nin = 1; /* first node and size of the inner ring (the centre first) */
    double x[3];
    to_world(m->axis, 0, 0, w, m->origin, x);
    st = fe_builder_add_node(b, x, &in0, err);
    for (int k = 1; k <= nr && st == MCS_OK; k++) {
        int nout = k == nr ? nc : (int)fmax(3, floor((double)nc * k / nr + 0.5)), out0 = -1;
        if (k < nr) {
            out0 = b->nnode;
            for (int j = 0; j < nout && st == MCS_OK; j++) {
                double th = 2 * M_PI * j / nout, r = R * k / nr;
                to_world(m->axis, r * cos(th), r * sin(th), w, m->origin, x);
                st = fe_builder_add_node(b, x, NULL, err);
            }
        }
#define OUT(j) (k == nr ? ring[(j) % nout] : out0 + (j) % nout)
#define IN(i) (in0 + (i) % nin)
        /* merge walk: advance on the ring whose next point comes first in angle */
        int i = nin == 1 ? 1 : 0, j = 0; /* around the centre: a fan of nout triangles */
        while ((i < nin || j < nout) && st == MCS_OK) {
            double ti = nin == 1 ? 2.0 : (double)(i + 1) / nin, tj = (double)(j + 1) / nout;
            if (j < nout && (tj <= ti || i >= nin)) {
                st = add_tri(b, ip, IN(i), OUT(j), OUT(j + 1), flip, err);
                j++;
            } else {
                st = add_tri(b, ip, IN(i), OUT(j), IN(i + 1), flip, err);
                i++;
            }
        }
#undef OUT
#undef IN
        in0 = out0;
        nin = nout;
    }
    return st;
}

mcs_status fe_mesh_cylinder(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err)
{
    const char *name = b->part[ip].name;
    if (!(m->diameter > 0) || !(m->length > 0) || !(m->element_size > 0) ||
        !isfinite(m->diameter + m->length + m->element_size))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': mesh: diameter, length and element_size must be > 0", name);
    double ncd = fmax(3, floor(M_PI * m->diameter / m->element_size + 0.5));
    double nld = fmax(1, floor(m->length / m->element_size + 0.5));
    if (ncd * (nld + 1) * (m->closed ? 2 : 1) > 5e7)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': mesh: too many elements", name);
    const int nc = (int)ncd, nl = (int)nld, base = b->nnode;
    mcs_status st = MCS_OK;
    for (int j = 0; j <= nl && st == MCS_OK; j++)
        for (int k = 0; k < nc && st == MCS_OK; k++) {
            double x[3], th = 2 * M_PI * k / nc;
            to_world(m->axis, 0.5 * m->diameter * cos(th), 0.5 * m->diameter * sin(th),
                     m->length * j / nl, m->origin, x);
            st = fe_builder_add_node(b, x, NULL, err);
        }
    /* (ring angle, axis) runs counter-clockwise about the outward radius */
    for (int j = 0; j < nl && st == MCS_OK; j++)
        for (int k = 0; k < nc && st == MCS_OK; k++) {
            int k1 = (k + 1) % nc;
            st = add_quad(b, ip, base + nc * j + k, base + nc * j + k1, base + nc * (j + 1) + k1,
                          base + nc * (j + 1) + k, 0, err);
        }
    if (m->closed && st == MCS_OK) {
        int *ring = calloc((size_t)nc, sizeof(int));
        if (!ring) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory meshing '%s'", name);
        for (int k = 0; k < nc; k++) ring[k] = base + k;
        st = gen_cap(b, ip, m, 0, ring, nc, 1, err);
        for (int k = 0; k < nc; k++) ring[k] = base + nc * nl + k;
        if (st == MCS_OK) st = gen_cap(b, ip, m, m->length, ring, nc, 0, err);
        free(ring);
    }
    return st;
}

mcs_status fe_mesh_flat_bag(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err)
{
    const char *name = b->part[ip].name;
    if (!(m->size[0] > 0) || !(m->size[1] > 0) || !(m->gap > 0) || !(m->element_size > 0) ||
        !isfinite(m->size[0] + m->size[1] + m->gap + m->element_size))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': mesh: size, gap and element_size must be > 0", name);
    double nud = fmax(2, floor(m->size[0] / m->element_size + 0.5));
    double nvd = fmax(2, floor(m->size[1] / m->element_size + 0.5));
    if (2 * nud * nvd > 5e7)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': mesh: too many elements", name);
    const int nu = (int)nud, nv = (int)nvd, np = (nu + 1) * (nv + 1);
    int *grid = malloc(sizeof(int) * 2 * (size_t)np); /* panel s: node of lattice (i, j) */
    if (!grid) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory meshing '%s'", name);
    mcs_status st = MCS_OK;
    for (int s = 0; s < 2 && st == MCS_OK; s++)
        for (int j = 0; j <= nv && st == MCS_OK; j++)
            for (int i = 0; i <= nu && st == MCS_OK; i++) {
                int edge = i == 0 || j == 0 || i == nu || j == nv, k = i + (nu + 1) * j;
                if (edge && s == 1) {
                    grid[np + k] = grid[k];
                    continue;
                }
                double x[3], w = edge ? 0 : (s ? -0.5 : 0.5) * m->gap;
                to_world(m->axis, m->size[0] * ((double)i / nu - 0.5),
                         m->size[1] * ((double)j / nv - 0.5), w, m->origin, x);
                st = fe_builder_add_node(b, x, &grid[s * np + k], err);
            }
    /* (u, v) counter-clockwise about +axis: the w > 0 panel faces +axis, the other is reversed */
    for (int s = 0; s < 2 && st == MCS_OK; s++)
        for (int j = 0; j < nv && st == MCS_OK; j++)
            for (int i = 0; i < nu && st == MCS_OK; i++) {
                const int *g = grid + s * np, k = i + (nu + 1) * j;
                int c[4] = {g[k], g[k + 1], g[k + nu + 2], g[k + nu + 1]};
                int r = (i == nu - 1 && j == 0) || (i == 0 && j == nv - 1); /* corners */
                st = add_quad(b, ip, c[r], c[r + 1], c[r + 2], c[(r + 3) % 4], s, err);
            }
    free(grid);
    return st;
}

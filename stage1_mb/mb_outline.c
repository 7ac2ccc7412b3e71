/* mb_outline.c: the bodies' contact surfaces as triangle meshes for viewing (mb_model.h
 * mb_outline_write): /stage1/outlines/<body>/{nodes [n,3] m, elements [ne,3] tri3} in the body
 * frame (origin at the centre of gravity, the frame /stage1/bodies/<body>/orientation turns into
 * the world), so that `mcrash export --xdmf` can draw each body where its position and
 * orientation put it. Ellipsoids: a latitude-longitude mesh of the ellipsoid; cylinders (the
 * wheels' tori): the torus; facets: their own triangles; planes (the ground): none. */
#include "core/mcs_results.h"
#include "stage1_mb/mb_geom.h"
#include "stage1_mb/mb_model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { NLON = 12, NLAT = 6, NAROUND = 16, NTUBE = 6 }; /* mesh divisions */

typedef struct {
    double *x; /* (cap x 3) */
    int *t;    /* (tcap x 3) */
    int n, nt, cap, tcap;
} outline;

static int grow(outline *o, int nv, int nt)
{
    if (o->n + nv > o->cap) {
        int c = 2 * (o->n + nv);
        double *x = realloc(o->x, sizeof *x * 3 * (size_t)c);
        if (!x) return -1;
        o->x = x, o->cap = c;
    }
    if (o->nt + nt > o->tcap) {
        int c = 2 * (o->nt + nt);
        int *t = realloc(o->t, sizeof *t * 3 * (size_t)c);
        if (!t) return -1;
        o->t = t, o->tcap = c;
    }
    return 0;
}

static void vert(outline *o, const double p[3])
{
    for (int i = 0; i < 3; i++)
        o->x[3 * o->n + i] = p[i];
    o->n++;
}

static void tri(outline *o, int a, int b, int c)
{
    o->t[3 * o->nt] = a, o->t[3 * o->nt + 1] = b, o->t[3 * o->nt + 2] = c;
    o->nt++;
}

/* a grid of nu x nv vertices (u periodic; v periodic when vper) into triangles */
static void grid_tris(outline *o, int base, int nu, int nv, int vper)
{
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv - 1 + vper; j++) {
            int a = base + i * nv + j, b = base + ((i + 1) % nu) * nv + j;
            int c = base + ((i + 1) % nu) * nv + (j + 1) % nv, d = base + i * nv + (j + 1) % nv;
            tri(o, a, b, c);
            tri(o, a, c, d);
        }
}

static int ellipsoid(outline *o, const mb_surface *s)
{
    /* poles + (NLAT - 1) rings of NLON */
    if (grow(o, 2 + (NLAT - 1) * NLON, 2 * NLON * (NLAT - 1))) return -1;
    const int base = o->n;
    for (int k = 0; k <= NLAT; k++) {
        double th = M_PI * k / NLAT;
        int nring = (k == 0 || k == NLAT) ? 1 : NLON;
        for (int j = 0; j < nring; j++) {
            double ph = 2 * M_PI * j / NLON;
            double u[3] = {s->semi[0] * sin(th) * cos(ph), s->semi[1] * sin(th) * sin(ph),
                           s->semi[2] * cos(th)};
            double p[3];
            for (int i = 0; i < 3; i++)
                p[i] = s->center[i] + s->rot[3 * i] * u[0] + s->rot[3 * i + 1] * u[1] +
                       s->rot[3 * i + 2] * u[2];
            vert(o, p);
        }
    }
    const int top = base, bot = base + 1 + (NLAT - 1) * NLON;
    for (int j = 0; j < NLON; j++) {
        int r0 = base + 1, jn = (j + 1) % NLON, rl = base + 1 + (NLAT - 2) * NLON;
        tri(o, top, r0 + j, r0 + jn);
        tri(o, bot, rl + jn, rl + j);
    }
    for (int k = 0; k < NLAT - 2; k++)
        for (int j = 0; j < NLON; j++) {
            int a = base + 1 + k * NLON + j, b = base + 1 + k * NLON + (j + 1) % NLON;
            tri(o, a, a + NLON, b + NLON);
            tri(o, a, b + NLON, b);
        }
    return 0;
}

/* the torus of crown radius s->radius and tube s->tube about the axis s->normal */
static int torus(outline *o, const mb_surface *s)
{
    if (grow(o, NAROUND * NTUBE, 2 * NAROUND * NTUBE)) return -1;
    const double *a = s->normal;
    double e1[3] = {1, 0, 0};
    if (fabs(a[0]) > 0.9) e1[0] = 0, e1[1] = 1;
    double d = e1[0] * a[0] + e1[1] * a[1] + e1[2] * a[2], n1 = 0;
    for (int i = 0; i < 3; i++)
        e1[i] -= d * a[i], n1 += e1[i] * e1[i];
    n1 = sqrt(n1);
    for (int i = 0; i < 3; i++)
        e1[i] /= n1;
    double e2[3] = {a[1] * e1[2] - a[2] * e1[1], a[2] * e1[0] - a[0] * e1[2],
                    a[0] * e1[1] - a[1] * e1[0]};
    const int base = o->n;
    for (int i = 0; i < NAROUND; i++) {
        double ph = 2 * M_PI * i / NAROUND, c = cos(ph), sn = sin(ph);
        for (int j = 0; j < NTUBE; j++) {
            double ps = 2 * M_PI * j / NTUBE, rr = s->radius + s->tube * cos(ps);
            double p[3];
            for (int k = 0; k < 3; k++)
                p[k] = s->center[k] + rr * (c * e1[k] + sn * e2[k]) + s->tube * sin(ps) * a[k];
            vert(o, p);
        }
    }
    grid_tris(o, base, NAROUND, NTUBE, 1);
    return 0;
}

static int facets(outline *o, const mb_surface *s)
{
    int nv = 0, nt = mb_mesh_ntri(s->mesh);
    const double *v = mb_mesh_vert(s->mesh, &nv);
    if (grow(o, nv, nt)) return -1;
    const int *t = mb_mesh_tri(s->mesh), base = o->n;
    for (int i = 0; i < nv; i++)
        vert(o, v + 3 * i);
    for (int i = 0; i < nt; i++)
        tri(o, base + t[3 * i], base + t[3 * i + 1], base + t[3 * i + 2]);
    return 0;
}

mcs_status mb_outline_write(const mb_model *m, mcs_results *r, mcs_error *err)
{
    outline o = {0};
    mcs_status st = MCS_OK;
    for (int b = 0; b < m->nbody && !st; b++) {
        o.n = o.nt = 0;
        for (int k = 0; k < m->nsurf && !st; k++) {
            const mb_surface *s = &m->surf[k];
            if (s->body != b) continue;
            int bad = s->type == MB_SURF_ELLIPSOID          ? ellipsoid(&o, s)
                      : s->type == MB_SURF_CYLINDER         ? torus(&o, s)
                      : s->type == MB_SURF_FACET && s->mesh ? facets(&o, s)
                                                            : 0;
            if (bad) st = MCS_ERR(err, MCS_ERR_NOMEM, "stage 1 output: out of memory (outlines)");
        }
        if (st || o.nt == 0) continue;
        char path[MB_NAME + 64];
        size_t dn[2] = {(size_t)o.n, 3}, de[2] = {(size_t)o.nt, 3};
        snprintf(path, sizeof path, "/stage%d/outlines/%s/nodes", mb_out_stage(m), m->body_name[b]);
        st = mcs_results_write(r, path, 2, dn, o.x, "m", err);
        snprintf(path, sizeof path, "/stage%d/outlines/%s/elements", mb_out_stage(m),
                 m->body_name[b]);
        if (!st) st = mcs_results_write_int(r, path, 2, de, o.t, "-", err);
        if (!st) st = mcs_results_set_attr_str(r, path, "type", "tri3", err);
    }
    free(o.x);
    free(o.t);
    return st;
}

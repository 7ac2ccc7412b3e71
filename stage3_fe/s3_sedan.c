/* s3_sedan.c: the sedan's side structure in FE (see s3_sedan.h). Placement from the stage-1
 * model's surfaces; the design constants below that the model does not hold carry their
 * source (docs/validation_stage3.md "The sedan side": they are published-class values for a
 * 2011 mid-size sedan, not checked against the NHTSA/NCAC 2011 Accord FE model's own cards). */
#include "stage3_fe/s3_sedan.h"
#include "stage3_fe/s3_model_file.h"

#include "fe/fe_builder_impl.h" /* the body part's given mass properties, set after meshing */
#include "fe/fe_elem.h"         /* fe_shell_frame: the kernel's shell area, so the masses agree */
#include "fe/fe_joint.h"
#include "fe/fe_scn_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- design constants ---- */
#define DOOR_DEPTH 0.10   /* outer skin to inner panel (front doors 100-150 mm) [m] */
#define SKIN_T 0.0007     /* door outer skin, 0.7 mm bake-hardening steel [m] */
#define SKIN_SY 210e6     /* its yield (BH210) [Pa] */
#define INNER_T 0.0008    /* door inner panel, 0.8 mm mild steel [m] */
#define INNER_SY 180e6    /* its yield (DC04-class mild steel) [Pa] */
#define BEAM_D 0.0298     /* side impact beam 31.8 x 2.0 mm tube: mid-surface diameter [m] */
#define BEAM_T 0.0020     /* [m] */
#define BEAM_SY 1000e6    /* ultra-high-strength (martensitic / boron) tube yield [Pa] */
#define BEAM_GAP 0.015    /* beam surface to the outer skin [m] */
#define SILL_DEPTH 0.12   /* rocker section, across the car [m] (height: the stage-1 sill) */
#define SILL_T 0.0016     /* [m] */
#define SILL_SY 590e6     /* DP590-class [Pa] */
#define PILLAR_DEPTH 0.10 /* B-pillar section across the car [m] (width: the stage-1 pillar) */
#define PILLAR_T 0.0016   /* [m] */
#define PILLAR_SY 980e6   /* DP980-class [Pa] */
#define RAIL_DEPTH 0.08   /* roof rail section across the car [m] (height: the stage-1 rail) */
#define RAIL_T 0.0012     /* [m] */
#define RAIL_SY 590e6     /* [Pa] */
#define GLASS_T 0.004     /* tempered soda-lime side glass, 4 mm [m] */
#define GLASS_E 70e9      /* [Pa] */
#define GLASS_SY 120e6    /* tempered glass characteristic bending strength (EN 12150-1) [Pa] */
#define GLASS_FS 0.001    /* plastic strain at erosion: breaks just past its strength [-] */
#define GLASS_NU 0.22
#define GLASS_RHO 2500.0
#define STEEL_E 210e9
#define STEEL_NU 0.3
#define STEEL_RHO 7850.0
#define BODY_T 0.001 /* the rigid body's shells (contact thickness only) [m] */

typedef struct {
    fe_builder *b;
    double h;
    const char *pre;
    const s3_sedan_opts *o;
    int base, n, cap; /* builder index of our first node; our nodes */
    double *x, *m;    /* (cap x 3) positions, (cap) lumped masses of deformable shells */
    char *tied;       /* (cap) 1: an extra node of the rigid body */
    double prho[64], pt[64];
    int prigid[64];
    mcs_error *err;
    mcs_status st;
} gen;

static int divs(double len, double h, int lo)
{
    int n = (int)lround(len / h);
    return n < lo ? lo : n;
}

static int node(gen *g, const double x[3])
{
    if (g->st) return -1;
    if (g->n == g->cap) {
        int cap = g->cap ? 2 * g->cap : 4096;
        double *x2 = realloc(g->x, sizeof(double) * 3 * (size_t)cap);
        if (x2) g->x = x2;
        double *m2 = realloc(g->m, sizeof(double) * (size_t)cap);
        if (m2) g->m = m2;
        char *t2 = realloc(g->tied, (size_t)cap);
        if (t2) g->tied = t2;
        if (!x2 || !m2 || !t2) {
            g->st = MCS_ERR(g->err, MCS_ERR_NOMEM, "sedan_side: out of memory");
            return -1;
        }
        g->cap = cap;
    }
    int idx;
    g->st = fe_builder_add_node(g->b, x, &idx, g->err);
    if (g->st) return -1;
    memcpy(g->x + 3 * g->n, x, 3 * sizeof(double));
    g->m[g->n] = 0, g->tied[g->n] = 0;
    g->n++;
    return idx;
}

static void quad(gen *g, int part, int n0, int n1, int n2, int n3)
{
    if (g->st) return;
    int c[4] = {n0, n1, n2, n3};
    g->st = fe_builder_add_elem(g->b, part, c, g->err);
    if (g->st || g->prigid[part]) return;
    double xe[4][3], fr[3][3], xl[4], yl[4];
    for (int i = 0; i < 4; i++)
        memcpy(xe[i], g->x + 3 * (c[i] - g->base), sizeof xe[i]);
    double mn = g->prho[part] * g->pt[part] * fe_shell_frame(xe, fr, xl, yl) / 4;
    for (int i = 0; i < 4; i++)
        g->m[c[i] - g->base] += mn;
}

typedef enum { M_RIGID, M_PLASTIC, M_ELASTIC } mkind;

static int part(gen *g, const char *comp, mkind k, double t, double rho, double E, double nu,
                double sy)
{
    if (g->st) return -1;
    fe_part_desc d = fe_part_desc_default();
    snprintf(d.name, sizeof d.name, "%.31s_%.31s", g->pre, comp);
    d.mesh.generate = FE_MESH_NONE;
    d.section.type = FE_SECTION_SHELL;
    d.section.thickness = t;
    d.section.integration_points = 3;
    d.material.model = k == M_RIGID     ? FE_MAT_RIGID
                       : k == M_PLASTIC ? FE_MAT_ELASTIC_PLASTIC
                                        : FE_MAT_ELASTIC;
    d.material.density = rho;
    d.material.youngs_modulus = E;
    d.material.poisson = nu;
    d.material.yield_stress = sy;
    memcpy(d.initial_velocity, g->o->velocity, sizeof d.initial_velocity);
    int ip = -1;
    g->st = fe_builder_add_part(g->b, &d, &ip, g->err);
    if (!g->st && ip >= 64) g->st = MCS_ERR(g->err, MCS_ERR_RANGE, "sedan_side: too many parts");
    if (g->st) return -1;
    g->prho[ip] = rho, g->pt[ip] = t, g->prigid[ip] = k == M_RIGID;
    return ip;
}

static void tie(gen *g, int idx)
{
    if (idx >= 0) g->tied[idx - g->base] = 1;
}

/* a plate o + s u + r v (s, r in [0, 1]); its perimeter tied when `edges` */
static void plate(gen *g, int p, const double o[3], const double u[3], const double v[3], int edges)
{
    double lu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    double lv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    int nu = divs(lu, g->h, 2), nv = divs(lv, g->h, 2);
    int first = g->base + g->n;
    for (int j = 0; j <= nv; j++)
        for (int i = 0; i <= nu; i++) {
            double x[3];
            for (int k = 0; k < 3; k++)
                x[k] = o[k] + u[k] * i / nu + v[k] * j / nv;
            int id = node(g, x);
            if (edges && (i == 0 || j == 0 || i == nu || j == nv)) tie(g, id);
        }
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            int a = first + j * (nu + 1) + i;
            quad(g, p, a, a + 1, a + nu + 2, a + nu + 1);
        }
}

/* a closed tube along a (unit) from o, length L, its section the loop sec[0..ns) (offsets
 * normal to a), closed; end rings tied */
static void tube(gen *g, int p, const double o[3], const double a[3], double L,
                 const double (*sec)[3], int ns)
{
    int nl = divs(L, g->h, 2), first = g->base + g->n;
    for (int j = 0; j <= nl; j++)
        for (int i = 0; i < ns; i++) {
            double x[3];
            for (int k = 0; k < 3; k++)
                x[k] = o[k] + a[k] * L * j / nl + sec[i][k];
            int id = node(g, x);
            if (j == 0 || j == nl) tie(g, id);
        }
    for (int j = 0; j < nl; j++)
        for (int i = 0; i < ns; i++) {
            int a0 = first + j * ns + i, a1 = first + j * ns + (i + 1) % ns;
            quad(g, p, a0, a1, a1 + ns, a0 + ns);
        }
}

#define SEC_MAX 256
/* rectangle w along e1 by d along e2, centred: perimeter points at about h */
static int rect_section(double h, const double e1[3], const double e2[3], double w, double d,
                        double (*sec)[3])
{
    int n1 = divs(w, h, 1), n2 = divs(d, h, 1), n = 0;
    double c[4][2] = {{-w / 2, -d / 2}, {w / 2, -d / 2}, {w / 2, d / 2}, {-w / 2, d / 2}};
    int nn[4] = {n1, n2, n1, n2};
    for (int s = 0; s < 4; s++)
        for (int i = 0; i < nn[s] && n < SEC_MAX; i++) {
            double f = (double)i / nn[s];
            double s1 = c[s][0] + f * (c[(s + 1) % 4][0] - c[s][0]);
            double s2 = c[s][1] + f * (c[(s + 1) % 4][1] - c[s][1]);
            for (int k = 0; k < 3; k++)
                sec[n][k] = s1 * e1[k] + s2 * e2[k];
            n++;
        }
    return n;
}

static const mcs_node *find_named(const mcs_node *list, const char *name)
{
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *n = mcs_node_at(list, i);
        const char *s = mcs_node_str(mcs_node_get(n, "name"));
        if (s && strcmp(s, name) == 0) return n;
    }
    return NULL;
}

/* the ellipsoid `name` of body B in world: centre c, semi-axes s */
static mcs_status ellipsoid(const mcs_node *B, const double P[3], const char *name, double c[3],
                            double s[3], mcs_error *err)
{
    const mcs_node *e = find_named(mcs_node_get(B, "surfaces"), name);
    if (!e)
        return mcs_node_error(B, err, MCS_ERR_KEY, "sedan_side: the model has no surface '%s'",
                              name);
    mcs_status st = mcs_node_vec3(mcs_node_get(e, "center"), c, err);
    if (!st) st = mcs_node_vec3(mcs_node_get(e, "semi_axes"), s, err);
    for (int k = 0; k < 3; k++)
        c[k] += P[k];
    return st;
}

static mcs_status total_of(const mcs_node *bodies, s3_sedan_mass *t, mcs_error *err)
{
    memset(t, 0, sizeof *t);
    int nb = mcs_node_len(bodies);
    double mx[3] = {0, 0, 0};
    for (int i = 0; i < nb; i++) {
        const mcs_node *B = mcs_node_at(bodies, i);
        double p[3];
        mcs_status st = mcs_node_vec3(mcs_node_get(B, "position"), p, err);
        if (st) return st;
        double m = mcs_node_num(mcs_node_get(B, "mass"));
        t->mass += m;
        for (int k = 0; k < 3; k++)
            mx[k] += m * p[k];
    }
    if (!(t->mass > 0)) return MCS_ERR(err, MCS_ERR_RANGE, "sedan_side: the model has no mass");
    for (int k = 0; k < 3; k++)
        t->cg[k] = mx[k] / t->mass;
    for (int i = 0; i < nb; i++) {
        const mcs_node *B = mcs_node_at(bodies, i), *I = mcs_node_get(B, "inertia");
        double p[3], r[3];
        mcs_node_vec3(mcs_node_get(B, "position"), p, err);
        if (mcs_node_len(I) != 3)
            return mcs_node_error(I, err, MCS_ERR_KEY,
                                  "sedan_side: give the body inertia as 3 principal values "
                                  "along the world axes");
        double m = mcs_node_num(mcs_node_get(B, "mass")), rr = 0;
        for (int k = 0; k < 3; k++)
            r[k] = p[k] - t->cg[k], rr += r[k] * r[k];
        for (int a = 0; a < 3; a++) {
            t->inertia[a][a] += mcs_node_num(mcs_node_at(I, a));
            for (int c = 0; c < 3; c++)
                t->inertia[a][c] += m * ((a == c) * rr - r[a] * r[c]);
        }
    }
    return MCS_OK;
}

mcs_status s3_sedan_build(fe_builder *b, const mcs_node *model, const s3_sedan_opts *o,
                          s3_sedan_mass *total, mcs_error *err)
{
    /* our nodes follow the builder's (another generator's may come first: plate() numbers
       from base before its first node) */
    gen g = {.b = b, .h = o->element_size, .pre = o->name, .o = o, .err = err,
             .base = fe_builder_nnode(b)};
    const mcs_node *bodies = mcs_node_get(model, "bodies");
    const mcs_node *car = find_named(bodies, "sedan"), *upper = find_named(bodies, "sedan_upper");
    if (!car || !upper)
        return mcs_node_error(model, err, MCS_ERR_KEY,
                              "sedan_side: the model needs bodies 'sedan' and 'sedan_upper'");
    s3_sedan_mass T;
    double P[3], Pu[3], dc[3], ds[3], sc[3], ss[3], pc[3], ps[3], rc[3], rs[3];
    mcs_status st = total_of(bodies, &T, err);
    if (!st) st = mcs_node_vec3(mcs_node_get(car, "position"), P, err);
    if (!st) st = mcs_node_vec3(mcs_node_get(upper, "position"), Pu, err);
    if (!st) st = ellipsoid(car, P, "sedan_front_door", dc, ds, err);
    if (!st) st = ellipsoid(car, P, "sedan_sill", sc, ss, err);
    if (!st) st = ellipsoid(car, P, "sedan_b_pillar", pc, ps, err);
    const mcs_node *gl = find_named(mcs_node_get(upper, "surfaces"), "sedan_side_glass");
    /* the roof rail: the bounding box of sedan_upper's facet surface sedan_roof_rail (its side
     * strip and top), as centre and half extents */
    const mcs_node *rf = find_named(mcs_node_get(upper, "surfaces"), "sedan_roof_rail");
    const mcs_node *rv = mcs_node_get(rf, "vertices");
    if (!st && (!rf || mcs_node_len(rv) < 3))
        st = mcs_node_error(upper, err, MCS_ERR_KEY,
                            "sedan_side: the model needs the facet surface 'sedan_roof_rail'");
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; !st && i < mcs_node_len(rv); i++) {
        double q[3];
        st = mcs_node_vec3(mcs_node_at(rv, i), q, err);
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], q[k] + Pu[k]), hi[k] = fmax(hi[k], q[k] + Pu[k]);
    }
    for (int k = 0; k < 3; k++)
        rc[k] = 0.5 * (lo[k] + hi[k]), rs[k] = 0.5 * (hi[k] - lo[k]);
    double gv[4][3];
    if (!st && (!gl || mcs_node_len(mcs_node_get(gl, "vertices")) != 4))
        st = mcs_node_error(upper, err, MCS_ERR_KEY,
                            "sedan_side: the model needs the 4-vertex facet 'sedan_side_glass'");
    for (int i = 0; !st && i < 4; i++) {
        st = mcs_node_vec3(mcs_node_at(mcs_node_get(gl, "vertices"), i), gv[i], err);
        for (int k = 0; k < 3; k++)
            gv[i][k] += Pu[k];
    }
    if (st) return st;
    if (total) *total = T;

    /* the struck side faces -x: the door skin's outermost x, the door between the hinge end of
     * its ellipsoid and the B-pillar's front face, from the sill's top to the beltline */
    double xo = dc[0] - ds[0], ya = dc[1] - ds[1], yb = fmin(dc[1] + ds[1], pc[1] - ps[1]);
    double zlo = sc[2] + ss[2], zhi = dc[2] + ds[2];
    const double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0}, ez[3] = {0, 0, 1};

    int p_body = part(&g, "body", M_RIGID, BODY_T, STEEL_RHO, STEEL_E, STEEL_NU, 0);
    int p_out = part(&g, "door_outer", M_PLASTIC, SKIN_T, STEEL_RHO, STEEL_E, STEEL_NU, SKIN_SY);
    int p_in = part(&g, "door_inner", M_PLASTIC, INNER_T, STEEL_RHO, STEEL_E, STEEL_NU, INNER_SY);
    int p_beam = part(&g, "door_beam", M_PLASTIC, BEAM_T, STEEL_RHO, STEEL_E, STEEL_NU, BEAM_SY);
    int p_sill = part(&g, "sill", M_PLASTIC, SILL_T, STEEL_RHO, STEEL_E, STEEL_NU, SILL_SY);
    int p_pil = part(&g, "b_pillar", M_PLASTIC, PILLAR_T, STEEL_RHO, STEEL_E, STEEL_NU, PILLAR_SY);
    int p_rail = part(&g, "roof_rail", M_PLASTIC, RAIL_T, STEEL_RHO, STEEL_E, STEEL_NU, RAIL_SY);
    int p_glass = part(&g, "glass", M_PLASTIC, GLASS_T, GLASS_RHO, GLASS_E, GLASS_NU, GLASS_SY);
    if (g.st) return g.st;
    b->part[p_glass].material.failure_strain = GLASS_FS; /* erodes (fe/step/fe_stages.c) */

    /* door panels: perimeters on the body (hinges, latch, frame) */
    double o1[3] = {xo, ya, zlo}, u[3] = {0, yb - ya, 0}, v[3] = {0, 0, zhi - zlo};
    plate(&g, p_out, o1, u, v, 1);
    double o2[3] = {xo + DOOR_DEPTH, ya, zlo};
    plate(&g, p_in, o2, u, v, 1);
    /* the beam at the door's mid-height, BEAM_GAP behind the skin, hinge end to latch end */
    double sec[SEC_MAX][3];
    int nc = divs(M_PI * BEAM_D, g.h, 8);
    for (int i = 0; i < nc && i < SEC_MAX; i++) {
        double t = 2 * M_PI * i / nc;
        sec[i][0] = BEAM_D / 2 * cos(t), sec[i][1] = 0, sec[i][2] = BEAM_D / 2 * sin(t);
    }
    double ob[3] = {xo + BEAM_GAP + BEAM_D / 2, ya, 0.5 * (zlo + zhi)};
    tube(&g, p_beam, ob, ey, yb - ya, (const double(*)[3])sec, nc);
    /* sill along the car: the stage-1 sill's height and length, outer face at its outer x */
    int ns = rect_section(g.h, ex, ez, SILL_DEPTH, 2 * ss[2], sec);
    double os[3] = {sc[0] - ss[0] + SILL_DEPTH / 2, sc[1] - ss[1], sc[2]};
    tube(&g, p_sill, os, ey, 2 * ss[1], (const double(*)[3])sec, ns);
    /* B-pillar, vertical: the stage-1 pillar's width, sill top to roof rail bottom */
    ns = rect_section(g.h, ex, ey, PILLAR_DEPTH, 2 * ps[1], sec);
    double op[3] = {pc[0] - ps[0] + PILLAR_DEPTH / 2, pc[1], zlo};
    tube(&g, p_pil, op, ez, rc[2] - rs[2] - zlo, (const double(*)[3])sec, ns);
    /* roof rail along the car */
    ns = rect_section(g.h, ex, ez, RAIL_DEPTH, 2 * rs[2], sec);
    double orr[3] = {rc[0] - rs[0] + RAIL_DEPTH / 2, rc[1] - rs[1], rc[2]};
    tube(&g, p_rail, orr, ey, 2 * rs[1], (const double(*)[3])sec, ns);
    /* front side glass: the stage-1 glass facet (lower edge v0 v1, upper v3 v2) over the door */
    double f0 = (ya - gv[0][1]) / (gv[1][1] - gv[0][1]),
           f1 = (yb - gv[0][1]) / (gv[1][1] - gv[0][1]);
    double g0[3], gu[3], gw[3];
    for (int k = 0; k < 3; k++) {
        g0[k] = gv[0][k] + f0 * (gv[1][k] - gv[0][k]);
        gu[k] = (f1 - f0) * (gv[1][k] - gv[0][k]);
        gw[k] = gv[3][k] - gv[0][k];
    }
    plate(&g, p_glass, g0, gu, gw, 1);
    /* the rigid rest of the car: a coarse closed box inboard of the door, sill to roof rail */
    double hb = fmax(g.h, 0.25), x0 = xo + DOOR_DEPTH + 0.02, x1 = 2 * P[0] - xo - DOOR_DEPTH;
    double y0 = sc[1] - ss[1], y1 = sc[1] + ss[1], z0 = sc[2] - ss[2], z1 = rc[2] + rs[2];
    double hs = g.h;
    g.h = hb;
    ns = rect_section(hb, ex, ez, x1 - x0, z1 - z0, sec);
    double ox[3] = {0.5 * (x0 + x1), y0, 0.5 * (z0 + z1)};
    int bfirst = g.base + g.n;
    tube(&g, p_body, ox, ey, y1 - y0, (const double(*)[3])sec, ns);
    g.h = hs;
    if (g.st) goto out;

    /* the body's given mass properties: the stage-1 total less the free deformable nodes */
    {
        double mf = 0, mx[3] = {0, 0, 0}, J[3][3] = {{0}};
        int ntied = 0;
        for (int i = 0; i < g.n; i++) {
            if (g.base + i >= bfirst) continue; /* the body's own nodes: the given values */
            if (g.tied[i]) {
                ntied++;
                continue;
            }
            const double *x = g.x + 3 * i;
            double r[3], rr = 0;
            for (int k = 0; k < 3; k++)
                r[k] = x[k] - T.cg[k], rr += r[k] * r[k];
            mf += g.m[i];
            for (int k = 0; k < 3; k++)
                mx[k] += g.m[i] * r[k];
            for (int a = 0; a < 3; a++)
                for (int c = 0; c < 3; c++)
                    J[a][c] += g.m[i] * ((a == c) * rr - r[a] * r[c]);
        }
        fe_rigid_inertia gi = {.given = 1};
        gi.mass = T.mass - mf;
        if (!(gi.mass > 0)) {
            g.st = MCS_ERR(err, MCS_ERR_RANGE, "sedan_side: the side outweighs the car");
            goto out;
        }
        double cr[3], rr = 0; /* the body's CG, from the total's */
        for (int k = 0; k < 3; k++)
            cr[k] = -mx[k] / gi.mass, rr += cr[k] * cr[k];
        for (int k = 0; k < 3; k++)
            gi.cg[k] = T.cg[k] + cr[k];
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++)
                gi.inertia[a][c] =
                    T.inertia[a][c] - J[a][c] - gi.mass * ((a == c) * rr - cr[a] * cr[c]);
        memcpy(gi.velocity, o->velocity, sizeof gi.velocity);
        b->part[p_body].rigid = gi;
        int *tl = malloc(sizeof(int) * (size_t)(ntied ? ntied : 1)), nt = 0;
        if (!tl) {
            g.st = MCS_ERR(err, MCS_ERR_NOMEM, "sedan_side: out of memory");
            goto out;
        }
        for (int i = 0; i < g.n; i++)
            if (g.tied[i] && g.base + i < bfirst) tl[nt++] = g.base + i;
        char bn[FE_NAME_MAX];
        snprintf(bn, sizeof bn, "%.31s_body", g.pre);
        g.st = fe_builder_add_extra_nodes(b, bn, tl, nt, err);
        free(tl);
    }
out:
    free(g.x), free(g.m), free(g.tied);
    return g.st;
}

mcs_status s3_sedan_part(fe_builder *b, const mcs_node *root, const mcs_node *p, mcs_error *err)
{
    (void)root;
    const mcs_node *mesh = mcs_node_get(p, "mesh"), *mf = mcs_node_get(mesh, "model");
    s3_sedan_opts o = {.element_size = mcs_node_num(mcs_node_get(mesh, "element_size"))};
    snprintf(o.name, sizeof o.name, "%s", mcs_node_str(mcs_node_get(p, "name")));
    mcs_status st = MCS_OK;
    if (mcs_node_kind(mcs_node_get(p, "initial_velocity")) != MCS_NODE_NULL)
        st = mcs_node_vec3(mcs_node_get(p, "initial_velocity"), o.velocity, err);
    mcs_scenario *m = NULL;
    if (!st) st = s3_load_model(mf, "sedan", &m, err);
    if (!st) st = s3_sedan_build(b, mcs_scenario_root(m), &o, NULL, err);
    mcs_scenario_destroy(&m);
    return st;
}

void s3_sedan_register(void)
{
    fe_scn_set_generator("sedan_side", s3_sedan_part);
}

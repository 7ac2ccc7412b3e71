/* s3_moto.c: the parametric FE motorcycle (see s3_moto.h). Geometry from the stage-1 model;
 * the design constants below that the model does not hold carry their source. */
#include "stage3_fe/s3_moto.h"
#include "stage3_fe/s3_model_file.h"

#include "fe/fe_contact.h"
#include "fe/fe_elem.h" /* fe_shell_frame: the kernel's shell area, so the masses agree */
#include "fe/fe_joint.h"
#include "fe/fe_restraint.h"
#include "fe/fe_scn_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- design constants (docs/validation_stage3.md "The motorcycle mesh") ---- */
#define STANCHION_D 0.041   /* 43 x 2 mm stanchion, mid-surface diameter (stage-1 fork hinge) */
#define STANCHION_T 0.002   /* [m] */
#define STANCHION_SY 700e6  /* yield stress (stage-1 fork hinge: M_e = pi r^2 t sigma_y) [Pa] */
#define FORK_HALF_SPAN 0.105 /* leg distance from the centre plane (210 mm, sport forks) [m] */
#define SLIDER_D 0.055      /* slider mid-surface diameter [m] */
#define SLIDER_T 0.0025     /* [m] */
#define SLIDER_OVERLAP 0.13 /* stanchion length inside the slider [m] */
#define CLAMP_SPAN 0.15     /* upper to lower triple clamp along the fork [m] */
#define RIM_R 0.2159        /* 17 in rim: bead-seat diameter 431.8 mm (ETRTO) [m] */
#define RIM_W_FRONT 0.089   /* 3.50 in front rim [m] */
#define RIM_W_REAR 0.140    /* 5.50 in rear rim [m] */
#define HUB_R 0.05          /* hub radius [m] */
#define NSPOKE 5            /* cast spokes per wheel [-] */
#define SHOCK_LEVER 0.15    /* shock arm about the swing-arm pivot [m] */
/* mass at each spring end (part of its rigid body: counted in the body's mass). The kernel
 * bounds a spring's step by its end nodes' own masses, 2 m / c and 2 sqrt(m / k): 0.25 kg
 * keeps the shock's 40 kN s/m damper at 12.5 us, above the shells' step */
#define SPRING_END_MASS 0.25
#define SPAR_D 0.06         /* twin-spar tube, mid-surface diameter [m] */
#define SWING_HALF_SPAN 0.12 /* swing-arm legs from the centre plane [m] */
#define STEEL_E 210e9
#define STEEL_RHO 7850.0
#define AL_E 70e9
#define AL_RHO 2700.0
#define ABS_E 2.2e9 /* fairing and seat pan plastic */
#define ABS_RHO 1050.0
#define RUBBER_E 0.1e9 /* tyre carcass (cord-reinforced rubber, effective) */
#define SPOKE_T 0.006  /* cast spoke plate, aluminium (A356-T6 class, sigma_y 200 MPa) [m] */

#define RUBBER_RHO 1100.0
/* tyre inflation, gauge, cold (Kawasaki Ninja ZX-6R 2009 service manual, "Air Pressure (when
 * Cold)", up to 180 kg load: front 250 kPa, rear 290 kPa; a 600 cc sport bike on 120/70 ZR17
 * and 180/55 ZR17 tyres, the sizes of the stage-1 model) [Pa] */
#define TYRE_GAUGE_FRONT 250e3
#define TYRE_GAUGE_REAR 290e3

enum { G_FRAME, G_UPPER, G_DEFORM, G_LOWER, G_FWHEEL, G_SWING, G_RWHEEL, G_N };
static const char *const body_of[G_N] = {"moto_frame",      "moto_upper_fork", "moto_fork_deform",
                                         "moto_lower_fork", "moto_front_wheel", "moto_swing_arm",
                                         "moto_rear_wheel"};
/* the rigid part carrying each body's point masses (NULL: spread on the tubes) */
static const char *const host_of[G_N] = {"frame",       "upper_fork", NULL,       "lower_fork",
                                         "front_wheel", "swing_arm",  "rear_wheel"};

typedef struct {
    double m, mx[3], S[3][3]; /* mass, first moment, sum m x x^T (world) */
} acc;

typedef struct {
    fe_builder *b;
    double h;
    const char *pre;
    const s3_moto_opts *o;
    int base, n, cap; /* builder index of our first node; our nodes */
    double *x;        /* (cap x 3) their positions */
    signed char *grp; /* (cap) their group */
    acc a[G_N];
    double spin_c[G_N][3], spin_w[G_N]; /* wheels: axle centre [m], spin about +y [rad/s] */
    double tyre_r2[G_N];                /* wheels: mean square radius of the tyre's nodes [m^2] */
    double prho[64], pt[64]; /* density and thickness of the builder's parts (by index) */
    mcs_error *err;
    mcs_status st;
} gen;

static void v_axpy(double r[3], const double a[3], double s, const double b[3])
{
    for (int i = 0; i < 3; i++) r[i] = a[i] + s * b[i];
}

static double v_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void v_unit(double a[3])
{
    double n = sqrt(v_dot(a, a));
    for (int i = 0; i < 3; i++) a[i] /= n;
}

/* e1, e2 normal to unit a (right-handed e1 x e2 = a) */
static void normals(const double a[3], double e1[3], double e2[3])
{
    double t[3] = {0, 0, 0};
    int lo = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(a[k]) < fabs(a[lo])) lo = k;
    t[lo] = 1;
    double d = v_dot(t, a);
    for (int i = 0; i < 3; i++) e1[i] = t[i] - d * a[i];
    v_unit(e1);
    e2[0] = a[1] * e1[2] - a[2] * e1[1];
    e2[1] = a[2] * e1[0] - a[0] * e1[2];
    e2[2] = a[0] * e1[1] - a[1] * e1[0];
}

static int divs(double len, double h, int lo)
{
    int n = (int)lround(len / h);
    return n < lo ? lo : n;
}

static int node(gen *g, const double x[3], int grp)
{
    if (g->st) return -1;
    if (g->n == g->cap) {
        int cap = g->cap ? 2 * g->cap : 4096;
        double *x2 = realloc(g->x, sizeof(double) * 3 * (size_t)cap);
        if (x2) g->x = x2;
        signed char *g2 = realloc(g->grp, (size_t)cap);
        if (g2) g->grp = g2;
        if (!x2 || !g2) {
            g->st = MCS_ERR(g->err, MCS_ERR_NOMEM, "motorcycle: out of memory");
            return -1;
        }
        g->cap = cap;
    }
    int idx;
    g->st = fe_builder_add_node(g->b, x, &idx, g->err);
    if (g->st) return -1;
    memcpy(g->x + 3 * g->n, x, 3 * sizeof(double));
    g->grp[g->n++] = (signed char)grp;
    return idx;
}

static void acc_add(acc *a, double m, const double x[3]);
static void node_vel(gen *g, int n, int k);

/* a node with a point mass m (a spring's end on a rigid body: the spring's step needs it) */
static int mass_node(gen *g, const double x[3], int grp, double m)
{
    int n = node(g, x, grp);
    if (g->st) return -1;
    fe_mass_desc md = {0};
    md.node = n, md.mass = m;
    g->st = fe_builder_add_mass(g->b, &md, g->err);
    if (grp >= 0) acc_add(&g->a[grp], m, x);
    node_vel(g, n, grp);
    return n;
}

static const double *xof(const gen *g, int idx) { return g->x + 3 * (idx - g->base); }

/* the initial velocity of our node n (builder index) in group k (-1 none): the motorcycle's,
 * plus a wheel's spin w e_y x r about its axle (a point mass has no part to take it from) */
static void node_vel(gen *g, int n, int k)
{
    const double *V = g->o->velocity, *x = xof(g, n);
    const double w = k >= 0 ? g->spin_w[k] : 0, *c = k >= 0 ? g->spin_c[k] : V;
    if (g->st || (V[0] == 0 && V[1] == 0 && V[2] == 0 && w == 0)) return;
    const double r[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
    const double v[3] = {V[0] + w * r[2], V[1], V[2] - w * r[0]};
    g->st = fe_builder_node_velocity(g->b, n, v, g->err);
}

static void acc_add(acc *a, double m, const double x[3])
{
    a->m += m;
    for (int i = 0; i < 3; i++) {
        a->mx[i] += m * x[i];
        for (int j = 0; j < 3; j++) a->S[i][j] += m * x[i] * x[j];
    }
}

/* a shell (n3 == n2: a triangle), its lumped mass counted as the kernel lumps it */
static void quad(gen *g, int part, int n0, int n1, int n2, int n3)
{
    if (g->st) return;
    int c[4] = {n0, n1, n2, n3};
    g->st = fe_builder_add_elem(g->b, part, c, g->err);
    if (g->st) return;
    double xe[4][3], fr[3][3], xl[4], yl[4];
    for (int i = 0; i < 4; i++) memcpy(xe[i], xof(g, c[i]), sizeof xe[i]);
    double area = fe_shell_frame(xe, fr, xl, yl);
    int nn = n2 == n3 ? 3 : 4;
    double mn = g->prho[part] * g->pt[part] * area / nn;
    for (int i = 0; i < nn; i++) {
        int k = g->grp[c[i] - g->base];
        if (k >= 0) acc_add(&g->a[k], mn, xof(g, c[i]));
    }
}

typedef enum { M_RIGID, M_PLASTIC, M_ELASTIC } mkind;

static int part(gen *g, const char *comp, mkind k, double t, double rho, double E, double sy)
{
    if (g->st) return -1;
    fe_part_desc d = fe_part_desc_default();
    snprintf(d.name, sizeof d.name, "%.31s_%.31s", g->pre, comp);
    d.mesh.generate = FE_MESH_NONE;
    d.section.type = FE_SECTION_SHELL;
    d.section.thickness = t;
    d.section.integration_points = 3;
    d.material.model = k == M_RIGID ? FE_MAT_RIGID : k == M_PLASTIC ? FE_MAT_ELASTIC_PLASTIC
                                                                  : FE_MAT_ELASTIC;
    d.material.density = rho;
    d.material.youngs_modulus = E;
    d.material.poisson = 0.3;
    d.material.yield_stress = sy;
    if (k == M_PLASTIC) { /* linear hardening to 1.2 sigma_y at 20 % plastic strain */
        d.material.nhardening = 2;
        d.material.hardening[0][0] = 0, d.material.hardening[0][1] = sy;
        d.material.hardening[1][0] = 0.2, d.material.hardening[1][1] = 1.2 * sy;
    }
    memcpy(d.initial_velocity, g->o->velocity, sizeof d.initial_velocity);
    int ip = -1;
    g->st = fe_builder_add_part(g->b, &d, &ip, g->err);
    if (!g->st && ip >= 64) g->st = MCS_ERR(g->err, MCS_ERR_RANGE, "motorcycle: too many parts");
    if (g->st) return -1;
    g->prho[ip] = rho, g->pt[ip] = t;
    return ip;
}

/* a circular tube p0 -> p1 of mid-surface diameter D; its end rings into r0, r1 (room for
 * 512); returns the nodes per ring */
static int tube(gen *g, int ip, int grp, const double p0[3], const double p1[3], double D,
                int *r0, int *r1)
{
    double a[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]}, e1[3], e2[3];
    double L = sqrt(v_dot(a, a));
    v_unit(a);
    normals(a, e1, e2);
    int nt = divs(M_PI * D, g->h, 8), nl = divs(L, g->h, 1);
    if (nt > 512) nt = 512;
    int prev[512], cur[512];
    for (int k = 0; k <= nl && !g->st; k++) {
        for (int i = 0; i < nt; i++) {
            double th = 2 * M_PI * i / nt, x[3];
            for (int c = 0; c < 3; c++)
                x[c] = p0[c] + a[c] * L * k / nl + 0.5 * D * (cos(th) * e1[c] + sin(th) * e2[c]);
            cur[i] = node(g, x, grp);
        }
        if (k > 0)
            for (int i = 0; i < nt; i++)
                quad(g, ip, prev[i], prev[(i + 1) % nt], cur[(i + 1) % nt], cur[i]);
        if (k == 0 && r0) memcpy(r0, cur, sizeof(int) * (size_t)nt);
        memcpy(prev, cur, sizeof(int) * (size_t)nt);
    }
    if (r1) memcpy(r1, prev, sizeof(int) * (size_t)nt);
    return nt;
}

/* the surface of a box (centre c, half sizes hs); the nodes of face `face` (0..5: x-, x+, y-,
 * y+, z-, z+; -1 none) into out (room cap); returns their number */
static int box(gen *g, int ip, int grp, const double c[3], const double hs[3], int face,
               int *out, int cap)
{
    int n[3];
    for (int i = 0; i < 3; i++) n[i] = divs(2 * hs[i], g->h, 1);
    size_t tot = (size_t)(n[0] + 1) * (size_t)(n[1] + 1) * (size_t)(n[2] + 1);
    int *id = malloc(sizeof(int) * tot);
    if (!id) {
        g->st = MCS_ERR(g->err, MCS_ERR_NOMEM, "motorcycle: out of memory");
        return 0;
    }
    for (size_t i = 0; i < tot; i++) id[i] = -1;
#define BOX_AT(i, j, k) id[((size_t)(k) * (size_t)(n[1] + 1) + (size_t)(j)) * (size_t)(n[0] + 1) + (size_t)(i)]
    int cnt = 0;
    for (int d = 0; d < 3; d++) {
        int u = (d + 1) % 3, v = (d + 2) % 3;
        for (int s = 0; s < 2; s++)
            for (int iu = 0; iu < n[u]; iu++)
                for (int iv = 0; iv < n[v]; iv++) {
                    int q[4];
                    static const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
                    for (int k = 0; k < 4; k++) {
                        int ijk[3];
                        ijk[d] = s * n[d], ijk[u] = iu + du[k], ijk[v] = iv + dv[k];
                        int *slot = &BOX_AT(ijk[0], ijk[1], ijk[2]);
                        if (*slot < 0) {
                            double x[3];
                            for (int e = 0; e < 3; e++)
                                x[e] = c[e] - hs[e] + 2 * hs[e] * ijk[e] / n[e];
                            *slot = node(g, x, grp);
                        }
                        q[k] = *slot;
                    }
                    if (s) quad(g, ip, q[0], q[1], q[2], q[3]);
                    else quad(g, ip, q[0], q[3], q[2], q[1]);
                }
    }
    if (face >= 0) {
        int d = face / 2, s = face % 2;
        for (size_t i = 0; i < tot; i++) {
            int ijk[3] = {(int)(i % (size_t)(n[0] + 1)),
                          (int)(i / (size_t)(n[0] + 1) % (size_t)(n[1] + 1)),
                          (int)(i / ((size_t)(n[0] + 1) * (size_t)(n[1] + 1)))};
            if (id[i] >= 0 && ijk[d] == s * n[d] && cnt < cap) out[cnt++] = id[i];
        }
    }
#undef BOX_AT
    free(id);
    return cnt;
}

/* a flat rectangle centre c, unit in-plane u, v, half sizes a, b */
static void plate(gen *g, int ip, int grp, const double c[3], const double u[3],
                  const double v[3], double a, double b)
{
    int nu = divs(2 * a, g->h, 1), nv = divs(2 * b, g->h, 1);
    int *id = malloc(sizeof(int) * (size_t)(nu + 1) * (size_t)(nv + 1));
    if (!id) {
        g->st = MCS_ERR(g->err, MCS_ERR_NOMEM, "motorcycle: out of memory");
        return;
    }
    for (int j = 0; j <= nv; j++)
        for (int i = 0; i <= nu; i++) {
            double x[3], su = -a + 2 * a * i / nu, sv = -b + 2 * b * j / nv;
            for (int e = 0; e < 3; e++) x[e] = c[e] + su * u[e] + sv * v[e];
            id[j * (nu + 1) + i] = node(g, x, grp);
        }
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++)
            quad(g, ip, id[j * (nu + 1) + i], id[j * (nu + 1) + i + 1],
                 id[(j + 1) * (nu + 1) + i + 1], id[(j + 1) * (nu + 1) + i]);
    free(id);
}

/* the air in the tyre: a gas bag bounded by the tyre and rim shells (a closed surface), constant
 * gas mass (no inflator, no vent, no leakage), at the gauge pressure above ambient at t = 0 */
static void tyre_gas(gen *g, const char *which, double gauge)
{
    if (g->st) return;
    fe_airbag_desc d = fe_airbag_desc_default();
    snprintf(d.name, sizeof d.name, "%.31s_%s_tyre", g->pre, which);
    d.nparts = 2;
    snprintf(d.parts[0], sizeof d.parts[0], "%.31s_%s_tyre", g->pre, which);
    snprintf(d.parts[1], sizeof d.parts[1], "%.31s_%s_rim", g->pre, which);
    d.initial_pressure = d.gas.ambient_pressure + gauge;
    g->st = fe_builder_add_airbag(g->b, &d, g->err);
}

/* a wheel about the y axis at centre c: rigid hub band and NSPOKE spokes (part `hub`), rim band
 * (radius RIM_R, width wr), tyre (outer radius R, width W) sealed on the rim's edges. The
 * wheel's nodes roll: v = V + w x r, w = (0, V_x / R, 0) */
static void wheel(gen *g, const char *which, int grp, const double c[3], double R, double W,
                  double wr, double gauge)
{
    char nm[FE_NAME_MAX];
    snprintf(nm, sizeof nm, "%s_wheel", which);
    int hub = part(g, nm, M_RIGID, 0.004, AL_RHO, AL_E, 0);
    snprintf(nm, sizeof nm, "%s_rim", which);
    int rim = part(g, nm, M_PLASTIC, 0.004, AL_RHO, AL_E, 200e6);
    snprintf(nm, sizeof nm, "%s_spokes", which);
    int spk = part(g, nm, M_PLASTIC, SPOKE_T, AL_RHO, AL_E, 200e6);
    snprintf(nm, sizeof nm, "%s_tyre", which);
    int tyre = part(g, nm, M_ELASTIC, 0.006, RUBBER_RHO, RUBBER_E, 0);
    if (g->st) return;
    const int first = g->n;
    int nt = divs(2 * M_PI * RIM_R, g->h, 20);
    nt = (nt + NSPOKE - 1) / NSPOKE * NSPOKE;
    const int ny = divs(wr, g->h, 2), nr = divs(RIM_R - HUB_R, g->h, 2);
    const double ar = R - RIM_R;
    const int nk = divs(M_PI * 0.5 * (ar + 0.5 * W), g->h, 6);
    int *rn = malloc(sizeof(int) * (size_t)nt * (size_t)(ny + 1) * 3);
    int *tn = malloc(sizeof(int) * (size_t)nt * (size_t)(nk + 1));
    if (!rn || !tn) {
        free(rn), free(tn);
        g->st = MCS_ERR(g->err, MCS_ERR_NOMEM, "motorcycle: out of memory");
        return;
    }
    int *hn = rn + nt * (ny + 1), *sp = hn + nt * (ny + 1);
    for (int i = 0; i < nt; i++) /* rim and hub bands */
        for (int j = 0; j <= ny; j++) {
            double th = 2 * M_PI * i / nt, y = -0.5 * wr + wr * j / ny;
            double xr[3] = {c[0] + RIM_R * cos(th), c[1] + y, c[2] + RIM_R * sin(th)};
            double xh[3] = {c[0] + HUB_R * cos(th), c[1] + y, c[2] + HUB_R * sin(th)};
            rn[i * (ny + 1) + j] = node(g, xr, grp);
            hn[i * (ny + 1) + j] = node(g, xh, grp);
        }
    for (int i = 0; i < nt; i++)
        for (int j = 0; j < ny; j++) {
            int i1 = (i + 1) % nt;
            quad(g, rim, rn[i * (ny + 1) + j], rn[i1 * (ny + 1) + j], rn[i1 * (ny + 1) + j + 1],
                 rn[i * (ny + 1) + j + 1]);
            quad(g, hub, hn[i * (ny + 1) + j], hn[i * (ny + 1) + j + 1],
                 hn[i1 * (ny + 1) + j + 1], hn[i1 * (ny + 1) + j]);
        }
    for (int s = 0; s < NSPOKE; s++) { /* radial plates hub -> rim, sharing both bands' nodes */
        const int i = s * nt / NSPOKE;
        const double th = 2 * M_PI * i / nt;
        for (int k = 0; k <= nr; k++)
            for (int j = 0; j <= ny; j++) {
                if (k == 0 || k == nr) {
                    sp[k * (ny + 1) + j] = (k ? rn : hn)[i * (ny + 1) + j];
                    continue;
                }
                double r = HUB_R + (RIM_R - HUB_R) * k / nr, y = -0.5 * wr + wr * j / ny;
                double x[3] = {c[0] + r * cos(th), c[1] + y, c[2] + r * sin(th)};
                sp[k * (ny + 1) + j] = node(g, x, grp);
            }
        for (int k = 0; k < nr; k++)
            for (int j = 0; j < ny; j++)
                quad(g, spk, sp[k * (ny + 1) + j], sp[(k + 1) * (ny + 1) + j],
                     sp[(k + 1) * (ny + 1) + j + 1], sp[k * (ny + 1) + j + 1]);
    }
    /* tyre section: r = RIM_R + ar cos(psi), y = sin(psi) (wr/2 + (W - wr)/2 cos(psi)), psi from
       -pi/2 (the rim's y- edge) to pi/2 (its y+ edge) */
    for (int i = 0; i < nt; i++)
        for (int k = 0; k <= nk; k++) {
            if (k == 0 || k == nk) {
                tn[i * (nk + 1) + k] = rn[i * (ny + 1) + (k ? ny : 0)];
                continue;
            }
            double psi = -0.5 * M_PI + M_PI * k / nk, th = 2 * M_PI * i / nt;
            double r = RIM_R + ar * cos(psi), y = sin(psi) * (0.5 * wr + 0.5 * (W - wr) * cos(psi));
            double x[3] = {c[0] + r * cos(th), c[1] + y, c[2] + r * sin(th)};
            tn[i * (nk + 1) + k] = node(g, x, grp);
        }
    for (int i = 0; i < nt; i++)
        for (int k = 0; k < nk; k++) {
            int i1 = (i + 1) % nt;
            quad(g, tyre, tn[i * (nk + 1) + k], tn[i * (nk + 1) + k + 1],
                 tn[i1 * (nk + 1) + k + 1], tn[i1 * (nk + 1) + k]);
        }
    double r2 = 0; /* the tyre's nodes (their rim edges too), for the wheel's ballast */
    for (int i = 0; i < nt * (nk + 1); i++) {
        const double *x = xof(g, tn[i]);
        r2 += ((x[0] - c[0]) * (x[0] - c[0]) + (x[2] - c[2]) * (x[2] - c[2])) / (nt * (nk + 1));
    }
    g->tyre_r2[grp] = r2;
    free(rn), free(tn);
    tyre_gas(g, which, gauge);
    g->spin_w[grp] = g->o->velocity[0] / R; /* rolling: w = v_x / R */
    memcpy(g->spin_c[grp], c, sizeof g->spin_c[grp]);
    if (g->spin_w[grp] != 0)
        for (int n = first; n < g->n && !g->st; n++) node_vel(g, g->base + n, grp);
}

/* ---- the stage-1 model ---- */

typedef struct {
    double m, I[3], c[3];
} s1body;

static const mcs_node *named(const mcs_node *list, const char *name)
{
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *e = mcs_node_at(list, i);
        const char *n = mcs_node_str(mcs_node_get(e, "name"));
        if (n && strcmp(n, name) == 0) return e;
    }
    return NULL;
}

static const mcs_node *need(const mcs_node *list, const char *name, const mcs_node *at,
                            gen *g)
{
    const mcs_node *e = named(list, name);
    if (!e && !g->st)
        g->st = mcs_node_error(at, g->err, MCS_ERR_KEY, "motorcycle model: no '%s'", name);
    return e;
}

static void vec(gen *g, const mcs_node *e, const char *key, double v[3])
{
    v[0] = v[1] = v[2] = 0;
    if (!g->st && e) g->st = mcs_node_vec3(mcs_node_get(e, key), v, g->err);
}

/* the ellipsoid `name` of the frame body: centre (world) and semi-axes */
static void surface(gen *g, const mcs_node *body, const double pos[3], const char *name,
                    double c[3], double s[3])
{
    const mcs_node *e = need(mcs_node_get(body, "surfaces"), name, body, g);
    vec(g, e, "center", c);
    vec(g, e, "semi_axes", s);
    for (int i = 0; i < 3; i++) c[i] += pos[i];
}

/* a spring on the fe builder: F(d) (tension positive) from a stage-1 loading curve L(s) above
 * preload P in compression (d = -s lever) and a top-out T(e) in extension (d = e lever), both
 * divided by `share`, forces by lever: F = -(P + L(s)) / (lever share), (T(e) - P) / (...) */
static void spring(gen *g, const char *name, int n0, int n1, const mcs_node *ch,
                   const char *load, const char *topout, double P, double lever, double share)
{
    if (g->st) return;
    fe_spring_desc d = {0};
    snprintf(d.name, sizeof d.name, "%.31s_%.31s", g->pre, name);
    d.end[0].node = n0, d.end[1].node = n1;
    const mcs_node *L = mcs_node_get(ch, load), *T = mcs_node_get(ch, topout);
    if (!L || !T) {
        g->st = mcs_node_error(ch, g->err, MCS_ERR_KEY, "motorcycle model: no '%s' or '%s'",
                               load, topout);
        return;
    }
    double x[FE_CURVE_MAX], y[FE_CURVE_MAX], xt[FE_CURVE_MAX], yt[FE_CURVE_MAX];
    int nl = mcs_node_curve_len(mcs_node_get(L, "loading"));
    int nt = mcs_node_curve_len(mcs_node_get(T, "loading"));
    if (nl + nt - 1 > FE_CURVE_MAX || nl < 2 || nt < 2) {
        g->st = mcs_node_error(L, g->err, MCS_ERR_RANGE, "motorcycle: suspension curve: 2..%d "
                               "points", FE_CURVE_MAX / 2);
        return;
    }
    g->st = mcs_node_curve(mcs_node_get(L, "loading"), x, y, FE_CURVE_MAX, g->err);
    if (!g->st) g->st = mcs_node_curve(mcs_node_get(T, "loading"), xt, yt, FE_CURVE_MAX, g->err);
    if (g->st) return;
    int k = 0;
    for (int i = nl - 1; i >= 0; i--, k++)
        d.curve[k][0] = -x[i] * lever, d.curve[k][1] = -(P + y[i]) / (lever * share);
    for (int i = 1; i < nt; i++, k++)
        d.curve[k][0] = xt[i] * lever, d.curve[k][1] = (yt[i] - P) / (lever * share);
    d.ncurve = k;
    d.damping = mcs_node_num_or(L, "damping", 0) / (lever * lever * share);
    g->st = fe_builder_add_spring(g->b, &d, g->err);
}

static void joint(gen *g, const char *name, fe_joint_type type, const char *a, const char *b,
                  const double p[3], const double ax[3], const mcs_node *at)
{
    if (g->st) return;
    fe_joint_desc j = fe_joint_desc_default();
    snprintf(j.name, sizeof j.name, "%.31s_%.31s", g->pre, name);
    j.type = type;
    snprintf(j.body[0], sizeof j.body[0], "%.31s_%.31s", g->pre, a);
    snprintf(j.body[1], sizeof j.body[1], "%.31s_%.31s", g->pre, b);
    memcpy(j.point, p, sizeof j.point);
    memcpy(j.axis, ax, sizeof j.axis);
    (void)at; /* the model file's nodes are freed before the model is made */
    const mcs_node *w = g->o->at;
    if (w) j.file = mcs_node_file(w), j.line = mcs_node_line(w), j.col = mcs_node_col(w);
    g->st = fe_builder_add_joint(g->b, &j, g->err);
}

/* a two-surface contact between the parts <pre>_<a[i]> and <pre>_<b[j]> */
static void contact(gen *g, const char *name, const char *const *a, int na, const char *const *b,
                    int nb, double mu)
{
    if (g->st) return;
    fe_contact_desc d = fe_contact_desc_default();
    snprintf(d.name, sizeof d.name, "%.31s_%.31s", g->pre, name);
    d.type = FE_CONTACT_TWO_SURFACE;
    d.nslave = na, d.nmaster = nb, d.friction = mu;
    for (int i = 0; i < na; i++) snprintf(d.slave[i], FE_NAME_MAX, "%.31s_%.31s", g->pre, a[i]);
    for (int i = 0; i < nb; i++) snprintf(d.master[i], FE_NAME_MAX, "%.31s_%.31s", g->pre, b[i]);
    g->st = fe_builder_add_contact(g->b, &d, g->err);
}

static void nrb(gen *g, const char *name, const int *nodes, int n)
{
    char nm[FE_NAME_MAX];
    snprintf(nm, sizeof nm, "%.31s_%.31s", g->pre, name);
    if (!g->st) g->st = fe_builder_add_nodal_rigid_body(g->b, nm, nodes, n, g->err);
}

static void extra(gen *g, const char *host, const int *nodes, int n)
{
    char nm[FE_NAME_MAX];
    snprintf(nm, sizeof nm, "%.31s_%.31s", g->pre, host);
    if (!g->st) g->st = fe_builder_add_extra_nodes(g->b, nm, nodes, n, g->err);
}

/* six point masses on host making the group's mass, centre and inertia those of body s */
/* a wheel's missing mass spread on its rim band (radius RIM_R) and its tyre's nodes (mean
 * square radius tyre_r2), split so that the spin inertia about the axle is the stage-1 body's
 * Iyy: m_r RIM_R^2 + m_t tyre_r2 = Iyy - the mesh's, m_r + m_t = the rest of the mass (rubber
 * and rim metal the shells' thicknesses leave out); both are rings about the axle, so the centre
 * stays there (the stage-1 wheel's). Not six rigid point masses: they would sit near the tyre's
 * radius and strike a wall as rigid points. Ixx = Izz follow from the rings (not matched) */
static void wheel_ballast(gen *g, int k, const s1body *s, const char *which, const mcs_node *at)
{
    if (g->st) return;
    const acc *a = &g->a[k];
    const double mb = s->m - a->m, *c = s->c, rt2 = g->tyre_r2[k], rr2 = RIM_R * RIM_R;
    double iy = 0; /* the mesh's spin inertia about the axle (y through c) */
    for (int i = 0; i < 3; i += 2) iy += a->S[i][i] - 2 * c[i] * a->mx[i] + a->m * c[i] * c[i];
    const double mt = (s->I[1] - iy - mb * rr2) / (rt2 - rr2);
    if (!(mb > 0) || !(rt2 > rr2) || mt < 0 || mt > mb) {
        g->st = mcs_node_error(at, g->err, MCS_ERR_RANGE,
                               "motorcycle: the %s wheel's mesh (%.3g kg, spin inertia %.3g kg "
                               "m^2) cannot be brought to the stage-1 body's %.3g kg, %.3g kg m^2",
                               which, a->m, iy, s->m, s->I[1]);
        return;
    }
    const char *band[2] = {"tyre", "rim"};
    const double mass[2] = {mt, mb - mt};
    for (int i = 0; i < 2 && !g->st; i++) {
        if (!(mass[i] > 0)) continue;
        fe_mass_desc md = {0};
        md.node = -1, md.where = FE_WHERE_ALL, md.mass = mass[i];
        snprintf(md.part, sizeof md.part, "%.31s_%.15s_%.15s", g->pre, which, band[i]);
        g->st = fe_builder_add_mass(g->b, &md, g->err);
    }
}

static void ballast(gen *g, int k, const s1body *s, const mcs_node *at)
{
    if (g->st) return;
    const acc *a = &g->a[k];
    const double mb = s->m - a->m;
    if (!(mb > 0)) {
        g->st = mcs_node_error(at, g->err, MCS_ERR_RANGE,
                               "motorcycle: the mesh of '%s' weighs %.3g kg, more than the "
                               "stage-1 body's %.3g kg",
                               body_of[k], a->m, s->m);
        return;
    }
    double cb[3], d[3], J[3], Ib[3];
    for (int i = 0; i < 3; i++) cb[i] = (s->m * s->c[i] - a->mx[i]) / mb, d[i] = cb[i] - s->c[i];
    /* the mesh's inertia about the target centre: sum m (|r|^2 - r_i^2), r = x - c */
    double rr[3];
    for (int i = 0; i < 3; i++)
        rr[i] = a->S[i][i] - 2 * s->c[i] * a->mx[i] + a->m * s->c[i] * s->c[i];
    for (int i = 0; i < 3; i++) {
        J[i] = rr[(i + 1) % 3] + rr[(i + 2) % 3];
        Ib[i] = s->I[i] - J[i] - mb * (v_dot(d, d) - d[i] * d[i]); /* about cb */
    }
    int nodes[6];
    char host[FE_NAME_MAX];
    snprintf(host, sizeof host, "%.40s", host_of[k]);
    for (int i = 0; i < 3; i++) {
        double si = 0.5 * (Ib[(i + 1) % 3] + Ib[(i + 2) % 3] - Ib[i]); /* sum m x_i^2 */
        double r = sqrt(fmax(si, 0) / (mb / 3));
        for (int sg = 0; sg < 2; sg++) {
            double x[3] = {cb[0], cb[1], cb[2]};
            x[i] += sg ? r : -r;
            nodes[2 * i + sg] = node(g, x, -1);
            if (g->st) return;
            fe_mass_desc md = {0};
            md.node = nodes[2 * i + sg], md.mass = mb / 6;
            g->st = fe_builder_add_mass(g->b, &md, g->err);
            node_vel(g, nodes[2 * i + sg], k);
            if (g->st) return;
        }
    }
    extra(g, host, nodes, 6);
}

static void body(gen *g, const mcs_node *bodies, int k, const mcs_node *at, s1body *s)
{
    const mcs_node *e = need(bodies, body_of[k], at, g);
    if (g->st) return;
    s->m = mcs_node_num(mcs_node_get(e, "mass"));
    vec(g, e, "inertia", s->I);
    vec(g, e, "position", s->c);
}

static void jpoint(gen *g, const mcs_node *joints, const char *name, const mcs_node *at,
                   double p[3], double ax[3])
{
    const mcs_node *e = need(joints, name, at, g);
    vec(g, e, "anchor", p);
    if (ax) {
        vec(g, e, "axis", ax);
        if (!g->st) v_unit(ax);
    }
}

static double jpreload(const mcs_node *joints, const char *name)
{
    return mcs_node_num_or(named(joints, name), "preload", 0);
}

static void build(gen *g, const mcs_node *root)
{
    const mcs_node *bodies = mcs_node_get(root, "bodies"), *joints = mcs_node_get(root, "joints");
    const mcs_node *ch = mcs_node_get(root, "characteristics");
    s1body s[G_N];
    for (int k = 0; k < G_N; k++) body(g, bodies, k, root, &s[k]);
    double S[3], as[3], K[3], U[3], Af[3], P[3], Ar[3], tmp[3];
    jpoint(g, joints, "moto_steering", root, S, as);
    jpoint(g, joints, "moto_fork_deformation", root, K, NULL);
    jpoint(g, joints, "moto_front_suspension", root, U, tmp);
    jpoint(g, joints, "moto_front_axle", root, Af, NULL);
    jpoint(g, joints, "moto_swing_arm_pivot", root, P, NULL);
    jpoint(g, joints, "moto_rear_axle", root, Ar, NULL);
    const mcs_node *fb = named(bodies, "moto_frame"), *fw = named(bodies, "moto_front_wheel");
    const mcs_node *rw = named(bodies, "moto_rear_wheel"), *ub = named(bodies, "moto_upper_fork");
    const mcs_node *ft = need(mcs_node_get(fw, "surfaces"), "front_tyre", root, g);
    const mcs_node *rt = need(mcs_node_get(rw, "surfaces"), "rear_tyre", root, g);
    double ce[3], se[3], ct[3], st_[3], cs[3], ss[3], cf[3], sf[3], hb[3], hbs[3];
    surface(g, fb, s[G_FRAME].c, "engine", ce, se);
    surface(g, fb, s[G_FRAME].c, "tank", ct, st_);
    surface(g, fb, s[G_FRAME].c, "seat", cs, ss);
    surface(g, fb, s[G_FRAME].c, "fairing_nose", cf, sf);
    surface(g, ub, s[G_UPPER].c, "handlebar_left", hb, hbs);
    if (g->st) return;
    const double Rf = mcs_node_num(mcs_node_get(ft, "radius"));
    const double Wf = mcs_node_num(mcs_node_get(ft, "length"));
    const double Rr = mcs_node_num(mcs_node_get(rt, "radius"));
    const double Wr = mcs_node_num(mcs_node_get(rt, "length"));
    const double ey[3] = {0, 1, 0};
    int ring[4][512], face[8192], nf;

    /* frame: rigid engine, steering head, spars, tank, seat, fairing */
    int pe = part(g, "frame", M_RIGID, 0.003, AL_RHO, AL_E, 0);
    double he[3] = {0.8 * se[0], 0.8 * se[1], 0.8 * se[2]};
    box(g, pe, G_FRAME, ce, he, -1, NULL, 0);
    int head[8192], nh = 0;
    int ph = part(g, "head_tube", M_PLASTIC, 0.004, STEEL_RHO, STEEL_E, 350e6);
    double h0[3], h1[3];
    v_axpy(h0, S, -0.09, as), v_axpy(h1, S, 0.09, as);
    const int nh0 = g->n;
    tube(g, ph, G_FRAME, h0, h1, 0.06, NULL, NULL);
    for (int n = nh0; n < g->n && nh < 4096; n++) head[nh++] = g->base + n;
    for (int side = -1; side <= 1; side += 2) {
        char nm[16];
        snprintf(nm, sizeof nm, "frame_%c", side < 0 ? 'r' : 'l');
        int pt = part(g, nm, M_PLASTIC, 0.003, AL_RHO, AL_E, 250e6);
        double p0[3] = {S[0] - 0.06, side * 0.10, S[2] - 0.04};
        double p1[3] = {P[0] + 0.06, side * 0.10, P[2] + 0.10};
        int n = tube(g, pt, G_FRAME, p0, p1, SPAR_D, ring[0], ring[1]);
        for (int i = 0; i < n && nh < 8192; i++) head[nh++] = ring[0][i];
        extra(g, "frame", ring[1], n);
    }
    int pf = part(g, "fairing", M_PLASTIC, 0.003, ABS_RHO, ABS_E, 40e6);
    double hf[3] = {0.8 * sf[0], 0.8 * sf[1], 0.8 * sf[2]};
    nf = box(g, pf, G_FRAME, cf, hf, 0, face, 8192);
    for (int i = 0; i < nf && nh < 8192; i++) head[nh++] = face[i];
    nrb(g, "head", head, nh);
    int pk = part(g, "tank", M_PLASTIC, 0.0008, STEEL_RHO, STEEL_E, 200e6);
    double hk[3] = {0.8 * st_[0], 0.8 * st_[1], 0.8 * st_[2]};
    nf = box(g, pk, G_FRAME, ct, hk, 4, face, 8192);
    extra(g, "frame", face, nf);
    int pst = part(g, "seat", M_PLASTIC, 0.003, ABS_RHO, ABS_E, 40e6);
    double hs_[3] = {0.8 * ss[0], 0.8 * ss[1], 0.8 * ss[2]};
    nf = box(g, pst, G_FRAME, cs, hs_, 4, face, 8192);
    extra(g, "frame", face, nf);
    if (g->st) return;

    /* upper fork: rigid clamps, upper stanchions, clip-ons */
    double T[3], e1[3], e2[3], fwd[3];
    v_axpy(T, K, CLAMP_SPAN, as);
    normals(as, e1, e2);
    for (int i = 0; i < 3; i++) fwd[i] = 0;
    /* the clamps' long side across (y), short side fore-aft in the plane normal to the axis */
    double cx[3] = {as[2], 0, -as[0]}; /* in the x-z plane, normal to as */
    v_unit(cx);
    int pu = part(g, "upper_fork", M_RIGID, 0.012, AL_RHO, AL_E, 0);
    for (int c = 0; c < 2; c++) {
        const double *q = c ? T : K;
        double pc[3];
        v_axpy(pc, q, -0.02, cx); /* between the steering axis and the legs */
        plate(g, pu, G_UPPER, pc, cx, ey, 0.035, FORK_HALF_SPAN + 0.025);
    }
    for (int side = -1; side <= 1; side += 2) {
        double a0[3] = {K[0], K[1] + side * FORK_HALF_SPAN, K[2]};
        double a1[3] = {T[0], T[1] + side * FORK_HALF_SPAN, T[2]};
        tube(g, pu, G_UPPER, a0, a1, STANCHION_D, NULL, NULL);
        double b0[3] = {T[0], T[1] + side * FORK_HALF_SPAN, T[2]};
        double b1[3] = {hb[0], side * hb[1], hb[2]};
        tube(g, pu, G_UPPER, b0, b1, 0.022, NULL, NULL);
    }
    (void)fwd;

    /* fork legs: stanchions (the stage-1 fork-deformation body), sliders, axle */
    double Cd[3];
    memcpy(Cd, s[G_DEFORM].c, sizeof Cd);
    double dK[3] = {K[0] - Cd[0], K[1] - Cd[1], K[2] - Cd[2]};
    const double Ls = 2 * v_dot(dK, as); /* its centre at the stage-1 body's */
    double t = v_dot((double[3]){Af[0] - K[0], Af[1] - K[1], Af[2] - K[2]}, as);
    int pl = part(g, "lower_fork", M_RIGID, 0.003, STEEL_RHO, STEEL_E, 0);
    double ax0[3] = {Af[0], Af[1] - FORK_HALF_SPAN, Af[2]};
    double ax1[3] = {Af[0], Af[1] + FORK_HALF_SPAN, Af[2]};
    tube(g, pl, G_LOWER, ax0, ax1, 0.025, NULL, NULL);
    char stn[2][FE_NAME_MAX];
    for (int side = -1; side <= 1; side += 2) {
        const char sc = side < 0 ? 'r' : 'l';
        char nm[32];
        snprintf(nm, sizeof nm, "stanchion_%c", sc);
        snprintf(stn[side > 0], sizeof stn[0], "%.31s_%.31s", g->pre, nm);
        int pss = part(g, nm, M_PLASTIC, STANCHION_T, STEEL_RHO, STEEL_E, STANCHION_SY);
        double k0[3] = {K[0], K[1] + side * FORK_HALF_SPAN, K[2]}, k1[3], sb[3];
        v_axpy(k1, k0, -Ls, as);
        int n = tube(g, pss, G_DEFORM, k0, k1, STANCHION_D, ring[0], ring[1]);
        extra(g, "upper_fork", ring[0], n);
        int cn = mass_node(g, k1, G_DEFORM, SPRING_END_MASS); /* the spring's upper end, on the axis */
        ring[1][n] = cn;
        snprintf(nm, sizeof nm, "stanchion_bot_%c", sc);
        nrb(g, nm, ring[1], n + 1);
        snprintf(nm, sizeof nm, "slider_%c", sc);
        int psl = part(g, nm, M_PLASTIC, SLIDER_T, AL_RHO, AL_E, 250e6);
        double s0[3], s1[3];
        v_axpy(s0, k0, -(Ls - SLIDER_OVERLAP), as);
        v_axpy(s1, k0, t, as); /* level with the axle */
        int m = tube(g, psl, G_LOWER, s0, s1, SLIDER_D, ring[2], ring[3]);
        snprintf(nm, sizeof nm, "slider_top_%c", sc);
        nrb(g, nm, ring[2], m);
        ring[3][m] = mass_node(g, s1, G_LOWER, SPRING_END_MASS); /* the spring's lower end */
        extra(g, "lower_fork", ring[3], m + 1);
        snprintf(nm, sizeof nm, "fork_spring_%c", sc);
        spring(g, nm, cn, ring[3][m], ch, "susp_front", "susp_front_topout",
               jpreload(joints, "moto_front_suspension"), 1, 2);
        char jn[32], ja[32], jb[32];
        snprintf(jn, sizeof jn, "front_suspension_%c", sc);
        snprintf(ja, sizeof ja, "stanchion_bot_%c", sc);
        snprintf(jb, sizeof jb, "slider_top_%c", sc);
        memcpy(sb, k1, sizeof sb);
        joint(g, jn, FE_JOINT_TRANSLATIONAL, jb, ja, sb, as, root);
    }
    if (g->st) return;

    /* wheels, swing arm, shock */
    wheel(g, "front", G_FWHEEL, Af, Rf, Wf, RIM_W_FRONT, TYRE_GAUGE_FRONT);
    wheel(g, "rear", G_RWHEEL, Ar, Rr, Wr, RIM_W_REAR, TYRE_GAUGE_REAR);
    int pw = part(g, "swing_arm", M_RIGID, 0.003, AL_RHO, AL_E, 0);
    for (int side = -1; side <= 1; side += 2) {
        double a0[3] = {P[0], side * SWING_HALF_SPAN, P[2]};
        double a1[3] = {Ar[0], side * SWING_HALF_SPAN, Ar[2]};
        tube(g, pw, G_SWING, a0, a1, 0.05, NULL, NULL);
    }
    double c0[3] = {P[0], -SWING_HALF_SPAN, P[2]}, c1[3] = {P[0], SWING_HALF_SPAN, P[2]};
    tube(g, pw, G_SWING, c0, c1, 0.05, NULL, NULL);
    double arm[3] = {Ar[0] - P[0], 0, Ar[2] - P[2]}, up[3];
    v_unit(arm);
    up[0] = -arm[2], up[1] = 0, up[2] = arm[0]; /* normal to the arm in x-z */
    if (up[2] < 0)
        for (int i = 0; i < 3; i++) up[i] = -up[i];
    double q0[3], q1[3];
    v_axpy(q0, P, SHOCK_LEVER, arm);
    v_axpy(q1, q0, 0.3, up);
    int sq0 = mass_node(g, q0, G_SWING, SPRING_END_MASS);
    int sq1 = mass_node(g, q1, G_FRAME, SPRING_END_MASS);
    extra(g, "swing_arm", &sq0, 1);
    extra(g, "frame", &sq1, 1);
    spring(g, "shock", sq1, sq0, ch, "susp_rear", "susp_rear_topout",
           jpreload(joints, "moto_swing_arm_pivot"), SHOCK_LEVER, 1);

    /* joints (the stage-1 model's points and axes) */
    joint(g, "steering", FE_JOINT_REVOLUTE, "upper_fork", "head", S, as, root);
    joint(g, "front_axle", FE_JOINT_REVOLUTE, "front_wheel", "lower_fork", Af, ey, root);
    joint(g, "swing_arm_pivot", FE_JOINT_REVOLUTE, "swing_arm", "frame", P, ey, root);
    joint(g, "rear_axle", FE_JOINT_REVOLUTE, "rear_wheel", "swing_arm", Ar, ey, root);

    /* the front wheel against the engine and fairing (stage 1's moto_front_wheel_engine):
     * steel/aluminium on rubber and metal, friction 0.3 (assumed) */
    static const char *const wh[] = {"front_tyre", "front_rim", "front_spokes", "front_wheel"};
    static const char *const en[] = {"frame", "fairing"};
    contact(g, "wheel_engine", wh, 4, en, 2, 0.3);

    /* masses: six point masses per rigid body; the fork-deformation body's rest on its tubes */
    for (int k = 0; k < G_N && !g->st; k++) {
        if (k == G_FWHEEL || k == G_RWHEEL) {
            wheel_ballast(g, k, &s[k], k == G_FWHEEL ? "front" : "rear", root);
            continue;
        }
        if (host_of[k]) {
            ballast(g, k, &s[k], root);
            continue;
        }
        const double mb = s[k].m - g->a[k].m;
        for (int side = 0; side < 2 && !g->st && mb > 0; side++) {
            fe_mass_desc md = {0};
            md.node = -1, md.where = FE_WHERE_ALL, md.mass = 0.5 * mb;
            memcpy(md.part, stn[side], sizeof md.part);
            g->st = fe_builder_add_mass(g->b, &md, g->err);
        }
    }
}

mcs_status s3_moto_build(fe_builder *b, const mcs_node *model, const s3_moto_opts *o,
                         mcs_error *err)
{
    if (!(o->element_size > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "motorcycle: element_size must be > 0");
    gen g = {.b = b, .h = o->element_size, .pre = o->name, .o = o, .err = err};
    g.base = fe_builder_nnode(b);
    build(&g, model);
    free(g.x);
    free(g.grp);
    return g.st;
}

mcs_status s3_moto_part(fe_builder *b, const mcs_node *root, const mcs_node *p, mcs_error *err)
{
    (void)root;
    const mcs_node *mesh = mcs_node_get(p, "mesh"), *mf = mcs_node_get(mesh, "model");
    s3_moto_opts o = {.element_size = mcs_node_num(mcs_node_get(mesh, "element_size")), .at = p};
    snprintf(o.name, sizeof o.name, "%s", mcs_node_str(mcs_node_get(p, "name")));
    mcs_status st = MCS_OK;
    if (mcs_node_kind(mcs_node_get(p, "initial_velocity")) != MCS_NODE_NULL)
        st = mcs_node_vec3(mcs_node_get(p, "initial_velocity"), o.velocity, err);
    mcs_scenario *m = NULL;
    if (!st) st = s3_load_model(mf, "motorcycle", &m, err);
    if (!st) st = s3_moto_build(b, mcs_scenario_root(m), &o, err);
    mcs_scenario_destroy(&m);
    return st;
}

void s3_moto_register(void)
{
    fe_scn_set_generator("motorcycle", s3_moto_part);
}

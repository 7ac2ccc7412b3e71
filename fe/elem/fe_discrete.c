/* fe_discrete: 2-node discrete springs and dampers and point masses (what users know as
 * LS-DYNA *ELEMENT_DISCRETE with *MAT_SPRING_ELASTIC / *MAT_SPRING_NONLINEAR_ELASTIC /
 * *MAT_DAMPER_VISCOUS, and *ELEMENT_MASS).
 *
 * A spring acts along the line of its two ends (a node, or a fixed anchor point):
 *     F = k (l - l0)  or  F = curve(l - l0)  (tension positive; the curve's end segments
 *     continue linearly),  plus a damper F_d = c dl/dt,
 * with l0 the length at t = 0 and dl/dt = (v_b - v_a).e from the velocities at t - dt/2 (as the
 * elements' strain rates). Elastic energy and damper dissipation are summed with the
 * trapezoidal rule over the elongation increments, like the element stress power.
 * Stable step of a spring (central differences, Belytschko, Liu & Moran 2000, Sec. 6.3):
 *     dt = (2 / w) (sqrt(1 + z^2) - z),  w^2 = k (1/m_a + 1/m_b),  z = c / (2 mu w), 1/mu = 1/m_a + 1/m_b,
 * with k the largest slope of a tabulated curve. A point mass adds to the lumped mass of its
 * node(s); a node may carry a mass and no element (a spring-mass system). */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int grow_to(void **p, int *cap, int need, size_t sz)
{
    if (need <= *cap) return 0;
    int nc = *cap ? 2 * *cap : 8;
    while (nc < need) nc *= 2;
    void *q = realloc(*p, (size_t)nc * sz);
    if (!q) return -1;
    *p = q;
    *cap = nc;
    return 0;
}

mcs_status fe_builder_add_spring(fe_builder *b, const fe_spring_desc *d, mcs_error *err)
{
    const char *n = d->name[0] ? d->name : "(unnamed)";
    if (!(d->stiffness >= 0) || !(d->damping >= 0) || !isfinite(d->stiffness) ||
        !isfinite(d->damping))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: spring '%s': stiffness and damping must be >= 0",
                       n);
    if (d->ncurve < 0 || d->ncurve > FE_CURVE_MAX || d->ncurve == 1)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: spring '%s': curve needs 2..%d points", n,
                       FE_CURVE_MAX);
    for (int i = 0; i < d->ncurve; i++)
        if (!isfinite(d->curve[i][0]) || !isfinite(d->curve[i][1]) ||
            (i > 0 && !(d->curve[i][0] > d->curve[i - 1][0])))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: spring '%s': curve point %d: elongations must be finite and "
                           "increasing",
                           n, i);
    if (d->ncurve == 0 && d->stiffness == 0 && d->damping == 0)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: spring '%s': needs stiffness, curve or damping",
                       n);
    for (int e = 0; e < 2; e++) {
        const fe_spring_end *x = &d->end[e];
        if (x->node >= b->nnode)
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: spring '%s': node %d does not exist", n,
                           x->node);
        for (int i = 0; i < 3; i++)
            if (!isfinite(x->point[i]))
                return MCS_ERR(err, MCS_ERR_RANGE, "fe: spring '%s': point is not finite", n);
    }
    if (grow_to((void **)&b->spring, &b->cap_spring, b->nspring + 1, sizeof *b->spring))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding spring '%s'", n);
    b->spring[b->nspring++] = *d;
    return MCS_OK;
}

mcs_status fe_builder_add_mass(fe_builder *b, const fe_mass_desc *d, mcs_error *err)
{
    if (!(d->mass > 0) || !isfinite(d->mass))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: point mass: mass must be > 0, got %g kg",
                       d->mass);
    if (d->node >= b->nnode)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: point mass: node %d does not exist", d->node);
    if (grow_to((void **)&b->mass, &b->cap_mass, b->nmass + 1, sizeof *b->mass))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding a point mass");
    b->mass[b->nmass++] = *d;
    return MCS_OK;
}

int fe_builder_nearest_node(const fe_builder *b, const fe_model *m, const char *name,
                            const double p[3], unsigned char *mark, const char *what,
                            mcs_error *err)
{
    int ip = fe_builder_find_part(b, name);
    if (ip < 0) {
        MCS_ERR(err, MCS_ERR_KEY, "fe: %s: unknown part '%s'", what, name);
        return -1;
    }
    fe_builder_part_nodes(b, ip, mark);
    int best = -1;
    double dbest = INFINITY;
    for (int n = 0; n < m->nnode; n++) {
        if (!mark[n]) continue;
        double d2 = 0;
        for (int i = 0; i < 3; i++) d2 += (m->node_x0[3 * n + i] - p[i]) * (m->node_x0[3 * n + i] - p[i]);
        if (d2 < dbest) dbest = d2, best = n;
    }
    if (best < 0) MCS_ERR(err, MCS_ERR_RANGE, "fe: %s: part '%s' has no nodes", what, name);
    return best;
}

static mcs_status add_masses(const fe_builder *b, fe_model *m, unsigned char *mark, int *idx,
                             mcs_error *err)
{
    for (int i = 0; i < b->nmass; i++) {
        const fe_mass_desc *d = &b->mass[i];
        int cnt = 1;
        char what[32];
        snprintf(what, sizeof what, "point mass %d", i);
        if (d->node >= 0) {
            idx[0] = d->node;
        } else if (d->at_point) {
            idx[0] = fe_builder_nearest_node(b, m, d->part, d->point, mark, what, err);
            if (idx[0] < 0) return err->status;
        } else {
            int ip = fe_builder_find_part(b, d->part);
            if (ip < 0) return MCS_ERR(err, MCS_ERR_KEY, "fe: %s: unknown part '%s'", what, d->part);
            cnt = fe_builder_select(b, ip, d->where, idx, m->nnode);
            if (cnt <= 0)
                return MCS_ERR(err, MCS_ERR_RANGE, "fe: %s: no node of part '%s' selected", what,
                               d->part);
        }
        for (int j = 0; j < cnt; j++) m->node_mass[idx[j]] += d->mass / cnt;
        m->mass_total += d->mass;
    }
    return MCS_OK;
}

/* largest slope of a spring's force law [N/m] */
static double spring_stiffness(const fe_spring *sp)
{
    if (sp->ncurve == 0) return sp->stiffness;
    double k = 0;
    for (int i = 0; i + 1 < sp->ncurve; i++)
        k = fmax(k, fabs((sp->curve[i + 1][1] - sp->curve[i][1]) /
                         (sp->curve[i + 1][0] - sp->curve[i][0])));
    return k;
}

int fe_spring_part_find(const fe_model *m, const char *name)
{
    for (int i = 0; i < m->nspring_part; i++)
        if (strcmp(m->spring_part[i], name) == 0) return i;
    return -1;
}

/* the spring part named `name` (created on first use); a name of its own */
static mcs_status spring_part(const fe_builder *b, fe_model *m, const char *name, int *out,
                              mcs_error *err)
{
    *out = fe_spring_part_find(m, name);
    if (*out >= 0) return MCS_OK;
    if (fe_builder_find_part(b, name) >= 0)
        return MCS_ERR(err, MCS_ERR_KEY,
                       "fe: spring part '%s' has the name of an element part: give springs a "
                       "part name of their own",
                       name);
    if (strlen(name) >= FE_NAME_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: spring part name longer than %d characters",
                       FE_NAME_MAX - 1);
    /* at most one part per spring: nspring slots allocated with the springs */
    *out = m->nspring_part++;
    snprintf(m->spring_part[*out], FE_NAME_MAX, "%s", name);
    return MCS_OK;
}

static mcs_status add_springs(const fe_builder *b, fe_model *m, unsigned char *mark, mcs_error *err)
{
    mcs_status st = MCS_OK;
    m->nspring = b->nspring;
    m->dt_discrete = INFINITY;
    if (b->nspring == 0) return MCS_OK;
    m->spring = calloc((size_t)b->nspring, sizeof *m->spring);
    m->spring_part = calloc((size_t)b->nspring, sizeof *m->spring_part);
    if (!m->spring || !m->spring_part)
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (springs)");
    m->bytes += (sizeof *m->spring + sizeof *m->spring_part) * (size_t)b->nspring;
    for (int i = 0; i < b->nspring; i++) {
        const fe_spring_desc *d = &b->spring[i];
        fe_spring *sp = &m->spring[i];
        char what[FE_NAME_MAX + 16];
        snprintf(what, sizeof what, "spring '%s'", d->name);
        memcpy(sp->name, d->name, FE_NAME_MAX);
        double xe[2][3];
        for (int e = 0; e < 2; e++) {
            const fe_spring_end *x = &d->end[e];
            sp->node[e] = x->node >= 0 ? x->node
                          : x->part[0] ? fe_builder_nearest_node(b, m, x->part, x->point, mark, what, err)
                                       : -1;
            if (sp->node[e] < 0 && (x->node >= 0 || x->part[0])) return err->status;
            memcpy(sp->anchor[e], x->point, sizeof sp->anchor[e]);
            memcpy(xe[e], sp->node[e] >= 0 ? m->node_x0 + 3 * sp->node[e] : x->point,
                   sizeof xe[e]);
        }
        if (sp->node[0] < 0 && sp->node[1] < 0)
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: %s: both ends are fixed anchors", what);
        if (sp->node[0] == sp->node[1])
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: %s: both ends are node %d", what, sp->node[0]);
        double dx[3] = {xe[1][0] - xe[0][0], xe[1][1] - xe[0][1], xe[1][2] - xe[0][2]};
        sp->length0 = sqrt(fe_dot(dx, dx));
        if (!(sp->length0 > 0))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: %s: its ends coincide at t = 0 (no line of action)", what);
        sp->stiffness = d->stiffness;
        sp->damping = d->damping;
        st = spring_part(b, m, d->part[0] ? d->part : "springs", &sp->part, err);
        if (st) return st;
        sp->ncurve = d->ncurve;
        memcpy(sp->curve, d->curve, sizeof sp->curve);
    }
    return MCS_OK;
}

/* stable step of the springs from the final nodal masses */
static mcs_status spring_steps(fe_model *m, mcs_error *err)
{
    for (int i = 0; i < m->nspring; i++) {
        const fe_spring *sp = &m->spring[i];
        double inv = 0;
        for (int e = 0; e < 2; e++) {
            if (sp->node[e] < 0) continue;
            double mass = m->node_mass[sp->node[e]];
            if (!(mass > 0))
                return MCS_ERR(err, MCS_ERR_RANGE,
                               "fe: spring '%s': node %d has no mass (add an element or a point "
                               "mass)",
                               sp->name, sp->node[e]);
            inv += 1 / mass;
        }
        double k = spring_stiffness(sp), w = sqrt(k * inv), c = sp->damping * inv;
        /* w^2 = k/mu, z = c/(2 mu w): dt = 2/w (sqrt(1+z^2) - z) = (sqrt(w^2 + c'^2/4) - c'/2) * 2/w^2
         * with c' = c/mu; written for w -> 0 (a pure damper: dt = 2/c') */
        double dt = k > 0 ? 2 * (sqrt(w * w + 0.25 * c * c) - 0.5 * c) / (w * w)
                          : c > 0 ? 2 / c : INFINITY;
        m->dt_discrete = fmin(m->dt_discrete, dt);
    }
    return MCS_OK;
}

mcs_status fe_discrete_build(const fe_builder *b, fe_model *m, mcs_error *err)
{
    unsigned char *mark = malloc((size_t)(m->nnode ? m->nnode : 1));
    int *idx = malloc(sizeof(int) * (size_t)(m->nnode ? m->nnode : 1));
    mcs_status st = MCS_OK;
    if (!mark || !idx) st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    if (!st) st = add_masses(b, m, mark, idx, err);
    if (!st) st = add_springs(b, m, mark, err);
    free(mark);
    free(idx);
    return st;
}

mcs_status fe_discrete_steps(fe_model *m, mcs_error *err) { return spring_steps(m, err); }

double fe_spring_part_energy(const fe_model *m, const fe_state *s, int sp, fe_energy_kind k)
{
    if (sp < 0 || sp >= m->nspring_part || k < 0 || k >= FE_NENERGY) return NAN;
    return s->spring_part_energy[FE_NENERGY * sp + k];
}

static double spring_force(const fe_spring *sp, double d)
{
    if (sp->ncurve == 0) return sp->stiffness * d;
    const double(*c)[2] = sp->curve;
    int n = sp->ncurve, i = 0;
    while (i < n - 2 && d >= c[i + 1][0]) i++;
    return c[i][1] + (c[i + 1][1] - c[i][1]) / (c[i + 1][0] - c[i][0]) * (d - c[i][0]);
}

void fe_discrete_forces(const fe_model *m, fe_state *s)
{
    double e_int = 0, e_diss = 0;
    for (int i = 0; i < m->nspring; i++) {
        const fe_spring *sp = &m->spring[i];
        double xa[3], xb[3], va[3] = {0, 0, 0}, vb[3] = {0, 0, 0};
        const int a = sp->node[0], b = sp->node[1];
        memcpy(xa, a >= 0 ? s->node_x + 3 * a : sp->anchor[0], sizeof xa);
        memcpy(xb, b >= 0 ? s->node_x + 3 * b : sp->anchor[1], sizeof xb);
        if (a >= 0) memcpy(va, s->node_v + 3 * a, sizeof va);
        if (b >= 0) memcpy(vb, s->node_v + 3 * b, sizeof vb);
        double d[3] = {xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]};
        double len = sqrt(fe_dot(d, d));
        double e[3] = {0, 0, 0};
        if (len > 0)
            for (int k = 0; k < 3; k++) e[k] = d[k] / len;
        double dv[3] = {vb[0] - va[0], vb[1] - va[1], vb[2] - va[2]};
        double el = len - sp->length0, rate = fe_dot(dv, e);
        double f = spring_force(sp, el), fd = sp->damping * rate;
        /* trapezoidal works over the elongation increment since the last evaluation */
        double dd = el - s->spring_d[i];
        double wi = 0.5 * (s->spring_f[i] + f) * dd, wd = 0.5 * (s->spring_fd[i] + fd) * dd;
        e_int += wi;
        e_diss += wd;
        s->spring_part_energy[FE_NENERGY * sp->part + FE_E_internal] += wi;
        s->spring_part_energy[FE_NENERGY * sp->part + FE_E_dissipated] += wd;
        s->spring_f[i] = f;
        s->spring_fd[i] = fd;
        s->spring_d[i] = el;
        /* resisting forces: the tension pulls a towards b */
        double ft = f + fd;
        for (int k = 0; k < 3; k++) {
            if (a >= 0) s->node_fint[3 * a + k] -= ft * e[k];
            if (b >= 0) s->node_fint[3 * b + k] += ft * e[k];
        }
    }
    s->free_energy[FE_E_internal] += e_int;
    s->free_energy[FE_E_dissipated] += e_diss;
}

/* fe_massscale: selective mass scaling at t = 0 (what users know as LS-DYNA *CONTROL_TIMESTEP
 * DT2MS < 0: mass only where it is needed). With a target step dt_t (safety factor included),
 * every deformable element whose step dt_scale * dt_e is below dt_t gets its density scaled by
 * f^2, f = dt_t / (dt_scale * dt_e): its wave speed drops by f, its step rises to dt_t, and its
 * mass grows by
 *     dM_e = M_e (f^2 - 1),
 * lumped to its nodes as its own mass is (hex 1/8, shell 1/3 or 1/4 with the rotary inertia
 * scaled alike, truss 1/2). The element's step is multiplied by f in the time loop
 * (elem_dt_factor), so the run goes at dt_t as long as the scaled elements set the step.
 * The element step is the one of fe_part_dt (hex V / largest face over the dilatational speed
 * with the linear bulk viscosity, fe_bulk_dt; shell area / longest side over the plate speed,
 * truss length over the bar speed). Rigid parts and membranes are not scaled. The added mass
 * is reported (m->mass_added; /stage3 attributes and the run summary) because it changes the
 * dynamics: keep it small where things happen.
 *
 * During the run (opts.mass_scaling_interval = N > 0; LS-DYNA re-checks as elements deform):
 * every N cycles each scaled-capable element's current step, the kernel's formula from the
 * current geometry (hex L/(Q + sqrt(Q^2 + c^2)) with the bulk-viscosity rate Q from the
 * current volumetric strain rate, fe_bulk_dt, shell and truss as above) times its step factor and
 * sqrt(F/F0) (F its density factor now, F0 the t = 0 one), is compared with dt_t / dt_scale;
 * below it, F rises to F0 (dt_t / (dt_scale dt_e factor))^2 and the element's mass by
 * M_e (F_new - F_old), lumped as above into state arrays (node_dm, node_din) the kernel adds to
 * the model's masses. The added mass keeps the node's velocity; its kinetic energy
 * 1/2 dm v.v is counted as external work, so the balance still closes. The step of the run is
 * then the smallest of the scaled elements' own (>= dt_t / dt_scale), the other parts' (rigid,
 * membranes) and the springs'. Between checks (N > 1) an element keeps the mass of the last
 * check: if it shrinks faster than dt_scale's margin in N cycles it runs past its limit. */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* step (no safety factor) and mass of element e of part p at t = 0; nodes in c, count nn */
static double elem_step(const fe_model *m, const fe_part *p, int e, double *mass, int *c, int *nn)
{
    const double *x = m->node_x0;
    if (p->elem_kind == FE_KIND_HEX) {
        double xe[8][3], b[8][3], a[8][3];
        for (int n = 0; n < 8; n++) {
            c[n] = m->hex_node[8 * e + n];
            memcpy(xe[n], x + 3 * c[n], sizeof xe[n]);
        }
        double vol = fe_hex_gradients(xe, b, a);
        *mass = p->material.density * vol;
        int u[8];
        *nn = fe_hex_distinct(c, u); /* tetrahedra, pentahedra: distinct nodes (fe_tet.c) */
        memcpy(c, u, sizeof u);
        return fe_bulk_dt(m, fe_hex_length(xe, vol), p->wave_speed, 0);
    }
    if (p->elem_kind == FE_KIND_SHELL) {
        double xe[4][3], fr[3][3], xl[4], yl[4];
        for (int n = 0; n < 4; n++) {
            c[n] = m->shell_node[4 * e + n];
            memcpy(xe[n], x + 3 * c[n], sizeof xe[n]);
        }
        double area = fe_shell_frame(xe, fr, xl, yl);
        *mass = p->material.density * m->shell_t[e] * area;
        *nn = c[2] == c[3] ? 3 : 4;
        return fe_shell_length(xe, area) / p->wave_speed;
    }
    c[0] = m->truss_node[2 * e], c[1] = m->truss_node[2 * e + 1];
    double d[3];
    for (int i = 0; i < 3; i++) d[i] = x[3 * c[1] + i] - x[3 * c[0] + i];
    double len = sqrt(fe_dot(d, d));
    *mass = p->material.density * p->section.area * len;
    *nn = 2;
    return len / p->wave_speed;
}

mcs_status fe_dt_factors_alloc(fe_model *m, mcs_error *err)
{
    if (m->elem_dt_factor) return MCS_OK;
    m->elem_dt_factor = malloc(sizeof(double) * (size_t)(m->nelem > 0 ? m->nelem : 1));
    if (!m->elem_dt_factor)
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (element step factors)");
    m->bytes += sizeof(double) * (size_t)m->nelem;
    for (int i = 0; i < m->nelem; i++) m->elem_dt_factor[i] = 1;
    return MCS_OK;
}

/* element masses and t = 0 density factors for the run-time checks */
static mcs_status run_arrays(fe_model *m, mcs_error *err)
{
    m->nms_node = m->nnode;
    m->nms_elem = m->nelem;
    m->elem_ms0 = malloc(sizeof(double) * (size_t)(m->nelem > 0 ? m->nelem : 1));
    m->elem_mass0 = malloc(sizeof(double) * (size_t)(m->nelem > 0 ? m->nelem : 1));
    if (!m->elem_ms0 || !m->elem_mass0)
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (mass scaling)");
    m->bytes += 2 * sizeof(double) * (size_t)m->nelem;
    for (int e = 0; e < m->nelem; e++) m->elem_ms0[e] = 1, m->elem_mass0[e] = 0;
    return MCS_OK;
}

mcs_status fe_massscale_build(fe_model *m, mcs_error *err)
{
    const double target = m->opts.mass_scaling_dt, sc = m->opts.dt_scale;
    if (!(target > 0)) return MCS_OK;
    mcs_status st = fe_dt_factors_alloc(m, err);
    if (!st && m->opts.mass_scaling_interval > 0) st = run_arrays(m, err);
    if (st) return st;
    int nscaled = 0;
    for (int ip = 0; ip < m->npart; ip++) {
        const fe_part *p = &m->part[ip];
        /* tet10 parts are not scaled (their step is their own frequency's: fe_tet10.c) */
        if (p->material.model == FE_MAT_RIGID || p->material.model == FE_MAT_NULL ||
            p->section.type == FE_SECTION_MEMBRANE ||
            p->elem_kind == FE_KIND_TET10)
            continue;
        const int off = p->elem_kind == FE_KIND_HEX     ? 0
                        : p->elem_kind == FE_KIND_SHELL ? m->nhex
                                                        : m->nhex + m->nshell;
        for (int e = p->elem_begin; e < p->elem_end; e++) {
            double mass;
            int c[8], nn;
            /* the step with the factor already there (tetrahedra: fe_tet.c) */
            double dte = sc * elem_step(m, p, e, &mass, c, &nn) * m->elem_dt_factor[off + e];
            if (m->elem_mass0) m->elem_mass0[off + e] = mass;
            if (!(dte < target)) continue;
            double f = target / dte, dm = mass * (f * f - 1);
            m->elem_dt_factor[off + e] *= f;
            if (m->elem_ms0) m->elem_ms0[off + e] = f * f;
            for (int i = 0; i < nn; i++) {
                /* shells: the rotary inertia grows with the translational mass */
                if (p->elem_kind == FE_KIND_SHELL && m->node_mass[c[i]] > 0)
                    m->node_inertia[c[i]] *= 1 + dm / nn / m->node_mass[c[i]];
                m->node_mass[c[i]] += dm / nn;
            }
            m->mass_added += dm;
            nscaled++;
        }
    }
    m->mass_total += m->mass_added;
    if (nscaled > 0)
        mcs_log(MCS_LOG_INFO,
                "fe: mass scaling to a %.4g s step added %.6g kg (%.3g %% of %.6g kg) to %d "
                "element(s)",
                target, m->mass_added, 100 * m->mass_added / (m->mass_total - m->mass_added),
                m->mass_total - m->mass_added, nscaled);
    return MCS_OK;
}

/* ---- during the run ---------------------------------------------------------------------- */

void fe_massscale_reset(const fe_model *m, fe_state *s)
{
    s->mass_added_run = 0;
    s->dt_ms = INFINITY;
    for (int e = 0; e < m->nms_elem; e++) s->elem_ms[e] = m->elem_ms0[e];
}

static int scalable(const fe_part *p)
{
    return p->material.model != FE_MAT_RIGID && p->material.model != FE_MAT_NULL &&
           p->section.type != FE_SECTION_MEMBRANE &&
           p->elem_kind != FE_KIND_TET10;
}

/* the kernel's step of element e of part p (no safety factor, no step factor) at the current
 * geometry; its distinct nodes in c (count nn) */
static double step_now(const fe_model *m, const fe_state *s, const fe_part *p, int e, int *c,
                       int *nn)
{
    const double *x = s->node_x, c0 = p->wave_speed;
    if (p->elem_kind == FE_KIND_HEX) {
        double xe[8][3], b[8][3], a[8][3], ev = 0;
        const int *h = m->hex_node + 8 * e;
        for (int n = 0; n < 8; n++) memcpy(xe[n], x + 3 * h[n], sizeof xe[n]);
        double vol = fe_hex_gradients(xe, b, a), len = fe_hex_length(xe, vol);
        for (int n = 0; n < 8; n++) ev += fe_dot(b[n], s->node_v + 3 * h[n]);
        *nn = fe_hex_distinct(h, c);
        return fe_bulk_dt(m, len, c0, ev);
    }
    if (p->elem_kind == FE_KIND_SHELL) {
        double xe[4][3], fr[3][3], xl[4], yl[4];
        for (int n = 0; n < 4; n++) {
            c[n] = m->shell_node[4 * e + n];
            memcpy(xe[n], x + 3 * c[n], sizeof xe[n]);
        }
        *nn = c[2] == c[3] ? 3 : 4;
        return fe_shell_length(xe, fe_shell_frame(xe, fr, xl, yl)) / c0;
    }
    c[0] = m->truss_node[2 * e], c[1] = m->truss_node[2 * e + 1];
    double d[3];
    for (int i = 0; i < 3; i++) d[i] = x[3 * c[1] + i] - x[3 * c[0] + i];
    *nn = 2;
    return sqrt(fe_dot(d, d)) / c0;
}

/* mass dm onto the nodes of an element (shells: rotary inertia in proportion); the kinetic
 * energy the added mass carries goes into the external work */
static void add_mass(const fe_model *m, fe_state *s, int shell, const int *c, int nn, double dm)
{
    for (int i = 0; i < nn; i++) {
        const int n = c[i];
        const double mn = m->node_mass[n] + s->node_dm[n], d = dm / nn, *v = s->node_v + 3 * n;
        if (shell && mn > 0) s->node_din[n] += (m->node_inertia[n] + s->node_din[n]) * d / mn;
        s->node_dm[n] += d;
        s->work_ext += 0.5 * d * fe_dot(v, v);
    }
    s->mass_added_run += dm;
}

double fe_massscale_run(const fe_model *m, fe_state *s, double dtmin)
{
    const double target = m->opts.mass_scaling_dt, sc = m->opts.dt_scale;
    const int every = m->opts.mass_scaling_interval;
    if (s->nstep % every == 0 || !isfinite(s->dt_ms)) {
        double dts = INFINITY;
        for (int ip = 0; ip < m->npart; ip++) {
            const fe_part *p = &m->part[ip];
            if (!scalable(p)) continue;
            const int off = p->elem_kind == FE_KIND_HEX     ? 0
                            : p->elem_kind == FE_KIND_SHELL ? m->nhex
                                                            : m->nhex + m->nshell;
            for (int e = p->elem_begin; e < p->elem_end; e++) {
                const int k = off + e;
                if (m->nerode && k < m->nerode && s->elem_dead[k]) continue; /* eroded */
                int c[8], nn;
                double dte = step_now(m, s, p, e, c, &nn) * m->elem_dt_factor[k] *
                             sqrt(s->elem_ms[k] / m->elem_ms0[k]);
                if (sc * dte < target && dte > 0) {
                    double f2 = s->elem_ms[k] * (target / (sc * dte)) * (target / (sc * dte));
                    add_mass(m, s, p->elem_kind == FE_KIND_SHELL, c, nn,
                             m->elem_mass0[k] * (f2 - s->elem_ms[k]));
                    s->elem_ms[k] = f2;
                    dte = target / sc;
                }
                dts = fmin(dts, dte);
            }
        }
        s->dt_ms = dts;
    }
    /* the step: scaled parts from the check, the others as the kernel found them */
    double dt = fmin(m->dt_discrete, s->dt_ms);
    for (int ip = 0; ip < m->npart; ip++)
        if (!scalable(&m->part[ip])) dt = fmin(dt, s->part_dt[ip]);
    (void)dtmin;
    return dt;
}

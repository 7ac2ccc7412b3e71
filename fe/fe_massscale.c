/* fe_massscale: selective mass scaling at t = 0 (what users know as LS-DYNA *CONTROL_TIMESTEP
 * DT2MS < 0: mass only where it is needed). With a target step dt_t (safety factor included),
 * every deformable element whose step dt_scale * dt_e is below dt_t gets its density scaled by
 * f^2, f = dt_t / (dt_scale * dt_e): its wave speed drops by f, its step rises to dt_t, and its
 * mass grows by
 *     dM_e = M_e (f^2 - 1),
 * lumped to its nodes as its own mass is (hex 1/8, shell 1/3 or 1/4 with the rotary inertia
 * scaled alike, truss 1/2). The element's step is multiplied by f in the time loop
 * (elem_dt_factor), so the run goes at dt_t as long as the scaled elements set the step.
 * The element step is the one of fe_part_dt (hex V / largest face over the dilatational speed,
 * shell area / longest side over the plate speed, truss length over the bar speed). Rigid
 * parts and membranes are not scaled. The added mass is reported (m->mass_added; /stage3
 * attributes and the run summary) because it changes the dynamics: keep it small where
 * things happen. */
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
        return fe_hex_length(xe, vol) / p->wave_speed;
    }
    if (p->elem_kind == FE_KIND_SHELL) {
        double xe[4][3], fr[3][3], xl[4], yl[4];
        for (int n = 0; n < 4; n++) {
            c[n] = m->shell_node[4 * e + n];
            memcpy(xe[n], x + 3 * c[n], sizeof xe[n]);
        }
        double area = fe_shell_frame(xe, fr, xl, yl);
        *mass = p->material.density * p->section.thickness * area;
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

mcs_status fe_massscale_build(fe_model *m, mcs_error *err)
{
    const double target = m->opts.mass_scaling_dt, sc = m->opts.dt_scale;
    if (!(target > 0)) return MCS_OK;
    mcs_status st = fe_dt_factors_alloc(m, err);
    if (st) return st;
    int nscaled = 0;
    for (int ip = 0; ip < m->npart; ip++) {
        const fe_part *p = &m->part[ip];
        if (p->material.model == FE_MAT_RIGID || p->section.type == FE_SECTION_MEMBRANE) continue;
        const int off = p->elem_kind == FE_KIND_HEX     ? 0
                        : p->elem_kind == FE_KIND_SHELL ? m->nhex
                                                        : m->nhex + m->nshell;
        for (int e = p->elem_begin; e < p->elem_end; e++) {
            double mass;
            int c[8], nn;
            /* the step with the factor already there (tetrahedra: fe_tet.c) */
            double dte = sc * elem_step(m, p, e, &mass, c, &nn) * m->elem_dt_factor[off + e];
            if (!(dte < target)) continue;
            double f = target / dte, dm = mass * (f * f - 1);
            m->elem_dt_factor[off + e] *= f;
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

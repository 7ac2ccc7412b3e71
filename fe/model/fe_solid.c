/* fe_solid: model-building and state-reset entry points of the discrete, rigid, foam,
 * fully integrated hex and mass scaling modules (fe_solid.h), called once each from
 * fe_model_create, fe_model_destroy and fe_state_reset. */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"
#include "fe/fe_tet10.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static mcs_status check_opts(const fe_model *m, mcs_error *err)
{
    const fe_opts *o = &m->opts;
    for (int i = 0; i < 3; i++)
        if (!isfinite(o->gravity[i]))
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: options: gravity is not finite");
    if (!(o->mass_scaling_dt >= 0) || !isfinite(o->mass_scaling_dt))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: options: mass scaling time step must be >= 0");
    if (o->mass_scaling_interval < 0)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: options: mass scaling check interval must be >= 0");
    return MCS_OK;
}

mcs_status fe_solid_build(const fe_builder *b, fe_model *m, mcs_error *err)
{
    mcs_status st = check_opts(m, err);
    if (st) return st;
    for (int n = 0; n < m->nnode; n++) m->node_body[n] = -1;
    for (int ip = 0; ip < m->npart; ip++) {
        fe_part *p = &m->part[ip];
        p->body = -1;
        /* Gauss points of the fully integrated hexes */
        if (p->elem_kind == FE_KIND_HEX && p->section.formulation == FE_HEX_FULL) {
            p->gp_begin = m->nhex_gp;
            m->nhex_gp += 8 * (p->elem_end - p->elem_begin);
        }
        /* foam history tensors: one per integration point */
        if (p->elem_kind == FE_KIND_HEX && p->material.model == FE_MAT_FOAM) {
            p->foam_begin = m->nfoam_ip;
            int npt = p->section.formulation == FE_HEX_FULL ? 8 : 1;
            m->nfoam_ip += npt * (p->elem_end - p->elem_begin);
        }
    }
    st = fe_discrete_build(b, m, err);
    if (!st) st = fe_tet_dt_build(m, err);
    if (!st) st = fe_tet10_dt_build(m, err);
    if (!st) st = fe_massscale_build(m, err);
    if (!st) st = fe_hex_dt_build(m, err);
    if (!st) st = fe_rigid_build(b, m, err);
    if (!st) st = fe_discrete_steps(m, err);
    return st;
}

mcs_status fe_solid_finish(fe_model *m, mcs_error *err)
{
    mcs_status st = fe_rigid_finish(m, err);
    return st ? st : fe_wall_finish(m, err);
}

void fe_solid_free(fe_model *m)
{
    free(m->spring);
    free(m->spring_part);
    free(m->body);
    free(m->body_node);
    free(m->body_r0);
    free(m->joint);
    m->joint = NULL;
    m->njoint = 0;
    free(m->elem_dt_factor);
    free(m->elem_ms0);
    free(m->elem_mass0);
    free(m->wall_slave);
    m->wall_slave = NULL;
    m->elem_ms0 = m->elem_mass0 = NULL;
    m->spring = NULL;
    m->spring_part = NULL;
    m->body = NULL;
    m->body_node = NULL;
    m->body_r0 = NULL;
    m->elem_dt_factor = NULL;
}

void fe_solid_reset(const fe_model *m, fe_state *s)
{
    memset(s->free_energy, 0, sizeof s->free_energy);
    fe_rigid_reset(m, s);
    fe_wall_reset(m, s);
    fe_massscale_reset(m, s);
}

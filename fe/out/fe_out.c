/* fe_out.c: an FE model's /stage<N> series, opened, sampled and freed together (fe_out.h) */
#include "fe/fe_out.h"

mcs_status fe_out_open(mcs_results *r, int stage, const fe_model *m, fe_out *o, mcs_error *err)
{
    mcs_status st = fe_out_contact_open(r, stage, m, &o->contact, err);
    if (!st) st = fe_out_field_open(r, stage, m, &o->field, err);
    if (!st) st = fe_out_restraint_open(r, stage, m, &o->rest, err);
    if (!st) st = fe_out_slipring_open(r, stage, m, &o->rings, err);
    if (!st) st = fe_out_parts_open(r, stage, m, &o->parts, err);
    if (!st) st = fe_out_motion_open(r, stage, m, &o->motion, err);
    if (!st) st = fe_out_joint_open(r, stage, m, &o->joints, err);
    return st;
}

mcs_status fe_out_sample(const fe_model *m, const fe_state *s, fe_out *o, mcs_error *err)
{
    mcs_status st = fe_out_restraint_sample(s, &o->rest, err);
    if (!st) st = fe_out_slipring_sample(s, &o->rings, err);
    if (!st) st = fe_out_contact_sample(m, s, &o->contact, err);
    if (!st) st = fe_out_parts_sample(m, s, &o->parts, err);
    if (!st) st = fe_out_motion_sample(m, s, &o->motion, err);
    if (!st) st = fe_out_joint_sample(m, s, &o->joints, err);
    return st;
}

void fe_out_free(fe_out *o)
{
    fe_out_field_free(&o->field);
    fe_out_restraint_free(&o->rest);
    fe_out_slipring_free(&o->rings);
    fe_out_parts_free(&o->parts);
    fe_out_motion_free(&o->motion);
    fe_out_joint_free(&o->joints);
}

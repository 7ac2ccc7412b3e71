/* mb_state.c: a state of a stage-1 model: the ODE world built from the model, the histories,
 * the scratch and the output records, all allocated here once (none in the time loop). */
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_egroup.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_prescribe.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int add_joint(mb_world *w, const mb_joint_def *j, mcs_error *err)
{
    switch (j->type) {
    case MB_J_REVOLUTE: return mb_joint_revolute(w, j->parent, j->child, j->anchor, j->axis, err);
    case MB_J_SPHERICAL: return mb_joint_spherical(w, j->parent, j->child, j->anchor, err);
    case MB_J_UNIVERSAL:
        return mb_joint_universal(w, j->parent, j->child, j->anchor, j->axis, j->axis2, err);
    case MB_J_TRANSLATIONAL: return mb_joint_translational(w, j->parent, j->child, j->axis, err);
    case MB_J_FIXED: return mb_joint_fixed(w, j->parent, j->child, err);
    }
    return -1;
}

static mcs_status build_world(const mb_model *m, mb_state *s, mcs_error *err)
{
    mcs_status st = mb_world_create(&s->world, m->nbody, m->njoint, m->gravity, err);
    if (st) return st;
    for (int i = 0; i < m->nbody; i++)
        if (mb_world_add_body(s->world, &m->body[i], err) != i)
            return err->status ? err->status : MCS_ERR(err, MCS_ERR_RANGE, "body %d", i);
    for (int i = 0; i < m->njoint; i++)
        if (add_joint(s->world, &m->joint[i], err) != i)
            return err->status ? err->status
                               : MCS_ERR(err, MCS_ERR_RANGE, "joint %s", m->joint[i].name);
    for (int i = 0; i < m->nrestraint1; i++) {
        if ((st = mb_restraint_check(&m->restraint1[i], s->world, m->restraint1_name[i], err)))
            return st;
        mb_restraint_reset(&m->restraint1[i], &s->r1[i]);
    }
    for (int i = 0; i < m->nrestraint3; i++) {
        if ((st = mb_restraint3_check(&m->restraint3[i], s->world, m->restraint3_name[i], err)))
            return st;
        mb_restraint3_reset(&m->restraint3[i], &s->r3[i], s->world);
    }
    for (int i = 0; i < m->nattach; i++) {
        if ((st = mb_attach_check(&m->attach[i], s->world, m->attach_name[i], err))) return st;
        mb_attach_reset(&m->attach[i], &s->att[i]);
    }
    return MCS_OK;
}

#define MB_ALLOC(p, n) ((p) = calloc((size_t)((n) > 0 ? (n) : 1), sizeof *(p)))

mcs_status mb_state_create(const mb_model *m, mb_state **out, mcs_error *err)
{
    *out = NULL;
    mb_state *s = calloc(1, sizeof *s);
    if (!s) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    size_t nb = (size_t)m->nbody, no = (size_t)m->nout;
    int ok = MB_ALLOC(s->pair, m->npair) && MB_ALLOC(s->r1, m->nrestraint1) &&
             MB_ALLOC(s->r3, m->nrestraint3) && MB_ALLOC(s->att, m->nattach) &&
             MB_ALLOC(s->kin, nb) && MB_ALLOC(s->pc, m->npair) && MB_ALLOC(s->vel_prev, 3 * nb) && MB_ALLOC(s->angvel_prev, 3 * nb) &&
             MB_ALLOC(s->acc, 3 * nb) && MB_ALLOC(s->angacc, 3 * nb) &&
             MB_ALLOC(s->pos0, 3 * nb) && MB_ALLOC(s->rot0, 9 * nb) && MB_ALLOC(s->rec_t, no) &&
             MB_ALLOC(s->rec_body, no * nb * MB_BODY_ROW) &&
             MB_ALLOC(s->rec_sensor, no * (size_t)m->nsensor * 3) &&
             MB_ALLOC(s->rec_energy, no * MB_NENERGY) &&
             MB_ALLOC(s->rec_chan, no * (size_t)mb_channels_count(m)) &&
             MB_ALLOC(s->rec_loadcell, no * (size_t)m->nloadcell * 6) &&
             MB_ALLOC(s->surf_ell, m->nsurf);
    if (!ok) {
        mb_state_destroy(&s);
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory for %ld output samples",
                       m->nout);
    }
    for (int i = 0; i < m->npair; i++) mcs_hyst_reset(&m->pair[i].hyst, &s->pair[i].h);
    mcs_status st = build_world(m, s, err);
    if (!st) st = mb_prescribe_init(m, s, err);
    if (!st && m->couple) st = mb_couple_state_create(m, &s->couple, err);
    if (!st && m->egroup) st = mb_egroup_state_create(m, &s->egroup, err);
    if (st) {
        mb_state_destroy(&s);
        return st;
    }
    /* t = 0: geometry for the first step's forces, energies and the first output row (its
     * accelerations are filled after step 1) */
    mb_contact_detect(m, s);
    for (int b = 0; b < m->nbody; b++) {
        const mb_body_kin *k = &s->kin[b];
        mb_copy(k->pos, s->pos0 + 3 * b);
        memcpy(s->rot0 + 9 * b, k->rot, sizeof k->rot);
        mb_copy(k->vel, s->vel_prev + 3 * b);
        mb_copy(k->angvel, s->angvel_prev + 3 * b);
    }
    mb_energy_update(m, s);
    s->e_total0 = s->e.total;
    mb_record(m, s);
    *out = s;
    return MCS_OK;
}

void mb_state_destroy(mb_state **ps)
{
    mb_state *s = ps ? *ps : NULL;
    if (!s) return;
    mb_world_destroy(&s->world);
    mb_couple_state_destroy(&s->couple);
    mb_egroup_state_destroy(&s->egroup);
    free(s->pair), free(s->r1), free(s->r3), free(s->att);
    free(s->kin), free(s->pc), free(s->vel_prev), free(s->angvel_prev), free(s->acc), free(s->angacc);
    free(s->pos0), free(s->rot0);
    free(s->rec_t), free(s->rec_body), free(s->rec_sensor), free(s->rec_energy);
    free(s->rec_chan), free(s->surf_ell);
    free(s->rec_loadcell);
    free(s->presc_next);
    free(s);
    *ps = NULL;
}

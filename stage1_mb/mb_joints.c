/* mb_joints.c: the restraint sub-stage of mb_step: joint restraints (one- and three-axis) and
 * breakable attachments add their loads for the coming step (mb_restraint*.c). */
#include "stage1_mb/mb_model.h"

/* restraints: reads joint positions and rates, writes loads on the bodies and the histories */
void mb_restraints_apply(const mb_model *m, mb_state *s)
{
    for (int i = 0; i < m->nrestraint1; i++)
        mb_restraint_apply(&m->restraint1[i], &s->r1[i], s->world, m->h);
    for (int i = 0; i < m->nrestraint3; i++)
        mb_restraint3_apply(&m->restraint3[i], &s->r3[i], s->world, m->h);
    for (int i = 0; i < m->nattach; i++) mb_attach_apply(&m->attach[i], &s->att[i], s->world, m->h);
}

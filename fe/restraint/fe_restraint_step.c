/* fe_restraint_step: the per-step coupling of gas bags and retractors (fe_restraint.h).
 * Called at the end of fe_external_forces with x = x(t_n), s->time = t_n and
 * s->dt_prev = t_n - t_n-1 (0 on the first step): the bag gases and the retractors are
 * advanced to t_n, so the forces they add into node_fext are those of t_n, as central
 * differences want. The retractor anchors are the state's (a coupling may move them); the
 * segment's reaction on each anchor is recorded. No allocation. */
#include "fe/fe_restraint.h"

#include <math.h>
#include <stdio.h>

static void bags(const fe_model *m, fe_state *s)
{
    const struct fe_restraints *r = m->restraints;
    for (int i = 0; i < r->nbag; i++) {
        const fe_airbag *b = &r->bag[i];
        mcs_error e = {0};
        mcs_status st = fe_gasbag_step_surface(b->gas, &s->restraint->bag[i], b->nface, b->face,
                                               s->node_x, s->dt_prev, s->node_fext, &e);
        if (st != MCS_OK) {
            MCS_ERR(&s->err, st, "%s", e.msg); /* names the bag and the time */
            return;
        }
    }
}

static void retractors(const fe_model *m, fe_state *s)
{
    const struct fe_restraints *r = m->restraints;
    for (int i = 0; i < r->nretractor; i++) {
        const fe_belt_retractor *b = &r->retractor[i];
        fe_retractor_state *rs = &s->restraint->retractor[i];
        double d[3], *x = s->node_x + 3 * b->node;
        const double *anchor = s->restraint->retractor_anchor + 3 * i;
        double *fa = s->restraint->retractor_fanchor + 3 * i;
        for (int j = 0; j < 3; j++) d[j] = x[j] - anchor[j], fa[j] = 0;
        double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        s->restraint->retractor_length[i] = l;
        if (s->dt_prev > 0) {
            /* the tension the segment would carry with the current payout and what slip
             * rings moved into it (slack < 0) */
            double trial = b->k * (l - b->l0 - rs->payout - s->restraint->retractor_ring[i]);
            mcs_error e = {0};
            mcs_status st = fe_retractor_advance(b->model, rs, s->dt_prev, trial, b->k, &e);
            if (st != MCS_OK) {
                MCS_ERR(&s->err, st, "%s", e.msg);
                return;
            }
        }
        if (!(l > 0)) continue; /* on the anchor: no direction to pull along */
        double f = rs->force / l;
        for (int j = 0; j < 3; j++) {
            s->node_fext[3 * b->node + j] -= f * d[j];
            fa[j] = f * d[j]; /* the reaction on the anchor */
        }
    }
}

void fe_restraint_forces(const fe_model *m, fe_state *s)
{
    if (!m->restraints || !s->restraint) return;
    bags(m, s);
    if (s->err.status == MCS_OK) retractors(m, s);
}

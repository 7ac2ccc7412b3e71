/* mb_couple_anchor.c: retractor anchors carried by stage-1 bodies (fe.retractors[].anchor_body;
 * mb_couple_rx.h). The anchor moves as the attached nodes do (mb_couple.c): on the straight line
 * between its body points at the ODE step's ends, set before each FE step at that step's start
 * (where the kernel evaluates the segment force, fe_restraint_step.c). The reaction of the
 * segment on the anchor at t_j (fe_restraint_state.retractor_fanchor, slip rings included)
 * acts over the same half steps as a node's force, so its impulse is f_j dth_j; their sum over
 * the subcycle divided by h is the mean force on the body, applied at the anchor in the next
 * ODE step, extrapolated with the attached nodes' factor. */
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_pt.h"
#include "stage1_mb/mb_couple_rx.h"
#include "stage1_mb/mb_prescribe.h"
#include "stage1_mb/mb_vec.h"
#include "fe/fe_restraint.h"

#include <stdlib.h>
#include <string.h>

mcs_status mb_couple_anchor_build(const mcs_node *fe, mb_model *m, mb_couple_rx *rx,
                                  mcs_error *err)
{
    const fe_model *fm = m->couple->fe.model;
    const mcs_node *rets = mcs_node_get(fe, "retractors");
    int n = mcs_node_len(rets);
    rx->anchor_ret = calloc((size_t)(n ? n : 1), sizeof *rx->anchor_ret);
    rx->anchor_body = calloc((size_t)(n ? n : 1), sizeof *rx->anchor_body);
    rx->anchor_local = calloc(3 * (size_t)(n ? n : 1), sizeof *rx->anchor_local);
    if (!rx->anchor_ret || !rx->anchor_body || !rx->anchor_local)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int i = 0; i < n; i++) {
        const mcs_node *r = mcs_node_at(rets, i), *bn = mcs_node_get(r, "anchor_body");
        if (mcs_node_kind(bn) == MCS_NODE_NULL) continue;
        int b = mb_model_body(m, mcs_node_str(bn));
        if (b < 0) return mcs_node_error(bn, err, MCS_ERR_KEY, "no body of that name");
        int k = fe_retractor_find(fm, mcs_node_str(mcs_node_get(r, "name")));
        if (k < 0) continue;
        /* the anchor in the body frame from the t = 0 pose */
        mb_couple_pt_local(&m->body[b], fm->restraints->retractor[k].anchor,
                           rx->anchor_local + 3 * rx->nanchor);
        rx->anchor_ret[rx->nanchor] = k;
        rx->anchor_body[rx->nanchor++] = b;
    }
    return MCS_OK;
}

void mb_couple_anchor_apply(const mb_model *m, mb_state *s)
{
    const mb_couple_rx *rx = m->couple->rx;
    mb_couple_rx_state *q = s->couple->rx;
    mb_couple_pt_apply(s, rx->nanchor, rx->anchor_body, rx->anchor_local, q->force, q->xa);
}

void mb_couple_anchor_begin(const mb_model *m, mb_state *s)
{
    const mb_couple_rx *rx = m->couple->rx;
    mb_couple_rx_state *q = s->couple->rx;
    for (int a = 0; a < rx->nanchor; a++) {
        double *x1 = q->x1 + 3 * a;
        mb_couple_pt_now(s, rx->anchor_body[a], rx->anchor_local + 3 * a, x1);
        /* the body's work of the last force over this step's displacement of the anchor */
        double w = 0;
        for (int i = 0; i < 3; i++) w += q->force[3 * a + i] * (x1[i] - q->xa[3 * a + i]);
        q->w_anchor += w;
        if (mb_body_prescribed(m, rx->anchor_body[a])) q->w_anchor_presc += w;
    }
    memset(q->imp, 0, 3 * (size_t)rx->nanchor * sizeof *q->imp);
}

void mb_couple_anchor_move(const mb_model *m, mb_state *s, double tau)
{
    const mb_couple_rx *rx = m->couple->rx;
    if (rx->nanchor == 0) return; /* (no restraint state without retractors) */
    mb_couple_rx_state *q = s->couple->rx;
    double *an = s->couple->fe->restraint->retractor_anchor;
    for (int a = 0; a < rx->nanchor; a++)
        for (int i = 0; i < 3; i++)
            an[3 * rx->anchor_ret[a] + i] =
                q->xa[3 * a + i] + tau * (q->x1[3 * a + i] - q->xa[3 * a + i]);
}

void mb_couple_anchor_collect(const mb_model *m, mb_state *s, double dth)
{
    const mb_couple_rx *rx = m->couple->rx;
    if (rx->nanchor == 0) return;
    mb_couple_rx_state *q = s->couple->rx;
    const double *fa = s->couple->fe->restraint->retractor_fanchor;
    for (int a = 0; a < rx->nanchor; a++)
        for (int i = 0; i < 3; i++) q->imp[3 * a + i] += fa[3 * rx->anchor_ret[a] + i] * dth;
}

void mb_couple_anchor_end(const mb_model *m, mb_state *s, double h, double alpha, int started)
{
    const mb_couple_rx *rx = m->couple->rx;
    mb_couple_rx_state *q = s->couple->rx;
    mb_couple_mean_force(3 * rx->nanchor, q->imp, 1, h, alpha, started, q->fmean, q->force);
}

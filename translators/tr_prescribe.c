/* tr_prescribe.c: a tr_motion as the engine's prescribed-motion callback (tr_prescribe.h) */
#include "translators/tr_prescribe.h"
#include "stage1_mb/mb_prescribe.h"

#include <stdlib.h>
#include <string.h>

struct tr_prescribe {
    const tr_motion *mo;
    int nbody;
    int *motion_body; /* the motion's body of each model body, -1 free (nbody) */
    mcs_error err;    /* the last callback failure                            */
};

static int motion_cb(void *ctx, int body, double t, double pos[3], double quat[4], double vel[3],
                     double omega[3])
{
    tr_prescribe *p = ctx;
    tr_motion_kin k;
    if (tr_motion_eval(p->mo, p->motion_body[body], t, &k, &p->err)) return -1;
    memcpy(pos, k.pos, sizeof k.pos);
    memcpy(quat, k.quat, sizeof k.quat);
    memcpy(vel, k.vel, sizeof k.vel);
    memcpy(omega, k.angvel, sizeof k.angvel);
    return 0;
}

mcs_status tr_prescribe_create(tr_prescribe **out, mb_model *m, const tr_motion *mo,
                               const char *const *bodies, const char *const *from, int n,
                               mcs_error *err)
{
    *out = NULL;
    tr_prescribe *p = calloc(1, sizeof *p);
    if (p) p->motion_body = malloc((size_t)(m->nbody > 0 ? m->nbody : 1) * sizeof(int));
    if (!p || !p->motion_body) {
        free(p);
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 2: out of memory");
    }
    p->mo = mo, p->nbody = m->nbody;
    for (int b = 0; b < m->nbody; b++)
        p->motion_body[b] = -1;
    double t0, t1;
    int nt;
    tr_motion_span(mo, &t0, &t1, &nt);
    mcs_status st = MCS_OK;
    for (int i = 0; i < n && !st; i++) {
        const char *src = from && from[i] ? from[i] : bodies[i];
        int b = mb_model_body(m, bodies[i]), k = tr_motion_body(mo, src);
        if (b < 0)
            st = MCS_ERR(err, MCS_ERR_KEY, "stage 2: prescribed body %s: no such body", bodies[i]);
        else if (k < 0)
            st = MCS_ERR(err, MCS_ERR_KEY, "stage 2: prescribed body %s: the motion has no body %s",
                         bodies[i], src);
        else if (t0 > 1e-12 || t1 < m->t_end * (1 - 1e-9))
            st = MCS_ERR(err, MCS_ERR_RANGE,
                         "stage 2: prescribed body %s: the motion spans %.6g to %.6g s, the run "
                         "0 to %.6g s",
                         bodies[i], t0, t1, m->t_end);
        else {
            p->motion_body[b] = k;
            st = mb_model_prescribe(m, b, motion_cb, p, err);
        }
    }
    if (st) { /* the model's bodies free again: the context goes */
        for (int b = 0; b < m->nbody; b++)
            if (p->motion_body[b] >= 0 && m->presc) m->presc[b].fn = NULL;
        tr_prescribe_destroy(&p);
        return st;
    }
    *out = p;
    return MCS_OK;
}

void tr_prescribe_destroy(tr_prescribe **pp)
{
    tr_prescribe *p = pp ? *pp : NULL;
    if (!p) return;
    free(p->motion_body);
    free(p);
    *pp = NULL;
}

const char *tr_prescribe_error(const tr_prescribe *p)
{
    return p->err.msg;
}

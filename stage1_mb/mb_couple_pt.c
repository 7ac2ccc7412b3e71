/* mb_couple_pt.c: body-carried points and the mean coupling force (mb_couple_pt.h) */
#include "stage1_mb/mb_couple_pt.h"
#include "stage1_mb/mb_vec.h"

void mb_couple_pt_local(const mb_body_desc *d, const double x[3], double l[3])
{
    double R[9], q[4];
    mb_quat_unit(d->quat, q);
    mb_quat_to_rot(q, R);
    double r[3] = {x[0] - d->pos[0], x[1] - d->pos[1], x[2] - d->pos[2]};
    for (int i = 0; i < 3; i++) /* R^T r */
        l[i] = R[i] * r[0] + R[3 + i] * r[1] + R[6 + i] * r[2];
}

void mb_couple_pt_now(const mb_state *s, int b, const double l[3], double x[3])
{
    mb_body_kin k;
    mb_body_get(s->world, b, &k);
    for (int i = 0; i < 3; i++)
        x[i] = k.pos[i] + k.rot[3 * i] * l[0] + k.rot[3 * i + 1] * l[1] + k.rot[3 * i + 2] * l[2];
}

void mb_couple_pt_apply(mb_state *s, int n, const int *body, const double *local,
                        const double *force, double *xa)
{
    for (int a = 0; a < n; a++) {
        mb_couple_pt_now(s, body[a], local + 3 * a, xa + 3 * a);
        mb_body_add_force_at_pos(s->world, body[a], force + 3 * a, xa + 3 * a);
    }
}

void mb_couple_mean_force(int n, const double *imp, double sg, double h, double alpha, int started,
                          double *fmean, double *force)
{
    for (int i = 0; i < n; i++) {
        double fm = sg * imp[i] / h, fp = started ? fmean[i] : fm;
        force[i] = fm + alpha * (fm - fp);
        fmean[i] = fm;
    }
}

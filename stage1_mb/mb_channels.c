/* mb_channels.c: contact and joint channels of /stage1/channels (docs/contracts.md).
 * Per contact (its surface pairs summed, at the last step's forces):
 *   <contact>_fn   normal force, sum of the pairs' normal forces [N] (>= 0)
 *   <contact>_ft   friction force, magnitude of the pairs' summed friction vectors [N]
 *   <contact>_pen  penetration, the deepest pair [m]
 * Per revolute / translational joint with a restraint (or range stops):
 *   <joint>_angle | <joint>_disp    joint position from the initial one [rad | m]
 *   <joint>_moment | <joint>_force  restraint load resisting the deflection: characteristic,
 *                                   preload, damper and stop, as applied (the child receives
 *                                   minus this about / along the joint axis) [N m | N]
 * Per spherical / universal joint with a restraint (mb_restraint3, axes i = x, y, z of the
 * restraint frame: the parent's axes; for a universal joint x = axis, y = axis2, no z):
 *   <joint>_angle_<i>   rotation-vector component theta_i of the child relative to the
 *                       parent since the initial posture [rad]
 *   <joint>_moment_<i>  the axis' generalised restraint moment g_i resisting it: preload,
 *                       characteristic, damper and stop, as applied (the torque component
 *                       about axis i for a rotation about that axis alone) [N m]
 * Unfiltered (cfc 0); attribute body: the contact's body a, the joint's child. */
#include "core/mcs_results.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>

#define MB_CH_CONTACT 3 /* channels per contact */
#define MB_CH_JOINT 2   /* channels per one-axis restraint */
#define MB_CH_JOINT3 6  /* channels per three-axis restraint (universal: 4 of them written) */

int mb_channels_count(const mb_model *m)
{
    return MB_CH_CONTACT * m->ncontact + MB_CH_JOINT * m->nrestraint1 +
           MB_CH_JOINT3 * m->nrestraint3;
}

/* one output row: reads the pair and restraint states, writes row[mb_channels_count] */
void mb_channels_sample(const mb_model *m, const mb_state *s, double *row)
{
    for (int c = 0; c < m->ncontact; c++) {
        const mb_contact_def *d = &m->contact[c];
        double fn = 0, ft[3] = {0, 0, 0}, pen = 0;
        for (int p = d->pair0; p < d->pair0 + d->npair; p++) {
            fn += s->pair[p].fn;
            mb_add(ft, s->pair[p].ft, ft);
            pen = fmax(pen, s->pair[p].depth);
        }
        row[MB_CH_CONTACT * c] = fn;
        row[MB_CH_CONTACT * c + 1] = mb_norm(ft);
        row[MB_CH_CONTACT * c + 2] = pen;
    }
    double *jr = row + MB_CH_CONTACT * m->ncontact;
    for (int i = 0; i < m->nrestraint1; i++) {
        jr[MB_CH_JOINT * i] = s->r1[i].x;
        jr[MB_CH_JOINT * i + 1] = -s->r1[i].load;
    }
    double *r3 = jr + MB_CH_JOINT * m->nrestraint1;
    for (int i = 0; i < m->nrestraint3; i++)
        for (int k = 0; k < 3; k++) {
            r3[MB_CH_JOINT3 * i + k] = s->r3[i].theta[k];
            r3[MB_CH_JOINT3 * i + 3 + k] = s->r3[i].load[k];
        }
}

static mcs_status put(const mb_model *m, const mb_state *s, mcs_results *r, double *buf, int col,
                      const char *name, const char *unit, const char *frame, int body,
                      mcs_error *err)
{
    size_t nt = (size_t)s->nrec;
    int nch = mb_channels_count(m);
    for (size_t t = 0; t < nt; t++)
        buf[t] = s->rec_chan[t * (size_t)nch + (size_t)col];
    return mcs_results_put_channel(r, mb_out_stage(m), name, nt, buf, unit, frame, 0,
                                   body >= 0 ? m->body_name[body] : "ground", err);
}

mcs_status mb_channels_write(const mb_model *m, const mb_state *s, mcs_results *r, double *buf,
                             mcs_error *err)
{
    static const char *const csuf[] = {"fn", "ft", "pen"};
    static const char *const cunit[] = {"N", "N", "m"};
    static const char *const cframe[] = {"contact normal", "contact plane (magnitude)",
                                         "contact normal"};
    char name[MB_NAME + 16];
    mcs_status st = MCS_OK;
    for (int c = 0; c < m->ncontact && !st; c++)
        for (int k = 0; k < MB_CH_CONTACT && !st; k++) {
            snprintf(name, sizeof name, "%s_%s", m->contact[c].name, csuf[k]);
            st = put(m, s, r, buf, MB_CH_CONTACT * c + k, name, cunit[k], cframe[k],
                     m->contact[c].body_a, err);
        }
    int base = MB_CH_CONTACT * m->ncontact;
    for (int i = 0; i < m->nrestraint1 && !st; i++) {
        const mb_joint_def *j = &m->joint[m->restraint1[i].joint];
        int rot = j->type == MB_J_REVOLUTE;
        snprintf(name, sizeof name, "%s_%s", j->name, rot ? "angle" : "disp");
        st = put(m, s, r, buf, base + MB_CH_JOINT * i, name, rot ? "rad" : "m", "joint axis",
                 j->child, err);
        if (st) break;
        snprintf(name, sizeof name, "%s_%s", j->name, rot ? "moment" : "force");
        st = put(m, s, r, buf, base + MB_CH_JOINT * i + 1, name, rot ? "N m" : "N", "joint axis",
                 j->child, err);
    }
    base += MB_CH_JOINT * m->nrestraint1;
    static const char axn[3] = {'x', 'y', 'z'};
    for (int i = 0; i < m->nrestraint3 && !st; i++) {
        const mb_joint_def *j = &m->joint[m->restraint3[i].joint];
        int nax = j->type == MB_J_UNIVERSAL ? 2 : 3;
        for (int q = 0; q < 2 && !st; q++)
            for (int k = 0; k < nax && !st; k++) {
                snprintf(name, sizeof name, "%s_%s_%c", j->name, q ? "moment" : "angle", axn[k]);
                st = put(m, s, r, buf, base + MB_CH_JOINT3 * i + 3 * q + k, name, q ? "N m" : "rad",
                         "restraint axes (parent)", j->child, err);
            }
    }
    return st;
}

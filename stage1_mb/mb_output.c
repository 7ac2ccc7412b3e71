/* mb_output.c: /stage1 of the results file (DESIGN.md) from a state's records (/stage2 for a
 * stage-2 model: mb_out_stage):
 *   /stage1/time [nt] s; /stage1/bodies/<b>/{position, orientation, velocity,
 *   angular_velocity, acceleration}; /stage1/channels/<sensor>_<q><axis> [nt] for q = a
 *   (acceleration, m/s^2), v (velocity, m/s), d (displacement, m), w (angular velocity, rad/s),
 *   al (angular acceleration, rad/s^2) and axis x, y, z in the SAE J211 local frame, filtered
 *   with the sensor's CFC when it has one (attribute cfc); /stage1/energy/<kind> [nt] J.
 * Attributes of /stage1: time_step [s], steps, output_rate [Hz], energy_drift [-]. */
#include "analysis/an_cfc.h"
#include "core/mcs_results.h"
#include "stage1_mb/mb_couple_rx.h"
#include "stage1_mb/mb_egroup.h"
#include "stage1_mb/mb_loadcell.h"
#include "stage1_mb/mb_model.h"

#include <stdio.h>
#include <stdlib.h>

static const char *const q_suffix[] = {"a", "v", "d", "w", "al"};
static const char *const q_unit[] = {"m/s^2", "m/s", "m", "rad/s", "rad/s^2"};

static mcs_status write_bodies(const mb_model *m, const mb_state *s, mcs_results *r, double *buf,
                               mcs_error *err)
{
    size_t nt = (size_t)s->nrec;
    for (int b = 0; b < m->nbody; b++) {
        int off = 0;
#define MB_X_BODY(name, width)                                                                     \
    {                                                                                              \
        for (size_t t = 0; t < nt; t++)                                                            \
            for (int k = 0; k < (width); k++)                                                      \
                buf[t * (width) + k] = s->rec_body[(t * m->nbody + b) * MB_BODY_ROW + off + k];    \
        mcs_status st =                                                                            \
            mcs_results_put_body(r, mb_out_stage(m), m->body_name[b], #name, nt, buf, err);        \
        if (st) return st;                                                                         \
        off += (width);                                                                            \
    }
        MB_BODY_FIELDS(MB_X_BODY)
#undef MB_X_BODY
    }
    return MCS_OK;
}

static mcs_status write_channels(const mb_model *m, const mb_state *s, mcs_results *r, double *buf,
                                 mcs_error *err)
{
    size_t nt = (size_t)s->nrec;
    double dt = 1.0 / m->output_rate;
    for (int i = 0; i < m->nsensor; i++) {
        const mb_sensor *se = &m->sensor[i];
        for (int k = 0; k < 3; k++) {
            for (size_t t = 0; t < nt; t++)
                buf[t] = s->rec_sensor[(t * m->nsensor + i) * 3 + k];
            int cfc = se->cfc;
            if (cfc > 0 && nt >= 2) {
                mcs_status st = an_cfc_filter(buf, (int)nt, dt, cfc, buf, err);
                if (st) return st;
            }
            char name[MB_NAME + 8];
            snprintf(name, sizeof name, "%s_%s%c", se->name, q_suffix[se->type], "xyz"[k]);
            mcs_status st =
                mcs_results_put_channel(r, mb_out_stage(m), name, nt, buf, q_unit[se->type],
                                        "SAE J211 local (x forward, y right, z down)",
                                        nt >= 2 ? cfc : 0, m->body_name[se->body], err);
            if (st) return st;
        }
    }
    return MCS_OK;
}

static mcs_status write_energy(const mb_model *m, const mb_state *s, mcs_results *r, double *buf,
                               mcs_error *err)
{
    size_t nt = (size_t)s->nrec;
    int j = 0;
#define MB_X_EN(name, unit)                                                                        \
    {                                                                                              \
        for (size_t t = 0; t < nt; t++)                                                            \
            buf[t] = s->rec_energy[t * MB_NENERGY + j];                                            \
        mcs_status st = mcs_results_put_energy(r, mb_out_stage(m), #name, nt, buf, err);           \
        if (st) return st;                                                                         \
        j++;                                                                                       \
    }
    MB_ENERGY_FIELDS(MB_X_EN)
#undef MB_X_EN
    return MCS_OK;
}

mcs_status mb_output_write(const mb_model *m, const mb_state *s, mcs_results *r, mcs_error *err)
{
    size_t nt = (size_t)s->nrec;
    double *buf = malloc((nt > 0 ? nt : 1) * 4 * sizeof *buf);
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1 output: out of memory");
    char grp[32];
    snprintf(grp, sizeof grp, "/stage%d", mb_out_stage(m));
    mcs_status st = mcs_results_put_time(r, mb_out_stage(m), nt, s->rec_t, err);
    if (!st) st = write_bodies(m, s, r, buf, err);
    if (!st) st = mb_outline_write(m, r, err);
    if (!st) st = write_channels(m, s, r, buf, err);
    if (!st) st = mb_loadcell_write(m, s, r, err);
    if (!st) st = write_energy(m, s, r, buf, err);
    if (!st) st = mb_channels_write(m, s, r, buf, err);
    if (!st) st = mcs_results_set_attr_double(r, grp, "time_step", m->h, err);
    if (!st) st = mcs_results_set_attr_double(r, grp, "output_rate", m->output_rate, err);
    if (!st) st = mcs_results_set_attr_int(r, grp, "steps", (int)s->step, err);
    if (!st) st = mcs_results_set_attr_double(r, grp, "energy_drift", mb_energy_drift(m, s), err);
    /* the rider's Hybrid III size (rider: dummy:): mcrash injury's intercepts and limits */
    if (!st && m->rider_dummy[0])
        st = mcs_results_set_attr_str(r, grp, "dummy", m->rider_dummy, err);
    /* fire_time of the coupled bags and retractors (their groups: mb_couple_out.c) */
    if (!st) st = mb_couple_trigger_write(m, s, r, err);
    if (!st) st = mb_egroup_write(m, s, r, mb_out_stage(m), err); /* the rider's (mb_egroup.h) */
    free(buf);
    return st;
}

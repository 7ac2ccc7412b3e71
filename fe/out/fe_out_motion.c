/* fe_out_motion.c: each element part's mass, centre of mass, mean velocity and mean
 * acceleration into /stage<N>/parts (fe_out_motion.h) */
#include "fe/out/fe_out_motion.h"

#include <stdio.h>
#include <stdlib.h>

static const char *const what[3] = {"position", "velocity", "acceleration"};
static const char *const unit[3] = {"m", "m/s", "m/s^2"};

mcs_status fe_out_motion_open(mcs_results *r, int stage, const fe_model *m, fe_out_motion *o,
                              mcs_error *err)
{
    o->n = m->npart;
    o->mass = calloc((size_t)(o->n > 0 ? o->n : 1), sizeof *o->mass);
    o->ser = calloc((size_t)(o->n > 0 ? o->n : 1) * 3, sizeof *o->ser);
    if (!o->mass || !o->ser)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage %d: out of memory (part motion)", stage);
    for (int n = 0; n < m->nnode; n++) {
        const int p = m->node_part[n];
        if (p >= 0 && p < o->n && (!m->node_body || m->node_body[n] < 0))
            o->mass[p] += m->node_mass[n];
    }
    mcs_status st = MCS_OK;
    const size_t three = 3, one = 1;
    for (int p = 0; p < o->n && !st; p++) {
        if (!(o->mass[p] > 0)) continue;
        char path[256];
        snprintf(path, sizeof path, "/stage%d/parts/%s/mass", stage, m->part[p].name);
        st = mcs_results_write(r, path, 1, &one, &o->mass[p], "kg", err);
        for (int k = 0; k < 3 && !st; k++) {
            snprintf(path, sizeof path, "/stage%d/parts/%s/motion/%s", stage, m->part[p].name,
                     what[k]);
            st = mcs_results_series_create(r, path, 2, &three, unit[k], 0, &o->ser[3 * p + k], err);
        }
    }
    return st;
}

mcs_status fe_out_motion_sample(const fe_model *m, const fe_state *s, const fe_out_motion *o,
                                mcs_error *err)
{
    if (o->n <= 0) return MCS_OK;
    double *sum = calloc((size_t)o->n * 9, sizeof *sum);
    if (!sum) return MCS_ERR(err, MCS_ERR_NOMEM, "out of memory (part motion)");
    for (int n = 0; n < m->nnode; n++) {
        const int p = m->node_part[n];
        if (p < 0 || p >= o->n || !(o->mass[p] > 0) || (m->node_body && m->node_body[n] >= 0))
            continue;
        const double mn = m->node_mass[n];
        for (int k = 0; k < 3; k++) {
            sum[9 * p + k] += mn * s->node_x[3 * n + k];
            sum[9 * p + 3 + k] += mn * s->node_v[3 * n + k];
            sum[9 * p + 6 + k] += mn * s->node_a[3 * n + k];
        }
    }
    mcs_status st = MCS_OK;
    for (int p = 0; p < o->n && !st; p++) {
        if (!(o->mass[p] > 0)) continue;
        for (int j = 0; j < 9; j++)
            sum[9 * p + j] /= o->mass[p];
        for (int k = 0; k < 3 && !st; k++)
            st = mcs_results_series_append(o->ser[3 * p + k], sum + 9 * p + 3 * k, err);
    }
    free(sum);
    return st;
}

void fe_out_motion_free(fe_out_motion *o)
{
    free(o->mass);
    free(o->ser);
    *o = (fe_out_motion){0};
}

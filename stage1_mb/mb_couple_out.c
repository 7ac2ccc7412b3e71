/* mb_couple_out.c: the coupled FE parts' /stage1 (/stage2) output (mb_couple_out.h), written as a
 * stage-3 run writes /stage3 (stage3_fe/s3_run.c): with fe/fe_out.h and stage 1. */
#include "stage1_mb/mb_couple_out.h"
#include "fe/fe_out.h"
#include "stage1_mb/mb_couple.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct mb_couple_out {
    long rows;        /* stage-1 output rows sampled so far             */
    long field_every; /* a field at every k-th row (simulation.field_rate) */
    fe_out fe;        /* fields, contacts, restraints, slip rings, parts (fe/fe_out.h) */
    /* bodies contacts: /stage1/contact/<name>/force, the sum over their kernel surfaces */
    int ngroup;
    mcs_results_series *gforce[FE_ELLIPSOID_MAX + FE_FACETS_MAX];
    int ell_group[FE_ELLIPSOID_MAX], fac_group[FE_FACETS_MAX]; /* -1: none */
};

/* the contact a kernel surface of a bodies contact belongs to: its name "<contact>:<surface>"
 * (mb_couple_contact.c); len 0 for other surfaces */
static size_t contact_prefix(const char *name)
{
    const char *c = strchr(name, ':');
    return c ? (size_t)(c - name) : 0;
}

/* group index of the surface name among names[0..*n-1] (added when new); -1: no contact */
static int group_of(const char *name, char (*names)[FE_NAME_MAX], int *n)
{
    size_t len = contact_prefix(name);
    if (len == 0) return -1;
    for (int g = 0; g < *n; g++)
        if (strlen(names[g]) == len && strncmp(names[g], name, len) == 0) return g;
    snprintf(names[*n], FE_NAME_MAX, "%.*s", (int)len, name);
    return (*n)++;
}

static mcs_status open_groups(mcs_results *r, int stage, const fe_model *fm, mb_couple_out *o,
                              mcs_error *err)
{
    const fe_contact_model *c = fm->contact;
    char names[FE_ELLIPSOID_MAX + FE_FACETS_MAX][FE_NAME_MAX];
    int n = 0;
    for (int i = 0; i < FE_ELLIPSOID_MAX; i++)
        o->ell_group[i] = -1;
    for (int i = 0; i < FE_FACETS_MAX; i++)
        o->fac_group[i] = -1;
    for (int i = 0; c && i < c->nell; i++)
        o->ell_group[i] = group_of(c->ell[i].name, names, &n);
    for (int i = 0; c && i < c->nfac; i++)
        o->fac_group[i] = group_of(c->fac[i].name, names, &n);
    o->ngroup = n;
    const size_t three = 3;
    mcs_status st = MCS_OK;
    for (int g = 0; g < n && !st; g++) {
        char path[FE_NAME_MAX + 64];
        snprintf(path, sizeof path, "/stage%d/contact/%.*s/force", stage, FE_NAME_MAX - 1,
                 names[g]);
        st = mcs_results_series_create(r, path, 2, &three, "N", 0, &o->gforce[g], err);
    }
    return st;
}

/* force on the FE side of each bodies contact: minus the structure's on its surfaces */
static mcs_status sample_groups(const fe_model *fm, const fe_state *f, const mb_couple_out *o,
                                mcs_error *err)
{
    const fe_contact_model *c = fm->contact;
    double sum[FE_ELLIPSOID_MAX + FE_FACETS_MAX][3] = {{0}};
    for (int i = 0; c && i < c->nell; i++)
        for (int k = 0; k < 3 && o->ell_group[i] >= 0; k++)
            sum[o->ell_group[i]][k] -= f->contact->ell_force[3 * i + k];
    for (int i = 0; c && i < c->nfac; i++)
        for (int k = 0; k < 3 && o->fac_group[i] >= 0; k++)
            sum[o->fac_group[i]][k] -= f->contact->fac_force[3 * i + k];
    mcs_status st = MCS_OK;
    for (int g = 0; g < o->ngroup && !st; g++)
        st = mcs_results_series_append(o->gforce[g], sum[g], err);
    return st;
}

mcs_status mb_couple_out_open(const mb_model *m, mcs_results *r, mb_couple_out **out,
                              mcs_error *err)
{
    *out = NULL;
    if (!m->couple) return MCS_OK;
    const fe_model *fm = m->couple->fe.model;
    mb_couple_out *o = calloc(1, sizeof *o);
    if (!o) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    *out = o;
    /* field_rate (its default: FE_SCN_FIELD_FRAMES per run, fe_scn_field_rate) -> every k-th
     * output row */
    const fe_problem *p = &m->couple->fe;
    o->field_every = lround(fmax(1.0, m->output_rate / fe_scn_field_rate(p)));
    int stage = mb_out_stage(m);
    mcs_status st = fe_out_meshes(r, stage, fm, err);
    if (!st) st = fe_out_open(r, stage, fm, &o->fe, err);
    if (!st) st = open_groups(r, stage, fm, o, err);
    return st;
}

mcs_status mb_couple_out_sample(const mb_model *m, const mb_state *s, mb_couple_out *o,
                                mcs_error *err)
{
    if (!o) return MCS_OK;
    const fe_model *fm = m->couple->fe.model;
    const fe_state *f = s->couple->fe;
    mcs_status st = MCS_OK;
    /* the FE state is that of the last recorded row: a row per step at most */
    for (; o->rows < s->nrec && !st; o->rows++) {
        if (o->rows % o->field_every == 0)
            st = fe_out_field_sample(fm, f, s->rec_t[o->rows], &o->fe.field, err);
        if (!st) st = fe_out_sample(fm, f, &o->fe, err);
        if (!st) st = sample_groups(fm, f, o, err);
    }
    return st;
}

void mb_couple_out_free(mb_couple_out **po)
{
    mb_couple_out *o = po ? *po : NULL;
    if (!o) return;
    fe_out_free(&o->fe);
    free(o);
    *po = NULL;
}

/* mb_egroup_work.c: the energy groups' step, balance and output (mb_egroup.h) */
#include "core/mcs_hysteresis.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_contact.h"
#include "stage1_mb/mb_couple_rx.h"
#include "stage1_mb/mb_egroup_impl.h"
#include "stage1_mb/mb_vec.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the step's work ---------------------------------------------------------------------- */

/* work over the step of force f at world point p (at the step's start) on body b [J] */
static double point_work(const mb_state *s, int b, const double f[3], const double p[3], double h)
{
    const double *vb = s->egroup->vbar + 6 * b;
    double r[3], wr[3];
    mb_sub(p, s->kin[b].pos, r);
    mb_cross(vb + 3, r, wr);
    return h * (f[0] * (vb[0] + wr[0]) + f[1] * (vb[1] + wr[1]) + f[2] * (vb[2] + wr[2]));
}

/* work of force f at the CG and moment t on body b [J] */
static double load_work(const mb_state *s, int b, const double f[3], const double t[3], double h)
{
    const double *vb = s->egroup->vbar + 6 * b;
    return h * (mb_dot(f, vb) + mb_dot(t, vb + 3));
}

/* world point of body-frame point l (about the CG) of body b at the step's start */
static void body_point(const mb_state *s, int b, const double l[3], double x[3])
{
    mb_mat_vec(s->kin[b].rot, l, x);
    mb_add(x, s->kin[b].pos, x);
}

static void pairs_work(const mb_model *m, mb_state *s, const eg_group *g, double *w)
{
    for (int i = 0; i < m->npair; i++) {
        const int p = g->pair[i];
        const mb_pair_state *ps = &s->pair[i];
        if (p < 0 || (ps->fn == 0 && ps->ft[0] == 0 && ps->ft[1] == 0 && ps->ft[2] == 0)) continue;
        const mb_contact *c = &s->pc[i];
        double f[3];
        mb_axpy(ps->ft, ps->fn, c->normal, f); /* on body a (mb_contact.c) */
        int b = m->pair[i].ba;
        if (!g->in[b]) b = m->pair[i].bb, mb_scale(f, -1, f);
        w[p] += point_work(s, b, f, c->point, m->h);
    }
}

static void attach_work(const mb_model *m, mb_state *s, const eg_group *g, double *w)
{
    for (int i = 0; i < m->nattach; i++) {
        const mb_attach_model *a = &m->attach[i];
        const mb_attach_state *t = &s->att[i];
        if (g->att[i] < 0 || t->broken) continue;
        double x[3], f[3];
        if (g->in[a->body_a]) {
            body_point(s, a->body_a, a->pa, x);
            w[g->att[i]] += point_work(s, a->body_a, t->force, x, m->h);
        } else {
            body_point(s, a->body_b, a->pb, x);
            mb_scale(t->force, -1, f);
            w[g->att[i]] += point_work(s, a->body_b, f, x, m->h);
        }
    }
}

/* joints across the boundary: the constraint reaction and a one-axis restraint's load */
static void joints_work(const mb_model *m, mb_state *s, const eg_group *g, double *w)
{
    for (int j = 0; j < m->njoint; j++) {
        if (g->joint[j] < 0) continue;
        const mb_joint_def *d = &m->joint[j];
        const int child = d->child >= 0 && g->in[d->child];
        const int b = child ? d->child : d->parent;
        double f[3], t[3], ax[3];
        if (child)
            mb_joint_reaction(s->world, j, f, t);
        else
            mb_joint_reaction_parent(s->world, j, f, t);
        const int r = d->restraint;
        if (r >= 0 && (d->type == MB_J_REVOLUTE || d->type == MB_J_TRANSLATIONAL)) {
            double load = child ? s->r1[r].load : -s->r1[r].load;
            mb_joint_axis(s->world, j, ax);
            mb_axpy(d->type == MB_J_REVOLUTE ? t : f, load, ax, d->type == MB_J_REVOLUTE ? t : f);
        }
        w[g->joint[j]] += load_work(s, b, f, t, m->h);
    }
}

/* the FE parts' loads applied at points: attached nodes and anchors */
static void fe_work(const mb_model *m, mb_state *s, const eg_group *g, double *w)
{
    const mb_couple *c = m->couple;
    const mb_couple_state *cs = s->couple;
    for (int a = 0; a < g->nnode; a++)
        if (g->node[a] >= 0)
            w[g->node[a]] += point_work(s, c->body[a], cs->force + 3 * a, cs->xa + 3 * a, m->h);
    for (int a = 0; a < g->nanchor; a++)
        if (g->anchor[a] >= 0)
            w[g->anchor[a]] += point_work(s, c->rx->anchor_body[a], cs->rx->force + 3 * a,
                                          cs->rx->xa + 3 * a, m->h);
    for (int k = 0; k < g->nsurf; k++) {
        if (g->surf[k] < 0) continue;
        int ct;
        const int b = mb_couple_contact_surf(m, k, &ct);
        const double *f = mb_couple_contact_surf_force(m, s, k);
        w[g->surf[k]] += load_work(s, b, f, f + 3, m->h);
    }
}

void mb_egroup_step(const mb_model *m, mb_state *s)
{
    double *vbar = s->egroup->vbar;
    for (int b = 0; b < m->nbody; b++) {
        mb_body_kin k;
        mb_body_get(s->world, b, &k);
        for (int i = 0; i < 3; i++) {
            vbar[6 * b + i] = 0.5 * (s->kin[b].vel[i] + k.vel[i]);
            vbar[6 * b + 3 + i] = 0.5 * (s->kin[b].angvel[i] + k.angvel[i]);
        }
    }
    for (int i = 0; i < m->egroup->ngroup; i++) {
        const eg_group *g = &m->egroup->g[i];
        double *w = s->egroup->work[i];
        pairs_work(m, s, g, w);
        attach_work(m, s, g, w);
        joints_work(m, s, g, w);
        if (m->couple) fe_work(m, s, g, w);
    }
}

/* ---- the balance ------------------------------------------------------------------------- */

static double kinetic(const mb_model *m, const mb_state *s, const eg_group *g)
{
    double e = 0;
    for (int b = 0; b < m->nbody; b++)
        if (g->in[b]) e += mb_body_kinetic(m, s, b);
    return e;
}

static double potential(const mb_model *m, const mb_state *s, const eg_group *g)
{
    double e = 0;
    for (int b = 0; b < m->nbody; b++)
        if (g->in[b]) e -= m->body[b].mass * mb_dot(m->gravity, s->kin[b].pos);
    return e;
}

/* stored + dissipated of a contact pair at the new penetration (as mb_energy.c) */
static double pair_energy(const mb_model *m, const mb_state *s, int i)
{
    const mcs_hyst_model *h = &m->pair[i].hyst;
    double x = s->pc[i].depth > 0 ? s->pc[i].depth : 0;
    double e = s->pair[i].e_damp + s->pair[i].e_fric;
    if (x == 0 && s->pair[i].h.x_max == 0) return e;
    mcs_hyst_state t = s->pair[i].h;
    mcs_hyst_update(h, &t, x);
    double st = x > 0 ? mcs_hyst_stored(h, &t) : 0;
    e += st;
    if (h->unload != MCS_UNLOAD_ELASTIC && t.x_max > h->elastic_limit) e += t.work - st;
    return e;
}

/* internal: the contacts, restraints and attachments between two members */
static double internal(const mb_model *m, const mb_state *s, const eg_group *g)
{
    double e = 0;
    for (int i = 0; i < m->npair; i++)
        if (g->pair[i] == EG_INTERNAL) e += pair_energy(m, s, i);
    for (int i = 0; i < m->nrestraint1; i++) {
        const mb_restraint_model *r = &m->restraint1[i];
        if (g->joint[r->joint] != EG_INTERNAL) continue;
        mb_restraint_state t = s->r1[i];
        mb_restraint_spring(r, &t, mb_joint_position(s->world, r->joint));
        e += mb_restraint_stored(r, &t) + mb_restraint_dissipated(r, &t);
    }
    for (int i = 0; i < m->nrestraint3; i++)
        if (g->joint[m->restraint3[i].joint] == EG_INTERNAL)
            e += mb_restraint3_stored(&m->restraint3[i], &s->r3[i]) +
                 mb_restraint3_dissipated(&m->restraint3[i], &s->r3[i]);
    for (int i = 0; i < m->nattach; i++)
        if (g->att[i] == EG_INTERNAL)
            e += mb_attach_stored(&m->attach[i], &s->att[i]) + s->att[i].e_damp + s->att[i].e_lost;
    return e;
}

void mb_egroup_now(const mb_model *m, const mb_state *s, int gi, double *e, double *partner)
{
    const eg_group *g = &m->egroup->g[gi];
    const double *w = s->egroup->work[gi];
    double c = 0;
    for (int p = 0; p < g->npartner; p++)
        partner[p] = 0.0 - w[p]; /* no -0 */
    for (int p = 0; p < g->npartner; p++)
        c += partner[p];
    e[0] = kinetic(m, s, g);
    e[1] = potential(m, s, g);
    e[2] = internal(m, s, g);
    e[3] = c;
    e[4] = e[0] + e[1] + e[2] + e[3];
}

void mb_egroup_record(const mb_model *m, mb_state *s, long row)
{
    for (int i = 0; i < m->egroup->ngroup; i++) {
        const size_t wd = (size_t)(MB_EGROUP_NSERIES + m->egroup->g[i].npartner);
        double *r = s->egroup->rec[i] + (size_t)row * wd;
        mb_egroup_now(m, s, i, r, r + MB_EGROUP_NSERIES);
    }
}

/* ---- output ------------------------------------------------------------------------------ */

static const char *const series_name[MB_EGROUP_NSERIES] = {"kinetic", "potential", "internal",
                                                           "contact_total", "total"};

static mcs_status put(mcs_results *r, const char *path, const double *rec, size_t wd, int col,
                      size_t nt, double *buf, mcs_error *err)
{
    for (size_t t = 0; t < nt; t++)
        buf[t] = rec[t * wd + (size_t)col];
    return mcs_results_write(r, path, 1, &nt, buf, "J", err);
}

static mcs_status write_group(const mb_model *m, const mb_state *s, int gi, mcs_results *r,
                              int stage, double *buf, mcs_error *err)
{
    const eg_group *g = &m->egroup->g[gi];
    const size_t nt = (size_t)s->nrec, wd = (size_t)(MB_EGROUP_NSERIES + g->npartner);
    const double *rec = s->egroup->rec[gi];
    char path[3 * MB_NAME + 64], base[MB_NAME + 48];
    snprintf(base, sizeof base, "/stage%d/energy_groups/%s", stage, g->name);
    mcs_status st = MCS_OK;
    for (int k = 0; k < MB_EGROUP_NSERIES && !st; k++) {
        snprintf(path, sizeof path, "%s/%s", base, series_name[k]);
        st = put(r, path, rec, wd, k, nt, buf, err);
    }
    for (int p = 0; p < g->npartner && !st; p++) {
        snprintf(path, sizeof path, "%s/contact/%s", base, g->pname[p]);
        st = put(r, path, rec, wd, MB_EGROUP_NSERIES + p, nt, buf, err);
        if (!st) st = mcs_results_set_attr_str(r, path, "category", g->pcat[p], err);
    }
    /* the members, one string */
    size_t len = 1;
    for (int b = 0; b < m->nbody; b++)
        len += g->in[b] ? strlen(m->body_name[b]) + 1 : 0;
    char *names = calloc(len, 1);
    if (!names) return MCS_ERR(err, MCS_ERR_NOMEM, "energy groups: out of memory");
    for (int b = 0; b < m->nbody; b++)
        if (g->in[b]) {
            if (names[0]) strcat(names, " ");
            strcat(names, m->body_name[b]);
        }
    if (!st) st = mcs_results_set_attr_str(r, base, "bodies", names, err);
    free(names);
    return st;
}

mcs_status mb_egroup_write(const mb_model *m, const mb_state *s, mcs_results *r, int stage,
                           mcs_error *err)
{
    if (!m->egroup || s->nrec == 0) return MCS_OK;
    double *buf = malloc(sizeof *buf * (size_t)s->nrec);
    if (!buf) return MCS_ERR(err, MCS_ERR_NOMEM, "energy groups: out of memory");
    mcs_status st = MCS_OK;
    for (int i = 0; i < m->egroup->ngroup && !st; i++)
        st = write_group(m, s, i, r, stage, buf, err);
    free(buf);
    return st;
}

/* ---- queries ------------------------------------------------------------------------------ */

int mb_egroup_count(const mb_model *m)
{
    return m->egroup ? m->egroup->ngroup : 0;
}

int mb_egroup_find(const mb_model *m, const char *name)
{
    for (int i = 0; i < mb_egroup_count(m); i++)
        if (strcmp(m->egroup->g[i].name, name) == 0) return i;
    return -1;
}

int mb_egroup_npartner(const mb_model *m, int g)
{
    return m->egroup->g[g].npartner;
}

const char *mb_egroup_partner(const mb_model *m, int g, int p, const char **category)
{
    if (category) *category = m->egroup->g[g].pcat[p];
    return m->egroup->g[g].pname[p];
}

int mb_egroup_partner_find(const mb_model *m, int g, const char *name)
{
    for (int p = 0; p < m->egroup->g[g].npartner; p++)
        if (strcmp(m->egroup->g[g].pname[p], name) == 0) return p;
    return -1;
}

/* s3_carcase.c: pitch, the vehicles' velocities and the door intrusion of a generated
 * motorcycle meeting a generated sedan side (s3_carcase.h). Buffers are made at open; a sample
 * only reads the state and appends rows. */
#include "stage3_fe/s3_carcase.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the door's panels and their intrusion channels */
static const char *const panel[2] = {"door_outer", "door_inner"};
static const char *const channel[2] = {"door_intrusion", "door_inner_intrusion"};

struct s3_carcase {
    char pm[FE_NAME_MAX], ps[FE_NAME_MAX]; /* the motorcycle's and the sedan's name prefixes */
    int frame, body;                 /* bodies: the motorcycle's frame, the sedan's rest      */
    int door[2];                     /* parts <s>_door_outer, <s>_door_inner                  */
    unsigned char *veh;              /* (nnode + nbody) 1 motorcycle, 2 sedan, 0 neither       */
    double mass[2];                  /* the vehicles' masses [kg]                             */
    mcs_results_series *pitch, *vel[2], *intr[2];
    double intr_max[2];              /* largest intrusion of each panel so far [m]            */
    int intr_node[2];                /* its node                                              */
};

static int has_prefix(const char *name, const char *pre)
{
    const size_t k = strlen(pre);
    return strncmp(name, pre, k) == 0 && name[k] == '_';
}

static int body_named(const fe_model *m, const char *pre, const char *comp)
{
    char nm[2 * FE_NAME_MAX];
    snprintf(nm, sizeof nm, "%s_%s", pre, comp);
    for (int b = 0; b < m->nbody; b++)
        if (strcmp(m->body[b].name, nm) == 0) return b;
    return -1;
}

/* the prefix of a body named <pre>_<suffix>, into pre; 0 when none */
static int find_prefix(const fe_model *m, const char *suffix, char *pre, size_t n)
{
    const size_t k = strlen(suffix);
    for (int b = 0; b < m->nbody; b++) {
        const size_t l = strlen(m->body[b].name);
        if (l > k + 1 && strcmp(m->body[b].name + l - k, suffix) == 0 &&
            m->body[b].name[l - k - 1] == '_') {
            snprintf(pre, n, "%.*s", (int)(l - k - 1), m->body[b].name);
            return 1;
        }
    }
    return 0;
}

/* each free node and body to its vehicle by its part's (body's) name prefix; the masses */
static void classify(const fe_model *m, s3_carcase *c)
{
    for (int n = 0; n < m->nnode; n++) {
        if (m->node_body[n] >= 0 || m->node_part[n] < 0) continue;
        const char *nm = m->part[m->node_part[n]].name;
        c->veh[n] = has_prefix(nm, c->pm) ? 1 : has_prefix(nm, c->ps) ? 2 : 0;
        if (c->veh[n]) c->mass[c->veh[n] - 1] += m->node_mass[n];
    }
    for (int b = 0; b < m->nbody; b++) {
        const char *nm = m->body[b].name;
        unsigned char v = has_prefix(nm, c->pm) ? 1 : has_prefix(nm, c->ps) ? 2 : 0;
        c->veh[m->nnode + b] = v;
        if (v) c->mass[v - 1] += m->body[b].mass;
    }
}

mcs_status s3_carcase_open(mcs_results *r, const fe_model *m, s3_carcase **out, mcs_error *err)
{
    *out = NULL;
    char pm[FE_NAME_MAX], ps[FE_NAME_MAX], nm[2 * FE_NAME_MAX];
    if (!find_prefix(m, "upper_fork", pm, sizeof pm) || !find_prefix(m, "body", ps, sizeof ps))
        return MCS_OK;
    const int frame = body_named(m, pm, "frame"), body = body_named(m, ps, "body");
    int door[2] = {-1, -1};
    for (int i = 0; i < 2; i++) {
        snprintf(nm, sizeof nm, "%s_%s", ps, panel[i]);
        for (int p = 0; p < m->npart; p++)
            if (strcmp(m->part[p].name, nm) == 0) door[i] = p;
    }
    if (frame < 0 || body < 0 || door[0] < 0 || door[1] < 0) return MCS_OK;
    s3_carcase *c = calloc(1, sizeof *c);
    if (c) c->veh = calloc((size_t)(m->nnode + m->nbody), 1);
    if (!c || !c->veh) {
        s3_carcase_free(&c);
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 3: out of memory (car case)");
    }
    snprintf(c->pm, sizeof c->pm, "%s", pm);
    snprintf(c->ps, sizeof c->ps, "%s", ps);
    c->frame = frame, c->body = body;
    for (int i = 0; i < 2; i++) c->door[i] = door[i], c->intr_node[i] = -1;
    classify(m, c);
    char path[512];
    snprintf(path, sizeof path, "/stage3/channels/%s_pitch", pm);
    mcs_status st = mcs_results_series_create(r, path, 1, NULL, "rad", 0, &c->pitch, err);
    if (!st) st = mcs_results_set_attr_str(r, path, "body", m->body[frame].name, err);
    for (int v = 0; v < 2 && !st; v++) {
        const size_t three = 3;
        snprintf(path, sizeof path, "/stage3/channels/%s_velocity", v ? ps : pm);
        st = mcs_results_series_create(r, path, 2, &three, "m/s", 0, &c->vel[v], err);
        if (!st) st = mcs_results_set_attr_double(r, path, "mass", c->mass[v], err);
    }
    for (int i = 0; i < 2 && !st; i++) {
        snprintf(path, sizeof path, "/stage3/channels/%s_%s", ps, channel[i]);
        st = mcs_results_series_create(r, path, 1, NULL, "m", 0, &c->intr[i], err);
        if (!st) st = mcs_results_set_attr_str(r, path, "part", m->part[door[i]].name, err);
    }
    if (st) s3_carcase_free(&c);
    *out = c;
    return st;
}

mcs_status s3_carcase_sample(const fe_model *m, const fe_state *s, s3_carcase *c,
                             mcs_error *err)
{
    if (!c) return MCS_OK;
    const double *R = s->body_rot + 9 * c->frame; /* row-major: R[6] = z of the body's x axis */
    const double pitch = -asin(fmax(-1.0, fmin(1.0, R[6])));
    mcs_status st = mcs_results_series_append(c->pitch, &pitch, err);
    double p[2][3] = {{0}};
    for (int n = 0; n < m->nnode; n++)
        if (c->veh[n])
            for (int k = 0; k < 3; k++) p[c->veh[n] - 1][k] += m->node_mass[n] * s->node_v[3 * n + k];
    for (int b = 0; b < m->nbody; b++)
        if (c->veh[m->nnode + b])
            for (int k = 0; k < 3; k++)
                p[c->veh[m->nnode + b] - 1][k] += m->body[b].mass * s->body_v[3 * b + k];
    for (int v = 0; v < 2 && !st; v++) {
        double u[3];
        for (int k = 0; k < 3; k++) u[k] = p[v][k] / c->mass[v];
        st = mcs_results_series_append(c->vel[v], u, err);
    }
    /* intrusion: the inner panel's nodes in the rest's frame (R^T (x - c)) against their
     * initial places about its initial centre, along +x */
    const fe_body *B = &m->body[c->body];
    const double *Rb = s->body_rot + 9 * c->body, *cb = s->body_x + 3 * c->body;
    double dmax[2] = {0, 0};
    int nmax[2] = {-1, -1};
    for (int n = 0; n < m->nnode; n++) {
        const int i = m->node_part[n] == c->door[0] ? 0 : m->node_part[n] == c->door[1] ? 1 : -1;
        if (i < 0 || m->node_body[n] >= 0) continue;
        double d[3];
        for (int k = 0; k < 3; k++) d[k] = s->node_x[3 * n + k] - cb[k];
        const double xl = Rb[0] * d[0] + Rb[3] * d[1] + Rb[6] * d[2]; /* (R^T d)_x */
        const double in = xl - (m->node_x0[3 * n] - B->x0[0]);
        if (in > dmax[i]) dmax[i] = in, nmax[i] = n;
    }
    for (int i = 0; i < 2 && !st; i++) {
        if (dmax[i] > c->intr_max[i]) c->intr_max[i] = dmax[i], c->intr_node[i] = nmax[i];
        st = mcs_results_series_append(c->intr[i], &dmax[i], err);
    }
    return st;
}

mcs_status s3_carcase_finish(mcs_results *r, s3_carcase **cp, mcs_error *err)
{
    s3_carcase *c = *cp;
    if (!c) return MCS_OK;
    char path[512];
    mcs_status st = MCS_OK;
    for (int i = 0; i < 2 && !st; i++) {
        snprintf(path, sizeof path, "/stage3/channels/%s_%s", c->ps, channel[i]);
        st = mcs_results_set_attr_int(r, path, "node", c->intr_node[i], err);
    }
    s3_carcase_free(cp);
    return st;
}

void s3_carcase_free(s3_carcase **cp)
{
    if (!*cp) return;
    free((*cp)->veh);
    free(*cp);
    *cp = NULL;
}

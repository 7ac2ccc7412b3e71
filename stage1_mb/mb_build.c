/* mb_build.c: scenario tree -> mb_model: simulation options, gravity, bodies, sensors; the
 * contact and joint parts are in mb_build_contact.c and mb_build_joint.c. Defaults where the
 * scenario is silent: time_step 10 us, output_rate 10 kHz (at most one sample per step),
 * gravity 9.81 m/s^2 along -z. */
#include "stage1_mb/mb_build_internal.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_egroup.h"
#include "stage1_mb/mb_impact.h"
#include "stage1_mb/mb_loadcell.h"
#include "stage1_mb/mb_position.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

mb_opts mb_opts_default(void)
{
    return (mb_opts){.energy_tol = 0.05, .energy_floor = 1e-9, .slip_speed = 0.01, .stage = 1};
}

int mb_out_stage(const mb_model *m)
{
    return m->opts.stage > 0 ? m->opts.stage : 1;
}

int mb_model_body(const mb_model *m, const char *name)
{
    for (int i = 0; i < m->nbody; i++)
        if (strcmp(m->body_name[i], name) == 0) return i;
    return -1;
}

int mb_build_body_ref(const mb_model *m, const mcs_node *ref)
{
    const char *s = mcs_node_str(ref);
    if (!s || strcmp(s, "ground") == 0) return MB_GROUND;
    return mb_model_body(m, s);
}

int mb_build_char_ref(const mb_model *m, const mcs_node *ref)
{
    const char *s = mcs_node_str(ref);
    for (int i = 0; s && i < m->nchar; i++)
        if (strcmp(m->chr[i].name, s) == 0) return i;
    return -1;
}

mcs_status mb_build_dir(const mcs_node *n, double v[3], mcs_error *err)
{
    mcs_status st = mcs_node_vec3(n, v, err);
    if (st) return st;
    if (!(mb_normalize(v) > 0))
        return mcs_node_error(n, err, MCS_ERR_RANGE, "direction must not be zero");
    return MCS_OK;
}

void mb_build_cardan(const double rpy[3], double R[9])
{
    static const double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0}, ez[3] = {0, 0, 1};
    double Rx[9], Ry[9], Rz[9], T[9];
    mb_rot_axis_angle(ex, rpy[0], Rx);
    mb_rot_axis_angle(ey, rpy[1], Ry);
    mb_rot_axis_angle(ez, rpy[2], Rz);
    mb_mat_mul(Rz, Ry, T);
    mb_mat_mul(T, Rx, R);
}

/* quaternion w, x, y, z of a rotation matrix (Shepperd) */
static void rot_to_quat(const double R[9], double q[4])
{
    double tr = R[0] + R[4] + R[8];
    if (tr > 0) {
        double s = 2 * sqrt(tr + 1);
        q[0] = s / 4, q[1] = (R[7] - R[5]) / s, q[2] = (R[2] - R[6]) / s, q[3] = (R[3] - R[1]) / s;
    } else if (R[0] > R[4] && R[0] > R[8]) {
        double s = 2 * sqrt(1 + R[0] - R[4] - R[8]);
        q[0] = (R[7] - R[5]) / s, q[1] = s / 4, q[2] = (R[1] + R[3]) / s, q[3] = (R[2] + R[6]) / s;
    } else if (R[4] > R[8]) {
        double s = 2 * sqrt(1 + R[4] - R[0] - R[8]);
        q[0] = (R[2] - R[6]) / s, q[1] = (R[1] + R[3]) / s, q[2] = s / 4, q[3] = (R[5] + R[7]) / s;
    } else {
        double s = 2 * sqrt(1 + R[8] - R[0] - R[4]);
        q[0] = (R[3] - R[1]) / s, q[1] = (R[2] + R[6]) / s, q[2] = (R[5] + R[7]) / s, q[3] = s / 4;
    }
}

static mcs_status build_simulation(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *sim = mcs_node_get(root, "simulation");
    if (mcs_node_kind(sim) != MCS_NODE_MAP)
        return mcs_node_error(root, err, MCS_ERR_KEY,
                              "simulation: missing: a model file has no end_time and cannot run");
    m->t_end = mcs_node_num(mcs_node_get(sim, "end_time"));
    m->h = mcs_node_num_or(sim, "time_step", 10e-6);
    m->output_rate = mcs_node_num_or(sim, "output_rate", 10e3);
    if (m->output_rate * m->h > 1) m->output_rate = 1 / m->h;
    m->nsteps = (long)ceil(m->t_end / m->h - 1e-9);
    if (m->nsteps > 2000000000L)
        return mcs_node_error(sim, err, MCS_ERR_RANGE, "%g s at %g s steps is too many steps",
                              m->t_end, m->h);
    double every = floor(1.0 / (m->output_rate * m->h) + 0.5);
    m->out_every = every < 1 ? 1 : (int)every;
    m->output_rate = 1.0 / (m->out_every * m->h);
    m->nout = m->nsteps / m->out_every + 1;
    const mcs_node *env = mcs_node_get(root, "environment");
    double g = mcs_node_num_or(env, "gravity", 9.81);
    m->gravity[0] = 0, m->gravity[1] = 0, m->gravity[2] = -g;
    return MCS_OK;
}

/* inverse of the symmetric tensor Ixx Iyy Izz Ixy Ixz Iyz (positive definite: the schema
 * checked it), row-major */
static void invert_inertia(const double I[6], double out[9])
{
    double a = I[0], b = I[3], c = I[4], d = I[1], e = I[5], f = I[2];
    double A = d * f - e * e, B = c * e - b * f, C = b * e - c * d;
    double D = a * f - c * c, E = b * c - a * e, F = a * d - b * b;
    double det = a * A + b * B + c * C;
    double v[9] = {A, B, C, B, D, E, C, E, F};
    for (int k = 0; k < 9; k++) out[k] = v[k] / det;
}

static mcs_status build_body(const mcs_node *b, mb_model *m, int i, mcs_error *err)
{
    mb_body_desc *d = &m->body[i];
    snprintf(m->body_name[i], MB_NAME, "%s", mcs_node_str(mcs_node_get(b, "name")));
    if (strcmp(m->body_name[i], "ground") == 0)
        return mcs_node_error(mcs_node_get(b, "name"), err, MCS_ERR_RANGE,
                              "'ground' is reserved for the ground and the world");
    d->name = m->body_name[i];
    d->mass = mcs_node_num(mcs_node_get(b, "mass"));
    const mcs_node *in = mcs_node_get(b, "inertia");
    double v[6] = {0};
    int n = mcs_node_len(in);
    mcs_status st = mcs_node_vec(in, v, n, err);
    if (st) return st;
    /* scenario order Ixx Iyy Izz Ixy Iyz Ixz (tensor entries) -> mb_ode Ixx Iyy Izz Ixy Ixz Iyz */
    d->inertia[0] = v[0], d->inertia[1] = v[1], d->inertia[2] = v[2];
    d->inertia[3] = v[3], d->inertia[4] = v[5], d->inertia[5] = v[4];
    invert_inertia(d->inertia, m->body_iinv[i]);
    if ((st = mcs_node_vec3(mcs_node_get(b, "position"), d->pos, err))) return st;
    if ((st = mcs_node_vec3(mcs_node_get(b, "velocity"), d->vel, err))) return st;
    const mcs_node *w = mcs_node_get(b, "angular_velocity");
    if (mcs_node_kind(w) == MCS_NODE_SEQ && (st = mcs_node_vec3(w, d->angvel, err))) return st;
    const mcs_node *o = mcs_node_get(b, "orientation");
    d->quat[0] = 1;
    if (mcs_node_len(o) == 4) {
        if ((st = mcs_node_vec(o, d->quat, 4, err))) return st;
    } else if (mcs_node_len(o) == 3) {
        double rpy[3], R[9];
        if ((st = mcs_node_vec3(o, rpy, err))) return st;
        mb_build_cardan(rpy, R);
        rot_to_quat(R, d->quat);
    }
    return MCS_OK;
}

static mcs_status build_bodies(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *bodies = mcs_node_get(root, "bodies");
    m->nbody = mcs_node_len(bodies);
    if (m->nbody == 0)
        return mcs_node_error(root, err, MCS_ERR_KEY, "bodies: stage 1 needs at least one body");
    m->body = MB_NEW(mb_body_desc, m->nbody);
    m->body_name = MB_NEW(mb_name, m->nbody);
    m->body_iinv = calloc((size_t)m->nbody, sizeof *m->body_iinv);
    if (!m->body || !m->body_name || !m->body_iinv) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int i = 0; i < m->nbody; i++) {
        mcs_status st = build_body(mcs_node_at(bodies, i), m, i, err);
        if (st) return st;
    }
    return MCS_OK;
}

static const char *const sensor_types[] = {"acceleration", "velocity", "displacement",
                                           "angular_velocity", "angular_acceleration"};

static mcs_status build_sensors(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *list = mcs_node_get(root, "sensors");
    m->nsensor = mcs_node_len(list);
    m->sensor = MB_NEW(mb_sensor, m->nsensor);
    if (!m->sensor) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    int nsens = m->nsensor;
    m->nsensor = 0;
    for (int i = 0; i < nsens; i++) {
        const mcs_node *n = mcs_node_at(list, i);
        const char *lct = mcs_node_str(mcs_node_get(n, "type"));
        if (lct && strcmp(lct, "load_cell") == 0) continue; /* mb_loadcell.c */
        mb_sensor *s = &m->sensor[m->nsensor++];
        snprintf(s->name, MB_NAME, "%s", mcs_node_str(mcs_node_get(n, "name")));
        s->body = mb_build_body_ref(m, mcs_node_get(n, "body"));
        const char *ty = mcs_node_str(mcs_node_get(n, "type"));
        for (int k = 0; k < 5; k++)
            if (ty && strcmp(ty, sensor_types[k]) == 0) s->type = (mb_sensor_type)k;
        const mcs_node *p = mcs_node_get(n, "point");
        if (mcs_node_kind(p) == MCS_NODE_SEQ) {
            mcs_status st = mcs_node_vec3(p, s->point, err);
            if (st) return st;
        }
        s->cfc = (int)mcs_node_num_or(n, "cfc", 0);
        if (s->cfc > 0 && 2.0775 * s->cfc >= 0.5 * m->output_rate)
            return mcs_node_error(mcs_node_get(n, "cfc"), err, MCS_ERR_RANGE,
                                  "CFC %d needs an output_rate above %g Hz (it is %g Hz)", s->cfc,
                                  2 * 2.0775 * s->cfc, m->output_rate);
    }
    return MCS_OK;
}

mcs_status mb_model_build(const mcs_scenario *scn, const mb_opts *opts, mb_model **out,
                          mcs_error *err)
{
    *out = NULL;
    mb_model *m = calloc(1, sizeof *m);
    if (!m) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    m->opts = opts ? *opts : mb_opts_default();
    m->ground_surf = -1;
    const mcs_node *root = mcs_scenario_root(scn);
    mcs_status st = build_simulation(root, m, err);
    if (!st) st = build_bodies(root, m, err);
    if (!st) st = mb_build_chars(root, m, err);
    if (!st) st = mb_build_surfaces(root, m, err);
    if (!st) st = mb_build_contacts(root, m, err);
    if (!st) st = mb_build_joints(root, m, err);
    if (!st) st = mb_position_rider(root, m, err); /* seat the rider before the attachments */
    if (!st) st = mb_build_attachments(root, m, err);
    if (!st) st = mb_position_attach(root, m, err);
    if (!st) st = build_sensors(root, m, err);
    if (!st) st = mb_build_loadcells(root, m, err);
    if (!st) st = mb_impact_apply(root, m, err); /* places the built motorcycle group */
    if (!st) st = mb_couple_build(scn, m, err);  /* last: FE parts placed with their bodies */
    if (!st) st = mb_egroup_build(root, m, err); /* the rider's energy balance (mb_egroup.h) */
    if (st) {
        mb_model_destroy(&m);
        return st;
    }
    *out = m;
    return MCS_OK;
}

void mb_model_destroy(mb_model **pm)
{
    mb_model *m = pm ? *pm : NULL;
    if (!m) return;
    for (int i = 0; m->chr && i < m->nchar; i++) {
        mcs_curve_destroy(&m->chr[i].loading);
        mcs_curve_destroy(&m->chr[i].unloading);
    }
    for (int i = 0; m->own_curves && i < m->npair; i++) mcs_curve_destroy(&m->own_curves[i]);
    for (int i = 0; m->surf && i < m->nsurf; i++) mb_mesh_destroy(&m->surf[i].mesh);
    free(m->own_curves);
    free(m->body_name), free(m->body), free(m->body_iinv), free(m->surf), free(m->chr), free(m->contact);
    free(m->pair), free(m->joint), free(m->restraint1), free(m->restraint1_name);
    free(m->restraint3), free(m->restraint3_name), free(m->attach), free(m->attach_name);
    free(m->sensor);
    free(m->loadcell);
    mb_couple_destroy(&m->couple);
    mb_egroup_destroy(&m->egroup);
    free(m->body_group);
    free(m->presc);
    free(m);
    *pm = NULL;
}

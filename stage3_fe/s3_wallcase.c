/* s3_wallcase.c: fork angle, wall force by part, crush and the impact phases of a generated
 * motorcycle against a rigid wall (s3_wallcase.h). All buffers are made at open; a sample
 * only reads the state and appends rows. */
#include "stage3_fe/s3_wallcase.h"
#include "fe/fe_contact.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const s3_phase_name[S3_NPHASE] = {"tyre", "rim", "fork", "engine"};

/* a part's role in the phases, from the generator's component names (stage3_fe/s3_moto.c) */
enum { R_NONE, R_TYRE, R_RIM, R_FORK, R_FRAME };
static const struct {
    const char *comp;
    int role;
} roles[] = {{"front_tyre", R_TYRE}, {"front_rim", R_RIM},     {"front_wheel", R_RIM},
             {"front_spokes", R_RIM},
             {"stanchion_l", R_FORK}, {"stanchion_r", R_FORK}, {"frame", R_FRAME},
             {"fairing", R_FRAME},    {"head_tube", R_FRAME},  {"frame_l", R_FRAME},
             {"frame_r", R_FRAME},    {"tank", R_FRAME}};

struct s3_wallcase {
    char pre[FE_NAME_MAX];       /* the motorcycle's name prefix                             */
    int bu, bl, bh;              /* bodies: upper fork, lower fork, heaviest                  */
    int wall;                    /* the impact wall, -1 none [-]                              */
    char wall_name[FE_NAME_MAX];
    int iwe;                     /* contact interface <pre>_wheel_engine, -1 none             */
    int *role;                   /* (npart) R_*                                               */
    mcs_results_series *angle, *crush, **pf; /* pf: (nwall x npart), NULL where not a slave  */
    double t_first, x_first[3];  /* the impact wall's first contact: time, heavy body centre */
    double t[S3_NPHASE], d[S3_NPHASE], peak[S3_NPHASE]; /* start time, crush, peak force     */
    double d_now;                /* crush at the last sample [m]                              */
    double *imp, imp_t;          /* (nwall_part) parts' wall impulses since the last row [N s] */
    int we;                      /* the wheel met the engine since the last row [-]           */
};

/* the body named <pre>_<comp> of the motorcycle whose upper fork is body bu, -1 none */
static int body_named(const fe_model *m, const char *pre, const char *comp)
{
    char nm[2 * FE_NAME_MAX];
    snprintf(nm, sizeof nm, "%s_%s", pre, comp);
    for (int b = 0; b < m->nbody; b++)
        if (strcmp(m->body[b].name, nm) == 0) return b;
    return -1;
}

static int find_roles(const fe_model *m, s3_wallcase *c)
{
    size_t lp = strlen(c->pre);
    for (int p = 0; p < m->npart; p++) {
        const char *n = m->part[p].name;
        if (strncmp(n, c->pre, lp) != 0 || n[lp] != '_') continue;
        for (size_t k = 0; k < sizeof roles / sizeof roles[0]; k++)
            if (strcmp(n + lp + 1, roles[k].comp) == 0) c->role[p] = roles[k].role;
    }
    char nm[2 * FE_NAME_MAX];
    snprintf(nm, sizeof nm, "%s_wheel_engine", c->pre);
    c->iwe = -1;
    for (int i = 0; m->contact && i < m->contact->nif; i++)
        if (strcmp(m->contact->iface[i].name, nm) == 0) c->iwe = i;
    return 0;
}

/* the penalty wall most against the heavy body's initial velocity, -1 none */
static int impact_wall(const fe_model *m, int bh)
{
    double v[3] = {0, 0, 0}, best = 0;
    int w0 = -1;
    const fe_body *B = &m->body[bh];
    for (int i = B->node_begin; i < B->node_end; i++) {
        const int n = m->body_node[i];
        for (int k = 0; k < 3; k++) v[k] += m->node_mass[n] * m->node_v0[3 * n + k] / B->mass;
    }
    for (int w = 0; w < m->nwall; w++) {
        const fe_wall *W = &m->wall[w];
        double vn = W->normal[0] * v[0] + W->normal[1] * v[1] + W->normal[2] * v[2];
        if (W->method == FE_WALL_PENALTY && vn < best) best = vn, w0 = w;
    }
    return w0;
}

static mcs_status open_series(mcs_results *r, const fe_model *m, s3_wallcase *c, mcs_error *err)
{
    char path[512];
    snprintf(path, sizeof path, "/stage3/channels/%s_fork_deformation_angle", c->pre);
    mcs_status st = mcs_results_series_create(r, path, 1, NULL, "rad", 0, &c->angle, err);
    if (!st) st = mcs_results_set_attr_str(r, path, "body", m->body[c->bl].name, err);
    for (int w = 0; w < m->nwall && !st; w++) {
        if (m->wall[w].method != FE_WALL_PENALTY) continue;
        unsigned char *slave = calloc((size_t)m->npart, 1);
        if (!slave) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 3: out of memory (wall parts)");
        for (int n = 0; n < m->nnode; n++) {
            int p = m->node_part[n], bd = m->node_body[n];
            if (p < 0 && bd >= 0) p = m->body[bd].part;
            if (p >= 0 && (m->node_walls[n] >> w & 1u)) slave[p] = 1;
        }
        for (int p = 0; p < m->npart && !st; p++) {
            if (!slave[p]) continue;
            snprintf(path, sizeof path, "/stage3/rigidwall/%s/parts/%s/force", m->wall[w].name,
                     m->part[p].name);
            st = mcs_results_series_create(r, path, 1, NULL, "N", 0, &c->pf[w * m->npart + p],
                                           err);
        }
        free(slave);
    }
    if (!st && c->wall >= 0) {
        snprintf(path, sizeof path, "/stage3/rigidwall/%s/crush", m->wall[c->wall].name);
        st = mcs_results_series_create(r, path, 1, NULL, "m", 0, &c->crush, err);
    }
    return st;
}

mcs_status s3_wallcase_open(mcs_results *r, const fe_model *m, s3_wallcase **out,
                            mcs_error *err)
{
    *out = NULL;
    int bu = -1;
    for (int b = 0; b < m->nbody && bu < 0; b++) {
        size_t n = strlen(m->body[b].name), k = strlen("_upper_fork");
        if (n > k && strcmp(m->body[b].name + n - k, "_upper_fork") == 0) bu = b;
    }
    if (bu < 0) return MCS_OK;
    s3_wallcase *c = calloc(1, sizeof *c);
    if (!c) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 3: out of memory (wall case)");
    snprintf(c->pre, sizeof c->pre, "%.*s", (int)(strlen(m->body[bu].name) - 11),
             m->body[bu].name);
    c->bu = bu, c->bl = body_named(m, c->pre, "lower_fork"), c->bh = 0;
    for (int b = 1; b < m->nbody; b++)
        if (m->body[b].mass > m->body[c->bh].mass) c->bh = b;
    if (c->bl < 0) {
        free(c);
        return MCS_OK;
    }
    c->wall = impact_wall(m, c->bh);
    if (c->wall >= 0) snprintf(c->wall_name, sizeof c->wall_name, "%s", m->wall[c->wall].name);
    c->t_first = NAN;
    for (int k = 0; k < S3_NPHASE; k++) c->t[k] = c->d[k] = c->peak[k] = NAN;
    c->role = calloc((size_t)m->npart + 1, sizeof *c->role);
    c->pf = calloc((size_t)m->nwall_part + 1, sizeof *c->pf);
    c->imp = calloc((size_t)m->nwall_part + 1, sizeof *c->imp);
    if (!c->role || !c->pf || !c->imp) {
        s3_wallcase_free(&c);
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 3: out of memory (wall case)");
    }
    find_roles(m, c);
    mcs_status st = open_series(r, m, c, err);
    if (st) s3_wallcase_free(&c);
    *out = c;
    return st;
}

/* rotation of body b at t_n (the state holds t_n+1 and w at t_n+1/2): exp(-h skew(w)) R */
static void rot_at_tn(const fe_state *s, int b, double R[3][3])
{
    const double h = s->dt_prev, *w = s->body_w + 3 * b;
    const double p[3] = {-h * w[0], -h * w[1], -h * w[2]};
    const double th = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const double a = th > 1e-8 ? sin(th) / th : 1, cc = th > 1e-8 ? (1 - cos(th)) / (th * th) : 0.5;
    const double K[3][3] = {{0, -p[2], p[1]}, {p[2], 0, -p[0]}, {-p[1], p[0], 0}};
    double E[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            E[i][j] = (i == j) + a * K[i][j] +
                      cc * (K[i][0] * K[0][j] + K[i][1] * K[1][j] + K[i][2] * K[2][j]);
    const double *R1 = s->body_rot + 9 * b;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = E[i][0] * R1[j] + E[i][1] * R1[3 + j] + E[i][2] * R1[6 + j];
}

/* the lower fork's rotation about the upper fork's y axis relative to it: Rr = Ru^T Rl is
 * R_y(phi) for a pure bend; phi = atan2(Rr_02, Rr_00), > 0 turns the wheel rearward */
static double fork_angle(const fe_state *s, const s3_wallcase *c)
{
    double Ru[3][3], Rl[3][3], Rr[3][3];
    rot_at_tn(s, c->bu, Ru);
    rot_at_tn(s, c->bl, Rl);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            Rr[i][j] = Ru[0][i] * Rl[0][j] + Ru[1][i] * Rl[1][j] + Ru[2][i] * Rl[2][j];
    return atan2(Rr[0][2], Rr[0][0]);
}

/* 1 when a part of role `role` has plastic strain at some shell point */
static int yielded(const fe_model *m, const fe_state *s, const s3_wallcase *c, int role)
{
    for (int e = 0; e < m->nshell; e++) {
        if (c->role[m->shell_part[e]] != role) continue;
        for (int k = 0; k < m->nip_max; k++)
            if (s->shell_epsp[(size_t)e * m->nip_max + k] > 0) return 1;
    }
    return 0;
}

void s3_wallcase_step(const fe_model *m, const fe_state *s, s3_wallcase *c)
{
    if (!c) return;
    for (int i = 0; i < m->nwall_part; i++) c->imp[i] += s->wall_part_f[i] * s->dt_prev;
    c->imp_t += s->dt_prev;
    if (c->iwe >= 0) {
        const double *f = s->contact->if_force + 3 * c->iwe;
        if (f[0] != 0 || f[1] != 0 || f[2] != 0) c->we = 1;
    }
}

static void begin(s3_wallcase *c, int k, double t)
{
    if (isnan(c->t[k])) c->t[k] = t, c->d[k] = c->d_now, c->peak[k] = 0;
}

mcs_status s3_wallcase_sample(const fe_model *m, const fe_state *s, s3_wallcase *c,
                              mcs_error *err)
{
    if (!c) return MCS_OK;
    const double t = s->energy_time, phi = fork_angle(s, c);
    mcs_status st = mcs_results_series_append(c->angle, &phi, err);
    for (int i = 0; i < m->nwall_part; i++) /* the interval's means (row 0: at t = 0) */
        c->imp[i] = c->imp_t > 0 ? c->imp[i] / c->imp_t : s->wall_part_f[i];
    c->imp_t = 0;
    for (int i = 0; i < m->nwall_part && !st; i++)
        if (c->pf[i]) st = mcs_results_series_append(c->pf[i], &c->imp[i], err);
    const int we = c->we;
    c->we = 0;
    if (st || c->wall < 0) {
        memset(c->imp, 0, sizeof(double) * (size_t)m->nwall_part);
        return st;
    }
    /* crush: the heavy body's travel into the wall since its first contact (x at t_n) */
    const double *n = m->wall[c->wall].normal, *xb = s->body_x + 3 * c->bh;
    const double *vb = s->body_v + 3 * c->bh, *pf = c->imp + (size_t)c->wall * m->npart;
    double F = 0;
    for (int p = 0; p < m->npart; p++) F += pf[p];
    double x[3];
    for (int i = 0; i < 3; i++) x[i] = xb[i] - s->dt_prev * vb[i];
    if (isnan(c->t_first) && F > 0) c->t_first = t, memcpy(c->x_first, x, sizeof x);
    c->d_now = 0;
    if (!isnan(c->t_first))
        for (int i = 0; i < 3; i++) c->d_now -= (x[i] - c->x_first[i]) * n[i];
    st = mcs_results_series_append(c->crush, &c->d_now, err);
    /* phases: which part group touches the wall first, the fork's first yield */
    for (int p = 0; p < m->npart; p++) {
        if (!(pf[p] > 0)) continue;
        if (c->role[p] == R_TYRE) begin(c, 0, t);
        if (c->role[p] == R_RIM) begin(c, 1, t);
        if (c->role[p] == R_FRAME) begin(c, 3, t);
    }
    if (isnan(c->t[1]) && yielded(m, s, c, R_RIM)) begin(c, 1, t); /* the rim collapsing */
    if (isnan(c->t[2]) && yielded(m, s, c, R_FORK)) begin(c, 2, t);
    if (we) begin(c, 3, t);
    int cur = -1; /* the phase begun last */
    for (int k = 0; k < S3_NPHASE; k++)
        if (!isnan(c->t[k]) && (cur < 0 || c->t[k] >= c->t[cur])) cur = k;
    if (cur >= 0) c->peak[cur] = fmax(c->peak[cur], F);
    memset(c->imp, 0, sizeof(double) * (size_t)m->nwall_part);
    return st;
}

mcs_status s3_wallcase_finish(mcs_results *r, s3_wallcase **cp, mcs_error *err)
{
    s3_wallcase *c = *cp;
    if (!c) return MCS_OK;
    mcs_status st = MCS_OK;
    char path[256];
    for (int k = 0; k < S3_NPHASE && !st && c->wall >= 0; k++) {
        const double v[3] = {c->t[k], c->d[k], c->peak[k]};
        const char *what[3] = {"start_time", "crush", "peak_force"}, *unit[3] = {"s", "m", "N"};
        for (int j = 0; j < 3 && !st; j++) {
            snprintf(path, sizeof path, "/stage3/phases/%s/%s", s3_phase_name[k], what[j]);
            st = mcs_results_write_scalar(r, path, v[j], unit[j], err);
        }
    }
    if (!st && c->wall >= 0 && mcs_results_kind(r, "/stage3/phases") != MCS_RES_NONE)
        st = mcs_results_set_attr_str(r, "/stage3/phases", "wall", c->wall_name, err);
    if (!st && c->wall >= 0) /* for retune: the wall force it fits (not the ground's) */
        st = mcs_results_set_attr_str(r, "/stage3/rigidwall", "impact_wall", c->wall_name, err);
    s3_wallcase_free(cp);
    return st;
}

void s3_wallcase_free(s3_wallcase **cp)
{
    if (!*cp) return;
    free((*cp)->role);
    free((*cp)->pf);
    free((*cp)->imp);
    free(*cp);
    *cp = NULL;
}

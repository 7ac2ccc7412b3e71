/* fe_rigid: rigid parts (material model rigid, what users know as LS-DYNA *MAT_RIGID). The
 * nodes of a rigid part move as one 6-DOF body; its elements compute nothing and do not limit
 * the step. Nodes shared with deformable parts belong to the body (merged, as LS-DYNA does),
 * so the deformable elements' forces act on it.
 *
 * Body: mass M = sum of the nodal masses (element masses, point masses, the deformable
 * elements' shares at shared nodes), centre of mass c, inertia about c
 * I0 = sum m_I (|r_I|^2 1 - r_I r_I^T) + sum i_I 1 (i_I: shell nodes' rotary inertia) at t = 0.
 * Each step it sums the nodal forces F = sum (f_ext - f_int) and moments about c, then
 *   V(n+1/2) = V(n-1/2) + dt_n F / M,         c(n+1) = c(n) + dt V(n+1/2),
 *   L(n+1/2) = L(n-1/2) + dt_n (moments),     (angular momentum about c, world axes)
 *   w(n+1/2) = R' I0^-1 R'^T L(n+1/2),  R' = exp(dt/2 w) R(n)  (fixed point, 3 passes),
 *   R(n+1) = exp(dt w(n+1/2)) R(n)            (Rodrigues),
 * so that the angular momentum of a free body is conserved to round-off whatever its shape
 * (Euler's equations are integrated through L; the rotational energy 1/2 L.w is conserved to
 * O(dt^2)). Nodes are placed exactly, x_I = c + R r_I0, and get v_I = (x_I(n+1) - x_I(n)) / dt.
 * A boundary on any node of a rigid part constrains the body: fixed translations hold V
 * (at the prescribed velocity), any fixed rotation holds all three. Kinetic energy
 * 1/2 M V(n-1/2).V(n+1/2) + the mean of 1/2 L.w at n-1/2 and n+1/2; external work with the
 * trapezoidal weights of fe_integrate. Rigid parts feel penalty rigid walls (forces), not
 * kinematic ones (rejected at build).
 * Given mass properties (fe_part_desc.rigid, LS-DYNA *PART_INERTIA) replace M, c and I0, and
 * the given velocity and angular velocity (L = I0 w) the nodes' initial velocities; the nodes
 * keep their own masses for the contact and wall stiffnesses. */
#include "fe/fe_builder_impl.h" /* fe_kind_nnode */
#include "fe/fe_elem.h"
#include "fe/fe_joint.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double det3(const double a[3][3])
{
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

static void inv3(const double a[3][3], double r[3][3])
{
    double d = det3(a);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            r[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / d;
        }
}

/* body B of part p with its given mass, centre of mass and inertia: the nodes keep their
 * masses (contact and wall stiffnesses use them), the body moves with the given ones */
static mcs_status given_inertia(fe_model *m, const fe_part *p, fe_body *B, mcs_error *err)
{
    const fe_rigid_inertia *g = &p->rigid;
    const double (*I)[3] = g->inertia;
    double m2 = I[0][0] * I[1][1] - I[0][1] * I[1][0];
    if (!(g->mass > 0) || !(I[0][0] > 0) || !(m2 > 0) || !(det3(I) > 0) ||
        I[0][1] != I[1][0] || I[0][2] != I[2][0] || I[1][2] != I[2][1])
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: rigid part '%s': the given mass must be > 0 and the inertia "
                       "symmetric positive definite",
                       p->name);
    m->mass_total += g->mass - B->mass;
    B->mass = g->mass;
    memcpy(B->x0, g->cg, sizeof B->x0);
    memcpy(B->inertia0, g->inertia, sizeof B->inertia0);
    for (int j = B->node_begin; j < B->node_end; j++)
        for (int i = 0; i < 3; i++)
            m->body_r0[3 * j + i] = m->node_x0[3 * m->body_node[j] + i] - B->x0[i];
    inv3(B->inertia0, B->inertia0_inv);
    return MCS_OK;
}

/* the nodes of each rigid part become one body; then extra nodes and nodal rigid bodies */
mcs_status fe_rigid_build(const fe_builder *bld, fe_model *m, mcs_error *err)
{
    int nb = 0;
    for (int ip = 0; ip < m->npart; ip++)
        if (m->part[ip].material.model == FE_MAT_RIGID) m->part[ip].body = nb++;
    const int nrigid = nb, nnrb = fe_nrb_count(bld);
    if (nb + nnrb == 0) return MCS_OK;
    for (int ip = 0; ip < m->npart; ip++) {
        const fe_part *p = &m->part[ip];
        if (p->body < 0) continue;
        const int *c = fe_kind_conn(m, p->elem_kind), w = fe_kind_nnode(p->elem_kind);
        for (int e = p->elem_begin; e < p->elem_end; e++)
            for (int i = 0; i < w; i++) {
                int n = c[w * e + i], *nb_ = &m->node_body[n];
                if (*nb_ >= 0 && *nb_ != p->body)
                    return MCS_ERR(err, MCS_ERR_RANGE,
                                   "fe: node %d belongs to two rigid parts ('%s' and another): "
                                   "merge them into one part",
                                   n, p->name);
                *nb_ = p->body;
            }
    }
    char(*names)[FE_NAME_MAX] = calloc((size_t)(nb + nnrb), FE_NAME_MAX);
    if (!names) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (rigid bodies)");
    mcs_status st = fe_nrb_assign(bld, m, &nb, names, nrigid + nnrb, err);
    if (st) {
        free(names);
        return st;
    }
    m->nbody = nb;
    int cnt = 0;
    for (int n = 0; n < m->nnode; n++) cnt += m->node_body[n] >= 0;
    m->nbody_node = cnt;
    m->body = calloc((size_t)nb, sizeof *m->body);
    m->body_node = malloc(sizeof(int) * (size_t)(cnt ? cnt : 1));
    m->body_r0 = malloc(3 * sizeof(double) * (size_t)(cnt ? cnt : 1));
    if (!m->body || !m->body_node || !m->body_r0) {
        free(names);
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (rigid bodies)");
    }
    m->bytes += sizeof *m->body * (size_t)nb + (sizeof(int) + 3 * sizeof(double)) * (size_t)cnt;
    for (int b = 0; b < nb; b++) m->body[b].part = -1;
    for (int ip = 0; ip < m->npart; ip++)
        if (m->part[ip].body >= 0) {
            m->body[m->part[ip].body].part = ip;
            snprintf(names[m->part[ip].body], FE_NAME_MAX, "%s", m->part[ip].name);
        }
    int at = 0;
    for (int bi = 0; bi < nb; bi++) {
        fe_body *B = &m->body[bi];
        memcpy(B->name, names[bi], FE_NAME_MAX);
        const char *pname = B->name;
        B->node_begin = at;
        double mx[3] = {0, 0, 0};
        for (int n = 0; n < m->nnode; n++)
            if (m->node_body[n] == bi) {
                m->body_node[at++] = n;
                B->mass += m->node_mass[n];
                for (int i = 0; i < 3; i++) mx[i] += m->node_mass[n] * m->node_x0[3 * n + i];
            }
        B->node_end = at;
        if (!(B->mass > 0)) {
            free(names);
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: rigid %s '%s' has no mass",
                           B->part >= 0 ? "part" : "body", pname);
        }
        for (int i = 0; i < 3; i++) B->x0[i] = mx[i] / B->mass;
        if (B->part >= 0 && m->part[B->part].rigid.given) { /* LS-DYNA *PART_INERTIA */
            mcs_status gst = given_inertia(m, &m->part[B->part], B, err);
            if (gst) {
                free(names);
                return gst;
            }
            continue;
        }
        double trace_scale = 0;
        for (int j = B->node_begin; j < B->node_end; j++) {
            int n = m->body_node[j];
            double *r = m->body_r0 + 3 * j, mn = m->node_mass[n];
            for (int i = 0; i < 3; i++) r[i] = m->node_x0[3 * n + i] - B->x0[i];
            double rr = fe_dot(r, r);
            for (int a = 0; a < 3; a++) {
                for (int b = 0; b < 3; b++) B->inertia0[a][b] += mn * ((a == b) * rr - r[a] * r[b]);
                B->inertia0[a][a] += m->node_inertia[n];
            }
            trace_scale += mn * rr;
        }
        double d = det3(B->inertia0), ref = trace_scale * trace_scale * trace_scale;
        if (!(d > 1e-12 * ref) || !(ref > 0)) {
            free(names);
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: rigid %s '%s': its nodes lie on a line (singular inertia)",
                           B->part >= 0 ? "part" : "body", pname);
        }
        inv3(B->inertia0, B->inertia0_inv);
    }
    free(names);
    return MCS_OK;
}

/* after boundaries and walls: body constraints from its nodes; kinematic walls refused */
mcs_status fe_rigid_finish(fe_model *m, mcs_error *err)
{
    int deformable = m->nspring > 0;
    int nnull = 0;
    for (int ip = 0; ip < m->npart; ip++) {
        const int null = m->part[ip].material.model == FE_MAT_NULL;
        deformable |= m->part[ip].body < 0 && !null;
        nnull += null;
    }
    if ((m->nbody > 0 || nnull > 0) && !deformable && !(m->opts.dt_max > 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: every part is rigid or null, so nothing sets the stable step: give "
                       "a time step (fe_opts.dt_max, simulation.time_step)");
    unsigned kin = 0;
    for (int w = 0; w < m->nwall; w++)
        if (m->wall[w].method == FE_WALL_KINEMATIC) kin |= 1u << w;
    for (int b = 0; b < m->nbody; b++) {
        fe_body *B = &m->body[b];
        for (int j = B->node_begin; j < B->node_end; j++) {
            int n = m->body_node[j];
            unsigned f = m->node_fix[n];
            if (m->node_walls[n] & kin) {
                int w = __builtin_ctz(m->node_walls[n] & kin);
                return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                               "fe: rigid wall '%s' (kinematic) cannot stop rigid part '%s': "
                               "use method penalty or list the wall's parts",
                               m->wall[w].name, B->name);
            }
            for (int i = 0; i < 3; i++)
                if (f & (1u << i)) {
                    if ((B->fix & (1u << i)) && B->vfix[i] != m->node_vfix[3 * n + i])
                        return MCS_ERR(err, MCS_ERR_RANGE,
                                       "fe: rigid body '%s': conflicting prescribed velocities",
                                       B->name);
                    B->vfix[i] = m->node_vfix[3 * n + i];
                }
            B->fix |= f;
        }
        /* the part's own constraints (*MAT_RIGID CMO 1), held at rest; a nodal rigid body
           (part -1) has none */
        if (B->part >= 0) B->fix |= m->part[B->part].material.rigid_fix;
        if (B->fix & FE_DOF_ROT) B->fix |= FE_DOF_ROT;
    }
    return MCS_OK;
}

/* R = exp(skew(phi)) (Rodrigues) */
static void rot_exp(const double phi[3], double R[3][3])
{
    double th = sqrt(fe_dot(phi, phi));
    double a = th > 1e-8 ? sin(th) / th : 1 - th * th / 6;
    double b = th > 1e-8 ? (1 - cos(th)) / (th * th) : 0.5 - th * th / 24;
    double K[3][3] = {{0, -phi[2], phi[1]}, {phi[2], 0, -phi[0]}, {-phi[1], phi[0], 0}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double k2 = 0;
            for (int k = 0; k < 3; k++) k2 += K[i][k] * K[k][j];
            R[i][j] = (i == j) + a * K[i][j] + b * k2;
        }
}

static void mat_mul(const double A[3][3], const double B[3][3], double C[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) C[i][j] = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
}

/* w = R I0^-1 R^T L */
static void ang_vel(const fe_body *B, const double R[3][3], const double L[3], double w[3])
{
    double t[3], u[3];
    for (int i = 0; i < 3; i++) t[i] = R[0][i] * L[0] + R[1][i] * L[1] + R[2][i] * L[2];
    for (int i = 0; i < 3; i++)
        u[i] = B->inertia0_inv[i][0] * t[0] + B->inertia0_inv[i][1] * t[1] + B->inertia0_inv[i][2] * t[2];
    for (int i = 0; i < 3; i++) w[i] = R[i][0] * u[0] + R[i][1] * u[1] + R[i][2] * u[2];
}

/* node positions and velocities from the body (positions at t, velocities v) */
static void place_nodes(const fe_model *m, fe_state *s, int b, const double R[3][3],
                        const double xc[3], double dt)
{
    const fe_body *B = &m->body[b];
    const double *w = s->body_w + 3 * b;
    for (int j = B->node_begin; j < B->node_end; j++) {
        int n = m->body_node[j];
        const double *r0 = m->body_r0 + 3 * j;
        double *x = s->node_x + 3 * n, *v = s->node_v + 3 * n;
        for (int i = 0; i < 3; i++) {
            double xn = xc[i] + R[i][0] * r0[0] + R[i][1] * r0[1] + R[i][2] * r0[2];
            if (dt > 0) v[i] = (xn - x[i]) / dt;
            x[i] = xn;
        }
        memcpy(s->node_w + 3 * n, w, 3 * sizeof(double));
    }
}

void fe_rigid_reset(const fe_model *m, fe_state *s)
{
    for (int b = 0; b < m->nbody; b++) {
        const fe_body *B = &m->body[b];
        double *V = s->body_v + 3 * b, *L = s->body_l + 3 * b, *R = s->body_rot + 9 * b;
        memcpy(s->body_x + 3 * b, B->x0, sizeof B->x0);
        for (int i = 0; i < 9; i++) R[i] = i % 4 == 0;
        double p[3] = {0, 0, 0};
        static const fe_rigid_inertia none = {0};
        const fe_rigid_inertia *g = B->part >= 0 ? &m->part[B->part].rigid : &none;
        for (int j = B->node_begin; j < B->node_end; j++) {
            int n = m->body_node[j];
            for (int i = 0; i < 3; i++) p[i] += m->node_mass[n] * m->node_v0[3 * n + i];
        }
        for (int i = 0; i < 3; i++) {
            V[i] = g->given ? g->velocity[i] : p[i] / B->mass;
            /* given: L = I0 w at t = 0 (R = 1) */
            L[i] = g->given && !(B->fix & FE_DOF_ROT)
                       ? B->inertia0[i][0] * g->omega[0] + B->inertia0[i][1] * g->omega[1] +
                             B->inertia0[i][2] * g->omega[2]
                       : 0;
            if (B->fix & (1u << i)) V[i] = B->vfix[i];
        }
        for (int j = B->node_begin; j < B->node_end && !(B->fix & FE_DOF_ROT) && !g->given;
             j++) {
            int n = m->body_node[j];
            double dv[3], c[3];
            for (int i = 0; i < 3; i++) dv[i] = m->node_v0[3 * n + i] - V[i];
            fe_cross(m->body_r0 + 3 * j, dv, c);
            for (int i = 0; i < 3; i++) L[i] += m->node_mass[n] * c[i];
        }
        double Rm[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        ang_vel(B, Rm, L, s->body_w + 3 * b);
        /* node velocities of the rigid motion */
        for (int j = B->node_begin; j < B->node_end; j++) {
            int n = m->body_node[j];
            double c[3];
            fe_cross(s->body_w + 3 * b, m->body_r0 + 3 * j, c);
            for (int i = 0; i < 3; i++) s->node_v[3 * n + i] = V[i] + c[i];
            memcpy(s->node_w + 3 * n, s->body_w + 3 * b, 3 * sizeof(double));
        }
    }
}

/* sums of the nodal forces on body b: external F, M and total (ext - int) F, M */
static void body_loads(const fe_model *m, const fe_state *s, int b, double fe_[3], double me[3],
                       double ft[3], double mt[3])
{
    const fe_body *B = &m->body[b];
    const double *xc = s->body_x + 3 * b;
    for (int i = 0; i < 3; i++) fe_[i] = me[i] = ft[i] = mt[i] = 0;
    for (int j = B->node_begin; j < B->node_end; j++) {
        int n = m->body_node[j];
        double r[3], f[3], c[3];
        for (int i = 0; i < 3; i++) r[i] = s->node_x[3 * n + i] - xc[i];
        const double *fx = s->node_fext + 3 * n, *fi = s->node_fint + 3 * n;
        fe_cross(r, fx, c);
        for (int i = 0; i < 3; i++) fe_[i] += fx[i], me[i] += c[i], f[i] = fx[i] - fi[i];
        fe_cross(r, f, c);
        for (int i = 0; i < 3; i++) ft[i] += f[i], mt[i] += c[i];
        /* shell nodes carry moments: the element's resisting moment acts on the body */
        for (int i = 0; i < 3; i++) mt[i] -= s->node_mint[3 * n + i];
    }
    /* joint loads (fe_joint_step.c) */
    for (int i = 0; m->njoint && i < 3; i++) {
        ft[i] += s->body_fj[6 * b + i];
        mt[i] += s->body_fj[6 * b + 3 + i];
    }
}

void fe_rigid_integrate(const fe_model *m, fe_state *s)
{
    if (m->nbody == 0) return;
    const double dt = s->dt, dtp = s->dt_prev, dth = 0.5 * (dt + dtp);
    const double c = m->opts.damping, d0 = 1 - 0.5 * c * dth, d1 = 1 / (1 + 0.5 * c * dth);
    const double hb = dtp > 0 ? dth : 0;
    double wb = 0, wf = 0, db = 0, dfw = 0, ke_all = 0;
    for (int b = 0; b < m->nbody; b++) {
        const fe_body *B = &m->body[b];
        double Fe[3], Me[3], F[3], Mo[3];
        body_loads(m, s, b, Fe, Me, F, Mo);
        s->body_fm[6 * b + 0] = F[0], s->body_fm[6 * b + 1] = F[1], s->body_fm[6 * b + 2] = F[2];
        s->body_fm[6 * b + 3] = Mo[0], s->body_fm[6 * b + 4] = Mo[1], s->body_fm[6 * b + 5] = Mo[2];
        double *V = s->body_v + 3 * b, *L = s->body_l + 3 * b, *W = s->body_w + 3 * b;
        double *xc = s->body_x + 3 * b, *Rp = s->body_rot + 9 * b;
        double Vo[3], Lo[3], Wo[3], Vn[3], Vfree[3], Ln[3], Wn[3];
        memcpy(Vo, V, sizeof Vo), memcpy(Lo, L, sizeof Lo), memcpy(Wo, W, sizeof Wo);
        for (int i = 0; i < 3; i++) {
            Vn[i] = Vfree[i] = (d0 * Vo[i] + dth * F[i] / B->mass) * d1;
            if (B->fix & (1u << i)) Vn[i] = B->vfix[i];
            Ln[i] = (d0 * Lo[i] + dth * Mo[i]) * d1;
        }
        double R[3][3], Rh[3][3], E[3][3];
        memcpy(R, Rp, sizeof R);
        if (B->fix & FE_DOF_ROT) {
            /* held rotation: no spin, and the reaction moment does no work */
            for (int i = 0; i < 3; i++) Wn[i] = 0, Ln[i] = 0;
        } else {
            memcpy(Wn, Wo, sizeof Wn);
            for (int it = 0; it < 3; it++) {
                double ph[3] = {0.5 * dt * Wn[0], 0.5 * dt * Wn[1], 0.5 * dt * Wn[2]};
                rot_exp(ph, E);
                mat_mul(E, R, Rh);
                ang_vel(B, Rh, Ln, Wn);
            }
            double ph[3] = {dt * Wn[0], dt * Wn[1], dt * Wn[2]};
            rot_exp(ph, E);
            mat_mul(E, R, Rh);
            memcpy(R, Rh, sizeof R);
        }
        /* energies and works (fe_integrate's weights) */
        double ke = 0;
        for (int i = 0; i < 3; i++) {
            double r = B->mass * (Vn[i] - Vfree[i]) / dth, fd = -c * B->mass * 0.5 * (Vo[i] + Vn[i]);
            ke += 0.5 * B->mass * Vo[i] * Vn[i] + 0.25 * (Lo[i] * Wo[i] + Ln[i] * Wn[i]);
            wb += 0.5 * (Fe[i] + r) * hb * Vo[i] + 0.5 * Me[i] * hb * Wo[i];
            wf += 0.5 * (Fe[i] + r) * dth * Vn[i] + 0.5 * Me[i] * dth * Wn[i];
            db -= 0.5 * fd * hb * Vo[i];
            dfw -= 0.5 * fd * dth * Vn[i];
            double fdr = -c * 0.5 * (Lo[i] + Ln[i]);
            db -= 0.5 * fdr * hb * Wo[i];
            dfw -= 0.5 * fdr * dth * Wn[i];
        }
        memcpy(V, Vn, sizeof Vn), memcpy(L, Ln, sizeof Ln), memcpy(W, Wn, sizeof Wn);
        memcpy(Rp, R, sizeof R);
        for (int i = 0; i < 3; i++) xc[i] += dt * Vn[i];
        place_nodes(m, s, b, R, xc, dt);
        if (!isfinite(ke) && s->bad_node < 0) s->bad_node = m->body_node[B->node_begin];
        const int kp = B->part >= 0 ? B->part : m->node_part[m->body_node[B->node_begin]];
        if (B->part >= 0) s->part_energy[FE_NENERGY * kp + FE_E_kinetic] = ke;
        else if (kp >= 0) s->part_energy[FE_NENERGY * kp + FE_E_kinetic] += ke; /* nodal body */
        ke_all += ke;
    }
    s->energy[FE_E_kinetic] += ke_all;
    s->work_ext += wb;
    s->work_pending[0] += wf;
    s->work_damp += db;
    s->work_pending[2] += dfw;
}

/* fe_wall_kin: a kinematic (constraint) rigid wall with mass M, moving along its normal n
 * (LS-DYNA *RIGIDWALL_PLANAR_MOVING in the constraint method). Before the node update the wall
 * and its slave nodes are solved together, perfectly plastic, momentum conserving:
 *
 * slave i (mass m_i, gap g_i = (x_i - p - d(n)).n at t, free normal velocity u_i at t + dt/2,
 * i.e. after forces and constraints, without the walls) lands on the wall moved to
 * d(n+1) = d(n) + dt V n when
 *     x_i + dt u_i < p + d(n+1)   <=>   w_i = u_i + g_i / dt < V,
 * w_i being the wall velocity at which it just touches at t + dt. A landing node takes the
 * normal velocity V - g_i/dt (on the plane at t + dt), an impulse m_i (V - w_i) > 0, and the
 * wall takes the opposite:
 *     M V + sum_{w_i < V} m_i (V - w_i) = M V0,       V0 = V(n-1/2) (no other force on it).
 * The left side is continuous, piecewise linear and increasing in V, so the root is unique and
 * solved exactly: only nodes with w_i < V0 can land (V <= V0); sorted by w, the active set is
 * the first k + 1 nodes for the first k with
 *     V_k = (M V0 + sum_{j<=k} m_j w_j) / (M + sum_{j<=k} m_j) <= w_{k+1}
 * (the left side minus M V0 is (M + sum m)(V - V_k) on (w_k, w_{k+1}]). The node loop
 * (fe_integrate) then lands the nodes on the plane d(n+1) exactly as for a prescribed wall, so
 * the nodes' impulses are the ones solved here (to round-off).
 *
 * Energy: the landing is inelastic. With fe_integrate's trapezoidal works (weights hb before t,
 * dth after), the work of the pair of impulses J_i (force J_i/dth at t) is
 *     before: 1/2 sum J_i (hb/dth) (v_i(n-1/2).n - V(n-1/2)),   after: 1/2 sum J_i (-g_i/dt),
 * both <= 0 for approaching nodes; its opposite is the landing loss, counted as dissipated and
 * given back to the external work (so the free wall does no net external work and `total`
 * stays constant). A node stopped by several walls with mass sees each solved with its free
 * velocity (walls are solved one at a time). */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdlib.h>

static int cmp_w(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* normal free velocity of node n at t + dt/2 (fe_integrate's update, constraints applied) */
static double free_normal(const fe_model *m, const fe_state *s, int n, const double *nrm,
                          const fe_wall_step *P)
{
    const double *vo = s->node_v + 3 * n, *a = s->node_a + 3 * n;
    double u = 0;
    for (int i = 0; i < 3; i++) {
        double v = (P->d0 * vo[i] + P->dth * a[i]) * P->d1;
        if (m->node_fix[n] & (1u << i)) v = fe_node_vfix(m, s)[3 * n + i];
        u += v * nrm[i];
    }
    return u;
}

static double node_mass(const fe_model *m, const fe_state *s, int n)
{
    return m->node_mass[n] + (m->nms_node ? s->node_dm[n] : 0);
}

void fe_wall_kin_solve(const fe_model *m, fe_state *s, int w, const fe_wall_step *P)
{
    const fe_wall *W = &m->wall[w];
    const double *nrm = W->normal, *d = s->wall_x + 3 * w, dt = P->dt, M = W->mass;
    const double V0 = fe_dot(s->wall_v + 3 * w, nrm), dn = fe_dot(d, nrm);
    const double pn = fe_dot(W->point, nrm);
    const int k0 = m->wall_slave_off[w], k1 = m->wall_slave_off[w + 1];
    double *c = s->wall_scr + 2 * (size_t)k0; /* (w_i, m_i) of the nodes that may land */
    int nc = 0;
    for (int k = k0; k < k1; k++) {
        const int n = m->wall_slave[k];
        const double mass = node_mass(m, s, n);
        if (!(mass > 0)) continue;
        const double g = fe_dot(s->node_x + 3 * n, nrm) - pn - dn;
        const double wi = free_normal(m, s, n, nrm, P) + g / dt;
        if (wi < V0) c[2 * nc] = wi, c[2 * nc + 1] = mass, nc++;
    }
    double V = V0;
    if (nc > 0) {
        qsort(c, (size_t)nc, 2 * sizeof(double), cmp_w);
        double num = M * V0, den = M;
        for (int k = 0; k < nc; k++) {
            num += c[2 * k + 1] * c[2 * k];
            den += c[2 * k + 1];
            V = num / den;
            if (k + 1 == nc || V <= c[2 * k + 2]) break;
        }
    }
    /* the landing loss, before and after t (see the header) */
    double db = 0, da = 0;
    for (int k = k0; k < k1 && nc > 0; k++) {
        const int n = m->wall_slave[k];
        const double mass = node_mass(m, s, n);
        if (!(mass > 0)) continue;
        const double g = fe_dot(s->node_x + 3 * n, nrm) - pn - dn;
        const double wi = free_normal(m, s, n, nrm, P) + g / dt;
        if (!(wi < V)) continue;
        const double J = mass * (V - wi);
        db -= 0.5 * J * (P->hb / P->dth) * (fe_dot(s->node_v + 3 * n, nrm) - V0);
        da += 0.5 * J * g / dt;
    }
    s->wall_diss[2 * w] = db;
    s->wall_diss[2 * w + 1] = da;
    for (int i = 0; i < 3; i++) {
        s->wall_vn[3 * w + i] = V * nrm[i];
        s->wall_xn[3 * w + i] = d[i] + dt * V * nrm[i];
    }
}

/* walls that keep a slave list: kinematic with mass, penalty with friction (fe_wall_fric.c) */
static int listed(const fe_wall *W)
{
    return fe_wall_kin_mass(W) || (W->method == FE_WALL_PENALTY && W->friction > 0);
}

/* the slave lists */
mcs_status fe_wall_kin_finish(fe_model *m, mcs_error *err)
{
    int cnt = 0;
    for (int w = 0; w <= m->nwall; w++) {
        m->wall_slave_off[w] = cnt;
        if (w == m->nwall || !listed(&m->wall[w])) continue;
        for (int n = 0; n < m->nnode; n++) cnt += (m->node_walls[n] >> w) & 1u;
    }
    m->nwall_slave = cnt;
    m->wall_slave = malloc(sizeof(int) * (size_t)(cnt ? cnt : 1));
    if (!m->wall_slave) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (wall slaves)");
    for (int w = 0, k = 0; w < m->nwall; w++) {
        if (!listed(&m->wall[w])) continue;
        for (int n = 0; n < m->nnode; n++)
            if ((m->node_walls[n] >> w) & 1u) m->wall_slave[k++] = n;
    }
    m->bytes += sizeof(int) * (size_t)cnt;
    return MCS_OK;
}

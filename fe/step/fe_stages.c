/* fe_stages: the sub-stages of fe_step (internal forces, contact, external forces,
 * accelerations, integration, stable step). Each reads and writes only what its comment says. */
#include "fe/fe_contact.h"
#include "fe/fe_elem.h"
#include "fe/fe_joint.h"
#include "fe/fe_membrane.h"
#include "fe/fe_parallel.h"
#include "fe/fe_restraint.h"
#include "fe/fe_slipring.h"
#include "fe/fe_solid.h"
#include "fe/fe_tet10.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* parts whose elements run in threaded chunks (fe_*_range) */
static int chunked_part(const fe_part *p)
{
    return fe_part_chunked(p);
}

/* the element chunks of share t: stresses, slot forces, partial sums; each chunk's time
 * summed when threaded (the next balance, fe_parallel.c) */
static void elem_share(const fe_model *m, fe_state *s, int t, int timed)
{
    fe_par_range r;
    fe_par_share(m, s, t, &r);
    for (int k = r.c0; k < r.c1; k++) {
        const int ip = m->chunk_part[k], e0 = m->chunk_elem[k];
        const int e1 = e0 + FE_CHUNK_ELEMS < m->part[ip].elem_end ? e0 + FE_CHUNK_ELEMS
                                                                 : m->part[ip].elem_end;
        if (!chunked_part(m->part + ip)) continue;
        const double t0 = timed ? fe_par_clock() : 0;
        s->chunk_acc[k].e_erode = 0, s->chunk_acc[k].nerode = 0; /* set by eroding parts */
        switch (m->part[ip].elem_kind) {
        case FE_KIND_HEX: fe_hex_range(m, s, ip, e0, e1, s->chunk_acc + k); break;
        case FE_KIND_SHELL: fe_shell_range(m, s, ip, e0, e1, s->chunk_acc + k); break;
        case FE_KIND_TET10: fe_tet10_range(m, s, ip, e0, e1, s->chunk_acc + k); break;
        default: fe_truss_range(m, s, ip, e0, e1, s->chunk_acc + k); break;
        }
        if (timed) s->chunk_cost[k] += fe_par_clock() - t0;
    }
}

/* gather of share t: each node sums its element slots in slot order (no element writes to a
 * shared node) */
static void gather_share(const fe_model *m, fe_state *s, int t)
{
    const int sb = m->slot_base[FE_KIND_SHELL], se = m->slot_base[FE_KIND_TRUSS];
    fe_par_range r;
    fe_par_share(m, s, t, &r);
    for (int n = r.n0; n < r.n1; n++) {
        double f0 = 0, f1 = 0, f2 = 0, m0 = 0, m1 = 0, m2 = 0;
        for (int j = m->node_slot_off[n]; j < m->node_slot_off[n + 1]; j++) {
            int sl = m->node_slot[j];
            const double *f = s->slot_f + 3 * (size_t)sl;
            f0 += f[0];
            f1 += f[1];
            f2 += f[2];
            if (sl >= sb && sl < se) {
                const double *mm = s->shell_m + 3 * (size_t)(sl - sb);
                m0 += mm[0];
                m1 += mm[1];
                m2 += mm[2];
            }
        }
        double *fi = s->node_fint + 3 * n, *mi = s->node_mint + 3 * n;
        double *fx = s->node_fext + 3 * n;
        fi[0] = f0, fi[1] = f1, fi[2] = f2;
        mi[0] = m0, mi[1] = m1, mi[2] = m2;
        fx[0] = fx[1] = fx[2] = 0; /* for fe_contact_forces, by the node's own thread */
    }
}

/* reads x, v (t - dt/2), stresses; writes stresses, slot forces, node_fint, node_mint,
 * part internal/hourglass/dissipated energies and part element steps; zeroes node_fext.
 * Threaded: each thread its own element chunks, then its own nodes (fe_parallel.h; the
 * result does not depend on the thread count). With threaded contact, each thread also runs
 * the contact entries of its nodes after its elements, with no barrier between: the thread
 * shares balance the two together (fe_parallel.c), which they could not do across a barrier
 * (the entries need only x and v at t; fe_contact.h). */
void fe_internal_forces(const fe_model *m, fe_state *s)
{
    const int nch = m->nchunk;
    /* parts without a chunked kernel: whole part at a time, before the gather */
    for (int ip = 0; ip < m->npart; ip++)
        if (m->part[ip].body >= 0 || m->part[ip].material.model == FE_MAT_NULL)
            s->part_dt[ip] = INFINITY; /* rigid or null: no element work, no step limit */
        else if (m->part[ip].elem_kind == FE_KIND_SHELL && m->part[ip].section.type == FE_SECTION_MEMBRANE)
            fe_membrane_part(m, s, ip);
    fe_chunk_acc *ca = s->chunk_acc;
    const int nt = fe_par_team(m, s);
    if (m->contact) fe_contact_begin(m, s);
    const int live = fe_contact_threaded(m, s);
    if (nt > 1) {
#pragma omp parallel num_threads(nt)
        {
            for (int t = fe_par_tid(); t < nt; t += fe_par_nth()) {
                elem_share(m, s, t, 1);
                if (live) fe_contact_live(m, s, t);
            }
#pragma omp barrier
            for (int t = fe_par_tid(); t < nt; t += fe_par_nth()) gather_share(m, s, t);
        }
    } else {
        elem_share(m, s, 0, 0);
        gather_share(m, s, 0);
    }
    if (live) s->contact->live_done = 1;
    /* partial sums of each part in chunk order */
    int nerode = 0;
    for (int k = 0; k < nch;) {
        const int ip = m->chunk_part[k];
        fe_chunk_acc acc = ca[k++];
        while (k < nch && m->chunk_part[k] == ip) fe_chunk_merge(&acc, ca + k++);
        if (chunked_part(m->part + ip)) fe_chunk_commit(s, ip, &acc), nerode += acc.nerode;
    }
    if (nerode > 0) { /* elements deleted this step: contacts leave them out from the next */
        memcpy(s->elem_gone, s->elem_dead, (size_t)m->nerode);
        if (s->neroded == 0) s->erode_first = s->time;
        s->neroded += nerode;
        s->erode_last = s->time;
    }
    fe_discrete_forces(m, s); /* springs and dampers add to node_fint */
    fe_joint_forces(m, s);    /* joints: loads on the rigid bodies (body_fj) */
}

/* reads x, time; adds the contact and penalty rigid-wall forces to node_fext (zeroed by
 * fe_internal_forces, each node by its own thread) and writes the walls' forces. Kinematic
 * walls act in fe_integrate (they need the new velocities). */
void fe_contact_forces(const fe_model *m, fe_state *s)
{
    memset(s->wall_force, 0, sizeof(double) * 3 * (size_t)m->nwall);
    memset(s->wall_part_f, 0, sizeof(double) * (size_t)m->nwall_part);
    if (m->contact) fe_contact_finish(m, s); /* begun in fe_internal_forces */
    unsigned pen = 0;
    for (int w = 0; w < m->nwall; w++)
        if (m->wall[w].method == FE_WALL_PENALTY) pen |= 1u << w;
    if (!pen) return;
    const double dt = s->dt;
    for (int n = 0; n < m->nnode; n++) {
        unsigned mask = m->node_walls[n] & pen;
        while (mask) {
            int w = __builtin_ctz(mask);
            mask &= mask - 1;
            const fe_wall *W = &m->wall[w];
            double g = 0;
            for (int i = 0; i < 3; i++)
                g += (s->node_x[3 * n + i] - W->point[i] - s->wall_x[3 * w + i]) * W->normal[i];
            if (g >= 0) continue;
            /* stiffness scale m / dt^2: a fraction of the node's own stability limit */
            double fn = -W->penalty_scale * m->node_mass[n] / (dt * dt) * g;
            for (int i = 0; i < 3; i++) {
                s->node_fext[3 * n + i] += fn * W->normal[i];
                s->wall_force[3 * w + i] -= fn * W->normal[i];
            }
            /* by part: a node without elements (a point mass) counts for its rigid part */
            int p = m->node_part[n], bd = m->node_body[n];
            if (p < 0 && bd >= 0) p = m->body[bd].part;
            if (p >= 0) s->wall_part_f[w * m->npart + p] += fn;
        }
    }
    if (m->nwall_slave) fe_wall_penalty_friction(m, s); /* after the normal forces */
}

/* a load curve's scale at t (constant beyond its ends; no points: 1) */
static double load_scale(const fe_load_curve *c, double t)
{
    double sc = 1;
    if (c->ncurve == 1 || (c->ncurve > 1 && t <= c->curve[0][0])) sc = c->curve[0][1];
    else if (c->ncurve > 1 && t >= c->curve[c->ncurve - 1][0]) sc = c->curve[c->ncurve - 1][1];
    else if (c->ncurve > 1) {
        int k = 0;
        while (t > c->curve[k + 1][0]) k++;
        double u = (t - c->curve[k][0]) / (c->curve[k + 1][0] - c->curve[k][0]);
        sc = c->curve[k][1] + u * (c->curve[k + 1][1] - c->curve[k][1]);
    }
    return sc;
}

/* reads time, the load curves, x (pressures); adds nodal loads and pressures to node_fext */
void fe_external_forces(const fe_model *m, fe_state *s)
{
    for (int i = 0; i < m->nnodal_load; i++) {
        const fe_nodal_load *l = &m->nodal_load[i];
        const double sc = load_scale(&m->load_curve[l->load], s->time);
        for (int j = 0; j < 3; j++) s->node_fext[3 * l->node + j] += sc * l->force[j];
    }
    /* pressures: -p A n over the current segment, A n = (x3 - x1) x (x4 - x2) / 2 (a
     * triangle's too, x4 = x3), shared by its 4 (3) nodes */
    for (int i = 0; i < m->npressure; i++) {
        const fe_pressure *pr = &m->pressure[i];
        const double p = pr->p * load_scale(&m->load_curve[pr->load], s->time);
        const double *x1 = s->node_x + 3 * pr->node[0], *x2 = s->node_x + 3 * pr->node[1];
        const double *x3 = s->node_x + 3 * pr->node[2], *x4 = s->node_x + 3 * pr->node[3];
        double d1[3], d2[3], an[3];
        for (int j = 0; j < 3; j++) d1[j] = x3[j] - x1[j], d2[j] = x4[j] - x2[j];
        fe_cross(d1, d2, an);
        const int tri = pr->node[3] == pr->node[2], nn = tri ? 3 : 4;
        for (int k = 0; k < nn; k++)
            for (int j = 0; j < 3; j++) s->node_fext[3 * pr->node[k] + j] -= 0.5 * p * an[j] / nn;
    }
    /* gas bag pressures and retractor pulls (fe_restraint_step.c); errors go to s->err */
    if (m->restraints) fe_restraint_forces(m, s);
    /* slip rings: webbing flows round the ring under the capstan law (fe_slipring_step.c) */
    if (m->sliprings) fe_slipring_forces(m, s);
    fe_gravity_forces(m, s);
}

static void accel_share(const fe_model *m, fe_state *s, int t)
{
    fe_par_range r;
    fe_par_share(m, s, t, &r);
    const double *dm = m->nms_node ? s->node_dm : NULL; /* run-time mass scaling */
    for (int n = r.n0; n < r.n1; n++) {
        double mass = m->node_mass[n] + (dm ? dm[n] : 0), inv = mass > 0 ? 1 / mass : 0;
        for (int i = 0; i < 3; i++)
            s->node_a[3 * n + i] = (s->node_fext[3 * n + i] - s->node_fint[3 * n + i]) * inv;
    }
}

/* reads node_fext, node_fint, masses; writes node_a (each thread its own nodes) */
void fe_accelerations(const fe_model *m, fe_state *s)
{
    const int nt = s->par_nt > 1 ? s->par_nt : 1;
    if (nt > 1) {
#pragma omp parallel num_threads(nt)
        for (int t = fe_par_tid(); t < nt; t += fe_par_nth()) accel_share(m, s, t);
    } else {
        accel_share(m, s, 0);
    }
}

/* constants of one integration step */
typedef struct {
    double dt, dth, tn, c, d0, d1, hb, idth;
    double ridth; /* (1 + c dth / 2) / dth: constraint force of a velocity jump per mass [1/s] */
    unsigned kin; /* bit w: wall w is kinematic */
} integ_par;

/* node chunk k: velocities, positions and the chunk's partial sums in node_acc */
static void integrate_chunk(const fe_model *m, fe_state *s, int k, const integ_par *P)
{
    const double dt = P->dt, dth = P->dth, c = P->c, d0 = P->d0, d1 = P->d1;
    const double hb = P->hb, idth = P->idth, ridth = P->ridth;
    double *react = s->node_react; /* a coupling's record of the reactions, or NULL */
    const unsigned kin = P->kin;
    const int stride = m->node_acc_stride, npart = m->npart, nwall = m->nwall;
    double *acc = s->node_acc + (size_t)stride * k, *pke = acc + FE_NACC_FIXED;
    double *wf_acc = pke + npart;
    for (int i = 0; i < FE_NACC_FIXED + npart + 3 * nwall; i++) acc[i] = 0;
    double ke = 0, wb = 0, wf = 0, db = 0, dfw = 0;
    int bad = -1;
    const int n1 = (k + 1) * FE_CHUNK_NODES < m->nnode ? (k + 1) * FE_CHUNK_NODES : m->nnode;
    const double *dm = m->nms_node ? s->node_dm : NULL, *din = m->nms_node ? s->node_din : NULL;
    for (int n = k * FE_CHUNK_NODES; n < n1; n++) {
        const double mass = m->node_mass[n] + (dm ? dm[n] : 0); /* run-time mass scaling */
        if (!(mass > 0) || m->node_body[n] >= 0) continue; /* rigid bodies: fe_rigid.c */
        double *v = s->node_v + 3 * n, *x = s->node_x + 3 * n;
        const double *a = s->node_a + 3 * n, *fe = s->node_fext + 3 * n;
        const unsigned fix = m->node_fix[n];
        double vo[3] = {v[0], v[1], v[2]}, vn[3], vfree[3];
        for (int i = 0; i < 3; i++) vn[i] = vfree[i] = (d0 * vo[i] + dth * a[i]) * d1;
        const double *vfix = fe_node_vfix(m, s) + 3 * n;
        for (int i = 0; i < 3; i++)
            if (fix & (1u << i)) vn[i] = vfix[i];
        unsigned mask = m->node_walls[n] & kin;
        while (mask) {
            int w = __builtin_ctz(mask);
            mask &= mask - 1;
            const fe_wall *W = &m->wall[w];
            double g = 0;
            for (int i = 0; i < 3; i++)
                g += (x[i] + dt * vn[i] - W->point[i] - s->wall_xn[3 * w + i]) * W->normal[i];
            if (g >= 0) continue;
            /* land on the wall: remove the normal velocity that would penetrate */
            double dv = -g / dt;
            for (int i = 0; i < 3; i++) {
                vn[i] += dv * W->normal[i];
                wf_acc[3 * w + i] -= mass * dv * idth * W->normal[i];
            }
            if (W->friction > 0) { /* Coulomb (fe_wall_fric.c) */
                double fd[2] = {0, 0};
                fe_wall_kin_friction(m, s, w, mass, dv, vo, vn, hb, dth, dt, wf_acc + 3 * w, fd);
                db += fd[0], dfw += fd[1], wb += fd[0], wf += fd[1];
            }
        }
        /* works of the forces at t: half on the interval before (now), half on the one
         * after (pending), each weighted by the velocity-update step dth, which makes
         * K(n+1) - K(n) = sum of the works exactly (fe_state.h); no interval before t = 0 */
        double ek = 0;
        for (int i = 0; i < 3; i++) {
            /* constraint and wall reaction: m (vn - vo) / dth = f + r - c m (vo + vn) / 2 */
            double r = mass * (vn[i] - vfree[i]) * ridth;
            if (react) react[3 * n + i] = r;
            double fd = -c * mass * 0.5 * (vo[i] + vn[i]);
            ek += vo[i] * vn[i];
            wb += 0.5 * (fe[i] + r) * hb * vo[i];
            wf += 0.5 * (fe[i] + r) * dth * vn[i];
            db -= 0.5 * fd * hb * vo[i];
            dfw -= 0.5 * fd * dth * vn[i];
            v[i] = vn[i];
            x[i] += dt * vn[i];
        }
        if (!isfinite(vn[0] + vn[1] + vn[2]) && bad < 0) bad = n;
        ek *= 0.5 * mass;
        const double in = m->node_inertia[n] + (din ? din[n] : 0);
        if (in > 0) {
            double *w = s->node_w + 3 * n;
            const double *mi = s->node_mint + 3 * n, iin = dth / in;
            for (int i = 0; i < 3; i++) {
                double wo = w[i], wn = (d0 * wo - mi[i] * iin) * d1;
                if (fix & (8u << i)) wn = 0;
                ek += 0.5 * in * wo * wn;
                db += 0.5 * c * in * 0.5 * (wo + wn) * hb * wo;
                dfw += 0.5 * c * in * 0.5 * (wo + wn) * dth * wn;
                w[i] = wn;
            }
            if (!isfinite(w[0] + w[1] + w[2]) && bad < 0) bad = n;
        }
        ke += ek;
        if (m->node_part[n] >= 0) pke[m->node_part[n]] += ek;
    }
    acc[FE_ACC_KE] = ke;
    acc[FE_ACC_WB] = wb;
    acc[FE_ACC_WF] = wf;
    acc[FE_ACC_DB] = db;
    acc[FE_ACC_DF] = dfw;
    acc[FE_ACC_BAD] = bad;
}

static void integrate_share(const fe_model *m, fe_state *s, int t, const integ_par *P)
{
    fe_par_range r;
    fe_par_share(m, s, t, &r);
    for (int k = r.nc0; k < r.nc1; k++) integrate_chunk(m, s, k, P);
}

/* reads node_a, node_mint, v, w, x; writes v, w (t + dt/2), x (t + dt), the kinematic
 * walls' forces, kinetic energy and the works of loads, constraints and damping (at t).
 * Threaded over node chunks (each thread its own, fe_parallel.h); each chunk's sums go to
 * node_acc and are added in chunk order. */
void fe_integrate(const fe_model *m, fe_state *s)
{
    integ_par P;
    P.dt = s->dt;
    const double dtp = s->dt_prev;
    P.dth = 0.5 * (P.dt + dtp), P.tn = s->time + P.dt;
    P.c = m->opts.damping, P.d0 = 1 - 0.5 * P.c * P.dth, P.d1 = 1 / (1 + 0.5 * P.c * P.dth);
    P.hb = dtp > 0 ? P.dth : 0; /* weight of the interval before t */
    P.idth = 1 / P.dth;
    P.ridth = (1 + 0.5 * P.c * P.dth) / P.dth; /* = idth without damping */
    P.kin = 0;
    for (int w = 0; w < m->nwall; w++)
        if (m->wall[w].method == FE_WALL_KINEMATIC) P.kin |= 1u << w;
    if (m->nwall) { /* walls at t + dt; kinematic walls with mass solved with their slaves */
        fe_wall_step ws = {P.dt, P.dth, P.hb, P.d0, P.d1};
        fe_wall_predict(m, s, &ws);
    }
    const int nch = m->nnode_chunk, stride = m->node_acc_stride, npart = m->npart;
    const int nwall = m->nwall, nt = s->par_nt > 1 ? s->par_nt : 1;
    if (nt > 1) {
#pragma omp parallel num_threads(nt)
        for (int t = fe_par_tid(); t < nt; t += fe_par_nth()) integrate_share(m, s, t, &P);
    } else {
        integrate_share(m, s, 0, &P);
    }
    double ke = 0, wb = 0, wf = 0, db = 0, dfw = 0;
    int bad = -1;
    for (int ip = 0; ip < npart; ip++) s->part_energy[FE_NENERGY * ip + FE_E_kinetic] = 0;
    for (int k = 0; k < nch; k++) {
        const double *acc = s->node_acc + (size_t)stride * k, *pke = acc + FE_NACC_FIXED;
        ke += acc[FE_ACC_KE];
        wb += acc[FE_ACC_WB];
        wf += acc[FE_ACC_WF];
        db += acc[FE_ACC_DB];
        dfw += acc[FE_ACC_DF];
        if (bad < 0 && acc[FE_ACC_BAD] >= 0) bad = (int)acc[FE_ACC_BAD];
        for (int ip = 0; ip < npart; ip++)
            s->part_energy[FE_NENERGY * ip + FE_E_kinetic] += pke[ip];
        for (int i = 0; i < 3 * nwall; i++) s->wall_force[i] += pke[npart + i];
    }
    s->energy[FE_E_kinetic] = ke;
    s->work_ext += wb + s->work_pending[0];
    s->work_damp += db + s->work_pending[2];
    s->work_pending[0] = wf;
    s->work_pending[2] = dfw;
    s->bad_node = bad;
    fe_rigid_integrate(m, s); /* rigid bodies move their nodes */
    for (int w = 0; w < m->nwall; w++) {
        const fe_wall *W = &m->wall[w];
        s->wall_normal[w] = -fe_dot(s->wall_force + 3 * w, W->normal);
        s->wall_disp[w] = fe_dot(s->wall_x + 3 * w, W->normal);
    }
    fe_wall_integrate(m, s); /* walls to t + dt; walls with mass: momentum, energy */
}

static void record_history(const fe_model *m, fe_state *s)
{
    int cap = m->opts.history_capacity;
    if (cap <= 0 || s->energy_time < s->hist_next - 1e-9 * s->dt) return;
    if (s->nhist >= cap) {
        s->hist_dropped++;
        return;
    }
    int k = s->nhist++;
    s->hist_time[k] = s->energy_time;
    memcpy(s->hist_energy + FE_NENERGY * (size_t)k, s->energy, sizeof s->energy);
    for (int w = 0; w < m->nwall; w++) {
        s->hist_wall_force[FE_WALL_MAX * (size_t)k + w] = s->wall_normal[w];
        s->hist_wall_disp[FE_WALL_MAX * (size_t)k + w] = s->wall_disp[w];
    }
    /* samples on the grid k * interval: the first step at or after each grid time */
    const double iv = m->opts.history_interval;
    if (iv > 0)
        s->hist_next += iv * fmax(1.0, ceil((s->energy_time - s->hist_next) / iv + 1e-9));
}

/* reads part energies and steps, the works; writes the global energies (at t), the history,
 * time, dt_prev and the next dt; stops on NaN, inverted elements, step collapse, energy growth */
mcs_status fe_stable_step(const fe_model *m, fe_state *s)
{
    const double t = s->time;
    double e_int = s->free_energy[FE_E_internal], e_hg = 0, e_erode = 0;
    double e_diss = s->work_damp + s->free_energy[FE_E_dissipated], dtmin = m->dt_discrete;
    for (int ip = 0; ip < m->npart; ip++) {
        const double *pe = s->part_energy + FE_NENERGY * ip;
        e_int += pe[FE_E_internal];
        e_hg += pe[FE_E_hourglass];
        e_diss += pe[FE_E_dissipated];
        e_erode += pe[FE_E_eroded];
        if (s->part_bad_elem[ip] >= 0)
            return MCS_ERR(&s->err, MCS_ERR_NUMERIC,
                           "fe: part '%s': element %d inverted or degenerate at t = %.6g s",
                           m->part[ip].name, s->part_bad_elem[ip] - m->part[ip].elem_begin, t);
        if (s->part_dt[ip] < dtmin) {
            dtmin = s->part_dt[ip];
            s->dt_part = ip;
            s->dt_elem = s->part_dt_elem[ip];
        }
    }
    if (s->bad_node >= 0)
        return MCS_ERR(&s->err, MCS_ERR_NUMERIC,
                       "fe: node %d: velocity is not finite at t = %.6g s (part '%s')",
                       s->bad_node, t,
                       m->node_part[s->bad_node] >= 0 ? m->part[m->node_part[s->bad_node]].name
                                                      : "-");
    double *en = s->energy;
    en[FE_E_potential] = 0;
    en[FE_E_internal] = e_int;
    en[FE_E_contact] = m->contact ? fe_contact_energy(m, s) : 0;
    en[FE_E_hourglass] = e_hg;
    en[FE_E_dissipated] = e_diss;
    en[FE_E_eroded] = e_erode;
    /* contact forces are internal to the structure: their work leaves the external work */
    en[FE_E_external_work] = s->work_ext - (m->contact ? fe_contact_work(m, s) : 0);
    en[FE_E_total] = en[FE_E_kinetic] + en[FE_E_potential] + e_int + en[FE_E_contact] + e_hg +
                     e_diss + e_erode - en[FE_E_external_work];
    s->energy_time = t;
    if (s->nstep == 0) s->energy0 = en[FE_E_total];
    double ref = fmax(fmax(en[FE_E_kinetic], e_int + e_hg), fabs(en[FE_E_external_work]));
    s->energy_ref = fmax(fmax(s->energy_ref, ref), fabs(s->energy0));
    double growth = en[FE_E_total] - s->energy0;
    if (!isfinite(en[FE_E_total]))
        return MCS_ERR(&s->err, MCS_ERR_NUMERIC, "fe: energy is not finite at t = %.6g s", t);
    /* a floor of 1 nJ under the reference: a structure at rest (a bag at ambient pressure
     * before a stage-1 body reaches it) has round-off energies of 1e-28 J */
    if (m->opts.energy_growth_limit > 0 &&
        growth > m->opts.energy_growth_limit * fmax(s->energy_ref, 1e-9)) {
        int ip = s->dt_part;
        return MCS_ERR(&s->err, MCS_ERR_NUMERIC,
                       "fe: energy grew by %.3g J (%.1f %% of %.3g J) at t = %.6g s: unstable; "
                       "smallest step in part '%s' element %d",
                       growth, 100 * growth / s->energy_ref, s->energy_ref, t,
                       ip >= 0 ? m->part[ip].name : "-",
                       ip >= 0 ? s->dt_elem - m->part[ip].elem_begin : -1);
    }
    record_history(m, s);
    /* advance the clock; the new step comes from the geometry at t */
    s->time = t + s->dt;
    s->dt_prev = s->dt;
    s->nstep++;
    if (m->nms_elem) dtmin = fe_massscale_run(m, s, dtmin); /* mass scaling in the run */
    /* the smallest estimate of the last FE_DT_WINDOW steps: a step that follows the element
     * lengths and strain rates step by step oscillates with the highest mode and pumps it
     * (docs/fe.md, rigid walls) */
    s->dt_win[s->nstep % FE_DT_WINDOW] = dtmin;
    for (int k = 0; k < FE_DT_WINDOW; k++) dtmin = fmin(dtmin, s->dt_win[k]);
    double dt = m->opts.dt_scale * dtmin;
    if (m->opts.dt_max > 0) dt = fmin(dt, m->opts.dt_max);
    if (isinf(dt) && s->neroded > 0) dt = s->dt_prev; /* every element eroded: the last step */
    if (!(dt >= m->opts.dt_min)) {
        int ip = s->dt_part;
        return MCS_ERR(&s->err, MCS_ERR_NUMERIC,
                       "fe: stable step collapsed to %.3g s at t = %.6g s (part '%s' element %d)",
                       dt, s->time, ip >= 0 ? m->part[ip].name : "-",
                       ip >= 0 ? s->dt_elem - m->part[ip].elem_begin : -1);
    }
    s->dt = dt;
    return MCS_OK;
}

/* fe_model: validation and freezing of a builder into the immutable model: elements sorted by
 * part, lumped masses, gather lists, boundary conditions, loads, rigid-wall slaves. */
#include "fe/fe_builder_impl.h"
#include "fe/fe_contact.h"
#include "fe/fe_elem.h"
#include "fe/fe_joint.h"
#include "fe/fe_membrane.h"
#include "fe/fe_restraint.h"
#include "fe/fe_slipring.h"
#include "fe/fe_solid.h"
#include "fe/fe_tet10.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

fe_opts fe_opts_default(void)
{
    fe_opts o;
    memset(&o, 0, sizeof o);
    o.dt_scale = 0.9;
    o.dt_min = 1e-12;
    o.bulk_q1 = 1.5;
    o.bulk_q2 = 0.06;
    o.energy_growth_limit = 0.05;
    return o;
}

void fe_model_destroy(fe_model **p)
{
    if (!p || !*p) return;
    fe_model *m = *p;
#define FE_X_FREE(T, name, n, k, unit, doc) free(m->name);
    FE_MODEL_ARRAYS(FE_X_FREE)
#undef FE_X_FREE
    free(m->part);
    free(m->wall);
    free(m->nodal_load);
    free(m->load_curve);
    free(m->pressure);
    fe_restraints_destroy(&m->restraints);
    fe_sliprings_destroy(&m->sliprings);
    fe_solid_free(m);
    fe_contact_model_free(m);
    free(m);
    *p = NULL;
}

/* Gauss-Legendre points and weights on [-1/2, 1/2], weights summing to 1 */
static void gauss_points(int n, double *z, double *w)
{
    for (int i = 0; i < n; i++) {
        double x = cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1;
        for (int it = 0; it < 100; it++) {
            double p0 = 1, p1 = x;
            for (int k = 2; k <= n; k++) {
                double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (x * p1 - p0) / (x * x - 1);
            double dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-16) break;
        }
        z[i] = -0.5 * x;
        w[i] = 1.0 / ((1 - x * x) * dp * dp); /* 2 / ((1 - x^2) P'^2) on [-1, 1], halved */
    }
}

static void derive_part(fe_part *p)
{
    const fe_material_desc *mt = &p->material;
    double E = mt->youngs_modulus, nu = mt->poisson, rho = mt->density;
    p->mu = E / (2 * (1 + nu));
    p->lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    p->bulk = E / (3 * (1 - 2 * nu));
    if (p->elem_kind == FE_KIND_HEX || p->elem_kind == FE_KIND_TET10)
        p->wave_speed = sqrt((p->lambda + 2 * p->mu) / rho);
    else if (p->elem_kind == FE_KIND_SHELL)
        p->wave_speed = sqrt(E / (rho * (1 - nu * nu)));
    else
        p->wave_speed = sqrt(E / rho);
    p->hg_coef = p->section.hourglass_coefficient > 0 ? p->section.hourglass_coefficient
                 : p->section.hourglass == FE_HG_VISCOUS ? 0.1 : 0.05;
    p->shear_factor = p->section.shear_factor > 0 ? p->section.shear_factor : 5.0 / 6.0;
    if (p->elem_kind == FE_KIND_SHELL) gauss_points(p->section.integration_points, p->ip_z, p->ip_w);
    if (mt->model == FE_MAT_FABRIC) p->wave_speed = fe_fabric_wave_speed(mt);
    if (mt->model == FE_MAT_FOAM) fe_foam_derive(p);
}

static mcs_status alloc_arrays(fe_model *m, mcs_error *err)
{
    m->bytes = sizeof *m;
#define FE_X_ALLOC(T, name, n, k, unit, doc)                                                       \
    {                                                                                              \
        size_t cnt = (size_t)(m->n) * (k);                                                         \
        m->name = calloc(cnt ? cnt : 1, sizeof(T));                                                \
        if (!m->name) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory (%s)", #name);        \
        m->bytes += cnt * sizeof(T);                                                               \
    }
    FE_MODEL_ARRAYS(FE_X_ALLOC)
#undef FE_X_ALLOC
    return MCS_OK;
}

/* elements of each kind, stably sorted by part (counting sort) */
static void sort_elements(const fe_builder *b, fe_model *m)
{
    int *dst_node[FE_NKIND] = {m->hex_node, m->shell_node, m->truss_node, m->tet10_node};
    int *dst_part[FE_NKIND] = {m->hex_part, m->shell_part, m->truss_part, m->tet10_part};
    for (int k = 0; k < FE_NKIND; k++) {
        int nn = fe_kind_nnode(k), pos = 0;
        for (int ip = 0; ip < m->npart; ip++) {
            if (m->part[ip].elem_kind != k) continue;
            m->part[ip].elem_begin = pos;
            for (int e = 0; e < b->nelem[k]; e++) {
                if (b->epart[k][e] != ip) continue;
                memcpy(dst_node[k] + (size_t)nn * pos, b->conn[k] + (size_t)nn * e,
                       (size_t)nn * sizeof(int));
                if (k == FE_KIND_SHELL) /* its own thickness, else its section's */
                    m->shell_t[pos] = e < b->nshell_t && b->shell_t[e] > 0
                                          ? b->shell_t[e]
                                          : m->part[ip].section.thickness;
                dst_part[k][pos++] = ip;
            }
            m->part[ip].elem_end = pos;
        }
    }
}

/* masses and rotary inertias; rejects inverted or degenerate elements */
static mcs_status lump_masses(fe_model *m, mcs_error *err)
{
    for (int ip = 0; ip < m->npart; ip++) {
        const fe_part *p = &m->part[ip];
        double rho = p->material.density;
        if (p->elem_kind == FE_KIND_TET10) { /* HRZ lumping (fe_tet10.c) */
            mcs_status st = fe_tet10_lump(m, ip, err);
            if (st) return st;
            continue;
        }
        for (int e = p->elem_begin; e < p->elem_end; e++) {
            if (p->elem_kind == FE_KIND_HEX) {
                double xe[8][3], bb[8][3], a[8][3];
                const int *c = m->hex_node + 8 * e;
                for (int i = 0; i < 8; i++) memcpy(xe[i], m->node_x0 + 3 * c[i], sizeof xe[i]);
                double v = fe_hex_gradients(xe, bb, a);
                if (!(v > 0))
                    return MCS_ERR(err, MCS_ERR_RANGE,
                                   "fe: part '%s': hex %d (nodes %d %d %d %d ...) has volume %g "
                                   "m^3: inverted or degenerate (order the bottom face "
                                   "counter-clockwise seen from the top)",
                                   p->name, e - p->elem_begin, c[0], c[1], c[2], c[3], v);
                /* an equal share per distinct node (tetrahedra, pentahedra: fe_tet.c) */
                int u[8], nu = fe_hex_distinct(c, u);
                for (int i = 0; i < nu; i++) m->node_mass[u[i]] += rho * v / nu;
            } else if (p->elem_kind == FE_KIND_SHELL) {
                double xe[4][3], fr[3][3], xl[4], yl[4];
                const int *c = m->shell_node + 4 * e;
                for (int i = 0; i < 4; i++) memcpy(xe[i], m->node_x0 + 3 * c[i], sizeof xe[i]);
                double area = fe_shell_frame(xe, fr, xl, yl), t = m->shell_t[e];
                if (!(area > 0))
                    return MCS_ERR(err, MCS_ERR_RANGE,
                                   "fe: part '%s': shell %d (nodes %d %d %d %d) has area %g m^2: "
                                   "degenerate or folded",
                                   p->name, e - p->elem_begin, c[0], c[1], c[2], c[3], area);
                /* a degenerate triangle (node 3 = node 4) lumps a third to each node */
                int nn = c[2] == c[3] ? 3 : 4;
                double mn = rho * t * area / nn;
                /* rotary inertia scaled up to m A / 8 so rotations do not limit the step */
                double in = mn * fmax(t * t / 12, area / 8);
                if (p->section.type == FE_SECTION_MEMBRANE) in = 0; /* no rotations */
                for (int i = 0; i < nn; i++) {
                    m->node_mass[c[i]] += mn;
                    m->node_inertia[c[i]] += in;
                }
            } else {
                const int *c = m->truss_node + 2 * e;
                double d[3], len;
                for (int i = 0; i < 3; i++)
                    d[i] = m->node_x0[3 * c[1] + i] - m->node_x0[3 * c[0] + i];
                len = sqrt(fe_dot(d, d));
                if (!(len > 0))
                    return MCS_ERR(err, MCS_ERR_RANGE,
                                   "fe: part '%s': truss %d (nodes %d %d) has zero length",
                                   p->name, e - p->elem_begin, c[0], c[1]);
                for (int i = 0; i < 2; i++) m->node_mass[c[i]] += rho * p->section.area * len / 2;
            }
        }
    }
    for (int n = 0; n < m->nnode; n++) m->mass_total += m->node_mass[n];
    return MCS_OK;
}

/* node -> element-slot gather lists (CSR), slots in increasing order */
static void build_gather(fe_model *m)
{
    const int *conn[FE_NKIND] = {m->hex_node, m->shell_node, m->truss_node, m->tet10_node};
    const int *epart[FE_NKIND] = {m->hex_part, m->shell_part, m->truss_part, m->tet10_part};
    int nel[FE_NKIND] = {m->nhex, m->nshell, m->ntruss, m->ntet10};
    m->slot_base[0] = 0;
    m->slot_base[1] = 8 * m->nhex;
    m->slot_base[2] = m->slot_base[1] + 4 * m->nshell;
    m->slot_base[3] = m->slot_base[2] + 2 * m->ntruss;
    for (int n = 0; n < m->nnode; n++) m->node_part[n] = -1;
    for (int k = 0; k < FE_NKIND; k++) {
        int nn = fe_kind_nnode(k);
        for (int s = 0; s < nn * nel[k]; s++) {
            int node = conn[k][s];
            m->node_slot_off[node + 1]++;
            if (m->node_part[node] < 0) m->node_part[node] = epart[k][s / nn];
        }
    }
    for (int n = 0; n < m->nnode; n++) m->node_slot_off[n + 1] += m->node_slot_off[n];
    int *fill = calloc((size_t)m->nnode + 1, sizeof(int));
    for (int k = 0; k < FE_NKIND; k++) {
        int nn = fe_kind_nnode(k);
        for (int s = 0; s < nn * nel[k]; s++) {
            int node = conn[k][s];
            int at = m->node_slot_off[node] + (fill ? fill[node]++ : 0);
            m->node_slot[at] = m->slot_base[k] + s;
        }
    }
    free(fill);
}

static mcs_status apply_boundaries(const fe_builder *b, fe_model *m, mcs_error *err)
{
    int *idx = malloc(sizeof(int) * (size_t)(m->nnode ? m->nnode : 1));
    if (!idx) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    mcs_status st = MCS_OK;
    for (int i = 0; i < b->nbc && st == MCS_OK; i++) {
        const fe_boundary_desc *d = &b->bc[i];
        int ip = fe_builder_find_part(b, d->part);
        if (ip < 0) {
            st = MCS_ERR(err, MCS_ERR_KEY, "fe: boundary[%d]: unknown part '%s'", i, d->part);
            break;
        }
        int cnt = fe_builder_select(b, ip, d->where, idx, m->nnode);
        if (cnt <= 0) {
            st = MCS_ERR(err, MCS_ERR_RANGE, "fe: boundary[%d]: no node of part '%s' selected",
                         i, d->part);
            break;
        }
        for (int j = 0; j < cnt; j++) {
            m->node_fix[idx[j]] |= d->fix;
            for (int c = 0; c < 3; c++)
                if (d->fix & (1u << c)) m->node_vfix[3 * idx[j] + c] = d->velocity[c];
        }
    }
    for (int i = 0; i < b->nfix; i++) {
        const fe_node_fix *f = &b->fix[i];
        m->node_fix[f->node] |= f->fix;
        for (int c = 0; c < 3; c++)
            if (f->fix & (1u << c)) m->node_vfix[3 * f->node + c] = f->v[c];
    }
    free(idx);
    return st;
}

static mcs_status resolve_loads(const fe_builder *b, fe_model *m, mcs_error *err)
{
    int *idx = malloc(sizeof(int) * (size_t)(m->nnode ? m->nnode : 1));
    if (!idx) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    int total = 0;
    mcs_status st = MCS_OK;
    /* first pass counts, second fills */
    for (int pass = 0; pass < 2 && st == MCS_OK; pass++) {
        if (pass == 1) {
            m->nnodal_load = total;
            m->nload = b->nload;
            m->nodal_load = calloc((size_t)(total ? total : 1), sizeof *m->nodal_load);
            m->load_curve = calloc((size_t)(b->nload ? b->nload : 1), sizeof *m->load_curve);
            int np = 0; /* pressure segments (fe_builder_add_pressure) */
            for (int i = 0; i < b->nload; i++) np += b->load[i].node == -2;
            m->pressure = calloc((size_t)(np ? np : 1), sizeof *m->pressure);
            if (!m->nodal_load || !m->load_curve || !m->pressure) {
                st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
                break;
            }
            total = 0;
        }
        for (int i = 0; i < b->nload; i++) {
            const fe_bload *l = &b->load[i];
            int cnt = 1;
            if (l->node == -2) { /* a pressure: its curve, its segment */
                if (pass == 1) {
                    m->load_curve[i].ncurve = l->d.ncurve;
                    memcpy(m->load_curve[i].curve, l->d.curve, sizeof l->d.curve);
                    fe_pressure *pr = &m->pressure[m->npressure++];
                    memcpy(pr->node, l->seg, sizeof pr->node);
                    pr->p = l->d.force[0];
                    pr->load = i;
                }
                continue;
            }
            if (l->node < 0) {
                int ip = fe_builder_find_part(b, l->d.part);
                if (ip < 0) {
                    st = MCS_ERR(err, MCS_ERR_KEY, "fe: load[%d]: unknown part '%s'", i, l->d.part);
                    break;
                }
                cnt = fe_builder_select(b, ip, l->d.where, idx, m->nnode);
                if (cnt <= 0) {
                    st = MCS_ERR(err, MCS_ERR_RANGE, "fe: load[%d]: no node of '%s' selected", i,
                                 l->d.part);
                    break;
                }
            } else {
                idx[0] = l->node;
            }
            if (pass == 1) {
                m->load_curve[i].ncurve = l->d.ncurve;
                memcpy(m->load_curve[i].curve, l->d.curve, sizeof l->d.curve);
                for (int j = 0; j < cnt; j++) {
                    fe_nodal_load *nl = &m->nodal_load[total + j];
                    nl->node = idx[j];
                    nl->load = i;
                    for (int c = 0; c < 3; c++) nl->force[c] = l->d.force[c] / cnt;
                }
            }
            total += cnt;
        }
    }
    free(idx);
    return st;
}

static mcs_status resolve_walls(const fe_builder *b, fe_model *m, mcs_error *err)
{
    m->nwall = b->nwall;
    m->nwall_part = b->nwall * m->npart;
    m->wall = calloc((size_t)(b->nwall ? b->nwall : 1), sizeof *m->wall);
    if (!m->wall) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    unsigned char *inpart = calloc((size_t)(m->nnode ? m->nnode : 1), 1), *mk = NULL;
    if (inpart) mk = malloc((size_t)(m->nnode ? m->nnode : 1));
    if (!inpart || !mk) {
        free(inpart);
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    }
    mcs_status st = MCS_OK;
    for (int w = 0; w < b->nwall && st == MCS_OK; w++) {
        const fe_wall_desc *d = &b->wall[w];
        fe_wall *W = &m->wall[w];
        double nn = sqrt(fe_dot(d->normal, d->normal));
        memcpy(W->name, d->name, FE_NAME_MAX);
        for (int i = 0; i < 3; i++) {
            W->point[i] = d->point[i];
            W->normal[i] = d->normal[i] / nn;
            W->velocity[i] = d->velocity[i];
        }
        W->method = d->method;
        W->mass = d->mass;
        W->friction = d->friction; /* motion and friction: fe_wall.c, fe_wall_motion.c */
        W->nmotion = d->nmotion;
        memcpy(W->motion, d->motion, sizeof W->motion);
        for (int k = 0; k < W->nmotion; k++) fe_wall_motion_unit(&W->motion[k]);
        W->penalty_scale = d->penalty_scale > 0 ? d->penalty_scale : 0.1;
        memset(inpart, d->nparts ? 0 : 1, (size_t)m->nnode);
        for (int j = 0; j < d->nparts; j++) {
            int ip = fe_builder_find_part(b, d->parts[j]);
            if (ip < 0) {
                st = MCS_ERR(err, MCS_ERR_KEY, "fe: rigid wall '%s': unknown part '%s'", d->name,
                             d->parts[j]);
                break;
            }
            fe_builder_part_nodes(b, ip, mk);
            for (int n = 0; n < m->nnode; n++) inpart[n] |= mk[n];
        }
        /* slaves: nodes with mass on the side the normal points to at t = 0 */
        for (int n = 0; n < m->nnode && st == MCS_OK; n++) {
            double g = 0;
            for (int i = 0; i < 3; i++) g += (m->node_x0[3 * n + i] - W->point[i]) * W->normal[i];
            if (inpart[n] && m->node_mass[n] > 0 && g >= -1e-12) m->node_walls[n] |= 1u << w;
        }
    }
    free(inpart);
    free(mk);
    return st;
}

mcs_status fe_model_create(const fe_builder *b, const fe_opts *opts, fe_model **out,
                           mcs_error *err)
{
    *out = NULL;
    fe_opts o = opts ? *opts : fe_opts_default();
    if (!(o.dt_scale > 0 && o.dt_scale <= 2) || o.dt_max < 0 || o.dt_min < 0 || o.damping < 0 ||
        o.bulk_q1 < 0 || o.bulk_q2 < 0 || o.energy_growth_limit < 0 ||
        o.history_capacity < 0 || o.history_interval < 0)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: options: dt_scale must be in (0, 2], the others >= 0");
    if (b->npart == 0) return MCS_ERR(err, MCS_ERR_RANGE, "fe: the model has no parts");
    fe_model *m = calloc(1, sizeof *m);
    if (!m) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    m->opts = o;
    m->nnode = b->nnode;
    m->nhex = b->nelem[FE_KIND_HEX];
    m->nshell = b->nelem[FE_KIND_SHELL];
    m->ntruss = b->nelem[FE_KIND_TRUSS];
    m->ntet10 = b->nelem[FE_KIND_TET10];
    m->nelem = m->nhex + m->nshell + m->ntruss + m->ntet10;
    m->nslot = 8 * m->nhex + 4 * m->nshell + 2 * m->ntruss + 10 * m->ntet10;
    m->npart = b->npart;
    mcs_status st = MCS_OK;
    m->part = calloc((size_t)m->npart, sizeof *m->part);
    if (!m->part) st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    int *count = calloc((size_t)m->npart, sizeof(int));
    if (!count && st == MCS_OK) st = MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    for (int k = 0; k < FE_NKIND && st == MCS_OK; k++)
        for (int e = 0; e < b->nelem[k]; e++) count[b->epart[k][e]]++;
    for (int ip = 0; ip < m->npart && st == MCS_OK; ip++) {
        fe_part *p = &m->part[ip];
        const fe_part_desc *d = &b->part[ip];
        memcpy(p->name, d->name, FE_NAME_MAX);
        p->section = d->section;
        p->material = d->material;
        p->rigid = d->rigid;
        p->elem_kind = fe_section_kind(d->section.type);
        derive_part(p);
        if (p->elem_kind == FE_KIND_SHELL && d->section.integration_points > m->nip_max)
            m->nip_max = d->section.integration_points;
        if (count[ip] == 0)
            st = MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s' has no elements", p->name);
        m->nchunk += (count[ip] + FE_CHUNK_ELEMS - 1) / FE_CHUNK_ELEMS;
    }
    free(count);
    m->nshell_ip = m->nshell * m->nip_max;
    /* the filtered strain rate per shell point only when a shell part has a rate factor */
    for (int ip = 0; ip < m->npart; ip++)
        if (m->part[ip].elem_kind == FE_KIND_SHELL && m->part[ip].material.cowper_symonds_c > 0)
            m->nshell_rate = m->nshell_ip;
    for (int ip = 0; ip < m->npart; ip++)
        if (m->part[ip].section.type == FE_SECTION_MEMBRANE) m->nshell_mref = m->nshell;
    for (int ip = 0; ip < m->npart; ip++) /* element erosion: flags of every hex and shell */
        if (m->part[ip].material.failure_strain > 0) m->nerode = m->nhex + m->nshell;
    if (st == MCS_OK) st = alloc_arrays(m, err);
    if (st == MCS_OK) {
        /* masses and the membranes' reference metric from the reference positions; the nodes
         * then start where they are (a scaled initial mesh differs: fe_imm.c) */
        memcpy(m->node_x0, b->xref ? b->xref : b->x, sizeof(double) * 3 * (size_t)m->nnode);
        sort_elements(b, m);
        fe_build_chunks(m);
        st = lump_masses(m, err);
        fe_membrane_references(m); /* reference geometry of the membranes */
        if (b->xref) memcpy(m->node_x0, b->x, sizeof(double) * 3 * (size_t)m->nnode);
    }
    if (st == MCS_OK) st = fe_solid_build(b, m, err); /* point masses, springs, rigid bodies */
    if (st == MCS_OK) fe_count_chunked(m);            /* rigid parts known: the threaded work */
    if (st == MCS_OK) {
        build_gather(m);
        /* initial velocities by part, then prescribed velocities of fixed dofs */
        for (int n = 0; n < m->nnode; n++)
            if (m->node_part[n] >= 0)
                memcpy(m->node_v0 + 3 * n, b->part[m->node_part[n]].initial_velocity,
                       3 * sizeof(double));
        for (int i = 0; i < b->nvel; i++) /* single nodes' (fe_builder_node_velocity) */
            memcpy(m->node_v0 + 3 * b->vel[i].node, b->vel[i].v, 3 * sizeof(double));
        st = apply_boundaries(b, m, err);
    }
    if (st == MCS_OK) st = resolve_loads(b, m, err);
    if (st == MCS_OK) st = resolve_walls(b, m, err);
    if (st == MCS_OK) st = fe_restraints_create(b, m, err); /* may lower opts.dt_max */
    if (st == MCS_OK) st = fe_sliprings_create(b, m, err);  /* after the retractors */
    if (st == MCS_OK) st = fe_solid_finish(m, err); /* rigid-body constraints, wall checks */
    if (st == MCS_OK) {
        for (int n = 0; n < m->nnode; n++)
            for (int c = 0; c < 3; c++)
                if (m->node_fix[n] & (1u << c)) m->node_v0[3 * n + c] = m->node_vfix[3 * n + c];
        double dt = INFINITY;
        for (int ip = 0; ip < m->npart; ip++) {
            int e;
            dt = fmin(dt, fe_part_dt(m, ip, m->node_x0, &e));
        }
        dt = fmin(dt, m->dt_discrete);
        m->dt_initial = o.dt_scale * dt;
        if (m->opts.dt_max > 0) m->dt_initial = fmin(m->dt_initial, m->opts.dt_max);
        m->bytes += sizeof(fe_part) * (size_t)m->npart + sizeof(fe_wall) * (size_t)m->nwall +
                    sizeof(fe_nodal_load) * (size_t)m->nnodal_load +
                    sizeof(fe_load_curve) * (size_t)m->nload +
                    sizeof(fe_pressure) * (size_t)m->npressure;
        st = fe_joints_build(b, m, err); /* penalties scaled to dt_initial */
        if (st == MCS_OK) st = fe_contact_model_build(b, m, err);
    }
    if (st == MCS_OK) {
        *out = m;
        return MCS_OK;
    }
    fe_model_destroy(&m);
    return st;
}

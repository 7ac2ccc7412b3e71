/* fe_builder: collects parts, nodes, elements, boundary conditions, loads and walls before
 * fe_model_create() validates and freezes them. Growable arrays live only here. */
#include "fe/fe_builder_impl.h"
#include "fe/fe_restraint.h"
#include "fe/fe_slipring.h"
#include "fe/fe_joint.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* grow *p (elements of sz bytes) to hold need; 0 on success */
static int grow(void **p, int *cap, int need, size_t sz)
{
    if (need <= *cap) return 0;
    int nc = *cap ? *cap : 16;
    while (nc < need) nc *= 2;
    void *q = realloc(*p, (size_t)nc * sz);
    if (!q) return -1;
    *p = q;
    *cap = nc;
    return 0;
}

static const int kind_nnode[FE_NKIND] = {8, 4, 2, 10};

int fe_kind_nnode(int kind) { return kind_nnode[kind]; }

int fe_section_kind(fe_section_type t)
{
    if (t == FE_SECTION_MEMBRANE) return FE_KIND_SHELL; /* degenerate triangles (fe_membrane.c) */
    if (t == FE_SECTION_TET10) return FE_KIND_TET10;
    return t == FE_SECTION_SOLID ? FE_KIND_HEX : t == FE_SECTION_SHELL ? FE_KIND_SHELL : FE_KIND_TRUSS;
}

mcs_status fe_builder_create(fe_builder **out, mcs_error *err)
{
    *out = calloc(1, sizeof **out);
    if (!*out) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: cannot allocate the model builder");
    return MCS_OK;
}

void fe_builder_destroy(fe_builder **p)
{
    if (!p || !*p) return;
    fe_builder *b = *p;
    free(b->x);
    free(b->x_sel);
    free(b->xref);
    for (int k = 0; k < FE_NKIND; k++) {
        free(b->conn[k]);
        free(b->epart[k]);
    }
    free(b->part);
    free(b->shell_t);
    free(b->bc);
    free(b->fix);
    free(b->vel);
    free(b->load);
    fe_restraint_list_free(b);
    fe_slipring_list_free(b);
    fe_joint_list_free(b);
    free(b->spring);
    free(b->mass);
    for (int i = 0; i < b->ncontact; i++) fe_contact_desc_free(&b->contact[i]);
    for (int i = 0; i < b->nfacets; i++) {
        free((void *)b->facets[i].vert);
        free((void *)b->facets[i].tri);
    }
    free(b);
    *p = NULL;
}

int fe_builder_nnode(const fe_builder *b) { return b->nnode; }

int fe_builder_find_part(const fe_builder *b, const char *name)
{
    for (int i = 0; i < b->npart; i++)
        if (strcmp(b->part[i].name, name) == 0) return i;
    return -1;
}

int fe_builder_part_rigid(const fe_builder *b, int part)
{
    return part >= 0 && part < b->npart && b->part[part].material.model == FE_MAT_RIGID;
}

fe_part_desc fe_part_desc_default(void)
{
    fe_part_desc d;
    memset(&d, 0, sizeof d);
    d.section.integration_points = 5;
    d.section.hourglass = FE_HG_STIFFNESS;
    d.mesh.axis = 2;
    return d;
}

mcs_status fe_builder_add_node(fe_builder *b, const double x[3], int *index, mcs_error *err)
{
    if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: node %d: coordinates are not finite", b->nnode);
    if (grow((void **)&b->x, &b->cap_node, b->nnode + 1, 3 * sizeof(double)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding node %d", b->nnode);
    memcpy(b->x + 3 * b->nnode, x, 3 * sizeof(double));
    if (b->xref) { /* a part has a scaled initial mesh (fe_imm.c): a new node is its own ref */
        mcs_status st = fe_builder_imm_grow(b, err);
        if (st) return st;
        memcpy(b->xref + 3 * b->nnode, x, 3 * sizeof(double));
    }
    if (index) *index = b->nnode;
    b->nnode++;
    return MCS_OK;
}

mcs_status fe_builder_add_elem(fe_builder *b, int part, const int *nodes, mcs_error *err)
{
    if (part < 0 || part >= b->npart)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: element of unknown part index %d", part);
    int k = fe_section_kind(b->part[part].section.type), nn = kind_nnode[k];
    if (b->part[part].section.type == FE_SECTION_MEMBRANE && nodes[2] != nodes[3]) {
        /* a membrane quad becomes two triangles along its 1-3 diagonal */
        const int t1[4] = {nodes[0], nodes[1], nodes[2], nodes[2]};
        const int t2[4] = {nodes[0], nodes[2], nodes[3], nodes[3]};
        mcs_status st = fe_builder_add_elem(b, part, t1, err);
        return st != MCS_OK ? st : fe_builder_add_elem(b, part, t2, err);
    }
    int hx[8];
    for (int i = 0; i < nn; i++) {
        if (nodes[i] < 0 || nodes[i] >= b->nnode)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: part '%s': element %d: node %d does not exist (%d nodes)",
                           b->part[part].name, b->nelem[k], nodes[i], b->nnode);
    }
    if (k == FE_KIND_HEX) { /* tetrahedra and pentahedra: degenerate hexahedra (fe_tet.c) */
        if (!fe_solid_from_lsdyna(nodes, hx))
            return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                           "fe: part '%s': element %d: repeated nodes that make neither a "
                           "tetrahedron (n1 n2 n3 n4 n4 n4 n4 n4) nor a pentahedron (n1 n2 n3 "
                           "n4 n5 n5 n6 n6)",
                           b->part[part].name, b->nelem[k]);
        nodes = hx;
    }
    for (int i = 0; i < nn && k != FE_KIND_HEX; i++) {
        for (int j = 0; j < i; j++)
            if (nodes[j] == nodes[i] && !(k == FE_KIND_SHELL && i == 3 && j == 2))
                return MCS_ERR(err, MCS_ERR_RANGE,
                               "fe: part '%s': element %d: node %d appears twice",
                               b->part[part].name, b->nelem[k], nodes[i]);
    }
    if (grow((void **)&b->conn[k], &b->cap_conn[k], b->nelem[k] + 1, (size_t)nn * sizeof(int)) ||
        grow((void **)&b->epart[k], &b->cap_epart[k], b->nelem[k] + 1, sizeof(int)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding an element");
    memcpy(b->conn[k] + (size_t)nn * b->nelem[k], nodes, (size_t)nn * sizeof(int));
    b->epart[k][b->nelem[k]++] = part;
    return MCS_OK;
}

static mcs_status check_material(const fe_part_desc *d, mcs_error *err)
{
    const fe_material_desc *m = &d->material;
    const char *n = d->name;
    if (!(m->density > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': material.density must be > 0", n);
    if (m->model == FE_MAT_NULL && m->youngs_modulus == 0) {
        /* a null part carries no stress: its modulus only makes contact stiffness */
    } else if (!(m->youngs_modulus > 0)) {
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': material.youngs_modulus must be > 0", n);
    }
    if (!(m->poisson > -1 && m->poisson < 0.5))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': material.poisson must be in (-1, 0.5), got %g", n,
                       m->poisson);
    if (m->model != FE_MAT_ELASTIC && m->model != FE_MAT_ELASTIC_PLASTIC &&
        m->model != FE_MAT_FABRIC && m->model != FE_MAT_FOAM && m->model != FE_MAT_RIGID &&
        m->model != FE_MAT_NULL)
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED, "fe: part '%s': material.model not built yet", n);
    if (m->failure_strain != 0 && m->model != FE_MAT_ELASTIC_PLASTIC)
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                       "fe: part '%s': material.failure_strain (element erosion) needs material "
                       "model elastic_plastic",
                       n);
    if ((m->model == FE_MAT_FABRIC) != (d->section.type == FE_SECTION_MEMBRANE))
        return MCS_ERR(err, MCS_ERR_TYPE,
                       "fe: part '%s': a membrane section takes material.model fabric, and "
                       "fabric is for membrane sections only",
                       n);
    if (m->model == FE_MAT_FABRIC) return fe_fabric_check(d, err);
    if (m->model == FE_MAT_FOAM) return fe_foam_check(d, err);
    if (m->model == FE_MAT_RIGID) {
        const unsigned rot = m->rigid_fix & FE_DOF_ROT;
        if ((m->rigid_fix & ~(unsigned)FE_DOF_ALL) || (rot && rot != FE_DOF_ROT))
            return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                           "fe: part '%s': a rigid body's rotations are held all together or "
                           "not at all",
                           n);
        return MCS_OK;
    }
    if (m->model == FE_MAT_NULL) return MCS_OK;
    if (m->model == FE_MAT_ELASTIC) return MCS_OK;
    if (m->nhardening < 0 || m->nhardening > FE_CURVE_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': material.hardening: 0..%d points", n,
                       FE_CURVE_MAX);
    if (m->nhardening == 0 && !(m->yield_stress > 0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': material.yield_stress must be > 0 (or give hardening)", n);
    for (int i = 0; i < m->nhardening; i++) {
        double e = m->hardening[i][0], s = m->hardening[i][1];
        if (!isfinite(e) || !(s > 0) || !isfinite(s))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: part '%s': material.hardening[%d]: need a finite strain and a "
                           "stress > 0",
                           n, i);
        if (i == 0 && e != 0)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: part '%s': material.hardening must start at plastic strain 0", n);
        if (i > 0 && !(e > m->hardening[i - 1][0]))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: part '%s': material.hardening[%d]: plastic strain must increase",
                           n, i);
    }
    if (m->cowper_symonds_c < 0 || (m->cowper_symonds_c > 0 && !(m->cowper_symonds_p > 0)))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': material.cowper_symonds: need c >= 0 and p > 0", n);
    if (!(m->failure_strain >= 0) || !isfinite(m->failure_strain))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': material.failure_strain must be >= 0",
                       n);
    const fe_section_desc *sc = &d->section;
    if (m->failure_strain > 0 &&
        !(sc->type == FE_SECTION_SHELL ||
          (sc->type == FE_SECTION_SOLID && sc->formulation == FE_HEX_ONE_POINT)))
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                       "fe: part '%s': element erosion (material.failure_strain) is built for "
                       "one-point hexahedra and shells only",
                       n);
    return MCS_OK;
}

static mcs_status check_section(const fe_part_desc *d, mcs_error *err)
{
    const fe_section_desc *s = &d->section;
    const char *n = d->name;
    if (s->type == FE_SECTION_SHELL) {
        if (!(s->thickness > 0))
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': section.thickness must be > 0", n);
        if (s->integration_points < 1 || s->integration_points > FE_NIP_MAX)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: part '%s': section.integration_points must be 1..%d, got %d", n,
                           FE_NIP_MAX, s->integration_points);
    } else if (s->type == FE_SECTION_MEMBRANE) {
        if (!(s->thickness > 0))
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': section.thickness must be > 0", n);
    } else if (s->type == FE_SECTION_TRUSS) {
        if (!(s->area > 0))
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': section.area must be > 0", n);
    } else if (s->type != FE_SECTION_SOLID && s->type != FE_SECTION_TET10) {
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED, "fe: part '%s': section.type not built yet", n);
    }
    if (!(s->hourglass_coefficient >= 0) || s->shear_factor < 0)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': section.hourglass_coefficient and shear_factor must be >= 0",
                       n);
    if (s->formulation != FE_HEX_ONE_POINT && (s->formulation != FE_HEX_FULL || s->type != FE_SECTION_SOLID))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': section.formulation full is for solid sections only", n);
    return MCS_OK;
}

mcs_status fe_builder_add_part(fe_builder *b, const fe_part_desc *d, int *index, mcs_error *err)
{
    if (!d->name[0] || memchr(d->name, 0, FE_NAME_MAX) == NULL)
        return MCS_ERR(err, MCS_ERR_KEY, "fe: a part needs a name (< %d characters)", FE_NAME_MAX);
    if (fe_builder_find_part(b, d->name) >= 0)
        return MCS_ERR(err, MCS_ERR_KEY, "fe: part '%s' is defined twice", d->name);
    mcs_status st = check_material(d, err);
    if (st == MCS_OK) st = check_section(d, err);
    for (int i = 0; st == MCS_OK && i < 3; i++)
        if (!isfinite(d->initial_velocity[i]))
            st = MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': initial_velocity is not finite",
                         d->name);
    if (st != MCS_OK) return st;
    if (grow((void **)&b->part, &b->cap_part, b->npart + 1, sizeof *b->part))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding part '%s'", d->name);
    b->part[b->npart] = *d;
    if (d->section.type == FE_SECTION_MEMBRANE) b->part[b->npart].section.integration_points = 1;
    int ip = b->npart++;
    if (index) *index = ip;
    if (d->mesh.generate != FE_MESH_NONE) {
        st = fe_mesh_generate(b, ip, &d->mesh, err);
        if (st != MCS_OK) b->npart--; /* its nodes stay but belong to nothing: harmless */
    }
    return st;
}

mcs_status fe_builder_add_boundary(fe_builder *b, const fe_boundary_desc *d, mcs_error *err)
{
    if ((d->fix & ~(unsigned)FE_DOF_ALL) || !d->fix)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: boundary on part '%s': fix must name dofs",
                       d->part);
    if (grow((void **)&b->bc, &b->cap_bc, b->nbc + 1, sizeof *b->bc))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    b->bc[b->nbc++] = *d;
    return MCS_OK;
}

mcs_status fe_builder_fix_node(fe_builder *b, int node, unsigned fix, const double vel[3],
                               mcs_error *err)
{
    if (node < 0 || node >= b->nnode || (fix & ~(unsigned)FE_DOF_ALL))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: fix node %d: no such node or bad dof mask", node);
    if (grow((void **)&b->fix, &b->cap_fix, b->nfix + 1, sizeof *b->fix))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    fe_node_fix *f = &b->fix[b->nfix++];
    f->node = node;
    f->fix = fix;
    for (int i = 0; i < 3; i++) f->v[i] = vel ? vel[i] : 0;
    return MCS_OK;
}

mcs_status fe_builder_node_velocity(fe_builder *b, int node, const double v[3], mcs_error *err)
{
    if (node < 0 || node >= b->nnode || !isfinite(v[0]) || !isfinite(v[1]) || !isfinite(v[2]))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: node %d: no such node or velocity not finite",
                       node);
    if (grow((void **)&b->vel, &b->cap_vel, b->nvel + 1, sizeof *b->vel))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    fe_node_fix *f = &b->vel[b->nvel++];
    f->node = node;
    f->fix = 0;
    for (int i = 0; i < 3; i++) f->v[i] = v[i];
    return MCS_OK;
}

static mcs_status check_curve(int n, const double (*c)[2], const char *what, mcs_error *err)
{
    if (n < 0 || n > FE_CURVE_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: %s: curve needs 0..%d points", what, FE_CURVE_MAX);
    for (int i = 0; i < n; i++) {
        if (!isfinite(c[i][0]) || !isfinite(c[i][1]) || (i > 0 && !(c[i][0] > c[i - 1][0])))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: %s: curve point %d: times must be finite and increasing", what, i);
    }
    return MCS_OK;
}

static mcs_status push_load(fe_builder *b, int node, const fe_load_desc *d, mcs_error *err)
{
    mcs_status st = check_curve(d->ncurve, d->curve, node < 0 ? d->part : "nodal load", err);
    if (st != MCS_OK) return st;
    for (int i = 0; i < 3; i++)
        if (!isfinite(d->force[i]))
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: load: force is not finite");
    if (grow((void **)&b->load, &b->cap_load, b->nload + 1, sizeof *b->load))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    b->load[b->nload].node = node;
    b->load[b->nload++].d = *d;
    return MCS_OK;
}

mcs_status fe_builder_add_load(fe_builder *b, const fe_load_desc *d, mcs_error *err)
{
    return push_load(b, -1, d, err);
}

mcs_status fe_builder_add_nodal_load(fe_builder *b, int node, const double force[3], int ncurve,
                                     const double (*curve)[2], mcs_error *err)
{
    if (node < 0 || node >= b->nnode)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: nodal load on node %d: no such node", node);
    if (ncurve < 0 || ncurve > FE_CURVE_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: nodal load: curve needs 0..%d points",
                       FE_CURVE_MAX);
    fe_load_desc d;
    memset(&d, 0, sizeof d);
    memcpy(d.force, force, sizeof d.force);
    d.ncurve = ncurve;
    if (ncurve) memcpy(d.curve, curve, (size_t)ncurve * sizeof d.curve[0]);
    return push_load(b, node, &d, err);
}

mcs_status fe_builder_add_pressure(fe_builder *b, const int nodes[4], double p, int ncurve,
                                   const double (*curve)[2], mcs_error *err)
{
    for (int i = 0; i < 4; i++)
        if (nodes[i] < 0 || nodes[i] >= b->nnode)
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: pressure on node %d: no such node",
                           nodes[i]);
    if (nodes[0] == nodes[1] || nodes[1] == nodes[2] || nodes[0] == nodes[2])
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: pressure segment: nodes 1, 2, 3 must differ");
    if (ncurve < 0 || ncurve > FE_CURVE_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: pressure: curve needs 0..%d points", FE_CURVE_MAX);
    fe_load_desc d;
    memset(&d, 0, sizeof d);
    d.force[0] = p;
    d.ncurve = ncurve;
    if (ncurve) memcpy(d.curve, curve, (size_t)ncurve * sizeof d.curve[0]);
    mcs_status st = push_load(b, -2, &d, err);
    if (!st) memcpy(b->load[b->nload - 1].seg, nodes, sizeof b->load[0].seg);
    return st;
}

mcs_status fe_builder_add_wall(fe_builder *b, const fe_wall_desc *d, mcs_error *err)
{
    if (b->nwall >= FE_WALL_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: at most %d rigid walls", FE_WALL_MAX);
    double nn = sqrt(d->normal[0] * d->normal[0] + d->normal[1] * d->normal[1] +
                     d->normal[2] * d->normal[2]);
    if (!(nn > 0) || !isfinite(nn))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: rigid wall '%s': normal must be a nonzero vector",
                       d->name);
    if (d->nparts < 0 || d->nparts > 8 || d->penalty_scale < 0)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: rigid wall '%s': 0..8 parts, penalty_scale >= 0",
                       d->name);
    mcs_status st = fe_wall_check(d, err); /* a wall with mass (fe_wall.c) */
    if (st) return st;
    for (int i = 0; i < b->nwall; i++)
        if (strcmp(b->wall[i].name, d->name) == 0)
            return MCS_ERR(err, MCS_ERR_KEY, "fe: rigid wall '%s' is defined twice", d->name);
    b->wall[b->nwall++] = *d;
    return MCS_OK;
}

/* mark the nodes used by a part's elements */
void fe_builder_part_nodes(const fe_builder *b, int part, unsigned char *mark)
{
    memset(mark, 0, (size_t)b->nnode);
    for (int k = 0; k < FE_NKIND; k++)
        for (int e = 0; e < b->nelem[k]; e++)
            if (b->epart[k][e] == part)
                for (int i = 0; i < kind_nnode[k]; i++) mark[b->conn[k][kind_nnode[k] * e + i]] = 1;
}

int fe_builder_nearest(const fe_builder *b, int part, const double p[3])
{
    if (part < 0 || part >= b->npart || b->nnode == 0) return -1;
    unsigned char *mark = malloc((size_t)b->nnode);
    if (!mark) return -1;
    fe_builder_part_nodes(b, part, mark);
    int best = -1;
    double dbest = INFINITY;
    for (int n = 0; n < b->nnode; n++) {
        if (!mark[n]) continue;
        double d2 = 0;
        for (int i = 0; i < 3; i++) d2 += (b->x[3 * n + i] - p[i]) * (b->x[3 * n + i] - p[i]);
        if (d2 < dbest) dbest = d2, best = n;
    }
    free(mark);
    return best;
}

int fe_builder_select(const fe_builder *b, int part, fe_where where, int *idx, int cap)
{
    if (part < 0 || part >= b->npart || b->nnode == 0) return 0;
    unsigned char *mark = malloc((size_t)b->nnode);
    if (!mark) return -1;
    fe_builder_part_nodes(b, part, mark);
    const double *x = b->x_sel ? b->x_sel : b->x; /* before a placement moved the part */
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int n = 0; n < b->nnode; n++)
        if (mark[n])
            for (int i = 0; i < 3; i++) {
                lo[i] = fmin(lo[i], x[3 * n + i]);
                hi[i] = fmax(hi[i], x[3 * n + i]);
            }
    double span = 0;
    for (int i = 0; i < 3; i++) span = fmax(span, hi[i] - lo[i]);
    double tol = 1e-6 * span;
    int axis = (where - 1) / 2, ismax = (where - 1) % 2, cnt = 0;
    for (int n = 0; n < b->nnode; n++) {
        if (!mark[n]) continue;
        int take = where == FE_WHERE_ALL;
        if (!take) {
            double c = x[3 * n + axis];
            take = ismax ? c >= hi[axis] - tol : c <= lo[axis] + tol;
        }
        if (take) {
            if (cnt < cap) idx[cnt] = n;
            cnt++;
        }
    }
    free(mark);
    return cnt;
}

mcs_status fe_builder_add_shell(fe_builder *b, int part, const int nodes[4], double thickness,
                                mcs_error *err)
{
    if (!(thickness > 0) || !isfinite(thickness))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: a shell's own thickness must be > 0, got %g",
                       thickness);
    if (part < 0 || part >= b->npart ||
        fe_section_kind(b->part[part].section.type) != FE_KIND_SHELL)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: a shell of part index %d, which is no shell part",
                       part);
    int e0 = b->nelem[FE_KIND_SHELL];
    mcs_status st = fe_builder_add_elem(b, part, nodes, err);
    if (st) return st;
    int e1 = b->nelem[FE_KIND_SHELL]; /* a membrane quad made two triangles */
    if (grow((void **)&b->shell_t, &b->cap_shell_t, e1, sizeof(double)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory adding a shell");
    for (int e = b->nshell_t; e < e0; e++) b->shell_t[e] = 0; /* the section's */
    for (int e = e0; e < e1; e++) b->shell_t[e] = thickness;
    b->nshell_t = e1;
    return MCS_OK;
}

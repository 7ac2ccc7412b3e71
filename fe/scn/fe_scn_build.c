/* fe_scn_build.c: scenario `fe:` block -> fe_model (see fe_scn_build.h). The kernel's descriptors
 * carry the scenario's key names (docs/fe.md), so this file copies keys, converts the few that
 * differ (axis names, tangent_modulus -> a hardening table) and locates every kernel error at the
 * scenario node it came from. */
#include "fe/fe_scn_build.h"
#include "fe/scn/fe_scn_node.h"
#include "fe/scn/fe_scn_contact.h"
#include "fe/scn/fe_scn_joint.h"
#include "fe/scn/fe_scn_solid.h"
#include "fe/fe_scn_restraints.h"
#include "fe/scn/fe_scn_slipring.h"
#include "fe/scn/fe_scn_deck.h"
#include "fe/fe_scn_keyword.h"
#include "fe/scn/fe_scn_from.h"
#include "fe/scn/fe_scn_place.h"
#include "fe/scn/fe_scn_pad.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FE_SCN_OUTPUT_RATE_DEFAULT 10e3 /* [Hz], as stage 1 */

static mcs_status unsupported(const mcs_node *n, mcs_error *err, const char *what)
{
    return mcs_node_error(n, err, MCS_ERR_UNSUPPORTED, "%s not supported yet", what);
}

static mcs_status read_mesh(const mcs_node *mesh, fe_mesh_desc *d, mcs_error *err)
{
    const char *gen = mcs_node_str(fe_scn_get(mesh, "generate"));
    if (!gen) return unsupported(mesh, err, "mesh from a keyword file");
    mcs_status st = MCS_OK;
    if (strcmp(gen, "box") == 0) {
        d->generate = FE_MESH_BOX;
        st = mcs_node_vec3(fe_scn_get(mesh, "size"), d->size, err);
        for (int i = 0; i < 3 && !st; i++)
            d->divisions[i] = (int)mcs_node_num(mcs_node_at(fe_scn_get(mesh, "divisions"), i));
        if (!st && fe_scn_given(mesh, "origin"))
            st = mcs_node_vec3(fe_scn_get(mesh, "origin"), d->origin, err);
    } else if (strcmp(gen, "plate") == 0) {
        d->generate = FE_MESH_PLATE;
        st = mcs_node_vec(fe_scn_get(mesh, "size"), d->size, 2, err);
        d->axis = fe_scn_axis_of(mcs_node_str(fe_scn_get(mesh, "axis")), 2);
        for (int i = 0; i < 2 && !st; i++) {
            if (fe_scn_given(mesh, "divisions"))
                d->divisions[i] = (int)mcs_node_num(mcs_node_at(fe_scn_get(mesh, "divisions"), i));
            else
                d->divisions[i] = (int)fmax(
                    1, floor(d->size[i] / mcs_node_num(fe_scn_get(mesh, "element_size")) + 0.5));
        }
        if (!st && fe_scn_given(mesh, "origin"))
            st = mcs_node_vec3(fe_scn_get(mesh, "origin"), d->origin, err);
    } else if (strcmp(gen, "line") == 0) {
        d->generate = FE_MESH_LINE;
        st = mcs_node_vec3(fe_scn_get(mesh, "origin"), d->origin, err);
        if (!st) st = mcs_node_vec3(fe_scn_get(mesh, "end"), d->end, err);
        d->divisions[0] = (int)mcs_node_num(fe_scn_get(mesh, "divisions"));
    } else if (strcmp(gen, "square_tube") == 0) {
        d->generate = FE_MESH_SQUARE_TUBE;
        d->side = mcs_node_num(fe_scn_get(mesh, "side"));
    } else if (strcmp(gen, "circular_tube") == 0) {
        d->generate = FE_MESH_CIRCULAR_TUBE;
        d->diameter = mcs_node_num(fe_scn_get(mesh, "diameter"));
    } else if (strcmp(gen, "cylinder_shell") == 0 || strcmp(gen, "sphere_shell") == 0 ||
               strcmp(gen, "flat_bag") == 0) {
        return fe_scn_read_shell_mesh(mesh, gen, d, err); /* fe_scn_restraints.c */
    } else {
        char what[96];
        snprintf(what, sizeof what, "mesh generator '%s'", gen);
        return unsupported(fe_scn_get(mesh, "generate"), err, what);
    }
    if (d->generate == FE_MESH_SQUARE_TUBE || d->generate == FE_MESH_CIRCULAR_TUBE) {
        d->length = mcs_node_num(fe_scn_get(mesh, "length"));
        d->element_size = mcs_node_num(fe_scn_get(mesh, "element_size"));
        d->axis = fe_scn_axis_of(mcs_node_str(fe_scn_get(mesh, "axis")), 2);
    }
    return st;
}

static mcs_status read_section(const mcs_node *sec, fe_section_desc *d, mcs_error *err)
{
    const char *type = mcs_node_str(fe_scn_get(sec, "type"));
    const char *hg = mcs_node_str(fe_scn_get(sec, "hourglass"));
    if (hg) d->hourglass = strcmp(hg, "stiffness") == 0 ? FE_HG_STIFFNESS : FE_HG_VISCOUS;
    d->hourglass_coefficient = mcs_node_num_or(sec, "hourglass_coefficient", 0);
    if (type && strcmp(type, "shell") == 0) {
        d->type = FE_SECTION_SHELL;
        d->thickness = mcs_node_num(fe_scn_get(sec, "thickness"));
        d->integration_points = (int)mcs_node_num_or(sec, "integration_points", 5);
        d->shear_factor = mcs_node_num_or(sec, "shear_factor", 0);
        return MCS_OK;
    }
    if (type && strcmp(type, "solid") == 0) {
        d->type = FE_SECTION_SOLID;
        const char *form = mcs_node_str(fe_scn_get(sec, "formulation"));
        if (form && strcmp(form, "full") == 0) d->formulation = FE_HEX_FULL;
        return MCS_OK;
    }
    if (type && strcmp(type, "membrane") == 0) {
        d->type = FE_SECTION_MEMBRANE;
        d->thickness = mcs_node_num(fe_scn_get(sec, "thickness"));
        return MCS_OK;
    }
    if (type && strcmp(type, "truss") == 0) {
        d->type = FE_SECTION_TRUSS;
        d->area = mcs_node_num(fe_scn_get(sec, "area"));
        d->tension_only = mcs_node_bool(fe_scn_get(sec, "tension_only"), 0);
        return MCS_OK;
    }
    char what[96];
    snprintf(what, sizeof what, "section type '%s'", type ? type : "?");
    return unsupported(fe_scn_get(sec, "type"), err, what);
}

static mcs_status read_material(const mcs_node *mat, fe_material_desc *d, mcs_error *err)
{
    const char *model = mcs_node_str(fe_scn_get(mat, "model"));
    if (model && (strcmp(model, "foam") == 0 || strcmp(model, "rigid") == 0))
        return fe_scn_solid_material(mat, d, err);
    if (model && strcmp(model, "nonstructural") == 0) { /* mass and contact only (*MAT_NULL) */
        d->model = FE_MAT_NULL;
        d->density = mcs_node_num(fe_scn_get(mat, "density"));
        return MCS_OK;
    }
    int plastic = model && strcmp(model, "elastic_plastic") == 0;
    if (model && strcmp(model, "fabric") == 0) return fe_scn_read_fabric(mat, d, err);
    if (!plastic && !(model && strcmp(model, "elastic") == 0)) {
        char what[96];
        snprintf(what, sizeof what, "material model '%s'", model ? model : "?");
        return unsupported(fe_scn_get(mat, "model"), err, what);
    }
    d->model = plastic ? FE_MAT_ELASTIC_PLASTIC : FE_MAT_ELASTIC;
    d->density = mcs_node_num(fe_scn_get(mat, "density"));
    d->youngs_modulus = mcs_node_num(fe_scn_get(mat, "youngs_modulus"));
    d->poisson = mcs_node_num(fe_scn_get(mat, "poisson"));
    if (!plastic) return MCS_OK;
    d->failure_strain = mcs_node_num_or(mat, "failure_strain", 0); /* element erosion */
    d->yield_stress = mcs_node_num(fe_scn_get(mat, "yield_stress"));
    d->cowper_symonds_c = mcs_node_num_or(mat, "cowper_symonds_c", 0);
    d->cowper_symonds_p = mcs_node_num_or(mat, "cowper_symonds_p", 0);
    const mcs_node *h = fe_scn_get(mat, "hardening");
    if (fe_scn_given(mat, "hardening")) {
        int n = mcs_node_curve_len(h), k = 0;
        double x[FE_CURVE_MAX], y[FE_CURVE_MAX];
        if (n > FE_CURVE_MAX - 1)
            return mcs_node_error(h, err, MCS_ERR_RANGE, "at most %d points, got %d",
                                  FE_CURVE_MAX - 1, n);
        mcs_status st = mcs_node_curve(h, x, y, FE_CURVE_MAX, err);
        if (st) return st;
        if (x[0] > 0) { /* the table starts at zero plastic strain with the yield stress */
            d->hardening[0][0] = 0;
            d->hardening[0][1] = d->yield_stress;
            k = 1;
        }
        for (int i = 0; i < n; i++, k++) {
            d->hardening[k][0] = x[i];
            d->hardening[k][1] = y[i];
        }
        d->nhardening = k;
    } else if (fe_scn_given(mat, "tangent_modulus")) {
        /* bilinear: tangent modulus Et of the stress-strain curve -> plastic modulus
         * H = E Et / (E - Et) (the slope of stress vs. plastic strain) */
        double E = d->youngs_modulus, Et = mcs_node_num(fe_scn_get(mat, "tangent_modulus"));
        if (!(Et < E))
            return mcs_node_error(fe_scn_get(mat, "tangent_modulus"), err, MCS_ERR_RANGE,
                                  "must be below youngs_modulus %g Pa", E);
        d->nhardening = 2;
        d->hardening[0][0] = 0;
        d->hardening[0][1] = d->yield_stress;
        d->hardening[1][0] = 1;
        d->hardening[1][1] = d->yield_stress + E * Et / (E - Et);
    }
    return MCS_OK;
}

/* mesh.initial: {scale, about}: the part starts on a scaled copy of its mesh, which stays its
 * reference (the initial metric method, fe_imm.c) */
static mcs_status initial_mesh(fe_builder *b, const mcs_node *mesh, const char *name,
                               mcs_error *err)
{
    const mcs_node *in = fe_scn_get(mesh, "initial");
    if (!fe_scn_given(mesh, "initial")) return MCS_OK;
    double scale[3], about[3];
    mcs_status st = mcs_node_vec3(fe_scn_get(in, "scale"), scale, err);
    int has_about = fe_scn_given(in, "about");
    if (!st && has_about) st = mcs_node_vec3(fe_scn_get(in, "about"), about, err);
    if (st) return st;
    mcs_error kerr = {0};
    st = fe_builder_imm(b, fe_builder_find_part(b, name), scale, has_about ? about : NULL, &kerr);
    return st ? fe_scn_relocate(st, in, &kerr, err) : MCS_OK;
}

/* the material node of part p: its own, or material_from's (that part's own material) */
static const mcs_node *material_of(const mcs_node *parts, const mcs_node *p, mcs_error *err)
{
    if (!fe_scn_given(p, "material_from")) return fe_scn_get(p, "material");
    const mcs_node *from = fe_scn_get(p, "material_from");
    for (int i = 0; i < mcs_node_len(parts); i++) {
        const mcs_node *q = mcs_node_at(parts, i);
        if (strcmp(mcs_node_str(fe_scn_get(q, "name")), mcs_node_str(from)) != 0) continue;
        if (fe_scn_given(q, "material")) return fe_scn_get(q, "material");
        break;
    }
    mcs_node_error(from, err, MCS_ERR_KEY, "part '%s' has no material: of its own to share",
                   mcs_node_str(from));
    return NULL;
}

static struct {
    char name[32];
    fe_scn_generator fn;
} generator[4];

void fe_scn_set_generator(const char *name, fe_scn_generator fn)
{
    for (int i = 0; i < 4; i++)
        if (!generator[i].fn || strcmp(generator[i].name, name) == 0) {
            snprintf(generator[i].name, sizeof generator[i].name, "%s", name);
            generator[i].fn = fn;
            return;
        }
}

/* the registered generator of part p's mesh, NULL none */
static fe_scn_generator generator_of(const mcs_node *p)
{
    const char *gen = mcs_node_str(fe_scn_get(fe_scn_get(p, "mesh"), "generate"));
    for (int i = 0; gen && i < 4 && generator[i].fn; i++)
        if (strcmp(generator[i].name, gen) == 0) return generator[i].fn;
    return NULL;
}

static mcs_status add_parts_(fe_builder *b, const mcs_node *root, const mcs_node *parts,
                             fe_scn_kw_cache **kc, mcs_error *err)
{
    for (int i = 0; i < mcs_node_len(parts); i++) {
        const mcs_node *p = mcs_node_at(parts, i);
        fe_scn_generator gen = generator_of(p);
        if (gen) { /* several parts from one entry (a motorcycle: stage3_fe/s3_moto.h) */
            mcs_status st = gen(b, root, p, err);
            if (st) return st;
            continue;
        }
        fe_part_desc d = fe_part_desc_default();
        snprintf(d.name, sizeof d.name, "%s", mcs_node_str(fe_scn_get(p, "name")));
        if (strlen(mcs_node_str(fe_scn_get(p, "name"))) >= sizeof d.name)
            return mcs_node_error(fe_scn_get(p, "name"), err, MCS_ERR_RANGE,
                                  "longer than %d characters", FE_NAME_MAX - 1);
        /* a keyword mesh (fe_scn_keyword.c) may take its section and material from the deck */
        int kw = fe_scn_given(fe_scn_get(p, "mesh"), "keyword");
        int pad = fe_scn_pad_is(fe_scn_get(p, "mesh")); /* on a body's surface: fe_scn_pad.c */
        int from = fe_scn_from_is(fe_scn_get(p, "mesh")); /* a results file: fe_scn_from.c */
        mcs_status st = kw || pad || from ? MCS_OK : read_mesh(fe_scn_get(p, "mesh"), &d.mesh, err);
        if (!st && (!kw || fe_scn_given(p, "section")))
            st = read_section(fe_scn_get(p, "section"), &d.section, err);
        if (!st && (!kw || fe_scn_given(p, "material") || fe_scn_given(p, "material_from"))) {
            const mcs_node *mat = material_of(parts, p, err);
            st = mat ? read_material(mat, &d.material, err) : MCS_ERR_KEY;
        }
        if (!st && fe_scn_given(p, "initial_velocity"))
            st = mcs_node_vec3(fe_scn_get(p, "initial_velocity"), d.initial_velocity, err);
        if (!st && kw) st = fe_scn_kw_add_part(kc, b, p, &d, err);
        if (!st && pad) st = fe_scn_pad_add(b, root, fe_scn_get(p, "mesh"), &d, err);
        if (!st && from) st = fe_scn_from_add_part(b, p, &d, err);
        if (st) return st;
        mcs_error kerr = {0};
        if (!kw && !pad && !from && (st = fe_builder_add_part(b, &d, NULL, &kerr)))
            return fe_scn_relocate(st, p, &kerr, err);
        st = initial_mesh(b, fe_scn_get(p, "mesh"), d.name, err);
        if (st) return st;
    }
    return MCS_OK;
}

static mcs_status add_parts(fe_builder *b, const mcs_node *root, const mcs_node *parts,
                            mcs_error *err)
{
    fe_scn_kw_cache *kc = NULL;
    mcs_status st = add_parts_(b, root, parts, &kc, err);
    fe_scn_kw_cache_free(&kc);
    return st;
}

static unsigned fix_mask(const char *s)
{
    static const struct { const char *name; unsigned mask; } tab[] = {
        {"all", FE_DOF_ALL}, {"translations", FE_DOF_TRANS}, {"rotations", FE_DOF_ROT},
        {"x", FE_DOF_X}, {"y", FE_DOF_Y}, {"z", FE_DOF_Z},
        {"xy", FE_DOF_X | FE_DOF_Y}, {"yz", FE_DOF_Y | FE_DOF_Z}, {"xz", FE_DOF_X | FE_DOF_Z}};
    if (!s) return FE_DOF_ALL;
    for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++)
        if (strcmp(s, tab[i].name) == 0) return tab[i].mask;
    return FE_DOF_ALL;
}

static fe_where where_of(const char *s)
{
    static const char *names[] = {"all", "x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
    for (int i = 0; i < 7; i++)
        if (s && strcmp(s, names[i]) == 0) return (fe_where)i;
    return FE_WHERE_ALL;
}

/* the attach/slip-ring node carrying FE node `node` already, NULL none */
static const mcs_node *carried_by(const fe_problem *out, int node)
{
    for (int a = 0; a < out->natt; a++)
        if (out->att[a].node == node) return out->att[a].attach;
    return NULL;
}

/* a boundary holding a translation of a node a body carries (attach, slip ring): the two
 * prescribe the same node's motion differently */
static mcs_status boundary_on_attached(fe_builder *b, const mcs_node *c, const fe_boundary_desc *d,
                                       const fe_problem *out, mcs_error *err)
{
    int part = fe_builder_find_part(b, d->part);
    int n = (d->fix & FE_DOF_TRANS) && out->natt ? fe_builder_select(b, part, d->where, NULL, 0)
                                                 : 0;
    if (n <= 0) return MCS_OK;
    int *idx = malloc((size_t)n * sizeof *idx);
    if (!idx) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
    fe_builder_select(b, part, d->where, idx, n);
    const mcs_node *hit = NULL;
    for (int k = 0; k < n && !hit; k++)
        hit = carried_by(out, idx[k]);
    free(idx);
    if (!hit) return MCS_OK;
    const mcs_node *body = fe_scn_get(hit, "body");
    return mcs_node_error(fe_scn_get(c, "where"), err, MCS_ERR_KEY,
                          "holds translations of nodes of part '%s' that body '%s' carries (line "
                          "%d): a node is either held in the world or carried by a body",
                          d->part, mcs_node_str(body), mcs_node_line(body));
}

static mcs_status add_boundaries(fe_builder *b, const mcs_node *list, const fe_problem *out,
                                 mcs_error *err)
{
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *c = mcs_node_at(list, i);
        if (fe_scn_given(c, "tolerance"))
            return unsupported(fe_scn_get(c, "tolerance"), err, "boundary tolerance");
        fe_boundary_desc d = {.where = where_of(mcs_node_str(fe_scn_get(c, "where"))),
                              .fix = fix_mask(mcs_node_str(fe_scn_get(c, "fix")))};
        snprintf(d.part, sizeof d.part, "%s", mcs_node_str(fe_scn_get(c, "part")));
        mcs_status bs = boundary_on_attached(b, c, &d, out, err);
        if (bs) return bs;
        if (fe_scn_given(c, "velocity")) {
            mcs_status vs = mcs_node_vec3(fe_scn_get(c, "velocity"), d.velocity, err);
            if (vs) return vs;
        }
        mcs_error kerr = {0};
        mcs_status st = fe_builder_add_boundary(b, &d, &kerr);
        if (st) return fe_scn_relocate(st, c, &kerr, err);
    }
    return MCS_OK;
}

/* a node carried twice (a slip ring on an attached node, parts sharing nodes): its reaction
 * would load the bodies twice */
static mcs_status carried_twice(const mcs_node *key, const mcs_node *by, mcs_error *err)
{
    const mcs_node *body = fe_scn_get(by, "body");
    return mcs_node_error(key, err, MCS_ERR_KEY,
                          "would carry a node that body '%s' carries already (line %d): a node "
                          "moves with one body, once",
                          mcs_node_str(body), mcs_node_line(body));
}

/* fe.parts[].attach: the selected nodes get their translations fixed (stage 1 prescribes
 * their velocity, mb_couple.c) and are recorded in out->att */
/* nodes `where` selects of part: a bounding-box side or all (fe_builder_select), or those on
 * the attach body's surfaces (fe_scn_pad.c) */
static int attach_select(const fe_builder *b, const mcs_node *root, const mcs_node *a, int part,
                         int *idx, int cap)
{
    const char *w = mcs_node_str(fe_scn_get(a, "where"));
    if (w && strcmp(w, "surface") == 0)
        return fe_scn_surface_nodes(b, root, part, mcs_node_str(fe_scn_get(a, "body")), idx, cap);
    return part < 0 ? 0 : fe_builder_select(b, part, where_of(w), idx, cap);
}

static mcs_status add_attach(fe_builder *b, const mcs_node *root, const mcs_node *parts,
                             fe_problem *out, mcs_error *err)
{
    for (int i = 0; i < mcs_node_len(parts); i++) {
        const mcs_node *p = mcs_node_at(parts, i), *a = fe_scn_get(p, "attach");
        if (!fe_scn_given(p, "attach")) continue;
        int part = fe_builder_find_part(b, mcs_node_str(fe_scn_get(p, "name")));
        /* a rigid part's nodes move with its FE rigid body, which takes the prescribed velocity
         * of a fixed node but gives the coupling no reaction: the body would drag it for free */
        if (fe_builder_part_rigid(b, part))
            return mcs_node_error(a, err, MCS_ERR_UNSUPPORTED,
                                  "part '%s' is rigid: its reaction would not reach the body; "
                                  "give it a deformable material, or make it a surface of the body",
                                  mcs_node_str(fe_scn_get(p, "name")));
        int n = attach_select(b, root, a, part, NULL, 0);
        if (n <= 0)
            return mcs_node_error(fe_scn_get(a, "where"), err, MCS_ERR_KEY,
                                  "selects no node of part '%s'",
                                  mcs_node_str(fe_scn_get(p, "name")));
        fe_attach *na = realloc(out->att, (size_t)(out->natt + n) * sizeof *na);
        int *idx = malloc((size_t)n * sizeof *idx);
        if (na) out->att = na;
        if (!na || !idx) {
            free(idx);
            return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
        }
        attach_select(b, root, a, part, idx, n);
        const double v0[3] = {0, 0, 0};
        for (int k = 0; k < n; k++) {
            const mcs_node *by = carried_by(out, idx[k]);
            if (by) {
                free(idx);
                return carried_twice(fe_scn_get(a, "body"), by, err);
            }
            mcs_error kerr = {0};
            mcs_status st = fe_builder_fix_node(b, idx[k], FE_DOF_TRANS, v0, &kerr);
            if (st) {
                free(idx);
                return fe_scn_relocate(st, a, &kerr, err);
            }
            out->att[out->natt++] = (fe_attach){.node = idx[k], .attach = a};
        }
        free(idx);
    }
    return MCS_OK;
}

/* fe.sliprings[].body: the ring node (the part's node nearest to `point`, as the kernel picks
 * it) is carried by the body like an attached node; its reactions (the belt tensions on both
 * sides) load the body */
static mcs_status add_ring_bodies(fe_builder *b, const mcs_node *rings, fe_problem *out,
                                  mcs_error *err)
{
    for (int i = 0; i < mcs_node_len(rings); i++) {
        const mcs_node *r = mcs_node_at(rings, i);
        if (!fe_scn_given(r, "body")) continue;
        double p[3];
        mcs_status st = mcs_node_vec3(fe_scn_get(r, "point"), p, err);
        if (st) return st;
        int part = fe_builder_find_part(b, mcs_node_str(fe_scn_get(r, "part")));
        int node = fe_builder_nearest(b, part, p);
        if (node < 0)
            return mcs_node_error(fe_scn_get(r, "part"), err, MCS_ERR_KEY, "part has no node");
        const mcs_node *by = carried_by(out, node);
        if (by) return carried_twice(fe_scn_get(r, "body"), by, err);
        fe_attach *na = realloc(out->att, (size_t)(out->natt + 1) * sizeof *na);
        if (!na) return MCS_ERR(err, MCS_ERR_NOMEM, "fe: out of memory");
        out->att = na;
        const double v0[3] = {0, 0, 0};
        mcs_error kerr = {0};
        st = fe_builder_fix_node(b, node, FE_DOF_TRANS, v0, &kerr);
        if (st) return fe_scn_relocate(st, r, &kerr, err);
        out->att[out->natt++] = (fe_attach){.node = node, .attach = r};
    }
    return MCS_OK;
}

static mcs_status wall_motion(const mcs_node *mo, fe_wall_desc *d, mcs_error *err)
{
    const char *type = mcs_node_str(fe_scn_get(mo, "type"));
    fe_wall_motion *k = &d->motion[d->nmotion++];
    k->kind = strcmp(type, "velocity") == 0       ? FE_MOTION_VELOCITY
              : strcmp(type, "acceleration") == 0 ? FE_MOTION_ACCELERATION
                                                  : FE_MOTION_DISPLACEMENT;
    memcpy(k->direction, d->normal, sizeof k->direction);
    mcs_status st = fe_scn_given(mo, "direction")
                        ? mcs_node_vec3(fe_scn_get(mo, "direction"), k->direction, err)
                        : MCS_OK;
    const mcs_node *c = fe_scn_get(mo, "curve");
    int n = mcs_node_curve_len(c);
    if (!st && n > FE_CURVE_MAX)
        return mcs_node_error(c, err, MCS_ERR_RANGE, "at most %d points, got %d", FE_CURVE_MAX, n);
    double x[FE_CURVE_MAX], y[FE_CURVE_MAX];
    if (!st) st = mcs_node_curve(c, x, y, FE_CURVE_MAX, err);
    for (int i = 0; i < n && !st; i++) k->curve[i][0] = x[i], k->curve[i][1] = y[i];
    k->ncurve = n;
    return st;
}

static mcs_status add_walls(fe_builder *b, const mcs_node *list, mcs_error *err)
{
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *w = mcs_node_at(list, i);
        if (fe_scn_given(w, "size"))
            return unsupported(fe_scn_get(w, "size"), err, "finite rigid wall size");
        const char *name = mcs_node_str(fe_scn_get(w, "name"));
        if (strlen(name) >= FE_NAME_MAX)
            return mcs_node_error(fe_scn_get(w, "name"), err, MCS_ERR_RANGE,
                                  "longer than %d characters", FE_NAME_MAX - 1);
        fe_wall_desc d = {.method = FE_WALL_KINEMATIC};
        snprintf(d.name, sizeof d.name, "%s", name);
        mcs_status st = mcs_node_vec3(fe_scn_get(w, "point"), d.point, err);
        if (!st) st = mcs_node_vec3(fe_scn_get(w, "normal"), d.normal, err);
        if (!st && fe_scn_given(w, "velocity"))
            st = mcs_node_vec3(fe_scn_get(w, "velocity"), d.velocity, err);
        if (st) return st;
        const char *method = mcs_node_str(fe_scn_get(w, "method"));
        if (method && strcmp(method, "penalty") == 0) d.method = FE_WALL_PENALTY;
        d.penalty_scale = mcs_node_num_or(w, "penalty_scale", 0);
        d.mass = mcs_node_num_or(w, "mass", 0); /* a free wall with mass (fe_wall.c) */
        d.friction = mcs_node_num_or(w, "friction", 0); /* Coulomb (fe_wall_fric.c) */
        if (fe_scn_given(w, "motion")) { /* moved by a curve (fe_wall_motion.c) */
            st = wall_motion(fe_scn_get(w, "motion"), &d, err);
            if (st) return st;
        }
        const mcs_node *parts = fe_scn_get(w, "parts");
        if (mcs_node_len(parts) > 8)
            return mcs_node_error(parts, err, MCS_ERR_RANGE, "at most 8 parts, got %d",
                                  mcs_node_len(parts));
        d.nparts = mcs_node_len(parts);
        for (int k = 0; k < d.nparts; k++)
            snprintf(d.parts[k], sizeof d.parts[k], "%s", mcs_node_str(mcs_node_at(parts, k)));
        mcs_error kerr = {0};
        st = fe_builder_add_wall(b, &d, &kerr);
        if (st) return fe_scn_relocate(st, w, &kerr, err);
    }
    return MCS_OK;
}

static mcs_status add_loads(fe_builder *b, const mcs_node *list, mcs_error *err)
{
    for (int i = 0; i < mcs_node_len(list); i++) {
        const mcs_node *l = mcs_node_at(list, i);
        fe_load_desc d = {.where = where_of(mcs_node_str(fe_scn_get(l, "where")))};
        snprintf(d.part, sizeof d.part, "%s", mcs_node_str(fe_scn_get(l, "part")));
        mcs_status st = mcs_node_vec3(fe_scn_get(l, "force"), d.force, err);
        if (st) return st;
        if (fe_scn_given(l, "curve")) {
            const mcs_node *c = fe_scn_get(l, "curve");
            int n = mcs_node_curve_len(c);
            double x[FE_CURVE_MAX], y[FE_CURVE_MAX];
            if (n > FE_CURVE_MAX)
                return mcs_node_error(c, err, MCS_ERR_RANGE, "at most %d points, got %d",
                                      FE_CURVE_MAX, n);
            st = mcs_node_curve(c, x, y, FE_CURVE_MAX, err);
            if (st) return st;
            for (int k = 0; k < n; k++) d.curve[k][0] = x[k], d.curve[k][1] = y[k];
            d.ncurve = n;
        }
        mcs_error kerr = {0};
        st = fe_builder_add_load(b, &d, &kerr);
        if (st) return fe_scn_relocate(st, l, &kerr, err);
    }
    return MCS_OK;
}

mcs_status fe_scn_build(const mcs_scenario *scn, fe_problem *out, mcs_error *err)
{
    return fe_scn_build_with(scn, NULL, NULL, NULL, out, err);
}

mcs_status fe_scn_build_with(const mcs_scenario *scn, const fe_scn_place *place,
                             fe_scn_hook hook, void *ctx, fe_problem *out, mcs_error *err)
{
    memset(out, 0, sizeof *out);
    const mcs_node *root = mcs_scenario_root(scn), *fe = fe_scn_get(root, "fe");
    const mcs_node *sim = fe_scn_get(root, "simulation");
    if (mcs_node_kind(fe) != MCS_NODE_MAP)
        return mcs_node_error(root, err, MCS_ERR_KEY, "no fe: block (stage 3 runs an FE model)");
    mcs_status st = MCS_OK;

    fe_opts opts = fe_opts_default();
    opts.dt_scale = mcs_node_num_or(sim, "time_step_scale", opts.dt_scale);
    opts.dt_max = mcs_node_num_or(sim, "time_step", 0);
    opts.history_capacity = 0; /* the run samples the state itself (s3_run.c) */
    fe_scn_solid_opts(root, &opts); /* gravity, mass scaling */
    /* mass damping, bulk viscosity, the energy check (fe_opts; defaults where not given) */
    opts.damping = mcs_node_num_or(fe, "damping", opts.damping);
    opts.bulk_q1 = mcs_node_num_or(fe, "bulk_q1", opts.bulk_q1);
    opts.bulk_q2 = mcs_node_num_or(fe, "bulk_q2", opts.bulk_q2);
    opts.energy_growth_limit = mcs_node_num_or(fe, "energy_growth_limit", opts.energy_growth_limit);
    out->end_time = mcs_node_num(fe_scn_get(sim, "end_time"));
    out->output_rate = mcs_node_num_or(sim, "output_rate", FE_SCN_OUTPUT_RATE_DEFAULT);
    out->field_rate = mcs_node_num_or(sim, "field_rate", 0); /* 0: fe_scn_field_rate */

    fe_builder *b = NULL;
    mcs_error kerr = {0};
    st = fe_builder_create(&b, &kerr);
    if (st) return fe_scn_relocate(st, fe, &kerr, err);
    if (fe_scn_given(fe, "keyword")) /* a whole deck (fe_scn_deck.c) */
        st = fe_scn_deck_add(b, fe, sim, &out->end_time, &opts, err);
    if (!st) st = add_parts(b, root, fe_scn_get(fe, "parts"), err);
    if (!st) st = add_attach(b, root, fe_scn_get(fe, "parts"), out, err);
    if (!st) st = add_ring_bodies(b, fe_scn_get(fe, "sliprings"), out, err);
    if (!st) st = add_boundaries(b, fe_scn_get(fe, "boundary"), out, err);
    if (!st) st = add_loads(b, fe_scn_get(fe, "loads"), err);
    if (!st) st = add_walls(b, fe_scn_get(fe, "rigid_walls"), err);
    if (!st) st = fe_scn_solid_add(b, fe, err); /* springs, point masses */
    if (!st) st = fe_scn_add_restraints(b, fe, err); /* airbags, retractors (fe_scn_restraints.c) */
    if (!st) st = fe_scn_add_sliprings(b, fe, err);  /* belt slip rings (fe_scn_slipring.c) */
    if (!st) st = fe_scn_add_joints(b, fe, err);     /* joints (fe_scn_joint.c) */
    if (!st) st = fe_scn_contact_add(b, fe, hook != NULL, err); /* contacts, ellipsoids */
    if (!st && place) st = fe_scn_place_apply(b, fe, place, out, err); /* fe_scn_place.c */
    if (!st && hook) st = hook(b, fe, ctx, err);
    if (!st) {
        st = fe_model_create(b, &opts, &out->model, &kerr);
        if (st) {
            const mcs_node *at = fe_scn_restraint_node(fe, kerr.msg);
            at = fe_scn_joint_node(fe, kerr.msg, fe_scn_slipring_node(fe, kerr.msg, at));
            fe_scn_relocate(st, at, &kerr, err);
        }
    }
    fe_builder_destroy(&b);
    return st;
}

void fe_problem_free(fe_problem *p)
{
    if (!p) return;
    fe_model_destroy(&p->model);
    free(p->att);
    free(p->part_carrier);
    p->part_carrier = NULL;
    p->att = NULL;
    p->natt = 0;
}

double fe_scn_field_rate(const fe_problem *p)
{
    if (p->field_rate > 0) return p->field_rate;
    const double r = p->end_time > 0 ? FE_SCN_FIELD_FRAMES / p->end_time : p->output_rate;
    return r < p->output_rate ? r : p->output_rate;
}

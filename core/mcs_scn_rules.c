/* mcs_scn_rules.c: rules that tie several keys of one map together (run after its keys passed).
 * The walker has already set every path and converted every quantity to SI. */
#include "core/mcs_schema.h"

#include <math.h>
#include <string.h>

static const mcs_node *given(const mcs_node *map, const char *key)
{
    const mcs_node *n = mcs_node_get(map, key);
    return n && n->kind != MCS_NODE_NULL ? n : NULL;
}

mcs_status mcs_rule_root(scn_walk *w, mcs_node *map)
{
    const mcs_node *v = given(map, "mcrash");
    if (v->num != 1.0)
        return mcs_node_error(v, w->err, MCS_ERR_RANGE,
                              "schema version %g is not supported (this mcrash reads version 1)",
                              v->num);
    /* end_time may come from a whole keyword deck's *CONTROL_TERMINATION (stage 3 only) */
    const mcs_node *sim = given(map, "simulation"), *fe = given(map, "fe");
    const mcs_node *bodies = given(map, "bodies");
    if (sim && !given(sim, "end_time") &&
        (!fe || !given(fe, "keyword") || (bodies && mcs_node_len(bodies) > 0)))
        return scn_walk_fail(w, sim, "end_time", MCS_ERR_KEY,
                             "required key is missing (only a whole keyword deck, fe.keyword, "
                             "without bodies may leave it out)");
    return MCS_OK;
}

/* fe: parts, or a whole keyword deck (or both: the scenario's parts beside the deck's) */
mcs_status mcs_rule_fe(scn_walk *w, mcs_node *map)
{
    if (!given(map, "parts") && !given(map, "keyword"))
        return scn_walk_fail(w, map, "parts", MCS_ERR_KEY,
                             "required key is missing (or give keyword:, a whole deck)");
    if ((given(map, "units") || given(map, "unknown_keywords")) && !given(map, "keyword"))
        return scn_walk_fail(w, map, given(map, "units") ? "units" : "unknown_keywords",
                             MCS_ERR_KEY, "belongs to a whole keyword deck: give keyword:");
    return MCS_OK;
}

mcs_status mcs_rule_simulation(scn_walk *w, mcs_node *map)
{
    const mcs_node *end = given(map, "end_time"), *dt = given(map, "time_step");
    if (end && dt && dt->num > end->num)
        return mcs_node_error(dt, w->err, MCS_ERR_RANGE,
                              "time step %g s is longer than end_time %g s", dt->num, end->num);
    return MCS_OK;
}

/* a range [min, max] must not be empty */
mcs_status mcs_rule_range(scn_walk *w, mcs_node *map)
{
    const mcs_node *r = given(map, "range");
    if (r && !(r->items[0]->num < r->items[1]->num))
        return mcs_node_error(r, w->err, MCS_ERR_RANGE, "min %g must be below max %g (SI units)",
                              r->items[0]->num, r->items[1]->num);
    return MCS_OK;
}

/* principal moments of a rigid body obey the triangle inequality: I1 + I2 >= I3 */
static mcs_status principal_inertia(scn_walk *w, const mcs_node *in)
{
    double I[3] = {in->items[0]->num, in->items[1]->num, in->items[2]->num};
    for (int i = 0; i < 3; i++) {
        if (!(I[i] > 0.0))
            return mcs_node_error(in->items[i], w->err, MCS_ERR_RANGE,
                                  "principal moment must be > 0 kg m^2 (got %g)", I[i]);
        double rest = I[(i + 1) % 3] + I[(i + 2) % 3];
        if (I[i] > rest * (1.0 + 1e-9))
            return mcs_node_error(in, w->err, MCS_ERR_RANGE,
                                  "not a rigid body's inertia: %g > %g + %g (triangle inequality)",
                                  I[i], I[(i + 1) % 3], I[(i + 2) % 3]);
    }
    return MCS_OK;
}

/* a full tensor (Ixx Iyy Izz Ixy Iyz Ixz) must be positive definite (Sylvester's criterion) */
static mcs_status full_inertia(scn_walk *w, const mcs_node *in)
{
    double v[6];
    for (int i = 0; i < 6; i++)
        v[i] = in->items[i]->num;
    double xx = v[0], yy = v[1], zz = v[2], xy = v[3], yz = v[4], xz = v[5];
    double m2 = xx * yy - xy * xy;
    double m3 = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz);
    if (!(xx > 0.0 && m2 > 0.0 && m3 > 0.0))
        return mcs_node_error(in, w->err, MCS_ERR_RANGE, "inertia tensor is not positive definite");
    return MCS_OK;
}

mcs_status mcs_rule_body(scn_walk *w, mcs_node *map)
{
    const mcs_node *in = given(map, "inertia");
    if (in->n != 3 && in->n != 6)
        return mcs_node_error(in, w->err, MCS_ERR_TYPE,
                              "expected 3 principal moments or 6 tensor components, got %d", in->n);
    mcs_status st = in->n == 3 ? principal_inertia(w, in) : full_inertia(w, in);
    if (st) return st;
    const mcs_node *q = given(map, "orientation");
    if (q && q->n == 4) {
        double n2 = 0;
        for (int i = 0; i < 4; i++)
            n2 += q->items[i]->num * q->items[i]->num;
        if (!(n2 > 0.0)) return mcs_node_error(q, w->err, MCS_ERR_RANGE, "quaternion is zero");
    }
    return MCS_OK;
}

static mcs_status distinct(scn_walk *w, mcs_node *map, const char *ka, const char *kb)
{
    const mcs_node *a = given(map, ka), *b = given(map, kb);
    if (a && b && strcmp(a->text, b->text) == 0)
        return mcs_node_error(b, w->err, MCS_ERR_RANGE, "'%s' is also %s: they must differ",
                              b->text, ka);
    return MCS_OK;
}

mcs_status mcs_rule_pair(scn_walk *w, mcs_node *map)
{
    return distinct(w, map, "a", "b");
}

/* stage 1 has nothing to restrain in a fixed joint */
mcs_status mcs_rule_fixed_joint(scn_walk *w, mcs_node *map)
{
    const mcs_node *r = given(map, "restraint");
    if (r) return mcs_node_error(r, w->err, MCS_ERR_KEY, "a fixed joint has no restraint");
    return MCS_OK;
}

mcs_status mcs_rule_joint(scn_walk *w, mcs_node *map)
{
    return distinct(w, map, "parent", "child");
}

mcs_status mcs_rule_sensor(scn_walk *w, mcs_node *map)
{
    const mcs_node *c = given(map, "cfc");
    double v = c ? c->num : 0.0;
    if (v != 0.0 && v != 60.0 && v != 180.0 && v != 600.0 && v != 1000.0)
        return mcs_node_error(c, w->err, MCS_ERR_RANGE,
                              "%g is not a SAE J211 class (0, 60, 180, 600, 1000)", v);
    return MCS_OK;
}

mcs_status mcs_rule_plate(scn_walk *w, mcs_node *map)
{
    if (!given(map, "divisions") && !given(map, "element_size"))
        return scn_walk_fail(w, map, "element_size", MCS_ERR_KEY,
                             "required key is missing (or give divisions)");
    return MCS_OK;
}

/* LS-DYNA *MAT_024: the curve's stress at zero plastic strain is the yield stress */
mcs_status mcs_rule_plastic(scn_walk *w, mcs_node *map)
{
    const mcs_node *h = given(map, "hardening"), *sy = given(map, "yield_stress");
    if (h && given(map, "tangent_modulus"))
        return mcs_node_error(given(map, "tangent_modulus"), w->err, MCS_ERR_KEY,
                              "give hardening (a curve) or tangent_modulus, not both");
    if (!h || h->items[0]->items[0]->num != 0.0) return MCS_OK;
    double s0 = h->items[0]->items[1]->num;
    if (fabs(s0 - sy->num) > 1e-6 * sy->num)
        return mcs_node_error(h->items[0], w->err, MCS_ERR_RANGE,
                              "stress at zero plastic strain %g Pa differs from yield_stress %g Pa",
                              s0, sy->num);
    return MCS_OK;
}

/* an FE part needs a section and a material, except with a keyword mesh, whose deck's
 * *SECTION_* and *MAT_* cards are then used (docs/keyword.md) */
mcs_status mcs_rule_fe_part(scn_walk *w, mcs_node *map)
{
    const mcs_node *mesh = given(map, "mesh");
    if (given(map, "material") && given(map, "material_from"))
        return scn_walk_fail(w, map, "material_from", MCS_ERR_KEY,
                             "give material or material_from, not both");
    if (mesh && given(mesh, "keyword")) return MCS_OK;
    /* a generated motorcycle or sedan side brings its own (stage3_fe/s3_moto.h, s3_sedan.h) */
    const char *gen = mcs_node_str(given(mesh, "generate"));
    if (gen && (strcmp(gen, "motorcycle") == 0 || strcmp(gen, "sedan_side") == 0)) return MCS_OK;
    static const char *const keys[] = {"section", "material"};
    for (int i = 0; i < 2; i++)
        if (!given(map, keys[i]) && !(i == 1 && given(map, "material_from")))
            return scn_walk_fail(w, map, keys[i], MCS_ERR_KEY,
                                 "required key is missing (only a keyword mesh may leave it out)");
    return MCS_OK;
}

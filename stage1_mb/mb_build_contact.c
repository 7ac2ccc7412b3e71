/* mb_build_contact.c: characteristics -> hysteresis models, body surfaces and the ground plane,
 * contacts -> surface pairs with their force law.
 *
 * Force law of a surface pair (thesis §3.1 and §3.2):
 *   - both surfaces name a characteristic: two deformable bodies in series. They carry the
 *     same force and their deflections add: loading x(F) = x_a(F) + x_b(F)
 *     (mcs_curve_create_series). Both unload together from the same force, so the combined
 *     unloading is elastic when both are elastic; otherwise a line whose slope is the series
 *     stiffness k = k_a k_b / (k_a + k_b) of each side's unloading slope (unloading_slope, the
 *     last segment of an unloading curve, or for an elastic side the slope of its loading curve
 *     at its last point), with the elastic limit at the smaller force where either side leaves
 *     its elastic range. Exact for linear loading and linear unloading; otherwise approximate.
 *   - otherwise: the contact's characteristic (a rigid surface against a deformable one).
 *   Damping always comes from the contact's characteristic. Friction: the contact's `friction`,
 *   else (ground contacts) environment.ground.friction, else the characteristic's, else 0. */
#include "stage1_mb/mb_build_internal.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static mcs_status curve_of(const mcs_node *n, const char *name, mcs_curve **out, mcs_error *err)
{
    int len = mcs_node_curve_len(n);
    double x[len > 0 ? len : 1], y[len > 0 ? len : 1];
    mcs_status st = mcs_node_curve(n, x, y, len, err);
    if (st) return st;
    mcs_error e2 = {0};
    st = mcs_curve_create(name, len, x, y, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR, out, &e2);
    if (st) return mcs_node_error(n, err, st, "%s", e2.msg);
    return MCS_OK;
}

static mcs_status build_char(const mcs_node *n, const char *name, mb_char *c, mcs_error *err)
{
    snprintf(c->name, MB_NAME, "%s", name);
    const char *ty = mcs_node_str(mcs_node_get(n, "type"));
    c->moment = ty && strcmp(ty, "moment") == 0;
    c->damping = mcs_node_num_or(n, "damping", 0);
    c->friction = mcs_node_num_or(n, "friction", NAN);
    mcs_status st = curve_of(mcs_node_get(n, "loading"), name, &c->loading, err);
    const mcs_node *un = mcs_node_get(n, "unloading");
    if (!st && mcs_node_kind(un) == MCS_NODE_SEQ)
        st = curve_of(un, name, &c->unloading, err);
    if (st) return st;
    double slope = mcs_node_num_or(n, "unloading_slope", NAN);
    c->hyst = (mcs_hyst_model){.loading = c->loading, .unloading = c->unloading,
                               .unload = MCS_UNLOAD_ELASTIC, .elastic_limit = INFINITY};
    if (c->unloading || !isnan(slope)) {
        c->hyst.unload = c->unloading ? MCS_UNLOAD_CURVE : MCS_UNLOAD_SLOPE;
        c->hyst.unload_slope = isnan(slope) ? 0 : slope;
        c->hyst.elastic_limit = mcs_node_num_or(n, "elastic_limit", 0);
    }
    mcs_error e2 = {0};
    st = mcs_hyst_model_check(&c->hyst, name, &e2);
    return st ? mcs_node_error(n, err, st, "%s", e2.msg) : MCS_OK;
}

mcs_status mb_build_chars(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *chars = mcs_node_get(root, "characteristics");
    m->nchar = mcs_node_len(chars);
    m->chr = MB_NEW(mb_char, m->nchar);
    if (!m->chr) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int i = 0; i < m->nchar; i++) {
        mcs_status st = build_char(mcs_node_at(chars, i), mcs_node_key(chars, i), &m->chr[i], err);
        if (st) return st;
    }
    return MCS_OK;
}

/* a contact surface's characteristic: a force characteristic or -1 */
static mcs_status surf_char(const mb_model *m, const mcs_node *ref, int *out, mcs_error *err)
{
    *out = mb_build_char_ref(m, ref);
    if (*out >= 0 && m->chr[*out].moment)
        return mcs_node_error(ref, err, MCS_ERR_TYPE,
                              "'%s' is a moment characteristic; a contact needs force vs. "
                              "penetration", m->chr[*out].name);
    return MCS_OK;
}

static mcs_status build_surface(const mb_model *m, const mcs_node *n, int body, int k,
                                mb_surface *s, mcs_error *err)
{
    const char *ty = mcs_node_str(mcs_node_get(n, "type"));
    const char *nm = mcs_node_str(mcs_node_get(n, "name"));
    if (nm)
        snprintf(s->name, MB_NAME, "%s", nm);
    else
        snprintf(s->name, MB_NAME, "%s.surfaces[%d]", m->body_name[body], k);
    s->body = body;
    mcs_status st = surf_char(m, mcs_node_get(n, "characteristic"), &s->chr, err);
    if (st) return st;
    if (ty && strcmp(ty, "ellipsoid") == 0) {
        const mcs_node *deg = mcs_node_get(n, "degree");
        if (mcs_node_kind(deg) == MCS_NODE_NUM && mcs_node_num(deg) != 2)
            return mcs_node_error(deg, err, MCS_ERR_UNSUPPORTED,
                                  "hyper-ellipsoids (degree > 2) are not built yet in stage 1");
        s->type = MB_SURF_ELLIPSOID;
        if ((st = mcs_node_vec3(mcs_node_get(n, "center"), s->center, err))) return st;
        if ((st = mcs_node_vec3(mcs_node_get(n, "semi_axes"), s->semi, err))) return st;
        double rpy[3] = {0, 0, 0};
        const mcs_node *o = mcs_node_get(n, "orientation");
        if (mcs_node_kind(o) == MCS_NODE_SEQ && (st = mcs_node_vec3(o, rpy, err))) return st;
        mb_build_cardan(rpy, s->rot);
        s->sphere = s->semi[0] == s->semi[1] && s->semi[1] == s->semi[2];
        return MCS_OK;
    }
    if (ty && strcmp(ty, "plane") == 0) {
        if (mcs_node_kind(mcs_node_get(n, "size")) == MCS_NODE_SEQ)
            return mcs_node_error(mcs_node_get(n, "size"), err, MCS_ERR_UNSUPPORTED,
                                  "finite planes are not built yet in stage 1 (omit size: "
                                  "an unbounded half-space)");
        s->type = MB_SURF_PLANE;
        if ((st = mcs_node_vec3(mcs_node_get(n, "point"), s->center, err))) return st;
        return mb_build_dir(mcs_node_get(n, "normal"), s->normal, err);
    }
    if (ty && strcmp(ty, "cylinder") == 0) {
        /* a wheel: the torus of the tyre's rounded profile, crown radius R - L/2, tube L/2 */
        double r = mcs_node_num(mcs_node_get(n, "radius"));
        double len = mcs_node_num(mcs_node_get(n, "length"));
        if (!(len < 2 * r))
            return mcs_node_error(mcs_node_get(n, "length"), err, MCS_ERR_RANGE,
                                  "a cylinder (wheel) must be shorter than its diameter %g m",
                                  2 * r);
        s->type = MB_SURF_CYLINDER;
        s->radius = r - len / 2, s->tube = len / 2;
        if ((st = mcs_node_vec3(mcs_node_get(n, "center"), s->center, err))) return st;
        return mb_build_dir(mcs_node_get(n, "axis"), s->normal, err);
    }
    if (ty && strcmp(ty, "facet") == 0) return mb_build_facet(n, s, err);
    return mcs_node_error(n, err, MCS_ERR_UNSUPPORTED,
                          "surface type '%s' is not built yet in stage 1 (ellipsoid, plane, "
                          "cylinder, facet)", ty ? ty : "?");
}

mcs_status mb_build_surfaces(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *bodies = mcs_node_get(root, "bodies");
    const mcs_node *ground = mcs_node_get(mcs_node_get(root, "environment"), "ground");
    int n = mcs_node_kind(ground) == MCS_NODE_MAP;
    for (int i = 0; i < m->nbody; i++)
        n += mcs_node_len(mcs_node_get(mcs_node_at(bodies, i), "surfaces"));
    m->surf = MB_NEW(mb_surface, n);
    if (!m->surf) return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    for (int i = 0; i < m->nbody; i++) {
        const mcs_node *list = mcs_node_get(mcs_node_at(bodies, i), "surfaces");
        for (int k = 0; k < mcs_node_len(list); k++) {
            mcs_status st = build_surface(m, mcs_node_at(list, k), i, k, &m->surf[m->nsurf], err);
            if (st) return st;
            m->nsurf++;
        }
    }
    if (mcs_node_kind(ground) == MCS_NODE_MAP) {
        mb_surface *g = &m->surf[m->nsurf];
        snprintf(g->name, MB_NAME, "ground");
        g->body = MB_GROUND, g->type = MB_SURF_PLANE;
        g->center[2] = mcs_node_num(mcs_node_get(ground, "height"));
        g->normal[2] = 1;
        mcs_status st = surf_char(m, mcs_node_get(ground, "characteristic"), &g->chr, err);
        if (st) return st;
        m->ground_surf = m->nsurf++;
    }
    return MCS_OK;
}

/* each side's unloading stiffness for the series combination [N/m] */
static double unload_stiffness(const mb_char *c)
{
    if (c->hyst.unload == MCS_UNLOAD_SLOPE) return c->hyst.unload_slope;
    const mcs_curve *g = c->unloading ? c->unloading : c->loading;
    return mcs_curve_slope(g, g->x[g->n - 1]);
}

/* the force at which a side leaves its elastic range [N] (INFINITY: never) */
static double elastic_force(const mb_char *c)
{
    if (c->hyst.unload == MCS_UNLOAD_ELASTIC || isinf(c->hyst.elastic_limit)) return INFINITY;
    return mcs_curve_eval(c->loading, c->hyst.elastic_limit);
}

static mcs_status series_law(mb_model *m, const mcs_node *cn, mb_pair *p, int ip, mcs_error *err)
{
    const mb_char *a = &m->chr[m->surf[p->sa].chr], *b = &m->chr[m->surf[p->sb].chr];
    char name[160];
    snprintf(name, sizeof name, "%s+%s", a->name, b->name);
    mcs_error e2 = {0};
    mcs_status st = mcs_curve_create_series(a->loading, b->loading, name, &m->own_curves[ip], &e2);
    if (st)
        return mcs_node_error(cn, err, st, "surfaces %s and %s in series: %s", m->surf[p->sa].name,
                              m->surf[p->sb].name, e2.msg);
    const mcs_curve *L = m->own_curves[ip];
    p->hyst = (mcs_hyst_model){.loading = L, .unload = MCS_UNLOAD_ELASTIC,
                               .elastic_limit = INFINITY};
    if (a->hyst.unload != MCS_UNLOAD_ELASTIC || b->hyst.unload != MCS_UNLOAD_ELASTIC) {
        double ka = unload_stiffness(a), kb = unload_stiffness(b);
        double fe = fmin(elastic_force(a), elastic_force(b));
        p->hyst.unload = MCS_UNLOAD_SLOPE;
        p->hyst.unload_slope = ka * kb / (ka + kb);
        p->hyst.elastic_limit = isinf(fe) ? INFINITY : fmax(0, mcs_curve_inverse(L, fe));
    }
    st = mcs_hyst_model_check(&p->hyst, name, &e2);
    return st ? mcs_node_error(cn, err, st, "%s", e2.msg) : MCS_OK;
}

/* the order of two surfaces with penetration geometry (first one: ellipsoid or cylinder):
 * 1 as given, -1 swapped, 0 none (plane-plane, and cylinders against facets) */
static int pair_order(const mb_surface *x, const mb_surface *y)
{
    mb_surf_type a = x->type, b = y->type;
    if (a == MB_SURF_CYLINDER && b == MB_SURF_CYLINDER) return 1; /* mb_geom_wheel2.h */
    if (a == MB_SURF_CYLINDER && b == MB_SURF_ELLIPSOID) return 1;
    if (b == MB_SURF_CYLINDER && a == MB_SURF_ELLIPSOID) return -1;
    if (a == MB_SURF_ELLIPSOID && b != MB_SURF_CYLINDER) return 1;
    if (b == MB_SURF_ELLIPSOID && a != MB_SURF_CYLINDER) return -1;
    if (a == MB_SURF_CYLINDER && b == MB_SURF_PLANE) return 1;
    if (b == MB_SURF_CYLINDER && a == MB_SURF_PLANE) return -1;
    return 0;
}

/* the pairs of two bodies' surfaces; count only when pairs is NULL. Pairs without geometry
 * are skipped, and reported (once, when listing) when a cylinder is involved. */
static int list_pairs(const mb_model *m, int a, int b, mb_pair *pairs, const char *contact)
{
    int n = 0;
    for (int i = 0; i < m->nsurf; i++) {
        if (m->surf[i].body != a) continue;
        for (int j = 0; j < m->nsurf; j++) {
            if (m->surf[j].body != b || j == i) continue;
            int o = pair_order(&m->surf[i], &m->surf[j]);
            if (o == 0) {
                if (pairs && (m->surf[i].type == MB_SURF_CYLINDER ||
                              m->surf[j].type == MB_SURF_CYLINDER))
                    mcs_log(MCS_LOG_WARN,
                            "stage 1: contact %s: %s against %s is not checked (a cylinder "
                            "meets planes, ellipsoids and cylinders only)",
                            contact, m->surf[i].name, m->surf[j].name);
                continue;
            }
            if (pairs) {
                int sa = o > 0 ? i : j, sb = o > 0 ? j : i;
                pairs[n] = (mb_pair){.sa = sa, .sb = sb, .ba = m->surf[sa].body,
                                     .bb = m->surf[sb].body};
            }
            n++;
        }
    }
    return n;
}

static mcs_status build_contact(const mcs_node *cn, mb_model *m, int ic, mcs_error *err)
{
    mb_contact_def *c = &m->contact[ic];
    const mcs_node *na = mcs_node_get(cn, "a"), *nb = mcs_node_get(cn, "b");
    c->body_a = mb_build_body_ref(m, na), c->body_b = mb_build_body_ref(m, nb);
    if (c->body_a == MB_GROUND) { /* keep the ground second */
        c->body_a = c->body_b, c->body_b = MB_GROUND;
        const mcs_node *t = na;
        na = nb, nb = t;
    }
    const char *nm = mcs_node_str(mcs_node_get(cn, "name"));
    if (nm)
        snprintf(c->name, MB_NAME, "%s", nm);
    else
        snprintf(c->name, MB_NAME, "%.30s-%.30s", mcs_node_str(na), mcs_node_str(nb));
    /* the name keys the channels <name>_fn ... and triggers: one contact per name (two unnamed
     * contacts of one pair, or a name equal to another's <a>-<b>) */
    for (int j = 0; j < ic; j++)
        if (strcmp(m->contact[j].name, c->name) == 0)
            return mcs_node_error(nm ? mcs_node_get(cn, "name") : cn, err, MCS_ERR_KEY,
                                  "contact name '%s' is also contacts[%d]'s (named, or <a>-<b> "
                                  "when unnamed): give each a name of its own",
                                  c->name, j);
    if (c->body_b == MB_GROUND && m->ground_surf < 0)
        return mcs_node_error(nb, err, MCS_ERR_KEY,
                              "a contact with the ground needs environment.ground");
    int chr;
    mcs_status st = surf_char(m, mcs_node_get(cn, "characteristic"), &chr, err);
    if (st) return st;
    c->pair0 = m->npair;
    c->npair = list_pairs(m, c->body_a, c->body_b, m->pair + m->npair, c->name);
    if (c->npair == 0)
        return mcs_node_error(cn, err, MCS_ERR_RANGE,
                              "no surface pair to check: give %s and %s surfaces (an ellipsoid "
                              "on one side, or a cylinder against a plane or a cylinder)", mcs_node_str(na),
                              mcs_node_str(nb));
    double mu = mcs_node_num_or(cn, "friction", NAN);
    for (int k = 0; k < c->npair; k++) {
        mb_pair *p = &m->pair[c->pair0 + k];
        p->contact = ic;
        p->damping = m->chr[chr].damping;
        p->friction = mu;
        if (m->surf[p->sa].chr >= 0 && m->surf[p->sb].chr >= 0)
            st = series_law(m, cn, p, c->pair0 + k, err);
        else
            p->hyst = m->chr[chr].hyst;
        if (st) return st;
    }
    m->npair += c->npair;
    return MCS_OK;
}

mcs_status mb_build_contacts(const mcs_node *root, mb_model *m, mcs_error *err)
{
    const mcs_node *list = mcs_node_get(root, "contacts");
    m->ncontact = mcs_node_len(list);
    int cap = 0;
    for (int i = 0; i < m->ncontact; i++) {
        const mcs_node *cn = mcs_node_at(list, i);
        int a = mb_build_body_ref(m, mcs_node_get(cn, "a"));
        int b = mb_build_body_ref(m, mcs_node_get(cn, "b"));
        cap += list_pairs(m, a, b, NULL, NULL) + list_pairs(m, b, a, NULL, NULL);
    }
    m->contact = MB_NEW(mb_contact_def, m->ncontact);
    m->pair = MB_NEW(mb_pair, cap);
    m->own_curves = MB_NEW(mcs_curve *, cap);
    if (!m->contact || !m->pair || !m->own_curves)
        return MCS_ERR(err, MCS_ERR_NOMEM, "stage 1: out of memory");
    /* friction fallbacks: ground, then the characteristic */
    const mcs_node *ground = mcs_node_get(mcs_node_get(root, "environment"), "ground");
    double mu_ground = mcs_node_num_or(ground, "friction", NAN);
    for (int i = 0; i < m->ncontact; i++) {
        mcs_status st = build_contact(mcs_node_at(list, i), m, i, err);
        if (st) return st;
        mb_contact_def *c = &m->contact[i];
        int chr = mb_build_char_ref(m, mcs_node_get(mcs_node_at(list, i), "characteristic"));
        for (int k = 0; k < c->npair; k++) {
            mb_pair *p = &m->pair[c->pair0 + k];
            if (isnan(p->friction) && c->body_b == MB_GROUND) p->friction = mu_ground;
            if (isnan(p->friction)) p->friction = m->chr[chr].friction;
            if (isnan(p->friction)) p->friction = 0;
        }
    }
    return MCS_OK;
}

/* fe_kw_build_contact: a deck's *CONTACT_*, *INITIAL_VELOCITY_NODE,
 * *BOUNDARY_PRESCRIBED_MOTION_NODE/_SET/_RIGID and *LOAD_* into a builder whose parts
 * fe_kw_add_deck has put in (docs/keyword.md says what each becomes). What the kernel cannot
 * honour is refused with the keyword's FILE:LINE. */
#include "fe/fe_contact.h"
#include "fe/fe_kw_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    fe_builder *b;
    const fe_kw_deck *dk;
    const char (*names)[FE_NAME_MAX];
    const int *map;
    mcs_error *err;
} kb;

static const char *ct_name(const fe_kw_contact *k)
{
    static const char *const nm[2][4] = {
        {"CONTACT_SINGLE_SURFACE", "CONTACT_GENERAL", "CONTACT_SURFACE_TO_SURFACE",
         "CONTACT_NODES_TO_SURFACE"},
        {"CONTACT_AUTOMATIC_SINGLE_SURFACE", "CONTACT_AUTOMATIC_GENERAL",
         "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_NODES_TO_SURFACE"}};
    return nm[k->automatic ? 1 : 0][k->type];
}

/* builder part index of deck part index k (-1: not in the model: no elements, discrete) */
static int model_part(const kb *c, int k)
{
    return fe_builder_find_part(c->b, c->names[k]);
}

static int deck_part_index(const fe_kw_deck *dk, int pid)
{
    for (int k = 0; k < dk->npart; k++)
        if (dk->part[k].id == pid) return k;
    return -1;
}

/* ---- contacts ---- */

typedef struct {
    int n;
    char part[FE_CONTACT_PARTS][FE_NAME_MAX];
    int nnode, nface; /* a node or segment set side: its builder nodes and faces (0: parts)  */
    int *node, *face; /* (nnode), (nface x 4), owned                                          */
} side;

static void side_free(side *s)
{
    free(s->node), free(s->face);
    s->node = s->face = NULL;
}

static mcs_status side_add(const kb *c, const fe_kw_contact *k, const char *what, int pk, side *s)
{
    for (int i = 0; i < s->n; i++)
        if (strcmp(s->part[i], c->names[pk]) == 0) return MCS_OK;
    if (s->n >= FE_CONTACT_PARTS)
        return kw_at(c->dk, k->loc, c->err, MCS_ERR_RANGE,
                  "*%s: the %s side holds more than %d parts; the kernel's contact takes at "
                  "most %d a side",
                  ct_name(k), what, FE_CONTACT_PARTS, FE_CONTACT_PARTS);
    snprintf(s->part[s->n++], FE_NAME_MAX, "%s", c->names[pk]);
    return MCS_OK;
}

/* deck node index -> the shells and solids using it (CSR, built once per deck) */
typedef struct {
    int *off, *el; /* (nnode + 1), (...): element e of type t as 2 e + (t == solid) */
} node_elems;

static int node_elems_make(const fe_kw_deck *dk, node_elems *ne)
{
    const fe_kw_etype ty[2] = {FE_KW_SHELL, FE_KW_SOLID};
    ne->off = calloc((size_t)dk->nnode + 1, sizeof(int));
    if (!ne->off) return -1;
    for (int t = 0; t < 2; t++) {
        const fe_kw_elems *e = &dk->elem[ty[t]];
        const int k = fe_kw_etype_nnode(ty[t]);
        for (int i = 0; i < e->n; i++)
            for (int j = 0; j < k; j++)
                ne->off[fe_kw_node_index(dk, e->node[(size_t)k * i + j]) + 1]++;
    }
    for (int i = 0; i < dk->nnode; i++)
        ne->off[i + 1] += ne->off[i];
    ne->el = malloc(sizeof(int) * (size_t)(ne->off[dk->nnode] ? ne->off[dk->nnode] : 1));
    int *fill = calloc((size_t)dk->nnode + 1, sizeof(int));
    if (!ne->el || !fill) {
        free(fill);
        return -1;
    }
    for (int t = 0; t < 2; t++) {
        const fe_kw_elems *e = &dk->elem[ty[t]];
        const int k = fe_kw_etype_nnode(ty[t]);
        for (int i = 0; i < e->n; i++)
            for (int j = 0; j < k; j++) {
                int di = fe_kw_node_index(dk, e->node[(size_t)k * i + j]);
                ne->el[ne->off[di] + fill[di]++] = 2 * i + t;
            }
    }
    free(fill);
    return 0;
}

/* the deck part index of an element that holds every node of the face q (deck indices), -1 */
static int face_part(const fe_kw_deck *dk, const node_elems *ne, const int q[4])
{
    for (int j = ne->off[q[0]]; j < ne->off[q[0] + 1]; j++) {
        const int t = ne->el[j] & 1, i = ne->el[j] >> 1;
        const fe_kw_etype ty = t ? FE_KW_SOLID : FE_KW_SHELL;
        const int k = fe_kw_etype_nnode(ty);
        const int *en = dk->elem[ty].node + (size_t)k * i;
        int all = 1;
        for (int a = 1; a < 4 && all; a++) {
            int in = 0;
            for (int b = 0; b < k && !in; b++)
                in = fe_kw_node_index(dk, en[b]) == q[a];
            all = in;
        }
        if (all) return deck_part_index(dk, dk->elem[ty].pid[i]);
    }
    return -1;
}

/* a segment set (typ 0) or node set (typ 4) side: the parts of its elements, its nodes and
 * (segment set) its faces in builder indices */
static mcs_status set_side(const kb *c, const fe_kw_contact *k, const char *what, int id, int typ,
                           side *s)
{
    const fe_kw_deck *dk = c->dk;
    const fe_kw_segset *ss = NULL;
    for (int i = 0; i < dk->nsegset && typ == 0; i++)
        if (dk->segset[i].id == id) ss = &dk->segset[i];
    const fe_kw_set *ns = typ == 4 ? fe_kw_find_set(dk, id, 0) : NULL;
    char skip[400];
    if (!ss && !ns)
        return kw_at(dk, k->loc, c->err, MCS_ERR_KEY, "*%s: %s side: %s %d is not defined%s",
                  ct_name(k), what, typ == 0 ? "segment set" : "node set", id,
                  fe_kw_skipped(dk, "SET_", skip, sizeof skip));
    const int nn = ss ? 4 * ss->n : ns->n;
    s->node = malloc(sizeof(int) * (size_t)(nn ? nn : 1));
    s->face = ss ? malloc(sizeof(int) * (size_t)(nn ? nn : 1)) : NULL;
    node_elems ne = {0};
    mcs_status st = MCS_OK;
    if (!s->node || (ss && !s->face) || node_elems_make(dk, &ne))
        st = MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    for (int i = 0; i < (ss ? ss->n : ns->n) && !st; i++) {
        int q[4], ids[4], n = ss ? 4 : 1;
        for (int j = 0; j < n; j++) {
            ids[j] = ss ? ss->node[4 * i + j] : ns->ids[i];
            q[j] = fe_kw_node_index(dk, ids[j]);
        }
        for (int j = 0; j < n && !st; j++)
            if (q[j] < 0 || c->map[q[j]] < 0)
                st = kw_at(dk, k->loc, c->err, MCS_ERR_KEY, "*%s: %s side: node %d of %s %d is %s",
                        ct_name(k), what, ids[j], ss ? "segment set" : "node set", id,
                        q[j] < 0 ? "not defined" : "in no element");
        if (st) break;
        if (ss) { /* the part of the element whose face it is */
            int pk = face_part(dk, &ne, q);
            if (pk < 0 || model_part(c, pk) < 0) {
                st = kw_at(dk, ss->loc, c->err, MCS_ERR_KEY,
                        "*SET_SEGMENT %d: segment %d %d %d %d is no face of a shell or solid of "
                        "the model",
                        id, ids[0], ids[1], ids[2], ids[3]);
                break;
            }
            st = side_add(c, k, what, pk, s);
            for (int j = 0; j < 4; j++)
                s->face[4 * s->nface + j] = c->map[q[j]];
            s->nface++;
            for (int j = 0; j < 4; j++)
                s->node[s->nnode++] = c->map[q[j]];
        } else { /* the parts of the elements holding the node */
            for (int j = ne.off[q[0]]; j < ne.off[q[0] + 1] && !st; j++) {
                const fe_kw_etype ty = ne.el[j] & 1 ? FE_KW_SOLID : FE_KW_SHELL;
                int pk = deck_part_index(dk, dk->elem[ty].pid[ne.el[j] >> 1]);
                if (pk >= 0 && model_part(c, pk) >= 0) st = side_add(c, k, what, pk, s);
            }
            s->node[s->nnode++] = c->map[q[0]];
        }
    }
    free(ne.off), free(ne.el);
    if (!st && s->n == 0)
        st = kw_at(dk, k->loc, c->err, MCS_ERR_RANGE,
                "*%s: %s side: set %d holds no node of a "
                "shell or solid",
                ct_name(k), what, id);
    return st;
}

/* the parts of one side: id of ID type typ (2 part set, 3 part, 5 all, 6 all but a part set);
 * single surface with id 0: every part */
static mcs_status side_parts(const kb *c, const fe_kw_contact *k, const char *what, int id, int typ,
                             side *s)
{
    const fe_kw_deck *dk = c->dk;
    s->n = 0;
    int single = k->type == FE_KW_CT_SINGLE || k->type == FE_KW_CT_GENERAL;
    if (typ == 4 && k->type != FE_KW_CT_N2S)
        return kw_at(dk, k->loc, c->err, MCS_ERR_UNSUPPORTED,
                  "*%s: the %s side is a node set (SSTYP 4): node sets are for nodes-to-surface "
                  "contacts",
                  ct_name(k), what);
    if (typ == 0 || typ == 4) return set_side(c, k, what, id, typ, s);
    const fe_kw_set *set = NULL;
    if ((typ == 2 || typ == 6) && !(single && id == 0)) {
        set = fe_kw_find_set(dk, id, 1);
        if (!set) {
            char skip[400];
            return kw_at(dk, k->loc, c->err, MCS_ERR_KEY, "*%s: %s side: part set %d is not defined%s",
                      ct_name(k), what, id, fe_kw_skipped(dk, "SET_", skip, sizeof skip));
        }
    }
    if (typ == 3 && !(single && id == 0)) {
        int pk = deck_part_index(dk, id);
        if (pk < 0 || model_part(c, pk) < 0)
            return kw_at(dk, k->loc, c->err, MCS_ERR_KEY, "*%s: %s side: part %d %s", ct_name(k), what,
                      id, pk < 0 ? "has no *PART card" : "has no elements in the model");
        return side_add(c, k, what, pk, s);
    }
    if (typ == 2 && set) {
        for (int i = 0; i < set->n; i++) {
            int pk = deck_part_index(dk, set->ids[i]);
            if (pk < 0 || model_part(c, pk) < 0)
                return kw_at(dk, k->loc, c->err, MCS_ERR_KEY,
                          "*%s: %s side: part %d of part set %d %s", ct_name(k), what, set->ids[i],
                          id, pk < 0 ? "has no *PART card" : "has no elements in the model");
            mcs_status st = side_add(c, k, what, pk, s);
            if (st) return st;
        }
        return MCS_OK;
    }
    /* every part of the model (5, single surface 0), or all but the set's (6) */
    for (int pk = 0; pk < dk->npart; pk++) {
        if (model_part(c, pk) < 0) continue;
        int out = 0;
        for (int i = 0; set && typ == 6 && i < set->n; i++)
            out |= set->ids[i] == dk->part[pk].id;
        if (out) continue;
        mcs_status st = side_add(c, k, what, pk, s);
        if (st) return st;
    }
    if (s->n == 0)
        return kw_at(dk, k->loc, c->err, MCS_ERR_RANGE, "*%s: %s side holds no part", ct_name(k),
                  what);
    return MCS_OK;
}

static mcs_status add_contact_sides(const kb *c, int i, side *sl, side *ms);

static mcs_status add_contact(const kb *c, int i)
{
    side sl = {0}, ms = {0};
    mcs_status st = add_contact_sides(c, i, &sl, &ms);
    side_free(&sl), side_free(&ms);
    return st;
}

static mcs_status add_contact_sides(const kb *c, int i, side *psl, side *pms)
{
    const fe_kw_deck *dk = c->dk;
    const fe_kw_contact *k = &dk->contact[i];
    fe_contact_desc d = fe_contact_desc_default();
    size_t nt = strlen(k->title);
    if (nt && nt < sizeof d.name)
        memcpy(d.name, k->title, nt + 1);
    else
        snprintf(d.name, sizeof d.name, "contact_%d", k->id ? k->id : i + 1);
    static const fe_contact_type type[4] = {FE_CONTACT_SINGLE_SURFACE, FE_CONTACT_SINGLE_SURFACE,
                                            FE_CONTACT_TWO_SURFACE, FE_CONTACT_NODE_TO_SURFACE};
    d.type = type[k->type];
    side *sl = psl, *ms = pms;
    mcs_status st = side_parts(c, k, "slave", k->ssid, k->sstyp, sl);
    if (!st && d.type != FE_CONTACT_SINGLE_SURFACE)
        st = side_parts(c, k, "master", k->msid, k->mstyp, ms);
    if (st) return st;
    d.nslave = sl->n, d.nmaster = ms->n;
    memcpy(d.slave, sl->part, sizeof sl->part);
    memcpy(d.master, ms->part, sizeof ms->part);
    /* segment and node set sides: the kernel's side filters (copied by the builder) */
    d.nslave_node = sl->nnode, d.slave_node = sl->node, d.nslave_face = sl->nface;
    d.slave_face = sl->face, d.nmaster_node = ms->nnode, d.master_node = ms->node;
    d.nmaster_face = ms->nface, d.master_face = ms->face;
    /* GENERAL adds beam edges to the single surface: refused when a part is of beams */
    const fe_kw_elems *be = &dk->elem[FE_KW_BEAM];
    for (int j = 0; j < be->n && k->type == FE_KW_CT_GENERAL; j++) {
        int pk = deck_part_index(dk, be->pid[j]);
        for (int q = 0; q < sl->n && pk >= 0; q++)
            if (strcmp(sl->part[q], c->names[pk]) == 0)
                return kw_at(dk, k->loc, c->err, MCS_ERR_UNSUPPORTED,
                          "*%s: part %d is of beams, whose edge contact is not built", ct_name(k),
                          be->pid[j]);
    }
    /* LS-DYNA: mu = FD + (FS - FD) exp(-DC |v_rel|), FS and FD scaled by FSF */
    d.friction = k->fs * k->fsf;
    d.friction_dynamic = k->dc > 0 ? k->fd * k->fsf : -1;
    d.friction_decay = k->dc;
    d.damping = k->vdc / 100; /* VDC: percent of critical -> fraction */
    d.birth = k->bt, d.death = k->dt;
    if (k->dc > 0 && k->fd > k->fs)
        return kw_at(dk, k->loc, c->err, MCS_ERR_UNSUPPORTED,
                  "*%s: FD %g > FS %g: friction that grows with the slip speed is not built",
                  ct_name(k), k->fd, k->fs);
    /* the penalty k = SLSFAC x SFS x (K A^2 / V or K A / diagonal), SLSFAC 0.1 (*CONTROL_CONTACT
     * default); shell offsets t/2 x SFST */
    d.penalty_scale = (dk->slsfac > 0 ? dk->slsfac : 0.1) * k->sfs;
    /* non-automatic contacts: LS-DYNA leaves the shell thickness out unless SHLTHK >= 1 */
    int shells = 0;
    for (int j = 0; j < dk->elem[FE_KW_SHELL].n && !k->automatic && dk->shlthk == 0; j++) {
        int pk = deck_part_index(dk, dk->elem[FE_KW_SHELL].pid[j]);
        for (int q = 0; q < sl->n + ms->n && pk >= 0 && !shells; q++)
            shells = strcmp(q < sl->n ? sl->part[q] : ms->part[q - sl->n], c->names[pk]) == 0;
        if (shells) break;
    }
    if (shells)
        mcs_log(MCS_LOG_WARN,
                "%s:%d: warning: *%s: shells meet at their t/2 offsets (x SFST), "
                "as in LS-DYNA's automatic contacts; its non-automatic ones leave the "
                "thickness out unless *CONTROL_CONTACT SHLTHK >= 1",
                dk->file[k->loc.file], k->loc.line, ct_name(k));
    d.thickness_scale = k->sfst;
    mcs_error kerr = {0};
    st = fe_builder_add_contact(c->b, &d, &kerr);
    if (st) return kw_at(dk, k->loc, c->err, st, "*%s: %s", ct_name(k), kerr.msg);
    return MCS_OK;
}

/* ---- node velocities, prescribed motions, loads ---- */

/* builder node of deck node nid; -1 (with a warning) when it belongs to no element */
static mcs_status node_of(const kb *c, int nid, fe_kw_loc l, const char *what, int *node)
{
    int di = fe_kw_node_index(c->dk, nid);
    if (di < 0) return kw_at(c->dk, l, c->err, MCS_ERR_KEY, "*%s: node %d is not defined", what, nid);
    *node = c->map[di];
    if (*node < 0)
        mcs_log(MCS_LOG_WARN, "%s:%d: warning: *%s: node %d belongs to no element: ignored",
                c->dk->file[l.file], l.line, what, nid);
    return MCS_OK;
}

static mcs_status add_node_velocities(const kb *c)
{
    for (int i = 0; i < c->dk->nnodevel; i++) {
        const fe_kw_nodevel *v = &c->dk->nodevel[i];
        if (v->vr[0] != 0 || v->vr[1] != 0 || v->vr[2] != 0)
            return kw_at(c->dk, v->loc, c->err, MCS_ERR_UNSUPPORTED,
                      "*INITIAL_VELOCITY_NODE: node %d: rotational velocity (VXR, VYR, VZR) is "
                      "not built",
                      v->nid);
        int node = -1;
        mcs_status st = node_of(c, v->nid, v->loc, "INITIAL_VELOCITY_NODE", &node);
        if (!st && node >= 0) st = fe_builder_node_velocity(c->b, node, v->v, c->err);
        if (st) return st;
    }
    return MCS_OK;
}

static const char *pm_name(fe_kw_target on)
{
    return on == FE_KW_ON_NODE      ? "BOUNDARY_PRESCRIBED_MOTION_NODE"
           : on == FE_KW_ON_NODESET ? "BOUNDARY_PRESCRIBED_MOTION_SET"
                                    : "BOUNDARY_PRESCRIBED_MOTION_RIGID";
}

/* the constant velocity a motion's curve gives: VAD 0 a constant ordinate, VAD 2 a
 * displacement d = v t through the origin (relative tolerance 1e-9) [m/s] */
static mcs_status motion_velocity(const kb *c, const fe_kw_pmotion *m, double *v)
{
    const fe_kw_deck *dk = c->dk;
    const fe_kw_curve *cv = fe_kw_find_curve(dk, m->lcid);
    char skip[400];
    if (!cv)
        return kw_at(dk, m->loc, c->err, MCS_ERR_KEY, "*%s: LCID %d is not defined%s", pm_name(m->on),
                  m->lcid, fe_kw_skipped(dk, "DEFINE_", skip, sizeof skip));
    double ymax = 0, k = 0;
    for (int i = 0; i < cv->n; i++)
        ymax = fmax(ymax, fabs(cv->xy[2 * i + 1]));
    if (m->vad == 0) {
        k = cv->xy[1];
        for (int i = 0; i < cv->n; i++)
            if (fabs(cv->xy[2 * i + 1] - k) > 1e-9 * ymax) k = NAN;
    } else {
        const double tl = cv->xy[2 * (cv->n - 1)];
        k = tl != 0 ? cv->xy[2 * (cv->n - 1) + 1] / tl : NAN;
        for (int i = 0; i < cv->n && isfinite(k); i++)
            if (fabs(cv->xy[2 * i + 1] - k * cv->xy[2 * i]) > 1e-9 * ymax) k = NAN;
    }
    if (!isfinite(k))
        return kw_at(dk, m->loc, c->err, MCS_ERR_UNSUPPORTED,
                  "*%s: curve %d: a motion that varies in time is not built on nodes; a "
                  "constant velocity is (VAD 0 with a constant curve, VAD 2 with a "
                  "displacement d = v t)",
                  pm_name(m->on), m->lcid);
    *v = k * m->sf * dk->unit[0] / dk->unit[1];
    return MCS_OK;
}

static mcs_status fix_nodes(const kb *c, const fe_kw_pmotion *m, const int *nodes, int n, double v)
{
    unsigned mask = 1u << (m->dof <= 3 ? m->dof - 1 : m->dof - 2);
    double vel[3] = {0, 0, 0};
    if (m->dof <= 3) vel[m->dof - 1] = v;
    if (m->dof > 3 && v != 0)
        return kw_at(c->dk, m->loc, c->err, MCS_ERR_UNSUPPORTED,
                  "*%s: DOF %d: a prescribed rotation rate is not built (a zero one, a fixed "
                  "rotation, is)",
                  pm_name(m->on), m->dof);
    for (int i = 0; i < n; i++) {
        if (nodes[i] < 0) continue;
        mcs_status st = fe_builder_fix_node(c->b, nodes[i], mask, vel, c->err);
        if (st) return st;
    }
    return MCS_OK;
}

static mcs_status add_motion(const kb *c, const fe_kw_pmotion *m)
{
    const fe_kw_deck *dk = c->dk;
    double v = 0;
    mcs_status st = motion_velocity(c, m, &v);
    if (st) return st;
    if (m->on == FE_KW_ON_PART) {
        int pk = deck_part_index(dk, m->id), ip = pk < 0 ? -1 : model_part(c, pk);
        if (ip < 0)
            return kw_at(dk, m->loc, c->err, MCS_ERR_KEY, "*%s: part %d is not in the model",
                      pm_name(m->on), m->id);
        if (!fe_builder_part_rigid(c->b, ip))
            return kw_at(dk, m->loc, c->err, MCS_ERR_TYPE, "*%s: part %d is not rigid (*MAT_RIGID)",
                      pm_name(m->on), m->id);
        int nn = fe_builder_nnode(c->b);
        int *idx = malloc(sizeof(int) * (size_t)(nn ? nn : 1));
        if (!idx) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        int cnt = fe_builder_select(c->b, ip, FE_WHERE_ALL, idx, nn);
        st = fix_nodes(c, m, idx, cnt, v);
        free(idx);
        return st;
    }
    if (m->on == FE_KW_ON_NODE) {
        int node = -1;
        st = node_of(c, m->id, m->loc, pm_name(m->on), &node);
        return st ? st : fix_nodes(c, m, &node, 1, v);
    }
    const fe_kw_set *s = fe_kw_find_set(dk, m->id, 0);
    char skip[400];
    if (!s)
        return kw_at(dk, m->loc, c->err, MCS_ERR_KEY, "*%s: node set %d is not defined%s",
                  pm_name(m->on), m->id, fe_kw_skipped(dk, "SET_", skip, sizeof skip));
    for (int i = 0; i < s->n && !st; i++) {
        int node = -1;
        st = node_of(c, s->ids[i], m->loc, pm_name(m->on), &node);
        if (!st) st = fix_nodes(c, m, &node, 1, v);
    }
    return st;
}

static mcs_status add_load(const kb *c, const fe_kw_load *l)
{
    const fe_kw_deck *dk = c->dk;
    const char *kw = l->segment == 1 ? "LOAD_SEGMENT"
                     : l->segment    ? "LOAD_NODE_SET"
                                     : "LOAD_NODE_POINT";
    if (l->segment == 1 && l->at != 0)
        return kw_at(dk, l->loc, c->err, MCS_ERR_UNSUPPORTED,
                  "*LOAD_SEGMENT: field AT: an arrival time is not built (leave 0)");
    const fe_kw_curve *cv = fe_kw_find_curve(dk, l->lcid);
    char skip[400];
    if (!cv)
        return kw_at(dk, l->loc, c->err, MCS_ERR_KEY, "*%s: LCID %d is not defined%s", kw, l->lcid,
                  fe_kw_skipped(dk, "DEFINE_", skip, sizeof skip));
    if (cv->n > FE_CURVE_MAX)
        return kw_at(dk, l->loc, c->err, MCS_ERR_RANGE,
                  "*%s: curve %d has %d points; a load takes "
                  "at most %d",
                  kw, l->lcid, cv->n, FE_CURVE_MAX);
    double curve[FE_CURVE_MAX][2], f[3] = {0, 0, 0};
    for (int i = 0; i < cv->n; i++)
        curve[i][0] = cv->xy[2 * i] * dk->unit[1], curve[i][1] = cv->xy[2 * i + 1];
    if (l->segment == 1) { /* a pressure SF x curve(t) [force / length^2], follows the segment */
        int q[4];
        for (int j = 0; j < 4; j++) {
            mcs_status st = node_of(c, l->node[j] ? l->node[j] : l->node[2], l->loc, kw, &q[j]);
            if (st) return st;
            if (q[j] < 0)
                return kw_at(dk, l->loc, c->err, MCS_ERR_KEY,
                          "*LOAD_SEGMENT: node %d belongs to no element", l->node[j]);
        }
        mcs_error kerr = {0};
        mcs_status st = fe_builder_add_pressure(c->b, q, l->sf * kw_u_stress(dk), cv->n,
                                                (const double(*)[2])curve, &kerr);
        return st ? kw_at(dk, l->loc, c->err, st, "*LOAD_SEGMENT: %s", kerr.msg) : MCS_OK;
    }
    /* force unit: mass x length / time^2 */
    f[l->dof - 1] = l->sf * dk->unit[2] * dk->unit[0] / (dk->unit[1] * dk->unit[1]);
    const fe_kw_set *s = l->segment == 2 ? fe_kw_find_set(dk, l->nid, 0) : NULL;
    if (l->segment == 2 && !s)
        return kw_at(dk, l->loc, c->err, MCS_ERR_KEY, "*%s: node set %d is not defined%s", kw, l->nid,
                  fe_kw_skipped(dk, "SET_", skip, sizeof skip));
    int n = s ? s->n : 1;
    for (int i = 0; i < n; i++) { /* LOAD_NODE_SET: each node of the set takes the load */
        int node = -1;
        mcs_status st = node_of(c, s ? s->ids[i] : l->nid, l->loc, kw, &node);
        if (!st && node >= 0)
            st = fe_builder_add_nodal_load(c->b, node, f, cv->n, (const double(*)[2])curve, c->err);
        if (st) return st;
    }
    return MCS_OK;
}

mcs_status kw_add_deck_more(fe_builder *b, const fe_kw_deck *dk, const char (*names)[FE_NAME_MAX],
                            const int *map, mcs_error *err)
{
    kb c = {b, dk, names, map, err};
    if (dk->rwpnal > 0 && dk->nwall > 0)
        return kw_at(dk, dk->control_contact, err, MCS_ERR_UNSUPPORTED,
                  "*CONTROL_CONTACT: RWPNAL %g asks penalty rigid walls; the deck's walls are "
                  "built as constraint walls (leave RWPNAL 0)",
                  dk->rwpnal);
    mcs_status st = add_node_velocities(&c);
    for (int i = 0; i < dk->npmotion && !st; i++)
        st = add_motion(&c, &dk->pmotion[i]);
    for (int i = 0; i < dk->nload && !st; i++)
        st = add_load(&c, &dk->load[i]);
    for (int i = 0; i < dk->ncontact && !st; i++)
        st = add_contact(&c, i);
    return st;
}

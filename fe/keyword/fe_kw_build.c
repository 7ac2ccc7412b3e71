/* fe_kw_build: a keyword deck into an fe_builder: sections and materials as kernel
 * descriptors, one part's nodes and elements, or the whole deck with its constraints, initial
 * velocities and rigid walls. Errors point at the deck line that defined the culprit. */
#include "fe/fe_kw_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static mcs_status section_desc(const fe_kw_deck *dk, const fe_kw_part *p, fe_section_desc *s,
                               mcs_error *err)
{
    const fe_kw_section *k = fe_kw_find_section(dk, p->secid);
    char skip[400];
    if (!k)
        return kw_at(dk, p->loc, err, MCS_ERR_KEY, "*PART %d: section %d is not defined%s", p->id,
                  p->secid, fe_kw_skipped(dk, "SECTION_", skip, sizeof skip));
    if (k->kind == FE_KW_SEC_SHELL) {
        if (k->elform != 0 && k->elform != 2)
            mcs_log(MCS_LOG_WARN, "%s:%d: warning: *SECTION_SHELL %d: ELFORM %d is run as "
                                  "Belytschko-Tsay (ELFORM 2), the only shell built",
                    dk->file[k->loc.file], k->loc.line, k->id, k->elform);
        s->type = FE_SECTION_SHELL;
        s->thickness = k->t[0];
        s->integration_points = k->nip > 0 ? k->nip : 2; /* LS-DYNA's default NIP */
        s->shear_factor = k->shrf > 0 && k->shrf <= 1 ? k->shrf : 0;
        /* T1 blank: every shell of the part gives its own (*ELEMENT_SHELL_THICKNESS); the
         * part's nominal thickness is then its first shell's. T1..T4 or THIC1..THIC4 that
         * differ: each shell gets the mean of its nodes' (add_elems) */
        for (int i = 0; i < dk->elem[FE_KW_SHELL].n && !(s->thickness > 0); i++)
            if (dk->elem[FE_KW_SHELL].pid[i] == p->id) s->thickness = kw_shell_thickness(dk, k, i);
        if (!(s->thickness > 0))
            return kw_at(dk, k->loc, err, MCS_ERR_RANGE,
                      "*SECTION_SHELL %d: T1 must be > 0 (or every shell give THIC1..THIC4)",
                      k->id);
    } else if (k->kind == FE_KW_SEC_TSHELL) {
        return kw_at(dk, k->loc, err, MCS_ERR_UNSUPPORTED,
                  "*SECTION_TSHELL %d: thick shells are not built (docs/keyword.md: one hexahedron "
                  "through the thickness would not bend like them)",
                  k->id);
    } else if (k->kind == FE_KW_SEC_SOLID && k->user) {
        return kw_at(dk, k->loc, err, MCS_ERR_UNSUPPORTED,
                  "*SECTION_SOLID %d: ELFORM %d (a user-defined element) is not built", k->id,
                  k->elform);
    } else if (k->kind == FE_KW_SEC_SOLID) {
        /* ELFORM 16/17 (10-node tetrahedra): fe_kw_add_part decides by the elements */
        if (k->elform != 0 && k->elform != 1 && k->elform != 16 && k->elform != 17)
            mcs_log(MCS_LOG_WARN, "%s:%d: warning: *SECTION_SOLID %d: ELFORM %d is run as the "
                                  "one-point hexahedron with hourglass control (ELFORM 1)",
                    dk->file[k->loc.file], k->loc.line, k->id, k->elform);
        s->type = FE_SECTION_SOLID;
    } else if (k->kind == FE_KW_SEC_DISCRETE) {
        return kw_at(dk, k->loc, err, MCS_ERR_TYPE,
                  "*SECTION_DISCRETE %d belongs to *ELEMENT_DISCRETE parts", k->id);
    } else {
        return kw_beam_section(dk, k, s, err); /* fe_kw_build_elem.c */
    }
    return kw_part_hourglass(dk, p, s, err); /* *HOURGLASS, *CONTROL_HOURGLASS */
}

/* MAT_024 hardening: LCSS curve, else the EPS/ES table, else ETAN (bilinear) */
static mcs_status hardening(const fe_kw_deck *dk, const fe_kw_mat *k, fe_material_desc *m,
                            mcs_error *err)
{
    double x[FE_CURVE_MAX + 1], y[FE_CURVE_MAX + 1];
    int n = 0;
    if (k->lcss) {
        const fe_kw_curve *c = fe_kw_find_curve(dk, k->lcss);
        if (!c)
            return kw_at(dk, k->loc, err, MCS_ERR_KEY,
                      "*MAT_024 %d: LCSS %d is not a *DEFINE_CURVE (tables are not built)", k->id,
                      k->lcss);
        if (c->n > FE_CURVE_MAX)
            return kw_at(dk, c->loc, err, MCS_ERR_RANGE,
                      "*DEFINE_CURVE %d: %d points; a hardening curve holds at most %d", c->id,
                      c->n, FE_CURVE_MAX);
        for (int i = 0; i < c->n; i++) {
            x[n] = c->xy[2 * i];
            y[n++] = c->xy[2 * i + 1] * kw_u_stress(dk);
        }
    } else if (k->neps > 0) {
        for (int i = 0; i < k->neps; i++) x[n] = k->eps[i], y[n++] = k->es[i];
    } else if (k->etan > 0) {
        /* bilinear: tangent modulus Et -> plastic modulus H = E Et / (E - Et) */
        if (!(k->etan < k->e))
            return kw_at(dk, k->loc, err, MCS_ERR_RANGE, "*MAT_024 %d: ETAN must be below E", k->id);
        x[0] = 0, y[0] = k->sigy, x[1] = 1, y[1] = k->sigy + k->e * k->etan / (k->e - k->etan);
        n = 2;
    }
    int off = n > 0 && x[0] > 0 ? 1 : 0; /* the table starts at zero plastic strain */
    if (n + off > FE_CURVE_MAX)
        return kw_at(dk, k->loc, err, MCS_ERR_RANGE, "*MAT_024 %d: more than %d hardening points",
                  k->id, FE_CURVE_MAX);
    if (off) m->hardening[0][0] = 0, m->hardening[0][1] = k->sigy;
    for (int i = 0; i < n; i++) m->hardening[off + i][0] = x[i], m->hardening[off + i][1] = y[i];
    m->nhardening = n + off;
    if (m->nhardening > 0 && !(m->hardening[0][1] > 0))
        return kw_at(dk, k->loc, err, MCS_ERR_RANGE,
                  "*MAT_024 %d: the yield stress (SIGY, or the curve at zero plastic strain) must "
                  "be > 0",
                  k->id);
    if (m->nhardening > 0) m->yield_stress = m->hardening[0][1];
    return MCS_OK;
}

static mcs_status material_desc(const fe_kw_deck *dk, const fe_kw_part *p, fe_material_desc *m,
                                mcs_error *err)
{
    const fe_kw_mat *k = fe_kw_find_mat(dk, p->mid);
    char skip[400];
    if (!k)
        return kw_at(dk, p->loc, err, MCS_ERR_KEY, "*PART %d: material %d is not defined%s", p->id,
                  p->mid, fe_kw_skipped(dk, "MAT", skip, sizeof skip));
    if (k->type == FE_KW_MAT_SPRING || k->type == FE_KW_MAT_DAMPER)
        return kw_at(dk, k->loc, err, MCS_ERR_TYPE,
                  "material %d is a spring or damper: it belongs to *ELEMENT_DISCRETE parts",
                  k->id);
    memset(m, 0, sizeof *m);
    m->density = k->ro;
    m->youngs_modulus = k->e;
    m->poisson = k->pr;
    mcs_status st;
    if (kw_mat_desc(dk, k, m, err, &st)) return st; /* fe_kw_cards_mat.c */
    if (k->type == FE_KW_MAT_ELASTIC) {
        m->model = FE_MAT_ELASTIC;
        return MCS_OK;
    }
    m->model = FE_MAT_ELASTIC_PLASTIC;
    m->yield_stress = k->sigy;
    m->cowper_symonds_c = k->c;
    m->cowper_symonds_p = k->c > 0 ? k->p : 0;
    m->failure_strain = k->fail; /* FAIL: element erosion */
    return hardening(dk, k, m, err);
}

mcs_status fe_kw_part_props(const fe_kw_deck *dk, int pid, fe_part_desc *d, mcs_error *err)
{
    const fe_kw_part *p = fe_kw_find_part(dk, pid);
    char skip[400];
    if (!p)
        return MCS_ERR(err, MCS_ERR_KEY, "%s: error: no *PART %d (its section and material)%s",
                       dk->nfile ? dk->file[0] : "(deck)", pid,
                       fe_kw_skipped(dk, "PART", skip, sizeof skip));
    mcs_status st = section_desc(dk, p, &d->section, err);
    if (!st) st = material_desc(dk, p, &d->material, err);
    if (!st) st = kw_part_inertia(dk, p, d, err); /* *PART_INERTIA */
    return st;
}

/* the element type of part pid (-1: none; -2: several) */
static int part_etype(const fe_kw_deck *dk, int pid)
{
    int t0 = -1;
    for (int t = 0; t < FE_KW_NETYPE; t++)
        for (int i = 0; i < dk->elem[t].n; i++)
            if (dk->elem[t].pid[i] == pid) {
                if (t0 >= 0 && t0 != t) return -2;
                t0 = t;
                break;
            }
    return t0;
}

static const fe_section_type etype_section[FE_KW_NETYPE] = {
    FE_SECTION_SHELL, FE_SECTION_SOLID, FE_SECTION_TRUSS, FE_SECTION_TRUSS, FE_SECTION_TET10,
    FE_SECTION_SOLID};

/* shells of a part whose section is the deck's (sec; NULL otherwise) get their own thickness
 * where it differs from the part's (nominal) */
static mcs_status add_elems(fe_builder *b, const fe_kw_deck *dk, int pid, fe_kw_etype t, int ip,
                            const int *map, const fe_kw_section *sec, double nominal,
                            mcs_error *err)
{
    const fe_kw_elems *e = &dk->elem[t];
    const int k = fe_kw_etype_nnode(t);
    for (int i = 0; i < e->n; i++) {
        if (e->pid[i] != pid) continue;
        int c[10];
        for (int j = 0; j < k; j++) c[j] = map[fe_kw_node_index(dk, e->node[(size_t)k * i + j])];
        /* solids: tetrahedra and pentahedra are checked and reordered by the builder */
        mcs_error kerr = {0};
        mcs_status st;
        double th = t == FE_KW_SHELL && sec ? kw_shell_thickness(dk, sec, i) : 0;
        if (t == FE_KW_SHELL && sec && !(th > 0))
            return kw_at(dk, e->loc[i], err, MCS_ERR_RANGE,
                      "*ELEMENT_SHELL %d: no thickness (THIC1..THIC4 blank, section T1 0)",
                      e->id[i]);
        if (th > 0 && fabs(th - nominal) > 1e-12 * nominal)
            st = fe_builder_add_shell(b, ip, c, th, &kerr); /* a thickness of its own */
        else
            st = fe_builder_add_elem(b, ip, c, &kerr);
        if (st)
            return kw_at(dk, e->loc[i], err, st, "*ELEMENT_%s %d: %s", fe_kw_etype_name(t), e->id[i],
                      kerr.msg);
    }
    return MCS_OK;
}

mcs_status fe_kw_add_part(fe_builder *b, const fe_kw_deck *dk, int pid, const fe_part_desc *base,
                          int props_from_deck, int *node_map, int *index, mcs_error *err)
{
    const char *fn = dk->nfile ? dk->file[0] : "(deck)";
    int t = part_etype(dk, pid);
    char skip[400];
    if (t == -1)
        return MCS_ERR(err, MCS_ERR_KEY, "%s: error: no element has part ID %d%s", fn, pid,
                       fe_kw_skipped(dk, "ELEMENT_", skip, sizeof skip));
    if (t == -2)
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                       "%s: error: part %d mixes element types; a part holds one type", fn, pid);
    if (t == FE_KW_TSHELL) {
        const fe_kw_elems *e = &dk->elem[FE_KW_TSHELL];
        int i = 0;
        while (e->pid[i] != pid) i++;
        const char *efn = e->loc[i].file < dk->nfile ? dk->file[e->loc[i].file] : fn;
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                       "%s:%d: error: *ELEMENT_TSHELL %d (part %d): thick shells are not built "
                       "(one hexahedron through the thickness would not bend like them: "
                       "docs/keyword.md)",
                       efn, e->loc[i].line, e->id[i], pid);
    }
    if (t == FE_KW_DISCRETE)
        return MCS_ERR(err, MCS_ERR_UNSUPPORTED,
                       "%s: error: part %d holds *ELEMENT_DISCRETE springs, not a continuum "
                       "part: read the whole deck (fe_kw_add_deck) or give fe.springs",
                       fn, pid);
    fe_part_desc d = *base;
    d.mesh.generate = FE_MESH_NONE;
    mcs_status st = props_from_deck ? fe_kw_part_props(dk, pid, &d, err) : MCS_OK;
    if (st) return st;
    /* a solid section on 10-node tetrahedra is the tet10 (LS-DYNA ELFORM 16/17) */
    if (t == FE_KW_TET10 && d.section.type == FE_SECTION_SOLID) {
        d.section.type = FE_SECTION_TET10;
        d.section.formulation = FE_HEX_ONE_POINT;
    }
    /* shells carry a shell section, or the scenario's membrane (a gas bag's fabric) */
    int membrane = t == FE_KW_SHELL && d.section.type == FE_SECTION_MEMBRANE;
    if (d.section.type != etype_section[t] && !membrane)
        return MCS_ERR(err, MCS_ERR_TYPE,
                       "%s: error: part %d has *ELEMENT_%s elements; its section must be %s", fn,
                       pid, fe_kw_etype_name((fe_kw_etype)t),
                       t == FE_KW_SHELL                        ? "shell or membrane"
                       : t == FE_KW_SOLID || t == FE_KW_TET10 ? "solid"
                                                               : "truss");
    int *map = node_map, ip = -1;
    if (!map) {
        map = malloc(sizeof(int) * (size_t)(dk->nnode ? dk->nnode : 1));
        if (!map) return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
        for (int i = 0; i < dk->nnode; i++) map[i] = -1;
    }
    unsigned char *used = calloc((size_t)(dk->nnode ? dk->nnode : 1), 1);
    if (!used) st = MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
    if (!st) st = fe_builder_add_part(b, &d, &ip, err);
    if (!st) {
        const fe_kw_elems *e = &dk->elem[t];
        int k = fe_kw_etype_nnode((fe_kw_etype)t);
        for (int i = 0; i < e->n; i++)
            if (e->pid[i] == pid)
                for (int j = 0; j < k; j++) used[fe_kw_node_index(dk, e->node[(size_t)k * i + j])] = 1;
        /* nodes in ascending ID order, each once per map */
        for (int i = 0; i < dk->nnode && !st; i++)
            if (used[i] && map[i] < 0) st = fe_builder_add_node(b, dk->node_x + 3 * i, &map[i], err);
    }
    if (!st) {
        const fe_kw_part *kp = fe_kw_find_part(dk, pid);
        const fe_kw_section *sec =
            props_from_deck && kp && d.section.type == FE_SECTION_SHELL
                ? fe_kw_find_section(dk, kp->secid)
                : NULL;
        st = add_elems(b, dk, pid, (fe_kw_etype)t, ip, map, sec, d.section.thickness, err);
    }
    if (!st && index) *index = ip;
    free(used);
    if (map != node_map) free(map);
    return st;
}

/* ---- the whole deck ---- */

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return x < y ? -1 : x > y;
}

static int in_sorted(const int *v, int n, int x)
{
    return bsearch(&x, v, (size_t)n, sizeof(int), cmp_int) != NULL;
}

/* how a node set covers part pid: 1 every node, 0 none, -1 some */
static int set_covers(const fe_kw_deck *dk, const int *ids, int nids, int pid)
{
    int some = 0, all = 1;
    for (int t = 0; t < FE_KW_NETYPE; t++) {
        const fe_kw_elems *e = &dk->elem[t];
        int k = fe_kw_etype_nnode((fe_kw_etype)t);
        for (int i = 0; i < e->n; i++) {
            if (e->pid[i] != pid) continue;
            for (int j = 0; j < k; j++) {
                int in = in_sorted(ids, nids, e->node[(size_t)k * i + j]);
                some |= in;
                all &= in;
            }
        }
    }
    return all ? 1 : some ? -1 : 0;
}

/* sorted copy of a node set's IDs (*ids NULL, *n -1 for set 0 = every node) */
static mcs_status set_ids(const fe_kw_deck *dk, int sid, fe_kw_loc l, int **ids, int *n,
                          mcs_error *err)
{
    *ids = NULL;
    *n = -1;
    if (sid == 0) return MCS_OK;
    const fe_kw_set *s = fe_kw_find_set(dk, sid, 0);
    char skip[400];
    if (!s)
        return kw_at(dk, l, err, MCS_ERR_KEY, "node set %d is not defined%s", sid,
                  fe_kw_skipped(dk, "SET_", skip, sizeof skip));
    *ids = malloc(sizeof(int) * (size_t)(s->n ? s->n : 1));
    if (!*ids) return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
    memcpy(*ids, s->ids, sizeof(int) * (size_t)s->n);
    qsort(*ids, (size_t)s->n, sizeof(int), cmp_int);
    *n = s->n;
    return MCS_OK;
}

/* does initial velocity / wall target `on id` cover deck part k? 1 yes, 0 no, -1 partly */
static mcs_status covers(const fe_kw_deck *dk, fe_kw_target on, int id, fe_kw_loc l, int k,
                         int *out, mcs_error *err)
{
    int pid = dk->part[k].id;
    if (on == FE_KW_ON_PART) {
        *out = id == pid;
        return MCS_OK;
    }
    if (on == FE_KW_ON_PARTSET) {
        const fe_kw_set *s = fe_kw_find_set(dk, id, 1);
        char skip[400];
        if (!s)
            return kw_at(dk, l, err, MCS_ERR_KEY, "part set %d is not defined%s", id,
                      fe_kw_skipped(dk, "SET_", skip, sizeof skip));
        *out = 0;
        for (int i = 0; i < s->n; i++) *out |= s->ids[i] == pid;
        return MCS_OK;
    }
    int *ids, n;
    mcs_status st = set_ids(dk, id, l, &ids, &n, err);
    if (st) return st;
    *out = n < 0 ? 1 : set_covers(dk, ids, n, pid);
    free(ids);
    return MCS_OK;
}

static mcs_status part_velocity(const fe_kw_deck *dk, int k, double v[3], mcs_error *err)
{
    for (int i = 0; i < dk->niv; i++) {
        const fe_kw_initvel *iv = &dk->iv[i];
        int c = 0;
        mcs_status st = covers(dk, iv->on, iv->id, iv->loc, k, &c, err);
        if (st) return st;
        if (c < 0)
            return kw_at(dk, iv->loc, err, MCS_ERR_UNSUPPORTED,
                      "initial velocity on part of the nodes of part %d: only whole parts are "
                      "built",
                      dk->part[k].id);
        if (c && (iv->vr[0] != 0 || iv->vr[1] != 0 || iv->vr[2] != 0))
            return kw_at(dk, iv->loc, err, MCS_ERR_UNSUPPORTED,
                      "rotational initial velocity (VXR, VYR, VZR) is not built");
        if (c) memcpy(v, iv->v, 3 * sizeof(double));
    }
    return MCS_OK;
}

static mcs_status add_spcs(fe_builder *b, const fe_kw_deck *dk, const int *map, mcs_error *err)
{
    for (int i = 0; i < dk->nspc; i++) {
        const fe_kw_spc *s = &dk->spc[i];
        int *ids = NULL, n = 1, one = s->id;
        if (s->on == FE_KW_ON_NODESET) {
            mcs_status st = set_ids(dk, s->id, s->loc, &ids, &n, err);
            if (st) return st;
            if (n < 0) n = 0;
        }
        mcs_status st = MCS_OK;
        for (int j = 0; j < n && !st; j++) {
            int nid = ids ? ids[j] : one, di = fe_kw_node_index(dk, nid);
            if (di < 0) {
                st = kw_at(dk, s->loc, err, MCS_ERR_KEY, "constraint on node %d, which is not "
                                                      "defined",
                        nid);
            } else if (map[di] >= 0) {
                double zero[3] = {0, 0, 0};
                st = fe_builder_fix_node(b, map[di], s->dof, zero, err);
            } else {
                mcs_log(MCS_LOG_WARN, "%s:%d: warning: constraint on node %d, which belongs to "
                                      "no element: ignored",
                        dk->file[s->loc.file], s->loc.line, nid);
            }
        }
        free(ids);
        if (st) return st;
    }
    return MCS_OK;
}

/* the deck wall a motion's ID names: the wall with that _ID, else the ID-th wall; -1 none */
static int motion_wall(const fe_kw_deck *dk, int id)
{
    for (int j = 0; j < dk->nwall; j++)
        if (dk->wall[j].id == id) return j;
    return id >= 1 && id <= dk->nwall ? id - 1 : -1;
}

/* the motions of deck wall w: curve abscissa in the deck's time unit, ordinate x SF in its
 * velocity, acceleration or length unit */
static mcs_status wall_motions(const fe_kw_deck *dk, int w, fe_wall_desc *d, mcs_error *err)
{
    const double T = dk->unit[1], L = dk->unit[0];
    for (int i = 0; i < dk->nwmotion; i++) {
        const fe_kw_wmotion *mo = &dk->wmotion[i];
        const int j = motion_wall(dk, mo->wall);
        if (j < 0) return kw_at(dk, mo->loc, err, MCS_ERR_KEY, "rigid wall %d is not defined", mo->wall);
        if (j != w) continue;
        const fe_kw_curve *c = fe_kw_find_curve(dk, mo->lcid);
        char skip[400];
        if (!c)
            return kw_at(dk, mo->loc, err, MCS_ERR_KEY, "LCID %d is not defined%s", mo->lcid,
                      fe_kw_skipped(dk, "DEFINE_", skip, sizeof skip));
        if (d->nmotion >= FE_WALL_NMOTION || c->n > FE_CURVE_MAX)
            return kw_at(dk, mo->loc, err, MCS_ERR_RANGE,
                      "a wall takes at most %d motions of at most %d curve points",
                      FE_WALL_NMOTION, FE_CURVE_MAX);
        fe_wall_motion *m = &d->motion[d->nmotion++];
        static const fe_motion_kind kind[3] = {FE_MOTION_VELOCITY, FE_MOTION_ACCELERATION,
                                               FE_MOTION_DISPLACEMENT};
        const double unit[3] = {L / T, L / (T * T), L};
        m->kind = kind[mo->vad];
        m->direction[mo->dof - 1] = 1;
        m->ncurve = c->n;
        for (int p = 0; p < c->n; p++) {
            m->curve[p][0] = c->xy[2 * p] * T;
            m->curve[p][1] = c->xy[2 * p + 1] * mo->sf * unit[mo->vad];
        }
    }
    return MCS_OK;
}

static mcs_status add_walls(fe_builder *b, const fe_kw_deck *dk, char (*names)[FE_NAME_MAX],
                            mcs_error *err)
{
    for (int w = 0; w < dk->nwall; w++) {
        const fe_kw_wall *k = &dk->wall[w];
        if (!(k->fric >= 0 && k->fric <= 1))
            return kw_at(dk, k->loc, err, MCS_ERR_UNSUPPORTED,
                      "FRIC %g: 0 (frictionless), Coulomb 0 < FRIC < 1 and 1 (no sliding) are "
                      "built, not welding (2, 3)",
                      k->fric);
        fe_wall_desc d = {.method = FE_WALL_KINEMATIC, .friction = k->fric};
        if (k->title[0] && strlen(k->title) < FE_NAME_MAX) memcpy(d.name, k->title, strlen(k->title) + 1);
        else snprintf(d.name, sizeof d.name, "wall_%d", k->id ? k->id : w + 1);
        for (int i = 0; i < 3; i++) {
            d.point[i] = k->tail[i];
            d.normal[i] = k->head[i] - k->tail[i];
        }
        if (k->moving) {
            /* a free wall with mass, V0 along the normal: the constraint method, as LS-DYNA
             * treats rigid walls by default (fe_wall_kin.c) */
            double nn = sqrt(d.normal[0] * d.normal[0] + d.normal[1] * d.normal[1] +
                             d.normal[2] * d.normal[2]);
            d.mass = k->mass;
            for (int i = 0; i < 3; i++) d.velocity[i] = k->v0 * d.normal[i] / nn;
        }
        mcs_status mst = wall_motions(dk, w, &d, err); /* *BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL */
        if (mst) return mst;
        for (int p = 0; p < dk->npart && k->nsid; p++) {
            int c = 0;
            mcs_status st = covers(dk, FE_KW_ON_NODESET, k->nsid, k->loc, p, &c, err);
            if (st) return st;
            if (c < 0)
                return kw_at(dk, k->loc, err, MCS_ERR_UNSUPPORTED,
                          "NSID %d holds part of the nodes of part %d: walls stop whole parts",
                          k->nsid, dk->part[p].id);
            if (c && d.nparts >= 8)
                return kw_at(dk, k->loc, err, MCS_ERR_RANGE, "a wall stops at most 8 parts");
            if (c) snprintf(d.parts[d.nparts++], FE_NAME_MAX, "%s", names[p]);
        }
        if (k->nsid && d.nparts == 0)
            return kw_at(dk, k->loc, err, MCS_ERR_RANGE, "NSID %d holds no node of any part",
                      k->nsid);
        mcs_status st = fe_builder_add_wall(b, &d, err);
        if (st) return st;
    }
    return MCS_OK;
}

/* the *ELEMENT_DISCRETE of part p as springs (*MAT_S01) or dampers (*MAT_S02), force x S */
static mcs_status add_springs(fe_builder *b, const fe_kw_deck *dk, const fe_kw_part *p,
                              const char *pname, int *map,
                              mcs_error *err)
{
    const fe_kw_section *s = fe_kw_find_section(dk, p->secid);
    const fe_kw_mat *m = fe_kw_find_mat(dk, p->mid);
    if (!s || s->kind != FE_KW_SEC_DISCRETE)
        return kw_at(dk, p->loc, err, MCS_ERR_KEY, "*PART %d: discrete elements need a "
                                                "*SECTION_DISCRETE (SECID %d)",
                  p->id, p->secid);
    if (s->elform != 0)
        return kw_at(dk, s->loc, err, MCS_ERR_UNSUPPORTED,
                  "*SECTION_DISCRETE %d: DRO %d (torsional) is not built", s->id, s->elform);
    if (!m || (m->type != FE_KW_MAT_SPRING && m->type != FE_KW_MAT_DAMPER))
        return kw_at(dk, p->loc, err, MCS_ERR_KEY,
                  "*PART %d: discrete elements need *MAT_SPRING_ELASTIC or *MAT_DAMPER_VISCOUS "
                  "(MID %d)",
                  p->id, p->mid);
    const fe_kw_elems *e = &dk->elem[FE_KW_DISCRETE];
    for (int i = 0; i < e->n; i++) {
        if (e->pid[i] != p->id) continue;
        double S = e->dval[2 * i];
        if (e->node[2 * i + 1] == 0 || e->dval[2 * i + 1] != 0 || !(S > 0))
            return kw_at(dk, e->loc[i], err, MCS_ERR_UNSUPPORTED,
                      "*ELEMENT_DISCRETE %d: N2 = 0 (to ground), OFFSET and S <= 0 are not built",
                      e->id[i]);
        fe_spring_desc d;
        memset(&d, 0, sizeof d);
        snprintf(d.name, sizeof d.name, "discrete_%d", e->id[i]);
        snprintf(d.part, sizeof d.part, "%s", pname); /* energies reported per deck part */
        for (int j = 0; j < 2; j++) {
            int di = fe_kw_node_index(dk, e->node[2 * i + j]);
            mcs_status st = map[di] >= 0 ? MCS_OK
                                         : fe_builder_add_node(b, dk->node_x + 3 * di, &map[di], err);
            if (st) return st;
            d.end[j].node = map[di];
        }
        if (m->type == FE_KW_MAT_SPRING) d.stiffness = S * m->k;
        else d.damping = S * m->k;
        mcs_error kerr = {0};
        mcs_status st = fe_builder_add_spring(b, &d, &kerr);
        if (st) return kw_at(dk, e->loc[i], err, st, "*ELEMENT_DISCRETE %d: %s", e->id[i], kerr.msg);
    }
    return MCS_OK;
}

mcs_status fe_kw_add_deck(fe_builder *b, const fe_kw_deck *dk, mcs_error *err)
{
    for (int t = 0; t < FE_KW_NETYPE; t++)
        for (int i = 0; i < dk->elem[t].n; i++)
            if (!fe_kw_find_part(dk, dk->elem[t].pid[i])) {
                char skip[400];
                return kw_at(dk, dk->elem[t].loc[i], err, MCS_ERR_KEY,
                          "*ELEMENT_%s %d: part %d has no *PART card%s", fe_kw_etype_name(t),
                          dk->elem[t].id[i], dk->elem[t].pid[i],
                          fe_kw_skipped(dk, "PART", skip, sizeof skip));
            }
    int *map = malloc(sizeof(int) * (size_t)(dk->nnode ? dk->nnode : 1));
    char(*names)[FE_NAME_MAX] = calloc((size_t)(dk->npart ? dk->npart : 1), FE_NAME_MAX);
    mcs_status st = map && names ? MCS_OK : MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
    for (int i = 0; i < dk->nnode && map; i++) map[i] = -1;
    int nempty = 0;
    for (int k = 0; k < dk->npart && !st; k++) {
        const fe_kw_part *p = &dk->part[k];
        fe_part_desc d = fe_part_desc_default();
        int unique = p->title[0] && strlen(p->title) < FE_NAME_MAX;
        for (int j = 0; j < k && unique; j++) unique = strcmp(names[j], p->title) != 0;
        if (unique) memcpy(names[k], p->title, strlen(p->title) + 1);
        else snprintf(names[k], FE_NAME_MAX, "part_%d", p->id);
        memcpy(d.name, names[k], FE_NAME_MAX);
        st = part_velocity(dk, k, d.initial_velocity, err);
        if (!st && part_etype(dk, p->id) == FE_KW_DISCRETE) {
            st = add_springs(b, dk, p, names[k], map, err);
            continue;
        }
        if (!st && part_etype(dk, p->id) == -1) {
            char skip[400];
            mcs_log(MCS_LOG_WARN, "%s:%d: warning: *PART %d has no elements: skipped%s",
                    dk->file[p->loc.file], p->loc.line, p->id,
                    fe_kw_skipped(dk, "ELEMENT_", skip, sizeof skip));
            /* every part empty: say why here rather than "the model has no parts" later */
            if (++nempty == dk->npart)
                st = MCS_ERR(err, MCS_ERR_KEY, "%s: error: no *PART has elements%s", dk->file[0],
                             fe_kw_skipped(dk, "ELEMENT_", skip, sizeof skip));
            continue;
        }
        if (!st) st = fe_kw_add_part(b, dk, p->id, &d, 1, map, NULL, err);
    }
    if (!st) st = kw_add_deck_joint_nodes(b, dk, map, err); /* fe_kw_build_joint.c */
    if (!st) st = add_spcs(b, dk, map, err);
    if (!st) st = add_walls(b, dk, names, err);
    if (!st) st = kw_add_deck_more(b, dk, (const char(*)[FE_NAME_MAX])names, map, err);
    if (!st) st = kw_add_deck_joints(b, dk, (const char(*)[FE_NAME_MAX])names, map, err);
    free(map);
    free(names);
    return st;
}

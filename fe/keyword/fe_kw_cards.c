/* fe_kw_cards: one handler per supported keyword, reading its cards into the deck in SI
 * (field names as in the LS-DYNA manual; layouts in docs/keyword.md). */
#include "fe/fe_kw_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef mcs_status (*kw_handler)(kw_ctx *c, const kw_card *cd, int n);

static mcs_status unsupported_field(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i,
                                    const char *name, const char *why)
{
    /* column of field i: recompute through a zero-width read of the blank check */
    int col = 1;
    for (int k = 0; k < i && k < l->n; k++)
        col += c->fmt == KW_FMT_LONG ? 20 : (c->fmt == KW_FMT_I10 && l->w[k] < 10 ? 10 : l->w[k]);
    if (memchr(cd->s, ',', (size_t)cd->len)) col = 0;
    return kw_fail(c, cd->file, cd->line, col, MCS_ERR_UNSUPPORTED, "field %s: %s", name, why);
}

/* the _TITLE card (ignored except for parts and walls) */
static int title_card(kw_ctx *c, int i) { return i + (c->has_title ? 1 : 0); }

/* the card of a 10-column ID (+ 70-column heading) of _ID keywords */
static mcs_status id_card(kw_ctx *c, const kw_card *cd, int n, int *i, int *id, char *title)
{
    if (!c->has_id) return MCS_OK;
    KW_TRY(kw_need(c, cd, n, *i, 1));
    static const kw_layout l = {1, {10}};
    int fmt = c->fmt;
    c->fmt = KW_FMT_STD; /* the ID card is I10 + A70 in every format */
    mcs_status st = kw_int(c, &cd[*i], &l, 0, "ID", 0, id);
    c->fmt = fmt;
    if (title) kw_text(&cd[*i], 10, 70, title, FE_KW_TITLE_MAX);
    (*i)++;
    return st;
}

/* ---- *TITLE, *NODE, *ELEMENT_* ---- */

static mcs_status h_title(kw_ctx *c, const kw_card *cd, int n)
{
    if (n > 0) kw_text(&cd[0], 0, 80, c->d->title, sizeof c->d->title);
    return MCS_OK;
}

static mcs_status h_none(kw_ctx *c, const kw_card *cd, int n)
{
    (void)c, (void)cd, (void)n;
    return MCS_OK;
}

/* TC/RC codes 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 all */
static unsigned tc_mask(int code)
{
    static const unsigned m[8] = {0, 1, 2, 4, 3, 6, 5, 7};
    return code >= 0 && code <= 7 ? m[code] : 0;
}

static mcs_status h_node(kw_ctx *c, const kw_card *cd, int n)
{
    const kw_layout *l = &KW_L_NODE;
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        int id, tc, rc;
        double x[3];
        KW_TRY(kw_int(c, &cd[i], l, 0, "NID", 0, &id));
        KW_TRY(kw_real(c, &cd[i], l, 1, "X", 0, &x[0]));
        KW_TRY(kw_real(c, &cd[i], l, 2, "Y", 0, &x[1]));
        KW_TRY(kw_real(c, &cd[i], l, 3, "Z", 0, &x[2]));
        KW_TRY(kw_int(c, &cd[i], l, 4, "TC", 0, &tc));
        KW_TRY(kw_int(c, &cd[i], l, 5, "RC", 0, &rc));
        if (id <= 0)
            return kw_fail(c, cd[i].file, cd[i].line, 1, MCS_ERR_FORMAT,
                           "field NID: node IDs must be > 0, got %d", id);
        if (tc < 0 || tc > 7 || rc < 0 || rc > 7)
            return unsupported_field(c, &cd[i], l, tc < 0 || tc > 7 ? 4 : 5, "TC/RC",
                                     "constraint codes are 0..7");
        for (int k = 0; k < 3; k++) x[k] *= kw_u_len(c->d);
        KW_TRY(kw_add_node(c, id, x, kw_loc_of(&cd[i])));
        if (tc || rc) {
            fe_kw_spc *s = kw_push((void **)&c->d->spc, &c->d->nspc, &c->d->cap_spc, sizeof *s);
            if (!s) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
            *s = (fe_kw_spc){FE_KW_ON_NODE, id, tc_mask(tc) | tc_mask(rc) << 3, kw_loc_of(&cd[i])};
        }
    }
    return MCS_OK;
}

/* EID, PID and node fields nf0.. of a card: count given in nn */
static mcs_status elem_nodes(kw_ctx *c, const kw_card *cd, int f0, int nn, int *nodes)
{
    static const char *nm[10] = {"N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8", "N9", "N10"};
    for (int k = 0; k < nn; k++) KW_TRY(kw_int(c, cd, &KW_L_ELEM, f0 + k, nm[k], 0, &nodes[k]));
    return MCS_OK;
}

static mcs_status h_shell(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        int id, pid, nd[8];
        KW_TRY(kw_int(c, &cd[i], &KW_L_ELEM, 0, "EID", 0, &id));
        KW_TRY(kw_int(c, &cd[i], &KW_L_ELEM, 1, "PID", 0, &pid));
        KW_TRY(elem_nodes(c, &cd[i], 2, 8, nd));
        for (int k = 4; k < 8; k++)
            if (nd[k])
                return unsupported_field(c, &cd[i], &KW_L_ELEM, 2 + k, "N5..N8",
                                         "8-node shells are not built (give 4 nodes)");
        if (nd[3] == 0) nd[3] = nd[2]; /* a triangle */
        KW_TRY(kw_add_elem(c, FE_KW_SHELL, id, pid, nd, NULL, kw_loc_of(&cd[i])));
    }
    return MCS_OK;
}

/* EID and PID of the solid element on card *i; the two-card form (fields 3..10 of the first
 * card blank: EID PID, then N1..N10 on the next card) sets *two and moves *i and *at to the
 * node card */
static mcs_status solid_head(kw_ctx *c, const kw_card *cd, int n, int *i, int *id, int *pid,
                             const kw_card **at, int *two)
{
    *at = &cd[*i];
    KW_TRY(kw_int(c, *at, &KW_L_ELEM, 0, "EID", 0, id));
    KW_TRY(kw_int(c, *at, &KW_L_ELEM, 1, "PID", 0, pid));
    *two = 1;
    for (int k = 2; k < 10; k++) *two = *two && kw_blank(c, *at, &KW_L_ELEM, k);
    if (*two) {
        KW_TRY(kw_need(c, cd, n, *i + 1, 1));
        *at = &cd[++*i];
    }
    return MCS_OK;
}

static mcs_status h_solid(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        int id, pid, nd[10] = {0}, two;
        const kw_card *at;
        KW_TRY(solid_head(c, cd, n, &i, &id, &pid, &at, &two));
        if (two) {
            KW_TRY(elem_nodes(c, at, 0, 10, nd));
            if (nd[8] || nd[9]) { /* the 10-node tetrahedron */
                for (int k = 0; k < 10; k++)
                    if (!nd[k])
                        return unsupported_field(c, at, &KW_L_ELEM, k, "N1..N10",
                                                 "a 10-node tetrahedron needs all ten nodes");
                KW_TRY(kw_add_elem(c, FE_KW_TET10, id, pid, nd, NULL, kw_loc_of(&cd[i])));
                continue;
            }
        } else {
            KW_TRY(elem_nodes(c, at, 2, 8, nd));
        }
        /* a tetrahedron with N5..N8 left blank: N4 repeated, as LS-DYNA writes it */
        if (nd[3] && !nd[4] && !nd[5] && !nd[6] && !nd[7])
            nd[4] = nd[5] = nd[6] = nd[7] = nd[3];
        KW_TRY(kw_add_elem(c, FE_KW_SOLID, id, pid, nd, NULL, kw_loc_of(&cd[i])));
    }
    return MCS_OK;
}

/* *ELEMENT_SOLID_TET4TOTET10: 4-node tetrahedra (either form) that become 10-node ones */
static mcs_status h_solid_tet10(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        int id, pid, nd[10] = {0}, two;
        const kw_card *at;
        KW_TRY(solid_head(c, cd, n, &i, &id, &pid, &at, &two));
        KW_TRY(elem_nodes(c, at, two ? 0 : 2, 8, nd));
        int tet = nd[0] && nd[1] && nd[2] && nd[3];
        for (int k = 4; k < 8; k++) tet = tet && (nd[k] == 0 || nd[k] == nd[3]);
        if (!tet)
            return unsupported_field(c, at, &KW_L_ELEM, two ? 0 : 2, "N1..N8",
                                     "TET4TOTET10 takes tetrahedra (N1 N2 N3 N4, N5..N8 blank "
                                     "or N4)");
        for (int k = 4; k < 8; k++) nd[k] = 0; /* mid-edge nodes: kw_tet4_to_tet10 */
        KW_TRY(kw_add_elem(c, FE_KW_TET10, id, pid, nd, NULL, kw_loc_of(&cd[i])));
    }
    return MCS_OK;
}

static mcs_status h_beam(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        int id, pid, nd[2];
        KW_TRY(kw_int(c, &cd[i], &KW_L_ELEM, 0, "EID", 0, &id));
        KW_TRY(kw_int(c, &cd[i], &KW_L_ELEM, 1, "PID", 0, &pid));
        KW_TRY(elem_nodes(c, &cd[i], 2, 2, nd)); /* N3 (orientation) is not needed by trusses */
        KW_TRY(kw_add_elem(c, FE_KW_BEAM, id, pid, nd, NULL, kw_loc_of(&cd[i])));
    }
    return MCS_OK;
}

static mcs_status h_discrete(kw_ctx *c, const kw_card *cd, int n)
{
    const kw_layout *l = &KW_L_DISCR;
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        int id, pid, nd[2], vid, pf;
        double dv[2];
        KW_TRY(kw_int(c, &cd[i], l, 0, "EID", 0, &id));
        KW_TRY(kw_int(c, &cd[i], l, 1, "PID", 0, &pid));
        KW_TRY(kw_int(c, &cd[i], l, 2, "N1", 0, &nd[0]));
        KW_TRY(kw_int(c, &cd[i], l, 3, "N2", 0, &nd[1]));
        KW_TRY(kw_int(c, &cd[i], l, 4, "VID", 0, &vid));
        KW_TRY(kw_real(c, &cd[i], l, 5, "S", 1, &dv[0]));
        KW_TRY(kw_int(c, &cd[i], l, 6, "PF", 0, &pf));
        KW_TRY(kw_real(c, &cd[i], l, 7, "OFFSET", 0, &dv[1]));
        dv[1] *= kw_u_len(c->d);
        KW_TRY(kw_add_elem(c, FE_KW_DISCRETE, id, pid, nd, dv, kw_loc_of(&cd[i])));
    }
    return MCS_OK;
}

/* ---- *PART, *SECTION_* ---- */

/* a section card's SECID (field 1), checked unique, and a new section of that kind */
static mcs_status new_section(kw_ctx *c, const kw_card *cd, fe_kw_sec_kind kind,
                              fe_kw_section **out)
{
    int id;
    KW_TRY(kw_int(c, cd, &KW_L10, 0, "SECID", 0, &id));
    for (int k = 0; k < c->d->nsection; k++)
        if (c->d->section[k].id == id)
            return kw_fail(c, cd->file, cd->line, 1, MCS_ERR_FORMAT,
                           "section %d is defined twice", id);
    fe_kw_section *s =
        kw_push((void **)&c->d->section, &c->d->nsection, &c->d->cap_section, sizeof *s);
    if (!s) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    s->id = id, s->loc = kw_loc_of(cd), s->kind = kind;
    *out = s;
    return MCS_OK;
}

static mcs_status h_section_shell(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i = title_card(c, i);
        KW_TRY(kw_need(c, cd, n, i, 2));
        int icomp;
        fe_kw_section *s;
        KW_TRY(new_section(c, &cd[i], FE_KW_SEC_SHELL, &s));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "ELFORM", 0, &s->elform));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 2, "SHRF", 0, &s->shrf));
        double nip;
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 3, "NIP", 0, &nip));
        if (!(nip >= 0 && nip <= 100))
            return unsupported_field(c, &cd[i], &KW_L10, 3, "NIP", "must be 0..100");
        s->nip = (int)nip;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 6, "ICOMP", 0, &icomp));
        if (icomp)
            return unsupported_field(c, &cd[i], &KW_L10, 6, "ICOMP",
                                     "composite layups are not built");
        static const char *tn[4] = {"T1", "T2", "T3", "T4"};
        for (int k = 0; k < 4; k++) {
            KW_TRY(kw_real(c, &cd[i + 1], &KW_L10, k, tn[k], 0, &s->t[k]));
            s->t[k] *= kw_u_len(c->d);
        }
        i += 2;
    }
    return MCS_OK;
}

/* SECID DRO KD V0 CL FD CDL TDL: only DRO is kept (0 translational, 1 torsional) */
static mcs_status h_section_discrete(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i = title_card(c, i);
        KW_TRY(kw_need(c, cd, n, i, 1));
        fe_kw_section *s;
        KW_TRY(new_section(c, &cd[i], FE_KW_SEC_DISCRETE, &s));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "DRO", 0, &s->elform));
        i++;
    }
    return MCS_OK;
}

/* ---- *MAT_*, *DEFINE_CURVE ---- */

static fe_kw_mat *new_mat(kw_ctx *c, const kw_card *cd, fe_kw_mat_type type, mcs_status *st)
{
    int id;
    *st = kw_int(c, cd, &KW_L10, 0, "MID", 0, &id);
    if (*st) return NULL;
    for (int k = 0; k < c->d->nmat; k++)
        if (c->d->mat[k].id == id) {
            *st = kw_fail(c, cd->file, cd->line, 1, MCS_ERR_FORMAT,
                          "material %d is defined twice", id);
            return NULL;
        }
    fe_kw_mat *m = kw_push((void **)&c->d->mat, &c->d->nmat, &c->d->cap_mat, sizeof *m);
    if (!m) {
        *st = MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        return NULL;
    }
    m->id = id;
    m->type = type;
    m->loc = kw_loc_of(cd);
    /* RO E PR: fields 2..4 of the first card of every supported material */
    *st = kw_real(c, cd, &KW_L10, 1, "RO", 0, &m->ro);
    if (!*st) *st = kw_real(c, cd, &KW_L10, 2, "E", 0, &m->e);
    if (!*st) *st = kw_real(c, cd, &KW_L10, 3, "PR", 0, &m->pr);
    m->ro *= kw_u_dens(c->d);
    m->e *= kw_u_stress(c->d);
    if (!*st && !(isfinite(m->ro) && isfinite(m->e)))
        *st = kw_fail(c, cd->file, cd->line, 0, MCS_ERR_FORMAT,
                      "RO or E is out of range in SI units");
    return *st ? NULL : m;
}

static mcs_status h_mat_elastic(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i = title_card(c, i);
        KW_TRY(kw_need(c, cd, n, i, 1));
        mcs_status st = MCS_OK;
        if (!new_mat(c, &cd[i], FE_KW_MAT_ELASTIC, &st)) return st;
        i++;
    }
    return MCS_OK;
}

/* *MAT_SPRING_ELASTIC: MID K; *MAT_DAMPER_VISCOUS: MID DC (force per length or velocity) */
static mcs_status h_mat_discrete(kw_ctx *c, const kw_card *cd, int n, fe_kw_mat_type type)
{
    for (int i = 0; i < n;) {
        i = title_card(c, i);
        KW_TRY(kw_need(c, cd, n, i, 1));
        int id;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "MID", 0, &id));
        if (fe_kw_find_mat(c->d, id))
            return kw_fail(c, cd[i].file, cd[i].line, 1, MCS_ERR_FORMAT,
                           "material %d is defined twice", id);
        fe_kw_mat *m = kw_push((void **)&c->d->mat, &c->d->nmat, &c->d->cap_mat, sizeof *m);
        if (!m) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        m->id = id, m->type = type, m->loc = kw_loc_of(&cd[i]);
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 1, type == FE_KW_MAT_SPRING ? "K" : "DC", 0, &m->k));
        /* N/m = kg/s^2; N s/m = kg/s */
        m->k *= type == FE_KW_MAT_SPRING ? c->d->unit[2] / (c->d->unit[1] * c->d->unit[1])
                                         : c->d->unit[2] / c->d->unit[1];
        if (!isfinite(m->k))
            return kw_fail(c, cd[i].file, cd[i].line, 0, MCS_ERR_FORMAT,
                           "the constant is out of range in SI units");
        i++;
    }
    return MCS_OK;
}

static mcs_status h_mat_spring(kw_ctx *c, const kw_card *cd, int n)
{
    return h_mat_discrete(c, cd, n, FE_KW_MAT_SPRING);
}
static mcs_status h_mat_damper(kw_ctx *c, const kw_card *cd, int n)
{
    return h_mat_discrete(c, cd, n, FE_KW_MAT_DAMPER);
}

static mcs_status h_mat_plp(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i = title_card(c, i);
        KW_TRY(kw_need(c, cd, n, i, 4));
        mcs_status st = MCS_OK;
        fe_kw_mat *m = new_mat(c, &cd[i], FE_KW_MAT_PLP, &st);
        if (!m) return st;
        double fail, lcsr;
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 4, "SIGY", 0, &m->sigy));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 5, "ETAN", 0, &m->etan));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 6, "FAIL", 0, &fail));
        m->sigy *= kw_u_stress(c->d);
        m->etan *= kw_u_stress(c->d);
        if (fail < 0)
            return unsupported_field(c, &cd[i], &KW_L10, 6, "FAIL",
                                     "a user failure subroutine (FAIL < 0) is not built");
        m->fail = fail < 1e20 ? fail : 0; /* element erosion at this plastic strain */
        KW_TRY(kw_real(c, &cd[i + 1], &KW_L10, 0, "C", 0, &m->c));
        KW_TRY(kw_real(c, &cd[i + 1], &KW_L10, 1, "P", 0, &m->p));
        KW_TRY(kw_int(c, &cd[i + 1], &KW_L10, 2, "LCSS", 0, &m->lcss));
        KW_TRY(kw_real(c, &cd[i + 1], &KW_L10, 3, "LCSR", 0, &lcsr));
        if (lcsr != 0)
            return unsupported_field(c, &cd[i + 1], &KW_L10, 3, "LCSR",
                                     "strain-rate curves are not built (use C and P)");
        m->c *= kw_u_rate(c->d);
        if (!(isfinite(m->sigy) && isfinite(m->etan) && isfinite(m->c)))
            return kw_fail(c, cd[i].file, cd[i].line, 0, MCS_ERR_FORMAT,
                           "SIGY, ETAN or C is out of range in SI units");
        static const char *en[8] = {"EPS1", "EPS2", "EPS3", "EPS4", "EPS5", "EPS6", "EPS7", "EPS8"};
        static const char *sn[8] = {"ES1", "ES2", "ES3", "ES4", "ES5", "ES6", "ES7", "ES8"};
        for (int k = 0; k < 8; k++) {
            KW_TRY(kw_real(c, &cd[i + 2], &KW_L10, k, en[k], 0, &m->eps[k]));
            KW_TRY(kw_real(c, &cd[i + 3], &KW_L10, k, sn[k], 0, &m->es[k]));
            m->es[k] *= kw_u_stress(c->d);
            if (!isfinite(m->es[k]))
                return kw_fail(c, cd[i + 3].file, cd[i + 3].line, 0, MCS_ERR_FORMAT,
                               "%s is out of range in SI units", sn[k]);
            if (m->es[k] != 0) m->neps = k + 1;
        }
        i += 4;
    }
    return MCS_OK;
}

static mcs_status h_curve(kw_ctx *c, const kw_card *cd, int n)
{
    int i = title_card(c, 0);
    KW_TRY(kw_need(c, cd, n, i, 1));
    int id;
    double sfa, sfo, offa, offo;
    KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "LCID", 0, &id));
    KW_TRY(kw_real(c, &cd[i], &KW_L10, 2, "SFA", 1, &sfa));
    KW_TRY(kw_real(c, &cd[i], &KW_L10, 3, "SFO", 1, &sfo));
    KW_TRY(kw_real(c, &cd[i], &KW_L10, 4, "OFFA", 0, &offa));
    KW_TRY(kw_real(c, &cd[i], &KW_L10, 5, "OFFO", 0, &offo));
    if (sfa == 0) sfa = 1;
    if (sfo == 0) sfo = 1;
    if (fe_kw_find_curve(c->d, id))
        return kw_fail(c, cd[i].file, cd[i].line, 1, MCS_ERR_FORMAT, "curve %d is defined twice",
                       id);
    fe_kw_curve *cv = kw_push((void **)&c->d->curve, &c->d->ncurve, &c->d->cap_curve, sizeof *cv);
    if (!cv) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    cv->id = id;
    cv->loc = kw_loc_of(&cd[i]);
    cv->xy = malloc(2 * sizeof(double) * (size_t)(n - i > 1 ? n - i : 1));
    if (!cv->xy) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    for (int k = i + 1; k < n; k++) {
        if (kw_blank_card(&cd[k])) continue;
        double a, o;
        KW_TRY(kw_real(c, &cd[k], &KW_L_CURVE, 0, "A", 0, &a));
        KW_TRY(kw_real(c, &cd[k], &KW_L_CURVE, 1, "O", 0, &o));
        /* LS-DYNA: abscissa = SFA (A + OFFA), ordinate = SFO (O + OFFO) */
        cv->xy[2 * cv->n] = sfa * (a + offa);
        cv->xy[2 * cv->n + 1] = sfo * (o + offo);
        if (cv->n > 0 && !(cv->xy[2 * cv->n] > cv->xy[2 * cv->n - 2]))
            return kw_fail(c, cd[k].file, cd[k].line, 1, MCS_ERR_FORMAT,
                           "curve %d: abscissa values must increase", id);
        cv->n++;
    }
    if (cv->n == 0)
        return kw_fail(c, cd[i].file, cd[i].line, 1, MCS_ERR_FORMAT, "curve %d has no points",
                       id);
    return MCS_OK;
}

/* ---- sets, walls, initial velocities, constraints ---- */

static mcs_status h_set(kw_ctx *c, const kw_card *cd, int n, int is_part)
{
    int i = title_card(c, 0);
    KW_TRY(kw_need(c, cd, n, i, 1));
    int id;
    KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "SID", 0, &id));
    if (fe_kw_find_set(c->d, id, is_part))
        return kw_fail(c, cd[i].file, cd[i].line, 1, MCS_ERR_FORMAT, "set %d is defined twice",
                       id);
    fe_kw_set *s = kw_push((void **)&c->d->set, &c->d->nset, &c->d->cap_set, sizeof *s);
    if (!s) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    s->id = id;
    s->is_part = is_part;
    s->loc = kw_loc_of(&cd[i]);
    s->ids = malloc(8 * sizeof(int) * (size_t)(n - i > 1 ? n - i : 1));
    if (!s->ids) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    static const char *nm[8] = {"ID1", "ID2", "ID3", "ID4", "ID5", "ID6", "ID7", "ID8"};
    for (int k = i + 1; k < n; k++)
        for (int f = 0; f < 8; f++) {
            int v;
            KW_TRY(kw_int(c, &cd[k], &KW_L10, f, nm[f], 0, &v));
            if (v > 0) s->ids[s->n++] = v;
        }
    return MCS_OK;
}

static mcs_status h_set_node(kw_ctx *c, const kw_card *cd, int n) { return h_set(c, cd, n, 0); }
static mcs_status h_set_part(kw_ctx *c, const kw_card *cd, int n) { return h_set(c, cd, n, 1); }

/* *RIGIDWALL_PLANAR(_MOVING)(_ID): [ID card] / NSID ... / XT ... FRIC / (MOVING) MASS V0 */
static mcs_status wall_cards(kw_ctx *c, const kw_card *cd, int n, int moving)
{
    for (int i = 0; i < n;) {
        fe_kw_wall w = {0};
        KW_TRY(id_card(c, cd, n, &i, &w.id, w.title));
        KW_TRY(kw_need(c, cd, n, i, moving ? 3 : 2));
        int nsidex, boxid;
        double offset, birth, death;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "NSID", 0, &w.nsid));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "NSIDEX", 0, &nsidex));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 2, "BOXID", 0, &boxid));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 3, "OFFSET", 0, &offset));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 4, "BIRTH", 0, &birth));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 5, "DEATH", 1e20, &death));
        if (nsidex || boxid)
            return unsupported_field(c, &cd[i], &KW_L10, nsidex ? 1 : 2, "NSIDEX/BOXID",
                                     "exempted node sets and boxes are not built");
        if (offset != 0 || birth != 0 || (death != 0 && death < 1e20))
            return unsupported_field(c, &cd[i], &KW_L10, offset != 0 ? 3 : birth != 0 ? 4 : 5,
                                     "OFFSET/BIRTH/DEATH", "not built (leave blank)");
        static const char *nm[7] = {"XT", "YT", "ZT", "XH", "YH", "ZH", "FRIC"};
        double v[7];
        for (int k = 0; k < 7; k++) KW_TRY(kw_real(c, &cd[i + 1], &KW_L10, k, nm[k], 0, &v[k]));
        for (int k = 0; k < 3; k++) {
            w.tail[k] = v[k] * kw_u_len(c->d);
            w.head[k] = v[3 + k] * kw_u_len(c->d);
        }
        w.fric = v[6];
        if (v[0] == v[3] && v[1] == v[4] && v[2] == v[5])
            return kw_fail(c, cd[i + 1].file, cd[i + 1].line, 0, MCS_ERR_FORMAT,
                           "the head (XH, YH, ZH) equals the tail (XT, YT, ZT): no normal");
        if (moving) {
            const kw_card *mc = &cd[i + 2];
            KW_TRY(kw_real(c, mc, &KW_L10, 0, "MASS", 0, &w.mass));
            KW_TRY(kw_real(c, mc, &KW_L10, 1, "V0", 0, &w.v0));
            if (!(w.mass > 0))
                return kw_fail(c, mc->file, mc->line, 1, MCS_ERR_FORMAT,
                               "field MASS: a moving wall needs a mass > 0, got %g", w.mass);
            w.moving = 1;
            w.mass *= c->d->unit[2];
            w.v0 *= kw_u_vel(c->d);
        }
        w.loc = kw_loc_of(&cd[i]);
        fe_kw_wall *p = kw_push((void **)&c->d->wall, &c->d->nwall, &c->d->cap_wall, sizeof *p);
        if (!p) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        *p = w;
        i += moving ? 3 : 2;
    }
    return MCS_OK;
}

static mcs_status h_wall(kw_ctx *c, const kw_card *cd, int n) { return wall_cards(c, cd, n, 0); }
static mcs_status h_wall_moving(kw_ctx *c, const kw_card *cd, int n)
{
    return wall_cards(c, cd, n, 1);
}

/* *BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL(_ID): [ID card] / ID DOF VAD LCID SF VID DEATH BIRTH */
static mcs_status h_wall_motion(kw_ctx *c, const kw_card *cd, int n)
{
    int i = 0, id0;
    KW_TRY(id_card(c, cd, n, &i, &id0, NULL));
    for (; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        fe_kw_wmotion mo = {.loc = kw_loc_of(&cd[i])};
        int vid;
        double death, birth;
        const kw_layout *l = &KW_L10;
        KW_TRY(kw_int(c, &cd[i], l, 0, "ID", 0, &mo.wall));
        KW_TRY(kw_int(c, &cd[i], l, 1, "DOF", 0, &mo.dof));
        KW_TRY(kw_int(c, &cd[i], l, 2, "VAD", 0, &mo.vad));
        KW_TRY(kw_int(c, &cd[i], l, 3, "LCID", 0, &mo.lcid));
        KW_TRY(kw_real(c, &cd[i], l, 4, "SF", 1, &mo.sf));
        KW_TRY(kw_int(c, &cd[i], l, 5, "VID", 0, &vid));
        KW_TRY(kw_real(c, &cd[i], l, 6, "DEATH", 0, &death));
        KW_TRY(kw_real(c, &cd[i], l, 7, "BIRTH", 0, &birth));
        if (mo.sf == 0) mo.sf = 1; /* LS-DYNA: 0 takes the default 1 */
        if (mo.dof < 1 || mo.dof > 3)
            return unsupported_field(c, &cd[i], l, 1, "DOF",
                                     "1, 2 or 3 (x, y, z translation) are built");
        if (mo.vad < 0 || mo.vad > 2)
            return unsupported_field(c, &cd[i], l, 2, "VAD",
                                     "0 velocity, 1 acceleration or 2 displacement are built");
        if (vid || birth != 0 || (death != 0 && death < 1e20))
            return unsupported_field(c, &cd[i], l, vid ? 5 : birth != 0 ? 7 : 6,
                                     "VID/DEATH/BIRTH", "not built (leave blank)");
        if (mo.lcid <= 0)
            return kw_fail(c, cd[i].file, cd[i].line, 0, MCS_ERR_FORMAT,
                           "field LCID: a motion needs a curve, got %d", mo.lcid);
        fe_kw_wmotion *p =
            kw_push((void **)&c->d->wmotion, &c->d->nwmotion, &c->d->cap_wmotion, sizeof *p);
        if (!p) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        *p = mo;
    }
    return MCS_OK;
}

static fe_kw_initvel *new_iv(kw_ctx *c)
{
    return kw_push((void **)&c->d->iv, &c->d->niv, &c->d->cap_iv, sizeof(fe_kw_initvel));
}

static mcs_status h_initvel(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n; i += 2) {
        KW_TRY(kw_need(c, cd, n, i, 2));
        int nsid, nsidex, boxid, irigid, icid;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "NSID", 0, &nsid));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "NSIDEX", 0, &nsidex));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 2, "BOXID", 0, &boxid));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 3, "IRIGID", 0, &irigid));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 4, "ICID", 0, &icid));
        if (nsidex || boxid || icid)
            return unsupported_field(c, &cd[i], &KW_L10, nsidex ? 1 : boxid ? 2 : 4,
                                     "NSIDEX/BOXID/ICID",
                                     "exempted sets, boxes and local systems are not built");
        fe_kw_initvel *v = new_iv(c);
        if (!v) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        static const char *nm[6] = {"VX", "VY", "VZ", "VXR", "VYR", "VZR"};
        double x[6];
        for (int k = 0; k < 6; k++) KW_TRY(kw_real(c, &cd[i + 1], &KW_L10, k, nm[k], 0, &x[k]));
        v->on = FE_KW_ON_NODESET;
        v->id = nsid;
        for (int k = 0; k < 3; k++) {
            v->v[k] = x[k] * kw_u_vel(c->d);
            v->vr[k] = x[3 + k] * kw_u_rate(c->d);
        }
        v->loc = kw_loc_of(&cd[i]);
    }
    return MCS_OK;
}

static mcs_status h_initvel_gen(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n; i += 2) {
        KW_TRY(kw_need(c, cd, n, i, 2));
        int id, styp, icid;
        double omega, v[3];
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "ID", 0, &id));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "STYP", 0, &styp));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 2, "OMEGA", 0, &omega));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 3, "VX", 0, &v[0]));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 4, "VY", 0, &v[1]));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 5, "VZ", 0, &v[2]));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 7, "ICID", 0, &icid));
        if (styp < 1 || styp > 3)
            return unsupported_field(c, &cd[i], &KW_L10, 1, "STYP",
                                     "must be 1 (part set), 2 (part) or 3 (node set)");
        if (omega != 0 || icid)
            return unsupported_field(c, &cd[i], &KW_L10, omega != 0 ? 2 : 7, "OMEGA/ICID",
                                     "rotating initial velocities and local systems are not "
                                     "built");
        fe_kw_initvel *p = new_iv(c);
        if (!p) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        p->on = styp == 1 ? FE_KW_ON_PARTSET : styp == 2 ? FE_KW_ON_PART : FE_KW_ON_NODESET;
        p->id = id;
        for (int k = 0; k < 3; k++) p->v[k] = v[k] * kw_u_vel(c->d);
        p->loc = kw_loc_of(&cd[i]);
    }
    return MCS_OK;
}

static mcs_status h_spc(kw_ctx *c, const kw_card *cd, int n, fe_kw_target on)
{
    int i = 0, id0;
    KW_TRY(id_card(c, cd, n, &i, &id0, NULL));
    static const char *nm[6] = {"DOFX", "DOFY", "DOFZ", "DOFRX", "DOFRY", "DOFRZ"};
    for (; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        int id, cid, dof;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, on == FE_KW_ON_NODE ? "NID" : "NSID", 0, &id));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "CID", 0, &cid));
        if (cid)
            return unsupported_field(c, &cd[i], &KW_L10, 1, "CID", "local systems are not built");
        unsigned mask = 0;
        for (int k = 0; k < 6; k++) {
            KW_TRY(kw_int(c, &cd[i], &KW_L10, 2 + k, nm[k], 0, &dof));
            if (dof != 0 && dof != 1)
                return unsupported_field(c, &cd[i], &KW_L10, 2 + k, nm[k], "must be 0 or 1");
            if (dof) mask |= 1u << k;
        }
        fe_kw_spc *s = kw_push((void **)&c->d->spc, &c->d->nspc, &c->d->cap_spc, sizeof *s);
        if (!s) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
        *s = (fe_kw_spc){on, id, mask, kw_loc_of(&cd[i])};
    }
    return MCS_OK;
}

static mcs_status h_spc_node(kw_ctx *c, const kw_card *cd, int n)
{
    return h_spc(c, cd, n, FE_KW_ON_NODE);
}
static mcs_status h_spc_set(kw_ctx *c, const kw_card *cd, int n)
{
    return h_spc(c, cd, n, FE_KW_ON_NODESET);
}

/* ---- the table ---- */

static const struct {
    const char *name;
    kw_handler fn;
    int id_ok; /* an _ID option exists */
} table[] = {
    {"KEYWORD", h_none, 0},
    {"COMMENT", h_none, 0},
    {"TITLE", h_title, 0},
    {"NODE", h_node, 0},
    {"ELEMENT_SHELL", h_shell, 0},
    {"ELEMENT_SOLID", h_solid, 0},
    {"ELEMENT_SOLID_TET4TOTET10", h_solid_tet10, 0},
    {"ELEMENT_BEAM", h_beam, 0},
    {"ELEMENT_DISCRETE", h_discrete, 0},
    {"PART", kw_h_part, 0},
    {"SECTION_SHELL", h_section_shell, 0},
    {"SECTION_SOLID", kw_h_section_solid, 0},
    {"SECTION_BEAM", kw_h_section_beam, 0},
    {"SECTION_DISCRETE", h_section_discrete, 0},
    {"MAT_SPRING_ELASTIC", h_mat_spring, 0},
    {"MAT_S01", h_mat_spring, 0},
    {"MAT_DAMPER_VISCOUS", h_mat_damper, 0},
    {"MAT_S02", h_mat_damper, 0},
    {"MAT_ELASTIC", h_mat_elastic, 0},
    {"MAT_001", h_mat_elastic, 0},
    {"MAT_PIECEWISE_LINEAR_PLASTICITY", h_mat_plp, 0},
    {"MAT_024", h_mat_plp, 0},
    {"MAT_RIGID", kw_h_mat_rigid, 0}, /* fe_kw_cards_mat.c */
    {"MAT_020", kw_h_mat_rigid, 0},
    {"MAT_PLASTIC_KINEMATIC", kw_h_mat_pk, 0},
    {"MAT_003", kw_h_mat_pk, 0},
    {"MAT_NULL", kw_h_mat_null, 0},
    {"MAT_009", kw_h_mat_null, 0},
    {"MAT_MOONEY-RIVLIN_RUBBER", kw_h_mat_mr, 0},
    {"MAT_027", kw_h_mat_mr, 0},
    {"MAT_LOW_DENSITY_FOAM", kw_h_mat_ldf, 0},
    {"MAT_057", kw_h_mat_ldf, 0},
    {"DEFINE_CURVE", h_curve, 0},
    {"SET_NODE", h_set_node, 0},
    {"SET_NODE_LIST", h_set_node, 0},
    {"SET_PART", h_set_part, 0},
    {"SET_PART_LIST", h_set_part, 0},
    {"RIGIDWALL_PLANAR", h_wall, 1},
    {"RIGIDWALL_PLANAR_MOVING", h_wall_moving, 1},
    {"INITIAL_VELOCITY", h_initvel, 0},
    {"INITIAL_VELOCITY_GENERATION", h_initvel_gen, 0},
    {"BOUNDARY_SPC_NODE", h_spc_node, 1},
    {"BOUNDARY_SPC_SET", h_spc_set, 1},
    {"BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL", h_wall_motion, 1},
    /* fe_kw_cards_elem.c */
    {"ELEMENT_SHELL_THICKNESS", kw_h_shell_opt, 0},
    {"ELEMENT_SHELL_BETA", kw_h_shell_opt, 0},
    {"ELEMENT_SHELL_MCID", kw_h_shell_opt, 0},
    {"ELEMENT_SHELL_THICKNESS_BETA", kw_h_shell_opt, 0},
    {"ELEMENT_SHELL_THICKNESS_MCID", kw_h_shell_opt, 0},
    {"ELEMENT_SHELL_OFFSET", kw_h_shell_opt, 0},
    {"ELEMENT_SHELL_THICKNESS_OFFSET", kw_h_shell_opt, 0},
    {"ELEMENT_SHELL_BETA_OFFSET", kw_h_shell_opt, 0},
    {"ELEMENT_SHELL_MCID_OFFSET", kw_h_shell_opt, 0},
    {"ELEMENT_TSHELL", kw_h_tshell, 0},
    {"ELEMENT_TSHELL_BETA", kw_h_tshell, 0},
    {"SECTION_TSHELL", kw_h_section_tshell, 0},
    {"PART_INERTIA", kw_h_part, 0},
    {"PART_CONTACT", kw_h_part, 0},
    {"PART_INERTIA_CONTACT", kw_h_part, 0},
    {"HOURGLASS", kw_h_hourglass, 0},
    {"CONTROL_HOURGLASS", kw_h_control_hourglass, 0},
    {"CONTROL_TIMESTEP", kw_h_control_timestep, 0},
    {"CONTACT_AUTOMATIC_SINGLE_SURFACE", kw_h_contact_single, 1},
    {"CONTACT_AUTOMATIC_GENERAL", kw_h_contact_general, 1},
    {"CONTACT_SURFACE_TO_SURFACE", kw_h_contact_s2s, 1},
    {"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", kw_h_contact_auto_s2s, 1},
    {"CONTACT_NODES_TO_SURFACE", kw_h_contact_n2s, 1},
    {"CONTACT_AUTOMATIC_NODES_TO_SURFACE", kw_h_contact_auto_n2s, 1},
    {"CONTACT_AUTOMATIC_SINGLE_SURFACE_MPP", kw_h_contact_mpp, 1},
    {"CONTACT_AUTOMATIC_SINGLE_SURFACE_ID_MPP", kw_h_contact_mpp, 0},
    {"CONTACT_AUTOMATIC_GENERAL_MPP", kw_h_contact_mpp, 1},
    {"CONTACT_AUTOMATIC_GENERAL_ID_MPP", kw_h_contact_mpp, 0},
    {"CONTACT_SURFACE_TO_SURFACE_MPP", kw_h_contact_mpp, 1},
    {"CONTACT_SURFACE_TO_SURFACE_ID_MPP", kw_h_contact_mpp, 0},
    {"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MPP", kw_h_contact_mpp, 1},
    {"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID_MPP", kw_h_contact_mpp, 0},
    {"CONTACT_NODES_TO_SURFACE_MPP", kw_h_contact_mpp, 1},
    {"CONTACT_NODES_TO_SURFACE_ID_MPP", kw_h_contact_mpp, 0},
    {"CONTACT_AUTOMATIC_NODES_TO_SURFACE_MPP", kw_h_contact_mpp, 1},
    {"CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID_MPP", kw_h_contact_mpp, 0},
    {"CONTROL_CONTACT", kw_h_control_contact, 0},
    {"SET_NODE_LIST_GENERATE", kw_h_set_node_gen, 0},
    {"SET_PART_LIST_GENERATE", kw_h_set_part_gen, 0},
    {"SET_SEGMENT", kw_h_set_segment, 0},
    {"INITIAL_VELOCITY_NODE", kw_h_initvel_node, 0},
    {"BOUNDARY_PRESCRIBED_MOTION_NODE", kw_h_pmotion_node, 1},
    {"BOUNDARY_PRESCRIBED_MOTION_SET", kw_h_pmotion_set, 1},
    {"BOUNDARY_PRESCRIBED_MOTION_RIGID", kw_h_pmotion_rigid, 1},
    {"LOAD_NODE_POINT", kw_h_load_node_point, 0},
    {"LOAD_NODE_SET", kw_h_load_node_set, 0},
    {"LOAD_SEGMENT", kw_h_load_segment, 0},
    {"CONTROL_TERMINATION", kw_h_control_termination, 0},
    {"CONSTRAINED_JOINT_SPHERICAL", kw_h_joint_spherical, 1}, /* fe_kw_cards_joint.c */
    {"CONSTRAINED_JOINT_REVOLUTE", kw_h_joint_revolute, 1},
    {"CONSTRAINED_JOINT_CYLINDRICAL", kw_h_joint_cylindrical, 1},
    {"CONSTRAINED_JOINT_TRANSLATIONAL", kw_h_joint_translational, 1},
    {"CONSTRAINED_NODAL_RIGID_BODY", kw_h_nodal_rigid_body, 0},
    {"CONSTRAINED_EXTRA_NODES_NODE", kw_h_extra_nodes_node, 0},
    {"CONSTRAINED_EXTRA_NODES_SET", kw_h_extra_nodes_set, 0},
    {"CONSTRAINED_JOINT_STIFFNESS_GENERALIZED", kw_h_jstiff_generalized, 0},
    {"CONSTRAINED_JOINT_STIFFNESS_TRANSLATIONAL", kw_h_jstiff_translational, 0},
};

int kw_dispatch(kw_ctx *c, const kw_card *cards, int ncard, mcs_status *st)
{
    static const char *titled[] = {"PART", "TITLE", "KEYWORD", "COMMENT", "NODE",
                                   "PART_INERTIA", "PART_CONTACT", "PART_INERTIA_CONTACT",
                                   "CONTROL_HOURGLASS", "CONTROL_TIMESTEP"};
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++) {
        if (strcmp(c->kw, table[i].name) != 0) continue;
        if (c->has_id && !table[i].id_ok) return 0;
        /* _TITLE exists only for sections, materials, curves and sets */
        if (c->has_title)
            for (size_t k = 0; k < sizeof titled / sizeof titled[0]; k++)
                if (strcmp(c->kw, titled[k]) == 0 || strncmp(c->kw, "ELEMENT_", 8) == 0 ||
                    strncmp(c->kw, "RIGIDWALL", 9) == 0 || strncmp(c->kw, "BOUNDARY", 8) == 0 ||
                    strncmp(c->kw, "INITIAL", 7) == 0)
                    return 0;
        *st = table[i].fn(c, cards, ncard);
        return 1;
    }
    return 0;
}

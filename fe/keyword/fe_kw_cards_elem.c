/* fe_kw_cards_elem: the element, section, part and control keywords beyond the base subset:
 * *ELEMENT_SHELL_THICKNESS/_BETA/_MCID/_OFFSET, *ELEMENT_TSHELL, *SECTION_SOLID (with the
 * user elements' extra cards), *SECTION_TSHELL, *SECTION_BEAM (every ELFORM's second card),
 * *PART(_INERTIA)(_CONTACT), *HOURGLASS, *CONTROL_HOURGLASS, *CONTROL_TIMESTEP. Field names
 * and layouts as in the LS-DYNA Keyword User's Manual, Vol. I; what is built is in
 * docs/keyword.md. */
#include "fe/fe_kw_impl.h"

#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const kw_layout L16 = {5, {16, 16, 16, 16, 16}}; /* THIC1..THIC4 BETA/MCID, OFFSET */

/* an unsupported value in field i: "FILE:LINE:COL: error: *KW: field NAME: why" */
static mcs_status refuse(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i,
                         const char *name, const char *why)
{
    int col = 1;
    for (int k = 0; k < i && k < l->n; k++)
        col += c->fmt == KW_FMT_LONG ? 20 : (c->fmt == KW_FMT_I10 && l->w[k] < 10 ? 10 : l->w[k]);
    if (memchr(cd->s, ',', (size_t)cd->len)) col = 0;
    return kw_fail(c, cd->file, cd->line, col, MCS_ERR_UNSUPPORTED, "field %s: %s", name, why);
}

/* does the keyword name (options joined by '_') hold option opt? */
static int has_opt(const kw_ctx *c, const char *opt)
{
    size_t n = strlen(opt);
    for (const char *p = strstr(c->kw, opt); p; p = strstr(p + 1, opt))
        if (p > c->kw && p[-1] == '_' && (p[n] == 0 || p[n] == '_')) return 1;
    return 0;
}

const fe_kw_hourglass *fe_kw_find_hourglass(const fe_kw_deck *d, int hgid)
{
    for (int i = 0; i < d->nhg; i++)
        if (d->hg[i].id == hgid) return &d->hg[i];
    return NULL;
}

/* ---- *ELEMENT_SHELL_{THICKNESS, BETA, MCID, OFFSET}, *ELEMENT_TSHELL ---- */

/* room for THIC1..4 of shell element index i (zeros: the section's) */
static mcs_status thick_room(kw_ctx *c, fe_kw_elems *e, int i)
{
    if (i < e->nthick) return MCS_OK;
    int cap = e->nthick;
    if (kw_grow((void **)&e->thick, &cap, i + 1, 4 * sizeof(double))) return kw_nomem(c);
    memset(e->thick + 4 * (size_t)e->nthick, 0, 4 * sizeof(double) * (size_t)(cap - e->nthick));
    e->nthick = cap;
    return MCS_OK;
}

/* EID PID N1..N8 / THIC1 THIC2 THIC3 THIC4 BETA|MCID (5E16) / [OFFSET (E16)]. BETA and MCID
 * orient orthotropic materials: the shells built are isotropic, so they are read and not used */
mcs_status kw_h_shell_opt(kw_ctx *c, const kw_card *cd, int n)
{
    const int card2 = has_opt(c, "THICKNESS") || has_opt(c, "BETA") || has_opt(c, "MCID");
    const int offset = has_opt(c, "OFFSET"), per = 1 + card2 + offset;
    static const char *nm[10] = {"EID", "PID", "N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8"};
    static const char *tn[4] = {"THIC1", "THIC2", "THIC3", "THIC4"};
    fe_kw_elems *e = &c->d->elem[FE_KW_SHELL];
    for (int i = 0; i < n; i += per) {
        if (kw_blank_card(&cd[i]) && i + 1 >= n) break;
        KW_TRY(kw_need(c, cd, n, i, per));
        int v[10];
        for (int k = 0; k < 10; k++) KW_TRY(kw_int(c, &cd[i], &KW_L_ELEM, k, nm[k], 0, &v[k]));
        for (int k = 6; k < 10; k++)
            if (v[k])
                return refuse(c, &cd[i], &KW_L_ELEM, k, "N5..N8",
                              "8-node shells are not built (give 4 nodes)");
        if (v[5] == 0) v[5] = v[4]; /* a triangle */
        double t[4] = {0, 0, 0, 0}, off = 0;
        if (card2)
            for (int k = 0; k < 4; k++) {
                KW_TRY(kw_real(c, &cd[i + 1], &L16, k, tn[k], 0, &t[k]));
                if (t[k] < 0)
                    return refuse(c, &cd[i + 1], &L16, k, tn[k], "a thickness must be >= 0");
                t[k] *= kw_u_len(c->d);
            }
        if (offset) KW_TRY(kw_real(c, &cd[i + per - 1], &L16, 0, "OFFSET", 0, &off));
        if (off != 0)
            return refuse(c, &cd[i + per - 1], &L16, 0, "OFFSET",
                          "shells offset from their nodes are not built (leave 0)");
        const int at = e->n;
        KW_TRY(kw_add_elem(c, FE_KW_SHELL, v[0], v[1], v + 2, NULL, kw_loc_of(&cd[i])));
        if (t[0] > 0 || t[1] > 0 || t[2] > 0 || t[3] > 0) {
            KW_TRY(thick_room(c, e, at));
            memcpy(e->thick + 4 * (size_t)at, t, sizeof t);
        }
    }
    return MCS_OK;
}

/* EID PID N1..N8 (10I8) [/ BETA (E16)] */
mcs_status kw_h_tshell(kw_ctx *c, const kw_card *cd, int n)
{
    static const char *nm[10] = {"EID", "PID", "N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8"};
    const int per = has_opt(c, "BETA") ? 2 : 1;
    for (int i = 0; i < n; i += per) {
        if (kw_blank_card(&cd[i]) && i + 1 >= n) break;
        KW_TRY(kw_need(c, cd, n, i, per));
        int v[10];
        for (int k = 0; k < 10; k++) KW_TRY(kw_int(c, &cd[i], &KW_L_ELEM, k, nm[k], 0, &v[k]));
        KW_TRY(kw_add_elem(c, FE_KW_TSHELL, v[0], v[1], v + 2, NULL, kw_loc_of(&cd[i])));
    }
    return MCS_OK;
}

/* ---- *SECTION_SOLID, *SECTION_TSHELL, *SECTION_BEAM ---- */

static int title_card(kw_ctx *c, int i) { return i + (c->has_title ? 1 : 0); }

static mcs_status new_section(kw_ctx *c, const kw_card *cd, fe_kw_sec_kind kind,
                              fe_kw_section **out)
{
    int id;
    KW_TRY(kw_int(c, cd, &KW_L10, 0, "SECID", 0, &id));
    if (fe_kw_find_section(c->d, id))
        return kw_fail(c, cd->file, cd->line, 1, MCS_ERR_FORMAT, "section %d is defined twice",
                       id);
    fe_kw_section *s =
        kw_push((void **)&c->d->section, &c->d->nsection, &c->d->cap_section, sizeof *s);
    if (!s) return kw_nomem(c);
    s->id = id, s->loc = kw_loc_of(cd), s->kind = kind;
    *out = s;
    return MCS_OK;
}

/* SECID ELFORM AET ... ; ELFORM 101..105 (user elements): NIP NXDOF IHGF ITAJ LMC NHSV ILOC,
 * then NIP cards XI ETA ZETA WGT and LMC parameters P1..P8 per card */
mcs_status kw_h_section_solid(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i = title_card(c, i);
        if (i >= n && c->has_title) break;
        if (kw_blank_card(&cd[i]) && i + 1 >= n) break;
        KW_TRY(kw_need(c, cd, n, i, 1));
        fe_kw_section *s;
        KW_TRY(new_section(c, &cd[i], FE_KW_SEC_SOLID, &s));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "ELFORM", 0, &s->elform));
        i++;
        if (s->elform < 101 || s->elform > 105) continue;
        KW_TRY(kw_need(c, cd, n, i, 1));
        int nip, lmc;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "NIP", 0, &nip));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 4, "LMC", 0, &lmc));
        if (nip < 0 || lmc < 0 || nip > 1000 || lmc > 8000)
            return refuse(c, &cd[i], &KW_L10, nip < 0 || nip > 1000 ? 0 : 4, "NIP/LMC",
                          "must be 0..1000 and 0..8000");
        int extra = nip + (lmc + 7) / 8;
        KW_TRY(kw_need(c, cd, n, i + 1, extra));
        s->user = 1;
        i += 1 + extra;
    }
    return MCS_OK;
}

/* SECID ELFORM SHRF NIP PROPT QR ICOMP TSHEAR [/ NIP angles B1..B8 per card when ICOMP 1] */
mcs_status kw_h_section_tshell(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i = title_card(c, i);
        if (i >= n && c->has_title) break;
        if (kw_blank_card(&cd[i]) && i + 1 >= n) break;
        KW_TRY(kw_need(c, cd, n, i, 1));
        fe_kw_section *s;
        double nip;
        int icomp;
        KW_TRY(new_section(c, &cd[i], FE_KW_SEC_TSHELL, &s));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "ELFORM", 0, &s->elform));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 2, "SHRF", 0, &s->shrf));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 3, "NIP", 0, &nip));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 6, "ICOMP", 0, &icomp));
        if (!(nip >= 0 && nip <= 100))
            return refuse(c, &cd[i], &KW_L10, 3, "NIP", "must be 0..100");
        s->nip = (int)nip;
        i++;
        if (icomp == 1) {
            int k = ((s->nip > 0 ? s->nip : 2) + 7) / 8;
            KW_TRY(kw_need(c, cd, n, i, k));
            i += k;
        }
    }
    return MCS_OK;
}

/* SECID ELFORM SHRF QR/IRID CST SCOOR NSM NAUPD / the card of ELFORM:
 *   1, 7, 8, 11: TS1 TS2 TT1 TT2 NSLOC NTLOC;  2, 12, 13: A ISS ITT J SA IST;
 *   3: A RAMPT STRESS;  4, 5, 9: TS1 TS2 TT1 TT2;  6: VOL INER CID CA OFFSET RRCON SRCON TRCON */
mcs_status kw_h_section_beam(kw_ctx *c, const kw_card *cd, int n)
{
    const double L = kw_u_len(c->d), L2 = L * L, L4 = L2 * L2;
    for (int i = 0; i < n;) {
        i = title_card(c, i);
        if (i >= n && c->has_title) break;
        if (kw_blank_card(&cd[i]) && i + 1 >= n) break;
        KW_TRY(kw_need(c, cd, n, i, 2));
        fe_kw_section *s;
        double qr, cst;
        KW_TRY(new_section(c, &cd[i], FE_KW_SEC_BEAM, &s));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "ELFORM", 1, &s->elform));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 2, "SHRF", 0, &s->shrf));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 3, "QR/IRID", 0, &qr));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 4, "CST", 0, &cst));
        /* integers written in real fields: past an int they are no rule's id or type (and
         * the conversion would be undefined: found by tests/fuzz/fuzz_keyword.c) */
        if (!(fabs(qr) <= INT_MAX))
            return refuse(c, &cd[i], &KW_L10, 3, "QR/IRID", "must be an integration rule id");
        if (!(fabs(cst) <= INT_MAX))
            return refuse(c, &cd[i], &KW_L10, 4, "CST", "must be 0, 1 or 2");
        s->irid = (int)qr, s->cst = (int)cst;
        const kw_card *b = &cd[i + 1];
        const int f = s->elform;
        if (f == 2 || f == 12 || f == 13 || f == 3) {
            KW_TRY(kw_real(c, b, &KW_L10, 0, "A", 0, &s->area));
            s->area *= L2;
        }
        if (f == 2 || f == 12 || f == 13) {
            KW_TRY(kw_real(c, b, &KW_L10, 1, "ISS", 0, &s->iss));
            KW_TRY(kw_real(c, b, &KW_L10, 2, "ITT", 0, &s->itt));
            KW_TRY(kw_real(c, b, &KW_L10, 3, "J", 0, &s->jt));
            s->iss *= L4, s->itt *= L4, s->jt *= L4;
        }
        if (f == 1 || f == 4 || f == 5 || f == 7 || f == 8 || f == 9 || f == 11) {
            static const char *nm[4] = {"TS1", "TS2", "TT1", "TT2"};
            double v[4];
            for (int k = 0; k < 4; k++) KW_TRY(kw_real(c, b, &KW_L10, k, nm[k], 0, &v[k]));
            /* TS2, TT2 default to TS1, TT1 */
            s->ts[0] = v[0] * L, s->ts[1] = (v[1] != 0 ? v[1] : v[0]) * L;
            s->tt[0] = v[2] * L, s->tt[1] = (v[3] != 0 ? v[3] : v[2]) * L;
        }
        i += 2;
    }
    return MCS_OK;
}

/* ---- *PART(_INERTIA)(_CONTACT) ---- */

/* XC YC ZC TM IRCS NODEID / IXX IXY IXZ IYY IYZ IZZ / VTX VTY VTZ VRX VRY VRZ
 * [/ XL YL ZL XLIP YLIP ZLIP CID when IRCS 1]; returns the cards used in *used */
static mcs_status inertia_cards(kw_ctx *c, const kw_card *cd, int n, int i, fe_kw_inertia *in,
                                int *used)
{
    KW_TRY(kw_need(c, cd, n, i, 3));
    const fe_kw_deck *d = c->d;
    const double L = kw_u_len(d), M = d->unit[2];
    static const char *n1[4] = {"XC", "YC", "ZC", "TM"};
    static const char *n2[6] = {"IXX", "IXY", "IXZ", "IYY", "IYZ", "IZZ"};
    static const char *n3[6] = {"VTX", "VTY", "VTZ", "VRX", "VRY", "VRZ"};
    double v[6];
    for (int k = 0; k < 4; k++) KW_TRY(kw_real(c, &cd[i], &KW_L10, k, n1[k], 0, &v[k]));
    KW_TRY(kw_int(c, &cd[i], &KW_L10, 4, "IRCS", 0, &in->ircs));
    KW_TRY(kw_int(c, &cd[i], &KW_L10, 5, "NODEID", 0, &in->nodeid));
    for (int k = 0; k < 3; k++) in->cg[k] = v[k] * L;
    in->mass = v[3] * M;
    for (int k = 0; k < 6; k++) KW_TRY(kw_real(c, &cd[i + 1], &KW_L10, k, n2[k], 0, &in->i[k]));
    for (int k = 0; k < 6; k++) in->i[k] *= M * L * L;
    for (int k = 0; k < 6; k++) KW_TRY(kw_real(c, &cd[i + 2], &KW_L10, k, n3[k], 0, &v[k]));
    for (int k = 0; k < 3; k++) in->v[k] = v[k] * kw_u_vel(d), in->w[k] = v[3 + k] * kw_u_rate(d);
    *used = 3;
    if (in->ircs == 1) { /* the orientation card: consumed, refused when built */
        KW_TRY(kw_need(c, cd, n, i + 3, 1));
        *used = 4;
    }
    in->given = 1;
    return MCS_OK;
}

/* FS FD DC VC OPTT SFT SSF CPARM8 */
static mcs_status contact_card(kw_ctx *c, const kw_card *cd, fe_kw_pcontact *pc)
{
    static const char *nm[7] = {"FS", "FD", "DC", "VC", "OPTT", "SFT", "SSF"};
    double v[7];
    for (int k = 0; k < 7; k++) KW_TRY(kw_real(c, cd, &KW_L10, k, nm[k], 0, &v[k]));
    const fe_kw_deck *d = c->d;
    pc->fs = v[0], pc->fd = v[1];
    pc->dc = v[2] / kw_u_vel(d);  /* [1/velocity] */
    pc->vc = v[3] * kw_u_stress(d);
    pc->optt = v[4] * kw_u_len(d);
    pc->sft = v[5], pc->ssf = v[6];
    pc->given = 1;
    return MCS_OK;
}

/* HEADING / PID SECID MID EOSID HGID GRAV ADPOPT TMID [/ inertia cards] [/ contact card] */
mcs_status kw_h_part(kw_ctx *c, const kw_card *cd, int n)
{
    const int inertia = has_opt(c, "INERTIA"), contact = has_opt(c, "CONTACT");
    for (int i = 0; i < n;) {
        if (kw_blank_card(&cd[i]) && i + 1 >= n) break;
        KW_TRY(kw_need(c, cd, n, i, 2));
        fe_kw_part *p = kw_push((void **)&c->d->part, &c->d->npart, &c->d->cap_part, sizeof *p);
        if (!p) return kw_nomem(c);
        const kw_card *m = &cd[i + 1];
        int adpopt;
        kw_text(&cd[i], 0, 80, p->title, sizeof p->title);
        KW_TRY(kw_int(c, m, &KW_L10, 0, "PID", 0, &p->id));
        KW_TRY(kw_int(c, m, &KW_L10, 1, "SECID", 0, &p->secid));
        KW_TRY(kw_int(c, m, &KW_L10, 2, "MID", 0, &p->mid));
        KW_TRY(kw_int(c, m, &KW_L10, 3, "EOSID", 0, &p->eosid));
        KW_TRY(kw_int(c, m, &KW_L10, 4, "HGID", 0, &p->hgid));
        KW_TRY(kw_int(c, m, &KW_L10, 6, "ADPOPT", 0, &adpopt));
        if (adpopt) kw_warn(c, m, "part %d: ADPOPT %d: adaptive remeshing is not built (ignored)",
                         p->id, adpopt);
        p->loc = kw_loc_of(m);
        for (int k = 0; k < c->d->npart - 1; k++)
            if (c->d->part[k].id == p->id)
                return kw_fail(c, m->file, m->line, 1, MCS_ERR_FORMAT,
                               "part %d is defined twice", p->id);
        i += 2;
        if (inertia) {
            int used;
            KW_TRY(inertia_cards(c, cd, n, i, &p->inertia, &used));
            i += used;
        }
        if (contact) {
            KW_TRY(kw_need(c, cd, n, i, 1));
            KW_TRY(contact_card(c, &cd[i], &p->contact));
            i++;
        }
    }
    return MCS_OK;
}

/* ---- *HOURGLASS, *CONTROL_HOURGLASS, *CONTROL_TIMESTEP ---- */

/* HGID IHQ QM IBQ Q1 Q2 QB/VDC QW */
mcs_status kw_h_hourglass(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = title_card(c, 0); i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        fe_kw_hourglass h = {.loc = kw_loc_of(&cd[i])};
        int ibq;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "HGID", 0, &h.id));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "IHQ", 0, &h.ihq));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 2, "QM", 0, &h.qm));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 3, "IBQ", 0, &ibq));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 4, "Q1", 0, &h.q1));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 5, "Q2", 0, &h.q2));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 6, "QB/VDC", 0, &h.qb));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 7, "QW", 0, &h.qw));
        if (h.ihq < 0 || h.ihq > 10)
            return refuse(c, &cd[i], &KW_L10, 1, "IHQ", "hourglass types are 0..10");
        if (!(h.qm >= 0))
            return refuse(c, &cd[i], &KW_L10, 2, "QM", "must be >= 0");
        if (fe_kw_find_hourglass(c->d, h.id))
            return kw_fail(c, cd[i].file, cd[i].line, 1, MCS_ERR_FORMAT,
                           "hourglass %d is defined twice", h.id);
        fe_kw_hourglass *p = kw_push((void **)&c->d->hg, &c->d->nhg, &c->d->cap_hg, sizeof *p);
        if (!p) return kw_nomem(c);
        *p = h;
    }
    return MCS_OK;
}

/* IHQ QH */
mcs_status kw_h_control_hourglass(kw_ctx *c, const kw_card *cd, int n)
{
    fe_kw_control *k = &c->d->ctl;
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "IHQ", 0, &k->hg_ihq));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 1, "QH", 0, &k->hg_qh));
        if (k->hg_ihq < -10 || k->hg_ihq > 10)
            return refuse(c, &cd[i], &KW_L10, 0, "IHQ", "hourglass types are 0..10");
        if (!(k->hg_qh >= 0)) return refuse(c, &cd[i], &KW_L10, 1, "QH", "must be >= 0");
        k->hg_given = 1;
        k->hg_loc = kw_loc_of(&cd[i]);
        break;
    }
    return MCS_OK;
}

/* DTINIT TSSFAC ISDO TSLIMT DT2MS LCTM ERODE MS1ST [/ DT2MSF DT2MSLC IMSCL ...] */
mcs_status kw_h_control_timestep(kw_ctx *c, const kw_card *cd, int n)
{
    fe_kw_control *k = &c->d->ctl;
    int i = 0;
    while (i < n && kw_blank_card(&cd[i])) i++;
    if (i >= n) return MCS_OK;
    const double T = c->d->unit[1];
    KW_TRY(kw_real(c, &cd[i], &KW_L10, 0, "DTINIT", 0, &k->dtinit));
    KW_TRY(kw_real(c, &cd[i], &KW_L10, 1, "TSSFAC", 0, &k->tssfac));
    KW_TRY(kw_int(c, &cd[i], &KW_L10, 2, "ISDO", 0, &k->isdo));
    KW_TRY(kw_real(c, &cd[i], &KW_L10, 3, "TSLIMT", 0, &k->tslimt));
    KW_TRY(kw_real(c, &cd[i], &KW_L10, 4, "DT2MS", 0, &k->dt2ms));
    KW_TRY(kw_int(c, &cd[i], &KW_L10, 5, "LCTM", 0, &k->lctm));
    KW_TRY(kw_int(c, &cd[i], &KW_L10, 7, "MS1ST", 0, &k->ms1st));
    if (!(k->tssfac >= 0 && k->tssfac <= 2))
        return refuse(c, &cd[i], &KW_L10, 1, "TSSFAC", "must be in [0, 2]");
    k->dtinit *= T, k->tslimt *= T, k->dt2ms *= T;
    k->ts_given = 1;
    k->ts_loc = kw_loc_of(&cd[i]);
    for (i++; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 0, "DT2MSF", 0, &k->dt2msf));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "DT2MSLC", 0, &k->dt2mslc));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 2, "IMSCL", 0, &k->imscl));
        break;
    }
    return MCS_OK;
}

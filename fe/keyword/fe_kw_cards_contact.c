/* fe_kw_cards_contact: handlers of *CONTACT_* (single surface, surface to surface, nodes to
 * surface, general), *SET_SEGMENT, *SET_NODE_LIST_GENERATE, *SET_PART_LIST_GENERATE,
 * *INITIAL_VELOCITY_NODE, *BOUNDARY_PRESCRIBED_MOTION_NODE/_SET/_RIGID, *LOAD_NODE_POINT,
 * *LOAD_NODE_SET, *LOAD_SEGMENT and *CONTROL_TERMINATION (field names as in the LS-DYNA
 * manual; what they become in a model: fe_kw_build_contact.c, docs/keyword.md). */
#include "fe/fe_kw_impl.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* column of field i of a 10-wide card (0 in free format) */
static int col_of(const kw_ctx *c, const kw_card *cd, int i)
{
    if (memchr(cd->s, ',', (size_t)cd->len)) return 0;
    return 1 + i * (c->fmt == KW_FMT_LONG ? 20 : 10);
}

static mcs_status refuse(kw_ctx *c, const kw_card *cd, int i, const char *name, const char *why)
{
    return kw_fail(c, cd->file, cd->line, col_of(c, cd, i), MCS_ERR_UNSUPPORTED, "field %s: %s",
                   name, why);
}

/* the ID card of the _ID and _TITLE options: CID (I10) HEADING (A70) */
static mcs_status id_card(kw_ctx *c, const kw_card *cd, int n, int *i, int *id, char *title)
{
    *id = 0;
    if (!c->has_id && !c->has_title) return MCS_OK;
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

static mcs_status reals(kw_ctx *c, const kw_card *cd, int f0, int nf, const char *const *nm,
                        const double *dflt, double *out)
{
    for (int k = 0; k < nf; k++)
        KW_TRY(kw_real(c, cd, &KW_L10, f0 + k, nm[k], dflt ? dflt[k] : 0, &out[k]));
    return MCS_OK;
}

/* ---- *CONTACT_* ---- */

/* card 1: SSID MSID SSTYP MSTYP SBOXID MBOXID SPR MPR */
static mcs_status contact_card1(kw_ctx *c, const kw_card *cd, fe_kw_contact *k)
{
    int sbox, mbox;
    KW_TRY(kw_int(c, cd, &KW_L10, 0, "SSID", 0, &k->ssid));
    KW_TRY(kw_int(c, cd, &KW_L10, 1, "MSID", 0, &k->msid));
    KW_TRY(kw_int(c, cd, &KW_L10, 2, "SSTYP", 0, &k->sstyp));
    KW_TRY(kw_int(c, cd, &KW_L10, 3, "MSTYP", 0, &k->mstyp));
    KW_TRY(kw_int(c, cd, &KW_L10, 4, "SBOXID", 0, &sbox));
    KW_TRY(kw_int(c, cd, &KW_L10, 5, "MBOXID", 0, &mbox));
    int spr, mpr; /* output flags of the interface force file: read, nothing to honour */
    KW_TRY(kw_int(c, cd, &KW_L10, 6, "SPR", 0, &spr));
    KW_TRY(kw_int(c, cd, &KW_L10, 7, "MPR", 0, &mpr));
    if (sbox || mbox)
        return refuse(c, cd, sbox ? 4 : 5, sbox ? "SBOXID" : "MBOXID",
                      "contact boxes are not built (leave blank)");
    if (k->sstyp < 0 || k->sstyp > 7 || k->mstyp < 0 || k->mstyp > 7)
        return refuse(c, cd, k->sstyp < 0 || k->sstyp > 7 ? 2 : 3, "SSTYP/MSTYP",
                      "ID types are 0..7");
    if (k->sstyp == 1 || k->sstyp == 7 || k->mstyp == 1 || k->mstyp == 7)
        return refuse(c, cd, k->sstyp == 1 || k->sstyp == 7 ? 2 : 3, "SSTYP/MSTYP",
                      "shell element sets (1) and branch IDs (7) are not built: give a part "
                      "(3), part set (2), all parts (5), all but a part set (6), a segment set "
                      "(0) or a node set (4, slave side)");
    if (k->mstyp == 4) return refuse(c, cd, 3, "MSTYP", "a node set cannot be the master side");
    return MCS_OK;
}

/* card 2: FS FD DC VC VDC PENCHK BT DT */
static mcs_status contact_card2(kw_ctx *c, const kw_card *cd, fe_kw_contact *k)
{
    static const char *const nm[5] = {"FS", "FD", "DC", "VC", "VDC"};
    double v[5];
    KW_TRY(reals(c, cd, 0, 5, nm, NULL, v));
    int penchk;
    KW_TRY(kw_int(c, cd, &KW_L10, 5, "PENCHK", 0, &penchk));
    KW_TRY(kw_real(c, cd, &KW_L10, 6, "BT", 0, &k->bt));
    KW_TRY(kw_real(c, cd, &KW_L10, 7, "DT", 0, &k->dt));
    k->fs = v[0], k->fd = v[1], k->dc = v[2] * c->d->unit[1] / c->d->unit[0];
    k->vc = v[3] * kw_u_stress(c->d), k->vdc = v[4];
    if (k->fs < 0 || k->fd < 0 || k->dc < 0)
        return refuse(c, cd,
                      k->fs < 0   ? 0
                      : k->fd < 0 ? 1
                                  : 2,
                      "FS/FD/DC",
                      "friction from *PART_CONTACT or a table (negative values) is not built");
    if (k->vc != 0)
        return refuse(c, cd, 3, "VC", "the viscous friction limit is not built (leave 0)");
    /* VDC: normal contact damping in percent of critical (fe_contact_desc.damping) */
    if (!(k->vdc >= 0 && k->vdc <= 100))
        return refuse(c, cd, 4, "VDC", "contact damping is a percentage of critical: 0..100");
    if (k->bt < 0)
        return refuse(c, cd, 6, "BT", "a negative birth time (dynamic relaxation) is not built");
    if (k->dt >= 1e20) k->dt = 0; /* the default: never */
    if (k->dt < 0)
        return refuse(c, cd, 7, "DT", "a negative death time (dynamic relaxation) is not built");
    if (k->dt != 0 && k->dt <= k->bt)
        return refuse(c, cd, 7, "DT", "the death time must come after the birth time BT");
    if (penchk != 0)
        kw_warn(c, cd,
             "PENCHK %d read and ignored: the kernel never releases a penetrating node "
             "(docs/fe.md, Contact)",
             penchk);
    k->bt *= c->d->unit[1], k->dt *= c->d->unit[1];
    return MCS_OK;
}

/* card 3: SFS SFM SST MST SFST SFMT FSF VSF */
static mcs_status contact_card3(kw_ctx *c, const kw_card *cd, fe_kw_contact *k)
{
    static const char *const nm[8] = {"SFS", "SFM", "SST", "MST", "SFST", "SFMT", "FSF", "VSF"};
    static const double dflt[8] = {1, 1, 0, 0, 1, 1, 1, 1};
    double v[8];
    KW_TRY(reals(c, cd, 0, 8, nm, dflt, v));
    for (int i = 0; i < 8; i++)
        if (v[i] == 0 && dflt[i] == 1) v[i] = 1; /* LS-DYNA: 0 takes the default 1 */
    k->sfs = v[0], k->sfm = v[1], k->sfst = v[4], k->sfmt = v[5], k->fsf = v[6];
    k->sst = v[2] * kw_u_len(c->d), k->mst = v[3] * kw_u_len(c->d);
    if (v[2] != 0 || v[3] != 0)
        return refuse(c, cd, v[2] != 0 ? 2 : 3, v[2] != 0 ? "SST" : "MST",
                      "a contact thickness override is not built (scale it with SFST/SFMT)");
    if (k->sfs != k->sfm)
        return refuse(c, cd, 1, "SFS/SFM",
                      "one penalty scale per interface is built: give SFS = SFM");
    if (k->sfst != k->sfmt)
        return refuse(c, cd, 5, "SFST/SFMT",
                      "one shell thickness scale per interface is built: give SFST = SFMT");
    if (!(k->sfs > 0) || !(k->sfst > 0) || !(k->fsf > 0))
        return refuse(c, cd, 0, "SFS/SFST/FSF", "scale factors must be > 0");
    return MCS_OK;
}

/* optional cards A (SOFT SOFSCL LCIDAB MAXPAR SBOPT DEPTH BSORT FRCFRQ) and B (PENMAX THKOPT
 * SHLTHK SNLOG ISYM I2D3D SLDTHK SLDSTF); C, D, E, F: search and output controls, read over */
static mcs_status contact_optional(kw_ctx *c, const kw_card *cd, int n, fe_kw_contact *k)
{
    if (n > 9)
        return kw_fail(c, cd[9].file, cd[9].line, 0, MCS_ERR_FORMAT,
                       "%d cards after card 3; a contact has at most the optional cards A to F",
                       n - 3);
    if (n > 3) {
        KW_TRY(kw_int(c, &cd[3], &KW_L10, 0, "SOFT", 0, &k->soft));
        if (k->soft != 0)
            return refuse(c, &cd[3], 0, "SOFT",
                          "soft constraint (1) and segment-based (2) contact are not built: the "
                          "penalty contact (0) is");
    }
    if (n > 4) {
        KW_TRY(kw_real(c, &cd[4], &KW_L10, 6, "SLDTHK", 0, &k->sldthk));
        KW_TRY(kw_real(c, &cd[4], &KW_L10, 7, "SLDSTF", 0, &k->sldstf));
        int isym, i2d3d;
        KW_TRY(kw_int(c, &cd[4], &KW_L10, 4, "ISYM", 0, &isym));
        KW_TRY(kw_int(c, &cd[4], &KW_L10, 5, "I2D3D", 0, &i2d3d));
        if (k->sldthk != 0 || k->sldstf != 0)
            return refuse(c, &cd[4], k->sldthk != 0 ? 6 : 7, "SLDTHK/SLDSTF",
                          "solid contact thickness and stiffness are not built (leave 0)");
        if (isym != 0)
            return refuse(c, &cd[4], 4, "ISYM", "symmetry planes are not built (leave 0)");
    }
    return MCS_OK;
}

/* the _MPP option's cards after the ID card: IGNORE BCKT LCBCKT NS2TRK INITITR PARMAX - CPARM8,
 * and a second (CHKSEGS PENSF GRPABLE) when the next card starts with '&': parallel search
 * settings, read over */
static mcs_status mpp_cards(kw_ctx *c, const kw_card *cd, int n, int *i)
{
    KW_TRY(kw_need(c, cd, n, *i, 1));
    int ignore;
    KW_TRY(kw_int(c, &cd[*i], &KW_L10, 0, "IGNORE", 0, &ignore));
    (*i)++;
    if (*i < n) {
        const char *p = cd[*i].s;
        while (*p == ' ')
            p++;
        if (*p == '&') (*i)++;
    }
    return MCS_OK;
}

static mcs_status h_contact_mpp(kw_ctx *c, const kw_card *cd, int n, fe_kw_ctype type,
                                int automatic, int mpp)
{
    fe_kw_contact k = {.type = type, .automatic = automatic};
    int i = 0;
    KW_TRY(id_card(c, cd, n, &i, &k.id, k.title));
    if (mpp) KW_TRY(mpp_cards(c, cd, n, &i));
    KW_TRY(kw_need(c, cd, n, i, 1));
    k.loc = kw_loc_of(&cd[i]);
    KW_TRY(contact_card1(c, &cd[i], &k));
    /* cards 2 and 3 may be left out: their defaults */
    static const kw_card none = {.s = "", .len = 0};
    kw_card blank = none;
    blank.file = cd[i].file, blank.line = cd[i].line;
    KW_TRY(contact_card2(c, i + 1 < n ? &cd[i + 1] : &blank, &k));
    KW_TRY(contact_card3(c, i + 2 < n ? &cd[i + 2] : &blank, &k));
    KW_TRY(contact_optional(c, cd + i, n - i, &k));
    fe_kw_contact *p =
        kw_push((void **)&c->d->contact, &c->d->ncontact, &c->d->cap_contact, sizeof *p);
    if (!p) return kw_nomem(c);
    *p = k;
    return MCS_OK;
}

static mcs_status h_contact(kw_ctx *c, const kw_card *cd, int n, fe_kw_ctype type, int automatic)
{
    return h_contact_mpp(c, cd, n, type, automatic, 0);
}

/* *CONTACT_<type>_MPP(_ID, _TITLE) and *CONTACT_<type>_ID_MPP: the type from the name */
mcs_status kw_h_contact_mpp(kw_ctx *c, const kw_card *cd, int n)
{
    static const struct {
        const char *name;
        fe_kw_ctype type;
        int automatic;
    } base[] = {{"CONTACT_AUTOMATIC_SINGLE_SURFACE", FE_KW_CT_SINGLE, 1},
                {"CONTACT_AUTOMATIC_GENERAL", FE_KW_CT_GENERAL, 1},
                {"CONTACT_SURFACE_TO_SURFACE", FE_KW_CT_S2S, 0},
                {"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", FE_KW_CT_S2S, 1},
                {"CONTACT_NODES_TO_SURFACE", FE_KW_CT_N2S, 0},
                {"CONTACT_AUTOMATIC_NODES_TO_SURFACE", FE_KW_CT_N2S, 1}};
    char name[FE_KW_NAME_MAX];
    snprintf(name, sizeof name, "%s", c->kw);
    size_t len = strlen(name);
    int id = len > 7 && strcmp(name + len - 7, "_ID_MPP") == 0;
    name[len - (id ? 7 : 4)] = 0; /* the table sends only names ending in _MPP */
    for (size_t k = 0; k < sizeof base / sizeof base[0]; k++) {
        if (strcmp(name, base[k].name) != 0) continue;
        int had = c->has_id;
        c->has_id = had || id;
        mcs_status st = h_contact_mpp(c, cd, n, base[k].type, base[k].automatic, 1);
        c->has_id = had;
        return st;
    }
    return kw_fail(c, c->kwloc.file, c->kwloc.line, 1, MCS_ERR_FORMAT, "not a contact type");
}

mcs_status kw_h_contact_single(kw_ctx *c, const kw_card *cd, int n)
{
    return h_contact(c, cd, n, FE_KW_CT_SINGLE, 1);
}
mcs_status kw_h_contact_general(kw_ctx *c, const kw_card *cd, int n)
{
    return h_contact(c, cd, n, FE_KW_CT_GENERAL, 1);
}
mcs_status kw_h_contact_s2s(kw_ctx *c, const kw_card *cd, int n)
{
    return h_contact(c, cd, n, FE_KW_CT_S2S, 0);
}
mcs_status kw_h_contact_auto_s2s(kw_ctx *c, const kw_card *cd, int n)
{
    return h_contact(c, cd, n, FE_KW_CT_S2S, 1);
}
mcs_status kw_h_contact_n2s(kw_ctx *c, const kw_card *cd, int n)
{
    return h_contact(c, cd, n, FE_KW_CT_N2S, 0);
}
mcs_status kw_h_contact_auto_n2s(kw_ctx *c, const kw_card *cd, int n)
{
    return h_contact(c, cd, n, FE_KW_CT_N2S, 1);
}

/* ---- sets ---- */

/* [title] / SID DA1 DA2 DA3 DA4 SOLVER: the SID, checked unique among sets of its kind */
static mcs_status set_head(kw_ctx *c, const kw_card *cd, int n, int *i, int *sid, int kind)
{
    *i = c->has_title ? 1 : 0;
    KW_TRY(kw_need(c, cd, n, *i, 1));
    KW_TRY(kw_int(c, &cd[*i], &KW_L10, 0, "SID", 0, sid));
    int dup = 0;
    if (kind < 2) dup = fe_kw_find_set(c->d, *sid, kind) != NULL;
    for (int k = 0; k < c->d->nsegset && kind == 2; k++)
        dup |= c->d->segset[k].id == *sid;
    if (dup)
        return kw_fail(c, cd[*i].file, cd[*i].line, 1, MCS_ERR_FORMAT, "set %d is defined twice",
                       *sid);
    (*i)++;
    return MCS_OK;
}

/* *SET_NODE_LIST_GENERATE, *SET_PART_LIST_GENERATE: B1BEG B1END ... B4BEG B4END ranges */
static mcs_status h_set_generate(kw_ctx *c, const kw_card *cd, int n, int is_part)
{
    int i, sid;
    KW_TRY(set_head(c, cd, n, &i, &sid, is_part));
    fe_kw_set s = {.id = sid, .is_part = is_part, .loc = kw_loc_of(&cd[i - 1])};
    int cap = 0;
    static const char *const nm[8] = {"B1BEG", "B1END", "B2BEG", "B2END",
                                      "B3BEG", "B3END", "B4BEG", "B4END"};
    mcs_status st = MCS_OK;
    for (; i < n && !st; i++)
        for (int f = 0; f < 8 && !st; f += 2) {
            int b, e;
            st = kw_int(c, &cd[i], &KW_L10, f, nm[f], 0, &b);
            if (!st) st = kw_int(c, &cd[i], &KW_L10, f + 1, nm[f + 1], 0, &e);
            if (st || (b == 0 && e == 0)) continue;
            if (b <= 0 || e < b || (long)e - b > 100000000L) {
                st = kw_fail(c, cd[i].file, cd[i].line, col_of(c, &cd[i], f), MCS_ERR_FORMAT,
                             "field %s/%s: a range needs 0 < BEG <= END, got %d %d", nm[f],
                             nm[f + 1], b, e);
                continue;
            }
            if (kw_grow((void **)&s.ids, &cap, s.n + (e - b + 1), sizeof(int))) {
                st = kw_nomem(c);
                continue;
            }
            for (int v = b; v <= e; v++)
                s.ids[s.n++] = v;
        }
    fe_kw_set *p = st ? NULL : kw_push((void **)&c->d->set, &c->d->nset, &c->d->cap_set, sizeof *p);
    if (!st && !p) st = kw_nomem(c);
    if (st) {
        free(s.ids);
        return st;
    }
    *p = s;
    return MCS_OK;
}

mcs_status kw_h_set_node_gen(kw_ctx *c, const kw_card *cd, int n)
{
    return h_set_generate(c, cd, n, 0);
}
mcs_status kw_h_set_part_gen(kw_ctx *c, const kw_card *cd, int n)
{
    return h_set_generate(c, cd, n, 1);
}

/* *SET_SEGMENT: N1 N2 N3 N4 A1 A2 A3 A4 per card (the attributes are read over) */
mcs_status kw_h_set_segment(kw_ctx *c, const kw_card *cd, int n)
{
    int i, sid;
    KW_TRY(set_head(c, cd, n, &i, &sid, 2));
    fe_kw_segset s = {.id = sid, .loc = kw_loc_of(&cd[i - 1])};
    s.node = malloc(4 * sizeof(int) * (size_t)(n - i > 0 ? n - i : 1));
    if (!s.node) return kw_nomem(c);
    static const char *const nm[4] = {"N1", "N2", "N3", "N4"};
    mcs_status st = MCS_OK;
    for (; i < n && !st; i++) {
        if (kw_blank_card(&cd[i])) continue;
        int *q = s.node + 4 * s.n;
        for (int k = 0; k < 4 && !st; k++)
            st = kw_int(c, &cd[i], &KW_L10, k, nm[k], 0, &q[k]);
        if (st) break;
        if (q[3] == 0) q[3] = q[2]; /* a triangle */
        if (q[0] <= 0 || q[1] <= 0 || q[2] <= 0)
            st = kw_fail(c, cd[i].file, cd[i].line, col_of(c, &cd[i], 0), MCS_ERR_FORMAT,
                         "field N1..N3: a segment needs at least three nodes");
        s.n++;
    }
    fe_kw_segset *p =
        st ? NULL : kw_push((void **)&c->d->segset, &c->d->nsegset, &c->d->cap_segset, sizeof *p);
    if (!st && !p) st = kw_nomem(c);
    if (st) {
        free(s.node);
        return st;
    }
    *p = s;
    return MCS_OK;
}

/* ---- *INITIAL_VELOCITY_NODE: NID VX VY VZ VXR VYR VZR ICID ---- */

mcs_status kw_h_initvel_node(kw_ctx *c, const kw_card *cd, int n)
{
    static const char *const nm[6] = {"VX", "VY", "VZ", "VXR", "VYR", "VZR"};
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        fe_kw_nodevel v = {.loc = kw_loc_of(&cd[i])};
        double x[6];
        int icid;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "NID", 0, &v.nid));
        KW_TRY(reals(c, &cd[i], 1, 6, nm, NULL, x));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 7, "ICID", 0, &icid));
        if (icid) return refuse(c, &cd[i], 7, "ICID", "local systems are not built");
        for (int k = 0; k < 3; k++) {
            v.v[k] = x[k] * kw_u_vel(c->d);
            v.vr[k] = x[3 + k] * kw_u_rate(c->d);
        }
        fe_kw_nodevel *p =
            kw_push((void **)&c->d->nodevel, &c->d->nnodevel, &c->d->cap_nodevel, sizeof *p);
        if (!p) return kw_nomem(c);
        *p = v;
    }
    return MCS_OK;
}

/* ---- *BOUNDARY_PRESCRIBED_MOTION_NODE | _SET | _RIGID (_ID) ---- */

static mcs_status h_pmotion(kw_ctx *c, const kw_card *cd, int n, fe_kw_target on)
{
    int i = 0, id0;
    KW_TRY(id_card(c, cd, n, &i, &id0, NULL));
    const char *idname = on == FE_KW_ON_NODE ? "NID" : on == FE_KW_ON_PART ? "PID" : "NSID";
    for (; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        fe_kw_pmotion m = {.on = on, .loc = kw_loc_of(&cd[i])};
        int vid;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, idname, 0, &m.id));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "DOF", 0, &m.dof));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 2, "VAD", 0, &m.vad));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 3, "LCID", 0, &m.lcid));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 4, "SF", 1, &m.sf));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 5, "VID", 0, &vid));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 6, "DEATH", 0, &m.death));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 7, "BIRTH", 0, &m.birth));
        if (m.sf == 0) m.sf = 1; /* LS-DYNA: 0 takes the default 1 */
        if (m.death >= 1e20) m.death = 0;
        if (!((m.dof >= 1 && m.dof <= 3) || (m.dof >= 5 && m.dof <= 7)))
            return refuse(c, &cd[i], 1, "DOF",
                          "1, 2, 3 (x, y, z) and 5, 6, 7 (rotations) are built, not vectors, "
                          "local or coupled dofs");
        if (m.vad != 0 && m.vad != 2)
            return refuse(c, &cd[i], 2, "VAD",
                          "0 (velocity) and 2 (displacement) are built on nodes and parts");
        if (vid) return refuse(c, &cd[i], 5, "VID", "direction vectors are not built");
        if (m.birth != 0 || m.death != 0)
            return refuse(c, &cd[i], m.birth != 0 ? 7 : 6, "BIRTH/DEATH",
                          "a prescribed motion holds for the whole run (leave blank)");
        if (m.lcid <= 0)
            return kw_fail(c, cd[i].file, cd[i].line, col_of(c, &cd[i], 3), MCS_ERR_FORMAT,
                           "field LCID: a motion needs a curve, got %d", m.lcid);
        fe_kw_pmotion *p =
            kw_push((void **)&c->d->pmotion, &c->d->npmotion, &c->d->cap_pmotion, sizeof *p);
        if (!p) return kw_nomem(c);
        *p = m;
    }
    return MCS_OK;
}

mcs_status kw_h_pmotion_node(kw_ctx *c, const kw_card *cd, int n)
{
    return h_pmotion(c, cd, n, FE_KW_ON_NODE);
}
mcs_status kw_h_pmotion_set(kw_ctx *c, const kw_card *cd, int n)
{
    return h_pmotion(c, cd, n, FE_KW_ON_NODESET);
}
mcs_status kw_h_pmotion_rigid(kw_ctx *c, const kw_card *cd, int n)
{
    return h_pmotion(c, cd, n, FE_KW_ON_PART);
}

/* ---- loads ---- */

/* *LOAD_NODE_POINT / *LOAD_NODE_SET: NID|NSID DOF LCID SF CID M1 M2 M3 */
static mcs_status h_load_node(kw_ctx *c, const kw_card *cd, int n, int set)
{
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        fe_kw_load l = {.loc = kw_loc_of(&cd[i]), .segment = set ? 2 : 0};
        int cid;
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, set ? "NSID" : "NID", 0, &l.nid));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "DOF", 0, &l.dof));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 2, "LCID", 0, &l.lcid));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 3, "SF", 1, &l.sf));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 4, "CID", 0, &cid));
        if (l.dof < 1 || l.dof > 3)
            return refuse(c, &cd[i], 1, "DOF",
                          "forces along x, y, z (1, 2, 3) are built, not moments or follower "
                          "forces");
        if (cid) return refuse(c, &cd[i], 4, "CID", "local systems are not built");
        if (l.lcid <= 0)
            return kw_fail(c, cd[i].file, cd[i].line, col_of(c, &cd[i], 2), MCS_ERR_FORMAT,
                           "field LCID: a load needs a curve, got %d", l.lcid);
        fe_kw_load *p = kw_push((void **)&c->d->load, &c->d->nload, &c->d->cap_load, sizeof *p);
        if (!p) return kw_nomem(c);
        *p = l;
    }
    return MCS_OK;
}

mcs_status kw_h_load_node_point(kw_ctx *c, const kw_card *cd, int n)
{
    return h_load_node(c, cd, n, 0);
}
mcs_status kw_h_load_node_set(kw_ctx *c, const kw_card *cd, int n)
{
    return h_load_node(c, cd, n, 1);
}

/* *LOAD_SEGMENT: LCID SF AT N1 N2 N3 N4 (N5..N8) per card; read whole, refused when built */
mcs_status kw_h_load_segment(kw_ctx *c, const kw_card *cd, int n)
{
    static const char *const nm[4] = {"N1", "N2", "N3", "N4"};
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        fe_kw_load l = {.loc = kw_loc_of(&cd[i]), .segment = 1};
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "LCID", 0, &l.lcid));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 1, "SF", 1, &l.sf));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 2, "AT", 0, &l.at));
        for (int k = 0; k < 4; k++)
            KW_TRY(kw_int(c, &cd[i], &KW_L10, 3 + k, nm[k], 0, &l.node[k]));
        l.at *= c->d->unit[1];
        fe_kw_load *p = kw_push((void **)&c->d->load, &c->d->nload, &c->d->cap_load, sizeof *p);
        if (!p) return kw_nomem(c);
        *p = l;
    }
    return MCS_OK;
}

/* ---- *CONTROL_TERMINATION: ENDTIM ENDCYC DTMIN ENDENG ENDMAS NOSOL ---- */

mcs_status kw_h_control_termination(kw_ctx *c, const kw_card *cd, int n)
{
    if (n < 1) return MCS_OK;
    double endtim, dtmin, endeng, endmas;
    int endcyc, nosol;
    KW_TRY(kw_real(c, &cd[0], &KW_L10, 0, "ENDTIM", 0, &endtim));
    KW_TRY(kw_int(c, &cd[0], &KW_L10, 1, "ENDCYC", 0, &endcyc));
    KW_TRY(kw_real(c, &cd[0], &KW_L10, 2, "DTMIN", 0, &dtmin));
    KW_TRY(kw_real(c, &cd[0], &KW_L10, 3, "ENDENG", 0, &endeng));
    KW_TRY(kw_real(c, &cd[0], &KW_L10, 4, "ENDMAS", 0, &endmas));
    KW_TRY(kw_int(c, &cd[0], &KW_L10, 5, "NOSOL", 0, &nosol));
    if (endtim < 0) return refuse(c, &cd[0], 0, "ENDTIM", "must be >= 0");
    if (endcyc || dtmin != 0 || endeng != 0 || endmas != 0)
        kw_warn(c, &cd[0],
             "ENDCYC, DTMIN, ENDENG, ENDMAS read and ignored: the run ends at ENDTIM "
             "and stops on its own checks (time-step collapse, energy growth)");
    if (nosol) return refuse(c, &cd[0], 5, "NOSOL", "a run without solution is not built");
    c->d->end_time = endtim * c->d->unit[1];
    return MCS_OK;
}

/* ---- *CONTROL_CONTACT: SLSFAC RWPNAL ISLCHK SHLTHK PENOPT THKCHG ORIEN ENMASS / ... ---- */

mcs_status kw_h_control_contact(kw_ctx *c, const kw_card *cd, int n)
{
    if (n < 1) return MCS_OK;
    KW_TRY(kw_real(c, &cd[0], &KW_L10, 0, "SLSFAC", 0, &c->d->slsfac));
    KW_TRY(kw_real(c, &cd[0], &KW_L10, 1, "RWPNAL", 0, &c->d->rwpnal));
    int v[6];
    static const char *const nm[6] = {"ISLCHK", "SHLTHK", "PENOPT", "THKCHG", "ORIEN", "ENMASS"};
    for (int k = 0; k < 6; k++)
        KW_TRY(kw_int(c, &cd[0], &KW_L10, 2 + k, nm[k], 0, &v[k]));
    if (c->d->slsfac < 0) return refuse(c, &cd[0], 0, "SLSFAC", "must be >= 0");
    c->d->shlthk = v[1];
    c->d->control_contact = kw_loc_of(&cd[0]);
    if (v[2] || v[3] || v[4] || v[5])
        kw_warn(c, &cd[0],
             "PENOPT, THKCHG, ORIEN, ENMASS read and ignored: the kernel's penalty "
             "is the segment's (docs/fe.md, Contact), shell thickness constant, "
             "segments oriented by their elements, no erosion");
    return MCS_OK;
}

void kw_contact_free(fe_kw_deck *d)
{
    for (int i = 0; i < d->nsegset; i++)
        free(d->segset[i].node);
    free(d->contact);
    free(d->segset);
    free(d->nodevel);
    free(d->pmotion);
    free(d->load);
}

/* fe_kw_cards_joint.c: the keyword handlers of joints and constraints (docs/keyword.md):
 * *CONSTRAINED_JOINT_SPHERICAL|REVOLUTE|CYLINDRICAL|TRANSLATIONAL(_ID),
 * *CONSTRAINED_NODAL_RIGID_BODY, *CONSTRAINED_EXTRA_NODES_NODE|SET,
 * *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED|TRANSLATIONAL. The deck keeps them as read (node
 * and set IDs); fe_kw_build_joint.c puts them into a builder. */
#include "fe/fe_kw_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* N1..N6 needed by each joint type */
static const int joint_nodes[4] = {2, 4, 4, 6};

static mcs_status joint_cards(kw_ctx *c, const kw_card *cd, int n, int type)
{
    for (int i = 0; i < n;) {
        fe_kw_joint j = {.type = type};
        if (c->has_id) { /* JID + HEADING: I10 + A70 in every format */
            static const kw_layout l = {1, {10}};
            int fmt = c->fmt;
            c->fmt = KW_FMT_STD;
            mcs_status st = kw_int(c, &cd[i], &l, 0, "JID", 0, &j.id);
            c->fmt = fmt;
            KW_TRY(st);
            kw_text(&cd[i], 10, 70, j.title, sizeof j.title);
            if (++i >= n)
                return kw_fail(c, cd[i - 1].file, cd[i - 1].line, 0, MCS_ERR_FORMAT,
                               "the node card N1..N6 must follow the ID card");
        }
        if (kw_blank_card(&cd[i])) {
            i++;
            continue;
        }
        static const char *nm[6] = {"N1", "N2", "N3", "N4", "N5", "N6"};
        for (int k = 0; k < 6; k++)
            KW_TRY(kw_int(c, &cd[i], &KW_L10, k, nm[k], 0, &j.node[k]));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 6, "RPS", 1, &j.rps));
        KW_TRY(kw_real(c, &cd[i], &KW_L10, 7, "DAMP", 1, &j.damp));
        if (j.rps == 0) j.rps = 1; /* LS-DYNA: 0 takes the default 1 */
        if (j.damp == 0) j.damp = 1;
        for (int k = 0; k < joint_nodes[type]; k++)
            if (j.node[k] <= 0) {
                int col = 1 + 10 * k;
                if (memchr(cd[i].s, ',', (size_t)cd[i].len)) col = 0;
                return kw_fail(c, cd[i].file, cd[i].line, col, MCS_ERR_FORMAT,
                               "field %s: this joint needs N1..N%d, got %d", nm[k],
                               joint_nodes[type], j.node[k]);
            }
        if (!(j.rps > 0) || !(j.rps <= 10))
            return kw_fail(c, cd[i].file, cd[i].line, 61, MCS_ERR_FORMAT,
                           "field RPS: %g: the relative penalty stiffness must be in (0, 10]",
                           j.rps);
        j.loc = kw_loc_of(&cd[i]);
        if (!c->has_id) j.id = c->d->njoint + 1;
        fe_kw_joint *p = kw_push((void **)&c->d->joint, &c->d->njoint, &c->d->cap_joint, sizeof *p);
        if (!p) return kw_nomem(c);
        *p = j;
        i++;
    }
    return MCS_OK;
}

mcs_status kw_h_joint_spherical(kw_ctx *c, const kw_card *cd, int n)
{
    return joint_cards(c, cd, n, 0);
}
mcs_status kw_h_joint_revolute(kw_ctx *c, const kw_card *cd, int n)
{
    return joint_cards(c, cd, n, 1);
}
mcs_status kw_h_joint_cylindrical(kw_ctx *c, const kw_card *cd, int n)
{
    return joint_cards(c, cd, n, 2);
}
mcs_status kw_h_joint_translational(kw_ctx *c, const kw_card *cd, int n)
{
    return joint_cards(c, cd, n, 3);
}

/* PID, then the node or set: one entry per card */
static mcs_status nrb_cards(kw_ctx *c, const kw_card *cd, int n, int kind)
{
    static const char *second[3] = {"NSID", "NID", "NSID"};
    for (int i = 0; i < n; i++) {
        if (kw_blank_card(&cd[i])) continue;
        fe_kw_nrb r = {.kind = kind, .loc = kw_loc_of(&cd[i])};
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 0, "PID", 0, &r.pid));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, kind == 0 ? 2 : 1, second[kind], 0, &r.id));
        if (kind == 0) {
            int cid;
            KW_TRY(kw_int(c, &cd[i], &KW_L10, 1, "CID", 0, &cid));
        }
        if (r.pid <= 0 || r.id <= 0)
            return kw_fail(c, cd[i].file, cd[i].line, 0, MCS_ERR_FORMAT,
                           "PID %d and %s %d must be > 0", r.pid, second[kind], r.id);
        fe_kw_nrb *p = kw_push((void **)&c->d->nrb, &c->d->nnrb, &c->d->cap_nrb, sizeof *p);
        if (!p) return kw_nomem(c);
        *p = r;
    }
    return MCS_OK;
}

mcs_status kw_h_nodal_rigid_body(kw_ctx *c, const kw_card *cd, int n)
{
    return nrb_cards(c, cd, n, 0);
}
mcs_status kw_h_extra_nodes_node(kw_ctx *c, const kw_card *cd, int n)
{
    return nrb_cards(c, cd, n, 1);
}
mcs_status kw_h_extra_nodes_set(kw_ctx *c, const kw_card *cd, int n)
{
    return nrb_cards(c, cd, n, 2);
}

/* JSID PIDA PIDB CIDA CIDB JID / 3 curves, 3 damping curves / ES FF x 3 / stops x 3 */
static mcs_status jstiff_cards(kw_ctx *c, const kw_card *cd, int n, int transl)
{
    static const char *const gen[4][6] = {
        {"JSID", "PIDA", "PIDB", "CIDA", "CIDB", "JID"},
        {"LCIDPH", "LCIDT", "LCIDPS", "DLCIDPH", "DLCIDT", "DLCIDPS"},
        {"ESPH", "FMPH", "EST", "FMT", "ESPS", "FMPS"},
        {"NSAPH", "PSAPH", "NSAT", "PSAT", "NSAPS", "PSAPS"}};
    static const char *const tra[4][6] = {{"JSID", "PIDA", "PIDB", "CIDA", "CIDB", "JID"},
                                          {"LCIDX", "LCIDY", "LCIDZ", "DLCIDX", "DLCIDY", "DLCIDZ"},
                                          {"ESX", "FFX", "ESY", "FFY", "ESZ", "FFZ"},
                                          {"NSDX", "PSDX", "NSDY", "PSDY", "NSDZ", "PSDZ"}};
    const char *const(*nm)[6] = transl ? tra : gen;
    for (int i = 0; i < n;) {
        if (kw_blank_card(&cd[i])) {
            i++;
            continue;
        }
        if (i + 3 > n)
            return kw_fail(c, cd[n - 1].file, cd[n - 1].line, 0, MCS_ERR_FORMAT,
                           "cards 2 and 3 (curves, stop stiffness) must follow card 1");
        fe_kw_jstiff j = {.translational = transl, .loc = kw_loc_of(&cd[i])};
        int *h[6] = {&j.jsid, &j.pida, &j.pidb, &j.cida, &j.cidb, &j.jid};
        for (int k = 0; k < 6; k++)
            KW_TRY(kw_int(c, &cd[i], &KW_L10, k, nm[0][k], 0, h[k]));
        for (int k = 0; k < 3; k++) {
            KW_TRY(kw_int(c, &cd[i + 1], &KW_L10, k, nm[1][k], 0, &j.lc[k]));
            KW_TRY(kw_int(c, &cd[i + 1], &KW_L10, 3 + k, nm[1][3 + k], 0, &j.dlc[k]));
            KW_TRY(kw_real(c, &cd[i + 2], &KW_L10, 2 * k, nm[2][2 * k], 0, &j.es[k]));
            KW_TRY(kw_real(c, &cd[i + 2], &KW_L10, 2 * k + 1, nm[2][2 * k + 1], 0, &j.ff[k]));
        }
        if (i + 3 < n) { /* card 4: stops, degrees (generalized) or lengths */
            const double u = transl ? kw_u_len(c->d) : M_PI / 180;
            for (int k = 0; k < 3; k++) {
                double a, b;
                KW_TRY(kw_real(c, &cd[i + 3], &KW_L10, 2 * k, nm[3][2 * k], 0, &a));
                KW_TRY(kw_real(c, &cd[i + 3], &KW_L10, 2 * k + 1, nm[3][2 * k + 1], 0, &b));
                j.neg[k] = -fabs(a) * u, j.pos[k] = fabs(b) * u;
            }
        }
        if (j.jid <= 0)
            return kw_fail(c, cd[i].file, cd[i].line, 51, MCS_ERR_FORMAT,
                           "field JID: the joint the stiffness acts on, got %d", j.jid);
        fe_kw_jstiff *p =
            kw_push((void **)&c->d->jstiff, &c->d->njstiff, &c->d->cap_jstiff, sizeof *p);
        if (!p) return kw_nomem(c);
        *p = j;
        i += i + 3 < n ? 4 : 3;
    }
    return MCS_OK;
}

mcs_status kw_h_jstiff_generalized(kw_ctx *c, const kw_card *cd, int n)
{
    return jstiff_cards(c, cd, n, 0);
}
mcs_status kw_h_jstiff_translational(kw_ctx *c, const kw_card *cd, int n)
{
    return jstiff_cards(c, cd, n, 1);
}

void kw_joint_free(fe_kw_deck *d)
{
    free(d->joint);
    free(d->nrb);
    free(d->jstiff);
    d->joint = NULL, d->nrb = NULL, d->jstiff = NULL;
    d->njoint = d->nnrb = d->njstiff = 0;
}

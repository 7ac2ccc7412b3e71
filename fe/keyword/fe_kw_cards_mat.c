/* fe_kw_cards_mat: the material keywords beyond the first subset, read with their documented
 * fields (LS-DYNA Keyword User's Manual, Vol. II; card layouts as in docs/keyword.md) and put
 * on the kernel's models, or refused by name where the kernel has no such behaviour:
 *   *MAT_PLASTIC_KINEMATIC (003)  RO E PR SIGY ETAN BETA / SRC SRP FS VP   -> elastic_plastic
 *   *MAT_NULL (009)               RO PC MU TEROD CEROD YM PR                -> null (no stress)
 *   *MAT_RIGID (020)              RO E PR N COUPLE M ALIAS / CMO CON1 CON2 / ...   -> rigid
 *   *MAT_MOONEY-RIVLIN_RUBBER (027) RO PR A B REF / SGL SW ST LCID          -> refused
 *   *MAT_LOW_DENSITY_FOAM (057)   RO E LCID TC HU BETA DAMP / SHAPE FAIL BVFLAG ED BETA1
 *                                 KCON REF                                  -> foam
 * Every value in SI; kw_mat_desc turns them into kernel descriptors (fe_kw_build.c). */
#include "fe/fe_kw_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* the refusal of field i of a card, at its column */
static mcs_status refuse(kw_ctx *c, const kw_card *cd, int i, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static mcs_status refuse(kw_ctx *c, const kw_card *cd, int i, const char *fmt, ...)
{
    char what[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    int col = 1;
    for (int k = 0; k < i; k++) col += c->fmt == KW_FMT_LONG ? 20 : 10;
    if (memchr(cd->s, ',', (size_t)cd->len)) col = 0;
    return kw_fail(c, cd->file, cd->line, col, MCS_ERR_UNSUPPORTED, "%s", what);
}

/* a new material with MID (field 1 of card cd), checked unique */
static mcs_status new_mat(kw_ctx *c, const kw_card *cd, fe_kw_mat_type type, fe_kw_mat **out)
{
    int id;
    KW_TRY(kw_int(c, cd, &KW_L10, 0, "MID", 0, &id));
    if (fe_kw_find_mat(c->d, id))
        return kw_fail(c, cd->file, cd->line, 1, MCS_ERR_FORMAT, "material %d is defined twice",
                       id);
    fe_kw_mat *m = kw_push((void **)&c->d->mat, &c->d->nmat, &c->d->cap_mat, sizeof *m);
    if (!m) return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
    m->id = id, m->type = type, m->loc = kw_loc_of(cd);
    *out = m;
    return MCS_OK;
}

/* real fields: names[k] of field k (NULL: skipped) into out[k] with defaults dflt[k] */
static mcs_status reals(kw_ctx *c, const kw_card *cd, int nf, const char *const *names,
                        const double *dflt, double *out)
{
    for (int k = 0; k < nf; k++)
        if (names[k]) KW_TRY(kw_real(c, cd, &KW_L10, k, names[k], dflt ? dflt[k] : 0, &out[k]));
    return MCS_OK;
}

static mcs_status all_finite(kw_ctx *c, const kw_card *cd, int n, const double *v)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(v[k]))
            return kw_fail(c, cd->file, cd->line, 0, MCS_ERR_FORMAT,
                           "a value is out of range in SI units");
    return MCS_OK;
}

/* ---- *MAT_PLASTIC_KINEMATIC: MID RO E PR SIGY ETAN BETA / SRC SRP FS VP ---- */

mcs_status kw_h_mat_pk(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i += c->has_title;
        KW_TRY(kw_need(c, cd, n, i, 2));
        fe_kw_mat *m = NULL;
        KW_TRY(new_mat(c, &cd[i], FE_KW_MAT_PK, &m));
        static const char *n1[7] = {NULL, "RO", "E", "PR", "SIGY", "ETAN", "BETA"};
        static const char *n2[4] = {"SRC", "SRP", "FS", "VP"};
        double v[7], w[4];
        KW_TRY(reals(c, &cd[i], 7, n1, NULL, v));
        KW_TRY(reals(c, &cd[i + 1], 4, n2, NULL, w));
        const double S = kw_u_stress(c->d);
        m->ro = v[1] * kw_u_dens(c->d), m->e = v[2] * S, m->pr = v[3];
        m->sigy = v[4] * S, m->etan = v[5] * S, m->beta = v[6];
        m->c = w[0] * kw_u_rate(c->d), m->p = w[1], m->fail = w[2];
        double chk[5] = {m->ro, m->e, m->sigy, m->etan, m->c};
        KW_TRY(all_finite(c, &cd[i], 5, chk));
        /* BETA 0 (blank) is kinematic hardening: the same as isotropic when nothing hardens */
        if (m->etan != 0 && m->beta != 1)
            return refuse(c, &cd[i], 6,
                          "field BETA: %g with ETAN > 0: kinematic or mixed hardening (BETA < 1) "
                          "is not built; BETA = 1 (isotropic) is, and any BETA with ETAN = 0",
                          m->beta);
        if (!(m->beta >= 0 && m->beta <= 1))
            return refuse(c, &cd[i], 6, "field BETA: %g is outside [0, 1]", m->beta);
        if (w[3] != 0 && m->c > 0)
            return refuse(c, &cd[i + 1], 3,
                          "field VP: %g: the viscoplastic rate formulation is not built (VP = 0 "
                          "scales the yield stress by the Cowper-Symonds factor)",
                          w[3]);
        if (m->fail < 0)
            return refuse(c, &cd[i + 1], 2, "field FS: %g: a failure strain is >= 0", m->fail);
        if (!(m->c > 0 && m->p > 0)) m->c = m->p = 0; /* SRC or SRP 0: no rate effects */
        i += 2;
    }
    return MCS_OK;
}

/* ---- *MAT_NULL: MID RO PC MU TEROD CEROD YM PR ---- */

mcs_status kw_h_mat_null(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i += c->has_title;
        KW_TRY(kw_need(c, cd, n, i, 1));
        fe_kw_mat *m = NULL;
        KW_TRY(new_mat(c, &cd[i], FE_KW_MAT_NULL, &m));
        static const char *nm[8] = {NULL, "RO", "PC", "MU", "TEROD", "CEROD", "YM", "PR"};
        double v[8];
        KW_TRY(reals(c, &cd[i], 8, nm, NULL, v));
        m->ro = v[1] * kw_u_dens(c->d), m->e = v[6] * kw_u_stress(c->d), m->pr = v[7];
        double chk[2] = {m->ro, m->e};
        KW_TRY(all_finite(c, &cd[i], 2, chk));
        /* PC bounds an equation of state's pressure: without one there is no pressure */
        if (v[3] != 0)
            return refuse(c, &cd[i], 3,
                          "field MU: %g: the viscous stress of a null material is not built",
                          v[3]);
        if (v[4] != 0 || v[5] != 0)
            return refuse(c, &cd[i], v[4] != 0 ? 4 : 5,
                          "fields TEROD/CEROD: erosion on volumetric strain is not built");
        if (m->e < 0 || !(m->pr > -1 && m->pr < 0.5))
            return refuse(c, &cd[i], m->e < 0 ? 6 : 7,
                          "fields YM/PR: YM >= 0 and -1 < PR < 0.5 (they serve contact only)");
        i++;
    }
    return MCS_OK;
}

/* ---- *MAT_RIGID: MID RO E PR N COUPLE M ALIAS / CMO CON1 CON2 / LCO or A1..V3 ---- */

mcs_status kw_h_mat_rigid(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i += c->has_title;
        KW_TRY(kw_need(c, cd, n, i, 3));
        fe_kw_mat *m = NULL;
        KW_TRY(new_mat(c, &cd[i], FE_KW_MAT_RIGID, &m));
        static const char *nm[4] = {NULL, "RO", "E", "PR"};
        double v[4], cmo;
        KW_TRY(reals(c, &cd[i], 4, nm, NULL, v));
        m->ro = v[1] * kw_u_dens(c->d), m->e = v[2] * kw_u_stress(c->d), m->pr = v[3];
        double chk[2] = {m->ro, m->e};
        KW_TRY(all_finite(c, &cd[i], 2, chk));
        const kw_card *c2 = &cd[i + 1];
        KW_TRY(kw_real(c, c2, &KW_L10, 0, "CMO", 0, &cmo));
        KW_TRY(kw_int(c, c2, &KW_L10, 1, "CON1", 0, &m->con1));
        KW_TRY(kw_int(c, c2, &KW_L10, 2, "CON2", 0, &m->con2));
        m->cmo = cmo == 1; /* 0 or 1 (refused below otherwise): no conversion of a huge value */
        if (cmo != 0 && cmo != 1)
            return refuse(c, c2, 0,
                          "field CMO: %g: constraints in a local system (CMO -1) are not built; "
                          "CMO 1 (global axes) is",
                          cmo);
        if (m->cmo == 0) m->con1 = m->con2 = 0; /* no constraints: CON1, CON2 unused */
        if (m->con1 < 0 || m->con1 > 7)
            return refuse(c, c2, 1, "field CON1: %d: translational codes are 0..7", m->con1);
        if (m->con2 != 0 && m->con2 != 7)
            return refuse(c, c2, 2,
                          "field CON2: %d: a rigid body's rotations are held all together (7) "
                          "or not at all (0); single axes are not built",
                          m->con2);
        i += 3;
    }
    return MCS_OK;
}

/* ---- *MAT_MOONEY-RIVLIN_RUBBER: MID RO PR A B REF / SGL SW ST LCID ---- */

mcs_status kw_h_mat_mr(kw_ctx *c, const kw_card *cd, int n)
{
    int i = c->has_title;
    KW_TRY(kw_need(c, cd, n, i, 1));
    fe_kw_mat *m = NULL;
    KW_TRY(new_mat(c, &cd[i], FE_KW_MAT_MR, &m));
    return kw_fail(c, cd[i].file, cd[i].line, 0, MCS_ERR_UNSUPPORTED,
                   "material %d: the Mooney-Rivlin hyperelastic solid is not built", m->id);
}

/* ---- *MAT_LOW_DENSITY_FOAM: MID RO E LCID TC HU BETA DAMP / SHAPE FAIL BVFLAG ED BETA1 KCON
 * REF ---- */

mcs_status kw_h_mat_ldf(kw_ctx *c, const kw_card *cd, int n)
{
    for (int i = 0; i < n;) {
        i += c->has_title;
        KW_TRY(kw_need(c, cd, n, i, 1));
        fe_kw_mat *m = NULL;
        KW_TRY(new_mat(c, &cd[i], FE_KW_MAT_LDF, &m));
        static const char *n1[8] = {NULL, "RO", "E", NULL, "TC", "HU", "BETA", "DAMP"};
        static const char *n2[7] = {"SHAPE", "FAIL", "BVFLAG", "ED", "BETA1", "KCON", "REF"};
        static const double d1[8] = {0, 0, 0, 0, 1e20, 1, 0, 0};
        static const double d2[7] = {1, 0, 0, 0, 0, 0, 0};
        double v[8], w[7] = {1, 0, 0, 0, 0, 0, 0};
        KW_TRY(reals(c, &cd[i], 8, n1, d1, v));
        KW_TRY(kw_int(c, &cd[i], &KW_L10, 3, "LCID", 0, &m->lcid));
        /* the second card may be left out when it is the keyword's last */
        const int two = i + 1 < n;
        if (two) KW_TRY(reals(c, &cd[i + 1], 7, n2, d2, w));
        const double S = kw_u_stress(c->d);
        m->ro = v[1] * kw_u_dens(c->d), m->e = v[2] * S;
        m->tc = v[4] > 0 && v[4] < 1e20 ? v[4] * S : 0; /* 0: no cut-off */
        m->hu = v[5] > 0 ? v[5] : 1;                    /* 0 is the default, as blank */
        m->shape = w[0] > 0 ? w[0] : 1;
        double chk[3] = {m->ro, m->e, m->tc};
        KW_TRY(all_finite(c, &cd[i], 3, chk));
        if (m->lcid <= 0)
            return refuse(c, &cd[i], 3, "field LCID: the loading curve is required, got %d",
                          m->lcid);
        if (!(m->hu <= 1))
            return refuse(c, &cd[i], 5, "field HU: %g is outside (0, 1]", m->hu);
        if (v[6] != 0)
            return refuse(c, &cd[i], 6, "field BETA: %g: creep in unloading is not built", v[6]);
        if (v[7] != 0)
            return refuse(c, &cd[i], 7,
                          "field DAMP: %g: the foam's viscous damping is not built (give 0)",
                          v[7]);
        if (two && w[1] != 0)
            return refuse(c, &cd[i + 1], 1,
                          "field FAIL: %g: a tension reset to zero is not built (FAIL 0: the "
                          "stress stays at TC)",
                          w[1]);
        if (two && (w[3] != 0 || w[4] != 0))
            return refuse(c, &cd[i + 1], w[3] != 0 ? 3 : 4,
                          "fields ED/BETA1: the foam's relaxation (rate effects) is not built");
        if (two && w[6] != 0)
            return refuse(c, &cd[i + 1], 6,
                          "field REF: a reference geometry (*INITIAL_FOAM_REFERENCE_GEOMETRY) "
                          "is not built");
        /* BVFLAG: the kernel's bulk viscosity acts on every hex; KCON: contacts take their
         * stiffness from E (docs/keyword.md) */
        i += two ? 2 : 1;
    }
    return MCS_OK;
}

/* ---- descriptors (from fe_kw_build.c) ---- */

/* the foam's loading curve: LCID's points of positive strain below 1 (compression positive),
 * stress in the deck's units */
static mcs_status foam_curve(const fe_kw_deck *dk, const fe_kw_mat *k, fe_material_desc *m,
                             mcs_error *err)
{
    const fe_kw_curve *cv = fe_kw_find_curve(dk, k->lcid);
    if (!cv)
        return kw_at(dk, k->loc, err, MCS_ERR_KEY, "*MAT_LOW_DENSITY_FOAM %d: LCID %d is not a "
                                                "*DEFINE_CURVE",
                  k->id, k->lcid);
    int np = 0, dropped = 0;
    for (int i = 0; i < cv->n; i++) {
        const double e = cv->xy[2 * i], s = cv->xy[2 * i + 1] * kw_u_stress(dk);
        if (e < 0 || (e == 0 && s == 0)) continue; /* tension side: E; (0, 0) is implied */
        if (e >= 1) {
            dropped++;
            continue;
        }
        if (np == FE_CURVE_MAX)
            return kw_at(dk, cv->loc, err, MCS_ERR_RANGE,
                      "*DEFINE_CURVE %d: more than %d points of compressive strain in (0, 1) for "
                      "the foam",
                      cv->id, FE_CURVE_MAX);
        m->foam_curve[0][np][0] = e, m->foam_curve[0][np][1] = s;
        np++;
    }
    if (dropped)
        mcs_log(MCS_LOG_WARN, "%s:%d: warning: *DEFINE_CURVE %d: %d point%s at strain >= 1 left "
                              "out of foam %d (the last segment's slope continues)",
                dk->file[cv->loc.file], cv->loc.line, cv->id, dropped, dropped == 1 ? "" : "s",
                k->id);
    if (np == 0)
        return kw_at(dk, cv->loc, err, MCS_ERR_RANGE,
                  "*DEFINE_CURVE %d: no point of compressive strain in (0, 1) for foam %d", cv->id,
                  k->id);
    m->nfoam_curve = 1;
    m->foam_npoint[0] = np;
    return MCS_OK;
}

int kw_mat_desc(const fe_kw_deck *dk, const fe_kw_mat *k, fe_material_desc *m, mcs_error *err,
                mcs_status *st)
{
    static const unsigned con[8] = {0, FE_DOF_X, FE_DOF_Y, FE_DOF_Z, FE_DOF_X | FE_DOF_Y,
                                    FE_DOF_Y | FE_DOF_Z, FE_DOF_Z | FE_DOF_X, FE_DOF_TRANS};
    *st = MCS_OK;
    switch (k->type) {
    case FE_KW_MAT_RIGID:
        m->model = FE_MAT_RIGID;
        if (k->cmo == 1) m->rigid_fix = con[k->con1 & 7] | (k->con2 == 7 ? FE_DOF_ROT : 0);
        return 1;
    case FE_KW_MAT_NULL:
        m->model = FE_MAT_NULL;
        mcs_log(MCS_LOG_INFO, "%s:%d: *MAT_NULL %d: its parts carry no stress (mass only%s)",
                dk->file[k->loc.file], k->loc.line, k->id,
                k->e > 0 ? "; YM sets contact stiffness" : "; no contact without YM");
        return 1;
    case FE_KW_MAT_PK:
        m->model = FE_MAT_ELASTIC_PLASTIC;
        m->yield_stress = k->sigy;
        m->cowper_symonds_c = k->c;
        m->cowper_symonds_p = k->p;
        m->failure_strain = k->fail; /* FS: element erosion */
        if (!(k->sigy > 0)) {
            *st = kw_at(dk, k->loc, err, MCS_ERR_RANGE, "*MAT_PLASTIC_KINEMATIC %d: SIGY must be > 0",
                     k->id);
            return 1;
        }
        if (k->etan > 0) {
            /* bilinear: tangent modulus Et -> plastic modulus H = E Et / (E - Et) */
            if (!(k->etan < k->e)) {
                *st = kw_at(dk, k->loc, err, MCS_ERR_RANGE,
                         "*MAT_PLASTIC_KINEMATIC %d: ETAN must be below E", k->id);
                return 1;
            }
            m->nhardening = 2;
            m->hardening[0][0] = 0, m->hardening[0][1] = k->sigy;
            m->hardening[1][0] = 1;
            m->hardening[1][1] = k->sigy + k->e * k->etan / (k->e - k->etan);
        }
        return 1;
    case FE_KW_MAT_LDF:
        m->model = FE_MAT_FOAM;
        m->poisson = 0; /* no coupling between directions (the manual's uniaxial assumption) */
        m->foam_hysteresis = k->hu;
        m->foam_shape = k->shape;
        m->foam_tension_cutoff = k->tc;
        *st = foam_curve(dk, k, m, err);
        return 1;
    default: return 0;
    }
}

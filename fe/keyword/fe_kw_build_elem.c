/* fe_kw_build_elem: what the element, section, part and control keywords of
 * fe_kw_cards_elem.c become in the kernel: a part's hourglass form (*HOURGLASS,
 * *CONTROL_HOURGLASS), beam sections, a rigid part's given mass properties (*PART_INERTIA),
 * per-element shell thickness (*ELEMENT_SHELL_THICKNESS) and the model options of
 * *CONTROL_TIMESTEP. What the kernel cannot build is refused with the deck line that asked. */
#include "fe/fe_kw_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void warn_at(const fe_kw_deck *dk, fe_kw_loc l, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void warn_at(const fe_kw_deck *dk, fe_kw_loc l, const char *fmt, ...)
{
    char what[800];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    const char *fn = l.file >= 0 && l.file < dk->nfile ? dk->file[l.file] : "(deck)";
    mcs_log(MCS_LOG_WARN, "%s:%d: warning: %s", fn, l.line, what);
}

/* LS-DYNA hourglass types on the kernel's two Flanagan-Belytschko forms: 1-3 viscous, 4-5
 * stiffness (QM as the coefficient, default 0.1); 6-10 (assumed-strain and other stiffness
 * forms) run as the FB stiffness form at the kernel's default coefficient, with a warning,
 * since their QM is scaled differently */
mcs_status kw_part_hourglass(const fe_kw_deck *dk, const fe_kw_part *p, fe_section_desc *s,
                             mcs_error *err)
{
    const fe_kw_hourglass *h = NULL;
    if (p->hgid) {
        h = fe_kw_find_hourglass(dk, p->hgid);
        if (!h)
            return kw_at(dk, p->loc, err, MCS_ERR_KEY, "*PART %d: HGID %d is not an *HOURGLASS",
                      p->id, p->hgid);
    }
    if (!h && !dk->ctl.hg_given) return MCS_OK; /* the kernel's default form */
    int ihq = h ? h->ihq : 0;
    double qm = h ? h->qm : 0;
    fe_kw_loc l = h ? h->loc : dk->ctl.hg_loc;
    if (ihq == 0 && dk->ctl.hg_given) ihq = abs(dk->ctl.hg_ihq), l = dk->ctl.hg_loc;
    if (qm == 0 && dk->ctl.hg_given) qm = dk->ctl.hg_qh;
    if (ihq == 0) ihq = 1; /* LS-DYNA's default type */
    if (ihq <= 3) {
        s->hourglass = FE_HG_VISCOUS;
        s->hourglass_coefficient = qm > 0 ? qm : 0.1;
    } else if (ihq <= 5) {
        s->hourglass = FE_HG_STIFFNESS;
        s->hourglass_coefficient = qm > 0 ? qm : 0.1;
    } else {
        warn_at(dk, l,
                "part %d: hourglass type %d is run as the Flanagan-Belytschko stiffness form "
                "(type 4) at the kernel's coefficient 0.05; QM is not carried over",
                p->id, ihq);
        s->hourglass = FE_HG_STIFFNESS;
        s->hourglass_coefficient = 0;
    }
    if (h && ((h->q1 != 0 && h->q1 != 1.5) || (h->q2 != 0 && h->q2 != 0.06)))
        warn_at(dk, h->loc,
                "*HOURGLASS %d: Q1 %g, Q2 %g: bulk viscosity is one per model (fe_opts "
                "bulk_q1, bulk_q2), not per part: ignored",
                h->id, h->q1, h->q2);
    return MCS_OK;
}

static const char *beam_name(int f)
{
    switch (f) {
    case 1: return "Hughes-Liu";
    case 2: return "Belytschko-Schwer resultant";
    case 4: return "Belytschko-Schwer integrated";
    case 5: return "Belytschko-Schwer tubular";
    case 6: return "discrete beam/cable";
    case 7: case 8: return "2D";
    case 9: return "spot-weld";
    case 11: return "integrated warped";
    case 12: return "resultant warped";
    case 13: return "linear Timoshenko";
    default: return "other";
    }
}

/* ELFORM 3: the truss; 1, 2, 4, 5, 11, 12, 13: trusses of their area only when the caller
 * asks (dk->beams_as_trusses), else refused: they carry bending and torsion, trusses do not */
mcs_status kw_beam_section(const fe_kw_deck *dk, const fe_kw_section *k, fe_section_desc *s,
                           mcs_error *err)
{
    const int f = k->elform;
    s->type = FE_SECTION_TRUSS;
    if (f == 3) {
        s->area = k->area;
        return MCS_OK;
    }
    if (f == 6 || f == 7 || f == 8 || f == 9 || f == 14 || f < 1 || f > 14)
        return kw_at(dk, k->loc, err, MCS_ERR_UNSUPPORTED,
                  "*SECTION_BEAM %d: ELFORM %d (%s) is not built (ELFORM 3, the truss, is)",
                  k->id, f, beam_name(f));
    double A = k->area;
    if (f != 2 && f != 12 && f != 13) { /* from the cross-section dimensions */
        if (k->cst == 2 || k->irid < 0)
            return kw_at(dk, k->loc, err, MCS_ERR_UNSUPPORTED,
                      "*SECTION_BEAM %d: an arbitrary cross-section (CST 2, or QR/IRID < 0: "
                      "*INTEGRATION_BEAM) is not built",
                      k->id);
        double a[2];
        for (int e = 0; e < 2; e++)
            a[e] = k->cst == 1 ? M_PI / 4 * (k->ts[e] * k->ts[e] - k->tt[e] * k->tt[e])
                               : k->ts[e] * k->tt[e];
        A = 0.5 * (a[0] + a[1]); /* the mean of the two ends */
    }
    if (!dk->beams_as_trusses)
        return kw_at(dk, k->loc, err, MCS_ERR_UNSUPPORTED,
                  "*SECTION_BEAM %d: ELFORM %d (%s beam) carries bending and torsion; the "
                  "kernel builds 2-node trusses only (axial force). Give ELFORM 3 with A = %g "
                  "(deck units) to run it as a truss, or read with beams_as_trusses",
                  k->id, f, beam_name(f), A / (dk->unit[0] * dk->unit[0]));
    if (!(A > 0))
        return kw_at(dk, k->loc, err, MCS_ERR_RANGE,
                  "*SECTION_BEAM %d: the cross-section area is %g: not > 0", k->id, A);
    warn_at(dk, k->loc,
            "*SECTION_BEAM %d: ELFORM %d built as a truss of area %g m^2: axial force only, "
            "bending and torsion dropped (beams_as_trusses)",
            k->id, f, A);
    s->area = A;
    return MCS_OK;
}

mcs_status kw_part_inertia(const fe_kw_deck *dk, const fe_kw_part *p, fe_part_desc *d,
                           mcs_error *err)
{
    if (p->eosid) /* the pressure would come from it */
        return kw_at(dk, p->loc, err, MCS_ERR_UNSUPPORTED,
                  "*PART %d: EOSID %d: equations of state are not built", p->id, p->eosid);
    const fe_kw_inertia *in = &p->inertia;
    if (!in->given) return MCS_OK;
    if (d->material.model != FE_MAT_RIGID)
        return kw_at(dk, p->loc, err, MCS_ERR_UNSUPPORTED,
                  "*PART_INERTIA %d: given mass properties are built on rigid parts "
                  "(*MAT_RIGID) only",
                  p->id);
    if (in->ircs)
        return kw_at(dk, p->loc, err, MCS_ERR_UNSUPPORTED,
                  "*PART_INERTIA %d: IRCS %d (principal moments with an orientation) is not "
                  "built: give the global tensor (IRCS 0)",
                  p->id, in->ircs);
    fe_rigid_inertia *g = &d->rigid;
    memset(g, 0, sizeof *g);
    g->given = 1;
    g->mass = in->mass;
    memcpy(g->cg, in->cg, sizeof g->cg);
    if (in->nodeid) {
        int ni = fe_kw_node_index(dk, in->nodeid);
        if (ni < 0)
            return kw_at(dk, p->loc, err, MCS_ERR_KEY, "*PART_INERTIA %d: NODEID %d is not defined",
                      p->id, in->nodeid);
        memcpy(g->cg, dk->node_x + 3 * ni, sizeof g->cg);
    }
    /* IXX IXY IXZ IYY IYZ IZZ: the tensor's components */
    const double *I = in->i;
    const double T[3][3] = {{I[0], I[1], I[2]}, {I[1], I[3], I[4]}, {I[2], I[4], I[5]}};
    memcpy(g->inertia, T, sizeof T);
    memcpy(g->velocity, in->v, sizeof g->velocity);
    memcpy(g->omega, in->w, sizeof g->omega);
    if (!(g->mass > 0) || !(I[0] > 0 && I[3] > 0 && I[5] > 0))
        return kw_at(dk, p->loc, err, MCS_ERR_RANGE,
                  "*PART_INERTIA %d: TM and IXX, IYY, IZZ must be > 0", p->id);
    return MCS_OK;
}

/* the thickness of shell element i (section k): THICj where given, else the section's Tj
 * (Tj 0: T1), the mean over its 3 or 4 nodes; 0 when neither gives one */
double kw_shell_thickness(const fe_kw_deck *dk, const fe_kw_section *k, int i)
{
    const fe_kw_elems *e = &dk->elem[FE_KW_SHELL];
    const double *g = e->thick && i < e->nthick ? e->thick + 4 * (size_t)i : NULL;
    const int nn = e->node[4 * (size_t)i + 2] == e->node[4 * (size_t)i + 3] ? 3 : 4;
    double sum = 0;
    for (int j = 0; j < nn; j++) {
        double t = g && g[j] > 0 ? g[j] : k->t[j] > 0 ? k->t[j] : k->t[0];
        if (!(t > 0)) return 0;
        sum += t;
    }
    return sum / nn;
}

mcs_status fe_kw_deck_opts(const fe_kw_deck *dk, fe_opts *o, mcs_error *err)
{
    const fe_kw_control *k = &dk->ctl;
    if (!k->ts_given) return MCS_OK;
    const fe_kw_loc l = k->ts_loc;
    if (k->tslimt > 0)
        return kw_at(dk, l, err, MCS_ERR_UNSUPPORTED,
                  "*CONTROL_TIMESTEP: TSLIMT (shells' minimum step by softened material) is not "
                  "built: use DT2MS < 0 (mass scaling)");
    if (k->lctm)
        return kw_at(dk, l, err, MCS_ERR_UNSUPPORTED,
                  "*CONTROL_TIMESTEP: LCTM (a curve of the largest step) is not built");
    if (k->dt2ms > 0)
        return kw_at(dk, l, err, MCS_ERR_UNSUPPORTED,
                  "*CONTROL_TIMESTEP: DT2MS > 0 (every element scaled to the step, mass "
                  "added or removed) is not built: DT2MS < 0 (mass only where the step is "
                  "smaller) is");
    if (k->dt2msf != 0 || k->dt2mslc || k->imscl)
        return kw_at(dk, l, err, MCS_ERR_UNSUPPORTED,
                  "*CONTROL_TIMESTEP: card 2 (DT2MSF, DT2MSLC, IMSCL) is not built");
    if (k->isdo != 0)
        warn_at(dk, l, "*CONTROL_TIMESTEP: ISDO %d: the shells' step uses area / longest side "
                       "(ISDO 0)",
                k->isdo);
    if (k->tssfac > 0) o->dt_scale = k->tssfac; /* 0: LS-DYNA's default 0.9, the kernel's */
    if (k->dt2ms < 0) {
        /* the step of the scaled elements is TSSFAC |DT2MS|, checked every cycle unless
         * MS1ST (mass added at t = 0 only) */
        o->mass_scaling_dt = (k->tssfac > 0 ? k->tssfac : 0.9) * -k->dt2ms;
        o->mass_scaling_interval = k->ms1st ? 0 : 1;
    }
    return MCS_OK;
}

/* fe_kw_write: a deck written as LS-DYNA keywords in fixed columns (standard, I10 or long),
 * values converted from SI to the deck's units; and the deck of a built fe_model. */
#include "fe/fe_kw_impl.h"
#include "fe/fe_solid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct {
    FILE *f;
    fe_kw_format fmt;
    char line[512];
    int pos;
    int bad_id;   /* an integer that did not fit its field */
    int bad_at;
    int bad_real; /* a value that is not finite in the deck's units */
} kw_out;

static int width(const kw_out *o, int w)
{
    if (o->fmt == FE_KW_FIXED_LONG) return 20;
    if (o->fmt == FE_KW_FIXED_I10 && w < 10) return 10;
    return w;
}

static void put_str(kw_out *o, int w, const char *s)
{
    int n = (int)strlen(s);
    if (o->pos + w >= (int)sizeof o->line) return;
    memset(o->line + o->pos, ' ', (size_t)(w - n > 0 ? w - n : 0));
    memcpy(o->line + o->pos + (w - n > 0 ? w - n : 0), s, (size_t)(n < w ? n : w));
    o->pos += w;
}

static void put_int(kw_out *o, int w0, int v)
{
    char s[32];
    int w = width(o, w0);
    snprintf(s, sizeof s, "%d", v);
    if ((int)strlen(s) > w && !o->bad_id) o->bad_id = 1, o->bad_at = v;
    put_str(o, w, s);
}

/* "1.5e+07" -> "1.5e7", "2e-05" -> "2e-5" */
static void compact_exp(char *s)
{
    char *e = strchr(s, 'e');
    if (!e) return;
    char *p = e + 1, *q = e + 1;
    if (*p == '+') p++;
    else if (*p == '-') *q++ = *p++;
    while (*p == '0' && p[1]) p++;
    memmove(q, p, strlen(p) + 1);
}

/* the shortest text that reads back to v and fits w; else the most digits that fit */
static void fmt_real(double v, int w, char *out)
{
    char s[64];
    out[0] = 0;
    if (v == 0) {
        snprintf(out, 8, "0.0");
        return;
    }
    for (int p = 1; p <= 17; p++) {
        snprintf(s, sizeof s, "%.*g", p, v);
        compact_exp(s);
        if ((int)strlen(s) > w) break;
        snprintf(out, 64, "%s", s);
        if (strtod(s, NULL) == v) break;
    }
    if (!out[0]) snprintf(out, 64, "%.0e", v); /* cannot happen for w >= 8 */
    /* a real gets a decimal point so no reader takes it for an integer */
    if (!strpbrk(out, ".e") && (int)strlen(out) + 1 <= w) strcat(out, ".");
}

static void put_real(kw_out *o, int w0, double v)
{
    char s[64];
    if (!isfinite(v)) o->bad_real = 1, v = 0;
    int w = width(o, w0);
    fmt_real(v, w, s);
    put_str(o, w, s);
}

static void endl(kw_out *o)
{
    o->line[o->pos] = 0;
    fprintf(o->f, "%s\n", o->line);
    o->pos = 0;
}

static void kw(kw_out *o, const char *name) { fprintf(o->f, "*%s\n", name); }

static void comment(kw_out *o, const char *const *names, const int *w, int n)
{
    o->pos = 0;
    for (int i = 0; i < n; i++) put_str(o, width(o, w[i]), names[i]);
    o->line[0] = '$';
    endl(o);
}

/* ---- blocks ---- */

/* *PART_INERTIA's three cards and *PART_CONTACT's card */
static void w_part_options(kw_out *o, const fe_kw_deck *d, const fe_kw_part *p)
{
    const double L = kw_u_len(d), M = d->unit[2];
    if (p->inertia.given) {
        const fe_kw_inertia *in = &p->inertia;
        for (int k = 0; k < 3; k++) put_real(o, 10, in->cg[k] / L);
        put_real(o, 10, in->mass / M), put_int(o, 10, in->ircs), put_int(o, 10, in->nodeid);
        endl(o);
        for (int k = 0; k < 6; k++) put_real(o, 10, in->i[k] / (M * L * L));
        endl(o);
        for (int k = 0; k < 3; k++) put_real(o, 10, in->v[k] / kw_u_vel(d));
        for (int k = 0; k < 3; k++) put_real(o, 10, in->w[k] / kw_u_rate(d));
        endl(o);
        if (in->ircs == 1) endl(o); /* the orientation card was not kept */
    }
    if (p->contact.given) {
        const fe_kw_pcontact *c = &p->contact;
        put_real(o, 10, c->fs), put_real(o, 10, c->fd), put_real(o, 10, c->dc * kw_u_vel(d));
        put_real(o, 10, c->vc / kw_u_stress(d)), put_real(o, 10, c->optt / L);
        put_real(o, 10, c->sft), put_real(o, 10, c->ssf), endl(o);
    }
}

static void w_parts(kw_out *o, const fe_kw_deck *d)
{
    static const char *h[] = {"pid", "secid", "mid", "eosid", "hgid"};
    static const int w[] = {10, 10, 10, 10, 10};
    for (int i = 0; i < d->npart; i++) {
        const fe_kw_part *p = &d->part[i];
        kw(o, p->inertia.given && p->contact.given ? "PART_INERTIA_CONTACT"
              : p->inertia.given                    ? "PART_INERTIA"
              : p->contact.given                    ? "PART_CONTACT"
                                                    : "PART");
        fprintf(o->f, "%s\n", p->title[0] ? p->title : "part");
        comment(o, h, w, p->hgid || p->eosid ? 5 : 3);
        put_int(o, 10, p->id);
        put_int(o, 10, p->secid);
        put_int(o, 10, p->mid);
        if (p->hgid || p->eosid) put_int(o, 10, p->eosid), put_int(o, 10, p->hgid);
        endl(o);
        w_part_options(o, d, p);
    }
}

/* *HOURGLASS, *CONTROL_HOURGLASS, *CONTROL_TIMESTEP */
static void w_controls(kw_out *o, const fe_kw_deck *d)
{
    for (int i = 0; i < d->nhg; i++) {
        const fe_kw_hourglass *h = &d->hg[i];
        kw(o, "HOURGLASS");
        put_int(o, 10, h->id), put_int(o, 10, h->ihq), put_real(o, 10, h->qm);
        put_int(o, 10, 0), put_real(o, 10, h->q1), put_real(o, 10, h->q2);
        put_real(o, 10, h->qb), put_real(o, 10, h->qw), endl(o);
    }
    const fe_kw_control *k = &d->ctl;
    if (k->hg_given) {
        kw(o, "CONTROL_HOURGLASS");
        put_int(o, 10, k->hg_ihq), put_real(o, 10, k->hg_qh), endl(o);
    }
    if (k->ts_given) {
        const double T = d->unit[1];
        kw(o, "CONTROL_TIMESTEP");
        put_real(o, 10, k->dtinit / T), put_real(o, 10, k->tssfac), put_int(o, 10, k->isdo);
        put_real(o, 10, k->tslimt / T), put_real(o, 10, k->dt2ms / T), put_int(o, 10, k->lctm);
        put_int(o, 10, 0), put_int(o, 10, k->ms1st), endl(o);
        if (k->dt2msf != 0 || k->dt2mslc || k->imscl)
            put_real(o, 10, k->dt2msf), put_int(o, 10, k->dt2mslc), put_int(o, 10, k->imscl),
                endl(o);
    }
}

static void w_sections(kw_out *o, const fe_kw_deck *d)
{
    double L = kw_u_len(d);
    for (int i = 0; i < d->nsection; i++) {
        const fe_kw_section *s = &d->section[i];
        if (s->kind == FE_KW_SEC_SHELL) {
            kw(o, "SECTION_SHELL");
            put_int(o, 10, s->id), put_int(o, 10, s->elform), put_real(o, 10, s->shrf);
            put_real(o, 10, s->nip), endl(o);
            for (int k = 0; k < 4; k++) put_real(o, 10, s->t[k] / L);
            endl(o);
        } else if (s->kind == FE_KW_SEC_SOLID) {
            kw(o, "SECTION_SOLID");
            put_int(o, 10, s->id), put_int(o, 10, s->elform), endl(o);
            if (s->user) put_int(o, 10, 0), endl(o); /* user parameters were not kept */
        } else if (s->kind == FE_KW_SEC_TSHELL) {
            kw(o, "SECTION_TSHELL");
            put_int(o, 10, s->id), put_int(o, 10, s->elform), put_real(o, 10, s->shrf);
            put_real(o, 10, s->nip), endl(o);
        } else if (s->kind == FE_KW_SEC_DISCRETE) {
            kw(o, "SECTION_DISCRETE");
            put_int(o, 10, s->id), put_int(o, 10, s->elform), endl(o);
        } else {
            const int f = s->elform;
            kw(o, "SECTION_BEAM");
            put_int(o, 10, s->id), put_int(o, 10, f), put_real(o, 10, s->shrf);
            put_real(o, 10, s->irid), put_real(o, 10, s->cst), endl(o);
            if (f == 2 || f == 3 || f == 12 || f == 13) put_real(o, 10, s->area / (L * L));
            if (f == 2 || f == 12 || f == 13) {
                const double L4 = L * L * L * L;
                put_real(o, 10, s->iss / L4), put_real(o, 10, s->itt / L4);
                put_real(o, 10, s->jt / L4);
            } else if (f != 3) {
                put_real(o, 10, s->ts[0] / L), put_real(o, 10, s->ts[1] / L);
                put_real(o, 10, s->tt[0] / L), put_real(o, 10, s->tt[1] / L);
            }
            endl(o);
        }
    }
}

/* *MAT_NULL, *MAT_LOW_DENSITY_FOAM, *MAT_PLASTIC_KINEMATIC (fe_kw_cards_mat.c); 0 for the rest */
static int w_mat_more(kw_out *o, const fe_kw_deck *d, const fe_kw_mat *m)
{
    const double R = kw_u_dens(d), S = kw_u_stress(d);
    if (m->type == FE_KW_MAT_NULL) { /* MID RO PC MU TEROD CEROD YM PR */
        kw(o, "MAT_NULL");
        put_int(o, 10, m->id), put_real(o, 10, m->ro / R);
        for (int k = 0; k < 4; k++) put_real(o, 10, 0);
        put_real(o, 10, m->e / S), put_real(o, 10, m->pr), endl(o);
        return 1;
    }
    if (m->type == FE_KW_MAT_LDF) { /* MID RO E LCID TC HU BETA DAMP / SHAPE */
        kw(o, "MAT_LOW_DENSITY_FOAM");
        put_int(o, 10, m->id), put_real(o, 10, m->ro / R), put_real(o, 10, m->e / S);
        put_int(o, 10, m->lcid), put_real(o, 10, m->tc > 0 ? m->tc / S : 1e20);
        put_real(o, 10, m->hu), put_real(o, 10, 0), put_real(o, 10, 0), endl(o);
        put_real(o, 10, m->shape), endl(o);
        return 1;
    }
    if (m->type == FE_KW_MAT_PK) { /* MID RO E PR SIGY ETAN BETA / SRC SRP FS VP */
        kw(o, "MAT_PLASTIC_KINEMATIC");
        put_int(o, 10, m->id), put_real(o, 10, m->ro / R), put_real(o, 10, m->e / S);
        put_real(o, 10, m->pr), put_real(o, 10, m->sigy / S), put_real(o, 10, m->etan / S);
        put_real(o, 10, m->beta), endl(o);
        put_real(o, 10, m->c * d->unit[1]), put_real(o, 10, m->p), put_real(o, 10, m->fail);
        endl(o);
        return 1;
    }
    return 0;
}

static void w_mats(kw_out *o, const fe_kw_deck *d)
{
    double R = kw_u_dens(d), S = kw_u_stress(d);
    for (int i = 0; i < d->nmat; i++) {
        const fe_kw_mat *m = &d->mat[i];
        if (m->type == FE_KW_MAT_SPRING || m->type == FE_KW_MAT_DAMPER) {
            int spring = m->type == FE_KW_MAT_SPRING;
            kw(o, spring ? "MAT_SPRING_ELASTIC" : "MAT_DAMPER_VISCOUS");
            put_int(o, 10, m->id);
            put_real(o, 10, m->k / (d->unit[2] / (spring ? d->unit[1] * d->unit[1] : d->unit[1])));
            endl(o);
            continue;
        }
        if (w_mat_more(o, d, m)) continue; /* null, foam, plastic kinematic */
        kw(o, m->type == FE_KW_MAT_ELASTIC ? "MAT_ELASTIC"
              : m->type == FE_KW_MAT_RIGID ? "MAT_RIGID" : "MAT_PIECEWISE_LINEAR_PLASTICITY");
        put_int(o, 10, m->id), put_real(o, 10, m->ro / R), put_real(o, 10, m->e / S);
        put_real(o, 10, m->pr);
        if (m->type == FE_KW_MAT_PLP) put_real(o, 10, m->sigy / S), put_real(o, 10, m->etan / S);
        if (m->type == FE_KW_MAT_PLP && m->fail > 0) put_real(o, 10, m->fail);
        endl(o);
        if (m->type == FE_KW_MAT_RIGID) { /* CMO CON1 CON2, then the third card blank */
            put_real(o, 10, m->cmo), put_int(o, 10, m->con1), put_int(o, 10, m->con2), endl(o);
            fprintf(o->f, "\n");
        }
        if (m->type != FE_KW_MAT_PLP) continue;
        put_real(o, 10, m->c * d->unit[1]), put_real(o, 10, m->p), put_int(o, 10, m->lcss);
        endl(o);
        for (int k = 0; k < 8; k++) put_real(o, 10, m->eps[k]);
        endl(o);
        for (int k = 0; k < 8; k++) put_real(o, 10, m->es[k] / S);
        endl(o);
    }
}

static void w_curves(kw_out *o, const fe_kw_deck *d)
{
    for (int i = 0; i < d->ncurve; i++) {
        const fe_kw_curve *c = &d->curve[i];
        kw(o, "DEFINE_CURVE");
        put_int(o, 10, c->id), endl(o);
        for (int k = 0; k < c->n; k++) put_real(o, 20, c->xy[2 * k]), put_real(o, 20, c->xy[2 * k + 1]), endl(o);
    }
}

static void w_sets(kw_out *o, const fe_kw_deck *d)
{
    for (int i = 0; i < d->nset; i++) {
        const fe_kw_set *s = &d->set[i];
        kw(o, s->is_part ? "SET_PART_LIST" : "SET_NODE_LIST");
        put_int(o, 10, s->id), endl(o);
        for (int k = 0; k < s->n; k++) {
            put_int(o, 10, s->ids[k]);
            if (k % 8 == 7 || k == s->n - 1) endl(o);
        }
    }
}

static void w_nodes(kw_out *o, const fe_kw_deck *d)
{
    static const char *h[] = {"nid", "x", "y", "z", "tc", "rc"};
    if (d->nnode == 0) return;
    kw(o, "NODE");
    comment(o, h, KW_L_NODE.w, 6);
    double L = kw_u_len(d);
    for (int i = 0; i < d->nnode; i++) {
        put_int(o, 8, d->node_id[i]);
        for (int k = 0; k < 3; k++) put_real(o, 16, d->node_x[3 * i + k] / L);
        endl(o);
    }
}

/* does shell i carry THIC1..THIC4 of its own? */
static int has_thick(const fe_kw_elems *e, int i)
{
    if (!e->thick || i >= e->nthick) return 0;
    const double *t = e->thick + 4 * (size_t)i;
    return t[0] > 0 || t[1] > 0 || t[2] > 0 || t[3] > 0;
}

/* the shells with a thickness of their own: *ELEMENT_SHELL_THICKNESS */
static void w_thick_shells(kw_out *o, const fe_kw_deck *d)
{
    const fe_kw_elems *e = &d->elem[FE_KW_SHELL];
    int any = 0;
    for (int i = 0; i < e->n && !any; i++) any = has_thick(e, i);
    if (!any) return;
    kw(o, "ELEMENT_SHELL_THICKNESS");
    for (int i = 0; i < e->n; i++) {
        if (!has_thick(e, i)) continue;
        put_int(o, 8, e->id[i]), put_int(o, 8, e->pid[i]);
        for (int j = 0; j < 4; j++) put_int(o, 8, e->node[4 * (size_t)i + j]);
        endl(o);
        for (int j = 0; j < 4; j++) put_real(o, 16, e->thick[4 * (size_t)i + j] / kw_u_len(d));
        endl(o);
    }
}

static void w_elems(kw_out *o, const fe_kw_deck *d)
{
    static const char *names[FE_KW_NETYPE] = {"ELEMENT_SHELL",    "ELEMENT_SOLID",
                                              "ELEMENT_BEAM",     "ELEMENT_DISCRETE",
                                              "ELEMENT_SOLID",    "ELEMENT_TSHELL"};
    w_thick_shells(o, d);
    for (int t = 0; t < FE_KW_NETYPE; t++) {
        const fe_kw_elems *e = &d->elem[t];
        int nplain = 0;
        for (int i = 0; i < e->n; i++) nplain += !(t == FE_KW_SHELL && has_thick(e, i));
        if (nplain == 0) continue;
        kw(o, names[t]);
        int k = fe_kw_etype_nnode((fe_kw_etype)t);
        for (int i = 0; i < e->n; i++) {
            if (t == FE_KW_SHELL && has_thick(e, i)) continue;
            put_int(o, 8, e->id[i]), put_int(o, 8, e->pid[i]);
            if (t == FE_KW_TET10) endl(o); /* the two-card form: EID PID, then N1..N10 */
            for (int j = 0; j < k; j++) put_int(o, 8, e->node[(size_t)k * i + j]);
            if (t == FE_KW_DISCRETE) {
                put_int(o, 8, 0), put_real(o, 16, e->dval[2 * i]), put_int(o, 8, 0);
                put_real(o, 16, e->dval[2 * i + 1] / kw_u_len(d));
            }
            endl(o);
        }
    }
}

static void w_conditions(kw_out *o, const fe_kw_deck *d)
{
    for (int i = 0; i < d->nspc; i++) {
        const fe_kw_spc *s = &d->spc[i];
        kw(o, s->on == FE_KW_ON_NODE ? "BOUNDARY_SPC_NODE" : "BOUNDARY_SPC_SET");
        put_int(o, 10, s->id), put_int(o, 10, 0);
        for (int k = 0; k < 6; k++) put_int(o, 10, (s->dof >> k) & 1);
        endl(o);
    }
    for (int i = 0; i < d->niv; i++) {
        const fe_kw_initvel *v = &d->iv[i];
        double V = kw_u_vel(d);
        if (v->on == FE_KW_ON_NODESET) {
            kw(o, "INITIAL_VELOCITY");
            put_int(o, 10, v->id), endl(o);
            for (int k = 0; k < 3; k++) put_real(o, 10, v->v[k] / V);
            for (int k = 0; k < 3; k++) put_real(o, 10, v->vr[k] * d->unit[1]);
            endl(o);
        } else {
            kw(o, "INITIAL_VELOCITY_GENERATION");
            put_int(o, 10, v->id), put_int(o, 10, v->on == FE_KW_ON_PARTSET ? 1 : 2);
            put_real(o, 10, 0);
            for (int k = 0; k < 3; k++) put_real(o, 10, v->v[k] / V);
            endl(o), endl(o);
        }
    }
    for (int i = 0; i < d->nwall; i++) {
        const fe_kw_wall *w = &d->wall[i];
        kw(o, w->id ? (w->moving ? "RIGIDWALL_PLANAR_MOVING_ID" : "RIGIDWALL_PLANAR_ID")
                    : (w->moving ? "RIGIDWALL_PLANAR_MOVING" : "RIGIDWALL_PLANAR"));
        if (w->id) fprintf(o->f, "%10d%.70s\n", w->id, w->title); /* I10 + A70 in every format */
        put_int(o, 10, w->nsid), endl(o);
        for (int k = 0; k < 3; k++) put_real(o, 10, w->tail[k] / kw_u_len(d));
        for (int k = 0; k < 3; k++) put_real(o, 10, w->head[k] / kw_u_len(d));
        put_real(o, 10, w->fric), endl(o);
        if (w->moving) {
            put_real(o, 10, w->mass / d->unit[2]);
            put_real(o, 10, w->v0 / kw_u_vel(d)), endl(o);
        }
    }
    for (int i = 0; i < d->nwmotion; i++) { /* the curves are written as read */
        const fe_kw_wmotion *mo = &d->wmotion[i];
        kw(o, "BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL");
        put_int(o, 10, mo->wall), put_int(o, 10, mo->dof), put_int(o, 10, mo->vad);
        put_int(o, 10, mo->lcid), put_real(o, 10, mo->sf), endl(o);
    }
}

/* nodal rigid bodies, extra nodes, joints and joint stiffnesses (fe_kw_cards_joint.c) */
static void w_constrained(kw_out *o, const fe_kw_deck *d)
{
    static const char *const jk[4] = {"SPHERICAL", "REVOLUTE", "CYLINDRICAL", "TRANSLATIONAL"};
    static const char *const nk[3] = {"NODAL_RIGID_BODY", "EXTRA_NODES_NODE", "EXTRA_NODES_SET"};
    char name[64];
    for (int i = 0; i < d->nnrb; i++) {
        const fe_kw_nrb *r = &d->nrb[i];
        snprintf(name, sizeof name, "CONSTRAINED_%s", nk[r->kind]);
        kw(o, name);
        put_int(o, 10, r->pid);
        if (r->kind == 0) put_int(o, 10, 0);
        put_int(o, 10, r->id), endl(o);
    }
    for (int i = 0; i < d->njoint; i++) {
        const fe_kw_joint *j = &d->joint[i];
        snprintf(name, sizeof name, "CONSTRAINED_JOINT_%s_ID", jk[j->type]);
        kw(o, name);
        fprintf(o->f, "%10d%.70s\n", j->id, j->title); /* I10 + A70 in every format */
        for (int k = 0; k < 6; k++) put_int(o, 10, j->node[k]);
        put_real(o, 10, j->rps), put_real(o, 10, j->damp), endl(o);
    }
    for (int i = 0; i < d->njstiff; i++) {
        const fe_kw_jstiff *s = &d->jstiff[i];
        kw(o, s->translational ? "CONSTRAINED_JOINT_STIFFNESS_TRANSLATIONAL"
                               : "CONSTRAINED_JOINT_STIFFNESS_GENERALIZED");
        const int c1[6] = {s->jsid, s->pida, s->pidb, s->cida, s->cidb, s->jid};
        for (int k = 0; k < 6; k++) put_int(o, 10, c1[k]);
        endl(o);
        for (int k = 0; k < 3; k++) put_int(o, 10, s->lc[k]);
        for (int k = 0; k < 3; k++) put_int(o, 10, s->dlc[k]);
        endl(o);
        for (int k = 0; k < 3; k++) put_real(o, 10, s->es[k]), put_real(o, 10, s->ff[k]);
        endl(o);
        /* stops: degrees (generalized) or the deck's length */
        const double u = s->translational ? kw_u_len(d) : M_PI / 180;
        for (int k = 0; k < 3; k++) put_real(o, 10, s->neg[k] / u), put_real(o, 10, s->pos[k] / u);
        endl(o);
    }
}

/* contacts, segment sets, node velocities, prescribed motions, loads, the end time
 * (fe_kw_cards_contact.c reads them back) */
static void w_contacts(kw_out *o, const fe_kw_deck *d)
{
    static const char *const nm[2][4] = {
        {"CONTACT_SINGLE_SURFACE", "CONTACT_GENERAL", "CONTACT_SURFACE_TO_SURFACE",
         "CONTACT_NODES_TO_SURFACE"},
        {"CONTACT_AUTOMATIC_SINGLE_SURFACE", "CONTACT_AUTOMATIC_GENERAL",
         "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_NODES_TO_SURFACE"}};
    const double T = d->unit[1], L = kw_u_len(d);
    if (d->end_time > 0) kw(o, "CONTROL_TERMINATION"), put_real(o, 10, d->end_time / T), endl(o);
    if (d->slsfac > 0 || d->shlthk) { /* SLSFAC RWPNAL ISLCHK SHLTHK */
        kw(o, "CONTROL_CONTACT"), put_real(o, 10, d->slsfac), put_real(o, 10, d->rwpnal);
        put_int(o, 10, 0), put_int(o, 10, d->shlthk), endl(o);
    }
    for (int i = 0; i < d->nsegset; i++) {
        const fe_kw_segset *s = &d->segset[i];
        kw(o, "SET_SEGMENT"), put_int(o, 10, s->id), endl(o);
        for (int k = 0; k < s->n; k++) {
            for (int j = 0; j < 4; j++) put_int(o, 10, s->node[4 * k + j]);
            endl(o);
        }
    }
    for (int i = 0; i < d->nnodevel; i++) {
        const fe_kw_nodevel *v = &d->nodevel[i];
        if (i == 0) kw(o, "INITIAL_VELOCITY_NODE");
        put_int(o, 10, v->nid);
        for (int k = 0; k < 3; k++) put_real(o, 10, v->v[k] / kw_u_vel(d));
        for (int k = 0; k < 3; k++) put_real(o, 10, v->vr[k] * T);
        endl(o);
    }
    for (int i = 0; i < d->npmotion; i++) {
        const fe_kw_pmotion *m = &d->pmotion[i];
        kw(o, m->on == FE_KW_ON_NODE      ? "BOUNDARY_PRESCRIBED_MOTION_NODE"
              : m->on == FE_KW_ON_NODESET ? "BOUNDARY_PRESCRIBED_MOTION_SET"
                                          : "BOUNDARY_PRESCRIBED_MOTION_RIGID");
        put_int(o, 10, m->id), put_int(o, 10, m->dof), put_int(o, 10, m->vad);
        put_int(o, 10, m->lcid), put_real(o, 10, m->sf), endl(o);
    }
    for (int i = 0; i < d->nload; i++) {
        const fe_kw_load *l = &d->load[i];
        if (l->segment == 1) {
            kw(o, "LOAD_SEGMENT"), put_int(o, 10, l->lcid), put_real(o, 10, l->sf);
            put_real(o, 10, l->at / T);
            for (int j = 0; j < 4; j++) put_int(o, 10, l->node[j]);
        } else {
            kw(o, l->segment ? "LOAD_NODE_SET" : "LOAD_NODE_POINT");
            put_int(o, 10, l->nid), put_int(o, 10, l->dof), put_int(o, 10, l->lcid);
            put_real(o, 10, l->sf);
        }
        endl(o);
    }
    for (int i = 0; i < d->ncontact; i++) {
        const fe_kw_contact *c = &d->contact[i];
        char name[64];
        snprintf(name, sizeof name, "%s%s", nm[c->automatic ? 1 : 0][c->type],
                 c->id || c->title[0] ? "_ID" : "");
        kw(o, name);
        if (c->id || c->title[0]) fprintf(o->f, "%10d%.70s\n", c->id, c->title);
        put_int(o, 10, c->ssid), put_int(o, 10, c->msid), put_int(o, 10, c->sstyp);
        put_int(o, 10, c->mstyp), endl(o);
        put_real(o, 10, c->fs), put_real(o, 10, c->fd), put_real(o, 10, c->dc * L / T), endl(o);
        put_real(o, 10, c->sfs), put_real(o, 10, c->sfm), put_real(o, 10, 0), put_real(o, 10, 0);
        put_real(o, 10, c->sfst), put_real(o, 10, c->sfmt), put_real(o, 10, c->fsf), endl(o);
    }
}

mcs_status fe_kw_write_stream(const fe_kw_deck *d, FILE *f, fe_kw_format fmt, mcs_error *err)
{
    kw_out o = {.f = f, .fmt = fmt};
    fprintf(f, "$ written by mcrash; units (length-time-mass, SI values): %g m, %g s, %g kg\n",
            d->unit[0], d->unit[1], d->unit[2]);
    fprintf(f, "*KEYWORD%s\n", fmt == FE_KW_FIXED_LONG ? " LONG=Y" : fmt == FE_KW_FIXED_I10 ? " I10=Y" : "");
    if (d->title[0]) fprintf(f, "*TITLE\n%.80s\n", d->title);
    w_parts(&o, d);
    w_sections(&o, d);
    w_mats(&o, d);
    w_controls(&o, d);
    w_curves(&o, d);
    w_sets(&o, d);
    w_nodes(&o, d);
    w_elems(&o, d);
    w_conditions(&o, d);
    w_contacts(&o, d); /* contacts, segment sets, node velocities, motions, loads, end time */
    w_constrained(&o, d);
    fprintf(f, "*END\n");
    if (o.bad_id)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "keyword: ID %d does not fit its 8-column field; write in the I10 or long "
                       "format",
                       o.bad_at);
    if (o.bad_real)
        return MCS_ERR(err, MCS_ERR_RANGE, "keyword: a value is not finite in the deck's units");
    if (ferror(f)) return MCS_ERR(err, MCS_ERR_IO, "keyword: write error");
    return MCS_OK;
}

mcs_status fe_kw_write(const fe_kw_deck *d, const char *path, fe_kw_format fmt, mcs_error *err)
{
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) return MCS_ERR(err, MCS_ERR_IO, "%s: cannot create the keyword file", path);
    mcs_status st = fe_kw_write_stream(d, f, fmt, err);
    if (fclose(f) != 0 && !st) st = MCS_ERR(err, MCS_ERR_IO, "%s: write error", path);
    if (!st && rename(tmp, path) != 0)
        st = MCS_ERR(err, MCS_ERR_IO, "%s: cannot rename the written file into place", path);
    if (st) remove(tmp);
    return st;
}

/* ---- the deck of a model ---- */

/* what the element keywords carry: shells of their own thickness (*ELEMENT_SHELL_THICKNESS),
 * each deformable hex or shell part's hourglass form (*HOURGLASS IHQ 2 viscous or 4
 * stiffness, QM its coefficient; HGID = PID) and rigid parts' given mass properties
 * (*PART_INERTIA) */
static mcs_status model_elem_extras(const fe_model *m, fe_kw_deck *d, mcs_error *err)
{
    fe_kw_elems *e = &d->elem[FE_KW_SHELL];
    int own = 0;
    for (int i = 0; i < m->nshell; i++)
        own |= m->shell_t[i] != m->part[m->shell_part[i]].section.thickness;
    if (own && e->n == m->nshell) {
        e->thick = calloc(4 * (size_t)e->n, sizeof(double));
        if (!e->thick) return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
        e->nthick = e->n;
        for (int i = 0; i < m->nshell; i++)
            if (m->shell_t[i] != m->part[m->shell_part[i]].section.thickness)
                for (int j = 0; j < 4; j++) e->thick[4 * (size_t)i + j] = m->shell_t[i];
    }
    for (int ip = 0; ip < m->npart; ip++) {
        const fe_part *p = &m->part[ip];
        fe_kw_part *kp = &d->part[ip];
        if (p->rigid.given) {
            const fe_rigid_inertia *g = &p->rigid;
            fe_kw_inertia *in = &kp->inertia;
            in->given = 1, in->mass = g->mass;
            memcpy(in->cg, g->cg, sizeof in->cg);
            memcpy(in->v, g->velocity, sizeof in->v);
            memcpy(in->w, g->omega, sizeof in->w);
            const double I[6] = {g->inertia[0][0], g->inertia[0][1], g->inertia[0][2],
                                 g->inertia[1][1], g->inertia[1][2], g->inertia[2][2]};
            memcpy(in->i, I, sizeof I);
        }
        if (p->body >= 0 || (p->elem_kind != FE_KIND_HEX && p->elem_kind != FE_KIND_SHELL))
            continue;
        fe_kw_hourglass *h = kw_push((void **)&d->hg, &d->nhg, &d->cap_hg, sizeof *h);
        if (!h) return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
        h->id = kp->hgid = ip + 1;
        h->ihq = p->section.hourglass == FE_HG_VISCOUS ? 2 : 4;
        h->qm = p->hg_coef;
    }
    return MCS_OK;
}

static mcs_status model_props(const fe_model *m, int ip, fe_kw_deck *d, mcs_error *err)
{
    const fe_part *p = &m->part[ip];
    fe_kw_section *s = kw_push((void **)&d->section, &d->nsection, &d->cap_section, sizeof *s);
    fe_kw_mat *k = s ? kw_push((void **)&d->mat, &d->nmat, &d->cap_mat, sizeof *k) : NULL;
    if (!k) return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
    s->id = k->id = ip + 1;
    if (p->section.type == FE_SECTION_SHELL) {
        s->kind = FE_KW_SEC_SHELL, s->elform = 2, s->nip = p->section.integration_points;
        s->shrf = p->section.shear_factor;
        for (int i = 0; i < 4; i++) s->t[i] = p->section.thickness;
    } else if (p->section.type == FE_SECTION_SOLID) {
        s->kind = FE_KW_SEC_SOLID, s->elform = 1;
    } else if (p->section.type == FE_SECTION_TET10) {
        s->kind = FE_KW_SEC_SOLID, s->elform = 16;
    } else {
        s->kind = FE_KW_SEC_BEAM, s->elform = 3, s->area = p->section.area;
    }
    if (p->section.type == FE_SECTION_MEMBRANE) /* a 3-node membrane: shell ELFORM 9 */
        s->kind = FE_KW_SEC_SHELL, s->elform = 9, s->nip = 1, s->t[0] = s->t[1] = s->t[2] =
            s->t[3] = p->section.thickness;
    const fe_material_desc *md = &p->material;
    k->ro = md->density, k->e = md->youngs_modulus, k->pr = md->poisson;
    k->type = md->model == FE_MAT_ELASTIC_PLASTIC ? FE_KW_MAT_PLP
              : md->model == FE_MAT_RIGID         ? FE_KW_MAT_RIGID
              : md->model == FE_MAT_NULL          ? FE_KW_MAT_NULL
                                                  : FE_KW_MAT_ELASTIC;
    if (md->model == FE_MAT_RIGID && md->rigid_fix) { /* CMO 1: CON1 and CON2 codes */
        static const unsigned con[8] = {0, 1, 2, 4, 3, 6, 5, 7};
        k->cmo = 1;
        for (int i = 0; i < 8; i++)
            if (con[i] == (md->rigid_fix & FE_DOF_TRANS)) k->con1 = i;
        k->con2 = md->rigid_fix & FE_DOF_ROT ? 7 : 0;
    }
    if (md->model == FE_MAT_FOAM && md->nfoam_curve == 1 && md->poisson == 0) {
        /* *MAT_LOW_DENSITY_FOAM: its one loading curve, stress in Pa as the deck's curves */
        fe_kw_curve *c = kw_push((void **)&d->curve, &d->ncurve, &d->cap_curve, sizeof *c);
        const int np = md->foam_npoint[0];
        if (!c || !(c->xy = malloc(2 * sizeof(double) * (size_t)(np + 1))))
            return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
        k->type = FE_KW_MAT_LDF;
        c->id = k->lcid = ip + 1;
        c->xy[0] = c->xy[1] = 0;
        c->n = 1;
        for (int i = 0; i < np; i++)
            if (md->foam_curve[0][i][0] > 0) {
                c->xy[2 * c->n] = md->foam_curve[0][i][0];
                c->xy[2 * c->n + 1] = md->foam_curve[0][i][1] / kw_u_stress(d);
                c->n++;
            }
        k->hu = md->foam_hysteresis > 0 ? md->foam_hysteresis : 1;
        k->shape = md->foam_shape > 0 ? md->foam_shape : 1;
        k->tc = md->foam_tension_cutoff;
        return MCS_OK;
    }
    if (md->model == FE_MAT_FOAM || md->model == FE_MAT_FABRIC)
        mcs_log(MCS_LOG_WARN, "keyword: part '%s': %s material written as *MAT_ELASTIC (RO, E, "
                              "PR only): %s",
                p->name, md->model == FE_MAT_FOAM ? "foam" : "fabric",
                md->model == FE_MAT_FOAM ? "*MAT_LOW_DENSITY_FOAM holds one curve and no Poisson "
                                           "effect"
                                         : "the subset has no fabric card");
    if (k->type != FE_KW_MAT_PLP) return MCS_OK;
    k->sigy = md->nhardening > 0 ? md->hardening[0][1] : md->yield_stress;
    k->c = md->cowper_symonds_c, k->p = md->cowper_symonds_p;
    k->fail = md->failure_strain;
    if (md->nhardening == 0) return MCS_OK;
    fe_kw_curve *c = kw_push((void **)&d->curve, &d->ncurve, &d->cap_curve, sizeof *c);
    if (!c || !(c->xy = malloc(2 * sizeof(double) * (size_t)md->nhardening)))
        return MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
    c->id = k->lcss = ip + 1;
    c->n = md->nhardening;
    for (int i = 0; i < c->n; i++) c->xy[2 * i] = md->hardening[i][0], c->xy[2 * i + 1] = md->hardening[i][1];
    return MCS_OK;
}

mcs_status fe_kw_from_model(const fe_model *m, const double *x, const char *title,
                            fe_kw_deck **out, mcs_error *err)
{
    fe_kw_deck *d = NULL;
    mcs_status st = fe_kw_deck_create(&d, err);
    if (st) return st;
    if (title) snprintf(d->title, sizeof d->title, "%s", title);
    const double *xs = x ? x : m->node_x0;
    for (int i = 0; i < m->nnode && !st; i++) st = fe_kw_deck_add_node(d, i + 1, xs + 3 * i, err);
    for (int ip = 0; ip < m->npart && !st; ip++) {
        fe_kw_part p = {.id = ip + 1, .secid = ip + 1, .mid = ip + 1};
        snprintf(p.title, sizeof p.title, "%s", m->part[ip].name);
        st = fe_kw_deck_add_part(d, &p, err);
        if (!st) st = model_props(m, ip, d, err);
    }
    static const fe_kw_etype et[FE_NKIND] = {FE_KW_SOLID, FE_KW_SHELL, FE_KW_BEAM, FE_KW_TET10};
    const int *conn[FE_NKIND] = {m->hex_node, m->shell_node, m->truss_node, m->tet10_node};
    const int *part[FE_NKIND] = {m->hex_part, m->shell_part, m->truss_part, m->tet10_part};
    const int ne[FE_NKIND] = {m->nhex, m->nshell, m->ntruss, m->ntet10};
    const int nn[FE_NKIND] = {8, 4, 2, 10};
    for (int k = 0; k < FE_NKIND && !st; k++)
        for (int e = 0; e < ne[k] && !st; e++) {
            int c[10];
            for (int j = 0; j < nn[k]; j++) c[j] = conn[k][(size_t)nn[k] * e + j] + 1;
            if (k == FE_KIND_HEX) { /* a tetrahedron as n1 n2 n3 n4 n4 n4 n4 n4 (fe_tet.c) */
                int h[8];
                memcpy(h, c, sizeof h);
                fe_solid_to_lsdyna(h, c);
            }
            /* tet10 IDs follow the hexes' (both are *ELEMENT_SOLID) */
            const int id = e + 1 + (k == FE_KIND_TET10 ? m->nhex : 0);
            st = fe_kw_deck_add_elem(d, et[k], id, part[k][e] + 1, c, err);
        }
    for (int i = 0; i < m->nnode && !st; i++) {
        if (!m->node_fix[i]) continue;
        fe_kw_spc *s = kw_push((void **)&d->spc, &d->nspc, &d->cap_spc, sizeof *s);
        if (!s) st = MCS_ERR(err, MCS_ERR_NOMEM, "keyword: out of memory");
        else *s = (fe_kw_spc){FE_KW_ON_NODE, i + 1, m->node_fix[i], {0, 0}};
    }
    if (!st) st = model_elem_extras(m, d, err);
    if (!st) st = kw_joints_from_model(m, xs, d, err); /* fe_kw_joint_model.c */
    if (st) fe_kw_deck_destroy(&d);
    *out = d;
    return st;
}

/* mb_energy.c: the energy sub-stage of mb_step: the balance of mb_model.h at the current
 * poses (s->kin, detected after the ODE step), evaluated at the output samples (the drift is
 * measured at the output rate). Every step, mb_energy_check_step checks growth and NaN on the
 * running sums (each element's work, cheap). Contacts and one-axis restraints are evaluated
 * at the new deflection on a copy of their history (nothing is committed here); three-axis
 * restraints and attachments report the deflection of their last apply (half a step behind:
 * an O(h) term of the balance). The growth check stops a run whose total energy rises by more
 * than opts.energy_tol of the reference energy (largest kinetic + stored so far). */
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_model.h"
#include "stage1_mb/mb_prescribe.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>

double mb_body_kinetic(const mb_model *m, const mb_state *s, int b)
{
    const mb_body_kin *k = &s->kin[b];
    const double *I = m->body[b].inertia; /* Ixx Iyy Izz Ixy Ixz Iyz, body axes */
    double w[3], Iw[3];
    mb_mat_tvec(k->rot, k->angvel, w);
    Iw[0] = I[0] * w[0] + I[3] * w[1] + I[4] * w[2];
    Iw[1] = I[3] * w[0] + I[1] * w[1] + I[5] * w[2];
    Iw[2] = I[4] * w[0] + I[5] * w[1] + I[2] * w[2];
    return 0.5 * m->body[b].mass * mb_dot(k->vel, k->vel) + 0.5 * mb_dot(w, Iw);
}

static double kinetic(const mb_model *m, const mb_state *s)
{
    double e = 0;
    for (int b = 0; b < m->nbody; b++) {
        if (mb_body_prescribed(m, b)) continue; /* moved from outside: external_work's */
        e += mb_body_kinetic(m, s, b);
    }
    return e;
}

static double potential(const mb_model *m, const mb_state *s)
{
    double e = 0;
    for (int b = 0; b < m->nbody; b++)
        if (!mb_body_prescribed(m, b)) e -= m->body[b].mass * mb_dot(m->gravity, s->kin[b].pos);
    return e;
}

/* contacts: stored and dissipated at the new penetration */
static void contact_energy(const mb_model *m, const mb_state *s, double *stored, double *diss)
{
    for (int i = 0; i < m->npair; i++) {
        const mcs_hyst_model *h = &m->pair[i].hyst;
        double x = s->pc[i].depth > 0 ? s->pc[i].depth : 0;
        *diss += s->pair[i].e_damp + s->pair[i].e_fric;
        if (x == 0 && s->pair[i].h.x_max == 0) continue; /* never touched: nothing stored */
        mcs_hyst_state t = s->pair[i].h;
        mcs_hyst_update(h, &t, x);
        /* work = stored + dissipated (the element's identity): one integral less; an
         * elastic element dissipates nothing (exactly) */
        double st = x > 0 ? mcs_hyst_stored(h, &t) : 0;
        *stored += st;
        if (h->unload != MCS_UNLOAD_ELASTIC && t.x_max > h->elastic_limit) *diss += t.work - st;
    }
}

static void restraint_energy(const mb_model *m, const mb_state *s, double *stored, double *diss)
{
    for (int i = 0; i < m->nrestraint1; i++) {
        const mb_restraint_model *r = &m->restraint1[i];
        mb_restraint_state t = s->r1[i];
        mb_restraint_spring(r, &t, mb_joint_position(s->world, r->joint));
        *stored += mb_restraint_stored(r, &t);
        *diss += mb_restraint_dissipated(r, &t);
    }
    for (int i = 0; i < m->nrestraint3; i++) {
        *stored += mb_restraint3_stored(&m->restraint3[i], &s->r3[i]);
        *diss += mb_restraint3_dissipated(&m->restraint3[i], &s->r3[i]);
    }
    for (int i = 0; i < m->nattach; i++) {
        *stored += mb_attach_stored(&m->attach[i], &s->att[i]);
        *diss += s->att[i].e_damp + s->att[i].e_lost;
    }
}

/* energy: reads s->kin and the histories, writes s->e and the drift */
void mb_energy_update(const mb_model *m, mb_state *s)
{
    mb_energy *e = &s->e;
    e->kinetic = kinetic(m, s);
    e->potential = potential(m, s);
    e->contact = e->internal = e->dissipated = 0;
    contact_energy(m, s, &e->contact, &e->dissipated);
    restraint_energy(m, s, &e->internal, &e->dissipated);
    /* the prescribed bodies' on the rest (mb_prescribe.c) */
    e->external_work = s->w_presc + mb_prescribe_couple_work(m, s);
    if (m->couple) { /* the coupled FE parts (mb_couple.h) */
        double f[MB_NENERGY];
        mb_couple_energy(m, s, f);
        e->kinetic += f[0], e->potential += f[1], e->internal += f[2], e->contact += f[3];
        e->dissipated += f[4], e->external_work += f[5];
    }
    e->total = e->kinetic + e->potential + e->internal + e->contact + e->dissipated -
               e->external_work;
    double live = e->kinetic + e->internal + e->contact;
    if (live > s->e_ref) s->e_ref = live;
    double d = fabs(e->total - s->e_total0);
    if (s->step > 0 && d > s->drift_abs) s->drift_abs = d;
}

double mb_energy_drift(const mb_model *m, const mb_state *s)
{
    return s->drift_abs / fmax(s->e_ref, m->opts.energy_floor);
}

/* the body moving fastest: where energy growth most likely comes from */
static int fastest_body(const mb_model *m, const mb_state *s)
{
    int best = 0;
    double vmax = -1;
    for (int b = 0; b < m->nbody; b++) {
        double v = mb_norm(s->kin[b].vel) + mb_norm(s->kin[b].angvel);
        if (!(v <= vmax)) best = b, vmax = isnan(v) ? INFINITY : v;
    }
    return best;
}

static mcs_status growth_error(const mb_model *m, const mb_state *s, double total, double ref,
                               mcs_error *err)
{
    double grow = total - s->e_total0;
    int b = fastest_body(m, s);
    if (!isfinite(total))
        return MCS_ERR(err, MCS_ERR_NUMERIC,
                       "stage 1: energy is not finite at t = %.6g s (body %s)", s->t,
                       m->body_name[b]);
    return MCS_ERR(err, MCS_ERR_NUMERIC,
                   "stage 1: energy grew by %.4g J (%.3g %% of %.4g J) at t = %.6g s; fastest "
                   "body %s: reduce simulation.time_step or stiffen less",
                   grow, 100 * grow / ref, ref, s->t, m->body_name[b]);
}

mcs_status mb_energy_check(const mb_model *m, mb_state *s, mcs_error *err)
{
    double ref = fmax(s->e_ref, m->opts.energy_floor);
    double grow = s->e.total - s->e_total0;
    if (isfinite(s->e.total) && grow <= m->opts.energy_tol * ref) return MCS_OK;
    return growth_error(m, s, s->e.total, ref, err);
}

/* the total from running sums, cheap enough for every step: each hysteresis element's work
 * (= stored + dissipated) as committed at the current poses by the force stages, plus the
 * dampers' and friction's running sums; kinetic and potential from s->kin (the same poses).
 * *kin: the bodies' kinetic energy plus the coupled FE parts' kinetic, internal and contact
 * energy (the reference of the growth check) */
static double running_total(const mb_model *m, const mb_state *s, double *kin)
{
    double e = 0;
    *kin = kinetic(m, s);
    for (int i = 0; i < m->npair; i++)
        e += s->pair[i].h.work + s->pair[i].e_damp + s->pair[i].e_fric;
    for (int i = 0; i < m->nrestraint1; i++) {
        const mb_restraint_model *r = &m->restraint1[i];
        const mb_restraint_state *t = &s->r1[i];
        double x = t->x > r->hi ? t->x - r->hi : t->x < r->lo ? t->x - r->lo : 0;
        if (r->has_spring) e += mcs_hyst2_work(&t->h) + r->preload * t->x;
        e += 0.5 * r->stop_stiffness * x * x + t->e_damp;
    }
    for (int i = 0; i < m->nrestraint3; i++) {
        const mb_restraint3_model *r = &m->restraint3[i];
        const mb_restraint3_state *t = &s->r3[i];
        for (int k = 0; k < 3; k++) {
            double th = t->theta[k];
            double x = th > r->hi[k] ? th - r->hi[k] : th < r->lo[k] ? th - r->lo[k] : 0;
            if (r->has_spring[k]) e += mcs_hyst2_work(&t->h[k]) + r->preload[k] * th;
            e += 0.5 * r->stop_stiffness[k] * x * x;
        }
        e += t->e_damp;
    }
    for (int i = 0; i < m->nattach; i++)
        e += mb_attach_stored(&m->attach[i], &s->att[i]) + s->att[i].e_damp + s->att[i].e_lost;
    double k = *kin;
    if (m->couple) { /* the coupled FE parts (mb_couple.h); their live energy joins the
                        reference, as in mb_energy_update */
        double f[MB_NENERGY];
        e += mb_couple_energy(m, s, f);
        *kin += f[0] + f[2] + f[3];
    }
    return e + k + potential(m, s) - s->w_presc - mb_prescribe_couple_work(m, s);
}

mcs_status mb_energy_check_step(const mb_model *m, mb_state *s, mcs_error *err)
{
    double kin, total = running_total(m, s, &kin);
    double ref = fmax(fmax(s->e_ref, kin), m->opts.energy_floor);
    if (isfinite(total) && total - s->e_total0 <= m->opts.energy_tol * ref) return MCS_OK;
    return growth_error(m, s, total, ref, err);
}

/* mb_restraint: joint restraints and breakable attachments (see mb_restraint.h). */
#include "stage1_mb/mb_restraint.h"
#include "stage1_mb/mb_vec.h"

#include <math.h>

/* ---- joint restraints ------------------------------------------------------------------------ */

mcs_status mb_restraint_check(const mb_restraint_model *m, const mb_world *w, const char *name,
                              mcs_error *err)
{
    if (m->joint < 0 || m->joint >= mb_world_njoint(w) || isnan(mb_joint_position(w, m->joint)))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: restraint needs a revolute or translational joint (joint %d)", name,
                       m->joint);
    if (!(m->damping >= 0) || !(m->stop_stiffness >= 0) || !(m->stop_damping >= 0) ||
        !isfinite(m->damping) || !isfinite(m->stop_stiffness) || !isfinite(m->stop_damping))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: damping and stop values must be finite and >= 0",
                       name);
    if (m->stop_stiffness > 0 && !(m->lo < m->hi))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: range [%g, %g] is empty", name, m->lo, m->hi);
    if (!isfinite(m->neutral))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: neutral position must be finite", name);
    if (!isfinite(m->preload) || (m->preload != 0 && !m->has_spring))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: a preload must be finite and needs a restraint characteristic", name);
    return m->has_spring ? mcs_hyst2_model_check(&m->spring, name, err) : MCS_OK;
}

void mb_restraint_reset(const mb_restraint_model *m, mb_restraint_state *s)
{
    *s = (mb_restraint_state){0};
    if (m->has_spring) mcs_hyst2_reset(&m->spring, &s->h);
}

/* how far x lies beyond the range (negative below lo), 0 inside */
static double stop_excess(const mb_restraint_model *m, double x)
{
    if (m->stop_stiffness <= 0) return 0;
    return x > m->hi ? x - m->hi : x < m->lo ? x - m->lo : 0;
}

void mb_restraint_apply(const mb_restraint_model *m, mb_restraint_state *s, mb_world *w, double h)
{
    double x = mb_joint_position(w, m->joint), rate = mb_joint_rate(w, m->joint);
    /* characteristic (history committed here, once per step) and viscous damping */
    double f = mb_restraint_spring(m, s, x);
    double fd = m->damping * rate;
    /* stop: one-sided spring-damper beyond the range that never pulls back */
    double e = stop_excess(m, x), fs = 0, fsd = 0;
    if (e != 0) {
        fs = m->stop_stiffness * e;
        fsd = m->stop_damping * rate;
        if (fs * (fs + fsd) < 0) fsd = -fs; /* clamp: the stop only pushes out */
    }
    s->x = x, s->rate = rate;
    s->load = -(f + fd + fs + fsd);
    s->e_damp += (fd + fsd) * rate * h; /* the damper's power over this step */
    mb_joint_add_load(w, m->joint, s->load);
}

double mb_restraint_spring(const mb_restraint_model *m, mb_restraint_state *s, double x)
{
    s->x = x;
    return m->has_spring ? m->preload + mcs_hyst2_update(&m->spring, &s->h, x - m->neutral) : 0;
}

/* the preload's potential is P (x - x0) with x0 = 0 the initial position */
double mb_restraint_stored(const mb_restraint_model *m, const mb_restraint_state *s)
{
    double e = stop_excess(m, s->x);
    double hs = m->has_spring ? mcs_hyst2_stored(&m->spring, &s->h) + m->preload * s->x : 0;
    return hs + 0.5 * m->stop_stiffness * e * e;
}

double mb_restraint_dissipated(const mb_restraint_model *m, const mb_restraint_state *s)
{
    return (m->has_spring ? mcs_hyst2_dissipated(&m->spring, &s->h) : 0) + s->e_damp;
}

/* ---- breakable attachments ------------------------------------------------------------------- */

mcs_status mb_attach_check(const mb_attach_model *m, const mb_world *w, const char *name,
                           mcs_error *err)
{
    int nb = mb_world_nbody(w);
    if (m->body_a < 0 || m->body_a >= nb || m->body_b < -1 || m->body_b >= nb ||
        m->body_a == m->body_b)
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: bad bodies %d and %d", name, m->body_a, m->body_b);
    if (!(m->stiffness > 0) || !isfinite(m->stiffness) || !(m->damping >= 0) ||
        !isfinite(m->damping))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: stiffness %g N/m must be > 0 and damping %g N s/m >= 0", name,
                       m->stiffness, m->damping);
    if (!(m->length >= 0) || !isfinite(m->length))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: free length %g m must be finite and >= 0", name,
                       m->length);
    if (!(m->fail_force > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: failure force %g N must be > 0", name,
                       m->fail_force);
    for (int k = 0; k < 3; k++)
        if (!isfinite(m->pa[k]) || !isfinite(m->pb[k]))
            return MCS_ERR(err, MCS_ERR_RANGE, "%s: attachment points must be finite", name);
    return MCS_OK;
}

void mb_attach_reset(const mb_attach_model *m, mb_attach_state *s)
{
    (void)m;
    *s = (mb_attach_state){.t_break = NAN};
}

/* a body-fixed point in world and its velocity (body -1: the world point itself, at rest) */
static void attach_point(const mb_world *w, int b, const double local[3], double p[3], double v[3])
{
    if (b < 0) {
        mb_copy(local, p);
        v[0] = v[1] = v[2] = 0;
        return;
    }
    mb_body_kin k;
    mb_body_get(w, b, &k);
    double r[3];
    mb_mat_vec(k.rot, local, r);
    mb_add(k.pos, r, p);
    mb_body_point_vel(w, b, p, v);
}

void mb_attach_apply(const mb_attach_model *m, mb_attach_state *s, mb_world *w, double h)
{
    if (s->broken) return;
    double pa[3], va[3], pb[3], vb[3], dv[3];
    attach_point(w, m->body_a, m->pa, pa, va);
    attach_point(w, m->body_b, m->pb, pb, vb);
    mb_sub(pb, pa, s->stretch);
    mb_sub(vb, va, dv);
    /* spring on the extension |d| - L along d (L = 0: k d); at |d| = 0 < L no direction: 0 */
    double d = mb_norm(s->stretch), ks = m->stiffness;
    if (m->length > 0) ks = d > 0 ? m->stiffness * (d - m->length) / d : 0;
    for (int k = 0; k < 3; k++)
        s->force[k] = ks * s->stretch[k] + m->damping * dv[k];
    if (mb_norm(s->force) > m->fail_force) {
        s->e_lost = mb_attach_stored(m, s);
        s->broken = 1;
        s->t_break = mb_world_time(w);
        s->force[0] = s->force[1] = s->force[2] = 0;
        return;
    }
    s->e_damp += m->damping * mb_dot(dv, dv) * h;
    mb_body_add_force_at_pos(w, m->body_a, s->force, pa);
    if (m->body_b >= 0) {
        double fb[3];
        mb_scale(s->force, -1, fb);
        mb_body_add_force_at_pos(w, m->body_b, fb, pb);
    }
}

double mb_attach_stored(const mb_attach_model *m, const mb_attach_state *s)
{
    if (s->broken) return 0;
    double e = mb_norm(s->stretch) - m->length;
    return 0.5 * m->stiffness * e * e;
}

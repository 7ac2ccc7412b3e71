/* tr_rom_fit.c: the reduced-order model calibrated from a stage-1 run and rated against
 * stage-1 runs (tr_rom_fit.h, docs/rom.md "Calibration"). */
#include "translators/tr_rom_fit.h"

#include "analysis/an_cfc.h"
#include "analysis/an_iso18571.h"
#include "analysis/an_resample.h"
#include "core/mcs_results.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void tr_rom_target_free(tr_rom_target *t)
{
    free(t->force), free(t->vel), free(t->acc);
    free(t->rider_vel), free(t->rider_force), free(t->chest_acc);
    memset(t, 0, sizeof *t);
}

/* out += w times a [nt, 3] body quantity projected on the normal, on the grid */
static mcs_status body_on_grid(mcs_results *r, const char *body, const char *q,
                               const mcs_array *time, const double n[3], double w,
                               tr_rom_target *t, double *out, mcs_error *err)
{
    char p[256];
    snprintf(p, sizeof p, "/stage1/bodies/%s/%s", body, q);
    mcs_array a = {0};
    mcs_status st = mcs_results_read(r, p, &a, err);
    if (!st && (a.rank != 2 || a.dims[1] != 3 || a.dims[0] != time->n))
        st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: expected [%zu, 3]", p, time->n);
    double *s = st ? NULL : malloc(sizeof *s * time->n);
    if (!st && !s) st = MCS_ERR(err, MCS_ERR_NOMEM, "rom target");
    for (size_t i = 0; !st && i < time->n; i++)
        s[i] = a.v[3 * i] * n[0] + a.v[3 * i + 1] * n[1] + a.v[3 * i + 2] * n[2];
    for (int i = 0; !st && i < t->n; i++)
        out[i] += w * an_interp_linear(time->v, s, (int)time->n, i * t->dt);
    free(s);
    mcs_array_free(&a);
    return st;
}

/* the barrier force: every stage-1 contact channel *_barrier_fn, summed */
static mcs_status force_on_grid(mcs_results *r, const mcs_array *time, tr_rom_target *t,
                                mcs_error *err)
{
    char **names = NULL;
    int nn = 0, used = 0;
    mcs_status st = mcs_results_list(r, "/stage1/channels", &names, &nn, err);
    for (int k = 0; !st && k < nn; k++) {
        size_t l = strlen(names[k]);
        if (l < 11 || strcmp(names[k] + l - 11, "_barrier_fn")) continue;
        char p[600];
        snprintf(p, sizeof p, "/stage1/channels/%s", names[k]);
        mcs_array a = {0};
        st = mcs_results_read(r, p, &a, err);
        if (!st && a.n != time->n) st = MCS_ERR(err, MCS_ERR_FORMAT, "%s: %zu samples", p, a.n);
        int rider = strncmp(names[k], "rider_", 6) == 0;
        for (int i = 0; !st && i < t->n; i++) {
            double f = an_interp_linear(time->v, a.v, (int)time->n, i * t->dt);
            t->force[i] += f;
            if (rider && t->rider_force) t->rider_force[i] += f;
        }
        mcs_array_free(&a);
        used++;
    }
    mcs_results_list_free(&names, nn);
    if (!st && !used)
        st = MCS_ERR(err, MCS_ERR_KEY, "no /stage1/channels/*_barrier_fn (a barrier contact)");
    return st;
}

/* the rider: centre-of-mass velocity (the rider_* bodies' velocities weighted by their masses
 * in the scenario) and the upper torso's acceleration */
static mcs_status rider_on_grid(mcs_results *r, const mcs_scenario *scn, const mcs_array *time,
                                const double n[3], tr_rom_target *t, mcs_error *err)
{
    const mcs_node *bodies = mcs_node_get(mcs_scenario_root(scn), "bodies");
    double mtot = 0;
    for (int i = 0; i < mcs_node_len(bodies); i++) {
        const mcs_node *b = mcs_node_at(bodies, i);
        if (!strncmp(mcs_node_str(mcs_node_get(b, "name")), "rider_", 6))
            mtot += mcs_node_num(mcs_node_get(b, "mass"));
    }
    mcs_status st = MCS_OK;
    for (int i = 0; !st && i < mcs_node_len(bodies); i++) {
        const mcs_node *b = mcs_node_at(bodies, i);
        const char *name = mcs_node_str(mcs_node_get(b, "name"));
        if (strncmp(name, "rider_", 6)) continue;
        double w = mcs_node_num(mcs_node_get(b, "mass")) / mtot;
        st = body_on_grid(r, name, "velocity", time, n, w, t, t->rider_vel, err);
    }
    if (!st) st = body_on_grid(r, "rider_upper_torso", "acceleration", time, n, 1, t, t->chest_acc,
                               err);
    if (!st) st = an_cfc_filter(t->chest_acc, t->n, t->dt, 180, t->chest_acc, err);
    return st;
}

static double *zeros(int n, int *bad)
{
    double *p = calloc((size_t)n, sizeof(double));
    *bad |= !p;
    return p;
}

mcs_status tr_rom_target_read(const char *h5, const mcs_scenario *scn, const double normal[3],
                              double t_end, double dt, tr_rom_target *t, mcs_error *err)
{
    memset(t, 0, sizeof *t);
    mcs_results *r = NULL;
    mcs_array time = {0};
    mcs_status st = mcs_results_open(&r, h5, err);
    if (!st) st = mcs_results_read(r, "/stage1/time", &time, err);
    if (!st && (time.n < 2 || time.v[time.n - 1] < t_end * (1 - 1e-9)))
        st = MCS_ERR(err, MCS_ERR_RANGE, "%s: /stage1/time ends before %g s", h5, t_end);
    if (!st) {
        int bad = 0;
        t->n = (int)floor(t_end / dt + 1e-9) + 1, t->dt = dt;
        t->rider = mcs_results_kind(r, "/stage1/bodies/rider_upper_torso") == MCS_RES_GROUP;
        t->force = zeros(t->n, &bad), t->vel = zeros(t->n, &bad), t->acc = zeros(t->n, &bad);
        if (t->rider) {
            t->rider_vel = zeros(t->n, &bad), t->rider_force = zeros(t->n, &bad);
            t->chest_acc = zeros(t->n, &bad);
        }
        if (bad) st = MCS_ERR(err, MCS_ERR_NOMEM, "rom target");
    }
    if (!st) st = force_on_grid(r, &time, t, err);
    if (!st) st = body_on_grid(r, "moto_frame", "velocity", &time, normal, 1, t, t->vel, err);
    if (!st) st = body_on_grid(r, "moto_frame", "acceleration", &time, normal, 1, t, t->acc, err);
    if (!st) st = an_cfc_filter(t->acc, t->n, dt, 60, t->acc, err);
    if (!st && t->rider) st = rider_on_grid(r, scn, &time, normal, t, err);
    if (!st) t->v0 = t->vel[0];
    mcs_array_free(&time);
    mcs_results_close(&r);
    if (st) tr_rom_target_free(t);
    return st;
}

/* bounds (docs/rom.md "Calibration"): the stage-1 characteristics' values within the ranges
 * docs/retune.md gives for the same quantities (a factor 2 on tyre and fork forces, the fork
 * stop 0.12 .. 0.35 rad at the 0.40 m lever), the frame gap 0.10 .. 0.30 m around the fairing
 * nose's 175 mm, the frame stiffness between half the engine's secant at 150 mm (533 kN/m) and
 * its initial slope (2 MN/m) */
static const char *const free_names[] = {"tyre_stiffness", "rim_stiffness", "fork_yield",
                                         "fork_stop",      "frame_gap",     "frame_stiffness"};
static const double free_lo[] = {125e3, 196e3, 4625, 0.048, 0.10, 2.67e5};
static const double free_hi[] = {500e3, 786e3, 18500, 0.14, 0.30, 2e6};

tr_rom_free tr_rom_free_default(void)
{
    return (tr_rom_free){6, free_names, free_lo, free_hi, 0};
}

/* the rider's bounds (docs/rom.md "Calibration"): the restraint gap from 0 (knees on the tank)
 * to 150 mm (the seat's H-point 110 mm behind the tank, sport_208kg.yaml, plus the thighs'
 * slide), its stiffness between the seat's secant at 80 mm (375 kN/m) halved and the tank's at
 * 100 mm (600 kN/m) doubled, its plateau between the rider's attachments and seat friction
 * (1.5 kN) and the tank's last point (60 kN); the barrier gap from the hands' (0.3 m behind the
 * tyre's front) to the pelvis' (1.2 m), the rider_torso characteristic's secants (100 kN/m at
 * 10 mm, 750 kN/m at 80 mm), its unloading slope from the loading's (elastic) to twice the
 * stiffest of stage 1's (tyre_front, 10 MN/m) */
static const char *const rider_names[] = {"rider_gap",      "rider_stiffness",
                                          "rider_limit",    "rider_wall_gap",
                                          "rider_wall_stiffness", "rider_wall_unload"};
static const double rider_lo[] = {0.0, 1.875e5, 1.5e3, 0.3, 1e5, 7.5e5};
static const double rider_hi[] = {0.15, 1.2e6, 60e3, 1.2, 7.5e5, 2e7};

tr_rom_free tr_rom_free_rider(void)
{
    return (tr_rom_free){6, rider_names, rider_lo, rider_hi, 1};
}

typedef struct {
    rom_model *m;
    const tr_rom_target *t;
    const tr_rom_free *f;
    double fscale;
} fit_ctx;

/* residuals: [(F_rom - F_1) / max F_1, (v_rom - v_1) / v0] / sqrt(n) */
static mcs_status residuals(void *ctx, const double *p, double *res, mcs_error *err)
{
    fit_ctx *c = ctx;
    rom_params q = c->m->p;
    for (int i = 0; i < c->f->n; i++) *rom_param_ptr(&q, c->f->name[i]) = p[i];
    mcs_status st = rom_model_rebuild(c->m, &q, err);
    rom_result r = {0};
    if (!st) st = rom_run(c->m, &r, err);
    if (st) return st;
    const int n = c->t->n;
    const double w = 1 / sqrt((double)n);
    const int rd = c->f->rider;
    const double *F = rd ? r.f[ROM_RIDERWALL] : r.wall_force;
    const double *V = r.v[rd ? ROM_RIDER : ROM_FRAME];
    const double *F1 = rd ? c->t->rider_force : c->t->force;
    const double *V1 = rd ? c->t->rider_vel : c->t->vel;
    for (int i = 0; i < n; i++) {
        double fr = i < r.nt ? F[i] : 0, vr = i < r.nt ? V[i] : 0;
        res[i] = w * (fr - F1[i]) / c->fscale;
        res[n + i] = w * (vr - V1[i]) / fabs(c->t->v0);
    }
    rom_result_free(&r);
    return MCS_OK;
}

/* the model on the target's grid and span */
static mcs_status on_grid(rom_model *m, const tr_rom_target *t, mcs_error *err)
{
    m->out_dt = t->dt;
    m->end_time = (t->n - 1) * t->dt;
    return rom_model_rebuild(m, &m->p, err);
}

mcs_status tr_rom_fit(rom_model *m, const tr_rom_target *t, const tr_rom_free *f,
                      tr_lm_result *res, mcs_error *err)
{
    mcs_status st = on_grid(m, t, err);
    if (st) return st;
    double p[16], fpk = 0;
    if (f->n > 16) return MCS_ERR(err, MCS_ERR_USAGE, "rom fit: %d parameters (16 at most)", f->n);
    for (int i = 0; i < f->n; i++) {
        double *v = rom_param_ptr(&m->p, f->name[i]);
        if (!v) return MCS_ERR(err, MCS_ERR_KEY, "rom fit: no parameter %s", f->name[i]);
        p[i] = *v;
    }
    if (f->rider && (!t->rider || !(m->mass[ROM_RIDER] > 0)))
        return MCS_ERR(err, MCS_ERR_USAGE, "rom fit: the rider's parameters need a rider");
    const double *F1 = f->rider ? t->rider_force : t->force;
    for (int i = 0; i < t->n; i++) fpk = fmax(fpk, F1[i]);
    if (!(fpk > 0) || !(fabs(t->v0) > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "rom fit: the target has no barrier force or speed");
    fit_ctx c = {m, t, f, fpk};
    tr_lm_opts o = tr_lm_opts_default();
    st = tr_lm_solve(residuals, &c, f->n, 2 * t->n, p, f->lo, f->hi, &o, res, err);
    if (st) return st;
    rom_params q = m->p;
    for (int i = 0; i < f->n; i++) *rom_param_ptr(&q, f->name[i]) = p[i];
    return rom_model_rebuild(m, &q, err);
}

static double peak_abs(const double *y, int n)
{
    double p = 0;
    for (int i = 0; i < n; i++) p = fmax(p, fabs(y[i]));
    return p;
}

/* the rider's rows: velocity and barrier force, its acceleration against the chest's */
static mcs_status rider_error(const rom_result *r, const tr_rom_target *t, tr_rom_error *e,
                              mcs_error *err)
{
    an_iso_opts o = an_iso_opts_default();
    an_iso_result ir;
    double *acc = malloc(sizeof *acc * (size_t)t->n);
    if (!acc) return MCS_ERR(err, MCS_ERR_NOMEM, "rom error");
    mcs_status st = an_cfc_filter(r->a[ROM_RIDER], t->n, t->dt, 180, acc, err);
    if (!st) st = an_iso18571_arrays(t->rider_vel, r->v[ROM_RIDER], t->n, t->dt, &o, &ir, err);
    if (!st) e->iso_rider_vel = ir.rating;
    if (!st)
        st = an_iso18571_arrays(t->rider_force, r->f[ROM_RIDERWALL], t->n, t->dt, &o, &ir, err);
    if (!st) e->iso_rider_force = ir.rating;
    if (!st) st = an_iso18571_arrays(t->chest_acc, acc, t->n, t->dt, &o, &ir, err);
    if (!st) {
        e->iso_chest = ir.rating;
        double a1 = peak_abs(t->chest_acc, t->n);
        e->peak_chest_err = (peak_abs(acc, t->n) - a1) / a1;
    }
    free(acc);
    return st;
}

mcs_status tr_rom_error_eval(const rom_model *m0, const tr_rom_target *t, tr_rom_error *e,
                             mcs_error *err)
{
    rom_model m = *m0;
    memset(m.elem, 0, sizeof m.elem); /* a copy with its own curves */
    m.out_dt = t->dt, m.end_time = (t->n - 1) * t->dt;
    mcs_status st = rom_model_rebuild(&m, &m0->p, err);
    if (st) return st;
    rom_result r = {0};
    st = rom_run(&m, &r, err);
    double *acc = st ? NULL : malloc(sizeof *acc * (size_t)t->n);
    if (!st && !acc) st = MCS_ERR(err, MCS_ERR_NOMEM, "rom error");
    if (!st && r.nt != t->n) st = MCS_ERR(err, MCS_ERR_RANGE, "rom error: %d of %d", r.nt, t->n);
    if (!st) st = an_cfc_filter(r.a[ROM_FRAME], t->n, t->dt, 60, acc, err);
    an_iso_opts o = an_iso_opts_default();
    an_iso_result ir;
    if (!st) st = an_iso18571_arrays(t->force, r.wall_force, t->n, t->dt, &o, &ir, err);
    if (!st) e->iso_force = ir.rating;
    if (!st) st = an_iso18571_arrays(t->vel, r.v[ROM_FRAME], t->n, t->dt, &o, &ir, err);
    if (!st) e->iso_vel = ir.rating;
    if (!st) st = an_iso18571_arrays(t->acc, acc, t->n, t->dt, &o, &ir, err);
    e->iso_rider_vel = e->iso_rider_force = e->iso_chest = e->peak_chest_err = NAN;
    if (!st && t->rider && m.mass[ROM_RIDER] > 0) st = rider_error(&r, t, e, err);
    if (!st) {
        e->iso_acc = ir.rating;
        double f1 = peak_abs(t->force, t->n), a1 = peak_abs(t->acc, t->n);
        e->peak_force_err = (peak_abs(r.wall_force, t->n) - f1) / f1;
        e->peak_acc_err = (peak_abs(acc, t->n) - a1) / a1;
        e->rebound_err = r.v[ROM_FRAME][t->n - 1] - t->vel[t->n - 1];
    }
    free(acc);
    rom_result_free(&r);
    rom_model_deinit(&m);
    return st;
}

/* rom_out.c: the reduced-order model's results in /stage0 (docs/contracts.md "Stage 0: the
 * reduced-order model"): time, channels, the bodies' velocity and acceleration (world frame,
 * along the barrier normal), energies. */
#include "rom/rom.h"

#include "analysis/an_cfc.h"
#include "core/mcs_results.h"

#include <stdlib.h>
#include <string.h>

#define ST ROM_STAGE

static mcs_status channel(mcs_results *res, const char *name, const rom_result *r,
                          const double *y, const char *unit, int cfc, const char *body,
                          mcs_error *err)
{
    if (!cfc)
        return mcs_results_put_channel(res, ST, name, (size_t)r->nt, y, unit,
                                       "reduced-order model: along the barrier normal", 0, body,
                                       err);
    double *yf = malloc(sizeof *yf * (size_t)r->nt);
    if (!yf) return MCS_ERR(err, MCS_ERR_NOMEM, "rom: channel %s", name);
    mcs_status st = an_cfc_filter(y, r->nt, r->t[1] - r->t[0], cfc, yf, err);
    if (!st)
        st = mcs_results_put_channel(res, ST, name, (size_t)r->nt, yf, unit,
                                     "reduced-order model: along the barrier normal", cfc, body,
                                     err);
    free(yf);
    return st;
}

/* velocity and acceleration of mass k as world vectors s * normal */
static mcs_status body(mcs_results *res, const rom_model *m, const rom_result *r, int k,
                       const char *name, mcs_error *err)
{
    double *w = malloc(sizeof *w * 3 * (size_t)r->nt);
    if (!w) return MCS_ERR(err, MCS_ERR_NOMEM, "rom: body %s", name);
    mcs_status st = MCS_OK;
    const double *src[2] = {r->v[k], r->a[k]};
    const char *q[2] = {"velocity", "acceleration"};
    for (int j = 0; !st && j < 2; j++) {
        for (int i = 0; i < r->nt; i++)
            for (int c = 0; c < 3; c++) w[3 * i + c] = src[j][i] * m->normal[c];
        st = mcs_results_put_body(res, ST, name, q[j], (size_t)r->nt, w, err);
    }
    free(w);
    return st;
}

mcs_status rom_write(const rom_model *m, const rom_result *r, mcs_results *res, mcs_error *err)
{
    if (r->nt < 2) return MCS_ERR(err, MCS_ERR_USAGE, "rom: %d output samples", r->nt);
    const int rider = m->mass[ROM_RIDER] > 0;
    mcs_status st = mcs_results_put_time(res, ST, (size_t)r->nt, r->t, err);
    /* forces: the barrier's (what stage 1 sums over its *_barrier_fn), then each element's */
    if (!st) st = channel(res, "barrier_fn", r, r->wall_force, "N", 0, NULL, err);
    if (!st) st = channel(res, "tyre_barrier_fn", r, r->f[ROM_TYRE], "N", 0, NULL, err);
    if (!st) st = channel(res, "frame_barrier_fn", r, r->f[ROM_FRAMEWALL], "N", 0, NULL, err);
    if (!st) st = channel(res, "fork_force", r, r->f[ROM_FORK], "N", 0, NULL, err);
    if (!st) st = channel(res, "fork_deflection", r, r->d[ROM_FORK], "m", 0, NULL, err);
    /* the frame's sensor as stage 1's (moto_frame, CFC 60) */
    if (!st)
        st = channel(res, "moto_frame_ax", r, r->a[ROM_FRAME], "m/s^2", 60, "moto_frame", err);
    if (!st)
        st = channel(res, "moto_frame_vel_vx", r, r->v[ROM_FRAME], "m/s", 0, "moto_frame", err);
    if (!st && rider)
        st = channel(res, "rider_moto_fn", r, r->f[ROM_RIDERFRAME], "N", 0, NULL, err);
    if (!st && rider)
        st = channel(res, "rider_barrier_fn", r, r->f[ROM_RIDERWALL], "N", 0, NULL, err);
    /* the rider mass as the chest's sensor (SAE J211: x forward, along the normal; y, z none),
     * so `mcrash injury --stage 0` gives its chest a3ms */
    double *zero = calloc((size_t)r->nt, sizeof *zero);
    if (!zero) return MCS_ERR(err, MCS_ERR_NOMEM, "rom: channels");
    const char *chest[3] = {"chest_ax", "chest_ay", "chest_az"};
    for (int k = 0; !st && rider && k < 3; k++)
        st = channel(res, chest[k], r, k ? zero : r->a[ROM_RIDER], "m/s^2", 0, "rider_torso", err);
    if (!st) st = body(res, m, r, ROM_FRONT, "moto_front", err);
    if (!st) st = body(res, m, r, ROM_FRAME, "moto_frame", err);
    if (!st && rider) st = body(res, m, r, ROM_RIDER, "rider_torso", err);
    if (!st && m->mass[ROM_OPP] > 0) st = body(res, m, r, ROM_OPP, "opponent", err);
    const char *kind[] = {"kinetic", "internal", "dissipated", "total", "potential",
                          "contact", "hourglass", "external_work"};
    const double *e[] = {r->kinetic, r->internal, r->dissipated, r->total, zero, zero, zero, zero};
    for (int i = 0; !st && i < 8; i++)
        st = mcs_results_put_energy(res, ST, kind[i], (size_t)r->nt, e[i], err);
    free(zero);
    if (!st) st = mcs_results_set_attr_int(res, "/stage0", "cvode_steps", (int)r->steps, err);
    if (!st)
        st = mcs_results_set_attr_str(res, "/stage0", "model",
                                      "reduced-order lumped mass-spring-damper (rom/rom.h)", err);
    return st;
}

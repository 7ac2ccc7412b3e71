/* rom_run.c: the reduced-order model integrated by CVODE (SUNDIALS 6), rom.h.
 * State y = (x[4], v[4], E_d): positions, velocities and the work of the dampers. CVODE runs in
 * one-step mode; after each accepted step the hysteresis histories are committed (as stage 1
 * does after each time step), and the outputs between two steps come from CVODE's
 * interpolating polynomial (CVodeGetDky) with the histories taken to that point. Root finding
 * stops a step where an element turns from loading to unloading, so its peak is exact. BDF with a
 * dense Newton solver (default) or Adams-Moulton with fixed-point iteration (method: adams);
 * relative tolerance rtol, absolute 1e-3 rtol of the scale (1 m, v0, initial energy). */
#include "rom/rom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

enum { NM = ROM_NMASS, Y_X = 0, Y_V = NM, Y_ED = 2 * NM, NY };

typedef struct {
    const rom_model *m;
    mcs_hyst_state hs[ROM_NELEM]; /* committed histories */
    long nrhs;
} rom_ode;

static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *ud)
{
    (void)t;
    rom_ode *o = ud;
    const double *Y = N_VGetArrayPointer(y);
    double *D = N_VGetArrayPointer(ydot), acc[NM], f[ROM_NELEM], d[ROM_NELEM];
    rom_forces(o->m, o->hs, Y + Y_X, Y + Y_V, acc, f, d);
    o->nrhs++;
    double pd = 0; /* damper power: element force minus spring force, times the rate */
    for (int i = 0; i < ROM_NELEM; i++) {
        const rom_elem *e = &o->m->elem[i];
        if (f[i] == 0 && d[i] <= 0) continue;
        double fs = d[i] > 0 ? mcs_hyst_force(&e->hyst, &o->hs[i], d[i]) : 0;
        double rate = Y[Y_V + e->a] - (e->b >= 0 ? Y[Y_V + e->b] : 0);
        pd += (f[i] - fs) * rate;
    }
    for (int k = 0; k < NM; k++) D[Y_X + k] = Y[Y_V + k], D[Y_V + k] = acc[k];
    D[Y_ED] = pd;
    return isfinite(pd) ? 0 : -1;
}

/* a root where an element in contact turns from loading to unloading (its rate crosses 0):
 * the step stops there, so the history's peak deflection is the true one */
static int roots(sunrealtype t, N_Vector y, sunrealtype *g, void *ud)
{
    (void)t;
    rom_ode *o = ud;
    const rom_model *m = o->m;
    const double *Y = N_VGetArrayPointer(y);
    for (int i = 0; i < ROM_NELEM; i++) {
        const rom_elem *e = &m->elem[i];
        g[i] = 1;
        if (m->mass[e->a] <= 0 || (e->b >= 0 && m->mass[e->b] <= 0)) continue;
        double xb = e->b >= 0 ? Y[Y_X + e->b] : 0, vb = e->b >= 0 ? Y[Y_V + e->b] : 0;
        if (Y[Y_X + e->a] - xb - e->gap > 0) g[i] = Y[Y_V + e->a] - vb;
    }
    return 0;
}

static void err_handler(int code, const char *module, const char *function, char *msg, void *ud)
{
    (void)ud;
    mcs_log(MCS_LOG_DEBUG, "%s %s (%d): %s", module, function, code, msg);
}

void rom_result_free(rom_result *r)
{
    double **a[] = {&r->t, &r->wall_force, &r->kinetic, &r->internal, &r->dissipated, &r->total};
    for (size_t i = 0; i < sizeof a / sizeof *a; i++) free(*a[i]), *a[i] = NULL;
    for (int k = 0; k < NM; k++) {
        free(r->x[k]), free(r->v[k]), free(r->a[k]);
        r->x[k] = r->v[k] = r->a[k] = NULL;
    }
    for (int i = 0; i < ROM_NELEM; i++) free(r->f[i]), free(r->d[i]), r->f[i] = r->d[i] = NULL;
}

static mcs_status alloc(rom_result *r, int nt, mcs_error *err)
{
    memset(r, 0, sizeof *r);
    r->nt = nt;
    int bad = 0;
    double **a[] = {&r->t, &r->wall_force, &r->kinetic, &r->internal, &r->dissipated, &r->total};
    for (size_t i = 0; i < sizeof a / sizeof *a; i++) bad |= !(*a[i] = calloc(nt, sizeof(double)));
    for (int k = 0; k < NM; k++) {
        bad |= !(r->x[k] = calloc(nt, sizeof(double)));
        bad |= !(r->v[k] = calloc(nt, sizeof(double)));
        bad |= !(r->a[k] = calloc(nt, sizeof(double)));
    }
    for (int i = 0; i < ROM_NELEM; i++) {
        bad |= !(r->f[i] = calloc(nt, sizeof(double)));
        bad |= !(r->d[i] = calloc(nt, sizeof(double)));
    }
    if (bad) {
        rom_result_free(r);
        return MCS_ERR(err, MCS_ERR_NOMEM, "rom: %d output samples", nt);
    }
    return MCS_OK;
}

/* output sample k at time t from state Y (histories committed up to the last step, taken to Y) */
static void sample(const rom_ode *o, rom_result *r, int k, double t, const double *Y)
{
    const rom_model *m = o->m;
    double acc[NM], f[ROM_NELEM], d[ROM_NELEM], ke = 0, stored = 0, diss = Y[Y_ED];
    rom_forces(m, o->hs, Y + Y_X, Y + Y_V, acc, f, d);
    r->t[k] = t;
    for (int j = 0; j < NM; j++) {
        r->x[j][k] = Y[Y_X + j], r->v[j][k] = Y[Y_V + j], r->a[j][k] = acc[j];
        ke += 0.5 * m->mass[j] * Y[Y_V + j] * Y[Y_V + j];
    }
    double fw = 0;
    for (int i = 0; i < ROM_NELEM; i++) {
        mcs_hyst_state h = o->hs[i];
        mcs_hyst_update(&m->elem[i].hyst, &h, d[i]);
        stored += mcs_hyst_stored(&m->elem[i].hyst, &h);
        diss += mcs_hyst_dissipated(&m->elem[i].hyst, &h);
        r->f[i][k] = f[i], r->d[i][k] = d[i];
        if (m->elem[i].b == -1 || m->elem[i].b == ROM_OPP) fw += f[i];
    }
    r->wall_force[k] = fw;
    r->kinetic[k] = ke, r->internal[k] = stored, r->dissipated[k] = diss;
    r->total[k] = ke + stored + diss;
}

/* commit the histories at the step's end */
static void commit(rom_ode *o, const double *Y)
{
    double acc[NM], f[ROM_NELEM], d[ROM_NELEM];
    rom_forces(o->m, o->hs, Y + Y_X, Y + Y_V, acc, f, d);
    for (int i = 0; i < ROM_NELEM; i++) mcs_hyst_update(&o->m->elem[i].hyst, &o->hs[i], d[i]);
}

static mcs_status integrate(rom_ode *o, void *cv, N_Vector y, N_Vector yk, rom_result *r,
                            mcs_error *err)
{
    const rom_model *m = o->m;
    double t = 0, *Y = N_VGetArrayPointer(y), *YK = N_VGetArrayPointer(yk);
    sample(o, r, 0, 0, Y);
    r->steps = 0;
    int k = 1;
    while (k < r->nt) {
        int flag = CVode(cv, m->end_time, y, &t, CV_ONE_STEP);
        if (flag < 0)
            return MCS_ERR(err, MCS_ERR_NUMERIC, "rom: CVODE failed at t = %.9g s (flag %d: %s)",
                           t, flag, CVodeGetReturnFlagName(flag));
        int root = flag == CV_ROOT_RETURN;
        r->steps++;
        for (; k < r->nt && k * m->out_dt <= t * (1 + 1e-12); k++) {
            double tk = k * m->out_dt;
            if (CVodeGetDky(cv, tk, 0, yk) != CV_SUCCESS)
                return MCS_ERR(err, MCS_ERR_NUMERIC, "rom: CVodeGetDky at %.9g s", tk);
            sample(o, r, k, tk, YK);
        }
        if (t >= m->end_time && k < r->nt)
            return MCS_ERR(err, MCS_ERR_NUMERIC, "rom: %d of %d samples at the end time %.9g s",
                           k, r->nt, t);
        commit(o, Y);
        /* the right side's slope changes at a turning point: restart the multistep history */
        if (root && CVodeReInit(cv, t, y) != CV_SUCCESS)
            return MCS_ERR(err, MCS_ERR_NUMERIC, "rom: CVodeReInit at %.9g s", t);
    }
    r->rhs_evals = o->nrhs;
    double e0 = r->total[0], drift = 0;
    for (int i = 0; i < r->nt; i++) drift = fmax(drift, fabs(r->total[i] - e0));
    r->energy_drift = e0 > 0 ? drift / e0 : drift;
    for (int i = 0; i < r->nt; i++)
        if (!isfinite(r->total[i]))
            return MCS_ERR(err, MCS_ERR_NUMERIC, "rom: non-finite energy at t = %.9g s", r->t[i]);
    return MCS_OK;
}

mcs_status rom_run(const rom_model *m, rom_result *r, mcs_error *err)
{
    int nt = (int)floor(m->end_time / m->out_dt + 1e-9) + 1;
    mcs_status st = alloc(r, nt, err);
    if (st) return st;
    rom_ode o = {.m = m};
    for (int i = 0; i < ROM_NELEM; i++) mcs_hyst_reset(&m->elem[i].hyst, &o.hs[i]);
    SUNContext ctx = NULL;
    N_Vector y = NULL, yk = NULL, atol = NULL;
    SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL;
    SUNNonlinearSolver NLS = NULL;
    void *cv = NULL;
    if (SUNContext_Create(NULL, &ctx) != 0) {
        rom_result_free(r);
        return MCS_ERR(err, MCS_ERR_NOMEM, "rom: SUNContext_Create failed");
    }
    y = N_VNew_Serial(NY, ctx), yk = N_VNew_Serial(NY, ctx), atol = N_VNew_Serial(NY, ctx);
    cv = CVodeCreate(m->p.adams ? CV_ADAMS : CV_BDF, ctx);
    if (!y || !yk || !atol || !cv) {
        st = MCS_ERR(err, MCS_ERR_NOMEM, "rom: CVODE setup");
        goto done;
    }
    double *Y = N_VGetArrayPointer(y), *AT = N_VGetArrayPointer(atol);
    double vs = fmax(fabs(m->v0), 1.0), e0 = 0;
    for (int k = 0; k < NM; k++) {
        double v = m->mass[k] > 0 ? m->vinit[k] : 0;
        Y[Y_X + k] = 0, Y[Y_V + k] = v;
        e0 += 0.5 * m->mass[k] * v * v;
        AT[Y_X + k] = 1e-3 * m->p.rtol, AT[Y_V + k] = 1e-3 * m->p.rtol * vs;
    }
    Y[Y_ED] = 0, AT[Y_ED] = 1e-3 * m->p.rtol * fmax(e0, 1.0);
    int bad = CVodeInit(cv, rhs, 0.0, y) != CV_SUCCESS ||
              CVodeSVtolerances(cv, m->p.rtol, atol) != CV_SUCCESS ||
              CVodeSetUserData(cv, &o) != CV_SUCCESS ||
              CVodeSetErrHandlerFn(cv, err_handler, NULL) != CV_SUCCESS ||
              CVodeSetMaxNumSteps(cv, 1000000) != CV_SUCCESS ||
              CVodeSetStopTime(cv, m->end_time) != CV_SUCCESS ||
              CVodeRootInit(cv, ROM_NELEM, roots) != CV_SUCCESS;
    if (!bad && m->p.adams) {
        NLS = SUNNonlinSol_FixedPoint(y, 0, ctx);
        bad = !NLS || CVodeSetNonlinearSolver(cv, NLS) != CV_SUCCESS;
    } else if (!bad) {
        A = SUNDenseMatrix(NY, NY, ctx);
        LS = A ? SUNLinSol_Dense(y, A, ctx) : NULL;
        bad = !LS || CVodeSetLinearSolver(cv, LS, A) != CV_SUCCESS;
    }
    if (bad) {
        st = MCS_ERR(err, MCS_ERR_NUMERIC, "rom: CVODE setup failed");
        goto done;
    }
    st = integrate(&o, cv, y, yk, r, err);
done:
    CVodeFree(&cv);
    if (NLS) SUNNonlinSolFree(NLS);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (y) N_VDestroy(y);
    if (yk) N_VDestroy(yk);
    if (atol) N_VDestroy(atol);
    SUNContext_Free(&ctx);
    if (st) rom_result_free(r);
    return st;
}

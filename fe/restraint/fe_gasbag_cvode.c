/* fe_gasbag_cvode: the gas-bag balances integrated by CVODE (SUNDIALS 6) for a volume known as a
 * function of time. Why CVODE here: with V(t) given, the gas state is a small ODE system
 * whose right side has kinks (choking, vent opening, table breakpoints) and a square-root
 * singularity as p -> p_amb; an integrator with local error control, root finding for vent
 * opening and stop times at the breakpoints gives a reference to any tolerance, independent
 * of the per-FE-step update it checks. BDF with a dense Newton solver: the blow-down tail
 * (p -> p_amb) is stiff. */
#include "fe/fe_gasbag.h"
#include "fe/restraint/fe_gasbag_impl.h"

#include <math.h>
#include <stdlib.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

/* y: mass, U, then the running totals */
enum { Y_M, Y_U, Y_MIN, Y_HIN, Y_MV, Y_EV, Y_ML, Y_EL, Y_W, NY };

typedef struct {
    const fe_gasbag_model *m;
    fe_gasbag_volume_fn vol;
    void *user;
    double area;   /* fabric area [m^2] */
    unsigned open; /* vents open */
    double tf;     /* firing time of the state [s] */
    int vol_failed;
} gb_ode;

static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gb_ode *o = ud;
    const fe_gasbag_model *m = o->m;
    double *Y = N_VGetArrayPointer(y), *D = N_VGetArrayPointer(ydot);
    double V, dV;
    if (o->vol(t, &V, &dV, o->user) != 0 || !(V > 0.0)) {
        o->vol_failed = 1;
        return -1;
    }
    double mass = Y[Y_M], U = Y[Y_U];
    if (!(mass > 0.0 && U > 0.0)) return 1; /* recoverable: CVODE retries a smaller step */
    double T = U / (mass * m->cv), p = (m->gamma - 1.0) * U / V, mdi, Tin, mv, ml;
    fe_gasbag_inflow_(m, o->tf, t, &mdi, &Tin);
    fe_gasbag_outflow_(m, o->open, o->area, mass, U, V, &mv, &ml);
    D[Y_M] = mdi - mv - ml;
    D[Y_U] = mdi * m->cp * Tin - (mv + ml) * m->cp * T - p * dV;
    D[Y_MIN] = mdi;
    D[Y_HIN] = mdi * m->cp * Tin;
    D[Y_MV] = mv;
    D[Y_EV] = mv * m->cp * T;
    D[Y_ML] = ml;
    D[Y_EL] = ml * m->cp * T;
    D[Y_W] = p * dV;
    return 0;
}

/* vent i opens when the gauge pressure reaches its open pressure */
static int roots(sunrealtype t, N_Vector y, sunrealtype *g, void *ud)
{
    gb_ode *o = ud;
    const fe_gasbag_model *m = o->m;
    double V, dV, *Y = N_VGetArrayPointer(y);
    if (o->vol(t, &V, &dV, o->user) != 0 || !(V > 0.0)) {
        o->vol_failed = 1;
        return -1;
    }
    double p = (m->gamma - 1.0) * Y[Y_U] / V;
    for (int i = 0; i < m->nvent; i++)
        g[i] = (o->open & (1u << i)) ? 1.0 : p - m->ambient_pressure - m->vent[i].open_pressure;
    return 0;
}

static void err_handler(int code, const char *module, const char *function, char *msg, void *ud)
{
    (void)ud;
    mcs_log(MCS_LOG_DEBUG, "%s %s (%d): %s", module, function, code, msg);
}

/* next stop time after t: firing, a table breakpoint, or t_end (kinks restart the BDF) */
static double next_stop(const fe_gasbag_model *m, double tf, double t, double t_end)
{
    double ts = t_end;
    if (m->mass_flow) {
        if (tf > t && tf < ts) ts = tf;
        for (int i = 0; i < m->mass_flow->n; i++) {
            double tb = tf + m->mass_flow->x[i];
            if (tb > t * (1.0 + 1e-14) + 1e-15 && tb < ts) ts = tb;
        }
    }
    return ts;
}

static void commit(const fe_gasbag_model *m, fe_gasbag_state *s, const gb_ode *o, const double *Y,
                   double t)
{
    double V, dV;
    o->vol(t, &V, &dV, o->user);
    s->time = t;
    s->volume = V;
    s->mass = Y[Y_M];
    s->energy = Y[Y_U];
    s->temperature = Y[Y_U] / (Y[Y_M] * m->cv);
    s->pressure = (m->gamma - 1.0) * Y[Y_U] / V;
    s->mass_in = Y[Y_MIN], s->energy_in = Y[Y_HIN];
    s->mass_vent = Y[Y_MV], s->energy_vent = Y[Y_EV];
    s->mass_leak = Y[Y_ML], s->energy_leak = Y[Y_EL];
    s->work = Y[Y_W];
    s->vent_open = o->open;
    double Tin;
    fe_gasbag_inflow_(m, o->tf, t, &s->mass_flow_in, &Tin);
    fe_gasbag_outflow_(m, o->open, s->area, s->mass, s->energy, V, &s->mass_flow_vent,
                       &s->mass_flow_leak);
}

/* run CVODE from s->time to t_end; the SUNDIALS objects are created by the caller */
static mcs_status run(const fe_gasbag_model *m, fe_gasbag_state *s, double t_end, gb_ode *o,
                      void *cv, N_Vector y, mcs_error *err)
{
    double *Y = N_VGetArrayPointer(y), t = s->time;
    while (t < t_end) {
        double ts = next_stop(m, o->tf, t, t_end);
        if (CVodeSetStopTime(cv, ts) != CV_SUCCESS)
            return MCS_ERR(err, MCS_ERR_NUMERIC, "%s: CVodeSetStopTime failed", m->name);
        int flag = CVode(cv, ts, y, &t, CV_NORMAL);
        if (flag == CV_ROOT_RETURN) {
            int rf[FE_GASBAG_VENT_MAX] = {0};
            CVodeGetRootInfo(cv, rf);
            for (int i = 0; i < m->nvent; i++)
                if (rf[i]) o->open |= 1u << i;
        } else if (flag < 0 || o->vol_failed) {
            return MCS_ERR(err, MCS_ERR_NUMERIC, "%s: CVODE failed at t = %.9g s (flag %d%s)",
                           m->name, t, flag, o->vol_failed ? ", volume function" : "");
        }
        /* restart after a kink (root or breakpoint) */
        if (t < t_end && CVodeReInit(cv, t, y) != CV_SUCCESS)
            return MCS_ERR(err, MCS_ERR_NUMERIC, "%s: CVodeReInit failed", m->name);
    }
    commit(m, s, o, Y, t_end);
    return MCS_OK;
}

mcs_status fe_gasbag_integrate_cvode(const fe_gasbag_model *m, fe_gasbag_state *s, double t_end,
                                     fe_gasbag_volume_fn vol, void *user, double rtol,
                                     mcs_error *err)
{
    if (!(t_end >= s->time) || !(rtol > 0.0) || !vol)
        return MCS_ERR(err, MCS_ERR_USAGE, "%s: integrate to %g s from %g s, rtol %g", m->name,
                       t_end, s->time, rtol);
    if (t_end == s->time) return MCS_OK;
    gb_ode o = {m, vol, user, s->area, s->vent_open, s->fire_time, 0};
    SUNContext ctx = NULL;
    N_Vector y = NULL, atol = NULL;
    SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL;
    void *cv = NULL;
    mcs_status st = MCS_OK;
    if (SUNContext_Create(NULL, &ctx) != 0)
        return MCS_ERR(err, MCS_ERR_NOMEM, "%s: SUNContext_Create failed", m->name);
    y = N_VNew_Serial(NY, ctx);
    atol = N_VNew_Serial(NY, ctx);
    cv = CVodeCreate(CV_BDF, ctx);
    if (!y || !atol || !cv) {
        st = MCS_ERR(err, MCS_ERR_NOMEM, "%s: CVODE setup", m->name);
        goto done;
    }
    double *Y = N_VGetArrayPointer(y), *AT = N_VGetArrayPointer(atol);
    const double init[NY] = {s->mass,      s->energy,      s->mass_in,
                             s->energy_in, s->mass_vent,   s->energy_vent,
                             s->mass_leak, s->energy_leak, s->work};
    /* absolute tolerances on the scale of each component */
    double mscale = s->mass, escale = s->energy;
    for (int i = 0; i < NY; i++) {
        Y[i] = init[i];
        AT[i] = rtol * 1e-3 * ((i % 2 == 0 && i != Y_W) ? mscale : escale);
    }
    A = SUNDenseMatrix(NY, NY, ctx);
    LS = A ? SUNLinSol_Dense(y, A, ctx) : NULL;
    if (!A || !LS || CVodeInit(cv, rhs, s->time, y) != CV_SUCCESS ||
        CVodeSVtolerances(cv, rtol, atol) != CV_SUCCESS || CVodeSetUserData(cv, &o) != CV_SUCCESS ||
        CVodeSetLinearSolver(cv, LS, A) != CV_SUCCESS ||
        CVodeSetErrHandlerFn(cv, err_handler, NULL) != CV_SUCCESS ||
        CVodeSetMaxNumSteps(cv, 1000000) != CV_SUCCESS ||
        (m->nvent > 0 && CVodeRootInit(cv, m->nvent, roots) != CV_SUCCESS)) {
        st = MCS_ERR(err, MCS_ERR_NUMERIC, "%s: CVODE setup failed", m->name);
        goto done;
    }
    st = run(m, s, t_end, &o, cv, y, err);
done:
    CVodeFree(&cv);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (y) N_VDestroy(y);
    if (atol) N_VDestroy(atol);
    SUNContext_Free(&ctx);
    return st;
}

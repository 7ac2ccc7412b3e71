/* mb_run.c: a whole stage-1 run: state, time loop with progress, results file. The results
 * file is written to a temporary during the run and committed (renamed) only after the loop
 * succeeded, so a failed run leaves no file (and an older file of that name untouched). */
#include "core/mcs_interrupt.h"
#include "core/mcs_progress.h"
#include "stage1_mb/mb_couple_out.h"
#include "stage1_mb/mb_model.h"

#include <stdio.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* the results file of a finished run: /stage1 from the state's records, then commit; the
 * injury criteria of the dummy channels after it */
static mcs_status write_results(const mb_model *m, const mb_state *s, const mb_run_opts *o,
                                int interrupted, mcs_results **r, mcs_error *err)
{
    mcs_status st = mb_output_write(m, s, *r, err);
    if (!st && o->write_more) st = o->write_more(o->write_ctx, m, s, *r, err);
    /* an interrupted run's file: complete up to s->t, marked (core/mcs_interrupt.h) */
    if (!st && interrupted)
        st = mcs_results_set_attr_str(*r, "/meta", "status", "interrupted", err);
    if (!st) st = mcs_results_commit(r, err);
    mcs_results_abort(r);
    if (!st) mcs_failure_record_remove(o->out_path); /* an earlier failure's, now stale */
    /* no injury criteria over the part of a run an interrupt left */
    if (st || m->nsensor == 0 || interrupted) return st;
    /* injury criteria of the dummy channels; a failure there leaves the motion results */
    mcs_error e2 = {0};
    int n = 0;
    if (mb_injury_write(o->out_path, mb_out_stage(m), &n, &e2))
        mcs_log(MCS_LOG_WARN, "stage %d: injury criteria not written: %s", mb_out_stage(m), e2.msg);
    return MCS_OK;
}

/* OUT.h5.failure.txt of a numerical failure: time, step, the body named, the energies */
static void failure_record(const mb_model *m, const mb_state *s, const char *out,
                           const mcs_error *err)
{
    static const char *const names[] = {
#define MB_X_NAME(name, unit) #name,
        MB_ENERGY_FIELDS(MB_X_NAME)
#undef MB_X_NAME
    };
    const double e[] = {
#define MB_X_VAL(name, unit) s->e.name,
        MB_ENERGY_FIELDS(MB_X_VAL)
#undef MB_X_VAL
    };
    char where[256];
    mcs_failure_where(err->msg, where, sizeof where);
    if (mcs_failure_record_write(out, mb_out_stage(m), s->t, s->step, where, err->msg, names, e,
                                 (int)(sizeof e / sizeof e[0])))
        mcs_log(MCS_LOG_WARN, "stage %d: failure record beside %s not written", mb_out_stage(m),
                out);
}

const char *mb_timer_name(int k)
{
    static const char *const names[] = {
#define MB_X_NAME(n) #n,
        MB_STEP_STAGES(MB_X_NAME)
#undef MB_X_NAME
    };
    return k >= 0 && k < MB_NTIMER ? names[k] : "?";
}

mcs_status mb_run(const mb_model *m, const mb_run_opts *o, mb_run_summary *sum, mcs_error *err)
{
    double w0 = now();
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, err);
    if (st) return st;
    s->timing = 1;
    /* the results file is open (as a temporary) during the run: the coupled FE parts' series
     * are written as they are sampled (mb_couple_out.c), the bodies' records at the end */
    mcs_results *r = NULL;
    mb_couple_out *co = NULL;
    if (o && o->out_path) {
        st = o->append ? mcs_results_append(&r, o->out_path, err)
                       : mcs_results_create(&r, o->out_path, o->scenario_text, err);
        if (!st) st = mb_couple_out_open(m, r, &co, err);
        if (!st) st = mb_couple_out_sample(m, s, co, err); /* t = 0 */
    }
    mcs_progress p;
    mcs_progress_opts po = mcs_progress_opts_default();
    po.quiet = o && o->quiet;
    char label[16];
    snprintf(label, sizeof label, "stage %d", mb_out_stage(m));
    po.label = label;
    mcs_progress_start(&p, &po, m->t_end);
    int interrupted = 0;
    while (!st && s->step < m->nsteps) {
        /* SIGINT / SIGTERM: stop between steps (core/mcs_interrupt.h). Issue 18 item 3's
         * restart dump of the state at s->t belongs here, before the results are written. */
        if (mcs_interrupt_pending()) {
            interrupted = 1;
            break;
        }
        st = mb_step(m, s, err);
        if (!st) st = mb_couple_out_sample(m, s, co, err);
        mcs_progress_update(&p, s->t);
    }
    mcs_progress_finish(&p, s->t);
    if (!st && r) st = write_results(m, s, o, interrupted, &r, err);
    mcs_results_abort(&r);
    if (st == MCS_ERR_NUMERIC && o && o->out_path) failure_record(m, s, o->out_path, err);
    if (!st && interrupted) {
        const char *out = o && o->out_path ? o->out_path : NULL;
        st = MCS_ERR(err, MCS_INTERRUPTED, "stage %d: interrupted at t = %.9g s (step %ld)%s%s",
                     mb_out_stage(m), s->t, s->step, out ? "; results up to then in " : "",
                     out ? out : "");
    }
    mb_couple_out_free(&co);
    if (sum) {
        *sum = (mb_run_summary){.steps = s->step,
                                .bodies = m->nbody,
                                .wall_time_s = now() - w0,
                                .energy_drift = mb_energy_drift(m, s),
                                .t_end = s->t};
        for (int k = 0; k < MB_NTIMER; k++)
            sum->timer[k] = s->timer[k];
    }
    mb_state_destroy(&s);
    return st;
}

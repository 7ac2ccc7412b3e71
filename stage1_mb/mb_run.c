/* mb_run.c: a whole stage-1 run: state, time loop with progress, results file. The results
 * file is written to a temporary during the run and committed (renamed) only after the loop
 * succeeded, so a failed run leaves no file (and an older file of that name untouched). */
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
                                mcs_results **r, mcs_error *err)
{
    mcs_status st = mb_output_write(m, s, *r, err);
    if (!st && o->write_more) st = o->write_more(o->write_ctx, m, s, *r, err);
    if (!st) st = mcs_results_commit(r, err);
    mcs_results_abort(r);
    if (st || m->nsensor == 0) return st;
    /* injury criteria of the dummy channels; a failure there leaves the motion results */
    mcs_error e2 = {0};
    int n = 0;
    if (mb_injury_write(o->out_path, mb_out_stage(m), &n, &e2))
        mcs_log(MCS_LOG_WARN, "stage %d: injury criteria not written: %s", mb_out_stage(m), e2.msg);
    return MCS_OK;
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
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, err);
        if (!st) st = mb_couple_out_sample(m, s, co, err);
        mcs_progress_update(&p, s->t);
    }
    mcs_progress_finish(&p, s->t);
    if (!st && r) st = write_results(m, s, o, &r, err);
    mcs_results_abort(&r);
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

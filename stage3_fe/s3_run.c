/* s3_run.c: the stage-3 time loop and its /stage3 output (see s3_run.h). Every buffer is
 * allocated before the loop; the loop calls fe_step and appends rows to results series at
 * the output rate. */
#include "stage3_fe/s3_run.h"
#include "fe/fe_out.h"

#include "core/mcs_interrupt.h"
#include "core/mcs_progress.h"
#include "core/mcs_results.h"
#include "fe/fe_contact.h"
#include "stage3_fe/s3_carcase.h"
#include "stage3_fe/s3_wallcase.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct {
    mcs_results_series *time, *energy[FE_NENERGY], *wall_f[FE_WALL_MAX], *wall_d[FE_WALL_MAX];
    mcs_results_series *wall_m[FE_WALL_MAX]; /* penalty walls: mean force over the interval */
    double imp[FE_WALL_MAX], imp_t;          /* their impulses and the time since the last row */
    mcs_results_series *eroded; /* elements deleted so far (erosion only), NULL without */
    fe_out fe; /* fields, contacts, restraints, slip rings, parts (fe/fe_out.h) */
    s3_wallcase *wc; /* a motorcycle's fork angle, wall force by part, phases; NULL none */
    s3_carcase *cc;  /* a motorcycle into a sedan: pitch, velocities, door intrusion; NULL none */
    double hg_max; /* largest hourglass / internal energy once internal is 1 % of its end [-] */
    double *eint;  /* (rows) internal and hourglass energy of each row, for hg_max [J] */
    size_t nrow, caprow;
} s3_out;

static mcs_status open_series(mcs_results *r, const fe_model *m, s3_out *o, mcs_error *err)
{
    char path[256];
    mcs_status st = mcs_results_series_create(r, "/stage3/time", 1, NULL, "s", 0, &o->time, err);
    for (int k = 0; k < FE_NENERGY && !st; k++) {
        snprintf(path, sizeof path, "/stage3/energy/%s", fe_energy_name[k]);
        st = mcs_results_series_create(r, path, 1, NULL, "J", 0, &o->energy[k], err);
    }
    for (int w = 0; w < m->nwall && !st; w++) {
        snprintf(path, sizeof path, "/stage3/rigidwall/%s/force", m->wall[w].name);
        st = mcs_results_series_create(r, path, 1, NULL, "N", 0, &o->wall_f[w], err);
        snprintf(path, sizeof path, "/stage3/rigidwall/%s/displacement", m->wall[w].name);
        if (!st) st = mcs_results_series_create(r, path, 1, NULL, "m", 0, &o->wall_d[w], err);
        snprintf(path, sizeof path, "/stage3/rigidwall/%s/force_mean", m->wall[w].name);
        if (!st && m->wall[w].method == FE_WALL_PENALTY)
            st = mcs_results_series_create(r, path, 1, NULL, "N", 0, &o->wall_m[w], err);
    }
    if (!st && m->nerode > 0)
        st = mcs_results_series_create(r, "/stage3/erosion/count", 1, NULL, "-", 0, &o->eroded,
                                       err);
    if (!st) st = fe_out_open(r, 3, m, &o->fe, err);
    if (!st) st = s3_wallcase_open(r, m, &o->wc, err);
    if (!st) st = s3_carcase_open(r, m, &o->cc, err);
    return st;
}

static mcs_status sample_energy(const fe_model *m, const fe_state *s, s3_out *o, mcs_error *err)
{
    mcs_status st = mcs_results_series_append(o->time, &s->energy_time, err);
    for (int k = 0; k < FE_NENERGY && !st; k++)
        st = mcs_results_series_append(o->energy[k], &s->energy[k], err);
    for (int w = 0; w < m->nwall && !st; w++) {
        st = mcs_results_series_append(o->wall_f[w], &s->wall_normal[w], err);
        if (!st) st = mcs_results_series_append(o->wall_d[w], &s->wall_disp[w], err);
        const double fm = o->imp_t > 0 ? o->imp[w] / o->imp_t : s->wall_normal[w];
        if (!st && o->wall_m[w]) st = mcs_results_series_append(o->wall_m[w], &fm, err);
        o->imp[w] = 0;
    }
    o->imp_t = 0;
    if (!st && o->eroded) {
        double n = s->neroded;
        st = mcs_results_series_append(o->eroded, &n, err);
    }
    if (!st) st = fe_out_sample(m, s, &o->fe, err);
    if (!st) st = s3_wallcase_sample(m, s, o->wc, err);
    if (!st) st = s3_carcase_sample(m, s, o->cc, err);
    if (o->nrow < o->caprow) { /* beyond the rows planned: not in hg_max */
        o->eint[2 * o->nrow] = s->energy[FE_E_internal];
        o->eint[2 * o->nrow++ + 1] = s->energy[FE_E_hourglass];
    }
    return st;
}

/* the largest hourglass / internal energy ratio over the rows whose internal energy is at
 * least 1 % of the last row's (LS-DYNA practice: hourglass below 10 % of internal) */
static double hourglass_max(const s3_out *o)
{
    if (o->nrow == 0) return 0;
    const double e_end = o->eint[2 * (o->nrow - 1)];
    double r = 0;
    for (size_t i = 0; i < o->nrow; i++)
        if (o->eint[2 * i] > 0.01 * e_end && o->eint[2 * i] > 0)
            r = fmax(r, o->eint[2 * i + 1] / o->eint[2 * i]);
    return r;
}

static mcs_status sample_field(const fe_model *m, const fe_state *s, s3_out *o, mcs_error *err)
{
    return fe_out_field_sample(m, s, s->time, &o->fe.field, err);
}

/* after a step: the walls' impulses F(t_n) dt over the step just taken (for force_mean) */
static void accumulate(const fe_model *m, const fe_state *s, s3_out *o)
{
    for (int w = 0; w < m->nwall; w++) o->imp[w] += s->wall_normal[w] * s->dt_prev;
    o->imp_t += s->dt_prev;
    s3_wallcase_step(m, s, o->wc);
}

/* the time loop: fe_step until end_time, sampling energies (at t_n) and fields (at t_n+1) */
static mcs_status loop(const fe_problem *p, const s3_run_opts *ro, fe_state *s, s3_out *o,
                       int *interrupted, mcs_error *err)
{
    const fe_model *m = p->model;
    const double every = 1.0 / p->output_rate;
    const double fevery = 1.0 / fe_scn_field_rate(p); /* fields: their own rate */
    double next_e = 0, next_f = fevery;
    mcs_progress prog;
    mcs_progress_opts po = mcs_progress_opts_default();
    po.quiet = ro->quiet;
    po.label = "stage 3";
    mcs_progress_start(&prog, &po, p->end_time);
    mcs_status st = sample_field(m, s, o, err); /* t = 0: zero displacement */
    while (!st && s->time < p->end_time) {
        /* SIGINT / SIGTERM: stop between steps (core/mcs_interrupt.h). Issue 18 item 3's
         * restart dump of the state at s->time belongs here, before the results are written. */
        if (mcs_interrupt_pending()) {
            *interrupted = 1;
            break;
        }
        st = fe_step(m, s);
        if (st) {
            MCS_ERR(err, st, "stage 3: %s", s->err.msg);
            break;
        }
        accumulate(m, s, o);
        const double eps = 1e-9 * s->dt;
        if (s->energy_time >= next_e - eps) {
            st = sample_energy(m, s, o, err);
            next_e += every * fmax(1.0, ceil((s->energy_time - next_e) / every + 1e-9));
        }
        if (!st && s->time >= next_f - eps) {
            st = sample_field(m, s, o, err);
            next_f += fevery * fmax(1.0, ceil((s->time - next_f) / fevery + 1e-9));
        }
        mcs_progress_update(&prog, s->time);
    }
    mcs_progress_finish(&prog, s->time);
    return st;
}

/* OUT.h5.failure.txt of a numerical failure: time, step, the element or node named, the
 * energies */
static void failure_record(const fe_state *s, const char *out, const mcs_error *err)
{
    char where[256];
    mcs_failure_where(err->msg, where, sizeof where);
    if (mcs_failure_record_write(out, 3, s->time, (long)s->nstep, where, err->msg,
                                 fe_energy_name, s->energy, FE_NENERGY))
        mcs_log(MCS_LOG_WARN, "stage 3: failure record beside %s not written", out);
}

mcs_status s3_run(const fe_problem *p, const s3_run_opts *ro, s3_summary *sum, mcs_error *err)
{
    const fe_model *m = p->model;
    memset(sum, 0, sizeof *sum);
    if (!(p->output_rate > 0) || !(p->end_time > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "stage 3: end_time and output_rate must be > 0");
    double wall0 = now_s();
    fe_state *s = NULL;
    mcs_results *r = NULL;
    s3_out o = {0};
    mcs_status st = fe_state_create(m, &s, err);
    o.caprow = (size_t)ceil(p->end_time * p->output_rate) + 2;
    o.eint = st ? NULL : malloc(2 * sizeof(double) * o.caprow);
    if (!st && !o.eint) st = MCS_ERR(err, MCS_ERR_NOMEM, "stage 3: out of memory");
    if (!st)
        st = ro->append ? mcs_results_append(&r, ro->out_path, err)
                        : mcs_results_create(&r, ro->out_path, ro->scenario_text, err);
    if (!st) st = fe_out_meshes(r, 3, m, err);
    if (!st) st = open_series(r, m, &o, err);
    int interrupted = 0;
    if (!st) st = loop(p, ro, s, &o, &interrupted, err);
    if (!st) {
        sum->steps = s->nstep;
        sum->elements = m->nelem;
        sum->nodes = m->nnode;
        sum->t_end = s->time;
        sum->dt_initial = m->dt_initial;
        sum->energy_drift =
            fabs(s->energy[FE_E_total] - s->energy0) / fmax(s->energy_ref, DBL_MIN);
        memcpy(sum->timer, s->timer, sizeof sum->timer);
        st = mcs_results_set_attr_int(r, "/stage3", "steps", (int)fmin(s->nstep, 2147483647.0), err);
        if (!st) st = mcs_results_set_attr_int(r, "/stage3", "elements", m->nelem, err);
        if (!st) st = mcs_results_set_attr_int(r, "/stage3", "nodes", m->nnode, err);
        if (!st) st = mcs_results_set_attr_double(r, "/stage3", "energy_drift", sum->energy_drift, err);
        if (!st) st = mcs_results_set_attr_double(r, "/stage3", "output_rate", p->output_rate, err);
        if (!st && m->nerode > 0) { /* element erosion: how many, first and last time */
            st = mcs_results_set_attr_int(r, "/stage3/erosion", "eroded", s->neroded, err);
            if (!st)
                st = mcs_results_set_attr_double(r, "/stage3/erosion", "first_time",
                                                 s->neroded ? s->erode_first : NAN, err);
            if (!st)
                st = mcs_results_set_attr_double(r, "/stage3/erosion", "last_time",
                                                 s->neroded ? s->erode_last : NAN, err);
        }
        sum->mass_added = m->mass_added + s->mass_added_run; /* at t = 0 and during the run */
        sum->mass_added_fraction = sum->mass_added / fmax(m->mass_total - m->mass_added, DBL_MIN);
        if (!st) st = mcs_results_set_attr_double(r, "/stage3", "mass_added", sum->mass_added, err);
        if (!st)
            st = mcs_results_set_attr_double(r, "/stage3", "mass_added_fraction",
                                             sum->mass_added_fraction, err);
        const double e_int = s->energy[FE_E_internal], e_hg = s->energy[FE_E_hourglass];
        sum->hourglass_fraction = e_int > 0 ? e_hg / e_int : 0;
        sum->hourglass_fraction_max = hourglass_max(&o);
        if (!st)
            st = mcs_results_set_attr_double(r, "/stage3", "hourglass_fraction",
                                             sum->hourglass_fraction, err);
        if (!st)
            st = mcs_results_set_attr_double(r, "/stage3", "hourglass_fraction_max",
                                             sum->hourglass_fraction_max, err);
        if (!st) st = s3_wallcase_finish(r, &o.wc, err);
        if (!st) st = s3_carcase_finish(r, &o.cc, err);
        /* an interrupted run's file: complete up to s->time, marked (core/mcs_interrupt.h) */
        if (!st && interrupted)
            st = mcs_results_set_attr_str(r, "/meta", "status", "interrupted", err);
        if (!st) st = mcs_results_commit(&r, err);
        if (!st) mcs_failure_record_remove(ro->out_path); /* an earlier failure's, now stale */
    }
    mcs_results_abort(&r);
    if (st == MCS_ERR_NUMERIC && s && ro->out_path) failure_record(s, ro->out_path, err);
    if (!st && interrupted)
        st = MCS_ERR(err, MCS_INTERRUPTED,
                     "stage 3: interrupted at t = %.9g s (step %ld); results up to then in %s",
                     s->time, (long)s->nstep, ro->out_path);
    s3_wallcase_free(&o.wc);
    s3_carcase_free(&o.cc);
    free(o.eint);
    fe_out_free(&o.fe);
    fe_state_destroy(&s);
    sum->wall_time_s = now_s() - wall0;
    return st;
}

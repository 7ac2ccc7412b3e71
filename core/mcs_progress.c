#include "core/mcs_progress.h"

#include <math.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static double clock_monotonic(void *user)
{
    (void)user;
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

mcs_progress_opts mcs_progress_opts_default(void)
{
    return (mcs_progress_opts){.out = NULL,
                               .quiet = 0,
                               .force = 0,
                               .min_interval = 0.2,
                               .check_every = 64,
                               .clock = NULL,
                               .clock_user = NULL,
                               .label = NULL};
}

/* "850 ms", "12.3 s", "4 min 05 s", "2 h 03 min" */
static void fmt_wall(char *b, size_t n, double s)
{
    if (!(s >= 0) || !isfinite(s))
        snprintf(b, n, "--");
    else if (s < 1)
        snprintf(b, n, "%.0f ms", s * 1e3);
    else if (s < 60)
        snprintf(b, n, "%.1f s", s);
    else if (s < 3600)
        snprintf(b, n, "%d min %02d s", (int)(s / 60), (int)fmod(s, 60));
    else
        snprintf(b, n, "%d h %02d min", (int)(s / 3600), (int)fmod(s / 60, 60));
}

int mcs_progress_format(char *buf, size_t n, const char *label, double frac, double t_sim,
                        double t_end, double wall, double eta)
{
    char w[32], e[32];
    fmt_wall(w, sizeof w, wall);
    fmt_wall(e, sizeof e, eta);
    if (frac < 0) frac = 0;
    if (frac > 1) frac = 1;
    /* crash runs last tens to hundreds of milliseconds: simulated time in ms */
    return snprintf(buf, n, "%s%s%5.1f %%  t %.1f / %.1f ms  wall %s  ETA %s", label ? label : "",
                    label ? "  " : "", 100 * frac, t_sim * 1e3, t_end * 1e3, w, e);
}

void mcs_progress_start(mcs_progress *p, const mcs_progress_opts *o, double t_end)
{
    memset(p, 0, sizeof *p);
    p->o = o ? *o : mcs_progress_opts_default();
    if (!p->o.out) p->o.out = stderr;
    if (!p->o.clock) p->o.clock = clock_monotonic;
    if (p->o.check_every < 1) p->o.check_every = 1;
    p->t_end = t_end;
    p->active = !p->o.quiet && (p->o.force || isatty(fileno(p->o.out)));
    if (!p->active) return;
    p->wall0 = p->o.clock(p->o.clock_user);
    p->wall_last = p->wall0;
}

static void draw(mcs_progress *p, double t_sim, double now)
{
    double frac = p->t_end > 0 ? t_sim / p->t_end : 1.0, wall = now - p->wall0;
    double eta = frac > 0 ? wall * (1 - frac) / frac : -1;
    if (eta < 0 && frac >= 1) eta = 0;
    char line[256];
    int len = mcs_progress_format(line, sizeof line, p->o.label, frac, t_sim, p->t_end, wall, eta);
    if (len >= (int)sizeof line) len = (int)sizeof line - 1;
    /* pad with blanks over the rest of a longer previous line */
    fprintf(p->o.out, "\r%s%*s", line, p->width > len ? p->width - len : 0, "");
    fflush(p->o.out);
    p->width = len;
    p->wall_last = now;
    p->redraws++;
}

void mcs_progress_update(mcs_progress *p, double t_sim)
{
    if (!p->active || ++p->calls < p->o.check_every) return;
    p->calls = 0;
    double now = p->o.clock(p->o.clock_user);
    if (now - p->wall_last >= p->o.min_interval) draw(p, t_sim, now);
}

void mcs_progress_finish(mcs_progress *p, double t_sim)
{
    if (!p->active) return;
    draw(p, t_sim, p->o.clock(p->o.clock_user));
    fputc('\n', p->o.out);
    fflush(p->o.out);
    p->active = 0;
}

/* mcs_interrupt.c: the stop flag, the signal handlers, the temporaries a second signal removes,
 * and the failure record (core/mcs_interrupt.h) */
#include "core/mcs_interrupt.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static volatile sig_atomic_t pending; /* the first signal's number, -1 for a request, or 0 */

/* the temporaries: a slot's path is filled before `used` is set, so the handler reads only
 * complete paths */
static char tmp_path[MCS_INTERRUPT_MAXTMP][4096];
static volatile sig_atomic_t tmp_used[MCS_INTERRUPT_MAXTMP];

static void on_signal(int sig)
{
    if (!pending) {
        pending = sig;
        return;
    }
    /* the second signal: no partial file, stop now (only async-signal-safe calls) */
    for (int i = 0; i < MCS_INTERRUPT_MAXTMP; i++)
        if (tmp_used[i]) unlink(tmp_path[i]);
    static const char msg[] = "\nmcrash: second signal: stopped at once, no results file\n";
    ssize_t w = write(STDERR_FILENO, msg, sizeof msg - 1);
    (void)w;
    _exit(130);
}

void mcs_interrupt_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

int mcs_interrupt_pending(void) { return pending; }
void mcs_interrupt_request(void) { pending = -1; }
void mcs_interrupt_clear(void) { pending = 0; }

int mcs_interrupt_track(const char *path)
{
    if (!path || strlen(path) >= sizeof tmp_path[0]) return -1;
    for (int i = 0; i < MCS_INTERRUPT_MAXTMP; i++) {
        if (tmp_used[i]) continue;
        memcpy(tmp_path[i], path, strlen(path) + 1);
        tmp_used[i] = 1;
        return i;
    }
    return -1;
}

void mcs_interrupt_untrack(int slot)
{
    if (slot >= 0 && slot < MCS_INTERRUPT_MAXTMP) tmp_used[slot] = 0;
}

int mcs_failure_record_path(const char *out_path, char *buf, size_t n)
{
    int k = snprintf(buf, n, "%s.failure.txt", out_path ? out_path : "");
    return k < 0 || (size_t)k >= n ? -1 : 0;
}

void mcs_failure_record_remove(const char *out_path)
{
    char p[4200];
    if (out_path && mcs_failure_record_path(out_path, p, sizeof p) == 0) unlink(p);
}

int mcs_failure_record_write(const char *out_path, int stage, double time, long step,
                             const char *where, const char *message, const char *const *names,
                             const double *energies, int n)
{
    char p[4200], tmp[4300];
    if (!out_path || mcs_failure_record_path(out_path, p, sizeof p)) return -1;
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", p, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) return -1;
    fprintf(f, "mcrash failure record\nstage: %d\ntime_s: %.9g\nstep: %ld\nwhere: %s\n", stage,
            time, step, where && *where ? where : "-");
    /* one line: the message's line breaks as blanks */
    fputs("message: ", f);
    for (const char *c = message ? message : ""; *c; c++)
        fputc(*c == '\n' || *c == '\r' ? ' ' : *c, f);
    fputc('\n', f);
    for (int i = 0; i < n; i++)
        fprintf(f, "energy_%s_J: %.9g\n", names[i], energies[i]);
    int bad = ferror(f);
    if (fclose(f) != 0) bad = 1;
    if (bad || rename(tmp, p) != 0) {
        unlink(tmp);
        return -1;
    }
    return 0;
}

/* the word after the first `key` in msg (up to a blank, ':', ',', ')' or a quote) */
static int word_after(const char *msg, const char *key, char *w, size_t n)
{
    const char *k = strstr(msg, key);
    if (!k) return 0;
    k += strlen(key);
    size_t len = strcspn(k, " \t:,)'\"");
    if (len == 0 || len >= n) return 0;
    memcpy(w, k, len);
    w[len] = 0;
    return 1;
}

void mcs_failure_where(const char *msg, char *buf, size_t n)
{
    char part[128] = "", w[128];
    if (n) buf[0] = 0;
    if (!msg || !n) return;
    word_after(msg, "part '", part, sizeof part);
    static const char *const keys[] = {"element ", "node ", "body "};
    for (int i = 0; i < 3; i++)
        if (word_after(msg, keys[i], w, sizeof w)) {
            if (part[0] && i == 0)
                snprintf(buf, n, "part '%s' %s%s", part, keys[i], w);
            else
                snprintf(buf, n, "%s%s", keys[i], w);
            return;
        }
    if (part[0]) snprintf(buf, n, "part '%s'", part);
}

/* tr_pool.c: a fork pool (tr_pool.h). A child writes its mcs_error then its result into a pipe
 * and exits; the parent polls the pipes of the running children, reads as the data come (a
 * result larger than a pipe's buffer cannot block the child) and reaps each child by its pid
 * at end of file. */
#include "translators/tr_pool.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

int tr_pool_cpus(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n >= 1 ? (int)n : 1;
}

typedef struct {
    pid_t pid;     /* child, 0: slot free                         */
    int fd;        /* read end of its pipe                        */
    int k;         /* its case                                    */
    size_t got;    /* bytes received so far                       */
    char *buf;     /* mcs_error then the result (sizeof + nbytes) */
} slot;

static int write_all(int fd, const void *p, size_t n)
{
    const char *c = p;
    while (n > 0) {
        ssize_t w = write(fd, c, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return -1;
        c += w, n -= (size_t)w;
    }
    return 0;
}

/* in the child: run case k, send error and result, never return */
static void child(tr_pool_fn fn, void *ctx, int k, size_t nbytes, int fd)
{
    signal(SIGPIPE, SIG_IGN);
    mcs_error e = {0};
    void *out = calloc(1, nbytes ? nbytes : 1);
    if (!out)
        MCS_ERR(&e, MCS_ERR_NOMEM, "out of memory");
    else
        fn(ctx, k, out, &e);
    int bad = write_all(fd, &e, sizeof e) || (out && write_all(fd, out, nbytes));
    _exit(bad ? 3 : 0);
}

/* the slot's child has closed its pipe: reap it, check it sent everything */
static void finish(slot *s, size_t nbytes, void *out, mcs_status *st_k, mcs_error *err_k)
{
    close(s->fd);
    int ws = 0;
    while (waitpid(s->pid, &ws, 0) < 0 && errno == EINTR) {
    }
    mcs_error e = {0};
    if (s->got == sizeof e + nbytes && WIFEXITED(ws) && WEXITSTATUS(ws) == 0) {
        memcpy(&e, s->buf, sizeof e);
        memcpy((char *)out + (size_t)s->k * nbytes, s->buf + sizeof e, nbytes);
    } else if (WIFSIGNALED(ws)) {
        MCS_ERR(&e, MCS_ERR_NUMERIC, "case %d: its process died of signal %d", s->k,
                WTERMSIG(ws));
    } else {
        MCS_ERR(&e, MCS_ERR_IO, "case %d: its process ended (status %d) after %zu of %zu bytes",
                s->k, WIFEXITED(ws) ? WEXITSTATUS(ws) : -1, s->got, sizeof e + nbytes);
    }
    st_k[s->k] = e.status;
    if (e.status) err_k[s->k] = e;
    s->pid = 0;
}

/* start case k in slot s */
static mcs_status start(slot *s, tr_pool_fn fn, void *ctx, int k, size_t nbytes, mcs_error *err)
{
    int p[2];
    if (pipe(p) < 0) return MCS_ERR(err, MCS_ERR_IO, "pipe: %s", strerror(errno));
    pid_t pid = fork();
    if (pid < 0) {
        close(p[0]), close(p[1]);
        return MCS_ERR(err, MCS_ERR_IO, "fork: %s", strerror(errno));
    }
    if (pid == 0) {
        close(p[0]);
        child(fn, ctx, k, nbytes, p[1]);
    }
    close(p[1]);
    *s = (slot){.pid = pid, .fd = p[0], .k = k, .buf = s->buf};
    return MCS_OK;
}

mcs_status tr_pool_run(tr_pool_fn fn, void *ctx, int n, size_t nbytes, void *out, int jobs,
                       mcs_error *err)
{
    if (n <= 0) return MCS_OK;
    if (jobs < 1) jobs = tr_pool_cpus();
    if (jobs > n) jobs = n;
    if (jobs > 64) jobs = 64;
    size_t sz = sizeof(mcs_error) + nbytes;
    slot *sl = calloc((size_t)jobs, sizeof *sl);
    struct pollfd *pf = calloc((size_t)jobs, sizeof *pf);
    mcs_status *st_k = calloc((size_t)n, sizeof *st_k);
    mcs_error *err_k = calloc((size_t)n, sizeof *err_k);
    int ok = sl && pf && st_k && err_k;
    for (int i = 0; ok && i < jobs; i++)
        ok = (sl[i].buf = malloc(sz)) != NULL;
    mcs_status st = ok ? MCS_OK : MCS_ERR(err, MCS_ERR_NOMEM, "out of memory");
    fflush(NULL); /* nothing buffered is written twice by a child */
    int next = 0, running = 0, failed = 0;
    while (!st && (running > 0 || (next < n && !failed))) {
        for (int i = 0; i < jobs && next < n && !failed && !st; i++)
            if (!sl[i].pid) {
                st = start(&sl[i], fn, ctx, next++, nbytes, err);
                running += !st;
            }
        int np = 0, map[64];
        for (int i = 0; i < jobs && np < 64; i++)
            if (sl[i].pid) {
                pf[np] = (struct pollfd){.fd = sl[i].fd, .events = POLLIN};
                map[np++] = i;
            }
        if (np == 0) break;
        if (poll(pf, (nfds_t)np, -1) < 0) {
            if (errno == EINTR) continue;
            st = MCS_ERR(err, MCS_ERR_IO, "poll: %s", strerror(errno));
            break;
        }
        for (int j = 0; j < np; j++) {
            if (!(pf[j].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            slot *s = &sl[map[j]];
            char tmp[1 << 16];
            ssize_t r = read(s->fd, tmp, sizeof tmp);
            if (r < 0 && errno == EINTR) continue;
            if (r > 0) {
                if (s->got + (size_t)r > sz) /* more than a result: marked bad */
                    s->got = sz + 1;
                else
                    memcpy(s->buf + s->got, tmp, (size_t)r), s->got += (size_t)r;
                continue;
            }
            finish(s, nbytes, out, st_k, err_k);
            running--;
            failed |= st_k[s->k] != MCS_OK;
        }
    }
    /* an error of the pool itself: stop the children still running */
    for (int i = 0; sl && i < jobs; i++)
        if (sl[i].pid) {
            kill(sl[i].pid, SIGTERM);
            close(sl[i].fd);
            while (waitpid(sl[i].pid, NULL, 0) < 0 && errno == EINTR) {
            }
        }
    for (int k = 0; !st && st_k && k < n; k++)
        if (st_k[k]) {
            *err = err_k[k];
            st = st_k[k];
        }
    for (int i = 0; sl && i < jobs; i++)
        free(sl[i].buf);
    free(sl), free(pf), free(st_k), free(err_k);
    return st;
}

#include "core/mcs_error.h"

#include <stdio.h>
#include <string.h>

static const char *const status_text[] = {
#define MCS_X_TEXT(name, text) text,
    MCS_STATUS_LIST(MCS_X_TEXT)
#undef MCS_X_TEXT
};

const char *mcs_status_str(mcs_status st)
{
    if ((int)st < 0 || st >= MCS_NSTATUS) return "unknown status";
    return status_text[st];
}

int mcs_status_exit_code(mcs_status st)
{
    if (st == MCS_OK) return 0;
    if (st == MCS_ERR_NUMERIC || st == MCS_ERR_ARENA) return 1;
    if (st == MCS_INTERRUPTED) return 130;
    return 2;
}

mcs_status mcs_error_set_(mcs_error *e, mcs_status st, const char *file, int line,
                          const char *func, const char *fmt, ...)
{
    if (!e || e->status != MCS_OK) return st;
    e->status = st;
    e->where = file;
    e->where_line = line;
    e->func = func;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(e->msg, sizeof e->msg, fmt, ap);
    va_end(ap);
    return st;
}

void mcs_error_clear(mcs_error *e)
{
    memset(e, 0, sizeof *e);
}

/* the log handler is process-wide by design (one replaceable handler, STYLE.md §5) */
static void log_stderr(mcs_log_level lvl, const char *msg, void *user)
{
    (void)user;
    static const char *const tag[] = {"debug", "info", "warning", "error"};
    fprintf(stderr, "mcrash: %s: %s\n", tag[lvl], msg);
}

static mcs_log_fn log_fn = log_stderr;
static void *log_user;
static mcs_log_level log_min = MCS_LOG_INFO;

void mcs_log_set_handler(mcs_log_fn fn, void *user)
{
    log_fn = fn ? fn : log_stderr;
    log_user = user;
}

void mcs_log_set_level(mcs_log_level min_level)
{
    log_min = min_level;
}

void mcs_vlog(mcs_log_level lvl, const char *fmt, va_list ap)
{
    if (lvl < log_min) return;
    char buf[2048];
    vsnprintf(buf, sizeof buf, fmt, ap);
    log_fn(lvl, buf, log_user);
}

void mcs_log(mcs_log_level lvl, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    mcs_vlog(lvl, fmt, ap);
    va_end(ap);
}

/* mcs_error: status codes, error values with a message, and the one log handler. */
#ifndef MCS_ERROR_H
#define MCS_ERROR_H

#include <stdarg.h>

/* status of any library call; MCS_OK is 0 */
#define MCS_STATUS_LIST(X)                                                                         \
    X(MCS_OK, "ok")                                                                                \
    X(MCS_ERR_USAGE, "bad usage")                                                                  \
    X(MCS_ERR_IO, "input/output error")                                                            \
    X(MCS_ERR_YAML, "YAML syntax error")                                                           \
    X(MCS_ERR_KEY, "unknown or missing key")                                                       \
    X(MCS_ERR_TYPE, "wrong type")                                                                  \
    X(MCS_ERR_UNIT, "bad unit")                                                                    \
    X(MCS_ERR_RANGE, "value out of range")                                                         \
    X(MCS_ERR_INCLUDE, "include error")                                                            \
    X(MCS_ERR_FORMAT, "bad file format")                                                           \
    X(MCS_ERR_HDF5, "HDF5 error")                                                                  \
    X(MCS_ERR_NOMEM, "out of memory")                                                              \
    X(MCS_ERR_ARENA, "scratch arena exhausted")                                                    \
    X(MCS_ERR_NUMERIC, "numerical failure")                                                        \
    X(MCS_ERR_UNSUPPORTED, "not built yet")                                                        \
    X(MCS_INTERRUPTED, "interrupted") /* by a signal; results written up to then (exit 130) */

typedef enum {
#define MCS_X_ENUM(name, text) name,
    MCS_STATUS_LIST(MCS_X_ENUM)
#undef MCS_X_ENUM
        MCS_NSTATUS
} mcs_status;

/* an error value: status, a message for the user, and where in the code it was raised */
typedef struct {
    mcs_status status;   /* MCS_OK when no error                  */
    char msg[1024];      /* "FILE:LINE:COL: error: KEY: what" etc. */
    const char *where;   /* source file of the code that raised it */
    int where_line;      /* source line                            */
    const char *func;    /* function                               */
} mcs_error;

const char *mcs_status_str(mcs_status st);

/* exit status of the command for a status: 0 ok, 1 numerical failure, 2 bad input/usage,
 * 130 interrupted (core/mcs_interrupt.h) */
int mcs_status_exit_code(mcs_status st);

/* record an error (first one wins if e already holds one); returns st */
mcs_status mcs_error_set_(mcs_error *e, mcs_status st, const char *file, int line,
                          const char *func, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
#define MCS_ERR(e, st, ...) mcs_error_set_((e), (st), __FILE__, __LINE__, __func__, __VA_ARGS__)

void mcs_error_clear(mcs_error *e);

/* log levels and the one replaceable handler (default: stderr, debug hidden) */
typedef enum { MCS_LOG_DEBUG, MCS_LOG_INFO, MCS_LOG_WARN, MCS_LOG_ERROR } mcs_log_level;
typedef void (*mcs_log_fn)(mcs_log_level lvl, const char *msg, void *user);

void mcs_log_set_handler(mcs_log_fn fn, void *user);
void mcs_log_set_level(mcs_log_level min_level);
void mcs_log(mcs_log_level lvl, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void mcs_vlog(mcs_log_level lvl, const char *fmt, va_list ap);

#endif

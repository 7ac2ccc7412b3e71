/* fe_kw_util: small helpers the keyword handlers (fe_kw_cards*.c) and the deck builders
 * (fe_kw_build*.c) share: card counts, blank cards, warnings and errors at a card or a deck
 * place. */
#include "fe/fe_kw_impl.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

mcs_status kw_need(kw_ctx *c, const kw_card *cd, int n, int i, int k)
{
    if (i + k <= n) return MCS_OK;
    int line = n > 0 ? cd[n - 1].line : c->kwloc.line;
    return kw_fail(c, c->kwloc.file, line, 0, MCS_ERR_FORMAT,
                   "%d more card%s expected after line %d (the keyword has %d card%s per entry)",
                   i + k - n, i + k - n == 1 ? "" : "s", line, k, k == 1 ? "" : "s");
}

int kw_blank_card(const kw_card *cd)
{
    for (int i = 0; i < cd->len; i++)
        if (cd->s[i] != ' ' && cd->s[i] != '\t') return 0;
    return 1;
}

void kw_warn(kw_ctx *c, const kw_card *cd, const char *fmt, ...)
{
    if (c->o->quiet) return;
    char what[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    mcs_log(MCS_LOG_WARN, "%s:%d: warning: *%s: %s", c->d->file[cd->file], cd->line, c->kw, what);
}

mcs_status kw_nomem(kw_ctx *c)
{
    return MCS_ERR(c->err, MCS_ERR_NOMEM, "keyword: out of memory");
}

mcs_status kw_at(const fe_kw_deck *dk, fe_kw_loc l, mcs_error *err, mcs_status st, const char *fmt,
                 ...)
{
    char what[800];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    const char *fn = l.file >= 0 && l.file < dk->nfile ? dk->file[l.file] : "(deck)";
    if (l.line > 0) return MCS_ERR(err, st, "%s:%d: error: %s", fn, l.line, what);
    return MCS_ERR(err, st, "%s: error: %s", fn, what);
}

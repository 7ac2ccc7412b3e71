/* mcs_scn_json.c: the resolved scenario as JSON (quantities are SI numbers) */
#include "core/mcs_scn_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        switch (*p) {
        case '"':
            fputs("\\\"", f);
            break;
        case '\\':
            fputs("\\\\", f);
            break;
        case '\n':
            fputs("\\n", f);
            break;
        case '\r':
            fputs("\\r", f);
            break;
        case '\t':
            fputs("\\t", f);
            break;
        default:
            if (*p < 0x20 || *p == 0x7f)
                fprintf(f, "\\u%04x", *p);
            else
                fputc(*p, f); /* UTF-8 passes through (JSON text is UTF-8) */
        }
    }
    fputc('"', f);
}

/* shortest decimal that reads back to the same double */
static void json_number(FILE *f, double v)
{
    char buf[40];
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, sizeof buf, "%.*g", prec, v);
        if (strtod(buf, NULL) == v) break;
    }
    fputs(buf, f);
}

static int is_leaf_seq(const mcs_node *n)
{
    for (int i = 0; i < n->n; i++)
        if (n->items[i]->kind == MCS_NODE_MAP)
            return 0;
        else if (n->items[i]->kind == MCS_NODE_SEQ && !is_leaf_seq(n->items[i]))
            return 0;
    return 1;
}

static void json_node(FILE *f, const mcs_node *n, int indent);

static void json_seq(FILE *f, const mcs_node *n, int indent)
{
    int inline_ = is_leaf_seq(n);
    fputc('[', f);
    for (int i = 0; i < n->n; i++) {
        if (i) fputs(inline_ ? ", " : ",", f);
        if (!inline_) fprintf(f, "\n%*s", indent + 2, "");
        json_node(f, n->items[i], indent + 2);
    }
    if (!inline_ && n->n) fprintf(f, "\n%*s", indent, "");
    fputc(']', f);
}

static void json_map(FILE *f, const mcs_node *n, int indent)
{
    fputc('{', f);
    for (int i = 0; i < n->n; i++) {
        fprintf(f, "%s\n%*s", i ? "," : "", indent + 2, "");
        json_string(f, n->keys[i]->text);
        fputs(": ", f);
        json_node(f, n->items[i], indent + 2);
    }
    if (n->n) fprintf(f, "\n%*s", indent, "");
    fputc('}', f);
}

static void json_node(FILE *f, const mcs_node *n, int indent)
{
    switch (n->kind) {
    case MCS_NODE_NULL:
        fputs("null", f);
        break;
    case MCS_NODE_BOOL:
        fputs(n->num != 0.0 ? "true" : "false", f);
        break;
    case MCS_NODE_NUM:
        if (isfinite(n->num))
            json_number(f, n->num);
        else
            fputs("null", f); /* never in a validated tree */
        break;
    case MCS_NODE_STR:
        json_string(f, n->text);
        break;
    case MCS_NODE_SEQ:
        json_seq(f, n, indent);
        break;
    case MCS_NODE_MAP:
        json_map(f, n, indent);
        break;
    }
}

mcs_status mcs_scenario_write_json(const mcs_scenario *scn, FILE *f)
{
    if (!scn || !scn->root) return MCS_ERR_USAGE;
    json_node(f, scn->root, 0);
    fputc('\n', f);
    return ferror(f) ? MCS_ERR_IO : MCS_OK;
}

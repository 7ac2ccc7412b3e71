/* cmd_check.c: `mcrash check [--json] SCENARIO.yaml...` — validate scenarios; with --json print
 * one resolved (includes merged, every quantity in SI); `--schema` prints the key reference.
 * A scenario with a simulation: block is also built into the model `mcrash run` would run
 * (stage 1, or stage 3 for an fe: block without bodies; both with a stage3: block), so what
 * run refuses at load, check refuses with the same message; nothing is simulated or written. A stage-1 model's surface
 * pairs that penetrate more than 1 mm at t = 0 are listed as warnings on stderr (contact,
 * surfaces, depth, the force its law gives there; stage1_mb/mb_initial.h): a model should
 * start without them. Warnings do not change the exit status. Every LS-DYNA keyword deck the
 * scenario names is read (a missing deck, an error in it or a part ID with no elements is an
 * error, exit 2); --json adds "keyword_decks": each deck's sizes and unknown keywords (each once,
 * with its count and first file:line). */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "core/mcs_scenario.h"
#include "fe/fe_keyword.h"
#include "fe/fe_scn_keyword.h"
#include "stage1_mb/mb_initial.h"
#include "stage1_mb/mb_model.h"
#include "stage3_fe/s3_scenario.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHECK_MIN_DEPTH 1e-3 /* initial penetrations listed above this [m] */

/* warn of every surface pair penetrating at t = 0 (the model as built, after seating and
 * impact: placement) */
static mcs_status warn_initial(const char *path, const mb_model *m, mcs_error *err)
{
    mb_initial_pen *p = NULL;
    int n = 0;
    mcs_status st = mb_initial_penetrations(m, CHECK_MIN_DEPTH, &p, &n, err);
    if (st) return st;
    for (int i = 0; i < n; i++) {
        const mb_pair *q = &m->pair[p[i].pair];
        fprintf(stderr,
                "%s: warning: initial penetration: contact %s, %s (%s) into %s (%s): %.1f mm, "
                "%.0f N from its characteristic\n",
                path, m->contact[q->contact].name, m->surf[q->sa].name,
                q->ba >= 0 ? m->body_name[q->ba] : "ground", m->surf[q->sb].name,
                q->bb >= 0 ? m->body_name[q->bb] : "ground", p[i].depth * 1e3, p[i].force);
    }
    free(p);
    return MCS_OK;
}

/* build (and free) the model `mcrash run` would run of a runnable scenario */
static mcs_status build_model(const char *path, const mcs_scenario *scn, mcs_error *err)
{
    const mcs_node *root = mcs_scenario_root(scn);
    if (!mcs_node_get(root, "simulation")) return MCS_OK; /* a model or include file */
    mcs_status st;
    mcs_log_set_level(MCS_LOG_WARN); /* the build's notes (a seated rider) are run's to show */
    const int fe_only = mcs_node_kind(mcs_node_get(root, "fe")) == MCS_NODE_MAP &&
                        mcs_node_len(mcs_node_get(root, "bodies")) == 0;
    if (fe_only)
        st = MCS_OK;
    else {
        mb_model *m = NULL;
        st = mb_model_build(scn, NULL, &m, err);
        if (!st) st = warn_initial(path, m, err);
        mb_model_destroy(&m);
    }
    if (!st && (fe_only || s3_scenario_has_block(scn))) { /* stage 3's model (stage3: block) */
        fe_problem p = {0};
        mcs_scenario *s3 = NULL;
        st = cli_stage3_build(scn, &s3, &p, err);
        fe_problem_free(&p);
        mcs_scenario_destroy(&s3);
    }
    mcs_log_set_level(MCS_LOG_INFO);
    return st;
}

/* a JSON string */
static void json_str(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\') fprintf(f, "\\%c", *s);
        else if ((unsigned char)*s < 0x20) fprintf(f, "\\u%04x", *s);
        else fputc(*s, f);
    }
    fputc('"', f);
}

/* one keyword deck's entry of "keyword_decks" (--json): sizes and unknown keywords */
static void kw_visit(const char *path, const mcs_node *at, const fe_kw_deck *d, void *user)
{
    (void)at;
    FILE *f = user;
    int nelem = 0;
    for (int t = 0; t < FE_KW_NETYPE; t++) nelem += d->elem[t].n;
    fprintf(f, "%s\n    {\"file\": ", ftell(f) ? "," : "");
    json_str(f, path);
    fprintf(f, ", \"nodes\": %d, \"elements\": %d, \"parts\": %d, \"unknown_keywords\": [",
            d->nnode, nelem, d->npart);
    for (int i = 0; i < d->nunknown; i++) {
        char where[1200];
        snprintf(where, sizeof where, "%s:%d", d->file[d->unknown[i].loc.file],
                 d->unknown[i].loc.line);
        fprintf(f, "%s\n      {\"keyword\": \"*%s\", \"count\": %d, \"first\": ", i ? "," : "",
                d->unknown[i].name, d->unknown[i].count);
        json_str(f, where);
        fputc('}', f);
    }
    fprintf(f, "%s]}", d->nunknown ? "\n    " : "");
}

/* the resolved scenario as JSON, with "keyword_decks" (decks is their entries, "" for none) */
static mcs_status write_json(const mcs_scenario *scn, const char *decks)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&buf, &len);
    if (!m) return MCS_ERR_NOMEM;
    mcs_status st = mcs_scenario_write_json(scn, m);
    fclose(m);
    char *close = buf ? strrchr(buf, '}') : NULL;
    if (!st && close && *decks) {
        char *end = close;
        while (end > buf && (end[-1] == ' ' || end[-1] == '\n')) end--;
        fwrite(buf, 1, (size_t)(end - buf), stdout);
        printf(",\n  \"keyword_decks\": [%s\n  ]\n}\n", decks);
    } else if (!st && buf) {
        fputs(buf, stdout);
    }
    free(buf);
    return st;
}

/* check one file; 0 ok, else the exit status */
static int check_one(const char *path, int json)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mcs_status st = mcs_scenario_load(path, &scn, &err);
    char *decks = NULL;
    size_t ndecks = 0;
    FILE *df = open_memstream(&decks, &ndecks);
    if (!df) st = MCS_ERR(&err, MCS_ERR_NOMEM, "mcrash check: out of memory");
    /* every keyword deck it names is read (a missing deck or part ID is an error here) */
    if (!st) st = fe_scn_kw_check(mcs_scenario_root(scn), kw_visit, df, &err);
    if (df) fclose(df);
    if (!st) st = build_model(path, scn, &err);
    if (st) {
        mcs_scenario_destroy(&scn);
        free(decks);
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    if (json)
        st = write_json(scn, decks ? decks : "");
    else
        printf("%s: ok\n", path);
    mcs_scenario_destroy(&scn);
    free(decks);
    return st ? 2 : 0;
}

static int finish(int status)
{
    if (fflush(stdout) != 0) {
        fprintf(stderr, "mcrash check: cannot write the output\n");
        return 2;
    }
    return status;
}

int cli_check(int argc, char **argv)
{
    if (cli_wants_help(argv[0], argc, argv)) return 0;
    int json = 0, schema = 0, nfiles = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0)
            json = 1;
        else if (strcmp(argv[i], "--schema") == 0)
            schema = 1;
        else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "mcrash check: unknown option '%s'\n", argv[i]);
            return cli_usage(argv[0]);
        } else
            nfiles++;
    }
    if (schema && nfiles == 0 && !json) return finish(mcs_schema_write_markdown(stdout) ? 2 : 0);
    if (nfiles == 0 || schema || (json && nfiles > 1)) return cli_usage(argv[0]);
    int status = 0;
    for (int i = 1; i < argc; i++) {
        if (argv[i][0] == '-' && argv[i][1]) continue;
        int s = check_one(argv[i], json);
        if (s > status) status = s;
    }
    return finish(status);
}

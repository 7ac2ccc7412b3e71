/* cmd_check.c: `mcrash check [--json] SCENARIO.yaml...` — validate scenarios; with --json print
 * one resolved (includes merged, every quantity in SI); `--schema` prints the key reference.
 * A scenario with a simulation: block is also built into the model `mcrash run` would run
 * (stage 1, or stage 3 for an fe: block without bodies), so what run refuses at load, check
 * refuses with the same message; nothing is simulated or written. A stage-1 model's surface
 * pairs that penetrate more than 1 mm at t = 0 are listed as warnings on stderr (contact,
 * surfaces, depth, the force its law gives there; stage1_mb/mb_initial.h): a model should
 * start without them. Warnings do not change the exit status. */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "core/mcs_scenario.h"
#include "stage1_mb/mb_initial.h"
#include "stage1_mb/mb_model.h"

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
    if (mcs_node_kind(mcs_node_get(root, "fe")) == MCS_NODE_MAP &&
        mcs_node_len(mcs_node_get(root, "bodies")) == 0) {
        fe_problem p = {0};
        st = cli_stage3_build(scn, &p, err);
        fe_problem_free(&p);
    } else {
        mb_model *m = NULL;
        st = mb_model_build(scn, NULL, &m, err);
        if (!st) st = warn_initial(path, m, err);
        mb_model_destroy(&m);
    }
    mcs_log_set_level(MCS_LOG_INFO);
    return st;
}

/* check one file; 0 ok, else the exit status */
static int check_one(const char *path, int json)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mcs_status st = mcs_scenario_load(path, &scn, &err);
    if (!st) st = build_model(path, scn, &err);
    if (st) {
        mcs_scenario_destroy(&scn);
        fprintf(stderr, "%s\n", err.msg);
        return mcs_status_exit_code(st);
    }
    if (json)
        st = mcs_scenario_write_json(scn, stdout);
    else
        printf("%s: ok\n", path);
    mcs_scenario_destroy(&scn);
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

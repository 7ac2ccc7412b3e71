/* cmd_stage2.c: `mcrash stage2 SCENARIO.yaml [--motion STAGE1.h5] [-o OUT.h5] [--quiet]
 * [--json]`: the scenario's model with the stage2.prescribed bodies moved as the stage-1 file's
 * (stage2_fe/s2_run.h) to /stage2 of a results file. --motion wins over stage2.motion (which is
 * relative to the scenario file). Without -o the file is <scenario basename>.h5; when it is the
 * motion file itself, /stage2 is added to it. --json prints {"output": ..., "stage2": {"steps",
 * "bodies", "prescribed", "wall_time_s", "energy_drift", "end_time_s", "motion_file", "method",
 * "position_error_m", "angle_error_rad", "timers_s"}}. Exit status: 0 done, 1 numerical
 * failure, 2 bad input (no stage2: block, a motion file that is missing, not HDF5, corrupt,
 * without /stage1, without a prescribed body or shorter than the run: no results file). */
#include "cli/cli.h"
#include "cli/cli_common.h"
#include "stage2_fe/s2_run.h"
#include "stage3_fe/s3_scenario.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the same file (both exist and resolve to one path, or the same name) */
static int same_file(const char *a, const char *b)
{
    char ra[PATH_MAX], rb[PATH_MAX];
    if (realpath(a, ra) && realpath(b, rb)) return strcmp(ra, rb) == 0;
    return strcmp(a, b) == 0;
}

static void stage2_json(const s2_model *m, const s2_summary *s)
{
    const mb_run_summary *r = &s->mb;
    printf("{\"steps\": %ld, \"bodies\": %d, \"prescribed\": %d, \"wall_time_s\": %.6g, "
           "\"energy_drift\": %.6g, \"end_time_s\": %.9g, \"motion_file\": ",
           r->steps, r->bodies, s->prescribed, r->wall_time_s, r->energy_drift, r->t_end);
    cli_json_string(tr_stage2_motion_path(m->motion));
    printf(", \"method\": \"%s\", \"position_error_m\": %.6g, \"angle_error_rad\": %.6g, "
           "\"timers_s\": {",
           tr_motion_method_name(tr_motion_get_method(tr_stage2_motion_get(m->motion))),
           s->position_error, s->angle_error);
    for (int k = 0; k < MB_NTIMER; k++)
        printf("%s\"%s\": %.4g", k ? ", " : "", mb_timer_name(k), r->timer[k]);
    printf("}}");
}

/* build and run; with json print the summary object (with stage 1's when s1 is given; json 2:
 * only its member `, "stage2": {...}`, the caller opens and closes the object) */
static int stage2_exec(const mcs_scenario *scn, const char *motion, const char *out, int append,
                       int quiet, int json, const mb_run_summary *s1)
{
    mcs_error err = {0};
    s2_model *m = NULL;
    s2_summary sum = {0};
    mcs_status st = s2_model_build(scn, motion, &m, &err);
    if (!st) {
        s2_run_opts o = {.out_path = out,
                         .scenario_text = mcs_scenario_text(scn),
                         .quiet = quiet,
                         .append = append || same_file(out, tr_stage2_motion_path(m->motion))};
        st = s2_run(m, &o, &sum, &err);
    }
    if (st) {
        fprintf(stderr, "%s\n", err.msg);
        s2_model_destroy(&m);
        return mcs_status_exit_code(st);
    }
    if (json == 2) {
        printf(", \"stage2\": ");
        stage2_json(m, &sum);
    } else if (json) {
        printf("{\"output\": ");
        cli_json_string(out);
        if (s1) printf(", \"stage1\": ");
        if (s1) cli_stage1_json(s1);
        printf(", \"stage2\": ");
        stage2_json(m, &sum);
        printf("}\n");
    } else if (!quiet) {
        fprintf(stderr,
                "stage 2: %ld steps, %d bodies (%d prescribed), %.3g s wall, energy drift %.3g, "
                "motion error %.3g m %.3g rad -> %s\n",
                sum.mb.steps, sum.mb.bodies, sum.prescribed, sum.mb.wall_time_s,
                sum.mb.energy_drift, sum.position_error, sum.angle_error, out);
    }
    s2_model_destroy(&m);
    return 0;
}

int cli_stage2_scenario(const mcs_scenario *scn, const char *motion, const char *out, int append,
                        int quiet, int json)
{
    int rc = stage2_exec(scn, motion, out, append, quiet, json, NULL);
    return fflush(stdout) ? 2 : rc;
}

int cli_stage12_scenario(const mcs_scenario *scn, const char *out, int quiet, int json)
{
    mb_run_summary s1 = {0};
    int rc = cli_stage1_exec(scn, out, quiet, &s1);
    if (rc) return rc;
    if (!json && !quiet) {
        fprintf(stderr, "stage 1: %ld steps, %d bodies, %.3g s wall, energy drift %.3g -> %s\n",
                s1.steps, s1.bodies, s1.wall_time_s, s1.energy_drift, out);
    }
    rc = stage2_exec(scn, out, out, 1, quiet, json, &s1);
    return fflush(stdout) ? 2 : rc;
}

int cli_stage_all_scenario(const mcs_scenario *scn, const char *out, int quiet, int json)
{
    const mcs_node *root = mcs_scenario_root(scn);
    const int has2 = mcs_node_kind(mcs_node_get(root, "stage2")) == MCS_NODE_MAP;
    if (!s3_scenario_has_block(scn))
        return has2 ? cli_stage12_scenario(scn, out, quiet, json)
                    : cli_stage1_scenario(scn, out, quiet, json);
    mb_run_summary s1 = {0};
    int rc = cli_stage1_exec(scn, out, quiet, &s1);
    if (rc) return rc;
    if (json) {
        printf("{\"output\": ");
        cli_json_string(out);
        printf(", \"stage1\": ");
        cli_stage1_json(&s1);
    } else if (!quiet) {
        fprintf(stderr, "stage 1: %ld steps, %d bodies, %.3g s wall, energy drift %.3g -> %s\n",
                s1.steps, s1.bodies, s1.wall_time_s, s1.energy_drift, out);
    }
    if (has2) rc = stage2_exec(scn, out, out, 1, quiet, json ? 2 : 0, NULL);
    s3_summary s3 = {0};
    if (!rc) rc = cli_stage3_exec(scn, out, 1, quiet, &s3);
    if (!rc && json) {
        printf(", \"stage3\": ");
        cli_stage3_json(&s3);
    } else if (!rc && !quiet)
        cli_stage3_note(&s3, out);
    if (json) printf("}\n"); /* the object closed also after a failed stage */
    return fflush(stdout) ? 2 : rc;
}

int cli_stage2(int argc, char **argv)
{
    cli_run_args a;
    int rc = cli_parse_run_args(argc, argv, 0, &a);
    if (rc >= 0) return rc;
    mcs_scenario *scn = cli_load_scenario(a.path, &rc);
    if (!scn) return rc;
    rc = cli_stage2_scenario(scn, a.motion, a.out, 0, a.quiet, a.json);
    mcs_scenario_destroy(&scn);
    return rc;
}

/* test_tr_prescribe.c: stage-1 trajectories as prescribed bodies (translators/tr_prescribe.h,
 * stage1_mb/mb_prescribe.h). Replay: the two-sphere impact (scenarios/verification/
 * two_spheres.yaml) is run in stage 1 to a results file; then the same model runs with sphere
 * a prescribed from the file (both motion methods) and b free. The reference is stage 1's own
 * free run of b (another method: both bodies integrated), read back from the file: b must
 * repeat it to within the motion's interpolation error, and leave with the same velocity.
 * Errors: a body the file lacks and a file shorter than the run are refused, naming them. */
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_test_util.h"
#include "stage1_mb/mb_prescribe.h"
#include "translators/tr_prescribe.h"
#include "translators/tr_stage2_motion.h"

#include <unistd.h>

#define SCN "scenarios/verification/two_spheres.yaml"

static char tdir[64], h5[128];

/* b's largest position and final velocity difference from the file, a prescribed by method */
static int replay(tr_motion_method method, double *dpos, double *dvel, double *drift)
{
    mcs_error err = {0};
    mb_model *m = mt_model_file(SCN);
    tr_motion *mo = NULL, *ref = NULL;
    tr_prescribe *p = NULL;
    mb_state *s = NULL;
    const char *a[] = {"a"}, *b[] = {"b"};
    mcs_status st = m ? MCS_OK : MCS_ERR_IO;
    if (!st) st = tr_motion_open(&mo, h5, a, 1, method, &err);
    if (!st) st = tr_motion_open(&ref, h5, b, 1, TR_MOTION_POSE, &err);
    if (!st) st = tr_prescribe_create(&p, m, mo, a, NULL, 1, &err);
    if (!st) st = mb_state_create(m, &s, &err);
    *dpos = *dvel = 0;
    const int ib = m ? mb_model_body(m, "b") : 0;
    while (!st && s->step < m->nsteps) {
        if ((st = mb_step(m, s, &err))) break;
        if (s->step % m->out_every) continue;
        tr_motion_kin k; /* the pose method passes through the file's samples */
        if ((st = tr_motion_eval(ref, 0, s->t, &k, &err))) break;
        mb_body_kin x;
        mb_body_get(s->world, ib, &x);
        double d[3];
        mb_sub(x.pos, k.pos, d);
        *dpos = fmax(*dpos, mb_norm(d));
        mb_sub(x.vel, k.vel, d);
        if (s->step == m->nsteps) *dvel = mb_norm(d);
    }
    if (st) fprintf(stderr, "%s\n", err.msg);
    *drift = s ? mb_energy_drift(m, s) : 1;
    mb_state_destroy(&s);
    tr_prescribe_destroy(&p);
    tr_motion_destroy(&mo), tr_motion_destroy(&ref);
    mb_model_destroy(&m);
    return st == MCS_OK;
}

static void test_replay_two_spheres(void)
{
    double dp, dv, dr, qp, qv, qr;
    CHECK(replay(TR_MOTION_POSE, &dp, &dv, &dr));
    CHECK(replay(TR_MOTION_PULSE, &qp, &qv, &qr));
    printf("b free, a prescribed: pose: |dx| %.3g m, final |dv| %.3g m/s, drift %.3g; "
           "pulse: %.3g m, %.3g m/s, %.3g\n",
           dp, dv, dr, qp, qv, qr);
    FIG("stage1_engine.presc_replay_pose_um", "%.2g", 1e6 * dp);
    FIG("stage1_engine.presc_replay_pulse_um", "%.2g", 1e6 * qp);
    FIG("stage1_engine.presc_replay_drift", "%.4f", dr);
    /* pose: through the samples (C1 cubic, 0.1 ms apart); pulse: the acceleration history
     * integrated, it drifts (translators/tr_motion.h). The replay bound is 1 mm. */
    CHECK(dp < 3e-8 && dv < 1e-6);
    CHECK(qp < 2.1e-4 && qv < 0.0062); /* 3x the pulse's 70 um, 0.0021 m/s */
    CHECK(dr < 0.01 && qr < 0.01);
}

static void test_refusals(void)
{
    mcs_error err = {0};
    mb_model *m = mt_model_file(SCN);
    tr_motion *mo = NULL;
    tr_prescribe *p = NULL;
    const char *a[] = {"a"}, *zz[] = {"zz"};
    CHECK(m && tr_motion_open(&mo, h5, NULL, 0, TR_MOTION_POSE, &err) == MCS_OK);
    if (!m || !mo) goto done;
    CHECK(tr_prescribe_create(&p, m, mo, a, zz, 1, &err) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(err.msg, "zz");
    CHECK(!mb_body_prescribed(m, 0));
    mcs_error_clear(&err);
    CHECK(tr_prescribe_create(&p, m, mo, zz, NULL, 1, &err) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(err.msg, "zz");
    /* a run longer than the file */
    mcs_error_clear(&err);
    m->t_end = 0.05;
    CHECK(tr_prescribe_create(&p, m, mo, a, NULL, 1, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "spans");
    CHECK(p == NULL && !mb_body_prescribed(m, 0));
done:
    tr_motion_destroy(&mo);
    mb_model_destroy(&m);
}

/* the scenario text of two_spheres.yaml followed by `extra` (malloc'ed) */
static char *scenario_with(const char *extra)
{
    FILE *f = fopen(SCN, "rb");
    if (!f) return NULL;
    char *t = calloc(8192, 1);
    size_t n = t ? fread(t, 1, 4096, f) : 0;
    fclose(f);
    if (t) snprintf(t + n, 8192 - n, "%s", extra);
    return t;
}

/* a (the scenario's) stage2: block drives the same replay: the same numbers as the direct
 * use of tr_prescribe (pulse); a missing block and a body the file lacks are refused */
static void test_stage2_block(void)
{
    char blk[512];
    snprintf(blk, sizeof blk, "stage2: {motion: %s, method: pulse, prescribed: [{body: a}]}\n", h5);
    char *y = scenario_with(blk);
    mcs_error err = {0};
    mb_model *m = y ? mt_model_text(SCN, y, &err) : NULL;
    mcs_scenario *scn = NULL;
    CHECK(m && mcs_scenario_load_text(SCN, y, strlen(y), &scn, &err) == MCS_OK);
    tr_stage2_motion *sm = NULL;
    mb_state *s = NULL;
    mcs_status st = m && scn ? tr_stage2_motion_create(&sm, scn, m, NULL, &err) : MCS_ERR_IO;
    CHECK(st == MCS_OK);
    if (!st) st = mt_run(m, &s, &err);
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    double qp, qv, qr, d[3];
    CHECK(replay(TR_MOTION_PULSE, &qp, &qv, &qr));
    if (!st) { /* the final state of b: the same run as the direct replay's */
        tr_motion *ref = NULL;
        const char *b[] = {"b"};
        tr_motion_kin k;
        mb_body_kin x;
        CHECK(tr_motion_open(&ref, h5, b, 1, TR_MOTION_POSE, &err) == MCS_OK);
        CHECK(ref && tr_motion_eval(ref, 0, s->t, &k, &err) == MCS_OK);
        mb_body_get(s->world, 1, &x);
        mb_sub(x.vel, k.vel, d);
        CHECK_NEAR(mb_norm(d), qv, 1e-15);
        tr_motion_destroy(&ref);
    }
    mb_state_destroy(&s);
    tr_stage2_motion_destroy(&sm);
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);
    free(y);
    /* a body the file lacks (from:) */
    snprintf(blk, sizeof blk, "stage2: {motion: %s, prescribed: [{body: a, from: zz}]}\n", h5);
    y = scenario_with(blk);
    mcs_error_clear(&err);
    m = y ? mt_model_text(SCN, y, &err) : NULL;
    CHECK(m && mcs_scenario_load_text(SCN, y, strlen(y), &scn, &err) == MCS_OK);
    if (m && scn) {
        CHECK(tr_stage2_motion_create(&sm, scn, m, NULL, &err) != MCS_OK);
        CHECK_STR_CONTAINS(err.msg, "zz");
        CHECK(sm == NULL && !mb_body_prescribed(m, 0));
    }
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);
    free(y);
    /* no stage2: block */
    y = scenario_with("");
    mcs_error_clear(&err);
    m = y ? mt_model_text(SCN, y, &err) : NULL;
    CHECK(m && mcs_scenario_load_text(SCN, y, strlen(y), &scn, &err) == MCS_OK);
    if (m && scn) {
        CHECK(tr_stage2_motion_create(&sm, scn, m, h5, &err) == MCS_ERR_KEY);
        CHECK_STR_CONTAINS(err.msg, "stage2");
    }
    mb_model_destroy(&m);
    mcs_scenario_destroy(&scn);
    free(y);
}

int main(void)
{
    snprintf(tdir, sizeof tdir, "/tmp/mcs_presc_XXXXXX");
    if (!mkdtemp(tdir)) return perror("mkdtemp"), 1;
    snprintf(h5, sizeof h5, "%s/two_spheres.h5", tdir);
    mb_model *m = mt_model_file(SCN);
    mcs_error err = {0};
    mb_run_opts o = {.out_path = h5, .quiet = 1};
    if (!m || mb_run(m, &o, NULL, &err)) return fprintf(stderr, "stage 1: %s\n", err.msg), 1;
    mb_model_destroy(&m);
    RUN(test_replay_two_spheres);
    RUN(test_refusals);
    RUN(test_stage2_block);
    unlink(h5);
    rmdir(tdir);
    TEST_END();
}

/* test_mb_channels.c: the contact and joint channels of /stage1/channels (mb_channels.c,
 * docs/contracts.md) equal the state's values at the output steps, and the energy growth check
 * runs every step (mb_energy_check_step), not only at the output samples. */
#include "core/mcs_results.h"
#include "harness.h"
#include "tests/mb_test_util.h"
#include "stage1_mb/mb_model.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a damped ball bouncing on the ground with friction (sliding), a restrained pendulum beside */
static const char *SCN =
    "mcrash: 1\n"
    "simulation: {end_time: 0.3 s, time_step: 10 us, output_rate: 2 kHz}\n"
    "environment: {gravity: 9.81, ground: {height: 0, friction: 0.3}}\n"
    "characteristics:\n"
    "  pad: {loading: [[0, 0], [0.01, 1000]], damping: 5}\n"
    "  spring: {type: moment, loading: [[0, 0], [1, 30]], damping: 0.2}\n"
    "bodies:\n"
    "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004], position: [0, 0, 0.15],\n"
    "     velocity: [1, 0, 0], surfaces: [{type: ellipsoid, center: [0, 0, 0],\n"
    "     semi_axes: [0.1, 0.1, 0.1]}]}\n"
    "  - {name: arm, mass: 1, inertia: [0.01, 0.01, 0.01], position: [2, 0, 0.5],\n"
    "     velocity: [-1.5, 0, 0], angular_velocity: [0, 3, 0]}\n"
    "joints:\n"
    "  - {name: hinge, type: revolute, parent: ground, child: arm, anchor: [2, 0, 1],\n"
    "     axis: [0, 1, 0], restraint: spring}\n"
    "contacts: [{name: drop, a: ball, b: ground, characteristic: pad}]\n";

/* the file's channels against the same (deterministic) run stepped here: at every output step
 * fn = the pair's normal force, ft = |friction|, pen = depth, angle = the joint position and
 * moment = minus the load applied to the child; exact (same numbers, same order) */
static void test_channels_equal_state(void)
{
    mb_model *m = mt_model_text("channels.yaml", SCN, NULL);
    CHECK(m != NULL);
    if (!m) return;
    const char *out = "/tmp/mcrash_test_channels.h5";
    mcs_error err = {0};
    mb_run_opts o = {.out_path = out, .quiet = 1};
    CHECK(mb_run(m, &o, NULL, &err) == MCS_OK);
    mb_state *s = NULL;
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    size_t no = (size_t)m->nout;
    double *ref = calloc(5 * no, sizeof *ref);
    long k = 1;
    while (s->step < m->nsteps && mb_step(m, s, &err) == MCS_OK)
        if (s->step % m->out_every == 0 && k < (long)no) {
            double *r = ref + 5 * k++;
            r[0] = s->pair[0].fn;
            r[1] = sqrt(s->pair[0].ft[0] * s->pair[0].ft[0] + s->pair[0].ft[1] * s->pair[0].ft[1] +
                        s->pair[0].ft[2] * s->pair[0].ft[2]);
            r[2] = s->pair[0].depth;
            r[3] = s->r1[0].x;
            r[4] = -s->r1[0].load;
        }
    const char *names[] = {"drop_fn", "drop_ft", "drop_pen", "hinge_angle", "hinge_moment"};
    const char *units[] = {"N", "N", "m", "rad", "N m"};
    double peak[5] = {0};
    for (int c = 0; c < 5; c++) {
        size_t n = 0;
        char unit[32] = "";
        double *v = mt_read_channel(out, names[c], &n, unit, NULL);
        CHECK(v != NULL && n == no);
        CHECK(strcmp(unit, units[c]) == 0);
        int bad = 0;
        for (size_t i = 0; v && i < n && i < no; i++) {
            if (v[i] != ref[5 * i + c]) bad++;
            peak[c] = fmax(peak[c], fabs(v[i]));
        }
        CHECK(bad == 0);
        free(v);
    }
    printf("  channels: %zu samples; peaks fn %.1f N, ft %.2f N, pen %.2f mm, angle %.4f rad, "
           "moment %.3f N m\n",
           no, peak[0], peak[1], peak[2] * 1e3, peak[3], peak[4]);
    /* the channels saw the events: contact with sliding friction, the pendulum swinging */
    CHECK(peak[0] > 9.81 && peak[1] > 0 && peak[2] > 0.002 && peak[3] > 0.1 && peak[4] > 1);
    free(ref);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    remove(out);
}

/* growth is caught at the step it happens, not at the next output sample: a contact with
 * w h = 3.2 (k = 1e6 N/m over 1 mm, m = 1 kg, h = 100 us) blows up within the first contact
 * (~10 ms); with output_rate 10 Hz the first output sample after t = 0 is at 0.1 s */
static void test_energy_checked_every_step(void)
{
    const char *y = "mcrash: 1\n"
                    "simulation: {end_time: 0.3 s, time_step: 100 us, output_rate: 10 Hz}\n"
                    "environment: {gravity: 9.81, ground: {height: 0}}\n"
                    "characteristics: {stiff: {loading: [[0, 0], [0.001, 1e6]]}}\n"
                    "bodies:\n"
                    "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004],\n"
                    "     position: [0, 0, 0.1005], velocity: [0, 0, -1],\n"
                    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, "
                    "0.1]}]}\n"
                    "contacts: [{a: ball, b: ground, characteristic: stiff}]\n";
    mb_model *m = mt_model_text("channels.yaml", y, NULL);
    CHECK(m != NULL);
    if (!m) return;
    CHECK(m->out_every == 1000);
    mb_state *s = NULL;
    mcs_error err = {0};
    CHECK(mb_state_create(m, &s, &err) == MCS_OK);
    mcs_status st = MCS_OK;
    while (!st && s->step < m->nsteps) st = mb_step(m, s, &err);
    printf("  energy check: stopped at t = %.4f s: %s\n", s->t, err.msg);
    CHECK(st == MCS_ERR_NUMERIC);
    CHECK(s->t < 0.02);
    CHECK_STR_CONTAINS(err.msg, "ball");
    CHECK_STR_CONTAINS(err.msg, "t = ");
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_channels_equal_state);
    RUN(test_energy_checked_every_step);
    TEST_END();
}

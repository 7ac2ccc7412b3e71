/* test_sedan_upper.c: the sedan's struck side is closed from the beltline to the roof
 * (scenarios/models/opponents/sedan_1668kg.yaml, docs/models.md "The 1668 kg sedan"): a ball
 * smaller than any rider's head, placed 5 mm into the side at points of a grid over it, meets
 * the upper body's facets everywhere. The side's position at each height is the model file's,
 * worked by hand from its documented world coordinates: side glass from the beltline (z 1.00 m,
 * x 1.755 m) leaning in to its top edge (z 1.30 m, x 1.845 m), y -0.55 ... 1.35 m; above it the
 * roof rail strip, vertical at x 1.845 m up to the roof's edge (z 1.41 m), y 0 ... 1.50 m (its
 * front edge runs down along the windscreen's side edge to y -0.243 m at z 1.30 m). Earlier
 * versions left the strip's place open (an ellipsoid tapering to nothing at y = 0): the ball at
 * y = 0, z 1.36 m met nothing there. */
#include "harness.h"
#include "stage1_mb/mb_initial.h"
#include "tests/mb_test_util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* the ball's radius [m]: below the 5th female's smallest head semi-axis, 0.071 m (5.6 in / 2) */
#define BALL_R 0.05
#define DEPTH 0.005 /* [m] into the side, along the heading (-x) */

/* the side's outer x at height z [m] (hand, from the coordinates above) */
static double side_x(double z)
{
    if (z <= 1.30) return 1.755 + (z - 1.00) / 0.30 * 0.09;
    return 1.845;
}

/* the deepest penetration of a ball at (x, y, z) into sedan_upper's facets, at t = 0 [m] */
static double ball_depth(double x, double y, double z)
{
    char txt[1024];
    snprintf(txt, sizeof txt,
             "mcrash: 1\n"
             "name: sedan side probe\n"
             "include: [models/opponents/sedan_1668kg.yaml]\n"
             "simulation: {end_time: 1 ms, time_step: 10 us}\n"
             "environment: {ground: {height: 0 m}}\n"
             "characteristics:\n"
             "  probe: {loading: [[0, 0], [0.01, 1000]]}\n"
             "bodies:\n"
             "  - {name: probe, mass: 1 kg, inertia: [0.001, 0.001, 0.001],\n"
             "     position: [%.6f m, %.6f m, %.6f m], velocity: [0, 0, 0],\n"
             "     surfaces: [{name: ball, type: ellipsoid, center: [0, 0, 0],\n"
             "                 semi_axes: [%g, %g, %g]}]}\n"
             "contacts:\n"
             "  - {name: probe_upper, a: probe, b: sedan_upper, characteristic: probe}\n",
             x, y, z, BALL_R, BALL_R, BALL_R);
    mb_model *m = mt_model_text("scenarios/sedan_side_probe.yaml", txt, NULL);
    CHECK(m != NULL);
    if (!m) return NAN;
    mb_initial_pen *p = NULL;
    int n = 0;
    mcs_error err = {0};
    double d = 0;
    CHECK(mb_initial_penetrations(m, 0, &p, &n, &err) == MCS_OK);
    for (int i = 0; i < n; i++)
        if (strcmp(m->contact[m->pair[p[i].pair].contact].name, "probe_upper") == 0)
            d = fmax(d, p[i].depth);
    free(p);
    mb_model_destroy(&m);
    return d;
}

static void test_side_closed(void)
{
    static const double ys[] = {0.0, 0.1, 0.3, 0.6, 0.9, 1.2, 1.3};
    static const double zs[] = {1.05, 1.15, 1.25, 1.30, 1.33, 1.36, 1.39};
    int open = 0;
    double strip_err = 0;
    for (size_t i = 0; i < sizeof ys / sizeof *ys; i++)
        for (size_t k = 0; k < sizeof zs / sizeof *zs; k++) {
            double x = side_x(zs[k]) - BALL_R + DEPTH;
            double d = ball_depth(x, ys[i], zs[k]);
            if (!(d > 0)) {
                open++;
                printf("  open at y %.2f m, z %.2f m\n", ys[i], zs[k]);
            }
            /* on the vertical strip, clear of its edges: the depth is the 5 mm exactly */
            if (zs[k] > 1.30 + BALL_R / 2 && zs[k] < 1.41 - BALL_R / 2 + 1e-9 && ys[i] > 0.05)
                strip_err = fmax(strip_err, fabs(d - DEPTH));
        }
    /* the former gap's worst point: the header, 6 cm above the glass's top edge */
    double d_header = ball_depth(1.845 - BALL_R + DEPTH, 0.0, 1.36);
    printf("  %d grid points open; strip depth error %.1e m; at the header %.2f mm\n", open,
           strip_err, 1e3 * d_header);
    CHECK(open == 0);
    CHECK(strip_err < 1e-9);
    CHECK(d_header > 0.004);
}

int main(void)
{
    RUN(test_side_closed);
    TEST_END();
}

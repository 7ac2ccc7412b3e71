/* test_svg: the SVG plot primitives of the report (analysis/an_svg.c). The expected ticks are
 * Heckbert's nice-number rule worked by hand ("Nice numbers for graph labels", Graphics Gems,
 * 1990: range = nice(hi - lo), step = nice(range / n, rounded), ticks from floor(lo / step) to
 * ceil(hi / step)); pixel coordinates of a known line worked by hand from the box. */
#include "analysis/an_svg.h"
#include "harness.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* what f wrote, as a string (free it) */
static char *memfile_text(FILE *f, char **buf)
{
    fclose(f);
    return *buf;
}

static void test_nice(void)
{
    CHECK_NEAR(an_svg_nice(0.25, 1), 0.2, 1e-15);  /* f = 2.5 < 3 -> 2 */
    CHECK_NEAR(an_svg_nice(3.2, 1), 5, 1e-15);     /* f = 3.2 < 7 -> 5 */
    CHECK_NEAR(an_svg_nice(8.33, 1), 10, 1e-15);   /* f >= 7 -> 10 */
    CHECK_NEAR(an_svg_nice(12, 0), 20, 1e-15);     /* ceiling: 1.2 -> 2 */
    CHECK_NEAR(an_svg_nice(0.3, 0), 0.5, 1e-15);   /* ceiling: 3 -> 5 */
    CHECK_NEAR(an_svg_nice(1000, 0), 1000, 1e-12); /* exactly 1 x 10^3 */
}

static void test_ticks(void)
{
    double t[AN_SVG_MAXTICKS], step;
    /* [0, 1], 5: range 1, step nice(0.2) = 0.2 -> 0, 0.2, ..., 1 */
    int n = an_svg_ticks(0, 1, 5, t, &step);
    CHECK(n == 6);
    CHECK_NEAR(step, 0.2, 1e-15);
    CHECK_NEAR(t[0], 0, 0);
    CHECK_NEAR(t[3], 0.6, 1e-15);
    CHECK_NEAR(t[5], 1, 1e-15);
    /* [-3.7, 12.2], 5: range nice(15.9) = 20, step nice(4) = 5 -> -5, 0, 5, 10, 15 */
    n = an_svg_ticks(-3.7, 12.2, 5, t, &step);
    CHECK(n == 5);
    CHECK_NEAR(step, 5, 0);
    CHECK_NEAR(t[0], -5, 0);
    CHECK_NEAR(t[1], 0, 0);
    CHECK_NEAR(t[4], 15, 0);
    /* [0, 0.3] s, 6: range nice(0.3) = 0.5, step nice(0.0833) = 0.1 -> 0 .. 0.3 */
    n = an_svg_ticks(0, 0.3, 6, t, &step);
    CHECK(n == 4);
    CHECK_NEAR(step, 0.1, 1e-15);
    CHECK_NEAR(t[3], 0.3, 1e-15);
    /* zero width [5, 5] -> [4.5, 5.5], range 1, step 0.2 -> 4.4 .. 5.6 */
    n = an_svg_ticks(5, 5, 5, t, &step);
    CHECK(n == 7);
    CHECK_NEAR(t[0], 4.4, 1e-12);
    CHECK_NEAR(t[6], 5.6, 1e-12);
    /* reversed and non-finite input still give ticks */
    n = an_svg_ticks(10, 0, 5, t, &step);
    CHECK(n == 6 && t[0] == 0 && t[5] == 10);
    n = an_svg_ticks(NAN, 1, 5, t, &step);
    CHECK(n >= 2 && n <= AN_SVG_MAXTICKS);
    /* a target the array cannot hold gets a coarser step */
    n = an_svg_ticks(0, 1000, 500, t, &step);
    CHECK(n <= AN_SVG_MAXTICKS && n >= 2);
}

static void test_tick_label(void)
{
    char b[32];
    an_svg_tick_label(0.4, 0.2, b, sizeof b);
    CHECK(strcmp(b, "0.4") == 0);
    an_svg_tick_label(-1e-17, 0.1, b, sizeof b);
    CHECK(strcmp(b, "0.0") == 0);
    an_svg_tick_label(1500, 500, b, sizeof b);
    CHECK(strcmp(b, "1500") == 0);
    an_svg_tick_label(0.05, 0.05, b, sizeof b);
    CHECK(strcmp(b, "0.05") == 0);
    an_svg_tick_label(-2.5, 0.5, b, sizeof b);
    CHECK(strcmp(b, "-2.5") == 0);
}

/* y = 2x on x in [0, 10] into the box (50, 10, 100 x 50): the ticks fit the range exactly
 * (x step 2, y step 5), so px = 50 + 10 x, py = 60 - 2.5 y = 60 - 5 x */
static void test_path_known_line(void)
{
    an_svg_axes a;
    an_svg_axes_fit(&a, 50, 10, 100, 50, 0, 10, 0, 20);
    CHECK_NEAR(a.xmin, 0, 0);
    CHECK_NEAR(a.xmax, 10, 0);
    CHECK_NEAR(a.ymax, 20, 0);
    CHECK_NEAR(an_svg_px(&a, 3), 80, 1e-12);
    CHECK_NEAR(an_svg_py(&a, 6), 45, 1e-12);
    double x[11], y[11];
    for (int i = 0; i <= 10; i++) {
        x[i] = i;
        y[i] = 2 * i;
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    size_t k = an_svg_path(f, &a, x, y, 11, 1, "#000", 1, NULL);
    char *s = memfile_text(f, &buf);
    CHECK(k == 11);
    CHECK_STR_CONTAINS(s, "d=\"M50.0 60.0L60.0 55.0 70.0 50.0 80.0 45.0 90.0 40.0 100.0 35.0 "
                          "110.0 30.0 120.0 25.0 130.0 20.0 140.0 15.0 150.0 10.0\"");
    free(s);
    /* yscale: the same samples in kilo-units land at y/1000 */
    buf = NULL;
    f = open_memstream(&buf, &len);
    an_svg_axes_fit(&a, 50, 10, 100, 50, 0, 10, 0, 0.02);
    an_svg_path(f, &a, x, y, 11, 1e-3, "#000", 1, NULL);
    s = memfile_text(f, &buf);
    CHECK_STR_CONTAINS(s, "M50.0 60.0L60.0 55.0");
    free(s);
}

/* 1000 samples on 100 pixel columns with one spike: thinned to at most 4 points a column,
 * and the spike's pixel (x 50.5 -> px 50.5, y 10 -> the top of the box, 10.0) is kept */
static void test_path_thinning(void)
{
    an_svg_axes a;
    an_svg_axes_fit(&a, 0, 10, 100, 100, 0, 100, 0, 10);
    double x[1000], y[1000];
    for (int i = 0; i < 1000; i++) {
        x[i] = 0.1 * i;
        y[i] = 0;
    }
    y[505] = 10;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    size_t k = an_svg_path(f, &a, x, y, 1000, 1, "#000", 1, NULL);
    char *s = memfile_text(f, &buf);
    CHECK(k >= 100 && k <= 4 * 101);
    CHECK_STR_CONTAINS(s, " 50.5 10.0");
    free(s);
    /* a NaN breaks the line into two runs */
    y[300] = NAN;
    buf = NULL;
    f = open_memstream(&buf, &len);
    an_svg_path(f, &a, x, y, 1000, 1, "#000", 1, NULL);
    s = memfile_text(f, &buf);
    char *m1 = strchr(s, 'M'), *m2 = m1 ? strchr(m1 + 1, 'M') : NULL;
    CHECK(m1 && m2 && !strchr(m2 + 1, 'M'));
    free(s);
}

static void test_axes_and_text(void)
{
    an_svg_axes a;
    an_svg_axes_fit(&a, 60, 10, 400, 200, 0, 300, -2.3, 7.9);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    an_svg_begin(f, 500, 260, "energy <J>");
    an_svg_draw_axes(f, &a, "time [ms]", "energy [J]");
    const char *lab[] = {"kinetic & more"}, *col[] = {"#1f77b4"};
    an_svg_legend(f, 70, 20, lab, col, NULL, 1);
    an_svg_end(f);
    char *s = memfile_text(f, &buf);
    /* x: [0, 300], 6 intervals: step nice(nice(300)/6 = 83) = 100; y: [-2.3, 7.9], 5: range
     * nice(10.2) = 20, step nice(4) = 5 -> -5, 0, 5, 10 */
    CHECK_STR_CONTAINS(s, ">100</text>");
    CHECK_STR_CONTAINS(s, ">300</text>");
    CHECK_STR_CONTAINS(s, ">-5</text>");
    CHECK_STR_CONTAINS(s, ">10</text>");
    CHECK_STR_CONTAINS(s, ">time [ms]</text>");
    CHECK_STR_CONTAINS(s, "aria-label=\"energy &lt;J&gt;\"");
    CHECK_STR_CONTAINS(s, ">kinetic &amp; more</text>");
    CHECK_STR_CONTAINS(s, "</svg>");
    free(s);
}

static void test_hull(void)
{
    /* the unit square's corners and points inside and on its edges */
    double xy[] = {0.5, 0.5, 1, 1, 0, 0, 1, 0, 0.2, 0.7, 0, 1, 0.5, 0, 1, 0.5};
    double h[4 * 8 + 2];
    int n = an_svg_hull(xy, 8, h);
    CHECK(n == 4);
    double want[] = {0, 0, 1, 0, 1, 1, 0, 1}; /* counter-clockwise from the lowest x, y */
    for (int i = 0; i < 8 && n == 4; i++)
        CHECK_NEAR(h[i], want[i], 0);
}

int main(void)
{
    RUN(test_nice);
    RUN(test_ticks);
    RUN(test_tick_label);
    RUN(test_path_known_line);
    RUN(test_path_thinning);
    RUN(test_axes_and_text);
    RUN(test_hull);
    TEST_END();
}

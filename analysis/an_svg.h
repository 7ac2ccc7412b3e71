/* an_svg.h: plots drawn as inline SVG text (`mcrash report`): nice tick values, axes that map
 * data to pixels, polylines thinned to the pixel columns they cover, bars, legends, text.
 * Everything writes to a FILE * (open_memstream for a string). Pixels: x right, y down, the
 * origin at the top left of the <svg>. Numbers are printed with one decimal (0.1 px). */
#ifndef AN_SVG_H
#define AN_SVG_H

#include <stddef.h>
#include <stdio.h>

#define AN_SVG_MAXTICKS 32

/* a "nice" number near x > 0: 1, 2, 5 x 10^k (round: the nearest; else the smallest >= x)
 * (Heckbert, "Nice numbers for graph labels", Graphics Gems, 1990) */
double an_svg_nice(double x, int round);

/* ticks covering [lo, hi] with about `target` intervals: *step a nice number, the first tick
 * floor(lo/step)*step, the last ceil(hi/step)*step; returns the count (<= AN_SVG_MAXTICKS)
 * written to t. A range of zero width (or lo > hi, or not finite) is widened first: [v-1, v+1]
 * for v = 0, else v -+ |v|/10 */
int an_svg_ticks(double lo, double hi, int target, double *t, double *step);

/* a tick label: v with the decimals its step needs (step 0.2 -> "0.4"; no "-0") */
void an_svg_tick_label(double v, double step, char *buf, size_t n);

/* a plot area: data [xmin, xmax] x [ymin, ymax] drawn in the box (x0, y0, w, h) [px] */
typedef struct {
    double x0, y0, w, h;                 /* plot box [px], y0 its top                  */
    double xmin, xmax, ymin, ymax;       /* data range (the outer ticks after fit)     */
    double xt[AN_SVG_MAXTICKS], xstep;   /* x ticks and their step                     */
    double yt[AN_SVG_MAXTICKS], ystep;   /* y ticks and their step                     */
    int nxt, nyt;                        /* tick counts                                */
} an_svg_axes;

/* set the box and the data range; the range is widened to the outer nice ticks (about 6
 * intervals in x, 5 in y) */
void an_svg_axes_fit(an_svg_axes *a, double x0, double y0, double w, double h, double xmin,
                     double xmax, double ymin, double ymax);

/* data -> pixel */
double an_svg_px(const an_svg_axes *a, double x);
double an_svg_py(const an_svg_axes *a, double y);

/* <svg width height viewBox> with a text style; `label` goes into aria-label */
void an_svg_begin(FILE *f, double w, double h, const char *label);
void an_svg_end(FILE *f);

/* grid, frame, ticks with their labels, axis titles ("time [ms]"; either may be NULL) */
void an_svg_draw_axes(FILE *f, const an_svg_axes *a, const char *xlabel, const char *ylabel);

/* polyline of (x[i], y[i]*yscale), i < n, clipped to the x range: samples that fall into one
 * pixel column are thinned to their first, lowest, highest and last (peaks stay); non-finite
 * samples break the line. Returns the number of points written */
size_t an_svg_path(FILE *f, const an_svg_axes *a, const double *x, const double *y, size_t n,
                   double yscale, const char *color, double width, const char *dash);

/* a legend box at (x, y) [px], one row per entry: a line of colors[i] (dashed when dash[i] is
 * non-NULL, dash itself may be NULL) and labels[i] */
void an_svg_legend(FILE *f, double x, double y, const char *const *labels,
                   const char *const *colors, const char *const *dash, int n);

/* the i-th colour of the palette (cycles) */
const char *an_svg_color(int i);

/* text at (x, y) [px]; anchor "start" | "middle" | "end"; the text is XML-escaped */
void an_svg_text(FILE *f, double x, double y, const char *anchor, double size, const char *fill,
                 const char *text);

/* s XML-escaped (& < > " ') */
void an_svg_escape(FILE *f, const char *s);

/* filled rectangle in pixels (title: a tooltip, may be NULL) */
void an_svg_rect(FILE *f, double x, double y, double w, double h, const char *fill,
                 const char *title);

/* a line in pixels */
void an_svg_line(FILE *f, double x1, double y1, double x2, double y2, const char *color,
                 double width, const char *dash);

/* closed polygon of n points (px, py) [px] */
void an_svg_polygon(FILE *f, const double *px, const double *py, int n, const char *fill,
                    const char *stroke, double opacity);

/* convex hull of n points xy [n,2] (Andrew's monotone chain): its corners in counter-clockwise
 * order (in a y-up frame) into hull (room for 4n + 2 values), returns their count; collinear
 * points on an edge are dropped. xy is sorted in place. */
int an_svg_hull(double *xy, int n, double *hull);

#endif

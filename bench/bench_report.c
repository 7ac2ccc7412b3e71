/* bench_report: time of `mcrash report` on a 300 ms stage-1 + stage-2 file (issue 17: at most
 * 5 s). The file is tests/report_sample.h's (every section; 5 kHz, 1501 samples a stage) with
 * 200 more channels and 30 more bodies with outlines in stages 1 and 2, about the 413 concept
 * case's count (so the stage-against-stage table rates 120 channels). Prints wall and CPU time
 * and the page's size. Never fails on time. */
#include "tests/report_sample.h"
#include "translators/tr_report.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

static double now(clockid_t c)
{
    struct timespec ts;
    clock_gettime(c, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* the extra channels and bodies of stage s */
static int more(mcs_results *r, int s, mcs_error *e)
{
    double t[RS_NT];
    int bad = 0;
    for (int i = 0; i < RS_NT; i++) t[i] = i * RS_DT;
    for (int k = 0; k < 200 && !bad; k++) {
        char name[32];
        snprintf(name, sizeof name, "contact%03d_fn", k);
        bad = rs_channel(r, s, name, t, 1000 + 10 * k, 0.02 + 1e-3 * (k % 50) + 0.003 * s, "N",
                         0, e);
    }
    double *pos = malloc(sizeof *pos * 3 * RS_NT), *ori = malloc(sizeof *ori * 4 * RS_NT);
    for (int b = 0; pos && ori && b < 30 && !bad; b++) {
        for (int i = 0; i < RS_NT; i++) {
            pos[3 * i] = 0.1 * b + 5 * t[i];
            pos[3 * i + 1] = 0.02 * b;
            pos[3 * i + 2] = 0.5 + 0.03 * b;
            ori[4 * i] = 1;
            ori[4 * i + 1] = ori[4 * i + 2] = ori[4 * i + 3] = 0;
        }
        char name[32], p[96];
        snprintf(name, sizeof name, "rider_part%02d", b);
        bad |= mcs_results_put_body(r, s, name, "position", RS_NT, pos, e) != MCS_OK;
        bad |= mcs_results_put_body(r, s, name, "orientation", RS_NT, ori, e) != MCS_OK;
        /* a 12 x 6 latitude-longitude outline, as stage 1 writes an ellipsoid's */
        double nodes[62 * 3];
        int tri[120 * 3], nt = 0;
        nodes[0] = nodes[1] = 0, nodes[2] = 0.1;
        nodes[183] = nodes[184] = 0, nodes[185] = -0.1;
        for (int la = 1; la < 6; la++)
            for (int lo = 0; lo < 12; lo++) {
                double th = M_PI * la / 6, ph = 2 * M_PI * lo / 12;
                int n = 1 + (la - 1) * 12 + lo;
                nodes[3 * n] = 0.08 * sin(th) * cos(ph);
                nodes[3 * n + 1] = 0.06 * sin(th) * sin(ph);
                nodes[3 * n + 2] = 0.1 * cos(th);
                int right = 1 + (la - 1) * 12 + (lo + 1) % 12;
                if (la == 1) {
                    tri[3 * nt] = 0, tri[3 * nt + 1] = n, tri[3 * nt + 2] = right, nt++;
                } else {
                    tri[3 * nt] = n - 12, tri[3 * nt + 1] = n, tri[3 * nt + 2] = right, nt++;
                }
                if (la == 5) tri[3 * nt] = n, tri[3 * nt + 1] = 61, tri[3 * nt + 2] = right, nt++;
            }
        size_t dn[2] = {62, 3}, de[2] = {(size_t)nt, 3};
        snprintf(p, sizeof p, "/stage%d/outlines/%s/nodes", s, name);
        bad |= mcs_results_write(r, p, 2, dn, nodes, "m", e) != MCS_OK;
        snprintf(p, sizeof p, "/stage%d/outlines/%s/elements", s, name);
        bad |= mcs_results_write_int(r, p, 2, de, tri, "-", e) != MCS_OK;
    }
    free(pos);
    free(ori);
    return bad || !pos || !ori;
}

int main(void)
{
    char dir[] = "/tmp/mcrash_bench_report_XXXXXX", h5[96], html[96];
    if (!mkdtemp(dir)) return 1;
    snprintf(h5, sizeof h5, "%s/sample.h5", dir);
    snprintf(html, sizeof html, "%s/sample.html", dir);
    mcs_results *r = NULL;
    mcs_error e = {0};
    if (rs_write(h5) || mcs_results_append(&r, h5, &e) || more(r, 1, &e) ||
        more(r, 2, &e) || mcs_results_commit(&r, &e)) {
        fprintf(stderr, "bench_report: %s\n", e.msg);
        mcs_results_abort(&r);
        return 1;
    }
    tr_report_summary sum;
    double w0 = now(CLOCK_MONOTONIC), c0 = now(CLOCK_PROCESS_CPUTIME_ID);
    mcs_status st = tr_report_write(h5, html, NULL, &sum, &e);
    double w = now(CLOCK_MONOTONIC) - w0, c = now(CLOCK_PROCESS_CPUTIME_ID) - c0;
    if (st) fprintf(stderr, "bench_report: %s\n", e.msg);
    else
        printf("report of a 300 ms stage-1 + stage-2 file (215 channels, 32 bodies a stage): "
               "%.2f s wall, %.2f s CPU (issue 17: <= 5 s); page %zu bytes, %d plots\n",
               w, c, sum.bytes, sum.nsvg);
    remove(h5);
    remove(html);
    rmdir(dir);
    return st ? 1 : 0;
}

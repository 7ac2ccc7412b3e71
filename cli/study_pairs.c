/* study_pairs.c: a study with compare: runs every row of its design on two scenarios (the
 * ISO 13232 pairs: a motorcycle with a device against the same without it, in the same
 * configuration). Per row and response: the scenario's value, the compared one's, and compare -
 * base, as STUDY_pairs.csv; and a summary over the rows. */
#include "cli/study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int study_write_pairs(const study *s, const study_result *res, const char *csv)
{
    FILE *f = fopen(csv, "w");
    if (!f) return -1;
    fprintf(f, "row,code,status_base,status_compare");
    for (int i = 0; i < s->nresp; i++)
        fprintf(f, ",%s.base,%s.compare,%s.difference", s->r[i].name, s->r[i].name, s->r[i].name);
    fputc('\n', f);
    for (long w = 0; w < s->nrow; w++) {
        const study_result *a = &res[2 * w], *b = &res[2 * w + 1];
        fprintf(f, "%ld,%s,%d,%d", w, s->code ? s->code[w] : "", a->status, b->status);
        for (int i = 0; i < s->nresp; i++) {
            double v[3] = {a->v[i], b->v[i], b->v[i] - a->v[i]};
            for (int k = 0; k < 3; k++)
                isnan(v[k]) ? fprintf(f, ",NaN") : fprintf(f, ",%.17g", v[k]);
        }
        fputc('\n', f);
    }
    return fclose(f);
}

/* per response: the rows with both values, the mean of each side and of the difference, and
 * in how many rows the compared scenario's value is lower */
void study_pairs_summary(const study *s, const study_result *res, FILE *out)
{
    if (s->nvar != 2) return;
    fprintf(out, "study: compare - base over %ld rows (%s against %s):\n", s->nrow, s->alt_path,
            s->scenario);
    fprintf(out, "  %-28s %6s %12s %12s %12s %6s\n", "response", "rows", "mean base",
            "mean compare", "mean diff", "lower");
    for (int i = 0; i < s->nresp; i++) {
        long n = 0, lower = 0;
        double sa = 0, sb = 0;
        for (long w = 0; w < s->nrow; w++) {
            double a = res[2 * w].v[i], b = res[2 * w + 1].v[i];
            if (isnan(a) || isnan(b)) continue;
            n++, sa += a, sb += b, lower += b < a;
        }
        double ma = n ? sa / n : NAN, mb = n ? sb / n : NAN;
        fprintf(out, "  %-28s %6ld %12.4g %12.4g %12.4g %6ld\n", s->r[i].name, n, ma, mb,
                mb - ma, lower);
    }
}

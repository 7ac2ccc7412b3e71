/* test_scenario_copies: the restraint, motorcycle and opponent parameters are written once and
 * included, never copied (issue 16, item 4; docs/exchange.md "One design file"). Every YAML
 * file under scenarios/ (the verification cases and the rider models aside: they are not a
 * design's parameters) is read line by line; a line of a parameter block -- under
 * characteristics:, bodies:, joints:, fe:, stage2:, stage3:, or contacts: (the rider's own
 * contacts, lines naming rider_ bodies there, aside) -- of at least 40 characters once
 * comments and spacing are dropped, found in two files, is a copy: the test names both places.
 * A few laws one vehicle model assumes from another are accepted, listed with the reason.
 * The detector itself is checked on a belt definition pasted into two files. */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "harness.h"

#define MIN_LEN 40

typedef struct {
    char *text; /* the normalised line */
    int file;   /* index into the file names */
    int line;   /* 1-based */
} pline;

typedef struct {
    pline *v;
    int n, cap;
    char **files;
    int nfile;
} plines;

static const char *const sections[] = {"characteristics", "bodies", "joints", "fe",
                                       "stage2",          "stage3", "contacts"};

/* s without its comment and with runs of blanks as one space, in out */
static void normalise(const char *s, char *out, size_t n)
{
    size_t k = 0;
    int quote = 0, space = 0;
    for (; *s && *s != '\n' && k + 1 < n; s++) {
        if (*s == '"') quote = !quote;
        if (*s == '#' && !quote && (k == 0 || space)) break;
        if (*s == ' ' || *s == '\t') {
            space = 1;
            continue;
        }
        if (space && k) out[k++] = ' ';
        space = 0;
        out[k++] = *s;
    }
    out[k] = 0;
}

static void add_line(plines *p, const char *t, int file, int line)
{
    if (p->n == p->cap) {
        p->cap = p->cap ? 2 * p->cap : 1024;
        p->v = realloc(p->v, sizeof *p->v * (size_t)p->cap);
    }
    p->v[p->n++] = (pline){strdup(t), file, line};
}

/* the parameter lines of one file's text */
static void scan_text(plines *p, const char *name, const char *text)
{
    p->files = realloc(p->files, sizeof *p->files * (size_t)(p->nfile + 1));
    p->files[p->nfile] = strdup(name);
    const int f = p->nfile++;
    char top[64] = "", norm[1024];
    int line = 0;
    for (const char *s = text; *s; s = strchr(s, '\n') ? strchr(s, '\n') + 1 : s + strlen(s)) {
        line++;
        normalise(s, norm, sizeof norm);
        if (!norm[0]) continue;
        if (s[0] != ' ' && s[0] != '-' && s[0] != '\t') {
            size_t k = strcspn(norm, ":");
            snprintf(top, sizeof top, "%.*s", (int)(k < 63 ? k : 63), norm);
        }
        int in = 0;
        for (size_t i = 0; i < sizeof sections / sizeof sections[0]; i++)
            in |= strcmp(top, sections[i]) == 0;
        if (!in || strlen(norm) < MIN_LEN) continue;
        if (strcmp(top, "contacts") == 0 && strstr(norm, "rider_")) continue;
        add_line(p, norm, f, line);
    }
}

static int by_text(const void *a, const void *b)
{
    const pline *x = a, *y = b;
    int c = strcmp(x->text, y->text);
    return c ? c : x->file != y->file ? x->file - y->file : x->line - y->line;
}

/* copies accepted, with the reason: one vehicle model's law assumed for another vehicle. Each
 * vehicle keeps its own named characteristics (a characteristic cannot name another's law, and
 * a vehicle model is the unit a study varies); the values and their source are in
 * docs/models.md. Each entry must still be a copy (a stale entry fails). */
static const char *const accepted[] = {
    /* the sedan's upper-body laws (side glass, windshield, roof, hood) for the B-segment car */
    "loading: [[0, 0], [10 mm, 3 kN], [100 mm, 3.5 kN], [150 mm, 30 kN]]",
    "loading: [[0, 0], [20 mm, 4 kN], [80 mm, 6 kN], [150 mm, 30 kN]]",
    "loading: [[0, 0], [30 mm, 3 kN], [100 mm, 8 kN], [150 mm, 40 kN]]",
    "loading: [[0, 0], [30 mm, 3 kN], [80 mm, 5 kN], [120 mm, 40 kN]]",
    /* the sedan's door law for MYMOSA's one lateral law of the 1100 kg car */
    "loading: [[0, 0], [20 mm, 9 kN], [150 mm, 16 kN], [300 mm, 24 kN], [450 mm, 32 kN], "
    "[550 mm, 120 kN]]",
    /* the roof rail law of the sedan and the 1100 kg car */
    "loading: [[0, 0], [30 mm, 15 kN], [100 mm, 40 kN], [150 mm, 150 kN]]",
};
#define NACCEPTED ((int)(sizeof accepted / sizeof accepted[0]))

static int accepted_at(const char *t)
{
    for (int i = 0; i < NACCEPTED; i++)
        if (strcmp(t, accepted[i]) == 0) return i;
    return -1;
}

/* lines found in two files, the accepted ones aside (seen[i] set for accepted[i] found); each
 * printed once with its places when verbose */
static int copies(plines *p, int verbose, int *seen)
{
    qsort(p->v, (size_t)p->n, sizeof *p->v, by_text);
    int n = 0;
    for (int i = 0; i < p->n;) {
        int j = i + 1, other = 0;
        while (j < p->n && strcmp(p->v[j].text, p->v[i].text) == 0) {
            other |= p->v[j].file != p->v[i].file;
            j++;
        }
        int a = other && seen ? accepted_at(p->v[i].text) : -1;
        if (a >= 0) seen[a] = 1;
        if (other && a < 0) {
            n++;
            if (verbose) {
                fprintf(stderr, "copied parameter line: %s\n", p->v[i].text);
                for (int k = i; k < j; k++)
                    fprintf(stderr, "  %s:%d\n", p->files[p->v[k].file], p->v[k].line);
            }
        }
        i = j;
    }
    return n;
}

static void plines_free(plines *p)
{
    for (int i = 0; i < p->n; i++) free(p->v[i].text);
    for (int i = 0; i < p->nfile; i++) free(p->files[i]);
    free(p->v);
    free(p->files);
    memset(p, 0, sizeof *p);
}

/* every .yaml under dir, the skipped folders aside */
static void scan_dir(plines *p, const char *dir, int *nfiles)
{
    if (strcmp(dir, "scenarios/verification") == 0 || strcmp(dir, "scenarios/models/riders") == 0)
        return;
    DIR *d = opendir(dir);
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        struct stat sb;
        if (stat(path, &sb) != 0) continue;
        size_t l = strlen(e->d_name);
        if (S_ISDIR(sb.st_mode)) {
            scan_dir(p, path, nfiles);
        } else if (l > 5 && strcmp(e->d_name + l - 5, ".yaml") == 0) {
            char *t = th_slurp(path, NULL);
            if (t) scan_text(p, path, t), (*nfiles)++;
            free(t);
        }
    }
    closedir(d);
}

/* the detector: a belt pasted into two files is one copy (its two long lines count once
 * each); the same belt included, the rider's own contacts and comments are not */
static void test_detector(void)
{
    static const char *belt =
        "fe:\n  parts:\n    - name: belt_l\n"
        "      mesh: {generate: line, origin: [0.7 m, 0.06 m, 0.87 m],"
        " end: [0.7 m, 0.27 m, 0.87 m], divisions: 10}\n"
        "      section: {type: truss, area: 60 mm^2, tension_only: true}   # webbing\n";
    static const char *rider =
        "contacts:\n  - {name: rider_head_road, a: rider_head, b: ground, characteristic: "
        "rider_torso, friction: 0.5}\n# section: {type: truss, area: 60 mm^2, tension_only: "
        "true}\n";
    plines p = {0};
    scan_text(&p, "a.yaml", belt);
    scan_text(&p, "b.yaml", "include: [a.yaml]\nfe:\n  parts:\n    - name: belt_l\n");
    scan_text(&p, "c.yaml", rider);
    scan_text(&p, "d.yaml", rider);
    CHECK(copies(&p, 0, NULL) == 0);
    plines_free(&p);
    scan_text(&p, "a.yaml", belt);
    scan_text(&p, "b.yaml", belt);
    CHECK(copies(&p, 0, NULL) == 2);
    plines_free(&p);
}

static void test_scenarios(void)
{
    plines p = {0};
    int nfiles = 0;
    scan_dir(&p, "scenarios", &nfiles);
    int seen[NACCEPTED] = {0}, stale = 0;
    int n = copies(&p, 1, seen);
    for (int i = 0; i < NACCEPTED; i++)
        if (!seen[i]) fprintf(stderr, "accepted copy no longer a copy: %s\n", accepted[i]);
    for (int i = 0; i < NACCEPTED; i++) stale += !seen[i];
    printf("  %d scenario and model files, %d parameter lines, %d copied (%d accepted: one "
           "vehicle's law assumed for another)\n",
           nfiles, p.n, n, NACCEPTED - stale);
    CHECK(nfiles > 20 && p.n > 200);
    CHECK(n == 0 && stale == 0);
    plines_free(&p);
}

int main(void)
{
    RUN(test_detector);
    RUN(test_scenarios);
    TEST_END();
}

/* test_couple_errors.c: bad input of a coupled stage-1 scenario (bodies + fe:, issue 12 item 6)
 * through the command, as a user meets it: `mcrash check`, `mcrash run` and `mcrash stage1` each
 * exit with status 2, print FILE:LINE:COL of the offending key with its key path and the reason,
 * and leave no results file (nor its temporary) behind; no crash, no sanitizer report.
 *
 * One valid scenario (BASE_YAML: a frame body carrying a bag by attach, a belt through a slip
 * ring and a retractor anchored on it, a ball in a stage-1 contact with the ground that triggers
 * the inflator and the pretensioner, a fixed plate in a `type: bodies` contact with the ball)
 * runs with status 0; each case edits one thing in it. The reference for the place of an error
 * is the text itself: the case names the text the message must point at (unique in the edited
 * scenario), and the test turns its offset into line and column (1-based, as YAML editors
 * count), independently of the parser. docs/stage1_engine.md "Errors" lists these refusals. */
#include "cli_util.h"
#include "harness.h"

#include <dirent.h>
#include <limits.h>
#include <sys/stat.h>

#define BASE_YAML                                                                                  \
    "mcrash: 1\n"                                                                                  \
    "name: errs\n"                                                                                 \
    "simulation: {end_time: 1 ms, time_step: 10 us, output_rate: 10 kHz}\n"                        \
    "environment: {gravity: 9.81, ground: {height: 0}}\n"                                          \
    "characteristics:\n"                                                                           \
    "  pad: {loading: [[0, 0], [0.01, 1000]], damping: 0, friction: 0}\n"                          \
    "bodies:\n"                                                                                    \
    "  - {name: moto_frame, mass: 50, inertia: [1, 2, 2.5], position: [0.5, 0, 0.8], velocity: "   \
    "[0, 0, 0],\n"                                                                                 \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.2, 0.2, 0.2]}]}\n"         \
    "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004], position: [0, 0, 0.2], velocity: "  \
    "[0, 0, 0],\n"                                                                                 \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"         \
    "  - {name: bare, mass: 1, inertia: [1, 1, 1], position: [3, 0, 1], velocity: [0, 0, 0]}\n"    \
    "contacts:\n"                                                                                  \
    "  - {name: ball_ground, a: ball, b: ground, characteristic: pad}\n"                           \
    "fe:\n"                                                                                        \
    "  parts:\n"                                                                                   \
    "    - name: fabric\n"                                                                         \
    "      mesh: {generate: sphere_shell, origin: [1, 0, 0.5], radius: 100 mm, element_size: 60 "  \
    "mm}\n"                                                                                        \
    "      section: {type: membrane, thickness: 0.5 mm}\n"                                         \
    "      material: {model: fabric, density: 1000, youngs_modulus: 500 MPa, poisson: 0.3}\n"      \
    "      attach: {body: moto_frame, where: z_min}\n"                                             \
    "    - name: belt\n"                                                                           \
    "      mesh: {generate: line, origin: [1, 1, 0.5], end: [1.5, 1, 0.5], divisions: 4}\n"        \
    "      section: {type: truss, area: 1e-6, tension_only: true}\n"                               \
    "      material: {model: elastic, density: 1000, youngs_modulus: 1 GPa, poisson: 0}\n"         \
    "    - name: plate\n"                                                                          \
    "      mesh: {generate: plate, origin: [0, 0, 0.05], size: [0.2, 0.2], divisions: [2, 2]}\n"   \
    "      section: {type: shell, thickness: 2 mm}\n"                                              \
    "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"     \
    "  boundary:\n"                                                                                \
    "    - {part: belt, where: x_max, fix: all}\n"                                                 \
    "    - {part: plate, where: all, fix: all}\n"                                                  \
    "  contacts:\n"                                                                                \
    "    - {type: bodies, parts: [plate], bodies: [ball], friction: 0.3}\n"                        \
    "  airbags:\n"                                                                                 \
    "    - name: bag\n"                                                                            \
    "      parts: [fabric]\n"                                                                      \
    "      inflator: {mass_flow: [[0, 0.1], [1, 0.1]], temperature: [[0, 600 K]],\n"               \
    "                 trigger: {contact: ball_ground, force: 10 N, delay: 1 ms}}\n"                \
    "  sliprings: [{name: ring, part: belt, point: [1.25, 1, 0.5], body: moto_frame}]\n"           \
    "  retractors:\n"                                                                              \
    "    - {name: ret, part: belt, where: x_min, anchor: [0.5, 1, 0.5], anchor_body: "             \
    "moto_frame,\n"                                                                                \
    "       load_limit: 2 kN, trigger: {contact: ball_ground, force: 50 N, delay: 2 ms}}\n"

/* with impact: the moto_* group (moto_frame, and the parts it carries) is placed and set moving;
 * the belt is then carried by moto_frame (ring, anchor) and may not be held in the world */
#define IMPACT_BLOCK                                                                               \
    "impact: {heading_angle: 30 deg, motorcycle_speed: 10 m/s, motorcycle_contact: [1.2, 0, "      \
    "0.3],\n"                                                                                      \
    "         opponent_contact: [3.0, 1.0, 0.3], initial_gap: 0.1}\n"

typedef struct {
    const char *name;
    int impact;       /* on the impact base */
    const char *from; /* replaced (first occurrence) */
    const char *to;
    const char *at;  /* the text the message must point at (unique in the edited scenario) */
    const char *key; /* key path in the message */
    const char *why; /* reason in the message */
} bad_case;

static const bad_case cases[] = {
    /* fe.parts[].attach */
    {"attach to an unknown body", 0, "body: moto_frame, where", "body: moto_frmae, where",
     "moto_frmae", "fe.parts[0].attach.body", "unknown body 'moto_frmae'"},
    {"attach: {} (no body)", 0, "attach: {body: moto_frame, where: z_min}", "attach: {}", "{}",
     "fe.parts[0].attach.body", "required key is missing"},
    {"attach where: a mapping", 0, "where: z_min}", "where: {x: 1}}", "{x: 1}",
     "fe.parts[0].attach.where", "expected a string"},
    {"attach to the ground", 0, "body: moto_frame, where", "body: ground, where", "ground, where",
     "fe.parts[0].attach.body", "unknown body 'ground'"},
    {"attach on a missing keyword part", 0, "    - name: belt\n",
     "    - name: kbar\n      mesh: {keyword: %KW%, part: 99, units: mm-s-t}\n"
     "      attach: {body: moto_frame, where: x_min}\n    - name: belt\n",
     "99, units", "fe.parts[1].mesh.part", "no *PART 99"},
    {"boundary on attached nodes", 0, "    - {part: plate, where: all, fix: all}\n",
     "    - {part: plate, where: all, fix: all}\n    - {part: fabric, where: z_min, fix: x}\n",
     "z_min, fix: x", "fe.boundary[2].where", "that body 'moto_frame' carries"},
    {"boundary on a slip ring's node", 0, "{part: belt, where: x_max, fix: all}",
     "{part: belt, where: all, fix: z}", "all, fix: z", "fe.boundary[0].where",
     "nodes of part 'belt' that body 'moto_frame' carries"},
    {"attach on a rigid part", 0, "membrane, thickness: 0.5 mm}\n      material: {model: fabric,",
     "shell, thickness: 0.5 mm}\n      material: {model: rigid,",
     "{body: moto_frame, where: z_min}", "fe.parts[0].attach", "part 'fabric' is rigid"},
    {"slip ring on an attached node", 0, "poisson: 0}\n    - name: plate",
     "poisson: 0}\n      attach: {body: ball, where: all}\n    - name: plate", "moto_frame}]",
     "fe.sliprings[0].body", "that body 'ball' carries already"},
    /* contact names (they key the channels and the triggers) */
    {"stage-1 contact named twice", 0, "characteristic: pad}\n",
     "characteristic: pad}\n  - {name: ball_ground, a: moto_frame, b: ground, characteristic: "
     "pad}\n",
     "ball_ground, a: moto_frame", "contacts[1].name", "duplicate name 'ball_ground'"},
    {"two unnamed contacts of one pair", 0, "characteristic: pad}\n",
     "characteristic: pad}\n  - {a: moto_frame, b: ground, characteristic: pad}\n"
     "  - {a: ground, b: moto_frame, characteristic: pad}\n",
     "{a: ground, b: moto_frame", "contacts[2]", "'moto_frame-ground' is also contacts[1]'s"},
    {"FE contact named twice", 0, "    - {type: bodies, parts: [plate], bodies: [ball]",
     "    - {name: c1, type: bodies, parts: [plate], bodies: [moto_frame]}\n"
     "    - {name: c1, type: bodies, parts: [plate], bodies: [ball]",
     "c1, type: bodies, parts: [plate], bodies: [ball]", "fe.contacts[1].name",
     "duplicate name 'c1'"},
    /* fe.contacts[] of type: bodies */
    {"bodies contact: unknown body", 0, "bodies: [ball]", "bodies: [bal1]", "bal1",
     "fe.contacts[0].bodies[0]", "unknown body 'bal1'"},
    {"bodies contact: body without surfaces", 0, "bodies: [ball]", "bodies: [ball, bare]", "bare]",
     "fe.contacts[0].bodies[1]", "no ellipsoid or facet surfaces"},
    {"bodies contact: unknown part", 0, "parts: [plate]", "parts: [plat]", "plat]",
     "fe.contacts[0].parts[0]", "unknown FE part 'plat'"},
    {"bodies contact: no parts", 0, "parts: [plate]", "parts: []", "[], bodies",
     "fe.contacts[0].parts", "at least 1 value"},
    {"bodies contact: no bodies", 0, "bodies: [ball]", "bodies: []", "[], friction",
     "fe.contacts[0].bodies", "at least 1 value"},
    /* triggers */
    {"inflator trigger: unknown contact", 0, "contact: ball_ground, force: 10 N",
     "contact: ball_gruond, force: 10 N", "ball_gruond", "fe.airbags[0].inflator.trigger.contact",
     "unknown stage-1 contact 'ball_gruond'"},
    {"retractor trigger: unknown contact", 0, "contact: ball_ground, force: 50 N",
     "contact: ball_gruond, force: 50 N", "ball_gruond", "fe.retractors[0].trigger.contact",
     "unknown stage-1 contact 'ball_gruond'"},
    {"trigger: an FE contact's name", 0, "contact: ball_ground, force: 10 N",
     "contact: contact0, force: 10 N", "contact0", "fe.airbags[0].inflator.trigger.contact",
     "unknown stage-1 contact 'contact0'"},
    {"trigger: no contact", 0, "trigger: {contact: ball_ground, force: 50 N, delay: 2 ms}",
     "trigger: {}", "{}", "fe.retractors[0].trigger.contact", "required key is missing"},
    {"trigger: negative delay", 0, "delay: 1 ms", "delay: -1 ms", "-1 ms",
     "fe.airbags[0].inflator.trigger.delay", "must be >= 0"},
    {"trigger: negative force", 0, "force: 50 N", "force: -50 N", "-50 N",
     "fe.retractors[0].trigger.force", "must be >= 0"},
    {"trigger: force as a word", 0, "force: 50 N", "force: fifty", "fifty",
     "fe.retractors[0].trigger.force", "expected a force (N)"},
    {"trigger: force in seconds", 0, "force: 50 N", "force: 50 ms", "50 ms",
     "fe.retractors[0].trigger.force", "is a time (s), expected a force (N)"},
    {"trigger beside fire_time", 0, "load_limit: 2 kN,", "load_limit: 2 kN, fire_time: 1 ms,",
     "1 ms, trigger", "fe.retractors[0].fire_time", "fire_time and trigger exclude each other"},
    /* airbags */
    {"airbag: surface not closed", 0, "parts: [fabric]", "parts: [plate]", "[plate]\n",
     "fe.airbags[0].parts", "the surface is not closed"},
    {"airbag: truss part", 0, "parts: [fabric]", "parts: [belt]", "[belt]", "fe.airbags[0].parts",
     "must be made of shells or membranes"},
    {"two airbags share a part", 0, "  sliprings:",
     "    - name: bag2\n      parts: [fabric]\n"
     "      inflator: {mass_flow: [[0, 0.2], [1, 0.2]], temperature: [[0, 600 K]]}\n"
     "  sliprings:",
     "fabric]\n      inflator: {mass_flow: [[0, 0.2]", "fe.airbags[1].parts[0]",
     "part 'fabric' is already in airbag 'bag'"},
    {"airbag: a part twice", 0, "parts: [fabric]", "parts: [fabric, fabric]", "fabric]\n",
     "fe.airbags[0].parts[1]", "already in airbag 'bag'"},
    /* anchors on bodies */
    {"retractor anchor_body: unknown", 0, "anchor_body: moto_frame", "anchor_body: moto", "moto,",
     "fe.retractors[0].anchor_body", "unknown body 'moto'"},
    {"slip ring body: unknown", 0, "body: moto_frame}]", "body: motoframe}]", "motoframe",
     "fe.sliprings[0].body", "unknown body 'motoframe'"},
    {"two slip rings on one element", 0, "body: moto_frame}]",
     "body: moto_frame}, {name: ring2, part: belt, point: [1.375, 1, 0.5], body: ball}]",
     "{name: ring2", "fe.sliprings[1]", "share a belt element"},
    /* impact placement */
    {"impact: part carried by two groups", 1, "body: moto_frame}]", "body: ball}]", "ball}]",
     "fe.sliprings[0].body", "bodies of two groups"},
    {"impact: moved part held in the world", 1, "    - {part: plate, where: all, fix: all}\n",
     "    - {part: plate, where: all, fix: all}\n    - {part: belt, where: x_max, fix: all}\n",
     "{part: belt", "fe.boundary[1]", "moves with the impact placement"},
    {"impact: ground anchor on a moved part", 1, " anchor_body: moto_frame,", "", "[0.5, 1, 0.5]",
     "fe.retractors[0].anchor", "fixed to the ground"},
    {"impact: initial_velocity on a carried part", 1,
     "      attach:", "      initial_velocity: [1, 0, 0]\n      attach:", "[1, 0, 0]\n",
     "fe.parts[0].initial_velocity", "remove initial_velocity"},
};

static char tmpdir[64];
static char kwpath[PATH_MAX];

/* first occurrence of from replaced by to, into out (n bytes); 0 when from is absent */
static int replace(char *out, size_t n, const char *text, const char *from, const char *to)
{
    const char *p = strstr(text, from);
    if (!p) return 0;
    snprintf(out, n, "%.*s%s%s", (int)(p - text), text, to, p + strlen(from));
    return 1;
}

static void scenario(const bad_case *c, char *y, size_t n)
{
    static char a[16384], b[16384];
    snprintf(a, sizeof a, "%s", BASE_YAML);
    if (c && c->impact) { /* the belt's world boundary goes: the placement refuses it */
        CHECK(replace(b, sizeof b, a, "contacts:\n  - {name: ball_ground",
                      IMPACT_BLOCK "contacts:\n  - {name: ball_ground"));
        CHECK(replace(a, sizeof a, b, "    - {part: belt, where: x_max, fix: all}\n", ""));
    }
    if (!c) {
        snprintf(y, n, "%s", a);
        return;
    }
    char to[1024];
    snprintf(to, sizeof to, "%s", c->to);
    char *kw = strstr(to, "%KW%");
    if (kw) {
        char tail[1024];
        snprintf(tail, sizeof tail, "%s", kw + 4);
        snprintf(kw, sizeof to - (size_t)(kw - to), "%s%s", kwpath, tail);
    }
    CHECK(replace(y, n, a, c->from, to));
}

/* "bad.yaml:LINE:COL:" of the unique occurrence of at in y; "" when absent or not unique */
static void location(const char *y, const char *at, char *loc, size_t n)
{
    loc[0] = 0;
    const char *p = strstr(y, at);
    if (!p || strstr(p + 1, at)) return;
    int line = 1, col = 1;
    for (const char *q = y; q < p; q++) {
        col++;
        if (*q == '\n') line++, col = 1;
    }
    snprintf(loc, n, "bad.yaml:%d:%d: ", line, col);
}

static int count_files(const char *dir)
{
    DIR *d = opendir(dir);
    int k = 0;
    if (!d) return -1;
    for (struct dirent *e; (e = readdir(d));)
        if (e->d_name[0] != '.') k++;
    closedir(d);
    return k;
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

/* the base runs: the refusals below are the edits' */
static void test_base_runs(void)
{
    static char y[16384];
    char path[128], args[512];
    snprintf(path, sizeof path, "%s/bad.yaml", tmpdir);
    for (int imp = 0; imp < 2; imp++) {
        bad_case c = {.impact = imp, .from = "name: errs", .to = "name: errs"};
        scenario(&c, y, sizeof y);
        write_file(path, y);
        snprintf(args, sizeof args, "run %s -o %s/out/ok.h5 --quiet", path, tmpdir);
        cli_result *r = cli_run(args);
        if (r->status) fprintf(stderr, "base (impact %d): %s", imp, r->err);
        CHECK(r->status == 0);
        snprintf(args, sizeof args, "check %s", path);
        CHECK(cli_run(args)->status == 0);
        snprintf(args, sizeof args, "%s/out/ok.h5", tmpdir);
        CHECK(remove(args) == 0);
    }
}

static void test_refusals(void)
{
    static char y[16384];
    char path[128], out[160], outdir[128], args[512], loc[64];
    snprintf(path, sizeof path, "%s/bad.yaml", tmpdir);
    snprintf(outdir, sizeof outdir, "%s/out", tmpdir);
    snprintf(out, sizeof out, "%s/x.h5", outdir);
    const char *cmds[3] = {"check", "run", "stage1"};
    int n = (int)(sizeof cases / sizeof cases[0]);
    for (int i = 0; i < n; i++) {
        const bad_case *c = &cases[i];
        scenario(c, y, sizeof y);
        location(y, c->at, loc, sizeof loc);
        CHECK(loc[0] != 0); /* the text pointed at is in the scenario once */
        write_file(path, y);
        for (int k = 0; k < 3; k++) {
            if (k == 0)
                snprintf(args, sizeof args, "check %s", path);
            else
                snprintf(args, sizeof args, "%s %s -o %s --quiet", cmds[k], path, out);
            cli_result *r = cli_run(args);
            int ok = r->status == 2 && strstr(r->err, loc) && strstr(r->err, c->key) &&
                     strstr(r->err, c->why) && !strstr(r->err, "Sanitizer") &&
                     !strstr(r->err, "runtime error") && count_files(outdir) == 0 && r->out[0] == 0;
            CHECK(ok);
            if (!ok)
                fprintf(stderr, "  %s / %s: status %d, want %s%s: ...%s; got: %s", c->name, cmds[k],
                        r->status, loc, c->key, c->why, r->err);
            if (k == 1 && ok) printf("%-42s %s", c->name, r->err);
        }
    }
    printf("%d cases x check, run, stage1: exit 2 at the key, no file\n", n);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_cerr_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    char d[128];
    snprintf(d, sizeof d, "%s/out", tmpdir);
    mkdir(d, 0700);
    if (!realpath("tests/data/keyword/bar_mm.k", kwpath)) snprintf(kwpath, sizeof kwpath, "-");
    RUN(test_base_runs);
    RUN(test_refusals);
    char cmd[160];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd)) printf("could not remove %s\n", tmpdir);
    TEST_END();
}

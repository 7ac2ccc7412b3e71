/* tests for the scenario reader (core/mcs_scenario.h) and `mcrash check`.
 * Run from the repository root (make test does): paths below are relative to it. */
#include "tests/cli_util.h"
#include "tests/harness.h"
#include "core/mcs_scenario.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define PI 3.14159265358979323846
#define DATA "tests/data/scenarios/"

static mcs_scenario *load_ok(const char *path)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    mcs_status st = mcs_scenario_load(path, &scn, &err);
    if (st) fprintf(stderr, "unexpected error: %s\n", err.msg);
    CHECK(st == MCS_OK);
    CHECK(scn != NULL);
    return scn;
}

/* number at a path of keys and indices: "bodies", "#0", "mass" */
static const mcs_node *at(const mcs_node *n, const char *const *path, int len)
{
    for (int i = 0; i < len && n; i++)
        n = path[i][0] == '#' ? mcs_node_at(n, atoi(path[i] + 1)) : mcs_node_get(n, path[i]);
    return n;
}
#define AT(root, ...)                                                                              \
    at((root), (const char *const[]){__VA_ARGS__},                                                 \
       (int)(sizeof((const char *const[]){__VA_ARGS__}) / sizeof(const char *)))

static void test_sphere_drop_reads_in_si(void)
{
    mcs_scenario *scn = load_ok("scenarios/verification/sphere_drop.yaml");
    const mcs_node *r = mcs_scenario_root(scn);
    CHECK(mcs_node_kind(r) == MCS_NODE_MAP);
    CHECK_NEAR(mcs_node_num(AT(r, "simulation", "end_time")), 0.2, 0);
    CHECK(mcs_node_num(AT(r, "simulation", "time_step")) == 1e-5); /* "10 us", exactly */
    CHECK_NEAR(mcs_node_num(AT(r, "simulation", "output_rate")), 1e4, 0);
    CHECK_NEAR(mcs_node_num(AT(r, "environment", "gravity")), 9.81, 0);
    const mcs_node *ball = AT(r, "bodies", "#0");
    CHECK(strcmp(mcs_node_str(mcs_node_get(ball, "name")), "ball") == 0);
    double p[3], x[4], y[4];
    mcs_error err = {0};
    CHECK(mcs_node_vec3(mcs_node_get(ball, "position"), p, &err) == MCS_OK);
    CHECK_NEAR(p[2], 0.5, 0);
    const mcs_node *load = AT(r, "characteristics", "linear_pad", "loading");
    CHECK(mcs_node_curve_len(load) == 2);
    CHECK(mcs_node_curve(load, x, y, 4, &err) == MCS_OK);
    CHECK_NEAR(x[1], 0.01, 0);
    CHECK_NEAR(y[1], 1000, 0);
    CHECK(mcs_node_kind(AT(r, "characteristics", "linear_pad", "unloading")) == MCS_NODE_NULL);
    /* where things were written, and their paths */
    const mcs_node *mass = mcs_node_get(ball, "mass");
    CHECK(mcs_node_line(mass) == 16);
    CHECK(mcs_node_col(mass) == 11);
    CHECK(strcmp(mcs_node_path(mass), "bodies[0].mass") == 0);
    CHECK(strcmp(mcs_node_text(mass), "1 kg") == 0);
    CHECK_STR_CONTAINS(mcs_node_file(mass), "sphere_drop.yaml");
    mcs_scenario_destroy(&scn);
    CHECK(scn == NULL);
}

static void test_units_in_every_kind_of_key(void)
{
    mcs_scenario *scn = load_ok(DATA "good/units_everywhere.yaml");
    const mcs_node *r = mcs_scenario_root(scn);
    CHECK_NEAR(mcs_node_num(AT(r, "environment", "gravity")), 9.80665, 1e-15); /* "1 g" */
    CHECK_NEAR(mcs_node_num(AT(r, "environment", "ground", "height")), -0.05, 1e-15);
    CHECK_NEAR(mcs_node_num(AT(r, "characteristics", "hinge", "loading", "#1", "#0")), PI / 2,
               1e-15);
    CHECK_NEAR(mcs_node_num(AT(r, "characteristics", "hinge", "loading", "#1", "#1")), 2000, 0);
    CHECK_NEAR(mcs_node_num(AT(r, "characteristics", "hinge", "unloading_slope")), 1000, 0);
    CHECK_NEAR(mcs_node_num(AT(r, "bodies", "#0", "velocity", "#0")), 48.5 / 3.6, 1e-12);
    CHECK_NEAR(mcs_node_num(AT(r, "bodies", "#0", "angular_velocity", "#2")), 2 * PI, 1e-12);
    CHECK_NEAR(mcs_node_num(AT(r, "bodies", "#0", "orientation", "#1")), 5 * PI / 180, 1e-15);
    CHECK_NEAR(mcs_node_num(AT(r, "bodies", "#0", "position", "#2")), 0.9, 1e-15);
    CHECK_NEAR(mcs_node_num(AT(r, "bodies", "#1", "velocity", "#0")), 30 * 0.44704, 1e-12);
    CHECK(strcmp(mcs_node_str(AT(r, "joints", "#1", "restraint")), "hinge") == 0);
    CHECK_NEAR(mcs_node_num(AT(r, "attachments", "#0", "stiffness")), 5e4, 0);
    CHECK_NEAR(mcs_node_num(AT(r, "attachments", "#0", "failure_force")), 2e3, 0);
    CHECK_NEAR(mcs_node_num(AT(r, "sensors", "#0", "cfc")), 1000, 0);
    CHECK_NEAR(mcs_node_num(AT(r, "impact", "heading_angle")), PI / 2, 1e-15);
    CHECK(strcmp(mcs_node_str(AT(r, "impact", "code")), "413-0/13.4") == 0);
    CHECK(strcmp(mcs_node_str(AT(r, "impact", "motorcycle_bodies", "#1")), "rider") == 0);
    CHECK_NEAR(mcs_node_num_or(AT(r, "contacts", "#0"), "friction", -1), 0.3, 0);
    CHECK_NEAR(mcs_node_num_or(AT(r, "contacts", "#0"), "absent", -1), -1, 0);
    mcs_scenario_destroy(&scn);
}

/* top.yaml includes base.yaml then parts/extra.yaml (which includes leaf.yaml beside it) */
static void test_include_merge_rule(void)
{
    mcs_scenario *scn = load_ok(DATA "include/top.yaml");
    const mcs_node *r = mcs_scenario_root(scn);
    CHECK(mcs_node_get(r, "include") == NULL);
    CHECK(strcmp(mcs_node_str(mcs_node_get(r, "name")), "top") == 0); /* scalar: includer wins */
    /* entity lists concatenate, included first: base [A], extra [L (its include), B], top [C] */
    const mcs_node *bodies = mcs_node_get(r, "bodies");
    CHECK(mcs_node_len(bodies) == 4);
    const char *order[] = {"A", "L", "B", "C"};
    for (int i = 0; i < 4 && i < mcs_node_len(bodies); i++) {
        const char *name = mcs_node_str(mcs_node_get(mcs_node_at(bodies, i), "name"));
        CHECK(name && strcmp(name, order[i]) == 0);
    }
    CHECK_NEAR(mcs_node_num(AT(bodies, "#1", "mass")), 0.5, 0); /* "500 g" is a mass */
    /* maps merge recursively: friction from the later include, damping from top, loading kept */
    const mcs_node *pad = AT(r, "characteristics", "pad");
    CHECK_NEAR(mcs_node_num(mcs_node_get(pad, "friction")), 0.5, 0);
    CHECK_NEAR(mcs_node_num(mcs_node_get(pad, "damping")), 20, 0);
    CHECK(mcs_node_curve_len(mcs_node_get(pad, "loading")) == 2);
    CHECK_NEAR(mcs_node_num(AT(r, "simulation", "time_step")), 1e-3, 0);
    /* nodes remember the file they came from */
    CHECK_STR_CONTAINS(mcs_node_file(AT(bodies, "#0", "mass")), "include/base.yaml");
    CHECK_STR_CONTAINS(mcs_node_file(AT(bodies, "#1", "mass")), "include/parts/leaf.yaml");
    CHECK(mcs_node_line(AT(bodies, "#1", "mass")) == 3);
    CHECK_STR_CONTAINS(mcs_node_file(mcs_node_get(pad, "damping")), "include/top.yaml");
    /* the source text holds every file read */
    const char *text = mcs_scenario_text(scn);
    CHECK_STR_CONTAINS(text, "# === mcrash source: " DATA "include/top.yaml");
    CHECK_STR_CONTAINS(text, "# === mcrash source: " DATA "include/parts/leaf.yaml");
    CHECK_STR_CONTAINS(text, "name: L, mass: 500 g");
    mcs_scenario_destroy(&scn);
}

static char *resolved_json(const char *path)
{
    mcs_scenario *scn = load_ok(path);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    CHECK(f && scn && mcs_scenario_write_json(scn, f) == MCS_OK);
    if (f) fclose(f);
    mcs_scenario_destroy(&scn);
    return buf;
}

/* override_top.yaml includes override_base.yaml and names its entries again: the resolved tree
 * is override_merged.yaml, the expected result written out by hand (the rule, not the code) */
static void test_include_override_by_name(void)
{
    char *got = resolved_json(DATA "include/override_top.yaml");
    char *want = resolved_json(DATA "include/override_merged.yaml");
    CHECK(got && want && strcmp(got, want) == 0);
    if (got && want && strcmp(got, want)) fprintf(stderr, "got:\n%s\nwant:\n%s\n", got, want);
    free(got);
    free(want);
    /* a merged entry keeps each node's origin: B's mass from top, its inertia from base */
    mcs_scenario *scn = load_ok(DATA "include/override_top.yaml");
    const mcs_node *b = AT(mcs_scenario_root(scn), "bodies", "#1");
    CHECK_STR_CONTAINS(mcs_node_file(mcs_node_get(b, "mass")), "include/override_top.yaml");
    CHECK_STR_CONTAINS(mcs_node_file(mcs_node_get(b, "inertia")), "include/override_base.yaml");
    CHECK(strcmp(mcs_node_path(mcs_node_get(b, "mass")), "bodies[1].mass") == 0);
    mcs_scenario_destroy(&scn);
}

static void test_include_diamond_is_not_a_cycle(void)
{
    mcs_scenario *scn = load_ok(DATA "include/diamond_top.yaml");
    const mcs_node *r = mcs_scenario_root(scn);
    CHECK(strcmp(mcs_node_str(mcs_node_get(r, "name")), "right") == 0);
    /* a curve given twice is a value: replaced, not concatenated */
    CHECK(mcs_node_curve_len(AT(r, "characteristics", "soft", "loading")) == 2);
    mcs_scenario_destroy(&scn);
}

static void test_include_cycle_reports_chain(void)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    CHECK(mcs_scenario_load(DATA "bad/include_cycle_a.yaml", &scn, &err) == MCS_ERR_INCLUDE);
    CHECK(scn == NULL);
    CHECK_STR_CONTAINS(err.msg, "include_cycle_b.yaml:2:11: error: include: include cycle: ");
    CHECK_STR_CONTAINS(err.msg, "include_cycle_a.yaml -> " DATA "bad/include_cycle_b.yaml -> ");
}

/* ---- malformed scenarios: status, position and key of the message ---- */

typedef struct {
    const char *file;  /* under tests/data/scenarios/bad/ */
    mcs_status status; /* expected status */
    const char *where; /* "LINE:COL" in the file named by the message */
    const char *what;  /* key path and words expected in the message */
} bad_case;

static const bad_case bad_cases[] = {
    {"alias", MCS_ERR_YAML, "14:42", "aliases (*p) are not supported"},
    {"attachment_negative_failure", MCS_ERR_RANGE, "15:21",
     "attachments[0].failure_force: must be > 0 N (got -5000 N)"},
    {"bad_enum_joint", MCS_ERR_RANGE, "14:12", "joints[0].type: 'sphercal' is not one of"},
    {"binary_control", MCS_ERR_FORMAT, "2:3", "binary data: control byte 0x01"},
    {"binary_nul", MCS_ERR_FORMAT, "2:8", "binary data: NUL byte"},
    {"comments_only", MCS_ERR_FORMAT, "1:1", "empty scenario"},
    {"contact_same_body", MCS_ERR_RANGE, "14:18", "contacts[0].b: 'ball' is also a"},
    {"curve_bad_point", MCS_ERR_TYPE, "6:23", "characteristics.pad.loading[1]: expected 2 values"},
    {"curve_not_increasing", MCS_ERR_RANGE, "6:36", "characteristics.pad.loading[2]: x must"},
    {"curve_wrong_dim", MCS_ERR_UNIT, "6:31",
     "loading[1][1]: '1 kg' is a mass (kg), expected a force"},
    {"deep_nesting", MCS_ERR_FORMAT, "3:68", "nesting deeper than 64 levels"},
    {"duplicate_body", MCS_ERR_KEY, "13:11", "bodies[1].name: duplicate name 'ball'"},
    {"duplicate_key", MCS_ERR_KEY, "10:5", "bodies[0].mass: duplicate key (first at line 9)"},
    {"empty", MCS_ERR_FORMAT, "1:1", "empty file"},
    {"fe_no_parts", MCS_ERR_TYPE, "3:10", "fe.parts: expected at least 1 value"},
    {"friction_angle", MCS_ERR_UNIT, "7:15", "characteristics.pad.friction: '30 deg' is an angle"},
    {"gravity_mass", MCS_ERR_UNIT, "3:24", "environment.gravity: '5 kg' is a mass"},
    {"hardening_mismatch", MCS_ERR_RANGE, "9:30", "material.hardening[0]: stress at zero plastic"},
    {"include_cycle_a", MCS_ERR_INCLUDE, "2:11", "include: include cycle"},
    {"include_cycle_b", MCS_ERR_INCLUDE, "2:10", "include: include cycle"},
    {"include_missing", MCS_ERR_INCLUDE, "3:10", "include: cannot read '" DATA "bad/no_such_model"},
    {"include_not_string", MCS_ERR_TYPE, "3:11", "include: expected a file path"},
    {"include_override_name", MCS_ERR_TYPE, "5:12",
     "bodies[0].name: entries of an included list merge by name: expected a name, got a sequence"},
    {"include_self", MCS_ERR_INCLUDE, "2:10", "include: include cycle"},
    {"inertia_count", MCS_ERR_TYPE, "10:14", "bodies[0].inertia: expected 3 principal"},
    {"inertia_triangle", MCS_ERR_RANGE, "10:14", "bodies[0].inertia: not a rigid body's inertia"},
    {"inf_in_vector", MCS_ERR_RANGE, "11:22", "bodies[0].position[2]: '.inf' is not a finite"},
    {"integer_expected", MCS_ERR_TYPE, "6:69", "section.integration_points: expected an integer"},
    {"joint_missing_axis", MCS_ERR_KEY, "14:5", "joints[0].axis: required key is missing"},
    {"map_expected", MCS_ERR_TYPE, "3:13", "simulation: expected a mapping"},
    {"mesh_missing_side", MCS_ERR_KEY, "5:13", "fe.parts[0].mesh.side: required key is missing"},
    {"mesh_neither", MCS_ERR_KEY, "5:13", "fe.parts[0].mesh.keyword: required key is missing"},
    {"mesh_typo", MCS_ERR_RANGE, "5:24", "mesh.generate: 'squaretube' is not one of"},
    {"missing_required", MCS_ERR_KEY, "8:5", "bodies[0].mass: required key is missing"},
    {"missing_version", MCS_ERR_KEY, "1:1", "mcrash: required key is missing"},
    {"multi_document", MCS_ERR_YAML, "15:1", "more than one YAML document"},
    {"nan_value", MCS_ERR_RANGE, "9:11", "bodies[0].mass: '.nan' is not a finite number"},
    {"negative_mass", MCS_ERR_RANGE, "9:11", "bodies[0].mass: must be > 0 kg (got -1 kg)"},
    {"not_utf8", MCS_ERR_FORMAT, "2:11", "not UTF-8 text (byte 0xE9)"},
    {"number_expected", MCS_ERR_TYPE, "9:11",
     "bodies[0].mass: expected a mass (kg), got a sequence"},
    {"overlong_utf8", MCS_ERR_FORMAT, "2:8", "not UTF-8 text (byte 0xC0)"},
    {"poisson_range", MCS_ERR_RANGE, "8:27", "material.poisson: must be < 0.5 (got 0.5)"},
    {"random_bytes", MCS_ERR_FORMAT, "1:3", "not UTF-8 text"},
    {"restraint_on_fixed", MCS_ERR_KEY, "14:78",
     "joints[0].restraint: a fixed joint has no restraint"},
    {"restraint_range_empty", MCS_ERR_RANGE, "15:29",
     "joints[0].range: min 0.174533 must be below max"},
    {"restraint_unknown", MCS_ERR_KEY, "15:17",
     "joints[0].restraint: unknown characteristic 'pda' (did you mean 'pad'?)"},
    {"sensor_cfc", MCS_ERR_RANGE, "14:54", "sensors[0].cfc: 100 is not a SAE J211 class"},
    {"string_not_number", MCS_ERR_TYPE, "9:11",
     "bodies[0].mass: expected a mass (kg), got 'heavy'"},
    {"string_nul", MCS_ERR_FORMAT, "2:7", "NUL character in a string"},
    {"time_step_too_long", MCS_ERR_RANGE, "3:42", "simulation.time_step: time step 1 s is longer"},
    {"top_level_list", MCS_ERR_TYPE, "1:1", "a scenario must be a mapping of keys, not a sequence"},
    {"top_level_scalar", MCS_ERR_TYPE, "1:1", "a scenario must be a mapping of keys, not a string"},
    {"unknown_body", MCS_ERR_KEY, "14:9",
     "contacts[0].a: unknown body 'bal' (did you mean 'ball'?)"},
    {"unknown_characteristic", MCS_ERR_KEY, "14:42",
     "unknown characteristic 'pda' (did you mean 'pad'?)"},
    {"unknown_fe_part", MCS_ERR_KEY, "9:21",
     "fe.boundary[0].part: unknown FE part 'tub' (did you mean 'tube'?)"},
    {"unknown_key", MCS_ERR_KEY, "9:5",
     "bodies[0].mas: unknown key in a body (did you mean 'mass'?)"},
    {"unknown_top_key", MCS_ERR_KEY, "3:1",
     "simulaton: unknown key in a scenario (did you mean 'simulation'?)"},
    {"unknown_unit", MCS_ERR_UNIT, "3:24", "simulation.end_time: unknown unit 'fortnight'"},
    {"vector_length", MCS_ERR_TYPE, "11:15", "bodies[0].position: expected 3 values, got 2"},
    {"wrong_dimension", MCS_ERR_UNIT, "9:11",
     "bodies[0].mass: '2 kN' is a force (N), expected a mass (kg)"},
    {"wrong_version", MCS_ERR_RANGE, "1:9", "mcrash: schema version 2 is not supported"},
    {"yaml_indent", MCS_ERR_YAML, "12:4", "YAML syntax: did not find expected '-' indicator"},
    {"yaml_syntax", MCS_ERR_YAML, "12:13", "YAML syntax: did not find expected ',' or ']'"},
    {"zero_normal", MCS_ERR_RANGE, "14:49", "surfaces[0].normal: must not be the zero vector"},
    {"zero_time_step", MCS_ERR_RANGE, "3:42", "simulation.time_step: must be > 0 s (got 0 s)"},
};
static const int nbad = (int)(sizeof bad_cases / sizeof bad_cases[0]);

static void check_bad_message(const bad_case *c, const char *msg)
{
    char where[64];
    snprintf(where, sizeof where, ":%s: error: ", c->where);
    CHECK_STR_CONTAINS(msg, where);
    CHECK_STR_CONTAINS(msg, c->what);
    CHECK(strncmp(msg, DATA "bad/", strlen(DATA "bad/")) == 0); /* starts with the file */
}

static void test_malformed_scenarios_via_library(void)
{
    for (int i = 0; i < nbad; i++) {
        const bad_case *c = &bad_cases[i];
        char path[256];
        snprintf(path, sizeof path, DATA "bad/%s.yaml", c->file);
        mcs_scenario *scn = NULL;
        mcs_error err = {0};
        mcs_status st = mcs_scenario_load(path, &scn, &err);
        if (st != c->status)
            fprintf(stderr, "%s: status %s, expected %s (%s)\n", c->file, mcs_status_str(st),
                    mcs_status_str(c->status), err.msg);
        CHECK(st == c->status);
        CHECK(mcs_status_exit_code(st) == 2);
        CHECK(scn == NULL);
        check_bad_message(c, err.msg);
    }
}

/* every file under bad/ is in the table (none silently unchecked), and there are >= 30 */
static void test_every_bad_file_is_listed(void)
{
    DIR *d = opendir(DATA "bad");
    CHECK(d != NULL);
    int nfiles = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n < 6 || strcmp(e->d_name + n - 5, ".yaml") != 0) continue;
        nfiles++;
        int found = 0;
        for (int i = 0; i < nbad; i++)
            if (strlen(bad_cases[i].file) == n - 5 && !strncmp(bad_cases[i].file, e->d_name, n - 5))
                found = 1;
        if (!found) fprintf(stderr, "bad/%s is not in bad_cases\n", e->d_name);
        CHECK(found);
    }
    if (d) closedir(d);
    CHECK(nfiles == nbad);
    CHECK(nbad >= 30);
}

/* a few through the command (one run, several files: each message on stderr, status 2);
 * process start-up is the slow part of these tests, so runs are few */
static void test_malformed_scenarios_via_cli(void)
{
    const int picks[] = {0, 8, 12, 17, 36, 50, 55};
    char args[1024] = "check";
    size_t n = strlen(args);
    for (size_t k = 0; k < sizeof picks / sizeof picks[0]; k++)
        n += (size_t)snprintf(args + n, sizeof args - n, " " DATA "bad/%s.yaml",
                              bad_cases[picks[k]].file);
    snprintf(args + n, sizeof args - n, " %s %s", DATA "no_such_file.yaml", DATA "bad");
    cli_result *r = cli_run(args);
    CHECK(r->status == 2);
    CHECK(r->out[0] == 0);
    for (size_t k = 0; k < sizeof picks / sizeof picks[0]; k++)
        check_bad_message(&bad_cases[picks[k]], r->err);
    CHECK_STR_CONTAINS(r->err, DATA "no_such_file.yaml: error: cannot read: No such file");
    CHECK_STR_CONTAINS(r->err, DATA "bad: error: cannot read");
    r = cli_run("check");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "usage: mcrash check");
    r = cli_run("check --frobnicate x.yaml");
    CHECK(r->status == 2);
}

/* ---- JSON ---- */

static char *json_of(const mcs_scenario *scn, size_t *len)
{
    char *buf = NULL;
    FILE *f = open_memstream(&buf, len);
    CHECK(f != NULL);
    if (!f) return NULL;
    CHECK(mcs_scenario_write_json(scn, f) == MCS_OK);
    fclose(f);
    return buf;
}

/* JSON is YAML: reading the JSON back gives the same tree, hence the same JSON */
static void test_json_round_trip(void)
{
    mcs_scenario *scn = load_ok(DATA "good/units_everywhere.yaml");
    size_t len = 0;
    char *json = json_of(scn, &len);
    CHECK_STR_CONTAINS(json, "\"name\": \"units \\\"everywhere\\\" \\\\ tab\\there\"");
    CHECK_STR_CONTAINS(json, "\"time_step\": 1e-05");
    CHECK_STR_CONTAINS(json, "\"gravity\": 9.80665");
    CHECK_STR_CONTAINS(json, "\"loading\": [[0, 0], [1.5707963267948966, 2000]]");
    CHECK_STR_CONTAINS(json, "\"code\": \"413-0/13.4\"");
    mcs_scenario *back = NULL;
    mcs_error err = {0};
    CHECK(mcs_scenario_load_text("roundtrip.json", json, len, &back, &err) == MCS_OK);
    size_t len2 = 0;
    char *json2 = back ? json_of(back, &len2) : NULL;
    CHECK(json2 && len2 == len && strcmp(json, json2) == 0);
    free(json);
    free(json2);
    mcs_scenario_destroy(&back);
    mcs_scenario_destroy(&scn);
}

static void test_cli_json_and_ok(void)
{
    cli_result *r = cli_run("check --json scenarios/verification/tube_crush.yaml");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"thickness\": 0.0015");
    CHECK_STR_CONTAINS(r->out, "\"youngs_modulus\": 210000000000");
    CHECK_STR_CONTAINS(r->out, "\"velocity\": [0, 0, -10]");
    CHECK_STR_CONTAINS(r->out,
                       "\"hardening\": [[0, 250000000], [0.05, 300000000], [1, 400000000]]");
    r = cli_run("check --json " DATA "include/top.yaml");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"name\": \"top\"");
    CHECK(strstr(r->out, "include") == NULL);
}

/* docs/scenario_keys.md is what `mcrash check --schema` writes from the schema tables */
static void test_key_reference_is_current(void)
{
    size_t len = 0, dlen = 0;
    char *buf = NULL;
    FILE *f = open_memstream(&buf, &len);
    CHECK(f && mcs_schema_write_markdown(f) == MCS_OK);
    if (f) fclose(f);
    FILE *d = fopen("docs/scenario_keys.md", "rb");
    char *doc = d ? malloc(len + 2) : NULL;
    if (doc) dlen = fread(doc, 1, len + 1, d);
    if (d) fclose(d);
    int same = doc && buf && dlen == len && memcmp(doc, buf, len) == 0;
    if (!same) fprintf(stderr, "run: bin/mcrash check --schema > docs/scenario_keys.md\n");
    CHECK(same);
    CHECK_STR_CONTAINS(buf, "| `mass` | number [kg] | yes | > 0 | mass [kg] |");
    CHECK_STR_CONTAINS(buf, "## `fe.parts[].material` — material");
    free(doc);
    free(buf);
    cli_result *r = cli_run("check --schema");
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "| *`model: elastic_plastic`* |");
}

static void test_cli_several_files(void)
{
    cli_result *r = cli_run("check scenarios/verification/sphere_drop.yaml " DATA
                            "bad/negative_mass.yaml scenarios/verification/tube_crush.yaml");
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->out, "sphere_drop.yaml: ok");
    CHECK_STR_CONTAINS(r->out, "tube_crush.yaml: ok");
    CHECK_STR_CONTAINS(r->err, "negative_mass.yaml:9:11: error: bodies[0].mass: must be > 0 kg");
    r = cli_run("check --json scenarios/verification/sphere_drop.yaml "
                "scenarios/verification/tube_crush.yaml");
    CHECK(r->status == 2); /* --json prints one scenario */
    CHECK_STR_CONTAINS(r->err, "usage:");
}

/* ---- every shipped scenario passes `mcrash check` ---- */

/* 1 if the file has a top-level `mcrash:` line: a scenario; without one it is an include
 * fragment (e.g. scenarios/models/stage2/concept_cockpit.yaml), checked through the scenarios
 * that include it */
static int is_scenario_file(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[1024];
    int yes = 0;
    while (f && !yes && fgets(line, sizeof line, f))
        yes = strncmp(line, "mcrash:", 7) == 0;
    if (f) fclose(f);
    return yes;
}

/* append every scenario .yaml under dir to args (space separated) */
static void collect_yaml(const char *dir, char *args, size_t cap, int *count)
{
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d));) {
        if (e->d_name[0] == '.') continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        struct stat sb;
        size_t n = strlen(path);
        if (stat(path, &sb) != 0) continue;
        if (S_ISDIR(sb.st_mode))
            collect_yaml(path, args, cap, count);
        else if (n > 5 && strcmp(path + n - 5, ".yaml") == 0 && strlen(args) + n + 2 < cap &&
                 is_scenario_file(path)) {
            strcat(strcat(args, " "), path);
            (*count)++;
        }
    }
    if (d) closedir(d);
}

static void test_every_shipped_scenario_checks(void)
{
    static char args[32768];
    int count = 0;
    snprintf(args, sizeof args, "check");
    collect_yaml("scenarios", args, sizeof args, &count);
    CHECK(count >= 4);
    cli_result *r = cli_run(args);
    if (r->status != 0) fprintf(stderr, "%s", r->err);
    CHECK(r->status == 0);
    /* stderr: nothing but the initial-penetration warnings (the cars' tyres on their static
     * deflection, tests/test_initial_pen.c) */
    for (const char *l = r->err; *l;) {
        const char *e = strchr(l, '\n');
        size_t n = e ? (size_t)(e - l) : strlen(l);
        char line[512];
        snprintf(line, sizeof line, "%.*s", (int)(n < sizeof line ? n : sizeof line - 1), l);
        if (!strstr(line, ": warning: initial penetration: contact ")) printf("%s\n", line);
        CHECK(strstr(line, ": warning: initial penetration: contact ") != NULL);
        l += n + (e != NULL);
    }
    int oks = 0;
    for (const char *p = r->out; (p = strstr(p, ": ok\n")); p++)
        oks++;
    CHECK(oks == count);
}

/* ---- robustness ---- */

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *buf = malloc(1 << 20);
    *len = buf ? fread(buf, 1, (1 << 20) - 1, f) : 0;
    fclose(f);
    return buf;
}

/* random byte mutations of a valid file: every outcome is ok or a located error, never a crash */
static void test_fuzz_mutations(void)
{
    size_t len = 0;
    char *orig = slurp("scenarios/verification/pendulum_strike.yaml", &len);
    CHECK(orig != NULL);
    if (!orig) return;
    char *buf = malloc(len + 64);
    unsigned long long s = 0x9E3779B97F4A7C15ull;
    int nok = 0, nerr = 0;
    for (int it = 0; it < 600; it++) {
        memcpy(buf, orig, len);
        size_t n = len;
        int nmut = 1 + it % 6;
        for (int m = 0; m < nmut; m++) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            size_t pos = (size_t)(s >> 33) % n;
            unsigned char byte = (unsigned char)(s >> 20);
            int op = (int)((s >> 8) % 4);
            if (op == 0)
                buf[pos] = (char)byte; /* replace */
            else if (op == 1 && n > 1)
                memmove(buf + pos, buf + pos + 1, n - pos - 1), n--; /* delete */
            else if (op == 2)
                memmove(buf + pos + 1, buf + pos, n - pos),
                    buf[pos] = "[]{}:,-&*!|>'\"#\n "[byte % 17], n++;
            else
                buf[pos] = "0123456789.e-+ ms"[byte % 17];
        }
        mcs_scenario *scn = NULL;
        mcs_error err = {0};
        /* named inside scenarios/verification so its include resolves when intact */
        mcs_status st =
            mcs_scenario_load_text("scenarios/verification/fuzz.yaml", buf, n, &scn, &err);
        if (st == MCS_OK) {
            nok++;
            FILE *f = fopen("/dev/null", "w");
            CHECK(f && mcs_scenario_write_json(scn, f) == MCS_OK);
            if (f) fclose(f);
        } else {
            nerr++;
            CHECK(mcs_status_exit_code(st) == 2);
            CHECK(strstr(err.msg, ": error: ") != NULL);
            CHECK(scn == NULL);
        }
        mcs_scenario_destroy(&scn);
    }
    CHECK(nok > 0 && nerr > 0); /* the mutations exercise both outcomes */
    free(buf);
    free(orig);
}

static void test_limits(void)
{
    mcs_scenario *scn = NULL;
    mcs_error err = {0};
    size_t big = MCS_SCN_MAX_BYTES + 1;
    char *text = malloc(big);
    memset(text, ' ', big);
    CHECK(mcs_scenario_load_text("big.yaml", text, big, &scn, &err) == MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(err.msg, "big.yaml:1:1: error: file too large");
    /* 5000 nested flow sequences stop at the depth limit */
    size_t n = 0;
    n += (size_t)sprintf(text, "mcrash: 1\nimpact: {x: ");
    for (int i = 0; i < 5000; i++)
        text[n++] = '[';
    mcs_error_clear(&err);
    CHECK(mcs_scenario_load_text("deep.yaml", text, n, &scn, &err) == MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(err.msg, "deep.yaml:2:");
    CHECK_STR_CONTAINS(err.msg, "nesting deeper than 64 levels");
    /* block-style nesting too */
    n = (size_t)sprintf(text, "mcrash: 1\nimpact:\n");
    for (int i = 0; i < 100; i++)
        n += (size_t)sprintf(text + n, "%*sk%d:\n", i + 1, "", i);
    mcs_error_clear(&err);
    CHECK(mcs_scenario_load_text("deep2.yaml", text, n, &scn, &err) == MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(err.msg, "nesting deeper than 64 levels");
    free(text);
}

static void test_accessors_on_absent_nodes(void)
{
    CHECK(mcs_node_kind(NULL) == MCS_NODE_NULL);
    CHECK(mcs_node_get(NULL, "x") == NULL);
    CHECK(mcs_node_len(NULL) == 0);
    CHECK(mcs_node_at(NULL, 0) == NULL);
    CHECK(isnan(mcs_node_num(NULL)));
    CHECK_NEAR(mcs_node_num_or(NULL, "x", 7), 7, 0);
    CHECK(mcs_node_str(NULL) == NULL);
    CHECK(mcs_node_bool(NULL, 1) == 1);
    CHECK(mcs_node_curve_len(NULL) == 0);
    double v[3];
    mcs_error err = {0};
    CHECK(mcs_node_vec3(NULL, v, &err) == MCS_ERR_TYPE);
    /* a stage's own check, located at a node */
    mcs_scenario *scn = load_ok("scenarios/verification/sphere_drop.yaml");
    const mcs_node *m = AT(mcs_scenario_root(scn), "bodies", "#0", "mass");
    mcs_error_clear(&err);
    CHECK(mcs_node_error(m, &err, MCS_ERR_RANGE, "too light for stage %d", 1) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg,
                       "sphere_drop.yaml:16:11: error: bodies[0].mass: too light for stage 1");
    CHECK(mcs_node_vec3(m, v, &err) == MCS_ERR_TYPE); /* a number is not a vector... */
    CHECK_STR_CONTAINS(err.msg, "too light");         /* ...but the first error is kept */
    mcs_scenario_destroy(&scn);
}

int main(void)
{
    RUN(test_sphere_drop_reads_in_si);
    RUN(test_units_in_every_kind_of_key);
    RUN(test_include_merge_rule);
    RUN(test_include_override_by_name);
    RUN(test_include_diamond_is_not_a_cycle);
    RUN(test_include_cycle_reports_chain);
    RUN(test_malformed_scenarios_via_library);
    RUN(test_every_bad_file_is_listed);
    RUN(test_malformed_scenarios_via_cli);
    RUN(test_json_round_trip);
    RUN(test_cli_json_and_ok);
    RUN(test_key_reference_is_current);
    RUN(test_cli_several_files);
    RUN(test_every_shipped_scenario_checks);
    RUN(test_fuzz_mutations);
    RUN(test_limits);
    RUN(test_accessors_on_absent_nodes);
    TEST_END();
}

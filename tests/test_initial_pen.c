/* test_initial_pen.c: the initial-penetration check (stage1_mb/mb_initial.h, `mcrash check`):
 * the pairs deeper than 1 mm at t = 0 with their depth and the force their law gives there,
 * on spheres placed by hand (depth r_a + r_b - d and F = k x, closed form); and the shipped
 * rider scenarios, where no rider contact may start penetrated and the only pairs listed are
 * the cars' tyres on their static deflection m g / (4 k) (the opponent files' own figure). */
#include "harness.h"
#include "tests/cli_util.h"
#include "stage1_mb/mb_initial.h"
#include "tests/mb_test_util.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* a overlaps b by 5 mm (centres 0.195 m apart, radii 0.1 m), c overlaps a by 0.5 mm (below
 * the check's 1 mm), d sits 3 mm into the ground; no gravity, the contacts' linear law
 * 1 kN at 10 mm (100 kN/m): 500 N and 300 N */
static const char *const spheres =
    "mcrash: 1\n"
    "name: initial penetrations\n"
    "simulation: {end_time: 1 ms, time_step: 10 us}\n"
    "environment: {gravity: 0 m/s^2, ground: {height: 0 m}}\n"
    "characteristics:\n"
    "  pad: {loading: [[0, 0], [0.01, 1000]]}\n"
    "bodies:\n"
    "  - {name: a, mass: 1 kg, inertia: [0.004, 0.004, 0.004], position: [0, 0, 0.5 m],\n"
    "     velocity: [0, 0, 0],\n"
    "     surfaces: [{name: sa, type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"
    "  - {name: b, mass: 1 kg, inertia: [0.004, 0.004, 0.004], position: [0.195 m, 0, 0.5 m],\n"
    "     velocity: [0, 0, 0],\n"
    "     surfaces: [{name: sb, type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"
    "  - {name: c, mass: 1 kg, inertia: [0.004, 0.004, 0.004], position: [0, 0.1995 m, 0.5 m],\n"
    "     velocity: [0, 0, 0],\n"
    "     surfaces: [{name: sc, type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"
    "  - {name: d, mass: 1 kg, inertia: [0.004, 0.004, 0.004], position: [2 m, 0, 0.097 m],\n"
    "     velocity: [0, 0, 0],\n"
    "     surfaces: [{name: sd, type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"
    "contacts:\n"
    "  - {name: ab, a: a, b: b, characteristic: pad}\n"
    "  - {name: ac, a: a, b: c, characteristic: pad}\n"
    "  - {name: d_road, a: d, b: ground, characteristic: pad}\n";

static void test_spheres(void)
{
    mb_model *m = mt_model_text("scenarios/initial_pen.yaml", spheres, NULL);
    CHECK(m != NULL);
    if (!m) return;
    mb_initial_pen *p = NULL;
    int n = -1;
    mcs_error err = {0};
    CHECK(mb_initial_penetrations(m, 1e-3, &p, &n, &err) == MCS_OK);
    CHECK(n == 2);
    if (n == 2) { /* deepest first */
        CHECK(strcmp(m->contact[m->pair[p[0].pair].contact].name, "ab") == 0);
        CHECK_NEAR(p[0].depth, 0.005, 1e-9);
        CHECK_NEAR(p[0].force, 500, 1e-4);
        CHECK(strcmp(m->contact[m->pair[p[1].pair].contact].name, "d_road") == 0);
        CHECK_NEAR(p[1].depth, 0.003, 1e-9);
        CHECK_NEAR(p[1].force, 300, 1e-4);
    }
    free(p);
    /* every overlap without the threshold: c's 0.5 mm as well */
    CHECK(mb_initial_penetrations(m, 0, &p, &n, &err) == MCS_OK);
    CHECK(n == 3);
    if (n == 3) CHECK_NEAR(p[2].depth, 0.0005, 1e-9);
    free(p);
    mb_model_destroy(&m);

    /* the command: warnings on stderr, exit status 0, "ok" on stdout */
    char path[] = "/tmp/mcrash_initial_pen_XXXXXX.yaml";
    int fd = mkstemps(path, 5);
    CHECK(fd >= 0);
    if (fd < 0) return;
    CHECK(write(fd, spheres, strlen(spheres)) == (ssize_t)strlen(spheres));
    close(fd);
    char args[128];
    snprintf(args, sizeof args, "check %s", path);
    cli_result *r = cli_run(args);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, ": ok");
    CHECK_STR_CONTAINS(r->err, "warning: initial penetration: contact ab, sa (a) into sb (b): "
                               "5.0 mm, 500 N from its characteristic");
    CHECK_STR_CONTAINS(r->err, "contact d_road, sd (d) into ground (ground): 3.0 mm, 300 N");
    CHECK(strstr(r->err, "contact ac") == NULL);
    printf("%s", r->err);
    remove(path);
}

/* every shipped scenario with a seated rider: no pair of a rider body penetrates at t = 0 (any
 * depth); the pairs that do are the opponent's tyres on the ground at their static deflection,
 * m g / (4 k): sedan 1668 kg, 40 kN/m: 102.27 mm, 4091 N (sedan_1668kg.yaml); the MYMOSA car
 * 1100 kg, 30 kN/m: 89.9 mm, 2698 N (car_1100kg_b_segment.yaml; its spheres sit 0.2 mm deeper
 * than that figure, hence the wider tolerance) */
static void test_rider_scenarios(void)
{
    static const char *const files[] = {
        "iso13232_413-0_13.4_sedan_rider.yaml",
        "iso13232_413-0_13.4_sedan_rider_05f.yaml",
        "iso13232_413-0_13.4_sedan_rider_95m.yaml",
        "iso13232_413-0_13.4_sedan_rider_concept.yaml",
        "iso13232_413-0_13.4_sedan_rider_concept_05f.yaml",
        "iso13232_413-0_13.4_sedan_rider_concept_95m.yaml",
        "moving_car_413-6.7_13.4_sedan_rider.yaml",
        "mymosa_lateral_car_1100kg_rider.yaml",
        "mymosa_lateral_car_1100kg_rider_concept.yaml",
    };
    for (size_t f = 0; f < sizeof files / sizeof *files; f++) {
        char path[160];
        snprintf(path, sizeof path, "scenarios/%s", files[f]);
        mb_model *m = mt_model_file(path);
        CHECK(m != NULL);
        if (!m) continue;
        mb_initial_pen *p = NULL;
        int n = 0, rider = 0, tyres = 0;
        mcs_error err = {0};
        CHECK(mb_initial_penetrations(m, 0, &p, &n, &err) == MCS_OK);
        int mymosa = strncmp(files[f], "mymosa", 6) == 0;
        for (int i = 0; i < n; i++) {
            const mb_pair *q = &m->pair[p[i].pair];
            const char *ba = m->body_name[q->ba];
            if (strncmp(ba, "rider_", 6) == 0 ||
                (q->bb >= 0 && strncmp(m->body_name[q->bb], "rider_", 6) == 0)) {
                rider++;
                printf("  %s: %s at t = 0: %.2f mm\n", files[f], m->contact[q->contact].name,
                       p[i].depth * 1e3);
                continue;
            }
            CHECK(q->bb == MB_GROUND);
            tyres++;
            if (mymosa) {
                CHECK_NEAR(p[i].depth, 1100 * 9.81 / 4 / 30000, 5e-4);
                CHECK_NEAR(p[i].force, 1100 * 9.81 / 4, 10);
            } else {
                CHECK_NEAR(p[i].depth, 1668 * 9.81 / 4 / 40000, 1e-5);
                CHECK_NEAR(p[i].force, 1668 * 9.81 / 4, 1);
            }
        }
        printf("  %s: %d pairs penetrate at t = 0 (%d of the car's tyres), %d of the rider\n",
               files[f], n, tyres, rider);
        CHECK(rider == 0);
        CHECK(tyres == 4);
        free(p);
        mb_model_destroy(&m);
    }
}

int main(void)
{
    RUN(test_spheres);
    RUN(test_rider_scenarios);
    TEST_END();
}

/* tests for the impact: placement of FE parts carried by stage-1 bodies (stage1_mb/mb_impact.c,
 * mb_couple.c, fe/scn/fe_scn_place.c; docs/stage1_engine.md "Coupling to FE parts").
 *
 * A box body moto_frame (the motorcycle group by the default pattern moto_*) carries a steel
 * truss bar attached at its x_min end. impact: turns the group by heading_angle psi about the
 * vertical after rolling it by roll_angle phi about its x axis, brings motorcycle_contact to
 * opponent_contact less initial_gap along the heading (plan view), and gives it the speed V
 * along the heading (mb_impact.h). References, computed here by hand from those definitions:
 * - x' = Rz(psi) Rx(phi) x + t, t = (po - gap h - R pm) in x and y, 0 in z, h = (cos psi,
 *   sin psi, 0): every node of the bar, attached or not (a rigid motion of the whole part);
 * - the bar's nodes start with the body's velocity field v + w x (x' - p'), v = V h, w = R w0;
 * - the energy at t = 0: M V^2 / 2 + w0.I w0 / 2 (I in body axes) + sum of m_n |v_n|^2 / 2
 *   with the bar's lumped masses rho A l_e (half at the two ends). */
#include "fe/fe_restraint.h"
#include "fe/fe_slipring.h"
#include "fe/fe_state.h"
#include "stage1_mb/mb_couple.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_couple_test_util.h"
#include "tests/mb_test_util.h"

#define PSI (30 * M_PI / 180)
#define PHI (10 * M_PI / 180)
#define V_MC 10.0
#define GAP 0.1
#define NDIV 8

static const double p0[3] = {0.5, 0, 0.8};       /* body CG before the placement [m] */
static const double w0[3] = {0, 0.5, 2};         /* body angular velocity, model frame [rad/s] */
static const double pm[3] = {1.2, 0, 0.3};       /* motorcycle_contact [m] */
static const double po[3] = {3.0, 1.0, 0.29544}; /* opponent_contact [m] */
static const double Ib[3] = {1.0, 2.0, 2.5};     /* principal inertia, body axes [kg m^2] */
#define M_BODY 50.0

#define BOX_YAML                                                                                   \
    "mcrash: 1\nname: carried\n"                                                                   \
    "simulation: {end_time: %s, time_step: 10 us, output_rate: 10 kHz}\n"                          \
    "environment: {gravity: 0}\n"                                                                  \
    "bodies:\n"                                                                                    \
    "  - {name: moto_frame, mass: 50, inertia: [1.0, 2.0, 2.5], position: [0.5, 0, 0.8],\n"        \
    "     velocity: [0, 0, 0], angular_velocity: [0, 0.5, 2]}\n"                                   \
    "impact: {heading_angle: 30 deg, roll_angle: 10 deg, motorcycle_speed: 10 m/s,\n"              \
    "         motorcycle_contact: [1.2, 0, 0.3], opponent_contact: [3.0, 1.0, 0.29544],\n"         \
    "         initial_gap: 0.1}\n"                                                                 \
    "fe:\n  parts:\n    - name: bar\n"                                                             \
    "      mesh: {generate: line, origin: [0.6, 0.1, 0.8], end: [1.0, 0.1, 0.8], divisions: 8}\n"  \
    "      section: {type: truss, area: 1e-4}\n"                                                   \
    "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"     \
    "      attach: {body: moto_frame, where: x_min}\n"

static char yaml[4096];

static const char *box(const char *end_time)
{
    snprintf(yaml, sizeof yaml, BOX_YAML, end_time);
    return yaml;
}

/* an opponent body, in front of the impact: block */
#define CAR_BODY                                                                                   \
    "  - {name: car, mass: 1000, inertia: [300, 1000, 1000], position: [5, 0, 0.5],\n"             \
    "     velocity: [0, 0, 0], angular_velocity: [0, 0, 0]}\n"

static char edited[8192];

/* box("1 ms") with the first `from` replaced by `to` (from NULL: none) and `more` (fe: text
 * after the bar) appended */
static const char *box_edit(const char *from, const char *to, const char *more)
{
    const char *y = box("1 ms"), *p = from ? strstr(y, from) : NULL;
    CHECK(!from || p);
    if (p)
        snprintf(edited, sizeof edited, "%.*s%s%s%s", (int)(p - y), y, to, p + strlen(from), more);
    else
        snprintf(edited, sizeof edited, "%s%s", y, more);
    return edited;
}

/* the largest offsets of the part after the bar from the nodes x0 + 0.25 k (0, 1, 0) and of
 * their start velocities from v; its node count */
static int second_part(const fe_model *fm, const double x0[3], const double v[3], double *ex,
                       double *ev)
{
    *ex = *ev = 0;
    for (int n = NDIV + 1; fm && n < fm->nnode; n++)
        for (int i = 0; i < 3; i++) {
            const double x = x0[i] + (i == 1 ? 0.25 * (n - NDIV - 1) : 0);
            *ex = fmax(*ex, fabs(fm->node_x0[3 * n + i] - x));
            *ev = fmax(*ev, fabs(fm->node_v0[3 * n + i] - v[i]));
        }
    return fm ? fm->nnode - NDIV - 1 : 0;
}

/* R = Rz(psi) Rx(phi), row-major, written out */
static void rot(double R[9])
{
    const double c = cos(PSI), s = sin(PSI), cr = cos(PHI), sr = sin(PHI);
    const double Rz[9] = {c, -s, 0, s, c, 0, 0, 0, 1}, Rx[9] = {1, 0, 0, 0, cr, -sr, 0, sr, cr};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            R[3 * i + j] = 0;
            for (int k = 0; k < 3; k++)
                R[3 * i + j] += Rz[3 * i + k] * Rx[3 * k + j];
        }
}

static void apply(const double R[9], const double x[3], double y[3])
{
    for (int i = 0; i < 3; i++)
        y[i] = R[3 * i] * x[0] + R[3 * i + 1] * x[1] + R[3 * i + 2] * x[2];
}

static void place(const double R[9], const double x[3], double y[3])
{
    const double h[3] = {cos(PSI), sin(PSI), 0};
    double rp[3], rx[3];
    apply(R, pm, rp);
    apply(R, x, rx);
    const double t[3] = {po[0] - GAP * h[0] - rp[0], po[1] - GAP * h[1] - rp[1], 0};
    for (int i = 0; i < 3; i++)
        y[i] = rx[i] + t[i];
}

static void test_placement_and_velocity_field(void)
{
    mcs_error err = {0};
    mb_model *m = mc_model("carried.yaml", box("1 ms"));
    if (!m) return;
    const mb_couple *c = m->couple;
    const fe_model *fm = c->fe.model;
    CHECK(fm->nnode == NDIV + 1 && c->natt == 1);
    double R[9], p1[3], w1[3], v1[3];
    rot(R);
    place(R, p0, p1);
    apply(R, w0, w1);
    const double h[3] = {cos(PSI), sin(PSI), 0};
    for (int i = 0; i < 3; i++)
        v1[i] = V_MC * h[i];
    double ex = 0, ev = 0, ek = 0, mtot = 0;
    for (int n = 0; n < fm->nnode; n++) {
        /* the generator's node n lies at origin + n / NDIV (end - origin) before the move */
        const double x[3] = {0.6 + 0.4 * n / NDIV, 0.1, 0.8};
        double y[3], r[3], wr[3];
        place(R, x, y);
        for (int i = 0; i < 3; i++) {
            ex = fmax(ex, fabs(fm->node_x0[3 * n + i] - y[i]));
            r[i] = y[i] - p1[i];
        }
        wr[0] = w1[1] * r[2] - w1[2] * r[1];
        wr[1] = w1[2] * r[0] - w1[0] * r[2];
        wr[2] = w1[0] * r[1] - w1[1] * r[0];
        double v2 = 0;
        for (int i = 0; i < 3; i++) {
            ev = fmax(ev, fabs(fm->node_v0[3 * n + i] - (v1[i] + wr[i])));
            v2 += (v1[i] + wr[i]) * (v1[i] + wr[i]);
        }
        const double mn = 7850 * 1e-4 * 0.4 / NDIV * (n == 0 || n == NDIV ? 0.5 : 1);
        ek += 0.5 * mn * v2;
        mtot += mn;
    }
    /* the attached node: x_min before the move (node 0), at the body point it was on */
    CHECK(c->node[0] == 0);
    const double l0[3] = {0.1, 0.1, 0}; /* x_min end - CG, body axes (identity at t = 0) */
    for (int i = 0; i < 3; i++)
        CHECK_NEAR(c->local[i], l0[i], 1e-12);
    /* the body itself, against the same hand placement */
    mb_body_desc *d = &m->body[0];
    for (int i = 0; i < 3; i++) {
        CHECK_NEAR(d->pos[i], p1[i], 1e-12);
        CHECK_NEAR(d->angvel[i], w1[i], 1e-12);
        CHECK_NEAR(d->vel[i], v1[i], 1e-12);
    }
    printf("placed bar: position error %.3g m, velocity error %.3g m/s\n", ex, ev);
    CHECK(ex < 1e-12);
    CHECK(ev < 1e-12);
    /* energy at t = 0 */
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    CHECK(st == MCS_OK);
    const double eb = 0.5 * M_BODY * V_MC * V_MC +
                      0.5 * (Ib[0] * w0[0] * w0[0] + Ib[1] * w0[1] * w0[1] + Ib[2] * w0[2] * w0[2]);
    if (s) {
        printf("energy at t = 0: %.9g J (hand %.9g J: body %.6g, bar %.6g, bar mass %.4g kg)\n",
               s->e.total, eb + ek, eb, ek, mtot);
        CHECK_REL(s->e.total, eb + ek, 1e-12);
        CHECK_REL(s->e.kinetic, eb + ek, 1e-12);
    }
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* a short run of the placed model: one energy balance of the body and the bar */
static void test_short_run_drift(void)
{
    mb_model *m = mc_model("carried.yaml", box("20 ms"));
    if (!m) return;
    mb_state *s = NULL;
    mc_run(m, &s);
    double drift = s ? mb_energy_drift(m, s) : 1;
    printf("placed bar, 20 ms: energy drift %.3g, FE steps %ld\n", drift,
           s ? s->couple->substeps : 0);
    FIG_TOL("stage1_engine.couple_impact_drift", "%.1e", drift, 2e-8);
    CHECK(drift < 1e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* a part attached to nothing stays where the fe: block puts it, with its initial_velocity */
static void test_free_part_stays(void)
{
    mb_model *m = mc_model(
        "free.yaml",
        box_edit(NULL, NULL,
                 "    - name: free\n"
                 "      mesh: {generate: line, origin: [5, 5, 1], end: [5, 6, 1], divisions: 4}\n"
                 "      section: {type: truss, area: 1e-4}\n"
                 "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, "
                 "poisson: 0.3}\n"
                 "      initial_velocity: [1, 2, 3]\n"));
    const double x0[3] = {5, 5, 1}, v[3] = {1, 2, 3}; /* the generator's nodes, the key's v */
    double ex, ev;
    CHECK(second_part(m ? m->couple->fe.model : NULL, x0, v, &ex, &ev) == 5);
    CHECK(ex == 0 && ev == 0);
    mb_model_destroy(&m);
}

/* a part carried by an opponent body stays in place (the opponent is not moved) and starts
 * with the opponent's speed along its heading (+x by default) */
static void test_opponent_part(void)
{
    mb_model *m = mc_model(
        "opp.yaml",
        box_edit(
            "impact: {", CAR_BODY "impact: {opponent_speed: 2 m/s, ",
            "    - name: door\n"
            "      mesh: {generate: line, origin: [5, 1, 0.5], end: [5, 2, 0.5], divisions: 4}\n"
            "      section: {type: truss, area: 1e-4}\n"
            "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, "
            "poisson: 0.3}\n"
            "      attach: {body: car, where: y_min}\n"));
    const double x0[3] = {5, 1, 0.5}, v[3] = {2, 0, 0}; /* in place; opponent_speed along +x */
    double ex, ev;
    CHECK(second_part(m ? m->couple->fe.model : NULL, x0, v, &ex, &ev) == 5);
    CHECK(ex == 0 && ev == 0);
    mb_model_destroy(&m);
}

/* a carried shell part: its nodes also take the body's spin w (rotations of a rigid motion) */
static void test_shell_nodes_spin(void)
{
    mcs_error err = {0};
    mb_model *m = mc_model(
        "shell.yaml",
        box_edit(NULL, NULL,
                 "    - name: plate\n"
                 "      mesh: {generate: plate, origin: [0.2, -0.1, 0.9], size: [0.2, 0.2],\n"
                 "             divisions: [2, 2], axis: z}\n"
                 "      section: {type: shell, thickness: 1 mm}\n"
                 "      material: {model: elastic, density: 2700, youngs_modulus: 70 GPa, "
                 "poisson: 0.3}\n"
                 "      attach: {body: moto_frame, where: x_min}\n"));
    const fe_model *fm = m ? m->couple->fe.model : NULL;
    double R[9], w1[3], ew = 0;
    rot(R);
    apply(R, w0, w1);
    int nshell = 0;
    for (int n = NDIV + 1; fm && n < fm->nnode; n++, nshell++)
        for (int i = 0; i < 3; i++)
            ew = fmax(ew, fabs(fm->node_w0[3 * n + i] - w1[i]));
    CHECK(nshell == 9);
    CHECK(ew == 0);
    mb_state *s = NULL;
    if (m && !mb_state_create(m, &s, &err)) /* the state starts from them */
        CHECK(s->couple->fe->node_w[3 * (NDIV + 1) + 2] == w1[2]);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* retractor anchors and slip-ring points on a body of the motorcycle group move with it (the
 * model's anchor = R a + t exactly; the ring picks the node nearest to the moved point); a
 * retractor anchored on an opponent body while its part rides on moto_frame is refused */
static void test_anchor_and_ring_on_moved_body(void)
{
    mb_model *m = mc_model(
        "anchor.yaml",
        box_edit(NULL, NULL,
                 "  retractors:\n"
                 "    - {name: ret, part: bar, where: x_max, anchor: [1.1, 0.1, 0.8],\n"
                 "       anchor_body: moto_frame}\n"
                 "  sliprings:\n"
                 "    - {name: ring, part: bar, point: [0.8, 0.1, 0.8], body: moto_frame}\n"));
    const fe_model *fm = m ? m->couple->fe.model : NULL;
    if (fm) {
        double R[9], a1[3];
        const double a0[3] = {1.1, 0.1, 0.8};
        rot(R);
        place(R, a0, a1);
        CHECK(fm->restraints && fm->restraints->nretractor == 1);
        CHECK(fm->sliprings && fm->sliprings->n == 1);
        double ea = 0;
        for (int i = 0; fm->restraints && i < 3; i++)
            ea = fmax(ea, fabs(fm->restraints->retractor[0].anchor[i] - a1[i]));
        printf("moved anchor: error %.3g m; ring node %d (node 4 at x = 0.8 before the move)\n", ea,
               fm->sliprings ? fm->sliprings->ring[0].node : -1);
        CHECK(ea == 0);
        CHECK(fm->sliprings && fm->sliprings->ring[0].node == 4);
        /* the body-frame anchor is taken from the placed poses: a run starts balanced */
        mb_state *s = NULL;
        mc_run(m, &s);
        double drift = s ? mb_energy_drift(m, s) : 1;
        printf("moved anchor and ring, 1 ms: energy drift %.3g\n", drift);
        CHECK(drift < 1e-3);
        mb_state_destroy(&s);
    }
    mb_model_destroy(&m);
}

/* what the placement refuses, at FILE:LINE:COL */
static void expect_error(const char *what, const char *from, const char *to, const char *loc,
                         const char *msg)
{
    mcs_error err = {0};
    mb_model *m = mt_model_text("bad.yaml", box_edit(from, to, ""), &err);
    printf("%s: %s\n", what, err.msg);
    CHECK(m == NULL);
    CHECK(err.status != MCS_OK);
    CHECK(mcs_status_exit_code(err.status) == 2);
    CHECK_STR_CONTAINS(err.msg, loc);
    CHECK_STR_CONTAINS(err.msg, msg);
    mb_model_destroy(&m);
}

static void test_refusals(void)
{
    /* carried by bodies of two groups: the bar on moto_frame, its retractor on the car */
    {
        const char *y =
            box_edit("impact: {", CAR_BODY "impact: {",
                     "  retractors:\n"
                     "    - {name: ret, part: bar, where: x_max, anchor: [1.1, 0.1, 0.8],\n"
                     "       anchor_body: car}\n");
        mcs_error err = {0};
        mb_model *m = mt_model_text("two.yaml", y, &err);
        printf("two groups: %s\n", err.msg);
        CHECK(m == NULL);
        CHECK(mcs_status_exit_code(err.status) == 2);
        CHECK_STR_CONTAINS(err.msg, "two.yaml:22:");
        CHECK_STR_CONTAINS(err.msg, "bodies of two groups");
        mb_model_destroy(&m);
    }
    /* a translation held in the world on a moved part */
    expect_error("boundary", "x_min}\n", "x_min}\n  boundary: [{part: bar, where: x_max}]\n",
                 "bad.yaml:18:14", "moves with the impact placement");
    /* a retractor on a moved part anchored to the ground */
    expect_error("ground anchor", "x_min}\n",
                 "x_min}\n  retractors:\n"
                 "    - {name: ret, part: bar, where: x_max, anchor: [1.1, 0.1, 0.8]}\n",
                 "bad.yaml:19:", "fixed to the ground");
    /* an initial velocity on a carried part */
    expect_error("initial_velocity", "      attach:",
                 "      initial_velocity: [1, 0, 0]\n      attach:", "bad.yaml:17:25",
                 "remove initial_velocity");
}

int main(void)
{
    RUN(test_placement_and_velocity_field);
    RUN(test_short_run_drift);
    RUN(test_free_part_stays);
    RUN(test_opponent_part);
    RUN(test_shell_nodes_spin);
    RUN(test_anchor_and_ring_on_moved_body);
    RUN(test_refusals);
    TEST_END();
}

/* test_fe_rigid: rigid parts (fe_rigid.c) against rigid-body mechanics: a tumbling plate keeps
 * its angular momentum, energy and shape; a pushed block accelerates at F/M; a block dropped on
 * a penalty wall rebounds; a rigid mass on an elastic bar (shared nodes) oscillates with
 * T = 2 pi sqrt(M / k). */
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/fe_test_util.h"

#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

static fe_part_desc rigid_box(const char *name, double sx, double sy, double sz, int n,
                              double rho)
{
    fe_part_desc d = ft_part(name, FE_SECTION_SOLID, 1e9, 0.3, rho);
    d.material.model = FE_MAT_RIGID;
    d.mesh.generate = FE_MESH_BOX;
    d.mesh.size[0] = sx, d.mesh.size[1] = sy, d.mesh.size[2] = sz;
    d.mesh.divisions[0] = d.mesh.divisions[1] = d.mesh.divisions[2] = n;
    return d;
}

/* a free rigid shell plate (0.2 x 0.1, 2 mm) spun about an oblique axis (not principal, so it
 * tumbles): angular momentum L = sum m r x v is constant to round-off (no moments), the
 * kinetic energy 1/2 L.w to O(dt^2), node distances exactly */
static void test_tumbling_plate(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d = ft_part("plate", FE_SECTION_SHELL, 70e9, 0.3, 2700);
    d.material.model = FE_MAT_RIGID;
    d.section.thickness = 0.002;
    d.mesh.generate = FE_MESH_PLATE;
    d.mesh.size[0] = 0.2, d.mesh.size[1] = 0.1;
    d.mesh.divisions[0] = 8, d.mesh.divisions[1] = 4;
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_ERR_RANGE); /* no step: all rigid */
    CHECK_STR_CONTAINS(err.msg, "every part is rigid");
    o.dt_max = 2e-5;
    mcs_error e2 = {0};
    CHECK(fe_model_create(b, &o, &m, &e2) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    CHECK(m->nbody == 1);
    const fe_body *B = &m->body[0];
    CHECK_REL(B->mass, 2700 * 0.002 * 0.02, 1e-12);
    /* spin w0 about an oblique axis through the centre, plus a drift */
    const double w0[3] = {30, 10, 50}, v0[3] = {1, -2, 0.5};
    for (int n = 0; n < m->nnode; n++) {
        double r[3], c[3];
        for (int i = 0; i < 3; i++) r[i] = m->node_x0[3 * n + i] - B->x0[i];
        fe_cross(w0, r, c);
        for (int i = 0; i < 3; i++) m->node_v0[3 * n + i] = v0[i] + c[i];
    }
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double L0[3], ke0 = 0;
    memcpy(L0, s->body_l, sizeof L0);
    for (int i = 0; i < 3; i++) ke0 += 0.5 * B->mass * v0[i] * v0[i] + 0.5 * L0[i] * s->body_w[i];
    double d01 = 0, lerr = 0, derr = 0, kerr = 0;
    for (int i = 0; i < 3; i++) {
        double dx = m->node_x0[3 * 0 + i] - m->node_x0[3 * (m->nnode - 1) + i];
        d01 += dx * dx;
    }
    for (int k = 0; k < 20000; k++) { /* 0.4 s: several tumbling periods */
        CHECK(fe_step(m, s) == MCS_OK);
        for (int i = 0; i < 3; i++) lerr = fmax(lerr, fabs(s->body_l[i] - L0[i]));
        double dd = 0;
        for (int i = 0; i < 3; i++) {
            double dx = s->node_x[3 * 0 + i] - s->node_x[3 * (m->nnode - 1) + i];
            dd += dx * dx;
        }
        derr = fmax(derr, fabs(sqrt(dd) - sqrt(d01)));
        kerr = fmax(kerr, fabs(s->energy[FE_E_kinetic] - ke0) / ke0);
    }
    double lnorm = sqrt(fe_dot(L0, L0));
    printf("  tumbling plate: |dL|/|L| %.2e, distance %.2e m, kinetic energy %.2e\n",
           lerr / lnorm, derr, kerr);
    FIG("fe.rigid_tumble_dist_m", "%.0e", derr);
    FIG("fe.rigid_tumble_ke", "%.0e", kerr);
    CHECK(lerr <= 1e-12 * lnorm);
    CHECK(derr <= 1e-12);
    CHECK(kerr <= 1.2e-7); /* 4e-8 stated */
    /* the body really tumbles: w is not parallel to L (oblique, non-principal spin) */
    double wl = fe_dot(s->body_w, s->body_l) / (sqrt(fe_dot(s->body_w, s->body_w)) * lnorm);
    CHECK(wl < 0.999);
    /* the centre drifts at v0 */
    for (int i = 0; i < 3; i++) CHECK_NEAR(s->body_v[i], v0[i], 1e-12);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a rigid block loaded by F on all its nodes and by gravity: V = (F/M + g) t exactly, no
 * spin; total energy constant (work of F and g = kinetic energy) */
static void test_pushed_block(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d = rigid_box("block", 0.1, 0.05, 0.08, 3, 1000);
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    fe_load_desc l = {.where = FE_WHERE_ALL, .force = {120, 0, 30}};
    snprintf(l.part, sizeof l.part, "block");
    CHECK(fe_builder_add_load(b, &l, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-4;
    o.gravity[2] = -9.81;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    const double M = 1000 * 0.1 * 0.05 * 0.08;
    CHECK_REL(m->body[0].mass, M, 1e-12);
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    for (int k = 0; k < 1000; k++) CHECK(fe_step(m, s) == MCS_OK);
    /* V(n+1/2) = a (t_n + dt/2) with t_n = energy_time */
    double t = s->energy_time + 0.5 * s->dt_prev, a[3] = {120 / M, 0, 30 / M - 9.81};
    for (int i = 0; i < 3; i++) CHECK_NEAR(s->body_v[i], a[i] * t, 1e-12 * fabs(a[0]) * t);
    CHECK(fabs(s->body_w[0]) + fabs(s->body_w[1]) + fabs(s->body_w[2]) < 1e-12);
    /* a node moves with the body: x = x0 + a t^2 / 2 (t = time) */
    double tt = s->time;
    CHECK_NEAR(s->node_x[0], m->node_x0[0] + 0.5 * a[0] * tt * tt, 1e-12);
    CHECK_NEAR(s->energy[FE_E_total], s->energy0, 1e-9 * s->energy[FE_E_kinetic]);
    CHECK_NEAR(fe_part_energy(m, s, 0, FE_E_kinetic), s->energy[FE_E_kinetic], 1e-12);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a rigid block at 2 m/s onto a penalty wall: the penalty force is elastic, so it leaves at
 * 2 m/s (to the O(dt) of the contact integration); kinematic walls are refused */
static void test_block_on_penalty_wall(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d = rigid_box("block", 0.05, 0.05, 0.05, 2, 2000);
    d.mesh.origin[2] = 0.001;
    d.initial_velocity[2] = -2;
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    fe_wall_desc w = {.normal = {0, 0, 1}, .method = FE_WALL_KINEMATIC};
    snprintf(w.name, sizeof w.name, "floor");
    CHECK(fe_builder_add_wall(b, &w, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-5;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_ERR_UNSUPPORTED);
    CHECK_STR_CONTAINS(err.msg, "cannot stop rigid part 'block'");
    b->wall[0].method = FE_WALL_PENALTY;
    b->wall[0].penalty_scale = 0.05;
    mcs_error e2 = {0};
    CHECK(fe_model_create(b, &o, &m, &e2) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double fmax_ = 0;
    while (s->time < 0.01 && fe_step(m, s) == MCS_OK) fmax_ = fmax(fmax_, s->wall_normal[0]);
    CHECK(fmax_ > 0);
    FIG("fe.rigid_wall_rebound_err", "%.0e", fabs(s->body_v[2] / 2.0 - 1));
    CHECK_REL(s->body_v[2], 2.0, 1.5e-3); /* 5e-4 stated: penalty onset and release */
    CHECK(fabs(s->body_v[0]) + fabs(s->body_v[1]) < 1e-9);
    CHECK_NEAR(s->energy[FE_E_total], s->energy0, 0.01 * s->energy0);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* an elastic column (10 hexes, E A / L = k, nu = 0, light) clamped at the bottom carries a
 * rigid block (mass M) on its top nodes (shared): the block oscillates with
 * T = 2 pi sqrt((M + m_bar / 3) / k) (Rayleigh's correction for the column's own mass;
 * Timoshenko, Vibration Problems in Engineering, sec. 1.3), the column's force reaching the
 * body through the shared nodes */
static void test_rigid_on_elastic_column(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    const double a = 0.01, len = 0.1, E = 1e9, rho = 100, M = 1.0;
    const int ne = 10;
    fe_part_desc col = ft_part("column", FE_SECTION_SOLID, E, 0, rho);
    fe_part_desc top = ft_part("mass", FE_SECTION_SOLID, E, 0.3, M / (a * a * a));
    top.material.model = FE_MAT_RIGID;
    int pc, pt;
    CHECK(fe_builder_add_part(b, &col, &pc, &err) == MCS_OK);
    CHECK(fe_builder_add_part(b, &top, &pt, &err) == MCS_OK);
    /* layers of 4 nodes at z = k a (k = 0..ne + 1); the last hex is the rigid block */
    for (int k = 0; k <= ne + 1; k++) {
        double z = k < ne + 1 ? k * len / ne : len + a;
        double xy[4][2] = {{0, 0}, {a, 0}, {a, a}, {0, a}};
        for (int i = 0; i < 4; i++) {
            double x[3] = {xy[i][0], xy[i][1], z};
            CHECK(fe_builder_add_node(b, x, NULL, &err) == MCS_OK);
        }
    }
    for (int k = 0; k <= ne; k++) {
        int c[8];
        for (int i = 0; i < 4; i++) c[i] = 4 * k + i, c[4 + i] = 4 * (k + 1) + i;
        CHECK(fe_builder_add_elem(b, k < ne ? pc : pt, c, &err) == MCS_OK);
    }
    for (int i = 0; i < 4; i++) CHECK(fe_builder_fix_node(b, i, FE_DOF_ALL, NULL, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    double mbar = rho * a * a * len, k = E * a * a / len;
    /* the body carries the block and half of the top column element */
    CHECK_REL(m->body[0].mass, M + mbar / ne / 2, 1e-12);
    for (int n = 0; n < m->nnode; n++)
        if (m->node_body[n] >= 0) m->node_v0[3 * n + 2] = 0.1;
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    const double T = 2 * M_PI * sqrt((M + mbar / 3) / k);
    double zprev = 0, tprev = 0, tc[3];
    int nc = 0;
    while (s->time < 2.6 * T && fe_step(m, s) == MCS_OK) {
        double z = s->body_x[2] - m->body[0].x0[2];
        if (zprev > 0 && z <= 0 && nc < 3) tc[nc++] = tprev + (s->time - tprev) * zprev / (zprev - z);
        zprev = z, tprev = s->time;
    }
    CHECK(s->err.status == MCS_OK);
    CHECK(nc >= 2);
    if (nc >= 2) {
        printf("  rigid mass on a column: T %.6g s, 2 pi sqrt(M_eff/k) %.6g s (%+.3f %%)\n",
               tc[1] - tc[0], T, 100 * ((tc[1] - tc[0]) / T - 1));
        FIG("fe.rigid_column_period_err", "%.0e", fabs((tc[1] - tc[0]) / T - 1));
        CHECK_REL(tc[1] - tc[0], T, 6e-6); /* 2e-6 stated */
    }
    double e0 = 0.5 * (M + mbar / ne / 2) * 0.01;
    CHECK_NEAR(s->energy[FE_E_total], s->energy0, 0.01 * e0);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a boundary on a rigid part's nodes holds the body: translations at the prescribed velocity
 * (gravity acting), rotations held; the constraint's work balances the energy */
static void test_constrained_body(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d = rigid_box("block", 0.1, 0.05, 0.08, 2, 1000);
    d.initial_velocity[1] = 3; /* free along y */
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    fe_boundary_desc bc = ft_bc("block", FE_WHERE_X_MIN, FE_DOF_X | FE_DOF_Z | FE_DOF_ROT);
    bc.velocity[0] = 2, bc.velocity[2] = -1;
    CHECK(fe_builder_add_boundary(b, &bc, &err) == MCS_OK);
    fe_load_desc l = {.where = FE_WHERE_ALL, .force = {50, 20, 70}};
    snprintf(l.part, sizeof l.part, "block");
    CHECK(fe_builder_add_load(b, &l, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-4;
    o.gravity[2] = -9.81;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    CHECK(m->body[0].fix == (FE_DOF_X | FE_DOF_Z | FE_DOF_ROT));
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    for (int k = 0; k < 500; k++) CHECK(fe_step(m, s) == MCS_OK);
    const double M = m->body[0].mass, t = s->energy_time + 0.5 * s->dt_prev;
    CHECK_NEAR(s->body_v[0], 2, 1e-12);
    CHECK_NEAR(s->body_v[2], -1, 1e-12);
    CHECK_NEAR(s->body_v[1], 3 + 20 / M * t, 1e-9);
    CHECK(fabs(s->body_w[0]) + fabs(s->body_w[1]) + fabs(s->body_w[2]) == 0);
    /* every node moves with the body */
    for (int n = 0; n < m->nnode; n++) {
        CHECK_NEAR(s->node_x[3 * n] - m->node_x0[3 * n], 2 * s->time, 1e-12);
        CHECK_NEAR(s->node_x[3 * n + 2] - m->node_x0[3 * n + 2], -1 * s->time, 1e-12);
    }
    CHECK_NEAR(s->energy[FE_E_total], s->energy0, 1e-9 * s->energy[FE_E_kinetic]);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

int main(void)
{
    RUN(test_tumbling_plate);
    RUN(test_pushed_block);
    RUN(test_block_on_penalty_wall);
    RUN(test_rigid_on_elastic_column);
    RUN(test_constrained_body);
    TEST_END();
}

/* test_fe_wall: planar rigid walls with mass (fe/step/fe_wall.c; LS-DYNA *RIGIDWALL_PLANAR_MOVING)
 * against closed forms: momentum, the elastic two-body collision, the energy balance. */
#include <math.h>

#include "fe/fe_keyword.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/fe_test_util.h"
#include "tests/fe_test_build.h"

#include <stdlib.h>
#include <unistd.h>

/* a wall of mass M at speed V along +x hits a free point mass m at rest. The penalty spring is
 * linear and elastic, so the collision is elastic: afterwards (Newton; any mechanics text,
 * e.g. Goldstein, Classical Mechanics, 3rd ed., sec. 3.10)
 *     V' = (M - m)/(M + m) V,   v' = 2M/(M + m) V,
 * and the momentum M V + m v is conserved at every step (equal and opposite forces in the same
 * central difference), to round-off. The penalty onset within a step leaves an error of the
 * order of the penalty scale s (energy k (v dt)^2 / (m v^2) = s); s = 0.002 here. */
static void test_wall_hits_point_mass(void)
{
    const double M = 3, mpt = 1, V = 2, dt = 1e-6;
    /* a part far behind the wall so that the model has one (not a slave: behind the plane) */
    fe_part_desc d = ft_part("dummy", FE_SECTION_SOLID, 1e6, 0.3, 1000);
    ft_box(&d, 0.01, 0.01, 0.01, 1, 1, 1);
    d.mesh.origin[0] = -10;
    fe_builder *b;
    mcs_error err = {0};
    CHECK(ft_builder(&b, &d, NULL, &err) == MCS_OK);
    int node;
    double p[3] = {0.001, 0, 0};
    CHECK(fe_builder_add_node(b, p, &node, &err) == MCS_OK);
    fe_mass_desc md = {.node = node, .mass = mpt};
    CHECK(fe_builder_add_mass(b, &md, &err) == MCS_OK);
    fe_wall_desc w = {.normal = {1, 0, 0}, .velocity = {V, 0, 0}, .method = FE_WALL_PENALTY,
                      .mass = M};
    snprintf(w.name, sizeof w.name, "ram");
    /* a wall with mass moves along its normal (kinematic walls with mass: test_fe_wall_kin.c) */
    w.velocity[1] = 1;
    mcs_error e2 = {0};
    CHECK(fe_builder_add_wall(b, &w, &e2) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e2.msg, "parallel to the normal");
    w.velocity[1] = 0;
    w.penalty_scale = 0.002;
    CHECK(fe_builder_add_wall(b, &w, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = dt;
    o.history_capacity = 100000;
    fe_model *m;
    fe_state *s;
    CHECK(ft_model_state(&b, &o, &m, &s, &err) == MCS_OK);
    if (!m) return;
    double pmax = 0, fmax_ = 0;
    while (s->time < 3e-3 && fe_step(m, s) == MCS_OK) {
        double pm = M * s->wall_v[0] + mpt * s->node_v[3 * node];
        pmax = fmax(pmax, fabs(pm - M * V));
        fmax_ = fmax(fmax_, s->wall_normal[0]);
    }
    CHECK(s->err.status == MCS_OK);
    CHECK(fmax_ > 0);
    printf("  wall M %g at %g m/s on point mass %g: wall %.6f (closed form %.6f), mass %.6f "
           "(%.6f), momentum error %.2e, energy %.3e of E0\n",
           M, V, mpt, s->wall_v[0], (M - mpt) / (M + mpt) * V, s->node_v[3 * node],
           2 * M / (M + mpt) * V, pmax, (s->energy[FE_E_total] - s->energy0) / s->energy0);
    FIG("fe.wallm_wall_err", "%+.0e", s->wall_v[0] / ((M - mpt) / (M + mpt) * V) - 1);
    FIG("fe.wallm_mass_err", "%+.0e", s->node_v[3 * node] / (2 * M / (M + mpt) * V) - 1);
    FIG("fe.wallm_momentum", "%.0e", pmax / (M * V));
    CHECK(pmax < 1e-12 * M * V);
    CHECK_REL(s->wall_v[0], (M - mpt) / (M + mpt) * V, 3e-4); /* -9e-5 stated */
    CHECK_REL(s->node_v[3 * node], 2 * M / (M + mpt) * V, 3e-4);
    CHECK(fabs(s->wall_v[1]) + fabs(s->wall_v[2]) == 0);
    /* after separation: kinetic energy = initial (elastic), total constant */
    CHECK_NEAR(s->energy[FE_E_total], s->energy0, 5e-3 * s->energy0);
    CHECK_REL(s->energy[FE_E_kinetic], 0.5 * M * V * V, 5e-3);
    /* the wall's displacement follows its velocity: d(t_n) is the wall's own history */
    CHECK(s->wall_disp[0] > 0 && s->wall_disp[0] < V * s->time);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a wall of mass M (twice the bar's) at 5 m/s hits a free elastic hex bar (nu = 0) end on:
 * momentum conserved to round-off at every step; energy balance closes after the impact.
 * Saint-Venant's solution for a mass striking a bar (Goldsmith, Impact, 1960, ch. 2): the force
 * starts at rho c A V when the struck end takes the wall's speed at once; the penalty spring
 * (scale 0.1) rounds the rise, so the peak is a fraction of it (measured 0.76) */
static void test_wall_hits_bar(void)
{
    const double E = 2e9, rho = 1000, a = 0.01, L = 0.2, V = 5;
    fe_part_desc d = ft_part("bar", FE_SECTION_SOLID, E, 0, rho);
    ft_box(&d, L, a, a, 40, 1, 1);
    d.mesh.origin[0] = 1e-4;
    fe_builder *b;
    mcs_error err = {0};
    CHECK(ft_builder(&b, &d, NULL, &err) == MCS_OK);
    const double mbar = rho * a * a * L, M = 2 * mbar;
    fe_wall_desc w = {.normal = {1, 0, 0}, .velocity = {V, 0, 0}, .method = FE_WALL_PENALTY,
                      .mass = M, .penalty_scale = 0.1};
    snprintf(w.name, sizeof w.name, "ram");
    CHECK(fe_builder_add_wall(b, &w, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.bulk_q1 = o.bulk_q2 = 0; /* no bulk viscosity: elastic, energy conserved */
    fe_model *m;
    fe_state *s;
    CHECK(ft_model_state(&b, &o, &m, &s, &err) == MCS_OK);
    if (!m) return;
    const double c = sqrt(E / rho), tend = 6 * L / c;
    double perr = 0, fmax_ = 0;
    while (s->time < tend && fe_step(m, s) == MCS_OK) {
        double pm = M * s->wall_v[0];
        for (int n = 0; n < m->nnode; n++) pm += m->node_mass[n] * s->node_v[3 * n];
        perr = fmax(perr, fabs(pm - M * V));
        fmax_ = fmax(fmax_, s->wall_normal[0]);
    }
    CHECK(s->err.status == MCS_OK);
    double F0 = rho * c * a * a * V;
    printf("  wall %g kg at %g m/s on a %g kg bar: momentum error %.2e of MV, peak force %.4g N "
           "(rho c A V %.4g), energy %.2e of E0\n",
           M, V, mbar, perr / (M * V), fmax_, F0, (s->energy[FE_E_total] - s->energy0) / s->energy0);
    FIG("fe.wallm_bar_momentum", "%.0e", perr / (M * V));
    FIG("fe.wallm_bar_energy", "%.0e", fabs(s->energy[FE_E_total] / s->energy0 - 1));
    FIG("fe.wallm_bar_peak", "%.2f", fmax_ / F0);
    CHECK(perr < 1e-12 * M * V);
    CHECK(fmax_ > 0.6 * F0 && fmax_ < 1.05 * F0); /* the penalty spring rounds the rise */
    CHECK_NEAR(s->energy[FE_E_total], s->energy0, 3e-8 * s->energy0); /* 8e-9 stated */
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* *RIGIDWALL_PLANAR_MOVING read (MASS, V0 in the deck's units), built as a penalty wall with
 * mass, and written back */
static void test_keyword_moving_wall(void)
{
    static const char deck[] =
        "*KEYWORD\n"
        "*NODE\n"
        "       1             0.0             0.0             0.0\n"
        "*RIGIDWALL_PLANAR_MOVING_ID\n"
        "         7wall seven\n"
        "         0\n"
        "      -1.0       0.0       0.0       0.0       0.0       0.0\n"
        "    2.5E-3    -5.0E3\n"
        "*END\n";
    fe_kw_opts o = fe_kw_opts_default();
    o.units = "mm-s-t";
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    CHECK(fe_kw_read_mem("moving.k", deck, sizeof deck - 1, &o, &d, &err) == MCS_OK);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK(d->nwall == 1 && d->wall[0].moving == 1 && d->wall[0].id == 7);
    CHECK_REL(d->wall[0].mass, 2.5, 1e-12);  /* 2.5e-3 t */
    CHECK_REL(d->wall[0].v0, -5.0, 1e-12);   /* -5000 mm/s */
    CHECK_REL(d->wall[0].tail[0], -1e-3, 1e-12);
    /* written and read back */
    char path[] = "/tmp/mcrash_wall_XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    if (fd >= 0) close(fd);
    CHECK(fe_kw_write(d, path, FE_KW_FIXED, &err) == MCS_OK);
    fe_kw_deck *e = NULL;
    CHECK(fe_kw_read(path, &o, &e, &err) == MCS_OK);
    if (e) {
        CHECK(e->nwall == 1 && e->wall[0].moving == 1);
        CHECK(e->wall[0].mass == d->wall[0].mass && e->wall[0].v0 == d->wall[0].v0);
        fe_kw_deck_destroy(&e);
    }
    remove(path);
    /* a moving wall without mass is an error at its card */
    static const char bad2[] = "*KEYWORD\n*RIGIDWALL_PLANAR_MOVING\n0\n0,0,0,1,0,0\n"
                               "0.0,1.0\n*END\n";
    fe_kw_deck *f = NULL;
    mcs_error e3 = {0};
    CHECK(fe_kw_read_mem("bad.k", bad2, sizeof bad2 - 1, &o, &f, &e3) == MCS_ERR_FORMAT);
    CHECK_STR_CONTAINS(e3.msg, "bad.k:5:");
    CHECK_STR_CONTAINS(e3.msg, "MASS");
    fe_kw_deck_destroy(&f);
    fe_kw_deck_destroy(&d);
}

int main(void)
{
    RUN(test_wall_hits_point_mass);
    RUN(test_wall_hits_bar);
    RUN(test_keyword_moving_wall);
    TEST_END();
}

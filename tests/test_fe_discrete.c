/* test_fe_discrete: discrete springs and dampers, point masses and gravity in the explicit FE
 * kernel (fe_discrete.c, fe_gravity.c), against closed forms. */
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/fe_test_util.h"
#include "fe/fe_builder_impl.h"

static mcs_status add_free_node(fe_builder *b, double x, double y, double z, int *idx)
{
    mcs_error err = {0};
    double p[3] = {x, y, z};
    return fe_builder_add_node(b, p, idx, &err);
}

/* a hex part so that the model has one (fe_model_create needs a part); far away, untouched */
static void add_dummy_part(fe_builder *b)
{
    mcs_error err = {0};
    fe_part_desc d = ft_part("dummy", FE_SECTION_SOLID, 1e6, 0.3, 1000);
    d.mesh.generate = FE_MESH_BOX;
    d.mesh.size[0] = d.mesh.size[1] = d.mesh.size[2] = 0.01;
    d.mesh.divisions[0] = d.mesh.divisions[1] = d.mesh.divisions[2] = 1;
    d.mesh.origin[0] = 10;
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
}

/* times of the upward zero crossings of x(t) (linear interpolation between steps) */
static int up_crossings(const double *t, const double *x, int n, double *tc, int cap)
{
    int k = 0;
    for (int i = 1; i < n && k < cap; i++)
        if (x[i - 1] < 0 && x[i] >= 0) tc[k++] = t[i - 1] + (t[i] - t[i - 1]) * (-x[i - 1]) / (x[i] - x[i - 1]);
    return k;
}

/* run the oscillator (node along x; relative to node2 if >= 0) for nsteps, recording the
 * displacement at t_{n+1} */
static int record2(const fe_model *m, fe_state *s, int node, int node2, int nsteps, double *t,
                   double *x)
{
    int k = 0;
    for (int i = 0; i < nsteps && s->err.status == MCS_OK; i++) {
        if (fe_step(m, s) != MCS_OK) break;
        t[k] = s->time;
        x[k] = s->node_x[3 * node] - m->node_x0[3 * node];
        if (node2 >= 0) x[k] -= s->node_x[3 * node2] - m->node_x0[3 * node2];
        k++;
    }
    return k;
}

static int record(const fe_model *m, fe_state *s, int node, int nsteps, double *t, double *x)
{
    return record2(m, s, node, -1, nsteps, t, x);
}

/* undamped spring-mass oscillator: T = 2 pi sqrt(m/k) (node to an anchor) and
 * T = 2 pi sqrt(mu/k), 1/mu = 1/m1 + 1/m2 (two free masses); central differences shorten the
 * period by (w dt)^2/24 (Belytschko, Liu & Moran 2000, Sec. 6.3): dt = T/2000 -> 4e-7 */
static void test_spring_mass_period(void)
{
    double perr = 0, eerr = 0; /* worst over both: period (relative), energy (of e0) */
    for (int two = 0; two < 2; two++) {
        fe_builder *b;
        mcs_error err = {0};
        CHECK(fe_builder_create(&b, &err) == MCS_OK);
        add_dummy_part(b);
        int a, c;
        CHECK(add_free_node(b, 0, 0, 0, &a) == MCS_OK);
        CHECK(add_free_node(b, 0.1, 0, 0, &c) == MCS_OK);
        const double mass = 2.0, mass2 = 3.0, k = 5000;
        fe_mass_desc md = {.node = a, .mass = mass};
        CHECK(fe_builder_add_mass(b, &md, &err) == MCS_OK);
        fe_spring_desc sd = {.stiffness = k};
        snprintf(sd.name, sizeof sd.name, "s");
        sd.end[0].node = a;
        if (two) {
            fe_mass_desc m2 = {.node = c, .mass = mass2};
            CHECK(fe_builder_add_mass(b, &m2, &err) == MCS_OK);
            sd.end[1].node = c;
        } else {
            sd.end[1].node = -1; /* anchor at point */
            sd.end[1].point[0] = 0.1;
        }
        CHECK(fe_builder_add_spring(b, &sd, &err) == MCS_OK);
        double mu = two ? mass * mass2 / (mass + mass2) : mass, w = sqrt(k / mu);
        double T = 2 * M_PI / w;
        fe_opts o = fe_opts_default();
        o.dt_max = T / 2000;
        fe_model *m = NULL;
        CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
        fe_builder_destroy(&b);
        if (!m) {
            fprintf(stderr, "%s\n", err.msg);
            return;
        }
        /* the spring's stable step 2/w (no damping) */
        CHECK_REL(m->dt_discrete, 2 / w, 1e-12);
        m->node_v0[3 * a] = 0.5; /* m/s */
        fe_state *s = NULL;
        CHECK(fe_state_create(m, &s, &err) == MCS_OK);
        enum { N = 7000 };
        static double t[N], x[N], tc[8];
        int n = record2(m, s, a, two ? c : -1, N, t, x);
        CHECK(n == N);
        /* the stretch starts at 0 going up: crossings at T, 2T, 3T */
        int nc = up_crossings(t, x, n, tc, 8);
        CHECK(nc >= 3);
        if (nc >= 3)
            perr = fmax(perr, fmax(fabs((tc[2] - tc[0]) / (2 * T) - 1), fabs(tc[0] / T - 1)));
        /* energy: total constant; kinetic + spring energy = 1/2 m v0^2 (two masses: the
         * second is at rest at t = 0) */
        double e0 = 0.5 * mass * 0.25;
        eerr = fmax(eerr, fabs(s->energy[FE_E_total] - s->energy0) / e0);
        eerr = fmax(eerr, fabs(s->energy[FE_E_kinetic] + s->energy[FE_E_internal] - e0) / e0);
        fe_state_destroy(&s);
        fe_model_destroy(&m);
    }
    printf("  spring-mass: period to %.2e (central differences: (w dt)^2/24 = %.2e), energy to "
           "%.1e of e0\n", perr, pow(2 * M_PI / 2000, 2) / 24, eerr);
    FIG("fe.spring_period_err", "%.0e", perr);
    FIG("fe.spring_energy_err", "%.0e", eerr);
    CHECK(perr < 1.2e-6); /* 4e-7 stated, the central-difference error */
    CHECK(eerr < 3e-13); /* 1e-13 stated */
}

/* viscous damping c: x = A exp(-z w t) sin(w_d t), z = c / (2 sqrt(k m)), w_d = w sqrt(1 - z^2):
 * successive maxima one damped period T_d = 2 pi / w_d apart, in the ratio exp(-z w T_d)
 * (any vibrations text, e.g. Rao, Mechanical Vibrations, Sec. 2.6); energy lost = dissipated */
static void test_spring_damper_decay(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    add_dummy_part(b);
    int a;
    CHECK(add_free_node(b, 0, 0, 0, &a) == MCS_OK);
    const double mass = 1.5, k = 2000, z = 0.05, c = 2 * z * sqrt(k * mass);
    fe_mass_desc md = {.node = a, .mass = mass};
    CHECK(fe_builder_add_mass(b, &md, &err) == MCS_OK);
    fe_spring_desc sd = {.stiffness = k, .damping = c};
    sd.end[0].node = a;
    sd.end[1].node = -1;
    sd.end[1].point[0] = -0.2; /* the spring lies along -x */
    CHECK(fe_builder_add_spring(b, &sd, &err) == MCS_OK);
    const double w = sqrt(k / mass), wd = w * sqrt(1 - z * z), Td = 2 * M_PI / wd;
    fe_opts o = fe_opts_default();
    o.dt_max = Td / 4000;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    m->node_v0[3 * a] = 1.0;
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    enum { N = 13000 };
    static double t[N], x[N];
    int n = record(m, s, a, N, t, x);
    CHECK(n == N);
    /* maxima by a parabola through the three samples around each discrete peak */
    double tp[4], xp[4];
    int np = 0;
    for (int i = 1; i + 1 < n && np < 4; i++)
        if (x[i] > x[i - 1] && x[i] >= x[i + 1] && x[i] > 0) {
            double d1 = x[i + 1] - x[i - 1], d2 = x[i + 1] - 2 * x[i] + x[i - 1], h = t[i] - t[i - 1];
            double u = -0.5 * d1 / d2;
            tp[np] = t[i] + u * h;
            xp[np++] = x[i] - 0.125 * d1 * d1 / d2;
        }
    CHECK(np >= 3);
    double terr = 1, rerr = 1;
    if (np >= 3) {
        terr = fabs((tp[2] - tp[1]) / Td - 1);
        rerr = fabs(xp[2] / xp[1] / exp(-z * w * Td) - 1);
        CHECK_REL(log(xp[1] / xp[0]), -z * w * Td, 1e-2); /* the first peak: phase shifted */
    }
    double e0 = 0.5 * mass * 1.0, berr = fabs(s->energy[FE_E_total] - s->energy0) / e0;
    printf("  spring-damper: T_d to %.1e, peak ratio to %.1e, balance %.1e of e0\n", terr, rerr,
           berr);
    FIG("fe.damper_period_err", "%.0e", terr);
    FIG("fe.damper_ratio_err", "%.0e", rerr);
    FIG("fe.damper_balance", "%.0e", berr);
    CHECK(s->energy[FE_E_dissipated] > 0.5 * e0);
    CHECK(terr < 1.2e-4 && rerr < 4e-5 && berr < 2.4e-4); /* 4e-05, 1e-05, 8e-05 stated */
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a tabulated spring stretched at a prescribed velocity: the force is the curve at the
 * elongation (exact for piecewise-linear tables), the energy its integral */
static void test_spring_curve(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    add_dummy_part(b);
    int a;
    CHECK(add_free_node(b, 0, 0, 0.05, &a) == MCS_OK);
    fe_mass_desc md = {.node = a, .mass = 0.1};
    CHECK(fe_builder_add_mass(b, &md, &err) == MCS_OK);
    fe_spring_desc sd = {.ncurve = 3, .curve = {{-0.01, -500}, {0, 0}, {0.01, 100}, {0.02, 400}}};
    sd.ncurve = 4;
    snprintf(sd.name, sizeof sd.name, "tab");
    sd.end[0].node = -1; /* anchor at the origin */
    sd.end[1].node = a;
    CHECK(fe_builder_add_spring(b, &sd, &err) == MCS_OK);
    double v[3] = {0, 0, 0.2};
    CHECK(fe_builder_fix_node(b, a, FE_DOF_TRANS, v, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double maxerr = 0;
    while (s->time < 0.1 && fe_step(m, s) == MCS_OK) {
        double d = 0.2 * s->energy_time; /* elongation at the force evaluation time */
        double f = d <= 0.01 ? 1e4 * d : 100 + 3e4 * (d - 0.01);
        maxerr = fmax(maxerr, fabs(s->spring_f[0] - f));
    }
    printf("  tabulated spring: force to %.1e N of 100\n", maxerr);
    FIG("fe.tabspring_force_err", "%.0e", maxerr / 100);
    CHECK(maxerr < 6e-13 * 100); /* 2e-13 stated */
    /* energy stored = integral of the curve, supplied as external (constraint) work */
    double d = 0.2 * s->energy_time;
    CHECK(d > 0.015);
    double w = 0.5 * 1e4 * 0.01 * 0.01 + 100 * (d - 0.01) + 0.5 * 3e4 * (d - 0.01) * (d - 0.01);
    double werr = fabs(s->energy[FE_E_internal] / w - 1); /* trapezoid across the kink */
    double berr = fabs(s->energy[FE_E_total] - s->energy0) / w;
    printf("  tabulated spring: energy to %.1e of the integral, balance %.1e\n", werr, berr);
    FIG("fe.tabspring_energy_err", "%.0e", werr);
    FIG("fe.tabspring_balance", "%.0e", berr);
    CHECK(werr < 2.2e-6 && berr < 3e-13); /* 7e-07, 9e-14 stated */
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* free fall: every node accelerates at g exactly (a stress-free translation), positions
 * x0 + g t^2 / 2; kinetic energy = work of gravity, total constant */
static void test_gravity_free_fall(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d = ft_part("block", FE_SECTION_SOLID, 1e7, 0.3, 1200);
    d.mesh.generate = FE_MESH_BOX;
    d.mesh.size[0] = 0.1, d.mesh.size[1] = 0.05, d.mesh.size[2] = 0.04;
    d.mesh.divisions[0] = 4, d.mesh.divisions[1] = 2, d.mesh.divisions[2] = 2;
    d.initial_velocity[0] = 1.0;
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    const double g = 9.80665;
    o.gravity[2] = -g;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    for (int i = 0; i < 400; i++) CHECK(fe_step(m, s) == MCS_OK);
    double amax = 0, xerr = 0, t = s->time, abar = 0;
    for (int n = 0; n < m->nnode; n++) {
        amax = fmax(amax, fabs(s->node_a[3 * n + 2] + g) + fabs(s->node_a[3 * n]));
        abar += m->node_mass[n] * s->node_a[3 * n + 2] / m->mass_total;
        double z = m->node_x0[3 * n + 2] - 0.5 * g * t * t, x = m->node_x0[3 * n] + 1.0 * t;
        xerr = fmax(xerr, fabs(s->node_x[3 * n + 2] - z) + fabs(s->node_x[3 * n] - x));
    }
    /* the part's acceleration (the internal forces cancel) is g to round-off; single nodes
     * see round-off stresses of the moving mesh (~1e-11 Pa) */
    printf("  free fall: part acceleration to %.1e of g, nodes %.1e of g, positions %.1e m\n",
           fabs(abar / g + 1), amax / g, xerr);
    FIG("fe.fall_accel_err", "%.0e", fabs(abar / g + 1));
    FIG("fe.fall_x_err_m", "%.0e", xerr);
    CHECK(fabs(abar / g + 1) < 7e-16); /* 2e-16 stated */
    CHECK(amax <= 5e-12 * g); /* 1.4e-12 measured */
    CHECK(xerr <= 6e-15); /* 2e-15 stated */
    /* KE(t_n) = 1/2 M (v0^2 + (g t_n)^2) up to the half-step product; total constant */
    double tn = s->energy_time, M = m->mass_total;
    CHECK_REL(s->energy[FE_E_external_work], 0.5 * M * g * g * tn * tn, 1e-4);
    double fb = fabs(s->energy[FE_E_total] - s->energy0) / s->energy[FE_E_kinetic];
    printf("  free fall: balance %.1e of KE\n", fb);
    FIG("fe.fall_balance", "%.0e", fb);
    CHECK(fb < 3e-15); /* 9e-16 stated */
    CHECK_NEAR(s->energy[FE_E_internal], 0, 1e-12);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* point masses: on a part's side (split equally) and at the nearest node; bad inputs */
static void test_point_masses_and_errors(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc d = ft_part("plate", FE_SECTION_SHELL, 70e9, 0.3, 2700);
    d.section.thickness = 0.002;
    d.mesh.generate = FE_MESH_PLATE;
    d.mesh.size[0] = d.mesh.size[1] = 0.1;
    d.mesh.divisions[0] = d.mesh.divisions[1] = 2;
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    fe_mass_desc m1 = {.node = -1, .where = FE_WHERE_X_MAX, .mass = 0.3};
    snprintf(m1.part, sizeof m1.part, "plate");
    fe_mass_desc m2 = {.node = -1, .at_point = 1, .point = {0.051, 0.049, 0.01}, .mass = 0.5};
    snprintf(m2.part, sizeof m2.part, "plate");
    CHECK(fe_builder_add_mass(b, &m1, &err) == MCS_OK);
    CHECK(fe_builder_add_mass(b, &m2, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (m) {
        double plate = 2700 * 0.002 * 0.01;
        CHECK_REL(m->mass_total, plate + 0.8, 1e-12);
        for (int n = 0; n < m->nnode; n++) {
            const double *x = m->node_x0 + 3 * n;
            double share = (x[0] > 0.099 ? 0.1 : 0) + (fabs(x[0] - 0.05) < 1e-9 && fabs(x[1] - 0.05) < 1e-9 ? 0.5 : 0);
            int corner = (x[0] < 1e-9 || x[0] > 0.099) + (x[1] < 1e-9 || x[1] > 0.099);
            double own = plate / 16 * (corner == 2 ? 1 : corner == 1 ? 2 : 4);
            CHECK_REL(m->node_mass[n], own + share, 1e-12);
        }
        fe_model_destroy(&m);
    }
    /* errors: both ends anchored; unknown part; a spring on a node without mass */
    fe_spring_desc bad = {.stiffness = 1};
    snprintf(bad.name, sizeof bad.name, "bad");
    bad.end[0].node = bad.end[1].node = -1;
    bad.end[1].point[0] = 1;
    CHECK(fe_builder_add_spring(b, &bad, &err) == MCS_OK);
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "both ends are fixed anchors");
    fe_builder_destroy(&b);

    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    add_dummy_part(b);
    int a;
    CHECK(add_free_node(b, 0, 0, 0, &a) == MCS_OK);
    fe_spring_desc s1 = {.stiffness = 1};
    snprintf(s1.name, sizeof s1.name, "massless");
    s1.end[0].node = a;
    s1.end[1].node = -1;
    s1.end[1].point[2] = 1;
    CHECK(fe_builder_add_spring(b, &s1, &err) == MCS_OK);
    mcs_error e2 = {0};
    CHECK(fe_model_create(b, NULL, &m, &e2) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(e2.msg, "has no mass");
    fe_spring_desc s2 = s1;
    s2.end[0].node = -1;
    snprintf(s2.end[0].part, sizeof s2.end[0].part, "nope");
    fe_builder_destroy(&b);
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    add_dummy_part(b);
    CHECK(fe_builder_add_spring(b, &s2, &err) == MCS_OK);
    mcs_error e3 = {0};
    CHECK(fe_model_create(b, NULL, &m, &e3) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(e3.msg, "unknown part 'nope'");
    mcs_error e4 = {0};
    fe_spring_desc s3 = {.stiffness = -1};
    CHECK(fe_builder_add_spring(b, &s3, &e4) == MCS_ERR_RANGE);
    fe_mass_desc m3 = {.node = 0, .mass = 0};
    CHECK(fe_builder_add_mass(b, &m3, &e4) == MCS_ERR_RANGE);
    fe_builder_destroy(&b);
}

/* two spring parts ("front": k1, "rear": k2), each a mass on an anchored spring oscillating:
 * a linear spring's elastic energy summed with the trapezoidal rule over the elongation
 * increments telescopes to 1/2 k x^2 (x the elongation now), so each part's internal energy is
 * exactly its spring's 1/2 k x^2, and the two parts add up to the global internal energy
 * (the only other part is an untouched hex); a spring named after an element part is refused */
static void test_spring_part_energies(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    add_dummy_part(b);
    const double k[2] = {4000, 9000}, mass = 1.5;
    const char *pn[2] = {"front", "rear"};
    int nd[2];
    for (int i = 0; i < 2; i++) {
        CHECK(add_free_node(b, 0, 0.5 * i, 0, &nd[i]) == MCS_OK);
        fe_mass_desc md = {.node = nd[i], .mass = mass};
        CHECK(fe_builder_add_mass(b, &md, &err) == MCS_OK);
        fe_spring_desc sd = {.stiffness = k[i]};
        snprintf(sd.name, sizeof sd.name, "s%d", i);
        snprintf(sd.part, sizeof sd.part, "%s", pn[i]);
        sd.end[0].node = nd[i];
        sd.end[1].node = -1;
        sd.end[1].point[0] = 0.1, sd.end[1].point[1] = 0.5 * i;
        CHECK(fe_builder_add_spring(b, &sd, &err) == MCS_OK);
    }
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-5;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    if (!m) {
        fprintf(stderr, "%s\n", err.msg);
        fe_builder_destroy(&b);
        return;
    }
    CHECK(m->nspring_part == 2 && fe_spring_part_find(m, "rear") == 1);
    m->node_v0[3 * nd[0]] = 0.3, m->node_v0[3 * nd[1]] = -0.2;
    fe_state *s;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double emax = 0;
    for (int n = 0; n < 3000 && fe_step(m, s) == MCS_OK; n++) {
        double sum = 0;
        for (int i = 0; i < 2; i++) {
            double x = s->spring_d[i], e = fe_spring_part_energy(m, s, i, FE_E_internal);
            emax = fmax(emax, fabs(e - 0.5 * k[i] * x * x) / (0.5 * mass * 0.09));
            sum += e;
        }
        CHECK_NEAR(sum, s->energy[FE_E_internal], 1e-12 * 0.5 * mass * 0.09);
    }
    printf("  spring parts: |E_part - k x^2/2| <= %.2e of the energy, parts sum to the global "
           "internal energy\n",
           emax);
    FIG("fe.spring_part_energy", "%.0e", emax);
    CHECK(emax < 6e-15); /* 2e-15 stated: the trapezoidal sum of a linear spring telescopes */
    CHECK(fe_spring_part_energy(m, s, 0, FE_E_internal) > 0);
    CHECK(isnan(fe_spring_part_energy(m, s, 2, FE_E_internal)));
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    /* a spring part named after an element part */
    snprintf(b->spring[0].part, FE_NAME_MAX, "dummy");
    mcs_error e2 = {0};
    CHECK(fe_model_create(b, &o, &m, &e2) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(e2.msg, "spring part 'dummy'");
    fe_builder_destroy(&b);
}

int main(void)
{
    RUN(test_spring_part_energies);
    RUN(test_spring_mass_period);
    RUN(test_spring_damper_decay);
    RUN(test_spring_curve);
    RUN(test_gravity_free_fall);
    RUN(test_point_masses_and_errors);
    TEST_END();
}

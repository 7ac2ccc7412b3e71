/* test_fe_joint: FE joints (fe_joint.h) against rigid-body mechanics in closed form:
 * a pendulum on a revolute joint (small-amplitude period, energy, bounded constraint gap), the
 * same pendulum as a nodal rigid body of elastic hexes, a conical pendulum on a spherical
 * joint (precession rate), a mass on a translational joint with a spring (mass-spring period)
 * and with a stop (elastic rebound: the
 * speed back, the time 2 d / v0 + pi sqrt(M / k_stop)), a cylindrical joint with spin and slide, a
 * spinning wheel on an axle of a free frame (angular momentum); and bad input. */
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/fe_test_util.h"

#include "fe/fe_builder_impl.h"
#include "fe/fe_elem.h"
#include "fe/fe_joint.h"
#include "fe/fe_solid.h"

#include <math.h>

static const double G = 9.81; /* [m/s^2] */

/* a square rod of n hexes, side a, from p0 along unit e3 to p0 + L e3 (part `name`) */
static int add_rod(fe_builder *b, const char *name, const double p0[3], const double e3[3],
                   double L, double a, int n, double rho, int rigid)
{
    mcs_error err = {0};
    fe_part_desc d = ft_part(name, FE_SECTION_SOLID, rigid ? 1e9 : 1e6, 0.3, rho);
    if (rigid) d.material.model = FE_MAT_RIGID;
    int ip;
    CHECK(fe_builder_add_part(b, &d, &ip, &err) == MCS_OK);
    /* e1, e2 normal to e3 with e1 x e2 = e3 (a positive hex volume) */
    double e1[3] = {0, 0, 0}, e2[3];
    int lo = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(e3[k]) < fabs(e3[lo])) lo = k;
    e1[lo] = 1;
    double t = fe_dot(e1, e3);
    for (int k = 0; k < 3; k++)
        e1[k] -= t * e3[k];
    t = sqrt(fe_dot(e1, e1));
    for (int k = 0; k < 3; k++)
        e1[k] /= t;
    fe_cross(e3, e1, e2);
    const int n0 = fe_builder_nnode(b);
    const double cs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int lev = 0; lev <= n; lev++)
        for (int c = 0; c < 4; c++) {
            double x[3];
            for (int k = 0; k < 3; k++)
                x[k] =
                    p0[k] + L * lev / n * e3[k] + 0.5 * a * (cs[c][0] * e1[k] + cs[c][1] * e2[k]);
            CHECK(fe_builder_add_node(b, x, NULL, &err) == MCS_OK);
        }
    for (int e = 0; e < n; e++) {
        int c[8];
        for (int k = 0; k < 4; k++)
            c[k] = n0 + 4 * e + k, c[4 + k] = n0 + 4 * (e + 1) + k;
        CHECK(fe_builder_add_elem(b, ip, c, &err) == MCS_OK);
    }
    return n0;
}

/* lumped moments of inertia of that rod about its end (pivot): the hex masses lumped 1/8 per
 * node put the trapezoidal rule on int z^2 dm, M L^2 (1/3 + 1/(6 n^2)), and the section's
 * nodes at a/2 from both section axes: I_perp = M (L^2 (1/3 + 1/(6 n^2)) + a^2/4) about an
 * axis normal to the rod, I_axis = M a^2 / 2 about the rod */
static double rod_iperp(double M, double L, double a, int n)
{
    return M * (L * L * (1.0 / 3 + 1.0 / (6.0 * n * n)) + a * a / 4);
}

static void set_spin(fe_model *m, const double w[3], const double about[3], const double v[3],
                     int node_begin, int node_end)
{
    for (int n = node_begin; n < node_end; n++) {
        double r[3], c[3];
        for (int i = 0; i < 3; i++)
            r[i] = m->node_x0[3 * n + i] - about[i];
        fe_cross(w, r, c);
        for (int i = 0; i < 3; i++)
            m->node_v0[3 * n + i] = v[i] + c[i];
    }
}

/* upward zero crossings of y(t) (linear interpolation) into tz; count */
static int crossing(double t0, double y0, double t1, double y1, double *tz, int k, int cap)
{
    if (y0 < 0 && y1 >= 0 && k < cap) tz[k++] = t0 + (t1 - t0) * (-y0) / (y1 - y0);
    return k;
}

static fe_joint_desc joint(const char *name, fe_joint_type type, const char *a, const char *b,
                           const double p[3], const double ax[3])
{
    fe_joint_desc d = fe_joint_desc_default();
    snprintf(d.name, sizeof d.name, "%s", name);
    d.type = type;
    snprintf(d.body[0], sizeof d.body[0], "%s", a);
    snprintf(d.body[1], sizeof d.body[1], "%s", b);
    memcpy(d.point, p, sizeof d.point);
    memcpy(d.axis, ax, sizeof d.axis);
    return d;
}

/* the pendulum: a rod L = 1 m, a = 20 mm, 4 hexes, 1000 kg/m^3 hanging from a revolute joint
 * about y at the origin (to the ground), started at the bottom with w0 = theta0 Omega.
 * Physical pendulum (e.g. Meriam & Kraige, Dynamics, 6/ compound pendulum):
 * Omega^2 = M g (L/2) / I_pivot, T = 2 pi / Omega (1 + theta0^2 / 16 + ...). `nrb`: the rod
 * is elastic and its nodes a nodal rigid body: the same motion. */
static void pendulum(int nrb)
{
    const double L = 1, a = 0.02, rho = 1000, th0 = 0.05;
    const int n = 4;
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    const double p0[3] = {0, 0, 0}, down[3] = {0, 0, -1}, ay[3] = {0, 1, 0};
    add_rod(b, "rod", p0, down, L, a, n, rho, !nrb);
    const char *body = "rod";
    if (nrb) {
        int nodes[20];
        for (int i = 0; i < 20; i++)
            nodes[i] = i;
        CHECK(fe_builder_add_nodal_rigid_body(b, "bob", nodes, 20, &err) == MCS_OK);
        body = "bob";
    }
    fe_joint_desc j = joint("pivot", FE_JOINT_REVOLUTE, body, "", p0, ay);
    CHECK(fe_builder_add_joint(b, &j, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-4;
    o.gravity[2] = -G;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) {
        printf("  %s\n", err.msg);
        return;
    }
    CHECK(m->nbody == 1 && m->njoint == 1);
    const double M = rho * a * a * L, Ip = rod_iperp(M, L, a, n);
    CHECK_REL(m->body[0].mass, M, 1e-12);
    const double Om = sqrt(M * G * 0.5 * L / Ip), T = 2 * M_PI / Om * (1 + th0 * th0 / 16);
    const double w0[3] = {0, th0 * Om, 0}, v0[3] = {0, 0, 0};
    set_spin(m, w0, p0, v0, 0, m->nnode);
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double tz[8], gap1 = 0, gapn = 0, emax = 0, ke_max = 0, e0 = NAN;
    int nz = 0;
    double tp = 0, yp = 0;
    const double t_end = 3.2 * T;
    while (s->time < t_end && fe_step(m, s) == MCS_OK) {
        /* the joint point of the rod and the mechanical energy (body state, independent) */
        const double *x = s->body_x, *R = s->body_rot, *V = s->body_v, *W = s->body_w;
        const double *Lm = s->body_l;
        double P[3], r0[3] = {0 - m->body[0].x0[0], 0 - m->body[0].x0[1], -m->body[0].x0[2]};
        for (int i = 0; i < 3; i++)
            P[i] = x[i] + R[3 * i] * r0[0] + R[3 * i + 1] * r0[1] + R[3 * i + 2] * r0[2];
        double gap = sqrt(fe_dot(P, P));
        if (s->time < T) gap1 = fmax(gap1, gap);
        if (s->time > 2.2 * T) gapn = fmax(gapn, gap);
        double ke = 0.5 * M * fe_dot(V, V) + 0.5 * fe_dot(Lm, W);
        /* + what the joint stores and has dissipated (its own penalty vibration) */
        const double *jo = s->joint_out;
        double zm = x[2] - 0.5 * s->dt_prev * V[2]; /* the height at t + dt/2, with V */
        double e = ke + M * G * zm + jo[FE_JOUT_EEL] + jo[FE_JOUT_EDISS];
        if (isnan(e0)) e0 = e;
        emax = fmax(emax, fabs(e - e0));
        ke_max = fmax(ke_max, ke);
        double y = s->joint_out[FE_JOUT_ANGLE];
        nz = crossing(tp, yp, s->time, y, tz, nz, 8);
        tp = s->time, yp = y;
    }
    CHECK(s->err.status == MCS_OK);
    CHECK(nz >= 3);
    double Tm = nz >= 3 ? (tz[nz - 1] - tz[0]) / (nz - 1) : 0;
    double err_pct = 100 * fabs(Tm / T - 1);
    printf("  %s: period %.6f s (closed form %.6f s, %.4f %%), energy drift %.2e of the swing, "
           "gap %.2e m (first period) %.2e m (third)\n",
           nrb ? "nodal rigid body" : "rigid part", Tm, T, err_pct, emax / ke_max, gap1, gapn);
    /* the error: central differences' O((Omega dt)^2) and the penalty's compliance */
    CHECK(err_pct < 0.01);
    if (!nrb) FIG_TOL("fe.joint_pendulum_period_err_pct", "%.4f", err_pct, 0.003);
    CHECK(emax < 1e-3 * ke_max);
    if (!nrb) FIG_TOL("fe.joint_pendulum_energy_pct", "%.3f", 100 * emax / ke_max, 0.03);
    /* static penalty gap: load M g over k = 0.1 / (dt^2 lambda), lambda = 1/M + (L/2)^2 / I_cm
     * (= 4/M for a slender rod); the gap stays at that size, no drift */
    const double Icm = Ip - M * 0.25 * L * L, lam = 1 / M + 0.25 * L * L / Icm;
    const double gap_static = M * G * lam * 1e-8 / 0.1;
    CHECK(gap1 < 2 * gap_static);
    CHECK(gapn < 1.2 * gap1);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

static void test_pendulum_revolute(void)
{
    pendulum(0);
}
static void test_pendulum_nodal_rigid_body(void)
{
    pendulum(1);
}

/* conical pendulum: the rod hangs from a spherical joint at alpha = 30 deg from the vertical
 * and turns about the vertical at the steady rate of a symmetric top with no spin:
 * Omega^2 cos(alpha) (I_perp - I_axis) = M g (L/2) (Euler's equations; e.g. Goldstein,
 * Classical Mechanics, 5.7, slow/fast precession with zero spin). It keeps its angle and
 * precesses at Omega. */
static void test_conical_spherical(void)
{
    const double L = 0.5, a = 0.02, rho = 2000, al = M_PI / 6;
    const int n = 2;
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    const double p0[3] = {0, 0, 0}, e3[3] = {sin(al), 0, -cos(al)}, z[3] = {0, 0, 1};
    add_rod(b, "rod", p0, e3, L, a, n, rho, 1);
    fe_joint_desc j = joint("ball", FE_JOINT_SPHERICAL, "rod", "", p0, z);
    CHECK(fe_builder_add_joint(b, &j, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-4;
    o.gravity[2] = -G;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    const double M = rho * a * a * L, I1 = rod_iperp(M, L, a, n), I3 = M * a * a / 2;
    const double Om = sqrt(M * G * 0.5 * L / (cos(al) * (I1 - I3)));
    const double w[3] = {0, 0, Om}, v0[3] = {0, 0, 0};
    set_spin(m, w, p0, v0, 0, m->nnode);
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    const double Tp = 2 * M_PI / Om;
    double dal = 0, az = 0, azp = 0;
    while (s->time < Tp && fe_step(m, s) == MCS_OK) {
        const double *x = s->body_x;
        double rr = sqrt(x[0] * x[0] + x[1] * x[1]);
        dal = fmax(dal, fabs(atan2(rr, -x[2]) - al));
        double a1 = atan2(x[1], x[0]);
        az += remainder(a1 - azp, 2 * M_PI);
        azp = a1;
    }
    double om_m = az / s->time, err_pct = 100 * fabs(om_m / Om - 1);
    printf("  conical: precession %.5f rad/s (closed form %.5f, %.4f %%), angle held to %.2e "
           "rad\n",
           om_m, Om, err_pct, dal);
    CHECK(err_pct < 0.05);
    CHECK(dal < 1e-3);
    FIG_TOL("fe.joint_conical_rate_err_pct", "%.3f", err_pct, 0.01);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a block on a translational joint along x to the ground: with a spring k, the mass-spring
 * period T = 2 pi sqrt(M / k); without, a stop at +d sends it back at its speed (the stop is
 * elastic: restitution 1) after 2 d / v0 (the stop contact lasts pi / omega_stop, ~ 60 steps) */
static void slider(double k, double d, double *period, double *v_back, double *t_back,
                   double *kstop)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    const double p0[3] = {0, 0, 0}, ax[3] = {1, 0, 0};
    add_rod(b, "block", p0, ax, 0.1, 0.1, 1, 1000, 1); /* 1 kg */
    fe_joint_desc j = joint("slide", FE_JOINT_TRANSLATIONAL, "block", "", p0, ax);
    j.stiffness = k;
    if (d > 0) j.has_range = 1, j.range[0] = -d, j.range[1] = d;
    CHECK(fe_builder_add_joint(b, &j, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-4;
    o.gravity[2] = -G;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    const double v0 = 0.5, w0[3] = {0, 0, 0}, vv[3] = {v0, 0, 0};
    set_spin(m, w0, p0, vv, 0, m->nnode);
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    const double M = m->body[0].mass;
    *kstop = m->joint[0].kstop;
    double tz[8], tp = 0, yp = 0;
    int nz = 0;
    *v_back = NAN, *t_back = NAN;
    const double t_end = k > 0 ? 3.3 * 2 * M_PI * sqrt(M / k) : 3 * d / v0;
    while (s->time < t_end && fe_step(m, s) == MCS_OK) {
        double y = s->joint_out[FE_JOUT_SLIDE];
        if (k > 0)
            nz = crossing(tp, yp, s->time, y, tz, nz, 8);
        else if (isnan(*t_back) && yp > 0 && y <= 0) {
            *t_back = tp + (s->time - tp) * yp / (yp - y);
            *v_back = s->body_v[0];
        }
        tp = s->time, yp = y;
    }
    CHECK(s->err.status == MCS_OK);
    *period = nz >= 3 ? (tz[nz - 1] - tz[0]) / (nz - 1) : NAN;
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

static void test_translational_spring_stop(void)
{
    const double M = 1, k = 400, T = 2 * M_PI * sqrt(M / k);
    double Tm, vb, tb, ks;
    slider(k, 0, &Tm, &vb, &tb, &ks);
    double err_pct = 100 * fabs(Tm / T - 1);
    printf("  translational + spring: period %.6f s (closed form %.6f s, %.4f %%)\n", Tm, T,
           err_pct);
    CHECK(err_pct < 0.01);
    FIG_TOL("fe.joint_slider_period_err_pct", "%.4f", err_pct, 0.003);
    const double d = 0.05, v0 = 0.5;
    slider(0, d, &Tm, &vb, &tb, &ks);
    /* free flight 2 d / v0 and half a period of the stop spring pi sqrt(M / k_stop) */
    const double tc = M_PI * sqrt(M / ks), tback = 2 * d / v0 + tc;
    printf("  translational + stop: back at %.5f s (2 d / v0 + pi sqrt(M / k_stop) = %.5f s), "
           "speed %.5f m/s (%.5f)\n",
           tb, tback, vb, -v0);
    CHECK_NEAR(vb, -v0, 1e-3 * v0);
    CHECK_NEAR(tb, tback, 0.02 * tc);
}

/* a square rod (I_yy = I_zz: a stable spin) on a cylindrical joint along its axis x, under
 * gravity, spinning at w and sliding at v: both free, so slide = v t and angle = w t */
static void test_cylindrical_spin_slide(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    const double p0[3] = {0, 0, 0}, ax[3] = {1, 0, 0};
    add_rod(b, "shaft", p0, ax, 0.4, 0.05, 2, 7800, 1);
    const double pj[3] = {0.2, 0, 0};
    fe_joint_desc j = joint("bush", FE_JOINT_CYLINDRICAL, "shaft", "", pj, ax);
    CHECK(fe_builder_add_joint(b, &j, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = 5e-5;
    o.gravity[2] = -G;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    const double w = 50, v = 0.3, wv[3] = {w, 0, 0}, vv[3] = {v, 0, 0};
    set_spin(m, wv, pj, vv, 0, m->nnode);
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double gap = 0;
    while (s->time < 0.5 && fe_step(m, s) == MCS_OK) {
        const double *x = s->body_x;
        gap = fmax(gap, sqrt(x[1] * x[1] + x[2] * x[2]));
    }
    CHECK(s->err.status == MCS_OK);
    /* the outputs are of t_n = energy_time */
    double t = s->energy_time, sl = s->joint_out[FE_JOUT_SLIDE], an = s->joint_out[FE_JOUT_ANGLE];
    printf("  cylindrical: slide %.6f m (v t = %.6f), angle %.5f rad (w t = %.5f), axis gap "
           "%.2e m\n",
           sl, v * t, an, w * t, gap);
    CHECK_NEAR(sl, v * t, 1e-3 * v * t);
    CHECK_NEAR(an, w * t, 1e-3 * w * t);
    CHECK(gap < 1e-5);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a wheel (a flat square plate of hexes, spinning at 100 rad/s about its axle y) on a
 * revolute joint to a free frame (a rod along x) tumbling at 3 rad/s about z: the joint
 * transmits gyroscopic moments, and the total angular momentum about the system's centre of
 * mass is conserved (no external moment), as is the spin relative to the frame (no moment
 * about the axle) */
static void test_wheel_on_axle(void)
{
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    const double p0[3] = {0, 0, 0}, ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0};
    add_rod(b, "frame", p0, ex, 0.6, 0.04, 3, 2000, 1);
    fe_part_desc d = ft_part("wheel", FE_SECTION_SOLID, 1e9, 0.3, 1000);
    d.material.model = FE_MAT_RIGID;
    d.mesh.generate = FE_MESH_BOX;
    d.mesh.size[0] = 0.5, d.mesh.size[1] = 0.04, d.mesh.size[2] = 0.5;
    d.mesh.divisions[0] = 4, d.mesh.divisions[1] = 1, d.mesh.divisions[2] = 4;
    d.mesh.origin[0] = 0.35, d.mesh.origin[1] = 0.05, d.mesh.origin[2] = -0.25;
    CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    const double pa[3] = {0.6, 0.07, 0};
    fe_joint_desc j = joint("axle", FE_JOINT_REVOLUTE, "wheel", "frame", pa, ey);
    CHECK(fe_builder_add_joint(b, &j, &err) == MCS_OK);
    fe_opts o = fe_opts_default();
    o.dt_max = 2e-5;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    const int wb = fe_body_find(m, "wheel"), fb = fe_body_find(m, "frame");
    CHECK(wb >= 0 && fb >= 0);
    const double *xw = m->body[wb].x0, wf[3] = {0, 0, 3}, v0[3] = {0, 0, 0};
    double vw[3], ww[3] = {0, 100, 3}, c[3], r[3];
    for (int i = 0; i < 3; i++)
        r[i] = xw[i] - 0.3 * ex[i];
    fe_cross(wf, r, c);
    for (int i = 0; i < 3; i++)
        vw[i] = c[i];
    const double fc[3] = {0.3, 0, 0};
    for (int k = 0; k < 2; k++) {
        const fe_body *B = &m->body[k];
        int n0 = m->body_node[B->node_begin], n1 = m->body_node[B->node_end - 1] + 1;
        if (k == wb)
            set_spin(m, ww, xw, vw, n0, n1);
        else
            set_spin(m, wf, fc, v0, n0, n1);
    }
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double L0[3] = {0}, dl = 0, l0n = 0, spin_err = 0;
    for (int it = 0; s->time < 0.3; it++) {
        if (fe_step(m, s) != MCS_OK) break;
        double Lt[3] = {0, 0, 0};
        for (int k = 0; k < m->nbody; k++) {
            double h[3];
            fe_cross(s->body_x + 3 * k, s->body_v + 3 * k, h);
            for (int i = 0; i < 3; i++)
                Lt[i] += s->body_l[3 * k + i] + m->body[k].mass * h[i];
        }
        if (it == 0) memcpy(L0, Lt, sizeof L0), l0n = sqrt(fe_dot(L0, L0));
        double dd[3] = {Lt[0] - L0[0], Lt[1] - L0[1], Lt[2] - L0[2]};
        dl = fmax(dl, sqrt(fe_dot(dd, dd)) / l0n);
        /* Euler: I3 dw3/dt = (I1 - I2) w1 w2 + M3 = 0 for the symmetric wheel (I1 = I2) */
        double aA[3];
        const double *R = s->body_rot + 9 * wb;
        for (int i = 0; i < 3; i++)
            aA[i] = R[3 * i + 1];
        spin_err = fmax(spin_err, fabs(fe_dot(s->body_w + 3 * wb, aA) - 100) / 100);
    }
    CHECK(s->err.status == MCS_OK);
    printf("  wheel on axle: |dL| / |L| = %.2e, relative spin held to %.2e\n", dl, spin_err);
    CHECK(dl < 1e-9);
    CHECK(spin_err < 1e-6);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* a chain of 4 links (0.25 m, densities 100 and 10000 kg/m^3 alternating: mass ratio 100)
 * hanging from the ground by revolute joints about y, started with 2 rad/s on every link: the
 * middle links carry two joints each, the penalties of a body add up, and the chaotic swing
 * stays stable: mechanical energy (with what the joints store and dissipate) constant. The
 * pivots open by force / k: k is bounded by the light links (0.1 m / dt^2 each side), so a
 * 10 g link pulled by 1 kg ones at 30 N opens ~1 mm at dt = 0.1 ms (dt^2: 0.1 um at 1 us) */
static void test_chain_stability(void)
{
    const double l = 0.25, a = 0.02, ay[3] = {0, 1, 0}, down[3] = {0, 0, -1};
    fe_builder *b;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    const char *names[4] = {"l0", "l1", "l2", "l3"};
    for (int k = 0; k < 4; k++) {
        double p0[3] = {0, 0, -k * l};
        add_rod(b, names[k], p0, down, l, a, 2, k % 2 ? 10000 : 100, 1);
        fe_joint_desc j =
            joint(names[k], FE_JOINT_REVOLUTE, names[k], k ? names[k - 1] : "", p0, ay);
        CHECK(fe_builder_add_joint(b, &j, &err) == MCS_OK);
    }
    fe_opts o = fe_opts_default();
    o.dt_max = 1e-4;
    o.gravity[2] = -G;
    fe_model *m = NULL;
    CHECK(fe_model_create(b, &o, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    const double w[3] = {0, 2, 0}, p0[3] = {0, 0, 0}, v0[3] = {0, 0, 0};
    set_spin(m, w, p0, v0, 0, m->nnode);
    fe_state *s = NULL;
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    double e0 = NAN, emax = 0, ke_max = 0, gap = 0;
    while (s->time < 2 && fe_step(m, s) == MCS_OK) {
        double e = 0, ke = 0;
        for (int k = 0; k < m->nbody; k++) {
            const double *V = s->body_v + 3 * k, M = m->body[k].mass;
            double kb = 0.5 * M * fe_dot(V, V) + 0.5 * fe_dot(s->body_l + 3 * k, s->body_w + 3 * k);
            ke += kb;
            e += kb + M * G * (s->body_x[3 * k + 2] - 0.5 * s->dt_prev * V[2]);
        }
        for (int j = 0; j < m->njoint; j++) {
            const double *jo = s->joint_out + FE_JOUT_N * j;
            e += jo[FE_JOUT_EEL] + jo[FE_JOUT_EDISS];
            gap = fmax(gap, sqrt(fe_dot(jo + FE_JOUT_FORCE, jo + FE_JOUT_FORCE)) / m->joint[j].k);
        }
        if (isnan(e0)) e0 = e;
        emax = fmax(emax, fabs(e - e0));
        ke_max = fmax(ke_max, ke);
    }
    CHECK(s->err.status == MCS_OK);
    printf("  chain of 4: energy within %.2e of the largest kinetic energy over 2 s, pivot gaps "
           "(force / k) up to %.2e m\n",
           emax / ke_max, gap);
    CHECK(emax < 2e-3 * ke_max);
    CHECK(gap < 2e-3);
    FIG_TOL("fe.joint_chain_energy_pct", "%.3f", 100 * emax / ke_max, 0.005);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
}

/* joints naming unknown bodies or one body twice, a node on no body, a massless rigid part */
static void test_bad_input(void)
{
    const double p0[3] = {0, 0, 0}, ax[3] = {1, 0, 0};
    for (int c = 0; c < 4; c++) {
        fe_builder *b;
        mcs_error err = {0};
        CHECK(fe_builder_create(&b, &err) == MCS_OK);
        add_rod(b, "a", p0, ax, 0.1, 0.1, 1, 1000, 1);
        fe_part_desc d = ft_part("soft", FE_SECTION_SOLID, 1e6, 0.3, 1000);
        d.mesh.generate = FE_MESH_BOX;
        d.mesh.size[0] = d.mesh.size[1] = d.mesh.size[2] = 0.1;
        d.mesh.divisions[0] = d.mesh.divisions[1] = d.mesh.divisions[2] = 1;
        d.mesh.origin[0] = 1;
        CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
        fe_joint_desc j = joint("j", FE_JOINT_REVOLUTE, "a", c == 0 ? "nobody" : "a", p0, ax);
        if (c == 2) j.node[0] = 0, j.node[1] = 9; /* node 9: on the deformable part */
        if (c == 3) { /* a nodal rigid body on nodes of no element: no mass */
            int nn[3];
            for (int k = 0; k < 3; k++) {
                double x[3] = {2, k, k * k};
                CHECK(fe_builder_add_node(b, x, &nn[k], &err) == MCS_OK);
            }
            CHECK(fe_builder_add_nodal_rigid_body(b, "lump", nn, 3, &err) == MCS_OK);
            snprintf(j.body[1], sizeof j.body[1], "lump");
        }
        j.file = "s.yaml", j.line = 7, j.col = 9;
        CHECK(fe_builder_add_joint(b, &j, &err) == MCS_OK);
        fe_opts o = fe_opts_default();
        o.dt_max = 1e-4;
        fe_model *m = NULL;
        mcs_status st = fe_model_create(b, &o, &m, &err);
        CHECK(st != MCS_OK && !m);
        const char *want[4] = {"s.yaml:7:9: fe: joint 'j': 'nobody' is no rigid part",
                               "joins 'a' to itself", "node N2 is on no rigid part",
                               "rigid body 'lump' has no mass"};
        CHECK_STR_CONTAINS(err.msg, want[c]);
        fe_builder_destroy(&b);
    }
}

int main(void)
{
    RUN(test_pendulum_revolute);
    RUN(test_pendulum_nodal_rigid_body);
    RUN(test_conical_spherical);
    RUN(test_translational_spring_stop);
    RUN(test_cylindrical_spin_slide);
    RUN(test_wheel_on_axle);
    RUN(test_chain_stability);
    RUN(test_bad_input);
    TEST_END();
}

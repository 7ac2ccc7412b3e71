/* tests for stage1_mb/mb_ode: ODE is double precision, dWorldStep integrates free fall,
 * pendulums and applied forces as the closed forms say, errors are values, and ODE's messages
 * reach mcs_log. */
#include "stage1_mb/mb_ode.h"
#include "stage1_mb/mb_vec.h"
#include "tests/harness.h"

#include <ode/ode.h> /* only to raise an ODE message in test_message_routing */

static const double G[3] = {0, 0, -9.81};

static mb_body_desc ball(const char *name, double m, double I, double x, double y, double z)
{
    mb_body_desc d = {.name = name,
                      .mass = m,
                      .inertia = {I, I, I, 0, 0, 0},
                      .pos = {x, y, z},
                      .quat = {1, 0, 0, 0}};
    return d;
}

static void test_double_precision(void)
{
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_ode_init(&err) == MCS_OK);
    CHECK(mb_ode_double_precision() == 1);
    mb_ode_close();
}

/* free fall: ODE's step is v1 = v0 + h g, x1 = x0 + h v1, so after n steps (t = n h)
 * z = z0 - g t^2 / 2 - g h t / 2 exactly and v = -g t; the continuous z0 - g t^2 / 2 is
 * approached with error g h t / 2 */
static void test_free_fall(void)
{
    double hs[3] = {1e-5, 1e-4, 1e-3};
    for (int k = 0; k < 3; k++) {
        double h = hs[k];
        mb_world *w = NULL;
        mcs_error err;
        mcs_error_clear(&err);
        CHECK(mb_world_create(&w, 1, 0, G, &err) == MCS_OK);
        if (!w) return;
        mb_body_desc d = ball("ball", 2.0, 0.01, 0, 0, 10);
        int b = mb_world_add_body(w, &d, &err);
        CHECK(b == 0);
        int n = (int)lround(0.5 / h);
        for (int i = 0; i < n; i++)
            CHECK(mb_world_step(w, h, &err) == MCS_OK);
        double t = n * h, g = 9.81;
        mb_body_kin s;
        mb_body_get(w, b, &s);
        CHECK_NEAR(s.vel[2], -g * t, 1e-9);
        CHECK_NEAR(s.pos[2], 10 - 0.5 * g * t * t - 0.5 * g * h * t, 1e-9);
        CHECK_NEAR(s.pos[2], 10 - 0.5 * g * t * t, 0.5 * g * h * t + 1e-9);
        CHECK_NEAR(mb_world_time(w), t, 1e-9);
        CHECK(mb_world_steps(w) == n);
        mb_world_destroy(&w);
        CHECK(w == NULL);
    }
}

/* complete elliptic integral of the first kind K(k) = pi / (2 AGM(1, sqrt(1 - k^2)))
 * (Abramowitz & Stegun 17.6) */
static double ellip_k(double k)
{
    double a = 1, b = sqrt(1 - k * k);
    for (int i = 0; i < 40 && fabs(a - b) > 1e-16 * a; i++) {
        double an = 0.5 * (a + b);
        b = sqrt(a * b), a = an;
    }
    return M_PI / (2 * a);
}

/* physical pendulum on a revolute joint at the origin (axis y), CG at distance L: equivalent
 * length Le = (Icg + m L^2) / (m L); period T = 4 sqrt(Le/g) K(sin(theta0/2)), which tends to
 * 2 pi sqrt(Le/g) for small theta0 (e.g. Goldstein, Classical Mechanics, sec. 3.8). Measured
 * from successive upward zero crossings of the angle over `nper` periods. */
static double pendulum_period(double theta0, double h, double L, double m, double Icg, int nper,
                              double *le)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    if (mb_world_create(&w, 1, 1, G, &err) != MCS_OK) return NAN;
    double y[3] = {0, 1, 0}, o[3] = {0, 0, 0};
    mb_body_desc d = ball("bob", m, Icg, L * sin(theta0), 0, -L * cos(theta0));
    int b = mb_world_add_body(w, &d, &err);
    int j = mb_joint_revolute(w, -1, b, o, y, &err);
    *le = (Icg + m * L * L) / (m * L);
    double prev = theta0, tprev = 0, first = -1, last = -1;
    int crossings = 0;
    double Test = 2 * M_PI * sqrt(*le / 9.81) * 1.5;
    long nmax = (long)((nper + 1) * Test / h);
    for (long i = 0; i < nmax && crossings <= nper; i++) {
        if (mb_world_step(w, h, &err) != MCS_OK) break;
        mb_body_kin s;
        mb_body_get(w, b, &s);
        double th = atan2(s.pos[0], -s.pos[2]), t = mb_world_time(w);
        if (prev < 0 && th >= 0) { /* upward crossing, linear interpolation */
            double tc = tprev + (t - tprev) * (-prev) / (th - prev);
            if (first < 0) first = tc;
            last = tc;
            crossings++;
        }
        prev = th, tprev = t;
    }
    (void)j;
    mb_world_destroy(&w);
    return crossings > 1 ? (last - first) / (crossings - 1) : NAN;
}

static void test_pendulum_small_angle(void)
{
    /* tolerance vs the elliptic period: the step's phase error grows with h */
    double hs[3] = {1e-5, 1e-4, 1e-3}, tol[3] = {1e-8, 1e-7, 1e-5};
    for (int k = 0; k < 3; k++) {
        double le, theta0 = 0.01;
        double T = pendulum_period(theta0, hs[k], 0.25, 1.5, 1e-4, 3, &le);
        double T0 = 2 * M_PI * sqrt(le / 9.81);
        double Tex = 4 * sqrt(le / 9.81) * ellip_k(sin(theta0 / 2));
        printf("  pendulum 0.01 rad, h = %g s: T = %.9f s, 2 pi sqrt(L/g) = %.9f s (rel %.2e), "
               "elliptic rel %.2e\n",
               hs[k], T, T0, fabs(T - T0) / T0, fabs(T - Tex) / Tex);
        CHECK_REL(T, Tex, tol[k]);
        CHECK_REL(T, T0, 1e-5); /* the amplitude correction theta0^2/16 = 6.25e-6 */
    }
}

static void test_pendulum_large_angle(void)
{
    double theta0 = M_PI / 2, le;
    double h = th_verify() ? 1e-5 : 1e-4;
    double T = pendulum_period(theta0, h, 0.25, 1.5, 1e-4, 2, &le);
    double Tex = 4 * sqrt(le / 9.81) * ellip_k(sin(theta0 / 2));
    double T0 = 2 * M_PI * sqrt(le / 9.81);
    printf("  pendulum 90 deg, h = %g s: T = %.9f s, elliptic %.9f s (T/T0 = %.7f), rel err "
           "%.2e\n",
           h, T, Tex, Tex / T0, fabs(T - Tex) / Tex);
    CHECK_NEAR(Tex / T0, 1.1803406, 1e-6); /* 2 K(1/sqrt 2) / pi, A&S table 17.1 */
    CHECK_REL(T, Tex, h < 5e-5 ? 5e-8 : 5e-6);
}

/* revolute joint angle sign and rate: child turning +w about +axis reads +angle */
static void test_joint_angle(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    double zero[3] = {0, 0, 0};
    CHECK(mb_world_create(&w, 2, 2, zero, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d = ball("wheel", 1, 0.01, 0, 0, 0);
    d.angvel[1] = 2.0;
    int b = mb_world_add_body(w, &d, &err);
    double y[3] = {0, 1, 0};
    int j = mb_joint_revolute(w, -1, b, zero, y, &err);
    /* ODE advances the quaternion by q += (h/2) w q and renormalises: each step turns by
     * 2 atan(w h / 2), so 100 steps of 1 ms at 2 rad/s turn 200 atan(0.001) = 0.2 - 6.7e-8 */
    for (int i = 0; i < 100; i++)
        mb_world_step(w, 1e-3, &err);
    CHECK_NEAR(mb_joint_position(w, j), 200 * atan(1e-3), 1e-12);
    CHECK_NEAR(mb_joint_rate(w, j), 2.0, 1e-9);
    /* translational: child sliding at +1 m/s along +x reads +position */
    mb_body_desc s = ball("slider", 1, 0.01, 1, 0, 0);
    s.vel[0] = 1;
    int bs = mb_world_add_body(w, &s, &err);
    double x[3] = {1, 0, 0};
    int js = mb_joint_translational(w, -1, bs, x, &err);
    for (int i = 0; i < 100; i++)
        mb_world_step(w, 1e-3, &err);
    CHECK_NEAR(mb_joint_position(w, js), 0.1, 1e-9);
    CHECK_NEAR(mb_joint_rate(w, js), 1.0, 1e-9);
    CHECK(err.status == MCS_OK);
    mb_world_destroy(&w);
}

/* a force F at point p on a body at rest (no gravity) for one step h:
 * dv = F h / m, dw = I_w^-1 ((p - c) x F) h with I_w = R I_b R^T; the full tensor with
 * products of inertia and a rotated body */
static void test_force_at_pos(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    double zero[3] = {0, 0, 0};
    CHECK(mb_world_create(&w, 1, 0, zero, &err) == MCS_OK);
    if (!w) return;
    double ax[3] = {0.3, -0.5, 0.8}, R[9];
    mb_normalize(ax);
    double ang = 0.9;
    mb_rot_axis_angle(ax, ang, R);
    mb_body_desc d = {
        .name = "frame",
        .mass = 200,
        .inertia = {10, 25, 22, 1.5, -2.0, 0.8},
        .pos = {0.1, 0.2, 0.6},
        .quat = {cos(ang / 2), sin(ang / 2) * ax[0], sin(ang / 2) * ax[1], sin(ang / 2) * ax[2]}};
    int b = mb_world_add_body(w, &d, &err);
    CHECK(b == 0);
    double F[3] = {1000, -300, 500}, p[3] = {0.5, 0.1, 0.9}, h = 1e-3;
    mb_body_add_force_at_pos(w, b, F, p);
    CHECK(mb_world_step(w, h, &err) == MCS_OK);
    mb_body_kin s;
    mb_body_get(w, b, &s);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(s.vel[k], F[k] * h / 200, 1e-12);
    /* expected angular velocity: solve I_b (R^T dw) = R^T tau h by Cramer's rule */
    double r[3], tau[3], tb[3];
    mb_sub(p, d.pos, r);
    mb_cross(r, F, tau);
    mb_mat_tvec(R, tau, tb);
    const double *I = d.inertia;
    double M[9] = {I[0], I[3], I[4], I[3], I[1], I[5], I[4], I[5], I[2]};
    double det = M[0] * (M[4] * M[8] - M[5] * M[7]) - M[1] * (M[3] * M[8] - M[5] * M[6]) +
                 M[2] * (M[3] * M[7] - M[4] * M[6]);
    double wb[3];
    for (int c = 0; c < 3; c++) {
        double A[9];
        for (int i = 0; i < 9; i++)
            A[i] = M[i];
        for (int i = 0; i < 3; i++)
            A[3 * i + c] = tb[i] * h;
        wb[c] = (A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
                 A[2] * (A[3] * A[7] - A[4] * A[6])) /
                det;
    }
    double wexp[3];
    mb_mat_vec(R, wb, wexp);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(s.angvel[k], wexp[k], 1e-9 * mb_norm(wexp));
    CHECK(mb_norm(wexp) > 1e-3);
    /* rotation and point velocity agree with ODE's quaternion and v + w x r */
    for (int k = 0; k < 9; k++)
        CHECK_NEAR(s.rot[k], R[k], 1e-3);
    double pv[3], wr[3], rr[3];
    mb_body_point_vel(w, b, p, pv);
    mb_sub(p, s.pos, rr);
    mb_cross(s.angvel, rr, wr);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(pv[k], s.vel[k] + wr[k], 1e-12);
    mb_world_destroy(&w);
}

/* constant force and a torque about a principal axis for 1 s: v = F t / m, w = tau t / I */
static void test_constant_load(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    double zero[3] = {0, 0, 0};
    CHECK(mb_world_create(&w, 1, 0, zero, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d = {.name = "box", .mass = 3, .inertia = {0.1, 0.2, 0.25}, .quat = {1}};
    int b = mb_world_add_body(w, &d, &err);
    double F[3] = {6, 0, -3}, T[3] = {0, 0.4, 0};
    for (int i = 0; i < 1000; i++) {
        mb_body_add_force(w, b, F);
        mb_body_add_torque(w, b, T);
        CHECK(mb_world_step(w, 1e-3, &err) == MCS_OK);
    }
    mb_body_kin s;
    mb_body_get(w, b, &s);
    CHECK_NEAR(s.vel[0], 2.0, 1e-12);
    CHECK_NEAR(s.vel[2], -1.0, 1e-12);
    CHECK_NEAR(s.angvel[1], 2.0, 1e-12);
    CHECK_NEAR(s.angvel[0], 0, 1e-12);
    mb_world_destroy(&w);
}

/* a body hanging at rest on a revolute joint: the joint carries its weight, reaction +m g */
static void test_joint_reaction(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 1, 1, G, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d = ball("arm", 2.5, 0.01, 0, 0, -0.3);
    int b = mb_world_add_body(w, &d, &err);
    double o[3] = {0, 0, 0}, y[3] = {0, 1, 0}, f[3], tq[3];
    int j = mb_joint_revolute(w, -1, b, o, y, &err);
    for (int i = 0; i < 10; i++)
        CHECK(mb_world_step(w, 1e-3, &err) == MCS_OK);
    mb_joint_reaction(w, j, f, tq);
    CHECK_NEAR(f[0], 0, 1e-9);
    CHECK_NEAR(f[2], 2.5 * 9.81, 1e-6);
    mb_body_kin s;
    mb_body_get(w, b, &s);
    CHECK_NEAR(s.pos[2], -0.3, 1e-9);
    mb_world_destroy(&w);
}

/* a spherical joint swinging in a plane is the same pendulum: same period; the CG stays at
 * distance L from the anchor */
static void test_spherical_pendulum(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 1, 1, G, &err) == MCS_OK);
    if (!w) return;
    double L = 0.25, m = 1.5, I = 1e-4, th0 = 0.01, o[3] = {0, 0, 0};
    mb_body_desc d = ball("head", m, I, L * sin(th0), 0, -L * cos(th0));
    int b = mb_world_add_body(w, &d, &err);
    CHECK(mb_joint_spherical(w, -1, b, o, &err) == 0);
    double le = (I + m * L * L) / (m * L), T0 = 2 * M_PI * sqrt(le / 9.81);
    double prev = th0, tprev = 0, first = -1, last = -1, maxr = 0;
    int nc = 0;
    while (nc < 3 && mb_world_time(w) < 5) {
        CHECK(mb_world_step(w, 1e-4, &err) == MCS_OK);
        mb_body_kin s;
        mb_body_get(w, b, &s);
        double th = atan2(s.pos[0], -s.pos[2]), t = mb_world_time(w);
        maxr = fmax(maxr, fabs(mb_norm(s.pos) - L));
        if (prev < 0 && th >= 0) {
            double tc = tprev + (t - tprev) * (-prev) / (th - prev);
            if (first < 0) first = tc;
            last = tc, nc++;
        }
        prev = th, tprev = t;
    }
    CHECK(nc == 3);
    CHECK_REL((last - first) / 2, T0, 1e-5);
    CHECK(maxr < 1e-9);
    mb_world_destroy(&w);
}

/* fixed joint: two bodies move as one, a = F / (m1 + m2); universal joint: no rotation about
 * the axis normal to both of its axes, free rotation about the others */
static void test_fixed_and_universal(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    double zero[3] = {0, 0, 0};
    CHECK(mb_world_create(&w, 4, 3, zero, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d1 = ball("tank", 12, 0.2, 0, 0, 0), d2 = ball("seat", 3, 0.05, 0.4, 0, 0);
    int b1 = mb_world_add_body(w, &d1, &err), b2 = mb_world_add_body(w, &d2, &err);
    CHECK(mb_joint_fixed(w, b1, b2, &err) == 0);
    double F[3] = {0, 30, 0}, p[3] = {0.08, 0, 0}; /* combined CG (12*0 + 3*0.4)/15: no spin */
    for (int i = 0; i < 1000; i++) {
        mb_body_add_force_at_pos(w, b1, F, p);
        CHECK(mb_world_step(w, 1e-3, &err) == MCS_OK);
    }
    mb_body_kin s1, s2;
    mb_body_get(w, b1, &s1);
    mb_body_get(w, b2, &s2);
    CHECK_NEAR(s1.vel[1], 30.0 / 15.0, 1e-6);
    CHECK_NEAR(s2.vel[1], 30.0 / 15.0, 1e-6);
    CHECK_NEAR(s2.pos[0] - s1.pos[0], 0.4, 1e-9);

    mb_body_desc d3 = ball("hand", 0.5, 1e-3, 0, 0, -1);
    int b3 = mb_world_add_body(w, &d3, &err);
    double anchor[3] = {0, 0, -0.9}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    CHECK(mb_joint_universal(w, -1, b3, anchor, x, y, &err) == 1);
    double tz[3] = {0, 0, 0.01}, tx[3] = {0.01, 0, 0};
    for (int i = 0; i < 100; i++) {
        mb_body_add_torque(w, b3, tz);
        CHECK(mb_world_step(w, 1e-3, &err) == MCS_OK);
    }
    mb_body_kin s3;
    mb_body_get(w, b3, &s3);
    CHECK_NEAR(mb_norm(s3.angvel), 0, 1e-9); /* blocked about z */
    for (int i = 0; i < 100; i++) {
        mb_body_add_torque(w, b3, tx);
        CHECK(mb_world_step(w, 1e-3, &err) == MCS_OK);
    }
    mb_body_get(w, b3, &s3);
    CHECK(fabs(s3.angvel[0]) > 0.05); /* free about x */
    CHECK(isnan(mb_joint_position(w, 1)));
    double skew[3] = {0.6, 0.8, 0};
    CHECK(mb_joint_universal(w, -1, b3, anchor, x, skew, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, "not perpendicular");
    mb_world_destroy(&w);
}

static void test_bad_input(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 1, 0, G, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d = ball("pelvis", -1, 0.1, 0, 0, 0);
    CHECK(mb_world_add_body(w, &d, &err) == -1);
    CHECK(err.status == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "body pelvis: mass -1 kg");
    mcs_error_clear(&err);
    mb_body_desc t = {.name = "thigh", .mass = 9, .inertia = {0.1, 0.1, 0.5}};
    CHECK(mb_world_add_body(w, &t, &err) == -1); /* 0.1 + 0.1 < 0.5: not a body */
    CHECK_STR_CONTAINS(err.msg, "body thigh: inertia");
    mcs_error_clear(&err);
    mb_body_desc ok = ball("head", 4.5, 0.02, 0, 0, 1);
    CHECK(mb_world_add_body(w, &ok, &err) == 0);
    CHECK(mb_world_add_body(w, &ok, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, "more than 1 bodies");
    mcs_error_clear(&err);
    double y[3] = {0, 2, 0}, o[3] = {0, 0, 0};
    CHECK(mb_joint_revolute(w, -1, 0, o, y, &err) == -1); /* max_joints 0 */
    mcs_error_clear(&err);
    CHECK(mb_world_step(w, 0, &err) == MCS_ERR_RANGE);
    /* a NaN load stops the step with the body's name */
    mcs_error_clear(&err);
    double f[3] = {NAN, 0, 0};
    mb_body_add_force(w, 0, f);
    CHECK(mb_world_step(w, 1e-3, &err) == MCS_ERR_NUMERIC);
    CHECK_STR_CONTAINS(err.msg, "body head: state not finite at t = 0.001");
    mb_world_destroy(&w);
}

static char got_msg[512];
static int got_lvl = -1;
static void capture(mcs_log_level lvl, const char *msg, void *user)
{
    (void)user;
    got_lvl = (int)lvl;
    snprintf(got_msg, sizeof got_msg, "%s", msg);
}

static void test_message_routing(void)
{
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_ode_init(&err) == MCS_OK);
    mcs_log_set_handler(capture, NULL);
    long before = mb_ode_message_count();
    dMessage(7, "solver note %d", 42);
    CHECK(got_lvl == MCS_LOG_WARN);
    CHECK_STR_CONTAINS(got_msg, "ODE message 7: solver note 42");
    CHECK(mb_ode_message_count() == before + 1);
    mcs_log_set_handler(NULL, NULL);
    mb_ode_close();
}

int main(void)
{
    RUN(test_double_precision);
    RUN(test_free_fall);
    RUN(test_pendulum_small_angle);
    RUN(test_pendulum_large_angle);
    RUN(test_joint_angle);
    RUN(test_force_at_pos);
    RUN(test_constant_load);
    RUN(test_joint_reaction);
    RUN(test_spherical_pendulum);
    RUN(test_fixed_and_universal);
    RUN(test_bad_input);
    RUN(test_message_routing);
    TEST_END();
}

/* tests for stage1_mb/mb_restraint3: three-axis restraints of spherical joints against the
 * 1-axis closed form, energy conservation at large 3-D angles (which checks the Jacobian) and
 * angular-momentum conservation between two free bodies. */
#include "stage1_mb/mb_restraint3.h"
#include "stage1_mb/mb_vec.h"
#include "tests/harness.h"
#include "tests/figures.h"

static const double ZERO[3] = {0, 0, 0};
static const double EYE[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

static mcs_curve *line_curve(double k)
{
    mcs_curve *c = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    double xy[2][2] = {{0, 0}, {1, k}};
    mcs_curve_create_xy("k", 2, xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR, &c, &err);
    return c;
}

static void set_elastic(mb_restraint3_model *m, int i, const mcs_curve *c)
{
    mcs_hyst_model e = {.loading = c, .unload = MCS_UNLOAD_ELASTIC, .elastic_limit = INFINITY};
    m->has_spring[i] = 1;
    m->spring[i].pos = e, m->spring[i].neg = e;
}

static double rot_kinetic(const mb_world *w, int b, const double I[3])
{
    mb_body_kin k;
    mb_body_get(w, b, &k);
    double wb[3];
    mb_mat_tvec(k.rot, k.angvel, wb);
    return 0.5 * (I[0] * wb[0] * wb[0] + I[1] * wb[1] * wb[1] + I[2] * wb[2] * wb[2]);
}

static void test_rot_log(void)
{
    double ax[3] = {0.2, -0.6, 0.3}, R[9], t[3];
    mb_normalize(ax);
    double angles[4] = {1e-6, 0.7, 3.0, M_PI - 1e-6};
    for (int i = 0; i < 4; i++) {
        mb_rot_axis_angle(ax, angles[i], R);
        mb_rot_log(R, t);
        for (int k = 0; k < 3; k++)
            CHECK_NEAR(t[k], angles[i] * ax[k], 1e-9);
    }
}

/* rotation about one axis on a spherical joint at the CG: theta_x = (w0/wn) sin(wn t),
 * wn = sqrt(kx / Ixx); the restraint frame is turned 90 deg about z, so its axis 1 is the
 * parent's -x and theta_1 = -theta_x (theta is sampled before each step: time t - h) */
static void test_single_axis(void)
{
    double I[3] = {0.05, 0.08, 0.1}, k = 5, w0 = 0.5, h = 1e-4, wn = sqrt(k / I[0]);
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 1, 1, ZERO, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d = {.name = "head",
                      .mass = 4.5,
                      .inertia = {I[0], I[1], I[2]},
                      .quat = {1},
                      .angvel = {w0, 0, 0}};
    int b = mb_world_add_body(w, &d, &err);
    int j = mb_joint_spherical(w, -1, b, ZERO, &err);
    mcs_curve *c = line_curve(k);
    /* frame columns: axis 0 = parent y, axis 1 = parent -x, axis 2 = parent z */
    mb_restraint3_model m = {.joint = j, .frame = {0, -1, 0, 1, 0, 0, 0, 0, 1}};
    for (int i = 0; i < 3; i++)
        set_elastic(&m, i, c);
    CHECK(mb_restraint3_check(&m, w, "neck", &err) == MCS_OK);
    mb_restraint3_state s;
    mb_restraint3_reset(&m, &s, w);
    double worst = 0;
    for (int i = 0; i < 10000; i++) {
        mb_restraint3_apply(&m, &s, w, h);
        CHECK(mb_world_step(w, h, &err) == MCS_OK);
        worst = fmax(worst, fabs(-s.theta[1] - w0 / wn * sin(wn * (mb_world_time(w) - h))));
    }
    printf("  single axis: max error %.2e rad on amplitude %.3f rad\n", worst, w0 / wn);
    CHECK(worst < 6.4e-8); /* 3x what docs/joints.md states */
    FIG("joints.r3_single_axis_err", "%.0e", worst);
    CHECK(fabs(s.theta[0]) < 1e-9 && fabs(s.theta[2]) < 1e-9);
    mb_world_destroy(&w);
    mcs_curve_destroy(&c);
}

/* large 3-D motion with three different stiffnesses: kinetic + stored energy stays constant
 * (torque = -J^-T grad V); with J taken as identity it would not */
static void test_energy_large_angles(void)
{
    double I[3] = {0.05, 0.08, 0.1}, h = 1e-5;
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 1, 1, ZERO, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d = {.name = "thorax",
                      .mass = 20,
                      .inertia = {I[0], I[1], I[2]},
                      .quat = {1},
                      .angvel = {6.0, -4.0, 8.0}};
    int b = mb_world_add_body(w, &d, &err);
    int j = mb_joint_spherical(w, -1, b, ZERO, &err);
    mcs_curve *c[3] = {line_curve(3), line_curve(5), line_curve(8)};
    mb_restraint3_model m = {.joint = j};
    for (int i = 0; i < 9; i++)
        m.frame[i] = EYE[i];
    for (int i = 0; i < 3; i++)
        set_elastic(&m, i, c[i]);
    mb_restraint3_state s;
    mb_restraint3_reset(&m, &s, w);
    double e0 = rot_kinetic(w, b, I), worst = 0, amax = 0;
    for (int i = 0; i < 100000; i++) { /* 1 s */
        mb_restraint3_apply(&m, &s, w, h);
        CHECK(mb_world_step(w, h, &err) == MCS_OK);
        worst = fmax(worst, fabs(rot_kinetic(w, b, I) + mb_restraint3_stored(&m, &s) - e0));
        amax = fmax(amax, mb_norm(s.theta));
    }
    printf("  3-axis: largest rotation %.2f rad, energy error %.2e of %.3f J\n", amax, worst / e0,
           e0);
    CHECK(amax > 1.0);
    CHECK(worst < 1.8e-4 * e0); /* 3x what docs/joints.md states */
    FIG("joints.r3_energy_err", "%.0e", worst / e0);
    mb_world_destroy(&w);
    for (int i = 0; i < 3; i++)
        mcs_curve_destroy(&c[i]);
}

/* two free bodies joined by a restrained, damped spherical joint: total angular momentum about
 * the system CG is conserved (internal torques and joint forces cancel); energy is balanced */
static void test_two_bodies_momentum(void)
{
    double h = 1e-5;
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 2, 1, ZERO, &err) == MCS_OK);
    if (!w) return;
    double Ia[3] = {0.2, 0.15, 0.1}, Ib[3] = {0.05, 0.02, 0.05};
    mb_body_desc a = {.name = "torso",
                      .mass = 30,
                      .inertia = {Ia[0], Ia[1], Ia[2]},
                      .quat = {1},
                      .angvel = {0.5, 1.0, -0.3}};
    mb_body_desc bb = {.name = "upper_arm",
                       .mass = 2,
                       .inertia = {Ib[0], Ib[1], Ib[2]},
                       .quat = {1},
                       .pos = {0, 0.2, 0.3},
                       .angvel = {-2, 3, 1}};
    double anchor[3] = {0, 0.2, 0.45}, ra[3], rb[3], va[3], vb[3];
    /* start consistent with the joint: both bodies' anchor points move alike */
    mb_sub(anchor, a.pos, ra);
    mb_sub(anchor, bb.pos, rb);
    mb_cross(a.angvel, ra, va);
    mb_cross(bb.angvel, rb, vb);
    mb_sub(va, vb, bb.vel);
    int ia = mb_world_add_body(w, &a, &err), ib = mb_world_add_body(w, &bb, &err);
    int j = mb_joint_spherical(w, ia, ib, anchor, &err);
    mcs_curve *c = line_curve(10);
    mb_restraint3_model m = {.joint = j, .damping = {0.05, 0.05, 0.05}};
    for (int i = 0; i < 9; i++)
        m.frame[i] = EYE[i];
    for (int i = 0; i < 3; i++)
        set_elastic(&m, i, c);
    CHECK(mb_restraint3_check(&m, w, "shoulder", &err) == MCS_OK);
    mb_restraint3_state s;
    mb_restraint3_reset(&m, &s, w);
    double L0[3] = {0}, L[3], e0 = 0;
    for (int pass = 0; pass < 2; pass++) {
        double Lt[3] = {0, 0, 0}, et = 0, mc[3] = {0, 0, 0}, mt = 32;
        int ids[2] = {ia, ib};
        double masses[2] = {30, 2};
        const double *Is[2] = {Ia, Ib};
        mb_body_kin k[2];
        for (int q = 0; q < 2; q++) {
            mb_body_get(w, ids[q], &k[q]);
            for (int i = 0; i < 3; i++)
                mc[i] += masses[q] * k[q].pos[i] / mt;
        }
        for (int q = 0; q < 2; q++) {
            double wb[3], Lb[3], Lw[3], r[3], p[3], rp[3];
            mb_mat_tvec(k[q].rot, k[q].angvel, wb);
            for (int i = 0; i < 3; i++)
                Lb[i] = Is[q][i] * wb[i];
            mb_mat_vec(k[q].rot, Lb, Lw);
            mb_sub(k[q].pos, mc, r);
            mb_scale(k[q].vel, masses[q], p);
            mb_cross(r, p, rp);
            for (int i = 0; i < 3; i++)
                Lt[i] += Lw[i] + rp[i];
            et += rot_kinetic(w, ids[q], Is[q]) + 0.5 * masses[q] * mb_dot(k[q].vel, k[q].vel);
        }
        if (pass == 0) {
            mb_copy(Lt, L0), e0 = et;
            for (int i = 0; i < 50000; i++) {
                mb_restraint3_apply(&m, &s, w, h);
                CHECK(mb_world_step(w, h, &err) == MCS_OK);
            }
        } else {
            mb_copy(Lt, L);
            double bal = et + mb_restraint3_stored(&m, &s) + mb_restraint3_dissipated(&m, &s);
            printf("  two bodies: |L - L0| = %.2e of %.3f N m s, energy balance %.2e\n",
                   sqrt((L[0] - L0[0]) * (L[0] - L0[0]) + (L[1] - L0[1]) * (L[1] - L0[1]) +
                        (L[2] - L0[2]) * (L[2] - L0[2])),
                   mb_norm(L0), fabs(bal - e0) / e0);
            /* the restraint's torques are equal and opposite couples; what drift remains is
             * ODE's step (implicit gyroscopic term), O(h): 5e-6 of |L0| at h = 10 us */
            for (int i = 0; i < 3; i++)
                CHECK_NEAR(L[i], L0[i], 1.6e-5 * mb_norm(L0));
            CHECK_REL(bal, e0, 4.5e-5); /* 3x what docs/joints.md states */
            double dl[3] = {L[0] - L0[0], L[1] - L0[1], L[2] - L0[2]};
            FIG("joints.r3_momentum_drift", "%.0e", mb_norm(dl) / mb_norm(L0));
            FIG("joints.r3_balance_err", "%.1e", fabs(bal - e0) / e0);
            CHECK(mb_restraint3_dissipated(&m, &s) > 0);
        }
    }
    mb_world_destroy(&w);
    mcs_curve_destroy(&c);
}

static void test_bad_input(void)
{
    mb_world *w = NULL;
    mcs_error err;
    mcs_error_clear(&err);
    CHECK(mb_world_create(&w, 1, 2, ZERO, &err) == MCS_OK);
    if (!w) return;
    mb_body_desc d = {.name = "head", .mass = 4, .inertia = {0.02, 0.02, 0.02}, .quat = {1}};
    int b = mb_world_add_body(w, &d, &err);
    double y[3] = {0, 1, 0};
    int j = mb_joint_revolute(w, -1, b, ZERO, y, &err);
    mb_restraint3_model m = {.joint = j};
    for (int i = 0; i < 9; i++)
        m.frame[i] = EYE[i];
    CHECK(mb_restraint3_check(&m, w, "neck", &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "needs a spherical or universal joint");
    mcs_error_clear(&err);
    m.joint = mb_joint_spherical(w, -1, b, ZERO, &err);
    m.frame[0] = -1; /* reflection */
    CHECK(mb_restraint3_check(&m, w, "neck", &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "left-handed");
    mcs_error_clear(&err);
    m.frame[0] = 2;
    CHECK(mb_restraint3_check(&m, w, "neck", &err) == MCS_ERR_RANGE);
    CHECK_STR_CONTAINS(err.msg, "not orthonormal");
    mb_world_destroy(&w);
}

int main(void)
{
    RUN(test_rot_log);
    RUN(test_single_axis);
    RUN(test_energy_large_angles);
    RUN(test_two_bodies_momentum);
    RUN(test_bad_input);
    TEST_END();
}

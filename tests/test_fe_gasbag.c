/* tests for fe_gasbag: the uniform-pressure gas bag (paper 2023 §2.3.2, Eq. 4-6) against
 * closed forms of ideal-gas thermodynamics, and the per-step update against CVODE. */
#include "fe/fe_gasbag.h"
#include "fe/fe_surface_volume.h"
#include "tests/fe_surf_mesh_util.h"
#include "tests/harness.h"

#include <stdio.h>

static fe_gasbag_model *make_bag(const fe_gasbag_desc *d)
{
    fe_gasbag_model *m = NULL;
    mcs_error err = {0};
    if (fe_gasbag_model_create("bag", d, &m, &err) != MCS_OK)
        fprintf(stderr, "%s\n", err.msg);
    return m;
}

/* mesh at compression s: z scaled by s, x and y by 1 + 0.1 (1 - s) */
static void deform(const sm_mesh *ref, double s, double *x)
{
    for (int i = 0; i < ref->nnode; i++) {
        double lat = 1.0 + 0.1 * (1.0 - s);
        x[3 * i] = lat * ref->x[3 * i];
        x[3 * i + 1] = lat * ref->x[3 * i + 1];
        x[3 * i + 2] = s * ref->x[3 * i + 2];
    }
}

/* 1. closed bag, no inflator, no vents, compressed adiabatically (reversible):
 *    p V^gamma = const (Poisson's law for an isentropic ideal gas), and the first law for a
 *    closed adiabatic system dU = -p dV, so U1 - U0 = (p1 V1 - p0 V0)/(gamma - 1) =
 *    -int p dV = -p0 V0^gamma (V1^(1-gamma) - V0^(1-gamma))/(1 - gamma) (e.g. Cengel & Boles,
 *    Thermodynamics, ch. 7). The volume is the enclosed volume of a deforming icosphere, and the
 *    work of the nodal pressure forces f = p dV/dx over the mesh motion must equal int p dV. */
static void test_closed_adiabatic(void)
{
    fe_gasbag_desc d = fe_gasbag_desc_default();
    fe_gasbag_model *m = make_bag(&d);
    CHECK(m != NULL);
    if (!m)
        return;
    sm_mesh ref = sm_icosphere(3, 0.3);
    double *x = malloc(sizeof(double) * 3 * ref.nnode), *xm = malloc(sizeof(double) * 3 * ref.nnode);
    double *f = malloc(sizeof(double) * 3 * ref.nnode);
    fe_gasbag_state s;
    mcs_error err = {0};
    deform(&ref, 1.0, x);
    double V0 = fe_surface_volume(ref.nface, ref.face_node, x);
    CHECK(fe_gasbag_state_init(m, &s, 0.0, V0, fe_surface_area(ref.nface, ref.face_node, x),
                               &err) == MCS_OK);
    double p0 = s.pressure, U0 = s.energy, g = m->gamma, wmech = 0.0, dev = 0.0;
    const int nstep = 2000;
    const double dt = 1e-5;
    for (int k = 0; k < nstep; k++) {
        double s0 = 1.0 - 0.5 * k / nstep, s1 = 1.0 - 0.5 * (k + 1) / nstep;
        double p_start = s.pressure;
        deform(&ref, s1, x);
        double V1 = fe_surface_volume(ref.nface, ref.face_node, x);
        CHECK(fe_gasbag_advance(m, &s, dt, V1, 0.0, &err) == MCS_OK);
        /* work of the nodal forces: gradient at the mid configuration, trapezoidal pressure */
        deform(&ref, 0.5 * (s0 + s1), xm);
        memset(f, 0, sizeof(double) * 3 * ref.nnode);
        fe_surface_pressure_forces(ref.nface, ref.face_node, xm, 0.5 * (p_start + s.pressure), f);
        double *xa = malloc(sizeof(double) * 3 * ref.nnode);
        deform(&ref, s0, xa);
        for (int i = 0; i < 3 * ref.nnode; i++)
            wmech += f[i] * (x[i] - xa[i]);
        free(xa);
        dev = fmax(dev, fabs(s.pressure * pow(s.volume, g) / (p0 * pow(V0, g)) - 1.0));
    }
    double V1 = s.volume, p1 = s.pressure;
    double w_exact = p0 * pow(V0, g) * (pow(V1, 1.0 - g) - pow(V0, 1.0 - g)) / (1.0 - g);
    printf("  closed bag V %.4f -> %.4f l: p %.0f -> %.0f Pa, max |pV^g/p0V0^g - 1| = %.2e\n",
           V0 * 1e3, V1 * 1e3, p0, p1, dev);
    printf("  work: gas %.6f J, closed form %.6f J, nodal forces %.6f J\n", s.work, w_exact,
           wmech);
    CHECK(dev < 1e-12);
    CHECK(V1 < 0.6 * V0 && p1 > 1.9 * p0);
    CHECK_REL(s.energy - U0, (p1 * V1 - p0 * V0) / (g - 1.0), 1e-12);
    CHECK_REL(s.work, w_exact, 1e-12);
    CHECK_REL(s.energy - U0, -w_exact, 1e-12);
    CHECK_NEAR(fe_gasbag_energy_residual(&s), 0.0, 1e-12 * U0);
    CHECK_REL(wmech, w_exact, 1e-6); /* trapezoid/midpoint error O(dV^2) per step */
    CHECK_REL(s.mass, s.mass0, 1e-15);
    CHECK(s.mass_vent == 0.0 && s.mass_leak == 0.0 && s.mass_in == 0.0);
    free(x);
    free(xm);
    free(f);
    sm_free(&ref);
    fe_gasbag_model_destroy(&m);
    CHECK(m == NULL);
}

int main(void)
{
    RUN(test_closed_adiabatic);
    TEST_END();
}

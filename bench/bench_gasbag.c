/* bench_gasbag: per-FE-step cost of the gas-bag update, of the enclosed volume with the
 * pressure nodal forces per face, and of a retractor update. Prints figures; never fails. */
#include "fe/fe_gasbag.h"
#include "fe/fe_retractor.h"
#include "fe/fe_surface_volume.h"
#include "tests/fe_surf_mesh_util.h"

#include <stdio.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(void)
{
    mcs_error err = {0};
    fe_gasbag_desc d = fe_gasbag_desc_default();
    d.ninflator = 3;
    const double tt[3] = {0.0, 0.005, 0.03}, md[3] = {0.0, 2.0, 0.0};
    for (int i = 0; i < 3; i++) {
        d.inflator_time[i] = tt[i];
        d.inflator_mass_flow[i] = md[i];
        d.inflator_temperature[i] = 700.0;
    }
    d.nvent = 2;
    d.vent[0] = d.vent[1] = (fe_gasbag_vent){7e-4, 0.7, 2e4};
    d.leak_area = 1e-5;
    fe_gasbag_model *m = NULL;
    if (fe_gasbag_model_create("bench", &d, &m, &err) != MCS_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    fe_gasbag_state s;
    fe_gasbag_state_init(m, &s, 0.0, 0.005, 0.8, &err);
    enum { N = 100000 };
    double t0 = now(), nsub = 0.0;
    for (int k = 1; k <= N; k++) {
        fe_gasbag_advance(m, &s, 1e-6, 0.005 + 0.055 * (1.0 - 1.0 / (1.0 + 100.0 * k * 1e-6)), 0.8,
                          &err);
        nsub += s.nsub;
    }
    double t1 = now();
    printf("gasbag advance (inflator, 2 vents, leakage, 1 us steps): %.0f ns/step, %.2f "
           "sub-steps/step\n",
           (t1 - t0) / N * 1e9, nsub / N);
    sm_mesh ico = sm_icosphere(4, 0.25);
    double *f = calloc(3 * (size_t)ico.nnode, sizeof(double));
    volatile double sink = 0.0;
    t0 = now();
    for (int k = 0; k < 200; k++)
        sink += fe_surface_pressure_forces(ico.nface, ico.face_node, ico.x, 1e4, f);
    t1 = now();
    printf("surface volume + pressure forces (%d triangles): %.1f ns/face\n", ico.nface,
           (t1 - t0) / (200.0 * ico.nface) * 1e9);
    (void)sink;
    free(f);
    sm_free(&ico);
    fe_gasbag_model_destroy(&m);
    fe_retractor_desc rd = fe_retractor_desc_default();
    fe_retractor_model *rm = NULL;
    fe_retractor_model_create("bench", &rd, &rm, &err);
    fe_retractor_state rs;
    fe_retractor_state_init(rm, &rs, 0.0);
    t0 = now();
    for (int k = 1; k <= N; k++)
        fe_retractor_advance(rm, &rs, 1e-6, 5e4 * (1e-4 + 2.0 * k * 1e-6 - rs.payout), 5e4, &err);
    t1 = now();
    printf("retractor advance: %.0f ns/step\n", (t1 - t0) / N * 1e9);
    fe_retractor_model_destroy(&rm);
    return 0;
}

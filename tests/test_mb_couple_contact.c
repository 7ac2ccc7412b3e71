/* tests for stage1_mb/mb_couple_contact: fe.contacts[] of type bodies (FE nodes against the
 * ellipsoid and facet surfaces of stage-1 bodies) in a coupled stage-1 run.
 * References, each derived beside its test, none a value of the code under test:
 * - a ball dropped on a fixed plate or hex block: a conservative oscillator on the lattice force
 *   sum k_n (delta - h_n) of the nodes under it (rebound at v0, peak force where its work is
 *   M v0^2 / 2), and the impulse 2 M v0 equal to the plate's;
 * - a solid ball set down sliding: Coulomb friction decelerates it at mu g until it rolls at
 *   5/7 v0 (Routh, Dynamics of a System of Rigid Bodies);
 * - a ball thrown at a free plate in space, a paddle spinning onto a free sheet: linear and
 *   angular momentum of bodies + FE conserved (no external load);
 * - a facet block on a fixed membrane: a linear spring K = sum k_n, peak force v0 sqrt(M K),
 *   contact time pi sqrt(M / K); half over the sheet's edge, the moment r_c x J of the
 *   impulse J at the stiffness-weighted centroid r_c of the nodes under it;
 * - the contact's written force equal and opposite to the facet's, row by row;
 * - bad input refused at its FILE:LINE:COL.
 *
 * The plates that stand for fixed FE surfaces are heavy (density x 1000): every node is fixed,
 * so their mass only sets the FE stable step dt0 (and the per-node penalty k = s m_n / dt0^2,
 * which the closed forms take from the model as an input), and keeps the subcycles few. */
#include "fe/fe_contact.h"
#include "fe/fe_state.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_couple_contact.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_couple_test_util.h"
#include "tests/mb_test_util.h"

/* a ball (sphere radius R, mass M) over a fixed square plate of quads in z = 0 */
#define DROP_YAML                                                                                  \
    "mcrash: 1\nname: drop\n"                                                                      \
    "simulation: {end_time: %g, time_step: %g, output_rate: 10 kHz}\n"                             \
    "environment: {gravity: %g}\n"                                                                 \
    "bodies:\n"                                                                                    \
    "  - {name: ball, mass: 1, inertia: [%g, %g, %g], position: [0, 0, %.9g],\n"                   \
    "     velocity: [%g, 0, %g], angular_velocity: [0, 0, 0],\n"                                   \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [%g, %g, %g]}]}\n"            \
    "fe:\n  parts:\n    - name: plate\n"                                                           \
    "      mesh: {generate: plate, size: [%g, %g], divisions: [%d, %d], origin: [%g, %g, 0]}\n"    \
    "      section: {type: shell, thickness: 2 mm}\n"                                              \
    "      material: {model: elastic, density: 7.85e6, youngs_modulus: 210 GPa, poisson: 0.3}\n"   \
    "  boundary: [{part: plate, where: all, fix: all}]\n"                                          \
    "  contacts: [{type: bodies, parts: [plate], bodies: [ball], friction: %g,\n"                  \
    "              penalty_scale: %g}]\n"

typedef struct {
    double end, h, g, inertia, z0, vx, vz, R, size[2], mu, scale;
    int div[2];
    double origin[2]; /* plate's min corner [m]; 0 0: centred on the axis */
} drop_case;

static char yaml[4096];

static const char *drop_text(const drop_case *c)
{
    snprintf(yaml, sizeof yaml, DROP_YAML, c->end, c->h, c->g, c->inertia, c->inertia, c->inertia,
             c->z0, c->vx, c->vz, c->R, c->R, c->R, c->size[0], c->size[1], c->div[0], c->div[1],
             c->origin[0] || c->origin[1] ? c->origin[0] : -0.5 * c->size[0],
             c->origin[0] || c->origin[1] ? c->origin[1] : -0.5 * c->size[1], c->mu, c->scale);
    return yaml;
}

/* the penalty force of the fixed plate on the sphere pushed delta below its first touch: the
 * sum over the plate's nodes of k_n (delta - h_n), h_n = R - sqrt(R^2 - rho_n^2) the height of
 * the sphere above node n at rho_n from the axis, k_n = s m_n / dt0^2 (docs/fe.md "Contact");
 * its work w */
static double lattice_force(const fe_model *fm, double R, double scale, double delta, double *w)
{
    double f = 0, e = 0, dt0 = fm->contact->dt0;
    for (int n = 0; n < fm->nnode; n++) {
        const double *x = fm->node_x0 + 3 * n;
        double r2 = x[0] * x[0] + x[1] * x[1]; /* the ball's axis is x = y = 0 */
        if (x[2] < -1e-9) continue;            /* below the top face (a block's inside) */
        if (r2 >= R * R) continue;
        double d = delta - (R - sqrt(R * R - r2));
        if (d <= 0) continue;
        double k = scale * fm->node_mass[n] / (dt0 * dt0);
        f += k * d, e += 0.5 * k * d * d;
    }
    *w = e;
    return f;
}

/* A ball dropped on a fixed plate, no gravity, v0 = 1 m/s: the penalty is elastic and the
 * plate does not move, so the ball is a conservative one-degree oscillator on the lattice
 * force F(delta) above: it rebounds at -v0, and the peak force is F(delta_max) with
 * W(delta_max) = M v0^2 / 2 (energy balance; no Hertz: the penalty is per node). The impulse
 * the body received equals the one the plate's nodes received (equal and opposite) and 2 M v0
 * (momentum). */
static void test_ball_drop_on_fixed_plate(void)
{
    const double R = 0.1, v0 = 1, t_half = 1e-3; /* half the plate's 2 mm shell thickness */
    drop_case c = {.end = 0.01,
                   .h = 20e-6,
                   .g = 0,
                   .inertia = 0.004,
                   .z0 = R + t_half + 0.5e-3,
                   .vx = 0,
                   .vz = -v0,
                   .R = R,
                   .size = {0.08, 0.08},
                   .div = {32, 32},
                   .mu = 0,
                   .scale = 0.001};
    mcs_error err = {0};
    mb_model *m = mc_model("drop.yaml", drop_text(&c));
    if (!m) return;
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    CHECK(st == MCS_OK);
    const fe_model *fm = m->couple->fe.model;
    double fpeak = 0, imp_body = 0, imp_fe = 0, vend = 0;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        const fe_contact_state *ks = s->couple->fe->contact;
        fpeak = fmax(fpeak, ks->ell_force[2]);
        mb_body_kin k;
        mb_body_get(s->world, 0, &k);
        vend = k.vel[2];
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    double jfe[6], jb[6];
    CHECK(mb_couple_contact_impulse(m, s, 0, jfe, jb) == 0);
    imp_fe = jfe[2], imp_body = jb[2];
    /* the closed form: delta_max from W = M v0^2 / 2 by bisection */
    double lo = 0, hi = 0.01, w = 0;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        lattice_force(fm, R, c.scale, mid, &w);
        if (w < 0.5 * 1 * v0 * v0)
            lo = mid;
        else
            hi = mid;
    }
    double fref = lattice_force(fm, R, c.scale, lo, &w);
    /* the contact's frequency at the peak, omega = sqrt(dF/ddelta / M), times the ODE step */
    const double dd = 1e-3 * lo, kf = (lattice_force(fm, R, c.scale, lo + dd, &w) -
                                       lattice_force(fm, R, c.scale, lo - dd, &w)) /
                                      (2 * dd);
    FIG("stage1_engine.contact_drop_omega_h", "%.2f", sqrt(kf / 1.0) * c.h);
    const double drift = mb_energy_drift(m, s), perr = 100 * (fpeak / fref - 1);
    const double verr = 100 * (vend / v0 - 1);
    printf("drop: rebound %.5f m/s (v0 = %.5f, %+.3f %%), peak force %.2f N (closed form %.2f N, "
           "delta %.3f mm, %+.3f %%), drift %.3g, FE steps %ld\n",
           vend, v0, verr, fpeak, fref, 1e3 * lo, perr, drift, s->couple->substeps);
    printf("drop: impulse given by the plate %.6f N s, received by the ball %.6f N s, "
           "2 M v0 = %.6f, M dv = %.6f\n",
           imp_fe, imp_body, 2 * v0, vend + v0);
    FIG("stage1_engine.contact_drop_rebound_err_pct", "%.3f", fabs(verr));
    FIG("stage1_engine.contact_drop_peak_err_pct", "%.2f", fabs(perr));
    FIG_TOL("stage1_engine.contact_drop_drift", "%.4f", drift, 3e-4);
    FIG_TOL("stage1_engine.contact_drop_impulse_err", "%.0e", fabs(imp_fe - 2 * v0), 1e-4);
    CHECK_NEAR(verr, 0, 0.1);
    CHECK_NEAR(perr, 0, 1.0);
    /* equal and opposite: what the plate's nodes received (minus it) is what the ball got;
     * the ball's momentum change is that impulse (ODE: M dv = J) */
    CHECK_NEAR(imp_body, imp_fe, 1e-6 * imp_fe);
    CHECK_NEAR(vend + v0, imp_body, 1e-9);
    CHECK_NEAR(imp_fe, 2 * v0, 1e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the sphere's rest penetration under its weight M g on the lattice (bisection) */
static double rest_depth(const fe_model *fm, double R, double scale, double weight)
{
    double lo = 0, hi = 0.01, w;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (lattice_force(fm, R, scale, mid, &w) < weight)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* The same drop on a fixed block of hex8 (10 mm thick, 2 elements through): the ball meets
 * the hex nodes of the top face (offset 0, as solid nodes), the same lattice closed form. */
static void test_ball_drop_on_fixed_hex_block(void)
{
    const double R = 0.1, v0 = 1, scale = 0.001;
    char y[4096];
    snprintf(y, sizeof y,
             "mcrash: 1\nname: hex\n"
             "simulation: {end_time: 0.01, time_step: 20 us, output_rate: 10 kHz}\n"
             "environment: {gravity: 0}\n"
             "bodies:\n"
             "  - {name: ball, mass: 1, inertia: [0.004, 0.004, 0.004], position: [0, 0, %.9g],\n"
             "     velocity: [0, 0, %g], angular_velocity: [0, 0, 0],\n"
             "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [%g, %g, %g]}]}\n"
             "fe:\n  parts:\n    - name: block\n"
             "      mesh: {generate: box, size: [0.08, 0.08, 0.01], divisions: [32, 32, 2],\n"
             "             origin: [-0.04, -0.04, -0.01]}\n"
             "      section: {type: solid}\n"
             "      material: {model: elastic, density: 7.85e6, youngs_modulus: 210 GPa, "
             "poisson: 0.3}\n"
             "  boundary: [{part: block, where: all, fix: all}]\n"
             "  contacts: [{type: bodies, parts: [block], bodies: [ball], penalty_scale: %g}]\n",
             R + 0.5e-3, -v0, R, R, R, scale);
    mcs_error err = {0};
    mb_model *m = mc_model("hex.yaml", y);
    if (!m) return;
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const fe_model *fm = m->couple->fe.model;
    double fpeak = 0;
    mb_body_kin k = {0};
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        fpeak = fmax(fpeak, s->couple->fe->contact->ell_force[2]);
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    mb_body_get(s->world, 0, &k);
    double lo = 0, hi = 0.01, w = 0;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        lattice_force(fm, R, scale, mid, &w);
        if (w < 0.5 * v0 * v0)
            lo = mid;
        else
            hi = mid;
    }
    const double fref = lattice_force(fm, R, scale, lo, &w);
    const double perr = 100 * (fpeak / fref - 1), verr = 100 * (k.vel[2] / v0 - 1);
    printf("hex block: rebound %.5f m/s (%+.3f %%), peak force %.2f N (closed form %.2f N, "
           "%+.3f %%), drift %.3g\n",
           k.vel[2], verr, fpeak, fref, perr, mb_energy_drift(m, s));
    FIG("stage1_engine.contact_hex_peak_err_pct", "%.2f", fabs(perr));
    CHECK_NEAR(verr, 0, 0.1);
    CHECK_NEAR(perr, 0, 1.0);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* A solid ball (I = 2/5 M R^2) set down sliding at v0 = 1 m/s, no spin, on a fixed plate with
 * friction mu = 0.3 under gravity: while it slides the CG decelerates at mu g and the spin
 * grows at 5 mu g / (2 R); it rolls from t* = 2 v0 / (7 mu g) = 97 ms on at v = 5/7 v0 and
 * omega = v / R (the classic billiard-ball result: Routh, Dynamics of a System of Rigid Bodies,
 * or any text on rolling with slipping). The spin comes only from the friction's moment about
 * the CG: the moment transfer is checked too. */
static void test_ball_slides_then_rolls(void)
{
    const double R = 0.1, v0 = 1, mu = 0.3, g = 9.81, scale = 1e-4;
    drop_case c = {.end = 0.13,
                   .h = 20e-6,
                   .g = g,
                   .inertia = 0.4 * R * R,
                   .vx = v0,
                   .vz = 0,
                   .R = R,
                   .size = {0.16, 0.04},
                   .div = {64, 16},
                   .origin = {-0.02, -0.02},
                   .mu = mu,
                   .scale = scale};
    /* first the model as placed, for the rest depth of the weight on the lattice */
    c.z0 = R + 1e-3;
    mb_model *m = mt_model_text("roll.yaml", drop_text(&c), NULL);
    CHECK(m != NULL);
    if (!m) return;
    const double d = rest_depth(m->couple->fe.model, R, scale, g);
    mb_model_destroy(&m);
    c.z0 = R + 1e-3 - d;
    mcs_error err = {0};
    m = mt_model_text("roll.yaml", drop_text(&c), &err);
    CHECK(m != NULL);
    if (!m) return;
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    /* least-squares slope of vx(t) over the sliding phase 10 .. 80 ms */
    double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
    mb_body_kin k = {0};
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        mb_body_get(s->world, 0, &k);
        if (s->t >= 0.01 && s->t <= 0.08)
            sx += s->t, sy += k.vel[0], sxx += s->t * s->t, sxy += s->t * k.vel[0], n++;
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    const double a = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    const double aerr = 100 * (-a / (mu * g) - 1), verr = 100 * (k.vel[0] / (5.0 / 7 * v0) - 1);
    const double werr = 100 * (k.angvel[1] * R / k.vel[0] - 1);
    printf("roll: rest depth %.4f mm; sliding deceleration %.4f m/s^2 (mu g = %.4f, %+.3f %%); "
           "rolling at %.5f m/s (5/7 v0 = %.5f, %+.3f %%), omega R / v %+.3f %%, drift %.3g, "
           "FE steps %ld\n",
           1e3 * d, -a, mu * g, aerr, k.vel[0], 5.0 / 7 * v0, verr, werr, mb_energy_drift(m, s),
           s->couple->substeps);
    FIG("stage1_engine.contact_slide_decel_err_pct", "%.2f", fabs(aerr));
    FIG("stage1_engine.contact_roll_speed_err_pct", "%.2f", fabs(verr));
    FIG("stage1_engine.contact_roll_spin_err_pct", "%.2f", fabs(werr));
    CHECK_NEAR(aerr, 0, 0.02);
    CHECK_NEAR(verr, 0, 0.2);
    CHECK_NEAR(werr, 0, 0.6);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* A ball (1 kg, R = 50 mm) thrown obliquely (vx 0.5, vz -1 m/s) at a free aluminium plate in
 * space (no supports, no gravity), friction 0.3: nothing outside acts on the ball and the
 * plate, so their total momentum M v + sum m_n v_n stays what it was (Newton's third law: the
 * contact force on the nodes and on the ball are equal and opposite); checked after the
 * contact, once nothing is in transit between them. */
#define FREE_YAML                                                                                  \
    "mcrash: 1\nname: free\n"                                                                      \
    "simulation: {end_time: 4 ms, time_step: 10 us, output_rate: 10 kHz}\n"                        \
    "environment: {gravity: 0}\n"                                                                  \
    "bodies:\n"                                                                                    \
    "  - {name: ball, mass: 1, inertia: [0.001, 0.001, 0.001], position: [0, 0, 0.0515],\n"        \
    "     velocity: [0.5, 0, -1], angular_velocity: [0, 0, 0],\n"                                  \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.05, 0.05, 0.05]}]}\n"      \
    "fe:\n  parts:\n    - name: plate\n"                                                           \
    "      mesh: {generate: plate, size: [0.1, 0.1], divisions: [20, 20],\n"                       \
    "             origin: [-0.05, -0.05, 0]}\n"                                                    \
    "      section: {type: shell, thickness: 2 mm}\n"                                              \
    "      material: {model: elastic, density: 2700, youngs_modulus: 70 GPa, poisson: 0.33}\n"     \
    "  contacts: [{type: bodies, parts: [plate], bodies: [ball], friction: 0.3}]\n"

static void fe_momentum(const fe_model *fm, const fe_state *f, double p[3])
{
    p[0] = p[1] = p[2] = 0;
    for (int n = 0; n < fm->nnode; n++)
        for (int i = 0; i < 3; i++)
            p[i] += fm->node_mass[n] * f->node_v[3 * n + i];
}

static void test_momentum_ball_on_free_plate(void)
{
    mcs_error err = {0};
    mb_model *m = mc_model("free.yaml", FREE_YAML);
    if (!m) return;
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const fe_model *fm = m->couple->fe.model;
    const double p0[3] = {0.5, 0, -1}; /* the ball's; the plate is at rest */
    double fpk = 0, p[3], pf[3];
    mb_body_kin k = {0};
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        const double *F = s->couple->fe->contact->ell_force;
        fpk = fmax(fpk, sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]));
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    const double *F = s->couple->fe->contact->ell_force;
    CHECK(F[0] == 0 && F[1] == 0 && F[2] == 0); /* apart at the end */
    mb_body_get(s->world, 0, &k);
    fe_momentum(fm, s->couple->fe, pf);
    double err_p = 0;
    for (int i = 0; i < 3; i++) {
        p[i] = k.vel[i] + pf[i];
        err_p = fmax(err_p, fabs(p[i] - p0[i]));
    }
    const double rel = err_p / sqrt(p0[0] * p0[0] + p0[2] * p0[2]);
    printf("free plate: peak force %.1f N, ball after %.4f %.4f %.4f m/s, plate momentum "
           "%.4f %.4f %.4f N s, total error %.3g N s (%.2g of |p0|), drift %.3g, FE steps %ld\n",
           fpk, k.vel[0], k.vel[1], k.vel[2], pf[0], pf[1], pf[2], err_p, rel,
           mb_energy_drift(m, s), s->couple->substeps);
    CHECK(fpk > 100);     /* they met */
    CHECK(pf[2] < -0.05); /* and the plate took some of the ball's momentum */
    CHECK(rel < 1e-12);   /* exchanged exactly: round-off */
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* A block whose underside is a facet surface (a 22.5 mm square of two triangles, outward
 * normal -z) dropped flat at v0 = 0.3 m/s on a fixed fabric membrane: the N = 81 membrane nodes
 * under the square each push with k_n (delta - 0): a linear spring K = sum k_n, so the block
 * leaves at -v0 after half a period pi sqrt(M / K) and the peak force is v0 sqrt(M K) (the
 * undamped oscillator). The nodes beside the square are 1.25 mm from its edge: out of reach. */
#define FACET_YAML                                                                                 \
    "mcrash: 1\nname: facet\n"                                                                     \
    "simulation: {end_time: 8 ms, time_step: 20 us, output_rate: 10 kHz}\n"                        \
    "environment: {gravity: 0}\n"                                                                  \
    "bodies:\n"                                                                                    \
    "  - {name: block, mass: 1, inertia: [0.01, 0.01, 0.01], position: [0, 0, 0.0207],\n"          \
    "     velocity: [0, 0, -0.3], angular_velocity: [0, 0, 0],\n"                                  \
    "     surfaces: [{type: facet, vertices: [[-0.01125, -0.01125, -0.02],\n"                      \
    "                 [0.01125, -0.01125, -0.02], [0.01125, 0.01125, -0.02],\n"                    \
    "                 [-0.01125, 0.01125, -0.02]], triangles: [[0, 2, 1], [0, 3, 2]]}]}\n"         \
    "fe:\n  parts:\n    - name: sheet\n"                                                           \
    "      mesh: {generate: plate, size: [0.1, 0.1], divisions: [40, 40],\n"                       \
    "             origin: [-0.05, -0.05, 0]}\n"                                                    \
    "      section: {type: membrane, thickness: 0.4 mm}\n"                                         \
    "      material: {model: fabric, density: 1e6, youngs_modulus: 0.5 GPa, poisson: 0.3}\n"       \
    "  boundary: [{part: sheet, where: all, fix: all}]\n"                                          \
    "  contacts: [{type: bodies, parts: [sheet], bodies: [block], penalty_scale: 0.001}]\n"

static void test_facet_block_on_membrane(void)
{
    mcs_error err = {0};
    mb_model *m = mc_model("facet.yaml", FACET_YAML);
    if (!m) return;
    const fe_model *fm = m->couple->fe.model;
    const double v0 = 0.3, M = 1, dt0 = fm->contact->dt0;
    double K = 0;
    int nunder = 0;
    for (int n = 0; n < fm->nnode; n++) {
        const double *x = fm->node_x0 + 3 * n;
        if (fabs(x[0]) < 0.01125 && fabs(x[1]) < 0.01125)
            K += 0.001 * fm->node_mass[n] / (dt0 * dt0), nunder++;
    }
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    double fpeak = 0, t_on = -1, t_off = -1, mz = 0;
    mb_body_kin k = {0};
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        const fe_contact_state *ks = s->couple->fe->contact;
        const double fz = ks->fac_force[2];
        fpeak = fmax(fpeak, fz);
        if (fz > 0 && t_on < 0) t_on = s->couple->fe->energy_time;
        if (fz > 0) t_off = s->couple->fe->energy_time;
        mz = fmax(mz, fabs(ks->fac_moment[0]) + fabs(ks->fac_moment[1]));
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    mb_body_get(s->world, 0, &k);
    const double fref = v0 * sqrt(M * K), tref = M_PI * sqrt(M / K);
    const double ferr = 100 * (fpeak / fref - 1), verr = 100 * (k.vel[2] / v0 - 1);
    double jfe[6], jb[6];
    CHECK(mb_couple_contact_impulse(m, s, 0, jfe, jb) == 0);
    printf("facet: %d nodes under it, K %.4g N/m; peak force %.2f N (v0 sqrt(M K) = %.2f, "
           "%+.3f %%), contact %.3f ms (pi sqrt(M/K) = %.3f), rebound %.5f m/s (%+.3f %%), "
           "largest moment about the CG %.2g N m, impulse %.6f / %.6f N s, drift %.3g\n",
           nunder, K, fpeak, fref, ferr, 1e3 * (t_off - t_on), 1e3 * tref, k.vel[2], verr, mz,
           jfe[2], jb[2], mb_energy_drift(m, s));
    CHECK(nunder == 81);
    /* the contact by its (default) name: what the body got from it at the last FE step */
    const int kc = mb_couple_contact_find(m, "contact0");
    double fc[3];
    CHECK(kc == 0 && mb_couple_contact_find(m, "nothing") == -1);
    if (kc == 0) mb_couple_contact_force(m, s, kc, fc);
    CHECK(kc == 0 && fc[2] == s->couple->fe->contact->fac_force[2]);
    FIG("stage1_engine.contact_facet_peak_err_pct", "%.2f", fabs(ferr));
    FIG("stage1_engine.contact_facet_rebound_err_pct", "%.3f", fabs(verr));
    CHECK_NEAR(ferr, 0, 0.05);
    CHECK_NEAR(verr, 0, 0.01);
    CHECK_NEAR(t_off - t_on, tref, 2 * 20e-6); /* to two ODE steps (the sampling) */
    CHECK_NEAR(jb[2], jfe[2], 1e-6 * jfe[2]);
    CHECK_NEAR(jb[2], M * (k.vel[2] + v0), 1e-9);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* The block half over the membrane's edge (the sheet from x = 0 on, heavy inertia so that it
 * stays level): the sheet pushes only on the nodes under the face with x >= 0, so the moment
 * the block receives about its CG is r_c x J, r_c the stiffness-weighted centroid of those
 * nodes (k_n = s m_n / dt0^2: the edge column has half the mass) at the face's depth -20 mm
 * and J the impulse (the force acts at the contact points, DESIGN.md "Coupling bodies and FE
 * parts"). */
static void test_facet_moment_off_centre(void)
{
    char y[4096];
    snprintf(y, sizeof y, "%s", FACET_YAML);
    char *p = strstr(y, "inertia: [0.01, 0.01, 0.01]");
    memcpy(p, "inertia: [1e3, 1e3, 1e3]   ", 27);
    p = strstr(y, "origin: [-0.05, -0.05, 0]");
    memcpy(p, "origin: [0.000, -0.05, 0]", 25);
    mb_model *m = mc_model("edge.yaml", y);
    if (!m) return;
    const fe_model *fm = m->couple->fe.model;
    double sk = 0, skx = 0, sky = 0;
    for (int n = 0; n < fm->nnode; n++) {
        const double *x = fm->node_x0 + 3 * n;
        if (fabs(x[0]) < 0.01125 && fabs(x[1]) < 0.01125)
            sk += fm->node_mass[n], skx += fm->node_mass[n] * x[0], sky += fm->node_mass[n] * x[1];
    }
    const double rc[3] = {skx / sk, sky / sk, -0.02};
    mb_state *s = NULL;
    mc_run(m, &s);
    double jfe[6], jb[6], mref[3];
    CHECK(mb_couple_contact_impulse(m, s, 0, jfe, jb) == 0);
    mb_cross(rc, jb, mref);
    double merr = 0;
    for (int i = 0; i < 3; i++)
        merr = fmax(merr, fabs(jb[3 + i] - mref[i]));
    const double rel = merr / fabs(mref[1]);
    printf("off centre: centroid x %.4f mm, impulse %.6f N s, moment impulse %.6g %.6g %.6g "
           "(r_c x J %.6g %.6g %.6g), error %.2g of it\n",
           1e3 * rc[0], jb[2], jb[3], jb[4], jb[5], mref[0], mref[1], mref[2], rel);
    FIG("stage1_engine.contact_facet_moment_err", "%.0e", rel);
    CHECK(jb[2] > 0.5 && rel < 6e-8);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* A flat ellipsoid (80 x 30 x 10 mm, 1 kg) spinning at 20 rad/s about its thin axis comes
 * down at 1 m/s onto a free fabric sheet in space (no gravity, friction 0.3): the friction at
 * the contact points turns the sheet. Nothing outside acts, so the total angular momentum
 * about the origin, I w + M x_cg x v_cg + sum m_n x_n x v_n, stays the body's initial I_zz w
 * (Newton's third law with moments: the body gets minus the sheet's moment about its CG);
 * checked after the contact, to the order of the one-step lag of the exchange. */
#define SPIN_YAML                                                                                  \
    "mcrash: 1\nname: spin\n"                                                                      \
    "simulation: {end_time: 6 ms, time_step: 10 us, output_rate: 10 kHz}\n"                        \
    "environment: {gravity: 0}\n"                                                                  \
    "bodies:\n"                                                                                    \
    "  - {name: paddle, mass: 1, inertia: [1e-4, 6.5e-4, 7.3e-4], position: [0, 0, 0.0107],\n"     \
    "     velocity: [0, 0, -1], angular_velocity: [0, 0, 20],\n"                                   \
    "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.08, 0.03, 0.01]}]}\n"      \
    "fe:\n  parts:\n    - name: sheet\n"                                                           \
    "      mesh: {generate: plate, size: [0.2, 0.2], divisions: [20, 20],\n"                       \
    "             origin: [-0.1, -0.1, 0]}\n"                                                      \
    "      section: {type: membrane, thickness: 0.4 mm}\n"                                         \
    "      material: {model: fabric, density: 1000, youngs_modulus: 0.5 GPa, poisson: 0.3}\n"      \
    "  contacts: [{type: bodies, parts: [sheet], bodies: [paddle], friction: 0.3}]\n"

static void test_angular_momentum_spinning_paddle(void)
{
    mb_model *m = mc_model("spin.yaml", SPIN_YAML);
    if (!m) return;
    const fe_model *fm = m->couple->fe.model;
    mb_state *s = NULL;
    mc_run(m, &s);
    const double *F = s->couple->fe->contact->ell_force;
    CHECK(F[0] == 0 && F[1] == 0 && F[2] == 0); /* apart at the end */
    /* the body's: I_world w + M x_cg x v_cg, I_world = R diag(I) R^T */
    mb_body_kin k;
    mb_body_get(s->world, 0, &k);
    const double I[3] = {1e-4, 6.5e-4, 7.3e-4};
    double wb[3], Iw[3], L[3], xv[3];
    mb_mat_tvec(k.rot, k.angvel, wb);
    for (int i = 0; i < 3; i++)
        wb[i] *= I[i];
    mb_mat_vec(k.rot, wb, Iw);
    mb_cross(k.pos, k.vel, xv);
    for (int i = 0; i < 3; i++)
        L[i] = Iw[i] + xv[i];
    /* the sheet's: sum m_n x_n x v_n (membrane nodes carry no spin) */
    double Ls[3] = {0, 0, 0};
    const fe_state *f = s->couple->fe;
    for (int n = 0; n < fm->nnode; n++) {
        double c[3];
        mb_cross(f->node_x + 3 * n, f->node_v + 3 * n, c);
        for (int i = 0; i < 3; i++)
            Ls[i] += fm->node_mass[n] * c[i];
    }
    const double L0 = 7.3e-4 * 20;
    double e = 0;
    for (int i = 0; i < 3; i++)
        e = fmax(e, fabs(L[i] + Ls[i] - (i == 2 ? L0 : 0)));
    printf("spin: body L %.6g %.6g %.6g, sheet L %.6g %.6g %.6g (initial 0 0 %.6g), error %.2g "
           "of it; body w_z %.3f rad/s\n",
           L[0], L[1], L[2], Ls[0], Ls[1], Ls[2], L0, e / L0, k.angvel[2]);
    /* the error against what went over (the sheet's spin), and the one-step lag's bound */
    const double rel = e / Ls[2];
    printf("spin: error %.2g of the angular momentum exchanged\n", rel);
    CHECK(Ls[2] > 1e-3 * L0); /* the sheet was turned */
    FIG("stage1_engine.contact_spin_angmom_err", "%.0e", rel);
    CHECK(rel < 2e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the facet block's run written to a results file: /stage1/contact/<name>/force (on the
 * parts' nodes) is minus /stage1/facets/<surface>/force (on the block) row by row, and its
 * peak over the 10 kHz rows is the closed form's v0 sqrt(M K) of the run above */
static void test_contact_output(void)
{
    char dir[] = "/tmp/mcrash_bodyct_XXXXXX", path[128];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/facet.h5", dir);
    mcs_error err = {0};
    mb_model *m = mt_model_text("facet.yaml", FACET_YAML, &err);
    CHECK(m != NULL);
    if (!m) return;
    const fe_model *fm = m->couple->fe.model;
    double K = 0;
    for (int n = 0; n < fm->nnode; n++) {
        const double *x = fm->node_x0 + 3 * n;
        if (fabs(x[0]) < 0.01125 && fabs(x[1]) < 0.01125)
            K += 0.001 * fm->node_mass[n] / (fm->contact->dt0 * fm->contact->dt0);
    }
    mb_run_opts o = {.out_path = path, .quiet = 1};
    mb_run_summary sum;
    CHECK(mb_run(m, &o, &sum, &err) == MCS_OK);
    mcs_results *h = NULL;
    mcs_array cf = {0}, ff = {0};
    CHECK(mcs_results_open(&h, path, &err) == MCS_OK);
    CHECK(h && mcs_results_read(h, "/stage1/contact/contact0/force", &cf, &err) == MCS_OK);
    CHECK(h && mcs_results_read(h, "/stage1/facets/contact0:block.surfaces[0]/force", &ff, &err) ==
                   MCS_OK);
    if (err.status) fprintf(stderr, "%s\n", err.msg);
    double worst = 0, peak = 0;
    for (size_t i = 0; i < cf.n && i < ff.n; i++)
        worst = fmax(worst, fabs(cf.v[i] + ff.v[i]));
    for (size_t i = 2; i < cf.n; i += 3)
        peak = fmax(peak, -cf.v[i]);
    const double fref = 0.3 * sqrt(1.0 * K);
    printf("output: %zu rows, contact + facets force %.3g N, peak %.2f N (v0 sqrt(M K) %.2f)\n",
           cf.n / 3, worst, peak, fref);
    CHECK(cf.n > 0 && cf.n == ff.n && worst == 0);
    CHECK_NEAR(peak, fref, 2e-3 * fref);
    mcs_array_free(&cf);
    mcs_array_free(&ff);
    mcs_results_close(&h);
    remove(path);
    remove(dir);
    mb_model_destroy(&m);
}

/* bad input is refused at its FILE:LINE:COL: a bodies contact naming an unknown body (the
 * schema's body reference), or a body without an ellipsoid or facet surface */
static void test_bodies_contact_errors_are_located(void)
{
    drop_case c = {.end = 0.001,
                   .h = 20e-6,
                   .R = 0.1,
                   .z0 = 0.2,
                   .size = {0.1, 0.1},
                   .div = {2, 2},
                   .inertia = 0.004,
                   .scale = 0.001};
    char *y = malloc(8192);
    strcpy(y, drop_text(&c));
    char *p = strstr(y, "bodies: [ball]");
    memcpy(p, "bodies: [bal1]", 14);
    mcs_error err = {0};
    mb_model *m = mt_model_text("bad.yaml", y, &err);
    CHECK(m == NULL);
    CHECK(err.status != MCS_OK);
    printf("unknown body: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "bad.yaml:16:54");
    CHECK_STR_CONTAINS(err.msg, "bal1");
    mb_model_destroy(&m);
    /* a body without surfaces, beside one with an ellipsoid */
    const char *nosurf =
        "mcrash: 1\nname: bad\nsimulation: {end_time: 1 ms, time_step: 20 us}\n"
        "bodies:\n"
        "  - {name: ball, mass: 1, inertia: [1, 1, 1], position: [0, 0, 1], velocity: [0, 0, 0],\n"
        "     surfaces: [{type: ellipsoid, center: [0, 0, 0], semi_axes: [0.1, 0.1, 0.1]}]}\n"
        "  - {name: bare, mass: 1, inertia: [1, 1, 1], position: [0, 0, 2], velocity: [0, 0, 0]}\n"
        "fe:\n  parts:\n    - name: plate\n"
        "      mesh: {generate: plate, size: [0.1, 0.1], divisions: [2, 2]}\n"
        "      section: {type: shell, thickness: 2 mm}\n"
        "      material: {model: elastic, density: 7850, youngs_modulus: 210 GPa, poisson: 0.3}\n"
        "  contacts: [{type: bodies, parts: [plate], bodies: [ball, bare]}]\n";
    strcpy(y, nosurf);
    memset(&err, 0, sizeof err);
    m = mt_model_text("bad.yaml", y, &err);
    CHECK(m == NULL);
    printf("no surfaces: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "bad.yaml:14:60");
    CHECK_STR_CONTAINS(err.msg, "no ellipsoid or facet surfaces");
    mb_model_destroy(&m);
    free(y);
}

int main(void)
{
    fe_set_threads(1); /* small models: one thread is faster than a team's start-up */
    RUN(test_ball_drop_on_fixed_plate);
    RUN(test_ball_drop_on_fixed_hex_block);
    RUN(test_ball_slides_then_rolls);
    RUN(test_momentum_ball_on_free_plate);
    RUN(test_facet_block_on_membrane);
    RUN(test_facet_moment_off_centre);
    RUN(test_contact_output);
    RUN(test_angular_momentum_spinning_paddle);
    RUN(test_bodies_contact_errors_are_located);
    TEST_END();
}

/* test_validation_restraints: the closed forms of docs/validation_restraints.md inside coupled
 * stage-1 runs (bodies + fe: block, stage1_mb/mb_couple.c), each on a scenario of
 * scenarios/verification/coupled_*.yaml (scripts/plot_restraints.sh plots the same files):
 * - a rigid body on a closed gas bag: p V^gamma = const (the ideal gas's adiabat, gamma 1.4;
 *   docs/gasbag.md), force on the body = gauge pressure x the cap's area (statics);
 * - a body pulled by a belt through the load limiter: deceleration plateau F_limit / M (Newton's
 *   second law; the paper's 2 kN, 2023 Sec. 2.3.1), the elastic onset and the stop by hand;
 * - the pretensioner's pay-in against the paper's Eq. 3 with no load, the free body against a
 *   tension-only spring's closed form;
 * - a body on a foam block: the foam's force-deflection curve as the model file defines it
 *   (force = area x S(strain, rate)), quasi-static and at impact rate;
 * - momentum of body + FE with no external load (conserved: Newton's third law);
 * and the energy drift of each run. Each case's derivation is beside it. */
#include "fe/fe_restraint.h"
#include "stage1_mb/mb_couple.h"
#include "tests/harness.h"
#include "tests/figures.h"
#include "tests/mb_test_util.h"

#define P_AMB 101325.0 /* default ambient pressure of a bag [Pa] */
#define GAMMA 1.4      /* default cp / cv of a bag's gas [-] */

/* the stage-1 body b's z position and z velocity now */
static void body_z(const mb_state *s, int b, double *z, double *vz)
{
    mb_body_kin k;
    mb_body_get(s->world, b, &k);
    *z = k.pos[2];
    *vz = k.vel[2];
}

static const fe_gasbag_state *bag_state(const mb_state *s, int i)
{
    return &s->couple->fe->restraint->bag[i];
}

/* area of the regular n-gon inscribed in radius r (the generated cylinder's cap) */
static double ngon_area(int n, double r)
{
    return 0.5 * n * r * r * sin(2 * M_PI / n);
}

/* nodes of the FE model on the top ring (z = zmax, radius r) of a generated cylinder */
static int ring_nodes(const fe_model *fm, double zmax, double r)
{
    int n = 0;
    for (int i = 0; i < fm->nnode; i++) {
        const double *x = fm->node_x0 + 3 * i;
        if (fabs(x[2] - zmax) < 1e-9 && fabs(hypot(x[0], x[1]) - r) < 1e-6) n++;
    }
    return n;
}

/* the gas spring's stroke: a piston of mass M at v0 on a prism of gas (area A, height h0, at
 * p0 = p_a): the body's kinetic energy goes into the gas less the ambient's work,
 * M v0^2 / 2 = p0 V0 / (gamma - 1) ((V0 / V)^(gamma - 1) - 1) - p_a (V0 - V), V = A (h0 - d);
 * d by bisection */
static double gas_spring_stroke(double M, double v0, double A, double h0)
{
    const double V0 = A * h0, e = 0.5 * M * v0 * v0;
    double lo = 0, hi = h0;
    for (int i = 0; i < 200; i++) {
        double d = 0.5 * (lo + hi), V = A * (h0 - d);
        double w = P_AMB * V0 / (GAMMA - 1) * (pow(V0 / V, GAMMA - 1) - 1) - P_AMB * (V0 - V);
        if (w < e)
            lo = d;
        else
            hi = d;
    }
    return 0.5 * (lo + hi);
}

/* scenarios/verification/coupled_bag_piston.yaml: a 20 kg plate carries the top cap of a
 * closed fabric cylinder (d 0.3 m, h 0.2 m, ambient air, no inflow or outflow) and strikes it
 * at 1.5 m/s. Closed forms: an adiabatic closed chamber keeps p V^gamma = p0 V0^gamma (the
 * isentrope of an ideal gas; paper 2023 Eq. 5-6 with the exponent gamma - 1 on e, as
 * docs/gasbag.md derives); the force on the plate is (p - p_amb) A_cap, A_cap the cap's
 * polygon area (the fabric wall carries no compression; the tilt of its first row as it bulges
 * is the residual). The plate's force is M dv/dt over a step, the reference (p - p_amb) A_cap
 * at the step's middle. The stroke against the gas spring's closed form (gas_spring_stroke:
 * the bag taken as a prism; the wall's bulge is the residual); the plate leaves at v0 (the
 * adiabatic gas returns the work; the fabric's damping takes a little). */
static void test_body_on_a_closed_bag(void)
{
    mb_model *m = mt_model_file("scenarios/verification/coupled_bag_piston.yaml");
    CHECK(m && m->couple);
    if (!m) return;
    mcs_error err = {0};
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const double M = m->body[0].mass, r = 0.15, h0 = 0.2, v0 = 1.5;
    const int nring = ring_nodes(m->couple->fe.model, h0, r);
    const double A = ngon_area(nring, r);
    double z, v, pvg0 = 0, pvg_err = 0, fref_peak = 0, ferr = 0, zmin = 1, p_prev = P_AMB;
    long n = m->nsteps;
    double *fb = calloc((size_t)n + 1, sizeof *fb), *fr = calloc((size_t)n + 1, sizeof *fr);
    body_z(s, 0, &z, &v);
    while (!st && s->step < n) {
        double vb = v;
        st = mb_step(m, s, &err);
        body_z(s, 0, &z, &v);
        const fe_gasbag_state *g = bag_state(s, 0);
        double pvg = g->pressure * pow(g->volume, GAMMA);
        if (s->step == 1) pvg0 = pvg;
        pvg_err = fmax(pvg_err, fabs(pvg / pvg0 - 1));
        fb[s->step] = M * (v - vb) / m->h;
        fr[s->step] = (0.5 * (g->pressure + p_prev) - P_AMB) * A;
        p_prev = g->pressure;
        fref_peak = fmax(fref_peak, fr[s->step]);
        zmin = fmin(zmin, z);
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    /* over the stroke where the gauge force exceeds 10 % of its peak */
    for (long i = 1; i <= n; i++)
        if (fr[i] > 0.1 * fref_peak) ferr = fmax(ferr, fabs(fb[i] - fr[i]) / fref_peak);
    double stroke = h0 - zmin, stroke_ref = gas_spring_stroke(M, v0, A, h0);
    double drift = mb_energy_drift(m, s);
    printf("bag: ring %d nodes, A_cap %.5f m^2; p V^gamma within %.2e; |M a - (p - p_a) A| <= "
           "%.3f %% of the peak %.1f N; stroke %.2f mm (prism gas spring %.2f mm, %+.2f %%); "
           "leaves at %.4f m/s; drift %.2e\n",
           nring, A, pvg_err, 100 * ferr, fref_peak, 1e3 * stroke, 1e3 * stroke_ref,
           100 * (stroke / stroke_ref - 1), v, drift);
    FIG_TOL("validation_restraints.bag_pvg", "%.0e", pvg_err, 1.5e-14); /* round-off */
    FIG("validation_restraints.bag_force_err_pct", "%.2f", 100 * ferr); /* 0.56 */
    FIG("validation_restraints.bag_force_peak", "%.0f", fref_peak);
    FIG("validation_restraints.bag_stroke_mm", "%.1f", 1e3 * stroke);
    FIG("validation_restraints.bag_stroke_prism_mm", "%.1f", 1e3 * stroke_ref);
    FIG("validation_restraints.bag_leave_speed", "%.3f", v);
    FIG_TOL("validation_restraints.bag_drift", "%.1e", drift, 1e-7);
    CHECK(pvg_err < 1.5e-14);
    CHECK(ferr < 0.015);
    CHECK(stroke > stroke_ref && stroke < 1.25 * stroke_ref); /* the bulge only softens */
    CHECK_NEAR(v, v0, 0.005);
    CHECK(drift < 1e-6);
    free(fb), free(fr);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* projected (xy) area of the bag faces whose nodes are all within tol below z_face (in
 * contact with a flat face at z_face) [m^2] */
static double contact_area(const fe_model *fm, const fe_state *f, double z_face, double tol)
{
    const fe_airbag *b = &fm->restraints->bag[0];
    double a = 0;
    for (int k = 0; k < b->nface; k++) {
        const int *q = b->face + 4 * k;
        int nv = q[3] < 0 ? 3 : 4, in = 1;
        for (int j = 0; j < nv && in; j++)
            in = f->node_x[3 * q[j] + 2] > z_face - tol;
        if (!in) continue;
        double s = 0; /* shoelace */
        for (int j = 0; j < nv; j++) {
            const double *p0 = f->node_x + 3 * q[j], *p1 = f->node_x + 3 * q[(j + 1) % nv];
            s += p0[0] * p1[1] - p1[0] * p0[1];
        }
        a += 0.5 * fabs(s);
    }
    return a;
}

/* scenarios/verification/coupled_bag_contact.yaml (make verify: 35 s): the bag of
 * coupled_bag_piston.yaml, its top cap free, struck by a flat-faced 20 kg body through
 * fe.contacts of type bodies. Closed forms: p V^gamma = const; the force on the body = (p -
 * p_amb) x the contact area, the patch of faces with all nodes within 3 mm of the body's face
 * (the fabric's contact thickness and the penalty's depth are below it). The body's force is
 * its mean M dv/dt over each millisecond (the penalty contact of the light fabric chatters
 * step to step), the reference the mean of (p - p_amb) A_contact over the same steps. */
static void test_body_on_a_bag_through_contact(void)
{
    if (!th_verify()) return;
    mb_model *m = mt_model_file("scenarios/verification/coupled_bag_contact.yaml");
    CHECK(m && m->couple);
    if (!m) return;
    mcs_error err = {0};
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const double M = m->body[0].mass, half = 0.02;
    const long w = (long)lround(1e-3 / m->h);
    double z, v, v_w, pvg0 = 0, pvg_err = 0, ref_sum = 0, worst = 0, fpk = 0, a_pk = 0;
    body_z(s, 0, &z, &v);
    v_w = v;
    double *fb = calloc((size_t)(m->nsteps / w + 2), sizeof *fb);
    double *fr = calloc((size_t)(m->nsteps / w + 2), sizeof *fr);
    long nw = 0;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        body_z(s, 0, &z, &v);
        const fe_gasbag_state *g = bag_state(s, 0);
        double pvg = g->pressure * pow(g->volume, GAMMA);
        if (s->step == 1) pvg0 = pvg;
        pvg_err = fmax(pvg_err, fabs(pvg / pvg0 - 1));
        double ac = contact_area(m->couple->fe.model, s->couple->fe, z - half, 3e-3);
        ref_sum += (g->pressure - P_AMB) * ac;
        if (s->step % w == 0) {
            fb[nw] = M * (v - v_w) / (w * m->h), fr[nw] = ref_sum / w;
            if (fr[nw] > fpk) fpk = fr[nw], a_pk = ac;
            nw++, v_w = v, ref_sum = 0;
        }
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    /* the impulse over the whole contact, and the means over 5 ms */
    double jb = 0, jr = 0;
    for (long i = 0; i < nw; i++)
        jb += fb[i] * 1e-3, jr += fr[i] * 1e-3;
    for (long i = 0; i + 5 <= nw; i += 5) {
        double b5 = 0, r5 = 0;
        for (long j = i; j < i + 5; j++)
            b5 += fb[j] / 5, r5 += fr[j] / 5;
        if (r5 > 0.1 * fpk) worst = fmax(worst, fabs(b5 - r5) / fpk);
    }
    double drift = mb_energy_drift(m, s);
    printf("bag through contact: p V^gamma within %.2e; impulse M dv %.3f N s against the "
           "integral of (p - p_a) A_contact %.3f N s (%+.2f %%); 5 ms means within %.2f %% of "
           "the peak %.1f N (contact area there %.4f m^2, the cap %.4f); leaves at %.3f m/s; "
           "drift %.2e\n",
           pvg_err, jb, jr, 100 * (jb / jr - 1), 100 * worst, fpk, a_pk, ngon_area(38, 0.15), v,
           drift);
    FIG_TOL("validation_restraints.bagc_pvg", "%.0e", pvg_err, 3e-14);
    FIG("validation_restraints.bagc_impulse_err_pct", "%+.1f", 100 * (jb / jr - 1));
    FIG("validation_restraints.bagc_force_err_pct", "%.1f", 100 * worst);
    FIG("validation_restraints.bagc_area", "%.4f", a_pk);
    FIG("validation_restraints.bagc_leave_speed", "%.2f", v);
    FIG_TOL("validation_restraints.bagc_drift", "%.1e", drift, 2e-4);
    CHECK(pvg_err < 3e-14);
    CHECK_NEAR(jb / jr, 1, 0.03);
    CHECK(worst < 0.15);
    CHECK(drift < 3e-3);
    free(fb), free(fr);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* the belt end's retractor state */
static const fe_retractor_state *retr_state(const mb_state *s, int i)
{
    return &s->couple->fe->restraint->retractor[i];
}

/* scenarios/verification/coupled_belt_limiter.yaml: a 20 kg body at v0 = 4 m/s pulls 0.9 m of
 * webbing out of a locked retractor with a 2 kN load limiter. Closed forms (Newton's second
 * law; the belt's 36 g, 0.2 % of the body, is the residual), with k = EA/0.9 m and EA/0.1 m in
 * series (the webbing and its segment to the retractor: 400 kN/m), omega = sqrt(k / M):
 * - elastic phase: the belt's tension k x reaches F at omega t_on = asin(F omega / (k v0)),
 *   the body then at v_on = sqrt(v0^2 - F^2 / (k M));
 * - limiting: constant deceleration F / M = 100 m/s^2 until the body stops at
 *   t_on + M v_on / F; the limiter pays out the travel meanwhile, M v_on^2 / (2 F).
 * The plateau: where the retractor's force is at the limit (within 1 N), the body's mean
 * deceleration over each millisecond, and over the whole plateau. */
static void test_belt_load_limiter(void)
{
    mb_model *m = mt_model_file("scenarios/verification/coupled_belt_limiter.yaml");
    CHECK(m && m->couple);
    if (!m) return;
    mcs_error err = {0};
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const double M = m->body[0].mass, F = 2000, a_ref = F / M, v0 = 4, k = 400e3;
    const double omega = sqrt(k / M), t_on_ref = asin(F * omega / (k * v0)) / omega;
    const double v_on_ref = sqrt(v0 * v0 - F * F / (k * M));
    const double t_stop_ref = t_on_ref + M * v_on_ref / F,
                 pay_ref = M * v_on_ref * v_on_ref / (2 * F);
    double x = 0, v = v0, worst = 0, t_on = -1, t_off = -1, v_on = 0, v_off = 0;
    double *vs = calloc((size_t)m->nsteps + 1, sizeof *vs);
    vs[0] = v0;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        mb_body_kin kb;
        mb_body_get(s->world, 0, &kb);
        x = kb.pos[0], v = vs[s->step] = kb.vel[0];
        const fe_retractor_state *r = retr_state(s, 0);
        if (fabs(r->force - F) < 1 && v > 0) {
            if (t_on < 0) t_on = s->t, v_on = v;
            t_off = s->t, v_off = v;
        }
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    /* each millisecond from 2 ms into the plateau to its end */
    const long w = (long)lround(1e-3 / m->h);
    for (long i = lround(t_on / m->h) + 2 * w; i + w <= lround(t_off / m->h); i += w)
        worst = fmax(worst, fabs(-(vs[i + w] - vs[i]) / (w * m->h) / a_ref - 1));
    free(vs);
    double amean = (v_on - v_off) / (t_off - t_on);
    double drift = mb_energy_drift(m, s);
    const fe_retractor_state *r = retr_state(s, 0);
    printf("limiter: plateau %.3f..%.3f ms (closed form %.3f..%.3f ms), mean deceleration %.3f "
           "m/s^2 (F/M %.1f, %+.3f %%), worst 1 ms mean %+.3f %%; limiter payout %.3f mm "
           "(closed form %.3f mm); x end %.4f m; drift %.2e\n",
           1e3 * t_on, 1e3 * t_off, 1e3 * t_on_ref, 1e3 * t_stop_ref, amean, a_ref,
           100 * (amean / a_ref - 1), 100 * worst, 1e3 * r->payout_limiter, 1e3 * pay_ref, x,
           drift);
    FIG("validation_restraints.limiter_decel_err_pct", "%+.2f", 100 * (amean / a_ref - 1));
    FIG("validation_restraints.limiter_decel_ms_pct", "%.1f", 100 * worst);
    FIG("validation_restraints.limiter_on_ms", "%.2f", 1e3 * t_on);
    FIG("validation_restraints.limiter_stop_ms", "%.2f", 1e3 * t_off);
    FIG("validation_restraints.limiter_payout_mm", "%.2f", 1e3 * r->payout_limiter);
    FIG_TOL("validation_restraints.limiter_drift", "%.1e", drift, 1e-5);
    CHECK_NEAR(amean / a_ref, 1, 0.01);
    CHECK(worst < 0.1);
    CHECK_NEAR(t_off, t_stop_ref, 0.1e-3);
    CHECK_NEAR(r->payout_limiter, pay_ref, 0.1e-3);
    CHECK(drift < 1e-4);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* scenarios/verification/coupled_belt_pretensioner.yaml: the pretensioner fires at 12 ms and
 * pulls in by the paper's Eq. 3, L(t) = 0 before t_fire, -(100/15 mm/ms)(t - t_fire) for
 * 15 ms, -100 mm after, with nothing on the belt but a free 1 kg body. Checks: the
 * retractor's pretensioner payout against Eq. 3 at every ODE step; the body, a mass on a
 * tension-only spring (k = EA/0.5 m and EA/0.1 m in series) whose far end starts at v: moves
 * by v tau - (v / omega) sin(omega tau) and is released at 2 v at tau = pi / omega (the
 * belt's 20 g, 2 % of the body, is the residual). */
static void test_pretensioner_payin(void)
{
    mb_model *m = mt_model_file("scenarios/verification/coupled_belt_pretensioner.yaml");
    CHECK(m && m->couple);
    if (!m) return;
    mcs_error err = {0};
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const double tf = 0.012, vp = 0.1 / 0.015, x0 = 0.6, M = m->body[0].mass;
    const double k = 1 / (0.5 / 400e3 + 0.1 / 400e3), omega = sqrt(k / M);
    const double t_rel = tf + M_PI / omega;
    double payin_err = 0, body_err = 0, x = x0, v = 0, t_free = -1;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        mb_body_kin kb;
        mb_body_get(s->world, 0, &kb);
        x = kb.pos[0], v = kb.vel[0];
        const fe_retractor_state *r = retr_state(s, 0);
        double tau = r->time - tf;
        double eq3 = tau <= 0 ? 0 : tau < 0.015 ? -vp * tau : -0.1;
        payin_err = fmax(payin_err, fabs(r->payout_pretensioner - eq3));
        tau = s->t - tf;
        if (tau > 0 && tau < M_PI / omega)
            body_err = fmax(body_err, fabs(x - x0 + vp * tau - vp / omega * sin(omega * tau)));
        if (t_free < 0 && tau > 0 && r->force == 0 && v < -vp) t_free = s->t;
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    double drift = mb_energy_drift(m, s);
    printf("pretensioner: |payout - Eq. 3| <= %.2e m; body against the spring's closed form "
           "<= %.3f mm until release; released at %.3f ms (closed form %.3f ms) at %.4f m/s "
           "(2 v = %.4f, %+.2f %%); drift %.2e\n",
           payin_err, 1e3 * body_err, 1e3 * t_free, 1e3 * t_rel, -v, 2 * vp,
           100 * (-v / (2 * vp) - 1), drift);
    FIG("validation_restraints.pretens_body_err_mm", "%.2f", 1e3 * body_err);
    FIG("validation_restraints.pretens_release_ms", "%.2f", 1e3 * t_free);
    FIG("validation_restraints.pretens_speed_err_pct", "%+.2f", 100 * (-v / (2 * vp) - 1));
    FIG_TOL("validation_restraints.pretens_drift", "%.1e", drift, 5e-5);
    CHECK(payin_err < 1e-12); /* Eq. 3 to round-off: the pay-in is prescribed */
    CHECK(body_err < 0.5e-3);
    CHECK_NEAR(t_free, t_rel, 0.3e-3);
    CHECK_NEAR(-v / (2 * vp), 1, 0.01);
    CHECK(drift < 1e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

/* nominal stress of a foam curve (strain, stress) pairs at strain e: piecewise linear through
 * (0, 0), the last segment continued (docs: fe/mat/fe_foam.c) */
static double foam_curve(const double (*c)[2], int n, double e)
{
    double x0 = 0, y0 = 0;
    for (int i = 0; i < n; i++) {
        if (e <= c[i][0] || i == n - 1) return y0 + (c[i][1] - y0) / (c[i][0] - x0) * (e - x0);
        x0 = c[i][0], y0 = c[i][1];
    }
    return 0;
}

/* the foam of coupled_foam_block.yaml: curves at 10 /s and 1000 /s */
static const double foam_lo[4][2] = {{0.05, 200e3}, {0.5, 300e3}, {0.7, 800e3}, {0.8, 2e6}};
static const double foam_hi[4][2] = {{0.05, 400e3}, {0.5, 600e3}, {0.7, 1.6e6}, {0.8, 4e6}};

/* S(e, rate): linear in log(rate) between the two curves, the end curves beyond them */
static double foam_stress(double e, double rate)
{
    double lo = foam_curve(foam_lo, 4, e), hi = foam_curve(foam_hi, 4, e);
    if (rate <= 10) return lo;
    if (rate >= 1000) return hi;
    double w = log(rate / 10) / log(1000.0 / 10);
    return lo + w * (hi - lo);
}

/* a body on the foam block (scenario file path): the force on the body M dv/dt (means over
 * 0.1 ms) against A S(d / h, rate) over the loading, rate = the body's speed / h (uniaxial:
 * nu = 0, every element at the same strain). The first millisecond after the body meets
 * the block (at once when attached, at the first touch through contact) is left out: the block's
 * strain is uniform only after the compression wave has crossed it twice (h / c = 0.5 ms,
 * c = sqrt(E / rho) = 108 m/s). Returns the worst error as a fraction of the peak force, and
 * at the peak force the ratio of the force to the quasi-static curve's A S(d / h) and the
 * reference's ratio. */
typedef struct {
    double worst, ratio, ratio_ref, dmax, fpeak, drift;
} foam_result;

static foam_result foam_run(const char *path, double z0)
{
    foam_result res = {0};
    mb_model *m = mt_model_file(path);
    CHECK(m && m->couple);
    if (!m) return res;
    mcs_error err = {0};
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const double M = m->body[0].mass, A = 0.01, H = 0.05;
    const long every = 10;
    double vprev = m->body[0].vel[2], zprev = z0, fpk = 0;
    double f_at = 0, fr_at = 0, fq_at = 0, worst = 0, t_touch = -1;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        if (s->step % every) continue;
        mb_body_kin k;
        mb_body_get(s->world, 0, &k);
        double a = (k.vel[2] - vprev) / (every * m->h), vm = 0.5 * (k.vel[2] + vprev);
        double dm = z0 - 0.5 * (k.pos[2] + zprev); /* at the interval's middle */
        vprev = k.vel[2], zprev = k.pos[2];
        if (vm >= 0) break;   /* loading only: unloading is on the hysteresis branch */
        if (dm < 0) continue; /* not there yet (through contact) */
        if (t_touch < 0) t_touch = s->t - every * m->h;
        res.dmax = fmax(res.dmax, dm);
        if (s->t <= t_touch + 1e-3) continue;
        double f = M * a, fr = A * foam_stress(dm / H, -vm / H), fq = A * foam_stress(dm / H, 0);
        worst = fmax(worst, fabs(f - fr));
        if (f > fpk) fpk = f, f_at = f, fr_at = fr, fq_at = fq;
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    res.worst = worst / fpk, res.ratio = f_at / fq_at, res.ratio_ref = fr_at / fq_at;
    res.fpeak = fpk, res.drift = mb_energy_drift(m, s);
    printf("%s: peak %.1f N, worst |F - A S| %.3f %% of it after 1 ms; at the peak F / (A S_qs) "
           "%.4f (reference %.4f); deflection %.2f mm; drift %.2e\n",
           path, fpk, 100 * res.worst, res.ratio, res.ratio_ref, 1e3 * res.dmax, res.drift);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
    return res;
}

static void test_body_on_foam(void)
{
    /* the attached top face starts at the body's z (0.05 m); through contact the body's face
     * (0.02 m below its CG) meets the top face when the CG is at 0.07 m */
    foam_result q = foam_run("scenarios/verification/coupled_foam_block.yaml", 0.05);
    foam_result i = foam_run("scenarios/verification/coupled_foam_impact.yaml", 0.05);
    foam_result c = foam_run("scenarios/verification/coupled_foam_contact.yaml", 0.07);
    FIG("validation_restraints.foam_qs_err_pct", "%.1f", 100 * q.worst);
    FIG("validation_restraints.foam_qs_peak", "%.0f", q.fpeak);
    FIG("validation_restraints.foam_qs_defl_mm", "%.2f", 1e3 * q.dmax);
    FIG_TOL("validation_restraints.foam_qs_drift", "%.1e", q.drift, 1e-6);
    FIG("validation_restraints.foam_imp_err_pct", "%.1f", 100 * i.worst);
    FIG("validation_restraints.foam_imp_ratio", "%.3f", i.ratio);
    FIG("validation_restraints.foam_imp_ratio_ref", "%.3f", i.ratio_ref);
    FIG("validation_restraints.foam_imp_peak", "%.0f", i.fpeak);
    FIG_TOL("validation_restraints.foam_imp_drift", "%.1e", i.drift, 5e-5);
    CHECK(q.worst < 0.05 && i.worst < 0.05);
    CHECK_NEAR(q.ratio, 1, 0.005);
    CHECK_NEAR(i.ratio, i.ratio_ref, 0.01);
    CHECK(i.ratio > 1.2); /* the rate effect: well above the quasi-static curve */
    CHECK(q.drift < 1e-5 && i.drift < 1e-3);
    FIG("validation_restraints.foamc_err_pct", "%.1f", 100 * c.worst);
    FIG("validation_restraints.foamc_ratio", "%.3f", c.ratio);
    FIG("validation_restraints.foamc_ratio_ref", "%.3f", c.ratio_ref);
    FIG("validation_restraints.foamc_peak", "%.0f", c.fpeak);
    FIG_TOL("validation_restraints.foamc_drift", "%.1e", c.drift, 2e-4);
    CHECK(c.worst < 0.1);
    CHECK_NEAR(c.ratio, c.ratio_ref, 0.03);
    CHECK(c.drift < 5e-3);
}

/* scenarios/verification/coupled_momentum.yaml: the momentum of bodies + rods, P, against its
 * initial value P0 (the bodies' and the attached end nodes', the rest at rest), every step. Nothing
 * outside acts, so P - P0 = J_b + J_fe exactly, with J_b the impulse the coupling forces gave the
 * bodies (the ODE step applies each force for h: m dv = F h) and J_fe the constraint impulses the
 * FE gave the attached nodes (the FE's internal and spring forces cancel in pairs): checked to
 * round-off. J_b + J_fe is the impulse in flight between the two sides: the last subcycle's,
 * which the bodies take in the next step, less the extrapolation's share taken ahead
 * (docs/stage1_engine.md "Coupling to FE parts"); it stays of the size of one step's coupling
 * impulse and does not accumulate (its mean over the second half of the run is stated). */
static void test_momentum_no_external_load(void)
{
    mb_model *m = mt_model_file("scenarios/verification/coupled_momentum.yaml");
    CHECK(m && m->couple);
    if (!m) return;
    mcs_error err = {0};
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    double P0[3] = {0}, J[3] = {0}, Jhalf[3] = {0}, imp_max = 0;
    const fe_model *fm = m->couple->fe.model;
    for (int b = 0; b < m->nbody; b++)
        for (int i = 0; i < 3; i++)
            P0[i] += m->body[b].mass * m->body[b].vel[i];
    for (int n = 0; n < fm->nnode; n++) /* the attached nodes move with their bodies */
        for (int i = 0; i < 3; i++)
            P0[i] += fm->node_mass[n] * s->couple->fe->node_v[3 * n + i];
    const int na = m->couple->natt;
    double worst = 0, worst_id = 0, pref = sqrt(P0[0] * P0[0] + P0[1] * P0[1] + P0[2] * P0[2]);
    long nh = 0;
    while (!st && s->step < m->nsteps) {
        for (int a = 0; a < na; a++) /* the force the bodies take in this step */
            for (int i = 0; i < 3; i++)
                J[i] += s->couple->force[3 * a + i] * m->h;
        st = mb_step(m, s, &err);
        double P[3] = {0}, step_imp[3] = {0};
        for (int a = 0; a < na; a++)
            for (int i = 0; i < 3; i++)
                J[i] += s->couple->imp[3 * a + i];
        for (int a = 0; a < na; a++)
            for (int i = 0; i < 3; i++)
                step_imp[i] += fabs(s->couple->imp[3 * a + i]);
        imp_max = fmax(imp_max, hypot(hypot(step_imp[0], step_imp[1]), step_imp[2]));
        for (int b = 0; b < m->nbody; b++) {
            mb_body_kin k;
            mb_body_get(s->world, b, &k);
            for (int i = 0; i < 3; i++)
                P[i] += m->body[b].mass * k.vel[i];
        }
        const fe_state *f = s->couple->fe;
        for (int n = 0; n < fm->nnode; n++)
            for (int i = 0; i < 3; i++)
                P[i] += fm->node_mass[n] * f->node_v[3 * n + i];
        double e = 0, eid = 0;
        for (int i = 0; i < 3; i++)
            e += pow(P[i] - P0[i], 2), eid += pow(P[i] - P0[i] - J[i], 2);
        worst = fmax(worst, sqrt(e) / pref), worst_id = fmax(worst_id, sqrt(eid) / pref);
        if (s->step > m->nsteps / 2) {
            for (int i = 0; i < 3; i++)
                Jhalf[i] += J[i];
            nh++;
        }
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    for (int i = 0; i < 3; i++)
        Jhalf[i] /= nh ? nh : 1;
    double jmean = hypot(hypot(Jhalf[0], Jhalf[1]), Jhalf[2]) / pref;
    printf("momentum: |P - P0| / |P0| <= %.2e; |P - P0 - (J_b + J_fe)| / |P0| <= %.2e; in flight: "
           "largest step impulse %.2e of |P0|, mean over the second half %.2e; drift %.2e\n",
           worst, worst_id, imp_max / pref, jmean, mb_energy_drift(m, s));
    double drift = mb_energy_drift(m, s);
    FIG_TOL("validation_restraints.mom_err", "%.1e", worst, 3e-5);
    FIG_TOL("validation_restraints.mom_identity", "%.0e", worst_id, 1e-14); /* round-off */
    FIG_TOL("validation_restraints.mom_flight_mean", "%.1e", jmean, 4e-6);
    FIG_TOL("validation_restraints.mom_drift", "%.1e", drift, 5e-5);
    CHECK(worst_id < 1e-14);
    CHECK(worst < 3e-4);
    CHECK(drift < 1e-3);
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_body_on_a_closed_bag);
    RUN(test_body_on_a_bag_through_contact);
    RUN(test_belt_load_limiter);
    RUN(test_pretensioner_payin);
    RUN(test_body_on_foam);
    RUN(test_momentum_no_external_load);
    TEST_END();
}

/* test_fe_parallel: the threaded FE loops give the same state to the last bit with 1 and 2
 * threads (chunked loops reduced in chunk order, fe_parallel.c), and the fast plane-stress
 * return satisfies the discrete plasticity equations (Simo & Hughes 1998, Box 3.3:
 * sigma = sigma_trial - C dgamma P sigma, q(sigma) = flow stress(epsp + dp),
 * dp = dgamma sqrt(2/3 sigma.P sigma)). */
#include "tests/harness.h"
#include "tests/figures.h"
#include "fe/fe_contact.h"
#include "fe/fe_elem.h"
#include "tests/fe_test_util.h"

/* a shell tube (J2, 5 points) crushed by a kinematic wall, a hex block (J2) hitting a penalty
 * wall and a truss line, in one model: every chunked kernel and both wall kinds */
static fe_model *build_mixed(void)
{
    mcs_error err = {0};
    fe_builder *b = NULL;
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc t = ft_part("tube", FE_SECTION_SHELL, 210e9, 0.3, 7850);
    t.material.model = FE_MAT_ELASTIC_PLASTIC;
    t.material.nhardening = 3;
    t.material.hardening[0][0] = 0, t.material.hardening[0][1] = 250e6;
    t.material.hardening[1][0] = 0.002, t.material.hardening[1][1] = 300e6;
    t.material.hardening[2][0] = 1, t.material.hardening[2][1] = 700e6;
    t.material.cowper_symonds_c = 40.4, t.material.cowper_symonds_p = 5;
    t.section.thickness = 1.5e-3;
    t.section.integration_points = 5;
    t.mesh.generate = FE_MESH_SQUARE_TUBE;
    t.mesh.side = 0.04, t.mesh.length = 0.1, t.mesh.element_size = 4e-3, t.mesh.axis = 2;
    CHECK(fe_builder_add_part(b, &t, NULL, &err) == MCS_OK);
    fe_boundary_desc bc = ft_bc("tube", FE_WHERE_Z_MIN, FE_DOF_ALL);
    CHECK(fe_builder_add_boundary(b, &bc, &err) == MCS_OK);
    fe_part_desc h = ft_part("block", FE_SECTION_SOLID, 210e9, 0.3, 7850);
    h.material.model = FE_MAT_ELASTIC_PLASTIC;
    h.material.yield_stress = 250e6;
    h.mesh.generate = FE_MESH_BOX;
    h.mesh.size[0] = h.mesh.size[1] = 0.04, h.mesh.size[2] = 0.02;
    h.mesh.divisions[0] = h.mesh.divisions[1] = 12, h.mesh.divisions[2] = 6;
    h.mesh.origin[0] = 0.1;
    h.initial_velocity[2] = -30;
    CHECK(fe_builder_add_part(b, &h, NULL, &err) == MCS_OK);
    fe_part_desc r = ft_part("rod", FE_SECTION_TRUSS, 210e9, 0.3, 7850);
    r.section.area = 1e-5;
    r.mesh.generate = FE_MESH_LINE;
    r.mesh.origin[0] = 0.3, r.mesh.end[0] = 0.5, r.mesh.divisions[0] = 300;
    r.initial_velocity[0] = 5;
    CHECK(fe_builder_add_part(b, &r, NULL, &err) == MCS_OK);
    fe_wall_desc w;
    memset(&w, 0, sizeof w);
    snprintf(w.name, sizeof w.name, "ram");
    w.point[2] = 0.1, w.normal[2] = -1, w.velocity[2] = -15;
    w.nparts = 1;
    snprintf(w.parts[0], sizeof w.parts[0], "tube");
    CHECK(fe_builder_add_wall(b, &w, &err) == MCS_OK);
    memset(&w, 0, sizeof w);
    snprintf(w.name, sizeof w.name, "floor");
    w.point[2] = -1e-4, w.normal[2] = 1, w.method = FE_WALL_PENALTY;
    w.nparts = 1;
    snprintf(w.parts[0], sizeof w.parts[0], "block");
    CHECK(fe_builder_add_wall(b, &w, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (err.status) fprintf(stderr, "%s\n", err.msg);
    fe_builder_destroy(&b);
    return m;
}

static double wall_max[2]; /* largest normal force on each wall during the last run [N] */

static fe_state *run_with(const fe_model *m, int threads, int steps)
{
    wall_max[0] = wall_max[1] = 0;
    mcs_error err = {0};
    fe_state *s = NULL;
    fe_set_threads(threads);
    CHECK(fe_state_create(m, &s, &err) == MCS_OK);
    for (int i = 0; i < steps && s; i++) {
        CHECK(fe_step(m, s) == MCS_OK);
        for (int w = 0; w < 2; w++) wall_max[w] = fmax(wall_max[w], s->wall_normal[w]);
    }
    return s;
}

#define SAME_ARRAY(a, b, name, cnt)                                                                \
    CHECK(memcmp((a)->name, (b)->name, sizeof(*(a)->name) * (size_t)(cnt)) == 0)

static void test_threads_bitwise(void)
{
    fe_model *m = build_mixed();
    if (!m) return;
    CHECK(m->nchunk > 4); /* several chunks per thread, so the split matters */
    const int steps = 300;
    fe_state *s1 = run_with(m, 1, steps), *s2 = run_with(m, 2, steps);
    if (s1 && s2) {
        /* the second run was threaded (when built with OpenMP: fe_threads() is then 2) */
        CHECK(s1->par_nt == 1 && s2->par_nt == (fe_threads() >= 2 ? 2 : 1));
        SAME_ARRAY(s1, s2, node_x, 3 * m->nnode);
        SAME_ARRAY(s1, s2, node_v, 3 * m->nnode);
        SAME_ARRAY(s1, s2, node_w, 3 * m->nnode);
        SAME_ARRAY(s1, s2, shell_sig, 3 * m->nshell_ip);
        SAME_ARRAY(s1, s2, shell_epsp, m->nshell_ip);
        SAME_ARRAY(s1, s2, hex_sig, 6 * m->nhex);
        SAME_ARRAY(s1, s2, part_energy, FE_NENERGY * m->npart);
        SAME_ARRAY(s1, s2, wall_force, 3 * m->nwall);
        CHECK(memcmp(s1->energy, s2->energy, sizeof s1->energy) == 0);
        CHECK(s1->dt == s2->dt && s1->time == s2->time);
        /* the run did something: plastic strain in the tube, the block hit the floor */
        double epmax = 0;
        for (int i = 0; i < m->nshell_ip; i++) epmax = fmax(epmax, s1->shell_epsp[i]);
        CHECK(epmax > 1e-4);
        CHECK(wall_max[0] > 0 && wall_max[1] > 0);
        printf("threads 1 vs 2: %d steps, %d nodes, %d elements in %d chunks: identical; "
               "max shell epsp %.3g\n", steps, m->nnode, m->nelem, m->nchunk, epmax);
    }
    fe_state_destroy(&s1);
    fe_state_destroy(&s2);
    fe_set_threads(1);
    fe_model_destroy(&m);
}

/* two J2 plates, the upper one thrown obliquely (20 m/s down, 5 m/s along) onto the lower one
 * clamped at its edges, two-surface contact with friction 0.3: more than 1024 slave entries
 * (the contact runs on the threads above FE_CONTACT_OMP_MIN in fe_contact.c) */
static fe_model *build_plates(void)
{
    mcs_error err = {0};
    fe_builder *b = NULL;
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    const double t = 1e-3;
    const char *name[2] = {"base", "top"};
    const double size[2] = {0.064, 0.05}, z[2] = {0, t + 0.05e-3};
    const int div[2] = {32, 25};
    for (int i = 0; i < 2; i++) {
        fe_part_desc d = ft_part(name[i], FE_SECTION_SHELL, 210e9, 0.3, 7850);
        d.material.model = FE_MAT_ELASTIC_PLASTIC;
        d.material.yield_stress = 250e6;
        d.section.thickness = t;
        d.mesh.generate = FE_MESH_PLATE;
        d.mesh.size[0] = d.mesh.size[1] = size[i];
        d.mesh.divisions[0] = d.mesh.divisions[1] = div[i];
        d.mesh.origin[0] = d.mesh.origin[1] = -0.5 * size[i] + 0.003 * i;
        d.mesh.origin[2] = z[i];
        d.initial_velocity[0] = 5 * i, d.initial_velocity[2] = -20 * i;
        CHECK(fe_builder_add_part(b, &d, NULL, &err) == MCS_OK);
    }
    fe_where sides[4] = {FE_WHERE_X_MIN, FE_WHERE_X_MAX, FE_WHERE_Y_MIN, FE_WHERE_Y_MAX};
    for (int i = 0; i < 4; i++) {
        fe_boundary_desc bc = ft_bc("base", sides[i], FE_DOF_ALL);
        CHECK(fe_builder_add_boundary(b, &bc, &err) == MCS_OK);
    }
    fe_contact_desc cd = fe_contact_desc_default();
    snprintf(cd.name, sizeof cd.name, "c");
    cd.type = FE_CONTACT_TWO_SURFACE;
    cd.nslave = cd.nmaster = 1;
    snprintf(cd.slave[0], FE_NAME_MAX, "top");
    snprintf(cd.master[0], FE_NAME_MAX, "base");
    cd.friction = 0.3;
    CHECK(fe_builder_add_contact(b, &cd, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (err.status) fprintf(stderr, "%s\n", err.msg);
    fe_builder_destroy(&b);
    return m;
}

/* the contact's threaded loops (entries, candidate lists, powers, node_fc into node_fext)
 * give the same state to the last bit with 1 and 2 threads */
static void test_contact_threads_bitwise(void)
{
    fe_model *m = build_plates();
    if (!m) return;
    const fe_contact_model *c = m->contact;
    CHECK(c && c->nent > 1024 && m->nchunk >= FE_PAR_MIN_CHUNKS);
    const int steps = 400;
    fe_state *s1 = run_with(m, 1, steps), *s2 = run_with(m, 2, steps);
    if (s1 && s2 && c) {
        /* the second run was threaded (when built with OpenMP: fe_threads() is then 2) */
        CHECK(s1->par_nt == 1 && s2->par_nt == (fe_threads() >= 2 ? 2 : 1));
        SAME_ARRAY(s1, s2, node_x, 3 * m->nnode);
        SAME_ARRAY(s1, s2, node_v, 3 * m->nnode);
        SAME_ARRAY(s1, s2, node_w, 3 * m->nnode);
        SAME_ARRAY(s1, s2, node_fext, 3 * m->nnode);
        SAME_ARRAY(s1, s2, shell_sig, 3 * m->nshell_ip);
        SAME_ARRAY(s1, s2, shell_epsp, m->nshell_ip);
        SAME_ARRAY(s1, s2, part_energy, FE_NENERGY * m->npart);
        SAME_ARRAY(s1->contact, s2->contact, node_fc, 3 * m->nnode);
        SAME_ARRAY(s1->contact, s2->contact, ent_ft, 6 * c->nent);
        SAME_ARRAY(s1->contact, s2->contact, if_force, 3 * c->nif);
        CHECK(memcmp(s1->energy, s2->energy, sizeof s1->energy) == 0);
        CHECK(s1->contact->work_nodes == s2->contact->work_nodes);
        CHECK(s1->dt == s2->dt && s1->time == s2->time);
        /* the contact carried the impact, slid with friction and searched again */
        double fric = 0;
        for (int ip = 0; ip < m->npart; ip++) fric += s1->contact->part_fric[ip];
        CHECK(s1->energy[FE_E_contact] > 0 && fric > 0);
        CHECK(s1->contact->nrebuild >= 2);
        printf("contact threads 1 vs 2: %d steps, %d slave entries, %ld searches: identical; "
               "contact energy %.3g J (friction %.3g J)\n", steps, c->nent,
               s1->contact->nrebuild, s1->energy[FE_E_contact], fric);
    }
    fe_state_destroy(&s1);
    fe_state_destroy(&s2);
    fe_set_threads(1);
    fe_model_destroy(&m);
}

/* von Mises stress of a plane stress state */
static double vm(const double s[3])
{
    return sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3 * s[2] * s[2]);
}

/* the flow stress of test_plane_stress_return's table written out: linear between the points
 * (0, 250), (0.002, 300), (0.05, 500) MPa, the last slope beyond; times the Cowper-Symonds
 * factor 1 + (rate / C)^(1/p) (Cowper & Symonds 1957; Jones, Structural Impact, eq. 8.3) */
static double flow_ref(double epsp, double rate, double C, double pcs)
{
    double y = epsp < 0.002 ? 250e6 + epsp * 50e6 / 0.002
                            : 300e6 + (epsp - 0.002) * 200e6 / 0.048;
    return C > 0 ? y * (1 + pow(rate / C, 1 / pcs)) : y;
}

/* the return against the discrete equations, for many trial states, across three hardening
 * segments, with and without the rate factor */
static void test_plane_stress_return(void)
{
    fe_part p;
    memset(&p, 0, sizeof p);
    const double E = 210e9, nu = 0.3;
    p.material.model = FE_MAT_ELASTIC_PLASTIC;
    p.material.youngs_modulus = E, p.material.poisson = nu;
    p.material.nhardening = 3;
    p.material.hardening[0][0] = 0, p.material.hardening[0][1] = 250e6;
    p.material.hardening[1][0] = 0.002, p.material.hardening[1][1] = 300e6;
    p.material.hardening[2][0] = 0.05, p.material.hardening[2][1] = 500e6;
    p.mu = E / (2 * (1 + nu));
    const double c = E / (1 - nu * nu);
    double worst_y = 0, worst_n = 0;
    int nplastic = 0;
    unsigned seed = 12345;
    for (int k = 0; k < 2000; k++) {
        double r[5];
        for (int i = 0; i < 5; i++) {
            seed = seed * 1103515245u + 12345u;
            r[i] = (double)((seed >> 8) & 0xffff) / 65535.0 * 2 - 1;
        }
        double epsp = 0.03 * (r[4] + 1); /* 0 .. 0.06: every segment, beyond the table */
        double sig[3] = {300e6 * r[0], 300e6 * r[1], 150e6 * r[2]};
        double de[3] = {2e-3 * r[1], 2e-3 * r[2], 3e-3 * r[3]};
        double rate = k % 3 == 0 ? 500.0 : 0.0;
        p.material.cowper_symonds_c = k % 3 == 0 ? 40.4 : 0;
        p.material.cowper_symonds_p = 5;
        double trial[3] = {sig[0] + c * (de[0] + nu * de[1]), sig[1] + c * (de[1] + nu * de[0]),
                           sig[2] + p.mu * de[2]};
        double out[3] = {sig[0], sig[1], sig[2]};
        double dp = fe_mat_plane_stress(&p, out, de, epsp, rate);
        const double C = p.material.cowper_symonds_c;
        double sy = flow_ref(epsp + dp, rate, C, 5);
        if (dp == 0) {
            CHECK(vm(trial) <= flow_ref(epsp, rate, C, 5) * (1 + 1e-14));
            continue;
        }
        nplastic++;
        double q = vm(out);
        worst_y = fmax(worst_y, fabs(q - sy) / sy);
        /* normality: trial - sigma = C dgamma P sigma, dgamma = dp / ((2/3) q) */
        double dg = 1.5 * dp / q;
        double ps[3] = {(2 * out[0] - out[1]) / 3, (2 * out[1] - out[0]) / 3, 2 * out[2]};
        double cps[3] = {c * (ps[0] + nu * ps[1]), c * (ps[1] + nu * ps[0]), p.mu * ps[2]};
        for (int i = 0; i < 3; i++)
            worst_n = fmax(worst_n, fabs(trial[i] - out[i] - dg * cps[i]) / vm(trial));
    }
    printf("plane-stress return: %d plastic of 2000; yield residual %.2e, normality %.2e\n",
           nplastic, worst_y, worst_n);
    FIG("fe.ps_return_yield", "%.0e", worst_y);
    FIG("fe.ps_return_normality", "%.0e", worst_n);
    CHECK(nplastic > 500);
    CHECK(worst_y < 1e-14); /* 3e-15 stated */
    CHECK(worst_n < 6e-15); /* 2e-15 stated */
}

/* the team size (fe_par_team): a model like the stage-1 concept's restraints -- a 1058-triangle
 * membrane bag (not in the chunk loops: one thread) and two 10-truss belts, 11 element chunks
 * -- runs on one thread when 2 are offered, as its 20 threaded elements are below
 * FE_PAR_MIN_WORK per thread (fe_model.h); a 1024-hex block (2 x FE_PAR_MIN_WORK) on two */
static void test_team_size(void)
{
    mcs_error err = {0};
    fe_builder *b = NULL;
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc bag = ft_part("bag", FE_SECTION_MEMBRANE, 5e8, 0.3, 1000);
    bag.material.model = FE_MAT_FABRIC;
    bag.section.thickness = 5e-4;
    bag.mesh.generate = FE_MESH_PLATE;
    bag.mesh.size[0] = bag.mesh.size[1] = 0.5;
    bag.mesh.divisions[0] = 23, bag.mesh.divisions[1] = 23; /* 529 quads, 1058 triangles */
    bag.mesh.axis = 2;
    CHECK(fe_builder_add_part(b, &bag, NULL, &err) == MCS_OK);
    for (int i = 0; i < 2; i++) {
        fe_part_desc r = ft_part(i ? "belt_r" : "belt_l", FE_SECTION_TRUSS, 2.33e9, 0, 1000);
        r.section.area = 6e-5;
        r.mesh.generate = FE_MESH_LINE;
        r.mesh.origin[0] = 1, r.mesh.origin[1] = i, r.mesh.end[0] = 1.3, r.mesh.end[1] = i;
        r.mesh.divisions[0] = 10;
        CHECK(fe_builder_add_part(b, &r, NULL, &err) == MCS_OK);
    }
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    CHECK(m->nchunk >= FE_PAR_MIN_CHUNKS && m->nelem_chunked == 20);
    fe_state *s = run_with(m, 2, 3);
    CHECK(s && s->par_nt == 1);
    printf("team: %d elements in %d chunks, %d in the chunk loops: %d thread(s) of 2\n",
           m->nelem, m->nchunk, m->nelem_chunked, s ? s->par_nt : -1);
    fe_state_destroy(&s);
    fe_model_destroy(&m);
    /* the block: 16 x 16 x 4 hexes */
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc h = ft_part("block", FE_SECTION_SOLID, 210e9, 0.3, 7850);
    h.mesh.generate = FE_MESH_BOX;
    h.mesh.size[0] = h.mesh.size[1] = 0.16, h.mesh.size[2] = 0.04;
    h.mesh.divisions[0] = h.mesh.divisions[1] = 16, h.mesh.divisions[2] = 4;
    CHECK(fe_builder_add_part(b, &h, NULL, &err) == MCS_OK);
    m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    CHECK(m->nelem_chunked == 2 * FE_PAR_MIN_WORK);
    s = run_with(m, 2, 3);
    CHECK(s && s->par_nt == (fe_threads() >= 2 ? 2 : 1));
    fe_state_destroy(&s);
    fe_set_threads(1);
    fe_model_destroy(&m);
}

int main(void)
{
    RUN(test_plane_stress_return);
    RUN(test_threads_bitwise);
    RUN(test_contact_threads_bitwise);
    RUN(test_team_size);
    TEST_END();
}

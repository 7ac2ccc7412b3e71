/* test_fe_keyword.c: the LS-DYNA keyword subset (fe/fe_keyword.h, docs/keyword.md): every
 * keyword's values, the same mesh in the standard, long, I10 and free formats, unit systems,
 * located errors (bad number -> FILE:LINE:COL, undefined node, unknown keyword), the writer's
 * round trip of generated meshes, a deck into a model, the elastic bar run from a keyword mesh
 * against the generated one, and random mutations of the decks (never a crash, always a status). */
#include "cli_util.h"
#include "core/mcs_results.h"
#include "fe/fe_keyword.h"
#include "fe/fe_state.h"
#include "harness.h"
#include "figures.h"
#include "fe/fe_scn_build.h"
#include "stage3_fe/s3_run.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define KD "tests/data/keyword/"

static char tmpdir[64];

static fe_kw_opts quiet_opts(const char *units)
{
    fe_kw_opts o = fe_kw_opts_default();
    o.quiet = 1;
    o.units = units;
    return o;
}

static fe_kw_deck *read_deck(const char *path, const char *units)
{
    fe_kw_opts o = quiet_opts(units);
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    mcs_status st = fe_kw_read(path, &o, &d, &err);
    if (st) fprintf(stderr, "read %s: %s\n", path, err.msg);
    CHECK(st == MCS_OK && d);
    return d;
}

static const double *node_at(const fe_kw_deck *d, int id)
{
    int i = fe_kw_node_index(d, id);
    return i >= 0 ? d->node_x + 3 * i : NULL;
}

/* every keyword of all_keywords.k (and its *INCLUDE) read with its values */
static void test_all_keywords(void)
{
    fe_kw_deck *d = read_deck(KD "all_keywords.k", NULL);
    if (!d) return;
    CHECK(strcmp(d->title, "all supported keywords") == 0);
    CHECK(d->nfile == 2 && strstr(d->file[1], "all_keywords_nodes.k"));
    CHECK(d->nnode == 20);
    const double *x = node_at(d, 19);
    CHECK(x && x[0] == 0.1 && x[1] == 0.1 && x[2] == 1.2);
    /* solids: one-card and two-card forms */
    const fe_kw_elems *s = &d->elem[FE_KW_SOLID];
    CHECK(s->n == 2 && s->pid[0] == 2 && s->node[0] == 9 && s->node[7] == 16);
    CHECK(s->id[1] == 2 && s->node[8] == 13 && s->node[15] == 20);
    const fe_kw_elems *sh = &d->elem[FE_KW_SHELL];
    CHECK(sh->n == 2 && sh->node[4 + 2] == 3 && sh->node[4 + 3] == 3); /* triangle */
    CHECK(d->elem[FE_KW_BEAM].n == 1 && d->elem[FE_KW_BEAM].node[0] == 5 &&
          d->elem[FE_KW_BEAM].node[1] == 6);
    const fe_kw_elems *ds = &d->elem[FE_KW_DISCRETE];
    CHECK(ds->n == 1 && ds->pid[0] == 4 && ds->dval[0] == 2.0 && ds->dval[1] == 0.001);
    /* parts (two in one *PART block) */
    CHECK(d->npart == 4);
    const fe_kw_part *p = fe_kw_find_part(d, 3);
    CHECK(p && strcmp(p->title, "truss") == 0 && p->secid == 3 && p->mid == 3);
    /* sections */
    const fe_kw_section *sc = fe_kw_find_section(d, 1);
    CHECK(sc && sc->kind == FE_KW_SEC_SHELL && sc->elform == 16 && sc->nip == 5 &&
          sc->shrf == 0.8 && sc->t[0] == 0.002 && sc->t[3] == 0.002);
    sc = fe_kw_find_section(d, 3);
    CHECK(sc && sc->kind == FE_KW_SEC_BEAM && sc->elform == 3 && sc->area == 1e-4);
    CHECK(fe_kw_find_section(d, 2) && fe_kw_find_section(d, 2)->kind == FE_KW_SEC_SOLID);
    /* materials */
    const fe_kw_mat *m = fe_kw_find_mat(d, 1);
    CHECK(m && m->type == FE_KW_MAT_PLP && m->ro == 7850 && m->e == 2.1e11 && m->pr == 0.3 &&
          m->sigy == 2.5e8 && m->c == 40.4 && m->p == 5 && m->lcss == 7 && m->neps == 0);
    CHECK(fe_kw_find_mat(d, 2) && fe_kw_find_mat(d, 2)->type == FE_KW_MAT_ELASTIC &&
          fe_kw_find_mat(d, 2)->e == 7e10);
    CHECK(fe_kw_find_mat(d, 3) && fe_kw_find_mat(d, 3)->type == FE_KW_MAT_ELASTIC);
    CHECK(fe_kw_find_mat(d, 4) && fe_kw_find_mat(d, 4)->type == FE_KW_MAT_RIGID);
    /* the curve with SFO = 1e6 applied */
    const fe_kw_curve *cv = fe_kw_find_curve(d, 7);
    CHECK(cv && cv->n == 3 && cv->xy[0] == 0 && cv->xy[1] == 250e6 && cv->xy[4] == 0.5 &&
          cv->xy[5] == 400e6);
    /* sets */
    const fe_kw_set *ns = fe_kw_find_set(d, 1, 0), *ps = fe_kw_find_set(d, 2, 1);
    CHECK(ns && ns->n == 12 && ns->ids[0] == 9 && ns->ids[11] == 20);
    CHECK(ps && ps->n == 2 && ps->ids[1] == 3);
    /* constraints: TC = 7 on node 8, *BOUNDARY_SPC_NODE, *BOUNDARY_SPC_SET_ID */
    CHECK(d->nspc == 3);
    int seen = 0;
    for (int i = 0; i < d->nspc; i++) {
        const fe_kw_spc *c = &d->spc[i];
        if (c->on == FE_KW_ON_NODE && c->id == 8 && c->dof == FE_DOF_TRANS) seen |= 1;
        if (c->on == FE_KW_ON_NODE && c->id == 1 && c->dof == FE_DOF_TRANS) seen |= 2;
        if (c->on == FE_KW_ON_NODESET && c->id == 1 && c->dof == (FE_DOF_Z | FE_DOF_ROT))
            seen |= 4;
    }
    CHECK(seen == 7);
    /* initial velocities */
    CHECK(d->niv == 2 && d->iv[0].on == FE_KW_ON_NODESET && d->iv[0].id == 1 &&
          d->iv[0].v[2] == -2 && d->iv[1].on == FE_KW_ON_PARTSET && d->iv[1].id == 2 &&
          d->iv[1].v[0] == 3);
    /* the wall */
    CHECK(d->nwall == 1 && d->wall[0].id == 9 && strcmp(d->wall[0].title, "floor") == 0 &&
          d->wall[0].nsid == 1 && d->wall[0].tail[2] == -0.5 && d->wall[0].head[2] == 0.5);
    /* unknown keywords listed with their lines; nothing after *END read */
    CHECK(d->nunknown == 1 && d->end_time == 0.01); /* *CONTROL_TERMINATION is read */
    if (d->nunknown == 1) {
        CHECK(strcmp(d->unknown[0].name, "DATABASE_BINARY_D3PLOT") == 0);
        CHECK(d->unknown[0].loc.line == 87 && d->unknown[0].loc.file == 0);
    }
    fe_kw_deck_destroy(&d);
    CHECK(d == NULL);
}

/* the same plate in five layouts reads to the same numbers */
static void test_formats_agree(void)
{
    static const char *files[] = {KD "plate_fixed.k", KD "plate_long.k", KD "plate_i10.k",
                                  KD "plate_i10y.k", KD "plate_free.k"};
    fe_kw_deck *ref = read_deck(files[0], NULL);
    if (!ref) return;
    CHECK(ref->nnode == 7 && ref->elem[FE_KW_SHELL].n == 3);
    CHECK(node_at(ref, 5) && node_at(ref, 5)[2] == -1.5e-3 && node_at(ref, 4)[1] == 10.25);
    for (int f = 1; f < 5; f++) {
        fe_kw_deck *d = read_deck(files[f], NULL);
        if (!d) continue;
        CHECK(d->nnode == ref->nnode);
        for (int i = 0; i < d->nnode && d->nnode == ref->nnode; i++) {
            CHECK(d->node_id[i] == ref->node_id[i]);
            for (int k = 0; k < 3; k++) CHECK(d->node_x[3 * i + k] == ref->node_x[3 * i + k]);
        }
        const fe_kw_elems *a = &d->elem[FE_KW_SHELL], *b = &ref->elem[FE_KW_SHELL];
        CHECK(a->n == b->n);
        for (int i = 0; i < 4 * a->n && a->n == b->n; i++) CHECK(a->node[i] == b->node[i]);
        const fe_kw_section *s = fe_kw_find_section(d, 1);
        const fe_kw_mat *m = fe_kw_find_mat(d, 1);
        CHECK(s && s->nip == 3 && s->shrf == 0.8333 && s->t[2] == 1.5);
        CHECK(m && m->ro == 7.85e-9 && m->e == 2.1e5 && m->pr == 0.3);
        CHECK(fe_kw_find_part(d, 1) && strcmp(fe_kw_find_part(d, 1)->title, "plate") == 0);
        fe_kw_deck_destroy(&d);
    }
    fe_kw_deck_destroy(&ref);
}

/* units: mm-s-t (N, MPa, t/mm^3) and mm-ms-kg (kN, GPa) to SI */
static void test_units(void)
{
    fe_kw_deck *d = read_deck(KD "plate_fixed.k", "mm-s-t");
    if (d) {
        CHECK_REL(node_at(d, 2)[0], 0.0105, 1e-15);
        const fe_kw_mat *m = fe_kw_find_mat(d, 1);
        CHECK(m);
        if (m) {
            CHECK_REL(m->ro, 7850, 1e-14);  /* 7.85e-9 t/mm^3 */
            CHECK_REL(m->e, 2.1e11, 1e-14); /* 2.1e5 MPa */
        }
        CHECK_REL(fe_kw_find_section(d, 1)->t[0], 1.5e-3, 1e-15);
        fe_kw_deck_destroy(&d);
    }
    double u[3];
    mcs_error err = {0};
    CHECK(fe_kw_units("mm-ms-kg", u, &err) == MCS_OK && u[0] == 1e-3 && u[1] == 1e-3 && u[2] == 1);
    /* stress unit kg/(mm ms^2) = 1 GPa */
    CHECK_REL(u[2] / (u[0] * u[1] * u[1]), 1e9, 1e-12);
    CHECK(fe_kw_units("mm-s-lb", u, &err) == MCS_ERR_UNIT);
    CHECK_STR_CONTAINS(err.msg, "mm-s-lb");
}

/* bad number -> FILE:LINE:COL of its first character, keyword and field; exit status 2 */
static void test_errors(void)
{
    fe_kw_opts o = quiet_opts(NULL);
    fe_kw_deck *d = NULL;
    mcs_error err = {0};
    mcs_status st = fe_kw_read(KD "bad_number.k", &o, &d, &err);
    CHECK(st == MCS_ERR_FORMAT && d == NULL && mcs_status_exit_code(st) == 2);
    CHECK_STR_CONTAINS(err.msg, "bad_number.k:6:32: error: *NODE: field Y: '1.2.3'");
    mcs_error_clear(&err);
    st = fe_kw_read(KD "missing_node.k", &o, &d, &err);
    CHECK(st == MCS_ERR_FORMAT && d == NULL);
    CHECK_STR_CONTAINS(err.msg, "missing_node.k:10: error: *ELEMENT_SHELL: element 2: node N2 = 99");
    /* unknown keywords as errors */
    mcs_error_clear(&err);
    o.strict = 1;
    st = fe_kw_read(KD "all_keywords.k", &o, &d, &err);
    CHECK(st == MCS_ERR_FORMAT && d == NULL);
    CHECK_STR_CONTAINS(err.msg, "all_keywords.k:87:1: error: *DATABASE_BINARY_D3PLOT: keyword "
                                "not supported");
    /* small in-memory cases: missing card, duplicate node, text before *KEYWORD, bad include */
    static const struct {
        const char *text, *want;
    } cases[] = {
        {"*KEYWORD\n*MAT_024\n1\n", "mem:3: error: *MAT_024: 3 more cards expected after line 3"},
        {"*KEYWORD\n*NODE\n1,0,0,0\n1,1,0,0\n", "mem:4: error: *NODE: node 1 is defined twice"},
        {"hello\n*KEYWORD\n", "mem:1:1: error: data before the first keyword"},
        {"*KEYWORD\n*INCLUDE\nno_such_file.k\n", "mem:3:1: error: *INCLUDE: cannot open"},
        {"*KEYWORD\n*NODE\n1,0,0,x\n", "mem:3:7: error: *NODE: field Z: 'x' is not a number"},
        {"*KEYWORD\n*ELEMENT_SHELL\n       1       1     1.5\n",
         "mem:3:22: error: *ELEMENT_SHELL: field N1: '1.5' is not an integer"},
        {"*KEYWORD\n*SECTION_SHELL\n1,2,0,2,0,0,1\n1\n", "field ICOMP: composite layups"},
        {"*KEYWORD\n*RIGIDWALL_PLANAR\n0\n0,0,0,0,0,0\n", "no normal"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        mcs_error_clear(&err);
        o.strict = 0;
        st = fe_kw_read_mem("mem", cases[i].text, strlen(cases[i].text), &o, &d, &err);
        CHECK(st != MCS_OK && d == NULL);
        CHECK_STR_CONTAINS(err.msg, cases[i].want);
    }
}

/* a generated model (square tube of shells + box of hexes + a truss line) written in each
 * format and read back: the same connectivity, and coordinates to the written precision
 * (standard: 16 columns hold >= 11 significant digits; long: 20 columns hold >= 16) */
static void test_roundtrip(void)
{
    fe_builder *b = NULL;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    fe_part_desc t = fe_part_desc_default();
    snprintf(t.name, sizeof t.name, "tube");
    t.mesh.generate = FE_MESH_SQUARE_TUBE;
    t.mesh.side = 0.05, t.mesh.length = 0.2, t.mesh.element_size = 0.0125, t.mesh.axis = 2;
    t.section.type = FE_SECTION_SHELL, t.section.thickness = 1.5e-3;
    t.material.model = FE_MAT_ELASTIC_PLASTIC, t.material.density = 7850;
    t.material.youngs_modulus = 210e9, t.material.poisson = 0.3, t.material.yield_stress = 250e6;
    t.material.nhardening = 2;
    t.material.hardening[0][0] = 0, t.material.hardening[0][1] = 250e6;
    t.material.hardening[1][0] = 0.3, t.material.hardening[1][1] = 400e6;
    CHECK(fe_builder_add_part(b, &t, NULL, &err) == MCS_OK);
    fe_part_desc x = fe_part_desc_default();
    snprintf(x.name, sizeof x.name, "block");
    x.mesh.generate = FE_MESH_BOX;
    x.mesh.size[0] = 0.1, x.mesh.size[1] = 0.03, x.mesh.size[2] = 0.07;
    x.mesh.divisions[0] = 7, x.mesh.divisions[1] = 3, x.mesh.divisions[2] = 3;
    x.mesh.origin[0] = 0.3, x.mesh.origin[1] = -1.0 / 3, x.mesh.origin[2] = 1e-5;
    x.section.type = FE_SECTION_SOLID;
    x.material.model = FE_MAT_ELASTIC, x.material.density = 2700;
    x.material.youngs_modulus = 70e9, x.material.poisson = 0.33;
    CHECK(fe_builder_add_part(b, &x, NULL, &err) == MCS_OK);
    fe_part_desc l = x;
    snprintf(l.name, sizeof l.name, "cable");
    l.mesh.generate = FE_MESH_LINE;
    l.mesh.origin[0] = 0, l.mesh.end[0] = 1, l.mesh.end[1] = 1, l.mesh.divisions[0] = 3;
    l.section.type = FE_SECTION_TRUSS, l.section.area = 1e-5;
    CHECK(fe_builder_add_part(b, &l, NULL, &err) == MCS_OK);
    fe_model *m = NULL;
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    fe_builder_destroy(&b);
    if (!m) return;
    fe_kw_deck *out = NULL;
    CHECK(fe_kw_from_model(m, NULL, "round trip", &out, &err) == MCS_OK);
    static const fe_kw_format fmts[] = {FE_KW_FIXED, FE_KW_FIXED_I10, FE_KW_FIXED_LONG};
    for (int f = 0; f < 3 && out; f++) {
        char path[128];
        snprintf(path, sizeof path, "%s/rt%d.k", tmpdir, f);
        CHECK(fe_kw_write(out, path, fmts[f], &err) == MCS_OK);
        fe_kw_deck *in = read_deck(path, NULL);
        if (!in) continue;
        CHECK(in->nnode == m->nnode && strcmp(in->title, "round trip") == 0);
        double worst = 0;
        for (int i = 0; i < in->nnode && in->nnode == m->nnode; i++)
            for (int k = 0; k < 3; k++)
                worst = fmax(worst, fabs(in->node_x[3 * i + k] - m->node_x0[3 * i + k]));
        /* coordinates are below 1.1 m: 11 significant digits is 1.1e-11 m */
        CHECK(worst <= (f == 2 ? 2e-16 : 2e-11));
        if (worst > (f == 2 ? 2e-16 : 2e-11)) fprintf(stderr, "format %d: worst %g\n", f, worst);
        const int nn[3] = {8, 4, 2};
        const int *conn[3] = {m->hex_node, m->shell_node, m->truss_node};
        const fe_kw_etype et[3] = {FE_KW_SOLID, FE_KW_SHELL, FE_KW_BEAM};
        const int ne[3] = {m->nhex, m->nshell, m->ntruss};
        for (int k = 0; k < 3; k++) {
            CHECK(in->elem[et[k]].n == ne[k]);
            int same = in->elem[et[k]].n == ne[k];
            for (int i = 0; i < nn[k] * ne[k] && same; i++)
                same = in->elem[et[k]].node[i] == conn[k][i] + 1;
            CHECK(same);
        }
        /* and back into a model: same masses, sections and materials */
        fe_builder *b2 = NULL;
        fe_model *m2 = NULL;
        CHECK(fe_builder_create(&b2, &err) == MCS_OK);
        CHECK(fe_kw_add_deck(b2, in, &err) == MCS_OK);
        CHECK(fe_model_create(b2, NULL, &m2, &err) == MCS_OK);
        if (m2) {
            CHECK(m2->nnode == m->nnode && m2->nelem == m->nelem && m2->npart == 3);
            CHECK_REL(m2->mass_total, m->mass_total, 1e-9);
            CHECK(strcmp(m2->part[0].name, "tube") == 0 && m2->part[0].section.thickness == 1.5e-3);
            CHECK(m2->part[0].material.nhardening == 2 &&
                  m2->part[0].material.hardening[1][1] == 400e6);
            CHECK(m2->part[2].section.type == FE_SECTION_TRUSS && m2->part[2].section.area == 1e-5);
        }
        fe_model_destroy(&m2);
        fe_builder_destroy(&b2);
        fe_kw_deck_destroy(&in);
    }
    fe_kw_deck_destroy(&out);
    fe_model_destroy(&m);
}

/* all_keywords.k written and read back keeps every entity */
static void test_write_read_deck(void)
{
    fe_kw_deck *d = read_deck(KD "all_keywords.k", NULL);
    if (!d) return;
    char path[128];
    snprintf(path, sizeof path, "%s/all.k", tmpdir);
    mcs_error err = {0};
    CHECK(fe_kw_write(d, path, FE_KW_FIXED, &err) == MCS_OK);
    fe_kw_deck *e = read_deck(path, NULL);
    if (e) {
        CHECK(e->nnode == d->nnode && e->npart == d->npart && e->nsection == d->nsection);
        CHECK(e->nmat == d->nmat && e->ncurve == d->ncurve && e->nset == d->nset);
        CHECK(e->nspc == d->nspc && e->niv == d->niv && e->nwall == d->nwall);
        CHECK(e->nunknown == 0);
        for (int t = 0; t < FE_KW_NETYPE; t++) CHECK(e->elem[t].n == d->elem[t].n);
        CHECK(e->elem[FE_KW_DISCRETE].dval[0] == 2.0 && e->elem[FE_KW_DISCRETE].dval[1] == 0.001);
        CHECK(fe_kw_find_curve(e, 7) && fe_kw_find_curve(e, 7)->xy[5] == 400e6);
        CHECK(fe_kw_find_mat(e, 1) && fe_kw_find_mat(e, 1)->c == 40.4);
    }
    fe_kw_deck_destroy(&e);
    fe_kw_deck_destroy(&d);
}

/* bar_mm.k as a whole deck (mm-s-t): its *INITIAL_VELOCITY_GENERATION and *RIGIDWALL_PLANAR
 * become the model's initial velocity and wall; mass rho A L = 8000 * 1e-4 * 0.1 = 0.08 kg */
static void test_deck_to_model(void)
{
    fe_kw_deck *d = read_deck(KD "bar_mm.k", "mm-s-t");
    if (!d) return;
    fe_builder *b = NULL;
    fe_model *m = NULL;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    CHECK(fe_kw_add_deck(b, d, &err) == MCS_OK);
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (m) {
        CHECK(m->nnode == 204 && m->nhex == 50 && strcmp(m->part[0].name, "bar") == 0);
        CHECK_REL(m->mass_total, 0.08, 1e-12);
        CHECK_REL(m->part[0].material.youngs_modulus, 200e9, 1e-14);
        int allv = 1;
        for (int i = 0; i < m->nnode; i++) allv = allv && fabs(m->node_v0[3 * i] + 5) < 1e-12;
        CHECK(allv);
        CHECK(m->nwall == 1 && strcmp(m->wall[0].name, "wall") == 0);
        CHECK(m->wall[0].normal[0] == 1 && fabs(m->wall[0].point[0] + 1e-5) < 1e-18);
    }
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    /* a part that the kernel cannot build is refused with its reason */
    fe_kw_deck *a = read_deck(KD "all_keywords.k", NULL);
    if (a) {
        CHECK(fe_builder_create(&b, &err) == MCS_OK);
        mcs_error_clear(&err);
        CHECK(fe_kw_add_deck(b, a, &err) == MCS_ERR_KEY);
        CHECK_STR_CONTAINS(err.msg, "*PART 4: discrete elements need a *SECTION_DISCRETE");
        fe_builder_destroy(&b);
    }
    fe_kw_deck_destroy(&a);
    fe_kw_deck_destroy(&d);
}

/* spring_mass.k (mm-s-t): *ELEMENT_DISCRETE with *SECTION_DISCRETE and *MAT_SPRING_ELASTIC
 * (K 50 N/mm, S 2: k = 1e5 N/m each) under a 100 mm steel cube (M = 7850 * 1e-3 = 7.85 kg)
 * started at 1 m/s. Four springs in parallel: T = 2 pi sqrt(M / 4k) = 27.83 ms (the cube is
 * rigid by comparison: its own axial period is ~8e-5 s). The cube's mean z crosses its start
 * downward-going at T/2 and upward at T. */
static void test_spring_mass(void)
{
    fe_kw_deck *d = read_deck(KD "spring_mass.k", "mm-s-t");
    if (!d) return;
    CHECK(fe_kw_find_mat(d, 2) && fe_kw_find_mat(d, 2)->type == FE_KW_MAT_SPRING &&
          fabs(fe_kw_find_mat(d, 2)->k - 5e4) < 1e-9);
    fe_builder *b = NULL;
    fe_model *m = NULL;
    fe_state *st = NULL;
    mcs_error err = {0};
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    CHECK(fe_kw_add_deck(b, d, &err) == MCS_OK);
    CHECK(fe_model_create(b, NULL, &m, &err) == MCS_OK);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    if (m && fe_state_create(m, &st, &err) == MCS_OK) {
        CHECK(m->nspring == 4 && m->npart == 2);
        const double M = 7.85, k = 1e5, T = 2 * M_PI * sqrt(M / (4 * k));
        double z0 = 0, zprev = 0, tprev = 0, cross[2] = {0, 0};
        int nc = 0;
        for (int i = 8; i < 16; i++) z0 += m->node_x0[3 * i + 2] / 8;
        zprev = z0;
        while (st->time < 1.2 * T && nc < 2) {
            if (fe_step(m, st) != MCS_OK) break;
            double z = 0;
            for (int i = 8; i < 16; i++) z += st->node_x[3 * i + 2] / 8;
            if (st->time > 0.1 * T && (zprev - z0) * (z - z0) <= 0 && z != zprev)
                cross[nc++] = tprev + (st->time - tprev) * (z0 - zprev) / (z - zprev);
            zprev = z, tprev = st->time;
        }
        CHECK(nc == 2);
        FIG("readme.kw_spring_period_err", "%.0e", fabs(cross[1] / T - 1));
        CHECK_REL(cross[0], T / 2, 1e-4);
        CHECK_REL(cross[1], T, 6e-6); /* 2e-6 stated */
        printf("spring-mass from keyword springs: period %.7g s, analytic %.7g s (%+.2e)\n",
               cross[1], T, cross[1] / T - 1);
    }
    fe_state_destroy(&st);
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
}

/* *MAT_RIGID becomes a rigid part: a block given 2 m/s by *INITIAL_VELOCITY_GENERATION keeps
 * every node at 2 m/s (free flight of a rigid body) */
static void test_rigid_part(void)
{
    static const char deck[] = "*KEYWORD\n*PART\nblock\n1,1,1\n*SECTION_SOLID\n1,1\n"
                               "*MAT_RIGID\n1,7850,2.1e11,0.3\n\n\n*NODE\n"
                               "1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n"
                               "5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
                               "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n"
                               "*INITIAL_VELOCITY_GENERATION\n1,2,0,2,0,0\n0,0,0\n*END\n";
    fe_kw_opts o = quiet_opts(NULL);
    fe_kw_deck *d = NULL;
    fe_builder *b = NULL;
    fe_model *m = NULL;
    fe_state *st = NULL;
    mcs_error err = {0};
    CHECK(fe_kw_read_mem("rigid.k", deck, sizeof deck - 1, &o, &d, &err) == MCS_OK);
    CHECK(fe_builder_create(&b, &err) == MCS_OK);
    if (d) CHECK(fe_kw_add_deck(b, d, &err) == MCS_OK);
    fe_opts fo = fe_opts_default();
    fo.dt_max = 1e-4; /* a lone rigid part sets no stable step */
    CHECK(fe_model_create(b, &fo, &m, &err) == MCS_OK);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    if (m && fe_state_create(m, &st, &err) == MCS_OK) {
        CHECK(m->part[0].material.model == FE_MAT_RIGID);
        CHECK_REL(m->mass_total, 7850, 1e-12);
        for (int i = 0; i < 50; i++)
            if (fe_step(m, st) != MCS_OK) break;
        double worst = 0;
        for (int n = 0; n < 8; n++)
            worst = fmax(worst, fabs(st->node_x[3 * n] - m->node_x0[3 * n] - 2 * st->time));
        CHECK(st->time > 0 && worst < 1e-9);
    }
    fe_state_destroy(&st);
    fe_model_destroy(&m);
    fe_builder_destroy(&b);
    fe_kw_deck_destroy(&d);
}

static int read_force(const char *h5, mcs_array *f)
{
    mcs_results *h = NULL;
    mcs_error err = {0};
    int ok = mcs_results_open(&h, h5, &err) == MCS_OK &&
             mcs_results_read(h, "/stage3/rigidwall/wall/force", f, &err) == MCS_OK;
    mcs_results_close(&h);
    return ok;
}

/* the elastic bar into a rigid wall from a keyword mesh (mm-s-t, section and material from
 * the deck) gives the generated mesh's wall force history: same nodes up to a unit conversion
 * rounding (<= 1 ulp), so the forces agree to 1e-12 of the peak rho c A v = 20 kN */
static void test_bar_keyword_run(void)
{
    char a[128], b[128], cmd[512];
    snprintf(a, sizeof a, "%s/gen.h5", tmpdir);
    snprintf(b, sizeof b, "%s/kw.h5", tmpdir);
    snprintf(cmd, sizeof cmd, "run scenarios/verification/bar_wall_impact.yaml -o %s --quiet", a);
    CHECK(cli_run(cmd)->status == 0);
    snprintf(cmd, sizeof cmd, "run " KD "bar_keyword.yaml -o %s --quiet --json", b);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "\"elements\": 50");
    mcs_array fa = {0}, fb = {0};
    CHECK(read_force(a, &fa) && read_force(b, &fb));
    CHECK(fa.n == fb.n && fa.n > 100);
    double peak = 0, worst = 0;
    for (size_t i = 0; i < fa.n && fa.n == fb.n; i++) {
        peak = fmax(peak, fabs(fa.v[i]));
        worst = fmax(worst, fabs(fa.v[i] - fb.v[i]));
    }
    CHECK(peak > 19e3 && peak < 22e3);
    printf("bar: keyword vs generated mesh: max |dF| = %.3g N of peak %.6g N\n", worst, peak);
    FIG("readme.kw_bar_force_diff_n", "%.1e", worst);
    FIG("readme.kw_bar_peak_kn", "%.1f", 1e-3 * peak);
    CHECK(worst <= 5e-10); /* 1.5e-10 N stated: round-off of the node order */
    mcs_array_free(&fa);
    mcs_array_free(&fb);
}

/* `mcrash export OUT.h5 --k FILE`: the stage-3 mesh of the bar run (undeformed: the deck's
 * nodes in SI; --deformed: plus the final displacement; --units mm-s-t: in mm) */
static void test_export_k(void)
{
    char h5[128], k1[128], k2[128], k3[128], cmd[512];
    snprintf(h5, sizeof h5, "%s/kw.h5", tmpdir);
    snprintf(k1, sizeof k1, "%s/mesh.k", tmpdir);
    snprintf(k2, sizeof k2, "%s/deformed.k", tmpdir);
    snprintf(k3, sizeof k3, "%s/mesh_mm.k", tmpdir);
    snprintf(cmd, sizeof cmd, "export %s --k %s", h5, k1);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 0);
    CHECK_STR_CONTAINS(r->out, "(204 nodes, 50 elements)");
    snprintf(cmd, sizeof cmd, "export %s --k %s --deformed --long", h5, k2);
    CHECK(cli_run(cmd)->status == 0);
    snprintf(cmd, sizeof cmd, "export %s --k %s --units mm-s-t --stage 3", h5, k3);
    CHECK(cli_run(cmd)->status == 0);
    fe_kw_deck *ref = read_deck(KD "bar_mm.k", "mm-s-t"), *a = read_deck(k1, NULL);
    fe_kw_deck *b = read_deck(k2, NULL), *c = read_deck(k3, "mm-s-t");
    mcs_results *h = NULL;
    mcs_error err = {0};
    mcs_array u = {0};
    CHECK(mcs_results_open(&h, h5, &err) == MCS_OK &&
          mcs_results_read(h, "/stage3/fields/displacement", &u, &err) == MCS_OK);
    mcs_results_close(&h);
    if (ref && a && b && c && u.rank == 3 && u.dims[1] == 204) {
        CHECK(a->nnode == 204 && a->elem[FE_KW_SOLID].n == 50 && a->npart == 1);
        CHECK(strcmp(a->part[0].title, "bar") == 0);
        const double *ul = u.v + (u.dims[0] - 1) * 204 * 3;
        double w0 = 0, w1 = 0, w2 = 0, umax = 0;
        for (int i = 0; i < 204 * 3; i++) {
            w0 = fmax(w0, fabs(a->node_x[i] - ref->node_x[i]));
            w1 = fmax(w1, fabs(b->node_x[i] - (ref->node_x[i] + ul[i])));
            w2 = fmax(w2, fabs(c->node_x[i] - ref->node_x[i]));
            umax = fmax(umax, fabs(ul[i]));
        }
        CHECK(w0 <= 1e-15 && w1 <= 1e-15 && w2 <= 1e-15);
        CHECK(umax > 1e-5); /* the bar moved: 5 m/s for 60 us less the bounce */
        int same = 1;
        for (int i = 0; i < 8 * 50; i++)
            same = same && a->elem[FE_KW_SOLID].node[i] == ref->elem[FE_KW_SOLID].node[i];
        CHECK(same);
    }
    mcs_array_free(&u);
    fe_kw_deck_destroy(&ref), fe_kw_deck_destroy(&a), fe_kw_deck_destroy(&b);
    fe_kw_deck_destroy(&c);
    /* a results file without a mesh */
    snprintf(cmd, sizeof cmd, "export %s --k %s --stage 1", h5, k1);
    r = cli_run(cmd);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "no /stage1/mesh");
}

/* scenario errors name the YAML key and the deck's line */
static void test_scenario_errors(void)
{
    char yaml[128], cwd[512], text[1024];
    snprintf(yaml, sizeof yaml, "%s/bad.yaml", tmpdir);
    CHECK(getcwd(cwd, sizeof cwd) != NULL);
    snprintf(text, sizeof text,
             "mcrash: 1\nsimulation: {end_time: 1 us}\nfe:\n  parts:\n    - name: p\n"
             "      mesh: {keyword: %s/" KD "bad_number.k, part: 1}\n",
             cwd);
    FILE *f = fopen(yaml, "w");
    if (f) fputs(text, f), fclose(f);
    char cmd[256];
    snprintf(cmd, sizeof cmd, "run %s -o %s/bad.h5 --quiet", yaml, tmpdir);
    cli_result *r = cli_run(cmd);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "bad.yaml:6:");
    CHECK_STR_CONTAINS(r->err, "bad_number.k:6:32: error: *NODE: field Y");
    /* a generated mesh still needs its section and material */
    snprintf(text, sizeof text,
             "mcrash: 1\nsimulation: {end_time: 1 us}\nfe:\n  parts:\n    - name: p\n"
             "      mesh: {generate: box, size: [1, 1, 1], divisions: [1, 1, 1]}\n");
    f = fopen(yaml, "w");
    if (f) fputs(text, f), fclose(f);
    snprintf(cmd, sizeof cmd, "check %s", yaml);
    r = cli_run(cmd);
    CHECK(r->status == 2);
    CHECK_STR_CONTAINS(r->err, "section");
}

/* random mutations of the decks: every read returns a status (OK or a message), and a deck
 * that reads is built or refused cleanly. Runs under ASan/UBSan in `make check-asan`. */
static uint64_t rng = 0x9E3779B97F4A7C15ull;
static unsigned rnd(unsigned n)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (unsigned)(rng % n);
}

static char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *s = malloc(1 << 16);
    *n = s ? fread(s, 1, (1 << 16) - 1, f) : 0;
    fclose(f);
    return s;
}

static void mutate(char *s, size_t *n, size_t cap)
{
    static const char pool[] = "0123456789 ,.-+eE*$%\n\t&xX_";
    int k = 1 + (int)rnd(4);
    for (int i = 0; i < k && *n > 0; i++) {
        size_t at = rnd((unsigned)*n);
        switch (rnd(5)) {
        case 0: s[at] = pool[rnd(sizeof pool - 1)]; break;
        case 1: /* delete a byte */
            memmove(s + at, s + at + 1, *n - at - 1), (*n)--;
            break;
        case 2: /* insert a byte */
            if (*n + 1 < cap) memmove(s + at + 1, s + at, *n - at), s[at] = pool[rnd(sizeof pool - 1)], (*n)++;
            break;
        case 3: *n = at; break; /* truncate */
        default: s[at] = (char)rnd(256); break;
        }
    }
}

static void count_log(mcs_log_level lvl, const char *msg, void *user)
{
    (void)lvl, (void)msg;
    (*(int *)user)++;
}

static void test_fuzz(void)
{
    int nlog = 0;
    mcs_log_set_handler(count_log, &nlog); /* the mutants' warnings are not shown */
    static const char *files[] = {KD "all_keywords.k", KD "plate_fixed.k", KD "plate_long.k",
                                  KD "plate_i10.k", KD "plate_free.k", KD "bar_mm.k",
                                  KD "spring_mass.k"};
    const int nfiles = (int)(sizeof files / sizeof files[0]);
    int nread = 0, nfail = 0, nbuilt = 0, bad_status = 0;
    const int rounds = th_verify() ? 3000 : 400;
    for (int r = 0; r < rounds; r++) {
        const char *path = files[r % nfiles];
        size_t n = 0;
        char *s = slurp(path, &n);
        if (!s) continue;
        mutate(s, &n, 1 << 16);
        fe_kw_opts o = quiet_opts(r % 3 == 0 ? "mm-s-t" : NULL);
        o.strict = r % 7 == 0;
        fe_kw_deck *d = NULL;
        mcs_error err = {0};
        mcs_status st = fe_kw_read_mem(path, s, n, &o, &d, &err);
        if (st) {
            nfail++;
            if (!err.msg[0] || d) bad_status++;
        } else {
            nread++;
            fe_builder *b = NULL;
            fe_model *m = NULL;
            mcs_error e2 = {0};
            if (fe_builder_create(&b, &e2) == MCS_OK && fe_kw_add_deck(b, d, &e2) == MCS_OK &&
                fe_model_create(b, NULL, &m, &e2) == MCS_OK)
                nbuilt++;
            else if (!e2.msg[0])
                bad_status++;
            fe_model_destroy(&m);
            fe_builder_destroy(&b);
            char out[128];
            snprintf(out, sizeof out, "%s/fuzz.k", tmpdir);
            if (fe_kw_write(d, out, FE_KW_FIXED_LONG, &e2) == MCS_OK) {
                fe_kw_deck *back = NULL;
                fe_kw_opts q = quiet_opts(NULL);
                if (fe_kw_read(out, &q, &back, &e2) != MCS_OK) bad_status++;
                fe_kw_deck_destroy(&back);
            }
        }
        fe_kw_deck_destroy(&d);
        free(s);
    }
    mcs_log_set_handler(NULL, NULL);
    CHECK(bad_status == 0);
    CHECK(nread + nfail == rounds && nread > 0 && nfail > 0);
    printf("fuzz: %d mutated decks: %d read (%d built), %d refused with a message\n", rounds,
           nread, nbuilt, nfail);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mcrash_kw_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_all_keywords);
    RUN(test_formats_agree);
    RUN(test_units);
    RUN(test_errors);
    RUN(test_roundtrip);
    RUN(test_write_read_deck);
    RUN(test_deck_to_model);
    RUN(test_spring_mass);
    RUN(test_rigid_part);
    RUN(test_bar_keyword_run);
    RUN(test_export_k);
    RUN(test_scenario_errors);
    RUN(test_fuzz);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tmpdir);
    TEST_END();
}

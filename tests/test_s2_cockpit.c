/* tests for the stage-2 cockpit: stage2.fe merged into fe: (stage2_fe/s2_scenario.c,
 * core/mcs_scn_merge.c), foam pads generated on a body's ellipsoid and attached by
 * `where: surface` (fe/scn/fe_scn_pad.c), material_from (fe/scn/fe_scn_build.c).
 * References (docs/validation_stage2.md "The cockpit"), none a value of the code under test:
 * the merge against the scenario text it must give (keys added, settings replaced, errors at
 * their FILE:LINE:COL); the pads' geometry against closed forms (nodes at R and R + t on a
 * sphere, the inscribed facets' area and frustum volume times 425 kg/m^3, the paper's foam
 * density [2023 Sec. 2.3.3]; an ellipsoid's equation and its surface normal); a body pressed
 * into a pad against the foam's own 100/s loading curve times the contact area, S_100(e) A. */
#include "core/mcs_scenario.h"
#include "fe/fe_contact.h"
#include "fe/fe_model.h"
#include "fe/fe_state.h"
#include "fe/fe_scn_build.h"
#include "stage1_mb/mb_couple.h"
#include "stage1_mb/mb_prescribe.h"
#include "stage2_fe/s2_scenario.h"
#include "tests/harness.h"
#include "tests/mb_test_util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define DEG (M_PI / 180)

static mcs_scenario *load(const char *name, const char *y, mcs_error *err)
{
    mcs_scenario *scn = NULL;
    mcs_scenario_load_text(name, y, strlen(y), &scn, err);
    return scn;
}

/* ---- stage2.fe merged into fe: ---- */

#define FOAM_MAT                                                                                   \
    "{model: foam, density: 425 kg/m^3, youngs_modulus: 20 MPa,\n"                                 \
    "                 curves: [{rate: 1, points: [[0.05, 0.15 MPa], [0.5, 0.3 MPa]]}]}\n"

static const char *merge_yaml =
    "mcrash: 1\nname: merge\n"
    "simulation: {end_time: 1 ms, time_step: 10 us}\n"
    "bodies:\n"
    "  - {name: frame, mass: 10, inertia: [1, 1, 1], position: [0, 0, 0], velocity: [0, 0, 0],\n"
    "     surfaces: [{name: tank, type: ellipsoid, center: [0, 0, 0], semi_axes: [0.2, 0.2, "
    "0.2]}]}\n"
    "fe:\n"
    "  parts:\n"
    "    - name: knee\n"
    "      mesh: {generate: box, size: [15 mm, 40 mm, 40 mm], divisions: [1, 2, 2],\n"
    "             origin: [0.3, 0, 0]}\n"
    "      section: {type: solid}\n"
    "      material: " FOAM_MAT "      attach: {body: frame, where: x_min}\n"
    "  contacts: [{name: knee_frame, type: bodies, parts: [knee], bodies: [frame]}]\n"
    "stage2:\n"
    "  motion: none.h5\n"
    "  prescribed: [{body: frame}]\n"
    "  fe:\n"
    "    parts:\n"
    "      - name: pad\n"
    "        mesh: {generate: foam_pad, body: frame, surface: tank, thickness: 15 mm,\n"
    "               element_size: 40 mm, longitude: [-30 deg, 30 deg], latitude: [-20 deg, 20 "
    "deg]}\n"
    "        section: {type: solid}\n"
    "        material_from: knee\n"
    "        attach: {body: frame, where: surface}\n"
    "    contacts: [{name: pad_knee, type: bodies, parts: [pad, knee], bodies: [frame]}]\n"
    "    bulk_q2: 0.03\n";

static void test_merge(void)
{
    mcs_error err = {0};
    mcs_scenario *scn = load("merge.yaml", merge_yaml, &err), *s2 = NULL;
    CHECK(scn != NULL);
    if (!scn) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    /* stage 1 sees fe:'s own part only */
    const mcs_node *fe1 = mcs_node_get(mcs_scenario_root(scn), "fe");
    CHECK(mcs_node_len(mcs_node_get(fe1, "parts")) == 1);
    CHECK(s2_scenario_compile(scn, &s2, &err) == MCS_OK);
    mcs_scenario_destroy(&scn); /* the compiled one has its own nodes */
    if (!s2) return;
    const mcs_node *root = mcs_scenario_root(s2), *fe = mcs_node_get(root, "fe");
    const mcs_node *parts = mcs_node_get(fe, "parts"), *con = mcs_node_get(fe, "contacts");
    CHECK(mcs_node_len(parts) == 2 && mcs_node_len(con) == 2);
    CHECK(strcmp(mcs_node_str(mcs_node_get(mcs_node_at(parts, 0), "name")), "knee") == 0);
    CHECK(strcmp(mcs_node_str(mcs_node_get(mcs_node_at(parts, 1), "name")), "pad") == 0);
    CHECK(strcmp(mcs_node_str(mcs_node_get(mcs_node_at(con, 1), "name")), "pad_knee") == 0);
    CHECK_NEAR(mcs_node_num(mcs_node_get(fe, "bulk_q2")), 0.03, 1e-15); /* a setting: replaced */
    /* stage2.fe is gone (compiling again adds nothing), the rest of stage2 stays */
    const mcs_node *st2 = mcs_node_get(root, "stage2");
    CHECK(mcs_node_get(st2, "fe") == NULL);
    CHECK(mcs_node_len(mcs_node_get(st2, "prescribed")) == 1);
    /* the merged part keeps where it was written (line 23 of the text), in SI */
    const mcs_node *t = mcs_node_get(mcs_node_get(mcs_node_at(parts, 1), "mesh"), "thickness");
    CHECK(mcs_node_line(t) == 23 && strcmp(mcs_node_file(t), "merge.yaml") == 0);
    CHECK_NEAR(mcs_node_num(t), 0.015, 1e-15);
    mcs_scenario *again = NULL;
    CHECK(s2_scenario_compile(s2, &again, &err) == MCS_OK);
    CHECK(again &&
          mcs_node_len(mcs_node_get(mcs_node_get(mcs_scenario_root(again), "fe"), "parts")) == 2);
    mcs_scenario_destroy(&again);
    mcs_scenario_destroy(&s2);
}

/* text with `from` replaced by `to` (once) */
static const char *edit(const char *y, const char *from, const char *to)
{
    static char bufs[2][8192];
    static int k;
    char *buf = bufs[k++ % 2];
    const char *p = strstr(y, from);
    CHECK(p != NULL);
    if (!p) return y;
    snprintf(buf, sizeof bufs[0], "%.*s%s%s", (int)(p - y), y, to, p + strlen(from));
    return buf;
}

static void test_merge_errors(void)
{
    mcs_error err = {0};
    /* a stage2.fe part named as an fe: part: the merged list's names are unique */
    const char *dup = edit(edit(merge_yaml, "- name: pad", "- name: knee"), "parts: [pad, knee]",
                           "parts: [knee]");
    mcs_scenario *scn = load("dup.yaml", dup, &err);
    mcs_scenario *s2 = NULL;
    CHECK(scn != NULL);
    CHECK(scn && s2_scenario_compile(scn, &s2, &err) != MCS_OK && s2 == NULL);
    CHECK_STR_CONTAINS(err.msg, "dup.yaml:22:");
    CHECK_STR_CONTAINS(err.msg, "duplicate name 'knee'");
    mcs_scenario_destroy(&scn);
    err = (mcs_error){0};
    /* stage 1's fe: cannot name a stage-2 part */
    scn = load("ref.yaml", edit(merge_yaml, "parts: [knee], bodies", "parts: [pad], bodies"), &err);
    CHECK(scn == NULL);
    CHECK_STR_CONTAINS(err.msg, "unknown FE part 'pad'");
    err = (mcs_error){0};
    /* no stage2: block */
    const char *p = strstr(merge_yaml, "stage2:");
    char head[4096];
    snprintf(head, sizeof head, "%.*s", (int)(p - merge_yaml), merge_yaml);
    scn = load("no2.yaml", head, &err);
    CHECK(scn && s2_scenario_compile(scn, &s2, &err) == MCS_ERR_KEY);
    CHECK_STR_CONTAINS(err.msg, "no stage2: block");
    mcs_scenario_destroy(&scn);
    err = (mcs_error){0};
    /* a pad on a surface the body does not have, or reaching the pole */
    scn = load("surf.yaml", edit(merge_yaml, "surface: tank", "surface: seat"), &err);
    CHECK(scn == NULL);
    CHECK_STR_CONTAINS(err.msg, "no surface named 'seat'");
    err = (mcs_error){0};
    scn = load("pole.yaml", edit(merge_yaml, "[-20 deg, 20 deg]", "[-20 deg, 90 deg]"), &err);
    CHECK(scn == NULL);
    CHECK_STR_CONTAINS(err.msg, "-90 deg < from < to < 90 deg");
    err = (mcs_error){0};
    scn = load("both.yaml",
               edit(merge_yaml, "material_from: knee",
                    "material_from: knee\n"
                    "        material: " FOAM_MAT),
               &err);
    CHECK(scn == NULL);
    CHECK_STR_CONTAINS(err.msg, "material or material_from, not both");
}

/* ---- a foam pad on a body's ellipsoid ---- */

/* a frame at (0.5, 0.2, 0.8) m turned 90 deg about z (x -> y): a sphere R 0.1 m at (0.05, 0,
 * 0.1) in its frame, i.e. (0.5, 0.25, 0.9) in the world, and an ellipsoid 0.2 x 0.12 x 0.08 m
 * at (-0.3, 0, 0), turned 30 deg about its z; a pad on each (the second of 2 layers) */
static const char *pad_yaml =
    "mcrash: 1\nname: pads\n"
    "simulation: {end_time: 1 ms, time_step: 10 us}\n"
    "bodies:\n"
    "  - {name: frame, mass: 10, inertia: [1, 1, 1], position: [0.5, 0.2, 0.8],\n"
    "     orientation: [0, 0, 90 deg], velocity: [0, 0, 0],\n"
    "     surfaces: [{name: ball, type: ellipsoid, center: [0.05, 0, 0.1], semi_axes: [0.1, 0.1, "
    "0.1]},\n"
    "                {name: egg, type: ellipsoid, center: [-0.3, 0, 0], semi_axes: [0.2, 0.12, "
    "0.08],\n"
    "                 orientation: [0, 0, 30 deg]},\n"
    "                {name: lid, type: facet, vertices: [[0.2, -0.05, 0], [0.3, -0.05, 0],\n"
    "                 [0.3, 0.05, 0], [0.2, 0.05, 0]], triangles: [[0, 1, 2], [0, 2, 3]]}]}\n"
    "fe:\n"
    "  parts:\n"
    "    - name: src\n"
    "      mesh: {generate: box, size: [15 mm, 40 mm, 40 mm], divisions: [1, 2, 2],\n"
    "             origin: [2, 0, 0]}\n"
    "      section: {type: solid}\n"
    "      material: " FOAM_MAT "    - name: pad\n"
    "      mesh: {generate: foam_pad, body: frame, surface: ball, thickness: 15 mm,\n"
    "             element_size: 10 mm, longitude: [30 deg, 120 deg], latitude: [-20 deg, 40 deg]}\n"
    "      section: {type: solid}\n"
    "      material_from: src\n"
    "      attach: {body: frame, where: surface}\n"
    "    - name: egg_pad\n"
    "      mesh: {generate: foam_pad, body: frame, surface: egg, thickness: 12 mm, layers: 2,\n"
    "             element_size: 25 mm, longitude: [-60 deg, 60 deg], latitude: [-30 deg, 30 deg]}\n"
    "      section: {type: solid}\n"
    "      material_from: src\n"
    "      attach: {body: frame, where: surface}\n"
    "    - name: lid_pad\n"
    "      mesh: {generate: foam_pad, body: frame, surface: lid, thickness: 15 mm}\n"
    "      section: {type: solid}\n"
    "      material_from: src\n"
    "      attach: {body: frame, where: surface}\n"
    "    - name: lid_shell\n"
    "      mesh: {generate: surface_shell, body: frame, surface: lid}\n"
    "      section: {type: shell, thickness: 2 mm}\n"
    "      material: {model: elastic, density: 1000, youngs_modulus: 1 GPa, poisson: 0.3}\n"
    "    - name: ball_shell\n"
    "      mesh: {generate: surface_shell, body: frame, surface: ball, element_size: 10 mm,\n"
    "             longitude: [30 deg, 120 deg], latitude: [-20 deg, 40 deg]}\n"
    "      section: {type: shell, thickness: 2 mm}\n"
    "      material: {model: elastic, density: 1000, youngs_modulus: 1 GPa, poisson: 0.3}\n";

static int part_index(const fe_model *m, const char *name)
{
    for (int i = 0; i < m->npart; i++)
        if (strcmp(m->part[i].name, name) == 0) return i;
    return -1;
}

/* the lumped mass of a part's nodes (parts here share none) [kg] */
static double part_mass(const fe_model *m, int ip)
{
    const fe_part *p = &m->part[ip];
    int kind = p->elem_kind, nn = kind == FE_KIND_HEX ? 8 : 4;
    const int *conn = kind == FE_KIND_HEX ? m->hex_node : m->shell_node;
    unsigned char *seen = calloc((size_t)m->nnode, 1);
    double mass = 0;
    for (int e = p->elem_begin; seen && e < p->elem_end; e++)
        for (int k = 0; k < nn; k++) {
            int n = conn[nn * e + k];
            if (!seen[n]) seen[n] = 1, mass += m->node_mass[n];
        }
    free(seen);
    return mass;
}

static void sub3(const double *a, const double *b, double *r)
{
    for (int i = 0; i < 3; i++)
        r[i] = a[i] - b[i];
}

static void cross3(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1], r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static double norm3(const double *a)
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

/* the built pads (fe_scn_build: a stage-3 build, the attached nodes fixed) */
static fe_problem build_pads(mcs_error *err)
{
    fe_problem p = {0};
    mcs_scenario *scn = load("pads.yaml", pad_yaml, err);
    CHECK(scn != NULL);
    if (scn) CHECK(fe_scn_build(scn, &p, err) == MCS_OK);
    if (!p.model) fprintf(stderr, "%s\n", err->msg);
    mcs_scenario_destroy(&scn);
    return p;
}

/* The sphere pad against closed forms. The mesh: ceil(R dlon / h) = ceil(15.71) = 16 by
 * ceil(R dlat / h) = ceil(10.47) = 11 hexes. Inner nodes at R, outer at R + t from the centre.
 * Its faces are flat (a lat-lon quad on a sphere is an isosceles trapezoid; the side faces lie
 * in planes through the centre), so each hex is the frustum of a pyramid with its apex at the
 * centre: inner face area A_j = (c_j + c_j+1) / 2 * h_j with chords c_j = 2 R cos(lat_j)
 * sin(du / 2) and h_j the distance of the chords' midpoints (rho_j = R cos(lat_j) cos(du / 2),
 * z_j = R sin(lat_j)) in the mid-longitude plane; volume d_j A_j ((1 + t / R)^3 - 1) / 3 with
 * d_j = |rho_j z_j+1 - rho_j+1 z_j| / h_j the centre's distance from the face. The smooth
 * patch: A = R^2 dlon (sin lat1 - sin lat0), V = dlon (sin lat1 - sin lat0) ((R + t)^3 - R^3)
 * / 3, which the inscribed facets miss by O(du^2) (the figures below). */
static void test_pad_sphere(void)
{
    mcs_error err = {0};
    fe_problem p = build_pads(&err);
    if (!p.model) return;
    const fe_model *m = p.model;
    const double c[3] = {0.5, 0.25, 0.9}, R = 0.1, t = 0.015, rho = 425;
    const double lon0 = 30 * DEG, lon1 = 120 * DEG, lat0 = -20 * DEG, lat1 = 40 * DEG;
    const int nu = 16, nv = 11;
    int ip = part_index(m, "pad");
    CHECK(ip >= 0);
    if (ip < 0) return;
    const fe_part *pt = &m->part[ip];
    CHECK(pt->elem_end - pt->elem_begin == nu * nv);
    /* every node on the sphere or R + t out; the outer face of each hex t out along the radius */
    double area = 0, mass = 0, maxdev = 0;
    unsigned char *seen = calloc((size_t)m->nnode, 1);
    int nnode = 0;
    for (int e = pt->elem_begin; e < pt->elem_end; e++) {
        const int *n = m->hex_node + 8 * e;
        double x[8][3];
        for (int k = 0; k < 8; k++) {
            sub3(m->node_x0 + 3 * n[k], c, x[k]);
            maxdev = fmax(maxdev, fabs(norm3(x[k]) - (k < 4 ? R : R + t)));
            if (seen && !seen[n[k]]) {
                seen[n[k]] = 1, nnode++;
                mass += m->node_mass[n[k]];
            }
        }
        double d1[3], d2[3], cr[3];
        sub3(x[2], x[0], d1);
        sub3(x[3], x[1], d2);
        cross3(d1, d2, cr);
        area += 0.5 * norm3(cr); /* a planar quad */
    }
    free(seen);
    CHECK(nnode == 2 * (nu + 1) * (nv + 1));
    CHECK(maxdev < 1e-15);
    double du = (lon1 - lon0) / nu, dv = (lat1 - lat0) / nv, a_ref = 0, v_ref = 0;
    double k3 = pow(1 + t / R, 3) - 1;
    for (int j = 0; j < nv; j++) {
        double la = lat0 + j * dv, lb = la + dv;
        double ca = 2 * R * cos(la) * sin(du / 2), cb = 2 * R * cos(lb) * sin(du / 2);
        double ra = R * cos(la) * cos(du / 2), rb = R * cos(lb) * cos(du / 2);
        double za = R * sin(la), zb = R * sin(lb);
        double h = hypot(rb - ra, zb - za), aj = 0.5 * (ca + cb) * h;
        a_ref += nu * aj;
        v_ref += nu * fabs(ra * zb - rb * za) / h * aj * k3 / 3;
    }
    double a_smooth = R * R * (lon1 - lon0) * (sin(lat1) - sin(lat0));
    double v_smooth = (lon1 - lon0) * (sin(lat1) - sin(lat0)) * (pow(R + t, 3) - pow(R, 3)) / 3;
    printf("sphere pad: %d x %d hexes, inner area %.6e m^2 (facets %.6e, sphere %.6e: %+.3f %%), "
           "mass %.3f g (facets %.3f g, sphere %.3f g: %+.3f %%)\n",
           nu, nv, area, a_ref, a_smooth, 100 * (area / a_smooth - 1), 1e3 * mass,
           1e3 * rho * v_ref, 1e3 * rho * v_smooth, 100 * (mass / (rho * v_smooth) - 1));
    CHECK_REL(area, a_ref, 1e-12);
    CHECK_REL(mass, rho * v_ref, 1e-12); /* the lumped masses: density x the hexes' volume */
    /* surface_shell on the same patch: the hexes' inner faces, 2 mm at 1000 kg/m^3 */
    int is = part_index(m, "ball_shell");
    CHECK(is >= 0 && m->part[is].elem_end - m->part[is].elem_begin == nu * nv);
    CHECK_REL(part_mass(m, is), 1000 * 0.002 * a_ref, 1e-12);
    FIG("s2.pad_area_facet_pct", "%.2f", 100 * (area / a_smooth - 1));
    FIG("s2.pad_mass_g", "%.1f", 1e3 * mass);
    FIG("s2.pad_mass_facet_pct", "%.2f", 100 * (mass / (rho * v_smooth) - 1));
    fe_problem_free(&p);
}

/* The egg pad (a turned ellipsoid on the turned frame, 2 layers): its inner nodes solve the
 * ellipsoid's equation in its own frame, reached here by undoing the two turns by hand
 * (frame yaw 90 deg: world (x, y) = (-y_b, x_b); egg yaw 30 deg), and each first-layer hex's
 * outer nodes lie t/2 out along the normal (x / a^2, y / b^2, z / c^2) at its inner node. */
static void test_pad_ellipsoid(void)
{
    mcs_error err = {0};
    fe_problem p = build_pads(&err);
    if (!p.model) return;
    const fe_model *m = p.model;
    const double s[3] = {0.2, 0.12, 0.08}, t = 0.012, cw[3] = {0.5, 0.2 - 0.3, 0.8};
    int ip = part_index(m, "egg_pad");
    CHECK(ip >= 0);
    if (ip < 0) return;
    const fe_part *pt = &m->part[ip];
    double dev = 0, off = 0, par = 0;
    int inner = 0;
    for (int e = pt->elem_begin; e < pt->elem_end; e++) {
        const int *n = m->hex_node + 8 * e;
        for (int k = 0; k < 4; k++) {
            double d[3], b[3], l[3], ca = cos(30 * DEG), sa = sin(30 * DEG);
            sub3(m->node_x0 + 3 * n[k], cw, d);
            b[0] = d[1], b[1] = -d[0], b[2] = d[2]; /* undo the frame's yaw */
            l[0] = ca * b[0] + sa * b[1], l[1] = -sa * b[0] + ca * b[1], l[2] = b[2]; /* egg's */
            double f = l[0] * l[0] / (s[0] * s[0]) + l[1] * l[1] / (s[1] * s[1]) +
                       l[2] * l[2] / (s[2] * s[2]);
            if (fabs(f - 1) > 1e-6) continue; /* the second layer's hexes */
            inner++;
            dev = fmax(dev, fabs(f - 1));
            double g[3] = {l[0] / (s[0] * s[0]), l[1] / (s[1] * s[1]), l[2] / (s[2] * s[2])};
            double gb[3] = {ca * g[0] - sa * g[1], sa * g[0] + ca * g[1], g[2]};
            double gw[3] = {-gb[1], gb[0], gb[2]}, o[3], cr[3];
            sub3(m->node_x0 + 3 * n[k + 4], m->node_x0 + 3 * n[k], o);
            off = fmax(off, fabs(norm3(o) - t / 2));
            cross3(o, gw, cr);
            par = fmax(par, norm3(cr) / (norm3(o) * norm3(gw)));
        }
    }
    printf("egg pad: %d hexes, %d inner corners, |f - 1| <= %.1e, offset error %.1e m, "
           "angle to the normal %.1e rad\n",
           pt->elem_end - pt->elem_begin, inner, dev, off, par);
    CHECK(inner > 0 && inner == 2 * (pt->elem_end - pt->elem_begin)); /* half the hexes: 4 each */
    CHECK(dev < 1e-13 && off < 1e-15 && par < 1e-12);
    fe_problem_free(&p);
}

/* On the flat facet `lid` (0.1 x 0.1 m, two triangles, outward +z): foam_pad makes two prisms
 * (pentahedra) along the vertex normals, volume 0.1 x 0.1 x 0.015 m^3, 8 nodes, the 4 at the
 * facet's corners on it; surface_shell two triangles of area 0.01 m^2 */
static void test_pad_facet(void)
{
    mcs_error err = {0};
    fe_problem p = build_pads(&err);
    if (!p.model) return;
    const fe_model *m = p.model;
    int ip = part_index(m, "lid_pad"), is = part_index(m, "lid_shell");
    CHECK(ip >= 0 && is >= 0);
    if (ip < 0 || is < 0) return;
    CHECK(m->part[ip].elem_end - m->part[ip].elem_begin == 2);
    CHECK(m->part[is].elem_end - m->part[is].elem_begin == 2);
    double mp = part_mass(m, ip), ms = part_mass(m, is);
    printf("facet: pad mass %.6f g (425 x 1.5e-4 m^3 = %.6f g), shell %.6f g\n", 1e3 * mp,
           1e3 * 425 * 1.5e-4, 1e3 * ms);
    CHECK_REL(mp, 425 * 0.1 * 0.1 * 0.015, 1e-12);
    CHECK_REL(ms, 1000 * 0.002 * 0.01, 1e-12);
    /* the prisms' outer nodes 15 mm above (+z) their corners */
    for (int e = m->part[ip].elem_begin; e < m->part[ip].elem_end; e++) {
        const int *c = m->hex_node + 8 * e;
        CHECK(c[4] == c[5] && c[6] == c[7]); /* pentahedra: n1 n2 n3 n4 n5 n5 n6 n6 */
        CHECK_NEAR(m->node_x0[3 * c[2] + 2] - m->node_x0[3 * c[1] + 2], 0.015, 1e-15);
        CHECK_NEAR(m->node_x0[3 * c[6] + 2] - m->node_x0[3 * c[4] + 2], 0.015, 1e-15);
    }
    fe_problem_free(&p);
}

/* attach {where: surface}: the pads' inner nodes, (16 + 1) x (11 + 1) on the sphere and the
 * egg pad's first layer; and a keyword mesh modelled on a body: the spring_mass deck's base
 * cube (mm) has its bottom corners (0..100 mm, z = 0) on a sphere of radius sqrt(1.005) m
 * centred 1 m below its middle, the other nodes are 0.1 m or more off it */
static void test_attach_surface(void)
{
    mcs_error err = {0};
    fe_problem p = build_pads(&err);
    if (!p.model) return;
    int egg = part_index(p.model, "egg_pad");
    const fe_part *pe = &p.model->part[egg];
    int egg_inner = 0; /* the inner faces of both layers: the hexes' corners 0..3, distinct */
    unsigned char *seen = calloc((size_t)p.model->nnode, 1);
    for (int e = pe->elem_begin; e < pe->elem_end && seen; e++)
        for (int k = 0; k < 4; k++) {
            int n = p.model->hex_node[8 * e + k];
            if (!seen[n]) seen[n] = 1, egg_inner++;
        }
    free(seen);
    /* half of them on the surface (each layer's inner face has the same nodes' count) */
    printf("attach surface: %d nodes carried (sphere pad 204, egg pad %d, lid pad 4)\n", p.natt,
           egg_inner / 2);
    CHECK(p.natt == 17 * 12 + egg_inner / 2 + 4); /* + the lid pad's 4 corners */
    fe_problem_free(&p);
    char y[2048];
    snprintf(y, sizeof y,
             "mcrash: 1\nname: kw\nsimulation: {end_time: 1 ms, time_step: 10 us}\n"
             "bodies:\n"
             "  - {name: base, mass: 10, inertia: [1, 1, 1], position: [0.05, 0.05, -1],\n"
             "     velocity: [0, 0, 0], surfaces: [{name: s, type: ellipsoid, center: [0, 0, 0],\n"
             "     semi_axes: [%.12f, %.12f, %.12f]}]}\n"
             "fe:\n  parts:\n"
             "    - {name: cube, mesh: {keyword: spring_mass.k, part: 1, units: mm-s-t},\n"
             "       attach: {body: base, where: surface}}\n",
             sqrt(1.005), sqrt(1.005), sqrt(1.005));
    mcs_scenario *scn = load("tests/data/keyword/kw_attach.yaml", y, &err);
    fe_problem q = {0};
    CHECK(scn && fe_scn_build(scn, &q, &err) == MCS_OK);
    if (!q.model) fprintf(stderr, "%s\n", err.msg);
    CHECK(q.natt == 4);
    for (int i = 0; i < q.natt && q.model; i++)
        CHECK(fabs(q.model->node_x0[3 * q.att[i].node + 2]) < 1e-12);
    fe_problem_free(&q);
    mcs_scenario_destroy(&scn);
    /* the same keyword part as a stage-2-only part (stage2.fe): its deck is still found
     * relative to the file that names it once merged into fe: */
    char y2[2048];
    const char *fe_at = strstr(y, "fe:\n  parts:\n");
    snprintf(y2, sizeof y2,
             "%.*sstage2:\n  prescribed: [{body: base}]\n  fe:\n    parts:\n"
             "      - {name: cube, mesh: {keyword: spring_mass.k, part: 1, units: mm-s-t},\n"
             "         attach: {body: base, where: surface}}\n",
             fe_at ? (int)(fe_at - y) : 0, y);
    mcs_scenario *c2 = NULL;
    err = (mcs_error){0};
    scn = load("tests/data/keyword/kw_attach2.yaml", y2, &err);
    CHECK(scn && s2_scenario_compile(scn, &c2, &err) == MCS_OK);
    q = (fe_problem){0};
    CHECK(c2 && fe_scn_build(c2, &q, &err) == MCS_OK);
    if (!q.model) fprintf(stderr, "%s\n", err.msg);
    CHECK(q.natt == 4);
    fe_problem_free(&q);
    mcs_scenario_destroy(&c2);
    mcs_scenario_destroy(&scn);
}

/* ---- a body pressed into a pad ---- */

/* A pad 15 mm thick over a +-30 mm patch of a sphere of radius 20 m (nearly flat: the outer face
 * is (1 + t/R)^2 = 1.0015 times the inner) on `base`, attached by its inner face, and `press`,
 * a flat ellipsoid (0.05 x 2 x 2 m: its face bows 6 um over the pad) 0.1 mm off the pad and
 * pushed into it, both prescribed: its speed rises as (1 - cos(pi t / 2 ms)) / 2 to V = 1.5 m/s
 * (a step would ring the pad's outer face on the foam at ~1 kHz, +-2 %), then stays. The foam (the
 * concept model's leg protector curves) is loaded at the engineering strain rate V / t = 100/s, the
 * rate of its middle curve, without lateral strain (Poisson 0), so the press force is S_100(e) A
 * with e the outer face's mean travel over t and A the pad's mean section (fe_foam.c: nominal
 * stress). The bulk viscosity is off here: its default (q1 1.5, q2 0.06) adds rho l (q1^2 l |de/dt|
 * + q2 c) |de/dt|, ~1.5 % of the plateau at this rate (measured: +1.2 to +1.7 %). */
#define PRESS_V 1.5
#define PRESS_RAMP 2e-3 /* [s] */
#define PAD_T 0.015
static const char *press_yaml =
    "mcrash: 1\nname: press\n"
    "simulation: {end_time: 7 ms, time_step: 10 us, output_rate: 10 kHz}\n"
    "environment: {gravity: 0}\n"
    "bodies:\n"
    "  - {name: base, mass: 100, inertia: [1, 1, 1], position: [0, 0, 0], velocity: [0, 0, 0],\n"
    "     surfaces: [{name: dome, type: ellipsoid, center: [-20, 0, 0], semi_axes: [20, 20, "
    "20]}]}\n"
    "  - {name: press, mass: 100, inertia: [1, 1, 1], position: [0.0651, 0, 0],\n"
    "     velocity: [0, 0, 0],\n"
    "     surfaces: [{name: face, type: ellipsoid, center: [0, 0, 0], semi_axes: [0.05, 2, 2]}]}\n"
    "fe:\n"
    "  parts:\n"
    "    - name: pad\n"
    "      mesh: {generate: foam_pad, body: base, surface: dome, thickness: 15 mm,\n"
    "             element_size: 20 mm, longitude: [-0.0015, 0.0015], latitude: [-0.0015, 0.0015]}\n"
    "      section: {type: solid}\n"
    "      material:\n"
    "        model: foam\n"
    "        density: 425 kg/m^3\n"
    "        youngs_modulus: 20 MPa\n"
    "        curves:\n"
    "          - {rate: 1, points: [[0.05, 0.15 MPa], [0.5, 0.3 MPa], [0.7, 0.8 MPa], [0.85, 4 "
    "MPa]]}\n"
    "          - {rate: 100, points: [[0.05, 0.6 MPa], [0.5, 1.0 MPa], [0.7, 2.0 MPa], [0.85, 8 "
    "MPa]]}\n"
    "          - {rate: 1000, points: [[0.05, 0.9 MPa], [0.5, 1.4 MPa], [0.7, 2.8 MPa], [0.85, 11 "
    "MPa]]}\n"
    "        hysteresis: 0.2\n"
    "      attach: {body: base, where: surface}\n"
    "  contacts: [{type: bodies, parts: [pad], bodies: [press]}]\n"
    "  bulk_q1: 0\n  bulk_q2: 0\n";

/* S_100(e): the 100/s curve above, piecewise linear from (0, 0) [Pa] */
static double s100(double e)
{
    static const double tab[][2] = {{0, 0}, {0.05, 0.6e6}, {0.5, 1.0e6}, {0.7, 2.0e6}, {0.85, 8e6}};
    for (int i = 1; i < 5; i++)
        if (e <= tab[i][0] || i == 4)
            return tab[i - 1][1] +
                   (tab[i][1] - tab[i - 1][1]) * (e - tab[i - 1][0]) / (tab[i][0] - tab[i - 1][0]);
    return 0;
}

static int press_motion(void *ctx, int body, double t, double pos[3], double quat[4], double vel[3],
                        double omega[3])
{
    const double *x0 = ctx; /* the bodies' initial x */
    double v = 0, d = 0;    /* the press: speed up smoothly over PRESS_RAMP, then V */
    if (body == 1 && t < PRESS_RAMP) {
        v = -0.5 * PRESS_V * (1 - cos(M_PI * t / PRESS_RAMP));
        d = -0.5 * PRESS_V * (t - PRESS_RAMP / M_PI * sin(M_PI * t / PRESS_RAMP));
    } else if (body == 1) {
        v = -PRESS_V;
        d = -0.5 * PRESS_V * PRESS_RAMP - PRESS_V * (t - PRESS_RAMP);
    }
    pos[0] = x0[body] + d, pos[1] = pos[2] = 0;
    quat[0] = 1, quat[1] = quat[2] = quat[3] = 0;
    vel[0] = v, vel[1] = vel[2] = 0;
    omega[0] = omega[1] = omega[2] = 0;
    return 0;
}

static void test_press_pad(void)
{
    mb_model *m = mt_model_text("press.yaml", press_yaml, NULL);
    CHECK(m != NULL);
    if (!m) return;
    static double x0[2] = {0, 0.0651};
    mcs_error err = {0};
    CHECK(mb_model_body(m, "base") == 0 && mb_model_body(m, "press") == 1);
    CHECK(mb_model_prescribe(m, 0, press_motion, x0, &err) == MCS_OK);
    CHECK(mb_model_prescribe(m, 1, press_motion, x0, &err) == MCS_OK);
    mb_state *s = NULL;
    mcs_status st = mb_state_create(m, &s, &err);
    const fe_model *fm = m->couple->fe.model;
    /* the outer face: the nodes not carried by the base (the pad's inner face is attached) */
    int nouter = fm->nnode - m->couple->natt;
    double a_in = 0.06 * 0.06, a_mean = a_in * (1 + PAD_T / 20) * (1 + PAD_T / 20);
    a_mean = 0.5 * (a_in + a_mean); /* the mean of the inner and outer face [m^2] */
    double worst = 0, e_worst = 0;
    int nsample = 0;
    while (!st && s->step < m->nsteps) {
        st = mb_step(m, s, &err);
        const fe_state *fs = s->couple->fe;
        double u = 0;
        for (int n = 0; n < fm->nnode; n++)
            if (fm->node_x0[3 * n] > 0.01) u += fm->node_x0[3 * n] - fs->node_x[3 * n];
        /* the pad's push on the press (+x): its ellipsoid's force, the only one in contact */
        double e = u / nouter / PAD_T, fc = 0;
        for (int k = 0; k < fm->contact->nell; k++)
            fc += fs->contact->ell_force[3 * k];
        /* past the speed ramp (e 0.1 at 2 ms) and before the curve's kink at 0.5: there its
         * slope grows 0.9 -> 5 MPa, the contact's penetration with it, the face lags the
         * press and the rate falls to ~91/s (S 2 % below S_100) */
        if (e < 0.2 || e > 0.5) continue;
        double ref = s100(e) * a_mean, rel = fabs(fc / ref - 1);
        nsample++;
        if (rel > worst) worst = rel, e_worst = e;
    }
    CHECK(st == MCS_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    printf("press: %d outer nodes, %d samples at strain 0.2..0.5, max |F / (S_100(e) A) - 1| = "
           "%.4f (at e = %.3f)\n",
           nouter, nsample, worst, e_worst);
    CHECK(nsample > 250);
    FIG("s2.pad_press_err_pct", "%.1f", 100 * worst);
    CHECK(worst < 0.01); /* 0.5 % stated */
    mb_state_destroy(&s);
    mb_model_destroy(&m);
}

int main(void)
{
    RUN(test_merge);
    RUN(test_merge_errors);
    RUN(test_pad_sphere);
    RUN(test_pad_ellipsoid);
    RUN(test_pad_facet);
    RUN(test_attach_surface);
    RUN(test_press_pad);
    TEST_END();
}

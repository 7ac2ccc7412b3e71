/* fe_membrane: 3-node membrane (constant-strain triangle, no bending), total Lagrangian.
 *
 * Each triangle keeps its reference (t = 0) geometry in a 2-D frame of its own plane whose
 * first axis is the fibre direction a (fabric_direction projected on the element; without
 * one, the first side). With the constant shape-function gradients (b_k, c_k) of that frame,
 * the deformation gradient maps the reference plane into 3-D space:
 *   F = [F1 F2],  F1 = sum_k x_k b_k,  F2 = sum_k x_k c_k           (3 x 2)
 *   Green strain E11 = (F1.F1 - 1)/2, E22 = (F2.F2 - 1)/2, E12 = F1.F2 / 2
 * so any rigid rotation leaves E (and the stress) unchanged: large rotations are exact,
 * with no co-rotational frame to update. Stress: the second Piola-Kirchhoff S of the fabric
 * (fe_fabric.c, no compressive stress). Resisting nodal forces are the gradient of the
 * strain energy A0 t W(E) (Bonet & Wood, Nonlinear Continuum Mechanics for FE Analysis,
 * 2nd ed. 2008, §9.4):
 *   f_k = A0 t [ S11 F1 b_k + S22 F2 c_k + S12 (F1 c_k + F2 b_k) ]
 * Damping (fabric_damping = z): a viscous stress beta dS_e/dt, beta = z L / c (z of
 * critical at the element's top frequency 2c/L), dissipated energy in `dissipated`.
 * Energies: the stress power is summed with the trapezoidal rule between E(t_n-1) and E(t_n)
 * (E(t_n-1) from x(t_n) - dt v(t_n-1/2), which is exact), as the other elements do.
 * shell_sig of the element's first point holds S (elastic + viscous) in the fibre frame.
 * Quads of a membrane part are split into two triangles when they are added (fe_builder.c).
 * Stable step: smallest reference altitude over c times the largest stretch. */
#include "fe/fe_elem.h"
#include "fe/fe_membrane.h"

#include <math.h>
#include <string.h>

int fe_membrane_reference(const double X[3][3], const double fibre[3], fe_membrane_ref *r)
{
    double s1[3], s2[3], n[3], g1[3], g2[3];
    for (int i = 0; i < 3; i++) {
        s1[i] = X[1][i] - X[0][i];
        s2[i] = X[2][i] - X[0][i];
    }
    fe_cross(s1, s2, n);
    double nn = sqrt(fe_dot(n, n));
    memset(r, 0, sizeof *r);
    if (!(nn > 0)) return 0;
    for (int i = 0; i < 3; i++)
        n[i] /= nn;
    /* first axis: the fibre projected on the plane, else side 1 */
    double fa = fibre ? fe_dot(fibre, n) : 0, fl = 0;
    if (fibre) {
        for (int i = 0; i < 3; i++)
            g1[i] = fibre[i] - fa * n[i];
        fl = sqrt(fe_dot(g1, g1));
    }
    if (!(fl > 1e-6 * (fibre ? sqrt(fe_dot(fibre, fibre)) : 0))) {
        memcpy(g1, s1, sizeof g1);
        fl = sqrt(fe_dot(g1, g1));
    }
    for (int i = 0; i < 3; i++)
        g1[i] /= fl;
    fe_cross(n, g1, g2);
    double x[3], y[3], lmax = 0;
    for (int k = 0; k < 3; k++) {
        double d[3] = {X[k][0] - X[0][0], X[k][1] - X[0][1], X[k][2] - X[0][2]};
        x[k] = fe_dot(d, g1);
        y[k] = fe_dot(d, g2);
        const double *p = X[k], *q = X[(k + 1) % 3];
        double e[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        lmax = fmax(lmax, fe_dot(e, e));
    }
    double a2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if (!(a2 > 0)) return 0;
    for (int k = 0; k < 3; k++) {
        int j = (k + 1) % 3, l = (k + 2) % 3;
        r->b[k] = (y[j] - y[l]) / a2;
        r->c[k] = (x[l] - x[j]) / a2;
    }
    r->area = 0.5 * a2;
    r->length = a2 / sqrt(lmax);
    return 1;
}

/* F1, F2 of the triangle at positions xe and its Green strain (tensor xx, yy, xy) */
static void green(const fe_membrane_ref *r, const double xe[3][3], double F1[3], double F2[3],
                  double e[3])
{
    for (int i = 0; i < 3; i++) {
        F1[i] = r->b[0] * xe[0][i] + r->b[1] * xe[1][i] + r->b[2] * xe[2][i];
        F2[i] = r->c[0] * xe[0][i] + r->c[1] * xe[1][i] + r->c[2] * xe[2][i];
    }
    e[0] = 0.5 * (fe_dot(F1, F1) - 1);
    e[1] = 0.5 * (fe_dot(F2, F2) - 1);
    e[2] = 0.5 * fe_dot(F1, F2);
}

void fe_membrane_references(fe_model *m)
{
    for (int ip = 0; ip < m->npart && m->nshell_mref; ip++) {
        const fe_part *p = &m->part[ip];
        if (p->section.type != FE_SECTION_MEMBRANE) continue;
        const double *dir = p->material.fabric_direction;
        const int has_dir = fe_dot(dir, dir) > 0;
        for (int e = p->elem_begin; e < p->elem_end; e++) {
            const int *c = m->shell_node + 4 * e;
            double X[3][3];
            for (int k = 0; k < 3; k++)
                for (int i = 0; i < 3; i++)
                    X[k][i] = m->node_x0[3 * c[k] + i];
            fe_membrane_ref r;
            fe_membrane_reference(X, has_dir ? dir : NULL, &r); /* degenerate: area 0 */
            double *q = m->shell_mref + 8 * (size_t)e;
            memcpy(q, r.b, sizeof r.b), memcpy(q + 3, r.c, sizeof r.c);
            q[6] = r.area, q[7] = r.length;
        }
    }
}

void fe_membrane_part(const fe_model *m, fe_state *s, int ip)
{
    const fe_part *p = &m->part[ip];
    const double dt = s->dt_prev, c0 = p->wave_speed;
    const double zeta = p->material.fabric_damping;
    const int stride = m->nip_max;
    fe_fabric_c fc;
    fe_fabric_constants(&p->material, &fc);
    double e_int = 0, e_diss = 0, dtmin = INFINITY;
    int dtel = -1, bad = -1;
    for (int e = p->elem_begin; e < p->elem_end; e++) {
        const int *c = m->shell_node + 4 * e;
        double xe[3][3], xo[3][3];
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++) {
                xe[k][i] = s->node_x[3 * c[k] + i];
                xo[k][i] = xe[k][i] - dt * s->node_v[3 * c[k] + i];
            }
        double *f = s->slot_f + 3 * ((size_t)m->slot_base[FE_KIND_SHELL] + 4 * (size_t)e);
        double *sg = s->shell_sig + 3 * (size_t)stride * e;
        fe_membrane_ref r; /* the t = 0 geometry, kept in the model */
        const double *q = m->shell_mref + 8 * (size_t)e;
        memcpy(r.b, q, sizeof r.b), memcpy(r.c, q + 3, sizeof r.c);
        r.area = q[6], r.length = q[7];
        if (!(r.area > 0)) {
            if (bad < 0) bad = e;
            memset(f, 0, 12 * sizeof(double));
            continue;
        }
        double F1[3], F2[3], Fo1[3], Fo2[3], E[3], Eo[3], S[3], So[3];
        green(&r, xe, F1, F2, E);
        green(&r, xo, Fo1, Fo2, Eo);
        fe_fabric_stress(&fc, E, S);
        fe_fabric_stress(&fc, Eo, So);
        /* viscous part: beta dS_e/dt; the old one is what was stored minus the old elastic */
        const double beta = zeta * r.length / c0;
        double dE[3] = {E[0] - Eo[0], E[1] - Eo[1], 2 * (E[2] - Eo[2])}, w_el = 0, w_v = 0;
        for (int i = 0; i < 3; i++) {
            double sv = dt > 0 && beta > 0 ? beta * (S[i] - So[i]) / dt : 0;
            double svo = sg[i] - So[i];
            w_el += 0.5 * (So[i] + S[i]) * dE[i];
            w_v += 0.5 * (svo + sv) * dE[i];
            S[i] += sv;
            sg[i] = S[i];
        }
        const double vol = r.area * m->shell_t[e];
        e_int += vol * w_el;
        e_diss += vol * w_v;
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++)
                f[3 * k + i] = vol * (S[0] * F1[i] * r.b[k] + S[1] * F2[i] * r.c[k] +
                                      S[2] * (F1[i] * r.c[k] + F2[i] * r.b[k]));
        f[9] = f[10] = f[11] = 0;
        /* step: reference altitude over the speed, shortened by the largest stretch */
        double e1 = 0.5 * (E[0] + E[1]) + sqrt(0.25 * (E[0] - E[1]) * (E[0] - E[1]) + E[2] * E[2]);
        double dte = r.length / (c0 * sqrt(fmax(1.0, 1 + 2 * e1)));
        if (!isfinite(dte)) {
            if (bad < 0) bad = e;
        } else if (dte < dtmin) {
            dtmin = dte, dtel = e;
        }
    }
    double *pe = s->part_energy + FE_NENERGY * ip;
    pe[FE_E_internal] += e_int;
    pe[FE_E_dissipated] += e_diss;
    s->part_dt[ip] = dtmin;
    s->part_dt_elem[ip] = dtel;
    if (bad >= 0 && s->part_bad_elem[ip] < 0) s->part_bad_elem[ip] = bad;
}

/* fe_fabric: the fabric membrane material — linear elastic in the fibre frame (St. Venant-
 * Kirchhoff: second Piola-Kirchhoff stress S linear in the Green strain E, so large rotations
 * are exact) with no compressive stress (tension-field theory, wrinkling).
 *
 * Isotropic fabric (fabric_e2 = 0): the mixed principal-strain / principal-stress wrinkling
 * criterion of tension-field theory (Roddeman et al. 1987, J. Appl. Mech. 54:884-892; Kang & Im
 * 1997, J. Appl. Mech. 64:263-269). With principal strains e1 >= e2 and directions n1, n2:
 *   taut      e2 >= -nu e1 (both principal stresses >= 0):   S = Q : E
 *   slack     e1 <= 0:                                       S = 0
 *   wrinkled  otherwise: uniaxial tension along n1,          S = E e1 n1 n1
 * (the wrinkled energy E e1^2 / 2 is the relaxed strain energy; it joins the taut and slack
 * ones continuously, so the material stays hyperelastic and conserves energy).
 * Orthotropic fabric (fabric_e2 > 0, fibre a along fabric_direction, b normal to it in the
 * plane): the same theory through the relaxed energy (Pipkin 1986, IMA J. Appl. Math.
 * 36:85-99; Roddeman et al. 1987): taut while both principal stresses of S = Q : E are >= 0;
 * slack when E has no positive principal strain; otherwise wrinkles of normal m take up the
 * compression across them — the elastic strain is E + mu m m with mu >= 0 making m.S.m = 0 —
 * and their angle minimises the strain energy (a 36-point scan of [0, pi) refined by golden
 * section to 1e-10 rad); the stress is then uniaxial tension along the wrinkles. Being the
 * gradient of the relaxed energy, it conserves energy like the isotropic form.
 * Strains and stresses are (xx, yy, xy) tensor components in the fibre frame. */
#include "fe/fe_builder_impl.h"
#include "fe/fe_membrane.h"

#include <math.h>

void fe_fabric_constants(const fe_material_desc *mt, fe_fabric_c *c)
{
    const double E1 = mt->youngs_modulus, nu = mt->poisson;
    c->iso = !(mt->fabric_e2 > 0);
    c->E = E1;
    c->nu = nu;
    if (c->iso) {
        double q = E1 / (1 - nu * nu);
        c->q11 = c->q22 = q;
        c->q12 = nu * q;
        c->q66 = E1 / (2 * (1 + nu));
        return;
    }
    const double E2 = mt->fabric_e2, nu21 = nu * E2 / E1, d = 1 - nu * nu21;
    c->q11 = E1 / d;
    c->q22 = E2 / d;
    c->q12 = nu * E2 / d;
    c->q66 = mt->fabric_g12 > 0 ? mt->fabric_g12 : E1 / (2 * (1 + nu));
}

double fe_fabric_wave_speed(const fe_material_desc *mt)
{
    fe_fabric_c c;
    fe_fabric_constants(mt, &c);
    double q = fmax(fmax(c.q11, c.q22), c.q66);
    double z = mt->fabric_damping;
    /* stiffness-proportional damping at ratio z of the top frequency shrinks the central-
     * difference limit 2/w to (2/w)(sqrt(1 + z^2) - z) (Belytschko, Liu & Moran 2000, §6.3) */
    return sqrt(q / mt->density) / (sqrt(1 + z * z) - z);
}

/* principal values (a >= b) and the direction (cs, sn) of a of the symmetric 2x2 tensor t */
static void principal(const double t[3], double *a, double *b, double *cs, double *sn)
{
    double m = 0.5 * (t[0] + t[1]), h = 0.5 * (t[0] - t[1]), r = sqrt(h * h + t[2] * t[2]);
    *a = m + r;
    *b = m - r;
    /* the angle th = atan2(t12, h) / 2 in (-pi/2, pi/2] by the half-angle formulas of
     * cos 2th = h / r, sin 2th = t12 / r (no trigonometric calls: this runs twice per fabric
     * element and step); the larger of cos th, |sin th| from its square root, the other from
     * sin 2th = 2 sin th cos th, so neither loses digits */
    if (!(r > 0)) {
        *cs = 1, *sn = 0;
    } else if (h >= 0) {
        *cs = sqrt(0.5 * (1 + h / r));
        *sn = t[2] / (2 * r * *cs);
    } else {
        *sn = copysign(sqrt(0.5 * (1 - h / r)), t[2]);
        *cs = t[2] / (2 * r * *sn);
    }
}

/* S = Q : e (tensor components; the shear pairs with 2 e12) */
static void qmul(const fe_fabric_c *c, const double e[3], double s[3])
{
    s[0] = c->q11 * e[0] + c->q12 * e[1];
    s[1] = c->q12 * e[0] + c->q22 * e[1];
    s[2] = 2 * c->q66 * e[2];
}

static double taut_energy(const fe_fabric_c *c, const double e[3])
{
    double s[3];
    qmul(c, e, s);
    return 0.5 * (s[0] * e[0] + s[1] * e[1] + 2 * s[2] * e[2]);
}

/* wrinkles with normal m = (-sin th, cos th): the elastic strain e + mu m m with mu >= 0 taking
 * up the compression across them (m.S.m = 0), into ee; returns its energy */
static double wrinkled_at(const fe_fabric_c *c, const double e[3], double th, double ee[3])
{
    const double sn = sin(th), cs = cos(th), mm[3] = {sn * sn, cs * cs, -sn * cs};
    double se[3], sm[3];
    qmul(c, e, se);
    qmul(c, mm, sm);
    double a = se[0] * mm[0] + se[1] * mm[1] + 2 * se[2] * mm[2];
    double b = sm[0] * mm[0] + sm[1] * mm[1] + 2 * sm[2] * mm[2];
    double mu = a < 0 ? -a / b : 0;
    for (int i = 0; i < 3; i++) ee[i] = e[i] + mu * mm[i];
    return taut_energy(c, ee);
}

/* the relaxed (tension-field) strain: the wrinkle angle that minimises the energy, found on a
 * 36-point scan of [0, pi) refined by golden section; returns the angle of the tension n */
static double relax(const fe_fabric_c *c, const double e[3], double ee[3])
{
    enum { NSCAN = 36 };
    const double h = M_PI / NSCAN, g = 0.5 * (sqrt(5.0) - 1);
    int best = 0;
    double wbest = INFINITY;
    for (int k = 0; k < NSCAN; k++) {
        double w = wrinkled_at(c, e, k * h, ee);
        if (w < wbest) wbest = w, best = k;
    }
    double lo = (best - 1) * h, hi = (best + 1) * h;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = wrinkled_at(c, e, x1, ee), f2 = wrinkled_at(c, e, x2, ee);
    while (hi - lo > 1e-10) {
        if (f1 < f2) {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = wrinkled_at(c, e, x1, ee);
        } else {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = wrinkled_at(c, e, x2, ee);
        }
    }
    double th = 0.5 * (lo + hi);
    wrinkled_at(c, e, th, ee);
    return th;
}

int fe_fabric_stress(const fe_fabric_c *c, const double e[3], double s[3])
{
    double e1, e2, cs, sn;
    principal(e, &e1, &e2, &cs, &sn);
    if (e1 <= 0) { /* no direction is stretched */
        s[0] = s[1] = s[2] = 0;
        return FE_FABRIC_SLACK;
    }
    if (c->iso) {
        if (e2 < -c->nu * e1) {
            double f = c->E * e1;
            s[0] = f * cs * cs;
            s[1] = f * sn * sn;
            s[2] = f * cs * sn;
            return FE_FABRIC_WRINKLED;
        }
        qmul(c, e, s);
        return FE_FABRIC_TAUT;
    }
    qmul(c, e, s);
    double s1, s2;
    principal(s, &s1, &s2, &cs, &sn);
    if (s2 >= 0) return FE_FABRIC_TAUT;
    /* wrinkled: uniaxial tension along n from the relaxed strain */
    double ee[3], st[3];
    double th = relax(c, e, ee);
    qmul(c, ee, st);
    cs = cos(th), sn = sin(th);
    double f = fmax(0.0, st[0] * cs * cs + st[1] * sn * sn + 2 * st[2] * cs * sn);
    s[0] = f * cs * cs;
    s[1] = f * sn * sn;
    s[2] = f * cs * sn;
    return FE_FABRIC_WRINKLED;
}

double fe_fabric_energy(const fe_fabric_c *c, const double e[3])
{
    double e1, e2, cs, sn, s[3], ee[3];
    principal(e, &e1, &e2, &cs, &sn);
    if (e1 <= 0) return 0;
    if (c->iso && e2 < -c->nu * e1) return 0.5 * c->E * e1 * e1;
    qmul(c, e, s);
    double s1, s2;
    principal(s, &s1, &s2, &cs, &sn);
    if (c->iso || s2 >= 0) return taut_energy(c, e);
    relax(c, e, ee);
    return taut_energy(c, ee);
}

mcs_status fe_fabric_check(const fe_part_desc *d, mcs_error *err)
{
    const fe_material_desc *m = &d->material;
    const char *n = d->name;
    if (!(m->fabric_e2 >= 0) || !(m->fabric_g12 >= 0) || !isfinite(m->fabric_e2 + m->fabric_g12))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': material.youngs_modulus_b and shear_modulus must be >= 0",
                       n);
    if (m->fabric_e2 > 0 && !(m->poisson * m->poisson * m->fabric_e2 < m->youngs_modulus))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: part '%s': material: poisson^2 E_b < E_a is needed for a positive "
                       "definite fabric",
                       n);
    if (!(m->fabric_damping >= 0 && m->fabric_damping <= 1))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': material.damping must be in [0, 1]", n);
    for (int i = 0; i < 3; i++)
        if (!isfinite(m->fabric_direction[i]))
            return MCS_ERR(err, MCS_ERR_RANGE, "fe: part '%s': material.direction is not finite",
                           n);
    return MCS_OK;
}

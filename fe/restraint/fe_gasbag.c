/* fe_gasbag: uniform-pressure gas bag — model, orifice flow and the per-FE-step update.
 *
 * Why an explicit per-step update and not CVODE inside the FE loop: the FE step of an airbag
 * fabric is about 1 us (membrane wave speed over a 5-10 mm element), three to four orders
 * below the gas time scales (inflation 10-30 ms, venting 10-100 ms). A second-order explicit
 * update of two scalars is then accurate to ~1e-8 per ms and costs a few hundred flops per
 * step, while a CVODE call per step would rebuild its history each time (the volume, driven
 * by the membrane, is only known one step ahead). The volume change is integrated exactly
 * (isentropic, U V^(gamma-1) constant, the paper's Eq. 6 for a closed chamber) so that a
 * closed bag conserves p V^gamma to rounding; inflow and outflow are Heun steps, sub-cycled
 * when a step is not small against the bag's mass turnover time. CVODE is used where an
 * integrator with error control is the right tool: the reference solution for a volume
 * known as a function of time (fe_gasbag_cvode.c), which the tests compare with. */
#include "fe/fe_gasbag.h"
#include "fe/restraint/fe_gasbag_impl.h"
#include "fe/fe_surface_volume.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FE_GASBAG_SUB_MAX 4096  /* most sub-steps per half step before giving up */
#define FE_GASBAG_SUB_FRAC 0.02 /* sub-step as a fraction of the mass turnover time */

fe_gasbag_desc fe_gasbag_desc_default(void)
{
    fe_gasbag_desc d;
    memset(&d, 0, sizeof(d));
    d.gamma = 1.4;
    d.gas_constant = 287.05;
    d.leak_discharge_coefficient = 1.0;
    d.ambient_pressure = 101325.0;
    d.ambient_temperature = 293.15;
    return d;
}

#define FE_GASBAG_R_UNIVERSAL 8.314462618 /* J/(mol K), CODATA 2018 (exact since 2019 SI) */

/* gamma and R from whichever the description gives: cp and cv, or gamma with R or M */
static mcs_status resolve_gas(const char *name, const fe_gasbag_desc *d, double *g, double *R,
                              mcs_error *err)
{
    *g = d->gamma;
    *R = d->gas_constant;
    if (d->cp != 0.0 || d->cv != 0.0) {
        if (!(d->cp > d->cv && d->cv > 0.0 && isfinite(d->cp)) || d->molar_mass != 0.0)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%s: cp %g and cv %g J/(kg K) need cp > cv > 0 (and no molar_mass)",
                           name, d->cp, d->cv);
        *g = d->cp / d->cv;
        *R = d->cp - d->cv;
    } else if (d->molar_mass != 0.0) {
        if (!(d->molar_mass > 0.0 && isfinite(d->molar_mass)))
            return MCS_ERR(err, MCS_ERR_RANGE, "%s: molar_mass %g kg/mol must be > 0", name,
                           d->molar_mass);
        *R = FE_GASBAG_R_UNIVERSAL / d->molar_mass;
    }
    if (!(*g > 1.0 && *g < 2.0))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: gamma %g must lie in (1, 2)", name, *g);
    if (!(*R > 0.0 && isfinite(*R)))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: gas_constant %g J/(kg K) must be > 0", name, *R);
    return MCS_OK;
}

static mcs_status check_desc(const char *name, const fe_gasbag_desc *d, mcs_error *err)
{
    double g, R;
    mcs_status st = resolve_gas(name, d, &g, &R, err);
    if (st != MCS_OK) return st;
    if (!(d->ambient_pressure > 0.0 && d->ambient_temperature > 0.0))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: ambient pressure and temperature must be > 0",
                       name);
    if (!isfinite(d->fire_time))
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: fire_time is not finite", name);
    if (d->ninflator < 0 || d->ninflator > FE_GASBAG_TABLE_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: %d inflator points (0..%d)", name, d->ninflator,
                       FE_GASBAG_TABLE_MAX);
    for (int i = 0; i < d->ninflator; i++) {
        if (!(d->inflator_mass_flow[i] >= 0.0 && isfinite(d->inflator_mass_flow[i])))
            return MCS_ERR(err, MCS_ERR_RANGE, "%s: inflator mass flow point %d: %g kg/s < 0", name,
                           i, d->inflator_mass_flow[i]);
        if (!(d->inflator_temperature[i] > 0.0 && isfinite(d->inflator_temperature[i])))
            return MCS_ERR(err, MCS_ERR_RANGE, "%s: inflator temperature point %d: %g K <= 0", name,
                           i, d->inflator_temperature[i]);
    }
    if (d->nvent < 0 || d->nvent > FE_GASBAG_VENT_MAX)
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: %d vents (0..%d)", name, d->nvent,
                       FE_GASBAG_VENT_MAX);
    for (int i = 0; i < d->nvent; i++) {
        const fe_gasbag_vent *v = &d->vent[i];
        if (!(v->area >= 0.0 && v->discharge_coefficient > 0.0 && v->discharge_coefficient <= 1.0 &&
              v->open_pressure >= 0.0))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%s: vent %d: area %g m^2 >= 0, discharge coefficient %g in (0, 1], "
                           "open pressure %g Pa >= 0 required",
                           name, i, v->area, v->discharge_coefficient, v->open_pressure);
    }
    if (!(d->leak_area >= 0.0 && d->leak_porosity >= 0.0 && d->leak_porosity < 1.0 &&
          d->leak_discharge_coefficient > 0.0 && d->leak_discharge_coefficient <= 1.0))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: leakage: area >= 0, porosity in [0, 1), discharge coefficient in "
                       "(0, 1] required",
                       name);
    return MCS_OK;
}

mcs_status fe_gasbag_model_create(const char *name, const fe_gasbag_desc *d, fe_gasbag_model **out,
                                  mcs_error *err)
{
    *out = NULL;
    mcs_status st = check_desc(name, d, err);
    if (st != MCS_OK) return st;
    fe_gasbag_model *m = calloc(1, sizeof(*m));
    if (!m) return MCS_ERR(err, MCS_ERR_NOMEM, "%s: gas bag model", name);
    snprintf(m->name, sizeof(m->name), "%s", name);
    double g, R;
    resolve_gas(name, d, &g, &R, err); /* checked above */
    m->gamma = g;
    m->gas_constant = R;
    m->cv = R / (g - 1.0);
    m->cp = g * m->cv;
    m->fire_time = d->fire_time;
    m->nvent = d->nvent;
    memcpy(m->vent, d->vent, sizeof(m->vent));
    m->leak_area = d->leak_area;
    m->leak_porosity = d->leak_porosity;
    m->leak_cd = d->leak_discharge_coefficient;
    m->ambient_pressure = d->ambient_pressure;
    m->ambient_temperature = d->ambient_temperature;
    /* critical pressure ratio p_c / p0 = (2/(g+1))^(g/(g-1)) (e.g. Anderson, Modern Compressible
     * Flow, §5.4; 0.528 for g = 1.4) */
    m->crit_ratio = pow(2.0 / (g + 1.0), g / (g - 1.0));
    m->psi_choked = sqrt(g) * pow(2.0 / (g + 1.0), (g + 1.0) / (2.0 * (g - 1.0)));
    if (d->ninflator > 0) {
        char cname[96];
        snprintf(cname, sizeof(cname), "%s inflator mass flow", name);
        st = mcs_curve_create(cname, d->ninflator, d->inflator_time, d->inflator_mass_flow,
                              MCS_EXTRAP_CONSTANT, MCS_EXTRAP_CONSTANT, &m->mass_flow, err);
        if (st == MCS_OK) {
            snprintf(cname, sizeof(cname), "%s inflator temperature", name);
            st = mcs_curve_create(cname, d->ninflator, d->inflator_time, d->inflator_temperature,
                                  MCS_EXTRAP_CONSTANT, MCS_EXTRAP_CONSTANT, &m->temperature, err);
        }
        if (st != MCS_OK) {
            fe_gasbag_model_destroy(&m);
            return st;
        }
    }
    *out = m;
    return MCS_OK;
}

void fe_gasbag_model_destroy(fe_gasbag_model **p)
{
    if (!p || !*p) return;
    mcs_curve_destroy(&(*p)->mass_flow);
    mcs_curve_destroy(&(*p)->temperature);
    free(*p);
    *p = NULL;
}

double fe_gasbag_orifice_flow(const fe_gasbag_model *m, double cd_area, double p_up, double T_up,
                              double p_down)
{
    if (!(cd_area > 0.0) || !(p_up > p_down) || !(T_up > 0.0)) return 0.0;
    double g = m->gamma, r = p_down / p_up, psi;
    /* isentropic nozzle: m_dot = Cd A p0 / sqrt(R T0) psi(r); choked psi is constant */
    if (r <= m->crit_ratio)
        psi = m->psi_choked;
    else
        psi = sqrt(2.0 * g / (g - 1.0) * (pow(r, 2.0 / g) - pow(r, (g + 1.0) / g)));
    return cd_area * p_up / sqrt(m->gas_constant * T_up) * psi;
}

/* ---- the update ------------------------------------------------------------------------ */

/* gas and totals being advanced (a copy of the state's, committed on success) */
typedef struct {
    double tf; /* firing time of this state [s] */
    double mass, energy;
    double mass_in, energy_in, mass_vent, energy_vent, mass_leak, energy_leak;
} gb_work;

/* outflow rates at (mass, U, V): vent and leak mass flows [kg/s] */
void fe_gasbag_outflow_(const fe_gasbag_model *m, unsigned open, double area, double mass, double U,
                        double V, double *mv, double *ml)
{
    double T = U / (mass * m->cv), p = (m->gamma - 1.0) * U / V;
    double cda = 0.0;
    for (int i = 0; i < m->nvent; i++)
        if (open & (1u << i)) cda += m->vent[i].discharge_coefficient * m->vent[i].area;
    *mv = fe_gasbag_orifice_flow(m, cda, p, T, m->ambient_pressure);
    double la = m->leak_cd * (m->leak_area + m->leak_porosity * area);
    *ml = fe_gasbag_orifice_flow(m, la, p, T, m->ambient_pressure);
}

/* inflator mass flow [kg/s] and inflow temperature [K] at absolute time t */
void fe_gasbag_inflow_(const fe_gasbag_model *m, double tf, double t, double *mdot, double *Tin)
{
    *mdot = 0.0;
    *Tin = m->ambient_temperature;
    if (!m->mass_flow || t < tf) return;
    *mdot = mcs_curve_eval(m->mass_flow, t - tf);
    *Tin = mcs_curve_eval(m->temperature, t - tf);
}

/* inflator mass [kg] and enthalpy [J] over [a, b]: the mass exactly (integral of the
 * piecewise-linear table), the enthalpy by Simpson's rule (exact for linear m_dot and T) */
static void inflow_amounts(const fe_gasbag_model *m, double tf, double a, double b, double *dm,
                           double *dh)
{
    *dm = *dh = 0.0;
    if (!m->mass_flow || b <= tf) return;
    if (a < tf) a = tf;
    *dm = mcs_curve_integral(m->mass_flow, a - tf, b - tf);
    double q[3];
    for (int k = 0; k < 3; k++) {
        double md, T;
        fe_gasbag_inflow_(m, tf, a + 0.5 * k * (b - a), &md, &T);
        q[k] = md * m->cp * T;
    }
    *dh = (b - a) / 6.0 * (q[0] + 4.0 * q[1] + q[2]);
}

/* one Heun step of the exchange at fixed V over [t, t + h]; 0 ok, -1 mass or energy <= 0 */
static int heun(const fe_gasbag_model *m, unsigned open, double area, double V, double t, double h,
                gb_work *w)
{
    double dm_in, dh_in, mv0, ml0, mv1, ml1;
    inflow_amounts(m, w->tf, t, t + h, &dm_in, &dh_in);
    double T0 = w->energy / (w->mass * m->cv);
    fe_gasbag_outflow_(m, open, area, w->mass, w->energy, V, &mv0, &ml0);
    double m1 = w->mass + dm_in - h * (mv0 + ml0);
    double U1 = w->energy + dh_in - h * (mv0 + ml0) * m->cp * T0;
    if (!(m1 > 0.0 && U1 > 0.0)) return -1;
    double T1 = U1 / (m1 * m->cv);
    fe_gasbag_outflow_(m, open, area, m1, U1, V, &mv1, &ml1);
    double dmv = 0.5 * h * (mv0 + mv1), dml = 0.5 * h * (ml0 + ml1);
    double dev = 0.5 * h * m->cp * (mv0 * T0 + mv1 * T1);
    double del = 0.5 * h * m->cp * (ml0 * T0 + ml1 * T1);
    double mn = w->mass + dm_in - dmv - dml, Un = w->energy + dh_in - dev - del;
    if (!(mn > 0.0 && Un > 0.0)) return -1;
    w->mass = mn;
    w->energy = Un;
    w->mass_in += dm_in, w->energy_in += dh_in;
    w->mass_vent += dmv, w->energy_vent += dev;
    w->mass_leak += dml, w->energy_leak += del;
    return 0;
}

/* sub-steps for an exchange of length h: a fraction of the mass turnover time m / |m_dot| */
static int substeps(const fe_gasbag_model *m, unsigned open, double area, double V, double t,
                    double h, const gb_work *w)
{
    double md0, md1, T, mv, ml;
    fe_gasbag_inflow_(m, w->tf, t, &md0, &T);
    fe_gasbag_inflow_(m, w->tf, t + h, &md1, &T);
    fe_gasbag_outflow_(m, open, area, w->mass, w->energy, V, &mv, &ml);
    /* inflow enters exactly; it sets the scale through the mass it brings within h */
    double mdi = fmax(md0, md1), rate = (mdi + mv + ml) / (w->mass + mdi * h); /* 1/s */
    double n = ceil(h * rate / FE_GASBAG_SUB_FRAC);
    return n < 1.0 ? 1 : n > FE_GASBAG_SUB_MAX ? FE_GASBAG_SUB_MAX : (int)n;
}

/* exchange over [t, t + h] at fixed V, sub-cycled; retried with more sub-steps on failure */
static int exchange(const fe_gasbag_model *m, unsigned *open, double area, double V, double t,
                    double h, gb_work *w, int *nsub)
{
    if (h <= 0.0) return 0;
    for (int n = substeps(m, *open, area, V, t, h, w); n <= FE_GASBAG_SUB_MAX; n *= 4) {
        gb_work trial = *w;
        unsigned op = *open;
        int ok = 1;
        for (int j = 0; j < n && ok; j++) {
            /* vents open at the sub-step where the pressure reaches their opening pressure */
            op = fe_gasbag_latch_vents_(m, op, (m->gamma - 1.0) * trial.energy / V);
            ok = heun(m, op, area, V, t + h * j / n, h / n, &trial) == 0;
        }
        if (ok) {
            *w = trial;
            *open = op;
            *nsub += n;
            return 0;
        }
    }
    return -1;
}

unsigned fe_gasbag_latch_vents_(const fe_gasbag_model *m, unsigned open, double p)
{
    for (int i = 0; i < m->nvent; i++)
        if (p - m->ambient_pressure >= m->vent[i].open_pressure) open |= 1u << i;
    return open;
}

mcs_status fe_gasbag_state_init_gas(const fe_gasbag_model *m, fe_gasbag_state *s, double t,
                                    double volume, double area, double pressure, double temperature,
                                    mcs_error *err)
{
    if (!(volume > 0.0 && isfinite(volume)) || !(area >= 0.0 && isfinite(area)) || !isfinite(t))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: initial volume %g m^3 must be > 0 and area %g m^2 >= 0 (is the "
                       "surface oriented outward?)",
                       m->name, volume, area);
    if (!(pressure > 0.0 && isfinite(pressure) && temperature > 0.0 && isfinite(temperature)))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "%s: initial pressure %g Pa and temperature %g K "
                       "must be > 0",
                       m->name, pressure, temperature);
    memset(s, 0, sizeof(*s));
    s->time = t;
    s->volume = volume;
    s->area = area;
    s->temperature = temperature;
    s->pressure = pressure;
    s->mass = pressure * volume / (m->gas_constant * temperature);
    s->energy = s->mass * m->cv * temperature;
    s->mass0 = s->mass;
    s->energy0 = s->energy;
    s->fire_time = m->fire_time;
    s->vent_open = fe_gasbag_latch_vents_(m, 0, s->pressure);
    fe_gasbag_outflow_(m, s->vent_open, area, s->mass, s->energy, volume, &s->mass_flow_vent,
                       &s->mass_flow_leak);
    double Tin;
    fe_gasbag_inflow_(m, s->fire_time, t, &s->mass_flow_in, &Tin);
    return MCS_OK;
}

mcs_status fe_gasbag_state_init(const fe_gasbag_model *m, fe_gasbag_state *s, double t,
                                double volume, double area, mcs_error *err)
{
    return fe_gasbag_state_init_gas(m, s, t, volume, area, m->ambient_pressure,
                                    m->ambient_temperature, err);
}

mcs_status fe_gasbag_advance(const fe_gasbag_model *m, fe_gasbag_state *s, double dt, double volume,
                             double area, mcs_error *err)
{
    if (!(dt >= 0.0 && isfinite(dt)) || !(volume > 0.0 && isfinite(volume)) ||
        !(area >= 0.0 && isfinite(area)))
        return MCS_ERR(err, MCS_ERR_NUMERIC,
                       "%s: at t = %.9g s: step %g s, volume %g m^3, area %g m^2 (volume must "
                       "stay > 0)",
                       m->name, s->time, dt, volume, area);
    gb_work w = {s->fire_time, s->mass,      s->energy,      s->mass_in,  s->energy_in,
                 s->mass_vent, s->energy_vent, s->mass_leak, s->energy_leak};
    unsigned open = fe_gasbag_latch_vents_(m, s->vent_open, s->pressure);
    int nsub = 0;
    /* half the exchange at the old volume */
    if (exchange(m, &open, s->area, s->volume, s->time, 0.5 * dt, &w, &nsub) != 0) goto fail;
    /* isentropic volume change: U V^(gamma-1) constant; the gas does the work lost by U */
    double U_before = w.energy;
    w.energy *= pow(s->volume / volume, m->gamma - 1.0);
    double work = U_before - w.energy;
    open = fe_gasbag_latch_vents_(m, open, (m->gamma - 1.0) * w.energy / volume);
    /* the other half at the new volume */
    if (exchange(m, &open, area, volume, s->time + 0.5 * dt, 0.5 * dt, &w, &nsub) != 0) goto fail;
    if (!(isfinite(w.energy) && w.energy > 0.0 && w.mass > 0.0)) goto fail;
    s->time += dt;
    s->volume = volume;
    s->area = area;
    s->mass = w.mass;
    s->energy = w.energy;
    s->mass_in = w.mass_in, s->energy_in = w.energy_in;
    s->mass_vent = w.mass_vent, s->energy_vent = w.energy_vent;
    s->mass_leak = w.mass_leak, s->energy_leak = w.energy_leak;
    s->work += work;
    s->temperature = w.energy / (w.mass * m->cv);
    s->pressure = (m->gamma - 1.0) * w.energy / volume;
    s->vent_open = fe_gasbag_latch_vents_(m, open, s->pressure);
    s->nsub = nsub;
    double Tin;
    fe_gasbag_inflow_(m, s->fire_time, s->time, &s->mass_flow_in, &Tin);
    fe_gasbag_outflow_(m, s->vent_open, area, s->mass, s->energy, volume, &s->mass_flow_vent,
                       &s->mass_flow_leak);
    return MCS_OK;
fail:
    return MCS_ERR(err, MCS_ERR_NUMERIC,
                   "%s: at t = %.9g s the gas mass or energy would become <= 0 over a step of "
                   "%g s (volume %g -> %g m^3)",
                   m->name, s->time, dt, s->volume, volume);
}

mcs_status fe_gasbag_step_surface(const fe_gasbag_model *m, fe_gasbag_state *s, int nface,
                                  const int *face_node, const double *x, double dt, double *f,
                                  mcs_error *err)
{
    double V = fe_surface_volume(nface, face_node, x);
    double A = m->leak_porosity > 0.0 ? fe_surface_area(nface, face_node, x) : s->area;
    if (dt > 0.0 || V != s->volume) {
        mcs_status st = fe_gasbag_advance(m, s, dt, V, A, err);
        if (st != MCS_OK) return st;
    }
    fe_surface_pressure_forces(nface, face_node, x, fe_gasbag_gauge_pressure(m, s), f);
    return MCS_OK;
}

double fe_gasbag_gauge_pressure(const fe_gasbag_model *m, const fe_gasbag_state *s)
{
    return s->pressure - m->ambient_pressure;
}

const char *const fe_gasbag_channel_name[FE_GASBAG_NCHANNEL] = {
#define FE_GASBAG_X_NAME(name, unit, what) #name,
    FE_GASBAG_STATE_FIELDS(FE_GASBAG_X_NAME)
#undef FE_GASBAG_X_NAME
};

const char *const fe_gasbag_channel_unit[FE_GASBAG_NCHANNEL] = {
#define FE_GASBAG_X_UNIT(name, unit, what) unit,
    FE_GASBAG_STATE_FIELDS(FE_GASBAG_X_UNIT)
#undef FE_GASBAG_X_UNIT
};

double fe_gasbag_channel(const fe_gasbag_state *s, int channel)
{
    switch (channel) {
#define FE_GASBAG_X_CASE(name, unit, what)                                                         \
    case FE_GASBAG_CH_##name:                                                                      \
        return s->name;
        FE_GASBAG_STATE_FIELDS(FE_GASBAG_X_CASE)
#undef FE_GASBAG_X_CASE
    }
    return NAN;
}

double fe_gasbag_energy_residual(const fe_gasbag_state *s)
{
    return s->energy - s->energy0 - (s->energy_in - s->energy_vent - s->energy_leak - s->work);
}

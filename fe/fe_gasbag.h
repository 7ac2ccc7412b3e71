/* fe_gasbag: the uniform-pressure gas bag (control volume) of the 2023 paper, §2.3.2, Eq. 4-6.
 *
 * One ideal gas (gamma = cp/cv, specific gas constant R) at uniform pressure p and temperature
 * T fills the volume V enclosed by the bag's membrane surface; the walls are adiabatic. Mass
 * and energy balances (paper Eq. 4: m_dot_tot = m_dot_in + m_dot_exhaust + m_dot_leakage):
 *   dm/dt = m_dot_in(t) - m_dot_vent - m_dot_leak
 *   dU/dt = m_dot_in cp T_in(t) - (m_dot_vent + m_dot_leak) cp T - p dV/dt,  U = m cv T
 *   p = (gamma - 1) rho e = m R T / V                                      (paper Eq. 5)
 * Vents and fabric leakage are isentropic orifices with a discharge coefficient, choked when
 * p / p_amb >= ((gamma + 1)/2)^(gamma/(gamma - 1)); no backflow (flow is 0 when p <= p_amb).
 *
 * The kernel calls fe_gasbag_advance once per FE step with the new enclosed volume (from
 * fe_surface_volume) and applies the gauge pressure p - p_amb to the fabric as
 * f = (p - p_amb) dV/dx (fe_surface_pressure_forces). Nothing here allocates after
 * fe_gasbag_model_create. fe_gasbag_integrate_cvode is the CVODE reference for a volume
 * given as a function of time (verification, and stand-alone bags with a prescribed volume).
 * See docs/gasbag.md for the scheme and why the per-step update is explicit. */
#ifndef FE_GASBAG_H
#define FE_GASBAG_H

#include "core/mcs_curve.h"
#include "core/mcs_error.h"

#define FE_GASBAG_VENT_MAX 8   /* most vents (exhaust holes) per bag  */
#define FE_GASBAG_TABLE_MAX 64 /* most points in an inflator table     */

typedef struct {
    double area;                  /* orifice area [m^2]                                     */
    double discharge_coefficient; /* C_d, effective / geometric area (0, 1] [-]             */
    double open_pressure;         /* gauge pressure that opens the vent (latched); 0 = open
                                     from the start [Pa]                                     */
} fe_gasbag_vent;

/* what a bag is (the scenario keys map one to one) */
typedef struct {
    double gamma;        /* cp / cv of the gas [-] (1.4)                           */
    double gas_constant; /* specific gas constant R = R_u / M [J/(kg K)] (287.05)  */
    double molar_mass;   /* if > 0: R = R_u / molar_mass, overriding gas_constant [kg/mol] */
    double cp, cv;       /* if both > 0: gamma = cp/cv and R = cp - cv (Mayer), overriding
                            gamma and gas_constant [J/(kg K)]                      */
    double fire_time;    /* inflator firing time [s] (0); the state's copy is the one used */
    int ninflator;       /* points in the inflator tables (>= 1; 0 = no inflator)  */
    double inflator_time[FE_GASBAG_TABLE_MAX];        /* time since firing [s] (ninflator)     */
    double inflator_mass_flow[FE_GASBAG_TABLE_MAX];   /* mass flow into the bag [kg/s]         */
    double inflator_temperature[FE_GASBAG_TABLE_MAX]; /* gas temperature at inflow [K]       */
    int nvent; /* vents in use [-]                                       */
    fe_gasbag_vent vent[FE_GASBAG_VENT_MAX];
    double leak_area;                  /* fabric and seam leakage, effective area [m^2] (0)      */
    double leak_porosity;              /* leakage area per fabric area (scales with the current
                                          surface area) [-] (0)                                  */
    double leak_discharge_coefficient; /* C_d of the leakage [-] (1)                         */
    double ambient_pressure;           /* [Pa] (101325)                                          */
    double ambient_temperature;        /* also the initial gas temperature [K] (293.15)          */
} fe_gasbag_desc;

fe_gasbag_desc fe_gasbag_desc_default(void);

/* the immutable, validated bag */
typedef struct {
    char name[64];          /* used in messages                                       */
    double gamma;           /* [-]                                                    */
    double gas_constant;    /* R [J/(kg K)]                                           */
    double cv, cp;          /* specific heats R/(gamma-1), gamma R/(gamma-1) [J/(kg K)] */
    double fire_time;       /* [s]                                                    */
    mcs_curve *mass_flow;   /* inflator mass flow vs. time since firing [kg/s]; NULL none */
    mcs_curve *temperature; /* inflator gas temperature vs. time since firing [K]     */
    int nvent;              /* [-]                                                    */
    fe_gasbag_vent vent[FE_GASBAG_VENT_MAX];
    double leak_area;           /* [m^2]                                                  */
    double leak_porosity;       /* [-]                                                    */
    double leak_cd;             /* [-]                                                    */
    double ambient_pressure;    /* [Pa]                                                   */
    double ambient_temperature; /* [K]                                                    */
    double crit_ratio;          /* p_amb / p below which orifices choke [-]               */
    double psi_choked;          /* choked flow function sqrt(g) (2/(g+1))^((g+1)/(2(g-1))) [-] */
} fe_gasbag_model;

/* what changes: the gas, and running totals for the energy balance. The scalar fields are
 * declared once here, X(name, unit, what); the same table names the result channels. */
#define FE_GASBAG_STATE_FIELDS(X)                                                                  \
    X(time, "s", "time")                                                                           \
    X(volume, "m^3", "enclosed volume")                                                            \
    X(area, "m^2", "fabric area used for porosity leakage")                                        \
    X(mass, "kg", "gas mass")                                                                      \
    X(energy, "J", "internal energy U = m cv T")                                                   \
    X(pressure, "Pa", "absolute pressure")                                                         \
    X(temperature, "K", "gas temperature")                                                         \
    X(mass_flow_in, "kg/s", "inflator mass flow at the end of the last step")                      \
    X(mass_flow_vent, "kg/s", "vent mass flow at the end of the last step")                        \
    X(mass_flow_leak, "kg/s", "leakage mass flow at the end of the last step")                     \
    X(mass_in, "kg", "inflator mass in")                                                           \
    X(energy_in, "J", "inflator enthalpy in")                                                      \
    X(mass_vent, "kg", "mass out through the vents")                                               \
    X(energy_vent, "J", "enthalpy out through the vents")                                          \
    X(mass_leak, "kg", "mass leaked through the fabric")                                           \
    X(energy_leak, "J", "enthalpy leaked through the fabric")                                      \
    X(work, "J", "work of the gas on the fabric, int p dV")                                        \
    X(mass0, "kg", "initial gas mass")                                                             \
    X(energy0, "J", "initial internal energy")

typedef struct {
#define FE_GASBAG_X_DECL(name, unit, what) double name;
    FE_GASBAG_STATE_FIELDS(FE_GASBAG_X_DECL)
#undef FE_GASBAG_X_DECL
    unsigned vent_open; /* bit i set: vent i is open [-]           */
    int nsub;           /* sub-steps taken by the last advance [-] */
    double fire_time;   /* inflator firing time of this run: the model's at init; a coupling
                           may set it before the run reaches it (a trigger, INFINITY until it
                           fires; stage1_mb/mb_couple_trigger.c) [s] */
} fe_gasbag_state;

/* the scalar fields as result channels: count, name, unit, value */
enum {
#define FE_GASBAG_X_COUNT(name, unit, what) FE_GASBAG_CH_##name,
    FE_GASBAG_STATE_FIELDS(FE_GASBAG_X_COUNT)
#undef FE_GASBAG_X_COUNT
        FE_GASBAG_NCHANNEL
};
extern const char *const fe_gasbag_channel_name[FE_GASBAG_NCHANNEL];
extern const char *const fe_gasbag_channel_unit[FE_GASBAG_NCHANNEL];
double fe_gasbag_channel(const fe_gasbag_state *s, int channel);

mcs_status fe_gasbag_model_create(const char *name, const fe_gasbag_desc *d, fe_gasbag_model **out,
                                  mcs_error *err);
void fe_gasbag_model_destroy(fe_gasbag_model **p);

/* the bag at time t holding ambient gas in volume [m^3] with fabric area [m^2] */
mcs_status fe_gasbag_state_init(const fe_gasbag_model *m, fe_gasbag_state *s, double t,
                                double volume, double area, mcs_error *err);
/* the same holding gas at pressure [Pa] and temperature [K] (a pre-pressurised bag) */
mcs_status fe_gasbag_state_init_gas(const fe_gasbag_model *m, fe_gasbag_state *s, double t,
                                    double volume, double area, double pressure, double temperature,
                                    mcs_error *err);

/* advance from s->time to s->time + dt while the volume goes linearly to `volume` [m^3] and
 * the fabric area to `area` [m^2]. Strang split: exchange (inflator, vents, leakage) at fixed
 * volume for dt/2, the isentropic volume change (exact: U V^(gamma-1) constant), exchange for
 * dt/2. On failure (non-positive volume, mass or energy, NaN) the state is unchanged and
 * MCS_ERR_NUMERIC names the bag and the time. */
mcs_status fe_gasbag_advance(const fe_gasbag_model *m, fe_gasbag_state *s, double dt, double volume,
                             double area, mcs_error *err);

/* one kernel step of a bag bounded by a closed surface (faces nface x 4, -1 as the 4th index
 * of a triangle, outward): volume and area at the node positions x (nnode x 3) [m], the gas
 * advanced over dt [s] to them, and the gauge-pressure forces (p - p_amb) dV/dx added into f
 * (nnode x 3) [N]. Central-difference centring: call it in the external-force stage with
 * x = x(t_n) and dt = t_n - t_{n-1} (0 on the first step), so the pressure is that of t_n. */
mcs_status fe_gasbag_step_surface(const fe_gasbag_model *m, fe_gasbag_state *s, int nface,
                                  const int *face_node, const double *x, double dt, double *f,
                                  mcs_error *err);

/* gauge pressure p - p_amb to apply to the fabric [Pa] */
double fe_gasbag_gauge_pressure(const fe_gasbag_model *m, const fe_gasbag_state *s);

/* energy balance residual U - U0 - (H_in - H_vent - H_leak - W) [J]; 0 up to rounding */
double fe_gasbag_energy_residual(const fe_gasbag_state *s);

/* isentropic orifice mass flow [kg/s] from upstream (p_up [Pa], T_up [K]) to p_down [Pa]
 * through cd * area [m^2]; choked below the critical pressure ratio; 0 when p_up <= p_down */
double fe_gasbag_orifice_flow(const fe_gasbag_model *m, double cd_area, double p_up, double T_up,
                              double p_down);

/* CVODE reference: integrate the balances from s->time to t_end with V(t), dV/dt from `vol`
 * (returns 0 ok, nonzero failure), relative tolerance rtol; vent opening located by CVODE's
 * root finding. Sets s->volume, area (unchanged), totals and the gas state at t_end. */
typedef int (*fe_gasbag_volume_fn)(double t, double *volume, double *dvdt, void *user);
mcs_status fe_gasbag_integrate_cvode(const fe_gasbag_model *m, fe_gasbag_state *s, double t_end,
                                     fe_gasbag_volume_fn vol, void *user, double rtol,
                                     mcs_error *err);

#endif

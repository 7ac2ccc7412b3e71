/* rom_model.c: the reduced-order model's parameters, elements and masses (rom.h). */
#include "rom/rom.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* the stage-1 sport motorcycle (scenarios/models/motorcycles/sport_208kg.yaml) carried over to
 * one dimension; the fork's moments become forces at the axle, lever L = 0.40 m (hinge at
 * z = 0.70 m, axle at 0.30 m): F = M / L, k = k_rot / L^2. docs/rom.md "Parameters" */
rom_params rom_params_default(void)
{
    const double L = 0.40;
    return (rom_params){
        .tyre_stiffness = 15e3 / 0.060,        /* tyre_front: 15 kN at 60 mm            */
        .tyre_travel = 0.060,                  /* tyre_front's elastic limit             */
        .rim_stiffness = (70e3 - 15e3) / 0.14, /* tyre_front: 15 -> 70 kN, 60 -> 200 mm  */
        .tyre_unload = 1e7,                    /* tyre_front unloading_slope             */
        .tyre_damping = 300,
        .fork_stiffness = 3700 / 0.061667 / (L * L), /* fork_deformation elastic branch  */
        .fork_yield = 3700 / L,
        .fork_hardening = (4700 - 3700) / (0.2 - 0.061667) / (L * L),
        .fork_stop = 0.2 * L,                            /* 0.2 rad                      */
        .stop_stiffness = (64700 - 4700) / 0.02 / (L * L),
        .fork_unload = 60000 / (L * L),
        .fork_damping = 20 / (L * L),
        .frame_gap = 0.175,             /* fairing nose 175 mm behind the tyre's front    */
        .frame_stiffness = 80e3 / 0.15, /* engine: 80 kN at 150 mm                       */
        .frame_unload = 5e6,
        .frame_damping = 500,
        .rider_gap = 0.05,               /* seat travel before knees meet the tank       */
        .rider_stiffness = 20e3 / 0.060, /* tank: 20 kN at 60 mm                          */
        .rider_limit = 60e3,             /* tank: its last point, 60 kN at 100 mm         */
        .rider_unload = 2e6,             /* tank unloading_slope                          */
        .rider_damping = 200,
        .rider_wall_gap = 0.9,                /* chest to the tyre's front, seated        */
        .rider_wall_stiffness = 20e3 / 0.060, /* rider_torso: 20 kN at 60 mm              */
        .rider_wall_unload = 2e6,             /* as the tank's (an estimate)              */
        .rider_wall_damping = 500,
        .opponent_mass = 0,
        .rtol = 1e-6,
        .adams = 0,
    };
}

const char *const rom_param_names[] = {
    "tyre_stiffness", "tyre_travel", "rim_stiffness", "tyre_unload", "tyre_damping",
    "fork_stiffness", "fork_yield", "fork_hardening", "fork_stop", "stop_stiffness",
    "fork_unload", "fork_damping", "frame_gap", "frame_stiffness", "frame_unload",
    "frame_damping", "rider_gap", "rider_stiffness", "rider_limit", "rider_unload",
    "rider_damping", "rider_wall_gap", "rider_wall_unload", "rider_wall_stiffness",
    "rider_wall_damping", "opponent_mass", "rtol", NULL};

double *rom_param_ptr(rom_params *p, const char *name)
{
    double *v[] = {&p->tyre_stiffness, &p->tyre_travel, &p->rim_stiffness, &p->tyre_unload,
                   &p->tyre_damping, &p->fork_stiffness, &p->fork_yield, &p->fork_hardening,
                   &p->fork_stop, &p->stop_stiffness, &p->fork_unload, &p->fork_damping,
                   &p->frame_gap, &p->frame_stiffness, &p->frame_unload, &p->frame_damping,
                   &p->rider_gap, &p->rider_stiffness, &p->rider_limit, &p->rider_unload,
                   &p->rider_damping, &p->rider_wall_gap, &p->rider_wall_unload,
                   &p->rider_wall_stiffness, &p->rider_wall_damping, &p->opponent_mass,
                   &p->rtol};
    for (int i = 0; rom_param_names[i]; i++)
        if (strcmp(rom_param_names[i], name) == 0) return v[i];
    return NULL;
}

/* a loading curve through (0,0) and (x_i, F_i), extrapolated by its last slope */
static mcs_status curve(const char *name, int n, const double (*xy)[2], mcs_curve **out,
                        mcs_error *err)
{
    return mcs_curve_create_xy(name, n, xy, MCS_EXTRAP_LINEAR, MCS_EXTRAP_LINEAR, out, err);
}

static mcs_status elems(rom_model *m, mcs_error *err)
{
    const rom_params *p = &m->p;
    rom_elem *e = m->elem;
    const int wall = m->mass[ROM_OPP] > 0 ? ROM_OPP : -1;
    double ft = p->tyre_stiffness * p->tyre_travel;
    double tyre[3][2] = {{0, 0}, {p->tyre_travel, ft}, {p->tyre_travel + 1, ft + p->rim_stiffness}};
    double xe = p->fork_yield / p->fork_stiffness;
    double fs = p->fork_yield + p->fork_hardening * (p->fork_stop - xe);
    double fork[4][2] = {{0, 0}, {xe, p->fork_yield}, {p->fork_stop, fs},
                         {p->fork_stop + 1, fs + p->stop_stiffness}};
    double frame[2][2] = {{0, 0}, {1, p->frame_stiffness}};
    double xr = p->rider_limit / p->rider_stiffness;
    double rider[3][2] = {{0, 0}, {xr, p->rider_limit}, {xr + 1, p->rider_limit}};
    double head[2][2] = {{0, 0}, {1, p->rider_wall_stiffness}};
    if (!(xe > 0 && xe < p->fork_stop))
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "rom: fork elastic limit %g m (fork_yield / fork_stiffness) not in "
                       "(0, fork_stop = %g m)",
                       xe, p->fork_stop);
    mcs_status st = MCS_OK;
    e[ROM_TYRE] = (rom_elem){ROM_FRONT, wall, m->gap0, p->tyre_damping, NULL, {0}};
    e[ROM_FORK] = (rom_elem){ROM_FRAME, ROM_FRONT, 0, p->fork_damping, NULL, {0}};
    e[ROM_FRAMEWALL] = (rom_elem){ROM_FRAME, wall, m->gap0 + p->frame_gap, p->frame_damping,
                                  NULL, {0}};
    e[ROM_RIDERFRAME] = (rom_elem){ROM_RIDER, ROM_FRAME, p->rider_gap, p->rider_damping, NULL,
                                   {0}};
    e[ROM_RIDERWALL] = (rom_elem){ROM_RIDER, wall, m->gap0 + p->rider_wall_gap,
                                  p->rider_wall_damping, NULL, {0}};
    if (!st) st = curve("rom tyre", 3, tyre, &e[ROM_TYRE].loading, err);
    if (!st) st = curve("rom fork", 4, fork, &e[ROM_FORK].loading, err);
    if (!st) st = curve("rom frame", 2, frame, &e[ROM_FRAMEWALL].loading, err);
    if (!st) st = curve("rom rider", 3, rider, &e[ROM_RIDERFRAME].loading, err);
    if (!st) st = curve("rom head", 2, head, &e[ROM_RIDERWALL].loading, err);
    if (st) return st;
    /* unloading slopes and elastic limits as stage 1's characteristics (tyre_front, the fork
     * hinge, engine, tank); the rider on the barrier: rider_torso has none, but the one rider
     * mass stands for a jointed dummy that dissipates, so it unloads by a slope too */
    const double ku[ROM_NELEM] = {p->tyre_unload, p->fork_unload, p->frame_unload, p->rider_unload,
                                  p->rider_wall_unload};
    const double xl[ROM_NELEM] = {p->tyre_travel, xe, 0.005, 0.005, 0.005};
    for (int i = 0; i < ROM_NELEM; i++) {
        e[i].hyst = (mcs_hyst_model){.loading = e[i].loading,
                                     .unload = ku[i] > 0 ? MCS_UNLOAD_SLOPE : MCS_UNLOAD_ELASTIC,
                                     .unload_slope = ku[i],
                                     .elastic_limit = xl[i]};
        st = mcs_hyst_model_check(&e[i].hyst, e[i].loading->name, err);
        if (st) return st;
    }
    return MCS_OK;
}

static mcs_status check_params(const rom_params *p, mcs_error *err)
{
    rom_params q = *p;
    for (int i = 0; rom_param_names[i]; i++) {
        double v = *rom_param_ptr(&q, rom_param_names[i]);
        const char *n = rom_param_names[i];
        int may_be_zero = strstr(n, "damping") || strstr(n, "gap") || !strcmp(n, "opponent_mass");
        if (!isfinite(v) || v < 0 || (v == 0 && !may_be_zero))
            return MCS_ERR(err, MCS_ERR_RANGE, "rom: %s = %g: expected %s", rom_param_names[i], v,
                           may_be_zero ? ">= 0" : "> 0");
    }
    return MCS_OK;
}

mcs_status rom_model_init(rom_model *m, const double mass[ROM_NMASS], double v0, double gap0,
                          const rom_params *p, double end_time, double out_dt, mcs_error *err)
{
    memset(m, 0, sizeof *m);
    m->p = *p;
    for (int i = 0; i < ROM_NMASS; i++) m->mass[i] = mass[i];
    m->mass[ROM_OPP] = p->opponent_mass;
    m->v0 = v0, m->gap0 = gap0, m->end_time = end_time, m->out_dt = out_dt;
    m->normal[0] = 1;
    for (int i = 0; i < ROM_NMASS; i++) m->vinit[i] = i == ROM_OPP ? 0 : v0;
    if (!(mass[ROM_FRONT] > 0) || !(mass[ROM_FRAME] >= 0) || !(mass[ROM_RIDER] >= 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "rom: masses front %g, frame %g, rider %g kg",
                       mass[ROM_FRONT], mass[ROM_FRAME], mass[ROM_RIDER]);
    if (!(end_time > 0) || !(out_dt > 0) || !(gap0 >= 0) || !isfinite(v0))
        return MCS_ERR(err, MCS_ERR_RANGE, "rom: end time %g s, output step %g s, gap %g m",
                       end_time, out_dt, gap0);
    mcs_status st = check_params(p, err);
    if (!st) st = elems(m, err);
    if (st) rom_model_deinit(m);
    return st;
}

mcs_status rom_model_rebuild(rom_model *m, const rom_params *p, mcs_error *err)
{
    rom_model n;
    double mass[ROM_NMASS];
    memcpy(mass, m->mass, sizeof mass);
    mcs_status st = rom_model_init(&n, mass, m->v0, m->gap0, p, m->end_time, m->out_dt, err);
    if (st) return st;
    memcpy(n.normal, m->normal, sizeof n.normal);
    memcpy(n.vinit, m->vinit, sizeof n.vinit);
    rom_model_deinit(m);
    *m = n;
    return MCS_OK;
}

void rom_model_deinit(rom_model *m)
{
    for (int i = 0; i < ROM_NELEM; i++) mcs_curve_destroy(&m->elem[i].loading);
}

/* body name -> lumped mass: forks and the front wheel ride with the front, rider_* is the
 * rider, any other moto_* the frame; -1: not the motorcycle's (the barrier, the opponent) */
static int lump_of(const char *name)
{
    if (strncmp(name, "rider_", 6) == 0) return ROM_RIDER;
    if (strncmp(name, "moto_", 5) != 0) return -1;
    if (strstr(name, "fork") || strstr(name, "front_wheel")) return ROM_FRONT;
    return ROM_FRAME;
}

mcs_status rom_model_from_scenario(rom_model *m, const mcs_scenario *scn, mcs_error *err)
{
    const mcs_node *root = mcs_scenario_root(scn);
    const mcs_node *bodies = mcs_node_get(root, "bodies"), *imp = mcs_node_get(root, "impact");
    double mass[ROM_NMASS] = {0};
    for (int i = 0; i < mcs_node_len(bodies); i++) {
        const mcs_node *b = mcs_node_at(bodies, i);
        int k = lump_of(mcs_node_str(mcs_node_get(b, "name")));
        if (k >= 0) mass[k] += mcs_node_num(mcs_node_get(b, "mass"));
    }
    /* along the barrier's normal: the opponent's heading (a flat barrier's face normal) */
    double n[3] = {1, 0, 0};
    const mcs_node *oh = mcs_node_get(imp, "opponent_heading");
    if (oh && mcs_node_vec3(oh, n, err)) return MCS_ERR_RANGE;
    double ln = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++) n[k] /= ln;
    double c = cos(mcs_node_num_or(imp, "heading_angle", 0));
    double v0 = mcs_node_num_or(imp, "motorcycle_speed", 0) * c;
    double gap = mcs_node_num_or(imp, "initial_gap", 0) * c;
    const mcs_node *sim = mcs_node_get(root, "simulation");
    double tend = mcs_node_num_or(sim, "end_time", 0.25);
    double rate = mcs_node_num_or(sim, "output_rate", 10e3);
    rom_params p = rom_params_default();
    const mcs_node *blk = mcs_node_get(root, "rom");
    for (int i = 0; blk && rom_param_names[i]; i++) {
        const mcs_node *v = mcs_node_get(blk, rom_param_names[i]);
        if (v) *rom_param_ptr(&p, rom_param_names[i]) = mcs_node_num(v);
    }
    const mcs_node *meth = mcs_node_get(blk, "method");
    if (meth) p.adams = strcmp(mcs_node_str(meth), "adams") == 0;
    if (!(mass[ROM_FRONT] > 0 && mass[ROM_FRAME] > 0))
        return MCS_ERR(err, MCS_ERR_KEY,
                       "rom: the scenario has no moto_* bodies for the front (forks, front "
                       "wheel) and the frame");
    /* at least two samples (a study's probe runs two time steps) */
    double dt = fmin(1.0 / rate, tend / 2);
    mcs_status st = rom_model_init(m, mass, v0, gap, &p, tend, dt, err);
    if (!st) memcpy(m->normal, n, sizeof n);
    return st;
}

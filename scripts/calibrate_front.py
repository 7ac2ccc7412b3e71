#!/usr/bin/env python3
"""calibrate_front.py: why the stage-1 crash events come early against MYMOSA, and the fit.

  make && python3 scripts/calibrate_front.py [--part sens|fit|check|all] [--mcrash bin/mcrash]

MYMOSA's lateral impact [seed 002, Fig. 5.2]: the fork starts to deform at ~20 ms, reaches its
maximum at ~30 ms when the front wheel hits the motorcycle's body, the rider's attachments
release at ~60 ms, the head's acceleration peak starts at ~130 ms. The script runs
`mcrash run --stage 1` on wrapper scenarios (a temporary YAML that includes a shipped scenario
and overrides characteristics, the rider block or the end time; the scenario merge rule of
core/mcs_scn_include.c) and prints the event times:

  sens   one parameter at a time (MYMOSA rider case, 50 ms): the motorcycle's front end (fork
         yield moment, elastic slope, stop angle; tyre radial stiffness; rim-collapse level)
         and the car side at the wheel's height (the 1100 kg car's stiff sill against
         MYMOSA's one lateral spring).
  fit    the fitted parameters: the MYMOSA car side's crush level F150 (force at 150 mm of one
         homogeneous side law) against the fork-yield and wheel-engine times; then the
         attachment failure forces against the detachment time (~60 ms).
  check  the shipped scenarios as they are: MYMOSA rider and motorcycle-only cases, the 413
         rider case, the thesis frontal barrier; event times and energy drift.

Event definitions (as docs/validation_stage1.md): fork "starting to deform" = the fork hinge
past its elastic limit 0.05 rad; "wheel against the engine" = the hinge at its stop 0.2 rad
(and the first > 1 kN of the wheel-engine contact); attachment failure = the first sample where
|k d + c d'| (the attachment's force, d the stretch between the mount points, d' by central
differences of the 10 kHz output) passes the failure force; head peak = largest resultant of
the CFC 1000 head channels. Needs h5dump (hdf5-tools); no numpy."""
import argparse
import atexit
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import validation_stage1 as vs  # noqa: E402  (h5dump reader, mount points, quaternion helpers)

MYMOSA = {"yield": 20.0, "stop": 30.0, "detach": 60.0, "head": 130.0}  # [M Fig. 5.2], ms
RIDER = "scenarios/mymosa_lateral_car_1100kg_rider.yaml"
MOTO = "scenarios/mymosa_lateral_car_1100kg.yaml"
S413 = "scenarios/iso13232_413-0_13.4_sedan_rider.yaml"
BARRIER = "scenarios/thesis_frontal_barrier_13.4.yaml"
# attachment defaults of stage1_mb/mb_position.c (a scenario's rider: block overrides them)
ATTACH = {"seat": ("rider_h_point", "seat_h_point", "seat_failure_force", 1500.0),
          "grip_l": ("rider_grip_l", "grip_l", "grip_failure_force", 400.0),
          "grip_r": ("rider_grip_r", "grip_r", "grip_failure_force", 400.0),
          "peg_l": ("rider_peg_l", "peg_l", "peg_failure_force", 500.0),
          "peg_r": ("rider_peg_r", "peg_r", "peg_failure_force", 500.0)}


def fork_elastic_limit():
    """the shipped fork's elastic limit [rad] (fork_deformation: elastic_limit)"""
    y = open(os.path.join(ROOT, "scenarios/models/motorcycles/sport_208kg.yaml")).read()
    return float(re.search(r"fork_deformation:\n(?:    .*\n)*?    elastic_limit: ([0-9.]+) rad", y).group(1))


def law(name, pts, unload="2e6 N/m", elastic="10 mm", damping="500 N s/m"):
    """a force characteristic override: pts [(m, N)]"""
    p = ", ".join("[%g mm, %g kN]" % (1e3 * x, 1e-3 * f) for x, f in pts)
    return ("  %s:\n    loading: [%s]\n    unloading_slope: %s\n    elastic_limit: %s\n    damping: %s\n"
            % (name, p, unload, elastic, damping))


def fork(m_e, k_e=60e3, m_stop=None, phi_stop=0.2):
    """M_def(phi) override: elastic k_e to M_e, hardening to m_stop at phi_stop, stop beyond"""
    pe, m_stop = m_e / k_e, m_stop or m_e + 1000
    return ("  fork_deformation:\n    type: moment\n"
            "    loading: [[0, 0], [%g rad, %g N*m], [%g rad, %g N*m], [%g rad, %g N*m]]\n"
            "    unloading_slope: %g N m/rad\n    elastic_limit: %g rad\n    damping: 20 N m s/rad\n"
            "  fork_forward:\n    type: moment\n    loading: [[0, 0], [%g rad, %g N*m]]\n"
            % (pe, m_e, phi_stop, m_stop, phi_stop + 0.02, m_stop + 60e3, k_e, pe, pe, m_e))


def tyre(k=180e3, rim=50e3):
    """front tyre override: radial k to 10 mm (the shipped shape scaled), rim collapse from rim"""
    s = k / 180e3
    pts = [(0, 0), (0.01, 1800 * s), (0.03, 6000 * s), (0.06, 15000 * s), (0.08, rim),
           (0.2, rim + 20e3), (0.3, 200e3)]
    return law("tyre_front", pts, unload="1e7 N/m", elastic="60 mm", damping="300 N s/m")


def car_side(f150):
    """MYMOSA's car side: one lateral law for the sill and the door zone (no stiff sill)"""
    pts = [(0, 0), (0.15, f150), (0.30, 24e3), (0.45, 32e3), (0.55, 120e3)]
    return law("car_sill", pts) + law("car_door", pts)


SILL_1100 = law("car_sill", [(0, 0), (0.02, 40e3), (0.06, 100e3), (0.1, 250e3)], unload="5e6 N/m",
                elastic="5 mm")
DOOR_1100 = law("car_door", [(0, 0), (0.1, 20e3), (0.25, 40e3), (0.35, 150e3)])


TMP = [tempfile.mkdtemp(prefix="mcrash_calib_")]
atexit.register(shutil.rmtree, TMP[0], True)


def run(mcrash, scen, chars="", rider="", end=None, tag="run"):
    """run a wrapper scenario; returns (h5 path, json summary)"""
    tmp = TMP[0]
    yml = os.path.join(tmp, tag + ".yaml")
    with open(yml, "w") as f:
        f.write("include: [%s]\n" % os.path.join(ROOT, scen))
        if end:
            f.write("simulation: {end_time: %s}\n" % end)
        if rider:
            f.write("rider: {%s}\n" % rider)
        if chars:
            f.write("characteristics:\n" + chars)
    h5 = os.path.join(tmp, tag + ".h5")
    r = subprocess.run([mcrash, "run", yml, "--stage", "1", "--quiet", "--json", "-o", h5],
                       capture_output=True, text=True)
    if r.returncode:
        sys.exit("calibrate_front: %s: %s" % (yml, r.stderr.strip()))
    return h5, json.loads(r.stdout)["stage1"]


def rider_block(scen, extra="", text=None):
    """failure forces and attachment k, c: mb_position.c defaults, then the scenario's rider:
    block (the file scen, or its text), then extra"""
    vals = {"seat_failure_force": 1500.0, "grip_failure_force": 400.0, "peg_failure_force": 500.0,
            "attachment_stiffness": 2e4, "attachment_damping": 200.0}
    if text is None:
        text = open(os.path.join(ROOT, scen)).read()
    m = re.search(r"^\s*rider: \{(.*?)\}", text, re.M)
    for part in ([m.group(1)] if m else []) + [extra]:
        for k, v, unit in re.findall(r"(\w+): ([0-9.eE+-]+)\s*(kN)?", part):
            if k in vals:
                vals[k] = float(v) * (1e3 if unit else 1)
    return vals


def attach_times(h5, t, rb):
    """first time each attachment's spring-damper force passes its failure force [ms]"""
    pts, poses, out = vs.mounts(), {}, {}

    def pose(b):
        if b not in poses:
            poses[b] = (vs.h5(h5, "/stage1/bodies/%s/position" % b), vs.h5(h5, "/stage1/bodies/%s/orientation" % b))
        return poses[b]
    k, c = rb["attachment_stiffness"], rb["attachment_damping"]
    for name, (a, b, key, _) in ATTACH.items():
        (ba, pa), (bb, pb) = pts[a], pts[b]
        Pa, Qa = pose(ba)
        Pb, Qb = pose(bb)
        d = [[q - p for p, q in zip(vs.world(Pa, Qa, i, pa), vs.world(Pb, Qb, i, pb))] for i in range(len(t))]
        hit = None
        for i in range(1, len(t) - 1):
            dv = [(d[i + 1][j] - d[i - 1][j]) / (t[i + 1] - t[i - 1]) for j in range(3)]
            if math.sqrt(sum((k * d[i][j] + c * dv[j]) ** 2 for j in range(3))) > rb[key]:
                hit = 1e3 * t[i]
                break
        out[name] = hit
    return out


def events(h5, scen=None, rider_extra="", phi_e=None):
    t = vs.h5(h5, "/stage1/time")
    ev = {}
    phi_e = phi_e or fork_elastic_limit()
    fork_a = vs.h5(h5, "/stage1/channels/moto_fork_deformation_angle")
    if fork_a:
        a = [abs(x) for x in fork_a]
        first = lambda th: vs.first(t, a, lambda x: x > th)  # noqa: E731
        ev["yield"] = 1e3 * first(phi_e) if first(phi_e) is not None else None
        ev["stop"] = 1e3 * first(0.2) if first(0.2) is not None else None
        imax = max(range(len(a)), key=lambda i: a[i])
        ev["phi_max"], ev["t_phi_max"] = a[imax], 1e3 * t[imax]
    we = vs.h5(h5, "/stage1/channels/moto_front_wheel_engine_fn")
    if we:
        w = vs.first(t, we, lambda x: x > 1e3)
        ev["wheel_engine_1kN"] = None if w is None else 1e3 * w
    ax = vs.h5(h5, "/stage1/channels/head_ax")
    if ax and scen:
        ev["attach"] = attach_times(h5, t, rider_block(scen, rider_extra))
        known = [x for x in ev["attach"].values() if x is not None]
        ev["detach"] = max(known) if len(known) == len(ev["attach"]) else None
        ay, az = vs.h5(h5, "/stage1/channels/head_ay"), vs.h5(h5, "/stage1/channels/head_az")
        g = [math.sqrt(x * x + y * y + z * z) / 9.80665 for x, y, z in zip(ax, ay, az)]
        i = max(range(len(g)), key=lambda j: g[j])
        ev["head"], ev["head_g"] = 1e3 * t[i], g[i]
    return ev


def fmt(v):
    return "  --  " if v is None else "%5.1f" % v


def ratio(ev, key):
    v = ev.get(key)
    return None if v is None else v / MYMOSA[key]


def line(label, ev, summ=None):
    s = "  %-48s yield %s  stop %s  max %.3f rad at %s  wheel-engine >1 kN %s" % (
        label, fmt(ev.get("yield")), fmt(ev.get("stop")), ev.get("phi_max", 0), fmt(ev.get("t_phi_max")),
        fmt(ev.get("wheel_engine_1kN")))
    if "attach" in ev:
        s += "\n  %-48s attachments: %s; head peak %.0f g at %s ms" % (
            "", ", ".join("%s %s" % (k, fmt(v)) for k, v in ev["attach"].items()), ev["head_g"], fmt(ev["head"]))
    if summ:
        s += "  drift %.2e" % summ["energy_drift"]
    print(s)


def part_sens(mc):
    print("== sensitivity: MYMOSA rider case, 50 ms, one parameter at a time (times in ms)")
    old = SILL_1100 + DOOR_1100
    before = old + fork(3000)
    cases = [("before: stiff sill, door; fork M_e 3 kN m", before, 0.05),
             ("  fork M_e 3 -> 5 kN m (phi_e 0.083 rad)", old + fork(5000), 5000 / 60e3),
             ("  fork M_e 3 -> 2 kN m (phi_e 0.033 rad)", old + fork(2000), 2000 / 60e3),
             ("  elastic slope 60 -> 30 kN m/rad (0.1 rad)", old + fork(3000, k_e=30e3), 0.1),
             ("  fork stop 0.2 -> 0.3 rad (engine unmoved)", old + fork(3000, phi_stop=0.3), 0.05),
             ("  tyre radial 180 -> 120 kN/m", before + tyre(k=120e3), 0.05),
             ("  rim collapse 50 -> 20 kN", before + tyre(rim=20e3), 0.05),
             ("  car side one law, F150 10 kN", fork(3000) + car_side(10e3), 0.05),
             ("  car side one law, F150 10 kN; fork M_e 2 kN m", fork(2000) + car_side(10e3), 2000 / 60e3),
             ("  car side one law, F150 10 kN; fork M_e 5 kN m", fork(5000) + car_side(10e3), 5000 / 60e3),
             ("after: shipped (M_e 3.7 kN m, MYMOSA car side)", "", None)]
    for label, chars, phi_e in cases:
        h5, summ = run(mc, RIDER, chars, end="50 ms", tag="sens")
        line(label, events(h5, phi_e=phi_e), summ)


def part_fit(mc):
    print("== fit 1: MYMOSA car side F150 (one lateral law) against yield ~20 ms, stop ~30 ms")
    best = None
    for f150 in (20e3, 16e3, 13e3, 11e3, 10e3, 8e3):
        h5, summ = run(mc, RIDER, car_side(f150), end="50 ms", tag="fit")
        ev = events(h5)
        err = max(abs(ratio(ev, k) - 1) if ev.get(k) else 1 for k in ("yield", "stop"))
        line("F150 = %4.1f kN  (largest error %3.0f %%)" % (f150 / 1e3, 100 * err), ev, summ)
        if best is None or err < best[0] - 1e-9:
            best = (err, f150)
    print("  -> F150 = %.1f kN" % (best[1] / 1e3))
    best_f150 = best[1]
    print("== fit 2: attachment failure forces (grip, peg, seat) against the detachment at ~60 ms;"
          " criterion: the largest |t/60 ms - 1| over the five attachments")
    best = None
    for grip, peg, seat in ((400, 500, 1500), (800, 1000, 2500), (1000, 1000, 3000), (1000, 1200, 3000),
                            (1200, 1200, 3500)):
        extra = "grip_failure_force: %g N, peg_failure_force: %g N, seat_failure_force: %g N" % (grip, peg, seat)
        h5, summ = run(mc, RIDER, car_side(best_f150), rider=extra, end="120 ms", tag="fit")
        ev = events(h5, RIDER, extra)
        err = max(abs(x / MYMOSA["detach"] - 1) if x else 1 for x in ev["attach"].values())
        line("grip %4d, peg %4d, seat %4d N (error %3.0f %%)" % (grip, peg, seat, 100 * err), ev, summ)
        if best is None or err < best[0] - 1e-9:
            best = (err, grip, peg, seat)
    print("  -> grip %d N, peg %d N, seat %d N" % best[1:])


def part_check(mc):
    print("== check: the shipped scenarios (300 ms / 250 ms)")
    for scen in (RIDER, MOTO, S413, BARRIER):
        h5, summ = run(mc, scen, tag="check")
        ev = events(h5, scen if "rider" in scen else None)
        line(os.path.basename(scen), ev, summ)
        if scen == RIDER:
            for k in ("yield", "stop", "detach", "head"):
                r = ratio(ev, k)
                print("    %-7s ours %s ms, MYMOSA %5.0f ms: %s" % (
                    k, fmt(ev.get(k)), MYMOSA[k], "--" if r is None else "%+.0f %% (%s the +-25 %% band)" % (
                        100 * (r - 1), "within" if abs(r - 1) <= 0.25 else "outside")))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--part", default="all", choices=["sens", "fit", "check", "all"])
    ap.add_argument("--mcrash", default=os.path.join(ROOT, "bin", "mcrash"))
    a = ap.parse_args()
    os.chdir(ROOT)
    for p, fn in (("sens", part_sens), ("fit", part_fit), ("check", part_check)):
        if a.part in (p, "all"):
            fn(os.path.abspath(a.mcrash))


if __name__ == "__main__":
    main()

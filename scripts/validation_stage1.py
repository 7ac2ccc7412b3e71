#!/usr/bin/env python3
"""validation_stage1.py: the rider part of docs/validation_stage1.md from stage-1 results.

  bin/mcrash run scenarios/mymosa_lateral_car_1100kg_rider.yaml --stage 1 -o out/mymosa_rider.h5
  bin/mcrash run scenarios/iso13232_413-0_13.4_sedan_rider.yaml --stage 1 -o out/413_rider.h5
  python3 scripts/validation_stage1.py out/mymosa_rider.h5 car out/413_rider.h5 sedan

Prints the event times (fork past its elastic limit and at its stop, pelvis and head/helmet
contacts, head acceleration peak; the attachments' failure times and every figure of the doc
come from tests/test_validation_stage1.c) and plots the attachments' stretch and writes gnuplot data and a script to
out/validation/ (gnuplot out/validation/plots.gp makes the PNGs). Reads the HDF5 file with
h5dump (hdf5-tools); no numpy."""
import math
import os
import re
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def h5(path, ds):
    out = subprocess.run(["h5dump", "-A", "0", "-d", ds, "-y", "-w", "0", path], capture_output=True, text=True).stdout
    m = re.search(r"DATA \{\n(.*)\n\s*\}", out, re.S)
    if not m:
        return None
    nums = [float(x) for x in re.findall(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?", m.group(1))]
    dims = [int(x) for x in re.search(r"DATASPACE\s+SIMPLE\s+\{\s*\(\s*([\d, ]+)\)", out).group(1).split(",")]
    if len(dims) == 1:
        return nums
    return [nums[i * dims[1]:(i + 1) * dims[1]] for i in range(dims[0])]


# the rider's five attachments: rider mount point, motorcycle mount point
ATTACH = {"seat": ("rider_h_point", "seat_h_point"), "grip_l": ("rider_grip_l", "grip_l"),
          "grip_r": ("rider_grip_r", "grip_r"), "peg_l": ("rider_peg_l", "peg_l"),
          "peg_r": ("rider_peg_r", "peg_r")}


def fork_elastic_limit():
    """the shipped fork's elastic limit [rad] (fork_deformation: elastic_limit)"""
    y = open(os.path.join(ROOT, "scenarios/models/motorcycles/sport_208kg.yaml")).read()
    return float(re.search(r"fork_deformation:\n(?:    .*\n)*?    elastic_limit: ([0-9.]+) rad", y).group(1))


def mounts():
    pts = {}
    for f in ("scenarios/models/motorcycles/sport_208kg.yaml", "scenarios/models/riders/hybrid3_50th.yaml"):
        for n, b, p in re.findall(r"\{name: (\S+), body: (\S+), point: \[([^\]]*)\]\}", open(os.path.join(ROOT, f)).read()):
            pts[n] = (b, [float(x) for x in p.split(",")])
    return pts


def rot(q):
    w, x, y, z = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def world(P, Q, i, p):
    R = rot(Q[i])
    return [P[i][k] + sum(R[k][j] * p[j] for j in range(3)) for k in range(3)]


def first(t, y, cond):
    for ti, yi in zip(t, y):
        if cond(yi):
            return ti
    return None


def analyse(path, opp, tag, outdir):
    t = h5(path, "/stage1/time")
    pts = mounts()
    body = {}

    def pose(b):
        if b not in body:
            body[b] = (h5(path, "/stage1/bodies/%s/position" % b), h5(path, "/stage1/bodies/%s/orientation" % b))
        return body[b]
    res = {"t": t}
    fork = h5(path, "/stage1/channels/moto_fork_deformation_angle")
    res["fork"] = fork
    print("%s: %s" % (tag, path))
    if fork:
        pe = fork_elastic_limit()
        print("  fork past its elastic limit (%.4f rad): %s ms; at the stop (0.2 rad, wheel against the engine): %s ms; largest %.3f rad"
              % (pe, ms(first(t, fork, lambda v: abs(v) > pe)), ms(first(t, fork, lambda v: abs(v) > 0.2)), max(abs(v) for v in fork)))
    # attachments: the stretch between the mount points (plotted)
    for name, (a, b) in ATTACH.items():
        (ba, pa), (bb, pb) = pts[a], pts[b]
        Pa, Qa = pose(ba)
        Pb, Qb = pose(bb)
        res["stretch_" + name] = [math.dist(world(Pa, Qa, i, pa), world(Pb, Qb, i, pb)) for i in range(len(t))]
    # contacts of the pelvis with the motorcycle (seat, tank), the head with the opponent
    for ch in ["rider_pelvis_moto_fn", "rider_lower_torso_moto_fn", "rider_thigh_l_moto_fn", "rider_head_%s_fn" % opp,
               "rider_head_%s_upper_fn" % opp, "rider_helmet_%s_upper_fn" % opp, "rider_upper_torso_%s_fn" % opp, "rider_upper_torso_%s_upper_fn" % opp]:
        y = h5(path, "/stage1/channels/" + ch)
        if y is None:
            continue
        res[ch] = y
        imax = max(range(len(y)), key=lambda i: y[i])
        print("  %-28s first > 100 N at %s ms, peak %.2f kN at %.1f ms" % (ch, ms(first(t, y, lambda v: v > 100)), y[imax] / 1e3, 1e3 * t[imax]))
    ax, ay, az = (h5(path, "/stage1/channels/head_a" + c) for c in "xyz")
    a = [math.sqrt(x * x + y * y + z * z) / 9.80665 for x, y, z in zip(ax, ay, az)]
    res["head_a"] = a
    imax = max(range(len(a)), key=lambda i: a[i])
    print("  head resultant acceleration (CFC 1000) peak %.1f g at %.1f ms" % (a[imax], 1e3 * t[imax]))
    with open(os.path.join(outdir, tag + ".dat"), "w") as f:
        keys = [k for k in res if k != "t"]
        f.write("# t_ms " + " ".join(keys) + "\n")
        for i in range(len(t)):
            f.write("%.4f " % (1e3 * t[i]) + " ".join("%.6g" % (res[k][i] if res[k] else 0) for k in keys) + "\n")
    return [k for k in res if k != "t"]


def ms(v):
    return "never" if v is None else "%.1f" % (1e3 * v)


def main():
    outdir = os.path.join(ROOT, "out", "validation")
    os.makedirs(outdir, exist_ok=True)
    gp = ["set terminal pngcairo noenhanced size 800,500 font ',10'" if os.system("gnuplot -e 'set terminal pngcairo' 2>/dev/null") == 0
          else "set terminal png noenhanced size 800,500", "set xlabel 't [ms]'", "set grid"]
    args = sys.argv[1:]
    for i in range(0, len(args), 2):
        path, opp = args[i], args[i + 1]
        tag = os.path.splitext(os.path.basename(path))[0]
        keys = analyse(path, opp, tag, outdir)
        col = {k: j + 2 for j, k in enumerate(keys)}
        dat = os.path.join(outdir, tag + ".dat")
        gp += ["set output '%s'" % os.path.join(outdir, tag + "_events.png"),
               "set title '%s: fork angle, attachment stretch, contact forces, head acceleration'" % tag,
               "set ylabel 'see key'", "set y2tics", "set ytics nomirror", "set xrange [0:300]", "unset arrow", "unset label"] + [
               "set arrow from %d, graph 0 to %d, graph 1 nohead dt 2 lc rgb 'gray40'\nset label 'MYMOSA %s %d ms' at %d, graph %.2f font ',8'"
               % (tm, tm, what, tm, tm + 2, y) for tm, what, y in ((20, "fork", 0.97), (30, "wheel-engine", 0.93), (60, "detach", 0.97), (130, "head", 0.97))] + [
               "plot " + ", ".join(
                   ["'%s' u 1:(abs($%d)*1000) w l t 'fork angle [mrad]'" % (dat, col["fork"])] +
                   ["'%s' u 1:($%d*1000) w l t '%s stretch [mm]'" % (dat, col[k], k[8:]) for k in keys if k.startswith("stretch_") and k in ("stretch_seat", "stretch_grip_l")] +
                   ["'%s' u 1:($%d/10) w l t '%s [10 N]'" % (dat, col[k], k) for k in keys if k.endswith("_fn")] +
                   ["'%s' u 1:%d axes x1y2 w l lw 2 t 'head resultant [g] (right axis)'" % (dat, col["head_a"])])]
    with open(os.path.join(outdir, "plots.gp"), "w") as f:
        f.write("\n".join(gp) + "\n")
    print("gnuplot %s" % os.path.join(outdir, "plots.gp"))


if __name__ == "__main__":
    main()

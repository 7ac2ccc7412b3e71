#!/usr/bin/env python3
"""validation_restraints.py: the plots of docs/validation_restraints.md from coupled stage-1
results files (scripts/plot_restraints.sh runs the scenarios and calls this).

  python3 scripts/validation_restraints.py RESULTS_DIR IMG_DIR

RESULTS_DIR holds coupled_<case>.h5 of scenarios/verification/coupled_<case>.yaml (bag_piston,
belt_limiter, belt_pretensioner, foam_block, foam_impact, foam_contact, momentum). Writes the gnuplot data
and script to RESULTS_DIR and runs gnuplot: IMG_DIR/restraints_{bag,limiter,pretensioner,foam,
energy}.png. The closed forms drawn are the ones tests/test_validation_restraints.c checks
(its figures are the numbers the doc states; this script only draws). Reads the HDF5 files
with h5dump (hdf5-tools); no numpy."""
import math
import os
import re
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
P_AMB, GAMMA = 101325.0, 1.4


def h5(path, ds):
    out = subprocess.run(["h5dump", "-A", "0", "-d", ds, "-y", "-w", "0", path],
                         capture_output=True, text=True).stdout
    m = re.search(r"DATA \{\n(.*)\n\s*\}", out, re.S)
    if not m:
        sys.exit("validation_restraints: %s has no %s" % (path, ds))
    nums = [float(x) for x in re.findall(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?", m.group(1))]
    dims = [int(x) for x in re.search(r"DATASPACE\s+SIMPLE\s+\{\s*\(\s*([\d, ]+)\)", out)
            .group(1).split(",")]
    if len(dims) == 1:
        return nums
    return [nums[i * dims[1]:(i + 1) * dims[1]] for i in range(dims[0])]


def mean_accel(t, v, k):
    """component k of the mean acceleration over each output interval (velocity differences:
    the instantaneous acceleration of a step rings with the FE), at the interval's middle"""
    return [(v[i][k] - v[i - 1][k]) / (t[i] - t[i - 1]) for i in range(1, len(t))]


def scenario(case):
    return open(os.path.join(ROOT, "scenarios/verification/coupled_%s.yaml" % case)).read()


def write(path, rows):
    with open(path, "w") as f:
        for r in rows:
            f.write(" ".join("%.9g" % x for x in r) + "\n")


def bag(res, out):
    """plate force M a against the stroke; the prism gas spring (p0 (V0/V)^gamma - p_a) A"""
    h = os.path.join(res, "coupled_bag_piston.h5")
    t, z = h5(h, "/stage1/time"), h5(h, "/stage1/bodies/plate/position")
    a = mean_accel(t, h5(h, "/stage1/bodies/plate/velocity"), 2)
    M, r, h0, n = 20.0, 0.15, 0.2, 38  # the scenario's plate, cap radius, height, ring nodes
    A = 0.5 * n * r * r * math.sin(2 * math.pi / n)
    p, V = h5(h, "/stage1/airbag/bag/pressure"), h5(h, "/stage1/airbag/bag/volume")
    pvg0 = p[0] * V[0] ** GAMMA
    write(os.path.join(out, "bag.dat"),
          [(1e3 * (h0 - 0.5 * (z[i][2] + z[i - 1][2])), M * a[i - 1], 1e3 * t[i],
            (0.5 * (p[i] + p[i - 1]) - P_AMB) * A, p[i] * V[i] ** GAMMA / pvg0 - 1)
           for i in range(2, min(len(t), len(p)))])
    write(os.path.join(out, "bag_ref.dat"),
          [(1e3 * d, (P_AMB * (h0 / (h0 - d)) ** GAMMA - P_AMB) * A)
           for d in [k * 0.0005 for k in range(0, 70)]])


def limiter(res, out):
    """body velocity; closed form: elastic phase v0 cos(w t), then v_on - (F/M)(t - t_on)"""
    h = os.path.join(res, "coupled_belt_limiter.h5")
    t, v = h5(h, "/stage1/time"), h5(h, "/stage1/bodies/sled/velocity")
    M, v0, F, k = 20.0, 4.0, 2000.0, 400e3
    w = math.sqrt(k / M)
    t_on = math.asin(F * w / (k * v0)) / w
    v_on = math.sqrt(v0 * v0 - F * F / (k * M))
    ref = []
    for ti in t:
        if ti < t_on:
            ref.append(v0 * math.cos(w * ti))
        else:
            ref.append(max(v_on - F / M * (ti - t_on), float("nan")))
    f = h5(h, "/stage1/retractor/retractor/force")
    write(os.path.join(out, "limiter.dat"),
          [(1e3 * t[i], v[i][0], ref[i] if ref[i] > 0 else float("nan"), f[i] / 1e3)
           for i in range(min(len(t), len(f)))])


def pretensioner(res, out):
    """body displacement; Eq. 3; the tension-only spring closed form until release"""
    h = os.path.join(res, "coupled_belt_pretensioner.h5")
    t, x = h5(h, "/stage1/time"), h5(h, "/stage1/bodies/tongue/position")
    tf, vp, M = 0.012, 0.1 / 0.015, 1.0
    w = math.sqrt(1 / (0.5 / 400e3 + 0.1 / 400e3) / M)
    rows = []
    for i, ti in enumerate(t):
        tau = ti - tf
        eq3 = 0 if tau <= 0 else -vp * tau if tau < 0.015 else -0.1
        spring = float("nan")
        if 0 <= tau <= math.pi / w:
            spring = -(vp * tau - vp / w * math.sin(w * tau))
        elif tau > math.pi / w:
            spring = -(vp * math.pi / w + 2 * vp * (tau - math.pi / w))
        rows.append((1e3 * ti, 1e3 * (x[i][0] - 0.6), 1e3 * eq3, 1e3 * spring))
    write(os.path.join(out, "pretensioner.dat"), rows)


def foam_curves():
    y = scenario("foam_block")
    curves = []
    for rate, pts in re.findall(r"\{rate: ([0-9.e]+), points: \[(.*?)\]\]\}", y):
        pairs = re.findall(r"\[([0-9.]+), ([0-9.]+) (kPa|MPa)\]?", pts + "]")
        curves.append((float(rate), [(float(e), float(s) * (1e3 if u == "kPa" else 1e6))
                                     for e, s, u in pairs]))
    return curves


def curve_at(pts, e):
    x0, y0 = 0.0, 0.0
    for i, (x1, y1) in enumerate(pts):
        if e <= x1 or i == len(pts) - 1:
            return y0 + (y1 - y0) / (x1 - x0) * (e - x0)
        x0, y0 = x1, y1
    return 0.0


def foam(res, out):
    """force M a against the deflection, quasi-static and impact; A S(d/h) of both curves and
    the impact's reference A S(d/h, |v|/h) (log-rate interpolation)"""
    (r_lo, lo), (r_hi, hi) = foam_curves()
    A, H = 0.01, 0.05
    # the body's CG when it meets the block: attached at once (0.05 m), through contact when
    # its face (0.02 m below the CG) reaches the top (0.07 m)
    for case, M, z0 in (("foam_block", 300.0, 0.05), ("foam_impact", 5.0, 0.05),
                        ("foam_contact", 5.0, 0.07)):
        h = os.path.join(res, "coupled_%s.h5" % case)
        t, z = h5(h, "/stage1/time"), h5(h, "/stage1/bodies/mass/position")
        v = h5(h, "/stage1/bodies/mass/velocity")
        a = mean_accel(t, v, 2)
        rows = []
        for i in range(2, len(t)):
            vm = 0.5 * (v[i][2] + v[i - 1][2])
            if vm >= 0:  # loading only (unloading follows the hysteresis branch)
                break
            d, rate = z0 - 0.5 * (z[i][2] + z[i - 1][2]), -vm / H
            if d < 0:
                continue
            s_lo, s_hi = curve_at(lo, d / H), curve_at(hi, d / H)
            wgt = min(max(math.log(max(rate, 1e-9) / r_lo) / math.log(r_hi / r_lo), 0), 1)
            rows.append((1e3 * d, M * a[i - 1], A * (s_lo + wgt * (s_hi - s_lo))))
        write(os.path.join(out, case + ".dat"), rows)
    write(os.path.join(out, "foam_curves.dat"),
          [(1e3 * H * e, A * curve_at(lo, e), A * curve_at(hi, e))
           for e in [k * 0.005 for k in range(0, 101)]])


def energy(res, out):
    """(total - total(0)) / the largest kinetic + internal energy, every case"""
    for case in ("bag_piston", "belt_limiter", "belt_pretensioner", "foam_block", "foam_impact",
                 "foam_contact", "momentum"):
        h = os.path.join(res, "coupled_%s.h5" % case)
        t, tot = h5(h, "/stage1/time"), h5(h, "/stage1/energy/total")
        kin, inn = h5(h, "/stage1/energy/kinetic"), h5(h, "/stage1/energy/internal")
        ref = max(k + i for k, i in zip(kin, inn))
        write(os.path.join(out, "energy_%s.dat" % case),
              [(1e3 * t[i], (tot[i] - tot[0]) / ref) for i in range(len(t))])


GP = """set terminal pngcairo size 640,460 font "sans,10" noenhanced
set grid
set key outside below
set output "{img}/restraints_bag.png"
set title "Rigid body on a closed bag: force on the plate against the stroke"
set xlabel "stroke [mm]"; set ylabel "force [N]"
plot "{d}/bag.dat" using 1:2 with lines lw 2 title "coupled run: M a of the plate", \\
     "{d}/bag.dat" using 1:4 with lines dt 2 lw 2 title "coupled run: (p - p_a) A_cap of the bag's gas", \\
     "{d}/bag_ref.dat" using 1:2 with lines dt 2 lc rgb "black" title "closed form, the bag as a prism (no bulge): (p0 (V0/V)^1.4 - p_a) A_cap"
set output "{img}/restraints_limiter.png"
set title "Body pulled by a belt through a 2 kN load limiter (20 kg, 4 m/s)"
set xlabel "time [ms]"; set ylabel "velocity [m/s]"; set y2label "belt force at the retractor [kN]"
set ytics nomirror; set y2tics; set y2range [0:2.5]
plot "{d}/limiter.dat" using 1:2 with lines lw 2 title "coupled run: body velocity", \\
     "{d}/limiter.dat" using 1:3 with lines dt 2 lc rgb "black" title "closed form: elastic, then F/M = 100 m/s^2", \\
     "{d}/limiter.dat" using 1:4 axes x1y2 with lines lc rgb "gray50" title "belt force (/stage1/retractor)"
unset y2tics; unset y2label; set ytics mirror
set output "{img}/restraints_pretensioner.png"
set title "Pretensioner pay-in (Eq. 3) pulling a free 1 kg body"
set xlabel "time [ms]"; set ylabel "displacement [mm]"
set yrange [-160:10]
plot "{d}/pretensioner.dat" using 1:2 with lines lw 2 title "coupled run: body", \\
     "{d}/pretensioner.dat" using 1:3 with lines dt 2 lc rgb "black" title "Eq. 3 pay-in", \\
     "{d}/pretensioner.dat" using 1:4 with lines dt 3 lc rgb "red" title "tension-only spring, released at 2 v"
set autoscale y
set output "{img}/restraints_foam.png"
set title "Body on a foam block: force against deflection"
set xlabel "deflection [mm]"; set ylabel "force [N]"
set xrange [0:25]
plot "{d}/foam_block.dat" using 1:2 with lines lw 2 title "300 kg at 0.3 m/s (quasi-static)", \\
     "{d}/foam_impact.dat" using 1:2 with lines lw 2 title "5 kg at 5 m/s (impact)", \\
     "{d}/foam_impact.dat" using 1:3 with lines dt 2 lc rgb "black" title "A S(d/h, |v|/h), impact", \\
     "{d}/foam_contact.dat" using 1:2 with lines lw 1 title "5 kg at 5 m/s through contact", \\
     "{d}/foam_curves.dat" using 1:2 with lines dt 3 lc rgb "gray40" title "A S at 10 /s", \\
     "{d}/foam_curves.dat" using 1:3 with lines dt 4 lc rgb "gray40" title "A S at 1000 /s"
set autoscale x
set output "{img}/restraints_energy.png"
set title "Energy balance of the coupled runs"
set xlabel "time [ms]"; set ylabel "(total - total(0)) / largest kinetic + internal"
plot for [c in "bag_piston belt_limiter belt_pretensioner foam_block foam_impact foam_contact momentum"] \\
     "{d}/energy_".c.".dat" using 1:2 with lines lw 2 title c
"""


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    res, img = sys.argv[1], sys.argv[2]
    bag(res, res)
    limiter(res, res)
    pretensioner(res, res)
    foam(res, res)
    energy(res, res)
    gp = os.path.join(res, "restraints.gp")
    with open(gp, "w") as f:
        f.write(GP.format(d=res, img=img))
    subprocess.run(["gnuplot", gp], check=True)


if __name__ == "__main__":
    main()

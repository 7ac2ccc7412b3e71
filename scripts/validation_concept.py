#!/usr/bin/env python3
"""validation_concept.py: the paper-phase plots of docs/validation_restraints.md from two stage-1
results files of the ISO 13232 413-0/13.4 pair (scripts/plot_restraints.sh runs them).

  python3 scripts/validation_concept.py CONVENTIONAL.h5 CONCEPT.h5 WORK_DIR IMG_DIR

Draws (gnuplot, data and script in WORK_DIR):
  IMG_DIR/concept_belts.png       thigh belt force and payout (pretensioner, limiter) - paper Fig. 13
  IMG_DIR/concept_airbag.png      front bag gauge pressure, volume, gas mass, rider contact - Fig. 16
  IMG_DIR/concept_trajectory.png  head and pelvis paths (side view), both motorcycles - Fig. 20
  IMG_DIR/concept_velocity.png    frame, sedan, pelvis, upper torso, head velocity along the
                                  heading, both - Fig. 21
  IMG_DIR/concept_criteria.png    injury criteria / their limits, both - Fig. 22
  IMG_DIR/concept_energy.png      the rider's energy balance (concept) and its cumulative contact
                                  energy by partner category, both - Fig. 24
The figures the doc states come from tests/test_validation_restraints.c (make verify). Reads the
HDF5 files with h5dump (hdf5-tools); no numpy."""
import os
import re
import subprocess
import sys


def h5(path, ds, missing_ok=False):
    out = subprocess.run(["h5dump", "-A", "0", "-d", ds, "-y", "-w", "0", path],
                         capture_output=True, text=True).stdout
    m = re.search(r"DATA \{\n(.*)\n\s*\}", out, re.S)
    if not m:
        if missing_ok:
            return None
        sys.exit("validation_concept: %s has no %s" % (path, ds))
    nums = [float(x) for x in re.findall(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?", m.group(1))]
    dims = [int(x) for x in re.search(r"DATASPACE\s+(?:SIMPLE|SCALAR)\s*\{?\s*\(?\s*([\d, ]*)\)?", out)
            .group(1).split(",") if x.strip()]
    if len(dims) <= 1:
        return nums
    return [nums[i * dims[1]:(i + 1) * dims[1]] for i in range(dims[0])]


def write(path, rows):
    with open(path, "w") as f:
        for r in rows:
            f.write(" ".join("%.9g" % x for x in r) + "\n")


def belts(h, out):
    t = h5(h, "/stage1/time")
    cols = [[1e3 * x for x in t]]
    for side in ("thigh_l", "thigh_r"):
        g = "/stage1/retractor/%s/" % side
        cols.append([x / 1e3 for x in h5(h, g + "force")])
        cols.append([1e3 * x for x in h5(h, g + "payout_pretensioner")])
        cols.append([1e3 * x for x in h5(h, g + "payout_limiter")])
        cols.append([1e3 * x for x in h5(h, g + "payout")])
    n = min(len(c) for c in cols)
    write(os.path.join(out, "belts.dat"), [[c[i] for c in cols] for i in range(n)])


def contact_norm(h, name):
    f = h5(h, "/stage1/contact/%s/force" % name, missing_ok=True)
    return [sum(x * x for x in r) ** 0.5 for r in f] if f else None


def airbag(h, out):
    t = h5(h, "/stage1/time")
    g = "/stage1/airbag/front/"
    p, V, m = h5(h, g + "pressure"), h5(h, g + "volume"), h5(h, g + "mass")
    # the bag's contacts, named in the concept scenario
    rider = contact_norm(h, "bag_rider") or [0] * len(t)
    car = contact_norm(h, "bag_car") or [0] * len(t)
    n = min(len(t), len(p), len(rider), len(car))
    write(os.path.join(out, "airbag.dat"),
          [(1e3 * t[i], (p[i] - 101325) / 1e3, 1e3 * V[i], 1e3 * m[i], rider[i] / 1e3, car[i] / 1e3)
           for i in range(n)])


def paths(h, tag, out):
    t = h5(h, "/stage1/time")
    rows = []
    bodies = [h5(h, "/stage1/bodies/%s/position" % b)
              for b in ("rider_head", "rider_pelvis", "moto_frame")]
    for i in range(0, len(t), 10):
        rows.append([1e3 * t[i]] + [c for b in bodies for c in (b[i][0], b[i][2])])
    write(os.path.join(out, "path_%s.dat" % tag), rows)


def velocity(h, tag, out):
    t = h5(h, "/stage1/time")
    bodies = [h5(h, "/stage1/bodies/%s/velocity" % b)
              for b in ("moto_frame", "sedan", "rider_pelvis", "rider_upper_torso", "rider_head")]
    write(os.path.join(out, "vel_%s.dat" % tag),
          [[1e3 * t[i]] + [b[i][0] for b in bodies] for i in range(len(t))])


CRITERIA = [("hic15", "HIC15", 700), ("head_a3ms", "head a3ms", 80), ("nij", "Nij", 1),
            ("neck_tension", "neck tension", 4170), ("neck_compression", "neck compr.", 4000),
            ("neck_extension", "neck ext. M", 57), ("neck_shear", "neck shear", 3100),
            ("chest_a3ms", "chest a3ms", 60), ("femur_compression", "femur", 10000),
            ("tibia_index", "tibia index", 1.3)]


def criteria(conv, conc, out):
    rows = []
    for i, (key, label, lim) in enumerate(CRITERIA):
        a = h5(conv, "/stage1/injury/" + key, missing_ok=True)
        b = h5(conc, "/stage1/injury/" + key, missing_ok=True)
        rows.append('%d "%s" %.6g %.6g' % (i, label, a[0] / lim if a else 0, b[0] / lim if b else 0))
    with open(os.path.join(out, "criteria.dat"), "w") as f:
        f.write("\n".join(rows) + "\n")


CATEGORIES = ("belts", "airbags", "foam", "motorcycle", "opponent", "ground")


def h5_attr(path, obj, name):
    out = subprocess.run(["h5dump", "-a", obj + "/" + name, path], capture_output=True,
                         text=True).stdout
    m = re.search(r'\(0\): "([^"]*)"', out)
    return m.group(1) if m else ""


def h5_members(path, group):
    out = subprocess.run(["h5ls", path + "/" + group], capture_output=True, text=True).stdout
    return [line.split()[0] for line in out.splitlines() if line.strip()]


def energy(h, tag, out):
    """the rider's balance and its contact energy summed by partner category (mb_egroup.c)"""
    g = "/stage1/energy_groups/rider/"
    t = h5(h, "/stage1/time")
    cols = [[1e3 * x for x in t]]
    for k in ("kinetic", "potential", "internal", "contact_total", "total"):
        cols.append(h5(h, g + k))
    cat = {c: [0.0] * len(t) for c in CATEGORIES}
    for p in h5_members(h, g + "contact"):
        c = h5_attr(h, g + "contact/" + p, "category")
        v = h5(h, g + "contact/" + p)
        if c in cat:
            cat[c] = [a + b for a, b in zip(cat[c], v)]
    cols += [cat[c] for c in CATEGORIES]
    n = min(len(c) for c in cols)
    write(os.path.join(out, "energy_%s.dat" % tag),
          [[c[i] / (1 if j == 0 else 1e3) for j, c in enumerate(cols)] for i in range(n)])


GP = """set terminal pngcairo size 700,480 font "sans,10" noenhanced
set grid
set key outside below
set output "{img}/concept_belts.png"
set title "Thigh belts of the concept, 413-0/13.4: force and payout at the retractor"
set xlabel "time [ms]"; set ylabel "force [kN]"; set y2label "payout [mm] (< 0 pulled in)"
set ytics nomirror; set y2tics; set xrange [0:300]; set yrange [0:2.6]
plot "{d}/belts.dat" using 1:2 with lines lw 2 title "force, left", \\
     "{d}/belts.dat" using 1:6 with lines lw 1 title "force, right", \\
     "{d}/belts.dat" using 1:3 axes x1y2 with lines dt 2 lw 2 title "pretensioner pay-in, left (Eq. 3)", \\
     "{d}/belts.dat" using 1:4 axes x1y2 with lines dt 3 lw 2 title "limiter payout, left", \\
     "{d}/belts.dat" using 1:5 axes x1y2 with lines dt 1 lc rgb "gray40" title "total payout, left"
set autoscale y; unset y2tics; unset y2label; set ytics mirror
set output "{img}/concept_airbag.png"
set title "Front airbag of the concept, 413-0/13.4"
set ylabel "gauge pressure [kPa], volume [l], gas mass [g]"; set y2label "contact force [kN]"
set y2tics; set ytics nomirror
plot "{d}/airbag.dat" using 1:2 with lines lw 2 title "gauge pressure [kPa]", \\
     "{d}/airbag.dat" using 1:3 with lines lw 2 title "volume [l]", \\
     "{d}/airbag.dat" using 1:4 with lines lw 2 title "gas mass [g]", \\
     "{d}/airbag.dat" using 1:5 axes x1y2 with lines dt 2 title "bag on the rider [kN]", \\
     "{d}/airbag.dat" using 1:6 axes x1y2 with lines dt 3 title "bag on the car [kN]"
unset y2tics; unset y2label; set ytics mirror
set output "{img}/concept_trajectory.png"
set title "Side view, 0-300 ms: head and pelvis paths (world x along the heading, z up)"
set xlabel "x [m]"; set ylabel "z [m]"; set xrange [0.4:2.8]; set yrange [0.4:1.9]
plot "{d}/path_conv.dat" using 2:3 with lines lw 2 lc rgb "red" title "head, conventional", \\
     "{d}/path_conv.dat" using 4:5 with lines lw 2 dt 2 lc rgb "red" title "pelvis, conventional", \\
     "{d}/path_conv.dat" using 6:7 with lines lw 1 dt 3 lc rgb "red" title "frame CG, conventional", \\
     "{d}/path_conc.dat" using 2:3 with lines lw 2 lc rgb "blue" title "head, concept", \\
     "{d}/path_conc.dat" using 4:5 with lines lw 2 dt 2 lc rgb "blue" title "pelvis, concept", \\
     "{d}/path_conc.dat" using 6:7 with lines lw 1 dt 3 lc rgb "blue" title "frame CG, concept", \\
     1.41 with lines dt 3 lc rgb "black" title "sedan roof height 1.41 m"
set autoscale y
set output "{img}/concept_velocity.png"
set title "Velocity along the heading (paper Fig. 21): conventional (dashed), concept (solid)"
set xlabel "time [ms]"; set ylabel "velocity [m/s]"; set xrange [0:300]
plot for [c=2:6] "{d}/vel_conc.dat" using 1:c with lines lw 2 lc c-1 \\
         title word("frame sedan pelvis upper_torso head", c-1), \\
     for [c=2:6] "{d}/vel_conv.dat" using 1:c with lines dt 2 lc c-1 notitle
set output "{img}/concept_criteria.png"
set title "Injury criteria / limit (paper Fig. 22): conventional and concept, 413-0/13.4"
set style data histograms; set style histogram clustered gap 1; set style fill solid 0.8
set xtics rotate by -40; set xlabel ""; set ylabel "value / limit"; set autoscale x; set yrange [0:*]
plot "{d}/criteria.dat" using 3:xtic(2) title "conventional", "" using 4 title "concept", \\
     1 with lines dt 2 lc rgb "black" title "limit"
set style data lines; set style fill empty; set xtics norotate; set autoscale
set terminal pngcairo size 1000,480 font "sans,10" noenhanced
set output "{img}/concept_energy.png"
set multiplot layout 1,2
set title "(a) the concept rider's energy (paper Eq. 9, Fig. 24a)"
set xlabel "time [ms]"; set ylabel "energy [kJ]"; set xrange [0:300]; set yrange [0:*]
plot for [c=2:6] "{d}/energy_conc.dat" using 1:c lw 2 \\
         title word("kinetic potential internal contact total", c-1)
set title "(b) contact energy by partner category (Fig. 24b); dashed: conventional"
set yrange [*:*]
plot for [c=7:12] "{d}/energy_conc.dat" using 1:c lw 2 lc c-6 \\
         title word("belts airbags foam motorcycle opponent ground", c-6), \\
     for [c=10:12] "{d}/energy_conv.dat" using 1:c dt 2 lc c-6 notitle
unset multiplot
"""


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    conv, conc, work, img = sys.argv[1:]
    belts(conc, work)
    airbag(conc, work)
    paths(conv, "conv", work)
    paths(conc, "conc", work)
    velocity(conv, "conv", work)
    velocity(conc, "conc", work)
    criteria(conv, conc, work)
    energy(conv, "conv", work)
    energy(conc, "conc", work)
    gp = os.path.join(work, "concept.gp")
    with open(gp, "w") as f:
        f.write(GP.format(d=work, img=img))
    subprocess.run(["gnuplot", gp], check=True)


if __name__ == "__main__":
    main()

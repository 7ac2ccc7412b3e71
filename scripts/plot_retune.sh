#!/bin/sh
# plot_retune.sh: the before/after plots of docs/loop.md from the compared curves `mcrash
# retune --csv FILE` writes (or a loop's DIR/curves_<k>.csv): wall force and fork angle of the
# stage-3 target, of stage 1 before and of stage 1 after the retune, drawn with gnuplot
# (apt-get install gnuplot-nox) as SVG:
#   IMG/NAME_force.svg, IMG/NAME_angle.svg
# Usage: scripts/plot_retune.sh CURVES.csv NAME [IMG directory, default docs/img]
set -eu
[ $# -ge 2 ] || { echo "usage: scripts/plot_retune.sh CURVES.csv NAME [IMG]" >&2; exit 2; }
CSV=$1
NAME=$2
IMG=${3:-docs/img}
command -v gnuplot >/dev/null || { echo "plot_retune: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 2; }
[ -r "$CSV" ] || { echo "plot_retune: $CSV: cannot read" >&2; exit 2; }
mkdir -p "$IMG"
# columns: 1 time [s]; 2-4 force stage 3, before, after [N]; 5-7 angle stage 3, before, after
plot() { # output ylabel scale c_target c_before c_after
    gnuplot <<GP
set terminal svg size 640,400 dynamic font "sans,11"
set output "$1"
set datafile separator ","
set key top left
set grid
set xlabel "time [ms]"
set ylabel "$2"
plot "$CSV" every ::1 using (1e3*\$1):(\$$4*$3) with lines lw 2 lc rgb "black" title "stage 3", \
     "" every ::1 using (1e3*\$1):(\$$5*$3) with lines lw 1.5 dt 2 lc rgb "#c03030" title "stage 1 before", \
     "" every ::1 using (1e3*\$1):(\$$6*$3) with lines lw 1.5 lc rgb "#3050c0" title "stage 1 after"
GP
}
plot "$IMG/${NAME}_force.svg" "wall force [kN]" 1e-3 2 3 4
plot "$IMG/${NAME}_angle.svg" "fork angle [rad]" 1 5 6 7
echo "plot_retune: $IMG/${NAME}_force.svg $IMG/${NAME}_angle.svg"

#!/bin/sh
# plot_validation.sh: the stage-1 validation plots of docs/validation_stage1.md. Runs the MYMOSA
# lateral impact and the ISO 13232 413-0/13.4 scenario with `mcrash run --stage 1`, exports the
# channels to CSV and draws with gnuplot (apt-get install gnuplot-nox):
#   docs/img/validation_fork.png      fork deformation angle vs time, MYMOSA's 20 and 30 ms marked
#   docs/img/validation_force.png     motorcycle-car contact force (sum of the contacts) vs time
#   docs/img/validation_velocity.png  motorcycle frame and car velocity along the heading
#   docs/img/validation_mymosa_rider.png, docs/img/validation_413_rider.png  the rider cases:
#       fork angle, attachment stretch, rider contact forces, head acceleration
#       (scripts/validation_stage1.py, which also prints the event times)
# Usage: scripts/plot_validation.sh [bin/mcrash] [output directory for the PNGs]
set -eu
MCRASH=${1:-bin/mcrash}
IMG=${2:-docs/img}
WORK=${TMPDIR:-/tmp}/mcrash_validation.$$
mkdir -p "$WORK" "$IMG"
trap 'rm -rf "$WORK"' EXIT
command -v gnuplot >/dev/null || { echo "plot_validation: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 2; }

run() { # name scenario
    "$MCRASH" run "$2" --stage 1 --quiet -o "$WORK/$1.h5" >/dev/null
    "$MCRASH" export "$WORK/$1.h5" --csv "$WORK/$1" >/dev/null
}
run mymosa scenarios/mymosa_lateral_car_1100kg.yaml
run iso413 scenarios/iso13232_413-0_13.4_sedan.yaml
# the fork's elastic limit [rad], from the motorcycle model
PHI_E=$(awk '/^  fork_deformation:/ { f = 1 } f && /elastic_limit:/ { print $2; exit }' \
        scenarios/models/motorcycles/sport_208kg.yaml)

# a table t [ms], fork angle [rad], contact force [kN], frame vx, car vx [m/s] from the CSV
# columns named in its header (the car's velocity sensor: car_vel or sedan_vel)
table() { # name car_sensor
    awk -F', *' -v car="$2" '
        NR == 1 {
            for (i = 1; i <= NF; i++) {
                h = $i; sub(/ \[.*/, "", h); c[h] = i
            }
            next
        }
        {
            f = 0
            split("front_tyre_car frame_car handlebar_car fork_car", k, " ")
            for (j in k) if ((k[j] "_fn") in c) f += $(c[k[j] "_fn"])
            printf "%.2f %.5f %.4f %.5f %.5f\n", $1 * 1e3, $(c["moto_fork_deformation_angle"]),
                   f / 1e3, $(c["moto_frame_vel_vx"]), $(c[car "_vx"])
        }' "$WORK/$1/stage1_channels.csv" >"$WORK/$1.dat"
}
table mymosa car_vel
table iso413 sedan_vel

gnuplot <<EOF
set terminal pngcairo size 640,460 font "sans,10" noenhanced
set grid
set key outside below
set xlabel "time [ms]"
set xrange [0:150]

set output "$IMG/validation_fork.png"
set title "Fork deformation angle (rearward bending of the fork hinge)"
set ylabel "angle [rad]"
set arrow 1 from 20, graph 0 to 20, graph 1 nohead dt 2 lc rgb "gray40"
set arrow 2 from 30, graph 0 to 30, graph 1 nohead dt 2 lc rgb "gray40"
set label 1 "MYMOSA: deforming from about 20 ms" at 21, graph 0.12 font ",8"
set label 2 "MYMOSA: maximum at about 30 ms" at 31, graph 0.05 font ",8"
plot "$WORK/mymosa.dat" using 1:2 with lines lw 2 title "MYMOSA lateral, 1100 kg car", \
     "$WORK/iso413.dat" using 1:2 with lines lw 2 title "413-0/13.4, 1668 kg sedan", \
     $PHI_E with lines dt 3 lc rgb "black" title "elastic limit $PHI_E rad", \
     0.2 with lines dt 4 lc rgb "black" title "wheel against the engine 0.2 rad"
unset arrow; unset label

set output "$IMG/validation_force.png"
set title "Motorcycle-car contact force (tyre, frame, handlebar, fork tubes)"
set ylabel "force [kN]"
plot "$WORK/mymosa.dat" using 1:3 with lines lw 2 title "MYMOSA lateral, 1100 kg car", \
     "$WORK/iso413.dat" using 1:3 with lines lw 2 title "413-0/13.4, 1668 kg sedan"

set output "$IMG/validation_velocity.png"
set title "Velocity along the motorcycle's heading"
set ylabel "velocity [m/s]"

set xrange [0:300]
plot "$WORK/mymosa.dat" using 1:4 with lines lw 2 title "motorcycle frame, MYMOSA", \
     "$WORK/mymosa.dat" using 1:5 with lines lw 2 title "1100 kg car, MYMOSA", \
     "$WORK/iso413.dat" using 1:4 with lines lw 2 title "motorcycle frame, 413", \
     "$WORK/iso413.dat" using 1:5 with lines lw 2 title "1668 kg sedan, 413", \
     208*13.4/1308 with lines dt 2 lc rgb "gray40" title "common velocity 2.13 m/s (1100 kg)", \
     208*13.4/1876 with lines dt 3 lc rgb "gray40" title "common velocity 1.49 m/s (1668 kg)"
EOF

# the rider cases: event times printed, gnuplot script written by validation_stage1.py
"$MCRASH" run scenarios/mymosa_lateral_car_1100kg_rider.yaml --stage 1 --quiet -o "$WORK/mymosa_rider.h5" >/dev/null
"$MCRASH" run scenarios/iso13232_413-0_13.4_sedan_rider.yaml --stage 1 --quiet -o "$WORK/413_rider.h5" >/dev/null
python3 scripts/validation_stage1.py "$WORK/mymosa_rider.h5" car "$WORK/413_rider.h5" sedan
gnuplot out/validation/plots.gp
cp out/validation/mymosa_rider_events.png "$IMG/validation_mymosa_rider.png"
cp out/validation/413_rider_events.png "$IMG/validation_413_rider.png"
echo "plot_validation: $IMG/validation_fork.png $IMG/validation_force.png $IMG/validation_velocity.png" \
     "$IMG/validation_mymosa_rider.png $IMG/validation_413_rider.png"
